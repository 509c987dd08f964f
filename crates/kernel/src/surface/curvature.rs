//! Principal, Gaussian and mean curvature of surfaces from the fundamental forms.

use crate::surface::check_parameters;
use crate::surface::normal::regular_normal;
use crate::{Error, NurbsSurface, Point3, Result, SurfaceDerivatives, Vector3};

/// The curvature of a surface at a point, with openNURBS's sign convention.
///
/// Curvatures are signed with respect to the unit normal `N = (Su × Sv)/|Su × Sv|`: the normal
/// curvature in a tangent direction `w` is `II(w, w) / I(w, w)`, positive where the surface
/// bends towards `N`. Rhino's sphere and cylinder have outward normals, so a sphere of radius 2
/// has `k1 = k2 = −0.5`, Gaussian curvature `+0.25` and mean curvature `−0.5`, and a cylinder of
/// radius `r` has `k1 = 0` along its axis and `k2 = −1/r`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SurfaceCurvature {
    /// The surface point.
    pub point: Point3,
    /// The unit normal the curvatures are signed against.
    pub normal: Vector3,
    /// The larger principal curvature.
    pub k1: f64,
    /// The smaller principal curvature, `k2 ≤ k1`.
    pub k2: f64,
    /// The unit principal direction of `k1`, tangent to the surface. At an umbilic (all normal
    /// curvatures equal) every tangent direction is principal, and this is the unit `Su`
    /// (up to rounding).
    pub direction1: Vector3,
    /// The unit principal direction of `k2`: `N × direction1`, so that
    /// `(direction1, direction2, N)` is right-handed.
    pub direction2: Vector3,
    /// The Gaussian curvature `k1 · k2 = (LN − M²)/(EG − F²)`.
    pub gaussian: f64,
    /// The mean curvature `(k1 + k2)/2 = (EN − 2FM + GL)/(2(EG − F²))`.
    pub mean: f64,
}

impl SurfaceCurvature {
    /// The curvature from the point and partial derivatives up to order 2.
    ///
    /// # Errors
    /// [`Error::Degenerate`] where the first fundamental form is singular (`Su × Sv = 0`, as at
    /// a sphere's pole), so that curvatures cannot be computed from the derivatives there;
    /// [`Error::NotFinite`] if the derivatives are not finite.
    pub fn from_derivatives(d: &SurfaceDerivatives) -> Result<Self> {
        if !d.is_finite() {
            return Err(Error::NotFinite {
                what: "surface derivatives",
            });
        }
        let normal = regular_normal(d).ok_or(Error::Degenerate {
            what: "surface at the curvature point",
        })?;
        let [e, f, _] = d.first_fundamental_form();
        let [l, m, n] = d.second_fundamental_form(normal);
        // EG − F² = |Su × Sv|², computed without cancellation.
        let det = d.du.cross(d.dv).length_squared();
        let len_u = e.sqrt();
        if det.is_nan() || det <= 0.0 || len_u <= 0.0 {
            return Err(Error::Degenerate {
                what: "surface at the curvature point",
            });
        }
        // The shape operator in the orthonormal tangent frame e1 = Su/|Su|, e2 = N × e1 is the
        // symmetric matrix [[a, b], [b, c]] of the second fundamental form on (e1, e2). Its
        // eigenvalues follow without cancellation from the mean (a + c)/2 and the radius
        // hypot((a − c)/2, b), even at near-umbilics.
        let e1 = d.du / len_u;
        let e2 = normal.cross(e1);
        // e1 = α1 Su; e2 = α2 Su + β2 Sv from I·(α2, β2) = (Su·e2, Sv·e2) = (0, Sv·e2).
        let alpha1 = 1.0 / len_u;
        let s = d.dv.dot(e2);
        let (alpha2, beta2) = (-f * s / det, e * s / det);
        let a = l * alpha1 * alpha1;
        let b = alpha1 * (l * alpha2 + m * beta2);
        let c = l * alpha2 * alpha2 + 2.0 * m * alpha2 * beta2 + n * beta2 * beta2;
        let mean = 0.5 * (a + c);
        let half_spread = (0.5 * (a - c)).hypot(b);
        let k1 = mean + half_spread;
        let k2 = mean - half_spread;
        let gaussian = a * c - b * b;
        // The eigenvector of k1 is at angle θ = ½ atan2(2b, a − c) from e1; at an umbilic
        // (b = 0, a = c) this gives e1 itself.
        let theta = 0.5 * (2.0 * b).atan2(a - c);
        let direction1 = e1 * theta.cos() + e2 * theta.sin();
        let direction2 = normal.cross(direction1);
        Ok(Self {
            point: d.point,
            normal,
            k1,
            k2,
            direction1,
            direction2,
            gaussian,
            mean,
        })
    }

    /// Whether the point is an umbilic within `tolerance`: `k1 − k2 ≤ tolerance · max(1, |k1|,
    /// |k2|)`. There the principal directions are arbitrary.
    pub fn is_umbilic(&self, tolerance: f64) -> bool {
        self.k1 - self.k2 <= tolerance * 1f64.max(self.k1.abs()).max(self.k2.abs())
    }

    /// The normal curvature in the tangent direction at angle `angle` from `direction1`
    /// towards `direction2` (Euler's formula `k1 cos² θ + k2 sin² θ`).
    pub fn normal_curvature_at_angle(&self, angle: f64) -> f64 {
        let (s, c) = angle.sin_cos();
        self.k1 * c * c + self.k2 * s * s
    }
}

impl NurbsSurface {
    /// The principal curvatures and directions, and the Gaussian and mean curvature, at
    /// `(u, v)` (see [`SurfaceCurvature`] for the sign convention).
    ///
    /// # Errors
    /// [`Error::NotFinite`] for NaN or infinite parameters, [`Error::Degenerate`] where
    /// `Su × Sv = 0`.
    pub fn curvature_at(&self, u: f64, v: f64) -> Result<SurfaceCurvature> {
        check_parameters(u, v)?;
        SurfaceCurvature::from_derivatives(&self.derivatives_unchecked(u, v, 2))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::surface::tests::wavy;
    use crate::{Cylinder, Plane, Sphere};

    #[test]
    fn rhinos_sphere_and_cylinder_signs() {
        let sphere = Sphere::new(Point3::ORIGIN, 2.0)
            .unwrap()
            .to_nurbs()
            .unwrap();
        let c = sphere.curvature_at(1.0, 0.3).unwrap();
        assert!((c.k1 + 0.5).abs() < 1e-12 && (c.k2 + 0.5).abs() < 1e-12);
        assert!((c.gaussian - 0.25).abs() < 1e-12 && (c.mean + 0.5).abs() < 1e-12);
        assert!(c.is_umbilic(1e-9));

        let cylinder = Cylinder::new(Plane::WORLD_XY, 1.5, 4.0)
            .unwrap()
            .to_nurbs()
            .unwrap();
        let c = cylinder.curvature_at(2.0, 1.0).unwrap();
        assert!(c.k1.abs() < 1e-12 && (c.k2 + 1.0 / 1.5).abs() < 1e-12);
        assert!((c.direction1.dot(Vector3::Z).abs() - 1.0).abs() < 1e-12);
        assert!(!c.is_umbilic(1e-9));
        assert!((c.normal_curvature_at_angle(std::f64::consts::FRAC_PI_2) - c.k2).abs() < 1e-15);
    }

    #[test]
    fn principal_directions_are_tangent_and_extremal() {
        let s = wavy(true);
        for &(u, v) in &[(0.3, -0.5), (0.9, 1.7), (1.7, 2.6)] {
            let c = s.curvature_at(u, v).unwrap();
            let d = s.derivatives_at(u, v, 2).unwrap();
            assert!(c.k1 >= c.k2);
            assert!(c.direction1.dot(c.normal).abs() < 1e-12);
            assert!(c.direction1.dot(c.direction2).abs() < 1e-12);
            // The normal curvature in a direction w = a Su + b Sv is II(w, w)/I(w, w); it is
            // k1 along direction1, k2 along direction2, and between them elsewhere.
            let [e, f, g] = d.first_fundamental_form();
            let [l, m, n] = d.second_fundamental_form(c.normal);
            let det = e * g - f * f;
            let normal_curvature = |w: Vector3| {
                let (wu, wv) = (w.dot(d.du), w.dot(d.dv));
                let a = (g * wu - f * wv) / det;
                let b = (e * wv - f * wu) / det;
                (l * a * a + 2.0 * m * a * b + n * b * b)
                    / (e * a * a + 2.0 * f * a * b + g * b * b)
            };
            assert!((normal_curvature(c.direction1) - c.k1).abs() < 1e-10);
            assert!((normal_curvature(c.direction2) - c.k2).abs() < 1e-10);
            for k in 0..16 {
                let angle = k as f64 * 0.2;
                let w = c.direction1 * angle.cos() + c.direction2 * angle.sin();
                let kn = normal_curvature(w);
                assert!(kn <= c.k1 + 1e-10 && kn >= c.k2 - 1e-10);
                assert!((kn - c.normal_curvature_at_angle(angle)).abs() < 1e-10);
            }
            assert!((c.gaussian - c.k1 * c.k2).abs() < 1e-12);
            assert!((c.mean - 0.5 * (c.k1 + c.k2)).abs() < 1e-12);
        }
    }

    #[test]
    fn curvature_at_a_pole_is_reported_as_degenerate() {
        let sphere = Sphere::new(Point3::ORIGIN, 2.0)
            .unwrap()
            .to_nurbs()
            .unwrap();
        assert!(matches!(
            sphere.curvature_at(0.0, sphere.domain_v().t1),
            Err(Error::Degenerate { .. })
        ));
        assert!(sphere.curvature_at(f64::NAN, 0.0).is_err());
    }
}

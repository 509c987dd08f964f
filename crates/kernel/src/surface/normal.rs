//! Surface normals and frames, including the limit normal at singular points.

use crate::geometry::tolerance::SQRT_EPSILON;
use crate::surface::check_parameters;
use crate::{Error, NurbsSurface, Plane, Result, SurfaceDerivatives, Vector3};

impl NurbsSurface {
    /// The unit normal `N = (Su × Sv) / |Su × Sv|` at `(u, v)`.
    ///
    /// Where the partial derivatives vanish or are parallel (a sphere's pole, a cone's apex)
    /// the normal is the limit of `Su × Sv` as `(u, v)` is approached from inside the
    /// parameter rectangle, from the quadrant facing the nearer ends of the two domains; this
    /// is what openNURBS's `ON_EvNormal` does on the sides of the domain, so Rhino's sphere has
    /// outward normals `∓Z` at its poles.
    ///
    /// # Errors
    /// [`Error::NotFinite`] for NaN or infinite parameters, [`Error::Degenerate`] where even
    /// the limit does not exist (a flat collapse, such as a surface that is a single point).
    pub fn normal_at(&self, u: f64, v: f64) -> Result<Vector3> {
        check_parameters(u, v)?;
        let d = self.derivatives_unchecked(u, v, 1);
        if let Some(n) = regular_normal(&d) {
            return Ok(n);
        }
        let d = self.derivatives_unchecked(u, v, 2);
        self.limit_normal(u, v, &d).ok_or(Error::Degenerate {
            what: "surface normal",
        })
    }

    /// The normal from derivatives up to order 2 evaluated at `(u, v)`: `Su × Sv` where it is
    /// well defined, otherwise its limit (see [`normal_at`](Self::normal_at)).
    pub(crate) fn normal_from_derivatives(
        &self,
        u: f64,
        v: f64,
        d: &SurfaceDerivatives,
    ) -> Option<Vector3> {
        regular_normal(d).or_else(|| self.limit_normal(u, v, d))
    }

    /// The limit of the normal at a point where `Su × Sv` degenerates, from the Taylor
    /// expansions of `Su` and `Sv` along the diagonal `(u + a·h, v + b·h)`, `h → 0⁺`.
    fn limit_normal(&self, u: f64, v: f64, d: &SurfaceDerivatives) -> Option<Vector3> {
        let (du, dv) = (self.domain_u(), self.domain_v());
        // Approach from inside: towards increasing u when nearer u0, decreasing when nearer u1.
        let a = if u - du.t0 <= du.t1 - u { 1.0 } else { -1.0 };
        let b = if v - dv.t0 <= dv.t1 - v { 1.0 } else { -1.0 };
        // Su(h) ≈ Su + h·s0 and Sv(h) ≈ Sv + h·s1.
        let s0 = d.duu * a + d.duv * b;
        let s1 = d.duv * a + d.dvv * b;
        let first = d.du.cross(s1) + s0.cross(d.dv);
        let scale = d.du.length() * s1.length() + s0.length() * d.dv.length();
        if let Some(n) = unit_if_significant(first, scale) {
            return Some(n);
        }
        let second = s0.cross(s1);
        unit_if_significant(second, s0.length() * s1.length())
    }

    /// The frame at `(u, v)`: origin on the surface, x axis along `Su`, z axis the normal and
    /// y axis `N × x` (openNURBS's `FrameAt`). Where `Su` vanishes the y axis is along `Sv`
    /// instead and the x axis is `Sv × N`.
    ///
    /// # Errors
    /// As [`normal_at`](Self::normal_at), and [`Error::Degenerate`] when both partial
    /// derivatives vanish.
    pub fn frame_at(&self, u: f64, v: f64) -> Result<Plane> {
        check_parameters(u, v)?;
        let d = self.derivatives_unchecked(u, v, 2);
        let n = self
            .normal_from_derivatives(u, v, &d)
            .ok_or(Error::Degenerate {
                what: "surface normal",
            })?;
        frame_from(&d, n).ok_or(Error::Degenerate {
            what: "surface frame",
        })
    }
}

/// The frame at a surface point with known derivatives and unit normal `n`.
pub(crate) fn frame_from(d: &SurfaceDerivatives, n: Vector3) -> Option<Plane> {
    let tangential = |w: Vector3| (w - n * w.dot(n)).try_normalize();
    let (x_axis, y_axis) = if let Some(x) = tangential(d.du) {
        (x, n.cross(x))
    } else {
        let y = tangential(d.dv)?;
        (y.cross(n), y)
    };
    Some(Plane {
        origin: d.point,
        x_axis,
        y_axis,
        z_axis: n,
    })
}

/// `Su × Sv` normalized, when neither derivative is negligible beside the other and they are
/// not parallel (openNURBS's test in `ON_Surface::EvNormal`).
pub(crate) fn regular_normal(d: &SurfaceDerivatives) -> Option<Vector3> {
    let lu = d.du.length();
    let lv = d.dv.length();
    if !(lu > SQRT_EPSILON * lv && lv > SQRT_EPSILON * lu) {
        return None;
    }
    let n = (d.du / lu).cross(d.dv / lv);
    let len = n.length();
    (len > SQRT_EPSILON && len.is_finite()).then(|| n / len)
}

/// `w` normalized if its length is a significant part of `scale`.
fn unit_if_significant(w: Vector3, scale: f64) -> Option<Vector3> {
    let len = w.length();
    (len.is_finite() && len > 0.0 && len > SQRT_EPSILON * scale).then(|| w / len)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::surface::tests::wavy;
    use crate::{Cone, Point3, Sphere};

    #[test]
    fn sphere_normals_point_outwards_including_the_poles() {
        let center = Point3::new(1.0, -2.0, 0.5);
        let s = Sphere::new(center, 2.0).unwrap().to_nurbs().unwrap();
        let (du, dv) = (s.domain_u(), s.domain_v());
        for i in 0..=8 {
            for j in 0..=8 {
                let (u, v) = (
                    du.parameter_at(i as f64 / 8.0),
                    dv.parameter_at(j as f64 / 8.0),
                );
                let n = s.normal_at(u, v).unwrap();
                let radial = (s.point_at(u, v) - center) / 2.0;
                assert!(
                    (n - radial).length() < 1e-12,
                    "({u}, {v}): {n:?} vs {radial:?}"
                );
            }
        }
        assert!((s.normal_at(0.3, dv.t0).unwrap() + Vector3::Z).length() < 1e-15);
        assert!((s.normal_at(5.0, dv.t1).unwrap() - Vector3::Z).length() < 1e-15);
    }

    #[test]
    fn cone_apex_normal_is_the_limit_along_the_seam_side() {
        let cone = Cone::new(Plane::WORLD_XY, 2.0, 1.0).unwrap();
        let s = cone.to_nurbs().unwrap();
        for u in [0.0, 1.0, std::f64::consts::PI] {
            let at_apex = s.normal_at(u, 0.0).unwrap();
            let near = s.normal_at(u, 1e-7).unwrap();
            assert!((at_apex - near).length() < 1e-6, "{at_apex:?} vs {near:?}");
            // Outward and downward: the slant normal of a cone opening upwards.
            assert!(at_apex.z < 0.0);
        }
    }

    #[test]
    fn frames_are_orthonormal_and_right_handed() {
        let s = wavy(true);
        for &(u, v) in &[(0.0, -1.0), (0.7, 0.4), (2.0, 3.0)] {
            let f = s.frame_at(u, v).unwrap();
            let n = s.normal_at(u, v).unwrap();
            assert_eq!(f.z_axis, n);
            assert!((f.x_axis.length() - 1.0).abs() < 1e-15);
            assert!(f.x_axis.dot(f.y_axis).abs() < 1e-15);
            assert!((f.x_axis.cross(f.y_axis) - f.z_axis).length() < 1e-15);
            let du = s.derivatives_at(u, v, 1).unwrap().du;
            assert!((f.x_axis - du.try_normalize().unwrap()).length() < 1e-15);
        }
        let sphere = Sphere::new(Point3::ORIGIN, 1.0)
            .unwrap()
            .to_nurbs()
            .unwrap();
        let pole = sphere.frame_at(1.0, sphere.domain_v().t1).unwrap();
        assert!((pole.z_axis - Vector3::Z).length() < 1e-15);
        assert!((pole.x_axis.cross(pole.y_axis) - Vector3::Z).length() < 1e-15);
        assert!(s.frame_at(f64::NAN, 0.0).is_err());
    }

    #[test]
    fn a_surface_collapsed_to_a_point_has_no_normal() {
        let p = Point3::new(1.0, 1.0, 1.0);
        let s = NurbsSurface::non_rational(
            1,
            1,
            vec![vec![p, p], vec![p, p]],
            vec![0.0, 1.0],
            vec![0.0, 1.0],
        )
        .unwrap();
        assert!(matches!(
            s.normal_at(0.5, 0.5),
            Err(Error::Degenerate { .. })
        ));
    }
}

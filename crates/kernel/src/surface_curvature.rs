//! Principal, Gaussian and mean curvature of surfaces from the fundamental forms.

use crate::nurbs_surface::check_parameters;
use crate::surface_normal::regular_normal;
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
    /// curvatures equal) every tangent direction is principal, and this is the unit `Su`.
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
        let [e, f, g] = d.first_fundamental_form();
        let [l, m, n] = d.second_fundamental_form(normal);
        // EG − F² = |Su × Sv|², computed without cancellation.
        let det = d.du.cross(d.dv).length_squared();
        if det.is_nan() || det <= 0.0 {
            return Err(Error::Degenerate {
                what: "surface at the curvature point",
            });
        }
        let gaussian = (l * n - m * m) / det;
        let mean = (e * n - 2.0 * f * m + g * l) / (2.0 * det);
        let s = (mean * mean - gaussian).max(0.0).sqrt();
        // The root of larger magnitude first, the other from the product, to avoid cancellation.
        let (k1, k2) = if mean >= 0.0 {
            let k1 = mean + s;
            (k1, if k1 != 0.0 { gaussian / k1 } else { mean - s })
        } else {
            let k2 = mean - s;
            (gaussian / k2, k2)
        };
        let (k1, k2) = if k1 >= k2 { (k1, k2) } else { (k2, k1) };
        let direction1 = principal_direction(d, [e, f, g], [l, m, n], k1, k2)
            .or_else(|| d.du.try_normalize())
            .or_else(|| d.dv.cross(normal).try_normalize())
            .ok_or(Error::Degenerate {
                what: "surface at the curvature point",
            })?;
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

/// The unit 3-D principal direction for `k1`, or `None` at an umbilic.
fn principal_direction(
    d: &SurfaceDerivatives,
    [e, f, g]: [f64; 3],
    [l, m, n]: [f64; 3],
    k1: f64,
    k2: f64,
) -> Option<Vector3> {
    let spread = k1 - k2;
    if spread.is_nan() || spread <= 1e-12 * 1f64.max(k1.abs()).max(k2.abs()) {
        return None;
    }
    // (II − k I) w = 0: each row gives a direction perpendicular to it in (du, dv); take the
    // better conditioned one.
    let (a, b, c) = (l - k1 * e, m - k1 * f, n - k1 * g);
    let w1 = d.du * b - d.dv * a;
    let w2 = d.du * c - d.dv * b;
    let w = if w1.length_squared() >= w2.length_squared() {
        w1
    } else {
        w2
    };
    w.try_normalize()
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

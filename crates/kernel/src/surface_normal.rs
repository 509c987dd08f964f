//! Surface normals and frames, including the limit normal at singular points.

use crate::nurbs_surface::check_parameters;
use crate::tolerance::SQRT_EPSILON;
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

//! Isocurves: the curves on a surface along which one parameter is constant.

use crate::curve::nurbs::basis::{MAX_ORDER, basis_functions, span_index};
use crate::surface::direction::SurfaceDirection;
use crate::{Error, NurbsCurve, NurbsSurface, Point3, Result};

impl NurbsSurface {
    /// The isocurve running in `direction` with the other parameter fixed at `constant`, as an
    /// exact NURBS curve (Rhino's `IsoCurve`): `isocurve(U, c)` is `t ↦ S(t, c)` and
    /// `isocurve(V, c)` is `t ↦ S(c, t)`. The curve has the degree, knots and domain of the
    /// surface in `direction`.
    ///
    /// The control points are the surface's control points combined, in homogeneous form,
    /// with the basis functions of the fixed parameter, so the curve is exact also for rational
    /// surfaces. A constant outside the domain extrapolates.
    ///
    /// # Errors
    /// [`Error::NotFinite`] if `constant` is not finite.
    pub fn isocurve(&self, direction: SurfaceDirection, constant: f64) -> Result<NurbsCurve> {
        if !constant.is_finite() {
            return Err(Error::NotFinite { what: "parameter" });
        }
        let fixed = direction.other();
        let q = self.degree(fixed);
        let fixed_knots = self.knots(fixed);
        let span = span_index(q, fixed_knots, constant);
        let mut basis = [0.0; MAX_ORDER];
        basis_functions(q, fixed_knots, span, constant, &mut basis);
        let first = span + 1 - q;
        let count = self.count(direction);
        let mut points = Vec::with_capacity(count);
        let mut weights = Vec::with_capacity(count);
        for i in 0..count {
            let (mut x, mut y, mut z, mut w) = (0.0, 0.0, 0.0, 0.0);
            for (s, &b) in basis[..=q].iter().enumerate() {
                let (iu, iv) = match direction {
                    SurfaceDirection::U => (i, first + s),
                    SurfaceDirection::V => (first + s, i),
                };
                let index = iu * self.count_v() + iv;
                let p = self.points()[index];
                let bw = b * self.weights()[index];
                x += bw * p.x;
                y += bw * p.y;
                z += bw * p.z;
                w += bw;
            }
            points.push(Point3::new(x / w, y / w, z / w));
            weights.push(w);
        }
        // Snap weights that are 1 up to rounding, so that non-rational surfaces give
        // non-rational curves.
        if !self.is_rational() {
            weights.fill(1.0);
        }
        NurbsCurve::new(
            self.degree(direction),
            points,
            weights,
            self.knots(direction).to_vec(),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Sphere;

    #[test]
    fn isocurves_follow_the_surface() {
        let sphere = Sphere::new(Point3::new(1.0, -2.0, 0.5), 2.0)
            .unwrap()
            .to_nurbs()
            .unwrap();
        for c in [-1.5, -0.3, 0.0, 0.7, 1.2] {
            let curve = sphere.isocurve(SurfaceDirection::U, c).unwrap();
            assert_eq!(curve.domain(), sphere.domain_u());
            for k in 0..=20 {
                let t = sphere.domain_u().parameter_at(k as f64 / 20.0);
                assert!(curve.point_at(t).distance(sphere.point_at(t, c)) < 1e-14);
            }
        }
        for c in [0.0, 1.0, 3.0, 6.2] {
            let curve = sphere.isocurve(SurfaceDirection::V, c).unwrap();
            assert_eq!(curve.domain(), sphere.domain_v());
            for k in 0..=20 {
                let t = sphere.domain_v().parameter_at(k as f64 / 20.0);
                assert!(curve.point_at(t).distance(sphere.point_at(c, t)) < 1e-14);
            }
        }
        assert!(sphere.isocurve(SurfaceDirection::U, f64::NAN).is_err());
    }
}

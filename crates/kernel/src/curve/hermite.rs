//! Cubic Hermite curves: two end points and the derivatives there.

use crate::{Bezier, Error, NurbsCurve, Point3, Result, Vector3};

/// The cubic on `[0, 1]` with `C(0) = start`, `C'(0) = start_tangent`, `C(1) = end` and
/// `C'(1) = end_tangent` (the book's figure 32, right):
///
/// ```text
/// C(t) = h00(t) P0 + h10(t) T0 + h01(t) P1 + h11(t) T1
/// h00 = 2t³ − 3t² + 1,  h10 = t³ − 2t² + t,  h01 = −2t³ + 3t²,  h11 = t³ − t²
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CubicHermite {
    /// The point at `t = 0`.
    pub start: Point3,
    /// The derivative at `t = 0`.
    pub start_tangent: Vector3,
    /// The point at `t = 1`.
    pub end: Point3,
    /// The derivative at `t = 1`.
    pub end_tangent: Vector3,
}

impl CubicHermite {
    /// The Hermite cubic from its end points and end derivatives.
    #[inline]
    pub const fn new(
        start: Point3,
        start_tangent: Vector3,
        end: Point3,
        end_tangent: Vector3,
    ) -> Self {
        Self {
            start,
            start_tangent,
            end,
            end_tangent,
        }
    }

    /// Whether every input is finite.
    pub fn is_finite(&self) -> bool {
        self.start.is_finite()
            && self.start_tangent.is_finite()
            && self.end.is_finite()
            && self.end_tangent.is_finite()
    }

    /// The point at `t`.
    pub fn point_at(&self, t: f64) -> Point3 {
        let t2 = t * t;
        let t3 = t2 * t;
        let h00 = 2.0 * t3 - 3.0 * t2 + 1.0;
        let h10 = t3 - 2.0 * t2 + t;
        let h01 = -2.0 * t3 + 3.0 * t2;
        let h11 = t3 - t2;
        Point3::from_vector(
            self.start.to_vector() * h00
                + self.start_tangent * h10
                + self.end.to_vector() * h01
                + self.end_tangent * h11,
        )
    }

    /// The first derivative at `t`.
    pub fn derivative_at(&self, t: f64) -> Vector3 {
        let t2 = t * t;
        let d00 = 6.0 * t2 - 6.0 * t;
        let d10 = 3.0 * t2 - 4.0 * t + 1.0;
        let d11 = 3.0 * t2 - 2.0 * t;
        (self.start - self.end) * d00 + self.start_tangent * d10 + self.end_tangent * d11
    }

    /// The same cubic as a Bézier curve: `P0, P0 + T0/3, P1 − T1/3, P1`.
    ///
    /// # Errors
    /// [`Error::NotFinite`] for NaN or infinite input.
    pub fn to_bezier(&self) -> Result<Bezier> {
        if !self.is_finite() {
            return Err(Error::NotFinite {
                what: "hermite curve",
            });
        }
        Bezier::new(vec![
            self.start,
            self.start + self.start_tangent / 3.0,
            self.end - self.end_tangent / 3.0,
            self.end,
        ])
    }

    /// The exact NURBS form (the Bézier form with knots `0, 0, 0, 1, 1, 1`).
    ///
    /// # Errors
    /// [`Error::NotFinite`] for NaN or infinite input.
    pub fn to_nurbs(&self) -> Result<NurbsCurve> {
        Ok(self.to_bezier()?.to_nurbs())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn end_conditions_and_bezier_form() {
        let h = CubicHermite::new(
            Point3::new(0.0, 0.0, 0.0),
            Vector3::new(3.0, 3.0, 0.0),
            Point3::new(4.0, 0.0, 1.0),
            Vector3::new(0.0, -6.0, 0.0),
        );
        assert_eq!(h.point_at(0.0), h.start);
        assert_eq!(h.point_at(1.0), h.end);
        assert!((h.derivative_at(0.0) - h.start_tangent).length() < 1e-15);
        assert!((h.derivative_at(1.0) - h.end_tangent).length() < 1e-15);
        let n = h.to_nurbs().unwrap();
        for i in 0..=20 {
            let t = i as f64 / 20.0;
            assert!(n.point_at(t).distance(h.point_at(t)) < 1e-14);
            assert!((n.derivative_at(t) - h.derivative_at(t)).length() < 1e-13);
        }
        let bad = CubicHermite::new(
            h.start,
            Vector3::new(f64::NAN, 0.0, 0.0),
            h.end,
            h.end_tangent,
        );
        assert!(bad.to_nurbs().is_err());
    }
}

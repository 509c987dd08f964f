//! Line segments.

use crate::geometry::tolerance::ZERO_TOLERANCE;
use crate::{Error, NurbsCurve, Point3, Result, Transform, Vector3};

/// The straight segment from `from` to `to`, as Rhino's `Line`.
///
/// [`Line::point_at`] takes the normalized parameter `s ∈ [0, 1]`. As a curve (Rhino's
/// `LineCurve`, and [`crate::Curve::Line`]) a line has the domain `[0, length]`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Line {
    /// The start point.
    pub from: Point3,
    /// The end point.
    pub to: Point3,
}

impl Line {
    /// The segment from `from` to `to`.
    #[inline]
    pub const fn new(from: Point3, to: Point3) -> Self {
        Self { from, to }
    }

    /// The segment from `from` along `direction` (whose length is the segment's length).
    #[inline]
    pub fn from_direction(from: Point3, direction: Vector3) -> Self {
        Self::new(from, from + direction)
    }

    /// The vector from start to end.
    #[inline]
    pub fn direction(&self) -> Vector3 {
        self.to - self.from
    }

    /// The length.
    #[inline]
    pub fn length(&self) -> f64 {
        self.direction().length()
    }

    /// The unit direction, or `None` for a segment of zero length.
    #[inline]
    pub fn unit_direction(&self) -> Option<Vector3> {
        self.direction().try_normalize()
    }

    /// Whether both ends are finite.
    #[inline]
    pub fn is_finite(&self) -> bool {
        self.from.is_finite() && self.to.is_finite()
    }

    /// The point at normalized parameter `s`: `from` at 0, `to` at 1 (`from + s (to − from)`).
    #[inline]
    pub fn point_at(&self, s: f64) -> Point3 {
        self.from.lerp(self.to, s)
    }

    /// The midpoint.
    #[inline]
    pub fn midpoint(&self) -> Point3 {
        self.from.midpoint(self.to)
    }

    /// The normalized parameter of the point of the infinite line closest to `p` (not clamped).
    /// A zero-length segment gives 0.
    pub fn closest_parameter_unbounded(&self, p: Point3) -> f64 {
        let d = self.direction();
        let len2 = d.length_squared();
        if len2 <= ZERO_TOLERANCE * ZERO_TOLERANCE {
            return 0.0;
        }
        (p - self.from).dot(d) / len2
    }

    /// The normalized parameter in `[0, 1]` of the point of the segment closest to `p`.
    pub fn closest_parameter(&self, p: Point3) -> f64 {
        self.closest_parameter_unbounded(p).clamp(0.0, 1.0)
    }

    /// The point of the segment closest to `p`.
    pub fn closest_point(&self, p: Point3) -> Point3 {
        self.point_at(self.closest_parameter(p))
    }

    /// The distance from `p` to the segment.
    pub fn distance_to(&self, p: Point3) -> f64 {
        self.closest_point(p).distance(p)
    }

    /// The same segment traced from `to` to `from`.
    #[inline]
    pub fn reversed(&self) -> Self {
        Self::new(self.to, self.from)
    }

    /// The segment with both ends mapped by `transform`.
    pub fn transformed(&self, transform: &Transform) -> Self {
        Self::new(
            transform.transform_point(self.from),
            transform.transform_point(self.to),
        )
    }

    /// The domain of the line as a curve: `[0, length]`, or `[0, 1]` for a segment of zero
    /// length (as Rhino's `LineCurve`).
    pub fn curve_domain(&self) -> crate::Interval {
        let len = self.length();
        crate::Interval::new(0.0, if len > ZERO_TOLERANCE { len } else { 1.0 })
    }

    /// The exact NURBS form: degree 1, the two end points, knots `[0, length]` (see
    /// [`Line::curve_domain`]).
    ///
    /// # Errors
    /// [`Error::NotFinite`] when an end is not finite.
    pub fn to_nurbs(&self) -> Result<NurbsCurve> {
        if !self.is_finite() {
            return Err(Error::NotFinite { what: "line" });
        }
        let d = self.curve_domain();
        NurbsCurve::new_non_rational(1, vec![self.from, self.to], vec![d.t0, d.t1])
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn evaluation_and_closest_point() {
        let l = Line::new(Point3::new(0.0, 0.0, 0.0), Point3::new(4.0, 3.0, 0.0));
        assert_eq!(l.length(), 5.0);
        assert_eq!(l.point_at(0.5), Point3::new(2.0, 1.5, 0.0));
        assert_eq!(l.closest_parameter(Point3::new(-3.0, 0.0, 0.0)), 0.0);
        assert_eq!(l.closest_parameter(Point3::new(10.0, 10.0, 0.0)), 1.0);
        let p = Point3::new(4.0, 0.0, 2.0);
        let t = l.closest_parameter(p);
        assert!((t - 16.0 / 25.0).abs() < 1e-15);
        assert!((l.closest_point(p) - p).dot(l.direction()).abs() < 1e-12);
    }

    #[test]
    fn nurbs_form_has_length_domain() {
        let l = Line::new(Point3::new(1.0, 1.0, 1.0), Point3::new(1.0, 1.0, 4.0));
        let n = l.to_nurbs().unwrap();
        assert_eq!(n.degree(), 1);
        assert_eq!(n.knots(), &[0.0, 3.0]);
        assert_eq!(n.point_at(1.5), Point3::new(1.0, 1.0, 2.5));
        let zero = Line::new(Point3::ORIGIN, Point3::ORIGIN);
        assert_eq!(zero.to_nurbs().unwrap().knots(), &[0.0, 1.0]);
        assert_eq!(zero.closest_parameter(Point3::new(1.0, 0.0, 0.0)), 0.0);
        let bad = Line::new(Point3::new(f64::NAN, 0.0, 0.0), Point3::ORIGIN);
        assert!(bad.to_nurbs().is_err());
    }
}

//! Circular arcs.

use std::f64::consts::{FRAC_PI_2, PI, TAU};

use crate::curve::circle::circumcenter;
use crate::geometry::tolerance::ZERO_TOLERANCE;
use crate::{Circle, Error, Interval, NurbsCurve, Plane, Point3, Result, Transform, Vector3};

/// A circular arc: a circle and an increasing angle interval of length in `(0, 2π]`, as Rhino's
/// `Arc`. Its parameter is the angle, so the domain is the angle interval.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Arc {
    /// The supporting circle.
    pub circle: Circle,
    /// The angles of the start and end, measured as for [`Circle::point_at`].
    pub angle: Interval,
}

impl Arc {
    /// The arc of `circle` between two angles.
    ///
    /// # Errors
    /// [`Error::NotFinite`] for non-finite angles; [`Error::InvalidInput`] when the interval is
    /// not increasing or longer than `2π`.
    pub fn new(circle: Circle, angle: Interval) -> Result<Self> {
        if !angle.is_finite() {
            return Err(Error::NotFinite { what: "arc angle" });
        }
        let len = angle.length();
        if len <= 0.0 || len > TAU + ZERO_TOLERANCE {
            return Err(Error::InvalidInput(format!(
                "arc angle {} to {} must increase by at most 2π",
                angle.t0, angle.t1
            )));
        }
        Ok(Self { circle, angle })
    }

    /// The arc from `start` through `interior` to `end` (Rhino's Arc 3Pt).
    ///
    /// # Errors
    /// [`Error::Collinear`] when the points lie on one line or two coincide.
    pub fn from_three_points(start: Point3, interior: Point3, end: Point3) -> Result<Self> {
        let (center, normal) = circumcenter(start, interior, end)?;
        let x = start - center;
        let plane = Plane::from_frame(center, x, normal.cross(x))?;
        let circle = Circle::new(plane, x.length())?;
        let mut sweep = circle.closest_parameter(end);
        if sweep <= 0.0 {
            sweep = TAU;
        }
        Self::new(circle, Interval::new(0.0, sweep))
    }

    /// The arc from `start`, leaving in direction `tangent`, to `end` (Rhino's Arc SED).
    ///
    /// # Errors
    /// [`Error::Collinear`] when the tangent points along the chord (the arc would be a line);
    /// [`Error::ZeroLength`] for a zero tangent or coincident ends.
    pub fn from_start_tangent_end(start: Point3, tangent: Vector3, end: Point3) -> Result<Self> {
        if !start.is_finite() || !tangent.is_finite() || !end.is_finite() {
            return Err(Error::NotFinite { what: "arc" });
        }
        let t = tangent
            .try_normalize()
            .ok_or(Error::ZeroLength { what: "tangent" })?;
        let chord = end - start;
        if chord.try_normalize().is_none() {
            return Err(Error::ZeroLength { what: "chord" });
        }
        // The centre lies on the normal to t at start: C = start + s n, |C − end| = s.
        let normal = t.cross(chord).try_normalize().ok_or(Error::Collinear)?;
        let n = normal.cross(t);
        let s = chord.length_squared() / (2.0 * chord.dot(n));
        let center = start + n * s;
        let x = start - center;
        let plane = Plane::from_frame(center, x, t)?;
        let circle = Circle::new(plane, x.length())?;
        let mut sweep = circle.closest_parameter(end);
        if sweep <= 0.0 {
            sweep = TAU;
        }
        Self::new(circle, Interval::new(0.0, sweep))
    }

    /// The radius.
    #[inline]
    pub fn radius(&self) -> f64 {
        self.circle.radius
    }

    /// The centre.
    #[inline]
    pub fn center(&self) -> Point3 {
        self.circle.center()
    }

    /// The swept angle, `angle.t1 − angle.t0`.
    #[inline]
    pub fn sweep(&self) -> f64 {
        self.angle.length()
    }

    /// The domain: the angle interval.
    #[inline]
    pub fn domain(&self) -> Interval {
        self.angle
    }

    /// The length `r · sweep`.
    #[inline]
    pub fn length(&self) -> f64 {
        self.radius() * self.sweep()
    }

    /// Whether the arc is a whole circle (sweep `2π` within [`ZERO_TOLERANCE`]).
    #[inline]
    pub fn is_circle(&self) -> bool {
        (self.sweep() - TAU).abs() <= ZERO_TOLERANCE
    }

    /// The point at angle `angle`.
    #[inline]
    pub fn point_at(&self, angle: f64) -> Point3 {
        self.circle.point_at(angle)
    }

    /// The start point.
    pub fn start_point(&self) -> Point3 {
        self.point_at(self.angle.t0)
    }

    /// The end point.
    pub fn end_point(&self) -> Point3 {
        self.point_at(self.angle.t1)
    }

    /// The midpoint.
    pub fn mid_point(&self) -> Point3 {
        self.point_at(self.angle.mid())
    }

    /// The angle in the domain of the point of the arc closest to `p` (an end when the closest
    /// point of the circle lies outside the arc; the nearer end, or the start on a tie).
    pub fn closest_parameter(&self, p: Point3) -> f64 {
        let a0 = self.angle.t0;
        let full = self.circle.closest_parameter(p);
        // The same direction, expressed at or after the start angle.
        let mut a = a0 + (full - a0).rem_euclid(TAU);
        if self.circle.plane.local_coordinates(p)[..2] == [0.0, 0.0] {
            a = a0;
        }
        if a <= self.angle.t1 {
            return a;
        }
        let ds = self.start_point().distance_squared(p);
        let de = self.end_point().distance_squared(p);
        if de < ds { self.angle.t1 } else { a0 }
    }

    /// The arc traced from end to start, with domain `[−t1, −t0]` as Rhino's `Reverse`.
    pub fn reversed(&self) -> Self {
        Self {
            circle: self.circle.reversed(),
            angle: Interval::new(-self.angle.t1, -self.angle.t0),
        }
    }

    /// The arc mapped by a similarity transform.
    ///
    /// # Errors
    /// As [`Circle::transformed`].
    pub fn transformed(&self, transform: &Transform) -> Result<Self> {
        Ok(Self {
            circle: self.circle.transformed(transform)?,
            angle: self.angle,
        })
    }

    /// Rhino's NURBS form of an arc: degree 2, one rational segment per quarter turn or part of
    /// one (1 segment up to π/2, 2 up to π, 3 up to 3π/2, otherwise 4), each spanning the same
    /// angle `φ` with its middle control point at distance `r/cos(φ/2)` from the centre and
    /// weight `cos(φ/2)`. The knots are the angles at the segment ends, each doubled, so the
    /// domain is the angle interval and the curve passes through the arc's points at the knots.
    pub fn to_nurbs(&self) -> NurbsCurve {
        let sweep = self.sweep();
        let segments = if sweep <= FRAC_PI_2 + ZERO_TOLERANCE {
            1
        } else if sweep <= PI + ZERO_TOLERANCE {
            2
        } else if sweep <= 1.5 * PI + ZERO_TOLERANCE {
            3
        } else {
            4
        };
        let phi = sweep / segments as f64;
        let w = (0.5 * phi).cos();
        let o = self.center();
        let mut points = Vec::with_capacity(2 * segments + 1);
        let mut weights = Vec::with_capacity(2 * segments + 1);
        let mut knots = Vec::with_capacity(2 * segments + 2);
        let a0 = self.angle.t0;
        for i in 0..segments {
            let a = a0 + i as f64 * phi;
            points.push(self.point_at(a));
            weights.push(1.0);
            let mid = self.point_at(a + 0.5 * phi);
            points.push(o + (mid - o) / w);
            weights.push(w);
            knots.push(a);
            knots.push(a);
        }
        points.push(self.end_point());
        weights.push(1.0);
        knots.push(self.angle.t1);
        knots.push(self.angle.t1);
        NurbsCurve::from_parts_unchecked(2, points, weights, knots)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rhino_arc_r5_two_radians() {
        let c = Circle::new(Plane::WORLD_XY, 5.0).unwrap();
        let arc = Arc::new(c, Interval::new(0.0, 2.0)).unwrap();
        let n = arc.to_nurbs();
        assert_eq!(n.point_count(), 5);
        assert_eq!(n.knots(), &[0.0, 0.0, 1.0, 1.0, 2.0, 2.0]);
        let expected = [
            (Point3::new(5.0, 0.0, 0.0), 1.0),
            (
                Point3::new(5.0, 2.7315124492189526, 0.0),
                0.8775825618903728,
            ),
            (Point3::new(2.701511529340699, 4.207354924039483, 0.0), 1.0),
            (
                Point3::new(0.40302305868139715, 5.683197398860012, 0.0),
                0.8775825618903728,
            ),
            (Point3::new(-2.080734182735712, 4.546487134128409, 0.0), 1.0),
        ];
        for (i, (p, w)) in expected.iter().enumerate() {
            assert!(n.points()[i].distance(*p) < 1e-14, "cv {i}");
            assert!((n.weights()[i] - w).abs() < 1e-15, "w {i}");
        }
    }

    #[test]
    fn segment_counts_and_shape() {
        let c = Circle::new(Plane::WORLD_XY, 3.0).unwrap();
        for (sweep, segments) in [
            (1.0, 1),
            (FRAC_PI_2, 1),
            (3.0, 2),
            (4.0, 3),
            (5.0, 4),
            (TAU, 4),
        ] {
            let arc = Arc::new(c, Interval::new(0.5, 0.5 + sweep)).unwrap();
            let n = arc.to_nurbs();
            assert_eq!(n.point_count(), 2 * segments + 1, "sweep {sweep}");
            assert_eq!(n.domain(), arc.domain());
            for i in 0..=30 {
                let t = arc.domain().parameter_at(i as f64 / 30.0);
                assert!((n.point_at(t).distance(arc.center()) - 3.0).abs() < 1e-12);
            }
            assert!(n.start_point().distance(arc.start_point()) < 1e-12);
            assert!(n.end_point().distance(arc.end_point()) < 1e-12);
        }
    }

    #[test]
    fn three_point_arc_and_closest_point() {
        let arc = Arc::from_three_points(
            Point3::new(1.0, 0.0, 0.0),
            Point3::new(0.0, 1.0, 0.0),
            Point3::new(-1.0, 0.0, 0.0),
        )
        .unwrap();
        assert!((arc.sweep() - PI).abs() < 1e-14);
        assert!((arc.length() - PI).abs() < 1e-14);
        assert!(arc.mid_point().distance(Point3::new(0.0, 1.0, 0.0)) < 1e-14);
        // Below the chord the closest point is an end.
        assert_eq!(arc.closest_parameter(Point3::new(0.9, -2.0, 0.0)), 0.0);
        assert_eq!(
            arc.closest_parameter(Point3::new(-0.9, -2.0, 0.0)),
            arc.angle.t1
        );
        let t = arc.closest_parameter(Point3::new(1.0, 1.0, 0.0));
        assert!((t - PI / 4.0).abs() < 1e-14);
        let sed = Arc::from_start_tangent_end(
            Point3::new(1.0, 0.0, 0.0),
            Vector3::Y,
            Point3::new(-1.0, 0.0, 0.0),
        )
        .unwrap();
        assert!(sed.center().distance(Point3::ORIGIN) < 1e-14);
        assert!(sed.mid_point().distance(Point3::new(0.0, 1.0, 0.0)) < 1e-14);
        assert!(Arc::new(arc.circle, Interval::new(1.0, 1.0)).is_err());
        assert!(Arc::new(arc.circle, Interval::new(0.0, 7.0)).is_err());
    }
}

//! Control-point curves built from points as Rhino builds them (`NurbsCurve.Create`, the
//! `Curve` command, Grasshopper's *Nurbs Curve* component).

use crate::{Error, NurbsCurve, Point3, Result};

impl NurbsCurve {
    /// The curve whose control points are `points`, with uniform knots of spacing 1, as Rhino's
    /// `NurbsCurve.Create(periodic, degree, points)`.
    ///
    /// - **Open** (`periodic = false`): clamped ends, knots `0 (×degree), 1, 2, …, n − degree
    ///   (×degree)`; the curve starts at the first point and ends at the last.
    /// - **Periodic**, degree ≥ 2: the first `degree` points are appended again, giving
    ///   `n + degree` control points, and the knots run uniformly from `1 − degree` to
    ///   `n + degree − 1`, so the domain is `0..n`. A periodic cubic through four points has seven
    ///   control points and knots −2…6. A last point equal to the first is ignored.
    /// - **Periodic**, degree 1: the closed polyline through the points and back to the first
    ///   (not periodic in Rhino's sense, as Rhino gives it).
    ///
    /// All weights are 1.
    ///
    /// # Errors
    /// [`Error::InvalidDegree`] for degree 0 or above the maximum; [`Error::TooFewPoints`] when
    /// an open curve has fewer than `degree + 1` points or a periodic curve fewer than
    /// `max(3, degree)` distinct points; [`Error::NotFinite`] for NaN or infinite points.
    pub fn create(points: &[Point3], degree: usize, periodic: bool) -> Result<Self> {
        if points.iter().any(|p| !p.is_finite()) {
            return Err(Error::NotFinite { what: "point" });
        }
        if degree == 0 {
            return Err(Error::InvalidDegree {
                degree,
                reason: "the degree must be at least 1".into(),
            });
        }
        if !periodic {
            let n = points.len();
            if n <= degree {
                return Err(Error::TooFewPoints {
                    what: "an open curve of this degree",
                    needed: degree.saturating_add(1),
                    got: n,
                });
            }
            let spans = n - degree;
            let mut knots = Vec::with_capacity(n + degree - 1);
            knots.extend(std::iter::repeat_n(0.0, degree));
            knots.extend((1..spans).map(|i| i as f64));
            knots.extend(std::iter::repeat_n(spans as f64, degree));
            return Self::new_non_rational(degree, points.to_vec(), knots);
        }
        // A repeated closing point is ignored, as in Rhino.
        let mut distinct = points;
        if distinct.len() > 1 && distinct[0] == distinct[distinct.len() - 1] {
            distinct = &distinct[..distinct.len() - 1];
        }
        let n = distinct.len();
        let needed = degree.max(3);
        if n < needed {
            return Err(Error::TooFewPoints {
                what: "a closed curve of this degree",
                needed,
                got: n,
            });
        }
        let mut cvs = distinct.to_vec();
        if degree == 1 {
            cvs.push(distinct[0]);
            let knots = (0..=n).map(|i| i as f64).collect();
            return Self::new_non_rational(1, cvs, knots);
        }
        cvs.extend_from_slice(&distinct[..degree]);
        let count = cvs.len() + degree - 1;
        let knots = (0..count)
            .map(|i| i as f64 - (degree as f64 - 1.0))
            .collect();
        Self::new_non_rational(degree, cvs, knots)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn square() -> Vec<Point3> {
        vec![
            Point3::new(0.0, 0.0, 0.0),
            Point3::new(10.0, 0.0, 0.0),
            Point3::new(10.0, 10.0, 0.0),
            Point3::new(0.0, 10.0, 0.0),
        ]
    }

    #[test]
    fn book_periodic_cubic_has_seven_points_and_knots_minus_two_to_six() {
        let c = NurbsCurve::create(&square(), 3, true).unwrap();
        assert_eq!(c.point_count(), 7);
        assert_eq!(c.knots(), &[-2.0, -1.0, 0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0]);
        assert!(c.is_periodic());
        assert!(c.is_closed());
        assert_eq!(c.domain().t0, 0.0);
        assert_eq!(c.domain().t1, 4.0);
    }

    #[test]
    fn book_open_quadratic_knots() {
        let c = NurbsCurve::create(&square(), 2, false).unwrap();
        assert_eq!(c.knots(), &[0.0, 0.0, 1.0, 2.0, 2.0]);
        assert_eq!(c.start_point(), square()[0]);
        assert_eq!(c.end_point(), square()[3]);
    }

    #[test]
    fn closing_point_is_ignored_for_periodic_curves() {
        let mut pts = square();
        pts.push(pts[0]);
        let a = NurbsCurve::create(&pts, 3, true).unwrap();
        let b = NurbsCurve::create(&square(), 3, true).unwrap();
        assert_eq!(a, b);
    }

    #[test]
    fn bad_input_is_reported() {
        assert!(matches!(
            NurbsCurve::create(&square()[..2], 2, false),
            Err(Error::TooFewPoints { .. })
        ));
        assert!(matches!(
            NurbsCurve::create(&square()[..2], 3, true),
            Err(Error::TooFewPoints { .. })
        ));
        assert!(matches!(
            NurbsCurve::create(&square(), 0, false),
            Err(Error::InvalidDegree { .. })
        ));
        assert!(matches!(
            NurbsCurve::create(&[], 1, false),
            Err(Error::TooFewPoints { .. })
        ));
        let mut pts = square();
        pts[1].x = f64::INFINITY;
        assert!(matches!(
            NurbsCurve::create(&pts, 3, false),
            Err(Error::NotFinite { .. })
        ));
    }
}

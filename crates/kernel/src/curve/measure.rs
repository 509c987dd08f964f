//! Lengths, divisions and closest points of [`Curve`] values.
//!
//! Lines, polylines, circles and arcs are measured exactly (their lengths are linear in their
//! natural parameters, piecewise for polylines); NURBS curves use the adaptive quadrature of
//! `arc_length.rs` and the global search of `curve_closest_point.rs`.

use crate::{Curve, CurveClosestPoint, Error, Point3, Result};

impl Curve {
    /// The length of the curve (NURBS curves to [`crate::geometry::tolerance::LENGTH_TOLERANCE`]).
    pub fn length(&self) -> f64 {
        match self {
            Self::Line { line, .. } => line.length(),
            Self::Polyline { polyline, .. } => polyline.length(),
            Self::Circle { circle, .. } => circle.circumference(),
            Self::Arc { arc, .. } => arc.length(),
            Self::Nurbs(c) => c.length(),
        }
    }

    /// The length between the parameters `t0` and `t1` (in either order).
    ///
    /// # Errors
    /// [`Error::NotFinite`] for NaN parameters; [`Error::InvalidInput`] for parameters outside
    /// the domain.
    pub fn length_between(&self, t0: f64, t1: f64) -> Result<f64> {
        if let Self::Nurbs(c) = self {
            return c.length_between(t0, t1);
        }
        self.check_parameter(t0)?;
        self.check_parameter(t1)?;
        let map = self.parameter_map().expect("not a nurbs curve");
        let a = self.natural_length_to(map.to_natural(t0));
        let b = self.natural_length_to(map.to_natural(t1));
        Ok((b - a).abs())
    }

    /// The parameter at arc length `length` from the start.
    ///
    /// # Errors
    /// [`Error::NotFinite`] for NaN; [`Error::InvalidInput`] for a negative length or one
    /// beyond the curve's length.
    pub fn parameter_at_length(&self, length: f64) -> Result<f64> {
        if let Self::Nurbs(c) = self {
            return c.parameter_at_length(length);
        }
        if !length.is_finite() {
            return Err(Error::NotFinite { what: "length" });
        }
        let total = self.length();
        let slack = 1e-12 * total.max(1.0);
        if length < -slack || length > total + slack {
            return Err(Error::InvalidInput(format!(
                "length {length} is outside the curve's length 0 to {total}"
            )));
        }
        let map = self.parameter_map().expect("not a nurbs curve");
        let l = length.clamp(0.0, total);
        if l == total {
            return Ok(map.domain.t1);
        }
        Ok(map.to_curve(self.natural_at_length(l)))
    }

    /// The parameters at the arc lengths `lengths`, given in increasing order, in one pass
    /// (see [`NurbsCurve::parameters_at_lengths`](crate::NurbsCurve::parameters_at_lengths)).
    ///
    /// # Errors
    /// As [`Curve::parameter_at_length`]; [`Error::InvalidInput`] for lengths that decrease.
    pub fn parameters_at_lengths(&self, lengths: &[f64]) -> Result<Vec<f64>> {
        if let Self::Nurbs(c) = self {
            return c.parameters_at_lengths(lengths);
        }
        crate::curve::arc_length::check_increasing(lengths)?;
        let total = self.length();
        let slack = 1e-12 * total.max(1.0);
        let mut walk = LengthWalk::default();
        lengths
            .iter()
            .map(|&s| {
                if !s.is_finite() {
                    return Err(Error::NotFinite { what: "length" });
                }
                if s < -slack || s > total + slack {
                    return Err(Error::InvalidInput(format!(
                        "length {s} is outside the curve's length 0 to {total}"
                    )));
                }
                let s = s.clamp(0.0, total);
                Ok(if s == total {
                    self.domain().t1
                } else {
                    self.parameter_at_increasing_length(s, total, &mut walk)
                })
            })
            .collect()
    }

    /// The parameter at the fraction `fraction ∈ [0, 1]` of the length.
    ///
    /// # Errors
    /// As [`Curve::parameter_at_length`].
    pub fn parameter_at_normalized_length(&self, fraction: f64) -> Result<f64> {
        if let Self::Nurbs(c) = self {
            return c.parameter_at_normalized_length(fraction);
        }
        self.parameter_at_length(fraction * self.length())
    }

    /// The parameters dividing the curve into `count` pieces of equal length (Grasshopper's
    /// Divide Curve): `count + 1` parameters on an open curve, `count` on a closed one.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] when `count` is 0.
    pub fn divide_by_count(&self, count: usize) -> Result<Vec<f64>> {
        if let Self::Nurbs(c) = self {
            return c.divide_by_count(count);
        }
        crate::curve::arc_length::check_division_count(count)?;
        let total = self.length();
        let d = self.domain();
        let last = if self.is_closed() { count - 1 } else { count };
        let mut walk = LengthWalk::default();
        Ok((0..=last)
            .map(|k| match k {
                0 => d.t0,
                k if k == count => d.t1,
                k => self.parameter_at_increasing_length(
                    total * k as f64 / count as f64,
                    total,
                    &mut walk,
                ),
            })
            .collect())
    }

    /// The parameters at arc lengths `0, length, 2·length, …` from the start (Grasshopper's
    /// Divide Length); the end is included only when the length divides the curve exactly, and
    /// never repeated on a closed curve.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] for a length that is not positive and finite.
    pub fn divide_by_length(&self, length: f64) -> Result<Vec<f64>> {
        if let Self::Nurbs(c) = self {
            return c.divide_by_length(length);
        }
        if !(length.is_finite() && length > 0.0) {
            return Err(Error::InvalidInput(format!(
                "division length {length} is not positive"
            )));
        }
        let total = self.length();
        let slack = 1e-9 * total;
        let count = crate::curve::arc_length::division_count(total + slack, length)?;
        let mut out = Vec::with_capacity(count + 1);
        let mut walk = LengthWalk::default();
        for k in 0..=count {
            let s = k as f64 * length;
            if k > 0 && (s - total).abs() <= slack {
                if !self.is_closed() {
                    out.push(self.domain().t1);
                }
                break;
            }
            out.push(self.parameter_at_increasing_length(s.min(total), total, &mut walk));
        }
        Ok(out)
    }

    /// The point of the curve closest to `p` over the whole domain (ends, kinks and seams
    /// included), with its parameter and distance.
    ///
    /// # Errors
    /// [`Error::NotFinite`] when `p` is not finite.
    pub fn closest_point(&self, p: Point3) -> Result<CurveClosestPoint> {
        if !p.is_finite() {
            return Err(Error::NotFinite { what: "point" });
        }
        let s = match self {
            Self::Nurbs(c) => return c.closest_point(p),
            Self::Line { line, .. } => line.closest_parameter(p),
            Self::Polyline { polyline, .. } => polyline.closest_parameter(p),
            Self::Circle { circle, .. } => circle.closest_parameter(p),
            Self::Arc { arc, .. } => arc.closest_parameter(p),
        };
        let map = self.parameter_map().expect("not a nurbs curve");
        let t = map.to_curve(s).clamp(map.domain.t0, map.domain.t1);
        let point = self.point_at(t);
        Ok(CurveClosestPoint {
            t,
            point,
            distance: point.distance(p),
        })
    }

    /// Checks that `t` is finite and inside the domain (with a relative slack of 1e-12).
    fn check_parameter(&self, t: f64) -> Result<()> {
        if !t.is_finite() {
            return Err(Error::NotFinite { what: "parameter" });
        }
        let d = self.domain();
        let slack = 1e-12 * d.t0.abs().max(d.t1.abs()).max(d.length());
        if t < d.t0 - slack || t > d.t1 + slack {
            return Err(Error::InvalidInput(format!(
                "parameter {t} is outside the domain {} to {}",
                d.t0, d.t1
            )));
        }
        Ok(())
    }

    /// As [`Curve::parameter_at_length`] for `length` in `[0, total]` (`total` the length) on a
    /// non-NURBS curve, for lengths given in increasing order: a polyline's segments are walked
    /// once for all of them (`walk` keeps the place), instead of from the start for each.
    fn parameter_at_increasing_length(
        &self,
        length: f64,
        total: f64,
        walk: &mut LengthWalk,
    ) -> f64 {
        let map = self.parameter_map().expect("not a nurbs curve");
        let l = length.clamp(0.0, total);
        if l == total {
            return map.domain.t1;
        }
        let natural = match self {
            Self::Polyline { polyline, .. } => {
                let count = polyline.segment_count();
                loop {
                    if walk.segment >= count {
                        break polyline.domain().t1;
                    }
                    let len = polyline.segment(walk.segment).length();
                    if len > 0.0 && walk.walked + len > l {
                        break walk.segment as f64 + (l - walk.walked) / len;
                    }
                    walk.walked += len;
                    walk.segment += 1;
                }
            }
            _ => self.natural_at_length(l),
        };
        map.to_curve(natural)
    }

    /// The arc length from the start of the natural parameter interval to natural parameter
    /// `s` (non-NURBS variants).
    fn natural_length_to(&self, s: f64) -> f64 {
        match self {
            Self::Line { line, .. } => s * line.length(),
            Self::Polyline { polyline, .. } => {
                let (i, f) = polyline.segment_parameter(s);
                let before: f64 = polyline.segments().take(i).map(|l| l.length()).sum();
                before + f * polyline.segment(i).length()
            }
            Self::Circle { circle, .. } => s * circle.radius,
            Self::Arc { arc, .. } => (s - arc.angle.t0) * arc.radius(),
            Self::Nurbs(_) => unreachable!("nurbs curves are measured by quadrature"),
        }
    }

    /// The natural parameter at arc length `l ∈ [0, length)` (non-NURBS variants).
    fn natural_at_length(&self, l: f64) -> f64 {
        match self {
            Self::Line { line, .. } => {
                let len = line.length();
                if len > 0.0 { l / len } else { 0.0 }
            }
            Self::Polyline { polyline, .. } => {
                let mut walked = 0.0;
                for (i, seg) in polyline.segments().enumerate() {
                    let len = seg.length();
                    if len > 0.0 && walked + len > l {
                        return i as f64 + (l - walked) / len;
                    }
                    walked += len;
                }
                polyline.domain().t1
            }
            Self::Circle { circle, .. } => l / circle.radius,
            Self::Arc { arc, .. } => arc.angle.t0 + l / arc.radius(),
            Self::Nurbs(_) => unreachable!("nurbs curves are measured by quadrature"),
        }
    }
}

/// The place of a walk along a polyline's segments: the segment reached and the length before
/// it.
#[derive(Default)]
struct LengthWalk {
    segment: usize,
    walked: f64,
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Arc, Circle, Interval, Line, Plane, Polyline};
    use std::f64::consts::{PI, TAU};

    fn polyline() -> Curve {
        Polyline::new(vec![
            Point3::new(0.0, 0.0, 0.0),
            Point3::new(3.0, 0.0, 0.0),
            Point3::new(3.0, 0.0, 0.0),
            Point3::new(3.0, 4.0, 0.0),
        ])
        .unwrap()
        .into()
    }

    #[test]
    fn parameters_at_many_lengths_equal_one_at_a_time() {
        let circle: Curve = Circle::new(Plane::WORLD_XY, 2.0).unwrap().into();
        let nurbs = Curve::Nurbs(circle.to_nurbs());
        for curve in [polyline(), circle, nurbs] {
            let total = curve.length();
            let lengths: Vec<f64> = (0..=10).map(|k| total * k as f64 / 10.0).collect();
            let many = curve.parameters_at_lengths(&lengths).unwrap();
            for (s, t) in lengths.iter().zip(&many) {
                let one = curve.parameter_at_length(*s).unwrap();
                assert!((one - t).abs() < 1e-12, "{s}: {one} vs {t}");
            }
            assert!(curve.parameters_at_lengths(&[1.0, 0.5]).is_err());
            assert!(curve.parameters_at_lengths(&[total * 2.0]).is_err());
        }
    }

    #[test]
    fn exact_lengths_and_parameters() {
        let l: Curve = Line::new(Point3::ORIGIN, Point3::new(0.0, 6.0, 8.0)).into();
        assert_eq!(l.domain(), Interval::new(0.0, 10.0));
        assert_eq!(l.length(), 10.0);
        assert!((l.parameter_at_length(2.5).unwrap() - 2.5).abs() < 1e-15);
        let p = polyline();
        assert_eq!(p.length(), 7.0);
        assert_eq!(p.parameter_at_length(3.0).unwrap(), 2.0);
        assert_eq!(p.parameter_at_length(5.0).unwrap(), 2.5);
        assert_eq!(p.length_between(0.5, 2.5).unwrap(), 3.5);
        let c: Curve = Circle::new(Plane::WORLD_XY, 2.0).unwrap().into();
        assert!((c.length() - 2.0 * TAU).abs() < 1e-15);
        assert!((c.parameter_at_length(PI).unwrap() - PI / 2.0).abs() < 1e-15);
        let a: Curve = Arc::new(
            Circle::new(Plane::WORLD_XY, 2.0).unwrap(),
            Interval::new(1.0, 3.0),
        )
        .unwrap()
        .into();
        assert!((a.length() - 4.0).abs() < 1e-15);
        assert!((a.parameter_at_length(1.0).unwrap() - 1.5).abs() < 1e-15);
        assert!(a.parameter_at_length(5.0).is_err());
        assert!(a.length_between(0.0, 2.0).is_err());
    }

    #[test]
    fn divisions_follow_grasshopper() {
        let c: Curve = Circle::new(Plane::WORLD_XY, 1.0).unwrap().into();
        assert_eq!(c.divide_by_count(6).unwrap().len(), 6);
        let p = polyline();
        let ts = p.divide_by_count(7).unwrap();
        assert_eq!(ts.len(), 8);
        assert_eq!(ts[3], 2.0);
        assert_eq!(p.divide_by_length(2.0).unwrap().len(), 4);
        assert_eq!(p.divide_by_length(3.5).unwrap(), vec![0.0, 2.125, 3.0]);
        // The walk along the segments gives what one search per length gives.
        for count in [1, 3, 7, 50] {
            let total = p.length();
            let walked = p.divide_by_count(count).unwrap();
            for (k, &t) in walked.iter().enumerate().skip(1).take(count - 1) {
                let alone = p
                    .parameter_at_length(total * k as f64 / count as f64)
                    .unwrap();
                assert_eq!(t, alone, "count {count}, point {k}");
            }
        }
    }

    #[test]
    fn exact_closest_points_with_reparameterized_domains() {
        let c: Curve = Circle::new(Plane::WORLD_XY, 1.0).unwrap().into();
        let c = c.reparameterized(Interval::new(0.0, 1.0)).unwrap();
        let r = c.closest_point(Point3::new(0.0, 5.0, 0.0)).unwrap();
        assert!((r.t - 0.25).abs() < 1e-15);
        assert!((r.distance - 4.0).abs() < 1e-15);
        let p = polyline();
        let r = p.closest_point(Point3::new(4.0, -1.0, 0.0)).unwrap();
        assert_eq!(r.t, 1.0);
        assert!(p.closest_point(Point3::new(f64::NAN, 0.0, 0.0)).is_err());
    }
}

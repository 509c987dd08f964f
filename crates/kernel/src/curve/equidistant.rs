//! Dividing a curve into points a fixed straight-line distance apart (Rhino's
//! `Curve.DivideEquidistant`, Grasshopper's Divide Distance).
//!
//! From the start, each next point is where the curve, going on from the last point, first
//! reaches the distance from it (the first crossing of the sphere of that radius about the last
//! point): the squared distance is sampled forward ([`EQUIDISTANT_SAMPLES`] per span) until it
//! exceeds the radius's square, and the crossing is found by bisection to the last bit. The
//! division stops when the rest of the curve stays within the distance.

use crate::curve::arc_length::MAX_DIVISIONS;
use crate::{Curve, Error, Result};

/// Samples per span (per polyline segment, per quarter of a circle) searched for the next
/// crossing.
pub const EQUIDISTANT_SAMPLES: usize = 32;

impl Curve {
    /// The parameters of points `distance` apart in straight lines, from the start (see the
    /// module documentation).
    ///
    /// # Errors
    /// [`Error::InvalidInput`] for a distance that is not positive and finite, or more than
    /// [`MAX_DIVISIONS`] points (the curve's length over the distance).
    pub fn divide_equidistant(&self, distance: f64) -> Result<Vec<f64>> {
        if !(distance > 0.0 && distance.is_finite()) {
            return Err(Error::InvalidInput(format!(
                "division distance {distance} is not positive"
            )));
        }
        // Each step covers at least the distance along the curve.
        let bound = self.length() / distance;
        if bound.is_nan() || bound >= MAX_DIVISIONS as f64 {
            return Err(Error::InvalidInput(format!(
                "dividing by {distance} could make more than {MAX_DIVISIONS} points"
            )));
        }
        let d = self.domain();
        let breaks: Vec<f64> = match self {
            Curve::Nurbs(c) => c.span_breaks(),
            Curve::Polyline { polyline, .. } => {
                let n = polyline.segment_count();
                (0..=n)
                    .map(|i| d.parameter_at(i as f64 / n as f64))
                    .collect()
            }
            _ => (0..=4)
                .map(|i| d.parameter_at(f64::from(i) / 4.0))
                .collect(),
        };
        let mut grid = Vec::with_capacity(breaks.len() * EQUIDISTANT_SAMPLES);
        for w in breaks.windows(2) {
            for i in 0..EQUIDISTANT_SAMPLES {
                grid.push(w[0] + (w[1] - w[0]) * i as f64 / EQUIDISTANT_SAMPLES as f64);
            }
        }
        grid.push(d.t1);
        let r2 = distance * distance;
        let mut out = vec![d.t0];
        let mut t = d.t0;
        let mut k = 0usize;
        loop {
            let centre = self.point_at(t);
            let f = |s: f64| (self.point_at(s) - centre).length_squared() - r2;
            // The first grid step after t where the curve is at least the distance away.
            let mut a = t;
            let mut found = None;
            while k < grid.len() {
                let b = grid[k];
                if b > t && f(b) >= 0.0 {
                    found = Some((a, b));
                    break;
                }
                if b > t {
                    a = b;
                }
                k += 1;
            }
            let Some((mut lo, mut hi)) = found else {
                break;
            };
            for _ in 0..200 {
                let mid = 0.5 * (lo + hi);
                if mid <= lo || mid >= hi {
                    break;
                }
                if f(mid) >= 0.0 {
                    hi = mid;
                } else {
                    lo = mid;
                }
            }
            t = hi;
            out.push(t);
            if out.len() > MAX_DIVISIONS {
                return Err(Error::InvalidInput(format!(
                    "dividing by {distance} makes more than {MAX_DIVISIONS} points"
                )));
            }
        }
        Ok(out)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Circle, Line, Plane, Point3};

    #[test]
    fn points_on_a_circle_are_chords_apart() {
        // Chords of 2 on a circle of radius 2 subtend 60°: six points, the last before the
        // seam's repeat.
        let c = Curve::from(Circle::new(Plane::WORLD_XY, 2.0).unwrap());
        let ts = c.divide_equidistant(2.0).unwrap();
        assert_eq!(ts.len(), 6);
        for w in ts.windows(2) {
            let d = c.point_at(w[0]).distance(c.point_at(w[1]));
            assert!((d - 2.0).abs() < 1e-12, "{d}");
            assert!((w[1] - w[0] - std::f64::consts::FRAC_PI_3).abs() < 1e-12);
        }
    }

    #[test]
    fn a_line_and_bad_distances() {
        let l = Curve::from(Line::new(Point3::ORIGIN, Point3::new(10.0, 0.0, 0.0)));
        let ts = l.divide_equidistant(3.0).unwrap();
        let xs: Vec<f64> = ts.iter().map(|&t| l.point_at(t).x).collect();
        assert_eq!(xs.len(), 4);
        for (x, want) in xs.iter().zip([0.0, 3.0, 6.0, 9.0]) {
            assert!((x - want).abs() < 1e-12);
        }
        assert!(l.divide_equidistant(0.0).is_err());
        assert!(l.divide_equidistant(f64::NAN).is_err());
        assert!(l.divide_equidistant(1e-9).is_err());
    }
}

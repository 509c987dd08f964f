//! Kinks of curves: the incoming tangent at a parameter, the angle between the incoming and the
//! outgoing tangent, and the interior parameters where that angle is not zero.
//!
//! [`Curve::tangent_at`] gives the outgoing tangent (from the right) at a polyline vertex or a
//! NURBS knot. The incoming one (from the left) is the tangent at the end of the part of the curve
//! before the parameter. A NURBS curve can only kink at a knot whose multiplicity reaches the
//! degree (elsewhere it is at least C¹); a polyline only at its interior vertices; lines, circles
//! and arcs never.

use crate::geometry::tolerance::ZERO_TOLERANCE;
use crate::{Curve, Error, Interval, Result, Vector3};

/// The angle between incoming and outgoing tangents above which a point counts as a kink:
/// one degree, openNURBS's default angle tolerance for `GetNextDiscontinuity` (whose cosine is
/// `ON_DEFAULT_ANGLE_TOLERANCE_COSINE`), in radians.
pub const KINK_ANGLE_TOLERANCE: f64 = std::f64::consts::PI / 180.0;

impl Curve {
    /// The unit tangent at `t` approached from below: the direction in which the curve arrives
    /// at `t`. It differs from [`Curve::tangent_at`] only at a kink. At the start of the domain,
    /// where nothing arrives, it is the outgoing tangent.
    ///
    /// # Errors
    /// [`Error::NotFinite`] for a NaN or infinite `t`.
    pub fn tangent_from_left(&self, t: f64) -> Result<Option<Vector3>> {
        if !t.is_finite() {
            return Err(Error::NotFinite { what: "parameter" });
        }
        let d = self.domain();
        if t <= d.t0 || t > d.t1 {
            return Ok(self.tangent_at(t));
        }
        match self {
            Self::Line { .. } | Self::Circle { .. } | Self::Arc { .. } => Ok(self.tangent_at(t)),
            Self::Polyline { polyline, .. } => {
                let map = self.parameter_map().expect("polyline");
                let s = map.to_natural(t);
                // Vertex i sits at natural parameter i; arriving at it uses segment i − 1.
                let i = if s == s.floor() && s >= 1.0 {
                    s as usize - 1
                } else {
                    polyline.segment_parameter(s).0
                };
                let i = i.min(polyline.segment_count() - 1);
                Ok(polyline.segment(i).unit_direction())
            }
            Self::Nurbs(c) => {
                if t == d.t1 || !self.is_break(t) {
                    // Away from knots (and at the end, which is evaluated from the left) the two
                    // sides agree.
                    return Ok(c.tangent_at(t));
                }
                let before = c.trim(Interval::new(d.t0, t))?;
                Ok(before.tangent_at(t))
            }
        }
    }

    /// The angle in radians, in `[0, π]`, between the incoming and the outgoing tangent at `t`
    /// (Grasshopper's Evaluate Curve *Angle*): zero where the curve is smooth, and at the ends
    /// of the domain. `None` where a tangent is undefined (a collapsed piece).
    ///
    /// # Errors
    /// [`Error::NotFinite`] for a NaN or infinite `t`.
    pub fn kink_angle_at(&self, t: f64) -> Result<Option<f64>> {
        Ok(self.tangent_and_kink_angle_at(t)?.1)
    }

    /// The outgoing unit tangent ([`Curve::tangent_at`]) and the kink angle
    /// ([`Curve::kink_angle_at`]) at `t`, evaluating the incoming tangent only at a polyline
    /// vertex or a NURBS knot, where the two can differ.
    ///
    /// # Errors
    /// [`Error::NotFinite`] for a NaN or infinite `t`.
    pub fn tangent_and_kink_angle_at(&self, t: f64) -> Result<(Option<Vector3>, Option<f64>)> {
        if !t.is_finite() {
            return Err(Error::NotFinite { what: "parameter" });
        }
        let outgoing = self.tangent_at(t);
        let d = self.domain();
        if t <= d.t0 || t >= d.t1 || !self.is_break(t) {
            return Ok((outgoing, outgoing.map(|_| 0.0)));
        }
        let angle = match (self.tangent_from_left(t)?, outgoing) {
            (Some(a), Some(b)) => Some(a.cross(b).length().atan2(a.dot(b))),
            _ => None,
        };
        Ok((outgoing, angle))
    }

    /// Whether `t` is a place where the curve may kink: a polyline vertex or a NURBS knot.
    fn is_break(&self, t: f64) -> bool {
        match self {
            Self::Line { .. } | Self::Circle { .. } | Self::Arc { .. } => false,
            Self::Polyline { .. } => {
                let s = self.parameter_map().expect("polyline").to_natural(t);
                s == s.floor()
            }
            Self::Nurbs(c) => c.knots().binary_search_by(|k| k.total_cmp(&t)).is_ok(),
        }
    }

    /// The parameters strictly inside the domain where the angle between the incoming and the
    /// outgoing tangent exceeds `angle_tolerance` (radians), in increasing order. Places where a
    /// tangent is undefined (a zero-length polyline segment) count as kinks.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] for a negative or NaN tolerance.
    pub fn kinks(&self, angle_tolerance: f64) -> Result<Vec<f64>> {
        if angle_tolerance.is_nan() || angle_tolerance < 0.0 {
            return Err(Error::InvalidInput(format!(
                "kink angle tolerance {angle_tolerance} is not a non-negative angle"
            )));
        }
        let d = self.domain();
        let candidates: Vec<f64> = match self {
            Self::Line { .. } | Self::Circle { .. } | Self::Arc { .. } => Vec::new(),
            Self::Polyline { polyline, .. } => {
                let map = self.parameter_map().expect("polyline");
                (1..polyline.segment_count())
                    .map(|i| map.to_curve(i as f64))
                    .collect()
            }
            Self::Nurbs(c) => {
                let p = c.degree();
                let mut out: Vec<f64> = Vec::new();
                for &k in c.knots() {
                    if k > d.t0 && k < d.t1 && out.last() != Some(&k) && c.knot_multiplicity(k) >= p
                    {
                        out.push(k);
                    }
                }
                out
            }
        };
        let mut kinks = Vec::with_capacity(candidates.len());
        for t in candidates {
            let kinked = match self.kink_angle_at(t)? {
                Some(angle) => angle > angle_tolerance,
                None => true,
            };
            if kinked {
                kinks.push(t);
            }
        }
        Ok(kinks)
    }
}

/// Whether `t` lies strictly inside `domain` by more than a relative [`ZERO_TOLERANCE`].
pub(crate) fn is_interior(domain: Interval, t: f64) -> bool {
    let slack = ZERO_TOLERANCE * domain.t0.abs().max(domain.t1.abs()).max(1.0);
    t > domain.t0 + slack && t < domain.t1 - slack
}

#[cfg(test)]
mod tests {
    use std::f64::consts::FRAC_PI_2;

    use super::*;
    use crate::{Circle, NurbsCurve, Plane, Point3, Polyline};

    fn square() -> Curve {
        Polyline::new(vec![
            Point3::new(0.0, 0.0, 0.0),
            Point3::new(2.0, 0.0, 0.0),
            Point3::new(2.0, 2.0, 0.0),
            Point3::new(3.0, 3.0, 0.0),
        ])
        .unwrap()
        .into()
    }

    #[test]
    fn polyline_vertices_are_kinks_with_their_angles() {
        let c = square();
        assert_eq!(c.kink_angle_at(1.0).unwrap(), Some(FRAC_PI_2));
        let a = c.kink_angle_at(2.0).unwrap().unwrap();
        assert!((a - FRAC_PI_2 / 2.0).abs() < 1e-15);
        assert_eq!(c.kink_angle_at(0.5).unwrap(), Some(0.0));
        assert_eq!(c.kink_angle_at(0.0).unwrap(), Some(0.0));
        assert_eq!(c.kink_angle_at(3.0).unwrap(), Some(0.0));
        assert_eq!(c.kinks(KINK_ANGLE_TOLERANCE).unwrap(), vec![1.0, 2.0]);
        let r = c.reparameterized(Interval::new(0.0, 6.0)).unwrap();
        assert_eq!(r.kinks(KINK_ANGLE_TOLERANCE).unwrap(), vec![2.0, 4.0]);
        assert_eq!(
            r.tangent_from_left(2.0).unwrap(),
            Some(Vector3::new(1.0, 0.0, 0.0))
        );
        assert_eq!(r.tangent_at(2.0), Some(Vector3::new(0.0, 1.0, 0.0)));
    }

    #[test]
    fn nurbs_kinks_only_at_full_multiplicity_knots() {
        let pts = [
            Point3::new(0.0, 0.0, 0.0),
            Point3::new(1.0, 1.0, 0.0),
            Point3::new(2.0, 0.0, 0.0),
            Point3::new(3.0, 0.0, 0.0),
            Point3::new(4.0, 2.0, 0.0),
            Point3::new(5.0, 1.0, 0.0),
            Point3::new(6.0, 0.0, 0.0),
        ];
        // The book's figure 40 (B): a fully multiple interior knot forces a kink at the third
        // control point (index 3).
        let kinked =
            NurbsCurve::new_non_rational(3, pts.to_vec(), vec![0., 0., 0., 2., 2., 2., 4., 4., 4.])
                .unwrap();
        let c: Curve = kinked.into();
        assert_eq!(c.kinks(KINK_ANGLE_TOLERANCE).unwrap(), vec![2.0]);
        let angle = c.kink_angle_at(2.0).unwrap().unwrap();
        // The curve passes through P3 = (3, 0, 0), arriving along P3 − P2 and leaving along
        // P4 − P3.
        let expected = Vector3::new(1.0, 0.0, 0.0)
            .angle_to(Vector3::new(1.0, 2.0, 0.0))
            .unwrap();
        assert!((angle - expected).abs() < 1e-12, "{angle} {expected}");
        // (A): simple knots, no kink.
        let smooth: Curve =
            NurbsCurve::new_non_rational(3, pts.to_vec(), vec![0., 0., 0., 1., 2., 3., 4., 4., 4.])
                .unwrap()
                .into();
        assert!(smooth.kinks(KINK_ANGLE_TOLERANCE).unwrap().is_empty());
        assert!(smooth.kink_angle_at(2.0).unwrap().unwrap() < 1e-12);
    }

    #[test]
    fn smooth_kinds_and_bad_input() {
        let c: Curve = Circle::new(Plane::WORLD_XY, 2.0).unwrap().into();
        assert!(c.kinks(KINK_ANGLE_TOLERANCE).unwrap().is_empty());
        assert!(c.tangent_from_left(f64::NAN).is_err());
        assert!(c.kinks(f64::NAN).is_err());
        assert!(c.kinks(-1.0).is_err());
    }

    #[test]
    fn interior_test_has_a_relative_slack() {
        let d = Interval::new(0.0, 10.0);
        assert!(is_interior(d, 5.0));
        assert!(!is_interior(d, 0.0));
        assert!(!is_interior(d, 10.0 - 1e-12));
        assert!(!is_interior(d, -1.0));
    }
}

//! Geometric continuity between the end of one curve and the start of the next, as in the
//! book's continuity tutorial (chapter 3): compare the end points (G0), then the unit tangents
//! (G1), then the curvature vectors (G2), and report the highest level reached.

use crate::Curve;
use crate::geometry::tolerance::{
    ANGLE_TOLERANCE, CURVATURE_TOLERANCE, DEFAULT_TOLERANCE, ZERO_TOLERANCE,
};

/// How smoothly one curve continues into the next. The levels are ordered:
/// `None < G0 < G1 < G2`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Continuity {
    /// The curves do not meet.
    None,
    /// Position continuous: the end of the first curve is the start of the second.
    G0,
    /// Tangent continuous: G0, and the unit tangents agree.
    G1,
    /// Curvature continuous: G1, and the curvature vectors agree.
    G2,
}

/// The tolerances of a continuity test.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ContinuityTolerances {
    /// The largest distance between the end and the start for G0 (model units).
    pub position: f64,
    /// The largest angle between the tangents for G1 (radians).
    pub angle: f64,
    /// The largest difference between the curvature vectors for G2, relative to the larger
    /// curvature; two curvatures both below [`ZERO_TOLERANCE`] count as equal.
    pub curvature: f64,
}

impl Default for ContinuityTolerances {
    /// [`DEFAULT_TOLERANCE`], [`ANGLE_TOLERANCE`] and [`CURVATURE_TOLERANCE`].
    fn default() -> Self {
        Self {
            position: DEFAULT_TOLERANCE,
            angle: ANGLE_TOLERANCE,
            curvature: CURVATURE_TOLERANCE,
        }
    }
}

/// The continuity between the end of `first` and the start of `second`, with the default
/// tolerances.
pub fn continuity(first: &Curve, second: &Curve) -> Continuity {
    continuity_with_tolerances(first, second, ContinuityTolerances::default())
}

/// The continuity between the end of `first` and the start of `second`.
///
/// Tangents and curvatures are taken at the end of the first curve's domain (from the left) and
/// at the start of the second's (from the right). Where a tangent is undefined the level stays
/// at G0.
pub fn continuity_with_tolerances(
    first: &Curve,
    second: &Curve,
    tolerances: ContinuityTolerances,
) -> Continuity {
    let t1 = first.domain().t1;
    let t0 = second.domain().t0;
    let end = first.point_at(t1);
    let start = second.point_at(t0);
    let gap = end.distance(start);
    if gap.is_nan() || gap > tolerances.position {
        return Continuity::None;
    }
    let (Some(a), Some(b)) = (first.tangent_at(t1), second.tangent_at(t0)) else {
        return Continuity::G0;
    };
    let angle = a.cross(b).length().atan2(a.dot(b));
    if angle.is_nan() || angle > tolerances.angle {
        return Continuity::G0;
    }
    let (Some(ka), Some(kb)) = (first.curvature_at(t1), second.curvature_at(t0)) else {
        return Continuity::G1;
    };
    let larger = ka.length().max(kb.length());
    if larger <= ZERO_TOLERANCE || (ka - kb).length() <= tolerances.curvature * larger {
        Continuity::G2
    } else {
        Continuity::G1
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Arc, Circle, Interval, KnotStyle, Line, NurbsCurve, Plane, Point3, Vector3};
    use std::f64::consts::PI;

    fn arc(a0: f64, a1: f64) -> Curve {
        Arc::new(
            Circle::new(Plane::WORLD_XY, 1.0).unwrap(),
            Interval::new(a0, a1),
        )
        .unwrap()
        .into()
    }

    #[test]
    fn levels() {
        // Two arcs of one circle: curvature continuous.
        assert_eq!(continuity(&arc(0.0, 1.0), &arc(1.0, 2.0)), Continuity::G2);
        // A tangent line leaving the circle: tangent but not curvature continuous.
        let tangent_line: Curve =
            Line::from_direction(Point3::new(0.0, 1.0, 0.0), Vector3::new(-2.0, 0.0, 0.0)).into();
        assert_eq!(
            continuity(&arc(0.0, PI / 2.0), &tangent_line),
            Continuity::G1
        );
        // A kink.
        let kinked: Curve =
            Line::new(Point3::new(0.0, 1.0, 0.0), Point3::new(1.0, 3.0, 0.0)).into();
        assert_eq!(continuity(&arc(0.0, PI / 2.0), &kinked), Continuity::G0);
        // A gap.
        assert_eq!(continuity(&arc(0.0, 1.0), &arc(1.1, 2.0)), Continuity::None);
        // Reversed order: the end of the line is not the start of the arc.
        assert_eq!(continuity(&tangent_line, &arc(0.0, 1.0)), Continuity::None);
        assert!(Continuity::None < Continuity::G0 && Continuity::G1 < Continuity::G2);
    }

    #[test]
    fn split_cubic_spline_is_g2_and_looser_tolerances_help() {
        let pts = [
            Point3::new(0.0, 0.0, 0.0),
            Point3::new(2.0, 3.0, 0.0),
            Point3::new(5.0, 1.0, 1.0),
            Point3::new(7.0, 4.0, 0.0),
        ];
        let c = NurbsCurve::interpolate(&pts, 3, KnotStyle::Chord).unwrap();
        let (a, b) = c.split_at(c.domain().parameter_at(0.4)).unwrap();
        assert_eq!(continuity(&a.into(), &b.into()), Continuity::G2);
        // Two lines 1e-6 rad apart are G0 by default and G2 with a 1e-5 rad tolerance.
        let l1: Curve = Line::new(Point3::ORIGIN, Point3::new(1.0, 0.0, 0.0)).into();
        let l2: Curve = Line::new(Point3::new(1.0, 0.0, 0.0), Point3::new(2.0, 1e-6, 0.0)).into();
        assert_eq!(continuity(&l1, &l2), Continuity::G0);
        let loose = ContinuityTolerances {
            angle: 1e-5,
            ..ContinuityTolerances::default()
        };
        assert_eq!(continuity_with_tolerances(&l1, &l2, loose), Continuity::G2);
    }
}

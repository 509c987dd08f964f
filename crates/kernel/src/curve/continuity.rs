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

/// How smooth a curve must be at a parameter for [`Curve::discontinuities`] to pass over it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ParametricContinuity {
    /// The first derivative is continuous (C1).
    C1,
    /// The first and second derivatives are continuous (C2).
    C2,
    /// Every derivative up to the degree is continuous (C∞ for a piecewise polynomial).
    Infinite,
}

/// The relative difference between derivatives from the left and from the right above which
/// they differ: 1e-8 of the larger.
pub const DERIVATIVE_TOLERANCE: f64 = 1e-8;

impl Curve {
    /// The parameters strictly inside the domain where the curve is less smooth than `level`
    /// (Grasshopper's Discontinuity, Rhino's `GetNextDiscontinuity` with `Cn_continuous`):
    /// polyline vertices and NURBS knots where a derivative up to the level's order differs
    /// from the left and from the right by more than [`DERIVATIVE_TOLERANCE`] of the larger.
    /// Parametric, so a joint where the direction goes on but the speed changes counts. Lines,
    /// circles and arcs have none; a closed curve's seam is not inside the domain.
    pub fn discontinuities(&self, level: ParametricContinuity) -> Vec<f64> {
        let d = self.domain();
        match self {
            Curve::Line { .. } | Curve::Circle { .. } | Curve::Arc { .. } => Vec::new(),
            Curve::Polyline { polyline, .. } => {
                let n = polyline.segment_count();
                (1..n)
                    .filter(|&i| {
                        let a = polyline.segment(i - 1).direction();
                        let b = polyline.segment(i).direction();
                        differs(a, b)
                    })
                    .map(|i| d.parameter_at(i as f64 / n as f64))
                    .collect()
            }
            Curve::Nurbs(c) => {
                let p = c.degree();
                let order = match level {
                    ParametricContinuity::C1 => 1,
                    ParametricContinuity::C2 => 2,
                    ParametricContinuity::Infinite => p,
                };
                let knots = c.knots();
                let mut out = Vec::new();
                let mut i = 0;
                while i < knots.len() {
                    let k = knots[i];
                    let m = knots[i..].iter().take_while(|&&x| x == k).count();
                    // A knot of multiplicity m leaves C^(p−m): only where that is below the
                    // order asked for can the derivatives differ. Inside the domain i ≥ p.
                    if k > d.t0 && k < d.t1 && p < order + m {
                        let right = crate::curve::nurbs::basis::span_index(p, knots, k);
                        let mut a = vec![crate::Vector3::ZERO; order + 1];
                        let mut b = vec![crate::Vector3::ZERO; order + 1];
                        c.derivatives_in_span(i - 1, k, &mut a);
                        c.derivatives_in_span(right, k, &mut b);
                        if (1..=order).any(|j| differs(a[j], b[j])) {
                            out.push(k);
                        }
                    }
                    i += m;
                }
                out
            }
        }
    }
}

/// Whether two derivative vectors differ by more than [`DERIVATIVE_TOLERANCE`] of the larger.
fn differs(a: crate::Vector3, b: crate::Vector3) -> bool {
    (a - b).length() > DERIVATIVE_TOLERANCE * a.length().max(b.length())
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

    #[test]
    fn discontinuities_of_polylines_and_joined_curves() {
        use crate::{Interval, NurbsCurve, Point3, Polyline};
        let l = Curve::from(
            Polyline::new(vec![
                Point3::new(0.0, 0.0, 0.0),
                Point3::new(1.0, 0.0, 0.0),
                Point3::new(2.0, 0.0, 0.0),
                Point3::new(2.0, 1.0, 0.0),
            ])
            .unwrap(),
        );
        // The straight vertex is smooth; the corner is not.
        assert_eq!(l.discontinuities(ParametricContinuity::C1), vec![2.0]);
        // A cubic with a double knot is C1 but not C2 there.
        let c = NurbsCurve::new_non_rational(
            3,
            vec![
                Point3::new(0.0, 0.0, 0.0),
                Point3::new(1.0, 1.0, 0.0),
                Point3::new(2.0, -1.0, 0.0),
                Point3::new(3.0, 2.0, 0.0),
                Point3::new(4.0, 0.0, 0.0),
                Point3::new(5.0, 1.0, 0.0),
            ],
            vec![0.0, 0.0, 0.0, 1.0, 1.0, 2.0, 2.0, 2.0],
        )
        .unwrap();
        let c = Curve::from(c);
        assert!(c.discontinuities(ParametricContinuity::C1).is_empty());
        assert_eq!(c.discontinuities(ParametricContinuity::C2), vec![1.0]);
        // A single span has none at any level; a line neither.
        let smooth = Curve::from(c.to_nurbs().trim(Interval::new(0.0, 0.9)).unwrap());
        assert!(
            smooth
                .discontinuities(ParametricContinuity::Infinite)
                .is_empty()
        );
    }
}

//! Joining curves end to end (Rhino's `JoinCurves`) and raising the degree of NURBS curves.
//!
//! [`Curve::join`] chains curves whose ends meet within a tolerance, greedily: a chain starts
//! from the first curve not yet used and grows at its end, then at its start, each time by the
//! unused curve whose matching end is nearest (within the tolerance), reversing it when that is
//! allowed and needed. A chain stops when it closes. Each chain becomes one curve:
//!
//! - a chain of one curve is that curve, unchanged;
//! - a chain of lines and polylines is a polyline through their vertices (the first vertex of
//!   each later piece is dropped: the earlier piece's end is kept; a closed chain ends exactly at
//!   its start);
//! - any other chain is one NURBS curve: every piece is clamped and raised to the highest degree
//!   among them ([`NurbsCurve::elevated`]), the pieces' weights are scaled so that they agree at
//!   each joint, the joint control point is the midpoint of the two ends, and the knot vectors are
//!   concatenated with a knot of full multiplicity (the degree) at each joint, so the result
//!   traces every piece in turn. Its domain starts at the first piece's and each piece keeps the
//!   length of its own domain.

use crate::curve::kinks::KINK_ANGLE_TOLERANCE;
use crate::{Curve, Error, Interval, Line, NurbsCurve, Point3, Polyline, Result};

/// One piece of a chain: the index of a curve and whether it runs backwards.
#[derive(Clone, Copy, Debug)]
struct Piece {
    index: usize,
    reversed: bool,
}

impl Curve {
    /// Joins `curves` end to end where their ends meet within `tolerance` (see the module
    /// documentation). With `preserve_direction` no curve is reversed, so only an end meeting
    /// a start joins. Closed curves are not joined to others. The result lists the chains in the
    /// order of their first curves.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] for a negative or NaN tolerance or an invalid curve; the errors
    /// of building a joined curve.
    pub fn join(curves: &[Curve], tolerance: f64, preserve_direction: bool) -> Result<Vec<Curve>> {
        if tolerance.is_nan() || tolerance < 0.0 {
            return Err(Error::InvalidInput(format!(
                "join tolerance {tolerance} is not a non-negative distance"
            )));
        }
        if let Some(i) = curves.iter().position(|c| !c.is_valid()) {
            return Err(Error::InvalidInput(format!("curve {i} is not valid")));
        }
        let ends: Vec<(Point3, Point3)> = curves
            .iter()
            .map(|c| (c.start_point(), c.end_point()))
            .collect();
        let closed: Vec<bool> = curves.iter().map(Curve::is_closed).collect();
        let mut used = vec![false; curves.len()];
        let mut out = Vec::new();
        for seed in 0..curves.len() {
            if used[seed] {
                continue;
            }
            used[seed] = true;
            let mut chain = std::collections::VecDeque::from([Piece {
                index: seed,
                reversed: false,
            }]);
            let (mut head, mut tail) = ends[seed];
            while !closed[seed] && (chain.len() <= 1 || head.distance(tail) > tolerance) {
                // Grow at the end: a start (or, reversed, an end) meeting the tail.
                let next = nearest(&ends, &used, &closed, tail, preserve_direction, true);
                if let Some((index, reversed, _)) = next.filter(|n| n.2 <= tolerance) {
                    used[index] = true;
                    chain.push_back(Piece { index, reversed });
                    tail = if reversed {
                        ends[index].0
                    } else {
                        ends[index].1
                    };
                    continue;
                }
                let prev = nearest(&ends, &used, &closed, head, preserve_direction, false);
                if let Some((index, reversed, _)) = prev.filter(|n| n.2 <= tolerance) {
                    used[index] = true;
                    chain.push_front(Piece { index, reversed });
                    head = if reversed {
                        ends[index].1
                    } else {
                        ends[index].0
                    };
                    continue;
                }
                break;
            }
            let pieces: Vec<Piece> = chain.into_iter().collect();
            let is_closed = pieces.len() > 1 && head.distance(tail) <= tolerance;
            out.push(join_chain(curves, &pieces, is_closed)?);
        }
        Ok(out)
    }
}

impl Curve {
    /// The pieces of the curve, the inverse of [`Curve::join`] (Grasshopper's *Explode*): a
    /// polyline gives its segments as lines; a NURBS curve, when `recursive`, gives its pieces
    /// between kinks (interior knots of full multiplicity where the tangent turns by more than
    /// [`KINK_ANGLE_TOLERANCE`], as a joined curve has at its joints), each on its part of the
    /// domain, a straight two-point piece as a line; without `recursive`, and for lines,
    /// circles and arcs, the curve itself. The seam of a closed curve stays an end.
    ///
    /// # Errors
    /// The errors of [`Curve::trim`] (none for valid curves).
    pub fn explode(&self, recursive: bool) -> Result<Vec<Curve>> {
        match self {
            Self::Polyline { polyline, .. } => Ok(polyline.segments().map(Curve::from).collect()),
            Self::Nurbs(_) if recursive => {
                let d = self.domain();
                let mut bounds = vec![d.t0];
                bounds.extend(self.kinks(KINK_ANGLE_TOLERANCE)?);
                bounds.push(d.t1);
                bounds
                    .windows(2)
                    .map(|w| Ok(straightened(self.trim(Interval::new(w[0], w[1]))?)))
                    .collect()
            }
            _ => Ok(vec![self.clone()]),
        }
    }
}

/// A non-rational degree-1 NURBS curve with two control points as a line on its domain; any
/// other curve unchanged.
fn straightened(curve: Curve) -> Curve {
    if let Curve::Nurbs(c) = &curve
        && c.degree() == 1
        && c.point_count() == 2
        && !c.is_rational()
    {
        return Curve::Line {
            line: Line::new(c.points()[0], c.points()[1]),
            domain: c.domain(),
        };
    }
    curve
}

/// The unused, open curve whose end nearest to `at` is the one that would attach there: when
/// `after`, a start (or an end, reversed); otherwise an end (or a start, reversed). Gives the
/// index, whether it is reversed and the distance.
fn nearest(
    ends: &[(Point3, Point3)],
    used: &[bool],
    closed: &[bool],
    at: Point3,
    preserve_direction: bool,
    after: bool,
) -> Option<(usize, bool, f64)> {
    let mut best: Option<(usize, bool, f64)> = None;
    for (i, &(start, end)) in ends.iter().enumerate() {
        if used[i] || closed[i] {
            continue;
        }
        let (forward, backward) = if after { (start, end) } else { (end, start) };
        let mut consider = |reversed: bool, p: Point3| {
            let d = at.distance(p);
            if best.is_none_or(|b| d < b.2) {
                best = Some((i, reversed, d));
            }
        };
        consider(false, forward);
        if !preserve_direction {
            consider(true, backward);
        }
    }
    best
}

impl Curve {
    /// Joins curves that already follow one another in order and direction into one curve, as
    /// [`Curve::join`] joins a chain; `closed` makes the last end exactly the first start.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] for no curves; the errors of building the joined curve.
    pub(crate) fn join_ordered(curves: &[Curve], closed: bool) -> Result<Curve> {
        if curves.is_empty() {
            return Err(Error::InvalidInput("no curves to join".into()));
        }
        let pieces: Vec<Piece> = (0..curves.len())
            .map(|index| Piece {
                index,
                reversed: false,
            })
            .collect();
        join_chain(curves, &pieces, closed)
    }
}

/// One chain as one curve (see the module documentation).
fn join_chain(curves: &[Curve], pieces: &[Piece], closed: bool) -> Result<Curve> {
    let oriented = |p: &Piece| {
        if p.reversed {
            curves[p.index].reversed()
        } else {
            curves[p.index].clone()
        }
    };
    if pieces.len() == 1 {
        return Ok(oriented(&pieces[0]));
    }
    let straight = pieces
        .iter()
        .all(|p| matches!(curves[p.index], Curve::Line { .. } | Curve::Polyline { .. }));
    if straight {
        let mut points: Vec<Point3> = Vec::new();
        for piece in pieces {
            let vertices = match oriented(piece) {
                Curve::Line { line, .. } => vec![line.from, line.to],
                Curve::Polyline { polyline, .. } => polyline.points().to_vec(),
                _ => unreachable!("only lines and polylines"),
            };
            let skip = usize::from(!points.is_empty());
            points.extend_from_slice(&vertices[skip..]);
        }
        if closed {
            let first = points[0];
            *points.last_mut().expect("points") = first;
        }
        return Ok(Polyline::new(points)?.into());
    }
    let nurbs: Vec<NurbsCurve> = pieces
        .iter()
        .map(|p| oriented(p).to_nurbs().clamped())
        .collect();
    let degree = nurbs.iter().map(NurbsCurve::degree).max().expect("pieces");
    let mut cvs: Vec<[f64; 4]> = Vec::new();
    let mut knots: Vec<f64> = Vec::new();
    for piece in &nurbs {
        let piece = piece.elevated(degree)?;
        let mut h = piece.homogeneous_points();
        let mut k = piece.knots().to_vec();
        if let Some(&last) = cvs.last() {
            // Scale the piece so that its first weight is the previous end's, then put the joint
            // at the midpoint of the two ends.
            let scale = last[3] / h[0][3];
            for q in &mut h {
                q.iter_mut().for_each(|c| *c *= scale);
            }
            let w = last[3];
            let joint: [f64; 4] =
                std::array::from_fn(|c| if c == 3 { w } else { 0.5 * (last[c] + h[0][c]) });
            *cvs.last_mut().expect("cvs") = joint;
            let shift = knots.last().expect("knots") - k[0];
            k.iter_mut().for_each(|t| *t += shift);
            cvs.extend_from_slice(&h[1..]);
            knots.extend_from_slice(&k[degree..]);
        } else {
            cvs = h;
            knots = k;
        }
    }
    if closed {
        let first = cvs[0];
        let last = cvs.last_mut().expect("cvs");
        let w = last[3];
        for c in 0..3 {
            last[c] = first[c] / first[3] * w;
        }
    }
    Ok(NurbsCurve::from_homogeneous(degree, &cvs, knots)?.into())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::curve::nurbs::basis::MAX_DEGREE;
    use crate::geometry::tolerance::DOCUMENT_TOLERANCE;
    use crate::{Arc, Circle, Interval, Line, Plane, Vector3};

    fn p(x: f64, y: f64) -> Point3 {
        Point3::new(x, y, 0.0)
    }

    fn line(a: Point3, b: Point3) -> Curve {
        Line::new(a, b).into()
    }

    #[test]
    fn elevation_keeps_the_shape() {
        let c = NurbsCurve::create(
            &[p(0.0, 0.0), p(1.0, 2.0), p(3.0, 1.0), p(4.0, 3.0)],
            2,
            false,
        )
        .unwrap();
        let arc = Arc::new(
            Circle::new(Plane::WORLD_XY, 2.0).unwrap(),
            Interval::new(0.2, 4.0),
        )
        .unwrap()
        .to_nurbs();
        for curve in [c, arc] {
            for degree in [curve.degree(), 3, 5] {
                let e = curve.elevated(degree).unwrap();
                assert_eq!(e.degree(), degree);
                assert_eq!(e.domain(), curve.domain());
                for i in 0..=40 {
                    let t = curve.domain().parameter_at(i as f64 / 40.0);
                    assert!(
                        e.point_at(t).distance(curve.point_at(t)) < 1e-12,
                        "{degree} {t}"
                    );
                }
            }
            assert!(curve.elevated(1).is_err());
            assert!(curve.elevated(MAX_DEGREE + 1).is_err());
        }
    }

    #[test]
    fn three_sides_of_a_square_and_a_reversed_fourth_close_a_polyline() {
        let curves = vec![
            line(p(0.0, 0.0), p(1.0, 0.0)),
            line(p(0.0, 1.0), p(1.0, 1.0)), // reversed to follow (1,1)
            line(p(1.0, 0.0), p(1.0, 1.0)),
            line(p(0.0, 1.0), p(0.0, 0.0)),
        ];
        let joined = Curve::join(&curves, DOCUMENT_TOLERANCE, false).unwrap();
        assert_eq!(joined.len(), 1);
        let Curve::Polyline { polyline, .. } = &joined[0] else {
            panic!("{joined:?}")
        };
        assert_eq!(
            polyline.points(),
            [
                p(0.0, 0.0),
                p(1.0, 0.0),
                p(1.0, 1.0),
                p(0.0, 1.0),
                p(0.0, 0.0)
            ]
        );
        assert!(joined[0].is_closed());
        assert!((joined[0].length() - 4.0).abs() < 1e-15);
        // Preserving directions, the second line cannot follow: the fourth, first and third
        // make one chain, the second stays alone.
        let kept = Curve::join(&curves, DOCUMENT_TOLERANCE, true).unwrap();
        assert_eq!(kept.len(), 2);
        assert_eq!(kept[0].start_point(), p(0.0, 1.0));
        assert!((kept[0].length() - 3.0).abs() < 1e-15);
        assert_eq!(kept[1], curves[1]);
    }

    #[test]
    fn gaps_beyond_the_tolerance_do_not_join() {
        let curves = vec![
            line(p(0.0, 0.0), p(1.0, 0.0)),
            line(p(1.0 + 0.0005, 0.0), p(2.0, 0.0)),
            line(p(2.01, 0.0), p(3.0, 0.0)),
        ];
        let joined = Curve::join(&curves, DOCUMENT_TOLERANCE, false).unwrap();
        assert_eq!(joined.len(), 2);
        assert!(matches!(joined[0], Curve::Polyline { .. }));
        assert!(matches!(joined[1], Curve::Line { .. }));
        assert!(Curve::join(&curves, f64::NAN, false).is_err());
        assert!(
            Curve::join(&[], DOCUMENT_TOLERANCE, false)
                .unwrap()
                .is_empty()
        );
    }

    #[test]
    fn a_line_an_arc_and_a_cubic_join_into_one_nurbs_curve() {
        // A quarter arc of radius 1 about (1, 1) from (1, 0) to (2, 1), then a cubic upwards.
        let plane = Plane::from_frame(p(1.0, 1.0), Vector3::X, Vector3::Y).unwrap();
        let arc = Arc::new(
            Circle::new(plane, 1.0).unwrap(),
            Interval::new(-std::f64::consts::FRAC_PI_2, 0.0),
        )
        .unwrap();
        let cubic = NurbsCurve::create(
            &[p(2.0, 4.0), p(2.0, 3.0), p(2.5, 2.0), p(2.0, 1.0)],
            3,
            false,
        )
        .unwrap();
        let curves = vec![
            line(p(0.0, 0.0), p(1.0, 0.0)),
            cubic.clone().into(),
            arc.into(),
        ];
        let joined = Curve::join(&curves, DOCUMENT_TOLERANCE, false).unwrap();
        assert_eq!(joined.len(), 1);
        let Curve::Nurbs(n) = &joined[0] else {
            panic!()
        };
        assert_eq!(n.degree(), 3);
        assert!(n.start_point().distance(p(0.0, 0.0)) < 1e-12);
        assert!(n.end_point().distance(p(2.0, 4.0)) < 1e-12);
        let total = 1.0 + std::f64::consts::FRAC_PI_2 + Curve::from(cubic.clone()).length();
        assert!((joined[0].length() - total).abs() < 1e-9);
        // Every piece is traced: the arc's midpoint and the cubic's midpoint lie on the result.
        let mid = p(
            1.0 + std::f64::consts::FRAC_1_SQRT_2,
            1.0 - std::f64::consts::FRAC_1_SQRT_2,
        );
        for q in [mid, cubic.point_at(cubic.domain().mid())] {
            let cp = joined[0].closest_point(q).unwrap();
            assert!(cp.point.distance(q) < 1e-9, "{q:?}");
        }
        // The joints are kinks of full multiplicity.
        assert_eq!(n.knot_multiplicity(1.0), 3);
    }

    #[test]
    fn explode_undoes_join() {
        let square = Polyline::new(vec![
            p(0.0, 0.0),
            p(1.0, 0.0),
            p(1.0, 1.0),
            p(0.0, 1.0),
            p(0.0, 0.0),
        ])
        .unwrap();
        let segments = Curve::from(square.clone()).explode(true).unwrap();
        assert_eq!(segments.len(), 4);
        assert!(segments.iter().all(|s| matches!(s, Curve::Line { .. })));
        assert_eq!(segments[2].start_point(), p(1.0, 1.0));
        // A polyline as a degree-1 NURBS curve explodes into lines only when recursive.
        let n = Curve::Nurbs(square.to_nurbs());
        assert_eq!(n.explode(false).unwrap(), vec![n.clone()]);
        let pieces = n.explode(true).unwrap();
        assert_eq!(pieces.len(), 4);
        assert!(pieces.iter().all(|s| matches!(s, Curve::Line { .. })));
        assert!((pieces[3].length() - 1.0).abs() < 1e-15);
        // The joined line, cubic and arc come apart at their joints.
        let cubic = NurbsCurve::create(
            &[p(1.0, 0.0), p(2.0, 1.0), p(3.0, -1.0), p(4.0, 0.0)],
            3,
            false,
        )
        .unwrap();
        let joined = Curve::join(
            &[line(p(0.0, 0.0), p(1.0, 0.0)), cubic.into()],
            DOCUMENT_TOLERANCE,
            false,
        )
        .unwrap();
        let pieces = joined[0].explode(true).unwrap();
        assert_eq!(pieces.len(), 2);
        assert!((pieces[0].length() - 1.0).abs() < 1e-12);
        let circle: Curve = Circle::new(Plane::WORLD_XY, 1.0).unwrap().into();
        assert_eq!(circle.explode(true).unwrap(), vec![circle.clone()]);
    }

    #[test]
    fn closed_curves_stay_alone() {
        let circle: Curve = Circle::new(Plane::WORLD_XY, 1.0).unwrap().into();
        let curves = vec![circle.clone(), line(p(1.0, 0.0), p(2.0, 0.0))];
        let joined = Curve::join(&curves, DOCUMENT_TOLERANCE, false).unwrap();
        assert_eq!(joined, curves);
    }
}

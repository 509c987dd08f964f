//! Where two curves meet (Rhino's `Intersection.CurveCurve`): points, each with its parameter on
//! both curves, and overlaps, the stretches where the curves coincide, as parameter intervals
//! on both.
//!
//! Both curves are searched in their NURBS form, span against span:
//!
//! 1. **Pruning.** Every span is a polynomial piece whose Bézier control points bound it (convex
//!    hull property). Span pairs whose control-point boxes are further apart than the tolerance
//!    cannot meet and are skipped.
//! 2. **Overlaps.** For the remaining pairs the ends of each span are projected onto the other
//!    span; where two or more of these four ends lie within the tolerance of the other curve,
//!    the stretch between the outermost of them is sampled, and if every sample lies within the
//!    tolerance the two spans overlap there. Two different polynomial pieces that agree on a
//!    stretch lie on one analytic curve, so an overlap inside a span pair always ends at an end
//!    of one of the spans: the ends found are exact. The rest of the two spans, outside the
//!    overlap, is searched for points as below.
//! 3. **Points.** Pairs of pieces are halved (de Casteljau, the larger piece first) while their
//!    boxes come within the tolerance, until both pieces are nearly straight (control points
//!    within 1/1000 of the chord from it). There Newton's method on the squared distance
//!    (`pair_newton.rs`), started from where the chords come closest and confined to the two
//!    spans, finds the closest pair of points; within the tolerance it is an intersection.
//!    Confinement to spans means one-sided derivatives at kinks and exact parameters at the
//!    ends of the curves (a T or L junction).
//! 4. **Merging.** Points within the tolerance of each other are reported once (the closest
//!    pair wins), points at the ends of or inside an overlap belong to the overlap, adjacent
//!    overlaps join, and on a closed curve a point at the seam is reported at the domain's
//!    start. A point is tangential when the curves' tangents there are parallel to within
//!    [`TANGENT_SINE`].
//!
//! Self-intersections (`curve_self.rs`) run the same search on the pieces of one curve.

use crate::intersect::pair_newton::{PairPoint, chord_estimate, closest_pair};
use crate::intersect::piece::{Piece, boxes_meet, diagonal};
use crate::{Curve, Error, Interval, NurbsCurve, Point3, Result};

/// The sine of the angle below which the tangents of two curves at a common point count as
/// parallel, making the point tangential: 1e-5 (2 seconds of arc). A tangency is located only
/// to about the square root of the rounding (1e-8 of the parameter), which tilts the tangents
/// by about that much times the curvature.
pub const TANGENT_SINE: f64 = 1e-5;

/// A piece is nearly straight when its control points lie within this fraction of its chord's
/// length from the chord.
const FLATNESS: f64 = 1e-3;

/// How many times a pair of pieces may be halved.
const MAX_DEPTH: usize = 60;

/// At most this many pairs of nearly straight pieces are polished per pair of segments; beyond
/// it the remaining pairs are polished without being halved further (a bound on the work where
/// curves run within the tolerance of each other without overlapping).
const MAX_LEAVES: usize = 4096;

/// How many intervals the stretch between two candidate points is sampled in, to tell whether
/// they are one event.
const SAME_EVENT_SAMPLES: usize = 4;

/// One point where two curves meet.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CurveCurveHit {
    /// The parameter on the first curve.
    pub t_a: f64,
    /// The parameter on the second curve.
    pub t_b: f64,
    /// The point on the first curve, `A(t_a)`.
    pub point_a: Point3,
    /// The point on the second curve, `B(t_b)`, within the tolerance of `point_a`.
    pub point_b: Point3,
    /// Whether the curves' tangents are parallel there (a tangency, or curves meeting end to
    /// end in the same direction), see [`TANGENT_SINE`].
    pub tangential: bool,
}

/// A stretch where two curves coincide (within the tolerance).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CurveOverlap {
    /// The interval on the first curve, increasing.
    pub a: Interval,
    /// The matching interval on the second curve: `b.t0` is the parameter of `A(a.t0)` and
    /// `b.t1` that of `A(a.t1)`, so it decreases where the curves run in opposite directions.
    pub b: Interval,
}

/// What two curves (or a curve and itself) have in common.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct CurveCurveIntersections {
    /// The points, in increasing order of the first parameter.
    pub points: Vec<CurveCurveHit>,
    /// The overlaps, in increasing order of the first interval; their end points are not
    /// listed in `points`.
    pub overlaps: Vec<CurveOverlap>,
}

impl Curve {
    /// Where this curve meets `other`: points within `tolerance` of both and the stretches where
    /// they coincide (see the module documentation). Parameters are each curve's own (a
    /// circle's or arc's angle mapped to its domain, as for every other query).
    ///
    /// # Errors
    /// [`Error::NotFinite`] for a tolerance that is not finite and positive,
    /// [`Error::InvalidInput`] for a curve without a valid NURBS form, [`Error::Degenerate`] for
    /// a curve collapsed to a point (all control points within `tolerance`).
    ///
    /// # Examples
    /// ```
    /// use locus_kernel::{Circle, Curve, Line, Plane, Point3};
    /// let circle: Curve = Circle::new(Plane::WORLD_XY, 1.0).unwrap().into();
    /// let line: Curve = Line::new(Point3::new(-2.0, 0.0, 0.0), Point3::new(2.0, 0.0, 0.0)).into();
    /// let x = circle.intersect_curve(&line, 1e-9).unwrap();
    /// assert_eq!(x.points.len(), 2);
    /// assert!(x.points.iter().all(|h| h.point_a.distance(h.point_b) < 1e-12));
    /// ```
    pub fn intersect_curve(&self, other: &Self, tolerance: f64) -> Result<CurveCurveIntersections> {
        check_tolerance(tolerance)?;
        let a = nurbs_form(self, tolerance)?;
        let b = nurbs_form(other, tolerance)?;
        let pieces_a = Piece::all(&a);
        let pieces_b = Piece::all(&b);
        let mut raw = Raw::default();
        for pa in &pieces_a {
            let box_a = pa.aabb();
            for pb in &pieces_b {
                if boxes_meet(&box_a, &pb.aabb(), tolerance) {
                    search_segments(pa, pb, tolerance, &mut raw);
                }
            }
        }
        let mut out = finish(&raw, Side::of(&a), Side::of(&b), false, tolerance);
        to_own_parameters(self, other, &mut out);
        Ok(out)
    }
}

/// The candidate points and overlap fragments of a search, before merging.
#[derive(Clone, Debug, Default)]
pub(crate) struct Raw {
    pub(crate) points: Vec<PairPoint>,
    pub(crate) overlaps: Vec<RawOverlap>,
}

/// An overlap fragment: `a` increasing, `b` the matching parameters.
#[derive(Clone, Copy, Debug)]
pub(crate) struct RawOverlap {
    pub(crate) a: [f64; 2],
    pub(crate) b: [f64; 2],
}

pub(crate) fn check_tolerance(tolerance: f64) -> Result<()> {
    if tolerance.is_finite() && tolerance > 0.0 {
        Ok(())
    } else {
        Err(Error::NotFinite { what: "tolerance" })
    }
}

/// The NURBS form that the searches run on, checked: valid, and not collapsed to a point
/// (all control points within `tolerance` of the first), where every piece would meet every
/// other and the search would never end.
pub(crate) fn nurbs_form(curve: &Curve, tolerance: f64) -> Result<NurbsCurve> {
    let nurbs = curve.to_nurbs();
    if !nurbs.is_valid() {
        return Err(Error::InvalidInput(
            "the curve has no valid NURBS form".into(),
        ));
    }
    let points = nurbs.points();
    if points.iter().all(|p| p.distance(points[0]) <= tolerance) {
        return Err(Error::Degenerate {
            what: "curve (all its control points coincide)",
        });
    }
    Ok(nurbs)
}

/// Searches two segments (spans, or parts of them): overlaps first, then points on what the
/// overlap leaves.
pub(crate) fn search_segments(sa: &Piece, sb: &Piece, tolerance: f64, raw: &mut Raw) {
    let Some(overlap) = segment_overlap(sa, sb, tolerance) else {
        let mut leaves = 0;
        descend(sa, sb, *sa, *sb, tolerance, 0, &mut leaves, raw);
        return;
    };
    raw.overlaps.push(overlap);
    // The parts of each segment before, inside and after the overlap; every pair but the
    // two overlapping parts is searched for points.
    let parts = |p: &Piece, [x0, x1]: [f64; 2]| -> [Option<Piece>; 3] {
        let (lo, hi) = (x0.min(x1), x0.max(x1));
        let part = |t0: f64, t1: f64| (t1 > t0).then(|| p.sub(t0, t1));
        [part(p.a, lo), part(lo, hi), part(hi, p.b)]
    };
    let pa = parts(sa, overlap.a);
    let pb = parts(sb, overlap.b);
    for (i, x) in pa.iter().enumerate() {
        for (j, y) in pb.iter().enumerate() {
            if let (Some(x), Some(y), false) = (x, y, i == 1 && j == 1) {
                let mut leaves = 0;
                descend(sa, sb, *x, *y, tolerance, 0, &mut leaves, raw);
            }
        }
    }
}

/// Halves `pa` and `pb` (parts of the segments `sa` and `sb`) while their boxes meet, and
/// polishes the nearly straight pairs (see the module documentation).
#[allow(
    clippy::too_many_arguments,
    reason = "a recursion over one search's state"
)]
fn descend(
    sa: &Piece,
    sb: &Piece,
    pa: Piece,
    pb: Piece,
    tolerance: f64,
    depth: usize,
    leaves: &mut usize,
    raw: &mut Raw,
) {
    let (box_a, box_b) = (pa.aabb(), pb.aabb());
    if !boxes_meet(&box_a, &box_b, tolerance) {
        return;
    }
    let flat_a = pa.is_flat(FLATNESS, 0.25 * tolerance);
    let flat_b = pb.is_flat(FLATNESS, 0.25 * tolerance);
    if (flat_a && flat_b) || depth >= MAX_DEPTH || *leaves >= MAX_LEAVES {
        *leaves += 1;
        let (s0, t0) = chord_estimate(&pa, &pb);
        let found = closest_pair(sa, [sa.a, sa.b], sb, [sb.a, sb.b], s0, t0);
        if found.distance <= tolerance {
            raw.points.push(found);
        }
        return;
    }
    let split_a = !flat_a && (flat_b || diagonal(&box_a) >= diagonal(&box_b));
    if split_a {
        let (l, r) = pa.halve();
        descend(sa, sb, l, pb, tolerance, depth + 1, leaves, raw);
        descend(sa, sb, r, pb, tolerance, depth + 1, leaves, raw);
    } else {
        let (l, r) = pb.halve();
        descend(sa, sb, pa, l, tolerance, depth + 1, leaves, raw);
        descend(sa, sb, pa, r, tolerance, depth + 1, leaves, raw);
    }
}

/// Where two segments coincide, if they do along a stretch (see the module documentation).
pub(crate) fn segment_overlap(a: &Piece, b: &Piece, tolerance: f64) -> Option<RawOverlap> {
    let mut ends: Vec<(f64, f64)> = Vec::with_capacity(4);
    for (s, p) in [(a.a, a.start()), (a.b, a.end())] {
        let (t, d) = b.closest(p);
        if d <= tolerance {
            ends.push((s, t));
        }
    }
    for (t, q) in [(b.a, b.start()), (b.b, b.end())] {
        let (s, d) = a.closest(q);
        if d <= tolerance {
            ends.push((s, t));
        }
    }
    if ends.len() < 2 {
        return None;
    }
    ends.sort_by(|x, y| x.0.total_cmp(&y.0));
    let (lo, hi) = (ends[0], ends[ends.len() - 1]);
    if a.point_at(lo.0).distance(a.point_at(hi.0)) <= tolerance {
        return None;
    }
    let n = 2 * (a.len() + b.len()) + 1;
    for k in 1..n {
        let s = lo.0 + (hi.0 - lo.0) * k as f64 / n as f64;
        if b.closest(a.point_at(s)).1 > tolerance {
            return None;
        }
    }
    Some(RawOverlap {
        a: [lo.0, hi.0],
        b: [lo.1, hi.1],
    })
}

/// What the merging needs to know of a curve.
#[derive(Clone, Debug)]
pub(crate) struct Side<'a> {
    pub(crate) curve: &'a NurbsCurve,
    pub(crate) domain: Interval,
    pub(crate) closed: bool,
}

impl<'a> Side<'a> {
    pub(crate) fn of(curve: &'a NurbsCurve) -> Self {
        Self {
            curve,
            domain: curve.domain(),
            closed: curve.is_closed(),
        }
    }
}

/// Merges what the search found (see the module documentation); `same_curve` when `a` and `b`
/// are one curve (a search for self-intersections).
pub(crate) fn finish(
    raw: &Raw,
    a: Side<'_>,
    b: Side<'_>,
    same_curve: bool,
    tolerance: f64,
) -> CurveCurveIntersections {
    // Overlaps: sorted, adjacent fragments joined where both curves run on continuously.
    let mut fragments = raw.overlaps.clone();
    fragments.sort_by(|x, y| x.a[0].total_cmp(&y.a[0]));
    let b_step = 1e-9 * b.domain.length().abs().max(f64::MIN_POSITIVE);
    let mut overlaps: Vec<RawOverlap> = Vec::with_capacity(fragments.len());
    for f in fragments {
        if let Some(last) = overlaps.last_mut() {
            let joins_a = f.a[0] <= last.a[1]
                || a.curve
                    .point_at(last.a[1])
                    .distance(a.curve.point_at(f.a[0]))
                    <= tolerance;
            let jump = (f.b[0] - last.b[1]).abs();
            let across_seam = b.closed && jump >= 0.5 * b.domain.length().abs();
            let joins_b = jump <= b_step
                || (!across_seam
                    && b.curve
                        .point_at(last.b[1])
                        .distance(b.curve.point_at(f.b[0]))
                        <= tolerance);
            if joins_a && joins_b {
                if f.a[1] > last.a[1] {
                    last.a[1] = f.a[1];
                    last.b[1] = f.b[1];
                }
                continue;
            }
        }
        overlaps.push(f);
    }
    let overlap_ends: Vec<[Point3; 2]> = overlaps
        .iter()
        .map(|o| [a.curve.point_at(o.a[0]), a.curve.point_at(o.a[1])])
        .collect();
    let in_overlap = |p: &PairPoint| {
        overlaps.iter().zip(&overlap_ends).any(|(o, ends)| {
            (p.s >= o.a[0] && p.s <= o.a[1]) || ends.iter().any(|e| e.distance(p.a) <= tolerance)
        })
    };
    // Points: clustered within the tolerance, the closest pair of each cluster kept.
    let mut candidates: Vec<PairPoint> = raw
        .points
        .iter()
        .filter(|p| !in_overlap(p))
        .copied()
        .collect();
    candidates.sort_by(|x, y| x.s.total_cmp(&y.s).then(x.t.total_cmp(&y.t)));
    let mut kept: Vec<PairPoint> = Vec::with_capacity(candidates.len());
    for c in candidates {
        match kept
            .iter_mut()
            .find(|k| same_event(k, &c, a.curve, b.curve, same_curve, tolerance))
        {
            Some(k) => {
                if c.distance < k.distance {
                    *k = c;
                }
            }
            None => kept.push(c),
        }
    }
    let mut points: Vec<CurveCurveHit> = kept
        .into_iter()
        .map(|p| {
            let mut t_a = p.s;
            let mut t_b = p.t;
            if a.closed && t_a == a.domain.t1 {
                t_a = a.domain.t0;
            }
            if b.closed && t_b == b.domain.t1 {
                t_b = b.domain.t0;
            }
            CurveCurveHit {
                t_a,
                t_b,
                point_a: p.a,
                point_b: p.b,
                tangential: tangential(a.curve, p.s, b.curve, p.t),
            }
        })
        .collect();
    points.sort_by(|x, y| x.t_a.total_cmp(&y.t_a).then(x.t_b.total_cmp(&y.t_b)));
    CurveCurveIntersections {
        points,
        overlaps: overlaps
            .into_iter()
            .map(|o| CurveOverlap {
                a: Interval::new(o.a[0], o.a[1]),
                b: Interval::new(o.b[0], o.b[1]),
            })
            .collect(),
    }
}

/// Whether two candidate points are one event: their points lie within the tolerance of each
/// other, or the curves stay within the tolerance of each other between them (a tangency,
/// where the candidates spread along the stretch on which the curves are that close). On one
/// curve the second test needs the two stretches to be apart, or it would find the stretch
/// itself.
fn same_event(
    x: &PairPoint,
    y: &PairPoint,
    a: &NurbsCurve,
    b: &NurbsCurve,
    same_curve: bool,
    tolerance: f64,
) -> bool {
    if x.a.distance(y.a) <= tolerance && x.b.distance(y.b) <= tolerance {
        return true;
    }
    let (t0, t1) = (x.t.min(y.t), x.t.max(y.t));
    let (s0, s1) = (x.s.min(y.s), x.s.max(y.s));
    if same_curve && s1 >= t0 && t1 >= s0 {
        return false;
    }
    (1..SAME_EVENT_SAMPLES).all(|k| {
        let f = k as f64 / SAME_EVENT_SAMPLES as f64;
        let p = a.point_at(x.s + f * (y.s - x.s));
        b.closest_point_between(p, t0, t1).distance <= tolerance
    })
}

/// Whether the tangents of `a` at `s` and `b` at `t` are parallel (see [`TANGENT_SINE`]).
pub(crate) fn tangential(a: &NurbsCurve, s: f64, b: &NurbsCurve, t: f64) -> bool {
    let (da, db) = (a.derivative_at(s), b.derivative_at(t));
    let (la, lb) = (da.length(), db.length());
    if !(la > 0.0 && lb > 0.0) {
        return false;
    }
    da.cross(db).length() <= TANGENT_SINE * la * lb
}

/// Maps parameters of the NURBS forms to the curves' own: they are equal for lines,
/// polylines and NURBS curves; a circle's or arc's angle is found from the point.
fn to_own_parameters(a: &Curve, b: &Curve, out: &mut CurveCurveIntersections) {
    let own = |curve: &Curve, t: f64, p: Point3| -> f64 {
        if !matches!(curve, Curve::Circle { .. } | Curve::Arc { .. }) {
            return t;
        }
        let d = curve.domain();
        if t == d.t0 || t == d.t1 {
            return t;
        }
        curve.closest_point(p).map_or(t, |c| c.t)
    };
    for hit in &mut out.points {
        hit.t_a = own(a, hit.t_a, hit.point_a);
        hit.t_b = own(b, hit.t_b, hit.point_b);
    }
    for o in &mut out.overlaps {
        let (pa0, pa1) = (a.point_at(o.a.t0), a.point_at(o.a.t1));
        o.a = Interval::new(own(a, o.a.t0, pa0), own(a, o.a.t1, pa1));
        o.b = Interval::new(own(b, o.b.t0, pa0), own(b, o.b.t1, pa1));
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Arc, Circle, Line, Plane, Polyline, Vector3};

    fn p(x: f64, y: f64, z: f64) -> Point3 {
        Point3::new(x, y, z)
    }

    #[test]
    fn a_curve_collapsed_to_a_point_is_an_error_not_an_endless_search() {
        let p = Point3::new(1.0, 2.0, 3.0);
        let c: Curve =
            NurbsCurve::new_non_rational(3, vec![p; 4], vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0])
                .unwrap()
                .into();
        let line: Curve = Line::new(Point3::new(0.0, 0.0, 0.0), Point3::new(2.0, 4.0, 6.0)).into();
        assert!(matches!(
            c.self_intersections(1e-9),
            Err(Error::Degenerate { .. })
        ));
        assert!(matches!(
            c.intersect_curve(&line, 1e-9),
            Err(Error::Degenerate { .. })
        ));
        assert!(matches!(
            line.intersect_curve(&c, 1e-9),
            Err(Error::Degenerate { .. })
        ));
    }

    #[test]
    fn two_circles_cross_twice_and_touch_once() {
        let a: Curve = Circle::new(Plane::WORLD_XY, 2.0).unwrap().into();
        let b: Curve = Circle::new(Plane::WORLD_XY.translated(Vector3::new(3.0, 0.0, 0.0)), 2.0)
            .unwrap()
            .into();
        let x = a.intersect_curve(&b, 1e-9).unwrap();
        assert_eq!(x.points.len(), 2, "{x:?}");
        for h in &x.points {
            assert!((h.point_a.x - 1.5).abs() < 1e-12, "{h:?}");
            assert!(a.point_at(h.t_a).distance(h.point_a) < 1e-12);
            assert!(b.point_at(h.t_b).distance(h.point_b) < 1e-12);
            assert!(!h.tangential);
        }
        let c: Curve = Circle::new(Plane::WORLD_XY.translated(Vector3::new(3.0, 0.0, 0.0)), 1.0)
            .unwrap()
            .into();
        let x = a.intersect_curve(&c, 1e-9).unwrap();
        assert_eq!(x.points.len(), 1, "{x:?}");
        assert!(x.points[0].tangential);
        assert!(x.points[0].point_a.distance(p(2.0, 0.0, 0.0)) < 1e-7);
    }

    #[test]
    fn arcs_of_one_circle_overlap() {
        let circle = Circle::new(Plane::WORLD_XY, 1.0).unwrap();
        let a: Curve = Arc::new(circle, Interval::new(0.0, 2.0)).unwrap().into();
        let b: Curve = Arc::new(circle, Interval::new(1.0, 3.0)).unwrap().into();
        let x = a.intersect_curve(&b, 1e-9).unwrap();
        assert!(x.points.is_empty(), "{x:?}");
        assert_eq!(x.overlaps.len(), 1, "{x:?}");
        let o = x.overlaps[0];
        assert!(
            (o.a.t0 - 1.0).abs() < 1e-12 && (o.a.t1 - 2.0).abs() < 1e-12,
            "{o:?}"
        );
        assert!(
            (o.b.t0 - 1.0).abs() < 1e-12 && (o.b.t1 - 2.0).abs() < 1e-12,
            "{o:?}"
        );
    }

    #[test]
    fn reversed_collinear_segments_overlap_decreasingly() {
        let a: Curve = Line::new(p(0.0, 0.0, 0.0), p(4.0, 0.0, 0.0)).into();
        let b: Curve = Line::new(p(6.0, 0.0, 0.0), p(2.0, 0.0, 0.0)).into();
        let x = a.intersect_curve(&b, 1e-9).unwrap();
        assert!(x.points.is_empty(), "{x:?}");
        assert_eq!(x.overlaps.len(), 1);
        let o = x.overlaps[0];
        assert_eq!((o.a.t0, o.a.t1), (2.0, 4.0));
        assert_eq!((o.b.t0, o.b.t1), (4.0, 2.0));
    }

    #[test]
    fn polylines_meet_at_vertices_and_ends() {
        let a: Curve = Polyline::new(vec![p(0.0, 0.0, 0.0), p(1.0, 1.0, 0.0), p(2.0, 0.0, 0.0)])
            .unwrap()
            .into();
        // Through the vertex, and an L junction at a's end.
        let b: Curve = Polyline::new(vec![p(1.0, 2.0, 0.0), p(1.0, 0.5, 0.0), p(2.0, 0.0, 0.0)])
            .unwrap()
            .into();
        let x = a.intersect_curve(&b, 1e-9).unwrap();
        assert_eq!(x.points.len(), 2, "{x:?}");
        assert!(
            (x.points[0].t_a - 1.0).abs() < 1e-15 && (x.points[0].t_b - 2.0 / 3.0).abs() < 1e-15
        );
        assert_eq!((x.points[1].t_a, x.points[1].t_b), (2.0, 2.0));
    }

    #[test]
    fn skew_and_parallel_lines_do_not_meet() {
        let a: Curve = Line::new(p(0.0, 0.0, 0.0), p(1.0, 0.0, 0.0)).into();
        let b: Curve = Line::new(p(0.5, -1.0, 1e-6), p(0.5, 1.0, 1e-6)).into();
        assert!(a.intersect_curve(&b, 1e-7).unwrap().points.is_empty());
        assert_eq!(a.intersect_curve(&b, 1e-5).unwrap().points.len(), 1);
        let c: Curve = Line::new(p(0.0, 1.0, 0.0), p(1.0, 1.0, 0.0)).into();
        let x = a.intersect_curve(&c, 1e-9).unwrap();
        assert!(x.points.is_empty() && x.overlaps.is_empty());
    }

    #[test]
    fn bad_tolerances_are_errors() {
        let a: Curve = Line::new(p(0.0, 0.0, 0.0), p(1.0, 0.0, 0.0)).into();
        assert!(a.intersect_curve(&a, 0.0).is_err());
        assert!(a.intersect_curve(&a, f64::NAN).is_err());
    }
}

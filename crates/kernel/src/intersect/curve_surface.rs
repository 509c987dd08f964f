//! Where a curve meets a surface (Rhino's `Intersection.CurveSurface`, Grasshopper's
//! Surface | Curve and Surface | Line): points, each with its curve parameter and surface
//! parameters, and overlaps, the curve intervals that lie in the surface.
//!
//! The curve and the surface are searched in their NURBS forms, span against patch:
//!
//! 1. **Pruning and subdivision.** Every curve span is a polynomial piece (`piece.rs`) and every
//!    knot rectangle of the surface a polynomial patch (`patch.rs`), each inside the box of its
//!    Bézier control points. Pairs whose boxes are further apart than the tolerance cannot
//!    meet; the others are halved (the larger first; a patch across the direction in which its
//!    net bends more) until the piece is nearly straight and the patch nearly flat.
//! 2. **Newton.** There Gauss–Newton on `½|C(t) − S(u, v)|²` (`surface_newton.rs`), started
//!    where the piece's chord meets the patch's corner plane and confined to the whole span and
//!    patch, finds the closest pair of points; within the tolerance it is a candidate.
//!    Confinement gives exact parameters on the surface's edges, at its corners, on creases and
//!    at the curve's ends, and one-sided derivatives at kinks.
//! 3. **Events.** Candidates are ordered along the curve; neighbours whose points lie within the
//!    tolerance of each other, or between which the curve stays within the tolerance of the
//!    surface, are one event (a crossing found from several patches, across a seam, or the
//!    spread of a tangency). An event whose ends lie further apart than the tolerance is an
//!    overlap, and so is a touching event from which the curve runs on in the surface.
//! 4. **Overlaps** are extended along the curve up to the next *break*: the curve's ends, its
//!    knots, and the points where it meets the surface's boundary curves (its four edges, or a
//!    B-rep face's edges; `curve_curve.rs`), as long as the curve stays in the surface up to it
//!    (sampled). A curve lying in a surface leaves it only at such a break unless it leaves the
//!    analytic continuation of a patch; there the end is found by bisection to the tolerance.
//!    Points inside or at the ends of an overlap belong to it.
//!
//! A point is tangential when the curve's tangent lies in the surface's tangent plane to within
//! [`TANGENT_SINE`]. B-reps (`brep_curve.rs`) run the same search on every face and keep what
//! lies inside the face's trims.

use crate::intersect::curve_curve::{TANGENT_SINE, check_tolerance, nurbs_form};
use crate::intersect::patch::{Patch, Slab};
use crate::intersect::piece::{Aabb, Piece, boxes_meet, diagonal};
use crate::intersect::surface_newton::{CurveSurfacePoint, closest_curve_surface, flat_estimate};
use crate::surface::direction::SurfaceDirection;
use crate::{BoundingBox, Curve, Error, Interval, Line, NurbsCurve, NurbsSurface, Point3, Result};

/// A piece is nearly straight, and a patch nearly flat, when its control points lie within this
/// fraction of its size from its chord (its corners' bilinear patch).
const FLATNESS: f64 = 1e-3;
/// How many times a pair may be halved.
const MAX_DEPTH: usize = 60;
/// At most this many leaves are polished per span and patch (a bound on the work where a
/// curve runs within the tolerance of a surface without lying in it).
const MAX_LEAVES: usize = 2048;
/// How many times steeper than the bends of a flat piece and a flat patch the piece must cross
/// the patch's plane for the pair to meet at most once (a bend of depth `d` over a width `w`
/// reaches slopes of a few `d / w`).
const UNIQUE_CROSSING_SLOPE: f64 = 8.0;
/// Samples between two candidates, or along a stretch, to tell whether the curve stays in the
/// surface there.
const STRETCH_SAMPLES: usize = 8;
/// Bisection steps for an overlap end that is not at a break.
const BISECTIONS: usize = 60;
/// Past a break, the fraction of the way to the next one at which a curve that still lies on
/// the target is taken to run on beyond the break.
const PROBE: f64 = 0.01;

/// One point where a curve meets a surface.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CurveSurfaceHit {
    /// The curve parameter.
    pub t: f64,
    /// The surface parameter `u`.
    pub u: f64,
    /// The surface parameter `v`.
    pub v: f64,
    /// The point on the curve, `C(t)`; `S(u, v)` lies within the tolerance of it.
    pub point: Point3,
    /// Whether the curve touches the surface there (its tangent lies in the tangent plane, see
    /// [`TANGENT_SINE`]).
    pub tangential: bool,
}

/// A stretch of the curve that lies in the surface (within the tolerance).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CurveSurfaceOverlap {
    /// The curve interval, increasing.
    pub t: Interval,
}

/// What a curve has in common with a surface.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct CurveSurfaceIntersections {
    /// The points, in increasing order of the curve parameter.
    pub points: Vec<CurveSurfaceHit>,
    /// The overlaps, in increasing order; their end points are not listed in `points`.
    pub overlaps: Vec<CurveSurfaceOverlap>,
}

impl NurbsSurface {
    /// Where `curve` meets the surface: points within `tolerance` of both and the stretches of
    /// the curve lying in the surface (see the module documentation). Curve parameters are the
    /// curve's own (a circle's or arc's angle mapped to its domain).
    ///
    /// # Errors
    /// [`Error::NotFinite`] for a tolerance that is not finite and positive or a surface that is
    /// not finite, [`Error::InvalidInput`] for a curve or surface that is not valid,
    /// [`Error::Degenerate`] for a curve collapsed to a point.
    ///
    /// # Examples
    /// ```
    /// use locus_kernel::{Curve, Line, Point3, Sphere};
    /// let sphere = Sphere::new(Point3::new(0.0, 0.0, 0.0), 2.0).unwrap().to_nurbs().unwrap();
    /// let line: Curve = Line::new(Point3::new(0.0, 0.0, -3.0), Point3::new(0.0, 0.0, 3.0)).into();
    /// let x = sphere.intersect_curve(&line, 1e-9).unwrap();
    /// assert_eq!(x.points.len(), 2);
    /// assert!((x.points[0].point.z + 2.0).abs() < 1e-12);
    /// ```
    pub fn intersect_curve(
        &self,
        curve: &Curve,
        tolerance: f64,
    ) -> Result<CurveSurfaceIntersections> {
        check_tolerance(tolerance)?;
        check_surface(self)?;
        let nurbs = nurbs_form(curve, tolerance)?;
        let target = SurfaceTarget {
            surface: self,
            tolerance,
        };
        let raw = raw_points(&nurbs, self, tolerance);
        let (points, overlaps) = events(&nurbs, &target, raw, tolerance);
        let mut out = CurveSurfaceIntersections {
            points: points
                .into_iter()
                .map(|(p, tangential)| CurveSurfaceHit {
                    t: p.t,
                    u: p.u,
                    v: p.v,
                    point: p.on_curve,
                    tangential,
                })
                .collect(),
            overlaps: overlaps
                .into_iter()
                .map(|[t0, t1]| CurveSurfaceOverlap {
                    t: Interval::new(t0, t1),
                })
                .collect(),
        };
        to_own_parameters(curve, &mut out.points, &mut out.overlaps);
        Ok(out)
    }

    /// Where the infinite `line` meets the surface; parameters are the line's
    /// (`line.point_at(t)`, 0 at `from` and 1 at `to`).
    ///
    /// # Errors
    /// As [`NurbsSurface::intersect_curve`], and [`Error::ZeroLength`] for a line of no length.
    pub fn intersect_line(&self, line: &Line, tolerance: f64) -> Result<CurveSurfaceIntersections> {
        check_tolerance(tolerance)?;
        check_surface(self)?;
        match clipped_line(line, &self.bounding_box(), tolerance)? {
            Some(segment) => self.intersect_curve(&segment, tolerance),
            None => Ok(CurveSurfaceIntersections::default()),
        }
    }
}

/// The surface checked for the searches: finite and valid.
pub(crate) fn check_surface(surface: &NurbsSurface) -> Result<()> {
    if !surface.is_finite() {
        return Err(Error::NotFinite { what: "surface" });
    }
    if !surface.is_valid() {
        return Err(Error::InvalidInput("the surface is not valid".into()));
    }
    Ok(())
}

/// The part of the infinite `line` inside `bbox` grown by the tolerance (and a little more), as a
/// curve whose parameters are the line's; `None` when the line misses the box.
pub(crate) fn clipped_line(
    line: &Line,
    bbox: &BoundingBox,
    tolerance: f64,
) -> Result<Option<Curve>> {
    if !line.is_finite() {
        return Err(Error::NotFinite { what: "line" });
    }
    let direction = line.to - line.from;
    if direction.length_squared() == 0.0 {
        return Err(Error::ZeroLength { what: "line" });
    }
    let (lo, hi) = (bbox.min.to_array(), bbox.max.to_array());
    let size = (bbox.max - bbox.min).length();
    let grow = 2.0 * tolerance + 1e-9 * size.max(1.0);
    let (from, d) = (line.from.to_array(), direction.to_array());
    let (mut t0, mut t1) = (f64::NEG_INFINITY, f64::INFINITY);
    for k in 0..3 {
        let (a, b) = (lo[k] - grow, hi[k] + grow);
        if d[k] == 0.0 {
            if from[k] < a || from[k] > b {
                return Ok(None);
            }
        } else {
            let (s0, s1) = ((a - from[k]) / d[k], (b - from[k]) / d[k]);
            t0 = t0.max(s0.min(s1));
            t1 = t1.min(s0.max(s1));
        }
    }
    if t0.is_nan() || t1.is_nan() || t0 >= t1 {
        return Ok(None);
    }
    Ok(Some(Curve::Line {
        line: Line::new(line.point_at(t0), line.point_at(t1)),
        domain: Interval::new(t0, t1),
    }))
}

/// Where the searches may keep a point, and where an overlap may end: a whole surface, or a
/// B-rep face inside its trims.
pub(crate) trait Target {
    /// Whether `p` lies on the target within the tolerance (`uv`, when known, its surface
    /// parameters).
    fn contains(&self, p: Point3, uv: Option<(f64, f64)>) -> bool;
    /// The curves bounding the target, where overlaps end.
    fn boundary(&self) -> Vec<NurbsCurve>;
    /// The target's surface.
    fn surface(&self) -> &NurbsSurface;
}

/// A whole surface.
#[derive(Debug)]
struct SurfaceTarget<'a> {
    surface: &'a NurbsSurface,
    tolerance: f64,
}

impl Target for SurfaceTarget<'_> {
    fn contains(&self, p: Point3, uv: Option<(f64, f64)>) -> bool {
        if uv.is_some() {
            return true;
        }
        self.surface
            .closest_point(p)
            .is_ok_and(|c| c.distance <= self.tolerance)
    }

    fn boundary(&self) -> Vec<NurbsCurve> {
        surface_edges(self.surface)
    }

    fn surface(&self) -> &NurbsSurface {
        self.surface
    }
}

/// The four boundary isocurves of a surface.
pub(crate) fn surface_edges(surface: &NurbsSurface) -> Vec<NurbsCurve> {
    let (du, dv) = (surface.domain_u(), surface.domain_v());
    [
        (SurfaceDirection::U, dv.t0),
        (SurfaceDirection::U, dv.t1),
        (SurfaceDirection::V, du.t0),
        (SurfaceDirection::V, du.t1),
    ]
    .into_iter()
    .filter_map(|(direction, c)| surface.isocurve(direction, c).ok())
    .collect()
}

/// Every candidate of the search of `curve` against `surface` (steps 1 and 2 of the module
/// documentation), unsorted.
pub(crate) fn raw_points(
    curve: &NurbsCurve,
    surface: &NurbsSurface,
    tolerance: f64,
) -> Vec<CurveSurfacePoint> {
    let pieces = Piece::all(curve);
    let patches = Patch::all(surface);
    let patch_boxes: Vec<_> = patches.iter().map(Patch::aabb).collect();
    let mut out = Vec::new();
    for piece in &pieces {
        let piece_box = piece.aabb();
        for (patch, patch_box) in patches.iter().zip(&patch_boxes) {
            if boxes_meet(&piece_box, patch_box, tolerance) {
                let mut leaves = 0;
                descend(
                    &(piece, patch),
                    *piece,
                    patch.clone(),
                    tolerance,
                    0,
                    &mut leaves,
                    &mut out,
                );
            }
        }
    }
    out
}

/// Halves a part of a span and a part of a patch while their boxes meet, and polishes the
/// flat pairs on the whole span and patch.
fn descend(
    whole: &(&Piece, &Patch),
    piece: Piece,
    patch: Patch,
    tolerance: f64,
    depth: usize,
    leaves: &mut usize,
    out: &mut Vec<CurveSurfacePoint>,
) {
    let (box_c, box_s) = (piece.aabb(), patch.aabb());
    if !boxes_meet(&box_c, &box_s, tolerance) {
        return;
    }
    let deviation = piece.deviation();
    let chord = piece.start().distance(piece.end());
    let flat_c = deviation <= 0.25 * tolerance || deviation <= FLATNESS * chord;
    // A nearly straight piece is tested as its chord, which prunes far better than its box.
    if flat_c && !segment_meets_box(piece.start(), piece.end(), &box_s, tolerance + deviation) {
        return;
    }
    // Both lie in the hulls of their control points: a piece clear of the patch's slab (across
    // the plane of its diagonals) cannot meet it.
    let slab = patch.slab();
    if slab
        .as_ref()
        .is_some_and(|s| s.separates(piece.points(), tolerance))
    {
        return;
    }
    let flat_s = patch.is_flat(slab.as_ref(), FLATNESS, 0.25 * tolerance);
    let (size_c, size_s) = (diagonal(&box_c), diagonal(&box_s));
    let piece_is_larger = size_c > 2.0 * size_s && size_c > tolerance;
    let exhausted = depth >= MAX_DEPTH || *leaves >= MAX_LEAVES;
    let tiny = size_c <= tolerance && size_s <= tolerance;
    let flat = flat_c && flat_s && !piece_is_larger;
    // A flat pair is one crossing at most only when the piece crosses the slab steeply; a
    // nearly tangent pair is halved further (counted against the leaf budget, so that a piece
    // lying on the patch cannot halve without end).
    let once = flat
        && (tiny
            || slab
                .as_ref()
                .is_some_and(|s| crosses_once(&piece, deviation, size_s, s)));
    if once || exhausted {
        *leaves += 1;
        let found = closest_curve_surface(whole.0, whole.1, flat_estimate(&piece, &patch));
        if found.distance <= tolerance {
            out.push(found);
            return;
        }
        // The polish from the flat estimate found nothing. That settles it only when nothing is
        // left to halve: a start on a patch can slide to a minimum on its edge.
        if exhausted || tiny {
            return;
        }
    } else if flat {
        *leaves += 1;
    }
    if (!flat_c && (flat_s || size_c >= size_s)) || (flat_s && piece_is_larger) {
        let (l, r) = piece.halve();
        descend(whole, l, patch.clone(), tolerance, depth + 1, leaves, out);
        descend(whole, r, patch, tolerance, depth + 1, leaves, out);
    } else {
        let (l, r) = patch.halve(patch.split_in_u());
        descend(whole, piece, l, tolerance, depth + 1, leaves, out);
        descend(whole, piece, r, tolerance, depth + 1, leaves, out);
    }
}

/// Whether a nearly straight piece crosses the slab of a nearly flat patch steeply enough to
/// meet the patch at most once: its slope across the patch's plane exceeds
/// [`UNIQUE_CROSSING_SLOPE`] times the slopes the bends of both can reach (each bend's depth
/// over its width). A piece nearly tangent to the patch can cross a slightly curved patch twice
/// (in and out again within its bend), so such pairs are halved further.
fn crosses_once(piece: &Piece, deviation: f64, patch_size: f64, slab: &Slab) -> bool {
    let chord = piece.end() - piece.start();
    let length = chord.length();
    if length == 0.0 {
        return true;
    }
    let bends = slab.thickness() / patch_size.max(f64::MIN_POSITIVE) + deviation / length;
    chord.dot(slab.normal).abs() / length >= UNIQUE_CROSSING_SLOPE * bends
}

/// Whether the segment `p0 p1` comes within `gap` of the box (the box grown by `gap`, clipped
/// against the segment slab by slab).
fn segment_meets_box(p0: Point3, p1: Point3, b: &Aabb, gap: f64) -> bool {
    let (a, d) = (p0.to_array(), (p1 - p0).to_array());
    let (mut s0, mut s1) = (0.0f64, 1.0f64);
    for k in 0..3 {
        let (lo, hi) = (b[0][k] - gap, b[1][k] + gap);
        if d[k] == 0.0 {
            if a[k] < lo || a[k] > hi {
                return false;
            }
        } else {
            let (x, y) = ((lo - a[k]) / d[k], (hi - a[k]) / d[k]);
            s0 = s0.max(x.min(y));
            s1 = s1.min(x.max(y));
            if s0 > s1 {
                return false;
            }
        }
    }
    true
}

/// Merges candidates into points (with whether each is tangential) and overlap intervals
/// (steps 3 and 4 of the module documentation).
#[allow(
    clippy::type_complexity,
    reason = "points with their flag, and intervals, consumed at once by the callers"
)]
pub(crate) fn events(
    curve: &NurbsCurve,
    target: &impl Target,
    raw: Vec<CurveSurfacePoint>,
    tolerance: f64,
) -> (Vec<(CurveSurfacePoint, bool)>, Vec<[f64; 2]>) {
    let mut candidates: Vec<CurveSurfacePoint> = raw
        .into_iter()
        .filter(|c| target.contains(c.on_surface, Some((c.u, c.v))))
        .collect();
    candidates.sort_by(|a, b| a.t.total_cmp(&b.t));
    // Clusters of candidates that are one event.
    let mut clusters: Vec<Vec<CurveSurfacePoint>> = Vec::new();
    for c in candidates {
        if let Some(last) = clusters.last_mut() {
            let previous = last[last.len() - 1];
            if previous.on_curve.distance(c.on_curve) <= tolerance
                || stays_on(curve, target, previous.t, c.t)
            {
                last.push(c);
                continue;
            }
        }
        clusters.push(vec![c]);
    }
    let domain = curve.domain();
    if curve.is_closed() && clusters.len() > 1 {
        let (first, last) = (
            &clusters[0][0],
            clusters[clusters.len() - 1].last().copied(),
        );
        if let Some(last) = last
            && first.on_curve.distance(last.on_curve) <= tolerance
        {
            let tail = clusters.pop().unwrap_or_default();
            clusters[0].extend(tail);
        }
    }
    let mut breaks: Option<Vec<f64>> = None;
    let mut points = Vec::new();
    let mut overlaps: Vec<[f64; 2]> = Vec::new();
    for cluster in clusters {
        let best = *cluster
            .iter()
            .min_by(|a, b| a.distance.total_cmp(&b.distance))
            .unwrap_or(&cluster[0]);
        let (lo, hi) = (cluster[0], cluster[cluster.len() - 1]);
        let spread = lo.on_curve.distance(hi.on_curve) > tolerance && lo.t < hi.t;
        let tangential = is_tangential(curve, target.surface(), &best);
        if !spread && !tangential {
            points.push((best, false));
            continue;
        }
        let breaks = breaks.get_or_insert_with(|| curve_breaks(curve, target, tolerance));
        let (t0, t1) = if spread {
            (lo.t, hi.t)
        } else {
            (best.t, best.t)
        };
        let (start, start_at_break) = extend(curve, target, breaks, t0, false, spread, tolerance);
        let (end, end_at_break) = extend(curve, target, breaks, t1, true, spread, tolerance);
        let long = curve.point_at(start).distance(curve.point_at(end)) > tolerance && start < end;
        if long && (start_at_break || end_at_break || !tangential) {
            overlaps.push([start, end]);
        } else if long {
            // A touching stretch (the curve within the tolerance on both sides of a
            // tangency): its middle is the tangency, to second order.
            points.push((
                touching_point(curve, target.surface(), 0.5 * (start + end), best),
                true,
            ));
        } else {
            points.push((best, tangential));
        }
    }
    // Overlaps joined where they touch; points inside or at the ends of one dropped.
    overlaps.sort_by(|a, b| a[0].total_cmp(&b[0]));
    let mut joined: Vec<[f64; 2]> = Vec::with_capacity(overlaps.len());
    for o in overlaps {
        if let Some(last) = joined.last_mut()
            && (o[0] <= last[1]
                || curve.point_at(o[0]).distance(curve.point_at(last[1])) <= tolerance)
        {
            last[1] = last[1].max(o[1]);
            continue;
        }
        joined.push(o);
    }
    let ends: Vec<[Point3; 2]> = joined
        .iter()
        .map(|o| [curve.point_at(o[0]), curve.point_at(o[1])])
        .collect();
    points.retain(|(p, _)| {
        !joined.iter().zip(&ends).any(|(o, e)| {
            (p.t >= o[0] && p.t <= o[1]) || e.iter().any(|q| q.distance(p.on_curve) <= tolerance)
        })
    });
    for (p, _) in &mut points {
        if curve.is_closed() && p.t == domain.t1 {
            p.t = domain.t0;
        }
    }
    points.sort_by(|a, b| a.0.t.total_cmp(&b.0.t));
    (points, joined)
}

/// The point of the curve at `t` with the surface parameters of its closest point (`near`'s
/// when the projection fails).
fn touching_point(
    curve: &NurbsCurve,
    surface: &NurbsSurface,
    t: f64,
    near: CurveSurfacePoint,
) -> CurveSurfacePoint {
    let on_curve = curve.point_at(t);
    match surface.closest_point(on_curve) {
        Ok(c) => CurveSurfacePoint {
            t,
            u: c.u,
            v: c.v,
            on_curve,
            on_surface: c.point,
            distance: c.distance,
        },
        Err(_) => near,
    }
}

/// Whether the curve stays on the target between `t0` and `t1` (sampled).
fn stays_on(curve: &NurbsCurve, target: &impl Target, t0: f64, t1: f64) -> bool {
    if t1 <= t0 {
        return true;
    }
    (1..STRETCH_SAMPLES).all(|k| {
        let t = t0 + (t1 - t0) * k as f64 / STRETCH_SAMPLES as f64;
        target.contains(curve.point_at(t), None)
    })
}

/// Whether the curve's tangent at the candidate lies in the surface's tangent plane.
fn is_tangential(curve: &NurbsCurve, surface: &NurbsSurface, p: &CurveSurfacePoint) -> bool {
    let tangent = curve.derivative_at(p.t);
    let Ok(normal) = surface.normal_at(p.u, p.v) else {
        return false;
    };
    let length = tangent.length();
    length > 0.0 && tangent.dot(normal).abs() <= TANGENT_SINE * length
}

/// The parameters where an overlap may end, sorted: the curve's ends and knots, and where it
/// meets the target's boundary curves.
fn curve_breaks(curve: &NurbsCurve, target: &impl Target, tolerance: f64) -> Vec<f64> {
    let mut breaks = curve.span_breaks();
    let own = Curve::Nurbs(curve.clone());
    for edge in target.boundary() {
        let Ok(found) = own.intersect_curve(&Curve::Nurbs(edge), tolerance) else {
            continue;
        };
        breaks.extend(found.points.iter().map(|h| h.t_a));
        for o in &found.overlaps {
            breaks.push(o.a.t0);
            breaks.push(o.a.t1);
        }
    }
    breaks.sort_by(f64::total_cmp);
    breaks.dedup();
    breaks
}

/// Extends an overlap from `t` forwards (`up`) or backwards over the breaks while the curve
/// stays on the target, and says whether the end is a break. Past a break, a curve that leaves
/// the target right after it ends there; otherwise (and from `t` itself when `bisect`, for an
/// event already known to be an overlap) the end between two breaks is found by bisection.
fn extend(
    curve: &NurbsCurve,
    target: &impl Target,
    breaks: &[f64],
    t: f64,
    up: bool,
    bisect: bool,
    tolerance: f64,
) -> (f64, bool) {
    let mut at = t;
    let scale = curve.domain().length().abs().max(t.abs()).max(1.0);
    let mut at_break = breaks.iter().any(|&b| (b - t).abs() <= 1e-12 * scale);
    let ordered: Vec<f64> = if up {
        breaks.iter().copied().filter(|&b| b > t).collect()
    } else {
        breaks.iter().rev().copied().filter(|&b| b < t).collect()
    };
    for b in ordered {
        let (lo, hi) = if up { (at, b) } else { (b, at) };
        if target.contains(curve.point_at(b), None) && stays_on(curve, target, lo, hi) {
            at = b;
            at_break = true;
            continue;
        }
        let leaves_at_once =
            at_break && !target.contains(curve.point_at(probe(curve, at, b, tolerance)), None);
        if (bisect || at_break) && !leaves_at_once {
            // The curve leaves the target between `at` and `b`.
            let (mut inside, mut outside) = (at, b);
            for _ in 0..BISECTIONS {
                let mid = 0.5 * (inside + outside);
                if mid == inside || mid == outside {
                    break;
                }
                if target.contains(curve.point_at(mid), None) {
                    inside = mid;
                } else {
                    outside = mid;
                }
            }
            return (inside, false);
        }
        break;
    }
    (at, at_break)
}

/// The parameter a little past the break `at` towards `b`: [`PROBE`] of the way, and at least
/// far enough for the curve to move ten tolerances (at most to `b`).
fn probe(curve: &NurbsCurve, at: f64, b: f64, tolerance: f64) -> f64 {
    let speed = curve.derivative_at(at).length();
    let least = if speed > 0.0 {
        10.0 * tolerance / speed
    } else {
        0.0
    };
    let step = (PROBE * (b - at).abs()).max(least).min((b - at).abs());
    if b > at { at + step } else { at - step }
}

/// Maps parameters of the NURBS form to the curve's own (a circle's or arc's angle).
pub(crate) fn to_own_parameters(
    curve: &Curve,
    points: &mut [CurveSurfaceHit],
    overlaps: &mut [CurveSurfaceOverlap],
) {
    if !matches!(curve, Curve::Circle { .. } | Curve::Arc { .. }) {
        return;
    }
    let d = curve.domain();
    let own = |t: f64, p: Point3| -> f64 {
        if t == d.t0 || t == d.t1 {
            t
        } else {
            curve.closest_point(p).map_or(t, |c| c.t)
        }
    };
    let nurbs = curve.to_nurbs();
    for h in points {
        h.t = own(h.t, h.point);
    }
    for o in overlaps {
        let (p0, p1) = (nurbs.point_at(o.t.t0), nurbs.point_at(o.t.t1));
        o.t = Interval::new(own(o.t.t0, p0), own(o.t.t1, p1));
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Cylinder, Plane, Sphere, Vector3};

    fn p(x: f64, y: f64, z: f64) -> Point3 {
        Point3::new(x, y, z)
    }

    #[test]
    fn a_line_through_a_sphere_and_along_a_cylinder() {
        let sphere = Sphere::new(p(0.0, 0.0, 0.0), 2.0)
            .unwrap()
            .to_nurbs()
            .unwrap();
        let x = sphere
            .intersect_line(&Line::new(p(-1.0, 0.5, 0.0), p(1.0, 0.5, 0.0)), 1e-9)
            .unwrap();
        assert_eq!(x.points.len(), 2, "{x:?}");
        let r = (4.0f64 - 0.25).sqrt();
        assert!((x.points[0].t - (0.5 - r / 2.0)).abs() < 1e-12, "{x:?}");
        for h in &x.points {
            assert!(sphere.point_at(h.u, h.v).distance(h.point) < 1e-12);
            assert!(!h.tangential);
        }
        let cylinder = Cylinder::new(Plane::WORLD_XY, 1.0, 2.0)
            .unwrap()
            .to_nurbs()
            .unwrap();
        let along: Curve = Line::new(p(0.0, 1.0, -1.0), p(0.0, 1.0, 3.0)).into();
        let x = cylinder.intersect_curve(&along, 1e-9).unwrap();
        assert!(x.points.is_empty(), "{x:?}");
        assert_eq!(x.overlaps.len(), 1, "{x:?}");
        let length = 4.0;
        assert!(
            (x.overlaps[0].t.t0 - 1.0 / 4.0 * length).abs() < 1e-12,
            "{x:?}"
        );
        assert!(
            (x.overlaps[0].t.t1 - 3.0 / 4.0 * length).abs() < 1e-12,
            "{x:?}"
        );
        let tangent: Curve = Line::new(p(1.0, -2.0, 1.0), p(1.0, 2.0, 1.0)).into();
        let x = cylinder.intersect_curve(&tangent, 1e-9).unwrap();
        assert_eq!(x.points.len(), 1, "{x:?}");
        assert!(x.points[0].tangential);
        let _ = Vector3::X;
    }

    #[test]
    fn bad_input_is_an_error() {
        let sphere = Sphere::new(p(0.0, 0.0, 0.0), 2.0)
            .unwrap()
            .to_nurbs()
            .unwrap();
        let line = Line::new(p(0.0, 0.0, 0.0), p(0.0, 0.0, 0.0));
        assert!(sphere.intersect_line(&line, 1e-9).is_err());
        let line = Line::new(p(0.0, 0.0, 0.0), p(1.0, 0.0, 0.0));
        assert!(sphere.intersect_line(&line, 0.0).is_err());
        assert!(sphere.intersect_line(&line, f64::NAN).is_err());
        let nan = Line::new(p(f64::NAN, 0.0, 0.0), p(1.0, 0.0, 0.0));
        assert!(sphere.intersect_line(&nan, 1e-9).is_err());
    }
}

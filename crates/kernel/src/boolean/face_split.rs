//! Splitting the faces of a B-rep along cuts: the planar arrangement of each face's trims and
//! cuts in its parameter rectangle, and the regions it bounds.
//!
//! 1. **Where cuts end.** A cut ends on the face's border (on a trim: the nearest in the
//!    parameter rectangle whose point lies within the tolerance in 3-D) or inside the face,
//!    where it meets other cuts. Each edge of the B-rep is split at every point where a cut of
//!    any of its faces ends on it, the same points for all its trims (`EdgeSplits`), so that
//!    the pieces of neighbouring faces still meet edge to edge.
//! 2. **The arrangement.** The trims, split there, run once in their loop's direction (the face
//!    lies to their left); each cut runs both ways. Cut ends inside the face that lie together
//!    are one vertex. Cuts that end nowhere (a dangling end) are dropped, repeatedly.
//! 3. **The regions.** From each directed piece, the walk turns at every vertex to the first
//!    piece clockwise from the one it came along, which keeps the region on its left. Every
//!    walk closes a loop: counter-clockwise loops (positive area) bound a region, clockwise ones
//!    are holes, each given to the smallest region around it. Cuts are assumed to meet one
//!    another only at their ends (true of the cuts of two B-reps away from singular points).
//!
//! Angles are compared in the parameter rectangle, which keeps the cyclic order of directions
//! on the surface wherever the surface is regular.

use crate::boolean::cuts::Cut;
use crate::boolean::regions::{Fragment, Vertex, regions};
use crate::brep::Brep;
use crate::curve::split::join_clamped;
use crate::{Error, Interval, NurbsCurve, Point3, Result};
use std::collections::HashMap;

/// Where an edge of the B-rep is split: its parameters, increasing, per edge.
pub(crate) type EdgeSplits = HashMap<usize, Vec<f64>>;

/// One region of a split face, as a B-rep of one face.
#[derive(Clone, Debug)]
pub(crate) struct Piece {
    /// The face it came from.
    pub(crate) face: usize,
    /// The region as a B-rep of one face (its edges not joined to anything).
    pub(crate) brep: Brep,
    /// The pieces of the original edges it runs along: `(edge, index of the stretch between
    /// the edge's splits)`. Pieces that share one are neighbours across an original edge.
    pub(crate) stretches: Vec<(usize, usize)>,
    /// A point of the region's parameter rectangle well inside it.
    pub(crate) inner: (f64, f64),
}

/// Where the end of a cut lies: on trim `trim` of the face, or inside the face.
#[derive(Clone, Copy, Debug)]
pub(crate) enum End {
    Trim { trim: usize, t: f64 },
    Inside,
}

/// The ends of the cuts of every face: records in `splits` where they split the edges, and
/// returns per face and cut the two ends. `curves` are the cuts' 3-D curves.
pub(crate) fn attach_ends(
    brep: &Brep,
    cuts: &[Vec<Cut>],
    curves: &[NurbsCurve],
    splits: &mut EdgeSplits,
    tolerance: f64,
) -> Vec<Vec<[End; 2]>> {
    let mut out = Vec::with_capacity(cuts.len());
    for (f, face_cuts) in cuts.iter().enumerate() {
        let trims: Vec<usize> = brep.faces()[f]
            .loops
            .iter()
            .flat_map(|&l| brep.loops()[l].trims.iter().copied())
            .collect();
        let surface = &brep.faces()[f].surface;
        let mut ends = Vec::with_capacity(face_cuts.len());
        for cut in face_cuts {
            let curve = &curves[cut.curve];
            let mut pair = [End::Inside; 2];
            for (k, (p, uv)) in [
                (curve.start_point(), cut.uv.start_point()),
                (curve.end_point(), cut.uv.end_point()),
            ]
            .into_iter()
            .enumerate()
            {
                let mut best: Option<(f64, usize, f64)> = None;
                for &t in &trims {
                    let trim = &brep.trims()[t];
                    let Ok(c) = trim.curve.closest_point(uv) else {
                        continue;
                    };
                    let on = surface.point_at(c.point.x, c.point.y);
                    let near = match trim.edge {
                        Some(e) => brep.edges()[e]
                            .curve
                            .closest_point(p)
                            .is_ok_and(|x| x.distance <= 10.0 * tolerance),
                        None => on.distance(p) <= 10.0 * tolerance,
                    };
                    if near && best.is_none_or(|b| c.distance < b.0) {
                        best = Some((c.distance, t, c.t));
                    }
                }
                if let Some((_, t, at)) = best {
                    pair[k] = End::Trim { trim: t, t: at };
                    if let Some(e) = brep.trims()[t].edge {
                        let edge = &brep.edges()[e].curve;
                        if let Ok(x) = edge.closest_point(p) {
                            add_split(splits, e, edge, x.t, tolerance);
                        }
                    }
                }
            }
            ends.push(pair);
        }
        out.push(ends);
    }
    out
}

/// Records a split of edge `e` at `t`, unless it lies within the tolerance of its ends or of a
/// split already there.
fn add_split(splits: &mut EdgeSplits, e: usize, edge: &NurbsCurve, t: f64, tolerance: f64) {
    let p = edge.point_at(t);
    let near = |s: f64| edge.point_at(s).distance(p) <= 10.0 * tolerance;
    let d = edge.domain();
    if near(d.t0) || near(d.t1) {
        return;
    }
    let list = splits.entry(e).or_default();
    if list.iter().any(|&s| near(s)) {
        return;
    }
    list.push(t);
    list.sort_by(f64::total_cmp);
}

/// The regions face `f` of `brep` is split into by its cuts (see the module documentation);
/// one region, its trims split where `splits` says, when no cut divides it.
pub(crate) fn split_face(
    brep: &Brep,
    f: usize,
    cuts: &[Cut],
    ends: &[[End; 2]],
    curves: &[NurbsCurve],
    splits: &EdgeSplits,
    tolerance: f64,
) -> Result<Vec<Piece>> {
    let face = &brep.faces()[f];
    let surface = &face.surface;
    let mut vertices: Vec<Vertex> = Vec::new();
    let mut fragments: Vec<Fragment> = Vec::new();
    // Trim vertices: per trim, its split parameters and their vertices.
    let mut trim_points: HashMap<usize, Vec<(f64, usize)>> = HashMap::new();
    for &l in &face.loops {
        let lp = &brep.loops()[l];
        let mut loop_trims: Vec<(usize, Vec<f64>)> = Vec::new();
        for &t in &lp.trims {
            let trim = &brep.trims()[t];
            let d = trim.curve.domain();
            let mut params = vec![d.t0];
            if let Some(e) = trim.edge
                && let Some(list) = splits.get(&e)
            {
                let edge = &brep.edges()[e].curve;
                for &s in list {
                    params.push(trim_parameter_at(brep, f, t, edge.point_at(s)));
                }
            }
            for end in ends.iter().flatten() {
                if let End::Trim { trim: tt, t: at } = *end
                    && tt == t
                    && trim.edge.is_none()
                {
                    params.push(at);
                }
            }
            params.sort_by(f64::total_cmp);
            let span = d.length();
            params.dedup_by(|b, a| (*b - *a).abs() <= 1e-9 * span);
            params.retain(|&s| s == d.t0 || (d.t1 - s) > 1e-9 * span);
            loop_trims.push((t, params));
        }
        // One vertex per parameter, the end of each trim being the start of the next.
        let mut starts = Vec::new();
        for (t, params) in &loop_trims {
            let trim = &brep.trims()[*t];
            let mut ids = Vec::new();
            for &s in params {
                let q = trim.curve.point_at(s);
                vertices.push(Vertex {
                    uv: (q.x, q.y),
                    point: surface.point_at(q.x, q.y),
                });
                ids.push((s, vertices.len() - 1));
            }
            starts.push(ids);
        }
        let n = loop_trims.len();
        for (k, (t, _)) in loop_trims.iter().enumerate() {
            let trim = &brep.trims()[*t];
            let d = trim.curve.domain();
            let next_start = starts[(k + 1) % n][0].1;
            let mut ids: Vec<(f64, usize)> = starts[k].clone();
            ids.push((d.t1, next_start));
            for w in ids.windows(2) {
                let ((s0, v0), (s1, v1)) = (w[0], w[1]);
                let uv = trim.curve.trim(Interval::new(s0, s1))?;
                let (xyz, stretch) = match trim.edge {
                    Some(e) => {
                        let edge = &brep.edges()[e].curve;
                        let ta = edge_parameter(edge, vertices[v0].point);
                        let tb = edge_parameter(edge, vertices[v1].point);
                        let whole = v0 == v1;
                        let piece = edge_piece(edge, ta, tb, !trim.reversed, whole, tolerance)?;
                        let mid = piece.point_at(piece.domain().mid());
                        let at = edge_parameter(edge, mid);
                        let index = splits
                            .get(&e)
                            .map_or(0, |l| l.iter().filter(|&&s| s < at).count());
                        (Some(piece), Some((e, index)))
                    }
                    None => (None, None),
                };
                fragments.push(Fragment {
                    uv,
                    xyz,
                    from: v0,
                    to: v1,
                    stretch,
                    cut: false,
                });
            }
            trim_points.insert(*t, starts[k].clone());
        }
    }
    // The cuts, their ends attached to trim vertices or to vertices inside the face.
    let boundary_vertices = vertices.len();
    for (cut, end) in cuts.iter().zip(ends) {
        let curve = &curves[cut.curve];
        let mut ids = [0usize; 2];
        for (k, e) in end.iter().enumerate() {
            let uv = if k == 0 {
                cut.uv.start_point()
            } else {
                cut.uv.end_point()
            };
            let point = if k == 0 {
                curve.start_point()
            } else {
                curve.end_point()
            };
            ids[k] = match *e {
                End::Trim { trim, .. } => {
                    let candidates = trim_points.get(&trim).cloned().unwrap_or_default();
                    let next = next_trim_start(brep, f, trim, &trim_points);
                    candidates
                        .iter()
                        .map(|c| c.1)
                        .chain(next)
                        .min_by(|&a, &b| {
                            uv_distance(vertices[a].uv, (uv.x, uv.y))
                                .total_cmp(&uv_distance(vertices[b].uv, (uv.x, uv.y)))
                        })
                        .ok_or_else(|| Error::InvalidInput("a trim without vertices".into()))?
                }
                End::Inside => {
                    let found = (boundary_vertices..vertices.len()).find(|&v| {
                        vertices[v].point.distance(point) <= 10.0 * tolerance
                            && uv_distance(vertices[v].uv, (uv.x, uv.y)) <= uv_gap(brep, f)
                    });
                    match found {
                        Some(v) => v,
                        None => {
                            vertices.push(Vertex {
                                uv: (uv.x, uv.y),
                                point,
                            });
                            vertices.len() - 1
                        }
                    }
                }
            };
        }
        // A cut may run along the border for a stretch (where the faces lie on each other):
        // it is split at the border's vertices it passes, and the stretches along the border
        // are dropped below.
        let (ends3, ends_uv) = (curve.domain(), cut.uv.domain());
        let mut stops: Vec<(f64, f64, usize)> = vec![(ends_uv.t0, ends3.t0, ids[0])];
        for (v, vertex) in vertices.iter().enumerate().take(boundary_vertices) {
            if ids.contains(&v) {
                continue;
            }
            let Ok(c3) = curve.closest_point(vertex.point) else {
                continue;
            };
            let inside = c3.distance <= tolerance
                && curve.start_point().distance(vertex.point) > 10.0 * tolerance
                && curve.end_point().distance(vertex.point) > 10.0 * tolerance;
            if !inside {
                continue;
            }
            let Ok(cuv) = cut
                .uv
                .closest_point(Point3::new(vertex.uv.0, vertex.uv.1, 0.0))
            else {
                continue;
            };
            stops.push((cuv.t, c3.t, v));
        }
        stops.push((ends_uv.t1, ends3.t1, ids[1]));
        stops[1..].sort_by(|x, y| x.0.total_cmp(&y.0));
        for w in stops.windows(2) {
            let ((u0, t0, a), (u1, t1, b)) = (w[0], w[1]);
            let whole = stops.len() == 2;
            let (piece_uv, piece) = if whole {
                (cut.uv.clone(), curve.clone())
            } else {
                if !(u1 > u0 && t1 > t0) {
                    continue;
                }
                (
                    cut.uv.trim(Interval::new(u0, u1))?,
                    curve.trim(Interval::new(t0, t1))?,
                )
            };
            push_cut(
                brep,
                f,
                &mut fragments,
                &vertices,
                boundary_vertices,
                (piece_uv, piece),
                [a, b],
                tolerance,
            )?;
        }
    }
    drop_dangling(&mut fragments, vertices.len());
    regions(brep, f, &vertices, &fragments, tolerance)
}

/// Adds a cut (or a stretch of one) from vertex `ids[0]` to `ids[1]` as a fragment, unless it
/// runs along the face's border, stays at one point, or was added already.
#[allow(clippy::too_many_arguments)]
fn push_cut(
    brep: &Brep,
    f: usize,
    fragments: &mut Vec<Fragment>,
    vertices: &[Vertex],
    boundary_vertices: usize,
    (uv, curve): (NurbsCurve, NurbsCurve),
    ids: [usize; 2],
    tolerance: f64,
) -> Result<()> {
    let uv = with_ends(&uv, vertices[ids[0]].uv, vertices[ids[1]].uv)?;
    let mid = curve.point_at(curve.domain().mid());
    let on_border =
        ids.iter().all(|&v| v < boundary_vertices) && lies_on_border(brep, f, mid, tolerance);
    let tiny = ids[0] == ids[1] && curve_span(&curve) <= 10.0 * tolerance;
    let duplicate = fragments.iter().any(|g| {
        g.cut
            && ((g.from, g.to) == (ids[0], ids[1]) || (g.from, g.to) == (ids[1], ids[0]))
            && g.xyz.as_ref().is_some_and(|x| {
                x.closest_point(mid)
                    .is_ok_and(|c| c.distance <= 10.0 * tolerance)
            })
    });
    if !(on_border || tiny || duplicate) {
        fragments.push(Fragment {
            uv,
            xyz: Some(curve),
            from: ids[0],
            to: ids[1],
            stretch: None,
            cut: true,
        });
    }
    Ok(())
}

/// The first vertex of the trim after `trim` in its loop.
fn next_trim_start(
    brep: &Brep,
    f: usize,
    trim: usize,
    trim_points: &HashMap<usize, Vec<(f64, usize)>>,
) -> Option<usize> {
    let l = brep.trims()[trim].loop_index;
    let lp = &brep.loops()[l];
    debug_assert_eq!(lp.face, f);
    let k = lp.trims.iter().position(|&t| t == trim)?;
    let next = lp.trims[(k + 1) % lp.trims.len()];
    trim_points.get(&next)?.first().map(|p| p.1)
}

fn uv_distance(a: (f64, f64), b: (f64, f64)) -> f64 {
    (a.0 - b.0).hypot(a.1 - b.1)
}

/// How far apart in parameters two cut ends inside face `f` may be and still be one vertex.
fn uv_gap(brep: &Brep, f: usize) -> f64 {
    let s = &brep.faces()[f].surface;
    1e-6 * (s.domain_u().length() + s.domain_v().length())
}

/// The parameter of the point of `edge` nearest `p`.
fn edge_parameter(edge: &NurbsCurve, p: Point3) -> f64 {
    edge.closest_point(p).map_or(edge.domain().t0, |c| c.t)
}

/// The stretch of `edge` from parameter `from` to `to`, running along the edge (`along`) or
/// against it; on a closed edge it may pass the edge's seam, and it is the whole edge when
/// `whole` is set or the two ends are the same point.
fn edge_piece(
    edge: &NurbsCurve,
    from: f64,
    to: f64,
    along: bool,
    whole: bool,
    tolerance: f64,
) -> Result<NurbsCurve> {
    if !along {
        return Ok(edge_piece(edge, to, from, true, whole, tolerance)?.reversed());
    }
    let d = edge.domain();
    let same = edge.point_at(from).distance(edge.point_at(to)) <= tolerance;
    if whole || same {
        if edge.is_closed() && (from - d.t0).abs().min((from - d.t1).abs()) <= 1e-12 * d.length() {
            return Ok(edge.clone());
        }
        if edge.is_closed() {
            let before = edge.trim(Interval::new(from, d.t1))?;
            let after = edge.trim(Interval::new(d.t0, from))?;
            return join_clamped(&before, &after);
        }
    }
    if to > from {
        return edge.trim(Interval::new(from, to));
    }
    // Across the seam of a closed edge.
    let gap = 1e-12 * d.length();
    match (from < d.t1 - gap, to > d.t0 + gap) {
        (true, true) => join_clamped(
            &edge.trim(Interval::new(from, d.t1))?,
            &edge.trim(Interval::new(d.t0, to))?,
        ),
        (true, false) => edge.trim(Interval::new(from, d.t1)),
        (false, true) => edge.trim(Interval::new(d.t0, to)),
        (false, false) => Ok(edge.clone()),
    }
}

/// The largest distance of a curve's control points from its start: zero for a curve that
/// stays at one point.
fn curve_span(curve: &NurbsCurve) -> f64 {
    let s = curve.start_point();
    curve
        .points()
        .iter()
        .map(|p| p.distance(s))
        .fold(0.0, f64::max)
}

/// Whether `p` lies within the tolerance of an edge of face `f`.
fn lies_on_border(brep: &Brep, f: usize, p: Point3, tolerance: f64) -> bool {
    brep.faces()[f].loops.iter().any(|&l| {
        brep.loops()[l].trims.iter().any(|&t| {
            brep.trims()[t].edge.is_some_and(|e| {
                brep.edges()[e]
                    .curve
                    .closest_point(p)
                    .is_ok_and(|c| c.distance <= tolerance)
            })
        })
    })
}

/// The parameter of trim `t` of face `f` whose surface point is nearest `p`: the best of a
/// sample, refined by golden-section search.
fn trim_parameter_at(brep: &Brep, f: usize, t: usize, p: Point3) -> f64 {
    let surface = &brep.faces()[f].surface;
    let curve = &brep.trims()[t].curve;
    let d = curve.domain();
    let at = |s: f64| {
        let q = curve.point_at(s);
        surface.point_at(q.x, q.y).distance_squared(p)
    };
    const N: usize = 64;
    let step = d.length() / N as f64;
    let best = (0..=N)
        .map(|k| d.t0 + step * k as f64)
        .min_by(|&a, &b| at(a).total_cmp(&at(b)))
        .unwrap_or(d.t0);
    let (mut lo, mut hi) = ((best - step).max(d.t0), (best + step).min(d.t1));
    let g = 0.5 * (5f64.sqrt() - 1.0);
    for _ in 0..80 {
        let (x1, x2) = (hi - g * (hi - lo), lo + g * (hi - lo));
        if at(x1) <= at(x2) {
            hi = x2;
        } else {
            lo = x1;
        }
    }
    0.5 * (lo + hi)
}

/// `curve` with its first and last control points moved onto `start` and `end`.
fn with_ends(curve: &NurbsCurve, start: (f64, f64), end: (f64, f64)) -> Result<NurbsCurve> {
    let mut points = curve.points().to_vec();
    let n = points.len();
    points[0] = Point3::new(start.0, start.1, 0.0);
    points[n - 1] = Point3::new(end.0, end.1, 0.0);
    NurbsCurve::new(
        curve.degree(),
        points,
        curve.weights().to_vec(),
        curve.knots().to_vec(),
    )
}

/// Drops cuts with an end that no other fragment reaches, until there are none.
fn drop_dangling(fragments: &mut Vec<Fragment>, vertex_count: usize) {
    loop {
        let mut degree = vec![0usize; vertex_count];
        for g in fragments.iter() {
            degree[g.from] += 1;
            degree[g.to] += 1;
        }
        let before = fragments.len();
        fragments.retain(|g| !(g.cut && (degree[g.from] < 2 || degree[g.to] < 2)));
        if fragments.len() == before {
            return;
        }
    }
}

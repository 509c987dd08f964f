//! The cuts of two B-reps: where each face of one meets the other, as 3-D curves with their
//! images in the parameter rectangles of both faces.
//!
//! Each pair of faces whose boxes meet is intersected (`surface_surface.rs`); the traced arcs
//! are kept where they lie on both faces and cut where they leave one, at the point where an
//! edge of either face crosses the other surface, as the B-rep intersection does
//! (`brep_brep.rs`). Each kept run becomes one 3-D curve (the Hermite fit of the traced points)
//! and one curve in each face's parameter rectangle: the Hermite fit of the traced parameters,
//! with the tangent of the 3-D curve carried into the rectangle through the surface's first
//! derivatives.

use crate::intersect::brep_brep::{Face, boxes_meet, faces_of};
use crate::intersect::brep_plane::segment_distance;
use crate::intersect::hermite_fit::{
    TracePoint, bezier_point, distance_to_segment, fit, hermite_segment,
};
use crate::intersect::surface_surface::{PairPoint, surface_surface};
use crate::{Brep, NurbsCurve, NurbsSurface, Point3, Result, Vector3};

/// The precision of the traced cuts relative to the size of the two B-reps' box: 1e-10, so
/// that volumes and areas of booleans agree with closed forms to about 1e-10 relative.
pub const TRACE_PRECISION: f64 = 1e-10;

/// One cut of one face: a 3-D curve of the shared list and its image on the face.
#[derive(Clone, Debug)]
pub(crate) struct Cut {
    /// The index of the 3-D curve in [`Cuts::curves`].
    pub(crate) curve: usize,
    /// The curve in the face's parameter rectangle (`x = u`, `y = v`, `z = 0`), running the
    /// same way as the 3-D curve.
    pub(crate) uv: NurbsCurve,
}

/// The cuts of two B-reps, face by face.
#[derive(Clone, Debug, Default)]
pub(crate) struct Cuts {
    /// The 3-D curves, each shared by one face of each B-rep.
    pub(crate) curves: Vec<NurbsCurve>,
    /// The cuts of each face of the first B-rep.
    pub(crate) of_a: Vec<Vec<Cut>>,
    /// The cuts of each face of the second B-rep.
    pub(crate) of_b: Vec<Vec<Cut>>,
    /// Whether two faces lie on each other somewhere.
    pub(crate) coincident: bool,
}

/// The cuts of `a` and `b` within `tolerance`.
pub(crate) fn find_cuts(a: &Brep, b: &Brep, tolerance: f64) -> Result<Cuts> {
    // The curves become edges that the volume and area of the result are integrated along, so
    // they are traced to a fixed precision relative to the size of the pair, whatever the
    // tolerance (which still decides what lies on a face and which points are one).
    let size = a
        .bounding_box()
        .union(&b.bounding_box())
        .diagonal()
        .length();
    let precision = tolerance.min(TRACE_PRECISION * size.max(f64::MIN_POSITIVE));
    let (faces_a, faces_b) = (faces_of(a), faces_of(b));
    let boxes_a: Vec<_> = faces_a.iter().map(|f| f.surface.bounding_box()).collect();
    let boxes_b: Vec<_> = faces_b.iter().map(|f| f.surface.bounding_box()).collect();
    let mut cuts = Cuts {
        of_a: vec![Vec::new(); faces_a.len()],
        of_b: vec![Vec::new(); faces_b.len()],
        ..Cuts::default()
    };
    for (i, (fa, box_a)) in faces_a.iter().zip(&boxes_a).enumerate() {
        for (j, (fb, box_b)) in faces_b.iter().zip(&boxes_b).enumerate() {
            if !boxes_meet(box_a, box_b, tolerance) {
                continue;
            }
            let x = surface_surface(fa.surface, fb.surface, precision);
            cuts.coincident |= x.coincident;
            if x.arcs.is_empty() {
                continue;
            }
            let untrimmed = fa.region.is_untrimmed() && fb.region.is_untrimmed();
            let mut crossings = Vec::new();
            if !untrimmed {
                crossings = fa.edge_crossings(fb.surface, tolerance);
                crossings.extend(fb.edge_crossings(fa.surface, tolerance));
            }
            for arc in &x.arcs {
                let runs = if untrimmed {
                    vec![arc.clone()]
                } else {
                    runs_on_both(arc, fa, fb, &crossings, tolerance)
                };
                for run in runs {
                    if run.len() < 2 {
                        continue;
                    }
                    let trace: Vec<TracePoint> = run.iter().map(|p| p.trace).collect();
                    let curve = fit(&trace)?;
                    if curve.start_point().distance(curve.end_point()) <= tolerance
                        && !is_closed_run(&run, tolerance)
                    {
                        continue;
                    }
                    let uv_a = fit_parameters(&run, |p| p.a, fa.surface, precision)?;
                    let uv_b = fit_parameters(&run, |p| p.b, fb.surface, precision)?;
                    let k = cuts.curves.len();
                    cuts.curves.push(curve);
                    cuts.of_a[i].push(Cut { curve: k, uv: uv_a });
                    cuts.of_b[j].push(Cut { curve: k, uv: uv_b });
                }
            }
        }
    }
    Ok(cuts)
}

/// Whether a run that ends where it starts goes somewhere on the way (a closed curve, not a
/// speck).
fn is_closed_run(run: &[PairPoint], tolerance: f64) -> bool {
    let start = run[0].trace.point;
    run.iter()
        .any(|p| p.trace.point.distance(start) > 10.0 * tolerance)
}

/// The stretches of a traced arc that lie on both faces, each ending at the crossing of an
/// edge nearest to where it leaves one (with its parameters on both surfaces).
fn runs_on_both(
    arc: &[PairPoint],
    fa: &Face,
    fb: &Face,
    crossings: &[Point3],
    tolerance: f64,
) -> Vec<Vec<PairPoint>> {
    let inside: Vec<bool> = arc
        .iter()
        .map(|p| {
            fa.contains(p.trace.point, p.a, tolerance) && fb.contains(p.trace.point, p.b, tolerance)
        })
        .collect();
    let cut = |x: &PairPoint, y: &PairPoint| -> Option<PairPoint> {
        let (p, d) = (x.trace.point, y.trace.point - x.trace.point);
        let best = *crossings
            .iter()
            .min_by(|m, n| segment_distance(**m, p, d).total_cmp(&segment_distance(**n, p, d)))?;
        let l = d.length_squared();
        let s = if l > 0.0 {
            ((best - p).dot(d) / l).clamp(0.0, 1.0)
        } else {
            0.0
        };
        let lerp = |a: (f64, f64), b: (f64, f64)| (a.0 + (b.0 - a.0) * s, a.1 + (b.1 - a.1) * s);
        Some(PairPoint {
            a: project_near(fa.surface, best, lerp(x.a, y.a)),
            b: project_near(fb.surface, best, lerp(x.b, y.b)),
            trace: TracePoint {
                point: best,
                tangent: d.normalize_or_zero(),
            },
        })
    };
    let mut runs: Vec<Vec<PairPoint>> = Vec::new();
    let mut current: Vec<PairPoint> = Vec::new();
    for k in 0..arc.len() {
        if inside[k] {
            if current.is_empty() && k > 0 && !inside[k - 1] {
                current.extend(cut(&arc[k - 1], &arc[k]));
            }
            current.push(arc[k]);
        } else if !current.is_empty() {
            current.extend(cut(&arc[k - 1], &arc[k]));
            runs.push(std::mem::take(&mut current));
        }
    }
    if !current.is_empty() {
        runs.push(current);
    }
    for run in &mut runs {
        run.dedup_by(|b, a| a.trace.point.distance(b.trace.point) <= tolerance * 1e-3);
    }
    runs
}

/// The parameters of the point of `surface` nearest `p`, by Newton's method from `start`
/// (kept when the surface is degenerate there).
pub(crate) fn project_near(surface: &NurbsSurface, p: Point3, start: (f64, f64)) -> (f64, f64) {
    let (du, dv) = (surface.domain_u(), surface.domain_v());
    let (mut u, mut v) = start;
    for _ in 0..12 {
        let Ok(d) = surface.derivatives_at(u, v, 1) else {
            break;
        };
        let e = d.point - p;
        let (a, b, c) = (d.du.dot(d.du), d.du.dot(d.dv), d.dv.dot(d.dv));
        let det = a * c - b * b;
        if det.is_nan() || det <= 1e-24 * a * c || !det.is_finite() {
            break;
        }
        let (gu, gv) = (d.du.dot(e), d.dv.dot(e));
        let nu = (u - (c * gu - b * gv) / det).clamp(du.t0, du.t1);
        let nv = (v - (a * gv - b * gu) / det).clamp(dv.t0, dv.t1);
        let moved = (nu - u).abs() + (nv - v).abs();
        (u, v) = (nu, nv);
        if moved <= 1e-15 * (1.0 + u.abs() + v.abs()) {
            break;
        }
    }
    (u, v)
}

/// The curve in a surface's parameter rectangle through the parameters `select` picks from
/// each traced point, with tangents carried from 3-D (or from the neighbouring parameters where
/// the surface is degenerate).
fn fit_parameters(
    run: &[PairPoint],
    select: impl Fn(&PairPoint) -> (f64, f64),
    surface: &NurbsSurface,
    tolerance: f64,
) -> Result<NurbsCurve> {
    let mut uv: Vec<(f64, f64)> = run.iter().map(&select).collect();
    let n = uv.len();
    // A closed trace ends on a copy of its first point; where that lies on a side of the
    // rectangle of a closed surface, one of its ends belongs on the opposite side, beside the
    // point next to it.
    if n >= 2 {
        uv[n - 1] = beside(surface, uv[n - 1], uv[n - 2]);
        uv[0] = beside(surface, uv[0], uv[1]);
    }
    let chord = |i: usize, j: usize| Vector3::new(uv[j].0 - uv[i].0, uv[j].1 - uv[i].1, 0.0);
    let points: Vec<TracePoint> = (0..n)
        .map(|k| {
            let neighbours = chord(k.saturating_sub(1), (k + 1).min(n - 1)).normalize_or_zero();
            TracePoint {
                point: Point3::new(uv[k].0, uv[k].1, 0.0),
                tangent: carried_tangent(surface, uv[k], run[k].trace.tangent)
                    .unwrap_or(neighbours),
            }
        })
        .collect();
    // The traced points are close enough for the 3-D curve; in the rectangle the curve may
    // bend more, so each piece is halved until the middle of its Hermite segment maps within a
    // tenth of the tolerance of the 3-D curve's.
    let mut refined = Vec::with_capacity(points.len());
    refined.push(points[0]);
    for k in 1..n {
        let c3 = hermite_segment(&run[k - 1].trace, &run[k].trace);
        refine(
            surface,
            &c3,
            (0.0, 1.0),
            (points[k - 1], points[k]),
            tolerance / 10.0,
            0,
            &mut refined,
        );
    }
    // Points that coincide (the end of a cut and the traced point beside it) would give a
    // segment of no length.
    let size = refined
        .iter()
        .map(|p| p.point.distance(refined[0].point))
        .fold(0.0, f64::max);
    refined.dedup_by(|b, a| a.point.distance(b.point) <= 1e-12 * size);
    if refined.len() < 2 {
        refined = vec![points[0], points[n - 1]];
    }
    fit(&refined)
}

/// The deepest halving of a piece of a cut in a parameter rectangle.
const MAX_REFINE_DEPTH: usize = 8;

/// Appends the points after `ends.0` up to `ends.1` of the piece of a cut that runs along the
/// 3-D Hermite segment `c3` on `[s.0, s.1]`, halving it where its Hermite segment in the
/// rectangle strays from the 3-D curve by more than `gap`.
fn refine(
    surface: &NurbsSurface,
    c3: &[Point3; 4],
    s: (f64, f64),
    ends: (TracePoint, TracePoint),
    gap: f64,
    depth: usize,
    out: &mut Vec<TracePoint>,
) {
    let mid_s = 0.5 * (s.0 + s.1);
    let target = bezier_point(c3, mid_s);
    let guess = bezier_point(&hermite_segment(&ends.0, &ends.1), 0.5);
    // The middle of the piece in the rectangle must map onto the 3-D segment (anywhere along
    // it: the two segments are not parametrised alike), up to how far the 3-D segment itself
    // leaves the surface where its end tangents are only chords (the ends of a cut).
    let uv = project_near(surface, target, (guess.x, guess.y));
    let off_surface = surface.point_at(uv.0, uv.1).distance(target);
    let off = distance_to_segment(c3, surface.point_at(guess.x, guess.y));
    if depth >= MAX_REFINE_DEPTH || off <= gap.max(2.0 * off_surface) {
        out.push(ends.1);
        return;
    }
    let tangent3 = bezier_derivative(c3, mid_s).normalize_or_zero();
    let fallback = (ends.1.point - ends.0.point).normalize_or_zero();
    let mid = TracePoint {
        point: Point3::new(uv.0, uv.1, 0.0),
        tangent: carried_tangent(surface, uv, tangent3).unwrap_or(fallback),
    };
    refine(
        surface,
        c3,
        (s.0, mid_s),
        (ends.0, mid),
        gap,
        depth + 1,
        out,
    );
    refine(
        surface,
        c3,
        (mid_s, s.1),
        (mid, ends.1),
        gap,
        depth + 1,
        out,
    );
}

/// The derivative of the cubic Bézier `c` at `s`.
fn bezier_derivative(c: &[Point3; 4], s: f64) -> Vector3 {
    let r = 1.0 - s;
    (c[1] - c[0]) * (3.0 * r * r) + (c[2] - c[1]) * (6.0 * r * s) + (c[3] - c[2]) * (3.0 * s * s)
}

/// The unit direction in the parameter rectangle at `uv` of the 3-D direction `t`, where the
/// surface is regular.
fn carried_tangent(surface: &NurbsSurface, uv: (f64, f64), t: Vector3) -> Option<Vector3> {
    let d = surface.derivatives_at(uv.0, uv.1, 1).ok()?;
    let (a, b, c) = (d.du.dot(d.du), d.du.dot(d.dv), d.dv.dot(d.dv));
    let det = a * c - b * b;
    if det.is_nan() || det <= 1e-12 * a * c {
        return None;
    }
    let (gu, gv) = (d.du.dot(t), d.dv.dot(t));
    let w = Vector3::new((c * gu - b * gv) / det, (a * gv - b * gu) / det, 0.0).normalize_or_zero();
    (w.length_squared() > 0.0).then_some(w)
}

/// Among the parameters of the same surface point as `uv` across a closed surface's seams
/// (shifted by a period and clamped to the rectangle), the nearest to `next`.
fn beside(surface: &NurbsSurface, uv: (f64, f64), next: (f64, f64)) -> (f64, f64) {
    let (du, dv) = (surface.domain_u(), surface.domain_v());
    let shifts = |x: f64, d: crate::Interval| {
        [x, x + d.length(), x - d.length()].map(|y| y.clamp(d.t0, d.t1))
    };
    let here = surface.point_at(uv.0, uv.1);
    let same = |c: &(f64, f64)| {
        surface.point_at(c.0, c.1).distance(here) <= 1e-9 * (1.0 + here.to_vector().length())
    };
    let near = |c: (f64, f64)| (c.0 - next.0).hypot(c.1 - next.1);
    shifts(uv.0, du)
        .into_iter()
        .flat_map(|a| shifts(uv.1, dv).map(|b| (a, b)))
        .filter(same)
        .min_by(|a, b| near(*a).total_cmp(&near(*b)))
        .unwrap_or(uv)
}

//! Where two NURBS surfaces meet: the intersection curves over both whole parameter
//! rectangles, traced as dense lists of exact points with the parameters of both surfaces.
//!
//! **Seeds.** Every curve that ends on a side of either parameter rectangle starts where that
//! side (an isocurve) crosses the other surface (`curve_surface.rs`), so these crossings are
//! seeds first, and no piece of curve cut off by a seam is missed however short it is. Curves
//! closed within both rectangles are found from the patches: the two surfaces' polynomial
//! patches (`patch.rs`) are paired wherever their boxes
//! meet, and each pair is subdivided (the less flat or larger patch halved by de Casteljau)
//! while the boxes still meet within the tolerance and neither patch's slab (the planes across
//! its diagonals that hold its control net) separates the other's control points. A pair whose
//! patches are both nearly flat ([`LEAF_FLATNESS`] of their size, or the tolerance) is a leaf:
//! Newton's method with the minimum-norm step (three equations `A(u, v) = B(s, t)`, four
//! unknowns) from the middles of the two patches finds an intersection point near them, if
//! there is one.
//!
//! **Tracing.** From each seed not already on a traced curve, the curve is followed both ways
//! along `T = nA × nB` (the two normals' cross product). Each step predicts `P + h·T`, and
//! corrects onto both surfaces by Newton's method on the four equations `A = B`,
//! `(A − P − h·T)·T = 0`. A step is kept when the tangent turns by at most
//! [`MAX_TURN`] and the true curve's point halfway lies within a tenth of the tolerance
//! ([`NEAR`]) of the Hermite segment (`hermite_fit.rs`) through the two points; otherwise it is
//! halved. A step that leaves either parameter rectangle is replaced by the point where the
//! curve crosses that rectangle's side (the same Newton's method with the crossing parameter
//! fixed), and the trace ends there. A trace that comes back to its seed is closed.
//!
//! **Where tracing stops.** Where the surfaces are tangent (`|nA × nB|` below
//! [`TANGENTIAL`] of `|nA|·|nB|`) the curve's direction is not defined: a seed there is a
//! touching point, reported as such, and a trace reaching such a place ends. Surfaces that
//! overlap (coincide over a region) are tangent everywhere on it, so their common region gives
//! no curves; where a touching point turns out to have the other surface within the tolerance
//! all around it (at [`touching_radius`] along both parameter directions), the surfaces are
//! flagged as coincident instead, and no point is given for it. The overlap's boundary is not
//! traced (decided here; Rhino returns it as curves). A traced curve along which the surfaces meet at so slight
//! an angle that they stay within the tolerance of each other across a band wider than the
//! curve is long is a touching point too. A degenerate side (a pole, where `nA` vanishes) ends a
//! trace as well.

use crate::geometry::small_linear::solve_dense;
use crate::intersect::hermite_fit::{
    TracePoint, bezier_point, distance_to_segment, hermite_segment,
};
use crate::intersect::patch::Patch;
use crate::intersect::piece::{boxes_meet, diagonal};
use crate::intersect::surface_plane::MAX_TURN;
use crate::{Curve, NurbsSurface, Point3, SurfaceDirection, Vector3};

/// Patches are leaves when both deviate from flat by at most this fraction of their size.
pub(crate) const LEAF_FLATNESS: f64 = 0.02;

/// The true curve's point halfway between two traced points lies within this fraction of the
/// tolerance of the Hermite segment through them.
const NEAR: f64 = 0.1;

/// The surfaces are tangent where `|nA × nB|` is below this fraction of `|nA|·|nB|` (the sine
/// of the angle between the normals).
pub(crate) const TANGENTIAL: f64 = 1e-7;

/// How many times a pair of patches may be halved.
const MAX_DEPTH: usize = 48;

/// At most this many leaf pairs are tried as seeds.
pub(crate) const MAX_LEAVES: usize = 100_000;

/// At most this many pairs of patches are looked at in the search for seeds.
pub(crate) const MAX_PAIRS: usize = 4_000_000;

/// Newton iterations per solve.
const NEWTON_STEPS: usize = 40;

/// Iterations of the search for a seed (slower where the surfaces touch: linear, not
/// quadratic, convergence).
const SEED_STEPS: usize = 100;

/// At most this many traced points per curve.
const MAX_ARC_POINTS: usize = 100_000;

/// At most this many touching points are reported.
const MAX_TOUCHING: usize = 10_000;

/// A traced intersection point: the parameters on both surfaces and the point with its unit
/// tangent.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct PairPoint {
    /// The parameters on the first surface.
    pub(crate) a: (f64, f64),
    /// The parameters on the second surface.
    pub(crate) b: (f64, f64),
    /// The point (midway between the two surfaces' points) and its tangent.
    pub(crate) trace: TracePoint,
}

/// What two surfaces have in common.
#[derive(Clone, Debug, Default)]
pub(crate) struct SurfaceSurface {
    /// The traced curves, each at least two points from one end to the other; a closed one
    /// ends on its first point.
    pub(crate) arcs: Vec<Vec<PairPoint>>,
    /// Points where the surfaces touch (are tangent) with the parameters on both.
    pub(crate) touching: Vec<PairPoint>,
    /// Whether the surfaces coincide over some region (not traced).
    pub(crate) coincident: bool,
}

/// The four unknowns `(u, v, s, t)`.
type X = [f64; 4];

/// The extra equation that makes the system square.
#[derive(Clone, Copy)]
enum Constraint {
    /// `(A − origin)·normal = 0`.
    Plane(Point3, Vector3),
    /// The unknown of this index equals the value.
    Fixed(usize, f64),
}

struct Tracer<'a> {
    a: &'a NurbsSurface,
    b: &'a NurbsSurface,
    /// The parameter rectangles: `[u0, u1, v0, v1]` of A, then of B.
    bounds: [[f64; 2]; 4],
    tolerance: f64,
    /// The first and largest step length.
    first_step: f64,
    max_step: f64,
}

/// The intersection of two surfaces within `tolerance` (see the module documentation).
pub(crate) fn surface_surface(
    a: &NurbsSurface,
    b: &NurbsSurface,
    tolerance: f64,
) -> SurfaceSurface {
    let (pa, pb) = (Patch::all(a), Patch::all(b));
    let size = pa
        .iter()
        .chain(&pb)
        .map(|p| diagonal(&p.aabb()))
        .fold(0.0, f64::max)
        .max(tolerance);
    let tracer = Tracer {
        a,
        b,
        bounds: [
            [a.domain_u().t0, a.domain_u().t1],
            [a.domain_v().t0, a.domain_v().t1],
            [b.domain_u().t0, b.domain_u().t1],
            [b.domain_v().t0, b.domain_v().t1],
        ],
        tolerance,
        first_step: size / 64.0,
        max_step: size / 8.0,
    };
    let mut seeds = boundary_seeds(&tracer, true);
    seeds.extend(boundary_seeds(&tracer, false));
    let mut coincident = false;
    seeds.extend(leaf_seeds(&pa, &pb, &tracer, &mut coincident));
    let touch_radius = touching_radius(tolerance, size);
    let mut out = SurfaceSurface {
        coincident,
        ..SurfaceSurface::default()
    };
    for seed in seeds {
        if out
            .arcs
            .iter()
            .any(|arc| on_arc(arc, &seed, tolerance, &tracer.bounds))
        {
            continue;
        }
        let mut touching = |seed: PairPoint| {
            if tracer.coincide_near(&seed, touch_radius) {
                out.coincident = true;
            } else if out.touching.len() < MAX_TOUCHING
                && !out
                    .touching
                    .iter()
                    .any(|t| t.trace.point.distance(seed.trace.point) <= touch_radius)
            {
                out.touching.push(seed);
            }
        };
        let Some(tangent) = tracer.tangent(&seed_x(&seed)) else {
            touching(seed);
            continue;
        };
        let start = PairPoint {
            trace: TracePoint {
                point: seed.trace.point,
                tangent,
            },
            ..seed
        };
        let (forward, closed) = tracer.trace(start, 1.0);
        let arc = if closed {
            forward
        } else {
            let (backward, _) = tracer.trace(start, -1.0);
            let mut arc: Vec<PairPoint> = backward
                .into_iter()
                .rev()
                .map(|mut p| {
                    p.trace.tangent = -p.trace.tangent;
                    p
                })
                .collect();
            arc.pop();
            arc.extend(forward);
            arc
        };
        if arc.len() >= 2 && !tracer.within_touching(&arc) {
            out.arcs.push(arc);
        } else if arc.len() >= 2 {
            touching(arc[arc.len() / 2]);
        } else {
            // No step could be taken either way: the surfaces touch here (a tangency too
            // slight for the tangent test, within the tolerance).
            touching(seed);
        }
    }
    out
}

/// How far apart the seeds found near one touching point can lie: where the surfaces are
/// tangent, a gap within the tolerance allows the parameters to stray by about
/// `√(tolerance / curvature)`, so touching points closer than `√(tolerance · size)` are one.
pub(crate) fn touching_radius(tolerance: f64, size: f64) -> f64 {
    (tolerance * size.max(tolerance)).sqrt()
}

fn seed_x(p: &PairPoint) -> X {
    [p.a.0, p.a.1, p.b.0, p.b.1]
}

/// Whether `seed` lies on the traced curve: within the tolerance of one of its segments and
/// near the parameter box of that segment on both surfaces. The parameters matter at seams,
/// where one point has two parameter pairs and belongs to two different pieces.
fn on_arc(arc: &[PairPoint], seed: &PairPoint, tolerance: f64, bounds: &[[f64; 2]; 4]) -> bool {
    let p = seed.trace.point;
    let x = seed_x(seed);
    let in_box = |a: &PairPoint, b: &PairPoint| {
        let (xa, xb) = (seed_x(a), seed_x(b));
        (0..4).all(|k| {
            // Parameters are not linear along a segment: a generous margin, still far below
            // the jump of a whole period at a seam.
            let slack = (xa[k] - xb[k]).abs() + 0.01 * (bounds[k][1] - bounds[k][0]).abs();
            x[k] >= xa[k].min(xb[k]) - slack && x[k] <= xa[k].max(xb[k]) + slack
        })
    };
    if arc.len() == 1 {
        return arc[0].trace.point.distance(p) <= tolerance && in_box(&arc[0], &arc[0]);
    }
    arc.windows(2).any(|w| {
        let (x, y) = (w[0].trace.point, w[1].trace.point);
        let reach = x.distance(y) + tolerance;
        if x.distance(p) > reach || y.distance(p) > reach || !in_box(&w[0], &w[1]) {
            return false;
        }
        distance_to_segment(&hermite_segment(&w[0].trace, &w[1].trace), p) <= tolerance
    })
}

/// The points where the sides of one surface's parameter rectangle (of A when `of_a`) cross
/// the other surface (`curve_surface.rs`): every curve that ends on a side starts at one of
/// them, however short it is. Sides collapsed to a point (poles) are skipped.
fn boundary_seeds(tracer: &Tracer, of_a: bool) -> Vec<PairPoint> {
    let (own, other) = if of_a {
        (tracer.a, tracer.b)
    } else {
        (tracer.b, tracer.a)
    };
    let (du, dv) = (own.domain_u(), own.domain_v());
    let mut out = Vec::new();
    for (direction, fixed) in [
        (SurfaceDirection::U, dv.t0),
        (SurfaceDirection::U, dv.t1),
        (SurfaceDirection::V, du.t0),
        (SurfaceDirection::V, du.t1),
    ] {
        let Ok(side) = own.isocurve(direction, fixed) else {
            continue;
        };
        let Ok(hits) = other.intersect_curve(&Curve::Nurbs(side), tracer.tolerance) else {
            continue;
        };
        for hit in hits.points {
            let uv = match direction {
                SurfaceDirection::U => (hit.t, fixed),
                SurfaceDirection::V => (fixed, hit.t),
            };
            let x = if of_a {
                [uv.0, uv.1, hit.u, hit.v]
            } else {
                [hit.u, hit.v, uv.0, uv.1]
            };
            if let Some(x) = tracer.seed(x) {
                out.push(tracer.pair_point(&x, Vector3::ZERO));
            }
        }
    }
    out
}

/// Intersection points near the leaves of the patch pairs, in a deterministic order.
fn leaf_seeds(
    pa: &[Patch],
    pb: &[Patch],
    tracer: &Tracer,
    coincident: &mut bool,
) -> Vec<PairPoint> {
    let tolerance = tracer.tolerance;
    let mut out = Vec::new();
    let mut leaves = 0;
    let mut visited = 0usize;
    let boxes_b: Vec<_> = pb.iter().map(Patch::aabb).collect();
    for p0 in pa {
        let box_p = p0.aabb();
        for (q0, box_q) in pb.iter().zip(&boxes_b) {
            if !boxes_meet(&box_p, box_q, tolerance) {
                continue;
            }
            let mut stack: Vec<(Patch, Patch, usize)> = vec![(p0.clone(), q0.clone(), 0)];
            while let Some((p, q, depth)) = stack.pop() {
                visited += 1;
                if visited > MAX_PAIRS {
                    return out;
                }
                let (bp, bq) = (p.aabb(), q.aabb());
                if !boxes_meet(&bp, &bq, tolerance) {
                    continue;
                }
                if same_net(&p, &q, tolerance) {
                    // The same piece of surface twice (a face given to both sides): coincident,
                    // nothing to trace, and no need to subdivide it into thousands of leaves.
                    *coincident = true;
                    continue;
                }
                let (sp, sq) = (p.slab(), q.slab());
                if sp.is_some_and(|s| s.separates(control_points(&q), tolerance))
                    || sq.is_some_and(|s| s.separates(control_points(&p), tolerance))
                {
                    continue;
                }
                let flat_p = p.is_flat(sp.as_ref(), LEAF_FLATNESS, tolerance);
                let flat_q = q.is_flat(sq.as_ref(), LEAF_FLATNESS, tolerance);
                if (flat_p && flat_q) || depth >= MAX_DEPTH {
                    leaves += 1;
                    if leaves > MAX_LEAVES {
                        return out;
                    }
                    let x = [
                        0.5 * (p.u[0] + p.u[1]),
                        0.5 * (p.v[0] + p.v[1]),
                        0.5 * (q.u[0] + q.u[1]),
                        0.5 * (q.v[0] + q.v[1]),
                    ];
                    if let Some(x) = tracer.seed(x) {
                        out.push(tracer.pair_point(&x, Vector3::ZERO));
                    }
                    continue;
                }
                let halve_p = if flat_p == flat_q {
                    diagonal(&bp) >= diagonal(&bq)
                } else {
                    !flat_p
                };
                if halve_p {
                    let (l, r) = p.halve(p.split_in_u());
                    stack.push((r, q.clone(), depth + 1));
                    stack.push((l, q, depth + 1));
                } else {
                    let (l, r) = q.halve(q.split_in_u());
                    stack.push((p.clone(), r, depth + 1));
                    stack.push((p, l, depth + 1));
                }
            }
        }
    }
    out
}

/// Whether two patches have the same control net within the tolerance (in either order of
/// their rows and columns), so that they are the same piece of surface.
fn same_net(p: &Patch, q: &Patch, tolerance: f64) -> bool {
    if p.nu != q.nu || p.nv != q.nv {
        return false;
    }
    let (nu, nv) = (p.nu, p.nv);
    let flips = [(false, false), (true, false), (false, true), (true, true)];
    flips.iter().any(|&(fu, fv)| {
        (0..nu).all(|i| {
            (0..nv).all(|j| {
                let (qi, qj) = (
                    if fu { nu - 1 - i } else { i },
                    if fv { nv - 1 - j } else { j },
                );
                let (a, b) = (p.homogeneous(i, j), q.homogeneous(qi, qj));
                p.point(i, j).distance(q.point(qi, qj)) <= tolerance
                    && (a[3] - b[3]).abs() <= 1e-12 * a[3].abs().max(b[3].abs())
            })
        })
    })
}

/// The control points of a patch.
fn control_points(x: &Patch) -> impl Iterator<Item = Point3> + '_ {
    (0..x.nu).flat_map(move |i| (0..x.nv).map(move |j| x.point(i, j)))
}

impl Tracer<'_> {
    /// The points and first derivatives of both surfaces.
    fn eval(&self, x: &X) -> [(Point3, Vector3, Vector3); 2] {
        let da = self.a.derivatives_unchecked(x[0], x[1], 1);
        let db = self.b.derivatives_unchecked(x[2], x[3], 1);
        [(da.point, da.du, da.dv), (db.point, db.du, db.dv)]
    }

    /// Whether `x` lies in both parameter rectangles (to rounding).
    fn inside(&self, x: &X) -> bool {
        (0..4).all(|k| {
            let [lo, hi] = self.bounds[k];
            let slack = 1e-12 * (hi - lo).abs().max(1.0);
            x[k] >= lo - slack && x[k] <= hi + slack
        })
    }

    fn clamp(&self, x: &mut X) {
        for (k, v) in x.iter_mut().enumerate() {
            *v = v.clamp(self.bounds[k][0], self.bounds[k][1]);
        }
    }

    /// Whether the surfaces coincide around a point where they touch: four points of A at
    /// `radius` from it, along its parameter directions, lie within the tolerance of B.
    fn coincide_near(&self, p: &PairPoint, radius: f64) -> bool {
        let x = seed_x(p);
        let [(_, au, av), _] = self.eval(&x);
        let (lu, lv) = (au.length(), av.length());
        if lu == 0.0 && lv == 0.0 {
            return false;
        }
        // A direction collapsed at a pole moves nowhere; the other one still does.
        let along_u = if lu > 0.0 { radius / lu } else { 0.0 };
        let along_v = if lv > 0.0 { radius / lv } else { 0.0 };
        let offsets = [
            (along_u, 0.0),
            (-along_u, 0.0),
            (0.0, along_v),
            (0.0, -along_v),
        ];
        offsets.iter().all(|&(du, dv)| {
            let u = (x[0] + du).clamp(self.bounds[0][0], self.bounds[0][1]);
            let v = (x[1] + dv).clamp(self.bounds[1][0], self.bounds[1][1]);
            let q = self.a.point_at(u, v);
            self.distance_to_b(q, (x[2], x[3])) <= self.tolerance
        })
    }

    /// The distance from `q` to B: by Gauss–Newton from the parameters `start`, or, where
    /// that does not come within the tolerance, B's closest point.
    fn distance_to_b(&self, q: Point3, start: (f64, f64)) -> f64 {
        let (mut s, mut t) = start;
        for _ in 0..NEWTON_STEPS {
            let d = self.b.derivatives_unchecked(s, t, 1);
            let Some((ds, dt)) = planar_step(d.du, d.dv, q - d.point) else {
                break;
            };
            let next = (
                (s + ds).clamp(self.bounds[2][0], self.bounds[2][1]),
                (t + dt).clamp(self.bounds[3][0], self.bounds[3][1]),
            );
            if next == (s, t) {
                break;
            }
            (s, t) = next;
        }
        let local = self.b.point_at(s, t).distance(q);
        if local <= self.tolerance {
            return local;
        }
        // Across a seam the nearest point has other parameters: the global search.
        self.b
            .closest_point(q)
            .map_or(local, |c| c.distance.min(local))
    }

    /// Whether a traced curve is too short for the angle at which the surfaces meet along it
    /// to tell it from a point: its length times the largest sine of that angle is below the
    /// tolerance, so the surfaces stay within the tolerance of each other across a band wider
    /// than the curve is long (a near-tangency, where rounding traces a sliver of curve).
    fn within_touching(&self, arc: &[PairPoint]) -> bool {
        let length: f64 = arc
            .windows(2)
            .map(|w| w[0].trace.point.distance(w[1].trace.point))
            .sum();
        let sine = arc
            .iter()
            .map(|p| {
                let [(_, au, av), (_, bu, bv)] = self.eval(&seed_x(p));
                let (na, nb) = (au.cross(av), bu.cross(bv));
                na.cross(nb).length() / (na.length() * nb.length())
            })
            .fold(0.0, f64::max);
        length * sine < self.tolerance
    }

    /// The unit tangent `nA × nB` at `x`, or `None` where the surfaces are tangent or one is
    /// degenerate.
    fn tangent(&self, x: &X) -> Option<Vector3> {
        let [(_, au, av), (_, bu, bv)] = self.eval(x);
        let (na, nb) = (au.cross(av), bu.cross(bv));
        let t = na.cross(nb);
        let scale = na.length() * nb.length();
        if scale.is_nan() || scale <= 0.0 || t.length() < TANGENTIAL * scale {
            return None;
        }
        Some(t / t.length())
    }

    fn pair_point(&self, x: &X, tangent: Vector3) -> PairPoint {
        let [(pa, _, _), (pb, _, _)] = self.eval(x);
        PairPoint {
            a: (x[0], x[1]),
            b: (x[2], x[3]),
            trace: TracePoint {
                point: pa.midpoint(pb),
                tangent,
            },
        }
    }

    /// Newton's method with the minimum-norm step from `x`, kept in the rectangles: an
    /// intersection point near `x`.
    fn seed(&self, mut x: X) -> Option<X> {
        for _ in 0..SEED_STEPS {
            let [(pa, au, av), (pb, bu, bv)] = self.eval(&x);
            let r = pa - pb;
            if r.length() <= 1e-3 * self.tolerance {
                return Some(x);
            }
            // J = [au av −bu −bv] (3 × 4). The Gauss–Newton step with a whisker of damping,
            // (JᵀJ + μI)·step = −Jᵀr: the minimum-norm Newton step where the surfaces cross,
            // and still a step towards the touching point where they are tangent (JᵀJ is then
            // of rank 2).
            let cols = [au, av, -bu, -bv];
            let mut m = [[0.0; 4]; 4];
            let mut rhs = [0.0; 4];
            for i in 0..4 {
                for j in 0..4 {
                    m[i][j] = cols[i].dot(cols[j]);
                }
                rhs[i] = cols[i].dot(r);
            }
            let trace = m[0][0] + m[1][1] + m[2][2] + m[3][3];
            for (i, row) in m.iter_mut().enumerate() {
                row[i] += 1e-12 * trace;
            }
            let step = solve_dense(m, rhs, 1e-300)?;
            let before = x;
            for k in 0..4 {
                x[k] -= step[k];
            }
            self.clamp(&mut x);
            if x == before {
                break;
            }
        }
        let [(pa, _, _), (pb, _, _)] = self.eval(&x);
        (pa.distance(pb) <= NEAR * self.tolerance).then_some(x)
    }

    /// Newton's method on `A = B` and the constraint, from `x`.
    fn correct(&self, mut x: X, constraint: Constraint) -> Option<X> {
        let mut converged = false;
        for _ in 0..NEWTON_STEPS {
            let [(pa, au, av), (pb, bu, bv)] = self.eval(&x);
            let d = pa - pb;
            let (g, row) = match constraint {
                Constraint::Plane(o, n) => ((pa - o).dot(n), [au.dot(n), av.dot(n), 0.0, 0.0]),
                Constraint::Fixed(k, value) => {
                    let mut row = [0.0; 4];
                    row[k] = 1.0;
                    (x[k] - value, row)
                }
            };
            let m = [
                [au.x, av.x, -bu.x, -bv.x],
                [au.y, av.y, -bu.y, -bv.y],
                [au.z, av.z, -bu.z, -bv.z],
                row,
            ];
            let step = solve_dense(m, [d.x, d.y, d.z, g], 1e-300)?;
            for k in 0..4 {
                x[k] -= step[k];
            }
            if converged {
                break;
            }
            let small = (0..4).all(|k| {
                step[k].abs() <= 1e-14 * (self.bounds[k][1] - self.bounds[k][0]).abs().max(1.0)
            });
            if d.length() <= 1e-3 * self.tolerance && small {
                // One more step polishes to rounding.
                converged = true;
            }
        }
        let [(pa, _, _), (pb, _, _)] = self.eval(&x);
        (x.iter().all(|v| v.is_finite()) && pa.distance(pb) <= 0.01 * self.tolerance).then_some(x)
    }

    /// Follows the curve from `start` in the direction `sign · tangent` until it leaves a
    /// rectangle, comes back to `start`, or cannot go on. The points, the first being `start`,
    /// with tangents in the direction of travel; and whether the trace closed.
    fn trace(&self, start: PairPoint, sign: f64) -> (Vec<PairPoint>, bool) {
        let mut first = start;
        first.trace.tangent = start.trace.tangent * sign;
        let mut points = vec![first];
        let mut h = self.first_step;
        let min_step = 1e-3 * self.tolerance;
        while points.len() < MAX_ARC_POINTS {
            let current = *points.last().unwrap();
            let Some((next, on_side)) = self.step(&current, h) else {
                h *= 0.5;
                if h < min_step {
                    break;
                }
                continue;
            };
            if points.len() >= 3 {
                let segment = hermite_segment(&current.trace, &next.trace);
                if distance_to_segment(&segment, first.trace.point) <= self.tolerance {
                    points.push(first);
                    return (points, true);
                }
            }
            if next.trace.point.distance(current.trace.point) <= min_step {
                break;
            }
            points.push(next);
            if on_side {
                break;
            }
            h = (h * 2.0).min(self.max_step);
        }
        (points, false)
    }

    /// One step of length about `h` from `current`: the next point, and whether it lies on a
    /// side of a rectangle (where the trace ends). `None` when the step must be shorter.
    fn step(&self, current: &PairPoint, h: f64) -> Option<(PairPoint, bool)> {
        let t = current.trace.tangent;
        let x0 = seed_x(current);
        let [(_, au, av), (_, bu, bv)] = self.eval(&x0);
        let move_a = planar_step(au, av, t * h)?;
        let move_b = planar_step(bu, bv, t * h)?;
        let guess = [
            x0[0] + move_a.0,
            x0[1] + move_a.1,
            x0[2] + move_b.0,
            x0[3] + move_b.1,
        ];
        let target = current.trace.point + t * h;
        let mut on_side = false;
        let mut x = self.correct(guess, Constraint::Plane(target, t))?;
        // The corrector must stay near the prediction in the parameters too: near a pole
        // (where one parameter sweeps fast) it can land on the same point's other parameters
        // across a seam, skipping the side the curve crosses.
        if (0..4).any(|k| {
            let span = (self.bounds[k][1] - self.bounds[k][0]).abs();
            (x[k] - guess[k]).abs() > (guess[k] - x0[k]).abs() + 0.01 * span
        }) {
            return None;
        }
        if !self.inside(&x) {
            x = self.to_side(&x0, &x)?;
            on_side = true;
        }
        let tangent = self.tangent(&x)?;
        let tangent = if tangent.dot(t) < 0.0 {
            -tangent
        } else {
            tangent
        };
        if tangent.dot(t).clamp(-1.0, 1.0).acos() > MAX_TURN {
            return None;
        }
        let next = self.pair_point(&x, tangent);
        if (next.trace.point - current.trace.point).dot(t) <= 0.0 {
            return None;
        }
        // The true point halfway, against the Hermite segment.
        let segment = hermite_segment(&current.trace, &next.trace);
        let middle = bezier_point(&segment, 0.5);
        let chord = (next.trace.point - current.trace.point).normalize_or_zero();
        let halfway = [
            0.5 * (x0[0] + x[0]),
            0.5 * (x0[1] + x[1]),
            0.5 * (x0[2] + x[2]),
            0.5 * (x0[3] + x[3]),
        ];
        let m = self.correct(halfway, Constraint::Plane(middle, chord))?;
        let [(pm, _, _), _] = self.eval(&m);
        if pm.distance(middle) > NEAR * self.tolerance {
            return None;
        }
        Some((next, on_side))
    }

    /// Where the curve from `from` (inside) towards `to` (outside) crosses the side of a
    /// rectangle: the crossing parameter fixed to the side, the rest solved.
    fn to_side(&self, from: &X, to: &X) -> Option<X> {
        // The sides crossed, the first crossed (smallest fraction of the way) first.
        let mut crossed: Vec<(f64, usize, f64)> = (0..4)
            .filter_map(|k| {
                let [lo, hi] = self.bounds[k];
                let side = if to[k] < lo {
                    lo
                } else if to[k] > hi {
                    hi
                } else {
                    return None;
                };
                let f = (side - from[k]) / (to[k] - from[k]);
                Some((f.clamp(0.0, 1.0), k, side))
            })
            .collect();
        crossed.sort_by(|a, b| a.0.total_cmp(&b.0));
        for (f, k, side) in crossed {
            let mut guess = [0.0; 4];
            for i in 0..4 {
                guess[i] = from[i] + (to[i] - from[i]) * f;
            }
            guess[k] = side;
            if let Some(mut x) = self.correct(guess, Constraint::Fixed(k, side))
                && self.inside(&x)
            {
                self.clamp(&mut x);
                return Some(x);
            }
        }
        None
    }
}

/// The parameter change `(du, dv)` whose first-order move `du·Su + dv·Sv` is nearest `d`.
fn planar_step(su: Vector3, sv: Vector3, d: Vector3) -> Option<(f64, f64)> {
    let (a, b, c) = (su.dot(su), su.dot(sv), sv.dot(sv));
    let det = a * c - b * b;
    if !det.is_finite() || det.abs() <= 1e-300 {
        return None;
    }
    let (p, q) = (su.dot(d), sv.dot(d));
    Some(((c * p - b * q) / det, (a * q - b * p) / det))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Plane, Sphere};

    fn plane_surface(z: f64, half: f64) -> NurbsSurface {
        let p = |x: f64, y: f64| Point3::new(x, y, z);
        NurbsSurface::non_rational(
            1,
            1,
            vec![
                vec![p(-half, -half), p(-half, half)],
                vec![p(half, -half), p(half, half)],
            ],
            vec![0.0, 1.0],
            vec![0.0, 1.0],
        )
        .unwrap()
    }

    #[test]
    fn a_sphere_and_a_plane_meet_in_a_circle() {
        let sphere = Sphere::new(Point3::ORIGIN, 2.0)
            .unwrap()
            .to_nurbs()
            .unwrap();
        let plane = plane_surface(1.0, 5.0);
        let x = surface_surface(&sphere, &plane, 1e-9);
        assert!(!x.arcs.is_empty());
        let r = 3.0f64.sqrt();
        for arc in &x.arcs {
            for p in arc {
                assert!((p.trace.point.z - 1.0).abs() < 1e-9);
                let rho = (p.trace.point.x.powi(2) + p.trace.point.y.powi(2)).sqrt();
                assert!((rho - r).abs() < 1e-9, "{rho}");
            }
        }
        let _ = Plane::WORLD_XY;
    }
}

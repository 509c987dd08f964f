//! Where a NURBS surface meets a plane: the section curves over the whole parameter rectangle,
//! traced as dense lists of exact points, and the points where the surface only touches the
//! plane.
//!
//! The signed distance from the plane, `f(u, v) = (S(u, v) − O)·n`, is a rational function
//! whose numerator has, on each polynomial patch, the Bernstein coefficients `w_ij·d_ij` (the
//! weights times the control points' distances, `patch.rs`). Its zero set is the section.
//! Patches are subdivided (de Casteljau, across the longer side) until each is simple:
//!
//! - **no section:** every control point is more than the tolerance on one side of the plane;
//! - **in the plane:** every control point lies within the tolerance of it (a flat region;
//!   planar faces are sectioned elsewhere, so nothing is traced);
//! - **a graph:** the numerator's differences in `u` (its derivative's coefficients) have one
//!   sign, so `f` is monotone in `u` and the section is a set of arcs `u = g(v)` over disjoint
//!   `v` intervals, each ending on the patch's boundary; or the same with `u` and `v`
//!   exchanged. The intervals are where `f` has opposite signs on the two sides `u = u0` and
//!   `u = u1`; their ends are roots of `f` on those sides (`bernstein.rs`) or the patch's other
//!   sides. Each arc is traced by solving `f(·, v) = 0` on `[u0, u1]` (bracketed) at values of
//!   `v` refined until consecutive points turn by at most [`MAX_TURN`] and the true point
//!   between them lies within a tenth of the tolerance of the Hermite segment
//!   (`hermite_fit.rs`) through them. Where a whole side of the patch collapses to a point (a
//!   pole or an apex) and lies in the plane, `f` vanishes along that side and the arc's end
//!   there is the root of `∂f/∂v` instead;
//! - **touching:** a patch that is not monotone either way but does not clearly change sign,
//!   once it is small (`√(tolerance · size)`): the surface touches the plane there at most;
//!   Newton's method on `∇f = 0` finds the extremum, a touching point when `|f|` is within the
//!   tolerance.
//!
//! A patch still not simple after [`MAX_DEPTH`] halvings is a singular crossing (a saddle
//! tangent to the plane); it is treated as touching, so the arcs around it end at its border.

use crate::intersect::bernstein;
use crate::intersect::hermite_fit::{TracePoint, distance_to_segment, hermite_segment};
use crate::intersect::patch::Patch;
use crate::intersect::piece::diagonal;
use crate::{NurbsSurface, Plane, Point3, Vector3};

/// The largest turning between consecutive traced points, 5° (the Hermite segments are then
/// within about 1e-11 of the radius of curvature of the curve).
pub(crate) const MAX_TURN: f64 = 5.0 * std::f64::consts::PI / 180.0;

/// How many times a patch may be halved.
const MAX_DEPTH: usize = 40;

/// How many times an interval between traced points may be halved.
const MAX_TRACE_DEPTH: usize = 30;

/// Traced points of an arc before refinement (besides its ends).
const INITIAL_STEPS: usize = 4;

/// Steps of the bracketed root search of a section point.
const ROOT_STEPS: usize = 200;

/// A traced section point with its surface parameters.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct SectionPoint {
    /// The surface parameters.
    pub(crate) uv: (f64, f64),
    /// The point and its tangent along the arc.
    pub(crate) trace: TracePoint,
}

/// What a surface has in common with a plane.
#[derive(Clone, Debug, Default)]
pub(crate) struct SurfaceSection {
    /// The arcs, each a list of at least two traced points from one end to the other; arcs
    /// meet at patch borders (and at seams) without being joined here.
    pub(crate) arcs: Vec<Vec<SectionPoint>>,
    /// Points where the surface touches the plane without crossing it.
    pub(crate) touching: Vec<((f64, f64), Point3)>,
}

/// The evaluation of `f` and its partial derivatives with the surface's.
struct Eval {
    f: f64,
    fu: f64,
    fv: f64,
    point: Point3,
    du: Vector3,
    dv: Vector3,
}

struct Tracer<'a> {
    surface: &'a NurbsSurface,
    plane: &'a Plane,
    tolerance: f64,
    /// Below this a Bernstein difference counts as zero (rounding of the coefficients).
    noise: f64,
    /// Patches smaller than this that do not clearly change sign are touching candidates.
    leaf_size: f64,
    out: SurfaceSection,
}

/// The section of `surface` by `plane` within `tolerance` (see the module documentation).
pub(crate) fn surface_plane(
    surface: &NurbsSurface,
    plane: &Plane,
    tolerance: f64,
) -> SurfaceSection {
    let patches = Patch::all(surface);
    let mut largest = 0.0_f64;
    let mut size = 0.0_f64;
    for p in &patches {
        let (c, _) = p.plane_values(plane);
        largest = c.iter().fold(largest, |m, x| m.max(x.abs()));
        size = size.max(diagonal(&p.aabb()));
    }
    let mut tracer = Tracer {
        surface,
        plane,
        tolerance,
        noise: 1e-12 * largest.max(f64::MIN_POSITIVE),
        leaf_size: (tolerance * size.max(tolerance)).sqrt(),
        out: SurfaceSection::default(),
    };
    let mut stack: Vec<(Patch, usize)> = patches.into_iter().map(|p| (p, 0)).collect();
    stack.reverse();
    while let Some((patch, depth)) = stack.pop() {
        if let Some((a, b)) = tracer.classify(&patch, depth) {
            stack.push((b, depth + 1));
            stack.push((a, depth + 1));
        }
    }
    tracer.out
}

/// The sign of a list of differences: `Some(true)` if all are at least `-noise` with one above
/// `noise`, `Some(false)` for the mirror case, `None` otherwise.
fn one_sign(values: impl Iterator<Item = f64> + Clone, noise: f64) -> Option<bool> {
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for x in values {
        lo = lo.min(x);
        hi = hi.max(x);
    }
    if lo >= -noise && hi > noise {
        Some(true)
    } else if hi <= noise && lo < -noise {
        Some(false)
    } else {
        None
    }
}

impl Tracer<'_> {
    fn eval(&self, u: f64, v: f64) -> Eval {
        let d = self.surface.derivatives_unchecked(u, v, 1);
        let n = self.plane.z_axis;
        Eval {
            f: (d.point - self.plane.origin).dot(n),
            fu: d.du.dot(n),
            fv: d.dv.dot(n),
            point: d.point,
            du: d.du,
            dv: d.dv,
        }
    }

    /// Handles one patch; returns its halves when it must be subdivided.
    fn classify(&mut self, patch: &Patch, depth: usize) -> Option<(Patch, Patch)> {
        let (c, w) = patch.plane_values(self.plane);
        let (nu, nv) = (patch.nu, patch.nv);
        let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
        for (x, y) in c.iter().zip(&w) {
            let d = x / y;
            lo = lo.min(d);
            hi = hi.max(d);
        }
        let tol = self.tolerance;
        if lo > tol || hi < -tol || lo.is_nan() || hi.is_nan() {
            return None;
        }
        if lo >= -tol && hi <= tol {
            return None;
        }
        let diff_u = (0..nu - 1).flat_map(|i| (0..nv).map(move |j| (i, j)));
        let diff_u = diff_u.map(|(i, j)| c[(i + 1) * nv + j] - c[i * nv + j]);
        let diff_v = (0..nu).flat_map(|i| (0..nv - 1).map(move |j| (i, j)));
        let diff_v = diff_v.map(|(i, j)| c[i * nv + j + 1] - c[i * nv + j]);
        if one_sign(diff_u, self.noise).is_some() {
            self.trace_graph(patch, &c, &w, true);
            return None;
        }
        if one_sign(diff_v, self.noise).is_some() {
            self.trace_graph(patch, &c, &w, false);
            return None;
        }
        let size = diagonal(&patch.aabb());
        let crosses = lo < -tol && hi > tol;
        if depth >= MAX_DEPTH || (!crosses && size <= self.leaf_size) {
            self.touching(patch);
            return None;
        }
        // Halve across the side along which the control net is longer.
        let along_u = patch.point(0, 0).distance(patch.point(nu - 1, 0))
            + patch.point(0, nv - 1).distance(patch.point(nu - 1, nv - 1));
        let along_v = patch.point(0, 0).distance(patch.point(0, nv - 1))
            + patch.point(nu - 1, 0).distance(patch.point(nu - 1, nv - 1));
        Some(patch.halve(along_u >= along_v))
    }

    /// The extremum of `f` in a small patch, kept as a touching point when within the
    /// tolerance of the plane.
    fn touching(&mut self, patch: &Patch) {
        let (mut u, mut v) = (
            0.5 * (patch.u[0] + patch.u[1]),
            0.5 * (patch.v[0] + patch.v[1]),
        );
        for _ in 0..30 {
            let d = self.surface.derivatives_unchecked(u, v, 2);
            let n = self.plane.z_axis;
            let (gu, gv) = (d.du.dot(n), d.dv.dot(n));
            let (huu, huv, hvv) = (d.duu.dot(n), d.duv.dot(n), d.dvv.dot(n));
            let det = huu * hvv - huv * huv;
            if det == 0.0 || !det.is_finite() {
                break;
            }
            let nu_ = (u - (hvv * gu - huv * gv) / det).clamp(patch.u[0], patch.u[1]);
            let nv_ = (v - (huu * gv - huv * gu) / det).clamp(patch.v[0], patch.v[1]);
            if nu_ == u && nv_ == v {
                break;
            }
            (u, v) = (nu_, nv_);
        }
        let e = self.eval(u, v);
        if e.f.abs() <= self.tolerance {
            self.out.touching.push(((u, v), e.point));
        }
    }

    /// Traces the arcs of a patch on which `f` is monotone in `u` (`solve_u`) or in `v`.
    fn trace_graph(&mut self, patch: &Patch, c: &[f64], w: &[f64], solve_u: bool) {
        // x: the solved coordinate, y: the one marched along.
        let (x_range, y_range) = if solve_u {
            (patch.u, patch.v)
        } else {
            (patch.v, patch.u)
        };
        let (nu, nv) = (patch.nu, patch.nv);
        // The Bernstein rows along y at x = x0 and x = x1.
        let side = |at_end: bool| -> (Vec<f64>, Vec<f64>) {
            if solve_u {
                let i = if at_end { nu - 1 } else { 0 };
                (
                    (0..nv).map(|j| c[i * nv + j]).collect(),
                    (0..nv).map(|j| w[i * nv + j]).collect(),
                )
            } else {
                let j = if at_end { nv - 1 } else { 0 };
                (
                    (0..nu).map(|i| c[i * nv + j]).collect(),
                    (0..nu).map(|i| w[i * nv + j]).collect(),
                )
            }
        };
        let mut breaks = vec![y_range[0], y_range[1]];
        // Places where a side touches the plane: where no arc passes, the surface touches the
        // plane there (f is monotone across the patch, so its extremum is on a side).
        let mut touches: Vec<(f64, f64)> = Vec::new();
        for at_end in [false, true] {
            let (n, ww) = side(at_end);
            let all_in_plane = n
                .iter()
                .zip(&ww)
                .all(|(a, b)| (a / b).abs() <= self.tolerance);
            if all_in_plane {
                continue;
            }
            let x = x_range[usize::from(at_end)];
            for root in bernstein::roots(&n, &ww, self.tolerance) {
                let y = y_range[0] + (y_range[1] - y_range[0]) * root.s;
                let y = self.polish_side(x, y, y_range, solve_u);
                if root.touching {
                    touches.push((x, y));
                }
                if y > y_range[0] && y < y_range[1] {
                    breaks.push(y);
                }
            }
        }
        breaks.sort_by(f64::total_cmp);
        breaks.dedup();
        let f_at = |x: f64, y: f64| {
            let (u, v) = if solve_u { (x, y) } else { (y, x) };
            self.eval(u, v).f
        };
        let mut components: Vec<[f64; 2]> = Vec::new();
        for pair in breaks.windows(2) {
            let mid = 0.5 * (pair[0] + pair[1]);
            if f_at(x_range[0], mid) * f_at(x_range[1], mid) > 0.0 {
                continue;
            }
            match components.last_mut() {
                Some(last) if last[1] == pair[0] => last[1] = pair[1],
                _ => components.push([pair[0], pair[1]]),
            }
        }
        for (x, y) in touches {
            if components.iter().any(|c| y >= c[0] && y <= c[1]) {
                continue;
            }
            let (u, v) = if solve_u { (x, y) } else { (y, x) };
            let e = self.eval(u, v);
            if e.f.abs() <= self.tolerance {
                self.out.touching.push(((u, v), e.point));
            }
        }
        for [ya, yb] in components {
            let arc = self.trace_arc(x_range, [ya, yb], solve_u);
            if arc.len() >= 2 {
                self.out.arcs.push(arc);
            }
        }
    }

    /// A root of `f(x, ·)` near `y` polished by bisection where it is bracketed nearby.
    fn polish_side(&self, x: f64, y: f64, range: [f64; 2], solve_u: bool) -> f64 {
        let f = |y: f64| {
            let (u, v) = if solve_u { (x, y) } else { (y, x) };
            self.eval(u, v).f
        };
        let h = 1e-9 * (range[1] - range[0]);
        let (mut a, mut b) = ((y - h).max(range[0]), (y + h).min(range[1]));
        let (mut fa, fb) = (f(a), f(b));
        if fa == 0.0 {
            return a;
        }
        if fb == 0.0 {
            return b;
        }
        if fa.signum() == fb.signum() {
            return y;
        }
        for _ in 0..ROOT_STEPS {
            let m = 0.5 * (a + b);
            if m <= a || m >= b {
                break;
            }
            let fm = f(m);
            if fm == 0.0 {
                return m;
            }
            if fm.signum() == fa.signum() {
                (a, fa) = (m, fm);
            } else {
                b = m;
            }
        }
        0.5 * (a + b)
    }

    /// The section point at `y`: the root of `f(·, y)` in `x_range` (see [`Self::solve`]),
    /// with its tangent.
    fn point_at(&self, x_range: [f64; 2], y: f64, solve_u: bool) -> SectionPoint {
        let x = self.solve(x_range, y, solve_u);
        let (u, v) = if solve_u { (x, y) } else { (y, x) };
        let e = self.eval(u, v);
        let (sx, sy, fx, fy) = if solve_u {
            (e.du, e.dv, e.fu, e.fv)
        } else {
            (e.dv, e.du, e.fv, e.fu)
        };
        // dP/dy along the arc, x' = −f_y / f_x.
        let along = if fx != 0.0 && (fy / fx).is_finite() {
            sx * (-fy / fx) + sy
        } else {
            sy
        };
        let normal = e.du.cross(e.dv);
        let mut tangent = self.plane.z_axis.cross(normal).normalize_or_zero();
        if tangent.dot(along) < 0.0 {
            tangent = -tangent;
        }
        if tangent == Vector3::ZERO {
            tangent = along.normalize_or_zero();
        }
        SectionPoint {
            uv: (u, v),
            trace: TracePoint {
                point: e.point,
                tangent,
            },
        }
    }

    /// The root of `f(·, y)` in `x_range`: bracketed bisection with secant steps (Illinois);
    /// where `f` vanishes along the whole line (a collapsed side lying in the plane), the root
    /// of the derivative across it; where nothing is bracketed, the nearer end.
    fn solve(&self, x_range: [f64; 2], y: f64, solve_u: bool) -> f64 {
        let eval = |x: f64| {
            let (u, v) = if solve_u { (x, y) } else { (y, x) };
            self.eval(u, v)
        };
        let (ea, eb) = (eval(x_range[0]), eval(x_range[1]));
        let degenerate = ea.f.abs() <= 1e-3 * self.tolerance
            && eb.f.abs() <= 1e-3 * self.tolerance
            && eval(0.5 * (x_range[0] + x_range[1])).f.abs() <= 1e-3 * self.tolerance;
        let g = |e: &Eval| -> f64 {
            if degenerate {
                if solve_u { e.fv } else { e.fu }
            } else {
                e.f
            }
        };
        let (mut a, mut b) = (x_range[0], x_range[1]);
        let (mut ga, mut gb) = (g(&ea), g(&eb));
        if ga == 0.0 {
            return a;
        }
        if gb == 0.0 {
            return b;
        }
        if ga.signum() == gb.signum() {
            return if ga.abs() <= gb.abs() { a } else { b };
        }
        let mut side = 0i8;
        for _ in 0..ROOT_STEPS {
            let m = (a * gb - b * ga) / (gb - ga);
            let m = if m > a && m < b { m } else { 0.5 * (a + b) };
            if m <= a || m >= b {
                break;
            }
            let gm = g(&eval(m));
            if gm == 0.0 {
                return m;
            }
            if gm.signum() == ga.signum() {
                (a, ga) = (m, gm);
                if side == -1 {
                    gb *= 0.5;
                }
                side = -1;
            } else {
                (b, gb) = (m, gm);
                if side == 1 {
                    ga *= 0.5;
                }
                side = 1;
            }
            if b - a <= 4.0 * f64::EPSILON * a.abs().max(b.abs()).max(1.0) {
                break;
            }
        }
        if ga.abs() <= gb.abs() { a } else { b }
    }

    /// The traced points of the arc over `y_range`, refined (see the module documentation).
    fn trace_arc(&self, x_range: [f64; 2], y_range: [f64; 2], solve_u: bool) -> Vec<SectionPoint> {
        let mut points: Vec<SectionPoint> = (0..=INITIAL_STEPS)
            .map(|k| {
                let y = if k == INITIAL_STEPS {
                    y_range[1]
                } else {
                    y_range[0] + (y_range[1] - y_range[0]) * k as f64 / INITIAL_STEPS as f64
                };
                self.point_at(x_range, y, solve_u)
            })
            .collect();
        let y_of = |p: &SectionPoint| if solve_u { p.uv.1 } else { p.uv.0 };
        let mut out = vec![points[0]];
        // Refine each interval depth-first, left to right.
        let mut stack: Vec<(SectionPoint, SectionPoint, usize)> =
            points.windows(2).rev().map(|w| (w[0], w[1], 0)).collect();
        points.clear();
        while let Some((a, b, depth)) = stack.pop() {
            let fine = depth >= MAX_TRACE_DEPTH || {
                let ym = 0.5 * (y_of(&a) + y_of(&b));
                let m = self.point_at(x_range, ym, solve_u);
                let turn = a.trace.tangent.dot(b.trace.tangent) >= MAX_TURN.cos();
                let near = turn
                    && distance_to_segment(&hermite_segment(&a.trace, &b.trace), m.trace.point)
                        <= 0.1 * self.tolerance;
                if !near {
                    stack.push((m, b, depth + 1));
                    stack.push((a, m, depth + 1));
                }
                near
            };
            if fine {
                out.push(b);
            }
        }
        // Tangents at points where the surface gave none: along the chord.
        for k in 0..out.len() {
            if out[k].trace.tangent == Vector3::ZERO {
                let (p, q) = if k + 1 < out.len() {
                    (out[k].trace.point, out[k + 1].trace.point)
                } else if k > 0 {
                    (out[k - 1].trace.point, out[k].trace.point)
                } else {
                    continue;
                };
                out[k].trace.tangent = (q - p).normalize_or_zero();
            }
        }
        out.dedup_by(|b, a| a.trace.point == b.trace.point);
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Cylinder, Sphere};

    #[test]
    fn a_sphere_cut_off_centre_gives_a_circle_of_the_right_radius() {
        let s = Sphere::new(Point3::new(0.0, 0.0, 0.0), 2.0)
            .unwrap()
            .to_nurbs()
            .unwrap();
        let plane =
            Plane::from_normal(Point3::new(0.0, 0.0, 1.0), Vector3::new(0.3, 0.1, 1.0)).unwrap();
        let section = surface_plane(&s, &plane, 1e-9);
        assert!(section.touching.is_empty());
        assert!(!section.arcs.is_empty());
        let d = plane.origin.to_vector().dot(plane.z_axis);
        let r = (4.0 - d * d).sqrt();
        let centre = Point3::from_vector(plane.z_axis * d);
        for arc in &section.arcs {
            for p in arc {
                assert!((p.trace.point.distance(centre) - r).abs() < 1e-12);
                assert!(plane.signed_distance_to(p.trace.point).abs() < 1e-12);
                assert!(s.point_at(p.uv.0, p.uv.1).distance(p.trace.point) < 1e-15);
            }
        }
    }

    #[test]
    fn a_tangent_plane_touches_a_sphere_once() {
        let s = Sphere::new(Point3::new(0.0, 0.0, 0.0), 2.0)
            .unwrap()
            .to_nurbs()
            .unwrap();
        let n = Vector3::new(1.0, 2.0, 0.5).normalize_or_zero();
        let plane = Plane::from_normal(Point3::from_vector(n * 2.0), n).unwrap();
        let section = surface_plane(&s, &plane, 1e-7);
        assert!(section.arcs.is_empty(), "{:?}", section.arcs.len());
        assert!(!section.touching.is_empty());
        for (_, p) in &section.touching {
            assert!(p.distance(Point3::from_vector(n * 2.0)) < 1e-3);
        }
    }

    #[test]
    fn a_plane_through_a_cylinders_axis_gives_two_generators() {
        let c = Cylinder::new(crate::Plane::WORLD_XY, 1.0, 3.0)
            .unwrap()
            .to_nurbs()
            .unwrap();
        let plane = Plane::from_normal(Point3::ORIGIN, Vector3::new(1.0, 1.0, 0.0)).unwrap();
        let section = surface_plane(&c, &plane, 1e-9);
        for arc in &section.arcs {
            for p in arc {
                let q = p.trace.point;
                assert!(((q.x * q.x + q.y * q.y).sqrt() - 1.0).abs() < 1e-12);
                assert!((q.x + q.y).abs() < 1e-12);
            }
        }
        let heights: f64 = section
            .arcs
            .iter()
            .map(|a| (a[a.len() - 1].trace.point.z - a[0].trace.point.z).abs())
            .sum();
        assert!((heights - 6.0).abs() < 1e-12, "{heights}");
    }
}

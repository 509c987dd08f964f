//! The closest point on a surface to a test point (Grasshopper's Pull and Surface Closest
//! Point): the global minimum of the distance over the whole parameter rectangle.
//!
//! The minimum may lie inside the surface, where the segment to the test point is normal to
//! it, or on a boundary edge, at a corner, or on a crease (an interior knot of full
//! multiplicity), where no such normal foot exists. The search therefore:
//!
//! 1. splits the domain into its polynomial patches (knot spans in `u` × `v`) and orders them by
//!    a lower bound of their distance, the distance to the bounding box of their control points
//!    (the convex hull property, valid for positive weights); patches whose bound exceeds the
//!    best distance found so far are skipped;
//! 2. samples each remaining patch on a small grid and polishes the best discrete local minima
//!    with a Newton iteration on `f = ½|S − P|²`, confined to the patch rectangle by an active
//!    set (a coordinate at a bound whose gradient points outwards is held fixed), with a
//!    backtracking line search that never lets `f` increase;
//! 3. searches the four boundary curves and every crease line in one dimension the same way;
//! 4. evaluates the four corners.
//!
//! The smallest distance wins.

use crate::curve::nurbs::basis::{MAX_ORDER, basis_functions, span_index};
use crate::surface::bezier_patch::{BezierPatches, MAX_PATCH_DEGREE, bernstein_table};
use crate::surface::check_parameters;
use crate::surface::direction::SurfaceDirection;
use crate::surface::direction::SurfaceSide;
use crate::{Error, NurbsSurface, Point3, Result, SurfaceDerivatives};

/// The closest point on a surface to a test point.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SurfaceClosestPoint {
    /// The `u` parameter of the closest point.
    pub u: f64,
    /// The `v` parameter of the closest point.
    pub v: f64,
    /// The closest point, `S(u, v)`.
    pub point: Point3,
    /// The distance from the test point to `point`.
    pub distance: f64,
}

/// At most this many Newton iterations per start.
const MAX_ITERATIONS: usize = 64;
/// At most this many halvings of a step in the line search.
const MAX_HALVINGS: usize = 40;
/// How many ulps of the largest coordinate (of the surface point and the test point) the
/// evaluation of a point may be off by: 16. A squared distance that rises by no more than the
/// rounding this causes is not a rise, so the line search accepts a step that changes `f` only
/// at rounding level and Newton's method goes on to the root of the gradient, to rounding level
/// in the parameters, instead of stopping where `f` no longer decreases measurably (about 1e-8
/// of the patch short of it, since `f` is flat to second order there).
const NOISE_ULPS: f64 = 16.0;
/// At most this many discrete local minima of a patch's sample grid are polished.
const STARTS_PER_PATCH: usize = 3;

/// A parameter rectangle `[u0, u1] × [v0, v1]`.
#[derive(Clone, Copy, Debug)]
struct Rect {
    u: [f64; 2],
    v: [f64; 2],
}

/// The best candidate so far, with its squared distance.
#[derive(Clone, Copy, Debug)]
struct Best {
    u: f64,
    v: f64,
    point: Point3,
    distance_squared: f64,
}

impl Best {
    fn offer(&mut self, u: f64, v: f64, point: Point3, distance_squared: f64) {
        if distance_squared < self.distance_squared {
            *self = Self {
                u,
                v,
                point,
                distance_squared,
            };
        }
    }
}

impl NurbsSurface {
    /// The point of the surface closest to `test`, searched globally over the whole domain:
    /// edges, corners and creases included. Where several points are equally close (a test
    /// point on a sphere's axis, or at its centre) one of them is returned.
    ///
    /// # Errors
    /// [`Error::NotFinite`] if the test point is not finite.
    pub fn closest_point(&self, test: Point3) -> Result<SurfaceClosestPoint> {
        if !test.is_finite() {
            return Err(Error::NotFinite { what: "test point" });
        }
        let breaks_u = self.span_breaks(SurfaceDirection::U);
        let breaks_v = self.span_breaks(SurfaceDirection::V);
        let (du, dv) = (self.domain_u(), self.domain_v());

        // 4. The corners, which also seed the best distance.
        let mut best = Best {
            u: du.t0,
            v: dv.t0,
            point: Point3::ORIGIN,
            distance_squared: f64::INFINITY,
        };
        for u in [du.t0, du.t1] {
            for v in [dv.t0, dv.t1] {
                let p = self.point_at(u, v);
                best.offer(u, v, p, p.distance_squared(test));
            }
        }

        // Lower bounds of the distance to each patch.
        let (nu, nv) = (breaks_u.len() - 1, breaks_v.len() - 1);
        let mut bounds = Vec::with_capacity(nu * nv);
        for &start_u in &breaks_u[..nu] {
            let su = span_index(self.degree_u(), self.knots_u(), start_u);
            for &start_v in &breaks_v[..nv] {
                let sv = span_index(self.degree_v(), self.knots_v(), start_v);
                bounds.push(self.span_box_distance_squared(su, sv, test));
            }
        }

        // 1 and 2. The patches, nearest bound first. Up to bicubic, each patch that its
        // B-spline box lets through is converted to Bézier form (two small products with the
        // spans' extraction matrices), which gives a tighter box and its sample grid.
        let mut order: Vec<usize> = (0..nu * nv).collect();
        order.sort_by(|&x, &y| bounds[x].total_cmp(&bounds[y]));
        let samples_u = samples_per_span(self.degree_u());
        let samples_v = samples_per_span(self.degree_v());
        let samples = [samples_u, samples_v];
        let mut grid = vec![0.0; samples_u * samples_v];
        let spans_u: Vec<usize> = breaks_u[..nu]
            .iter()
            .map(|&t| span_index(self.degree_u(), self.knots_u(), t))
            .collect();
        let spans_v: Vec<usize> = breaks_v[..nv]
            .iter()
            .map(|&t| span_index(self.degree_v(), self.knots_v(), t))
            .collect();
        let bezier = self.degree_u() <= MAX_PATCH_DEGREE && self.degree_v() <= MAX_PATCH_DEGREE;
        let mut patches = BezierPatches::new(self, &spans_u, &spans_v);
        let mut bernstein_u = [[0.0; MAX_PATCH_DEGREE + 1]; MAX_SAMPLES];
        let mut bernstein_v = [[0.0; MAX_PATCH_DEGREE + 1]; MAX_SAMPLES];
        if bezier {
            bernstein_table(self.degree_u(), samples_u, &mut bernstein_u);
            bernstein_table(self.degree_v(), samples_v, &mut bernstein_v);
        }
        for &index in &order {
            if bounds[index] > best.distance_squared {
                break;
            }
            let (a, b) = (index / nv, index % nv);
            let rect = Rect {
                u: [breaks_u[a], breaks_u[a + 1]],
                v: [breaks_v[b], breaks_v[b + 1]],
            };
            if bezier {
                let patch = *patches.get(a, b);
                if patch.box_distance_squared(test) > best.distance_squared {
                    continue;
                }
                patch.grid_distances_squared(
                    test,
                    &bernstein_u[..samples_u],
                    &bernstein_v[..samples_v],
                    &mut grid,
                );
                let evaluate = |u, v| patch.derivatives(u, v);
                Self::polish_grid_minima(test, rect, samples, &grid, evaluate, &mut best);
            } else {
                self.search_patch(test, rect, samples, &mut grid, &mut best);
            }
        }

        // 3. Boundary curves and creases, one dimension at a time.
        for direction in [SurfaceDirection::U, SurfaceDirection::V] {
            let (fixed_breaks, free_breaks) = match direction {
                SurfaceDirection::U => (&breaks_u, &breaks_v),
                SurfaceDirection::V => (&breaks_v, &breaks_u),
            };
            let domain = self.domain(direction);
            let mut lines: Vec<(f64, usize)> = Vec::new();
            let (start_side, end_side) = match direction {
                SurfaceDirection::U => (SurfaceSide::West, SurfaceSide::East),
                SurfaceDirection::V => (SurfaceSide::South, SurfaceSide::North),
            };
            if !self.is_singular(start_side) {
                lines.push((domain.t0, 0));
            }
            if !self.is_singular(end_side) {
                lines.push((domain.t1, fixed_breaks.len() - 2));
            }
            for k in self.c0_knots(direction) {
                let patch = fixed_breaks.partition_point(|&x| x <= k) - 1;
                lines.push((k, patch.min(fixed_breaks.len() - 2)));
            }
            let samples = samples_per_span(self.degree(direction.other()));
            for (fixed, fixed_patch) in lines {
                for c in 0..free_breaks.len() - 1 {
                    let bound = match direction {
                        SurfaceDirection::U => bounds[fixed_patch * nv + c],
                        SurfaceDirection::V => bounds[c * nv + fixed_patch],
                    };
                    if bound > best.distance_squared {
                        continue;
                    }
                    if bezier {
                        // The line is an edge of the patch, a Bézier curve whose control points
                        // are the patch's on that side.
                        let (a, b) = match direction {
                            SurfaceDirection::U => (fixed_patch, c),
                            SurfaceDirection::V => (c, fixed_patch),
                        };
                        let at_end = fixed >= fixed_breaks[fixed_patch + 1];
                        let edge = patches
                            .get(a, b)
                            .edge_box_distance_squared(direction, at_end, test);
                        if edge > best.distance_squared {
                            continue;
                        }
                    }
                    let range = [free_breaks[c], free_breaks[c + 1]];
                    self.search_line(test, direction, fixed, range, samples, &mut best);
                }
            }
        }

        Ok(SurfaceClosestPoint {
            u: best.u,
            v: best.v,
            point: best.point,
            distance: best.distance_squared.sqrt(),
        })
    }

    /// The closest point to `test` within the parameter rectangle `u_range × v_range` (each
    /// increasing and inside the domain), searched in the same global way but without the
    /// pruning by patches: a sampled grid of `8 × 8` points per span, Newton polish, sides and
    /// corners of the rectangle.
    ///
    /// # Errors
    /// [`Error::NotFinite`] for non-finite input, [`Error::InvalidInput`] for ranges that are
    /// not increasing.
    pub fn closest_point_in(
        &self,
        test: Point3,
        u_range: [f64; 2],
        v_range: [f64; 2],
    ) -> Result<SurfaceClosestPoint> {
        if !test.is_finite() {
            return Err(Error::NotFinite { what: "test point" });
        }
        check_parameters(u_range[0], v_range[0])?;
        check_parameters(u_range[1], v_range[1])?;
        if !(u_range[0] <= u_range[1] && v_range[0] <= v_range[1]) {
            return Err(Error::InvalidInput(
                "closest point ranges must be increasing".into(),
            ));
        }
        let rect = Rect {
            u: u_range,
            v: v_range,
        };
        let mut best = Best {
            u: u_range[0],
            v: v_range[0],
            point: Point3::ORIGIN,
            distance_squared: f64::INFINITY,
        };
        for u in u_range {
            for v in v_range {
                let p = self.point_at(u, v);
                best.offer(u, v, p, p.distance_squared(test));
            }
        }
        let samples = [
            samples_per_span(self.degree_u()),
            samples_per_span(self.degree_v()),
        ];
        let mut grid = vec![0.0; samples[0] * samples[1]];
        self.search_patch(test, rect, samples, &mut grid, &mut best);
        for (direction, fixed_range, free_range) in [
            (SurfaceDirection::U, u_range, v_range),
            (SurfaceDirection::V, v_range, u_range),
        ] {
            let n = samples_per_span(self.degree(direction.other()));
            for fixed in fixed_range {
                self.search_line(test, direction, fixed, free_range, n, &mut best);
            }
        }
        Ok(SurfaceClosestPoint {
            u: best.u,
            v: best.v,
            point: best.point,
            distance: best.distance_squared.sqrt(),
        })
    }

    /// The squared distance from `p` to the axis-aligned box of the B-spline control points of
    /// the patch of spans `su` × `sv` (finite, as a valid surface's are: plain comparisons,
    /// which compile to single min/max instructions, suffice).
    fn span_box_distance_squared(&self, su: usize, sv: usize, p: Point3) -> f64 {
        let (i0, j0) = (su + 1 - self.degree_u(), sv + 1 - self.degree_v());
        let first = self.points[i0 * self.count_v() + j0].to_array();
        let (mut lo, mut hi) = (first, first);
        for i in i0..=i0 + self.degree_u() {
            let row = i * self.count_v() + j0;
            for q in &self.points[row..=row + self.degree_v()] {
                for (k, c) in q.to_array().into_iter().enumerate() {
                    lo[k] = if c < lo[k] { c } else { lo[k] };
                    hi[k] = if c > hi[k] { c } else { hi[k] };
                }
            }
        }
        let mut sum = 0.0;
        for (k, c) in p.to_array().into_iter().enumerate() {
            let d = if lo[k] - c > 0.0 {
                lo[k] - c
            } else if c - hi[k] > 0.0 {
                c - hi[k]
            } else {
                0.0
            };
            sum += d * d;
        }
        sum
    }

    /// Samples one patch and polishes its best discrete local minima.
    fn search_patch(
        &self,
        test: Point3,
        rect: Rect,
        samples: [usize; 2],
        grid: &mut [f64],
        best: &mut Best,
    ) {
        self.sample_grid(test, rect, samples, grid);
        let evaluate = |u, v| self.derivatives_unchecked(u, v, 2);
        Self::polish_grid_minima(test, rect, samples, grid, evaluate, best);
    }

    /// The squared distances from `test` of the `nu × nv` grid of points of `rect` (row-major
    /// into `grid`), by the basis functions.
    fn sample_grid(&self, test: Point3, rect: Rect, [nu, nv]: [usize; 2], grid: &mut [f64]) {
        let param = grid_parameter;
        // The basis functions of each sample column once, then each row's combination.
        let (p, q) = (self.degree_u(), self.degree_v());
        let mut basis_v = [[0.0; MAX_ORDER]; MAX_SAMPLES];
        let mut first_v = [0usize; MAX_SAMPLES];
        for j in 0..nv {
            let v = param(rect.v, j, nv);
            let span = span_index(q, self.knots_v(), v);
            basis_functions(q, self.knots_v(), span, v, &mut basis_v[j]);
            first_v[j] = span + 1 - q;
        }
        let mut basis_u = [0.0; MAX_ORDER];
        for i in 0..nu {
            let u = param(rect.u, i, nu);
            let span = span_index(p, self.knots_u(), u);
            basis_functions(p, self.knots_u(), span, u, &mut basis_u);
            let i0 = span + 1 - p;
            for j in 0..nv {
                let (mut x, mut y, mut z, mut w) = (0.0, 0.0, 0.0, 0.0);
                for (r, &bu) in basis_u[..=p].iter().enumerate() {
                    let row = (i0 + r) * self.count_v() + first_v[j];
                    let cvs = self.points[row..=row + q]
                        .iter()
                        .zip(&self.weights[row..=row + q]);
                    for ((pt, &wt), &bv) in cvs.zip(&basis_v[j][..=q]) {
                        let b = bu * bv * wt;
                        x += b * pt.x;
                        y += b * pt.y;
                        z += b * pt.z;
                        w += b;
                    }
                }
                grid[i * nv + j] = Point3::new(x / w, y / w, z / w).distance_squared(test);
            }
        }
    }

    /// Polishes the best [`STARTS_PER_PATCH`] discrete local minima of the sampled `grid` of
    /// `rect`.
    fn polish_grid_minima(
        test: Point3,
        rect: Rect,
        [nu, nv]: [usize; 2],
        grid: &[f64],
        evaluate: impl Fn(f64, f64) -> SurfaceDerivatives,
        best: &mut Best,
    ) {
        let param = grid_parameter;
        let mut starts: Vec<(f64, usize, usize)> = Vec::new();
        for i in 0..nu {
            for j in 0..nv {
                let f = grid[i * nv + j];
                let mut is_min = true;
                for (di, dj) in [
                    (-1, -1),
                    (-1, 0),
                    (-1, 1),
                    (0, -1),
                    (0, 1),
                    (1, -1),
                    (1, 0),
                    (1, 1),
                ] {
                    let (ni, nj) = (i as isize + di, j as isize + dj);
                    if ni >= 0 && nj >= 0 && (ni as usize) < nu && (nj as usize) < nv {
                        let g = grid[ni as usize * nv + nj as usize];
                        // Strictly smaller neighbours before, smaller-or-equal after: one start
                        // per plateau.
                        if g < f || (g == f && (di, dj) < (0, 0)) {
                            is_min = false;
                            break;
                        }
                    }
                }
                if is_min {
                    starts.push((f, i, j));
                }
            }
        }
        starts.sort_by(|a, b| a.0.total_cmp(&b.0));
        for &(_, i, j) in starts.iter().take(STARTS_PER_PATCH) {
            let (u, v) = (param(rect.u, i, nu), param(rect.v, j, nv));
            Self::polish_2d(test, [u, v], rect, &evaluate, best);
        }
    }

    /// Newton iteration on `½|S(u, v) − P|²` inside `rect`, with an active set and a line
    /// search; offers the result to `best`.
    fn polish_2d(
        test: Point3,
        [mut u, mut v]: [f64; 2],
        rect: Rect,
        evaluate: impl Fn(f64, f64) -> SurfaceDerivatives,
        best: &mut Best,
    ) {
        let tol_u = 4.0 * f64::EPSILON * (rect.u[0].abs().max(rect.u[1].abs()) + 1.0);
        let tol_v = 4.0 * f64::EPSILON * (rect.v[0].abs().max(rect.v[1].abs()) + 1.0);
        let mut d = evaluate(u, v);
        let mut r = d.point - test;
        let mut f = r.length_squared();
        for _ in 0..MAX_ITERATIONS {
            let gu = r.dot(d.du);
            let gv = r.dot(d.dv);
            let e = d.du.dot(d.du);
            let fm = d.du.dot(d.dv);
            let g = d.dv.dot(d.dv);
            let huu = e + r.dot(d.duu);
            let huv = fm + r.dot(d.duv);
            let hvv = g + r.dot(d.dvv);
            let fix_u = (u <= rect.u[0] && gu > 0.0) || (u >= rect.u[1] && gu < 0.0);
            let fix_v = (v <= rect.v[0] && gv > 0.0) || (v >= rect.v[1] && gv < 0.0);
            let (su, sv) = match (fix_u, fix_v) {
                (true, true) => break,
                (true, false) => (0.0, step_1d(gv, hvv, g)),
                (false, true) => (step_1d(gu, huu, e), 0.0),
                (false, false) => step_2d([gu, gv], [huu, huv, hvv], [e, fm, g]),
            };
            if su == 0.0 && sv == 0.0 {
                break;
            }
            let mut alpha = 1.0;
            let mut accepted = None;
            for _ in 0..MAX_HALVINGS {
                let nu = (u + alpha * su).clamp(rect.u[0], rect.u[1]);
                let nv = (v + alpha * sv).clamp(rect.v[0], rect.v[1]);
                // The derivatives at once (the first step is nearly always taken, and its
                // derivatives are the next iteration's).
                let nd = evaluate(nu, nv);
                let nf = nd.point.distance_squared(test);
                if nf <= f + rounding_noise(nd.point, test, f) {
                    accepted = Some((nu, nv, nf, nd));
                    break;
                }
                alpha *= 0.5;
            }
            let Some((nu, nv, nf, nd)) = accepted else {
                break;
            };
            let small = (nu - u).abs() <= tol_u && (nv - v).abs() <= tol_v;
            u = nu;
            v = nv;
            f = nf;
            d = nd;
            r = d.point - test;
            if small {
                break;
            }
        }
        best.offer(u, v, d.point, d.point.distance_squared(test));
    }

    /// Samples the line where `direction`'s parameter equals `fixed`, over `range` of the
    /// other parameter, and polishes the best local minima in one dimension.
    fn search_line(
        &self,
        test: Point3,
        direction: SurfaceDirection,
        fixed: f64,
        range: [f64; 2],
        samples: usize,
        best: &mut Best,
    ) {
        let uv = |t: f64| match direction {
            SurfaceDirection::U => (fixed, t),
            SurfaceDirection::V => (t, fixed),
        };
        let param = |k: usize| {
            let s = k as f64 / (samples - 1) as f64;
            (1.0 - s) * range[0] + s * range[1]
        };
        let mut values = [0.0; 34];
        let samples = samples.min(values.len());
        for (k, value) in values[..samples].iter_mut().enumerate() {
            let (u, v) = uv(param(k));
            *value = self.point_at(u, v).distance_squared(test);
        }
        let mut starts: Vec<(f64, usize)> = (0..samples)
            .filter(|&k| {
                (k == 0 || values[k - 1] > values[k])
                    && (k + 1 == samples || values[k + 1] >= values[k])
            })
            .map(|k| (values[k], k))
            .collect();
        starts.sort_by(|a, b| a.0.total_cmp(&b.0));
        for &(_, k) in starts.iter().take(2) {
            self.polish_1d(test, direction, fixed, param(k), range, best);
        }
    }

    /// Newton iteration in one parameter with the other fixed.
    fn polish_1d(
        &self,
        test: Point3,
        direction: SurfaceDirection,
        fixed: f64,
        mut t: f64,
        range: [f64; 2],
        best: &mut Best,
    ) {
        let uv = |t: f64| match direction {
            SurfaceDirection::U => (fixed, t),
            SurfaceDirection::V => (t, fixed),
        };
        let tol = 4.0 * f64::EPSILON * (range[0].abs().max(range[1].abs()) + 1.0);
        let (u, v) = uv(t);
        let mut d = self.derivatives_unchecked(u, v, 2);
        for _ in 0..MAX_ITERATIONS {
            let r = d.point - test;
            let f = r.length_squared();
            let (dt, dtt) = match direction {
                SurfaceDirection::U => (d.dv, d.dvv),
                SurfaceDirection::V => (d.du, d.duu),
            };
            let g = r.dot(dt);
            if (t <= range[0] && g > 0.0) || (t >= range[1] && g < 0.0) {
                break;
            }
            let s = step_1d(g, dt.dot(dt) + r.dot(dtt), dt.dot(dt));
            if s == 0.0 {
                break;
            }
            let mut alpha = 1.0;
            let mut accepted = None;
            for _ in 0..MAX_HALVINGS {
                let nt = (t + alpha * s).clamp(range[0], range[1]);
                let (u, v) = uv(nt);
                let nd = self.derivatives_unchecked(u, v, 2);
                if nd.point.distance_squared(test) <= f + rounding_noise(nd.point, test, f) {
                    accepted = Some((nt, nd));
                    break;
                }
                alpha *= 0.5;
            }
            let Some((nt, nd)) = accepted else {
                break;
            };
            let small = (nt - t).abs() <= tol;
            t = nt;
            d = nd;
            if small {
                break;
            }
        }
        let (u, v) = uv(t);
        best.offer(u, v, d.point, d.point.distance_squared(test));
    }
}

/// The rounding level of the squared distance `f` between `point` (an evaluated surface
/// point) and `test`: `2·√f·e + e²` with `e` [`NOISE_ULPS`] ulps of the largest coordinate.
fn rounding_noise(point: Point3, test: Point3, f: f64) -> f64 {
    let magnitude = point
        .to_array()
        .into_iter()
        .chain(test.to_array())
        .fold(0.0f64, |m, c| m.max(c.abs()));
    let e = NOISE_ULPS * f64::EPSILON * magnitude;
    2.0 * f.sqrt() * e + e * e
}

/// The most samples per span and direction.
const MAX_SAMPLES: usize = 16;

/// Sample `k` of `n` over `range`: its start at 0, its end at `n − 1`.
fn grid_parameter(range: [f64; 2], k: usize, n: usize) -> f64 {
    let s = k as f64 / (n - 1) as f64;
    (1.0 - s) * range[0] + s * range[1]
}

/// The number of samples per span and direction for a degree: enough to separate the local
/// minima a polynomial of that degree can have.
fn samples_per_span(degree: usize) -> usize {
    (2 * degree + 2).clamp(4, MAX_SAMPLES)
}

/// The Newton step for `g + h·s = 0` in one variable, falling back to the Gauss–Newton
/// curvature `gn` (always positive where the derivative does not vanish) when `h ≤ 0`.
fn step_1d(g: f64, h: f64, gn: f64) -> f64 {
    if h > 0.0 {
        -g / h
    } else if gn > 0.0 {
        -g / gn
    } else {
        0.0
    }
}

/// The Newton step in two variables for gradient `g` and Hessian `[huu, huv, hvv]`, falling
/// back to Gauss–Newton on the first fundamental form `[E, F, G]` when the Hessian is not
/// positive definite, and to separate one-variable steps when that is singular too.
fn step_2d(g: [f64; 2], [huu, huv, hvv]: [f64; 3], [e, f, gg]: [f64; 3]) -> (f64, f64) {
    let solve = |a: f64, b: f64, c: f64| {
        let det = a * c - b * b;
        (a > 0.0 && det > 1e-14 * a * c)
            .then(|| (-(c * g[0] - b * g[1]) / det, -(a * g[1] - b * g[0]) / det))
    };
    solve(huu, huv, hvv)
        .or_else(|| solve(e, f, gg))
        .unwrap_or_else(|| (step_1d(g[0], huu, e), step_1d(g[1], hvv, gg)))
}

#[cfg(test)]
mod tests;

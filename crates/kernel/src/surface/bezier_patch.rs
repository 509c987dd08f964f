//! The Bézier form of one patch (a knot span in `u` × a knot span in `v`) of a NURBS surface of
//! degrees up to [`MAX_PATCH_DEGREE`] in both directions: its homogeneous control points, for
//! bounds (the patch, and each of its edges, lies in the convex hull of the projections of its
//! own control points, for positive weights) and for sampling a grid of points cheaply.
//!
//! A span's Bézier control points are a fixed linear combination of its B-spline control
//! points (the blossoms of [`blossoms`]). [`SpanExtraction`] keeps that combination as a small
//! matrix per span, computed once per direction and span, so that a patch's Bézier form is two
//! small matrix products instead of a de Boor triangle per row and column.

use crate::curve::bezier_piece::blossoms;
use crate::surface::direction::SurfaceDirection;
use crate::surface::{SurfaceDerivatives, rational_derivatives};
use crate::{NurbsSurface, Point3};

/// The highest degree (in each direction) with a Bézier patch: 3. Higher degrees, rare in
/// practice, are searched by the B-spline boxes alone.
pub(crate) const MAX_PATCH_DEGREE: usize = 3;

/// The fixed size of the patch arrays.
const N: usize = MAX_PATCH_DEGREE + 1;

/// The Bézier extraction matrix of one span: Bézier point `j` is `Σ_i m[j][i] · P_{first + i}`
/// (homogeneous), with `first = span + 1 − degree`.
#[derive(Clone, Copy, Debug)]
pub(crate) struct SpanExtraction {
    m: [[f64; N]; N],
}

impl SpanExtraction {
    /// The extraction matrix of span `span` (a Rhino knot index with `knots[span] <
    /// knots[span + 1]`) of degree `degree ≤ MAX_PATCH_DEGREE`, over Rhino-form `knots`.
    pub(crate) fn new(degree: usize, knots: &[f64], span: usize) -> Self {
        debug_assert!(degree <= MAX_PATCH_DEGREE);
        let first = span + 1 - degree;
        let local = &knots[first..first + 2 * degree];
        let range = [knots[span], knots[span + 1]];
        // The blossoms of the unit control points: component i of Bézier point j is the
        // weight of control point i in it.
        let unit: [[f64; 4]; N] =
            std::array::from_fn(|i| std::array::from_fn(|c| f64::from(u8::from(c == i))));
        let mut rows = [[0.0; 4]; N];
        blossoms::<N>(degree, local, range, &unit[..=degree], &mut rows[..=degree]);
        Self { m: rows }
    }
}

/// One patch in Bézier form: `(p + 1) × (q + 1)` homogeneous control points `(w·x, w·y, w·z,
/// w)`, row `r` along `u`, column `s` along `v`.
#[derive(Clone, Copy, Debug)]
pub(crate) struct BezierPatch {
    p: usize,
    q: usize,
    /// The patch's parameter ranges `[u0, u1]` and `[v0, v1]`.
    range_u: [f64; 2],
    range_v: [f64; 2],
    h: [[[f64; 4]; N]; N],
}

impl NurbsSurface {
    /// The Bézier form of the patch of spans `su` × `sv`, from the spans' extraction matrices
    /// (degrees at most [`MAX_PATCH_DEGREE`]).
    pub(crate) fn bezier_patch(
        &self,
        (su, eu): (usize, &SpanExtraction),
        (sv, ev): (usize, &SpanExtraction),
    ) -> BezierPatch {
        let (p, q) = (self.degree_u(), self.degree_v());
        let (first_u, first_v) = (su + 1 - p, sv + 1 - q);
        // Each row's B-spline points to Bézier form in v, then each column in u.
        let mut rows = [[[0.0; 4]; N]; N];
        for (i, row) in rows[..=p].iter_mut().enumerate() {
            let base = (first_u + i) * self.count_v() + first_v;
            for (s, out) in row[..=q].iter_mut().enumerate() {
                let mut acc = [0.0; 4];
                for k in 0..=q {
                    let (pt, w) = (self.points[base + k], self.weights[base + k]);
                    let c = ev.m[s][k] * w;
                    acc[0] += c * pt.x;
                    acc[1] += c * pt.y;
                    acc[2] += c * pt.z;
                    acc[3] += c;
                }
                *out = acc;
            }
        }
        let mut h = [[[0.0; 4]; N]; N];
        for (r, out_row) in h[..=p].iter_mut().enumerate() {
            for (s, out) in out_row[..=q].iter_mut().enumerate() {
                let mut acc = [0.0; 4];
                for (i, row) in rows[..=p].iter().enumerate() {
                    let c = eu.m[r][i];
                    for (a, x) in acc.iter_mut().zip(&row[s]) {
                        *a += c * x;
                    }
                }
                *out = acc;
            }
        }
        let knots = |k: &[f64], span: usize| [k[span], k[span + 1]];
        BezierPatch {
            p,
            q,
            range_u: knots(self.knots_u(), su),
            range_v: knots(self.knots_v(), sv),
            h,
        }
    }
}

/// The Bézier patches of one surface, built when first asked for and kept, with the spans'
/// extraction matrices (a closest-point query asks for few of them, some twice).
pub(crate) struct BezierPatches<'a> {
    surface: &'a NurbsSurface,
    spans_u: &'a [usize],
    spans_v: &'a [usize],
    extraction_u: Vec<Option<SpanExtraction>>,
    extraction_v: Vec<Option<SpanExtraction>>,
    patches: Vec<Option<BezierPatch>>,
}

impl<'a> BezierPatches<'a> {
    /// The patches of `surface` (degrees at most [`MAX_PATCH_DEGREE`]) over the spans (Rhino
    /// knot indices) `spans_u` × `spans_v`, none built yet.
    pub(crate) fn new(
        surface: &'a NurbsSurface,
        spans_u: &'a [usize],
        spans_v: &'a [usize],
    ) -> Self {
        Self {
            surface,
            spans_u,
            spans_v,
            extraction_u: vec![None; spans_u.len()],
            extraction_v: vec![None; spans_v.len()],
            patches: vec![None; spans_u.len() * spans_v.len()],
        }
    }

    /// Patch `a` (in `u`) × `b` (in `v`).
    pub(crate) fn get(&mut self, a: usize, b: usize) -> &BezierPatch {
        let index = a * self.spans_v.len() + b;
        if self.patches[index].is_none() {
            let s = self.surface;
            let (su, sv) = (self.spans_u[a], self.spans_v[b]);
            let eu = *self.extraction_u[a]
                .get_or_insert_with(|| SpanExtraction::new(s.degree_u(), s.knots_u(), su));
            let ev = *self.extraction_v[b]
                .get_or_insert_with(|| SpanExtraction::new(s.degree_v(), s.knots_v(), sv));
            self.patches[index] = Some(s.bezier_patch((su, &eu), (sv, &ev)));
        }
        self.patches[index].as_ref().expect("built above")
    }
}

impl BezierPatch {
    /// The squared distance from `test` to the axis-aligned box of the projected control
    /// points: a lower bound of the squared distance to every point of the patch.
    pub(crate) fn box_distance_squared(&self, test: Point3) -> f64 {
        let points = self.h[..=self.p]
            .iter()
            .flat_map(|row| row[..=self.q].iter());
        box_distance_squared(points, test)
    }

    /// The squared distance from `test` to the box of the control points of one edge: where
    /// the `direction` parameter is at the patch's start (`at_end` false) or end. The edge is
    /// a Bézier curve with those control points, so this bounds the distance to it.
    pub(crate) fn edge_box_distance_squared(
        &self,
        direction: SurfaceDirection,
        at_end: bool,
        test: Point3,
    ) -> f64 {
        match direction {
            SurfaceDirection::U => {
                let r = if at_end { self.p } else { 0 };
                box_distance_squared(self.h[r][..=self.q].iter(), test)
            }
            SurfaceDirection::V => {
                let s = if at_end { self.q } else { 0 };
                box_distance_squared(self.h[..=self.p].iter().map(|row| &row[s]), test)
            }
        }
    }

    /// The point and its first and second partial derivatives at `(u, v)` (inside the patch's
    /// ranges): the tensor product of the Bernstein polynomials and their derivatives, then
    /// the quotient rule. Cheaper than the B-spline basis, with the same values up to rounding.
    pub(crate) fn derivatives(&self, u: f64, v: f64) -> SurfaceDerivatives {
        let (hu, hv) = (
            1.0 / (self.range_u[1] - self.range_u[0]),
            1.0 / (self.range_v[1] - self.range_v[0]),
        );
        let bu = bernstein_with_derivatives(self.p, (u - self.range_u[0]) * hu, hu);
        let bv = bernstein_with_derivatives(self.q, (v - self.range_v[0]) * hv, hv);
        // a[k][l] = ∂^(k+l) Sw / ∂u^k ∂v^l, through the rows' curves in v.
        let mut a = [[[0.0; 4]; 3]; 3];
        for (k, bu_k) in bu.iter().enumerate() {
            let mut curve = [[0.0; 4]; N];
            for (s, c) in curve[..=self.q].iter_mut().enumerate() {
                for (r, &b) in bu_k[..=self.p].iter().enumerate() {
                    for (x, y) in c.iter_mut().zip(&self.h[r][s]) {
                        *x += b * y;
                    }
                }
            }
            for (l, bv_l) in bv[..3 - k].iter().enumerate() {
                let mut acc = [0.0; 4];
                for (s, &b) in bv_l[..=self.q].iter().enumerate() {
                    for (x, y) in acc.iter_mut().zip(&curve[s]) {
                        *x += b * y;
                    }
                }
                a[k][l] = acc;
            }
        }
        rational_derivatives(&a, 2)
    }

    /// The squared distances from `test` of the `nu × nv` grid of points at the parameters
    /// `k / (n − 1)` of the patch (row-major into `grid`), from the Bernstein values at those
    /// parameters (`bernstein_u[i][r]`, `bernstein_v[j][s]`, see [`bernstein_table`]).
    pub(crate) fn grid_distances_squared(
        &self,
        test: Point3,
        bernstein_u: &[[f64; N]],
        bernstein_v: &[[f64; N]],
        grid: &mut [f64],
    ) {
        let nv = bernstein_v.len();
        for (i, bu) in bernstein_u.iter().enumerate() {
            // The row's curve in v: its control points at this u.
            let mut curve = [[0.0; 4]; N];
            for (s, c) in curve[..=self.q].iter_mut().enumerate() {
                for (r, &b) in bu[..=self.p].iter().enumerate() {
                    for (x, y) in c.iter_mut().zip(&self.h[r][s]) {
                        *x += b * y;
                    }
                }
            }
            for (j, bv) in bernstein_v.iter().enumerate() {
                let mut a = [0.0; 4];
                for (s, &b) in bv[..=self.q].iter().enumerate() {
                    for (x, y) in a.iter_mut().zip(&curve[s]) {
                        *x += b * y;
                    }
                }
                let inv_w = 1.0 / a[3];
                let point = Point3::new(a[0] * inv_w, a[1] * inv_w, a[2] * inv_w);
                grid[i * nv + j] = point.distance_squared(test);
            }
        }
    }
}

/// The Bernstein polynomials of `degree` at the `samples` parameters `k / (samples − 1)`:
/// row `k` holds `B_r(k / (samples − 1))` for `r` in `0..=degree`.
pub(crate) fn bernstein_table(degree: usize, samples: usize, out: &mut [[f64; N]]) {
    for (k, row) in out[..samples].iter_mut().enumerate() {
        let s = k as f64 / (samples - 1) as f64;
        // de Casteljau's triangle on the unit coefficients.
        *row = [0.0; N];
        row[0] = 1.0;
        for level in 1..=degree {
            let mut next = [0.0; N];
            for r in 0..=level {
                let keep = if r < level { row[r] * (1.0 - s) } else { 0.0 };
                let moved = if r > 0 { row[r - 1] * s } else { 0.0 };
                next[r] = keep + moved;
            }
            *row = next;
        }
    }
}

/// The Bernstein polynomials of `degree` at `s` in `[0, 1]` and their first and second
/// derivatives with respect to the parameter of which `s` is the affine image with slope
/// `scale` (`s = (t − t0)·scale`): `[B_r, B_r′, B_r″]`.
fn bernstein_with_derivatives(degree: usize, s: f64, scale: f64) -> [[f64; N]; 3] {
    // Row `level` of de Casteljau's triangle of the unit coefficients: the Bernstein
    // polynomials of degree `level`, kept for the last three levels.
    let mut levels = [[0.0; N]; N];
    levels[0][0] = 1.0;
    for level in 1..=degree {
        for r in 0..=level {
            let keep = if r < level {
                levels[level - 1][r] * (1.0 - s)
            } else {
                0.0
            };
            let moved = if r > 0 {
                levels[level - 1][r - 1] * s
            } else {
                0.0
            };
            levels[level][r] = keep + moved;
        }
    }
    let n = degree as f64;
    let mut out = [[0.0; N]; 3];
    out[0] = levels[degree];
    if degree >= 1 {
        let lower = &levels[degree - 1];
        for r in 0..=degree {
            let left = if r > 0 { lower[r - 1] } else { 0.0 };
            let right = if r < degree { lower[r] } else { 0.0 };
            out[1][r] = n * scale * (left - right);
        }
    }
    if degree >= 2 {
        let lower = &levels[degree - 2];
        let at = |r: isize| {
            if r >= 0 && (r as usize) <= degree - 2 {
                lower[r as usize]
            } else {
                0.0
            }
        };
        for r in 0..=degree {
            let r = r as isize;
            out[2][r as usize] =
                n * (n - 1.0) * scale * scale * (at(r - 2) - 2.0 * at(r - 1) + at(r));
        }
    }
    out
}

/// The squared distance from `test` to the box of the projections of homogeneous points.
fn box_distance_squared<'a>(points: impl Iterator<Item = &'a [f64; 4]>, test: Point3) -> f64 {
    let mut lo = [f64::INFINITY; 3];
    let mut hi = [f64::NEG_INFINITY; 3];
    for h in points {
        let inv_w = 1.0 / h[3];
        for c in 0..3 {
            let v = h[c] * inv_w;
            lo[c] = lo[c].min(v);
            hi[c] = hi[c].max(v);
        }
    }
    let mut sum = 0.0;
    for (c, x) in test.to_array().into_iter().enumerate() {
        let d = (lo[c] - x).max(x - hi[c]).max(0.0);
        sum += d * d;
    }
    sum
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Vector3;

    fn surface() -> NurbsSurface {
        let points = (0..6)
            .map(|i| {
                (0..5)
                    .map(|j| {
                        let (x, y) = (i as f64, j as f64);
                        Point3::new(x, y, (0.7 * x).sin() * (0.5 * y).cos())
                    })
                    .collect()
            })
            .collect();
        let weights = (0..6)
            .map(|i| {
                (0..5)
                    .map(|j| 1.0 + 0.25 * ((i + 2 * j) % 3) as f64)
                    .collect()
            })
            .collect();
        let knots_u = vec![0.0, 0.0, 0.0, 0.2, 0.5, 1.0, 1.0, 1.0];
        let knots_v = vec![0.0, 0.0, 0.4, 0.7, 1.0, 1.0];
        NurbsSurface::new(3, 2, points, weights, knots_u, knots_v).unwrap()
    }

    #[test]
    fn the_patch_grid_is_the_surface_and_the_boxes_hold_it() {
        let s = surface();
        let (p, q) = (s.degree_u(), s.degree_v());
        let spans = |d: SurfaceDirection| -> Vec<usize> {
            let knots = match d {
                SurfaceDirection::U => s.knots_u(),
                SurfaceDirection::V => s.knots_v(),
            };
            let degree = s.degree(d);
            (degree - 1..knots.len() - degree)
                .filter(|&i| knots[i] < knots[i + 1])
                .collect()
        };
        let (nu, nv) = (7, 5);
        let mut bu = [[0.0; N]; 7];
        let mut bv = [[0.0; N]; 5];
        bernstein_table(p, nu, &mut bu);
        bernstein_table(q, nv, &mut bv);
        let far = Point3::new(40.0, -30.0, 7.0);
        for su in spans(SurfaceDirection::U) {
            let eu = SpanExtraction::new(p, s.knots_u(), su);
            for sv in spans(SurfaceDirection::V) {
                let ev = SpanExtraction::new(q, s.knots_v(), sv);
                let patch = s.bezier_patch((su, &eu), (sv, &ev));
                let mut grid = [0.0; 35];
                patch.grid_distances_squared(far, &bu, &bv, &mut grid);
                let (u0, u1) = (s.knots_u()[su], s.knots_u()[su + 1]);
                let (v0, v1) = (s.knots_v()[sv], s.knots_v()[sv + 1]);
                for i in 0..nu {
                    for j in 0..nv {
                        let u = u0 + (u1 - u0) * i as f64 / (nu - 1) as f64;
                        let v = v0 + (v1 - v0) * j as f64 / (nv - 1) as f64;
                        let on = s.point_at(u, v);
                        // At a patch's far side the B-spline evaluates the next patch, whose
                        // second derivatives may differ (v is only C¹ here).
                        let (d, e) = (s.derivatives_unchecked(u, v, 2), patch.derivatives(u, v));
                        let inside = i + 1 < nu && j + 1 < nv;
                        let close =
                            |x: Vector3, y: Vector3| (x - y).length() <= 1e-10 * (1.0 + x.length());
                        assert!(close(d.point.to_vector(), e.point.to_vector()));
                        for (x, y) in [
                            (d.du, e.du),
                            (d.dv, e.dv),
                            (d.duu, e.duu),
                            (d.duv, e.duv),
                            (d.dvv, e.dvv),
                        ] {
                            assert!(!inside || close(x, y), "{x:?} {y:?}");
                        }
                        let expected = on.distance_squared(far);
                        assert!((grid[i * nv + j] - expected).abs() <= 1e-11 * expected);
                        assert!(patch.box_distance_squared(on) <= 1e-24);
                        if i == 0 || i == nu - 1 {
                            let edge = patch.edge_box_distance_squared(
                                SurfaceDirection::U,
                                i == nu - 1,
                                on,
                            );
                            assert!(edge <= 1e-24, "{edge}");
                        }
                        if j == 0 || j == nv - 1 {
                            let edge = patch.edge_box_distance_squared(
                                SurfaceDirection::V,
                                j == nv - 1,
                                on,
                            );
                            assert!(edge <= 1e-24, "{edge}");
                        }
                    }
                }
            }
        }
    }

    #[test]
    fn bernstein_values_sum_to_one() {
        let mut t = [[0.0; N]; 8];
        bernstein_table(3, 8, &mut t);
        for row in &t {
            assert!((row.iter().sum::<f64>() - 1.0).abs() < 1e-15);
        }
        assert_eq!(t[0], [1.0, 0.0, 0.0, 0.0]);
        assert_eq!(t[7], [0.0, 0.0, 0.0, 1.0]);
    }
}

//! The Bézier form of one span of a NURBS curve: the homogeneous control points `(w·P, w)` of
//! the span's polynomial piece, for bounds (the piece lies in the convex hull of their
//! projections, for positive weights) and for cheap evaluation of the point and its first two
//! derivatives by de Casteljau's algorithm (`O(p²)` operations, without basis functions).

use crate::curve::nurbs::basis::MAX_ORDER;
use crate::{NurbsCurve, Point3, Vector3};

/// One span's polynomial piece in Bézier form on `[a, b]`, with room for `N > degree` control
/// points: `N` = [`MAX_ORDER`] (the default) holds every degree, and the closest-point search
/// uses `N` = 4 for degrees up to 3 (cubic), so that copies and working arrays stay small.
#[derive(Clone, Copy, Debug)]
pub(crate) struct BezierPiece<const N: usize = MAX_ORDER> {
    pub(crate) a: f64,
    pub(crate) b: f64,
    degree: usize,
    /// Whether some weight of the span differs from 1; when none does, every `w` is exactly 1
    /// and evaluation skips the quotient rule.
    rational: bool,
    /// Homogeneous control points `(w·x, w·y, w·z, w)`, `degree + 1` of them.
    points: [[f64; 4]; N],
}

impl NurbsCurve {
    /// The Bézier form of the piece of `span` (a Rhino knot index with `knots[span] <
    /// knots[span + 1]`): control point `j` is the blossom `B(a, …, a, b, …, b)` with `j` copies
    /// of `b`, computed by de Boor's triangle on the homogeneous control points.
    pub(crate) fn bezier_piece(&self, span: usize) -> BezierPiece {
        self.bezier_piece_in(span)
    }

    /// [`NurbsCurve::bezier_piece`] with room for `N > degree` control points.
    pub(crate) fn bezier_piece_in<const N: usize>(&self, span: usize) -> BezierPiece<N> {
        let degree = self.degree();
        debug_assert!(degree < N);
        let first = span + 1 - degree;
        let knots = &self.knots()[first..first + 2 * degree];
        let (a, b) = (self.knots()[span], self.knots()[span + 1]);
        let mut homogeneous = [[0.0; 4]; N];
        let mut rational = false;
        for (i, h) in homogeneous[..=degree].iter_mut().enumerate() {
            let (q, w) = (self.points()[first + i], self.weights()[first + i]);
            rational |= w != 1.0;
            *h = [q.x * w, q.y * w, q.z * w, w];
        }
        let mut points = [[0.0; 4]; N];
        blossoms::<N>(degree, knots, [a, b], &homogeneous[..=degree], &mut points);
        if !rational {
            // (1 − α)·1 + α·1 may round away from 1.
            for q in &mut points[..=degree] {
                q[3] = 1.0;
            }
        }
        BezierPiece {
            a,
            b,
            degree,
            rational,
            points,
        }
    }
}

/// The Bézier points of one span (see [`NurbsCurve::bezier_piece`]) from its `degree + 1`
/// homogeneous B-spline control points and its `2·degree` local knots (Rhino form, from the
/// span's first control point), into `points[..=degree]`, with `N > degree`-sized working
/// arrays, so that low degrees copy little.
pub(crate) fn blossoms<const N: usize>(
    degree: usize,
    knots: &[f64],
    [a, b]: [f64; 2],
    homogeneous: &[[f64; 4]],
    points: &mut [[f64; 4]],
) {
    // Point j is de Boor's triangle with `a` on its first `degree − j` levels and `b` on the
    // others. The levels with `a` are shared: the triangle runs once with `a` throughout, and
    // before its level r the branch for j = degree − r + 1 goes on with `b` (the same
    // operations, in the same order, as a triangle per point). The weights `alpha` of level r
    // at row i are computed once for `a` and once for `b`.
    let mut alpha_a = [[0.0; N]; N];
    let mut alpha_b = [[0.0; N]; N];
    for r in 1..=degree {
        for i in r..=degree {
            let (k0, k1) = (knots[i - 1], knots[i + degree - r]);
            alpha_a[r][i] = (a - k0) / (k1 - k0);
            alpha_b[r][i] = (b - k0) / (k1 - k0);
        }
    }
    let level = |d: &mut [[f64; 4]; N], alphas: &[f64; N], r: usize| {
        for i in (r..=degree).rev() {
            let alpha = alphas[i];
            let prev = d[i - 1];
            let q = &mut d[i];
            for c in 0..4 {
                q[c] = (1.0 - alpha) * prev[c] + alpha * q[c];
            }
        }
    };
    let mut d = [[0.0; 4]; N];
    d[..=degree].copy_from_slice(&homogeneous[..=degree]);
    for r in 1..=degree {
        let mut branch = d;
        for (s, alphas) in alpha_b.iter().enumerate().take(degree + 1).skip(r) {
            level(&mut branch, alphas, s);
        }
        points[degree - r + 1] = branch[degree];
        level(&mut d, &alpha_a[r], r);
    }
    points[0] = d[degree];
}

impl<const N: usize> BezierPiece<N> {
    /// The homogeneous control points `(w·x, w·y, w·z, w)`, `degree + 1` of them.
    pub(crate) fn homogeneous(&self) -> &[[f64; 4]] {
        &self.points[..=self.degree]
    }

    /// The squared distance from `p` to the axis-aligned box of the projected control points.
    pub(crate) fn box_distance_squared(&self, p: Point3) -> f64 {
        let mut lo = [f64::INFINITY; 3];
        let mut hi = [f64::NEG_INFINITY; 3];
        for h in &self.points[..=self.degree] {
            // Every weight is exactly 1 when the piece is not rational.
            let inv_w = if self.rational { 1.0 / h[3] } else { 1.0 };
            for c in 0..3 {
                let v = h[c] * inv_w;
                lo[c] = lo[c].min(v);
                hi[c] = hi[c].max(v);
            }
        }
        let mut sum = 0.0;
        for (c, x) in p.to_array().into_iter().enumerate() {
            let d = (lo[c] - x).max(x - hi[c]).max(0.0);
            sum += d * d;
        }
        sum
    }

    /// The two halves of the piece, split at the middle of `[a, b]` by de Casteljau's algorithm
    /// on the homogeneous points (exact up to rounding; each half lies in the convex hull of its
    /// own control points, which is tighter than the whole's).
    pub(crate) fn halves(&self) -> [Self; 2] {
        let p = self.degree;
        let mid = 0.5 * (self.a + self.b);
        let mut left = Self {
            a: self.a,
            b: mid,
            ..*self
        };
        let mut right = Self {
            a: mid,
            b: self.b,
            ..*self
        };
        let mut q = self.points;
        left.points[0] = q[0];
        right.points[p] = q[p];
        for level in 1..=p {
            for i in 0..=p - level {
                q[i] = std::array::from_fn(|c| 0.5 * (q[i][c] + q[i + 1][c]));
            }
            left.points[level] = q[0];
            right.points[p - level] = q[p - level];
        }
        [left, right]
    }

    /// The point (as a vector) and the first and second derivatives at `t`.
    pub(crate) fn derivatives(&self, t: f64) -> [Vector3; 3] {
        if N > 4 && self.degree < 4 {
            self.derivatives_with::<4>(t)
        } else {
            self.derivatives_with::<N>(t)
        }
    }

    /// [`BezierPiece::derivatives`] with an `M > degree`-sized working copy of the points.
    fn derivatives_with<const M: usize>(&self, t: f64) -> [Vector3; 3] {
        let p = self.degree;
        let inv_h = 1.0 / (self.b - self.a);
        let s = (t - self.a) * inv_h;
        let lerp = |x: [f64; 4], y: [f64; 4]| {
            [
                x[0] + s * (y[0] - x[0]),
                x[1] + s * (y[1] - x[1]),
                x[2] + s * (y[2] - x[2]),
                x[3] + s * (y[3] - x[3]),
            ]
        };
        let mut q = [[0.0; 4]; M];
        q.copy_from_slice(&self.points[..M]);
        // Down to three points (two for a line), keeping the last levels for the derivatives.
        for level in 1..=p.saturating_sub(2) {
            for i in 0..=p - level {
                q[i] = lerp(q[i], q[i + 1]);
            }
        }
        let (second, r0, r1) = if p >= 2 {
            let k = (p * (p - 1)) as f64 * (inv_h * inv_h);
            let second: [f64; 4] = std::array::from_fn(|c| k * (q[0][c] - 2.0 * q[1][c] + q[2][c]));
            (second, lerp(q[0], q[1]), lerp(q[1], q[2]))
        } else {
            ([0.0; 4], q[0], q[1])
        };
        let k = p as f64 * inv_h;
        let first: [f64; 4] = std::array::from_fn(|c| k * (r1[c] - r0[c]));
        let point = lerp(r0, r1);
        let c0 = Vector3::new(point[0], point[1], point[2]);
        let a1 = Vector3::new(first[0], first[1], first[2]);
        let a2 = Vector3::new(second[0], second[1], second[2]);
        if !self.rational {
            return [c0, a1, a2];
        }
        // The quotient rule for C = A / w.
        let inv_w = 1.0 / point[3];
        let c0 = c0 * inv_w;
        let c1 = (a1 - c0 * first[3]) * inv_w;
        let c2 = (a2 - c1 * (2.0 * first[3]) - c0 * second[3]) * inv_w;
        [c0, c1, c2]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn curve(degree: usize) -> NurbsCurve {
        let n = 8;
        let points = (0..n)
            .map(|i| Point3::new(i as f64, (i * i % 5) as f64, (i % 2) as f64))
            .collect();
        let weights = vec![1.0, 2.0, 0.5, 1.0, 1.5, 0.7, 1.0, 1.2];
        let mut knots = vec![0.0; degree];
        let interior = n - degree - 1;
        knots.extend((1..=interior).map(|k| (k * k) as f64 * 0.3));
        knots.extend(vec![(interior * interior) as f64 * 0.3 + 1.0; degree]);
        NurbsCurve::new(degree, points, weights, knots).unwrap()
    }

    #[test]
    fn the_piece_evaluates_as_the_curve_and_bounds_it() {
        for degree in 1..=5 {
            let c = curve(degree);
            for span in c.span_indices() {
                let piece = c.bezier_piece(span);
                for k in 0..=16 {
                    let t = piece.a + (piece.b - piece.a) * k as f64 / 16.0;
                    let mut d = [Vector3::ZERO; 3];
                    c.derivatives_in_span(span, t, &mut d);
                    let e = piece.derivatives(t);
                    for (x, y) in d.iter().zip(&e) {
                        assert!(
                            (*x - *y).length() <= 1e-11 * (1.0 + x.length()),
                            "{x:?} {y:?}"
                        );
                    }
                    assert!(piece.box_distance_squared(c.point_at(t)) <= 1e-26);
                }
                for (k, half) in piece.halves().iter().enumerate() {
                    assert_eq!(
                        half.a,
                        if k == 0 {
                            piece.a
                        } else {
                            0.5 * (piece.a + piece.b)
                        }
                    );
                    for j in 0..=8 {
                        let t = half.a + (half.b - half.a) * j as f64 / 8.0;
                        let (x, y) = (half.derivatives(t)[0], piece.derivatives(t)[0]);
                        assert!(
                            (x - y).length() <= 1e-11 * (1.0 + x.length()),
                            "{x:?} {y:?}"
                        );
                        let on = c.point_at(t);
                        assert!(half.box_distance_squared(on) <= 1e-26);
                        for quarter in half.halves() {
                            if (quarter.a..=quarter.b).contains(&t) {
                                assert!(quarter.box_distance_squared(on) <= 1e-26);
                            }
                        }
                    }
                }
                let beside = c.point_at(piece.a) + Vector3::new(0.0, 0.0, 50.0);
                assert!(piece.box_distance_squared(beside) > 1.0);
            }
        }
    }
}

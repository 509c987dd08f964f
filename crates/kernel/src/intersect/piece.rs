//! A piece of a curve in Bézier form that can be cut further: the homogeneous control points
//! `(w·P, w)` of one span's polynomial, or of a part of it, with its parameter range.
//!
//! The searches of this layer subdivide such pieces: a piece lies in the convex hull of its
//! projected control points (weights are positive), so two pieces whose control-point boxes
//! are further apart than the tolerance cannot meet, and a piece whose control points lie
//! close to the chord between its ends is nearly straight, where Newton's method converges
//! from the chord's estimate.

use crate::curve::nurbs::basis::MAX_ORDER;
use crate::{NurbsCurve, Point3, Vector3};

/// A polynomial piece on the parameter range `[a, b]`, in Bézier form.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Piece {
    /// The parameter at the start.
    pub(crate) a: f64,
    /// The parameter at the end.
    pub(crate) b: f64,
    /// The number of control points, degree + 1.
    len: usize,
    /// Homogeneous control points, `len` of them.
    h: [[f64; 4]; MAX_ORDER],
}

/// At most this many Newton steps in [`Piece::closest`].
const CLOSEST_STEPS: usize = 40;

/// An axis-aligned box as `[lo, hi]` corners.
pub(crate) type Aabb = [[f64; 3]; 2];

impl Piece {
    /// The piece of `span` (a Rhino knot index with `knots[span] < knots[span + 1]`).
    pub(crate) fn of_span(curve: &NurbsCurve, span: usize) -> Self {
        let bezier = curve.bezier_piece(span);
        let points = bezier.homogeneous();
        let mut h = [[0.0; 4]; MAX_ORDER];
        h[..points.len()].copy_from_slice(points);
        Self {
            a: bezier.a,
            b: bezier.b,
            len: points.len(),
            h,
        }
    }

    /// Every span's piece, in order.
    pub(crate) fn all(curve: &NurbsCurve) -> Vec<Self> {
        curve
            .span_indices()
            .map(|span| Self::of_span(curve, span))
            .collect()
    }

    /// The Euclidean control point `i`.
    #[inline]
    pub(crate) fn point(&self, i: usize) -> Point3 {
        let q = self.h[i];
        Point3::new(q[0] / q[3], q[1] / q[3], q[2] / q[3])
    }

    /// The Euclidean control points.
    pub(crate) fn points(&self) -> impl Iterator<Item = Point3> + '_ {
        (0..self.len).map(|i| self.point(i))
    }

    /// The number of control points.
    #[inline]
    pub(crate) fn len(&self) -> usize {
        self.len
    }

    /// The first control point, the curve's point at `a`.
    #[inline]
    pub(crate) fn start(&self) -> Point3 {
        self.point(0)
    }

    /// The last control point, the curve's point at `b`.
    #[inline]
    pub(crate) fn end(&self) -> Point3 {
        self.point(self.len - 1)
    }

    /// The box of the Euclidean control points, which holds the piece.
    pub(crate) fn aabb(&self) -> Aabb {
        let mut lo = [f64::INFINITY; 3];
        let mut hi = [f64::NEG_INFINITY; 3];
        for p in self.points() {
            for (c, x) in p.to_array().into_iter().enumerate() {
                lo[c] = lo[c].min(x);
                hi[c] = hi[c].max(x);
            }
        }
        [lo, hi]
    }

    /// The largest distance of a control point from the chord between the ends (from the
    /// start point where the ends coincide).
    pub(crate) fn deviation(&self) -> f64 {
        let (p0, p1) = (self.start(), self.end());
        let chord = p1 - p0;
        let length_squared = chord.length_squared();
        self.points()
            .map(|p| {
                let d = p - p0;
                if length_squared > 0.0 {
                    let t = (d.dot(chord) / length_squared).clamp(0.0, 1.0);
                    (d - chord * t).length()
                } else {
                    d.length()
                }
            })
            .fold(0.0, f64::max)
    }

    /// Whether the piece is nearly straight: its control points lie within `relative` of the
    /// chord's length from the chord, or within `absolute` of it.
    pub(crate) fn is_flat(&self, relative: f64, absolute: f64) -> bool {
        let deviation = self.deviation();
        deviation <= absolute || deviation <= relative * self.start().distance(self.end())
    }

    /// The two halves, by de Casteljau's algorithm at the middle.
    pub(crate) fn halve(&self) -> (Self, Self) {
        self.split(0.5)
    }

    /// The parts before and after the local parameter `u` in `(0, 1)`.
    pub(crate) fn split(&self, u: f64) -> (Self, Self) {
        let n = self.len;
        let mut left = [[0.0; 4]; MAX_ORDER];
        let mut right = [[0.0; 4]; MAX_ORDER];
        let mut q = self.h;
        left[0] = q[0];
        right[n - 1] = q[n - 1];
        for level in 1..n {
            for i in 0..n - level {
                let next = q[i + 1];
                for (x, y) in q[i].iter_mut().zip(next) {
                    *x += u * (y - *x);
                }
            }
            left[level] = q[0];
            right[n - 1 - level] = q[n - 1 - level];
        }
        let m = if u == 0.5 {
            0.5 * (self.a + self.b)
        } else {
            self.a + u * (self.b - self.a)
        };
        (
            Self {
                a: self.a,
                b: m,
                len: n,
                h: left,
            },
            Self {
                a: m,
                b: self.b,
                len: n,
                h: right,
            },
        )
    }

    /// The part on `[t0, t1]`, a sub-range of `[a, b]`.
    pub(crate) fn sub(&self, t0: f64, t1: f64) -> Self {
        let length = self.b - self.a;
        let mut out = *self;
        if t0 > self.a && length > 0.0 {
            out = out.split((t0 - self.a) / length).1;
            out.a = t0;
        }
        let length = out.b - out.a;
        if t1 < out.b && length > 0.0 {
            out = out.split((t1 - out.a) / length).0;
            out.b = t1;
        }
        out
    }

    /// The point and its first and second derivatives at `t` (one-sided at the ends), by de
    /// Casteljau's algorithm on the homogeneous points and the quotient rule.
    pub(crate) fn derivatives(&self, t: f64) -> [Vector3; 3] {
        let n = self.len;
        let p = n - 1;
        let h = self.b - self.a;
        let s = if h > 0.0 { (t - self.a) / h } else { 0.0 };
        let mut q = self.h;
        // Reduce to the last three points (or fewer), whose differences give the derivatives.
        let keep = n.min(3);
        for level in 1..=n - keep {
            for i in 0..n - level {
                let next = q[i + 1];
                for (x, y) in q[i].iter_mut().zip(next) {
                    *x += s * (y - *x);
                }
            }
        }
        let (point, first, second) = match keep {
            1 => (q[0], [0.0; 4], [0.0; 4]),
            2 => {
                let k = if h > 0.0 { p as f64 / h } else { 0.0 };
                let first: [f64; 4] = std::array::from_fn(|c| k * (q[1][c] - q[0][c]));
                let point: [f64; 4] = std::array::from_fn(|c| q[0][c] + s * (q[1][c] - q[0][c]));
                (point, first, [0.0; 4])
            }
            _ => {
                let k2 = if h > 0.0 {
                    (p * (p - 1)) as f64 / (h * h)
                } else {
                    0.0
                };
                let second: [f64; 4] =
                    std::array::from_fn(|c| k2 * (q[2][c] - 2.0 * q[1][c] + q[0][c]));
                let r0: [f64; 4] = std::array::from_fn(|c| q[0][c] + s * (q[1][c] - q[0][c]));
                let r1: [f64; 4] = std::array::from_fn(|c| q[1][c] + s * (q[2][c] - q[1][c]));
                let k = if h > 0.0 { p as f64 / h } else { 0.0 };
                let first: [f64; 4] = std::array::from_fn(|c| k * (r1[c] - r0[c]));
                let point: [f64; 4] = std::array::from_fn(|c| r0[c] + s * (r1[c] - r0[c]));
                (point, first, second)
            }
        };
        let w = point[3];
        let c0 = Vector3::new(point[0], point[1], point[2]) / w;
        let a1 = Vector3::new(first[0], first[1], first[2]);
        let a2 = Vector3::new(second[0], second[1], second[2]);
        let c1 = (a1 - c0 * first[3]) / w;
        let c2 = (a2 - c1 * (2.0 * first[3]) - c0 * second[3]) / w;
        [c0, c1, c2]
    }

    /// The point at `t`.
    pub(crate) fn point_at(&self, t: f64) -> Point3 {
        Point3::from_vector(self.derivatives(t)[0])
    }

    /// The parameter of the point of the piece closest to `p`, and the distance: the best of
    /// a few samples per control point, polished by Newton's method on `½|C(t) − p|²`,
    /// confined to `[a, b]`.
    pub(crate) fn closest(&self, p: Point3) -> (f64, f64) {
        let n = 4 * self.len;
        let (mut t, mut f) = (self.a, f64::INFINITY);
        for k in 0..=n {
            let s = if k == n {
                self.b
            } else {
                self.a + (self.b - self.a) * k as f64 / n as f64
            };
            let d = self.point_at(s).distance_squared(p);
            if d < f {
                (t, f) = (s, d);
            }
        }
        let scale = p.to_vector().length().max(1.0);
        let noise = (8.0 * f64::EPSILON * scale).powi(2);
        for _ in 0..CLOSEST_STEPS {
            let [c, d1, d2] = self.derivatives(t);
            let r = c - p.to_vector();
            let g = r.dot(d1);
            let h = d1.dot(d1) + r.dot(d2);
            let h = if h > 0.0 { h } else { d1.dot(d1) };
            if g == 0.0 || h.is_nan() || h <= 0.0 {
                break;
            }
            let mut step = -g / h;
            let mut moved = false;
            for _ in 0..30 {
                let tn = (t + step).clamp(self.a, self.b);
                let fn_ = self.point_at(tn).distance_squared(p);
                if fn_ <= f + noise {
                    moved = tn != t;
                    (t, f) = (tn, fn_);
                    break;
                }
                step *= 0.5;
            }
            if !moved {
                break;
            }
        }
        (t, f.sqrt())
    }

    /// Whether the piece runs one way: some direction has a positive component along every
    /// difference of consecutive control points (the hodograph's control points for a
    /// polynomial piece, and the same test suffices for positive weights since a rational
    /// piece's tangent direction lies in the cone of those differences). Such a piece has a
    /// strictly monotone projection on that direction and cannot meet itself.
    pub(crate) fn is_monotone(&self) -> bool {
        let mut sum = Vector3::ZERO;
        let mut differences = [Vector3::ZERO; MAX_ORDER];
        for (i, d) in differences[..self.len - 1].iter_mut().enumerate() {
            *d = self.point(i + 1) - self.point(i);
            sum += d.normalize_or_zero();
        }
        if sum.length_squared() == 0.0 {
            return false;
        }
        differences[..self.len - 1]
            .iter()
            .all(|d| d.length_squared() == 0.0 || d.dot(sum) > 0.0)
            && differences[..self.len - 1]
                .iter()
                .any(|d| d.length_squared() > 0.0)
    }
}

/// Whether two boxes come within `gap` of each other.
#[inline]
pub(crate) fn boxes_meet(a: &Aabb, b: &Aabb, gap: f64) -> bool {
    (0..3).all(|c| a[0][c] <= b[1][c] + gap && b[0][c] <= a[1][c] + gap)
}

/// The diagonal of a box.
#[inline]
pub(crate) fn diagonal(b: &Aabb) -> f64 {
    let d: [f64; 3] = std::array::from_fn(|c| b[1][c] - b[0][c]);
    (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn curve() -> NurbsCurve {
        let points = vec![
            Point3::new(0.0, 0.0, 0.0),
            Point3::new(1.0, 2.0, 0.0),
            Point3::new(3.0, -1.0, 1.0),
            Point3::new(4.0, 1.0, 0.0),
            Point3::new(6.0, 0.0, 2.0),
        ];
        NurbsCurve::new(
            3,
            points,
            vec![1.0, 2.0, 0.5, 1.0, 1.5],
            vec![0.0, 0.0, 0.0, 1.5, 2.0, 2.0, 2.0],
        )
        .unwrap()
    }

    #[test]
    fn pieces_evaluate_as_the_curve() {
        let c = curve();
        for piece in Piece::all(&c) {
            for k in 0..=10 {
                let t = piece.a + (piece.b - piece.a) * k as f64 / 10.0;
                let want = c.derivatives_at(t, 2);
                let got = piece.derivatives(t);
                for (x, y) in want.iter().zip(&got) {
                    assert!(
                        (*x - *y).length() < 1e-11 * (1.0 + x.length()),
                        "{x:?} {y:?}"
                    );
                }
            }
        }
    }

    #[test]
    fn sub_pieces_evaluate_as_the_curve() {
        let c = curve();
        let piece = Piece::all(&c)[0];
        let part = piece.sub(0.3, 1.1);
        assert_eq!((part.a, part.b), (0.3, 1.1));
        for k in 0..=8 {
            let t = 0.3 + 0.8 * k as f64 / 8.0;
            assert!(part.point_at(t).distance(c.point_at(t)) < 1e-12);
        }
        assert!(part.start().distance(c.point_at(0.3)) < 1e-12);
        assert!(part.end().distance(c.point_at(1.1)) < 1e-12);
        let (l, r) = part.halve();
        assert_eq!(l.b, r.a);
        assert!(l.end().distance(c.point_at(l.b)) < 1e-12);
    }

    #[test]
    fn flatness_and_monotony() {
        let line = NurbsCurve::new_non_rational(
            1,
            vec![Point3::new(0.0, 0.0, 0.0), Point3::new(2.0, 1.0, 0.0)],
            vec![0.0, 1.0],
        )
        .unwrap();
        let piece = Piece::all(&line)[0];
        assert!(piece.is_flat(0.0, 0.0));
        assert!(piece.is_monotone());
        // A loop: the control polygon doubles back.
        let looped = NurbsCurve::new_non_rational(
            3,
            vec![
                Point3::new(0.0, 0.0, 0.0),
                Point3::new(3.0, 2.0, 0.0),
                Point3::new(-1.0, 2.0, 0.0),
                Point3::new(2.0, 0.0, 0.0),
            ],
            vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0],
        )
        .unwrap();
        let piece = Piece::all(&looped)[0];
        assert!(!piece.is_flat(0.1, 0.0));
        assert!(!piece.is_monotone());
    }
}

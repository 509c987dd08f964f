//! The globally closest point of a NURBS curve to a test point.
//!
//! The minimum of `f(t) = |C(t) − P|²` over the closed domain lies either at a root of
//! `g(t) = C'(t)·(C(t) − P)` where `g` changes sign from negative to positive, or at a place
//! where `C` is not differentiable: the domain's ends and the interior knots of multiplicity at
//! least the degree (kinks). Since every span boundary is sampled, the ends and kinks are always
//! candidates. Inside each span `g` is sampled densely enough for the degree; every bracket
//! `g(a) < 0 ≤ g(b)` is polished by Newton's method on `g` (with `g' = C''·(C − P) + |C'|²`),
//! safeguarded by bisection so that it never leaves its bracket, and the best sample of the span
//! is kept as a fallback candidate. The answer is the candidate with the smallest distance; on a
//! tie the smallest parameter wins, so at the seam of a closed curve the domain's start is
//! reported.
//!
//! Most spans cannot hold the answer, and are skipped without being sampled: by the convex hull
//! property (weights are positive), every point of a span lies in the axis-aligned box of the
//! span's `degree + 1` control points, so the distance to that box is a lower bound of the
//! span's distances. The span with the nearest box is searched first, and a span whose bound
//! exceeds the best distance found so far cannot improve on it (nor tie with it), so it is left
//! out; spans that pass are checked again against the box of their Bézier control points,
//! which is much tighter, and against the boxes of their halves and quarters (de Casteljau at
//! the middles). A span's samples fall on its quarters' ends, so each quarter is sampled on its
//! own, the one with the nearest box first, and a quarter whose box is beyond the best distance
//! so far is not sampled. The bounds of the spans are kept on the stack (no allocation) for up
//! to `STACK_SPANS` spans, and pieces of degree up to 3 use four-point arrays. The
//! answer is the same as that of the search of every span,
//! [`NurbsCurve::closest_point_exhaustive`], which the tests compare it with.

use crate::curve::bezier_piece::BezierPiece;
use crate::curve::nurbs::basis::MAX_ORDER;
use crate::{Error, NurbsCurve, Point3, Result};

/// The closest point of a curve to a test point.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CurveClosestPoint {
    /// The parameter of the closest point.
    pub t: f64,
    /// The closest point, `C(t)`.
    pub point: Point3,
    /// The distance from the test point to the closest point.
    pub distance: f64,
}

/// How far (relative, in squared distance) a span's bound must exceed the best squared
/// distance for the span to be skipped: 1e-9, far above the rounding of both, so that a span
/// holding a candidate as close as the best (up to rounding) is still searched and ties are
/// broken as in the search of every span.
const PRUNE_MARGIN: f64 = 1e-9;

/// How many spans' bounds are kept on the stack (beyond, in a vector): 128.
const STACK_SPANS: usize = 128;

/// Lower bounds of the squared distance from a test point to the four quarters of a piece
/// (equal parts of its parameter interval), from the boxes of the Bézier control points of the
/// piece, of its halves and of its quarters (de Casteljau at the middles): a quarter's bound is
/// the largest of its own box's, its half's and the whole piece's.
struct QuarterBounds([f64; 4]);

impl QuarterBounds {
    /// The bounds, or `None` when every quarter is beyond `limit` (the piece cannot hold a
    /// point as close: it is skipped). The halves are only formed when the whole box is not
    /// beyond, and the quarters of a half only when the half's box is not.
    fn of<const N: usize>(piece: &BezierPiece<N>, p: Point3, limit: f64) -> Option<Self> {
        let whole = piece.box_distance_squared(p);
        if whole > limit {
            return None;
        }
        let mut bounds = [whole; 4];
        for (h, half) in piece.halves().iter().enumerate() {
            let bound = half.box_distance_squared(p).max(whole);
            if bound > limit {
                bounds[2 * h] = bound;
                bounds[2 * h + 1] = bound;
                continue;
            }
            for (q, quarter) in half.halves().iter().enumerate() {
                bounds[2 * h + q] = quarter.box_distance_squared(p).max(bound);
            }
        }
        if bounds.iter().all(|&b| b > limit) {
            None
        } else {
            Some(Self(bounds))
        }
    }
}

/// The number of samples per span of a non-rational curve of degree `p`.
fn samples_per_span(degree: usize, rational: bool) -> usize {
    let base = 4 * (degree + 1);
    if rational { 2 * base } else { base }
}

impl NurbsCurve {
    /// The point of the curve closest to `p`: the global minimum of the distance over the whole
    /// domain, ends, kinks and seams included (see the module documentation).
    ///
    /// # Errors
    /// [`Error::NotFinite`] when `p` is not finite.
    pub fn closest_point(&self, p: Point3) -> Result<CurveClosestPoint> {
        if !p.is_finite() {
            return Err(Error::NotFinite { what: "point" });
        }
        let d = self.domain();
        Ok(self.closest_point_between(p, d.t0, d.t1))
    }

    /// The closest point to `p` with the parameter restricted to `[lo, hi]` (`lo ≤ hi`, inside
    /// the domain), pruning the spans by the boxes of their control points.
    pub(crate) fn closest_point_between(&self, p: Point3, lo: f64, hi: f64) -> CurveClosestPoint {
        if self.degree() < 4 {
            self.closest_point_with::<4>(p, lo, hi)
        } else {
            self.closest_point_with::<MAX_ORDER>(p, lo, hi)
        }
    }

    /// [`NurbsCurve::closest_point_between`] with Bézier pieces of room `N > degree`.
    fn closest_point_with<const N: usize>(&self, p: Point3, lo: f64, hi: f64) -> CurveClosestPoint {
        let mut best = self.ends(p, lo, hi);
        let knots = self.knots();
        let first = self.degree() - 1;
        let count = self.points().len() - 1 - first;
        // The bound of every span (infinite for the empty spans and those outside `[lo, hi]`),
        // on the stack for most curves.
        let mut stack = [f64::INFINITY; STACK_SPANS];
        let mut heap = Vec::new();
        let bounds: &mut [f64] = if count <= STACK_SPANS {
            &mut stack[..count]
        } else {
            heap.resize(count, f64::INFINITY);
            &mut heap
        };
        let mut nearest = None;
        let mut nearest_bound = f64::INFINITY;
        let order = self.degree() + 1;
        let (points, spans) = (self.points(), &knots[first..]);
        for (k, (bound, ends)) in bounds.iter_mut().zip(spans.windows(2)).enumerate() {
            if ends[0] < ends[1] && ends[1] > lo && ends[0] < hi {
                // The span's control points are `first + k + 1 − degree = k` onwards.
                *bound = box_distance_squared(&points[k..k + order], p);
                if *bound < nearest_bound || nearest.is_none() {
                    nearest_bound = *bound;
                    nearest = Some(k);
                }
            }
        }
        let limit = |best: &CurveClosestPoint| best.distance * best.distance * (1.0 + PRUNE_MARGIN);
        // The span of the nearest box first, which usually holds the answer, then the others
        // in order, each unless its box (of the B-spline control points, then of the tighter
        // Bézier control points, then of the halves and quarters of its Bézier form) is beyond
        // the best distance so far.
        if let Some(k) = nearest {
            let piece = self.bezier_piece_in::<N>(first + k);
            self.search_pruned(&piece, p, lo, hi, &mut best, &limit);
        }
        for (k, &bound) in bounds.iter().enumerate() {
            if Some(k) == nearest || bound > limit(&best) {
                continue;
            }
            let piece = self.bezier_piece_in::<N>(first + k);
            self.search_pruned(&piece, p, lo, hi, &mut best, &limit);
        }
        self.finish(p, best)
    }

    /// Searches `piece` (restricted to `[lo, hi]`) unless its boxes show it is beyond the best
    /// distance so far; over a whole span, the quarters of the span whose boxes are beyond are
    /// not sampled (see [`QuarterBounds`]).
    fn search_pruned<const N: usize>(
        &self,
        piece: &BezierPiece<N>,
        p: Point3,
        lo: f64,
        hi: f64,
        best: &mut CurveClosestPoint,
        limit: &impl Fn(&CurveClosestPoint) -> f64,
    ) {
        let bounds = QuarterBounds::of(piece, p, limit(best));
        let Some(bounds) = bounds else {
            return;
        };
        if lo <= piece.a && piece.b <= hi {
            self.search_quarters(piece, p, &bounds, best, limit);
        } else {
            self.search_piece(piece, p, lo, hi, best);
        }
    }

    /// Samples the quarters of the whole `piece` nearest bound first, each unless its bound is
    /// beyond the best distance so far: the samples, brackets and roots of the quarters that
    /// are searched are those of [`NurbsCurve::search_piece`] on the whole piece (the quarters'
    /// ends are samples of the span's grid), and a quarter that is skipped holds no point as
    /// close as the best one.
    fn search_quarters<const N: usize>(
        &self,
        piece: &BezierPiece<N>,
        p: Point3,
        bounds: &QuarterBounds,
        best: &mut CurveClosestPoint,
        limit: &impl Fn(&CurveClosestPoint) -> f64,
    ) {
        let (a, b) = (piece.a, piece.b);
        let samples = samples_per_span(self.degree(), self.is_rational());
        let per_quarter = samples / 4;
        let at = |k: usize| {
            if k == samples {
                b
            } else {
                a + (b - a) * (k as f64 / samples as f64)
            }
        };
        let mut order = [0, 1, 2, 3];
        order.sort_by(|&x, &y| bounds.0[x].total_cmp(&bounds.0[y]));
        for quarter in order {
            if bounds.0[quarter] > limit(best) {
                continue;
            }
            let first = quarter * per_quarter;
            let mut prev_t = at(first);
            let (mut prev_g, start) = sample(piece, p, prev_t);
            let mut best_sample = start;
            for k in first + 1..=first + per_quarter {
                let t = at(k);
                let (g, c) = sample(piece, p, t);
                if c.distance < best_sample.distance {
                    best_sample = c;
                }
                if prev_g < 0.0 && g >= 0.0 {
                    let (root, _) = polish(piece, p, prev_t, t);
                    offer(best, self.candidate(p, root));
                }
                prev_t = t;
                prev_g = g;
            }
            offer(best, best_sample);
        }
    }

    /// The closest point to `p` over the whole domain by the search of every span, without the
    /// pruning of [`NurbsCurve::closest_point`] (the reference it is tested and benchmarked
    /// against; the answers are equal).
    ///
    /// # Errors
    /// [`Error::NotFinite`] when `p` is not finite.
    #[doc(hidden)]
    pub fn closest_point_exhaustive(&self, p: Point3) -> Result<CurveClosestPoint> {
        if !p.is_finite() {
            return Err(Error::NotFinite { what: "point" });
        }
        let d = self.domain();
        let mut best = self.ends(p, d.t0, d.t1);
        for span in self.span_indices() {
            self.search_piece(&self.bezier_piece(span), p, d.t0, d.t1, &mut best);
        }
        Ok(self.finish(p, best))
    }

    /// The better of the two ends `lo` and `hi` (the start on a tie).
    fn ends(&self, p: Point3, lo: f64, hi: f64) -> CurveClosestPoint {
        let start = self.candidate(p, lo);
        let end = self.candidate(p, hi);
        if end.distance < start.distance {
            end
        } else {
            start
        }
    }

    /// The answer with its point evaluated by [`NurbsCurve::point_at`] (the search measures
    /// distances with the points of the span derivatives, which may differ in the last bit).
    fn finish(&self, p: Point3, best: CurveClosestPoint) -> CurveClosestPoint {
        let point = self.point_at(best.t);
        CurveClosestPoint {
            t: best.t,
            point,
            distance: point.distance(p),
        }
    }

    /// Samples `piece` (restricted to `[lo, hi]`), polishes every bracket of a minimum and
    /// offers the roots and the best sample to `best` (smaller distance, or equal distance and
    /// smaller parameter, wins). The piece is evaluated in its Bézier form, so that at the
    /// span's end the derivatives are those from the left.
    fn search_piece<const N: usize>(
        &self,
        piece: &BezierPiece<N>,
        p: Point3,
        lo: f64,
        hi: f64,
        best: &mut CurveClosestPoint,
    ) {
        let a = piece.a.max(lo);
        let b = piece.b.min(hi);
        if b <= a {
            return;
        }
        let samples = samples_per_span(self.degree(), self.is_rational());
        let (mut prev_g, start) = sample(piece, p, a);
        let mut prev_t = a;
        let mut best_sample = start;
        for k in 1..=samples {
            let t = if k == samples {
                b
            } else {
                a + (b - a) * (k as f64 / samples as f64)
            };
            let (g, c) = sample(piece, p, t);
            if c.distance < best_sample.distance {
                best_sample = c;
            }
            if prev_g < 0.0 && g >= 0.0 {
                let (root, _) = polish(piece, p, prev_t, t);
                offer(best, self.candidate(p, root));
            }
            prev_t = t;
            prev_g = g;
        }
        offer(best, best_sample);
    }

    fn candidate(&self, p: Point3, t: f64) -> CurveClosestPoint {
        let point = self.point_at(t);
        CurveClosestPoint {
            t,
            point,
            distance: point.distance(p),
        }
    }
}

/// The squared distance from `p` to the axis-aligned box of `cvs` (at least one point).
fn box_distance_squared(cvs: &[Point3], p: Point3) -> f64 {
    // Finite coordinates (a valid curve), so plain comparisons, which compile to single
    // min/max instructions, suffice.
    let min = |x: f64, y: f64| if y < x { y } else { x };
    let max = |x: f64, y: f64| if y > x { y } else { x };
    let Some((head, tail)) = cvs.split_first() else {
        return f64::INFINITY;
    };
    let (mut lo, mut hi) = (*head, *head);
    for q in tail {
        lo.x = min(lo.x, q.x);
        lo.y = min(lo.y, q.y);
        lo.z = min(lo.z, q.z);
        hi.x = max(hi.x, q.x);
        hi.y = max(hi.y, q.y);
        hi.z = max(hi.z, q.z);
    }
    let dx = max(max(lo.x - p.x, p.x - hi.x), 0.0);
    let dy = max(max(lo.y - p.y, p.y - hi.y), 0.0);
    let dz = max(max(lo.z - p.z, p.z - hi.z), 0.0);
    dx * dx + dy * dy + dz * dz
}

/// `g(t) = C′·(C − P)` on `piece` and the candidate at `t`.
fn sample<const N: usize>(piece: &BezierPiece<N>, p: Point3, t: f64) -> (f64, CurveClosestPoint) {
    let [d0, d1, _] = piece.derivatives(t);
    let point = Point3::from_vector(d0);
    let r = point - p;
    (
        d1.dot(r),
        CurveClosestPoint {
            t,
            point,
            distance: r.length(),
        },
    )
}

/// `g(t) = C′·(C − P)` and its derivative `C″·(C − P) + |C′|²` on `piece`.
fn distance_gradient<const N: usize>(piece: &BezierPiece<N>, p: Point3, t: f64) -> (f64, f64) {
    let [d0, d1, d2] = piece.derivatives(t);
    let r = Point3::from_vector(d0) - p;
    (d1.dot(r), d2.dot(r) + d1.length_squared())
}

/// A root of `g` in `[a, b]` with `g(a) < 0 ≤ g(b)`: Newton's method, falling back to
/// bisection whenever a step would leave the bracket; with the number of evaluations of `g`.
fn polish<const N: usize>(piece: &BezierPiece<N>, p: Point3, a: f64, b: f64) -> (f64, usize) {
    let (mut lo, mut hi) = (a, b);
    let mut t = 0.5 * (a + b);
    let scale = a.abs().max(b.abs()).max(1.0);
    for step in 1..=100 {
        let (g, dg) = distance_gradient(piece, p, t);
        if g == 0.0 {
            return (t, step);
        }
        if g < 0.0 {
            lo = t;
        } else {
            hi = t;
        }
        let newton = t - g / dg;
        let tolerance = 2.0 * f64::EPSILON * scale;
        if dg > 0.0 && (newton - t).abs() <= tolerance {
            // Converged: the step is at rounding level (it may round back onto `t`, which is
            // then a bracket end, so it is not sent through the bracket test below, where it
            // would fall back to bisection and crawl to the other end).
            let root = if newton > lo && newton < hi {
                newton
            } else {
                t
            };
            return (root, step);
        }
        let next = if dg > 0.0 && newton > lo && newton < hi {
            newton
        } else {
            0.5 * (lo + hi)
        };
        if hi - lo <= tolerance {
            return (next, step);
        }
        t = next;
    }
    (t, 100)
}

/// Replaces `best` by `c` if `c` is closer, or as close with a smaller parameter.
fn offer(best: &mut CurveClosestPoint, c: CurveClosestPoint) {
    if c.distance < best.distance || (c.distance == best.distance && c.t < best.t) {
        *best = c;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Circle, Plane, Polyline};
    use proptest::prelude::*;

    /// How far the pruned search's distance may be from the search of every span, relative to
    /// the size of the scene (control points within 10 of the origin, queries within 20):
    /// 1e-12, rounding only (the pruning only leaves out spans and quarters whose boxes are
    /// beyond the best distance).
    const EQUAL_ANSWERS: f64 = 1e-12;

    /// Curves of degree 1 to 5 with 2 to 12 control points, random weights and knot spacings,
    /// some knots repeated up to the degree (kinks).
    fn arb_curve() -> impl Strategy<Value = NurbsCurve> {
        (1usize..=5, 0usize..=7, any::<bool>()).prop_flat_map(|(degree, extra, rational)| {
            let n = degree + 1 + extra;
            (
                prop::collection::vec((-10.0f64..10.0, -10.0f64..10.0, -10.0f64..10.0), n),
                prop::collection::vec(0.3f64..3.0, n),
                prop::collection::vec((0.05f64..2.0, 0usize..3), n - degree),
            )
                .prop_map(move |(points, weights, steps)| {
                    let points: Vec<Point3> = points
                        .into_iter()
                        .map(|(x, y, z)| Point3::new(x, y, z))
                        .collect();
                    let weights = if rational { weights } else { vec![1.0; n] };
                    let mut knots = vec![0.0; degree];
                    let (mut k, mut used) = (0.0, 0);
                    let slots = n - degree - 1;
                    while knots.len() < degree + slots {
                        let (step, repeat) = steps[used];
                        used += 1;
                        k += step;
                        let copies = (repeat + 1).min(degree).min(degree + slots - knots.len());
                        knots.extend(std::iter::repeat_n(k, copies));
                    }
                    let end = k + steps[used].0;
                    knots.extend(std::iter::repeat_n(end, degree));
                    NurbsCurve::new(degree, points, weights, knots).expect("a valid curve")
                })
        })
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(200))]

        /// The pruned search (span boxes, Bézier boxes, quarters skipped and searched nearest
        /// first) answers as the search of every span.
        #[test]
        fn the_pruned_search_equals_the_search_of_every_span(
            curve in arb_curve(),
            queries in prop::collection::vec(
                (-20.0f64..20.0, -20.0f64..20.0, -20.0f64..20.0), 1..16),
        ) {
            for (x, y, z) in queries {
                let p = Point3::new(x, y, z);
                let pruned = curve.closest_point(p).unwrap();
                let every = curve.closest_point_exhaustive(p).unwrap();
                prop_assert!(
                    (pruned.distance - every.distance).abs() <= EQUAL_ANSWERS * 40.0,
                    "{p:?}: pruned {pruned:?}, every span {every:?}"
                );
                prop_assert!(pruned.point.distance(p) == pruned.distance);
            }
        }
    }

    #[test]
    fn circle_closest_point_is_radial() {
        let c = Circle::new(Plane::WORLD_XY, 2.0).unwrap();
        let n = c.to_nurbs();
        let q = Point3::new(3.0, 4.0, 1.0);
        let r = n.closest_point(q).unwrap();
        assert!((r.distance - ((5.0f64 - 2.0).powi(2) + 1.0).sqrt()).abs() < 1e-12);
        assert!(r.point.distance(Point3::new(1.2, 1.6, 0.0)) < 1e-10);
    }

    #[test]
    fn the_polish_stops_when_newton_converges() {
        // Before, a converged Newton step that rounded back onto the bracket's end fell back to
        // bisection, which crawled to the other end: about 18 evaluations per root on this
        // helix (the benchmark's), against 4 now.
        let points: Vec<Point3> = (0..64)
            .map(|i| {
                let a = i as f64 * 0.4;
                Point3::new(10.0 * a.cos(), 10.0 * a.sin(), 0.5 * i as f64)
            })
            .collect();
        let c = NurbsCurve::create(&points, 3, false).unwrap();
        let (mut roots, mut steps) = (0, 0);
        for k in 0..200 {
            let a = k as f64 * 0.37;
            let p = Point3::new(4.0 * a.cos(), 5.0 * a.sin(), (k % 32) as f64);
            for span in c.span_indices() {
                let piece = c.bezier_piece(span);
                let g = |t: f64| distance_gradient(&piece, p, t).0;
                let n = 16;
                for j in 0..n {
                    let t0 = piece.a + (piece.b - piece.a) * j as f64 / n as f64;
                    let t1 = piece.a + (piece.b - piece.a) * (j + 1) as f64 / n as f64;
                    if g(t0) < 0.0 && g(t1) >= 0.0 {
                        let (t, count) = polish(&piece, p, t0, t1);
                        assert!((t0..=t1).contains(&t));
                        assert!(g(t).abs() <= 1e-9, "{}", g(t));
                        roots += 1;
                        steps += count;
                    }
                }
            }
        }
        assert!(roots > 100, "{roots}");
        assert!(steps <= 6 * roots, "{steps} evaluations for {roots} roots");
    }

    #[test]
    fn ends_and_kinks_are_found() {
        let p = Polyline::new(vec![
            Point3::new(0.0, 0.0, 0.0),
            Point3::new(10.0, 0.0, 0.0),
            Point3::new(10.0, 10.0, 0.0),
        ])
        .unwrap()
        .to_nurbs();
        // Outside the corner: the kink at t = 1 is closest.
        let r = p.closest_point(Point3::new(12.0, -1.0, 0.0)).unwrap();
        assert_eq!(r.t, 1.0);
        // Before the start.
        let r = p.closest_point(Point3::new(-3.0, -1.0, 0.0)).unwrap();
        assert_eq!(r.t, 0.0);
        assert!(p.closest_point(Point3::new(f64::NAN, 0.0, 0.0)).is_err());
    }
}

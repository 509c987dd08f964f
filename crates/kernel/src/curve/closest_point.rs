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
//! which is much tighter. The
//! answer is the same as that of the search of every span,
//! [`NurbsCurve::closest_point_exhaustive`], which the tests compare it with.

use crate::curve::bezier_piece::BezierPiece;
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

/// How many times a span's Bézier form is halved, at most, to show by the boxes of the parts
/// that the span is beyond the best distance so far, before it is searched: 2 (four parts).
/// Halving is cheap beside a search, and each halving about halves the margin between the box
/// and the curve.
const HALVINGS: u32 = 2;

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
        let mut best = self.ends(p, lo, hi);
        let mut spans: Vec<(f64, usize)> = Vec::with_capacity(self.points().len());
        spans.extend(
            self.span_indices()
                .filter(|&span| self.knots()[span + 1] > lo && self.knots()[span] < hi)
                .map(|span| (self.span_box_distance_squared(span, p), span)),
        );
        let limit = |best: &CurveClosestPoint| best.distance * best.distance * (1.0 + PRUNE_MARGIN);
        // The span of the nearest box first, which usually holds the answer, then the others
        // in order, each unless its box (of the B-spline control points, then of the tighter
        // Bézier control points, then of the halves of its Bézier form) is beyond the best
        // distance so far.
        let nearest = spans
            .iter()
            .enumerate()
            .min_by(|x, y| x.1.0.total_cmp(&y.1.0))
            .map(|(k, _)| k);
        if let Some(k) = nearest {
            self.search_piece(&self.bezier_piece(spans[k].1), p, lo, hi, &mut best);
        }
        for (k, &(bound, span)) in spans.iter().enumerate() {
            if Some(k) == nearest || bound > limit(&best) {
                continue;
            }
            let piece = self.bezier_piece(span);
            if !piece.is_beyond(p, limit(&best), HALVINGS) {
                self.search_piece(&piece, p, lo, hi, &mut best);
            }
        }
        self.finish(p, best)
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
        let spans: Vec<usize> = self.span_indices().collect();
        for span in spans {
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

    /// The squared distance from `p` to the axis-aligned box of the control points of `span`.
    fn span_box_distance_squared(&self, span: usize, p: Point3) -> f64 {
        // Finite coordinates (a valid curve), so plain comparisons, which compile to single
        // min/max instructions, suffice.
        let min = |x: f64, y: f64| if y < x { y } else { x };
        let max = |x: f64, y: f64| if y > x { y } else { x };
        let first = span + 1 - self.degree();
        let cvs = &self.points()[first..=first + self.degree()];
        let (mut lo, mut hi) = (
            [cvs[0].x, cvs[0].y, cvs[0].z],
            [cvs[0].x, cvs[0].y, cvs[0].z],
        );
        for q in &cvs[1..] {
            let q = [q.x, q.y, q.z];
            for c in 0..3 {
                lo[c] = min(lo[c], q[c]);
                hi[c] = max(hi[c], q[c]);
            }
        }
        let p = [p.x, p.y, p.z];
        let mut sum = 0.0;
        for c in 0..3 {
            let d = max(max(lo[c] - p[c], p[c] - hi[c]), 0.0);
            sum += d * d;
        }
        sum
    }

    /// Samples `piece` (restricted to `[lo, hi]`), polishes every bracket of a minimum and
    /// offers the roots and the best sample to `best` (smaller distance, or equal distance and
    /// smaller parameter, wins). The piece is evaluated in its Bézier form, so that at the
    /// span's end the derivatives are those from the left.
    fn search_piece(
        &self,
        piece: &BezierPiece,
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

/// `g(t) = C′·(C − P)` on `piece` and the candidate at `t`.
fn sample(piece: &BezierPiece, p: Point3, t: f64) -> (f64, CurveClosestPoint) {
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
fn distance_gradient(piece: &BezierPiece, p: Point3, t: f64) -> (f64, f64) {
    let [d0, d1, d2] = piece.derivatives(t);
    let r = Point3::from_vector(d0) - p;
    (d1.dot(r), d2.dot(r) + d1.length_squared())
}

/// A root of `g` in `[a, b]` with `g(a) < 0 ≤ g(b)`: Newton's method, falling back to
/// bisection whenever a step would leave the bracket; with the number of evaluations of `g`.
fn polish(piece: &BezierPiece, p: Point3, a: f64, b: f64) -> (f64, usize) {
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

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

use crate::{Error, NurbsCurve, Point3, Result, Vector3};

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
    /// the domain).
    pub(crate) fn closest_point_between(&self, p: Point3, lo: f64, hi: f64) -> CurveClosestPoint {
        let mut best = self.candidate(p, lo);
        let end = self.candidate(p, hi);
        if end.distance < best.distance {
            best = end;
        }
        let samples = samples_per_span(self.degree(), self.is_rational());
        let spans: Vec<usize> = self.span_indices().collect();
        for span in spans {
            let a = self.knots()[span].max(lo);
            let b = self.knots()[span + 1].min(hi);
            if b <= a {
                continue;
            }
            let mut prev_t = a;
            let mut prev_g = self.distance_gradient(span, p, a).0;
            let mut best_sample = self.candidate(p, a);
            for k in 1..=samples {
                let t = if k == samples {
                    b
                } else {
                    a + (b - a) * (k as f64 / samples as f64)
                };
                let (g, _) = self.distance_gradient(span, p, t);
                let c = self.candidate(p, t);
                if c.distance < best_sample.distance {
                    best_sample = c;
                }
                if prev_g < 0.0 && g >= 0.0 {
                    let root = self.polish(span, p, prev_t, t);
                    let c = self.candidate(p, root);
                    if c.distance < best.distance || (c.distance == best.distance && c.t < best.t) {
                        best = c;
                    }
                }
                prev_t = t;
                prev_g = g;
            }
            if best_sample.distance < best.distance {
                best = best_sample;
            }
        }
        best
    }

    fn candidate(&self, p: Point3, t: f64) -> CurveClosestPoint {
        let point = self.point_at(t);
        CurveClosestPoint {
            t,
            point,
            distance: point.distance(p),
        }
    }

    /// `g(t) = C'·(C − P)` and its derivative `C''·(C − P) + |C'|²`, on the polynomial piece of
    /// span `span` (so that at the span's end the derivatives are those from the left).
    fn distance_gradient(&self, span: usize, p: Point3, t: f64) -> (f64, f64) {
        let mut d = [Vector3::ZERO; 3];
        self.derivatives_in_span(span, t, &mut d);
        let r = Point3::from_vector(d[0]) - p;
        (d[1].dot(r), d[2].dot(r) + d[1].length_squared())
    }

    /// A root of `g` in `[a, b]` with `g(a) < 0 ≤ g(b)`: Newton's method, falling back to
    /// bisection whenever a step would leave the bracket.
    fn polish(&self, span: usize, p: Point3, a: f64, b: f64) -> f64 {
        let (mut lo, mut hi) = (a, b);
        let mut t = 0.5 * (a + b);
        let scale = a.abs().max(b.abs()).max(1.0);
        for _ in 0..100 {
            let (g, dg) = self.distance_gradient(span, p, t);
            if g == 0.0 {
                return t;
            }
            if g < 0.0 {
                lo = t;
            } else {
                hi = t;
            }
            let newton = t - g / dg;
            let next = if dg > 0.0 && newton > lo && newton < hi {
                newton
            } else {
                0.5 * (lo + hi)
            };
            if (next - t).abs() <= 2.0 * f64::EPSILON * scale
                || hi - lo <= 2.0 * f64::EPSILON * scale
            {
                return next;
            }
            t = next;
        }
        t
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

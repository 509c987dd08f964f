//! Batch evaluation of NURBS curves: many parameters at once, into a caller's buffer.
//!
//! Evaluating point after point spends most of its time finding the knot span and computing the
//! `p + 1` basis functions (with `p(p + 1)/2` divisions). When many parameters fall into the same
//! span both are wasted work: the curve is one polynomial there. [`NurbsCurve::points_at`]
//! therefore converts each span once to its Taylor (power) form about the span's start,
//!
//! ```text
//! A(t) = Σ_j a_j (t − t_span)^j,   a_j = A^(j)(t_span) / j!
//! ```
//!
//! for the homogeneous curve `A = (Σ N w P, Σ N w)`, and then evaluates each parameter with
//! Horner's rule: `p` multiply–adds per coordinate and no division (one for rational
//! curves). The span of consecutive parameters is found by checking the previous span first, so
//! sorted input never searches.
//!
//! The power form is well conditioned for the low degrees used in practice; above
//! [`POWER_FORM_MAX_DEGREE`], and for short batches where the conversion would not pay off, the
//! batch falls back to basis functions, still reusing the span between consecutive parameters.

use crate::curve::nurbs::basis::{self, MAX_ORDER};
use crate::{Error, NurbsCurve, Point3, Result};

/// The highest degree evaluated through the power form; rounding in the conversion grows like
/// `3^p`, which stays below 1e-12 relative up to here.
const POWER_FORM_MAX_DEGREE: usize = 7;

/// Batches shorter than this many parameters per span are evaluated through basis functions.
const MIN_POINTS_PER_SPAN: usize = 4;

impl NurbsCurve {
    /// Evaluates the curve at every parameter of `ts`, writing the points to `out`.
    ///
    /// The result equals [`NurbsCurve::point_at`] at each parameter up to rounding (about 1e-15
    /// relative to the size of the control polygon). Any order of parameters is accepted; sorted
    /// (increasing or decreasing) parameters are fastest. For batches of at least four
    /// parameters per span (and degree at most 7) the method allocates one table of
    /// `degree + 1` coefficients per span, once per call; otherwise it does not allocate.
    ///
    /// # Performance
    /// Measured with `cargo bench -p locus-kernel --bench curve_eval` (1,000,000 parameters on a
    /// cubic with 64 control points and 61 spans, one thread, on the shared 2-core AMD EPYC
    /// development machine under a load average of about 9, so wall-clock figures are
    /// depressed; CPU time is that of the benchmarking thread):
    ///
    /// | path | wall clock | CPU time |
    /// | --- | --- | --- |
    /// | `points_at`, sorted parameters | 57 M points/s | 101 M points/s |
    /// | `points_at`, scrambled parameters | 18 M points/s | 46 M points/s |
    /// | `point_at` loop (baseline) | 5.0 M points/s | 16.8 M points/s |
    /// | rational: `points_at`, sorted | 32 M points/s | 113 M points/s |
    /// | rational: `point_at` loop | 6.4 M points/s | 12.9 M points/s |
    ///
    /// Sorted batches are 6× (non-rational) to 9× (rational) faster than the per-point path in
    /// CPU time, and above the 30 M points/s target even in wall-clock time on the loaded
    /// machine.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] when `ts` and `out` have different lengths.
    pub fn points_at(&self, ts: &[f64], out: &mut [Point3]) -> Result<()> {
        if ts.len() != out.len() {
            return Err(Error::InvalidInput(format!(
                "{} parameters for an output buffer of {} points",
                ts.len(),
                out.len()
            )));
        }
        let spans = self.span_count();
        if self.degree() <= POWER_FORM_MAX_DEGREE && ts.len() >= MIN_POINTS_PER_SPAN * spans {
            self.points_at_power_form(ts, out);
        } else {
            self.points_at_basis(ts, out);
        }
        Ok(())
    }

    /// Per-parameter basis functions, reusing the span of the previous parameter when it fits.
    fn points_at_basis(&self, ts: &[f64], out: &mut [Point3]) {
        let p = self.degree();
        let knots = self.knots();
        let low = p - 1;
        let high = self.point_count() - 2;
        let mut span = basis::span_index(p, knots, ts.first().copied().unwrap_or(0.0));
        let mut n = [0.0; MAX_ORDER];
        for (&t, o) in ts.iter().zip(out.iter_mut()) {
            // Reuse the span when t lies in it (the end spans also cover extrapolation).
            let inside = (span == low || t >= knots[span]) && (span == high || t < knots[span + 1]);
            if !inside {
                span = basis::span_index(p, knots, t);
            }
            basis::basis_functions(p, knots, span, t, &mut n);
            *o = self.combine(span, &n);
        }
    }

    /// The power-form path described in the module documentation.
    fn points_at_power_form(&self, ts: &[f64], out: &mut [Point3]) {
        let table = PowerForm::new(self);
        let breaks = &table.starts;
        let last = breaks.len() - 1;
        let mut s = 0usize;
        for (&t, o) in ts.iter().zip(out.iter_mut()) {
            // Span s covers [starts[s], starts[s+1]); the first and last also extrapolate.
            let fits = (s == 0 || t >= breaks[s]) && (s == last || t < breaks[s + 1]);
            if !fits {
                s = locate(breaks, t);
            }
            *o = table.eval(s, t);
        }
    }
}

/// The index `s` of the span with `starts[s] ≤ t < starts[s + 1]`, clamped to the first and last
/// spans. NaN lands in some span (and evaluates to NaN) without panicking.
#[inline]
fn locate(starts: &[f64], t: f64) -> usize {
    // partition_point gives the number of starts ≤ t.
    let k = starts.partition_point(|&s| s <= t);
    k.saturating_sub(1).min(starts.len() - 1)
}

/// The Taylor coefficients of every span of a curve.
struct PowerForm {
    degree: usize,
    rational: bool,
    /// The parameter at the start of each non-empty span.
    starts: Vec<f64>,
    /// `(degree + 1)` homogeneous coefficients per span, highest power first (for Horner).
    coefficients: Vec<[f64; 4]>,
}

impl PowerForm {
    fn new(curve: &NurbsCurve) -> Self {
        let p = curve.degree();
        let knots = curve.knots();
        let span_count = curve.span_count();
        let mut starts = Vec::with_capacity(span_count);
        let mut coefficients = Vec::with_capacity(span_count * (p + 1));
        let mut ders = [[0.0; MAX_ORDER]; MAX_ORDER];
        for span in curve.span_indices() {
            let a = knots[span];
            starts.push(a);
            basis::basis_function_derivatives(p, knots, span, a, p, &mut ders[..=p]);
            let first = span + 1 - p;
            let cvs = &curve.points()[first..=first + p];
            let ws = &curve.weights()[first..=first + p];
            let mut factorial = 1.0;
            let mut taylor = [[0.0; 4]; MAX_ORDER];
            for (k, row) in ders.iter().enumerate().take(p + 1) {
                if k > 1 {
                    factorial *= k as f64;
                }
                let mut acc = [0.0; 4];
                for ((&n, &w), c) in row.iter().zip(ws).zip(cvs) {
                    let b = n * w;
                    acc[0] += b * c.x;
                    acc[1] += b * c.y;
                    acc[2] += b * c.z;
                    acc[3] += b;
                }
                taylor[k] = acc.map(|x| x / factorial);
            }
            coefficients.extend(taylor[..=p].iter().rev());
        }
        Self {
            degree: p,
            rational: curve.is_rational(),
            starts,
            coefficients,
        }
    }

    #[inline(always)]
    fn eval(&self, s: usize, t: f64) -> Point3 {
        let p = self.degree;
        let dt = t - self.starts[s];
        let c = &self.coefficients[s * (p + 1)..(s + 1) * (p + 1)];
        let [mut x, mut y, mut z, mut w] = c[0];
        // Plain multiply-add rather than `mul_add`, which is a libm call on targets compiled
        // without the FMA feature.
        for k in &c[1..] {
            x = x * dt + k[0];
            y = y * dt + k[1];
            z = z * dt + k[2];
            w = w * dt + k[3];
        }
        if self.rational {
            let r = 1.0 / w;
            Point3::new(x * r, y * r, z * r)
        } else {
            Point3::new(x, y, z)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sample_curve(rational: bool) -> NurbsCurve {
        let points: Vec<Point3> = (0..9)
            .map(|i| {
                let a = i as f64 * 0.7;
                Point3::new(10.0 * a.cos() + i as f64, 8.0 * a.sin(), (i % 3) as f64)
            })
            .collect();
        let weights = if rational {
            (0..9).map(|i| 0.5 + (i % 4) as f64 * 0.6).collect()
        } else {
            vec![1.0; 9]
        };
        let knots = vec![0.0, 0.0, 0.0, 0.5, 1.5, 1.5, 2.0, 3.25, 4.0, 4.0, 4.0];
        NurbsCurve::new(3, points, weights, knots).unwrap()
    }

    #[test]
    fn batch_matches_single_points() {
        for rational in [false, true] {
            let c = sample_curve(rational);
            // Sorted, reversed, shuffled and out-of-domain parameters, plus every knot.
            let mut ts: Vec<f64> = (0..=400).map(|i| i as f64 / 100.0).collect();
            ts.extend(c.knots().iter().copied());
            ts.extend([-0.5, 4.5, 2.0, 1.5, 0.0, 4.0]);
            ts.extend((0..200).map(|i| ((i * 7919) % 401) as f64 / 100.0));
            let rev: Vec<f64> = ts.iter().rev().copied().collect();
            for input in [&ts, &rev, &ts[..5].to_vec()] {
                let mut out = vec![Point3::ORIGIN; input.len()];
                c.points_at(input, &mut out).unwrap();
                for (&t, &p) in input.iter().zip(&out) {
                    let q = c.point_at(t);
                    assert!(p.distance(q) < 1e-12, "t {t}: {p:?} vs {q:?}");
                }
            }
        }
    }

    #[test]
    fn length_mismatch_is_an_error() {
        let c = sample_curve(false);
        let mut out = vec![Point3::ORIGIN; 2];
        assert!(matches!(
            c.points_at(&[0.0, 1.0, 2.0], &mut out),
            Err(Error::InvalidInput(_))
        ));
    }

    #[test]
    fn nan_parameters_do_not_panic() {
        let c = sample_curve(true);
        let ts = vec![f64::NAN; 100];
        let mut out = vec![Point3::ORIGIN; 100];
        c.points_at(&ts, &mut out).unwrap();
        assert!(out.iter().all(|p| p.is_nan()));
        let mut few = [Point3::ORIGIN; 1];
        c.points_at(&[f64::NAN], &mut few).unwrap();
        assert!(few[0].is_nan());
    }
}

//! Arc length of NURBS curves, parameters at given lengths, and division by count and length.
//!
//! The length `∫ |C'(t)| dt` is integrated span by span (between distinct knots the curve is one
//! smooth piece, so kinks never sit inside an integration interval) with adaptive
//! Gauss–Legendre quadrature: each interval is integrated with 10 nodes and as two halves, and
//! halved again until both estimates agree to the interval's share of the tolerance.
//!
//! Parameters at lengths (and the divisions, which need many) go through the length table of
//! `length_table.rs`: the accepted panels of that quadrature with their running sums, inverted
//! by a search for the panel and Newton's method inside it, so that `n` divisions cost one
//! quadrature of the curve and `O(n)` evaluations.

use std::sync::OnceLock;

use crate::curve::length_table::{Cursor, LengthTable};
use crate::geometry::tolerance::LENGTH_TOLERANCE;
use crate::{Error, NurbsCurve, Result, Vector3};

/// The number of Gauss–Legendre nodes per panel.
const NODES: usize = 10;

/// The deepest bisection of one span in the adaptive quadrature: a panel 2⁻²⁴ of its span
/// wide. Deeper bisection only chases rounding noise, and a cap on the depth is a cap on the
/// work (at most 2²⁴ panels a span, reached only when the tolerance cannot be met).
pub(crate) const MAX_DEPTH: u32 = 24;

/// How many times the rounding noise of a length the absolute length tolerance is at least:
/// the speed `|C'(t)|` of a curve whose control points coincide is not exactly zero but a few
/// ulps of the coordinates, so a tolerance relative to a (near) zero length could never be met.
const NOISE_FLOOR_ULPS: f64 = 64.0;

/// The most pieces a curve may be divided into (by count or by length): 10,000,000, so that a
/// mistyped count or a tiny length fails with a reason instead of exhausting memory.
pub const MAX_DIVISIONS: usize = 10_000_000;

/// Checks that `lengths` do not decrease (NaN is left to the per-length checks).
pub(crate) fn check_increasing(lengths: &[f64]) -> Result<()> {
    match lengths.windows(2).position(|w| w[1] < w[0]) {
        Some(i) => Err(Error::InvalidInput(format!(
            "lengths must not decrease: {} then {}",
            lengths[i],
            lengths[i + 1]
        ))),
        None => Ok(()),
    }
}

/// Checks a division count: at least 1, at most [`MAX_DIVISIONS`].
pub(crate) fn check_division_count(count: usize) -> Result<()> {
    if count == 0 {
        return Err(Error::InvalidInput(
            "division count must be at least 1".into(),
        ));
    }
    if count > MAX_DIVISIONS {
        return Err(Error::InvalidInput(format!(
            "division count {count} is more than {MAX_DIVISIONS}"
        )));
    }
    Ok(())
}

/// How many whole `length`s fit into `total`, at most [`MAX_DIVISIONS`].
pub(crate) fn division_count(total: f64, length: f64) -> Result<usize> {
    let count = (total / length).floor();
    if count > MAX_DIVISIONS as f64 {
        return Err(Error::InvalidInput(format!(
            "division length {length} cuts the curve of length {total} into more than \
             {MAX_DIVISIONS} pieces"
        )));
    }
    // `count` is a whole number in 0..=MAX_DIVISIONS here (NaN compares false above and
    // saturates to 0).
    Ok(count as usize)
}

/// The 10-point Gauss–Legendre nodes on `[−1, 1]` and their weights, computed once by Newton's
/// method on the Legendre polynomial `P₁₀`.
pub(crate) fn gauss_legendre() -> &'static ([f64; NODES], [f64; NODES]) {
    static TABLE: OnceLock<([f64; NODES], [f64; NODES])> = OnceLock::new();
    TABLE.get_or_init(|| {
        let n = NODES;
        let mut x = [0.0; NODES];
        let mut w = [0.0; NODES];
        for i in 0..n {
            let mut z = (std::f64::consts::PI * (i as f64 + 0.75) / (n as f64 + 0.5)).cos();
            let mut dp = 1.0;
            for _ in 0..100 {
                // Legendre recurrence for P_n(z) and its derivative.
                let (mut p0, mut p1) = (1.0, z);
                for k in 2..=n {
                    let k = k as f64;
                    let p2 = ((2.0 * k - 1.0) * z * p1 - (k - 1.0) * p0) / k;
                    p0 = p1;
                    p1 = p2;
                }
                dp = n as f64 * (z * p1 - p0) / (z * z - 1.0);
                let dz = p1 / dp;
                z -= dz;
                if dz.abs() < 1e-16 {
                    break;
                }
            }
            x[i] = z;
            w[i] = 2.0 / ((1.0 - z * z) * dp * dp);
        }
        (x, w)
    })
}

impl NurbsCurve {
    /// The speed `|C'(t)|`.
    #[inline]
    pub(crate) fn speed_at(&self, t: f64) -> f64 {
        let mut d = [Vector3::ZERO; 2];
        self.derivatives_into(t, &mut d);
        d[1].length()
    }

    /// Gauss–Legendre estimate of the length over `[a, b]` (one panel).
    fn panel(&self, a: f64, b: f64) -> f64 {
        let (x, w) = gauss_legendre();
        let half = 0.5 * (b - a);
        let mid = 0.5 * (a + b);
        let mut sum = 0.0;
        for (xi, wi) in x.iter().zip(w) {
            sum += wi * self.speed_at(mid + half * xi);
        }
        sum * half
    }

    /// The adaptive length over `[a, b]`, inside one span, to the absolute tolerance `tol`.
    fn adaptive(&self, a: f64, b: f64, whole: f64, tol: f64, depth: u32) -> f64 {
        let m = 0.5 * (a + b);
        let left = self.panel(a, m);
        let right = self.panel(m, b);
        let both = left + right;
        if depth >= MAX_DEPTH || (both - whole).abs() <= tol || !both.is_finite() {
            return both;
        }
        self.adaptive(a, m, left, 0.5 * tol, depth + 1)
            + self.adaptive(m, b, right, 0.5 * tol, depth + 1)
    }

    /// The length over `[a, b]` with `a ≤ b` inside one span, to the absolute tolerance `tol`.
    fn span_length(&self, a: f64, b: f64, tol: f64) -> f64 {
        if b <= a {
            return 0.0;
        }
        let whole = self.panel(a, b);
        // The tolerance cannot go below what rounding leaves of the span's length: a few ulps
        // of it, and, where the span is narrow beside the size of its parameters, the rounding
        // of the parameters themselves (`ε·|t| / (b − a)` of the span). Below that no
        // bisection can meet it, and the quadrature would bisect to `MAX_DEPTH` (16M panels)
        // chasing noise.
        let magnitude = a.abs().max(b.abs());
        let noise = NOISE_FLOOR_ULPS * f64::EPSILON * whole.abs() * (1.0 + magnitude / (b - a));
        self.adaptive(a, b, whole, tol.max(noise), 0)
    }

    /// A quick estimate of the length (one panel per span), used to turn relative tolerances
    /// into absolute ones.
    fn rough_length(&self) -> f64 {
        let breaks = self.span_breaks();
        breaks.windows(2).map(|w| self.panel(w[0], w[1])).sum()
    }

    /// The absolute tolerance of a length computed to the relative tolerance `relative`: that
    /// share of the rough length, but never below the rounding noise of the control points'
    /// coordinates ([`NOISE_FLOOR_ULPS`] ulps of the largest), so that degenerate curves (all
    /// points equal, length zero) finish at once.
    pub(crate) fn absolute_length_tolerance(&self, relative: f64) -> f64 {
        let magnitude = self
            .points()
            .iter()
            .map(|p| p.x.abs().max(p.y.abs()).max(p.z.abs()))
            .fold(0.0, f64::max);
        let noise = NOISE_FLOOR_ULPS * f64::EPSILON * magnitude;
        (relative.max(1e-15) * self.rough_length())
            .max(noise)
            .max(f64::MIN_POSITIVE)
    }

    /// The length of the curve to the default relative tolerance [`LENGTH_TOLERANCE`].
    pub fn length(&self) -> f64 {
        self.length_with_tolerance(LENGTH_TOLERANCE)
    }

    /// The length of the curve, with a quadrature error estimated below `tolerance` times the
    /// length.
    pub fn length_with_tolerance(&self, tolerance: f64) -> f64 {
        let tol = self.absolute_length_tolerance(tolerance);
        let breaks = self.span_breaks();
        let domain = self.domain().length();
        breaks
            .windows(2)
            .map(|w| self.span_length(w[0], w[1], tol * (w[1] - w[0]) / domain))
            .sum()
    }

    /// The length of the part of the curve between the parameters `t0` and `t1` (in either
    /// order), to the default tolerance.
    ///
    /// # Errors
    /// [`Error::NotFinite`] for NaN parameters; [`Error::InvalidInput`] for parameters outside
    /// the domain.
    pub fn length_between(&self, t0: f64, t1: f64) -> Result<f64> {
        for t in [t0, t1] {
            self.check_parameter(t)?;
        }
        let (a, b) = if t0 <= t1 { (t0, t1) } else { (t1, t0) };
        // Through the length table, so that lengths between parameters agree with the curve's
        // length and with divisions to rounding: an adaptive integration of the sub-range alone
        // can accept a panel whose halves agree by chance (a fixed-seed case measured 4e-10 on
        // a 57-unit curve, 7e-12 of its length, with the table exact to 1e-15 there).
        let table = LengthTable::new(self, LENGTH_TOLERANCE);
        Ok((table.length_to(self, b) - table.length_to(self, a)).max(0.0))
    }

    /// The length over `[a, b]` by the adaptive integration of each span to the absolute
    /// tolerance `tol` (shared by the spans in proportion to their parameter range): an
    /// integration independent of the length table, for tests.
    #[cfg(test)]
    pub(crate) fn length_between_adaptive(&self, a: f64, b: f64, tol: f64) -> f64 {
        let breaks = self.span_breaks();
        let mut total = 0.0;
        for w in breaks.windows(2) {
            let lo = w[0].max(a);
            let hi = w[1].min(b);
            if hi > lo {
                total += self.span_length(lo, hi, tol * (hi - lo) / (b - a).max(f64::MIN_POSITIVE));
            }
        }
        total
    }

    /// The parameter `t` with `length(domain start, t) = length`, to the default tolerance.
    ///
    /// # Errors
    /// [`Error::NotFinite`] for a NaN length; [`Error::InvalidInput`] for a negative length or
    /// one beyond the curve's length.
    pub fn parameter_at_length(&self, length: f64) -> Result<f64> {
        LengthTable::new(self, LENGTH_TOLERANCE).parameter_at(self, length)
    }

    /// The parameters at the arc lengths `lengths`, given in increasing order, in one pass
    /// over one length table (linear time in all, where one [`NurbsCurve::parameter_at_length`]
    /// per length would measure the curve again each time).
    ///
    /// # Errors
    /// As [`NurbsCurve::parameter_at_length`]; [`Error::InvalidInput`] for lengths that
    /// decrease.
    pub fn parameters_at_lengths(&self, lengths: &[f64]) -> Result<Vec<f64>> {
        check_increasing(lengths)?;
        let table = LengthTable::new(self, LENGTH_TOLERANCE);
        let mut cursor = Cursor::default();
        lengths
            .iter()
            .map(|&s| table.parameter_from(self, s, &mut cursor, true))
            .collect()
    }

    /// The parameter at the fraction `fraction ∈ [0, 1]` of the curve's length.
    ///
    /// # Errors
    /// As [`NurbsCurve::parameter_at_length`], for fractions outside `[0, 1]`.
    pub fn parameter_at_normalized_length(&self, fraction: f64) -> Result<f64> {
        let table = LengthTable::new(self, LENGTH_TOLERANCE);
        table.parameter_at(self, fraction * table.total())
    }

    /// The parameters dividing the curve into `count` pieces of equal length (Grasshopper's
    /// Divide Curve): `count + 1` parameters from start to end on an open curve, `count` on a
    /// closed one (the seam is not repeated).
    ///
    /// # Errors
    /// [`Error::InvalidInput`] when `count` is 0.
    pub fn divide_by_count(&self, count: usize) -> Result<Vec<f64>> {
        check_division_count(count)?;
        let table = LengthTable::new(self, LENGTH_TOLERANCE);
        let total = table.total();
        let d = self.domain();
        let last = if self.is_closed() { count - 1 } else { count };
        let mut out = Vec::with_capacity(last + 1);
        let mut cursor = Cursor::default();
        for k in 0..=last {
            let t = if k == 0 {
                d.t0
            } else if k == count {
                d.t1
            } else {
                let s = total * k as f64 / count as f64;
                table.parameter_from(self, s, &mut cursor, true)?
            };
            out.push(t);
        }
        Ok(out)
    }

    /// The parameters of the points at arc-length distances `0, length, 2·length, …` from the
    /// start (Grasshopper's Divide Length). The end is included only when the curve's length is
    /// a whole multiple of `length` (within the length tolerance), and on a closed curve the
    /// seam is never repeated.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] for a length that is not positive and finite.
    pub fn divide_by_length(&self, length: f64) -> Result<Vec<f64>> {
        if !(length.is_finite() && length > 0.0) {
            return Err(Error::InvalidInput(format!(
                "division length {length} is not positive"
            )));
        }
        let table = LengthTable::new(self, LENGTH_TOLERANCE);
        let total = table.total();
        let slack = 1e-9 * total;
        let count = division_count(total + slack, length)?;
        let closed = self.is_closed();
        let mut out = Vec::with_capacity(count + 1);
        let mut cursor = Cursor::default();
        for k in 0..=count {
            let s = k as f64 * length;
            if k > 0 && (s - total).abs() <= slack {
                if !closed {
                    out.push(self.domain().t1);
                }
                break;
            }
            out.push(table.parameter_from(self, s.min(total), &mut cursor, true)?);
        }
        Ok(out)
    }

    /// Checks that `t` is finite and in the domain (with a relative slack of 1e-12).
    pub(crate) fn check_parameter(&self, t: f64) -> Result<()> {
        if !t.is_finite() {
            return Err(Error::NotFinite { what: "parameter" });
        }
        let d = self.domain();
        let slack = 1e-12 * (d.t0.abs().max(d.t1.abs()).max(d.length()));
        if t < d.t0 - slack || t > d.t1 + slack {
            return Err(Error::InvalidInput(format!(
                "parameter {t} is outside the domain {} to {}",
                d.t0, d.t1
            )));
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Circle, Line, Plane, Point3};
    use std::f64::consts::TAU;

    #[test]
    fn a_curve_collapsed_to_a_point_far_from_the_origin_has_length_zero() {
        // The isocurve along the north pole of a sphere: nine rational control points that
        // coincide up to rounding, far from the origin (this once refined without end).
        let sphere = crate::Sphere::new(crate::Point3::new(10.0, -20.0, 30.0), 3.0)
            .unwrap()
            .to_nurbs()
            .unwrap();
        let pole = sphere
            .isocurve(crate::SurfaceDirection::U, sphere.domain_v().t1)
            .unwrap();
        assert!(pole.length() < 1e-12);
    }

    #[test]
    fn a_curve_whose_points_coincide_has_length_zero_at_once() {
        let p = crate::Point3::new(1.0, 1.0, 1.0);
        let c = NurbsCurve::create(&[p; 4], 3, false).expect("a degenerate cubic");
        assert!(c.length() < 1e-12);
        assert!(c.length_between(0.2, 0.7).expect("inside the domain") < 1e-12);
        let ts = c.divide_by_count(4).expect("a division");
        assert_eq!(ts.len(), 5);
    }

    #[test]
    fn gauss_legendre_integrates_polynomials_exactly() {
        let (x, w) = gauss_legendre();
        assert!((w.iter().sum::<f64>() - 2.0).abs() < 1e-14);
        // ∫ x^18 over [−1, 1] = 2/19, exact for 10 nodes (degree ≤ 19).
        let s: f64 = x.iter().zip(w).map(|(x, w)| w * x.powi(18)).sum();
        assert!((s - 2.0 / 19.0).abs() < 1e-14);
    }

    #[test]
    fn a_span_narrow_beside_its_parameters_is_integrated_to_its_rounding() {
        // Two cubic Bézier pieces: a tiny one (1e-9 wide) at parameters near 1e6, where the
        // parameters' own rounding (ε·1e6 / 1e-9, about 2e-1 of the span) is far above the
        // quadrature's 1e-12, and a long one (its rounding about 2e-10). Shifting the knots to
        // 0 gives the same curve without that noise: the lengths agree to the noise, and the
        // quadrature stops there instead of bisecting 2²⁴ times.
        let points = vec![
            Point3::new(0.0, 0.0, 0.0),
            Point3::new(1e-9, 0.2e-9, 0.0),
            Point3::new(2e-9, 0.5e-9, 0.0),
            Point3::new(3e-9, 0.4e-9, 0.0),
            Point3::new(1.0, 0.5, 0.0),
            Point3::new(2.0, -0.5, 0.0),
            Point3::new(3.0, 0.0, 0.0),
        ];
        let at = |origin: f64| {
            let k = [origin, origin + 1e-9, origin + 1.0];
            NurbsCurve::new_non_rational(
                3,
                points.clone(),
                vec![k[0], k[0], k[0], k[1], k[1], k[1], k[2], k[2], k[2]],
            )
            .unwrap()
        };
        let (far, near) = (at(1e6).length(), at(0.0).length());
        assert!((far - near).abs() <= 1e-9 * near, "{far} {near}");
    }

    #[test]
    fn circle_and_line_lengths() {
        let c = Circle::new(Plane::WORLD_XY, 3.0).unwrap().to_nurbs();
        assert!((c.length() - 3.0 * TAU).abs() < 1e-11);
        let quarter = c.length_between(0.0, TAU / 4.0).unwrap();
        assert!((quarter - 3.0 * TAU / 4.0).abs() < 1e-11);
        let l = Line::new(Point3::ORIGIN, Point3::new(3.0, 4.0, 0.0))
            .to_nurbs()
            .unwrap();
        assert!((l.length() - 5.0).abs() < 1e-14);
        assert!((l.parameter_at_length(2.0).unwrap() - 2.0).abs() < 1e-12);
    }

    #[test]
    fn parameter_at_length_inverts_length() {
        let c = NurbsCurve::new(
            3,
            vec![
                Point3::new(0.0, 0.0, 0.0),
                Point3::new(1.0, 3.0, 0.0),
                Point3::new(3.0, 4.0, 1.0),
                Point3::new(5.0, 2.0, 0.0),
                Point3::new(7.0, 5.0, 2.0),
            ],
            vec![1.0, 2.0, 0.5, 1.0, 1.0],
            vec![0.0, 0.0, 0.0, 0.7, 2.0, 2.0, 2.0],
        )
        .unwrap();
        let total = c.length();
        for f in [0.1, 0.25, 0.5, 0.77, 0.99] {
            let t = c.parameter_at_normalized_length(f).unwrap();
            let l = c.length_between(0.0, t).unwrap();
            assert!((l - f * total).abs() < 1e-10 * total, "f {f}");
        }
        assert!(c.parameter_at_length(-1.0).is_err());
        assert!(c.parameter_at_length(total * 1.01).is_err());
        assert!(c.parameter_at_length(f64::NAN).is_err());
        assert!(c.length_between(0.0, 3.0).is_err());
        assert_eq!(c.parameter_at_length(total).unwrap(), 2.0);
    }

    #[test]
    fn divide_open_and_closed() {
        let line = Line::new(Point3::ORIGIN, Point3::new(10.0, 0.0, 0.0))
            .to_nurbs()
            .unwrap();
        let ts = line.divide_by_count(4).unwrap();
        assert_eq!(ts.len(), 5);
        for (k, t) in ts.iter().enumerate() {
            assert!((t - 2.5 * k as f64).abs() < 1e-12);
        }
        let circle = Circle::new(Plane::WORLD_XY, 1.0).unwrap().to_nurbs();
        let ts = circle.divide_by_count(4).unwrap();
        assert_eq!(ts.len(), 4);
        for (k, &t) in ts.iter().enumerate() {
            let p = circle.point_at(t);
            let angle = TAU * k as f64 / 4.0;
            assert!(p.distance(Point3::new(angle.cos(), angle.sin(), 0.0)) < 1e-10);
        }
        // Divide Length: 10 / 3 gives 0, 3, 6, 9; 10 / 2.5 ends exactly at the end.
        let by3 = line.divide_by_length(3.0).unwrap();
        assert_eq!(by3.len(), 4);
        assert!((by3[3] - 9.0).abs() < 1e-12);
        let by25 = line.divide_by_length(2.5).unwrap();
        assert_eq!(by25.len(), 5);
        assert_eq!(by25[4], 10.0);
        let around = circle.divide_by_length(TAU / 4.0).unwrap();
        assert_eq!(around.len(), 4);
        assert!(line.divide_by_count(0).is_err());
        assert!(line.divide_by_length(0.0).is_err());
        assert!(line.divide_by_length(f64::NAN).is_err());
    }
}

//! Fitting a NURBS curve of a chosen degree to a curve within a tolerance (Grasshopper's *Fit
//! Curve*, Rhino's `Curve.Fit`).
//!
//! The fit is a least-squares approximation (The NURBS Book, §9.4.1) on uniform knots over the
//! curve's own domain: the curve is sampled at `2 (degree + 1)` evenly spaced parameters per
//! span, the end control points are the curve's end points, and the inner control points
//! minimize the sum of squared distances between the fit and the samples at the same
//! parameters (normal equations, banded, solved by Cholesky's method). The fit is accepted when
//! it lies within the tolerance of the curve at every sample and halfway between samples
//! (distances at equal parameters, which bound the distance between the curves from above);
//! otherwise the number of spans doubles, up to [`MAX_FIT_SPANS`]. The result keeps the
//! curve's domain and is non-rational; kinks are rounded off within the tolerance.

use crate::curve::nurbs::basis::{MAX_DEGREE, MAX_ORDER, basis_functions, span_index};
use crate::{Curve, Error, NurbsCurve, Point3, Result};

/// The most spans a fitted curve gets.
pub const MAX_FIT_SPANS: usize = 1024;

/// Knots in Rhino form for `spans` uniform spans of degree `degree` on `[t0, t1]`.
fn uniform_knots(degree: usize, spans: usize, t0: f64, t1: f64) -> Vec<f64> {
    let mut knots = vec![t0; degree];
    for k in 1..spans {
        knots.push(t0 + (t1 - t0) * k as f64 / spans as f64);
    }
    knots.extend(std::iter::repeat_n(t1, degree));
    knots
}

/// Solves the symmetric positive definite band system `M x = b` (half bandwidth `w`, `band[r][k]`
/// holding `M[r][r + k]`) by Cholesky's method, for three right-hand sides at once.
fn solve_band(mut band: Vec<Vec<f64>>, w: usize, mut rhs: Vec<[f64; 3]>) -> Option<Vec<[f64; 3]>> {
    let n = band.len();
    // Factor M = Uᵀ U in place (U upper triangular with the same band).
    for r in 0..n {
        for k in 0..=w.min(n - 1 - r) {
            let mut sum = band[r][k];
            let first = r.saturating_sub(w);
            for (i, row) in band.iter().enumerate().take(r).skip(first) {
                let (a, b) = (r - i, r + k - i);
                if b <= w {
                    sum -= row[a] * row[b];
                }
            }
            if k == 0 {
                if !(sum.is_finite() && sum > 0.0) {
                    return None;
                }
                band[r][0] = sum.sqrt();
            } else {
                band[r][k] = sum / band[r][0];
            }
        }
    }
    // Uᵀ y = b, then U x = y.
    for r in 0..n {
        let mut acc = rhs[r];
        for i in r.saturating_sub(w)..r {
            let u = band[i][r - i];
            for (x, y) in acc.iter_mut().zip(rhs[i]) {
                *x -= u * y;
            }
        }
        rhs[r] = acc.map(|x| x / band[r][0]);
    }
    for r in (0..n).rev() {
        let mut acc = rhs[r];
        for k in 1..=w.min(n - 1 - r) {
            let u = band[r][k];
            for (x, y) in acc.iter_mut().zip(rhs[r + k]) {
                *x -= u * y;
            }
        }
        rhs[r] = acc.map(|x| x / band[r][0]);
    }
    rhs.iter().flatten().all(|x| x.is_finite()).then_some(rhs)
}

/// The least-squares fit with `spans` uniform spans to `points` at `params`, its ends at the
/// first and last point.
fn least_squares(
    degree: usize,
    spans: usize,
    params: &[f64],
    points: &[Point3],
) -> Result<NurbsCurve> {
    let (t0, t1) = (params[0], params[params.len() - 1]);
    let knots = uniform_knots(degree, spans, t0, t1);
    let n = spans + degree;
    let (first, last) = (points[0], points[points.len() - 1]);
    if n == 2 {
        return NurbsCurve::new_non_rational(degree, vec![first, last], knots);
    }
    let inner = n - 2;
    let mut band = vec![vec![0.0; degree + 1]; inner];
    let mut rhs = vec![[0.0; 3]; inner];
    let mut basis = [0.0; MAX_ORDER];
    for (&t, &q) in params.iter().zip(points) {
        let span = span_index(degree, &knots, t);
        basis_functions(degree, &knots, span, t, &mut basis);
        let start = span + 1 - degree;
        // Move the fixed end points' share to the right-hand side.
        let mut r = q.to_vector();
        for (k, &b) in basis[..=degree].iter().enumerate() {
            let col = start + k;
            if col == 0 {
                r -= first.to_vector() * b;
            } else if col == n - 1 {
                r -= last.to_vector() * b;
            }
        }
        for (k, &bk) in basis[..=degree].iter().enumerate() {
            let row = start + k;
            if row == 0 || row == n - 1 || bk == 0.0 {
                continue;
            }
            let ri = row - 1;
            rhs[ri][0] += bk * r.x;
            rhs[ri][1] += bk * r.y;
            rhs[ri][2] += bk * r.z;
            for (l, &bl) in basis[..=degree].iter().enumerate().skip(k) {
                let col = start + l;
                if col == 0 || col == n - 1 {
                    continue;
                }
                band[ri][col - 1 - ri] += bk * bl;
            }
        }
    }
    let solved = solve_band(band, degree, rhs).ok_or(Error::NoConvergence { what: "curve fit" })?;
    let mut cvs = Vec::with_capacity(n);
    cvs.push(first);
    cvs.extend(solved.into_iter().map(|[x, y, z]| Point3::new(x, y, z)));
    cvs.push(last);
    NurbsCurve::new_non_rational(degree, cvs, knots)
}

impl Curve {
    /// A non-rational curve of degree `degree` within `tolerance` of this one, with the same
    /// domain and end points (see the module documentation).
    ///
    /// # Errors
    /// [`Error::InvalidDegree`] for a degree of 0 or above the maximum; [`Error::InvalidInput`]
    /// for a tolerance that is not positive and finite, an invalid curve, or when
    /// [`MAX_FIT_SPANS`] spans do not reach the tolerance.
    pub fn fit(&self, degree: usize, tolerance: f64) -> Result<NurbsCurve> {
        if degree == 0 || degree > MAX_DEGREE {
            return Err(Error::InvalidDegree {
                degree,
                reason: format!("a fitted curve has a degree from 1 to {MAX_DEGREE}"),
            });
        }
        if !(tolerance.is_finite() && tolerance > 0.0) {
            return Err(Error::InvalidInput(format!(
                "fit tolerance {tolerance} is not a positive distance"
            )));
        }
        if !self.is_valid() {
            return Err(Error::InvalidInput("the curve is not valid".into()));
        }
        let d = self.domain();
        let mut spans = 1;
        loop {
            let count = spans * 2 * (degree + 1);
            let params: Vec<f64> = (0..=count)
                .map(|k| d.parameter_at(k as f64 / count as f64))
                .collect();
            let mut points = vec![Point3::ORIGIN; params.len()];
            self.points_at(&params, &mut points)?;
            let fit = least_squares(degree, spans, &params, &points)?;
            let mut worst = 0.0f64;
            for (k, (&t, &p)) in params.iter().zip(&points).enumerate() {
                worst = worst.max(fit.point_at(t).distance(p));
                if k + 1 < params.len() {
                    let mid = 0.5 * (t + params[k + 1]);
                    worst = worst.max(fit.point_at(mid).distance(self.point_at(mid)));
                }
            }
            if worst <= tolerance {
                return Ok(fit);
            }
            if spans >= MAX_FIT_SPANS {
                return Err(Error::InvalidInput(format!(
                    "no fit of degree {degree} with up to {MAX_FIT_SPANS} spans is within \
                     {tolerance} of the curve (the closest is {worst} away)"
                )));
            }
            spans *= 2;
        }
    }
}

#[cfg(test)]
mod tests {
    use std::f64::consts::TAU;

    use proptest::prelude::*;

    use super::*;
    use crate::{Circle, Line, Plane, Polyline};

    #[test]
    fn a_line_fits_with_one_span() {
        let c: Curve = Line::new(Point3::ORIGIN, Point3::new(3.0, 4.0, 0.0)).into();
        let f = c.fit(3, 1e-9).unwrap();
        assert_eq!(f.span_count(), 1);
        assert_eq!(f.degree(), 3);
        assert_eq!(f.domain(), c.domain());
        assert!(f.point_at(2.5).distance(Point3::new(1.5, 2.0, 0.0)) < 1e-12);
    }

    #[test]
    fn a_circle_fits_within_the_tolerance() {
        let c: Curve = Circle::new(Plane::WORLD_XY, 10.0).unwrap().into();
        for degree in [2, 3, 5] {
            let f = c.fit(degree, 1e-4).unwrap();
            assert_eq!(f.degree(), degree);
            assert!(f.is_closed());
            for k in 0..200 {
                let t = TAU * k as f64 / 200.0;
                let r = f.point_at(t).distance(Point3::ORIGIN);
                assert!((r - 10.0).abs() < 1e-4, "degree {degree} at {t}: {r}");
            }
        }
    }

    #[test]
    fn bad_input_is_an_error() {
        let c: Curve = Line::new(Point3::ORIGIN, Point3::new(1.0, 0.0, 0.0)).into();
        assert!(c.fit(0, 1e-3).is_err());
        assert!(c.fit(3, 0.0).is_err());
        assert!(c.fit(3, f64::NAN).is_err());
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(32))]

        /// A fit of a polyline lies within the tolerance of it everywhere (measured at equal
        /// parameters) and keeps its ends.
        #[test]
        fn fit_lies_within_the_tolerance(
            ys in prop::collection::vec(-3.0f64..3.0, 3..6),
            degree in 1usize..5,
        ) {
            let points: Vec<Point3> = ys
                .iter()
                .enumerate()
                .map(|(i, &y)| Point3::new(i as f64 * 2.0, y, 0.0))
                .collect();
            let c: Curve = Polyline::new(points).unwrap().into();
            let tolerance = 0.01;
            let f = c.fit(degree, tolerance).unwrap();
            prop_assert_eq!(f.start_point(), c.start_point());
            prop_assert_eq!(f.end_point(), c.end_point());
            let d = c.domain();
            for k in 0..=97 {
                let t = d.parameter_at(k as f64 / 97.0);
                prop_assert!(f.point_at(t).distance(c.point_at(t)) <= tolerance * 1.5);
            }
        }
    }
}

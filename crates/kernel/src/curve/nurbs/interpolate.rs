//! Curves through points: global interpolation with chord-length (or other) parameters.
//!
//! As Rhino's `InterpCrv` and `Curve.CreateInterpolatedCurve`, the curve of odd degree `p`
//! through `n` points `Q_j` takes the parameters `t_j` of the points as its knots
//! (`t_0` and `t_{n−1}` with multiplicity `p`), which leaves `n + p − 1` control points for `n`
//! interpolation conditions `C(t_j) = Q_j`. The `p − 1` missing conditions are the *end
//! conditions*:
//!
//! - by default the **natural** end conditions of an odd-degree spline: the derivatives of
//!   orders `(p + 1)/2 ..= p − 1` vanish at both ends (for a cubic, `C'' = 0` at both ends);
//! - for a cubic, a given start or end tangent replaces the condition `C'' = 0` at that end by
//!   `C' = T·L/(t_{n−1} − t_0)`, with `T` the unit tangent and `L` the length of the polygon
//!   through the points, which is the speed of a chord-length parameterization.
//!
//! The parameters follow [`KnotStyle`]: uniform (`t_{j+1} − t_j = 1`), chord length
//! (`|Q_{j+1} − Q_j|`, the book's figure 42, which gives a smoother curve than uniform knots when
//! the points are unevenly spaced) or the square root of the chord length. The linear system is
//! banded and solved by Gaussian elimination with partial pivoting inside the band.

use crate::curve::nurbs::basis::{self, MAX_ORDER};
use crate::{Error, NurbsCurve, Point3, Result, Vector3};

/// How the parameters of the interpolated points, and so the knots, are spaced.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum KnotStyle {
    /// Spacing 1 between consecutive points.
    Uniform,
    /// Spacing equal to the distance between consecutive points (the default, as in Rhino's
    /// `InterpCrv`).
    #[default]
    Chord,
    /// Spacing equal to the square root of the distance between consecutive points.
    ChordSquareRoot,
}

/// Optional tangent directions at the ends of an interpolated cubic.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct EndTangents {
    /// The direction at the first point, if constrained.
    pub start: Option<Vector3>,
    /// The direction at the last point, if constrained.
    pub end: Option<Vector3>,
}

impl NurbsCurve {
    /// The non-rational curve of degree `degree` through `points`, with parameters spaced by
    /// `style` and natural end conditions (see the module documentation).
    ///
    /// Degree 1 gives the polyline through the points. Rhino's default is degree 3 with chord
    /// spacing: `NurbsCurve::interpolate(&pts, 3, KnotStyle::Chord)`.
    ///
    /// # Errors
    /// See [`NurbsCurve::interpolate_with_tangents`].
    pub fn interpolate(points: &[Point3], degree: usize, style: KnotStyle) -> Result<Self> {
        Self::interpolate_with_tangents(points, degree, style, EndTangents::default())
    }

    /// As [`NurbsCurve::interpolate`], with optional end tangents (degree 3 only).
    ///
    /// # Errors
    /// - [`Error::TooFewPoints`] with fewer than two points;
    /// - [`Error::InvalidDegree`] for an even degree, or a degree above the maximum;
    /// - [`Error::NotFinite`] for NaN or infinite points or tangents;
    /// - [`Error::ZeroLength`] for a zero tangent;
    /// - [`Error::InvalidInput`] when consecutive points coincide, or tangents are given for a
    ///   degree other than 3;
    /// - [`Error::NoConvergence`] if the linear system is singular (not expected for valid input).
    pub fn interpolate_with_tangents(
        points: &[Point3],
        degree: usize,
        style: KnotStyle,
        tangents: EndTangents,
    ) -> Result<Self> {
        let n = points.len();
        if n < 2 {
            return Err(Error::TooFewPoints {
                what: "an interpolated curve",
                needed: 2,
                got: n,
            });
        }
        if degree.is_multiple_of(2) || degree > basis::MAX_DEGREE {
            return Err(Error::InvalidDegree {
                degree,
                reason: "interpolation needs an odd degree no higher than the maximum".into(),
            });
        }
        if points.iter().any(|p| !p.is_finite()) {
            return Err(Error::NotFinite { what: "point" });
        }
        let has_tangents = tangents.start.is_some() || tangents.end.is_some();
        if has_tangents && degree != 3 {
            return Err(Error::InvalidInput(
                "end tangents are only supported for degree 3 interpolation".into(),
            ));
        }
        let start_tangent = tangents.start.map(unit_tangent).transpose()?;
        let end_tangent = tangents.end.map(unit_tangent).transpose()?;

        let params = parameters(points, style)?;
        let p = degree;
        let mut knots = Vec::with_capacity(n + 2 * p - 2);
        knots.extend(std::iter::repeat_n(params[0], p));
        knots.extend_from_slice(&params[1..n - 1]);
        knots.extend(std::iter::repeat_n(params[n - 1], p));
        let cv_count = n + p - 1;
        if p == 1 {
            return NurbsCurve::new_non_rational(1, points.to_vec(), knots);
        }

        // Rows: start conditions, interpolation conditions, end conditions.
        let half = p.div_ceil(2); // (p + 1) / 2
        let conditions_per_end = p - half; // orders half ..= p − 1
        let t0 = params[0];
        let t1 = params[n - 1];
        let polygon: f64 = points.windows(2).map(|w| w[0].distance(w[1])).sum();
        let speed = polygon / (t1 - t0);
        let mut rows: Vec<Row> = Vec::with_capacity(cv_count);
        let first_span = p - 1;
        let last_span = cv_count - 2;
        for k in 0..conditions_per_end {
            let order = half + k;
            rows.push(match (k, start_tangent) {
                (0, Some(tangent)) => derivative_row(p, &knots, first_span, t0, 1, tangent * speed),
                _ => derivative_row(p, &knots, first_span, t0, order, Vector3::ZERO),
            });
        }
        for (j, (&t, q)) in params.iter().zip(points).enumerate() {
            let span = if j + 1 == n {
                last_span
            } else {
                basis::span_index(p, &knots, t)
            };
            let mut nb = [0.0; MAX_ORDER];
            basis::basis_functions(p, &knots, span, t, &mut nb);
            rows.push(Row {
                first: span + 1 - p,
                coefficients: nb[..=p].to_vec(),
                rhs: q.to_array(),
            });
        }
        for k in 0..conditions_per_end {
            let order = half + k;
            rows.push(match (k, end_tangent) {
                (0, Some(tangent)) => derivative_row(p, &knots, last_span, t1, 1, tangent * speed),
                _ => derivative_row(p, &knots, last_span, t1, order, Vector3::ZERO),
            });
        }
        debug_assert_eq!(rows.len(), cv_count);
        let solution = solve_banded(&rows)?;
        let cvs = solution
            .into_iter()
            .map(|[x, y, z]| Point3::new(x, y, z))
            .collect();
        NurbsCurve::new_non_rational(p, cvs, knots)
    }
}

fn unit_tangent(v: Vector3) -> Result<Vector3> {
    if !v.is_finite() {
        return Err(Error::NotFinite { what: "tangent" });
    }
    v.try_normalize()
        .ok_or(Error::ZeroLength { what: "tangent" })
}

/// The parameters of the points, starting at 0.
fn parameters(points: &[Point3], style: KnotStyle) -> Result<Vec<f64>> {
    let mut t = Vec::with_capacity(points.len());
    t.push(0.0);
    for (i, w) in points.windows(2).enumerate() {
        let d = w[0].distance(w[1]);
        if d == 0.0 {
            return Err(Error::InvalidInput(format!(
                "points {i} and {} coincide",
                i + 1
            )));
        }
        let step = match style {
            KnotStyle::Uniform => 1.0,
            KnotStyle::Chord => d,
            KnotStyle::ChordSquareRoot => d.sqrt(),
        };
        let last = t[t.len() - 1];
        t.push(last + step);
    }
    Ok(t)
}

/// One row of the interpolation system: coefficients for control points `first..first + len`.
struct Row {
    first: usize,
    coefficients: Vec<f64>,
    rhs: [f64; 3],
}

/// The row `C^(order)(t) = value`, evaluated in span `span`.
fn derivative_row(
    p: usize,
    knots: &[f64],
    span: usize,
    t: f64,
    order: usize,
    value: Vector3,
) -> Row {
    let mut ders = [[0.0; MAX_ORDER]; MAX_ORDER];
    basis::basis_function_derivatives(p, knots, span, t, order, &mut ders[..=order]);
    Row {
        first: span + 1 - p,
        coefficients: ders[order][..=p].to_vec(),
        rhs: value.to_array(),
    }
}

/// Solves the square banded system given by `rows` (row `r` has its non-zeros in columns
/// `first..first + coefficients.len()`) with partial pivoting restricted to the band.
fn solve_banded(rows: &[Row]) -> Result<Vec<[f64; 3]>> {
    let n = rows.len();
    let mut kl = 0usize;
    let mut ku = 0usize;
    for (r, row) in rows.iter().enumerate() {
        let last = row.first + row.coefficients.len() - 1;
        kl = kl.max(r.saturating_sub(row.first));
        ku = ku.max(last.saturating_sub(r));
    }
    // Band storage with room for the fill-in of pivoting: columns r − kl ..= r + kl + ku.
    let width = 2 * kl + ku + 1;
    let mut a = vec![0.0; n * width];
    let idx = |r: usize, c: usize| r * width + (c + kl - r);
    let mut b: Vec<[f64; 3]> = rows.iter().map(|row| row.rhs).collect();
    for (r, row) in rows.iter().enumerate() {
        for (j, &v) in row.coefficients.iter().enumerate() {
            let c = row.first + j;
            if c < n {
                a[idx(r, c)] = v;
            }
        }
    }
    let scale = a.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    for k in 0..n {
        let bottom = (k + kl).min(n - 1);
        let right = (k + kl + ku).min(n - 1);
        let pivot = (k..=bottom)
            .max_by(|&i, &j| a[idx(i, k)].abs().total_cmp(&a[idx(j, k)].abs()))
            .unwrap_or(k);
        if a[idx(pivot, k)].abs() <= 1e-14 * scale {
            return Err(Error::NoConvergence {
                what: "interpolation (singular system)",
            });
        }
        if pivot != k {
            for c in k..=right {
                a.swap(idx(k, c), idx(pivot, c));
            }
            b.swap(k, pivot);
        }
        let diag = a[idx(k, k)];
        for i in k + 1..=bottom {
            let f = a[idx(i, k)] / diag;
            if f == 0.0 {
                continue;
            }
            for c in k..=right {
                a[idx(i, c)] -= f * a[idx(k, c)];
            }
            let bk = b[k];
            for (bi, bkc) in b[i].iter_mut().zip(bk) {
                *bi -= f * bkc;
            }
        }
    }
    let mut x = vec![[0.0; 3]; n];
    for k in (0..n).rev() {
        let right = (k + kl + ku).min(n - 1);
        let mut s = b[k];
        for c in k + 1..=right {
            let v = a[idx(k, c)];
            for (si, xc) in s.iter_mut().zip(x[c]) {
                *si -= v * xc;
            }
        }
        let d = a[idx(k, k)];
        x[k] = s.map(|v| v / d);
    }
    Ok(x)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn pts() -> Vec<Point3> {
        vec![
            Point3::new(0.0, 0.0, 0.0),
            Point3::new(1.0, 2.0, 0.0),
            Point3::new(4.0, 2.5, 1.0),
            Point3::new(5.0, 0.0, 0.0),
            Point3::new(9.0, -1.0, 2.0),
            Point3::new(9.5, 3.0, 0.0),
        ]
    }

    #[test]
    fn cubic_passes_through_every_point_with_chord_knots() {
        let p = pts();
        let c = NurbsCurve::interpolate(&p, 3, KnotStyle::Chord).unwrap();
        assert_eq!(c.point_count(), p.len() + 2);
        assert_eq!(c.degree(), 3);
        // The knots are the cumulative chord lengths.
        let mut t = 0.0;
        let mut params = vec![0.0];
        for w in p.windows(2) {
            t += w[0].distance(w[1]);
            params.push(t);
        }
        assert_eq!(c.knots()[2..c.knots().len() - 2], params[..]);
        for (q, &t) in p.iter().zip(&params) {
            assert!(c.point_at(t).distance(*q) < 1e-12, "t {t}");
        }
        // Natural end conditions.
        let d = c.domain();
        assert!(c.derivatives_at(d.t0, 2)[2].length() < 1e-9);
        assert!(c.derivatives_at(d.t1, 2)[2].length() < 1e-9);
    }

    #[test]
    fn other_degrees_and_styles() {
        let p = pts();
        for style in [
            KnotStyle::Uniform,
            KnotStyle::ChordSquareRoot,
            KnotStyle::Chord,
        ] {
            for degree in [1, 3, 5] {
                let c = NurbsCurve::interpolate(&p, degree, style).unwrap();
                let knots = c.knots();
                for (j, q) in p.iter().enumerate() {
                    let t = knots[degree - 1 + j];
                    assert!(c.point_at(t).distance(*q) < 1e-10, "{style:?} {degree} {j}");
                }
            }
        }
        let two = NurbsCurve::interpolate(&p[..2], 3, KnotStyle::Chord).unwrap();
        assert!(
            two.point_at(two.domain().mid())
                .distance(p[0].midpoint(p[1]))
                < 1e-12
        );
    }

    #[test]
    fn end_tangents_are_honoured() {
        let p = pts();
        let tangents = EndTangents {
            start: Some(Vector3::new(0.0, 1.0, 0.0)),
            end: Some(Vector3::new(1.0, 0.0, 0.0)),
        };
        let c = NurbsCurve::interpolate_with_tangents(&p, 3, KnotStyle::Chord, tangents).unwrap();
        let d = c.domain();
        assert!((c.tangent_at(d.t0).unwrap() - Vector3::Y).length() < 1e-12);
        assert!((c.tangent_at(d.t1).unwrap() - Vector3::X).length() < 1e-12);
        for q in &p {
            let hit = c
                .knots()
                .iter()
                .any(|&t| c.point_at(t).distance(*q) < 1e-10);
            assert!(hit);
        }
    }

    #[test]
    fn bad_input_is_reported() {
        let p = pts();
        assert!(NurbsCurve::interpolate(&p[..1], 3, KnotStyle::Chord).is_err());
        assert!(NurbsCurve::interpolate(&p, 2, KnotStyle::Chord).is_err());
        let mut dup = p.clone();
        dup[2] = dup[1];
        assert!(matches!(
            NurbsCurve::interpolate(&dup, 3, KnotStyle::Chord),
            Err(Error::InvalidInput(_))
        ));
        let mut nan = p.clone();
        nan[0].z = f64::NAN;
        assert!(NurbsCurve::interpolate(&nan, 3, KnotStyle::Chord).is_err());
        let zero = EndTangents {
            start: Some(Vector3::ZERO),
            end: None,
        };
        assert!(NurbsCurve::interpolate_with_tangents(&p, 3, KnotStyle::Chord, zero).is_err());
    }
}

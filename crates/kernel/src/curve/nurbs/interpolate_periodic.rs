//! Closed, periodic curves through points (Rhino's `InterpCrv` with *Closed*, Grasshopper's
//! Interpolate with *Periodic* set).
//!
//! The `n` distinct points `Q_j` get parameters `t_0 = 0 < t_1 < … < t_n = T` spaced by
//! [`KnotStyle`], the last step closing the loop from `Q_{n−1}` back to `Q_0`. The knots are
//! these parameters repeated with period `T` (`u_{j + mn} = t_j + mT`), so the domain is
//! `[0, T]`, and the curve has `n` free control points `P_0 … P_{n−1}` followed, as Rhino stores
//! periodic curves, by copies of the first `degree` of them. For an odd degree `p` the curve is
//! made to pass through `Q_j` at the knot `t_j`, where exactly `p` basis functions are non-zero:
//! those of `P_j … P_{j+p−1}` (indices modulo `n`). Row `j` of the `n × n` system therefore has
//! its non-zeros in columns `j … j + p − 1` (modulo `n`): a band with a few entries wrapping
//! round into the corners, solved in `O(n p²)` operations (see `solve_cyclic`).

use crate::curve::nurbs::basis::{self, MAX_DEGREE, MAX_ORDER};
use crate::{Error, KnotStyle, NurbsCurve, Point3, Result};

impl NurbsCurve {
    /// The periodic curve of odd degree `degree` through `points` (see the module
    /// documentation). A last point equal to the first is ignored, as in Rhino. Degree 1 gives
    /// the closed polyline through the points (as a degree-1 curve with the parameters as
    /// knots).
    ///
    /// # Errors
    /// - [`Error::InvalidDegree`] for an even degree or one above the maximum;
    /// - [`Error::TooFewPoints`] with fewer than `max(3, degree)` distinct points;
    /// - [`Error::NotFinite`] for NaN or infinite points;
    /// - [`Error::InvalidInput`] when consecutive points (the last and the first included)
    ///   coincide;
    /// - [`Error::NoConvergence`] if the system is singular (not expected for valid input).
    pub fn interpolate_periodic(
        points: &[Point3],
        degree: usize,
        style: KnotStyle,
    ) -> Result<Self> {
        if degree.is_multiple_of(2) || degree > MAX_DEGREE {
            return Err(Error::InvalidDegree {
                degree,
                reason: "interpolation needs an odd degree no higher than the maximum".into(),
            });
        }
        if points.iter().any(|p| !p.is_finite()) {
            return Err(Error::NotFinite { what: "point" });
        }
        let mut q = points;
        if q.len() > 1 && q[0] == q[q.len() - 1] {
            q = &q[..q.len() - 1];
        }
        let n = q.len();
        let needed = degree.max(3);
        if n < needed {
            return Err(Error::TooFewPoints {
                what: "a periodic interpolated curve",
                needed,
                got: n,
            });
        }
        let t = closed_parameters(q, style)?;
        let period = t[n];
        let p = degree;
        if p == 1 {
            let mut cvs = q.to_vec();
            cvs.push(q[0]);
            return NurbsCurve::new_non_rational(1, cvs, t);
        }
        // Rhino-form knots k[i] = u_{i − (p − 1)}, i = 0 ..= n + 2p − 2.
        let u = |i: isize| -> f64 {
            let m = i.div_euclid(n as isize);
            let j = i.rem_euclid(n as isize) as usize;
            t[j] + m as f64 * period
        };
        let knots: Vec<f64> = (0..n + 2 * p - 1)
            .map(|i| u(i as isize - (p as isize - 1)))
            .collect();
        // Row j: the p non-zero basis functions at t_j, for control points j .. j + p − 1.
        let mut rows: Vec<[f64; MAX_ORDER]> = Vec::with_capacity(n);
        for (j, &tj) in t[..n].iter().enumerate() {
            let span = j + p - 1; // k[span] = t_j
            let mut nb = [0.0; MAX_ORDER];
            basis::basis_functions(p, &knots, span, tj, &mut nb);
            // nb[c] belongs to control point span + 1 − p + c = j + c; nb[p] vanishes at t_j.
            rows.push(nb);
        }
        let solution = solve_cyclic(&rows, p, q)?;
        let mut cvs: Vec<Point3> = solution
            .into_iter()
            .map(|[x, y, z]| Point3::new(x, y, z))
            .collect();
        cvs.extend_from_within(..p);
        NurbsCurve::new_non_rational(p, cvs, knots)
    }
}

/// The parameters `t_0 = 0 … t_n` of the closed polygon through `q` and back to `q[0]`.
fn closed_parameters(q: &[Point3], style: KnotStyle) -> Result<Vec<f64>> {
    let n = q.len();
    let mut t = Vec::with_capacity(n + 1);
    t.push(0.0);
    for i in 0..n {
        let next = (i + 1) % n;
        let d = q[i].distance(q[next]);
        if d == 0.0 {
            return Err(Error::InvalidInput(format!(
                "points {i} and {next} coincide"
            )));
        }
        let step = match style {
            KnotStyle::Uniform => 1.0,
            KnotStyle::Chord => d,
            KnotStyle::ChordSquareRoot => d.sqrt(),
        };
        let last = t[i];
        t.push(last + step);
    }
    Ok(t)
}

/// Solves `A x = q` where row `j` of `A` holds `rows[j][c]` in column `(j + c) mod n` for
/// `c < p`, `p = 2h + 1`.
///
/// Numbering the unknowns from `h` on (`x'_i = x_{(i + h) mod n}`) puts the largest basis
/// function of each row on the diagonal: row `j` then spans columns `j − h … j + h`, a band,
/// except for the few entries that wrap round into the corners. With `A' = B + Σ_s u_s e_sᵀ`
/// (`B` the band, `u_s` the corner entries of column `s`), the Sherman–Morrison–Woodbury
/// formula solves the system with the banded LU of `B` (partial pivoting) and one small dense
/// system of at most `2h` unknowns.
fn solve_cyclic(rows: &[[f64; MAX_ORDER]], p: usize, q: &[Point3]) -> Result<Vec<[f64; 3]>> {
    let n = rows.len();
    let h = (p - 1) / 2;
    let mut band = Band::new(n, h);
    // Corner entries by column: (column, [(row, value)]).
    let mut corners: Vec<(usize, Vec<(usize, f64)>)> = Vec::new();
    for (j, row) in rows.iter().enumerate() {
        for (c, &v) in row[..p].iter().enumerate() {
            let col = j as isize - h as isize + c as isize;
            if (0..n as isize).contains(&col) {
                band.set(j, col as usize, v);
            } else {
                let col = col.rem_euclid(n as isize) as usize;
                match corners.iter_mut().find(|(s, _)| *s == col) {
                    Some((_, entries)) => entries.push((j, v)),
                    None => corners.push((col, vec![(j, v)])),
                }
            }
        }
    }
    let m = corners.len();
    // Right-hand sides: the 3 coordinates, then one column u_s per corner column.
    let width = 3 + m;
    let mut rhs = vec![0.0; n * width];
    for (j, point) in q.iter().enumerate() {
        rhs[j * width..j * width + 3].copy_from_slice(&point.to_array());
    }
    for (k, (_, entries)) in corners.iter().enumerate() {
        for &(r, v) in entries {
            rhs[r * width + 3 + k] = v;
        }
    }
    band.solve(&mut rhs, width)?;
    // Small system (I + Vᵀ Z) w = Vᵀ y, with Vᵀ picking the rows of the corner columns.
    let mut small = vec![0.0; m * (m + 3)];
    for (i, &(s, _)) in corners.iter().enumerate() {
        for k in 0..m {
            small[i * (m + 3) + k] = rhs[s * width + 3 + k] + if i == k { 1.0 } else { 0.0 };
        }
        small[i * (m + 3) + m..(i + 1) * (m + 3)].copy_from_slice(&rhs[s * width..s * width + 3]);
    }
    let w = solve_dense(&mut small, m)?;
    let mut x = vec![[0.0; 3]; n];
    for (i, xi) in x.iter_mut().enumerate() {
        let row = &rhs[i * width..(i + 1) * width];
        for (d, v) in xi.iter_mut().enumerate() {
            let correction: f64 = (0..m).map(|k| row[3 + k] * w[k][d]).sum();
            *v = row[d] - correction;
        }
    }
    // Undo the numbering: control point c is unknown (c − h) mod n.
    Ok((0..n).map(|c| x[(c + n - h) % n]).collect())
}

/// A square band matrix with `h` diagonals on each side, stored with room for the fill-in of
/// partial pivoting (`h` more above), and solved in place by LU with partial pivoting.
struct Band {
    n: usize,
    h: usize,
    width: usize,
    a: Vec<f64>,
}

impl Band {
    fn new(n: usize, h: usize) -> Self {
        let width = 3 * h + 1;
        Self {
            n,
            h,
            width,
            a: vec![0.0; n * width],
        }
    }

    /// Index of entry `(r, c)`, for `r − h ≤ c ≤ r + 2h`.
    fn idx(&self, r: usize, c: usize) -> usize {
        r * self.width + (c + self.h - r)
    }

    fn set(&mut self, r: usize, c: usize, v: f64) {
        let i = self.idx(r, c);
        self.a[i] = v;
    }

    /// Solves for `width` right-hand sides stored row-major in `rhs` (`n × width`).
    fn solve(&mut self, rhs: &mut [f64], width: usize) -> Result<()> {
        let (n, h) = (self.n, self.h);
        let scale = self.a.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        for k in 0..n {
            let bottom = (k + h).min(n - 1);
            let right = (k + 2 * h).min(n - 1);
            let pivot = (k..=bottom)
                .max_by(|&i, &j| {
                    self.a[self.idx(i, k)]
                        .abs()
                        .total_cmp(&self.a[self.idx(j, k)].abs())
                })
                .unwrap_or(k);
            if self.a[self.idx(pivot, k)].abs() <= 1e-14 * scale {
                return Err(Error::NoConvergence {
                    what: "periodic interpolation (singular system)",
                });
            }
            if pivot != k {
                for c in k..=right {
                    let (i, j) = (self.idx(k, c), self.idx(pivot, c));
                    self.a.swap(i, j);
                }
                for d in 0..width {
                    rhs.swap(k * width + d, pivot * width + d);
                }
            }
            let diag = self.a[self.idx(k, k)];
            for i in k + 1..=bottom {
                let f = self.a[self.idx(i, k)] / diag;
                if f == 0.0 {
                    continue;
                }
                for c in k..=right {
                    let v = self.a[self.idx(k, c)];
                    let t = self.idx(i, c);
                    self.a[t] -= f * v;
                }
                for d in 0..width {
                    rhs[i * width + d] -= f * rhs[k * width + d];
                }
            }
        }
        for k in (0..n).rev() {
            let right = (k + 2 * h).min(n - 1);
            for c in k + 1..=right {
                let v = self.a[self.idx(k, c)];
                if v == 0.0 {
                    continue;
                }
                for d in 0..width {
                    rhs[k * width + d] -= v * rhs[c * width + d];
                }
            }
            let diag = self.a[self.idx(k, k)];
            for d in 0..width {
                rhs[k * width + d] /= diag;
            }
        }
        Ok(())
    }
}

/// Solves the dense `m × m` system stored row-major with 3 right-hand sides after each row
/// (`m × (m + 3)`), by Gaussian elimination with partial pivoting.
fn solve_dense(a: &mut [f64], m: usize) -> Result<Vec<[f64; 3]>> {
    let w = m + 3;
    for k in 0..m {
        let pivot = (k..m)
            .max_by(|&i, &j| a[i * w + k].abs().total_cmp(&a[j * w + k].abs()))
            .unwrap_or(k);
        if a[pivot * w + k].abs() <= 1e-14 {
            return Err(Error::NoConvergence {
                what: "periodic interpolation (singular system)",
            });
        }
        for c in 0..w {
            a.swap(k * w + c, pivot * w + c);
        }
        for i in k + 1..m {
            let f = a[i * w + k] / a[k * w + k];
            for c in k..w {
                a[i * w + c] -= f * a[k * w + c];
            }
        }
    }
    let mut x = vec![[0.0; 3]; m];
    for k in (0..m).rev() {
        for d in 0..3 {
            let mut s = a[k * w + m + d];
            for c in k + 1..m {
                s -= a[k * w + c] * x[c][d];
            }
            x[k][d] = s / a[k * w + k];
        }
    }
    Ok(x)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Curve, KINK_ANGLE_TOLERANCE};

    fn loop_points() -> Vec<Point3> {
        vec![
            Point3::new(0.0, 0.0, 0.0),
            Point3::new(4.0, -1.0, 0.5),
            Point3::new(6.0, 2.0, 0.0),
            Point3::new(5.0, 5.0, -1.0),
            Point3::new(1.0, 6.0, 0.0),
            Point3::new(-2.0, 3.0, 1.0),
        ]
    }

    #[test]
    fn passes_through_every_point_and_is_periodic() {
        for style in [
            KnotStyle::Uniform,
            KnotStyle::Chord,
            KnotStyle::ChordSquareRoot,
        ] {
            for degree in [3, 5] {
                let pts = loop_points();
                let c = NurbsCurve::interpolate_periodic(&pts, degree, style).unwrap();
                assert!(c.is_periodic(), "{style:?} {degree}");
                assert_eq!(c.point_count(), pts.len() + degree);
                let t = closed_parameters(&pts, style).unwrap();
                assert_eq!(c.domain().t0, 0.0);
                assert_eq!(c.domain().t1, t[pts.len()]);
                for (q, &tj) in pts.iter().zip(&t) {
                    assert!(c.point_at(tj).distance(*q) < 1e-12, "{style:?} {degree}");
                }
                let curve: Curve = c.clone().into();
                assert!(curve.kinks(KINK_ANGLE_TOLERANCE).unwrap().is_empty());
                // Smooth across the seam: the same derivatives at both ends of the domain.
                let d = c.domain();
                let (a, b) = (c.derivatives_at(d.t0, 2), c.derivatives_at(d.t1, 2));
                for k in 0..=2 {
                    assert!((a[k] - b[k]).length() < 1e-9 * (1.0 + a[k].length()));
                }
            }
        }
    }

    #[test]
    fn minimal_and_degenerate_inputs() {
        let tri = [
            Point3::new(0.0, 0.0, 0.0),
            Point3::new(3.0, 0.0, 0.0),
            Point3::new(0.0, 4.0, 0.0),
        ];
        let c = NurbsCurve::interpolate_periodic(&tri, 3, KnotStyle::Uniform).unwrap();
        for (j, q) in tri.iter().enumerate() {
            assert!(c.point_at(j as f64).distance(*q) < 1e-12);
        }
        // A repeated closing point is ignored.
        let mut closed = tri.to_vec();
        closed.push(tri[0]);
        assert_eq!(
            NurbsCurve::interpolate_periodic(&closed, 3, KnotStyle::Uniform).unwrap(),
            c
        );
        let poly = NurbsCurve::interpolate_periodic(&tri, 1, KnotStyle::Chord).unwrap();
        assert_eq!(poly.domain().t1, 12.0);
        assert!(poly.is_closed());
        assert!(matches!(
            NurbsCurve::interpolate_periodic(&tri[..2], 3, KnotStyle::Chord),
            Err(Error::TooFewPoints { .. })
        ));
        assert!(matches!(
            NurbsCurve::interpolate_periodic(&tri, 2, KnotStyle::Chord),
            Err(Error::InvalidDegree { .. })
        ));
        assert!(matches!(
            NurbsCurve::interpolate_periodic(&loop_points()[..4], 5, KnotStyle::Chord),
            Err(Error::TooFewPoints { .. })
        ));
        let dup = [tri[0], tri[1], tri[1], tri[2]];
        assert!(NurbsCurve::interpolate_periodic(&dup, 3, KnotStyle::Chord).is_err());
        let nan = [tri[0], Point3::new(f64::NAN, 0.0, 0.0), tri[2]];
        assert!(matches!(
            NurbsCurve::interpolate_periodic(&nan, 3, KnotStyle::Chord),
            Err(Error::NotFinite { .. })
        ));
    }

    #[test]
    fn many_points_solve_quickly_and_exactly() {
        let pts: Vec<Point3> = (0..2000)
            .map(|i| {
                let a = i as f64 / 2000.0 * std::f64::consts::TAU;
                Point3::new(10.0 * a.cos(), 7.0 * a.sin(), (3.0 * a).sin())
            })
            .collect();
        let c = NurbsCurve::interpolate_periodic(&pts, 3, KnotStyle::Chord).unwrap();
        let t = closed_parameters(&pts, KnotStyle::Chord).unwrap();
        for j in (0..pts.len()).step_by(97) {
            assert!(c.point_at(t[j]).distance(pts[j]) < 1e-10);
        }
    }
}

//! Fast evaluation of a surface on a grid of parameters.
//!
//! Evaluating `S(uᵢ, vⱼ)` point by point costs two span searches, two sets of basis functions
//! and `(p + 1)(q + 1)` control points per point. On a grid most of that repeats: the `v`
//! basis functions depend only on the column, and for a fixed row `uᵢ` the surface is the
//! curve in `v` whose control points are `Qⱼ = Σᵣ Nᵣ(uᵢ) wᵣⱼ Pᵣⱼ` (homogeneous). So
//! [`NurbsSurface::points_on_grid`] computes the `v` basis once per column, the row curve once
//! per row, and then only `q + 1` control points per grid point.

use crate::curve::nurbs::basis::{MAX_ORDER, basis_functions, span_index};
use crate::{Error, NurbsSurface, Point3, Result};

impl NurbsSurface {
    /// Evaluates the surface at every pair `(us[i], vs[j])`, writing `S(us[i], vs[j])` to
    /// `out[i · vs.len() + j]` (row-major, rows along `u`).
    ///
    /// The results are the same as [`point_at`](Self::point_at)'s up to rounding; the work per
    /// point is that of a curve evaluation. Scratch space is allocated once per call, in
    /// proportion to `vs.len()` and the number of control points, never per point.
    ///
    /// # Performance
    /// Measured with `cargo bench -p locus-kernel --bench surface_eval` (a 1000 × 1000 grid on
    /// a bicubic surface with 8 × 8 control points and 5 × 5 spans, one thread, on the shared
    /// 2-core development machine under a load average of 8 to 12, so wall-clock figures are
    /// depressed and vary by a factor of two between runs; CPU time is that of the evaluating
    /// thread, read from `/proc/thread-self/schedstat` around the same loops):
    ///
    /// | path | wall clock (criterion) | CPU time |
    /// | --- | --- | --- |
    /// | `points_on_grid` | 49–97 M points/s | 176 M points/s |
    /// | `point_at` loop (baseline) | 2.0–4.6 M points/s | 9.2 M points/s |
    /// | rational: `points_on_grid` | 28–73 M points/s | 111 M points/s |
    /// | rational: `point_at` loop | 2.0–4.6 M points/s | 7.5 M points/s |
    ///
    /// The grid path is 15× (rational) to 19× (non-rational) faster than the per-point path in
    /// CPU time, and above the 60 M points/s target in CPU time for both and in wall-clock time
    /// for the non-rational surface whenever the machine is not saturated.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] if `out.len() != us.len() · vs.len()`, [`Error::NotFinite`] if a
    /// parameter is NaN or infinite.
    pub fn points_on_grid(&self, us: &[f64], vs: &[f64], out: &mut [Point3]) -> Result<()> {
        if out.len() != us.len() * vs.len() {
            return Err(Error::InvalidInput(format!(
                "grid output needs {} points, got room for {}",
                us.len() * vs.len(),
                out.len()
            )));
        }
        if us.iter().chain(vs).any(|t| !t.is_finite()) {
            return Err(Error::NotFinite { what: "parameter" });
        }
        if vs.is_empty() {
            return Ok(());
        }
        let (p, q) = (self.degree_u(), self.degree_v());
        let order_v = q + 1;
        let count_v = self.count_v();

        // Per column: the first control point index and the q + 1 basis values.
        let mut column_basis = vec![0.0; vs.len() * order_v];
        let mut column_first = vec![0usize; vs.len()];
        let mut scratch = [0.0; MAX_ORDER];
        for ((&v, basis), first) in vs
            .iter()
            .zip(column_basis.chunks_exact_mut(order_v))
            .zip(&mut column_first)
        {
            let span = span_index(q, self.knots_v(), v);
            basis_functions(q, self.knots_v(), span, v, &mut scratch);
            basis.copy_from_slice(&scratch[..order_v]);
            *first = span + 1 - q;
        }

        let points = self.points();
        let weights = self.weights();
        let mut nu = [0.0; MAX_ORDER];
        if self.is_rational() {
            let mut row = vec![[0.0f64; 4]; count_v];
            for (&u, out_row) in us.iter().zip(out.chunks_exact_mut(vs.len())) {
                let span = span_index(p, self.knots_u(), u);
                basis_functions(p, self.knots_u(), span, u, &mut nu);
                let i0 = span + 1 - p;
                row.fill([0.0; 4]);
                for (r, &b) in nu[..=p].iter().enumerate() {
                    let start = (i0 + r) * count_v;
                    let src = points[start..start + count_v]
                        .iter()
                        .zip(&weights[start..start + count_v]);
                    for (dst, (pt, &w)) in row.iter_mut().zip(src) {
                        let bw = b * w;
                        dst[0] += bw * pt.x;
                        dst[1] += bw * pt.y;
                        dst[2] += bw * pt.z;
                        dst[3] += bw;
                    }
                }
                match order_v {
                    4 => fill_row_rational::<4>(&row, &column_basis, &column_first, out_row),
                    3 => fill_row_rational::<3>(&row, &column_basis, &column_first, out_row),
                    2 => fill_row_rational::<2>(&row, &column_basis, &column_first, out_row),
                    _ => {
                        for ((o, basis), &first) in out_row
                            .iter_mut()
                            .zip(column_basis.chunks_exact(order_v))
                            .zip(&column_first)
                        {
                            let (mut x, mut y, mut z, mut w) = (0.0, 0.0, 0.0, 0.0);
                            for (h, &b) in row[first..first + order_v].iter().zip(basis) {
                                x += b * h[0];
                                y += b * h[1];
                                z += b * h[2];
                                w += b * h[3];
                            }
                            let inv = 1.0 / w;
                            *o = Point3::new(x * inv, y * inv, z * inv);
                        }
                    }
                }
            }
        } else {
            let mut row = vec![[0.0f64; 3]; count_v];
            for (&u, out_row) in us.iter().zip(out.chunks_exact_mut(vs.len())) {
                let span = span_index(p, self.knots_u(), u);
                basis_functions(p, self.knots_u(), span, u, &mut nu);
                let i0 = span + 1 - p;
                row.fill([0.0; 3]);
                for (r, &b) in nu[..=p].iter().enumerate() {
                    let start = (i0 + r) * count_v;
                    for (dst, pt) in row.iter_mut().zip(&points[start..start + count_v]) {
                        dst[0] += b * pt.x;
                        dst[1] += b * pt.y;
                        dst[2] += b * pt.z;
                    }
                }
                match order_v {
                    4 => fill_row::<4>(&row, &column_basis, &column_first, out_row),
                    3 => fill_row::<3>(&row, &column_basis, &column_first, out_row),
                    2 => fill_row::<2>(&row, &column_basis, &column_first, out_row),
                    _ => {
                        for ((o, basis), &first) in out_row
                            .iter_mut()
                            .zip(column_basis.chunks_exact(order_v))
                            .zip(&column_first)
                        {
                            let (mut x, mut y, mut z) = (0.0, 0.0, 0.0);
                            for (h, &b) in row[first..first + order_v].iter().zip(basis) {
                                x += b * h[0];
                                y += b * h[1];
                                z += b * h[2];
                            }
                            *o = Point3::new(x, y, z);
                        }
                    }
                }
            }
        }
        Ok(())
    }
}

/// One row of a rational grid (homogeneous row curve) with the `v` order known at compile
/// time.
#[inline]
fn fill_row_rational<const N: usize>(
    row: &[[f64; 4]],
    column_basis: &[f64],
    column_first: &[usize],
    out: &mut [Point3],
) {
    for ((o, basis), &first) in out
        .iter_mut()
        .zip(column_basis.chunks_exact(N))
        .zip(column_first)
    {
        let cvs = &row[first..first + N];
        let basis = &basis[..N];
        let (mut x, mut y, mut z, mut w) = (0.0, 0.0, 0.0, 0.0);
        for k in 0..N {
            x += basis[k] * cvs[k][0];
            y += basis[k] * cvs[k][1];
            z += basis[k] * cvs[k][2];
            w += basis[k] * cvs[k][3];
        }
        let inv = 1.0 / w;
        *o = Point3::new(x * inv, y * inv, z * inv);
    }
}

/// One row of a non-rational grid with the `v` order known at compile time, so that the inner
/// loop is unrolled.
#[inline]
fn fill_row<const N: usize>(
    row: &[[f64; 3]],
    column_basis: &[f64],
    column_first: &[usize],
    out: &mut [Point3],
) {
    for ((o, basis), &first) in out
        .iter_mut()
        .zip(column_basis.chunks_exact(N))
        .zip(column_first)
    {
        let cvs = &row[first..first + N];
        let basis = &basis[..N];
        let (mut x, mut y, mut z) = (0.0, 0.0, 0.0);
        for k in 0..N {
            x += basis[k] * cvs[k][0];
            y += basis[k] * cvs[k][1];
            z += basis[k] * cvs[k][2];
        }
        *o = Point3::new(x, y, z);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::surface::tests::wavy;
    use crate::{Interval, Plane, Sphere};

    fn check_against_point_at(s: &NurbsSurface) {
        let us: Vec<f64> = (0..=13)
            .map(|i| s.domain_u().parameter_at(i as f64 / 13.0))
            .collect();
        let vs: Vec<f64> = (0..=9)
            .map(|j| s.domain_v().parameter_at(j as f64 / 9.0))
            .collect();
        let mut out = vec![Point3::ORIGIN; us.len() * vs.len()];
        s.points_on_grid(&us, &vs, &mut out).unwrap();
        for (i, &u) in us.iter().enumerate() {
            for (j, &v) in vs.iter().enumerate() {
                let d = out[i * vs.len() + j].distance(s.point_at(u, v));
                assert!(d < 1e-13, "({u}, {v}): off by {d}");
            }
        }
    }

    #[test]
    fn grid_matches_pointwise_evaluation() {
        check_against_point_at(&wavy(false));
        check_against_point_at(&wavy(true));
        check_against_point_at(
            &Sphere::new(Point3::ORIGIN, 3.0)
                .unwrap()
                .to_nurbs()
                .unwrap(),
        );
        check_against_point_at(
            &NurbsSurface::from_plane(&Plane::WORLD_YZ, Interval::new(-1.0, 2.0), Interval::UNIT)
                .unwrap(),
        );
        // Degree 5 × 2, outside the unrolled orders.
        let points = (0..6)
            .map(|i| {
                (0..3)
                    .map(|j| Point3::new(i as f64, j as f64, ((i * j) % 3) as f64))
                    .collect()
            })
            .collect();
        let s = NurbsSurface::non_rational(
            5,
            2,
            points,
            vec![0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0, 1.0],
            vec![0.0, 0.0, 1.0, 1.0],
        )
        .unwrap();
        check_against_point_at(&s);
        check_against_point_at(&s.transposed());
    }

    #[test]
    fn grid_input_is_checked() {
        let s = wavy(false);
        let mut out = vec![Point3::ORIGIN; 3];
        assert!(matches!(
            s.points_on_grid(&[0.0, 1.0], &[0.0, 1.0], &mut out),
            Err(Error::InvalidInput(_))
        ));
        let mut out = vec![Point3::ORIGIN; 4];
        assert!(matches!(
            s.points_on_grid(&[0.0, f64::NAN], &[0.0, 1.0], &mut out),
            Err(Error::NotFinite { .. })
        ));
        assert!(s.points_on_grid(&[], &[0.0], &mut []).is_ok());
    }
}

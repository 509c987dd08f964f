//! Small dense linear systems (the 3 × 3 and 4 × 4 normal equations and Newton steps of fits
//! and intersections), by Gaussian elimination with partial pivoting.

/// Solves `m·x = b` for a system of `N` equations. `None` when a pivot is not finite or not
/// above `pivot_floor` in size (a singular or nearly singular system, by the caller's measure),
/// or the solution is not finite.
pub(crate) fn solve_dense<const N: usize>(
    mut m: [[f64; N]; N],
    mut b: [f64; N],
    pivot_floor: f64,
) -> Option<[f64; N]> {
    for col in 0..N {
        let pivot = (col..N).max_by(|&i, &j| m[i][col].abs().total_cmp(&m[j][col].abs()))?;
        let p = m[pivot][col];
        if !p.is_finite() || p.abs() <= pivot_floor {
            return None;
        }
        m.swap(col, pivot);
        b.swap(col, pivot);
        let top = m[col];
        for row in col + 1..N {
            let factor = m[row][col] / top[col];
            for (value, above) in m[row].iter_mut().zip(top).skip(col) {
                *value -= factor * above;
            }
            b[row] -= factor * b[col];
        }
    }
    let mut x = [0.0; N];
    for row in (0..N).rev() {
        let mut sum = b[row];
        for k in row + 1..N {
            sum -= m[row][k] * x[k];
        }
        x[row] = sum / m[row][row];
    }
    x.iter().all(|v| v.is_finite()).then_some(x)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn solves_a_system_that_needs_pivoting_and_refuses_a_singular_one() {
        // The first pivot is zero: rows must be exchanged.
        let m = [[0.0, 2.0, 1.0], [1.0, 1.0, 0.0], [2.0, 0.0, 3.0]];
        let x = solve_dense(m, [7.0, 3.0, 11.0], 0.0).unwrap();
        for (got, want) in x.iter().zip([1.0, 2.0, 3.0]) {
            assert!((got - want).abs() < 1e-15, "{x:?}");
        }
        let singular = [[1.0, 2.0], [2.0, 4.0]];
        assert!(solve_dense(singular, [1.0, 2.0], 1e-12).is_none());
    }
}

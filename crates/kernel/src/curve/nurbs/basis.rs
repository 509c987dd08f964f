//! B-spline basis functions on knot vectors in Rhino form.
//!
//! Rhino stores `n + p − 1` knots for `n` control points of degree `p`; the textbook ("full")
//! form adds one knot at each end. The algorithms here are those of Piegl and Tiller's
//! *The NURBS Book* (A2.1 span search, A2.2 basis functions, A2.3 derivatives), which never read
//! the two extra knots, written directly on the Rhino form: Rhino knot `k[j]` is full knot `U[j+1]`.
//!
//! A *span* is a Rhino knot index `i` with `k[i] ≤ t < k[i+1]` and `p − 1 ≤ i ≤ n − 2`; the
//! `p + 1` basis functions that are non-zero there belong to control points
//! `i + 1 − p ..= i + 1`.

/// The highest degree the fixed-size basis routines support.
///
/// Rhino itself rarely goes past degree 11; 15 leaves room while keeping all scratch space on
/// the stack.
pub const MAX_DEGREE: usize = 15;

/// The largest number of basis functions that can be non-zero at once (`MAX_DEGREE + 1`).
pub const MAX_ORDER: usize = MAX_DEGREE + 1;

/// The span containing `t`, as a Rhino knot index `i` with `k[i] ≤ t < k[i+1]`.
///
/// Parameters before the domain map to the first span and parameters at or after its end to the
/// last span, so that evaluation at the ends (and slight extrapolation) is well defined. The
/// search is a binary search over the domain's knots.
#[inline]
pub fn span_index(degree: usize, knots: &[f64], t: f64) -> usize {
    let low = degree - 1;
    let high = knots.len() - degree - 1; // the last span, n − 2
    if t >= knots[high] {
        // Walk back over a zero-length last span (cannot happen for valid knots, kept robust).
        let mut i = high;
        while i > low && knots[i] == knots[i + 1] {
            i -= 1;
        }
        return i;
    }
    if t <= knots[low] {
        let mut i = low;
        while i < high && knots[i] == knots[i + 1] {
            i += 1;
        }
        return i;
    }
    // Invariant: knots[lo] <= t < knots[hi].
    let (mut lo, mut hi) = (low, high + 1);
    while hi - lo > 1 {
        let mid = (lo + hi) / 2;
        if t < knots[mid] {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    lo
}

/// The `degree + 1` non-zero basis functions at `t` in span `span`, written to
/// `out[..=degree]` (The NURBS Book, A2.2).
#[inline]
pub fn basis_functions(degree: usize, knots: &[f64], span: usize, t: f64, out: &mut [f64]) {
    let mut left = [0.0; MAX_ORDER];
    let mut right = [0.0; MAX_ORDER];
    out[0] = 1.0;
    for j in 1..=degree {
        // With full span s = span + 1: t − U[s + 1 − j] = t − k[span + 1 − j] and
        // U[s + j] − t = k[span + j] − t.
        left[j] = t - knots[span + 1 - j];
        right[j] = knots[span + j] - t;
        let mut saved = 0.0;
        for r in 0..j {
            let denom = right[r + 1] + left[j - r];
            let temp = if denom != 0.0 { out[r] / denom } else { 0.0 };
            out[r] = saved + right[r + 1] * temp;
            saved = left[j - r] * temp;
        }
        out[j] = saved;
    }
}

/// The basis functions and their derivatives up to order `n_ders` at `t` in span `span`
/// (The NURBS Book, A2.3): `ders[k][j]` is the `k`-th derivative of the `j`-th non-zero basis
/// function. Derivatives above the degree are zero.
pub fn basis_function_derivatives(
    degree: usize,
    knots: &[f64],
    span: usize,
    t: f64,
    n_ders: usize,
    ders: &mut [[f64; MAX_ORDER]],
) {
    // The triangle of basis functions and knot differences is `(degree + 1)²`; sizing it for
    // the degree at hand keeps the common low degrees from clearing a `MAX_ORDER²` table on
    // every call.
    if degree < 4 {
        derivatives_with_table::<4>(degree, knots, span, t, n_ders, ders);
    } else if degree < 8 {
        derivatives_with_table::<8>(degree, knots, span, t, n_ders, ders);
    } else {
        derivatives_with_table::<MAX_ORDER>(degree, knots, span, t, n_ders, ders);
    }
}

/// [`basis_function_derivatives`] with an `N × N` triangle (`N > degree`).
fn derivatives_with_table<const N: usize>(
    degree: usize,
    knots: &[f64],
    span: usize,
    t: f64,
    n_ders: usize,
    ders: &mut [[f64; MAX_ORDER]],
) {
    let p = degree;
    let mut ndu = [[0.0; N]; N];
    let mut left = [0.0; MAX_ORDER];
    let mut right = [0.0; MAX_ORDER];
    ndu[0][0] = 1.0;
    for j in 1..=p {
        left[j] = t - knots[span + 1 - j];
        right[j] = knots[span + j] - t;
        let mut saved = 0.0;
        for r in 0..j {
            // Lower triangle: knot differences.
            ndu[j][r] = right[r + 1] + left[j - r];
            let temp = if ndu[j][r] != 0.0 {
                ndu[r][j - 1] / ndu[j][r]
            } else {
                0.0
            };
            // Upper triangle: basis functions.
            ndu[r][j] = saved + right[r + 1] * temp;
            saved = left[j - r] * temp;
        }
        ndu[j][j] = saved;
    }
    for j in 0..=p {
        ders[0][j] = ndu[j][p];
    }
    let mut a = [[0.0; N]; 2];
    let top = n_ders.min(p);
    for r in 0..=p {
        let (mut s1, mut s2) = (0usize, 1usize);
        a[0][0] = 1.0;
        for k in 1..=top {
            let mut d = 0.0;
            let rk = r as isize - k as isize;
            let pk = p - k;
            if r >= k {
                let rk = rk as usize;
                a[s2][0] = if ndu[pk + 1][rk] != 0.0 {
                    a[s1][0] / ndu[pk + 1][rk]
                } else {
                    0.0
                };
                d = a[s2][0] * ndu[rk][pk];
            }
            let j1 = if rk >= -1 { 1 } else { (-rk) as usize };
            let j2 = if r <= pk { k - 1 } else { p - r };
            for j in j1..=j2 {
                let idx = (rk + j as isize) as usize;
                a[s2][j] = if ndu[pk + 1][idx] != 0.0 {
                    (a[s1][j] - a[s1][j - 1]) / ndu[pk + 1][idx]
                } else {
                    0.0
                };
                d += a[s2][j] * ndu[idx][pk];
            }
            if r <= pk {
                a[s2][k] = if ndu[pk + 1][r] != 0.0 {
                    -a[s1][k - 1] / ndu[pk + 1][r]
                } else {
                    0.0
                };
                d += a[s2][k] * ndu[r][pk];
            }
            ders[k][r] = d;
            std::mem::swap(&mut s1, &mut s2);
        }
    }
    let mut factor = p as f64;
    for (k, row) in ders.iter_mut().enumerate().take(top + 1).skip(1) {
        for d in &mut row[..=p] {
            *d *= factor;
        }
        factor *= (p - k) as f64;
    }
    for row in ders.iter_mut().take(n_ders + 1).skip(top + 1) {
        row[..=p].fill(0.0);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    // The book's de Boor example: degree 3, knots 0,0,0,0.25,0.5,0.75,1,1,1 (Rhino form).
    const KNOTS: [f64; 9] = [0.0, 0.0, 0.0, 0.25, 0.5, 0.75, 1.0, 1.0, 1.0];

    #[test]
    fn spans_cover_the_domain() {
        assert_eq!(span_index(3, &KNOTS, 0.0), 2);
        assert_eq!(span_index(3, &KNOTS, 0.1), 2);
        assert_eq!(span_index(3, &KNOTS, 0.25), 3);
        assert_eq!(span_index(3, &KNOTS, 0.4), 3);
        assert_eq!(span_index(3, &KNOTS, 0.99), 5);
        assert_eq!(span_index(3, &KNOTS, 1.0), 5);
        assert_eq!(span_index(3, &KNOTS, 2.0), 5);
        assert_eq!(span_index(3, &KNOTS, -1.0), 2);
    }

    #[test]
    fn basis_is_a_partition_of_unity() {
        for i in 0..=100 {
            let t = i as f64 / 100.0;
            let span = span_index(3, &KNOTS, t);
            let mut n = [0.0; MAX_ORDER];
            basis_functions(3, &KNOTS, span, t, &mut n);
            let sum: f64 = n[..4].iter().sum();
            assert!((sum - 1.0).abs() < 1e-14, "t = {t}: sum {sum}");
            assert!(n[..4].iter().all(|&x| x >= -1e-15));
        }
    }

    #[test]
    fn derivatives_match_finite_differences() {
        let h = 1e-6;
        for &t in &[0.1, 0.3, 0.4, 0.6, 0.9] {
            let span = span_index(3, &KNOTS, t);
            let mut ders = [[0.0; MAX_ORDER]; 3];
            basis_function_derivatives(3, &KNOTS, span, t, 2, &mut ders);
            let mut plus = [0.0; MAX_ORDER];
            let mut minus = [0.0; MAX_ORDER];
            basis_functions(3, &KNOTS, span, t + h, &mut plus);
            basis_functions(3, &KNOTS, span, t - h, &mut minus);
            let mut mid = [0.0; MAX_ORDER];
            basis_functions(3, &KNOTS, span, t, &mut mid);
            for j in 0..4 {
                assert!((ders[0][j] - mid[j]).abs() < 1e-15);
                let d1 = (plus[j] - minus[j]) / (2.0 * h);
                assert!(
                    (ders[1][j] - d1).abs() < 1e-6,
                    "t {t} j {j}: {} vs {d1}",
                    ders[1][j]
                );
                let d2 = (plus[j] - 2.0 * mid[j] + minus[j]) / (h * h);
                assert!(
                    (ders[2][j] - d2).abs() < 1e-2,
                    "t {t} j {j}: {} vs {d2}",
                    ders[2][j]
                );
            }
        }
    }
}

//! Roots and near-roots of a rational function in Bernstein form on `[0, 1]`: the signed
//! distance of a Bézier piece from a plane, `d(s) = N(s) / W(s)`, with the numerator `N` and the
//! (positive) weight `W` given by their Bernstein coefficients.
//!
//! The search subdivides the piece (de Casteljau at the middle) until each part is simple:
//! - a part whose coefficient distances `N_j / W_j` are all above `tolerance`, or all below
//!   `−tolerance`, holds no point within the tolerance (the convex hull property: `d` is a convex
//!   combination of them) and is dropped;
//! - a part whose numerator is monotone (the differences of its coefficients, the derivative's
//!   coefficients, have one sign) has at most one root, found by bisection when its end values
//!   differ in sign; otherwise its nearest value is at an end, kept as a touching candidate
//!   when it is within the tolerance (a kink touching the plane);
//! - a part whose numerator has one extremum (the derivative's coefficients change sign once)
//!   has its extremum found by bisection on the derivative, and then at most two roots on either
//!   side of it, or a touching candidate at the extremum when it comes within the tolerance (a
//!   tangency, a double root);
//! - any other part is halved, to [`MAX_DEPTH`] levels.
//!
//! By the variation-diminishing property the number of sign changes of the coefficients bounds
//! the number of roots, and halving makes the coefficients converge to the function, so every
//! root is isolated after a few levels.

use crate::curve::nurbs::basis::MAX_ORDER;

/// How many times a piece may be halved: 2⁻⁴⁰ of a span is far below any tolerance.
pub(crate) const MAX_DEPTH: usize = 40;

/// Bisection steps on `[0, 1]`: 2⁻⁶⁰ is below the rounding of any parameter.
const BISECTION_STEPS: usize = 60;

/// A place in `[0, 1]` where the function is zero or comes within the tolerance of zero.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Root {
    /// The local parameter.
    pub(crate) s: f64,
    /// Whether the function touches zero there without changing sign (a double root or a
    /// near miss within the tolerance), rather than crossing it.
    pub(crate) touching: bool,
}

/// A polynomial's Bernstein coefficients on a sub-interval `[s0, s1]` of `[0, 1]`, with the
/// weight's.
#[derive(Clone, Copy)]
struct Part {
    n: [f64; MAX_ORDER],
    w: [f64; MAX_ORDER],
    s0: f64,
    s1: f64,
}

/// The roots of `N / W` on `[0, 1]` and the places where it touches zero within `tolerance`, in
/// increasing order of `s` (a root at a shared end of two parts may appear twice; callers merge
/// nearby events). `numerator` and `weight` have the same length, at most [`MAX_ORDER`].
pub(crate) fn roots(numerator: &[f64], weight: &[f64], tolerance: f64) -> Vec<Root> {
    let len = numerator.len();
    debug_assert!(len == weight.len() && (1..=MAX_ORDER).contains(&len));
    let mut part = Part {
        n: [0.0; MAX_ORDER],
        w: [0.0; MAX_ORDER],
        s0: 0.0,
        s1: 1.0,
    };
    part.n[..len].copy_from_slice(numerator);
    part.w[..len].copy_from_slice(weight);
    let mut out = Vec::new();
    search(&part, len, tolerance, 0, &mut out);
    out.sort_by(|a, b| a.s.total_cmp(&b.s));
    out
}

fn search(part: &Part, len: usize, tolerance: f64, depth: usize, out: &mut Vec<Root>) {
    let (n, w) = (&part.n[..len], &part.w[..len]);
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for (a, b) in n.iter().zip(w) {
        let d = a / b;
        lo = lo.min(d);
        hi = hi.max(d);
    }
    if !(lo <= tolerance && hi >= -tolerance) {
        return;
    }
    let local = |u: f64| part.s0 + (part.s1 - part.s0) * u;
    match derivative_sign_changes(n) {
        0 => monotone(part, len, tolerance, out),
        1 => {
            let extremum = bisect(|u| derivative_at(n, u), 0.0, 1.0);
            let (f0, fm, f1) = (n[0], evaluate(n, extremum), n[len - 1]);
            let mut crossed = false;
            if f0 == 0.0 || f0.signum() != fm.signum() && fm != 0.0 {
                out.push(root_between(n, 0.0, extremum, &local));
                crossed = true;
            }
            if f1 == 0.0 || f1.signum() != fm.signum() && fm != 0.0 {
                out.push(root_between(n, extremum, 1.0, &local));
                crossed = true;
            }
            if !crossed && (fm / evaluate(w, extremum)).abs() <= tolerance {
                out.push(Root {
                    s: local(extremum),
                    touching: true,
                });
            }
        }
        _ if depth >= MAX_DEPTH => {
            let d = evaluate(n, 0.5) / evaluate(w, 0.5);
            if d.abs() <= tolerance {
                out.push(Root {
                    s: local(0.5),
                    touching: true,
                });
            }
        }
        _ => {
            let (a, b) = halve(part, len);
            search(&a, len, tolerance, depth + 1, out);
            search(&b, len, tolerance, depth + 1, out);
        }
    }
}

/// A part whose numerator is monotone: its one root, or its end nearest zero when that is
/// within the tolerance.
fn monotone(part: &Part, len: usize, tolerance: f64, out: &mut Vec<Root>) {
    let n = &part.n[..len];
    let (f0, f1) = (n[0], n[len - 1]);
    let local = |u: f64| part.s0 + (part.s1 - part.s0) * u;
    if f0 == 0.0 || f1 == 0.0 || f0.signum() != f1.signum() {
        out.push(root_between(n, 0.0, 1.0, &local));
        return;
    }
    let (d0, d1) = (f0 / part.w[0], f1 / part.w[len - 1]);
    let (u, d) = if d0.abs() <= d1.abs() {
        (0.0, d0)
    } else {
        (1.0, d1)
    };
    if d.abs() <= tolerance {
        out.push(Root {
            s: local(u),
            touching: true,
        });
    }
}

/// The root of `n` in `[a, b]` where its end values differ in sign (or one is zero).
fn root_between(n: &[f64], a: f64, b: f64, local: &impl Fn(f64) -> f64) -> Root {
    let u = bisect(|u| evaluate(n, u), a, b);
    Root {
        s: local(u),
        touching: false,
    }
}

/// A zero of `f` in `[a, b]` by bisection, given that `f(a)` and `f(b)` differ in sign or one
/// of them is zero (the exact end is returned then).
fn bisect(f: impl Fn(f64) -> f64, mut a: f64, mut b: f64) -> f64 {
    let fa = f(a);
    if fa == 0.0 {
        return a;
    }
    if f(b) == 0.0 {
        return b;
    }
    for _ in 0..BISECTION_STEPS {
        let m = 0.5 * (a + b);
        if m <= a || m >= b {
            break;
        }
        let fm = f(m);
        if fm == 0.0 {
            return m;
        }
        if fm.signum() == fa.signum() {
            a = m;
        } else {
            b = m;
        }
    }
    0.5 * (a + b)
}

/// The number of sign changes of the coefficients' differences (zeros skipped).
fn derivative_sign_changes(n: &[f64]) -> usize {
    let mut changes = 0;
    let mut last = 0.0_f64;
    for pair in n.windows(2) {
        let d = pair[1] - pair[0];
        if d != 0.0 {
            if last != 0.0 && d.signum() != last.signum() {
                changes += 1;
            }
            last = d;
        }
    }
    changes
}

/// The polynomial at `u` by de Casteljau's algorithm.
pub(crate) fn evaluate(c: &[f64], u: f64) -> f64 {
    let mut q = [0.0; MAX_ORDER];
    let len = c.len();
    q[..len].copy_from_slice(c);
    for level in 1..len {
        for i in 0..len - level {
            q[i] += u * (q[i + 1] - q[i]);
        }
    }
    q[0]
}

/// The derivative at `u` (up to the positive factor `degree`): the polynomial of the
/// differences.
fn derivative_at(c: &[f64], u: f64) -> f64 {
    let mut d = [0.0; MAX_ORDER];
    let len = c.len();
    if len < 2 {
        return 0.0;
    }
    for i in 0..len - 1 {
        d[i] = c[i + 1] - c[i];
    }
    evaluate(&d[..len - 1], u)
}

/// The two halves of a part, by de Casteljau's algorithm at the middle.
fn halve(part: &Part, len: usize) -> (Part, Part) {
    let split = |c: &[f64; MAX_ORDER]| {
        let mut left = [0.0; MAX_ORDER];
        let mut right = [0.0; MAX_ORDER];
        let mut q = *c;
        left[0] = q[0];
        right[len - 1] = q[len - 1];
        for level in 1..len {
            for i in 0..len - level {
                q[i] = 0.5 * (q[i] + q[i + 1]);
            }
            left[level] = q[0];
            right[len - 1 - level] = q[len - 1 - level];
        }
        (left, right)
    };
    let (nl, nr) = split(&part.n);
    let (wl, wr) = split(&part.w);
    let m = 0.5 * (part.s0 + part.s1);
    (
        Part {
            n: nl,
            w: wl,
            s0: part.s0,
            s1: m,
        },
        Part {
            n: nr,
            w: wr,
            s0: m,
            s1: part.s1,
        },
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Bernstein coefficients of a polynomial given by its power coefficients (low first).
    fn from_power(p: &[f64]) -> Vec<f64> {
        let n = p.len() - 1;
        let binom = |n: usize, k: usize| -> f64 {
            (0..k).fold(1.0, |acc, i| acc * (n - i) as f64 / (i + 1) as f64)
        };
        (0..=n)
            .map(|j| (0..=j).map(|i| binom(j, i) / binom(n, i) * p[i]).sum())
            .collect()
    }

    fn ones(len: usize) -> Vec<f64> {
        vec![1.0; len]
    }

    #[test]
    fn evaluation_matches_the_power_form() {
        let p = [0.3, -2.0, 1.5, 4.0];
        let b = from_power(&p);
        for u in [0.0, 0.2, 0.5, 0.9, 1.0] {
            let want = p[0] + p[1] * u + p[2] * u * u + p[3] * u * u * u;
            assert!((evaluate(&b, u) - want).abs() < 1e-14);
        }
    }

    #[test]
    fn finds_every_simple_root() {
        // (u − 0.1)(u − 0.45)(u − 0.8) = u³ − 1.35u² + 0.485u − 0.036
        let b = from_power(&[-0.036, 0.485, -1.35, 1.0]);
        let r = roots(&b, &ones(4), 1e-12);
        let s: Vec<f64> = r.iter().map(|r| r.s).collect();
        assert_eq!(s.len(), 3, "{r:?}");
        for (got, want) in s.iter().zip([0.1, 0.45, 0.8]) {
            assert!((got - want).abs() < 1e-14, "{got} {want}");
        }
        assert!(r.iter().all(|r| !r.touching));
    }

    #[test]
    fn finds_a_double_root_as_touching() {
        // (u − 0.3)²
        let b = from_power(&[0.09, -0.6, 1.0]);
        let r = roots(&b, &ones(3), 1e-9);
        assert_eq!(r.len(), 1, "{r:?}");
        assert!(r[0].touching);
        assert!((r[0].s - 0.3).abs() < 1e-9);
    }

    #[test]
    fn a_near_miss_beyond_the_tolerance_is_no_root() {
        // (u − 0.3)² + 1e-6
        let b = from_power(&[0.09 + 1e-6, -0.6, 1.0]);
        assert!(roots(&b, &ones(3), 1e-7).is_empty());
        assert_eq!(roots(&b, &ones(3), 1e-5).len(), 1);
    }

    #[test]
    fn roots_at_the_ends_are_exact() {
        let b = from_power(&[0.0, 1.0, -3.0]);
        let r = roots(&b, &ones(3), 1e-12);
        assert!(r.iter().any(|r| r.s == 0.0), "{r:?}");
        assert!(r.iter().any(|r| (r.s - 1.0 / 3.0).abs() < 1e-15), "{r:?}");
    }

    #[test]
    fn weights_scale_the_tolerance_test_not_the_roots() {
        let b = from_power(&[-0.25, 1.0]);
        let r = roots(&b, &[2.0, 3.0], 1e-12);
        assert_eq!(r.len(), 1);
        assert!((r[0].s - 0.25).abs() < 1e-15);
    }
}

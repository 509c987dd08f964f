//! Property tests of curve invariants: reparameterization, knot insertion and splitting keep
//! the shape; derivatives agree with finite differences; a closest point is no farther than any
//! sampled point; the batch evaluator agrees with the single-point one.

use locus_kernel::{Curve, Interval, NurbsCurve, Point3};
use proptest::prelude::*;

/// A random valid NURBS curve: degree 1 to 5, clamped or periodic-like unclamped knots with
/// random spacing, some interior knots repeated (up to full multiplicity, giving kinks),
/// rational or not.
fn arb_curve() -> impl Strategy<Value = NurbsCurve> {
    (1usize..=5, 0usize..=6, any::<bool>(), any::<bool>()).prop_flat_map(
        |(degree, extra, rational, clamped)| {
            let n = degree + 1 + extra;
            let points = prop::collection::vec((-10.0f64..10.0, -10.0f64..10.0, -10.0f64..10.0), n);
            let weights = prop::collection::vec(0.3f64..3.0, n);
            let knot_count = n + degree - 1;
            let steps = prop::collection::vec(0.05f64..2.0, knot_count);
            let repeats = prop::collection::vec(0usize..4, knot_count);
            (
                Just(degree),
                points,
                weights,
                steps,
                repeats,
                Just(rational),
                Just(clamped),
                -5.0f64..5.0,
            )
                .prop_map(
                    |(degree, points, weights, steps, repeats, rational, clamped, start)| {
                        build(
                            degree, points, weights, &steps, &repeats, rational, clamped, start,
                        )
                    },
                )
        },
    )
}

#[allow(clippy::too_many_arguments, reason = "one argument per generated part")]
fn build(
    degree: usize,
    points: Vec<(f64, f64, f64)>,
    weights: Vec<f64>,
    steps: &[f64],
    repeats: &[usize],
    rational: bool,
    clamped: bool,
    start: f64,
) -> NurbsCurve {
    let n = points.len();
    let points: Vec<Point3> = points
        .into_iter()
        .map(|(x, y, z)| Point3::new(x, y, z))
        .collect();
    let weights = if rational { weights } else { vec![1.0; n] };
    let count = n + degree - 1;
    // Distinct increasing values, then merge some neighbours to repeat knots, keeping every
    // multiplicity at most the degree and the first and last spans non-empty.
    let mut knots = Vec::with_capacity(count);
    let mut value = start;
    for (i, step) in steps.iter().enumerate().take(count) {
        if i > 0 {
            value += step;
        }
        knots.push(value);
    }
    if clamped {
        let lo = knots[degree - 1];
        let hi = knots[n - 1];
        for k in &mut knots[..degree] {
            *k = lo;
        }
        for k in &mut knots[n - 1..] {
            *k = hi;
        }
    }
    // Interior repeats: copy a knot onto its right neighbours (never touching the first and
    // last spans of the domain).
    let (lo, hi) = (degree, n - 2);
    let mut i = lo;
    while i < hi {
        let r = repeats[i].min(degree - 1).min(hi - i);
        for j in 1..=r {
            if i + j < hi {
                knots[i + j] = knots[i];
            }
        }
        i += r + 1;
    }
    NurbsCurve::new(degree, points, weights, knots).expect("generated curve is valid")
}

fn parameters(curve: &NurbsCurve, count: usize) -> Vec<f64> {
    let d = curve.domain();
    (0..=count)
        .map(|i| d.parameter_at(i as f64 / count as f64))
        .collect()
}

fn scale(curve: &NurbsCurve) -> f64 {
    curve.points().iter().fold(1.0f64, |m, p| {
        m.max(p.x.abs()).max(p.y.abs()).max(p.z.abs())
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    #[test]
    fn reparameterize_keeps_every_point(curve in arb_curve(), a in -100.0f64..100.0, len in 0.01f64..50.0) {
        let target = Interval::new(a, a + len);
        let r = curve.reparameterized(target).unwrap();
        prop_assert_eq!(r.domain(), target);
        let tol = 1e-9 * scale(&curve);
        for t in parameters(&curve, 40) {
            let s = curve.map_parameter(t, target);
            prop_assert!(r.point_at(s).distance(curve.point_at(t)) <= tol);
        }
    }

    #[test]
    fn knot_insertion_keeps_the_shape(curve in arb_curve(), f in 0.01f64..0.99, times in 1usize..4) {
        let t = curve.domain().parameter_at(f);
        let allowed = curve.degree().saturating_sub(curve.knot_multiplicity(t));
        let times = times.min(allowed);
        prop_assume!(times > 0);
        let r = curve.insert_knot(t, times).unwrap();
        let tol = 1e-10 * scale(&curve);
        for s in parameters(&curve, 50) {
            prop_assert!(r.point_at(s).distance(curve.point_at(s)) <= tol);
        }
    }

    #[test]
    fn split_keeps_the_shape(curve in arb_curve(), f in 0.01f64..0.99) {
        let t = curve.domain().parameter_at(f);
        let (a, b) = curve.split_at(t).unwrap();
        let tol = 1e-9 * scale(&curve);
        for s in parameters(&curve, 50) {
            let piece = if s <= t { &a } else { &b };
            prop_assert!(piece.point_at(s).distance(curve.point_at(s)) <= tol);
        }
        prop_assert!(a.end_point().distance(b.start_point()) <= tol);
    }

    #[test]
    fn derivatives_agree_with_finite_differences(curve in arb_curve(), f in 0.0f64..1.0) {
        // Stay away from knots, where derivatives jump.
        let d = curve.domain();
        let t = d.parameter_at(f);
        let h = 1e-6 * d.length();
        let gap = curve.knots().iter().map(|k| (k - t).abs()).fold(f64::INFINITY, f64::min);
        prop_assume!(gap > 10.0 * h);
        let ders = curve.derivatives_at(t, 2);
        let fd1 = (curve.point_at(t + h) - curve.point_at(t - h)) / (2.0 * h);
        let m1 = ders[1].length().max(scale(&curve) / d.length());
        prop_assert!((ders[1] - fd1).length() <= 1e-5 * m1, "d1 {:?} fd {:?}", ders[1], fd1);
        let fd2 = (curve.derivatives_at(t + h, 1)[1] - curve.derivatives_at(t - h, 1)[1]) / (2.0 * h);
        let m2 = ders[2].length().max(m1 / d.length());
        prop_assert!((ders[2] - fd2).length() <= 1e-4 * m2, "d2 {:?} fd {:?}", ders[2], fd2);
    }

    #[test]
    fn closest_point_is_no_farther_than_any_sample(
        curve in arb_curve(),
        (x, y, z) in (-15.0f64..15.0, -15.0f64..15.0, -15.0f64..15.0),
    ) {
        let p = Point3::new(x, y, z);
        let r = curve.closest_point(p).unwrap();
        prop_assert!(curve.domain().contains(r.t));
        prop_assert!((r.point.distance(p) - r.distance).abs() <= 1e-12 * scale(&curve));
        for t in parameters(&curve, 2000) {
            let sample = curve.point_at(t).distance(p);
            prop_assert!(r.distance <= sample + 1e-9 * scale(&curve), "t {} sample {} found {}", t, sample, r.distance);
        }
        // The same through the enum.
        let via_enum = Curve::from(curve.clone()).closest_point(p).unwrap();
        prop_assert_eq!(via_enum.distance, r.distance);
    }

    #[test]
    fn batch_agrees_with_single_points(curve in arb_curve(), count in 1usize..300) {
        let ts = parameters(&curve, count);
        let mut out = vec![Point3::ORIGIN; ts.len()];
        curve.points_at(&ts, &mut out).unwrap();
        let tol = 1e-11 * scale(&curve);
        for (&t, p) in ts.iter().zip(&out) {
            prop_assert!(p.distance(curve.point_at(t)) <= tol, "t {}", t);
        }
    }

    #[test]
    fn lengths_are_additive(curve in arb_curve(), f in 0.05f64..0.95) {
        let d = curve.domain();
        let t = d.parameter_at(f);
        let whole = curve.length();
        let parts = curve.length_between(d.t0, t).unwrap() + curve.length_between(t, d.t1).unwrap();
        prop_assert!((whole - parts).abs() <= 1e-9 * whole.max(1.0));
    }
}

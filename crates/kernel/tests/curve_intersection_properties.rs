//! Property tests of curve | curve and curve | self intersections on random planar curves:
//!
//! - every reported point lies on both curves: `A(t_a)` and `B(t_b)` are within the tolerance
//!   of each other and are the reported points;
//! - nothing is missed: the curves are sampled densely into polylines, and every crossing of
//!   two polyline segments at a clear angle (where the curves themselves must cross, since
//!   they deviate from their chords by far less than the segments' length times the angle)
//!   has a reported point within two segment lengths;
//! - the same for a curve with itself (segments that are not neighbours).

use locus_kernel::{Curve, NurbsCurve, Point3};
use proptest::prelude::*;

/// The intersection tolerance of the properties (the oracle's).
const TOL: f64 = 1e-7;
/// Samples per curve for the dense polyline.
const SAMPLES: usize = 3000;
/// Sampled crossings at a smaller sine than this are not checked (the chords may cross where
/// the curves only come close, or miss a grazing crossing).
const CLEAR_SINE: f64 = 0.1;

/// A random planar NURBS curve (z = 0): degree 1 to 4, up to six extra control points, clamped
/// knots with random spacing, rational or not.
fn arb_planar_curve() -> impl Strategy<Value = NurbsCurve> {
    (1usize..=4, 0usize..=6, any::<bool>()).prop_flat_map(|(degree, extra, rational)| {
        let n = degree + 1 + extra;
        (
            Just(degree),
            prop::collection::vec((-5.0f64..5.0, -5.0f64..5.0), n),
            prop::collection::vec(0.5f64..2.0, n),
            prop::collection::vec(0.2f64..1.5, n - degree),
            Just(rational),
        )
            .prop_map(|(degree, points, weights, steps, rational)| {
                let n = points.len();
                let points = points
                    .into_iter()
                    .map(|(x, y)| Point3::new(x, y, 0.0))
                    .collect();
                let weights = if rational { weights } else { vec![1.0; n] };
                let mut knots = vec![0.0; degree];
                let mut k = 0.0;
                for s in &steps[..n - degree - 1] {
                    k += s;
                    knots.push(k);
                }
                k += steps[n - degree - 1];
                knots.extend(std::iter::repeat_n(k, degree));
                NurbsCurve::new(degree, points, weights, knots).expect("valid curve")
            })
    })
}

/// The curve sampled at `SAMPLES + 1` parameters, with the parameters.
fn polyline(c: &Curve) -> Vec<(f64, Point3)> {
    let d = c.domain();
    (0..=SAMPLES)
        .map(|k| {
            let t = d.parameter_at(k as f64 / SAMPLES as f64);
            (t, c.point_at(t))
        })
        .collect()
}

/// Where segments `p0 p1` and `q0 q1` cross in the plane, at a sine above `CLEAR_SINE`.
fn clear_crossing(p0: Point3, p1: Point3, q0: Point3, q1: Point3) -> Option<Point3> {
    let (d, e) = (p1 - p0, q1 - q0);
    let cross = d.x * e.y - d.y * e.x;
    let (ld, le) = (d.length(), e.length());
    if !(ld > 0.0 && le > 0.0) || cross.abs() < CLEAR_SINE * ld * le {
        return None;
    }
    let r = q0 - p0;
    let u = (r.x * e.y - r.y * e.x) / cross;
    let v = (r.x * d.y - r.y * d.x) / cross;
    // Away from the segments' ends, where a crossing could fall between two segment pairs.
    let inside = |x: f64| (0.01..=0.99).contains(&x);
    (inside(u) && inside(v)).then(|| p0 + d * u)
}

fn longest_segment(poly: &[(f64, Point3)]) -> f64 {
    poly.windows(2)
        .map(|w| w[0].1.distance(w[1].1))
        .fold(0.0, f64::max)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    #[test]
    fn curve_curve_points_lie_on_both_and_none_is_missed(
        a in arb_planar_curve(),
        b in arb_planar_curve(),
    ) {
        let (a, b) = (Curve::Nurbs(a), Curve::Nurbs(b));
        let x = a.intersect_curve(&b, TOL).unwrap();
        for h in &x.points {
            prop_assert!(h.point_a.distance(h.point_b) <= TOL, "{h:?}");
            prop_assert!(a.point_at(h.t_a).distance(h.point_a) <= 1e-12);
            prop_assert!(b.point_at(h.t_b).distance(h.point_b) <= 1e-12);
        }
        for o in &x.overlaps {
            for k in 0..=8 {
                let t = o.a.parameter_at(k as f64 / 8.0);
                let d = b.closest_point(a.point_at(t)).unwrap().distance;
                prop_assert!(d <= TOL, "overlap {o:?} leaves b by {d} at {t}");
            }
        }
        let (pa, pb) = (polyline(&a), polyline(&b));
        let reach = 2.0 * longest_segment(&pa).max(longest_segment(&pb));
        for sa in pa.windows(2) {
            for sb in pb.windows(2) {
                if let Some(c) = clear_crossing(sa[0].1, sa[1].1, sb[0].1, sb[1].1) {
                    let near = x.points.iter().any(|h| h.point_a.distance(c) <= reach)
                        || x.overlaps.iter().any(|o| {
                            (o.a.min()..=o.a.max()).contains(&sa[0].0)
                        });
                    prop_assert!(near, "missed the crossing near {c:?}: {x:?}");
                }
            }
        }
    }

    #[test]
    fn self_intersections_lie_on_the_curve_and_none_is_missed(c in arb_planar_curve()) {
        let c = Curve::Nurbs(c);
        let x = c.self_intersections(TOL).unwrap();
        for h in &x.points {
            prop_assert!(h.t_a < h.t_b, "{h:?}");
            prop_assert!(h.point_a.distance(h.point_b) <= TOL, "{h:?}");
            prop_assert!(c.point_at(h.t_a).distance(h.point_a) <= 1e-12);
            prop_assert!(c.point_at(h.t_b).distance(h.point_b) <= 1e-12);
        }
        let p = polyline(&c);
        let reach = 2.0 * longest_segment(&p);
        let segments: Vec<_> = p.windows(2).collect();
        for i in 0..segments.len() {
            for j in i + 2..segments.len() {
                let (s, t) = (segments[i], segments[j]);
                if let Some(q) = clear_crossing(s[0].1, s[1].1, t[0].1, t[1].1) {
                    let near = x.points.iter().any(|h| h.point_a.distance(q) <= reach);
                    prop_assert!(near, "missed the self-crossing near {q:?}: {x:?}");
                }
            }
        }
    }
}

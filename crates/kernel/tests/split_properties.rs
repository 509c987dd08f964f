//! Property tests of cutting curves and of periodic interpolation: shattered pieces trace the
//! curve, meet end to end and add up to its length; a periodic interpolated curve passes through
//! its points and is smooth everywhere, its seam included.

use locus_kernel::{
    Circle, Curve, KINK_ANGLE_TOLERANCE, KnotStyle, NurbsCurve, Plane, Point3, Polyline,
};
use proptest::prelude::*;

fn arb_points(min: usize, max: usize) -> impl Strategy<Value = Vec<Point3>> {
    prop::collection::vec(
        (-10.0f64..10.0, -10.0f64..10.0, -10.0f64..10.0).prop_map(|(x, y, z)| Point3::new(x, y, z)),
        min..=max,
    )
}

/// A random curve of every kind: a NURBS curve through `create` (open or periodic), a polyline
/// (open or closed), a circle.
fn arb_curve() -> impl Strategy<Value = Curve> {
    prop_oneof![
        (arb_points(6, 9), 1usize..=4, any::<bool>()).prop_map(|(pts, degree, periodic)| {
            NurbsCurve::create(&pts, degree, periodic)
                .expect("enough points")
                .into()
        }),
        (arb_points(4, 8), any::<bool>()).prop_map(|(mut pts, closed)| {
            if closed {
                pts.push(pts[0]);
            }
            Polyline::new(pts).expect("enough points").into()
        }),
        (0.5f64..5.0).prop_map(|r| Circle::new(Plane::WORLD_XY, r).expect("radius").into()),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn shattered_pieces_trace_the_curve(
        curve in arb_curve(),
        fractions in prop::collection::vec(0.01f64..0.99, 1..5),
    ) {
        let d = curve.domain();
        let ts: Vec<f64> = fractions.iter().map(|&f| d.parameter_at(f)).collect();
        let pieces = curve.split_at_parameters(&ts).expect("valid parameters");
        let total: f64 = pieces.iter().map(Curve::length).sum();
        let length = curve.length();
        prop_assert!((total - length).abs() <= 1e-8 * length.max(1.0), "{total} vs {length}");
        for w in pieces.windows(2) {
            prop_assert!(w[0].end_point().distance(w[1].start_point()) < 1e-9);
            prop_assert_eq!(w[0].domain().t1, w[1].domain().t0);
        }
        let period = d.length();
        for piece in &pieces {
            let pd = piece.domain();
            for i in 0..=8 {
                let t = pd.parameter_at(i as f64 / 8.0);
                let on_curve = if t > d.t1 { t - period } else { t };
                let gap = piece.point_at(t).distance(curve.point_at(on_curve));
                prop_assert!(gap < 1e-9, "{piece:?} at {t}: {gap}");
            }
        }
        if curve.is_closed() {
            let last = &pieces[pieces.len() - 1];
            prop_assert!(last.end_point().distance(pieces[0].start_point()) < 1e-9);
        }
    }

    #[test]
    fn periodic_interpolation_passes_through_and_is_smooth(
        pts in arb_points(4, 12),
        degree in prop::sample::select(vec![1usize, 3, 5]),
        style in prop::sample::select(vec![
            KnotStyle::Uniform,
            KnotStyle::Chord,
            KnotStyle::ChordSquareRoot,
        ]),
    ) {
        prop_assume!(pts.len() >= degree);
        let curve = NurbsCurve::interpolate_periodic(&pts, degree, style).expect("interpolation");
        for p in &pts {
            let cp = curve.closest_point(*p).expect("finite point");
            prop_assert!(cp.distance < 1e-7, "{cp:?}");
        }
        prop_assert!(curve.is_closed());
        if degree > 1 {
            prop_assert!(curve.is_periodic());
            let c: Curve = curve.into();
            prop_assert!(c.kinks(KINK_ANGLE_TOLERANCE).expect("tolerance").is_empty());
        }
    }
}

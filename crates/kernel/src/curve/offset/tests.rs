use proptest::prelude::*;

use super::*;
use crate::geometry::tolerance::DOCUMENT_TOLERANCE;
use crate::{Interval, Transform};

fn p(x: f64, y: f64) -> Point3 {
    Point3::new(x, y, 0.0)
}

fn offset(c: impl Into<Curve>, d: f64, corners: OffsetCorners) -> CurveOffset {
    c.into()
        .offset(d, &Plane::WORLD_XY, corners, DOCUMENT_TOLERANCE)
        .unwrap()
}

#[test]
fn lines_move_to_the_right() {
    let o = offset(
        Line::new(p(0.0, 0.0), p(4.0, 0.0)),
        1.0,
        OffsetCorners::Sharp,
    );
    assert_eq!(o.curve.start_point(), p(0.0, -1.0));
    assert_eq!(o.curve.end_point(), p(4.0, -1.0));
    assert!(o.warnings.is_empty());
    let up: Curve = Line::new(Point3::ORIGIN, Point3::new(0.0, 0.0, 1.0)).into();
    assert!(
        up.offset(1.0, &Plane::WORLD_XY, OffsetCorners::Sharp, 0.001)
            .is_err()
    );
}

#[test]
fn circles_and_arcs_change_radius() {
    let circle = Circle::new(Plane::WORLD_XY, 5.0).unwrap();
    let Curve::Circle { circle: c, .. } = offset(circle, 1.0, OffsetCorners::Sharp).curve else {
        panic!()
    };
    assert_eq!(c.radius, 6.0);
    let Curve::Circle { circle: c, .. } = offset(circle, -2.0, OffsetCorners::Sharp).curve else {
        panic!()
    };
    assert_eq!(c.radius, 3.0);
    let flipped: Curve = circle.reversed().into();
    let Curve::Circle { circle: c, .. } = flipped
        .offset(1.0, &Plane::WORLD_XY, OffsetCorners::Sharp, 0.001)
        .unwrap()
        .curve
    else {
        panic!()
    };
    assert_eq!(c.radius, 4.0);
    let e = Curve::from(circle)
        .offset(-5.0, &Plane::WORLD_XY, OffsetCorners::Sharp, 0.001)
        .unwrap_err();
    assert!(e.to_string().contains("collapses"), "{e}");
    let arc = Arc::new(circle, Interval::new(0.0, 1.0)).unwrap();
    let Curve::Arc { arc: a, .. } = offset(arc, 1.0, OffsetCorners::Sharp).curve else {
        panic!()
    };
    assert_eq!((a.radius(), a.angle), (6.0, arc.angle));
}

fn unit_square() -> Polyline {
    // Counter-clockwise.
    Polyline::new(vec![
        p(0.0, 0.0),
        p(1.0, 0.0),
        p(1.0, 1.0),
        p(0.0, 1.0),
        p(0.0, 0.0),
    ])
    .unwrap()
}

#[test]
fn a_square_offset_outwards_with_each_corner_style() {
    let sharp = offset(unit_square(), 1.0, OffsetCorners::Sharp);
    let Curve::Polyline { polyline, .. } = &sharp.curve else {
        panic!("{sharp:?}")
    };
    assert_eq!(
        polyline.points(),
        [
            p(-1.0, -1.0),
            p(2.0, -1.0),
            p(2.0, 2.0),
            p(-1.0, 2.0),
            p(-1.0, -1.0)
        ]
    );
    assert!((sharp.curve.length() - 12.0).abs() < 1e-14);
    assert_eq!(
        offset(unit_square(), 1.0, OffsetCorners::None).curve,
        sharp.curve
    );
    // Round: four sides of 1 and four quarter circles of radius 1.
    let round = offset(unit_square(), 1.0, OffsetCorners::Round).curve;
    assert!(round.is_closed());
    assert!((round.length() - (4.0 + 2.0 * std::f64::consts::PI)).abs() < 1e-9);
    // Chamfer: four sides of 1 and four diagonals of √2.
    let chamfer = offset(unit_square(), 1.0, OffsetCorners::Chamfer).curve;
    let Curve::Polyline { polyline, .. } = &chamfer else {
        panic!("{chamfer:?}")
    };
    assert_eq!(polyline.points().len(), 9);
    assert!((chamfer.length() - (4.0 + 4.0 * 2f64.sqrt())).abs() < 1e-12);
    let smooth = offset(unit_square(), 1.0, OffsetCorners::Smooth).curve;
    assert!(smooth.is_closed());
    assert!(smooth.length() > 4.0 + 4.0 * 2f64.sqrt() && smooth.length() < 12.0);
}

#[test]
fn a_square_offset_inwards_is_trimmed_and_may_turn_over() {
    let inner = offset(unit_square(), -0.25, OffsetCorners::Round);
    assert!((inner.curve.length() - 2.0).abs() < 1e-12);
    assert!(inner.warnings.is_empty());
    let over = offset(unit_square(), -0.75, OffsetCorners::Sharp);
    assert!(!over.warnings.is_empty());
    assert!(over.warnings[0].contains("intersects itself"));
}

#[test]
fn an_open_polyline_offsets_its_ends_squarely() {
    let l = Polyline::new(vec![p(0.0, 0.0), p(2.0, 0.0), p(2.0, 2.0)]).unwrap();
    let o = offset(l, 1.0, OffsetCorners::Sharp);
    let Curve::Polyline { polyline, .. } = &o.curve else {
        panic!()
    };
    assert_eq!(polyline.points(), [p(0.0, -1.0), p(3.0, -1.0), p(3.0, 2.0)]);
}

/// The distance from the points of `offset` to `curve`, sampled.
fn distance_range(curve: &Curve, offset: &Curve) -> (f64, f64) {
    let d = offset.domain();
    let (mut lo, mut hi) = (f64::INFINITY, 0.0f64);
    for i in 0..=200 {
        let q = offset.point_at(d.parameter_at(i as f64 / 200.0));
        let dist = curve.closest_point(q).unwrap().point.distance(q);
        lo = lo.min(dist);
        hi = hi.max(dist);
    }
    (lo, hi)
}

#[test]
fn a_tilted_circle_and_an_ellipse_are_approximated() {
    let ellipse = Curve::from(Circle::new(Plane::WORLD_XY, 2.0).unwrap())
        .transformed(&Transform::from_rows([
            [2.0, 0.0, 0.0, 0.0],
            [0.0, 1.0, 0.0, 0.0],
            [0.0, 0.0, 1.0, 0.0],
            [0.0, 0.0, 0.0, 1.0],
        ]))
        .unwrap();
    let o = ellipse
        .offset(
            0.5,
            &Plane::WORLD_XY,
            OffsetCorners::Sharp,
            DOCUMENT_TOLERANCE,
        )
        .unwrap();
    assert!(o.warnings.is_empty(), "{:?}", o.warnings);
    assert!(o.curve.is_closed());
    let (lo, hi) = distance_range(&ellipse, &o.curve);
    assert!(
        lo > 0.5 - DOCUMENT_TOLERANCE && hi < 0.5 + DOCUMENT_TOLERANCE,
        "{lo} {hi}"
    );
    // Inwards beyond the smallest radius of curvature (1 at the ends of the long axis).
    let cusp = ellipse
        .offset(
            -1.5,
            &Plane::WORLD_XY,
            OffsetCorners::Sharp,
            DOCUMENT_TOLERANCE,
        )
        .unwrap();
    assert!(
        cusp.warnings
            .iter()
            .any(|w| w.contains("radius of curvature"))
    );
}

#[test]
fn kinked_curves_offset_piece_by_piece() {
    // A line then an arc leaving at a right angle, as one NURBS curve.
    let arc = Arc::new(
        Circle::new(Plane::WORLD_XY.translated(Vector3::new(2.0, 0.0, 0.0)), 1.0).unwrap(),
        Interval::new(0.0, std::f64::consts::PI),
    )
    .unwrap();
    let joined = Curve::join(
        &[
            Line::new(p(0.0, 0.0), p(1.0, 0.0)).into(),
            Curve::from(arc).reversed(),
        ],
        DOCUMENT_TOLERANCE,
        false,
    )
    .unwrap();
    assert_eq!(joined.len(), 1);
    let o = joined[0]
        .offset(
            0.25,
            &Plane::WORLD_XY,
            OffsetCorners::Round,
            DOCUMENT_TOLERANCE,
        )
        .unwrap();
    let (lo, hi) = distance_range(&joined[0], &o.curve);
    assert!(
        lo > 0.25 - DOCUMENT_TOLERANCE && hi < 0.25 + DOCUMENT_TOLERANCE,
        "{lo} {hi}"
    );
}

#[test]
fn rational_circles_and_arcs_change_radius_exactly() {
    let plane = Plane::WORLD_XY.translated(Vector3::new(1.0, -2.0, 0.0));
    let circle = Circle::new(plane, 2.0).unwrap();
    let nurbs = circle.to_nurbs();
    let o = offset(Curve::Nurbs(nurbs.clone()), 0.5, OffsetCorners::Sharp);
    assert!(o.warnings.is_empty());
    let Curve::Nurbs(c) = &o.curve else {
        panic!("{:?}", o.curve)
    };
    // Same form (knots, weights), every point exactly 2.5 from the centre at the same parameter.
    assert_eq!((c.knots(), c.weights()), (nurbs.knots(), nurbs.weights()));
    for i in 0..=40 {
        let t = nurbs.domain().parameter_at(i as f64 / 40.0);
        let radial = (nurbs.point_at(t) - plane.origin).try_normalize().unwrap();
        let want = plane.origin + radial * 2.5;
        assert!(c.point_at(t).distance(want) < 1e-14, "{t}");
    }
    // A reversed arc shrinks for a positive distance; one the offset collapses is an error.
    let arc = Arc::new(circle, Interval::new(0.5, 2.0)).unwrap();
    let reversed = Curve::Nurbs(arc.to_nurbs()).reversed();
    let o = offset(reversed.clone(), 0.5, OffsetCorners::Sharp);
    let found = o.curve.try_arc(1e-12).unwrap();
    assert!((found.radius() - 1.5).abs() < 1e-14);
    assert!(
        reversed
            .offset(2.0, &Plane::WORLD_XY, OffsetCorners::Sharp, 0.001)
            .is_err()
    );
}

#[test]
fn open_curves_are_fitted_with_their_end_tangents() {
    let curve = Curve::from(
        NurbsCurve::create(
            &[p(0.0, 0.0), p(1.0, 1.5), p(3.0, -1.0), p(4.0, 0.5)],
            3,
            false,
        )
        .unwrap(),
    );
    let tolerance = 1e-8;
    let o = curve
        .offset(0.3, &Plane::WORLD_XY, OffsetCorners::Sharp, tolerance)
        .unwrap();
    assert!(o.warnings.is_empty(), "{:?}", o.warnings);
    for (t, s) in [(0.0, 0.0), (1.0, 1.0)] {
        let (d, e) = (curve.domain(), o.curve.domain());
        let want = curve.tangent_at(d.parameter_at(t)).unwrap();
        let got = o.curve.tangent_at(e.parameter_at(s)).unwrap();
        assert!((got - want).length() < 1e-12, "{got:?} {want:?}");
    }
    let (lo, hi) = distance_range(&curve, &o.curve);
    assert!(lo > 0.3 - tolerance && hi < 0.3 + tolerance, "{lo} {hi}");
}

#[test]
fn curved_pieces_are_trimmed_where_they_cross_inside_a_kink() {
    // A lens of two arcs meeting at two kinks, offset inwards: the offset arcs are trimmed where
    // they cross, so every point of the result is at the distance from the lens (a bridging
    // line would come nearer to the kinks).
    let top = Arc::from_three_points(p(-1.0, 0.0), p(0.0, 0.5), p(1.0, 0.0)).unwrap();
    let bottom = Arc::from_three_points(p(1.0, 0.0), p(0.0, -0.5), p(-1.0, 0.0)).unwrap();
    let lens = Curve::join(
        &[
            Curve::Nurbs(top.to_nurbs()),
            Curve::Nurbs(bottom.to_nurbs()),
        ],
        DOCUMENT_TOLERANCE,
        false,
    )
    .unwrap()
    .remove(0);
    assert!(lens.is_closed());
    for corners in [OffsetCorners::Sharp, OffsetCorners::Round] {
        // The lens runs clockwise, so a positive distance moves inwards.
        let o = offset(lens.clone(), 0.1, corners);
        assert!(o.warnings.is_empty(), "{:?}", o.warnings);
        assert!(o.curve.is_closed());
        let (lo, hi) = distance_range(&lens, &o.curve);
        assert!(lo > 0.1 - 1e-9 && hi < 0.1 + 1e-9, "{corners:?}: {lo} {hi}");
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    /// A smooth planar cubic offset by a distance below its smallest radius of curvature stays
    /// at that distance everywhere, within the tolerance.
    #[test]
    fn nurbs_offsets_stay_at_the_distance(
        ys in prop::collection::vec(-1.0f64..1.0, 4),
        d in prop::sample::select(vec![-0.2f64, -0.05, 0.05, 0.2]),
    ) {
        let points: Vec<Point3> = ys.iter().enumerate().map(|(i, &y)| p(2.0 * i as f64, y)).collect();
        let curve: Curve = NurbsCurve::create(&points, 3, false).unwrap().into();
        let dom = curve.domain();
        let min_radius = (0..=400)
            .filter_map(|i| curve.curvature_at(dom.parameter_at(i as f64 / 400.0)))
            .map(|k| 1.0 / k.length().max(1e-300))
            .fold(f64::INFINITY, f64::min);
        prop_assume!(min_radius > 2.0 * d.abs());
        let o = curve.offset(d, &Plane::WORLD_XY, OffsetCorners::Sharp, DOCUMENT_TOLERANCE).unwrap();
        prop_assert!(o.warnings.is_empty(), "{:?}", o.warnings);
        // Every exact offset point lies on the result...
        for i in 0..=300 {
            let t = dom.parameter_at(i as f64 / 300.0);
            let u = curve.tangent_at(t).unwrap().cross(Vector3::Z).try_normalize().unwrap();
            let q = curve.point_at(t) + u * d;
            let on = o.curve.closest_point(q).unwrap().point.distance(q);
            prop_assert!(on <= DOCUMENT_TOLERANCE, "{on} at {t}");
        }
        // ...and every point of the result is at the distance from the curve (away from the
        // ends, where on the inside of a bend the curve's end region can be nearer).
        let od = o.curve.domain();
        for i in 0..=300 {
            let q = o.curve.point_at(od.parameter_at(i as f64 / 300.0));
            let cp = curve.closest_point(q).unwrap();
            let margin = 0.05 * dom.length();
            if cp.t > dom.t0 + margin && cp.t < dom.t1 - margin {
                let dist = cp.point.distance(q);
                prop_assert!((dist - d.abs()).abs() <= DOCUMENT_TOLERANCE, "{dist} vs {d}");
            }
        }
        prop_assert!(o.curve.start_point().distance(curve.start_point()) - d.abs() < 1e-9);
    }
}

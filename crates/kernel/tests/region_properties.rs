//! Region booleans of closed planar curves: exact areas of cases with closed forms, the
//! orientation and count of the boundaries, and, on random pairs of circles, rectangles and
//! convex polygons, the identities of areas that any correct union, intersection and
//! difference obey:
//!
//! - `|A ∪ B| + |A ∩ B| = |A| + |B|`;
//! - `|A − B| = |A| − |A ∩ B|`;
//! - the results do not depend on the direction of the input curves.
//!
//! Areas are the signed areas of the boundaries (holes run clockwise, so they subtract), by
//! Green's theorem with Gauss–Legendre quadrature.

use std::f64::consts::PI;

use locus_kernel::{Circle, Curve, Error, Line, Plane, Point3, Polyline, RegionOperation, Vector3};
use proptest::prelude::*;

const TOL: f64 = 1e-9;

/// Signed area about +z of closed curves in the world XY plane.
fn area(curves: &[Curve]) -> f64 {
    const GAUSS: [(f64, f64); 5] = [
        (0.0, 0.568_888_888_888_888_9),
        (-0.538_469_310_105_683_1, 0.478_628_670_499_366_5),
        (0.538_469_310_105_683_1, 0.478_628_670_499_366_5),
        (-0.906_179_845_938_664, 0.236_926_885_056_189_1),
        (0.906_179_845_938_664, 0.236_926_885_056_189_1),
    ];
    let mut total = 0.0;
    for c in curves {
        assert!(c.is_closed(), "an open boundary: {c:?}");
        let n = c.to_nurbs();
        for w in n.span_breaks().windows(2) {
            let panels = 16;
            let h = (w[1] - w[0]) / panels as f64;
            for k in 0..panels {
                let mid = w[0] + h * (k as f64 + 0.5);
                for (x, weight) in GAUSS {
                    let (p, d, _) = n.point_and_derivatives_at(mid + 0.5 * h * x);
                    total += 0.5 * h * weight * 0.5 * (p.x * d.y - p.y * d.x);
                }
            }
        }
    }
    total
}

fn circle(x: f64, y: f64, r: f64) -> Curve {
    Circle::from_center_normal(Point3::new(x, y, 0.0), Vector3::new(0.0, 0.0, 1.0), r)
        .unwrap()
        .into()
}

fn rectangle(x0: f64, y0: f64, x1: f64, y1: f64) -> Curve {
    polygon(&[(x0, y0), (x1, y0), (x1, y1), (x0, y1)])
}

fn polygon(corners: &[(f64, f64)]) -> Curve {
    let mut points: Vec<Point3> = corners
        .iter()
        .map(|&(x, y)| Point3::new(x, y, 0.0))
        .collect();
    points.push(points[0]);
    Polyline::new(points).unwrap().into()
}

fn boolean(a: &[Curve], b: &[Curve], op: RegionOperation) -> Vec<Curve> {
    Curve::region_boolean(a, b, op, &Plane::WORLD_XY, TOL).unwrap()
}

fn union(a: &[Curve]) -> Vec<Curve> {
    boolean(a, &[], RegionOperation::Union)
}

#[test]
fn overlapping_squares_have_exact_areas() {
    let a = rectangle(0.0, 0.0, 1.0, 1.0);
    let b = rectangle(0.5, 0.25, 1.5, 1.25);
    let u = union(&[a.clone(), b.clone()]);
    assert_eq!(u.len(), 1);
    assert!((area(&u) - 1.625).abs() < 1e-12);
    let i = boolean(
        std::slice::from_ref(&a),
        std::slice::from_ref(&b),
        RegionOperation::Intersection,
    );
    assert_eq!(i.len(), 1);
    assert!((area(&i) - 0.375).abs() < 1e-12);
    let d = boolean(&[a], &[b], RegionOperation::Difference);
    assert_eq!(d.len(), 1);
    assert!((area(&d) - 0.625).abs() < 1e-12);
}

#[test]
fn two_circles_have_the_lens_area() {
    let (r, d) = (1.0f64, 1.0f64);
    let lens = 2.0 * r * r * (d / (2.0 * r)).acos() - 0.5 * d * (4.0 * r * r - d * d).sqrt();
    let a = circle(0.0, 0.0, r);
    let b = circle(d, 0.0, r);
    let u = union(&[a.clone(), b.clone()]);
    assert_eq!(u.len(), 1);
    assert!((area(&u) - (2.0 * PI - lens)).abs() < 1e-9, "{}", area(&u));
    let i = boolean(
        std::slice::from_ref(&a),
        std::slice::from_ref(&b),
        RegionOperation::Intersection,
    );
    assert!((area(&i) - lens).abs() < 1e-9);
    let d = boolean(&[a], &[b], RegionOperation::Difference);
    assert!((area(&d) - (PI - lens)).abs() < 1e-9);
}

#[test]
fn a_difference_inside_leaves_a_hole_that_runs_clockwise() {
    let d = boolean(
        &[circle(0.0, 0.0, 2.0)],
        &[circle(0.5, 0.0, 1.0)],
        RegionOperation::Difference,
    );
    assert_eq!(d.len(), 2);
    let mut signs: Vec<f64> = d.iter().map(|c| area(std::slice::from_ref(c))).collect();
    signs.sort_by(f64::total_cmp);
    assert!((signs[0] + PI).abs() < 1e-9 && (signs[1] - 4.0 * PI).abs() < 1e-9);
    // The hole is kept by an intersection with a region around it and by a union with a
    // disjoint curve.
    let u = union(&[circle(0.0, 0.0, 1.0), circle(5.0, 0.0, 1.0)]);
    assert_eq!(u.len(), 2);
    assert!((area(&u) - 2.0 * PI).abs() < 1e-9);
}

#[test]
fn shared_and_identical_edges_are_resolved() {
    // Squares sharing an edge merge into one rectangle.
    let u = union(&[rectangle(0.0, 0.0, 1.0, 1.0), rectangle(1.0, 0.0, 2.0, 1.0)]);
    assert_eq!(u.len(), 1, "{u:?}");
    assert!((area(&u) - 2.0).abs() < 1e-12);
    // A square with itself is itself, whichever way each runs.
    let s = rectangle(0.0, 0.0, 1.0, 1.0);
    let u = union(&[s.clone(), s.reversed()]);
    assert_eq!(u.len(), 1);
    assert!((area(&u) - 1.0).abs() < 1e-12);
    // Minus itself it is nothing; squares touching along an edge have no intersection.
    assert!(
        boolean(
            std::slice::from_ref(&s),
            std::slice::from_ref(&s),
            RegionOperation::Difference
        )
        .is_empty()
    );
    let side = rectangle(1.0, 0.0, 2.0, 1.0);
    assert!(boolean(&[s], &[side], RegionOperation::Intersection).is_empty());
    // A square half inside another along part of an edge.
    let u = union(&[rectangle(0.0, 0.0, 2.0, 2.0), rectangle(1.0, 0.5, 3.0, 1.5)]);
    assert_eq!(u.len(), 1);
    assert!((area(&u) - 5.0).abs() < 1e-12);
}

#[test]
fn curves_off_the_plane_are_projected_onto_it() {
    let lifted = circle(0.0, 0.0, 1.0)
        .transformed(&locus_kernel::Transform::translation(Vector3::new(
            0.0, 0.0, 3.0,
        )))
        .unwrap();
    let u = union(&[lifted, circle(1.0, 0.0, 1.0)]);
    assert_eq!(u.len(), 1);
    assert!(u[0].to_nurbs().points().iter().all(|p| p.z.abs() < 1e-12));
}

#[test]
fn bad_curves_are_named() {
    let open: Curve = Line::new(Point3::ORIGIN, Point3::new(1.0, 0.0, 0.0)).into();
    let e = Curve::region_boolean(
        &[circle(0.0, 0.0, 1.0)],
        &[circle(0.0, 0.0, 2.0), open],
        RegionOperation::Difference,
        &Plane::WORLD_XY,
        TOL,
    )
    .unwrap_err();
    assert!(
        matches!(&e, Error::InvalidInput(m) if m.contains("curve 1 of B")),
        "{e}"
    );
    // A circle standing upright on the plane bounds nothing there.
    let upright: Curve = Circle::new(Plane::WORLD_ZX, 1.0).unwrap().into();
    let e = Curve::region_boolean(
        &[upright],
        &[],
        RegionOperation::Union,
        &Plane::WORLD_XY,
        TOL,
    )
    .unwrap_err();
    assert!(e.to_string().contains("curve 0 of A"), "{e}");
    assert!(
        Curve::region_boolean(&[], &[], RegionOperation::Union, &Plane::WORLD_XY, f64::NAN)
            .is_err()
    );
}

/// A random circle, rectangle or convex polygon about the unit square.
fn arb_region() -> impl Strategy<Value = Curve> {
    prop_oneof![
        (-1.0f64..1.0, -1.0f64..1.0, 0.2f64..1.5).prop_map(|(x, y, r)| circle(x, y, r)),
        (-1.5f64..0.5, -1.5f64..0.5, 0.3f64..2.0, 0.3f64..2.0).prop_map(|(x, y, w, h)| rectangle(
            x,
            y,
            x + w,
            y + h
        )),
        (
            -1.0f64..1.0,
            -1.0f64..1.0,
            prop::collection::vec((0.0f64..1.0, 0.3f64..1.5), 3..8)
        )
            .prop_map(|(x, y, mut spokes)| {
                // Corners on a circle at sorted angles make a convex polygon.
                spokes.sort_by(|a, b| a.0.total_cmp(&b.0));
                let r = spokes[0].1;
                let corners: Vec<(f64, f64)> = spokes
                    .iter()
                    .map(|&(a, _)| {
                        let t = 2.0 * PI * a;
                        (x + r * t.cos(), y + r * t.sin())
                    })
                    .collect();
                polygon(&corners)
            }),
    ]
}

fn degenerate(c: &Curve) -> bool {
    // Polygons whose corners nearly coincide bound next to nothing.
    area(std::slice::from_ref(c)).abs() < 1e-3
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn areas_obey_inclusion_exclusion(a in arb_region(), b in arb_region(), flip in any::<bool>()) {
        prop_assume!(!degenerate(&a) && !degenerate(&b));
        let b = if flip { b.reversed() } else { b };
        let area_a = area(&union(std::slice::from_ref(&a)));
        let area_b = area(&union(std::slice::from_ref(&b)));
        prop_assert!(area_a > 0.0 && area_b > 0.0);
        let u = area(&union(&[a.clone(), b.clone()]));
        let i = area(&boolean(std::slice::from_ref(&a), std::slice::from_ref(&b), RegionOperation::Intersection));
        let d = area(&boolean(std::slice::from_ref(&a), std::slice::from_ref(&b), RegionOperation::Difference));
        let scale = area_a + area_b;
        prop_assert!((u + i - area_a - area_b).abs() < 1e-7 * scale, "u {u} i {i} a {area_a} b {area_b}");
        prop_assert!((d - (area_a - i)).abs() < 1e-7 * scale, "d {d} i {i} a {area_a}");
        prop_assert!(i >= -1e-9 && d >= -1e-9 && u >= area_a.max(area_b) - 1e-7 * scale);
    }
}

/// A rectangle on a half-unit grid: pairs share edges, corners and stretches of edges.
fn arb_grid_rectangle() -> impl Strategy<Value = Curve> {
    (0u8..4, 0u8..4, 1u8..4, 1u8..4, any::<bool>()).prop_map(|(x, y, w, h, flip)| {
        let g = |k: u8| f64::from(k) * 0.5;
        let r = rectangle(g(x), g(y), g(x + w), g(y + h));
        if flip { r.reversed() } else { r }
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn grid_rectangles_obey_inclusion_exclusion(a in arb_grid_rectangle(), b in arb_grid_rectangle()) {
        let area_a = area(&union(std::slice::from_ref(&a)));
        let area_b = area(&union(std::slice::from_ref(&b)));
        let u = area(&union(&[a.clone(), b.clone()]));
        let i = area(&boolean(std::slice::from_ref(&a), std::slice::from_ref(&b), RegionOperation::Intersection));
        let d = area(&boolean(std::slice::from_ref(&a), std::slice::from_ref(&b), RegionOperation::Difference));
        prop_assert!((u + i - area_a - area_b).abs() < 1e-12, "u {u} i {i} a {area_a} b {area_b}");
        prop_assert!((d - (area_a - i)).abs() < 1e-12, "d {d} i {i} a {area_a}");
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(32))]

    /// A set of several curves is the union of their regions:
    /// `|A ∪ B ∪ C| = |A ∪ B| + |C| − |(A ∪ B) ∩ C|`.
    #[test]
    fn sets_of_curves_are_unions(a in arb_region(), b in arb_region(), c in arb_region()) {
        prop_assume!(!degenerate(&a) && !degenerate(&b) && !degenerate(&c));
        let all = area(&union(&[a.clone(), b.clone(), c.clone()]));
        let ab = area(&union(&[a.clone(), b.clone()]));
        let area_c = area(&union(std::slice::from_ref(&c)));
        let abc = area(&boolean(&[a, b], std::slice::from_ref(&c), RegionOperation::Intersection));
        prop_assert!((all - (ab + area_c - abc)).abs() < 1e-7 * (ab + area_c), "{all} {ab} {area_c} {abc}");
    }
}

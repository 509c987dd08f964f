//! Property tests of Vector and Transform nodes run through the runtime: inverses undo, shears
//! move the grip onto the target, angles in a plane add up to a full turn, cross products are
//! perpendicular, planes pass through their points and pulled points lie on what pulled them.

use std::f64::consts::TAU;

use locus_kernel::{Interval, OrientedBox, Plane, Point3, Transform, Vector3};
use locus_nodes::transform::{affine, euclidean, util};
use locus_nodes::vector::{plane, products, pull};
use locus_runtime::{DataTree, NodeCall, NodeCallResult, NodeType, Value};
use proptest::prelude::*;

fn coordinate() -> impl Strategy<Value = f64> {
    -100.0..100.0f64
}

fn point() -> impl Strategy<Value = Point3> {
    (coordinate(), coordinate(), coordinate()).prop_map(|(x, y, z)| Point3::new(x, y, z))
}

/// Vectors of length 0.1 to about 1.7, in every direction.
fn direction() -> impl Strategy<Value = Vector3> {
    (-1.0..1.0f64, -1.0..1.0f64, -1.0..1.0f64)
        .prop_map(|(x, y, z)| Vector3::new(x, y, z))
        .prop_filter("not too short", |v| v.length() > 0.1)
}

fn a_plane() -> impl Strategy<Value = Plane> {
    (point(), direction()).prop_map(|(origin, normal)| {
        Plane::from_normal(origin, normal).expect("a non-zero normal gives a plane")
    })
}

fn run(node: &NodeType, inputs: Vec<DataTree>) -> NodeCallResult {
    let mut call = NodeCall::new(node);
    for input in inputs {
        call = call.input(input);
    }
    call.run()
}

fn only(result: &NodeCallResult, output: usize) -> Value {
    let values: Vec<Option<Value>> = result.outputs[output].values().collect();
    assert_eq!(values.len(), 1, "messages: {:?}", result.messages);
    values[0].clone().expect("a value")
}

fn point_of(v: Value) -> Point3 {
    match v {
        Value::Point(p) => p,
        other => panic!("expected a point, got {other:?}"),
    }
}

fn number_of(v: Value) -> f64 {
    match v {
        Value::Number(x) => x,
        other => panic!("expected a number, got {other:?}"),
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn inverse_transform_undoes_rotate_3d(
        p in point(), angle in -10.0..10.0f64, center in point(), axis in direction(),
    ) {
        let r = run(&euclidean::rotate_3d(), vec![
            DataTree::from_item(p),
            DataTree::from_item(angle),
            DataTree::from_item(center),
            DataTree::from_item(axis),
        ]);
        let moved = only(&r, 0);
        let Value::Transform(x) = only(&r, 1) else { panic!("expected a transform") };
        let inverse = run(&util::inverse_transform(), vec![DataTree::from_item(x)]);
        let Value::Transform(y) = only(&inverse, 0) else { panic!("expected a transform") };
        let back = run(&util::transform(), vec![
            DataTree::from_value(moved),
            DataTree::from_item(y),
        ]);
        prop_assert!(point_of(only(&back, 0)).abs_diff_eq(p, 1e-12));
    }

    #[test]
    fn compound_of_a_transform_and_its_inverse_is_the_identity(
        plane in a_plane(), x in 0.1..5.0f64, y in 0.1..5.0f64, z in 0.1..5.0f64,
    ) {
        let t = Transform::scale_non_uniform(&plane, x, y, z);
        let inverse = run(&util::inverse_transform(), vec![DataTree::from_item(t)]);
        let Value::Transform(u) = only(&inverse, 0) else { panic!("expected a transform") };
        let r = run(&util::compound(), vec![DataTree::from_list(vec![t, u])]);
        let Value::Transform(c) = only(&r, 0) else { panic!("expected a transform") };
        prop_assert!(c.is_identity(1e-12), "{:?}", c.to_rows());
    }

    #[test]
    fn shear_moves_the_grip_onto_the_target(
        plane in a_plane(), u in -10.0..10.0f64, v in -10.0..10.0f64,
        h in prop_oneof![-10.0..-0.1f64, 0.1..10.0f64], motion in direction(),
        q in point(),
    ) {
        let grip = plane.point_at(u, v, h);
        let target = grip + motion * 5.0;
        let r = run(&affine::shear(), vec![
            DataTree::from_list(vec![Value::Point(grip), Value::Point(plane.closest_point(q))]),
            DataTree::from_item(plane),
            DataTree::from_item(grip),
            DataTree::from_item(target),
        ]);
        let out: Vec<Option<Value>> = r.outputs[0].values().collect();
        let g = point_of(out[0].clone().expect("the grip"));
        prop_assert!(g.abs_diff_eq(target, 1e-9), "{g:?} vs {target:?}");
        // Points of the base plane stay where they are.
        let on_plane = point_of(out[1].clone().expect("the point on the plane"));
        prop_assert!(on_plane.abs_diff_eq(plane.closest_point(q), 1e-9));
    }

    #[test]
    fn angles_in_a_plane_add_up_to_a_full_turn(
        a in direction(), b in direction(), plane in a_plane(),
    ) {
        let n = plane.normal();
        let pa = a - n * a.dot(n);
        let pb = b - n * b.dot(n);
        prop_assume!(pa.length() > 1e-3 && pb.length() > 1e-3);
        prop_assume!(pa.cross(pb).length() > 1e-6 * pa.length() * pb.length());
        let ab = run(&products::angle(), vec![
            DataTree::from_item(a), DataTree::from_item(b), DataTree::from_item(plane),
        ]);
        let ba = run(&products::angle(), vec![
            DataTree::from_item(b), DataTree::from_item(a), DataTree::from_item(plane),
        ]);
        let (x, y) = (number_of(only(&ab, 0)), number_of(only(&ba, 0)));
        prop_assert!((x + y - TAU).abs() < 1e-12);
        // The reflex output is the other way round.
        prop_assert!((number_of(only(&ab, 1)) - y).abs() < 1e-12);
    }

    #[test]
    fn cross_products_are_perpendicular_with_the_sine_length(a in direction(), b in direction()) {
        let r = run(&products::cross_product(), vec![DataTree::from_item(a), DataTree::from_item(b)]);
        let Value::Vector(c) = only(&r, 0) else { panic!("expected a vector") };
        let length = number_of(only(&r, 1));
        prop_assert!(c.dot(a).abs() < 1e-12 && c.dot(b).abs() < 1e-12);
        let angle = a.angle_to(b).unwrap();
        prop_assert!((length - a.length() * b.length() * angle.sin()).abs() < 1e-12);
    }

    #[test]
    fn plane_3pt_passes_through_its_points(a in point(), b in point(), c in point()) {
        let r = run(&plane::plane_3pt(), vec![
            DataTree::from_item(a), DataTree::from_item(b), DataTree::from_item(c),
        ]);
        let values: Vec<Option<Value>> = r.outputs[0].values().collect();
        match &values[0] {
            Some(Value::Plane(p)) => {
                prop_assert!(p.is_valid());
                prop_assert_eq!(p.origin, a);
                let scale = 1.0 + a.distance(b).max(a.distance(c));
                prop_assert!(p.distance_to(b) < 1e-12 * scale);
                prop_assert!(p.distance_to(c) < 1e-12 * scale);
            }
            // Nearly collinear triples are rejected with an error, never a panic.
            None => prop_assert_eq!(r.messages.len(), 1),
            other => prop_assert!(false, "unexpected {:?}", other),
        }
    }

    #[test]
    fn pulled_points_lie_on_the_box(
        plane in a_plane(), p in point(), sx in 1.0..50.0f64, sy in 1.0..50.0f64, sz in 1.0..50.0f64,
    ) {
        let b = OrientedBox::new(
            plane,
            Interval::new(-sx, sx),
            Interval::new(-sy, sy),
            Interval::new(-sz, sz),
        );
        let r = run(&pull::pull_point(), vec![
            DataTree::from_item(p),
            DataTree::from_list(vec![Value::Box(b)]),
        ]);
        let q = point_of(only(&r, 0));
        let [u, v, w] = plane.local_coordinates(q);
        let on = |t: f64, s: f64| (t.abs() - s).abs() < 1e-9;
        prop_assert!(b.contains_point(q, 1e-9));
        prop_assert!(on(u, sx) || on(v, sy) || on(w, sz));
        prop_assert!((number_of(only(&r, 1)) - q.distance(p)).abs() < 1e-12);
    }
}

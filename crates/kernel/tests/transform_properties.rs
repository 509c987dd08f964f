//! Property tests for vectors, planes, boxes and transforms: inverses undo transforms,
//! rotations preserve lengths, mirrors are involutions, and the derived types stay valid.

use std::f64::consts::PI;

use locus_kernel::{
    BoundingBox, Interval, OrientedBox, Plane, Point3, Transform, Vector3, perpendicular_to,
};
use proptest::prelude::*;

fn coordinate() -> impl Strategy<Value = f64> {
    -100.0..100.0f64
}

fn point() -> impl Strategy<Value = Point3> {
    (coordinate(), coordinate(), coordinate()).prop_map(|(x, y, z)| Point3::new(x, y, z))
}

/// Vectors of length at least 1e-3, in every direction.
fn direction() -> impl Strategy<Value = Vector3> {
    (-1.0..1.0f64, -1.0..1.0f64, -1.0..1.0f64)
        .prop_map(|(x, y, z)| Vector3::new(x, y, z))
        .prop_filter("non-zero direction", |v| v.length() > 1e-3)
}

fn plane() -> impl Strategy<Value = Plane> {
    (point(), direction()).prop_map(|(origin, normal)| {
        Plane::from_normal(origin, normal).expect("a non-zero normal gives a plane")
    })
}

/// Non-zero scale factors of either sign, from 0.1 to 10 in magnitude.
fn factor() -> impl Strategy<Value = f64> {
    (0.1..10.0f64, any::<bool>()).prop_map(|(f, negative)| if negative { -f } else { f })
}

/// One invertible elementary transform of every kind the kernel builds.
fn elementary() -> impl Strategy<Value = Transform> {
    prop_oneof![
        direction().prop_map(|v| Transform::translation(v * 50.0)),
        (-10.0..10.0f64, direction(), point())
            .prop_map(|(angle, axis, center)| Transform::rotation(angle, axis, center).unwrap()),
        (point(), factor()).prop_map(|(center, f)| Transform::scale(center, f)),
        (plane(), factor(), factor(), factor())
            .prop_map(|(plane, x, y, z)| Transform::scale_non_uniform(&plane, x, y, z)),
        (plane(), -3.0..3.0f64, -3.0..3.0f64).prop_map(|(plane, a, b)| {
            Transform::shear(
                &plane,
                plane.x_axis,
                plane.y_axis,
                plane.z_axis + plane.x_axis * a + plane.y_axis * b,
            )
        }),
        plane().prop_map(|plane| Transform::mirror(&plane)),
        (plane(), plane()).prop_map(|(from, to)| Transform::plane_to_plane(&from, &to)),
    ]
}

/// Compositions of one to four elementary transforms.
fn invertible() -> impl Strategy<Value = Transform> {
    prop::collection::vec(elementary(), 1..=4).prop_map(|parts| {
        parts
            .into_iter()
            .fold(Transform::IDENTITY, |acc, t| t * acc)
    })
}

/// The largest absolute entry of a matrix.
fn scale_of(t: &Transform) -> f64 {
    t.to_rows()
        .iter()
        .flatten()
        .fold(0.0f64, |m, x| m.max(x.abs()))
}

proptest! {
    #[test]
    fn transform_times_inverse_is_identity(t in invertible(), p in point()) {
        let inverse = t.inverse().expect("compositions of invertible transforms invert");
        // The error of an inverse grows with the condition number, bounded here by the
        // product of the entry scales.
        let tol = 1e-12 * scale_of(&t) * scale_of(&inverse);
        prop_assert!((t * inverse).is_identity(tol), "{:?}", (t * inverse).to_rows());
        prop_assert!((inverse * t).is_identity(tol), "{:?}", (inverse * t).to_rows());
        let image = t.transform_point(p);
        let back = inverse.transform_point(image);
        let size = 1.0 + p.to_vector().length() + image.to_vector().length();
        prop_assert!(back.distance(p) <= 1e-12 * size * scale_of(&t) * scale_of(&inverse));
    }

    #[test]
    fn rotation_preserves_lengths_and_distances(
        angle in -10.0..10.0f64,
        axis in direction(),
        center in point(),
        v in direction(),
        a in point(),
        b in point(),
    ) {
        let r = Transform::rotation(angle, axis, center).unwrap();
        prop_assert!((r.transform_vector(v).length() - v.length()).abs() <= 1e-14);
        let d = a.distance(b);
        let rotated = r.transform_point(a).distance(r.transform_point(b));
        prop_assert!((rotated - d).abs() <= 1e-12 * (1.0 + d));
        prop_assert!((r.linear_determinant() - 1.0).abs() <= 1e-14);
        prop_assert!(r.is_similarity(1e-12));
        // The axis through the centre is fixed.
        let on_axis = center + axis * 3.0;
        prop_assert!(r.transform_point(on_axis).distance(on_axis) <= 1e-12);
    }

    #[test]
    fn mirror_twice_is_identity(plane in plane(), p in point()) {
        let m = Transform::mirror(&plane);
        prop_assert!((m * m).is_identity(1e-12), "{:?}", (m * m).to_rows());
        let image = m.transform_point(p);
        prop_assert!(m.transform_point(image).distance(p) <= 1e-12);
        prop_assert!(
            (plane.signed_distance_to(image) + plane.signed_distance_to(p)).abs() <= 1e-12
        );
        prop_assert!((m.linear_determinant() + 1.0).abs() <= 1e-14);
    }

    #[test]
    fn planar_projection_is_idempotent_and_singular(plane in plane(), p in point()) {
        let proj = Transform::planar_projection(&plane);
        let once = proj.transform_point(p);
        prop_assert!(plane.distance_to(once) <= 1e-12);
        prop_assert!(proj.transform_point(once).distance(once) <= 1e-12);
        prop_assert!(proj.inverse().is_err());
    }

    #[test]
    fn transformed_planes_stay_orthonormal(plane in plane(), t in invertible()) {
        let moved = plane.transformed(&t).expect("invertible transforms keep planes");
        prop_assert!(moved.is_valid(), "{moved:?}");
        prop_assert!(moved.origin.distance(t.transform_point(plane.origin)) <= 1e-12 * scale_of(&t) * 200.0);
    }

    #[test]
    fn plane_to_plane_maps_frames(from in plane(), to in plane(), u in coordinate(), v in coordinate()) {
        let orient = Transform::plane_to_plane(&from, &to);
        let image = orient.transform_point(from.point_at(u, v, 0.5));
        prop_assert!(image.distance(to.point_at(u, v, 0.5)) <= 1e-12);
    }

    #[test]
    fn perpendicular_is_exactly_orthogonal(v in direction()) {
        prop_assert_eq!(perpendicular_to(v).dot(v), 0.0);
        let plane = Plane::from_normal(Point3::ORIGIN, v).unwrap();
        prop_assert!(plane.is_valid());
    }

    #[test]
    fn angles_are_symmetric_and_in_range(a in direction(), b in direction(), n in direction()) {
        let angle = a.angle_to(b).unwrap();
        prop_assert!((0.0..=PI).contains(&angle));
        prop_assert_eq!(angle, b.angle_to(a).unwrap());
        if let (Ok(ab), Ok(ba)) = (a.signed_angle_to(b, n), b.signed_angle_to(a, n)) {
            prop_assert!(ab > -PI && ab <= PI);
            // Antisymmetric, except that a half turn is +π both ways.
            prop_assert!((ab + ba).abs() <= 1e-12 || (ab - PI).abs() <= 1e-12);
            let full = a.angle_in_plane(b, n).unwrap();
            prop_assert!((0.0..2.0 * PI).contains(&full));
        }
    }

    #[test]
    fn transformed_bounding_box_contains_transformed_points(
        a in point(),
        b in point(),
        s in (0.0..1.0f64, 0.0..1.0f64, 0.0..1.0f64),
        t in invertible(),
    ) {
        let bbox = BoundingBox::new(a, b);
        let inside = bbox.point_at(s.0, s.1, s.2);
        let moved = bbox.transformed(&t);
        let tol = 1e-12 * scale_of(&t) * 400.0;
        prop_assert!(moved.inflated(tol).contains_point(t.transform_point(inside)));
    }

    #[test]
    fn transformed_oriented_box_keeps_similar_boxes(
        plane in plane(),
        x in 0.1..10.0f64,
        y in 0.1..10.0f64,
        z in 0.1..10.0f64,
        angle in -10.0..10.0f64,
        axis in direction(),
        f in factor(),
        center in point(),
    ) {
        let bx = OrientedBox::new(plane, Interval::new(0.0, x), Interval::new(-y, 0.0), Interval::new(1.0, 1.0 + z));
        let t = Transform::rotation(angle, axis, center).unwrap() * Transform::scale(center, f);
        let moved = bx.transformed(&t).unwrap();
        let volume = bx.volume() * f.abs().powi(3);
        prop_assert!((moved.volume() - volume).abs() <= 1e-9 * volume);
        let mut corners = bx.corners();
        t.transform_points(&mut corners);
        for c in corners {
            prop_assert!(moved.contains_point(c, 1e-9 * (1.0 + c.to_vector().length())));
        }
    }
}

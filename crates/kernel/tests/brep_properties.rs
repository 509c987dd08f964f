//! Property tests for B-reps: exact box measures, round solids against their formulas,
//! planar polygons against the shoelace formula, and invariance under rigid motions.

use std::f64::consts::{PI, TAU};

use locus_kernel::{
    Brep, Cone, Cylinder, EdgeKind, Interval, OrientedBox, Plane, Point3, Sphere, Transform,
    Vector3,
};
use proptest::prelude::*;

fn point() -> impl Strategy<Value = Point3> {
    (-50.0..50.0f64, -50.0..50.0f64, -50.0..50.0f64).prop_map(|(x, y, z)| Point3::new(x, y, z))
}

fn plane() -> impl Strategy<Value = Plane> {
    (point(), -1.0..1.0f64, -1.0..1.0f64, -1.0..1.0f64)
        .prop_filter_map("normal too short", |(o, x, y, z)| {
            Plane::from_normal(o, Vector3::new(x, y, z + 0.01)).ok()
        })
}

fn interval() -> impl Strategy<Value = Interval> {
    (-10.0..10.0f64, 0.1..10.0f64, any::<bool>()).prop_map(|(a, len, flip)| {
        if flip {
            Interval::new(a + len, a)
        } else {
            Interval::new(a, a + len)
        }
    })
}

fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    #[test]
    fn box_area_and_volume_are_exact(plane in plane(), x in interval(), y in interval(), z in interval()) {
        let ob = OrientedBox::new(plane, x, y, z);
        let b = Brep::from_box(&ob).unwrap();
        prop_assert_eq!((b.faces().len(), b.edges().len(), b.vertices().len()), (6, 12, 8));
        prop_assert!(b.is_solid());
        prop_assert_eq!(b.edges_of_kind(EdgeKind::Interior).len(), 12);
        let [a, bb, c] = ob.sizes();
        let area = b.area_properties().unwrap();
        let volume = b.volume_properties().unwrap();
        prop_assert!(rel(area.area, 2.0 * (a * bb + bb * c + c * a)) < 1e-13, "area {}", area.area);
        prop_assert!(rel(volume.volume, a * bb * c) < 1e-13, "volume {}", volume.volume);
        prop_assert!(area.centroid.distance(ob.center()) < 1e-11);
        prop_assert!(volume.centroid.distance(ob.center()) < 1e-11);
        let bbox = b.bounding_box();
        let expected = ob.bounding_box();
        prop_assert!(bbox.min.distance(expected.min) < 1e-12 && bbox.max.distance(expected.max) < 1e-12);
    }

}

proptest! {
    // Each case integrates three curved solids twice; fewer cases keep the suite quick.
    #![proptest_config(ProptestConfig::with_cases(12))]

    #[test]
    fn round_solids_match_their_formulas(plane in plane(), r in 0.2..5.0f64, h in 0.2..8.0f64, below in any::<bool>()) {
        let h = if below { -h } else { h };
        let sphere = Sphere::from_plane(plane, r).unwrap();
        let s = Brep::from_sphere(&sphere).unwrap();
        prop_assert!(rel(s.area().unwrap(), sphere.area()) < 1e-11);
        let sv = s.volume_properties().unwrap();
        prop_assert!(rel(sv.volume, sphere.volume()) < 1e-11);
        prop_assert!(sv.centroid.distance(plane.origin) < 1e-10 * (1.0 + r));

        let cylinder = Cylinder::new(plane, r, h).unwrap();
        let c = Brep::from_cylinder(&cylinder, true).unwrap();
        prop_assert!(rel(c.area().unwrap(), cylinder.lateral_area() + 2.0 * PI * r * r) < 1e-11);
        prop_assert!(rel(c.volume().unwrap(), cylinder.volume()) < 1e-11);

        let cone = Cone::new(plane, h, r).unwrap();
        let k = Brep::from_cone(&cone, true).unwrap();
        prop_assert!(rel(k.area().unwrap(), cone.lateral_area() + PI * r * r) < 1e-11);
        let kv = k.volume_properties().unwrap();
        prop_assert!(rel(kv.volume, cone.volume()) < 1e-11);
        let centroid = plane.origin + plane.z_axis * (0.75 * h);
        prop_assert!(kv.centroid.distance(centroid) < 1e-10 * (1.0 + r + h.abs()));
    }

}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(32))]

    #[test]
    fn regular_polygon_area_is_exact(plane in plane(), n in 3usize..40, r in 0.1..20.0f64, phase in 0.0..TAU) {
        let points: Vec<Point3> = (0..n)
            .map(|k| {
                let a = phase + TAU * k as f64 / n as f64;
                plane.point_at(r * a.cos(), r * a.sin(), 0.0)
            })
            .collect();
        let b = Brep::from_planar_polyline(&points, 1e-9).unwrap();
        let props = b.area_properties().unwrap();
        let exact = 0.5 * n as f64 * r * r * (TAU / n as f64).sin();
        prop_assert!(rel(props.area, exact) < 1e-12, "{} vs {exact}", props.area);
        prop_assert!(props.centroid.distance(plane.origin) < 1e-11 * (1.0 + r));
        prop_assert_eq!(b.edges_of_kind(EdgeKind::Naked).len(), n);
    }

    #[test]
    fn rigid_motions_keep_measures(
        angle in 0.0..TAU,
        axis in (-1.0..1.0f64, -1.0..1.0f64, 0.1..1.0f64),
        shift in point(),
    ) {
        let axis = Vector3::new(axis.0, axis.1, axis.2);
        let motion = Transform::translation(shift.to_vector())
            * Transform::rotation(angle, axis, Point3::ORIGIN).unwrap();
        let b = Brep::from_cylinder(&Cylinder::new(Plane::WORLD_XY, 1.5, 3.0).unwrap(), true).unwrap();
        let moved = b.transformed(&motion).unwrap();
        let (v0, v1) = (b.volume_properties().unwrap(), moved.volume_properties().unwrap());
        prop_assert!(rel(v1.volume, v0.volume) < 1e-11);
        prop_assert!(v1.centroid.distance(motion.transform_point(v0.centroid)) < 1e-10);
        prop_assert!(rel(moved.area().unwrap(), b.area().unwrap()) < 1e-11);
    }
}

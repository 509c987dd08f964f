//! locus's own geometry written and read back: B-reps of every kernel constructor keep their
//! topology, and their geometry within the rounding of homogeneous storage.

#[path = "common/describe.rs"]
#[allow(dead_code)]
mod describe;

use locus_kernel::{Brep, Cone, Cylinder, Interval, OrientedBox, Plane, Point3, Sphere};
use locus_opennurbs_archive::{Geometry, decode, decode_json, encode, encode_json};

fn breps() -> Vec<(&'static str, Brep)> {
    let plane = Plane::from_frame(
        Point3::new(1.0, 2.0, 3.0),
        locus_kernel::Vector3::new(1.0, 1.0, 0.0),
        locus_kernel::Vector3::new(0.0, 1.0, 1.0),
    )
    .unwrap();
    vec![
        (
            "box",
            Brep::from_box(&OrientedBox::new(
                plane,
                Interval::new(0.0, 1.0),
                Interval::new(-1.0, 2.0),
                Interval::new(0.5, 3.0),
            ))
            .unwrap(),
        ),
        (
            "sphere",
            Brep::from_sphere(&Sphere::new(Point3::new(1.0, 2.0, 3.0), 2.0).unwrap()).unwrap(),
        ),
        (
            "cylinder",
            Brep::from_cylinder(&Cylinder::new(plane, 1.5, 4.0).unwrap(), true).unwrap(),
        ),
        (
            "cone",
            Brep::from_cone(&Cone::new(plane, 3.0, 1.0).unwrap(), true).unwrap(),
        ),
        (
            "face with a hole",
            Brep::from_planar_polylines(
                &[
                    Point3::new(0.0, 0.0, 0.0),
                    Point3::new(4.0, 0.0, 0.0),
                    Point3::new(5.0, 3.0, 0.0),
                    Point3::new(0.0, 3.0, 0.0),
                ],
                &[vec![
                    Point3::new(1.0, 1.0, 0.0),
                    Point3::new(2.0, 1.0, 0.0),
                    Point3::new(2.0, 2.0, 0.0),
                    Point3::new(1.0, 2.0, 0.0),
                ]],
                1e-9,
            )
            .unwrap(),
        ),
    ]
}

#[test]
fn breps_round_trip_with_their_topology_area_and_volume() {
    for (name, b) in breps() {
        let g = Geometry::Brep(b.clone());
        let back = decode_json(&encode_json(&g).unwrap()).unwrap_or_else(|e| panic!("{name}: {e}"));
        let Geometry::Brep(c) = &back else {
            panic!("{name}: {back:?}")
        };
        assert_eq!(
            (
                c.faces().len(),
                c.loops().len(),
                c.trims().len(),
                c.edges().len(),
                c.vertices().len()
            ),
            (
                b.faces().len(),
                b.loops().len(),
                b.trims().len(),
                b.edges().len(),
                b.vertices().len()
            ),
            "{name}"
        );
        for (t, u) in b.trims().iter().zip(c.trims()) {
            assert_eq!(
                (t.edge, t.reversed, t.kind, t.loop_index, t.vertices),
                (u.edge, u.reversed, u.kind, u.loop_index, u.vertices),
                "{name}"
            );
        }
        assert_eq!(c.is_solid(), b.is_solid(), "{name}");
        let (a, a2) = (b.area().unwrap(), c.area().unwrap());
        assert!((a - a2).abs() <= 1e-12 * a, "{name}: area {a} != {a2}");
        if b.is_solid() {
            let (v, v2) = (b.volume().unwrap(), c.volume().unwrap());
            assert!(
                (v - v2).abs() <= 1e-12 * v.abs(),
                "{name}: volume {v} != {v2}"
            );
        }
        // Written again, the bytes are the same: reading loses nothing that writing keeps.
        assert_eq!(
            encode(&back).unwrap().len(),
            encode(&g).unwrap().len(),
            "{name}"
        );
        let _ = describe::describe(&back);
    }
}

#[test]
fn a_brep_with_a_dangling_index_is_an_error_not_a_panic() {
    let g = Geometry::Brep(breps().remove(0).1);
    let bytes = encode(&g).unwrap();
    // Every 4-byte window set to a large index: decoding fails or succeeds, never panics.
    let mut failures = 0;
    for at in (0..bytes.len() - 4).step_by(7) {
        let mut b = bytes.clone();
        b[at..at + 4].copy_from_slice(&1000i32.to_le_bytes());
        if decode(&b).is_err() {
            failures += 1;
        }
    }
    assert!(failures > 0);
}

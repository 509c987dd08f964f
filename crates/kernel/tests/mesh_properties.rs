//! Property tests for tessellation: meshes of closed B-reps are closed, manifold and oriented
//! outwards, have no degenerate triangles or bad normals, and their area and volume converge to
//! the B-rep's as the limits tighten (within 1e-3 relative at the defaults).

use std::f64::consts::{PI, TAU};

use locus_kernel::{
    Brep, Cone, Cylinder, Interval, Mesh, MeshingParameters, OrientedBox, Plane, Point3, Sphere,
    Transform, Vector3,
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

fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs()
}

fn angle(degrees: f64) -> MeshingParameters {
    MeshingParameters {
        max_angle: degrees.to_radians(),
        ..Default::default()
    }
}

/// The checks every mesh of a closed solid must pass: closed and oriented, no degenerate
/// triangle, unit normals, a positive volume.
fn assert_solid_mesh(mesh: &Mesh, scale: f64) {
    assert!(
        mesh.is_closed_and_oriented(),
        "mesh is not closed and oriented"
    );
    assert_eq!(mesh.naked_edge_count(), 0);
    let v = mesh.vertices();
    for t in mesh.triangles() {
        let [a, b, c] = t.map(|i| v[i as usize]);
        let area = 0.5 * (b - a).cross(c - a).length();
        assert!(
            area > 1e-10 * scale * scale,
            "degenerate triangle {t:?}: area {area}"
        );
    }
    for n in mesh.normals().expect("meshes of B-reps have normals") {
        assert!(
            n.is_finite() && (n.length() - 1.0).abs() < 1e-9,
            "bad normal {n:?}"
        );
    }
    assert!(
        mesh.volume() > 0.0,
        "volume {} is not positive",
        mesh.volume()
    );
}

/// Every vertex normal and every face normal points away from `inside` by more than
/// `min_cos` of the direction.
fn assert_normals_point_out(mesh: &Mesh, outward_at: impl Fn(Point3) -> Vector3) {
    let v = mesh.vertices();
    for (p, n) in v.iter().zip(mesh.normals().unwrap()) {
        assert!(
            n.dot(outward_at(*p)) > 0.5,
            "vertex normal {n:?} at {p:?} points in"
        );
    }
    for (face, n) in mesh.faces().iter().zip(mesh.face_normals()) {
        let c = face.corners();
        let centroid = Point3::from_vector(
            c.iter()
                .fold(Vector3::ZERO, |s, &i| s + v[i as usize].to_vector())
                / c.len() as f64,
        );
        let n = n.expect("no degenerate faces");
        assert!(
            n.dot(outward_at(centroid)) > 0.0,
            "face normal {n:?} points in"
        );
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(12))]

    #[test]
    fn spheres_mesh_closed_with_their_area_and_volume(centre in point(), radius in 0.01..100.0f64) {
        let sphere = Sphere::new(centre, radius).unwrap();
        let brep = Brep::from_sphere(&sphere).unwrap();
        let mesh = Mesh::from_brep(&brep, &MeshingParameters::default()).unwrap();
        assert_solid_mesh(&mesh, radius);
        assert_normals_point_out(&mesh, |p| (p - centre).normalize_or_zero());
        prop_assert!(rel(mesh.area(), sphere.area()) < 1e-3, "area {} vs {}", mesh.area(), sphere.area());
        prop_assert!(rel(mesh.volume(), sphere.volume()) < 2e-3);
        // The poles are fans around one vertex each.
        for pole in brep.singular_points() {
            let at_pole = mesh.vertices().iter().filter(|p| p.distance(pole) < 1e-9 * radius).count();
            prop_assert_eq!(at_pole, 1);
        }
    }

    #[test]
    fn capped_cylinders_mesh_closed(plane in plane(), radius in 0.1..20.0f64, height in 0.1..20.0f64) {
        let cylinder = Cylinder::new(plane, radius, height).unwrap();
        let brep = Brep::from_cylinder(&cylinder, true).unwrap();
        let mesh = Mesh::from_brep(&brep, &MeshingParameters::default()).unwrap();
        assert_solid_mesh(&mesh, radius.max(height));
        let exact_area = TAU * radius * height + 2.0 * PI * radius * radius;
        prop_assert!(rel(mesh.area(), exact_area) < 1e-3, "area {} vs {}", mesh.area(), exact_area);
        prop_assert!(rel(mesh.volume(), cylinder.volume()) < 2e-3);
    }

    #[test]
    fn capped_cones_mesh_closed_with_a_fan_at_the_apex(plane in plane(), radius in 0.1..20.0f64, height in 0.1..20.0f64) {
        let cone = Cone::new(plane, height, radius).unwrap();
        let brep = Brep::from_cone(&cone, true).unwrap();
        let mesh = Mesh::from_brep(&brep, &MeshingParameters::default()).unwrap();
        assert_solid_mesh(&mesh, radius.max(height));
        let apex = cone.apex();
        let at_apex = mesh.vertices().iter().filter(|p| p.distance(apex) < 1e-9 * height).count();
        prop_assert_eq!(at_apex, 1);
        let exact_area = cone.lateral_area() + PI * radius * radius;
        prop_assert!(rel(mesh.area(), exact_area) < 1e-3, "area {} vs {}", mesh.area(), exact_area);
        prop_assert!(rel(mesh.volume(), cone.volume()) < 2e-3);
    }

    #[test]
    fn boxes_mesh_exactly(plane in plane(), x in 0.1..20.0f64, y in 0.1..20.0f64, z in 0.1..20.0f64) {
        let b = OrientedBox::new(plane, Interval::new(0.0, x), Interval::new(0.0, y), Interval::new(0.0, z));
        let brep = Brep::from_box(&b).unwrap();
        let mesh = Mesh::from_brep(&brep, &MeshingParameters::default()).unwrap();
        assert_solid_mesh(&mesh, x.max(y).max(z));
        prop_assert_eq!(mesh.vertices().len(), 8);
        prop_assert_eq!(mesh.triangle_count(), 12);
        prop_assert!(rel(mesh.area(), 2.0 * (x * y + y * z + z * x)) < 1e-12);
        prop_assert!(rel(mesh.volume(), x * y * z) < 1e-12);
    }
}

#[test]
fn sphere_area_and_volume_converge_as_the_angle_shrinks() {
    let sphere = Sphere::new(Point3::new(1.0, 2.0, 3.0), 5.0).unwrap();
    let brep = Brep::from_sphere(&sphere).unwrap();
    let mut last = (f64::INFINITY, f64::INFINITY);
    for degrees in [20.0, 10.0, 5.0, 2.5, 1.25] {
        let mesh = Mesh::from_brep(&brep, &angle(degrees)).unwrap();
        assert_solid_mesh(&mesh, 5.0);
        let errors = (
            rel(mesh.area(), sphere.area()),
            rel(mesh.volume(), sphere.volume()),
        );
        assert!(
            errors.0 < last.0 && errors.1 < last.1,
            "{degrees}°: {errors:?} after {last:?}"
        );
        last = errors;
    }
    assert!(last.0 < 1e-4, "area error {} at 1.25°", last.0);
}

#[test]
fn cylinder_area_converges_as_the_chord_deviation_shrinks() {
    let cylinder = Cylinder::new(Plane::WORLD_XY, 3.0, 7.0).unwrap();
    let brep = Brep::from_cylinder(&cylinder, true).unwrap();
    let exact = TAU * 3.0 * 7.0 + 2.0 * PI * 9.0;
    let mut last = f64::INFINITY;
    for tol in [1e-1, 1e-2, 1e-3, 1e-4] {
        let mesh = Mesh::from_brep(&brep, &MeshingParameters::with_chord_deviation(tol)).unwrap();
        assert_solid_mesh(&mesh, 7.0);
        let error = rel(mesh.area(), exact);
        assert!(error < last, "{tol}: {error} after {last}");
        last = error;
    }
    assert!(last < 1e-4);
}

#[test]
fn the_exploded_box_meshes_face_by_face_with_the_faces_areas() {
    // The book's exploded box: the six faces of the box (0,0,0)-(2,3,4) moved 1.5 away from
    // the centre; each face's mesh is an open quad of two triangles with the face's area.
    let b = OrientedBox::new(
        Plane::WORLD_XY,
        Interval::new(0.0, 2.0),
        Interval::new(0.0, 3.0),
        Interval::new(0.0, 4.0),
    );
    let brep = Brep::from_box(&b).unwrap();
    let centre = Point3::new(1.0, 1.5, 2.0);
    let mut total = 0.0;
    for f in 0..6 {
        let face = brep.extract_face(f).unwrap();
        let props = face.area_properties().unwrap();
        let away = (props.centroid - centre).normalize_or_zero() * 1.5;
        let moved = face.transformed(&Transform::translation(away)).unwrap();
        let mesh = Mesh::from_brep(&moved, &MeshingParameters::default()).unwrap();
        assert_eq!(mesh.naked_edge_count(), 4);
        assert!(rel(mesh.area(), props.area) < 1e-12);
        // The face's mesh faces away from the box, as the face does.
        let n = mesh.face_normals()[0].unwrap();
        assert!(n.dot(away) > 0.0);
        total += mesh.area();
    }
    assert!(rel(total, 2.0 * (6.0 + 12.0 + 8.0)) < 1e-12);
}

#[test]
fn planar_faces_with_holes_are_triangulated_around_the_holes() {
    let p = |x: f64, y: f64| Point3::new(x, y, 0.0);
    let outer = [
        p(0.0, 0.0),
        p(10.0, 0.0),
        p(10.0, 6.0),
        p(4.0, 8.0),
        p(0.0, 6.0),
    ];
    let holes = vec![
        vec![p(1.0, 1.0), p(3.0, 1.0), p(3.0, 3.0), p(1.0, 3.0)],
        vec![p(6.0, 2.0), p(8.0, 2.0), p(7.0, 5.0)],
    ];
    let brep = Brep::from_planar_polylines(&outer, &holes, 1e-9).unwrap();
    let mesh = Mesh::from_brep(&brep, &MeshingParameters::default()).unwrap();
    let exact = 60.0 + 0.5 * 10.0 * 2.0 - 4.0 - 3.0;
    assert!(rel(mesh.area(), exact) < 1e-12, "area {}", mesh.area());
    assert_eq!(mesh.naked_edge_count(), 5 + 4 + 3);
    assert_eq!(mesh.vertices().len(), 12);
    for n in mesh.face_normals() {
        assert!(n.unwrap().dot(Vector3::Z) > 0.999);
    }
}

#[test]
fn joined_faces_mesh_as_one_closed_mesh() {
    let b = OrientedBox::new(
        Plane::WORLD_XY,
        Interval::new(0.0, 1.0),
        Interval::new(0.0, 2.0),
        Interval::new(0.0, 3.0),
    );
    let brep = Brep::from_box(&b).unwrap();
    let faces: Vec<Brep> = (0..6).map(|f| brep.extract_face(f).unwrap()).collect();
    let joined = Brep::join(&faces, 1e-6).unwrap();
    assert_eq!(joined.len(), 1);
    let mesh = Mesh::from_brep(&joined[0], &MeshingParameters::default()).unwrap();
    assert_solid_mesh(&mesh, 3.0);
    assert!(rel(mesh.volume(), 6.0) < 1e-12);
}

#[test]
fn open_surfaces_mesh_within_a_chord_tolerance() {
    // A half cylinder as a bare surface: an open mesh whose triangles' midpoints stay within
    // the chord tolerance of the exact surface.
    let cylinder = Cylinder::new(Plane::WORLD_XY, 2.0, 5.0).unwrap();
    let surface = cylinder.to_nurbs().unwrap();
    let tol = 1e-3;
    let mesh = Mesh::from_surface(&surface, &MeshingParameters::with_chord_deviation(tol)).unwrap();
    let v = mesh.vertices();
    for t in mesh.triangles() {
        let [a, b, c] = t.map(|i| v[i as usize]);
        for m in [a.midpoint(b), b.midpoint(c), c.midpoint(a)] {
            let r = (m.x * m.x + m.y * m.y).sqrt();
            assert!(
                2.0 - r <= tol * 1.1,
                "edge midpoint {m:?} is {} inside",
                2.0 - r
            );
        }
    }
    // Closed around but open at the two circles.
    assert!(mesh.naked_edge_count() > 0);
}

#[test]
fn doubly_curved_meshes_stay_within_the_chord_deviation() {
    // The deviations of a surface's two directions add in the middle of a grid cell and of its
    // diagonal; the mesher shares the limit between them (`SURFACE_CHORD_SHARE`), so that
    // triangle centroids and edge midpoints stay within it (they were up to twice as far).
    let centre = Point3::new(1.0, -2.0, 0.5);
    let brep = Brep::from_sphere(&Sphere::new(centre, 3.0).unwrap()).unwrap();
    for tol in [1e-1, 1e-2, 1e-3] {
        let mesh = Mesh::from_brep(&brep, &MeshingParameters::with_chord_deviation(tol)).unwrap();
        let v = mesh.vertices();
        let mut worst: f64 = 0.0;
        for t in mesh.triangles() {
            let [a, b, c] = t.map(|i| v[i as usize]);
            let centroid = a + ((b - a) + (c - a)) / 3.0;
            for m in [centroid, a.midpoint(b), b.midpoint(c), c.midpoint(a)] {
                worst = worst.max(3.0 - m.distance(centre));
            }
        }
        assert!(
            worst <= tol * 1.05,
            "{tol}: a point {worst} inside the sphere"
        );
    }
}

#[test]
fn bad_parameters_fail_with_a_reason() {
    let brep = Brep::from_sphere(&Sphere::new(Point3::ORIGIN, 1.0).unwrap()).unwrap();
    for bad in [
        MeshingParameters {
            max_angle: f64::NAN,
            ..Default::default()
        },
        MeshingParameters {
            max_edge_length: -1.0,
            ..Default::default()
        },
        MeshingParameters {
            max_edge_length: 1e-9,
            min_edge_length: 0.0,
            ..Default::default()
        },
    ] {
        assert!(Mesh::from_brep(&brep, &bad).is_err(), "{bad:?}");
    }
}

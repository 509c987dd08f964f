use super::*;
use crate::brep::EdgeKind;

fn unit_corners(x: f64, y: f64, z: f64) -> [Point3; 8] {
    [
        Point3::new(0.0, 0.0, 0.0),
        Point3::new(x, 0.0, 0.0),
        Point3::new(x, y, 0.0),
        Point3::new(0.0, y, 0.0),
        Point3::new(0.0, 0.0, z),
        Point3::new(x, 0.0, z),
        Point3::new(x, y, z),
        Point3::new(0.0, y, z),
    ]
}

/// Every trim starts where the previous one in its loop ends, in parameter space and at
/// the same vertex, and every trim's edge runs between the trim's vertices.
fn check_topology(brep: &Brep) {
    for (l, lp) in brep.loops().iter().enumerate() {
        let n = lp.trims.len();
        for k in 0..n {
            let (a, b) = (
                &brep.trims()[lp.trims[k]],
                &brep.trims()[lp.trims[(k + 1) % n]],
            );
            assert_eq!(a.loop_index, l);
            assert!(a.curve.end_point().distance(b.curve.start_point()) < 1e-12);
            assert_eq!(a.vertices[1], b.vertices[0]);
        }
    }
    for t in brep.trims() {
        let face = &brep.faces()[brep.loops()[t.loop_index].face];
        let s = t.curve.start_point();
        let start_3d = face.surface.point_at(s.x, s.y);
        assert!(start_3d.distance(brep.vertices()[t.vertices[0]].point) < 1e-12);
        if let Some(e) = t.edge {
            let edge = &brep.edges()[e];
            let ends = if t.reversed {
                [edge.vertices[1], edge.vertices[0]]
            } else {
                edge.vertices
            };
            assert_eq!(ends, t.vertices);
            // The trim's curve on the surface follows the edge.
            let mid = t.curve.point_at(t.curve.domain().mid());
            let on_surface = face.surface.point_at(mid.x, mid.y);
            let cp = (0..=400)
                .map(|i| {
                    edge.curve
                        .point_at(edge.curve.domain().parameter_at(i as f64 / 400.0))
                        .distance(on_surface)
                })
                .fold(f64::INFINITY, f64::min);
            assert!(cp < 0.05, "trim midpoint {cp} away from its edge");
        } else {
            assert_eq!(t.kind, TrimKind::Singular);
        }
    }
}

#[test]
fn box_topology() {
    let b = Brep::from_box_corners(&unit_corners(2.0, 3.0, 4.0)).unwrap();
    assert_eq!(
        (b.faces().len(), b.edges().len(), b.vertices().len()),
        (6, 12, 8)
    );
    assert_eq!(b.trims().len(), 24);
    assert!(b.is_solid());
    assert!(b.trims().iter().all(|t| t.kind == TrimKind::Mated));
    assert_eq!(b.edges_of_kind(EdgeKind::Interior).len(), 12);
    assert!(b.singular_points().is_empty());
    assert!(b.faces().iter().all(|f| !f.reversed));
    check_topology(&b);
    // Outward normals at every face's centre.
    let centre = Point3::new(1.0, 1.5, 2.0);
    for f in b.faces() {
        let (u, v) = (f.surface.domain_u().mid(), f.surface.domain_v().mid());
        let n = f.surface.normal_at(u, v).unwrap();
        assert!(n.dot(f.surface.point_at(u, v) - centre) > 0.0);
    }
}

#[test]
fn mirrored_box_corners_give_reversed_faces() {
    let mut c = unit_corners(1.0, 1.0, 1.0);
    c.swap(1, 3);
    c.swap(5, 7);
    let b = Brep::from_box_corners(&c).unwrap();
    assert!(b.faces().iter().all(|f| f.reversed));
    let mut degenerate = unit_corners(1.0, 1.0, 1.0);
    degenerate[1] = degenerate[0];
    assert!(matches!(
        Brep::from_box_corners(&degenerate),
        Err(Error::ZeroLength { .. })
    ));
    let mut nan = unit_corners(1.0, 1.0, 1.0);
    nan[6].x = f64::NAN;
    assert!(Brep::from_box_corners(&nan).is_err());
}

#[test]
fn sphere_topology_matches_rhino() {
    let s = Sphere::new(Point3::ORIGIN, 2.0).unwrap();
    let b = Brep::from_sphere(&s).unwrap();
    assert_eq!(
        (b.faces().len(), b.edges().len(), b.vertices().len()),
        (1, 1, 2)
    );
    assert_eq!(b.vertices()[0].point, Point3::new(0.0, 0.0, -2.0));
    assert_eq!(b.vertices()[1].point, Point3::new(0.0, 0.0, 2.0));
    let kinds: Vec<TrimKind> = b.trims().iter().map(|t| t.kind).collect();
    assert_eq!(
        kinds,
        [
            TrimKind::Singular,
            TrimKind::Seam,
            TrimKind::Singular,
            TrimKind::Seam
        ]
    );
    assert!(b.is_solid());
    assert_eq!(
        b.singular_points(),
        vec![Point3::new(0.0, 0.0, -2.0), Point3::new(0.0, 0.0, 2.0)]
    );
    assert_eq!(b.trim_side(0), Some(SurfaceSide::South));
    assert_eq!(b.trim_side(3), Some(SurfaceSide::West));
    check_topology(&b);
}

#[test]
fn cylinder_and_cone_topology() {
    let plane =
        Plane::from_normal(Point3::new(1.0, 0.0, 2.0), Vector3::new(0.2, 0.1, 1.0)).unwrap();
    let cyl = Cylinder::new(plane, 1.5, 4.0).unwrap();
    let open = Brep::from_cylinder(&cyl, false).unwrap();
    assert_eq!(
        (
            open.faces().len(),
            open.edges().len(),
            open.vertices().len()
        ),
        (1, 3, 2)
    );
    assert_eq!(open.edges_of_kind(EdgeKind::Naked).len(), 2);
    assert!(!open.is_solid());
    check_topology(&open);
    let closed = Brep::from_cylinder(&cyl, true).unwrap();
    assert_eq!(
        (
            closed.faces().len(),
            closed.edges().len(),
            closed.vertices().len()
        ),
        (3, 3, 2)
    );
    assert!(closed.is_solid());
    check_topology(&closed);

    for height in [3.0, -3.0] {
        let cone = Cone::new(plane, height, 1.5).unwrap();
        let b = Brep::from_cone(&cone, false).unwrap();
        assert_eq!(
            (b.faces().len(), b.edges().len(), b.vertices().len()),
            (1, 2, 2)
        );
        assert_eq!(b.singular_points(), vec![plane.origin]);
        check_topology(&b);
        let capped = Brep::from_cone(&cone, true).unwrap();
        assert_eq!(capped.faces().len(), 2);
        assert!(capped.is_solid());
        check_topology(&capped);
    }
}

#[test]
fn planar_polyline_faces() {
    let square = [
        Point3::new(0.0, 0.0, 1.0),
        Point3::new(4.0, 0.0, 1.0),
        Point3::new(4.0, 4.0, 1.0),
        Point3::new(0.0, 4.0, 1.0),
        Point3::new(0.0, 0.0, 1.0),
    ];
    let b = Brep::from_planar_polyline(&square, 1e-9).unwrap();
    assert_eq!(
        (b.faces().len(), b.edges().len(), b.vertices().len()),
        (1, 4, 4)
    );
    assert_eq!(b.edges_of_kind(EdgeKind::Naked).len(), 4);
    check_topology(&b);
    // Clockwise input gives a face whose normal follows the winding: −z.
    let mut clockwise = square;
    clockwise.reverse();
    let c = Brep::from_planar_polyline(&clockwise, 1e-9).unwrap();
    let f = &c.faces()[0].surface;
    let n = f.normal_at(f.domain_u().mid(), f.domain_v().mid()).unwrap();
    assert!((n + Vector3::Z).length() < 1e-15);

    let hole = vec![
        Point3::new(1.0, 1.0, 1.0),
        Point3::new(1.0, 2.0, 1.0),
        Point3::new(2.0, 2.0, 1.0),
        Point3::new(2.0, 1.0, 1.0),
    ];
    let h = Brep::from_planar_polylines(&square, std::slice::from_ref(&hole), 1e-9).unwrap();
    assert_eq!(h.loops().len(), 2);
    assert_eq!(h.loops()[1].kind, LoopKind::Inner);
    assert_eq!(h.edges().len(), 8);
    check_topology(&h);

    let bow_tie = [
        Point3::new(0.0, 0.0, 0.0),
        Point3::new(3.0, 2.0, 0.0),
        Point3::new(3.0, 0.0, 0.0),
        Point3::new(0.0, 1.0, 0.0),
    ];
    assert!(matches!(
        Brep::from_planar_polyline(&bow_tie, 1e-9),
        Err(Error::InvalidInput(_))
    ));
    let bent = [
        Point3::new(0.0, 0.0, 0.0),
        Point3::new(1.0, 0.0, 0.0),
        Point3::new(1.0, 1.0, 0.1),
        Point3::new(0.0, 1.0, 0.0),
    ];
    assert!(Brep::from_planar_polyline(&bent, 1e-3).is_err());
    assert!(Brep::from_planar_polyline(&bent, 0.1).is_ok());
    let line = [
        Point3::new(0.0, 0.0, 0.0),
        Point3::new(1.0, 0.0, 0.0),
        Point3::new(2.0, 0.0, 0.0),
    ];
    assert!(matches!(
        Brep::from_planar_polyline(&line, 1e-9),
        Err(Error::Collinear)
    ));
    assert!(matches!(
        Brep::from_planar_polyline(&square[..2], 1e-9),
        Err(Error::TooFewPoints { .. })
    ));
    let outside = vec![
        Point3::new(5.0, 5.0, 1.0),
        Point3::new(6.0, 5.0, 1.0),
        Point3::new(6.0, 6.0, 1.0),
    ];
    assert!(Brep::from_planar_polylines(&square, &[outside], 1e-9).is_err());
    let crossing = vec![
        Point3::new(3.0, 1.0, 1.0),
        Point3::new(5.0, 1.0, 1.0),
        Point3::new(3.0, 2.0, 1.0),
    ];
    assert!(Brep::from_planar_polylines(&square, &[crossing], 1e-9).is_err());
}

#[test]
fn extract_face_keeps_its_own_topology() {
    let b = Brep::from_box_corners(&unit_corners(1.0, 2.0, 3.0)).unwrap();
    let f = b.extract_face(5).unwrap();
    assert_eq!(
        (f.faces().len(), f.edges().len(), f.vertices().len()),
        (1, 4, 4)
    );
    assert_eq!(f.edges_of_kind(EdgeKind::Naked).len(), 4);
    assert!(f.trims().iter().all(|t| t.kind == TrimKind::Boundary));
    check_topology(&f);
    assert!(b.extract_face(6).is_err());

    let cyl =
        Brep::from_cylinder(&Cylinder::new(Plane::WORLD_XY, 1.0, 2.0).unwrap(), true).unwrap();
    let lateral = cyl.extract_face(0).unwrap();
    assert_eq!(lateral.edges().len(), 3);
    assert_eq!(lateral.edges_of_kind(EdgeKind::Interior).len(), 1);
    assert_eq!(lateral.trims()[1].kind, TrimKind::Seam);
    check_topology(&lateral);
}

#[test]
fn transforms_move_everything_and_keep_faces_outward() {
    let b = Brep::from_box_corners(&unit_corners(1.0, 2.0, 3.0)).unwrap();
    let mirror = crate::Transform::from_rows([
        [-1.0, 0.0, 0.0, 5.0],
        [0.0, 1.0, 0.0, 0.0],
        [0.0, 0.0, 1.0, 0.0],
        [0.0, 0.0, 0.0, 1.0],
    ]);
    let m = b.transformed(&mirror).unwrap();
    assert!(m.faces().iter().all(|f| f.reversed));
    assert_eq!(m.vertices()[1].point, Point3::new(4.0, 0.0, 0.0));
    assert_eq!(m.edges()[0].curve.end_point(), Point3::new(4.0, 0.0, 0.0));
    check_topology(&m);
}

//! Solid booleans and splits of B-reps against volumes known in closed form.

use std::f64::consts::PI;

use locus_kernel::{
    BooleanOperation, Brep, Cylinder, Interval, OrientedBox, Plane, Point3, Sphere, Vector3,
};

const TOL: f64 = 1e-9;

fn cuboid(x: [f64; 2], y: [f64; 2], z: [f64; 2]) -> Brep {
    let i = |a: [f64; 2]| Interval::new(a[0], a[1]);
    Brep::from_box(&OrientedBox::new(Plane::WORLD_XY, i(x), i(y), i(z))).unwrap()
}

/// A capped cylinder of radius 0.5 along z from −1 to 2.
fn rod() -> Brep {
    let c = Cylinder::new(
        Plane::from_normal(Point3::new(0.0, 0.0, -1.0), Vector3::new(0.0, 0.0, 1.0)).unwrap(),
        0.5,
        3.0,
    )
    .unwrap();
    Brep::from_cylinder(&c, true).unwrap()
}

fn volume(breps: &[Brep]) -> f64 {
    breps.iter().map(|b| b.volume().unwrap()).sum()
}

fn all_solid(breps: &[Brep]) -> bool {
    breps.iter().all(Brep::is_solid)
}

#[test]
fn overlapping_cubes() {
    let a = cuboid([0.0, 2.0], [0.0, 2.0], [0.0, 2.0]);
    let b = cuboid([1.0, 3.0], [1.0, 3.0], [1.0, 3.0]);
    for (op, expected) in [
        (BooleanOperation::Union, 15.0),
        (BooleanOperation::Intersection, 1.0),
        (BooleanOperation::Difference, 7.0),
    ] {
        let r = a.boolean(&b, op, TOL).unwrap();
        assert_eq!(r.len(), 1, "{op:?}");
        assert!(all_solid(&r), "{op:?} not closed");
        assert!(
            (volume(&r) - expected).abs() < 1e-9,
            "{op:?}: {}",
            volume(&r)
        );
    }
}

#[test]
fn a_cylinder_drilled_through_a_box() {
    let a = cuboid([-2.0, 2.0], [-2.0, 2.0], [0.0, 1.0]);
    let b = rod();
    let r = a.boolean(&b, BooleanOperation::Difference, TOL).unwrap();
    assert_eq!(r.len(), 1);
    assert!(all_solid(&r));
    let expected = 16.0 - PI * 0.25;
    assert!((volume(&r) - expected).abs() < 1e-8, "{}", volume(&r));
    let u = a.boolean(&b, BooleanOperation::Union, TOL).unwrap();
    let expected = 16.0 + PI * 0.25 * 2.0;
    assert!(all_solid(&u));
    assert!((volume(&u) - expected).abs() < 1e-8, "{}", volume(&u));
}

#[test]
fn two_spheres() {
    let (r, d) = (2.0, 2.0);
    let a = Brep::from_sphere(&Sphere::new(Point3::ORIGIN, r).unwrap()).unwrap();
    let b = Brep::from_sphere(&Sphere::new(Point3::new(d, 0.0, 0.0), r).unwrap()).unwrap();
    // The lens: two caps of height h = r − d/2.
    let h = r - d / 2.0;
    let lens = 2.0 * PI * h * h * (3.0 * r - h) / 3.0;
    let ball = 4.0 / 3.0 * PI * r * r * r;
    for (op, expected) in [
        (BooleanOperation::Union, 2.0 * ball - lens),
        (BooleanOperation::Intersection, lens),
        (BooleanOperation::Difference, ball - lens),
    ] {
        let x = a.boolean(&b, op, TOL).unwrap();
        assert_eq!(x.len(), 1, "{op:?}");
        assert!(all_solid(&x), "{op:?} not closed");
        assert!(
            (volume(&x) - expected).abs() < 1e-7 * expected,
            "{op:?}: {} vs {expected}",
            volume(&x)
        );
    }
}

#[test]
fn a_box_split_by_a_box() {
    let a = cuboid([0.0, 2.0], [0.0, 2.0], [0.0, 2.0]);
    let b = cuboid([1.0, 3.0], [-1.0, 3.0], [-1.0, 3.0]);
    let parts = a.split_by_brep(&b, TOL).unwrap();
    assert_eq!(parts.len(), 2);
    // Two open boxes of five faces, 1 × 2 × 2 each with the face x = 1 missing.
    for p in &parts {
        assert_eq!(p.faces().len(), 5);
        assert!(
            (p.area().unwrap() - 12.0).abs() < 1e-12,
            "{}",
            p.area().unwrap()
        );
    }
    // Joined again, they are the box.
    let again = Brep::join(&parts, TOL).unwrap();
    assert_eq!(again.len(), 1);
    assert!(again[0].is_solid());
    assert!((again[0].volume().unwrap() - 8.0).abs() < 1e-12);
}

#[test]
fn a_capped_cylinder_split_by_a_slab_gives_three_parts_of_the_whole() {
    let slab = cuboid([-2.0, 2.0], [-2.0, 2.0], [0.0, 1.0]);
    let b = rod();
    let parts = b.split_by_brep(&slab, TOL).unwrap();
    assert_eq!(parts.len(), 3);
    let mut areas: Vec<f64> = parts.iter().map(|p| p.area().unwrap()).collect();
    areas.sort_by(f64::total_cmp);
    // The middle band (π), and a band with its cap at each end (π + π/4).
    for (area, expected) in areas.iter().zip([PI, 1.25 * PI, 1.25 * PI]) {
        assert!((area - expected).abs() < 1e-12, "{areas:?}");
    }
    let again = Brep::join(&parts, TOL).unwrap();
    assert_eq!(again.len(), 1);
    assert!(again[0].is_solid());
    assert!((again[0].volume().unwrap() - 0.75 * PI).abs() < 1e-12);
}

#[test]
fn solids_apart_or_nested() {
    let a = cuboid([0.0, 4.0], [0.0, 4.0], [0.0, 4.0]);
    let inner = cuboid([1.0, 2.0], [1.0, 2.0], [1.0, 2.0]);
    let far = cuboid([10.0, 11.0], [0.0, 1.0], [0.0, 1.0]);
    let v = |r: Vec<Brep>| (r.len(), volume(&r));
    assert_eq!(
        v(a.boolean(&far, BooleanOperation::Union, TOL).unwrap()),
        (2, 65.0)
    );
    assert_eq!(
        v(a.boolean(&far, BooleanOperation::Intersection, TOL)
            .unwrap()),
        (0, 0.0)
    );
    assert_eq!(
        v(a.boolean(&inner, BooleanOperation::Union, TOL).unwrap()),
        (1, 64.0)
    );
    assert_eq!(
        v(a.boolean(&inner, BooleanOperation::Intersection, TOL)
            .unwrap()),
        (1, 1.0)
    );
    // A box with a cavity: one B-rep of two shells, 63 in volume.
    let hollow = a
        .boolean(&inner, BooleanOperation::Difference, TOL)
        .unwrap();
    assert!(
        (volume(&hollow) - 63.0).abs() < 1e-12,
        "{}",
        volume(&hollow)
    );
}

#[test]
fn open_breps_are_refused() {
    let a = cuboid([0.0, 2.0], [0.0, 2.0], [0.0, 2.0]);
    let face = a.extract_face(0).unwrap();
    let e = a.boolean(&face, BooleanOperation::Union, TOL).unwrap_err();
    assert!(e.to_string().contains("not closed"), "{e}");
}

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig::with_cases(24))]

    /// Two boxes in general position: the volumes of the three booleans by the overlap of
    /// their intervals.
    #[test]
    fn boxes_in_general_position(
        a in proptest::array::uniform3((-2.0f64..0.0, 0.5f64..2.0)),
        b in proptest::array::uniform3((-1.0f64..1.0, 0.5f64..2.0)),
    ) {
        let span = |(lo, len): (f64, f64)| [lo, lo + len];
        let (ra, rb) = (a.map(span), b.map(span));
        let x = cuboid(ra[0], ra[1], ra[2]);
        let y = cuboid(rb[0], rb[1], rb[2]);
        let overlap: f64 = (0..3)
            .map(|k| (ra[k][1].min(rb[k][1]) - ra[k][0].max(rb[k][0])).max(0.0))
            .product();
        let (va, vb) = (a.iter().map(|s| s.1).product::<f64>(), b.iter().map(|s| s.1).product::<f64>());
        for (op, expected) in [
            (BooleanOperation::Union, va + vb - overlap),
            (BooleanOperation::Intersection, overlap),
            (BooleanOperation::Difference, va - overlap),
        ] {
            let r = x.boolean(&y, op, TOL).unwrap();
            if !all_solid(&r) {
                report("open", &r);
            }
            proptest::prop_assert!(all_solid(&r), "{:?} not closed", op);
            proptest::prop_assert!((volume(&r) - expected).abs() < 1e-9, "{:?}: {} vs {}", op, volume(&r), expected);
        }
    }
}

/// Prints the naked and non-manifold edges of the B-reps (for a failing test).
fn report(label: &str, breps: &[Brep]) {
    for (k, b) in breps.iter().enumerate() {
        eprintln!(
            "{label} brep {k}: {} faces, {} edges",
            b.faces().len(),
            b.edges().len()
        );
        for (e, edge) in b.edges().iter().enumerate() {
            if edge.trims.len() != 2 {
                eprintln!(
                    "  edge {e} ({} trims): {:?} -> {:?} mid {:?}",
                    edge.trims.len(),
                    edge.curve.start_point(),
                    edge.curve.end_point(),
                    edge.curve.point_at(edge.curve.domain().mid())
                );
            }
        }
    }
}

#[test]
fn a_pocket_flush_with_the_top_face() {
    // The second box shares part of the first's top face: the pieces lying on each other
    // face the same way and are dropped from the difference.
    let a = cuboid([0.0, 2.0], [0.0, 2.0], [0.0, 2.0]);
    let b = cuboid([0.5, 1.5], [0.5, 1.5], [1.0, 2.0]);
    let r = a.boolean(&b, BooleanOperation::Difference, 1e-3).unwrap();
    assert_eq!(r.len(), 1);
    assert!(all_solid(&r));
    assert_eq!(r[0].faces().len(), 11);
    assert!((volume(&r) - 7.0).abs() < 1e-12, "{}", volume(&r));
    let u = a.boolean(&b, BooleanOperation::Union, 1e-3).unwrap();
    assert!(
        all_solid(&u) && (volume(&u) - 8.0).abs() < 1e-12,
        "{}",
        volume(&u)
    );
}

#[test]
fn boxes_sharing_faces_as_in_a_real_dresser() {
    // From mcneel-compute's hops dresser3.gh: a shelf less a side board flush with three of
    // its faces, and a back panel less a shelf flush with its back.
    let shelf = cuboid([0.0, 1000.0], [0.0, 300.0], [0.0, 19.0]);
    let side = cuboid([0.0, 19.0], [0.0, 300.0], [7.0, 493.0]);
    let r = shelf
        .boolean(&side, BooleanOperation::Difference, 1e-3)
        .unwrap();
    assert_eq!(r.len(), 1);
    assert!(all_solid(&r));
    let expected = 1000.0 * 300.0 * 19.0 - 19.0 * 300.0 * 12.0;
    assert!(
        (volume(&r) - expected).abs() < 1e-12 * expected,
        "{}",
        volume(&r)
    );
    let top = 319.333_333_333_333_37;
    let back = cuboid([7.0, 993.0], [294.0, 300.0], [7.0, top]);
    let board = cuboid(
        [10.0, 990.0],
        [0.0, 300.0],
        [307.333_333_333_333_37, 326.333_333_333_333_37],
    );
    let r = back
        .boolean(&board, BooleanOperation::Difference, 1e-3)
        .unwrap();
    assert_eq!(r.len(), 1);
    assert!(all_solid(&r));
    let expected = 986.0 * 6.0 * (top - 7.0) - 980.0 * 6.0 * (top - 307.333_333_333_333_37);
    assert!(
        (volume(&r) - expected).abs() < 1e-12 * expected,
        "{} vs {expected}",
        volume(&r)
    );
}

//! Brep | Brep: intersections with closed forms (spheres, boxes, perpendicular cylinders, a
//! plane through a capped cylinder checked against the B-rep's section by the same plane),
//! and, on random pairs of spheres, that the curve is the one circle the two spheres share:
//! every point on both spheres, and its length `2π·r`.

mod support;

use std::f64::consts::PI;

use locus_kernel::{
    Brep, Curve, Cylinder, Interval, NurbsSurface, OrientedBox, Plane, Point3, Sphere, Vector3,
};
use proptest::prelude::*;
use support::worst_distance;

const TOL: f64 = 1e-9;

fn sphere(x: f64, y: f64, z: f64, r: f64) -> Brep {
    Brep::from_sphere(&Sphere::new(Point3::new(x, y, z), r).unwrap()).unwrap()
}

fn cube(lo: f64, hi: f64) -> Brep {
    Brep::from_box(&OrientedBox::new(
        Plane::WORLD_XY,
        Interval::new(lo, hi),
        Interval::new(lo, hi),
        Interval::new(lo, hi),
    ))
    .unwrap()
}

/// The square sheet of half size `half` about `plane`'s origin, in the plane, as a B-rep.
fn sheet(plane: &Plane, half: f64) -> Brep {
    let p = |x: f64, y: f64| plane.point_at(x, y, 0.0);
    let surface = NurbsSurface::non_rational(
        1,
        1,
        vec![
            vec![p(-half, -half), p(-half, half)],
            vec![p(half, -half), p(half, half)],
        ],
        vec![0.0, 1.0],
        vec![0.0, 1.0],
    )
    .unwrap();
    Brep::from_surface(surface).unwrap()
}

fn total_length(curves: &[Curve]) -> f64 {
    curves.iter().map(Curve::length).sum()
}

#[test]
fn two_spheres_meet_in_one_closed_circle() {
    let (a, b) = (sphere(0.0, 0.0, 0.0, 2.0), sphere(1.0, 1.5, 0.5, 1.5));
    let x = a.intersect_brep(&b, TOL).unwrap();
    assert_eq!(x.curves.len(), 1, "{:?}", x.curves.len());
    assert!(x.curves[0].is_closed());
    assert!(x.points.is_empty());
    // The radical plane: distance h from a's centre along the line of centres.
    let d = (1.0f64 + 2.25 + 0.25).sqrt();
    let h = (d * d + 4.0 - 2.25) / (2.0 * d);
    let r = (4.0 - h * h).sqrt();
    assert!((x.curves[0].length() - 2.0 * PI * r).abs() < 1e-8);
    assert!(worst_distance(&x.curves, &a) < TOL);
    assert!(worst_distance(&x.curves, &b) < TOL);
}

#[test]
fn apart_and_nested_spheres_do_not_meet() {
    let a = sphere(0.0, 0.0, 0.0, 1.0);
    for b in [sphere(3.0, 0.0, 0.0, 1.0), sphere(0.1, 0.0, 0.0, 0.5)] {
        let x = a.intersect_brep(&b, TOL).unwrap();
        assert!(x.curves.is_empty() && x.points.is_empty(), "{x:?}");
    }
}

#[test]
fn spheres_touching_outside_give_a_point() {
    let x = sphere(0.0, 0.0, 0.0, 1.0)
        .intersect_brep(&sphere(0.0, 2.0, 0.0, 1.0), TOL)
        .unwrap();
    assert!(x.curves.is_empty(), "{:?}", x.curves);
    assert_eq!(x.points.len(), 1);
    assert!(x.points[0].distance(Point3::new(0.0, 1.0, 0.0)) < 1e-6);
}

#[test]
fn overlapping_cubes_meet_in_a_hexagon() {
    let x = cube(0.0, 2.0).intersect_brep(&cube(1.0, 3.0), TOL).unwrap();
    assert_eq!(x.curves.len(), 1, "{:?}", x.curves);
    assert!(x.curves[0].is_closed());
    assert!((x.curves[0].length() - 6.0).abs() < 1e-9);
    let corners = [
        Point3::new(2.0, 1.0, 1.0),
        Point3::new(1.0, 2.0, 1.0),
        Point3::new(1.0, 1.0, 2.0),
        Point3::new(2.0, 2.0, 1.0),
        Point3::new(2.0, 1.0, 2.0),
        Point3::new(1.0, 2.0, 2.0),
    ];
    for c in corners {
        let d = x.curves[0].closest_point(c).unwrap().distance;
        assert!(d < TOL, "{c:?} at {d}");
    }
}

#[test]
fn perpendicular_cylinders_meet_in_two_closed_curves() {
    // A thin cylinder along z through a wide one along x: two saddle-shaped loops.
    let thin = Cylinder::new(
        Plane::from_normal(Point3::new(0.0, 0.0, -3.0), Vector3::Z).unwrap(),
        1.0,
        6.0,
    )
    .unwrap();
    let wide = Cylinder::new(
        Plane::from_normal(Point3::new(-3.0, 0.0, 0.0), Vector3::X).unwrap(),
        2.0,
        6.0,
    )
    .unwrap();
    let (a, b) = (
        Brep::from_cylinder(&thin, false).unwrap(),
        Brep::from_cylinder(&wide, false).unwrap(),
    );
    let x = a.intersect_brep(&b, TOL).unwrap();
    assert_eq!(x.curves.len(), 2, "{:?}", x.curves);
    assert!(x.curves.iter().all(Curve::is_closed));
    assert!(worst_distance(&x.curves, &a) < TOL);
    assert!(worst_distance(&x.curves, &b) < TOL);
    // Each loop: (cos θ, sin θ, ±√(4 − sin²θ)); its length by dense quadrature.
    let n = 200_000;
    let mut length = 0.0;
    let point = |t: f64| {
        let (s, c) = t.sin_cos();
        Point3::new(c, s, (4.0 - s * s).sqrt())
    };
    for k in 0..n {
        let (t0, t1) = (
            2.0 * PI * k as f64 / n as f64,
            2.0 * PI * (k + 1) as f64 / n as f64,
        );
        length += point(t0).distance(point(t1));
    }
    for c in &x.curves {
        assert!(
            (c.length() - length).abs() < 1e-7,
            "{} {length}",
            c.length()
        );
    }
}

#[test]
fn a_plane_through_a_capped_cylinder_gives_its_section() {
    let cylinder = Cylinder::new(Plane::WORLD_XY, 1.0, 4.0).unwrap();
    let solid = Brep::from_cylinder(&cylinder, true).unwrap();
    let plane =
        Plane::from_normal(Point3::new(0.0, 0.0, 2.0), Vector3::new(0.3, 0.2, 1.0)).unwrap();
    let x = solid.intersect_brep(&sheet(&plane, 5.0), TOL).unwrap();
    let section = solid.intersect_plane(&plane, TOL).unwrap();
    assert_eq!(x.curves.len(), 1);
    assert!(x.curves[0].is_closed());
    assert!((total_length(&x.curves) - total_length(&section.curves)).abs() < 1e-8);

    // Tilted far enough to cut the caps: a closed curve of lines and elliptic arcs.
    let steep =
        Plane::from_normal(Point3::new(0.0, 0.0, 2.0), Vector3::new(1.0, 0.0, 0.4)).unwrap();
    let x = solid.intersect_brep(&sheet(&steep, 9.0), TOL).unwrap();
    let section = solid.intersect_plane(&steep, TOL).unwrap();
    assert_eq!(x.curves.len(), 1, "{:?}", x.curves);
    assert!(x.curves[0].is_closed());
    assert!((total_length(&x.curves) - total_length(&section.curves)).abs() < 1e-8);
}

#[test]
fn a_brep_with_itself_is_flagged_coincident() {
    let a = sphere(1.0, 2.0, 3.0, 2.0);
    let x = a.intersect_brep(&a, 1e-3).unwrap();
    assert!(x.coincident);
    assert!(x.curves.is_empty() && x.points.is_empty(), "{x:?}");
    // Crossing spheres are not.
    let x = a.intersect_brep(&sphere(2.0, 2.0, 3.0, 2.0), 1e-3).unwrap();
    assert!(!x.coincident);
    assert_eq!(x.curves.len(), 1);
}

#[test]
fn sheets_through_a_spheres_poles_give_whole_circles() {
    // Sphere parameters collapse at the poles; the curves still pass them and close.
    let ball = sphere(0.0, 0.0, 0.0, 2.0);
    for normal in [
        Vector3::X,
        Vector3::new(1.0, 1.0, 0.0),
        Vector3::new(-0.3, 1.0, 0.0),
    ] {
        let plane = Plane::from_normal(Point3::ORIGIN, normal).unwrap();
        let x = ball.intersect_brep(&sheet(&plane, 5.0), TOL).unwrap();
        assert_eq!(x.curves.len(), 1, "{normal:?}: {:?}", x.curves);
        assert!(x.curves[0].is_closed());
        assert!((x.curves[0].length() - 4.0 * PI).abs() < 1e-9, "{normal:?}");
        assert!(x.points.is_empty());
    }
}

#[test]
fn a_bad_tolerance_is_an_error() {
    let a = sphere(0.0, 0.0, 0.0, 1.0);
    assert!(a.intersect_brep(&a, 0.0).is_err());
    assert!(a.intersect_brep(&a, f64::NAN).is_err());
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    #[test]
    fn random_spheres_share_their_circle(
        c in (-1.5f64..1.5, -1.5f64..1.5, -1.5f64..1.5),
        ra in 0.5f64..2.0,
        rb in 0.5f64..2.0,
    ) {
        let d = (c.0 * c.0 + c.1 * c.1 + c.2 * c.2).sqrt();
        // Clearly crossing: neither apart, nor nested, nor nearly touching.
        prop_assume!(d < ra + rb - 0.05 && d > (ra - rb).abs() + 0.05);
        let (a, b) = (sphere(0.0, 0.0, 0.0, ra), sphere(c.0, c.1, c.2, rb));
        let x = a.intersect_brep(&b, TOL).unwrap();
        prop_assert_eq!(x.curves.len(), 1);
        prop_assert!(x.curves[0].is_closed());
        let h = (d * d + ra * ra - rb * rb) / (2.0 * d);
        let r = (ra * ra - h * h).sqrt();
        prop_assert!((x.curves[0].length() - 2.0 * PI * r).abs() < 1e-7,
            "length {} against {}", x.curves[0].length(), 2.0 * PI * r);
        prop_assert!(worst_distance(&x.curves, &a) < 10.0 * TOL);
        prop_assert!(worst_distance(&x.curves, &b) < 10.0 * TOL);
    }
}

/// The length of `∂A ∩ ∂B` for boxes in general position: a face of A across axis `i` at
/// `a` meets a face of B across axis `j ≠ i` at `b` along the third axis, where `a` lies within
/// B's extent in `i`, `b` within A's extent in `j`, for the overlap of their extents in `k`.
fn box_boundary_length(a: &[[f64; 2]; 3], b: &[[f64; 2]; 3]) -> f64 {
    let within = |x: f64, r: [f64; 2]| r[0] < x && x < r[1];
    let mut total = 0.0;
    for i in 0..3 {
        for j in 0..3 {
            if i == j {
                continue;
            }
            let k = 3 - i - j;
            let overlap = (a[k][1].min(b[k][1]) - a[k][0].max(b[k][0])).max(0.0);
            for &x in &a[i] {
                for &y in &b[j] {
                    if within(x, b[i]) && within(y, a[j]) {
                        total += overlap;
                    }
                }
            }
        }
    }
    total
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    #[test]
    fn random_boxes_meet_along_their_boundaries(
        lo_a in prop::array::uniform3(-1.0f64..0.0),
        size_a in prop::array::uniform3(0.5f64..2.0),
        lo_b in prop::array::uniform3(-1.0f64..1.0),
        size_b in prop::array::uniform3(0.5f64..2.0),
    ) {
        let a = [0, 1, 2].map(|k| [lo_a[k], lo_a[k] + size_a[k]]);
        let b = [0, 1, 2].map(|k| [lo_b[k], lo_b[k] + size_b[k]]);
        // General position: no two face planes within 0.01 of each other.
        for k in 0..3 {
            for x in a[k] {
                for y in b[k] {
                    prop_assume!((x - y).abs() > 0.01);
                }
            }
        }
        let brep = |r: &[[f64; 2]; 3]| {
            Brep::from_box(&OrientedBox::new(
                Plane::WORLD_XY,
                Interval::new(r[0][0], r[0][1]),
                Interval::new(r[1][0], r[1][1]),
                Interval::new(r[2][0], r[2][1]),
            ))
            .unwrap()
        };
        let (ba, bb) = (brep(&a), brep(&b));
        let x = ba.intersect_brep(&bb, TOL).unwrap();
        let expected = box_boundary_length(&a, &b);
        prop_assert!((total_length(&x.curves) - expected).abs() < 1e-9,
            "length {} against {expected}", total_length(&x.curves));
        prop_assert!(x.curves.iter().all(Curve::is_closed), "{:?}", x.curves);
        prop_assert!(worst_distance(&x.curves, &ba) < TOL);
        prop_assert!(worst_distance(&x.curves, &bb) < TOL);
    }
}

/// A bicubic surface over `[0, 3]²` with the given heights at its 4 × 4 control points.
fn bumpy(heights: &[f64; 16]) -> NurbsSurface {
    let points = (0..4)
        .map(|i| {
            (0..4)
                .map(|j| Point3::new(i as f64, j as f64, heights[4 * i + j]))
                .collect()
        })
        .collect();
    NurbsSurface::non_rational(
        3,
        3,
        points,
        vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0],
        vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0],
    )
    .unwrap()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    /// A free-form surface against a planar sheet larger than it: the same curves as the
    /// section by the sheet's plane (an independent algorithm, `surface_plane.rs`).
    #[test]
    fn a_free_form_surface_meets_a_sheet_as_its_plane_section(
        heights in prop::array::uniform16(-1.0f64..1.0),
        z in -0.5f64..0.5,
        tilt in prop::array::uniform2(-0.3f64..0.3),
    ) {
        let surface = Brep::from_surface(bumpy(&heights)).unwrap();
        let normal = Vector3::new(tilt[0], tilt[1], 1.0);
        let plane = Plane::from_normal(Point3::new(1.5, 1.5, z), normal).unwrap();
        let x = surface.intersect_brep(&sheet(&plane, 9.0), TOL).unwrap();
        let section = surface.intersect_plane(&plane, TOL).unwrap();
        let (got, want) = (total_length(&x.curves), total_length(&section.curves));
        prop_assert!((got - want).abs() < 1e-8 * want.max(1.0), "length {got} against {want}");
        prop_assert_eq!(x.curves.len(), section.curves.len());
        prop_assert!(worst_distance(&x.curves, &surface) < 10.0 * TOL);
    }
}

/// The length of the curves' projection on the world XY plane, by dense polylines.
fn projected_length(curves: &[Curve]) -> f64 {
    let mut total = 0.0;
    for c in curves {
        let n = 20_000;
        let flat = |k: usize| {
            let p = c.point_at(c.domain().parameter_at(k as f64 / n as f64));
            Point3::new(p.x, p.y, 0.0)
        };
        total += (0..n).map(|k| flat(k).distance(flat(k + 1))).sum::<f64>();
    }
    total
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(32))]

    /// Two free-form surfaces that are both graphs over the same square (their control points
    /// lie on the same grid, so `x` and `y` are linear in the parameters): they meet where the
    /// difference of their heights vanishes, which is the section by `z = 0` of the surface
    /// with the differences of their heights. The curves' projection on XY is that section.
    #[test]
    fn two_free_form_graphs_meet_where_their_heights_agree(
        a in prop::array::uniform16(-1.0f64..1.0),
        b in prop::array::uniform16(-1.0f64..1.0),
    ) {
        let difference: [f64; 16] = std::array::from_fn(|k| a[k] - b[k]);
        let (sa, sb) = (
            Brep::from_surface(bumpy(&a)).unwrap(),
            Brep::from_surface(bumpy(&b)).unwrap(),
        );
        let x = sa.intersect_brep(&sb, TOL).unwrap();
        let section = Brep::from_surface(bumpy(&difference))
            .unwrap()
            .intersect_plane(&Plane::WORLD_XY, TOL)
            .unwrap();
        prop_assert_eq!(x.curves.len(), section.curves.len());
        let (got, want) = (projected_length(&x.curves), total_length(&section.curves));
        prop_assert!((got - want).abs() < 1e-6 * want.max(1.0), "length {got} against {want}");
        prop_assert!(worst_distance(&x.curves, &sa) < 10.0 * TOL);
        prop_assert!(worst_distance(&x.curves, &sb) < 10.0 * TOL);
    }
}

/// The square `[−3, 3]²` in the world XY plane with a round hole of radius 1 about the origin:
/// a trimmed planar face.
fn square_with_hole() -> Brep {
    let square = locus_kernel::Polyline::new(vec![
        Point3::new(-3.0, -3.0, 0.0),
        Point3::new(3.0, -3.0, 0.0),
        Point3::new(3.0, 3.0, 0.0),
        Point3::new(-3.0, 3.0, 0.0),
        Point3::new(-3.0, -3.0, 0.0),
    ])
    .unwrap();
    let outer = Curve::from(square).to_nurbs();
    let hole = locus_kernel::Circle::new(Plane::WORLD_XY, 1.0)
        .unwrap()
        .to_nurbs();
    Brep::from_planar_loops(&[vec![outer], vec![hole]], TOL).unwrap()
}

#[test]
fn a_sphere_through_a_face_with_a_hole_keeps_what_lies_on_the_face() {
    let face = square_with_hole();
    // Radius 2: the whole circle lies between the hole and the square's sides.
    let x = face
        .intersect_brep(&sphere(0.0, 0.0, 0.0, 2.0), TOL)
        .unwrap();
    assert_eq!(x.curves.len(), 1);
    assert!(x.curves[0].is_closed());
    assert!((x.curves[0].length() - 4.0 * PI).abs() < 1e-9);
    // Radius 0.5: the circle lies in the hole.
    let x = face
        .intersect_brep(&sphere(0.0, 0.0, 0.0, 0.5), TOL)
        .unwrap();
    assert!(x.curves.is_empty() && x.points.is_empty(), "{x:?}");
    // Radius 3.5: four arcs, each between two sides, where |x| ≤ 3 and |y| ≤ 3, ending exactly
    // on the sides.
    let x = face
        .intersect_brep(&sphere(0.0, 0.0, 0.0, 3.5), TOL)
        .unwrap();
    assert_eq!(x.curves.len(), 4, "{:?}", x.curves);
    let alpha = (3.0f64 / 3.5).acos();
    let arc = (PI / 2.0 - 2.0 * alpha) * 3.5;
    for c in &x.curves {
        assert!(!c.is_closed());
        assert!((c.length() - arc).abs() < 1e-9, "{} {arc}", c.length());
        for end in [c.start_point(), c.end_point()] {
            let on_side = (end.x.abs() - 3.0).abs() < 1e-9 || (end.y.abs() - 3.0).abs() < 1e-9;
            assert!(on_side, "{end:?}");
            assert!((end.x.hypot(end.y) - 3.5).abs() < 1e-9);
        }
    }
}

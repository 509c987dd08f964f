use super::*;
use crate::surface::tests::wavy;
use crate::{Cone, Interval, Plane, Sphere, Vector3};

/// The smallest distance over a dense grid, as an upper bound for the closest point.
fn brute_force(s: &NurbsSurface, p: Point3, n: usize) -> f64 {
    let mut best = f64::INFINITY;
    for i in 0..=n {
        for j in 0..=n {
            let u = s.domain_u().parameter_at(i as f64 / n as f64);
            let v = s.domain_v().parameter_at(j as f64 / n as f64);
            best = best.min(s.point_at(u, v).distance(p));
        }
    }
    best
}

#[test]
fn plane_interior_edge_and_corner() {
    let s = NurbsSurface::from_plane(
        &Plane::WORLD_XY,
        Interval::new(0.0, 4.0),
        Interval::new(0.0, 2.0),
    )
    .unwrap();
    let cp = s.closest_point(Point3::new(1.0, 1.5, 3.0)).unwrap();
    assert_eq!((cp.u, cp.v, cp.distance), (1.0, 1.5, 3.0));
    let cp = s.closest_point(Point3::new(2.0, -1.0, 0.0)).unwrap();
    assert!((cp.u - 2.0).abs() < 1e-15 && cp.v == 0.0 && (cp.distance - 1.0).abs() < 1e-15);
    let cp = s.closest_point(Point3::new(7.0, 6.0, 0.0)).unwrap();
    assert_eq!((cp.u, cp.v, cp.distance), (4.0, 2.0, 5.0));
}

#[test]
fn never_farther_than_a_dense_sample() {
    for rational in [false, true] {
        let s = wavy(rational);
        for p in [
            Point3::new(3.0, 2.0, 4.0),
            Point3::new(-2.0, -1.0, 0.0),
            Point3::new(9.0, 5.0, -3.0),
            Point3::new(3.3, 1.6, 0.1),
            Point3::new(100.0, -50.0, 20.0),
        ] {
            let cp = s.closest_point(p).unwrap();
            assert!(cp.point.distance(s.point_at(cp.u, cp.v)) < 1e-14);
            assert!((cp.point.distance(p) - cp.distance).abs() < 1e-14);
            let sampled = brute_force(&s, p, 200);
            assert!(
                cp.distance <= sampled + 1e-12,
                "{p:?}: {} vs {sampled}",
                cp.distance
            );
        }
    }
}

#[test]
fn the_polish_ends_at_rounding_level() {
    // Test points on the normals of interior points: the foot is the closest point, and
    // the answer must be it to rounding level in the parameters.
    for rational in [false, true] {
        let s = wavy(rational);
        for (u, v, h) in [(0.3, -0.2, 0.4), (1.1, 1.7, -0.3), (1.7, 2.5, 0.05)] {
            let foot = s.point_at(u, v);
            let normal = s.normal_at(u, v).unwrap();
            let cp = s.closest_point(foot + normal * h).unwrap();
            assert!(
                (cp.u - u).abs() <= 1e-13 && (cp.v - v).abs() <= 1e-13,
                "({u}, {v}) found as ({}, {})",
                cp.u,
                cp.v
            );
        }
    }
}

#[test]
fn random_queries_are_never_farther_than_a_dense_sample() {
    // A fixed linear congruential sequence of queries around the wavy surfaces.
    let mut state = 29u64;
    let mut r = || {
        state = state
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    for rational in [false, true] {
        let s = wavy(rational);
        for _ in 0..150 {
            let p = Point3::new(-2.0 + 10.0 * r(), -2.0 + 8.0 * r(), -3.0 + 6.0 * r());
            let cp = s.closest_point(p).unwrap();
            let sampled = brute_force(&s, p, 120);
            assert!(
                cp.distance <= sampled + 1e-12,
                "{p:?}: {} vs {sampled}",
                cp.distance
            );
        }
    }
}

#[test]
fn bezier_patch_boxes_hold_their_patches() {
    for rational in [false, true] {
        let s = wavy(rational);
        let (bu, bv) = (
            s.span_breaks(SurfaceDirection::U),
            s.span_breaks(SurfaceDirection::V),
        );
        let spans_u: Vec<usize> = bu[..bu.len() - 1]
            .iter()
            .map(|&t| span_index(s.degree_u(), s.knots_u(), t))
            .collect();
        let spans_v: Vec<usize> = bv[..bv.len() - 1]
            .iter()
            .map(|&t| span_index(s.degree_v(), s.knots_v(), t))
            .collect();
        let mut patches = BezierPatches::new(&s, &spans_u, &spans_v);
        for (ia, a) in bu.windows(2).enumerate() {
            for (ib, b) in bv.windows(2).enumerate() {
                let patch = patches.get(ia, ib);
                for i in 0..=6 {
                    for j in 0..=6 {
                        let u = a[0] + (a[1] - a[0]) * i as f64 / 6.0;
                        let v = b[0] + (b[1] - b[0]) * j as f64 / 6.0;
                        let d = patch.box_distance_squared(s.point_at(u, v));
                        assert!(d <= 1e-26, "({u}, {v}): {d}");
                    }
                }
                let above = s.point_at(a[0], b[0]) + Vector3::new(0.0, 0.0, 40.0);
                assert!(patch.box_distance_squared(above) > 1.0);
            }
        }
    }
}

#[test]
fn crease_is_found() {
    // A degree-1 fold along v = 1: the nearest point to a point outside the fold is on it.
    let s = NurbsSurface::non_rational(
        1,
        1,
        vec![
            vec![
                Point3::new(0.0, 0.0, 0.0),
                Point3::new(0.0, 1.0, 1.0),
                Point3::new(0.0, 2.0, 0.0),
            ],
            vec![
                Point3::new(1.0, 0.0, 0.0),
                Point3::new(1.0, 1.0, 1.0),
                Point3::new(1.0, 2.0, 0.0),
            ],
        ],
        vec![0.0, 1.0],
        vec![0.0, 1.0, 2.0],
    )
    .unwrap();
    let cp = s.closest_point(Point3::new(0.5, 1.0, 3.0)).unwrap();
    assert!((cp.v - 1.0).abs() < 1e-12 && (cp.u - 0.5).abs() < 1e-12);
    assert!((cp.distance - 2.0).abs() < 1e-12);
}

#[test]
fn sphere_and_cone_special_points() {
    let c = Point3::new(1.0, -2.0, 0.5);
    let sphere = Sphere::new(c, 2.0).unwrap().to_nurbs().unwrap();
    // From the centre every point is at the radius.
    let cp = sphere.closest_point(c).unwrap();
    assert!((cp.distance - 2.0).abs() < 1e-12);
    // On the axis above the north pole the pole itself.
    let cp = sphere
        .closest_point(c + Vector3::new(0.0, 0.0, 5.0))
        .unwrap();
    assert!((cp.distance - 3.0).abs() < 1e-12);
    assert!(cp.point.distance(c + Vector3::new(0.0, 0.0, 2.0)) < 1e-12);
    // A cone's apex from behind it.
    let cone = Cone::new(Plane::WORLD_XY, 2.0, 1.0)
        .unwrap()
        .to_nurbs()
        .unwrap();
    let cp = cone.closest_point(Point3::new(0.1, 0.0, -3.0)).unwrap();
    assert!(cp.point.distance(Point3::ORIGIN) < 1e-12 && cp.v == 0.0);
}

#[test]
fn restricted_search_and_bad_input() {
    let s = wavy(false);
    let p = Point3::new(3.0, 2.0, 4.0);
    let whole = s.closest_point(p).unwrap();
    let part = s.closest_point_in(p, [0.0, 0.5], [-1.0, 0.0]).unwrap();
    assert!(part.distance >= whole.distance);
    assert!(part.u <= 0.5 && part.v <= 0.0);
    assert!(s.closest_point(Point3::new(f64::NAN, 0.0, 0.0)).is_err());
    assert!(s.closest_point_in(p, [1.0, 0.0], [0.0, 1.0]).is_err());
}

//! Property tests for NURBS surfaces: curvature of the analytic forms, derivatives against
//! finite differences, global closest points against sampling, reparameterization and grid
//! evaluation.

use locus_kernel::{
    Cylinder, Interval, NurbsSurface, Plane, Point3, Sphere, SurfaceDirection, Vector3,
};
use proptest::prelude::*;

fn coordinate() -> impl Strategy<Value = f64> {
    -10.0..10.0f64
}

fn point() -> impl Strategy<Value = Point3> {
    (coordinate(), coordinate(), coordinate()).prop_map(|(x, y, z)| Point3::new(x, y, z))
}

/// A plane with a random origin and a random (non-degenerate) normal.
fn plane() -> impl Strategy<Value = Plane> {
    (point(), -1.0..1.0f64, -1.0..1.0f64, -1.0..1.0f64)
        .prop_filter_map("normal too short", |(o, x, y, z)| {
            Plane::from_normal(o, Vector3::new(x, y, z + 0.01)).ok()
        })
}

/// A random surface of degree 1 to 3 in each direction on a perturbed grid, with random
/// interior knots and optionally random weights.
fn surface() -> impl Strategy<Value = NurbsSurface> {
    (
        1usize..=3,
        1usize..=3,
        0usize..=2,
        0usize..=2,
        any::<bool>(),
    )
        .prop_flat_map(|(p, q, extra_u, extra_v, rational)| {
            let (nu, nv) = (p + 1 + extra_u, q + 1 + extra_v);
            (
                prop::collection::vec(-1.0..1.0f64, nu * nv * 3),
                prop::collection::vec(0.3..3.0f64, nu * nv),
                prop::collection::vec(0.1..1.0f64, extra_u),
                prop::collection::vec(0.1..1.0f64, extra_v),
            )
                .prop_map(move |(offsets, weights, gaps_u, gaps_v)| {
                    let points = (0..nu)
                        .map(|i| {
                            (0..nv)
                                .map(|j| {
                                    let k = 3 * (i * nv + j);
                                    Point3::new(
                                        i as f64 + 0.3 * offsets[k],
                                        j as f64 + 0.3 * offsets[k + 1],
                                        offsets[k + 2],
                                    )
                                })
                                .collect()
                        })
                        .collect();
                    let weights = (0..nu)
                        .map(|i| {
                            (0..nv)
                                .map(|j| if rational { weights[i * nv + j] } else { 1.0 })
                                .collect()
                        })
                        .collect();
                    NurbsSurface::new(
                        p,
                        q,
                        points,
                        weights,
                        clamped_knots(p, &gaps_u),
                        clamped_knots(q, &gaps_v),
                    )
                    .expect("a valid random surface")
                })
        })
}

/// Rhino-form clamped knots of the given degree with interior spans of the given lengths.
fn clamped_knots(degree: usize, gaps: &[f64]) -> Vec<f64> {
    let mut knots = vec![0.0; degree];
    let mut t = 0.0;
    for g in gaps {
        t += g;
        knots.push(t);
    }
    t += 1.0;
    knots.extend(std::iter::repeat_n(t, degree));
    knots
}

fn parameters(s: &NurbsSurface, a: f64, b: f64) -> (f64, f64) {
    (s.domain_u().parameter_at(a), s.domain_v().parameter_at(b))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn sphere_gaussian_curvature_is_one_over_r_squared(
        plane in plane(),
        radius in 0.1..20.0f64,
        a in 0.0..1.0f64,
        b in 0.02..0.98f64,
    ) {
        let s = Sphere::from_plane(plane, radius).unwrap().to_nurbs().unwrap();
        let (u, v) = parameters(&s, a, b);
        let c = s.curvature_at(u, v).unwrap();
        let k = 1.0 / radius;
        prop_assert!((c.gaussian - k * k).abs() <= 1e-9 * (k * k).max(1.0));
        // Outward normals: the sphere bends away from N, so both curvatures are −1/r.
        prop_assert!((c.k1 + k).abs() <= 1e-9 * k.max(1.0));
        prop_assert!((c.k2 + k).abs() <= 1e-9 * k.max(1.0));
        prop_assert!((c.mean + k).abs() <= 1e-9 * k.max(1.0));
        let outward = (s.point_at(u, v) - plane.origin) / radius;
        prop_assert!((c.normal - outward).length() < 1e-12);
    }

    #[test]
    fn cylinder_principal_curvatures_are_zero_and_minus_one_over_r(
        plane in plane(),
        radius in 0.1..20.0f64,
        height in 0.5..30.0f64,
        a in 0.0..1.0f64,
        b in 0.0..1.0f64,
    ) {
        let s = Cylinder::new(plane, radius, height).unwrap().to_nurbs().unwrap();
        let (u, v) = parameters(&s, a, b);
        let c = s.curvature_at(u, v).unwrap();
        let k = 1.0 / radius;
        prop_assert!(c.k1.abs() <= 1e-9 * k.max(1.0), "k1 {}", c.k1);
        prop_assert!((c.k2 + k).abs() <= 1e-9 * k.max(1.0), "k2 {} vs {}", c.k2, -k);
        prop_assert!(c.gaussian.abs() <= 1e-9 * (k * k).max(1.0));
        prop_assert!((c.direction1.dot(plane.z_axis).abs() - 1.0).abs() < 1e-9);
    }

    #[test]
    fn derivatives_agree_with_finite_differences(
        s in surface(),
        a in 0.05..0.95f64,
        b in 0.05..0.95f64,
    ) {
        let (u, v) = parameters(&s, a, b);
        let d = s.derivatives_at(u, v, 2).unwrap();
        let h = 1e-6;
        let p = |du: f64, dv: f64| s.point_at(u + du, v + dv);
        let d1 = |du: f64, dv: f64| s.derivatives_at(u + du, v + dv, 1).unwrap();
        // One-sided differences towards the span containing (u, v), so that knots do not
        // spoil them: derivatives at a knot are those of the span that starts there.
        let fd_u = (p(h, 0.0) - p(0.0, 0.0)) / h;
        let fd_v = (p(0.0, h) - p(0.0, 0.0)) / h;
        let scale = 1.0 + d.du.length() + d.dv.length() + d.duu.length() + d.dvv.length()
            + d.duv.length();
        prop_assert!((d.du - fd_u).length() < 1e-4 * scale, "{:?} vs {:?}", d.du, fd_u);
        prop_assert!((d.dv - fd_v).length() < 1e-4 * scale);
        let fd_uu = (d1(h, 0.0).du - d1(0.0, 0.0).du) / h;
        let fd_uv = (d1(0.0, h).du - d1(0.0, 0.0).du) / h;
        let fd_vv = (d1(0.0, h).dv - d1(0.0, 0.0).dv) / h;
        let scale2 = scale * scale * scale;
        prop_assert!((d.duu - fd_uu).length() < 1e-3 * scale2, "{:?} vs {:?}", d.duu, fd_uu);
        prop_assert!((d.duv - fd_uv).length() < 1e-3 * scale2);
        prop_assert!((d.dvv - fd_vv).length() < 1e-3 * scale2);
    }

    #[test]
    fn closest_point_is_no_farther_than_any_sample(s in surface(), test in point()) {
        let cp = s.closest_point(test).unwrap();
        prop_assert!(s.domain_u().contains(cp.u) && s.domain_v().contains(cp.v));
        prop_assert!(cp.point.distance(s.point_at(cp.u, cp.v)) < 1e-12);
        let n = 60;
        for i in 0..=n {
            for j in 0..=n {
                let (u, v) = parameters(&s, i as f64 / n as f64, j as f64 / n as f64);
                let d = s.point_at(u, v).distance(test);
                prop_assert!(cp.distance <= d + 1e-10, "sample ({u}, {v}) at {d} beats {}", cp.distance);
            }
        }
    }

    #[test]
    fn reparameterizing_keeps_every_point(
        s in surface(),
        u0 in -5.0..5.0f64,
        lu in 0.1..10.0f64,
        v0 in -5.0..5.0f64,
        lv in 0.1..10.0f64,
        a in 0.0..1.0f64,
        b in 0.0..1.0f64,
    ) {
        let r = s.reparameterized(Interval::new(u0, u0 + lu), Interval::new(v0, v0 + lv)).unwrap();
        let (u, v) = parameters(&s, a, b);
        let (ru, rv) = parameters(&r, a, b);
        prop_assert!(r.point_at(ru, rv).distance(s.point_at(u, v)) < 1e-12);
    }

    #[test]
    fn grid_evaluation_equals_pointwise(s in surface(), n in 1usize..12, m in 1usize..12) {
        let us: Vec<f64> = (0..n).map(|i| s.domain_u().parameter_at(i as f64 / n as f64)).collect();
        let vs: Vec<f64> = (0..=m).map(|j| s.domain_v().parameter_at(j as f64 / m as f64)).collect();
        let mut out = vec![Point3::ORIGIN; us.len() * vs.len()];
        s.points_on_grid(&us, &vs, &mut out).unwrap();
        for (i, &u) in us.iter().enumerate() {
            for (j, &v) in vs.iter().enumerate() {
                prop_assert!(out[i * vs.len() + j].distance(s.point_at(u, v)) < 1e-12);
            }
        }
    }

    #[test]
    fn isocurves_lie_on_the_surface(s in surface(), a in 0.0..1.0f64, b in 0.0..1.0f64) {
        let (u, v) = parameters(&s, a, b);
        let along_u = s.isocurve(SurfaceDirection::U, v).unwrap();
        let along_v = s.isocurve(SurfaceDirection::V, u).unwrap();
        prop_assert!(along_u.point_at(u).distance(s.point_at(u, v)) < 1e-12);
        prop_assert!(along_v.point_at(v).distance(s.point_at(u, v)) < 1e-12);
    }
}

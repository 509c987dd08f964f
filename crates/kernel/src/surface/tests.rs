//! Tests of the NURBS surface type, and the test surfaces other modules share.

use super::*;

/// A wavy bicubic test surface over `[0, 2] × [−1, 3]` with interior knots, optionally
/// rational.
pub(crate) fn wavy(rational: bool) -> NurbsSurface {
    let (nu, nv) = (6, 5);
    let mut points = Vec::new();
    let mut weights = Vec::new();
    for i in 0..nu {
        let mut row = Vec::new();
        let mut wrow = Vec::new();
        for j in 0..nv {
            let (x, y) = (i as f64 * 1.3, j as f64 * 0.9);
            row.push(Point3::new(x, y, (x * 0.7).sin() + (y * 1.1).cos() * 0.5));
            wrow.push(if rational {
                1.0 + 0.3 * ((i * 3 + j * 5) % 4) as f64
            } else {
                1.0
            });
        }
        points.push(row);
        weights.push(wrow);
    }
    NurbsSurface::new(
        3,
        3,
        points,
        weights,
        vec![0.0, 0.0, 0.0, 0.5, 1.2, 2.0, 2.0, 2.0],
        vec![-1.0, -1.0, -1.0, 1.0, 3.0, 3.0, 3.0],
    )
    .unwrap()
}

fn grid(nu: usize, nv: usize) -> Vec<Vec<Point3>> {
    (0..nu)
        .map(|i| {
            (0..nv)
                .map(|j| Point3::new(i as f64, j as f64, 0.0))
                .collect()
        })
        .collect()
}

#[test]
fn constructor_reports_each_problem() {
    let ok = |g| NurbsSurface::non_rational(1, 1, g, vec![0.0, 1.0], vec![0.0, 1.0]);
    assert!(ok(grid(2, 2)).is_ok());
    assert!(matches!(
        NurbsSurface::non_rational(0, 1, grid(2, 2), vec![0.0], vec![0.0, 1.0]),
        Err(Error::InvalidDegree { degree: 0, .. })
    ));
    assert!(matches!(
        NurbsSurface::non_rational(2, 1, grid(2, 2), vec![0.0, 0.0, 1.0], vec![0.0, 1.0]),
        Err(Error::TooFewPoints {
            needed: 3,
            got: 2,
            ..
        })
    ));
    assert!(matches!(
        NurbsSurface::non_rational(1, 1, grid(2, 2), vec![0.0, 1.0, 2.0], vec![0.0, 1.0]),
        Err(Error::InvalidKnots { .. })
    ));
    assert!(matches!(
        NurbsSurface::non_rational(1, 1, grid(3, 2), vec![0.0, 2.0, 1.0], vec![0.0, 1.0]),
        Err(Error::InvalidKnots { .. })
    ));
    assert!(matches!(
        NurbsSurface::non_rational(1, 1, grid(3, 2), vec![0.0, 1.0, 1.0], vec![0.0, 1.0]),
        Err(Error::InvalidKnots { .. })
    ));
    assert!(matches!(
        NurbsSurface::non_rational(1, 1, grid(2, 2), vec![1.0, 1.0], vec![0.0, 1.0]),
        Err(Error::InvalidKnots { .. })
    ));
    assert!(matches!(
        NurbsSurface::non_rational(1, 1, grid(2, 2), vec![0.0, f64::NAN], vec![0.0, 1.0]),
        Err(Error::NotFinite { .. })
    ));
    let mut ragged = grid(2, 2);
    ragged[1].pop();
    assert!(matches!(ok(ragged), Err(Error::InvalidInput(_))));
    let mut nan = grid(2, 2);
    nan[1][1].z = f64::INFINITY;
    assert!(matches!(ok(nan), Err(Error::NotFinite { .. })));
    let weights = vec![vec![1.0, 1.0], vec![1.0, 0.0]];
    assert!(matches!(
        NurbsSurface::new(1, 1, grid(2, 2), weights, vec![0.0, 1.0], vec![0.0, 1.0]),
        Err(Error::InvalidWeight { index: 3, .. })
    ));
    assert!(matches!(
        NurbsSurface::new(
            1,
            1,
            grid(2, 2),
            vec![vec![1.0; 2]],
            vec![0.0, 1.0],
            vec![0.0, 1.0]
        ),
        Err(Error::InvalidInput(_))
    ));
}

#[test]
fn bilinear_patch_interpolates_its_corners() {
    let s = NurbsSurface::non_rational(
        1,
        1,
        vec![
            vec![Point3::new(0.0, 0.0, 0.0), Point3::new(0.0, 2.0, 0.0)],
            vec![Point3::new(4.0, 0.0, 0.0), Point3::new(4.0, 2.0, 8.0)],
        ],
        vec![0.0, 1.0],
        vec![0.0, 1.0],
    )
    .unwrap();
    assert_eq!(s.point_at(0.5, 0.5), Point3::new(2.0, 1.0, 2.0));
    assert_eq!(s.point_at(1.0, 1.0), Point3::new(4.0, 2.0, 8.0));
    let d = s.derivatives_at(0.5, 0.5, 2).unwrap();
    assert_eq!(d.du, Vector3::new(4.0, 0.0, 4.0));
    assert_eq!(d.dv, Vector3::new(0.0, 2.0, 4.0));
    assert_eq!(d.duv, Vector3::new(0.0, 0.0, 8.0));
    assert_eq!(d.duu, Vector3::ZERO);
    assert!(s.is_valid() && s.is_finite() && !s.is_rational());
}

#[test]
fn bad_parameters_are_reported() {
    let s = wavy(true);
    assert!(s.try_point_at(f64::NAN, 0.0).is_err());
    assert!(s.try_point_at(0.0, f64::INFINITY).is_err());
    assert!(s.derivatives_at(0.0, f64::NAN, 1).is_err());
    assert!(matches!(
        s.derivatives_at(0.0, 0.0, 3),
        Err(Error::InvalidInput(_))
    ));
}

#[test]
fn corners_are_corner_control_points() {
    for rational in [false, true] {
        let s = wavy(rational);
        let (du, dv) = (s.domain_u(), s.domain_v());
        assert_eq!(du, Interval::new(0.0, 2.0));
        assert_eq!(dv, Interval::new(-1.0, 3.0));
        let corner = |u, v| s.point_at(u, v);
        assert!(corner(du.t0, dv.t0).distance(s.control_point(0, 0).unwrap()) < 1e-15);
        assert!(corner(du.t1, dv.t1).distance(s.control_point(5, 4).unwrap()) < 1e-14);
        assert!(s.control_point(6, 0).is_none() && s.weight(0, 5).is_none());
    }
}

#[test]
fn derivatives_match_finite_differences() {
    let h = 1e-5;
    for rational in [false, true] {
        let s = wavy(rational);
        for &(u, v) in &[(0.3, -0.5), (0.9, 1.7), (1.7, 2.6), (0.55, 1.05)] {
            let d = s.derivatives_at(u, v, 2).unwrap();
            assert!(d.point.distance(s.point_at(u, v)) < 1e-14);
            let p = |du: f64, dv: f64| s.point_at(u + du, v + dv);
            let fd_u = (p(h, 0.0) - p(-h, 0.0)) / (2.0 * h);
            let fd_v = (p(0.0, h) - p(0.0, -h)) / (2.0 * h);
            assert!((d.du - fd_u).length() < 1e-8, "{:?} {:?}", d.du, fd_u);
            assert!((d.dv - fd_v).length() < 1e-8);
            // Second derivatives from differences of the exact first derivatives.
            let d1 = |du: f64, dv: f64| s.derivatives_at(u + du, v + dv, 1).unwrap();
            let fd_uu = (d1(h, 0.0).du - d1(-h, 0.0).du) / (2.0 * h);
            let fd_uv = (d1(0.0, h).du - d1(0.0, -h).du) / (2.0 * h);
            let fd_vv = (d1(0.0, h).dv - d1(0.0, -h).dv) / (2.0 * h);
            assert!(
                (d.duu - fd_uu).length() < 1e-7,
                "{u} {v} {rational} {:?} {:?}",
                d.duu,
                fd_uu
            );
            assert!((d.duv - fd_uv).length() < 1e-7);
            assert!((d.dvv - fd_vv).length() < 1e-7);
        }
    }
}

#[test]
fn fast_basis_derivatives_match_a2_3() {
    use crate::curve::nurbs::basis::basis_function_derivatives;
    let cases: [(usize, &[f64]); 5] = [
        (1, &[0.0, 0.5, 1.0]),
        (2, &[0.0, 0.0, 0.3, 0.3, 1.0, 1.0]),
        (3, &[0.0, 0.0, 0.0, 0.2, 0.5, 0.5, 1.0, 1.0, 1.0]),
        (4, &[-1.0, -1.0, -1.0, -1.0, 0.0, 2.0, 2.0, 2.0, 2.0]),
        (5, &[0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0, 1.0]),
    ];
    for (p, knots) in cases {
        let n = knots.len() - p + 1;
        let (a, b) = (knots[p - 1], knots[n - 1]);
        for k in 0..=40 {
            let t = a + (b - a) * k as f64 / 40.0;
            let span = span_index(p, knots, t);
            let mut reference = [[0.0; MAX_ORDER]; 3];
            basis_function_derivatives(p, knots, span, t, 2, &mut reference);
            let mut fast = [[0.0; MAX_ORDER]; 3];
            basis_with_derivatives(p, knots, span, t, &mut fast);
            for order in 0..3 {
                for r in 0..=p {
                    let (x, y) = (fast[order][r], reference[order][r]);
                    assert!(
                        (x - y).abs() <= 1e-12 * (1.0 + y.abs()),
                        "degree {p}, t {t}, order {order}, function {r}: {x} vs {y}"
                    );
                }
            }
        }
    }
}

#[test]
fn spans_and_creases() {
    let s = NurbsSurface::non_rational(
        2,
        1,
        grid(5, 3),
        vec![0.0, 0.0, 1.0, 1.0, 2.0, 2.0],
        vec![0.0, 0.5, 1.0],
    )
    .unwrap();
    assert_eq!(s.span_breaks(SurfaceDirection::U), vec![0.0, 1.0, 2.0]);
    assert_eq!(s.c0_knots(SurfaceDirection::U), vec![1.0]);
    assert_eq!(s.span_breaks(SurfaceDirection::V), vec![0.0, 0.5, 1.0]);
    assert_eq!(s.c0_knots(SurfaceDirection::V), vec![0.5]);
    assert!(wavy(false).c0_knots(SurfaceDirection::U).is_empty());
}

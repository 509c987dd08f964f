use super::*;

fn book_curve() -> NurbsCurve {
    let pts = [
        [0.0, 0.0, 0.0],
        [1.0, 3.0, 0.0],
        [3.0, 4.0, 1.0],
        [5.0, 2.0, 0.0],
        [7.0, 5.0, 2.0],
        [9.0, 1.0, 0.0],
        [10.0, 4.0, 1.0],
    ]
    .map(|[x, y, z]| Point3::new(x, y, z));
    NurbsCurve::new_non_rational(
        3,
        pts.to_vec(),
        vec![0.0, 0.0, 0.0, 0.25, 0.5, 0.75, 1.0, 1.0, 1.0],
    )
    .unwrap()
}

fn near(a: Point3, b: Point3, tol: f64) -> bool {
    a.distance(b) <= tol
}

#[test]
fn book_de_boor_at_0_4() {
    // The book's de Boor scheme, with its knot numbering u0..u8 (the full form minus the two
    // superfluous end knots is exactly the Rhino form).
    let c = book_curve();
    let u = |i: usize| c.knots()[i];
    let p = c.points();
    let t = 0.4;
    let ac = (t - u(1)) / (u(4) - u(1));
    let bc = (t - u(2)) / (u(5) - u(2));
    let cc = (t - u(3)) / (u(6) - u(3));
    assert!((ac - 0.8).abs() < 1e-12);
    assert!((bc - 0.5333333333333333).abs() < 1e-12);
    assert!((cc - 0.2).abs() < 1e-12);
    let a = p[1].lerp(p[2], ac);
    let b = p[2].lerp(p[3], bc);
    let cpt = p[3].lerp(p[4], cc);
    let dc = (t - u(2)) / (u(4) - u(2));
    let ec = (t - u(3)) / (u(5) - u(3));
    assert!((dc - 0.8).abs() < 1e-12);
    assert!((ec - 0.3).abs() < 1e-12);
    let d = a.lerp(b, dc);
    let e = b.lerp(cpt, ec);
    let fc = (t - u(3)) / (u(4) - u(3));
    assert!((fc - 0.6).abs() < 1e-12);
    let f = d.lerp(e, fc);
    let expected = Point3::new(4.189333333333334, 2.942666666666667, 0.4813333333333334);
    assert!(near(f, expected, 1e-14));
    assert!(near(c.point_at(0.4), expected, 1e-14));
}

#[test]
fn domain_and_ends() {
    let c = book_curve();
    assert_eq!(c.domain(), Interval::new(0.0, 1.0));
    assert_eq!(c.start_point(), Point3::new(0.0, 0.0, 0.0));
    assert_eq!(c.end_point(), Point3::new(10.0, 4.0, 1.0));
    assert_eq!(c.span_count(), 4);
    assert_eq!(c.span_breaks(), vec![0.0, 0.25, 0.5, 0.75, 1.0]);
    assert!(!c.is_rational());
    assert!(!c.is_closed());
    assert!(!c.is_periodic());
}

#[test]
fn validation_errors() {
    let pts: Vec<Point3> = (0..4).map(|i| Point3::new(i as f64, 0.0, 0.0)).collect();
    let w = vec![1.0; 4];
    let k = vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0];
    assert!(NurbsCurve::new(3, pts.clone(), w.clone(), k.clone()).is_ok());
    assert!(matches!(
        NurbsCurve::new(0, pts.clone(), w.clone(), k.clone()),
        Err(Error::InvalidDegree { .. })
    ));
    assert!(matches!(
        NurbsCurve::new(16, pts.clone(), w.clone(), k.clone()),
        Err(Error::InvalidDegree { .. })
    ));
    assert!(matches!(
        NurbsCurve::new(3, pts[..3].to_vec(), w[..3].to_vec(), k[..5].to_vec()),
        Err(Error::TooFewPoints {
            needed: 4,
            got: 3,
            ..
        })
    ));
    assert!(matches!(
        NurbsCurve::new(3, pts.clone(), w.clone(), k[..5].to_vec()),
        Err(Error::InvalidKnots { .. })
    ));
    assert!(matches!(
        NurbsCurve::new(
            3,
            pts.clone(),
            w.clone(),
            vec![0.0, 0.0, 0.0, 1.0, 0.5, 1.0]
        ),
        Err(Error::InvalidKnots { .. })
    ));
    assert!(matches!(
        NurbsCurve::new(2, pts.clone(), w.clone(), vec![0.0, 0.0, 0.0, 1.0, 1.0]),
        Err(Error::InvalidKnots { .. })
    ));
    assert!(matches!(
        NurbsCurve::new(3, pts.clone(), vec![1.0, 0.0, 1.0, 1.0], k.clone()),
        Err(Error::InvalidWeight { index: 1, .. })
    ));
    assert!(matches!(
        NurbsCurve::new(3, pts.clone(), vec![1.0, 1.0, f64::NAN, 1.0], k.clone()),
        Err(Error::InvalidWeight { index: 2, .. })
    ));
    assert!(matches!(
        NurbsCurve::new(3, pts.clone(), vec![1.0; 3], k.clone()),
        Err(Error::InvalidInput(_))
    ));
    let mut bad = pts.clone();
    bad[2].y = f64::NAN;
    assert!(matches!(
        NurbsCurve::new(3, bad, w.clone(), k.clone()),
        Err(Error::NotFinite { .. })
    ));
    assert!(matches!(
        NurbsCurve::new(
            3,
            pts.clone(),
            w.clone(),
            vec![0.0, 0.0, 0.0, 1.0, 1.0, f64::NAN]
        ),
        Err(Error::InvalidKnots { .. })
    ));
    assert!(matches!(
        NurbsCurve::new(3, pts, w, vec![0.0; 6]),
        Err(Error::InvalidKnots { .. })
    ));
}

#[test]
fn nan_parameter_is_reported_by_try_point_at() {
    let c = book_curve();
    assert!(c.point_at(f64::NAN).is_nan());
    assert_eq!(
        c.try_point_at(f64::NAN),
        Err(Error::NotFinite { what: "parameter" })
    );
}

#[test]
fn derivatives_match_finite_differences() {
    let c = NurbsCurve::new(
        2,
        vec![
            Point3::new(0.0, 0.0, 0.0),
            Point3::new(1.0, 2.0, 0.5),
            Point3::new(3.0, -1.0, 1.0),
            Point3::new(4.0, 1.0, 0.0),
        ],
        vec![1.0, 2.5, 0.7, 1.3],
        vec![0.0, 0.0, 1.3, 2.0, 2.0],
    )
    .unwrap();
    let h = 1e-5;
    for &t in &[0.1, 0.7, 1.6, 1.9] {
        let d = c.derivatives_at(t, 3);
        let pp = c.point_at(t + h);
        let pm = c.point_at(t - h);
        let p0 = c.point_at(t);
        let fd1 = (pp - pm) / (2.0 * h);
        let fd2 = ((pp - p0) - (p0 - pm)) / (h * h);
        assert!(
            (d[1] - fd1).length() < 1e-6 * d[1].length().max(1.0),
            "t {t}"
        );
        assert!(
            (d[2] - fd2).length() < 1e-3 * d[2].length().max(1.0),
            "t {t}"
        );
        let (_, _, d2p) = c.point_and_derivatives_at(t + h);
        let (_, _, d2m) = c.point_and_derivatives_at(t - h);
        let fd3 = (d2p - d2m) / (2.0 * h);
        assert!(
            (d[3] - fd3).length() < 1e-4 * d[3].length().max(1.0),
            "t {t}"
        );
    }
}

#[test]
fn tangent_uses_higher_derivative_when_first_vanishes() {
    // A doubled first control point makes C'(0) = 0; the tangent comes from C''.
    let c = NurbsCurve::new_non_rational(
        3,
        vec![
            Point3::new(0.0, 0.0, 0.0),
            Point3::new(0.0, 0.0, 0.0),
            Point3::new(1.0, 1.0, 0.0),
            Point3::new(2.0, 0.0, 0.0),
        ],
        vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0],
    )
    .unwrap();
    assert!(c.derivative_at(0.0).length() < 1e-15);
    let t = c.tangent_at(0.0).unwrap();
    let expected = Vector3::new(1.0, 1.0, 0.0).try_normalize().unwrap();
    assert!((t - expected).length() < 1e-12);
    // At the end the first derivative is regular.
    assert!(c.tangent_at(1.0).is_some());
}

#[test]
fn signed_curvature_and_frame_on_a_parabola() {
    // y = x² as a quadratic Bézier over [-1, 1]: curvature 2 at the apex, turning left.
    let c = NurbsCurve::new_non_rational(
        2,
        vec![
            Point3::new(-1.0, 1.0, 0.0),
            Point3::new(0.0, -1.0, 0.0),
            Point3::new(1.0, 1.0, 0.0),
        ],
        vec![0.0, 0.0, 1.0, 1.0],
    )
    .unwrap();
    let k = c.signed_curvature_at(0.5, Vector3::Z).unwrap();
    assert!((k - 2.0).abs() < 1e-12);
    let kv = c.curvature_at(0.5).unwrap();
    assert!((kv - Vector3::new(0.0, 2.0, 0.0)).length() < 1e-12);
    let f = c.frame_at(0.5).unwrap();
    assert!((f.x_axis - Vector3::X).length() < 1e-12);
    assert!((f.y_axis - Vector3::Y).length() < 1e-12);
    assert!((f.z_axis - Vector3::Z).length() < 1e-12);
    assert!(c.signed_curvature_at(0.5, -Vector3::Z).unwrap() < 0.0);
}

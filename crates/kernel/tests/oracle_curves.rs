//! Replays the curve cases of the oracle files through the kernel.
//!
//! - `opennurbs-cases.json`, sections `curves` and `constructions`: points, first and second
//!   derivatives, unit tangents and curvature vectors at every sample, and the control points and
//!   knots that Rhino builds from input points.
//! - `occt-cases.json`, sections `curve_closest_point` and `arc_length`: global closest points
//!   (ends, kinks and the seam of a periodic curve included) and arc lengths.
//!
//! Every failing case is named and all failures are reported together.

mod support;

use locus_kernel::{NurbsCurve, Point3, Vector3};
use serde_json::Value;
use support::{Failures, close, close3, load_oracle, num, numbers, triple};

/// Agreement required with the oracle values: 1e-9 relative (to `max(1, |expected|)`).
const REL: f64 = 1e-9;

fn point(v: &Value) -> Point3 {
    let [x, y, z] = triple(v);
    Point3::new(x, y, z)
}

/// Builds a curve from an oracle record (`degree`, `cvs` with `p` and `w`, `knots`).
fn curve_from(case: &Value) -> NurbsCurve {
    let degree = case["degree"].as_u64().expect("degree") as usize;
    let cvs = case["cvs"].as_array().expect("cvs");
    let points = cvs.iter().map(|cv| point(&cv["p"])).collect();
    let weights = cvs.iter().map(|cv| num(&cv["w"])).collect();
    let knots = numbers(&case["knots"]);
    NurbsCurve::new(degree, points, weights, knots)
        .unwrap_or_else(|e| panic!("{}: invalid curve: {e}", case["name"]))
}

fn arr(p: Point3) -> [f64; 3] {
    p.to_array()
}

fn varr(v: Vector3) -> [f64; 3] {
    v.to_array()
}

/// Checks every sample of a case (point, d1, d2, tangent, curvature) against `curve`.
fn check_samples(name: &str, curve: &NurbsCurve, case: &Value, failures: &mut Failures) {
    let samples = case["samples"].as_array().expect("samples");
    assert!(!samples.is_empty(), "{name}: no samples");
    for s in samples {
        let t = num(&s["t"]);
        let (p, d1, d2) = curve.point_and_derivatives_at(t);
        let checks: [(&str, [f64; 3], &Value); 3] = [
            ("point", arr(p), &s["point"]),
            ("d1", varr(d1), &s["d1"]),
            ("d2", varr(d2), &s["d2"]),
        ];
        for (what, got, want) in checks {
            let want = triple(want);
            failures.check(close3(got, want, REL), || {
                format!("{name} t={t}: {what} {got:?}, expected {want:?}")
            });
        }
        // The batch path must agree with the single-point path.
        let mut out = [Point3::ORIGIN; 1];
        curve
            .points_at(&[t], &mut out)
            .expect("one parameter, one point");
        failures.check(close3(arr(out[0]), triple(&s["point"]), REL), || {
            format!("{name} t={t}: points_at {:?}", out[0])
        });
        let want_tangent = triple(&s["tangent"]);
        match curve.tangent_at(t) {
            Some(tan) => failures.check(close3(varr(tan), want_tangent, REL), || {
                format!("{name} t={t}: tangent {tan:?}, expected {want_tangent:?}")
            }),
            None => failures.push(format!("{name} t={t}: no tangent")),
        }
        let want_k = triple(&s["curvature"]);
        match curve.curvature_at(t) {
            Some(k) => failures.check(close3(varr(k), want_k, REL), || {
                format!("{name} t={t}: curvature {k:?}, expected {want_k:?}")
            }),
            None => failures.push(format!("{name} t={t}: no curvature")),
        }
    }
}

#[test]
fn opennurbs_curves() {
    let oracle = load_oracle("opennurbs-cases.json");
    let cases = oracle["curves"].as_array().expect("curves");
    assert!(cases.len() >= 15);
    let mut failures = Failures::default();
    for case in cases {
        let name = case["name"].as_str().expect("name");
        let curve = curve_from(case);
        let [d0, d1] = numbers(&case["domain"])[..] else {
            panic!("{name}: bad domain")
        };
        failures.check(curve.domain().t0 == d0 && curve.domain().t1 == d1, || {
            format!("{name}: domain {:?}, expected [{d0}, {d1}]", curve.domain())
        });
        let rational = case["rational"].as_bool().expect("rational");
        failures.check(curve.is_rational() == rational, || {
            format!("{name}: is_rational {}", curve.is_rational())
        });
        let periodic = case["periodic"].as_bool().expect("periodic");
        failures.check(curve.is_periodic() == periodic, || {
            format!("{name}: is_periodic {}", curve.is_periodic())
        });
        check_samples(name, &curve, case, &mut failures);
    }
    failures.finish("opennurbs curve");
}

#[test]
fn opennurbs_constructions() {
    let oracle = load_oracle("opennurbs-cases.json");
    let cases = oracle["constructions"].as_array().expect("constructions");
    assert!(cases.len() >= 6);
    let mut failures = Failures::default();
    for case in cases {
        let name = case["name"].as_str().expect("name");
        // The case records the built curve's periodicity; the call's flag is in the name
        // (Rhino returns a closed, non-periodic polyline for a periodic request of degree 1).
        let requested_periodic = name.starts_with("create-periodic");
        let degree = case["degree"].as_u64().expect("degree") as usize;
        let input: Vec<Point3> = case["input_points"]
            .as_array()
            .expect("input_points")
            .iter()
            .map(point)
            .collect();
        let curve = match NurbsCurve::create(&input, degree, requested_periodic) {
            Ok(c) => c,
            Err(e) => {
                failures.push(format!("{name}: create failed: {e}"));
                continue;
            }
        };
        let expected = curve_from(case);
        failures.check(curve.point_count() == expected.point_count(), || {
            format!(
                "{name}: {} control points, expected {}",
                curve.point_count(),
                expected.point_count()
            )
        });
        failures.check(curve.knots() == expected.knots(), || {
            format!(
                "{name}: knots {:?}, expected {:?}",
                curve.knots(),
                expected.knots()
            )
        });
        for (i, (a, b)) in curve.points().iter().zip(expected.points()).enumerate() {
            failures.check(close3(arr(*a), arr(*b), REL), || {
                format!("{name}: control point {i} {a:?}, expected {b:?}")
            });
        }
        failures.check(curve.weights() == expected.weights(), || {
            format!("{name}: weights {:?}", curve.weights())
        });
        let periodic = case["periodic"].as_bool().expect("periodic");
        failures.check(curve.is_periodic() == periodic, || {
            format!(
                "{name}: is_periodic {}, expected {periodic}",
                curve.is_periodic()
            )
        });
        failures.check(curve.is_closed() == requested_periodic, || {
            format!("{name}: is_closed {}", curve.is_closed())
        });
        check_samples(name, &curve, case, &mut failures);
    }
    failures.finish("opennurbs construction");
}

/// The OCCT file's curves by name.
fn occt_curves(oracle: &Value) -> std::collections::HashMap<String, NurbsCurve> {
    oracle["curves"]
        .as_array()
        .expect("curves")
        .iter()
        .map(|c| (c["name"].as_str().expect("name").to_owned(), curve_from(c)))
        .collect()
}

#[test]
fn occt_curve_closest_points() {
    let oracle = load_oracle("occt-cases.json");
    let curves = occt_curves(&oracle);
    let cases = oracle["curve_closest_point"]
        .as_array()
        .expect("curve_closest_point");
    assert!(cases.len() >= 20);
    let mut failures = Failures::default();
    let mut count = 0;
    for case in cases {
        let name = case["curve"].as_str().expect("curve");
        let curve = &curves[name];
        let span = curve.domain().length();
        for (i, q) in case["queries"]
            .as_array()
            .expect("queries")
            .iter()
            .enumerate()
        {
            count += 1;
            let kind = q["kind"].as_str().unwrap_or("?");
            let label = format!("{name} query {i} ({kind}, at {})", q["at"]);
            let test_point = point(&q["test_point"]);
            let got = match curve.closest_point(test_point) {
                Ok(r) => r,
                Err(e) => {
                    failures.push(format!("{label}: error {e}"));
                    continue;
                }
            };
            let want_d = num(&q["distance"]);
            failures.check(close(got.distance, want_d, REL), || {
                format!("{label}: distance {}, expected {want_d}", got.distance)
            });
            // The parameter and point are unique unless the case lists ties or a seam.
            let mut allowed: Vec<(f64, [f64; 3])> = vec![(num(&q["t"]), triple(&q["point"]))];
            if let Some(ties) = q.get("ties").and_then(Value::as_array) {
                allowed.extend(ties.iter().map(|t| (num(&t["t"]), triple(&t["point"]))));
            }
            if q.get("seam").is_some() {
                let d = curve.domain();
                allowed.push((d.t0, arr(curve.point_at(d.t0))));
                allowed.push((d.t1, arr(curve.point_at(d.t1))));
            }
            let param_ok = allowed
                .iter()
                .any(|(t, _)| (got.t - t).abs() <= 1e-6 * span);
            failures.check(param_ok, || {
                format!("{label}: t {}, expected one of {:?}", got.t, allowed)
            });
            let point_ok = allowed
                .iter()
                .any(|(_, p)| close3(arr(got.point), *p, 1e-6));
            failures.check(point_ok, || {
                format!(
                    "{label}: point {:?}, expected {:?}",
                    got.point, allowed[0].1
                )
            });
        }
    }
    assert!(count >= 100, "only {count} queries");
    failures.finish("occt closest point");
}

#[test]
fn occt_arc_lengths() {
    let oracle = load_oracle("occt-cases.json");
    let curves = occt_curves(&oracle);
    let cases = oracle["arc_length"].as_array().expect("arc_length");
    assert!(cases.len() >= 20);
    let mut failures = Failures::default();
    for case in cases {
        let name = case["curve"].as_str().expect("curve");
        let curve = &curves[name];
        let span = curve.domain().length();
        let want = num(&case["length"]);
        let got = curve.length();
        failures.check(close(got, want, REL), || {
            format!("{name}: length {got}, expected {want}")
        });
        for sub in case["sub_intervals"].as_array().expect("sub_intervals") {
            let (t0, t1) = (num(&sub["t0"]), num(&sub["t1"]));
            let want = num(&sub["length"]);
            match curve.length_between(t0, t1) {
                Ok(got) => failures.check(close(got, want, REL), || {
                    format!("{name}: length over [{t0}, {t1}] {got}, expected {want}")
                }),
                Err(e) => failures.push(format!("{name}: length over [{t0}, {t1}]: {e}")),
            }
        }
        for lp in case["length_parameters"]
            .as_array()
            .expect("length_parameters")
        {
            let fraction = num(&lp["fraction"]);
            let want_t = num(&lp["t"]);
            match curve.parameter_at_normalized_length(fraction) {
                Ok(t) => {
                    failures.check((t - want_t).abs() <= 1e-8 * span, || {
                        format!(
                            "{name}: parameter at {fraction} of the length {t}, expected {want_t}"
                        )
                    });
                    let want_p = triple(&lp["point"]);
                    failures.check(close3(arr(curve.point_at(t)), want_p, 1e-8), || {
                        format!("{name}: point at {fraction} of the length, expected {want_p:?}")
                    });
                }
                Err(e) => failures.push(format!("{name}: parameter at {fraction}: {e}")),
            }
        }
    }
    failures.finish("occt arc length");
}

/// Rhino's circle and arc NURBS forms: the kernel's exact forms must rebuild the oracle's
/// control points, weights and knots.
#[test]
fn opennurbs_exact_forms_of_circle_and_arc() {
    use locus_kernel::{Arc, Circle, Interval, Plane};
    let oracle = load_oracle("opennurbs-cases.json");
    let cases = oracle["curves"].as_array().expect("curves");
    let find = |name: &str| {
        cases
            .iter()
            .find(|c| c["name"] == name)
            .unwrap_or_else(|| panic!("no case {name}"))
    };
    let mut failures = Failures::default();
    let circle = Circle::new(
        Plane {
            origin: Point3::new(1.0, 2.0, 3.0),
            ..Plane::WORLD_XY
        },
        10.0,
    )
    .expect("circle");
    let arc = Arc::new(
        Circle::new(Plane::WORLD_XY, 5.0).expect("circle"),
        Interval::new(0.0, 2.0),
    )
    .expect("arc");
    for (name, built) in [
        ("circle-r10-at-1,2,3", circle.to_nurbs()),
        ("arc-r5-2rad", arc.to_nurbs()),
    ] {
        let expected = curve_from(find(name));
        failures.check(built.knots() == expected.knots(), || {
            format!(
                "{name}: knots {:?}, expected {:?}",
                built.knots(),
                expected.knots()
            )
        });
        failures.check(built.point_count() == expected.point_count(), || {
            format!("{name}: {} control points", built.point_count())
        });
        for (i, ((p, w), (q, v))) in built
            .points()
            .iter()
            .zip(built.weights())
            .zip(expected.points().iter().zip(expected.weights()))
            .enumerate()
        {
            failures.check(close3(arr(*p), arr(*q), REL) && close(*w, *v, REL), || {
                format!("{name}: control point {i} {p:?} w {w}, expected {q:?} w {v}")
            });
        }
        check_samples(name, &built, find(name), &mut failures);
    }
    failures.finish("exact form");
}

//! Replays the curve cases of the shared oracle files through the Curve nodes, as a graph
//! would run them: curves are built by Nurbs Curve PWK and Nurbs Curve, then evaluated by
//! Evaluate Curve, Curvature, Control Points, Length, Evaluate Length and Curve Closest Point.
//!
//! - `opennurbs-cases.json` (openNURBS, Rhino's library): points, unit tangents and curvature
//!   vectors at every sample, and the control points and knots Rhino builds from input points;
//!   agreement 1e-9 relative.
//! - `occt-cases.json` (OpenCASCADE): global closest points and arc lengths, with the file's
//!   suggested tolerances.
//!
//! Every failing case is named and all failures are reported together.

use locus_kernel::{Curve, Point3, Vector3};
use locus_nodes::curve::{analysis, spline};
use locus_runtime::{DataTree, NodeCall, NodeCallResult, Shared, Value};
use serde_json::Value as Json;

const REL: f64 = 1e-9;

fn load(file: &str) -> Json {
    locus_test_data::load_oracle(file)
}

fn num(v: &Json) -> f64 {
    v.as_f64()
        .unwrap_or_else(|| panic!("expected a number, got {v}"))
}

fn triple(v: &Json) -> [f64; 3] {
    let a = v.as_array().expect("array");
    [num(&a[0]), num(&a[1]), num(&a[2])]
}

fn point(v: &Json) -> Point3 {
    let [x, y, z] = triple(v);
    Point3::new(x, y, z)
}

fn vector(v: &Json) -> Vector3 {
    let [x, y, z] = triple(v);
    Vector3::new(x, y, z)
}

fn numbers(v: &Json) -> Vec<f64> {
    v.as_array().expect("array").iter().map(num).collect()
}

/// Whether `a` is within `rel` of `b`, relative to `max(1, |b|)`.
fn close(a: Vector3, b: Vector3, rel: f64) -> bool {
    (a - b).length() <= rel * b.length().max(1.0)
}

#[derive(Default)]
struct Failures(Vec<String>);

impl Failures {
    fn check(&mut self, ok: bool, message: impl FnOnce() -> String) {
        if !ok {
            self.0.push(message());
        }
    }

    fn finish(self, what: &str) {
        assert!(
            self.0.is_empty(),
            "{} {what} failure(s):\n  {}",
            self.0.len(),
            self.0.join("\n  ")
        );
    }
}

fn item(r: &NodeCallResult, output: usize) -> Value {
    let values: Vec<Option<Value>> = r.outputs[output].values().collect();
    assert_eq!(
        values.len(),
        1,
        "one item expected: {values:?} {:?}",
        r.messages
    );
    values[0]
        .clone()
        .unwrap_or_else(|| panic!("null output: {:?}", r.messages))
}

fn as_point(v: Value) -> Vector3 {
    match v {
        Value::Point(p) => p.to_vector(),
        other => panic!("expected a point, got {other:?}"),
    }
}

fn as_vector(v: Value) -> Vector3 {
    match v {
        Value::Vector(p) => p,
        other => panic!("expected a vector, got {other:?}"),
    }
}

fn as_number(v: Value) -> f64 {
    match v {
        Value::Number(x) => x,
        other => panic!("expected a number, got {other:?}"),
    }
}

/// The curve of an oracle record, built by the Nurbs Curve PWK node.
fn pwk(case: &Json) -> Shared<Curve> {
    let cvs = case["cvs"].as_array().expect("cvs");
    let points: Vec<Point3> = cvs.iter().map(|cv| point(&cv["p"])).collect();
    let weights: Vec<f64> = cvs.iter().map(|cv| num(&cv["w"])).collect();
    let r = NodeCall::new(&spline::nurbs_curve_pwk())
        .input(DataTree::from_list(points))
        .input(DataTree::from_list(weights))
        .input(DataTree::from_list(numbers(&case["knots"])))
        .run();
    assert!(r.messages.is_empty(), "{}: {:?}", case["name"], r.messages);
    match item(&r, 0) {
        Value::Curve(c) => c,
        other => panic!("expected a curve, got {other:?}"),
    }
}

/// Checks the samples of an oracle record (point, tangent, curvature) through Evaluate Curve
/// and Curvature.
fn check_samples(name: &str, curve: &Shared<Curve>, case: &Json, failures: &mut Failures) {
    let evaluate = analysis::evaluate_curve();
    let curvature = analysis::curvature();
    for s in case["samples"].as_array().expect("samples") {
        let t = num(&s["t"]);
        let e = NodeCall::new(&evaluate)
            .input(DataTree::from_item(curve.clone()))
            .input(DataTree::from_item(t))
            .run();
        let p = as_point(item(&e, 0));
        let want = point(&s["point"]).to_vector();
        failures.check(close(p, want, REL), || {
            format!("{name} t={t}: point {p:?}, expected {want:?}")
        });
        let tangent = as_vector(item(&e, 1));
        let want = vector(&s["tangent"]);
        failures.check(close(tangent, want, REL), || {
            format!("{name} t={t}: tangent {tangent:?}, expected {want:?}")
        });
        let k = NodeCall::new(&curvature)
            .input(DataTree::from_item(curve.clone()))
            .input(DataTree::from_item(t))
            .run();
        let kv = as_vector(item(&k, 1));
        let want = vector(&s["curvature"]);
        failures.check(close(kv, want, REL), || {
            format!("{name} t={t}: curvature {kv:?}, expected {want:?}")
        });
    }
}

/// Checks that Control Points gives back the record's control points, weights and knots.
fn check_control_points(name: &str, curve: &Shared<Curve>, case: &Json, failures: &mut Failures) {
    let r = NodeCall::new(&analysis::control_points())
        .input(DataTree::from_item(curve.clone()))
        .run();
    let cvs = case["cvs"].as_array().expect("cvs");
    let points: Vec<Value> = r.outputs[0].values().flatten().collect();
    let weights: Vec<Value> = r.outputs[1].values().flatten().collect();
    failures.check(points.len() == cvs.len(), || {
        format!(
            "{name}: {} control points, expected {}",
            points.len(),
            cvs.len()
        )
    });
    for (i, (p, cv)) in points.into_iter().zip(cvs).enumerate() {
        let (p, want) = (as_point(p), point(&cv["p"]).to_vector());
        failures.check(close(p, want, REL), || {
            format!("{name}: control point {i} {p:?}, expected {want:?}")
        });
    }
    let w: Vec<f64> = weights.into_iter().map(as_number).collect();
    let want_w: Vec<f64> = cvs.iter().map(|cv| num(&cv["w"])).collect();
    failures.check(w == want_w, || {
        format!("{name}: weights {w:?}, expected {want_w:?}")
    });
    let knots: Vec<f64> = r.outputs[2].values().flatten().map(as_number).collect();
    let want_k = numbers(&case["knots"]);
    failures.check(knots == want_k, || {
        format!("{name}: knots {knots:?}, expected {want_k:?}")
    });
}

#[test]
fn opennurbs_curves_through_nodes() {
    let oracle = load("opennurbs-cases.json");
    let cases = oracle["curves"].as_array().expect("curves");
    assert!(cases.len() >= 15);
    let mut failures = Failures::default();
    for case in cases {
        let name = case["name"].as_str().expect("name");
        let curve = pwk(case);
        check_control_points(name, &curve, case, &mut failures);
        check_samples(name, &curve, case, &mut failures);
    }
    failures.finish("opennurbs curve");
}

#[test]
fn opennurbs_constructions_through_the_nurbs_curve_node() {
    let oracle = load("opennurbs-cases.json");
    let cases = oracle["constructions"].as_array().expect("constructions");
    assert!(cases.len() >= 6);
    let mut failures = Failures::default();
    for case in cases {
        let name = case["name"].as_str().expect("name");
        // The record holds the built curve's periodicity; the request is in the name (Rhino
        // builds a closed, non-periodic polyline for a periodic request of degree 1).
        let periodic = name.starts_with("create-periodic");
        let input: Vec<Point3> = case["input_points"]
            .as_array()
            .expect("input_points")
            .iter()
            .map(point)
            .collect();
        let degree = case["degree"].as_i64().expect("degree");
        let r = NodeCall::new(&spline::nurbs_curve())
            .input(DataTree::from_list(input))
            .input(DataTree::from_item(degree))
            .input(DataTree::from_item(periodic))
            .run();
        failures.check(r.messages.is_empty(), || {
            format!("{name}: {:?}", r.messages)
        });
        let Value::Curve(curve) = item(&r, 0) else {
            panic!("{name}: not a curve")
        };
        let domain = match item(&r, 2) {
            Value::Domain(d) => d,
            other => panic!("{other:?}"),
        };
        let want = numbers(&case["domain"]);
        failures.check(domain.t0 == want[0] && domain.t1 == want[1], || {
            format!("{name}: domain {domain:?}, expected {want:?}")
        });
        check_control_points(name, &curve, case, &mut failures);
        check_samples(name, &curve, case, &mut failures);
    }
    failures.finish("opennurbs construction");
}

/// The OCCT file's curves by name, built by Nurbs Curve PWK.
fn occt_curves(oracle: &Json) -> std::collections::HashMap<String, Shared<Curve>> {
    oracle["curves"]
        .as_array()
        .expect("curves")
        .iter()
        .map(|c| (c["name"].as_str().expect("name").to_owned(), pwk(c)))
        .collect()
}

#[test]
fn occt_closest_points_through_the_node() {
    let oracle = load("occt-cases.json");
    let curves = occt_curves(&oracle);
    let node = analysis::curve_closest_point();
    let mut failures = Failures::default();
    let mut count = 0;
    for case in oracle["curve_closest_point"].as_array().expect("cases") {
        let name = case["curve"].as_str().expect("curve");
        let curve = &curves[name];
        for q in case["queries"].as_array().expect("queries") {
            count += 1;
            let test = point(&q["test_point"]);
            let r = NodeCall::new(&node)
                .input(DataTree::from_item(test))
                .input(DataTree::from_item(curve.clone()))
                .run();
            let d = as_number(item(&r, 2));
            let want = num(&q["distance"]);
            failures.check((d - want).abs() <= REL * want.max(1.0), || {
                format!("{name} {}: distance {d}, expected {want}", q["kind"])
            });
            let p = as_point(item(&r, 0));
            let want_p = point(&q["point"]).to_vector();
            failures.check((p - want_p).length() <= 1e-6, || {
                format!("{name} {}: point {p:?}, expected {want_p:?}", q["kind"])
            });
        }
    }
    assert!(count >= 50, "only {count} queries");
    failures.finish("occt closest point");
}

#[test]
fn occt_lengths_through_the_nodes() {
    let oracle = load("occt-cases.json");
    let curves = occt_curves(&oracle);
    let length = analysis::length();
    let at_length = analysis::evaluate_length();
    let mut failures = Failures::default();
    for case in oracle["arc_length"].as_array().expect("cases") {
        let name = case["curve"].as_str().expect("curve");
        let curve = &curves[name];
        let r = NodeCall::new(&length)
            .input(DataTree::from_item(curve.clone()))
            .run();
        let l = as_number(item(&r, 0));
        let want = num(&case["length"]);
        failures.check((l - want).abs() <= REL * want, || {
            format!("{name}: length {l}, expected {want}")
        });
        let domain = curve.domain().length();
        for lp in case["length_parameters"]
            .as_array()
            .expect("length parameters")
        {
            let fraction = num(&lp["fraction"]);
            let r = NodeCall::new(&at_length)
                .input(DataTree::from_item(curve.clone()))
                .input(DataTree::from_item(fraction))
                .run();
            let t = as_number(item(&r, 2));
            let want_t = num(&lp["t"]);
            failures.check((t - want_t).abs() <= 1e-8 * domain, || {
                format!("{name} at {fraction}: t {t}, expected {want_t}")
            });
            let p = as_point(item(&r, 0));
            let want_p = point(&lp["point"]).to_vector();
            failures.check(close(p, want_p, 1e-8), || {
                format!("{name} at {fraction}: point {p:?}, expected {want_p:?}")
            });
        }
    }
    failures.finish("occt arc length");
}

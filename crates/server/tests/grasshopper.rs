//! Grasshopper definitions over raw HTTP: mcneel/compute's own samples (checked in under
//! `tests/definitions/grasshopper/`, MIT, see the README there) solved by `algo` and by
//! `pointer`, with Compute's names for inputs and outputs, and importer errors in the answer.

mod support;

use base64::Engine as _;
use serde_json::{Value as Json, json};
use support::*;

const ONE: &str = "grasshopper/mcneel-compute__simple_circle_one.ghx";
const ARRAY: &str = "grasshopper/mcneel-compute__simple_circle_array.ghx";

/// The inputs of both samples, as Compute names them: the whole nickname of their group.
fn inputs(centre: [f64; 3], radius: f64) -> Json {
    let [x, y, z] = centre;
    json!([
        {"ParamName": "RH_IN:102:0001", "InnerTree": {"{0}": [
            {"type": "Rhino.Geometry.Point3d", "data": format!(r#"{{"X":{x},"Y":{y},"Z":{z}}}"#)}]}},
        {"ParamName": "RH_IN:105:0001", "InnerTree": {"{0}": [
            {"type": "System.Double", "data": radius.to_string()}]}},
    ])
}

/// The circles of an output: (centre, normal, radius).
fn circles(answer: &Json, output: &str) -> Vec<([f64; 3], [f64; 3], f64)> {
    let xyz = |j: &Json| {
        [
            j["X"].as_f64().unwrap(),
            j["Y"].as_f64().unwrap(),
            j["Z"].as_f64().unwrap(),
        ]
    };
    item_data(answer, output)
        .into_iter()
        .map(|(t, data)| {
            assert_eq!(t, "Rhino.Geometry.Circle");
            let c: Json = serde_json::from_str(&data).unwrap();
            (
                xyz(&c["Plane"]["Origin"]),
                xyz(&c["Plane"]["ZAxis"]),
                c["Radius"].as_f64().unwrap(),
            )
        })
        .collect()
}

fn close(a: [f64; 3], b: [f64; 3]) -> bool {
    a.iter().zip(b).all(|(x, y)| (x - y).abs() < 1e-9)
}

fn file_algo(name: &str) -> String {
    base64::engine::general_purpose::STANDARD
        .encode(std::fs::read(definitions().join(name)).unwrap())
}

#[test]
fn simple_circle_one_solves_with_computes_names() {
    let s = start(config());
    // Circle CNR with the point as centre, the number as radius, and the normal (0, 0, 1) typed
    // into the component: one circle, in the answer under its group's whole nickname.
    let body = json!({"algo": file_algo(ONE), "values": inputs([3.0, 4.0, 0.5], 2.5)});
    let answer = post(s.addr(), "/grasshopper", &body).json();
    assert!(answer.get("errors").is_none(), "{answer}");
    let names: Vec<&str> = answer["values"]
        .as_array()
        .unwrap()
        .iter()
        .map(|v| v["ParamName"].as_str().unwrap())
        .collect();
    assert_eq!(names, ["RH_OUT:109:0001"]);
    let [(centre, normal, radius)] = circles(&answer, "RH_OUT:109:0001")[..] else {
        panic!("one circle: {answer}");
    };
    assert!(
        close(centre, [3.0, 4.0, 0.5]) && close(normal, [0.0, 0.0, 1.0]),
        "{answer}"
    );
    assert_eq!(radius, 2.5);
    // The graph's own names (the prefix and type code dropped) are not Compute's: skipped.
    let body = json!({"pointer": answer["pointer"], "values": [
        {"ParamName": "0001", "InnerTree": {"{0}": [{"type": "System.Double", "data": "9"}]}}]});
    let again = post(s.addr(), "/grasshopper", &body).json();
    assert_eq!(again["locus"]["skipped_inputs"], json!(["0001"]));
}

#[test]
fn simple_circle_array_by_pointer_divides_the_circle() {
    let s = start(config());
    // Divide Curve (N = 10, typed in) on the circle, then a circle of the same radius at each
    // point: point k is centre + r (cos 2πk/10, sin 2πk/10, 0), the circle starting on the
    // world x axis (its plane's x axis for the normal (0, 0, 1)).
    let (c, r) = ([1.0, -2.0, 0.0], 4.0);
    let body = json!({"pointer": ARRAY, "values": inputs(c, r)});
    let answer = post(s.addr(), "/grasshopper", &body).json();
    assert!(answer.get("errors").is_none(), "{answer}");
    let ring = circles(&answer, "RH_OUT:109:0002");
    assert_eq!(ring.len(), 10);
    for (k, (centre, normal, radius)) in ring.into_iter().enumerate() {
        let a = std::f64::consts::TAU * k as f64 / 10.0;
        let want = [c[0] + r * a.cos(), c[1] + r * a.sin(), c[2]];
        assert!(
            close(centre, want) && close(normal, [0.0, 0.0, 1.0]),
            "{k}: {centre:?}"
        );
        assert!((radius - r).abs() < 1e-12);
    }
    assert_eq!(circles(&answer, "RH_OUT:109:0001").len(), 1);
}

#[test]
fn io_lists_computes_names_and_types() {
    let s = start(config());
    let io = post(s.addr(), "/io", &json!({"algo": file_algo(ARRAY)})).json();
    let mut names: Vec<&str> = io["InputNames"]
        .as_array()
        .unwrap()
        .iter()
        .map(|n| n.as_str().unwrap())
        .collect();
    names.sort_unstable();
    assert_eq!(names, ["RH_IN:102:0001", "RH_IN:105:0001"]);
    assert_eq!(
        io["OutputNames"],
        json!(["RH_OUT:109:0001", "RH_OUT:109:0002"])
    );
    for i in io["Inputs"].as_array().unwrap() {
        let want = if i["Name"] == "RH_IN:102:0001" {
            "Point"
        } else {
            "Number"
        };
        assert_eq!(i["ParamType"], json!(want), "{i}");
    }
    assert_eq!(io["Errors"], json!([]));
}

#[test]
fn components_locus_cannot_run_are_errors_in_the_answer() {
    let s = start(config());
    // The sample with its Circle CNR given a type no locus node declares: the definition still
    // loads, the circle output is empty, and the answer's errors name the component.
    let text = std::fs::read_to_string(definitions().join(ONE))
        .unwrap()
        .replace(
            "d114323a-e6ee-4164-946b-e4ca0ce15efa",
            "00000000-1111-2222-3333-444444444444",
        );
    let algo = base64::engine::general_purpose::STANDARD.encode(text);
    let answer = post(
        s.addr(),
        "/grasshopper",
        &json!({"algo": algo, "values": inputs([0.0; 3], 1.0)}),
    )
    .json();
    let errors = answer["errors"]
        .as_array()
        .unwrap_or_else(|| panic!("{answer}"));
    assert!(
        errors
            .iter()
            .any(|e| e.as_str().unwrap().contains("Circle CNR")
                && e.as_str().unwrap().contains("no locus node")),
        "{answer}"
    );
    let io = post(s.addr(), "/io", &json!({"algo": algo})).json();
    assert!(!io["Errors"].as_array().unwrap().is_empty(), "{io}");
}

#[test]
fn a_grasshopper_file_that_does_not_read_is_400() {
    let s = start(config());
    let text = std::fs::read_to_string(definitions().join(ONE)).unwrap();
    let cut = base64::engine::general_purpose::STANDARD.encode(&text[..text.len() / 2]);
    let (kind, m) = post(s.addr(), "/grasshopper", &json!({"algo": cut})).error(400);
    assert_eq!(kind, "bad_definition");
    assert!(m.contains(".ghx file does not read"), "{m}");
}

#[test]
fn two_inputs_with_one_compute_name_are_an_error_and_the_first_wins() {
    let s = start(config());
    // Both input groups renamed to the point's name: Compute reports the clash with every solve
    // and keeps the first group (the point); the radius is then no input Compute can set.
    let text = std::fs::read_to_string(definitions().join(ONE))
        .unwrap()
        .replace("RH_IN:105:0001", "RH_IN:102:0001");
    let algo = base64::engine::general_purpose::STANDARD.encode(text);
    let io = post(s.addr(), "/io", &json!({"algo": algo})).json();
    assert_eq!(io["InputNames"], json!(["RH_IN:102:0001"]), "{io}");
    let answer = post(
        s.addr(),
        "/grasshopper",
        &json!({"algo": algo, "values": inputs([1.0, 2.0, 3.0], 5.0)}),
    )
    .json();
    let errors = answer["errors"]
        .as_array()
        .unwrap_or_else(|| panic!("{answer}"));
    assert!(
        errors.iter().any(|e| e
            .as_str()
            .unwrap()
            .starts_with("Multiple input parameters with the same name")),
        "{answer}"
    );
}

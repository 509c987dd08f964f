//! Raw-HTTP tests of the server on a free loopback port: every endpoint, and every error path
//! answering a JSON error with the right status while the server goes on serving.

mod support;

use std::time::Duration;

use base64::Engine as _;
use locus_server::{Config, Limits};
use serde_json::{Value as Json, json};
use support::*;

#[test]
fn health_version_and_openapi() {
    let s = start(config());
    let r = send(s.addr(), "GET", "/healthcheck", &[], b"");
    assert_eq!((r.status, r.body.as_slice()), (200, b"Healthy".as_slice()));
    let v = send(s.addr(), "GET", "/version", &[], b"").json();
    assert!(v.get("rhino").is_some() && v.get("git_sha").is_some());
    assert_eq!(v["compute"], json!(env!("CARGO_PKG_VERSION")));
    let api = send(s.addr(), "GET", "/openapi.json", &[], b"").json();
    assert_eq!(api["openapi"], json!("3.0.3"));
    for p in [
        "/grasshopper",
        "/solve",
        "/io",
        "/v1/run",
        "/healthcheck",
        "/version",
    ] {
        assert!(api["paths"].get(p).is_some(), "{p}");
    }
}

#[test]
fn tangent_spheres_solve_in_compute_form_then_by_pointer() {
    let s = start(config());
    let body = json!({
        "algo": algo("tangent_spheres.ron"),
        "values": [
            {"ParamName": "t", "InnerTree": {"0": [{"data": 0.5}]}},
            {"ParamName": "B", "InnerTree": {"{0}": [{"type": "Rhino.Geometry.Point3d",
                "data": "{\"X\":10.0,\"Y\":0.0,\"Z\":0.0}"}]}},
        ],
    });
    let r = post(s.addr(), "/grasshopper", &body);
    assert_eq!(r.status, 200);
    let a = r.json();
    assert_eq!(
        item_data(&a, "D"),
        [(
            "Rhino.Geometry.Point3d".to_owned(),
            r#"{"X":5.0,"Y":0.0,"Z":0.0}"#.to_owned()
        )]
    );
    assert_eq!(
        item_data(&a, "r1"),
        [("System.Double".to_owned(), "2.5".to_owned())]
    );
    // Spheres go as openNURBS archives.
    let s1 = item_data(&a, "S1");
    assert_eq!(s1[0].0, "Rhino.Geometry.NurbsSurface");
    let archive: Json = serde_json::from_str(&s1[0].1).unwrap();
    assert!(archive["data"].is_string() && archive["archive3dm"].is_number());
    // No errors or warnings: the keys are left out, as Compute does.
    assert!(
        a.get("errors").is_none() && a.get("warnings").is_none(),
        "{a}"
    );
    let pointer = a["pointer"].as_str().unwrap().to_owned();
    assert!(pointer.starts_with("md5_"));
    // The same definition by pointer, with another t; B is back to the definition's own value.
    let by_pointer = json!({"pointer": pointer,
        "values": [{"ParamName": "t", "InnerTree": {"{0}": [{"type": "System.Double", "data": "0.25"}]}}]});
    let b = post(s.addr(), "/solve", &by_pointer).json();
    assert_eq!(item_data(&b, "D")[0].1, r#"{"X":2.0,"Y":1.5,"Z":0.0}"#);
    // A wrapped body `[ {...} ]` is the same request.
    let c = post(s.addr(), "/grasshopper", &json!([by_pointer])).json();
    assert_eq!(c["values"], b["values"]);
}

#[test]
fn repeated_solves_rerun_only_what_changed() {
    // One worker and one client: each solve gets the evaluator of the one before.
    let s = start(Config {
        workers: 1,
        ..config()
    });
    let solve = |t: f64| {
        post(
            s.addr(),
            "/grasshopper",
            &json!({"algo": algo("tangent_spheres.ron"),
            "values": [{"ParamName": "t", "InnerTree": {"0": [{"data": t}]}}]}),
        )
        .json()
    };
    let first = solve(0.5);
    assert_eq!(
        (
            first["locus"]["warm"].clone(),
            first["locus"]["nodes_run"].clone()
        ),
        (json!(false), json!(12))
    );
    let same = solve(0.5);
    assert_eq!(
        (
            same["locus"]["warm"].clone(),
            same["locus"]["nodes_run"].clone()
        ),
        (json!(true), json!(0))
    );
    assert_eq!(same["values"], first["values"]);
    // A new t runs t and everything downstream of it, not the points A and B.
    let other = solve(0.25);
    assert_eq!(other["locus"]["nodes_run"], json!(10));
    assert_eq!(item_data(&other, "D")[0].1, r#"{"X":2.0,"Y":1.5,"Z":0.0}"#);
}

#[test]
fn every_plain_item_type_round_trips() {
    let s = start(config());
    let plane = r#"{"Origin":{"X":1.0,"Y":2.0,"Z":3.0},"XAxis":{"X":0.0,"Y":1.0,"Z":0.0},"YAxis":{"X":0.0,"Y":0.0,"Z":1.0},"ZAxis":{"X":1.0,"Y":0.0,"Z":0.0}}"#;
    let inputs = [
        ("Num", "System.Double", "2.5".to_owned()),
        ("Int", "System.Int32", "4".to_owned()),
        ("Bool", "System.Boolean", "false".to_owned()),
        ("Text", "System.String", "\"a \\\"quoted\\\" text\"".to_owned()),
        ("Pt", "Rhino.Geometry.Point3d", r#"{"X":1.0,"Y":-2.0,"Z":3.5}"#.to_owned()),
        ("Vec", "Rhino.Geometry.Vector3d", r#"{"X":0.0,"Y":1.0,"Z":0.0}"#.to_owned()),
        ("Pln", "Rhino.Geometry.Plane", plane.to_owned()),
        ("Dom", "Rhino.Geometry.Interval", r#"{"T0":-1.0,"T1":4.0}"#.to_owned()),
        (
            "Box",
            "Rhino.Geometry.Box",
            format!(r#"{{"Plane":{plane},"X":{{"T0":0.0,"T1":1.0}},"Y":{{"T0":0.0,"T1":2.0}},"Z":{{"T0":0.0,"T1":3.0}}}}"#),
        ),
        (
            "Xf",
            "Rhino.Geometry.Transform",
            r#"{"M00":1.0,"M01":0.0,"M02":0.0,"M03":5.0,"M10":0.0,"M11":1.0,"M12":0.0,"M13":6.0,"M20":0.0,"M21":0.0,"M22":1.0,"M23":7.0,"M30":0.0,"M31":0.0,"M32":0.0,"M33":1.0}"#.to_owned(),
        ),
    ];
    let values: Vec<Json> = inputs
        .iter()
        .map(|(n, t, d)| json!({"ParamName": n, "InnerTree": {"{0;1}": [{"type": t, "data": d}]}}))
        .collect();
    let a = post(
        s.addr(),
        "/grasshopper",
        &json!({"algo": algo("types.ron"), "values": values}),
    );
    assert_eq!(a.status, 200);
    let a = a.json();
    for (n, t, d) in &inputs {
        assert_eq!(item_data(&a, n), [((*t).to_owned(), d.clone())], "{n}");
        // Outputs keep the input paths, written with braces.
        let v = a["values"]
            .as_array()
            .unwrap()
            .iter()
            .find(|v| v["ParamName"] == *n)
            .unwrap();
        assert!(v["InnerTree"].get("{0;1}").is_some(), "{v}");
    }
    assert_eq!(item_data(&a, "Sum")[0].1, "6.5");
    // A curve input as a line curve archive, and the plane surface as a NURBS surface.
    assert_eq!(item_data(&a, "Crv")[0].0, "Rhino.Geometry.LineCurve");
    assert_eq!(item_data(&a, "Srf")[0].0, "Rhino.Geometry.NurbsSurface");
    // What the curve archive holds goes back in as an input.
    let crv = item_data(&a, "Crv")[0].clone();
    let again = post(
        s.addr(),
        "/grasshopper",
        &json!({"algo": algo("types.ron"),
        "values": [{"ParamName": "Crv", "InnerTree": {"0": [{"type": crv.0, "data": crv.1}]}}]}),
    );
    assert_eq!(item_data(&again.json(), "Crv")[0], crv);
}

#[test]
fn null_items_are_left_out_and_unknown_params_skipped() {
    let s = start(config());
    let a = post(
        s.addr(),
        "/grasshopper",
        &json!({"algo": algo("types.ron"), "values": [
            {"ParamName": "Num", "InnerTree": {"{0}": [{"data": "1.0"}, null, {"type": "System.Double"}, {"data": 3}]}},
            {"ParamName": "NoSuchInput", "InnerTree": {"{0}": [{"data": 1}]}},
        ]}),
    );
    assert_eq!(a.status, 200);
    let a = a.json();
    let nums: Vec<String> = item_data(&a, "Num").into_iter().map(|(_, d)| d).collect();
    assert_eq!(nums, ["1.0", "3.0"]);
    assert_eq!(a["locus"]["skipped_inputs"], json!(["NoSuchInput"]));
}

#[test]
fn io_describes_inputs_and_outputs() {
    let s = start(config());
    let a = post(
        s.addr(),
        "/io",
        &json!({"algo": algo("tangent_spheres.ron")}),
    );
    assert_eq!(a.status, 200);
    let a = a.json();
    assert_eq!(a["InputNames"], json!(["A", "B", "t"]));
    assert_eq!(
        a["OutputNames"],
        json!(["D", "C1", "C2", "r1", "r2", "S1", "S2", "gap1", "gap2"])
    );
    assert!(a["CacheKey"].as_str().unwrap().starts_with("md5_"));
    let t = &a["Inputs"][2];
    assert_eq!(t["Name"], json!("t"));
    assert_eq!(t["ParamType"], json!("Number"));
    assert!(t.get("Nickname").is_some() && t["Nickname"].is_null());
    assert_eq!(
        t["Default"]["InnerTree"]["{0}"][0],
        json!({"type": "System.Double", "data": "0.25"})
    );
    for key in [
        "Description",
        "Icon",
        "Inputs",
        "Outputs",
        "Warnings",
        "Errors",
    ] {
        assert!(a.get(key).is_some(), "{key}");
    }
}

#[test]
fn native_run_answers_the_json_output_schema() {
    let s = start(config());
    let r = post(
        s.addr(),
        "/v1/run",
        &json!({
            "graph": text("tangent_spheres.ron"),
            "inputs": {"t": 0.5, "B": {"point": [10, 0, 0]}},
        }),
    );
    assert_eq!(r.status, 200);
    let a = r.json();
    assert_eq!(
        a["outputs"]["D"],
        json!({"{0}": [{"point": [5.0, 0.0, 0.0]}]})
    );
    assert_eq!(
        a["outputs"]["S1"]["{0}"][0]["surface"]["degree"],
        json!([2, 2])
    );
    assert_eq!(a["messages"], json!([]));
    let pointer = a["pointer"].as_str().unwrap();
    let b = post(
        s.addr(),
        "/v1/run",
        &json!({"pointer": pointer, "literals": {"B": "(0, 10, 0)"},
        "inputs": {"t": {"{0}": [0.5]}}}),
    )
    .json();
    assert_eq!(
        b["outputs"]["D"],
        json!({"{0}": [{"point": [0.0, 5.0, 0.0]}]})
    );
    // A file under --definitions, by name.
    let c = post(
        s.addr(),
        "/v1/run",
        &json!({"pointer": "slow.ron", "inputs": {"C": 5}}),
    )
    .json();
    assert_eq!(c["outputs"]["L"], json!({"{0;0}": [5]}));
}

#[test]
fn native_run_refuses_unknown_inputs_and_bad_values() {
    let s = start(config());
    let g = text("tangent_spheres.ron");
    let (kind, m) = post(
        s.addr(),
        "/v1/run",
        &json!({"graph": g, "inputs": {"x": 1}}),
    )
    .error(400);
    assert_eq!(kind, "bad_request");
    assert!(
        m.contains("unknown input \"x\"") && m.contains("A, B, t"),
        "{m}"
    );
    let (_, m) = post(
        s.addr(),
        "/v1/run",
        &json!({"graph": g, "inputs": {"A": "text"}}),
    )
    .error(400);
    assert!(m.contains("input \"A\" {0}[0]"), "{m}");
    let (_, m) = post(
        s.addr(),
        "/v1/run",
        &json!({"graph": g, "literals": {"t": "(1,"}}),
    )
    .error(400);
    assert!(m.contains("\"t\""), "{m}");
    let (_, m) = post(s.addr(), "/v1/run", &json!({"graph": g, "extra": 1})).error(400);
    assert!(m.contains("unknown field"), "{m}");
    let (_, m) = post(s.addr(), "/v1/run", &json!({"graph": g, "algo": "x"})).error(400);
    assert!(m.contains("not both"), "{m}");
}

#[test]
fn malformed_requests_are_400_with_the_reason() {
    let s = start(config());
    let a = s.addr();
    let cases: Vec<(Vec<u8>, &str)> = vec![
        (b"{not json".to_vec(), "not JSON"),
        (b"\xff\xfe\x00".to_vec(), "not JSON"),
        (b"42".to_vec(), "must be a JSON object"),
        (br#"{"values": 5}"#.to_vec(), "does not fit the schema"),
        (br#"{"values": []}"#.to_vec(), "names no definition"),
        (br#"{"algo": "!!!not base64!!!"}"#.to_vec(), "not base64"),
        ("[".repeat(10_000).into_bytes(), "not JSON"),
    ];
    for (body, want) in cases {
        let r = send(a, "POST", "/grasshopper", &[], &body);
        let (_, m) = r.error(400);
        assert!(m.contains(want), "{want}: {m}");
    }
    let bad_graph = base64::engine::general_purpose::STANDARD
        .encode("(format: 1, nodes: [(id: \"x\", type: \"no.such\")])");
    let (kind, m) = post(a, "/grasshopper", &json!({"algo": bad_graph})).error(400);
    assert_eq!(kind, "bad_definition");
    assert!(m.contains("no.such"), "{m}");
    let ghx = base64::engine::general_purpose::STANDARD.encode("<?xml version=\"1.0\"?><Archive/>");
    let (_, m) = post(a, "/grasshopper", &json!({"algo": ghx})).error(400);
    assert!(m.contains(".ghx"), "{m}");
    let binary = base64::engine::general_purpose::STANDARD.encode([0u8, 0xff, 0xfe, 0x80, 0x81]);
    let (_, m) = post(a, "/grasshopper", &json!({"algo": binary})).error(400);
    assert!(m.contains(".gh"), "{m}");
    // The server still answers.
    assert_eq!(send(a, "GET", "/healthcheck", &[], b"").status, 200);
}

#[test]
fn wrong_items_are_400_naming_input_path_and_index() {
    let s = start(config());
    let cases = [
        (
            json!({"ParamName": "A", "InnerTree": {"{0}": [{"type": "System.String", "data": "\"x\""}]}}),
            "input \"A\" {0}[0]",
        ),
        (
            json!({"ParamName": "A", "InnerTree": {"{0}": [{"type": "Rhino.Geometry.Point3d", "data": "{\"X\":1}"}]}}),
            "needs \"Y\"",
        ),
        (
            json!({"ParamName": "t", "InnerTree": {"{0}": [{"data": 1}, {"type": "Hostile.Type", "data": "1"}]}}),
            "input \"t\" {0}[1]: unknown item type",
        ),
        (
            json!({"ParamName": "t", "InnerTree": {"{0}": [{"data": "NaN"}]}}),
            "finite",
        ),
        (
            json!({"ParamName": "t", "InnerTree": {"{x}": [{"data": 1}]}}),
            "not a tree path",
        ),
        (
            json!({"ParamName": "t", "InnerTree": {"{0}": 5}}),
            "must be a list",
        ),
        (
            json!({"ParamName": "t", "InnerTree": {"{0}": [7]}}),
            "must be an object",
        ),
        (
            json!({"ParamName": "t", "InnerTree": {"{0}": [{"type": "Rhino.Geometry.NurbsCurve", "data": "{\"data\": \"AAAA\"}"}]}}),
            "does not read",
        ),
    ];
    for (tree, want) in cases {
        let r = post(
            s.addr(),
            "/grasshopper",
            &json!({"algo": algo("tangent_spheres.ron"), "values": [tree]}),
        );
        let (_, m) = r.error(400);
        assert!(m.contains(want), "{want}: {m}");
    }
}

#[test]
fn pointers_are_cached_keys_or_files_inside_the_folder() {
    let s = start(config());
    let a = s.addr();
    let (kind, _) = post(a, "/grasshopper", &json!({"pointer": "md5_0123"})).error(500);
    assert_eq!(kind, "unknown_pointer");
    let ok = post(a, "/grasshopper", &json!({"pointer": "slow.ron"}));
    assert_eq!(ok.status, 200);
    // The pointer of a file is the one its algo would have.
    let p = definition_pointer("slow.ron");
    assert_eq!(ok.json()["pointer"], json!(p));
    for bad in [
        "../Cargo.toml",
        "/etc/passwd",
        "./../../x",
        "http://example.invalid/x.gh",
    ] {
        let (kind, m) = post(a, "/grasshopper", &json!({"pointer": bad})).error(400);
        assert_eq!(kind, "bad_pointer", "{bad}: {m}");
    }
    let (kind, _) = post(a, "/grasshopper", &json!({"pointer": "missing.ron"})).error(404);
    assert_eq!(kind, "not_found");
    // A symbolic link out of the folder is refused too.
    let dir = std::env::temp_dir().join(format!("locus-server-test-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let link = dir.join("escape.ron");
    let _ = std::fs::remove_file(&link);
    #[cfg(unix)]
    {
        std::os::unix::fs::symlink(definitions().join("slow.ron"), &link).unwrap();
        let s2 = start(Config {
            definitions: Some(dir.clone()),
            ..config()
        });
        let (kind, _) =
            post(s2.addr(), "/grasshopper", &json!({"pointer": "escape.ron"})).error(400);
        assert_eq!(kind, "bad_pointer");
    }
    let _ = std::fs::remove_dir_all(&dir);
    // Without a folder, a name is an unknown pointer (500, as Compute).
    let s3 = start(Config {
        definitions: None,
        ..config()
    });
    post(s3.addr(), "/grasshopper", &json!({"pointer": "slow.ron"})).error(500);
}

fn definition_pointer(name: &str) -> String {
    locus_server::definition::pointer_of_bytes(text(name).as_bytes())
}

#[test]
fn limits_answer_413_504_503_and_the_server_goes_on() {
    let s = start(Config {
        limits: Limits {
            max_body_bytes: 4096,
            max_input_items: 10,
            ..Limits::default()
        },
        ..config()
    });
    let a = s.addr();
    // Body size, announced and chunked.
    let big = vec![b' '; 5000];
    send(a, "POST", "/grasshopper", &[], &big).error(413);
    let mut chunked = b"POST /grasshopper HTTP/1.1\r\nHost: x\r\nConnection: close\r\nTransfer-Encoding: chunked\r\n\r\n".to_vec();
    for _ in 0..5 {
        chunked.extend_from_slice(b"400\r\n");
        chunked.extend_from_slice(&[b' '; 0x400]);
        chunked.extend_from_slice(b"\r\n");
    }
    chunked.extend_from_slice(b"0\r\n\r\n");
    raw(a, &chunked).error(413);
    // Items.
    let items: Vec<Json> = (0..11).map(|i| json!({"data": i})).collect();
    let (_, m) = post(
        a,
        "/grasshopper",
        &json!({"pointer": "slow.ron",
        "values": [{"ParamName": "C", "InnerTree": {"0": items}}]}),
    )
    .error(413);
    assert!(m.contains("10 items"), "{m}");

    // A deadline shorter than the solve.
    let s = start(Config {
        workers: 1,
        limits: Limits {
            deadline: Duration::from_millis(50),
            queue: 0,
            ..Limits::default()
        },
        ..config()
    });
    let a = s.addr();
    let slow = json!({"pointer": "slow.ron", "values": [{"ParamName": "C", "InnerTree": {"0": [{"data": 3_000_000}]}}]});
    let (kind, m) = post(a, "/grasshopper", &slow).error(504);
    assert_eq!(kind, "deadline");
    assert!(m.contains("50 ms"), "{m}");
    // The late solve still holds the only worker, and the queue is 0: the next is refused.
    let busy = post(a, "/grasshopper", &json!({"pointer": "slow.ron"}));
    let (kind, _) = busy.error(503);
    assert_eq!(kind, "busy");
    assert_eq!(busy.header("retry-after"), Some("1"));
    // Once it is done, the server solves again.
    let mut ok = None;
    for _ in 0..100 {
        std::thread::sleep(Duration::from_millis(100));
        let r = post(a, "/grasshopper", &json!({"pointer": "slow.ron"}));
        if r.status == 200 {
            ok = Some(r);
            break;
        }
    }
    assert!(ok.is_some(), "the server did not recover");
}

#[test]
fn token_auth_and_unknown_routes() {
    let s = start(Config {
        token: Some("s3cret".into()),
        ..config()
    });
    let a = s.addr();
    let body = json!({"pointer": "slow.ron"}).to_string();
    let r = send(a, "POST", "/grasshopper", &[], body.as_bytes());
    r.error(401);
    assert_eq!(r.header("www-authenticate"), Some("Bearer"));
    send(
        a,
        "POST",
        "/grasshopper",
        &["Authorization: Bearer wrong"],
        body.as_bytes(),
    )
    .error(401);
    send(a, "GET", "/version", &[], b"").error(401);
    let ok = send(
        a,
        "POST",
        "/grasshopper",
        &["Authorization: Bearer s3cret"],
        body.as_bytes(),
    );
    assert_eq!(ok.status, 200);
    let ok = send(
        a,
        "POST",
        "/grasshopper",
        &["RhinoComputeKey: s3cret"],
        body.as_bytes(),
    );
    assert_eq!(ok.status, 200);
    // The health check needs no token (load balancers).
    assert_eq!(send(a, "GET", "/healthcheck", &[], b"").status, 200);
    let auth = "Authorization: Bearer s3cret";
    let (kind, _) = send(a, "GET", "/nope", &[auth], b"").error(404);
    assert_eq!(kind, "not_found");
    let (kind, _) = send(a, "GET", "/grasshopper", &[auth], b"").error(405);
    assert_eq!(kind, "method_not_allowed");
    // Garbage on the socket is answered 400 by the HTTP layer and breaks nothing.
    let r = raw(a, b"NOT HTTP AT ALL\r\n\r\n");
    assert_eq!(r.status, 400);
    assert_eq!(send(a, "GET", "/healthcheck", &[], b"").status, 200);
}

#[test]
fn concurrent_requests_all_succeed_with_their_own_inputs() {
    let s = start(config());
    let a = s.addr();
    let threads: Vec<_> = (0..8)
        .map(|k| {
            std::thread::spawn(move || {
                for i in 0..10 {
                    let t = f64::from(k * 10 + i) / 100.0;
                    let r = post(
                        a,
                        "/grasshopper",
                        &json!({"algo": algo("tangent_spheres.ron"),
                        "values": [{"ParamName": "t", "InnerTree": {"0": [{"data": t}]}}]}),
                    );
                    assert_eq!(r.status, 200);
                    let d: Json = serde_json::from_str(&item_data(&r.json(), "D")[0].1).unwrap();
                    assert!((d["X"].as_f64().unwrap() - 8.0 * t).abs() < 1e-12);
                    assert!((d["Y"].as_f64().unwrap() - 6.0 * t).abs() < 1e-12);
                }
            })
        })
        .collect();
    for t in threads {
        t.join().unwrap();
    }
}

/// Mutated requests (bytes flipped, cut, duplicated, JSON tokens spliced in) never break the
/// server: every answer is a JSON body with one of the documented statuses, and a good request
/// still succeeds afterwards.
#[test]
fn mutated_requests_never_break_the_server() {
    let s = start(config());
    let a = s.addr();
    let good = json!({"algo": algo("types.ron"), "values": [
        {"ParamName": "Num", "InnerTree": {"{0}": [{"type": "System.Double", "data": "2.5"}]}},
        {"ParamName": "Pt", "InnerTree": {"{0;1}": [{"type": "Rhino.Geometry.Point3d",
            "data": "{\"X\":1.0,\"Y\":2.0,\"Z\":3.0}"}]}},
        {"ParamName": "Pln", "InnerTree": {"0": [{"data": {"Origin": {"X": 0, "Y": 0, "Z": 0},
            "XAxis": {"X": 1, "Y": 0, "Z": 0}, "YAxis": {"X": 0, "Y": 1, "Z": 0}}}]}},
    ]})
    .to_string()
    .into_bytes();
    let splices: [&[u8]; 10] = [
        b"null",
        b"[]",
        b"{}",
        b"\"\"",
        b"-1e309",
        b"1e999",
        b"\"\\ud800\"",
        b"[[[[[[",
        b"\x00",
        b"\"type\":\"System.Int32\"",
    ];
    let mut rng: u64 = 0x9E37_79B9_7F4A_7C15;
    let mut next = move || {
        rng ^= rng << 13;
        rng ^= rng >> 7;
        rng ^= rng << 17;
        rng
    };
    for round in 0..300 {
        let mut body = good.clone();
        for _ in 0..=(next() % 4) {
            let at = (next() as usize) % body.len();
            match next() % 4 {
                0 => body[at] = (next() % 256) as u8,
                1 => body.truncate(at.max(1)),
                2 => {
                    let s = splices[(next() as usize) % splices.len()];
                    body.splice(at..at, s.iter().copied());
                }
                _ => {
                    let end = (at + (next() as usize) % 64).min(body.len());
                    let chunk = body[at..end].to_vec();
                    body.splice(at..at, chunk);
                }
            }
        }
        let path = ["/grasshopper", "/io", "/v1/run"][round % 3];
        let r = send(a, "POST", path, &[], &body);
        assert!(
            [200, 400, 404, 413, 500].contains(&r.status),
            "round {round}: status {} for {}",
            r.status,
            String::from_utf8_lossy(&body)
        );
        let _ = r.json();
    }
    let ok = send(a, "POST", "/grasshopper", &[], &good);
    assert_eq!(ok.status, 200);
}

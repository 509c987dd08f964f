//! Replays encodings made by rhino3dm (`tests/golden/*.json`, written by
//! `e2e/make_golden.py`): locus must decode each into the geometry rhino3dm describes, and
//! for NURBS curves and surfaces write back the very same bytes.

#[path = "common/describe.rs"]
#[allow(dead_code)]
mod describe;

use base64::Engine as _;
use locus_opennurbs_archive::{Geometry, decode_json, encode};
use serde_json::Value;

fn golden() -> Vec<(String, Value)> {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/golden");
    let mut out: Vec<(String, Value)> = std::fs::read_dir(&dir)
        .expect("tests/golden exists")
        .map(|e| e.expect("readable entry").path())
        .filter(|p| p.extension().is_some_and(|x| x == "json"))
        .map(|p| {
            let text = std::fs::read_to_string(&p).expect("readable golden file");
            let name = p.file_stem().unwrap().to_string_lossy().into_owned();
            (
                name,
                serde_json::from_str(&text).expect("golden file is JSON"),
            )
        })
        .collect();
    out.sort_by(|a, b| a.0.cmp(&b.0));
    assert!(out.len() >= 10, "golden files are missing");
    out
}

/// Compares two descriptions, numbers within `tol` (relative, with 1 as the smallest scale).
fn assert_close(a: &Value, b: &Value, tol: f64, path: &str) {
    match (a, b) {
        (Value::Object(x), Value::Object(y)) => {
            let mut kx: Vec<_> = x.keys().collect();
            let mut ky: Vec<_> = y.keys().collect();
            kx.sort();
            ky.sort();
            assert_eq!(kx, ky, "{path}: keys");
            for k in x.keys() {
                assert_close(&x[k], &y[k], tol, &format!("{path}.{k}"));
            }
        }
        (Value::Array(x), Value::Array(y)) => {
            assert_eq!(x.len(), y.len(), "{path}: lengths");
            for (i, (p, q)) in x.iter().zip(y).enumerate() {
                assert_close(p, q, tol, &format!("{path}[{i}]"));
            }
        }
        (Value::Number(p), Value::Number(q)) => {
            let (p, q) = (p.as_f64().unwrap(), q.as_f64().unwrap());
            assert!(
                (p - q).abs() <= tol * p.abs().max(q.abs()).max(1.0),
                "{path}: {p} != {q}"
            );
        }
        _ => assert_eq!(a, b, "{path}"),
    }
}

#[test]
fn locus_decodes_rhino3dm_encodings_into_the_geometry_rhino3dm_describes() {
    for (name, entry) in golden() {
        let g = decode_json(&entry["encoded"]).unwrap_or_else(|e| panic!("{name}: {e}"));
        let mut got = describe::describe(&g);
        let mut expect = entry["expect"].clone();
        if expect["type"] == "brep" {
            for key in ["faces", "edges", "vertices", "solid", "vertex_points"] {
                assert_close(&expect[key], &got[key], 0.0, &format!("{name}.{key}"));
            }
            for key in ["area", "volume"] {
                if let Some(exact) = entry["exact"][key].as_f64() {
                    let v = got[key]
                        .as_f64()
                        .unwrap_or_else(|| panic!("{name}: no {key}"));
                    assert!(
                        (v - exact).abs() <= 1e-12 * exact,
                        "{name}.{key}: {v} != {exact}"
                    );
                }
            }
            // And locus's own encoding of it reads back as the same B-rep (rational control
            // points are stored homogeneously: equal within rounding).
            let again = locus_opennurbs_archive::decode(&encode(&g).unwrap()).unwrap();
            assert_close(
                &describe::describe(&again),
                &got,
                1e-15,
                &format!("{name} re-encoded"),
            );
            continue;
        }
        if let Value::Object(exp) = &mut expect {
            if exp.get("type").and_then(Value::as_str) == Some("mesh") {
                let (a, b) = (
                    exp.remove("normals"),
                    got.as_object_mut().unwrap().remove("normals"),
                );
                assert_close(&a.unwrap(), &b.unwrap(), 1e-7, &format!("{name}.normals"));
            }
            // An arc's plane is orthonormalised again on read: equal within rounding.
            let tol = if name.contains("circle_curve") || name.contains("arc_curve") {
                1e-15
            } else {
                0.0
            };
            assert_close(&expect, &got, tol, &name);
        } else {
            // Objects rhino3dm describes by samples only (polycurves).
            let Geometry::Curve(c) = &g else {
                panic!("{name}: {g:?}")
            };
            for s in entry["samples"].as_array().expect("samples") {
                let t = s[0].as_f64().unwrap();
                let p = c.point_at(t);
                let q: Vec<f64> = s[1]
                    .as_array()
                    .unwrap()
                    .iter()
                    .map(|x| x.as_f64().unwrap())
                    .collect();
                // Same points at the breaks and on the line and cubic segments; on the arc the
                // NURBS form is parameterised differently, so check the circle there.
                let on_arc = (1.0..=1.0 + std::f64::consts::PI).contains(&t);
                if on_arc {
                    let r = ((p.x - 2.0).powi(2) + p.y * p.y).sqrt();
                    assert!(
                        (r - 1.0).abs() < 1e-12,
                        "{name} at {t}: {p:?} is off the arc"
                    );
                } else {
                    let d =
                        ((p.x - q[0]).powi(2) + (p.y - q[1]).powi(2) + (p.z - q[2]).powi(2)).sqrt();
                    assert!(d < 1e-12, "{name} at {t}: {p:?} != {q:?}");
                }
            }
        }
    }
}

#[test]
fn nurbs_curves_and_surfaces_are_written_byte_for_byte_as_rhino3dm_writes_them() {
    let mut checked = 0;
    for (name, entry) in golden() {
        if !(name.starts_with("nurbs_") || name.starts_with("surface_")) {
            continue;
        }
        let data = entry["encoded"]["data"].as_str().unwrap();
        let bytes = base64::engine::general_purpose::STANDARD
            .decode(data)
            .unwrap();
        let g = decode_json(&entry["encoded"]).unwrap();
        assert_eq!(encode(&g).unwrap(), bytes, "{name}");
        checked += 1;
    }
    assert!(checked >= 5);
}

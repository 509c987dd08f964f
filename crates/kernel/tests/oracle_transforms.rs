//! Replays the `transforms` section of `tests/data/oracle/opennurbs-cases.json`: for every case,
//! builds the transform from its parameters with the kernel, then compares the 4×4 matrix and
//! the images of the case's points with openNURBS's, to 1e-9 relative.
//!
//! Every failing case is named and all failures are reported together.

mod support;

use std::f64::consts::PI;

use locus_kernel::{Point3, Transform, Vector3};
use serde_json::Value;

/// The agreement required by the oracle's README.
const RELATIVE_TOLERANCE: f64 = 1e-9;

/// Whether `actual` agrees with `expected` to [`RELATIVE_TOLERANCE`], relative to `|expected|`
/// or to 1 if that is smaller. Matrix entries and coordinates in the oracle are of order 1, so
/// entries that are zero in exact arithmetic (and 2e-16 in openNURBS's rounding) compare on
/// the absolute scale of the matrix.
fn agrees(actual: f64, expected: f64) -> bool {
    (actual - expected).abs() <= RELATIVE_TOLERANCE * expected.abs().max(1.0)
}

fn number(value: &Value, key: &str) -> Result<f64, String> {
    value[key]
        .as_f64()
        .ok_or_else(|| format!("parameter `{key}` is missing or not a number"))
}

fn triple(value: &Value) -> Result<[f64; 3], String> {
    let items = value
        .as_array()
        .filter(|a| a.len() == 3)
        .ok_or_else(|| format!("{value} is not an array of three numbers"))?;
    let mut res = [0.0; 3];
    for (slot, item) in res.iter_mut().zip(items) {
        *slot = item
            .as_f64()
            .ok_or_else(|| format!("{item} is not a number"))?;
    }
    Ok(res)
}

fn point(value: &Value, key: &str) -> Result<Point3, String> {
    triple(&value[key])
        .map(Point3::from_array)
        .map_err(|err| format!("parameter `{key}`: {err}"))
}

fn vector(value: &Value, key: &str) -> Result<Vector3, String> {
    point(value, key).map(Point3::to_vector)
}

/// Builds the transform a case describes from its parameters, choosing the constructor by the
/// parameters present.
fn build(params: &Value) -> Result<Transform, String> {
    let has = |key: &str| params.get(key).is_some();
    if has("vector") {
        Ok(Transform::translation(vector(params, "vector")?))
    } else if has("angle_rad") {
        Transform::rotation(
            number(params, "angle_rad")?,
            vector(params, "axis")?,
            point(params, "center")?,
        )
        .map_err(|err| format!("rotation: {err}"))
    } else if has("factor") {
        Ok(Transform::scale(
            point(params, "center")?,
            number(params, "factor")?,
        ))
    } else if has("normal") {
        Transform::mirror_about(point(params, "point")?, vector(params, "normal")?)
            .map_err(|err| format!("mirror: {err}"))
    } else if has("centre") && has("angle_deg") && has("scale") {
        // The book's multiple-transformations tutorial, built the way the book builds it:
        // move the centre to the origin, rotate about z, scale, move back with the inverse of
        // the first move, and multiply from last to first.
        let centre = point(params, "centre")?;
        let angle = number(params, "angle_deg")? * PI / 180.0;
        let m1 = Transform::translation(Point3::ORIGIN - centre);
        let m2 = Transform::rotation(angle, Vector3::Z, Point3::ORIGIN)
            .map_err(|err| format!("rotation: {err}"))?;
        let m3 = Transform::scale(Point3::ORIGIN, number(params, "scale")?);
        let m4 = m1.inverse().map_err(|err| format!("inverse: {err}"))?;
        Ok(m4 * m3 * m2 * m1)
    } else {
        Err(format!("no constructor for parameters {params}"))
    }
}

/// Replays one case, returning a description of every disagreement.
fn replay(case: &Value) -> Vec<String> {
    let mut problems = Vec::new();
    let xform = match build(&case["params"]) {
        Ok(xform) => xform,
        Err(err) => return vec![err],
    };

    match case["matrix"].as_array().filter(|rows| rows.len() == 4) {
        Some(rows) => {
            let actual = xform.to_rows();
            for (i, row) in rows.iter().enumerate() {
                let Some(row) = row.as_array().filter(|r| r.len() == 4) else {
                    problems.push(format!("matrix row {i} is not four numbers"));
                    continue;
                };
                for (j, entry) in row.iter().enumerate() {
                    let Some(expected) = entry.as_f64() else {
                        problems.push(format!("matrix[{i}][{j}] is not a number"));
                        continue;
                    };
                    if !agrees(actual[i][j], expected) {
                        problems.push(format!(
                            "matrix[{i}][{j}] is {} but openNURBS gives {expected}",
                            actual[i][j]
                        ));
                    }
                }
            }
        }
        None => problems.push("`matrix` is not a 4×4 array".to_owned()),
    }

    let points = case["points"].as_array().cloned().unwrap_or_default();
    let images = case["transformed"].as_array().cloned().unwrap_or_default();
    if points.is_empty() || points.len() != images.len() {
        problems.push(format!(
            "{} points but {} transformed points",
            points.len(),
            images.len()
        ));
    }
    let inverse = xform.inverse().ok();
    for (k, (p, image)) in points.iter().zip(&images).enumerate() {
        let (p, image) = match (triple(p), triple(image)) {
            (Ok(p), Ok(image)) => (Point3::from_array(p), Point3::from_array(image)),
            (Err(err), _) | (_, Err(err)) => {
                problems.push(format!("point {k}: {err}"));
                continue;
            }
        };
        let actual = xform.transform_point(p);
        for (axis, a, e) in [
            ("x", actual.x, image.x),
            ("y", actual.y, image.y),
            ("z", actual.z, image.z),
        ] {
            if !agrees(a, e) {
                problems.push(format!(
                    "point {k} maps to {axis} = {a} but openNURBS gives {e}"
                ));
            }
        }
        // Every case of this section is invertible: the inverse must bring the image back.
        match inverse {
            Some(inverse) => {
                let back = inverse.transform_point(image);
                for (axis, a, e) in [("x", back.x, p.x), ("y", back.y, p.y), ("z", back.z, p.z)] {
                    if !agrees(a, e) {
                        problems.push(format!(
                            "the inverse maps image {k} back to {axis} = {a}, not {e}"
                        ));
                    }
                }
            }
            None if k == 0 => problems.push("the transform has no inverse".to_owned()),
            None => {}
        }
    }
    problems
}

#[test]
fn every_transform_case_matches_opennurbs() {
    let oracle = support::load_oracle("opennurbs-cases.json");
    let cases = oracle["transforms"]
        .as_array()
        .expect("the oracle has a `transforms` array");
    assert!(!cases.is_empty(), "the `transforms` section is empty");

    let mut failures = Vec::new();
    for (index, case) in cases.iter().enumerate() {
        let name = case["name"]
            .as_str()
            .map_or_else(|| format!("transforms[{index}] (unnamed)"), str::to_owned);
        for problem in replay(case) {
            failures.push(format!("{name}: {problem}"));
        }
    }
    assert!(
        failures.is_empty(),
        "{} problem(s) in {} transform case(s):\n{}",
        failures.len(),
        cases.len(),
        failures.join("\n")
    );
}

#[test]
fn tolerance_check_is_not_vacuous() {
    // A wrong matrix must be reported: replay a case with its expected matrix perturbed.
    let oracle = support::load_oracle("opennurbs-cases.json");
    let mut case = oracle["transforms"][0].clone();
    let entry = case["matrix"][0][3].as_f64().expect("a number");
    case["matrix"][0][3] = Value::from(entry + 1e-6);
    let problems = replay(&case);
    assert!(
        problems.iter().any(|p| p.contains("matrix[0][3]")),
        "{problems:?}"
    );
}

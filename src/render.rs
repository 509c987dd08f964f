//! Printing data trees and messages as text (Grasshopper notation) and as JSON.
//!
//! The JSON shapes are documented in `docs/json-output.md`.

use std::fmt::Write as _;

use locus_kernel::{Plane, Point3, Vector3};
use locus_runtime::{DataTree, Message, Value};
use serde_json::{Map, Value as Json, json};

/// A number as text: the shortest form that reads back to the same `f64`, `-0` printed as `0`.
pub fn format_number(x: f64) -> String {
    if x == 0.0 {
        return "0".to_owned();
    }
    if x.is_nan() {
        return "NaN".to_owned();
    }
    if x.is_infinite() {
        return if x > 0.0 { "∞".to_owned() } else { "-∞".to_owned() };
    }
    format!("{x}")
}

fn triple(x: f64, y: f64, z: f64) -> String {
    format!("{{{}, {}, {}}}", format_number(x), format_number(y), format_number(z))
}

fn point_text(p: Point3) -> String {
    triple(p.x, p.y, p.z)
}

fn vector_text(v: Vector3) -> String {
    triple(v.x, v.y, v.z)
}

fn plane_text(p: &Plane) -> String {
    format!(
        "O:{} X:{} Y:{} Z:{}",
        point_text(p.origin),
        vector_text(p.x_axis),
        vector_text(p.y_axis),
        vector_text(p.z_axis)
    )
}

/// One item as text, the way Grasshopper's panel shows it where it can.
pub fn value_text(value: &Value) -> String {
    match value {
        Value::Number(x) => format_number(*x),
        Value::Integer(i) => i.to_string(),
        Value::Boolean(b) => if *b { "True" } else { "False" }.to_owned(),
        Value::Text(s) => s.clone(),
        Value::Point(p) => point_text(*p),
        Value::Vector(v) => vector_text(*v),
        Value::Plane(p) => plane_text(p),
        Value::Domain(d) => format!("{} To {}", format_number(d.t0), format_number(d.t1)),
        Value::Transform(t) => {
            let rows = t.to_rows();
            let rows: Vec<String> = rows
                .iter()
                .map(|r| {
                    let cells: Vec<String> = r.iter().map(|&x| format_number(x)).collect();
                    format!("[{}]", cells.join(", "))
                })
                .collect();
            format!("Transform [{}]", rows.join(", "))
        }
    }
}

/// A tree as text: each branch as its path and item count, then its items one per line.
pub fn tree_text(tree: &DataTree) -> String {
    let mut out = String::new();
    if tree.is_empty() {
        out.push_str("  (empty tree)\n");
    }
    for (path, branch) in tree.branches() {
        let n = branch.len();
        let _ = writeln!(out, "  {path} ({n} item{})", if n == 1 { "" } else { "s" });
        for (i, v) in branch.values().enumerate() {
            match v {
                Some(v) => {
                    let _ = writeln!(out, "    {i}. {}", value_text(&v));
                }
                None => {
                    let _ = writeln!(out, "    {i}. <null>");
                }
            }
        }
    }
    out
}

fn xyz(x: f64, y: f64, z: f64) -> Json {
    json!([number_json(x), number_json(y), number_json(z)])
}

fn number_json(x: f64) -> Json {
    // JSON has no NaN or infinity: those become null (and are reported as messages by nodes).
    serde_json::Number::from_f64(if x == 0.0 { 0.0 } else { x }).map_or(Json::Null, Json::Number)
}

/// One item as JSON (see `docs/json-output.md`).
pub fn value_json(value: &Value) -> Json {
    match value {
        Value::Number(x) => number_json(*x),
        Value::Integer(i) => json!(i),
        Value::Boolean(b) => json!(b),
        Value::Text(s) => json!(s),
        Value::Point(p) => json!({ "point": xyz(p.x, p.y, p.z) }),
        Value::Vector(v) => json!({ "vector": xyz(v.x, v.y, v.z) }),
        Value::Plane(p) => json!({ "plane": {
            "origin": xyz(p.origin.x, p.origin.y, p.origin.z),
            "x": xyz(p.x_axis.x, p.x_axis.y, p.x_axis.z),
            "y": xyz(p.y_axis.x, p.y_axis.y, p.y_axis.z),
            "z": xyz(p.z_axis.x, p.z_axis.y, p.z_axis.z),
        }}),
        Value::Domain(d) => json!({ "domain": [number_json(d.t0), number_json(d.t1)] }),
        Value::Transform(t) => {
            let rows: Vec<Json> = t
                .to_rows()
                .iter()
                .map(|r| Json::Array(r.iter().map(|&x| number_json(x)).collect()))
                .collect();
            json!({ "transform": rows })
        }
    }
}

/// A tree as a JSON object `{"{0;1}": [item, …], …}` in path order.
pub fn tree_json(tree: &DataTree) -> Json {
    let mut map = Map::new();
    for (path, branch) in tree.branches() {
        let items: Vec<Json> = branch
            .values()
            .map(|v| v.as_ref().map_or(Json::Null, value_json))
            .collect();
        map.insert(path.to_string(), Json::Array(items));
    }
    Json::Object(map)
}

/// A runtime message as JSON.
pub fn message_json(m: &Message) -> Json {
    json!({
        "node": m.node.0,
        "level": m.level.name(),
        "path": m.path.as_ref().map(ToString::to_string),
        "index": m.index,
        "text": m.text,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_print_shortest_and_without_negative_zero() {
        assert_eq!(format_number(0.1), "0.1");
        assert_eq!(format_number(-0.0), "0");
        assert_eq!(format_number(2.0), "2");
    }

    #[test]
    fn trees_render_as_json_objects_by_path() {
        let t = DataTree::from_list(vec![Point3::new(1.0, 2.0, 3.0)]);
        assert_eq!(tree_json(&t).to_string(), r#"{"{0}":[{"point":[1.0,2.0,3.0]}]}"#);
    }
}

//! Printing data trees and messages as text (Grasshopper notation) and as JSON.
//!
//! The JSON shapes are documented in `docs/json-output.md`.

use std::fmt::Write as _;

use locus_kernel::{LoopKind, NurbsSurface, Plane, Point3};
use locus_runtime::{DataTree, Message, Value, format_value};
use serde_json::{Map, Value as Json, json};

/// One item as text, the way Grasshopper's panel shows it.
pub fn value_text(value: &Value) -> String {
    format_value(value)
}

/// A tree as text, one line at a time (each ending in a newline) through `emit`, built in
/// `line`: each branch as its path and item count, then its items one per line. Stops early,
/// returning `false`, when `emit` returns `false`.
pub fn tree_lines(
    tree: &DataTree,
    line: &mut String,
    emit: &mut impl FnMut(&str) -> std::io::Result<bool>,
) -> std::io::Result<bool> {
    if tree.is_empty() {
        return emit("  (empty tree)\n");
    }
    for (path, branch) in tree.branches() {
        let n = branch.len();
        line.clear();
        let _ = writeln!(line, "  {path} ({n} item{})", if n == 1 { "" } else { "s" });
        if !emit(line)? {
            return Ok(false);
        }
        for (i, v) in branch.values().enumerate() {
            line.clear();
            match v {
                Some(v) => {
                    let _ = writeln!(line, "    {i}. {}", value_text(&v));
                }
                None => {
                    let _ = writeln!(line, "    {i}. <null>");
                }
            }
            if !emit(line)? {
                return Ok(false);
            }
        }
    }
    Ok(true)
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
        Value::Plane(p) => json!({ "plane": plane_json(p) }),
        Value::Domain(d) => json!({ "domain": [number_json(d.t0), number_json(d.t1)] }),
        Value::Transform(t) => {
            let rows: Vec<Json> = t
                .to_rows()
                .iter()
                .map(|r| Json::Array(r.iter().map(|&x| number_json(x)).collect()))
                .collect();
            json!({ "transform": rows })
        }
        Value::Box(b) => json!({ "box": {
            "plane": plane_json(&b.plane),
            "x": [number_json(b.x.t0), number_json(b.x.t1)],
            "y": [number_json(b.y.t0), number_json(b.y.t1)],
            "z": [number_json(b.z.t0), number_json(b.z.t1)],
        }}),
        Value::Line(l) => json!({ "line": [point_json(l.from), point_json(l.to)] }),
        Value::Circle(c) => json!({ "circle": {
            "plane": plane_json(&c.plane),
            "radius": number_json(c.radius),
        }}),
        Value::Arc(a) => json!({ "arc": {
            "plane": plane_json(&a.circle.plane),
            "radius": number_json(a.circle.radius),
            "angle": [number_json(a.angle.t0), number_json(a.angle.t1)],
        }}),
        Value::Curve(c) => {
            let n = c.to_nurbs();
            let d = c.domain();
            json!({ "curve": {
                "degree": n.degree(),
                "points": n.points().iter().map(|p| point_json(*p)).collect::<Vec<_>>(),
                "weights": n.weights().iter().map(|&w| number_json(w)).collect::<Vec<_>>(),
                "knots": n.knots().iter().map(|&k| number_json(k)).collect::<Vec<_>>(),
                "periodic": n.is_periodic(),
                "domain": [number_json(d.t0), number_json(d.t1)],
            }})
        }
        Value::Surface(s) => json!({ "surface": surface_json(s) }),
        Value::Brep(b) => json!({ "brep": {
            "faces": b.faces().iter().map(|f| json!({
                "surface": surface_json(&f.surface),
                "reversed": f.reversed,
                // Each loop, the outer one first, as the edges its trims run along (null for a
                // trim without an edge: a singular side, such as a sphere's pole).
                "loops": f.loops.iter().map(|&l| {
                    let lp = &b.loops()[l];
                    json!({
                        "outer": lp.kind == LoopKind::Outer,
                        "edges": lp.trims.iter().map(|&t| b.trims()[t].edge).collect::<Vec<_>>(),
                    })
                }).collect::<Vec<_>>(),
            })).collect::<Vec<_>>(),
            "edges": b.edges().iter().map(|e| {
                let c = &e.curve;
                json!({
                    "degree": c.degree(),
                    "points": c.points().iter().map(|p| point_json(*p)).collect::<Vec<_>>(),
                    "weights": c.weights().iter().map(|&w| number_json(w)).collect::<Vec<_>>(),
                    "knots": c.knots().iter().map(|&k| number_json(k)).collect::<Vec<_>>(),
                    "vertices": e.vertices,
                })
            }).collect::<Vec<_>>(),
            "vertices": b.vertices().iter().map(|v| point_json(v.point)).collect::<Vec<_>>(),
        }}),
        Value::Mesh(m) => {
            let mut mesh = Map::new();
            mesh.insert(
                "vertices".into(),
                m.vertices().iter().map(|p| point_json(*p)).collect(),
            );
            // Faces as three or four vertex indices (a triangle does not repeat its last).
            mesh.insert(
                "faces".into(),
                m.faces().iter().map(|f| json!(f.corners())).collect(),
            );
            if let Some(n) = m.normals() {
                mesh.insert(
                    "normals".into(),
                    n.iter().map(|v| xyz(v.x, v.y, v.z)).collect(),
                );
            }
            if let Some(c) = m.colors() {
                mesh.insert(
                    "colours".into(),
                    c.iter().map(|&c| colour_json(c)).collect(),
                );
            }
            json!({ "mesh": mesh })
        }
        Value::Colour(c) => json!({ "colour": colour_json(*c) }),
    }
}

/// A colour as `[r, g, b, a]`, each 0 to 255.
fn colour_json(c: locus_kernel::Color) -> Json {
    json!([c.r, c.g, c.b, c.a])
}

fn surface_json(s: &NurbsSurface) -> Json {
    json!({
        "degree": [s.degree_u(), s.degree_v()],
        "count": [s.count_u(), s.count_v()],
        "points": s.points().iter().map(|p| point_json(*p)).collect::<Vec<_>>(),
        "weights": s.weights().iter().map(|&w| number_json(w)).collect::<Vec<_>>(),
        "knots_u": s.knots_u().iter().map(|&k| number_json(k)).collect::<Vec<_>>(),
        "knots_v": s.knots_v().iter().map(|&k| number_json(k)).collect::<Vec<_>>(),
    })
}

fn point_json(p: Point3) -> Json {
    xyz(p.x, p.y, p.z)
}

fn plane_json(p: &Plane) -> Json {
    json!({
        "origin": xyz(p.origin.x, p.origin.y, p.origin.z),
        "x": xyz(p.x_axis.x, p.x_axis.y, p.x_axis.z),
        "y": xyz(p.y_axis.x, p.y_axis.y, p.y_axis.z),
        "z": xyz(p.z_axis.x, p.z_axis.y, p.z_axis.z),
    })
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

/// Text from a graph made safe for a terminal: control characters other than newline and tab
/// (ANSI escape sequences start with one) and the bidirectional overrides and isolates that
/// reorder what is displayed (U+202A–U+202E, U+2066–U+2069) are written as `\u{…}` escapes.
pub fn terminal_safe(text: &str) -> std::borrow::Cow<'_, str> {
    let unsafe_char = |c: char| {
        (c.is_control() && c != '\n' && c != '\t')
            || ('\u{202a}'..='\u{202e}').contains(&c)
            || ('\u{2066}'..='\u{2069}').contains(&c)
    };
    if !text.chars().any(unsafe_char) {
        return std::borrow::Cow::Borrowed(text);
    }
    let mut out = String::with_capacity(text.len() + 8);
    for c in text.chars() {
        if unsafe_char(c) {
            let _ = write!(out, "\\u{{{:x}}}", c as u32);
        } else {
            out.push(c);
        }
    }
    std::borrow::Cow::Owned(out)
}

/// `text` made safe with [`terminal_safe`] when `stream` is a terminal, else as it is.
pub fn for_stream<'a>(
    text: &'a str,
    stream: &impl std::io::IsTerminal,
) -> std::borrow::Cow<'a, str> {
    if stream.is_terminal() {
        terminal_safe(text)
    } else {
        std::borrow::Cow::Borrowed(text)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn trees_render_as_json_objects_by_path() {
        let t = DataTree::from_list(vec![Point3::new(1.0, 2.0, 3.0)]);
        assert_eq!(
            serde_json::to_string(&crate::stream::TreeJson(&t)).unwrap(),
            r#"{"{0}":[{"point":[1.0,2.0,3.0]}]}"#
        );
    }

    #[test]
    fn negative_zero_is_written_as_zero() {
        assert_eq!(number_json(-0.0).to_string(), "0.0");
    }

    #[test]
    fn terminal_safe_escapes_ansi_and_bidi_controls() {
        assert_eq!(terminal_safe("plain\ttext\n"), "plain\ttext\n");
        assert_eq!(terminal_safe("a\u{1b}[31mred"), "a\\u{1b}[31mred");
        assert_eq!(
            terminal_safe("x\u{202e}y\u{2066}z"),
            "x\\u{202e}y\\u{2066}z"
        );
        assert_eq!(terminal_safe("bell\u{7}"), "bell\\u{7}");
    }
}

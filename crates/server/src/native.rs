//! locus's own API, `POST /v1/run`: the `--format json` schema of `locus run`
//! (`docs/json-output.md`), with inputs in the same item forms.
//!
//! Request: `{"graph": RON text | "algo": base64 | "pointer": key or file, "inputs": {NAME:
//! TREE}, "literals": {NAME: "literal text"}}`. A TREE is an object `{"{0;1}": [ITEM, …]}`, a
//! list (one branch `{0}`) or one item. Answer: `{"pointer", "outputs", "messages"}`. Unlike
//! the Compute endpoints, an unknown input name is a 400 here.

use base64::Engine as _;
use locus_kernel::{
    Arc, Circle, Interval, Line, LoopKind, NurbsSurface, OrientedBox, Plane, Point3, Transform,
    Vector3,
};
use locus_runtime::{Branch, DataTree, DataType, Message, Value, cast_value};
use serde::Deserialize;
use serde_json::{Map, Value as Json, json};

use crate::compute::parse_path;
use crate::definition::InputInfo;
use crate::error::ApiError;
use crate::state::State;

/// A `/v1/run` request.
#[derive(Debug, Default, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct RunRequest {
    /// The graph as RON text.
    pub graph: Option<String>,
    /// The definition as base64 (as in Compute's `algo`).
    pub algo: Option<String>,
    /// A cached definition's key or a file under the definitions folder.
    pub pointer: Option<String>,
    /// Input trees in locus's JSON item forms.
    pub inputs: Map<String, Json>,
    /// Inputs as literal text, written as in graph files (`"(1, 2, 3)"`).
    pub literals: Map<String, Json>,
}

/// Runs a `/v1/run` request.
///
/// # Errors
/// 400 for malformed requests, unknown inputs and bad values; as [`State::resolve`] otherwise.
pub fn run(state: &State, body: &[u8]) -> Result<Json, ApiError> {
    let request: RunRequest = serde_json::from_slice(body)
        .map_err(|e| ApiError::bad_request(format!("the request does not fit the schema: {e}")))?;
    let algo = match (&request.graph, &request.algo) {
        (Some(_), Some(_)) => {
            return Err(ApiError::bad_request(
                "send \"graph\" or \"algo\", not both",
            ));
        }
        (Some(text), None) => Some(base64::engine::general_purpose::STANDARD.encode(text)),
        (None, algo) => algo.clone(),
    };
    let entry = state.resolve(algo.as_deref(), request.pointer.as_deref())?;
    let definition = &entry.definition;
    let max_items = state.config.limits.max_input_items;
    let mut items = 0usize;
    let mut trees: Vec<(&str, DataTree)> = Vec::new();
    let find = |name: &str| -> Result<&InputInfo, ApiError> {
        definition
            .inputs
            .iter()
            .find(|i| i.name == name)
            .ok_or_else(|| {
                let known: Vec<&str> = definition.inputs.iter().map(|i| i.name.as_str()).collect();
                ApiError::bad_request(format!(
                    "unknown input \"{name}\" (the definition's inputs are: {})",
                    if known.is_empty() {
                        "none".into()
                    } else {
                        known.join(", ")
                    }
                ))
            })
    };
    for (name, tree) in &request.inputs {
        let input = find(name)?;
        let tree = decode_tree(input, tree)?;
        items += tree.item_count();
        if items > max_items {
            return Err(ApiError::too_large(format!(
                "the request sends more than {max_items} items (the per-request limit)"
            )));
        }
        trees.push((&input.name, tree));
    }
    let mut literals: Vec<(&str, &str)> = Vec::new();
    for (name, text) in &request.literals {
        let input = find(name)?;
        let Json::String(text) = text else {
            return Err(ApiError::bad_request(format!(
                "literal for input \"{name}\" must be a string"
            )));
        };
        literals.push((&input.name, text));
    }
    let (mut evaluator, _warm) = entry.checkout();
    for input in &definition.inputs {
        if let Some(k) = trees.iter().position(|(n, _)| *n == input.name) {
            let tree = std::mem::take(&mut trees[k].1);
            evaluator
                .set_input(&input.name, tree)
                .map_err(|e| ApiError::internal(e.to_string()))?;
        } else if let Some((_, text)) = literals.iter().find(|(n, _)| *n == input.name) {
            // A bad literal leaves this evaluator's inputs half set: it is dropped, not reused.
            evaluator
                .set_input_text(&input.name, text)
                .map_err(|e| ApiError::bad_request(e.to_string()))?;
        } else {
            evaluator.clear_input(&input.name);
        }
    }
    evaluator.evaluate();
    let mut outputs = Map::new();
    let mut count = 0usize;
    for (name, tree) in evaluator.outputs() {
        count += tree.item_count();
        if count > state.config.limits.max_output_items {
            return Err(ApiError::new(
                axum::http::StatusCode::INTERNAL_SERVER_ERROR,
                "output_limit",
                format!(
                    "the outputs hold more than {} items (the per-answer limit), at output \"{name}\"",
                    state.config.limits.max_output_items
                ),
            ));
        }
        outputs.insert(name.to_owned(), tree_json(tree));
    }
    let messages: Vec<Json> = evaluator.messages().map(message_json).collect();
    let answer = json!({
        "pointer": definition.pointer,
        "outputs": outputs,
        "messages": messages,
    });
    entry.checkin(evaluator);
    Ok(answer)
}

fn decode_tree(input: &InputInfo, json: &Json) -> Result<DataTree, ApiError> {
    let name = &input.name;
    let branch_of = |path: &str, items: &[Json]| -> Result<Branch, ApiError> {
        let mut b = Branch::new(input.data_type);
        for (i, item) in items.iter().enumerate() {
            let v = decode_item(item, input.data_type)
                .map_err(|e| ApiError::bad_request(format!("input \"{name}\" {path}[{i}]: {e}")))?;
            b.push_option(v);
        }
        Ok(b)
    };
    let mut tree = DataTree::new();
    match json {
        Json::Object(o) if o.keys().all(|k| k.starts_with('{')) && !o.is_empty() => {
            for (key, items) in o {
                let path = parse_path(key)
                    .map_err(|e| ApiError::bad_request(format!("input \"{name}\": {e}")))?;
                let Json::Array(items) = items else {
                    return Err(ApiError::bad_request(format!(
                        "input \"{name}\" {path}: a branch must be a list of items"
                    )));
                };
                let b = branch_of(key, items)?;
                tree.append(path, &b);
            }
        }
        Json::Array(items) => {
            tree.insert(locus_runtime::TreePath::zero(), branch_of("{0}", items)?);
        }
        item => {
            let b = branch_of("{0}", std::slice::from_ref(item))?;
            tree.insert(locus_runtime::TreePath::zero(), b);
        }
    }
    Ok(tree)
}

fn f(j: &Json, what: &str) -> Result<f64, String> {
    match j.as_f64() {
        Some(x) if x.is_finite() => Ok(x),
        _ => Err(format!("{what} must be a finite number")),
    }
}

fn triple(j: &Json, what: &str) -> Result<[f64; 3], String> {
    match j.as_array().map(Vec::as_slice) {
        Some([x, y, z]) => Ok([f(x, what)?, f(y, what)?, f(z, what)?]),
        _ => Err(format!("{what} must be [x, y, z]")),
    }
}

fn pair(j: &Json, what: &str) -> Result<Interval, String> {
    match j.as_array().map(Vec::as_slice) {
        Some([a, b]) => Ok(Interval::new(f(a, what)?, f(b, what)?)),
        _ => Err(format!("{what} must be [t0, t1]")),
    }
}

fn pt(j: &Json) -> Result<Point3, String> {
    let [x, y, z] = triple(j, "a point")?;
    Ok(Point3::new(x, y, z))
}

fn vec3(j: &Json) -> Result<Vector3, String> {
    let [x, y, z] = triple(j, "a vector")?;
    Ok(Vector3::new(x, y, z))
}

fn get<'a>(o: &'a Json, key: &str, what: &str) -> Result<&'a Json, String> {
    o.get(key).ok_or_else(|| format!("{what} needs \"{key}\""))
}

fn plane(j: &Json) -> Result<Plane, String> {
    Plane::from_frame(
        pt(get(j, "origin", "a plane")?)?,
        vec3(get(j, "x", "a plane")?)?,
        vec3(get(j, "y", "a plane")?)?,
    )
    .map_err(|e| format!("not a valid plane: {e}"))
}

fn circle(j: &Json, what: &str) -> Result<Circle, String> {
    Circle::new(
        plane(get(j, "plane", what)?)?,
        f(get(j, "radius", what)?, "a radius")?,
    )
    .map_err(|e| format!("not a valid {what}: {e}"))
}

/// Reads one item in locus's JSON form (`docs/json-output.md`) for an input of type `target`.
///
/// # Errors
/// The reason when the item has no such form or does not cast to `target`.
pub fn decode_item(j: &Json, target: DataType) -> Result<Option<Value>, String> {
    let value = match j {
        Json::Null => return Ok(None),
        Json::Bool(b) => Value::Boolean(*b),
        Json::Number(n) => match n.as_i64() {
            Some(i) if target == DataType::Integer => Value::Integer(i),
            _ => Value::Number(f(j, "a number")?),
        },
        Json::String(s) => Value::Text(s.clone()),
        Json::Object(o) if o.len() == 1 => {
            let (key, v) = o.iter().next().ok_or("an empty object is not an item")?;
            match key.as_str() {
                "point" => Value::Point(pt(v)?),
                "vector" => Value::Vector(vec3(v)?),
                "plane" => Value::Plane(plane(v)?),
                "domain" => Value::Domain(pair(v, "a domain")?),
                "line" => match v.as_array().map(Vec::as_slice) {
                    Some([a, b]) => Value::Line(Line::new(pt(a)?, pt(b)?)),
                    _ => return Err("a line must be [[x, y, z], [x, y, z]]".into()),
                },
                "circle" => Value::Circle(circle(v, "circle")?),
                "arc" => Value::Arc(
                    Arc::new(
                        circle(v, "arc")?,
                        pair(get(v, "angle", "an arc")?, "an angle")?,
                    )
                    .map_err(|e| format!("not a valid arc: {e}"))?,
                ),
                "box" => Value::Box(OrientedBox::new(
                    plane(get(v, "plane", "a box")?)?,
                    pair(get(v, "x", "a box")?, "\"x\" of a box")?,
                    pair(get(v, "y", "a box")?, "\"y\" of a box")?,
                    pair(get(v, "z", "a box")?, "\"z\" of a box")?,
                )),
                "transform" => {
                    let rows = v
                        .as_array()
                        .filter(|r| r.len() == 4)
                        .ok_or("a transform must be 4 rows of 4 numbers")?;
                    let mut m = [[0.0; 4]; 4];
                    for (r, row) in rows.iter().enumerate() {
                        let row = row
                            .as_array()
                            .filter(|c| c.len() == 4)
                            .ok_or("a transform must be 4 rows of 4 numbers")?;
                        for (c, x) in row.iter().enumerate() {
                            m[r][c] = f(x, "a transform entry")?;
                        }
                    }
                    Value::Transform(Transform::from_rows(m))
                }
                "curve" | "surface" | "brep" => {
                    return Err(format!("{key} items are not accepted as inputs yet"));
                }
                other => return Err(format!("unknown item form \"{other}\"")),
            }
        }
        other => {
            return Err(format!(
                "{} is not an item (see docs/json-output.md)",
                if other.is_array() {
                    "an array"
                } else {
                    "this object"
                }
            ));
        }
    };
    if target == DataType::Generic || value.data_type() == target {
        return Ok(Some(value));
    }
    cast_value(&value, target).map(Some).map_err(|e| {
        format!(
            "a {} item cannot be used as a {}: {e}",
            value.data_type().name(),
            target.name()
        )
    })
}

fn xyz(x: f64, y: f64, z: f64) -> Json {
    json!([number_json(x), number_json(y), number_json(z)])
}

fn number_json(x: f64) -> Json {
    // JSON has no NaN or infinity: those become null (their nodes report them).
    serde_json::Number::from_f64(if x == 0.0 { 0.0 } else { x }).map_or(Json::Null, Json::Number)
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

fn nums(xs: &[f64]) -> Vec<Json> {
    xs.iter().map(|&x| number_json(x)).collect()
}

fn surface_json(s: &NurbsSurface) -> Json {
    json!({
        "degree": [s.degree_u(), s.degree_v()],
        "count": [s.count_u(), s.count_v()],
        "points": s.points().iter().map(|p| point_json(*p)).collect::<Vec<_>>(),
        "weights": nums(s.weights()),
        "knots_u": nums(s.knots_u()),
        "knots_v": nums(s.knots_v()),
    })
}

/// One item in locus's JSON form, the same as `locus run --format json` writes.
pub fn value_json(value: &Value) -> Json {
    match value {
        Value::Number(x) => number_json(*x),
        Value::Integer(i) => json!(i),
        Value::Boolean(b) => json!(b),
        Value::Text(s) => json!(s),
        Value::Point(p) => json!({ "point": point_json(*p) }),
        Value::Vector(v) => json!({ "vector": xyz(v.x, v.y, v.z) }),
        Value::Plane(p) => json!({ "plane": plane_json(p) }),
        Value::Domain(d) => json!({ "domain": [number_json(d.t0), number_json(d.t1)] }),
        Value::Transform(t) => {
            let rows: Vec<Json> = t.to_rows().iter().map(|r| Json::Array(nums(r))).collect();
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
            "plane": plane_json(&c.plane), "radius": number_json(c.radius),
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
                "weights": nums(n.weights()),
                "knots": nums(n.knots()),
                "periodic": n.is_periodic(),
                "domain": [number_json(d.t0), number_json(d.t1)],
            }})
        }
        Value::Surface(s) => json!({ "surface": surface_json(s) }),
        Value::Brep(b) => json!({ "brep": {
            "faces": b.faces().iter().map(|f| json!({
                "surface": surface_json(&f.surface),
                "reversed": f.reversed,
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
                    "weights": nums(c.weights()),
                    "knots": nums(c.knots()),
                    "vertices": e.vertices,
                })
            }).collect::<Vec<_>>(),
            "vertices": b.vertices().iter().map(|v| point_json(v.point)).collect::<Vec<_>>(),
        }}),
        // As `locus run --format json` writes them (docs/json-output.md).
        Value::Mesh(m) => {
            let mut mesh = Map::new();
            mesh.insert(
                "vertices".into(),
                m.vertices().iter().map(|p| point_json(*p)).collect(),
            );
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
                    c.iter().map(|c| json!([c.r, c.g, c.b, c.a])).collect(),
                );
            }
            json!({ "mesh": Json::Object(mesh) })
        }
        Value::Colour(c) => json!({ "colour": [c.r, c.g, c.b, c.a] }),
    }
}

/// A tree as `{"{0;1}": [item, …]}` in path order.
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

/// A runtime message as JSON: node, level, path, index, text.
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
    fn items_read_back_what_value_json_writes() {
        let plane = Plane::WORLD_XY;
        let values = [
            Value::Number(1.5),
            Value::Point(Point3::new(1.0, 2.0, 3.0)),
            Value::Vector(Vector3::new(0.0, 1.0, 0.0)),
            Value::Plane(plane),
            Value::Domain(Interval::new(0.0, 2.0)),
            Value::Line(Line::new(Point3::ORIGIN, Point3::new(1.0, 0.0, 0.0))),
            Value::Circle(Circle::new(plane, 2.0).unwrap()),
            Value::Box(OrientedBox::new(
                plane,
                Interval::new(0.0, 1.0),
                Interval::new(0.0, 2.0),
                Interval::new(0.0, 3.0),
            )),
        ];
        for v in values {
            let back = decode_item(&value_json(&v), v.data_type());
            assert_eq!(back, Ok(Some(v.clone())));
        }
        assert_eq!(
            decode_item(&json!(3), DataType::Integer),
            Ok(Some(Value::Integer(3)))
        );
        assert!(decode_item(&json!({"nope": 1}), DataType::Number).is_err());
        assert!(decode_item(&json!({"point": [1, 2]}), DataType::Point).is_err());
    }
}

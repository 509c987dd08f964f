//! locus's own API, `POST /v1/run`: the `--format json` schema of `locus run`
//! (`docs/json-output.md`), with inputs in the same item forms.
//!
//! Request: `{"graph": RON text | "algo": base64 | "pointer": key or file, "inputs": {NAME:
//! TREE}, "literals": {NAME: "literal text"}}`. A TREE is an object `{"{0;1}": [ITEM, …]}`, a
//! list (one branch `{0}`) or one item. Answer: `{"pointer", "outputs", "messages"}`. Unlike
//! the Compute endpoints, an unknown input name is a 400 here.

use base64::Engine as _;
use locus_kernel::{
    Arc, Circle, Interval, Line, OrientedBox, Plane, Point3, Transform, UvInterval, Vector3,
};
use locus_runtime::{
    Branch, DataTree, DataType, Message, MessageJson, TreeJson, Value, ValueJson, cast_value,
};
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
                "domain2" => Value::Domain2(UvInterval::new(
                    pair(get(v, "u", "a domain2")?, "\"u\" of a domain2")?,
                    pair(get(v, "v", "a domain2")?, "\"v\" of a domain2")?,
                )),
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

/// A tree in locus's JSON form, as `locus run --format json` writes it.
pub fn tree_json(tree: &DataTree) -> Json {
    serde_json::to_value(TreeJson(tree)).unwrap_or(Json::Null)
}

/// A runtime message in locus's JSON form: node, level, path, index, text.
pub fn message_json(m: &Message) -> Json {
    serde_json::to_value(MessageJson(m)).unwrap_or(Json::Null)
}

/// One item in locus's JSON form.
pub fn value_json(value: &Value) -> Json {
    serde_json::to_value(ValueJson(value)).unwrap_or(Json::Null)
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

//! Rhino.Compute's Grasshopper endpoints: `POST /grasshopper` (and `/solve`) and `POST /io`,
//! in Compute's schema (`docs/server.md` has the mapping).
//!
//! The server is stateless per request: an input a request does not send takes the
//! definition's own value, not the one of an earlier request (Compute keeps the earlier one).

use std::collections::HashSet;

use locus_runtime::{Access, Branch, DataTree, DataType, Evaluator, Level, TreePath};
use serde::Deserialize;
use serde_json::{Map, Value as Json, json};

use crate::compute_items::{decode_item, dotnet_type, encode_value};
use crate::definition::{Definition, InputInfo, first_item};
use crate::error::ApiError;
use crate::native::message_json;
use crate::state::State;

/// A Compute request (unknown keys are ignored, as Compute does).
#[derive(Debug, Default, Deserialize)]
#[serde(default)]
pub struct ComputeRequest {
    /// Base64 of the definition file.
    pub algo: Option<String>,
    /// A cached definition's key or a file under the definitions folder.
    pub pointer: Option<String>,
    /// Input trees.
    pub values: Vec<InputTree>,
    /// Echoed back.
    pub absolutetolerance: Option<Json>,
    /// Echoed back.
    pub angletolerance: Option<Json>,
    /// Echoed back.
    pub modelunits: Option<Json>,
    /// Echoed back.
    pub dataversion: Option<Json>,
    /// Echoed back.
    pub cachesolve: Option<Json>,
    /// Echoed back.
    pub recursionlevel: Option<Json>,
}

/// One input tree: `{"ParamName": NAME, "InnerTree": {PATH: [ITEM, …]}}`.
#[derive(Debug, Default, Deserialize)]
#[serde(default)]
pub struct InputTree {
    /// The input's name.
    #[serde(rename = "ParamName")]
    pub param_name: String,
    /// The branches by path.
    #[serde(rename = "InnerTree")]
    pub inner_tree: Map<String, Json>,
}

/// Reads a Compute request body (a `[ {...} ]` wrapper is unwrapped).
///
/// # Errors
/// 400 with serde's reason (line and column) for malformed JSON or wrong field types.
pub fn parse_request(body: &[u8]) -> Result<ComputeRequest, ApiError> {
    let json: Json = serde_json::from_slice(body)
        .map_err(|e| ApiError::bad_request(format!("the body is not JSON: {e}")))?;
    let json = match json {
        Json::Array(mut items) if items.len() == 1 => items.remove(0),
        other => other,
    };
    if !json.is_object() {
        return Err(ApiError::bad_request("the body must be a JSON object"));
    }
    serde_json::from_value(json)
        .map_err(|e| ApiError::bad_request(format!("the request does not fit the schema: {e}")))
}

/// Reads a path key as Compute does: spaces and braces dropped, `;`-separated indices.
///
/// # Errors
/// The reason when an index is not a whole number.
pub fn parse_path(key: &str) -> Result<TreePath, String> {
    let cleaned: String = key
        .chars()
        .filter(|c| !c.is_whitespace() && *c != '{' && *c != '}')
        .collect();
    let indices: Result<Vec<u32>, _> = cleaned
        .split(';')
        .filter(|s| !s.is_empty())
        .map(str::parse::<u32>)
        .collect();
    match indices {
        Ok(i) if !i.is_empty() => Ok(TreePath::new(i)),
        _ => Err(format!("\"{key}\" is not a tree path such as {{0;1}}")),
    }
}

/// Reads one input tree against the input's type, counting items into `items`.
///
/// # Errors
/// 400 naming the input, path and index of the first bad item; 413 past the item limit.
fn decode_tree(
    input: &InputInfo,
    tree: &InputTree,
    items: &mut usize,
    max_items: usize,
) -> Result<DataTree, ApiError> {
    // Errors name the input as the caller did.
    let name = &tree.param_name;
    let mut out = DataTree::new();
    for (key, branch) in &tree.inner_tree {
        let path =
            parse_path(key).map_err(|e| ApiError::bad_request(format!("input \"{name}\": {e}")))?;
        let Json::Array(list) = branch else {
            return Err(ApiError::bad_request(format!(
                "input \"{name}\" {path}: a branch must be a list of items"
            )));
        };
        *items += list.len();
        if *items > max_items {
            return Err(ApiError::too_large(format!(
                "the request sends more than {max_items} items (the per-request limit)"
            )));
        }
        let data_type = if input.data_type == DataType::Generic {
            DataType::Generic
        } else {
            input.data_type
        };
        let mut b = Branch::new(data_type);
        for (i, item) in list.iter().enumerate() {
            let value = decode_item(item, input.data_type)
                .map_err(|e| ApiError::bad_request(format!("input \"{name}\" {path}[{i}]: {e}")))?;
            b.push_option(value);
        }
        out.append(path, &b);
    }
    Ok(out)
}

/// Sets the inputs a request sends and resets the others to the definition's values.
/// Returns the names that match no input (skipped, as Compute does) and the warnings.
///
/// # Errors
/// 400/413 from [`decode_tree`].
pub fn apply_inputs(
    definition: &Definition,
    evaluator: &mut Evaluator,
    values: &[InputTree],
    max_items: usize,
) -> Result<(Vec<String>, Vec<String>), ApiError> {
    let mut skipped = Vec::new();
    let mut warnings = Vec::new();
    let mut decoded: Vec<(&str, DataTree)> = Vec::new();
    let mut seen = HashSet::new();
    let mut items = 0;
    for tree in values {
        let Some(input) = definition
            .inputs
            .iter()
            .find(|i| i.compute_name.as_deref() == Some(tree.param_name.as_str()))
        else {
            skipped.push(tree.param_name.clone());
            continue;
        };
        if !seen.insert(input.name.as_str()) {
            warnings.push(format!(
                "input \"{}\" is sent more than once; the first is used",
                tree.param_name
            ));
            continue;
        }
        decoded.push((
            &input.name,
            decode_tree(input, tree, &mut items, max_items)?,
        ));
    }
    for input in &definition.inputs {
        match decoded.iter().position(|(n, _)| *n == input.name) {
            Some(k) => {
                let tree = std::mem::take(&mut decoded[k].1);
                evaluator
                    .set_input(&input.name, tree)
                    .map_err(|e| ApiError::internal(e.to_string()))?;
            }
            None => evaluator.clear_input(&input.name),
        }
    }
    Ok((skipped, warnings))
}

/// Solves a Compute request.
///
/// # Errors
/// 4xx for caller errors, 500 for unknown pointers and output limits.
pub fn solve(state: &State, body: &[u8]) -> Result<Json, ApiError> {
    let request = parse_request(body)?;
    let entry = state.resolve(request.algo.as_deref(), request.pointer.as_deref())?;
    let definition = &entry.definition;
    let (mut evaluator, warm) = entry.checkout();
    let limits = &state.config.limits;
    let (skipped, mut warnings) = apply_inputs(
        definition,
        &mut evaluator,
        &request.values,
        limits.max_input_items,
    )?;
    evaluator.evaluate();

    let mut errors: Vec<String> = definition.errors.clone();
    if definition.format != crate::definition::Format::Ron {
        // What the importer said about a Grasshopper file goes with every answer (a RON graph's
        // checking warnings are in `/io` only).
        warnings.splice(0..0, definition.warnings.iter().cloned());
    }
    let mut values = Vec::new();
    let mut count = 0usize;
    for out in &definition.outputs {
        let Some(compute_name) = &out.compute_name else {
            continue;
        };
        let Some(tree) = evaluator.output(&out.name) else {
            continue;
        };
        count += tree.item_count();
        if count > limits.max_output_items {
            return Err(ApiError::new(
                axum::http::StatusCode::INTERNAL_SERVER_ERROR,
                "output_limit",
                format!(
                    "the outputs hold more than {} items (the per-answer limit), at output \"{}\"",
                    limits.max_output_items, out.name
                ),
            ));
        }
        let mut inner = Map::new();
        for (path, branch) in tree.branches() {
            let mut items = Vec::with_capacity(branch.len());
            // Null items are left out, as Compute does (later indices shift).
            for (i, v) in branch.values().enumerate() {
                let Some(v) = v else { continue };
                match encode_value(&v) {
                    Ok((t, data)) => items.push(json!({"type": t, "data": data})),
                    Err(e) => errors.push(format!("output \"{compute_name}\" {path}[{i}]: {e}")),
                }
            }
            inner.insert(path.to_string(), Json::Array(items));
        }
        values.push(json!({"ParamName": compute_name, "InnerTree": inner}));
    }
    for m in evaluator.messages() {
        match m.level {
            Level::Error => errors.push(m.to_string()),
            Level::Warning => warnings.push(m.to_string()),
            Level::Remark => {}
        }
    }
    let messages: Vec<Json> = evaluator.messages().map(message_json).collect();
    let nodes_run = evaluator.last_run().len();

    let mut answer = Map::new();
    let echo = |v: &Option<Json>, default: Json| v.clone().unwrap_or(default);
    answer.insert(
        "absolutetolerance".into(),
        echo(&request.absolutetolerance, json!(0.0)),
    );
    answer.insert(
        "angletolerance".into(),
        echo(&request.angletolerance, json!(0.0)),
    );
    answer.insert(
        "modelunits".into(),
        echo(&request.modelunits, json!("Millimeters")),
    );
    answer.insert("dataversion".into(), echo(&request.dataversion, json!(7)));
    answer.insert("algo".into(), json!(""));
    answer.insert("pointer".into(), json!(definition.pointer));
    answer.insert("cachesolve".into(), echo(&request.cachesolve, json!(false)));
    answer.insert(
        "recursionlevel".into(),
        echo(&request.recursionlevel, json!(0)),
    );
    answer.insert("values".into(), Json::Array(values));
    if !warnings.is_empty() {
        answer.insert("warnings".into(), json!(warnings));
    }
    if !errors.is_empty() {
        answer.insert("errors".into(), json!(errors));
    }
    // What locus says beyond Compute, which Compute clients ignore.
    answer.insert(
        "locus".into(),
        json!({
            "messages": messages,
            "skipped_inputs": skipped,
            // Whether an evaluator of an earlier solve was reused, and how many nodes ran.
            "warm": warm,
            "nodes_run": nodes_run,
        }),
    );
    entry.checkin(evaluator);
    Ok(Json::Object(answer))
}

/// Grasshopper's name of a value type, as `/io`'s `ParamType`.
fn param_type(t: DataType) -> &'static str {
    match t {
        DataType::Domain => "Interval",
        DataType::Generic => "Geometry",
        other => other.name(),
    }
}

fn tree_json_compute(tree: &DataTree) -> Json {
    let mut inner = Map::new();
    for (path, branch) in tree.branches() {
        let items: Vec<Json> = branch
            .values()
            .flatten()
            .filter_map(|v| encode_value(&v).ok())
            .map(|(t, data)| json!({"type": t, "data": data}))
            .collect();
        inner.insert(path.to_string(), Json::Array(items));
    }
    Json::Object(inner)
}

/// Describes a definition's inputs and outputs (`POST /io`), in Compute's PascalCase schema.
///
/// # Errors
/// As [`State::resolve`].
pub fn io(state: &State, body: &[u8]) -> Result<Json, ApiError> {
    let request = parse_request(body)?;
    let entry = state.resolve(request.algo.as_deref(), request.pointer.as_deref())?;
    let d = &entry.definition;
    // Compute lists inputs and outputs top to bottom on the canvas.
    let mut visible_inputs: Vec<(&InputInfo, &str)> = d
        .inputs
        .iter()
        .filter_map(|i| Some((i, i.compute_name.as_deref()?)))
        .collect();
    visible_inputs.sort_by(|a, b| a.0.canvas_y.total_cmp(&b.0.canvas_y));
    let mut visible_outputs: Vec<(&crate::definition::OutputInfo, &str)> = d
        .outputs
        .iter()
        .filter_map(|o| Some((o, o.compute_name.as_deref()?)))
        .collect();
    visible_outputs.sort_by(|a, b| a.0.canvas_y.total_cmp(&b.0.canvas_y));
    let inputs: Vec<Json> = visible_inputs
        .iter()
        .map(|&(i, name)| {
            let at_most = if i.access == Access::Item {
                1
            } else {
                i32::MAX
            };
            let at_least = i32::from(!(i.optional || i.default.is_some()));
            json!({
                "Name": name,
                "Nickname": null,
                "ParamType": param_type(i.data_type),
                "Description": i.description,
                "AtLeast": at_least,
                "AtMost": at_most,
                "TreeAccess": i.access == Access::Tree,
                "Default": i.default.as_ref().map(|t| json!({
                    "ParamName": name, "InnerTree": tree_json_compute(t)
                })),
                // locus inputs have no slider limits.
                "Minimum": null,
                "Maximum": null,
                "locus": {"type": i.data_type.name(), "dotnet_type": dotnet_type(i.data_type),
                          "default_item": i.default.as_ref().and_then(first_item)
                              .map(|v| crate::native::value_json(&v))},
            })
        })
        .collect();
    let outputs: Vec<Json> = visible_outputs
        .iter()
        .map(|&(o, name)| json!({"Name": name, "Nickname": null, "ParamType": param_type(o.data_type)}))
        .collect();
    Ok(json!({
        "Description": d.description,
        "CacheKey": d.pointer,
        "InputNames": visible_inputs.iter().map(|(_, n)| *n).collect::<Vec<_>>(),
        "OutputNames": visible_outputs.iter().map(|(_, n)| *n).collect::<Vec<_>>(),
        "Icon": null,
        "Inputs": inputs,
        "Outputs": outputs,
        "Warnings": d.warnings,
        "Errors": d.errors,
    }))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn path_keys_are_normalised_as_compute_does() {
        let want = TreePath::new(vec![0, 1]);
        for key in ["{0;1}", "0;1", "{ 0; 1 }", "{0;1;}"] {
            assert_eq!(parse_path(key), Ok(want.clone()), "{key}");
        }
        assert!(parse_path("{a}").is_err());
        assert!(parse_path("{}").is_err());
        assert!(parse_path("{-1}").is_err());
    }

    #[test]
    fn an_array_wrapper_is_unwrapped() {
        let r = parse_request(br#"[{"pointer": "x", "values": []}]"#).unwrap();
        assert_eq!(r.pointer.as_deref(), Some("x"));
        assert!(parse_request(b"[1, 2]").is_err());
        assert!(parse_request(br#"{"values": 5}"#).is_err());
    }
}

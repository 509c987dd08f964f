//! `script.python` nodes as GhPython Script components: the script as `CodeInput`, each
//! input's access and type hint as `ScriptParamAccess` and `TypeHintID`.

use locus_runtime::{DataType, GraphNode, Value, parse_literal};

use super::ExportWarning;
use crate::import::TYPE_HINTS;

/// The node type written as a GhPython component.
pub(super) const PYTHON: &str = "script.python";

/// GhPython's "no type hint" (dynamic): what an input without a hint is written with.
const NO_HINT: &str = "35915213-5534-4277-81b8-1bdc9e7383d2";

/// A text setting of the node (empty when absent or not a text).
fn text_setting(node: &GraphNode, name: &str) -> String {
    node.settings
        .iter()
        .find(|(k, _)| k == name)
        .and_then(|(_, lit)| parse_literal(&lit.0, DataType::Text).ok())
        .and_then(|tree| tree.values().next().flatten())
        .and_then(|v| match v {
            Value::Text(t) => Some(t),
            _ => None,
        })
        .unwrap_or_default()
}

/// The script.
pub(super) fn code(node: &GraphNode) -> String {
    text_setting(node, "code")
}

/// The value of `name` in a setting of `name: value` entries.
fn entry(node: &GraphNode, setting: &str, name: &str) -> Option<String> {
    text_setting(node, setting)
        .split([',', ';', '\n'])
        .filter_map(|e| e.split_once([':', '=']))
        .find(|(k, _)| k.trim() == name)
        .map(|(_, v)| v.trim().to_owned())
}

/// `ScriptParamAccess` (0 item, 1 list, 2 tree) and `TypeHintID` of one input.
pub(super) fn input_items(node: &GraphNode, input: &str) -> (String, &'static str) {
    let access = match entry(node, "access", input).as_deref().map(str::to_ascii_lowercase) {
        Some(a) if a == "list" => "1",
        Some(a) if a == "tree" => "2",
        _ => "0",
    };
    let hint = entry(node, "hints", input)
        .and_then(|h| {
            TYPE_HINTS
                .iter()
                .find(|(_, name)| name.eq_ignore_ascii_case(&h))
                .map(|(id, _)| *id)
        })
        .unwrap_or(NO_HINT);
    (access.to_owned(), hint)
}

/// What a GhPython component cannot say about this node.
pub(super) fn warnings(node: &GraphNode) -> Vec<ExportWarning> {
    let mut out = Vec::new();
    let setting = |name: &str| node.settings.iter().find(|(k, _)| k == name);
    if setting("timeout").is_some() {
        out.push(ExportWarning(format!(
            "node \"{}\": GhPython has no time limit; the timeout is not written",
            node.id
        )));
    }
    if !setting("ghpython").is_some_and(|(_, lit)| lit.0.trim() == "true") {
        out.push(ExportWarning(format!(
            "node \"{}\": GhPython gives scripts Rhino types, not the locus package's: the \
             script may need changes to run there",
            node.id
        )));
    }
    for part in text_setting(node, "hints").split([',', ';', '\n']) {
        let Some((input, hint)) = part.split_once([':', '=']) else {
            continue;
        };
        if !TYPE_HINTS
            .iter()
            .any(|(_, name)| name.eq_ignore_ascii_case(hint.trim()))
        {
            out.push(ExportWarning(format!(
                "node \"{}\" input {}: the type hint {} has no GhPython counterpart; it is \
                 written without one",
                node.id,
                input.trim(),
                hint.trim()
            )));
        }
    }
    out
}

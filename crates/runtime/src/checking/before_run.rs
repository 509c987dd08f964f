//! What checking can know of a graph before running it, beyond types and wiring: each node
//! type's prepare step (a function of the node's settings and input names only, such as
//! compiling the Expression's formula or parsing the Path Mapper's masks) must succeed, and the
//! items of literal values must meet their port's static constraint ([`Port::constraint`],
//! such as a positive radius). Both are general: node types declare them, checking names no
//! node.
//!
//! [`Port::constraint`]: crate::Port::constraint

use std::panic::{AssertUnwindSafe, catch_unwind};

use crate::checking::diagnostic::{Diagnostic, DiagnosticKind, Severity};
use crate::file::format::Document;
use crate::{Graph, NodeConfig, Plan, Value};

/// The problems found in a plan (built from `graph`, node for node), each placed in `doc`.
pub(crate) fn check_before_run(
    plan: &Plan,
    graph: &Graph,
    doc: Option<&Document>,
) -> Vec<Diagnostic> {
    let mut out = Vec::new();
    let error = |kind: DiagnosticKind, offset: Option<usize>| Diagnostic {
        severity: Severity::Error,
        kind,
        location: doc.zip(offset).map(|(d, o)| d.location(o)),
        file: None,
    };
    for (i, node) in plan.nodes.iter().enumerate() {
        let Some(graph_node) = graph.nodes.get(i) else {
            continue;
        };
        let spans = doc.and_then(|d| d.map.nodes.get(i));
        if node.disabled {
            continue;
        }
        if let Some(prepare) = &node.node_type.prepare {
            let inputs: Vec<_> = node.inputs.iter().map(|input| input.port.clone()).collect();
            let config = NodeConfig {
                settings: &node.settings,
                inputs: &inputs,
            };
            let result = catch_unwind(AssertUnwindSafe(|| prepare(&config)));
            let message = match result {
                Ok(Ok(_)) => None,
                Ok(Err(e)) => Some(e.0),
                Err(_) => Some("internal error: the node's prepare step panicked".to_owned()),
            };
            if let Some(message) = message {
                // Point at the first setting given, which is what the prepare step reads.
                let kind = match graph_node.settings.first() {
                    Some((setting, _)) => DiagnosticKind::BadSetting {
                        node: node.id.0.clone(),
                        setting: setting.clone(),
                        message,
                    },
                    None => DiagnosticKind::Malformed {
                        message: format!("node \"{}\": {message}", node.id),
                    },
                };
                let at = spans.map(|s| s.settings.first().map_or(s.id.start, |v| v[1].start));
                out.push(error(kind, at));
            }
        }
        for (j, (port_name, _)) in graph_node.values.iter().enumerate() {
            let Some(input) = node
                .inputs
                .iter()
                .find(|input| input.port.is_named(port_name))
            else {
                continue;
            };
            let (Some(constraint), Some(tree)) = (&input.port.constraint, &input.value) else {
                continue;
            };
            let at = spans.and_then(|s| s.values.get(j)).map(|v| v[1].start);
            'items: for (path, branch) in tree.branches() {
                for (k, value) in branch.values().enumerate() {
                    let Some(value) = value else { continue };
                    if let Err(why) = check_item(constraint, &value) {
                        out.push(error(
                            DiagnosticKind::BadValue {
                                node: node.id.0.clone(),
                                port: input.port.nickname.clone(),
                                message: format!("{why} (item {path}[{k}])"),
                            },
                            at,
                        ));
                        break 'items;
                    }
                }
            }
        }
    }
    out
}

fn check_item(constraint: &crate::ValueConstraint, value: &Value) -> Result<(), String> {
    catch_unwind(AssertUnwindSafe(|| constraint.check(value)))
        .unwrap_or_else(|_| Err("internal error: the port's constraint panicked".to_owned()))
}

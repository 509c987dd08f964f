//! The canonical writer of graph files (`Graph::to_ron`, `locus fmt`): fixed field order,
//! defaults left out, one node per line when it fits in 100 columns and one field per line
//! otherwise, one wire, named input, named output and expected value per line (see
//! `docs/graph-format.md`, "Canonical layout").

use crate::file::syntax::{self, Field, Kind, Node};
use crate::{
    ExpectedMessage, FORMAT_VERSION, Graph, GraphNode, Literal, Matching, Modifier, SubGraph,
};

fn string_node(s: &str) -> Node {
    Node::new(Kind::Str(s.to_owned()))
}

/// A literal's syntax for writing; text that is not valid RON is kept raw.
fn literal_node(literal: &Literal) -> Node {
    syntax::parse(&literal.0).unwrap_or_else(|_| Node::new(Kind::Raw(literal.0.clone())))
}

fn field(name: &str, value: Node) -> Field {
    Field {
        name: name.to_owned(),
        name_span: 0..0,
        value,
    }
}

fn literal_map(entries: &[(String, Literal)]) -> Node {
    Node::new(Kind::Map(
        entries
            .iter()
            .map(|(k, v)| (string_node(k), literal_node(v)))
            .collect(),
    ))
}

pub(crate) fn expected_node(expected: &[(String, Literal)]) -> Node {
    literal_map(expected)
}

/// The `expected_messages` list: one `(node: …, level: …, text: …)` struct per message.
pub(crate) fn expected_messages_node(messages: &[ExpectedMessage]) -> Node {
    let items = messages
        .iter()
        .map(|m| {
            Node::new(Kind::Struct(
                None,
                vec![
                    field("node", string_node(&m.node.0)),
                    field("level", ident(m.level.name())),
                    field("text", string_node(&m.text)),
                ],
            ))
        })
        .collect();
    Node::new(Kind::List(items))
}

fn node_node(node: &GraphNode) -> Node {
    let mut fields = vec![
        field("id", string_node(&node.id.0)),
        field("type", string_node(&node.node_type)),
    ];
    if let Some(names) = &node.input_names {
        let names = names.iter().map(|n| string_node(n)).collect();
        fields.push(field("inputs", Node::new(Kind::List(names))));
    }
    if let Some(names) = &node.output_names {
        let names = names.iter().map(|n| string_node(n)).collect();
        fields.push(field("outputs", Node::new(Kind::List(names))));
    }
    if !node.values.is_empty() {
        fields.push(field("values", literal_map(&node.values)));
    }
    if !node.settings.is_empty() {
        fields.push(field("settings", literal_map(&node.settings)));
    }
    if !node.modifiers.is_empty() {
        fields.push(field("modifiers", modifiers_node(&node.modifiers)));
    }
    if !node.output_modifiers.is_empty() {
        fields.push(field(
            "output_modifiers",
            modifiers_node(&node.output_modifiers),
        ));
    }
    match node.matching {
        Matching::Longest => {}
        Matching::Shortest => fields.push(field("matching", ident("shortest"))),
        Matching::Cross => fields.push(field("matching", ident("cross"))),
    }
    if node.disabled {
        fields.push(field("disabled", Node::new(Kind::Bool(true))));
    }
    match &node.subgraph {
        None => {}
        Some(SubGraph::Path(path)) => fields.push(field("path", string_node(path))),
        Some(SubGraph::Inline(graph)) => {
            fields.push(field(
                "graph",
                Node::new(Kind::Struct(None, graph_fields(graph))),
            ));
        }
    }
    Node::new(Kind::Struct(None, fields))
}

/// A map from port names to lists of modifiers: `{"A": [graft, reverse]}`.
fn modifiers_node(modifiers: &[(String, Vec<Modifier>)]) -> Node {
    let entries = modifiers
        .iter()
        .map(|(port, list)| {
            let names = list.iter().map(|m| ident(m.name())).collect();
            (string_node(port), Node::new(Kind::List(names)))
        })
        .collect();
    Node::new(Kind::Map(entries))
}

fn ident(name: &str) -> Node {
    Node::new(Kind::Ident(name.to_owned()))
}

/// The fields of a graph in canonical order, defaults left out; `format` always.
fn graph_fields(graph: &Graph) -> Vec<Field> {
    let mut fields = vec![field(
        "format",
        Node::new(Kind::Number(FORMAT_VERSION.to_string())),
    )];
    if !graph.name.is_empty() {
        fields.push(field("name", string_node(&graph.name)));
    }
    if !graph.description.is_empty() {
        fields.push(field("description", string_node(&graph.description)));
    }
    if !graph.nodes.is_empty() {
        let nodes = graph.nodes.iter().map(node_node).collect();
        fields.push(field("nodes", Node::new(Kind::List(nodes))));
    }
    if !graph.wires.is_empty() {
        let wires = graph
            .wires
            .iter()
            .map(|w| {
                Node::new(Kind::Tuple(
                    None,
                    vec![
                        string_node(&w.from.to_string()),
                        string_node(&w.to.to_string()),
                    ],
                ))
            })
            .collect();
        fields.push(field("wires", Node::new(Kind::List(wires))));
    }
    if !graph.inputs.is_empty() {
        let entries = graph
            .inputs
            .iter()
            .map(|i| (string_node(&i.name), string_node(&i.target.to_string())))
            .collect();
        fields.push(field("inputs", Node::new(Kind::Map(entries))));
    }
    if !graph.outputs.is_empty() {
        let entries = graph
            .outputs
            .iter()
            .map(|o| (string_node(&o.name), string_node(&o.source.to_string())))
            .collect();
        fields.push(field("outputs", Node::new(Kind::Map(entries))));
    }
    if !graph.expected.is_empty() {
        fields.push(field("expected", expected_node(&graph.expected)));
    }
    if !graph.expected_messages.is_empty() {
        let messages = expected_messages_node(&graph.expected_messages);
        fields.push(field("expected_messages", messages));
    }
    fields
}

/// Writes a graph in canonical layout (see the module docs): the scalar fields on one line
/// when they fit, the lists and maps with one entry per line.
pub fn write_graph(graph: &Graph) -> String {
    let mut out = String::from("(\n");
    for f in graph_fields(graph) {
        let prefix = format!("    {}: ", f.name);
        out.push_str(&prefix);
        match f.value.kind {
            Kind::List(_) | Kind::Map(_) => syntax::write_broken(&f.value, 4, &mut out),
            _ => syntax::write_pretty(&f.value, 4, prefix.len() - 4, 1, &mut out),
        }
        out.push_str(",\n");
    }
    out.push_str(")\n");
    out
}

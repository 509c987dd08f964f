//! Graphs as Graphviz DOT text (`locus dot GRAPH | dot -Tsvg`).

use std::fmt::Write as _;

use crate::{Graph, NodeRegistry};

/// The graph in Graphviz DOT: one box per node labelled with its id and type (the type's
/// display name and id when `registry` knows it), one edge per wire labelled `output → input`,
/// named inputs and outputs as ellipses. Disabled nodes are dashed and grey.
///
/// The text is deterministic: nodes and edges in file order.
pub fn to_dot(graph: &Graph, registry: Option<&NodeRegistry>) -> String {
    let mut out = String::new();
    let name = if graph.name.is_empty() {
        "graph"
    } else {
        graph.name.as_str()
    };
    let _ = writeln!(out, "digraph {} {{", quote(name));
    out.push_str("    rankdir=LR;\n");
    out.push_str("    node [shape=box, fontname=\"Helvetica\"];\n");
    out.push_str("    edge [fontname=\"Helvetica\", fontsize=10];\n");
    for node in &graph.nodes {
        let type_label = match registry.and_then(|r| r.get(&node.node_type)) {
            Some(t) => format!("{} ({})", t.name, t.id),
            None => node.node_type.clone(),
        };
        let label = format!("{}\n{}", node.id, type_label);
        let style = if node.disabled {
            ", style=dashed, color=grey, fontcolor=grey"
        } else {
            ""
        };
        let _ = writeln!(
            out,
            "    {} [label={}{style}];",
            quote(&node.id.0),
            quote(&label)
        );
    }
    for wire in &graph.wires {
        let label = format!("{} → {}", wire.from.port, wire.to.port);
        let _ = writeln!(
            out,
            "    {} -> {} [label={}];",
            quote(&wire.from.node.0),
            quote(&wire.to.node.0),
            quote(&label)
        );
    }
    for input in &graph.inputs {
        let id = format!("input:{}", input.name);
        let _ = writeln!(
            out,
            "    {} [label={}, shape=ellipse];",
            quote(&id),
            quote(&input.name)
        );
        let _ = writeln!(
            out,
            "    {} -> {} [label={}, style=dotted];",
            quote(&id),
            quote(&input.target.node.0),
            quote(&input.target.port)
        );
    }
    for output in &graph.outputs {
        let id = format!("output:{}", output.name);
        let _ = writeln!(
            out,
            "    {} [label={}, shape=ellipse];",
            quote(&id),
            quote(&output.name)
        );
        let _ = writeln!(
            out,
            "    {} -> {} [label={}, style=dotted];",
            quote(&output.source.node.0),
            quote(&id),
            quote(&output.source.port)
        );
    }
    out.push_str("}\n");
    out
}

/// A DOT quoted string; newlines become DOT's centred line breaks.
fn quote(s: &str) -> String {
    let mut out = String::with_capacity(s.len() + 2);
    out.push('"');
    for c in s.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            '\n' => out.push_str("\\n"),
            '\r' => {}
            c => out.push(c),
        }
    }
    out.push('"');
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{GraphNode, NodeId, NodeType, PortRef, Wire};

    #[test]
    fn writes_nodes_and_labelled_edges() {
        let node = |id: &str, t: &str| GraphNode {
            id: NodeId::from(id),
            node_type: t.to_owned(),
            ..GraphNode::default()
        };
        let mut graph = Graph {
            name: "demo \"x\"".to_owned(),
            nodes: vec![node("a", "params.point"), node("d", "vector.dot_product")],
            ..Graph::default()
        };
        graph.nodes[1].disabled = true;
        graph.wires.push(Wire {
            from: PortRef {
                node: "a".into(),
                port: "P".to_owned(),
            },
            to: PortRef {
                node: "d".into(),
                port: "A".to_owned(),
            },
        });
        let mut registry = NodeRegistry::new();
        registry.register(NodeType::new(
            "vector.dot_product",
            "Dot Product",
            "DProd",
            "Vector",
        ));
        let dot = to_dot(&graph, Some(&registry));
        assert_eq!(
            dot,
            "digraph \"demo \\\"x\\\"\" {\n    rankdir=LR;\n    node [shape=box, \
             fontname=\"Helvetica\"];\n    edge [fontname=\"Helvetica\", fontsize=10];\n    \
             \"a\" [label=\"a\\nparams.point\"];\n    \"d\" [label=\"d\\nDot Product \
             (vector.dot_product)\", style=dashed, color=grey, fontcolor=grey];\n    \"a\" -> \
             \"d\" [label=\"P → A\"];\n}\n"
        );
    }
}

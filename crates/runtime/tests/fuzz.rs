//! Robustness: reading and checking never panic, whatever the text or the wiring, and graphs
//! that pass checking have a valid evaluation order.

mod common;

use locus_runtime::{
    Document, Graph, GraphInput, GraphNode, GraphOutput, Literal, Matching, Modifier, NodeId,
    NodeRegistry, PortRef, Wire, check, check_text,
};
use proptest::prelude::*;

const GRAPHS: [&str; 4] = [
    include_str!("graphs/tangent_spheres.ron"),
    include_str!("graphs/modifiers.ron"),
    include_str!("graphs/literals.ron"),
    include_str!("graphs/minimal.ron"),
];

fn registry() -> &'static NodeRegistry {
    static REGISTRY: std::sync::OnceLock<NodeRegistry> = std::sync::OnceLock::new();
    REGISTRY.get_or_init(common::registry)
}

/// Reads and checks `text`; any outcome but a panic is fine, and diagnostics print.
fn read_and_check(text: &str) {
    match check_text(text, registry()) {
        Ok(checked) => {
            for w in &checked.warnings {
                let _ = w.display_in("fuzz.ron").to_string();
            }
        }
        Err(diagnostics) => {
            assert!(!diagnostics.is_empty());
            for d in &diagnostics {
                let _ = d.display_in("fuzz.ron").to_string();
            }
        }
    }
    if let Ok(doc) = Document::parse(text) {
        let _ = doc.with_expected(&[("x".to_owned(), Literal("1".to_owned()))]);
        let _ = doc.graph().to_ron();
    }
}

/// A byte edit: delete, insert or replace with characters that matter to RON.
fn edit() -> impl Strategy<Value = (usize, u8, u8)> {
    let bytes = proptest::sample::select(b"()[]{}:,\".'#/*\\ \nrab019-eE_".to_vec());
    (any::<usize>(), 0u8..3, bytes)
}

fn apply(text: &str, edits: &[(usize, u8, u8)]) -> String {
    let mut bytes = text.as_bytes().to_vec();
    for &(at, op, b) in edits {
        let i = at % (bytes.len() + 1);
        match op {
            0 if i < bytes.len() => {
                bytes.remove(i);
            }
            1 => bytes.insert(i, b),
            _ if i < bytes.len() => bytes[i] = b,
            _ => bytes.push(b),
        }
    }
    String::from_utf8_lossy(&bytes).into_owned()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(512))]

    #[test]
    fn random_text_never_panics(text in "\\PC{0,200}") {
        read_and_check(&text);
    }

    #[test]
    fn truncated_graphs_never_panic(which in 0..GRAPHS.len(), cut in any::<prop::sample::Index>()) {
        let text = GRAPHS[which];
        let at = cut.index(text.len() + 1);
        read_and_check(&String::from_utf8_lossy(&text.as_bytes()[..at]));
    }

    #[test]
    fn mutated_graphs_never_panic(
        which in 0..GRAPHS.len(),
        edits in proptest::collection::vec(edit(), 1..6),
    ) {
        read_and_check(&apply(GRAPHS[which], &edits));
    }
}

const TYPES: [&str; 9] = [
    "params.point",
    "params.number",
    "params.generic",
    "vector.dot_product",
    "vector.two_pt",
    "math.addition",
    "math.expression",
    "sets.list_item",
    "vector.dott",
];

const PORTS: [&str; 10] = ["A", "B", "N", "Pt", "D", "R", "V", "L", "x", "Q"];

const VALUES: [&str; 8] = [
    "1",
    "0.5",
    "(1, 2, 3)",
    "[1, 2]",
    "\"abc\"",
    "true",
    "{\"{0;1}\": [1.0], \"{0;2}\": []}",
    "null",
];

fn port_ref(nodes: usize) -> impl Strategy<Value = PortRef> {
    (0..nodes + 1, proptest::sample::select(PORTS.to_vec())).prop_map(|(n, p)| PortRef {
        node: NodeId(format!("n{n}")),
        port: p.to_owned(),
    })
}

fn graph_node(i: usize) -> impl Strategy<Value = GraphNode> {
    (
        proptest::sample::select(TYPES.to_vec()),
        proptest::option::weighted(0.2, proptest::collection::vec("[a-z]", 0..3)),
        proptest::collection::vec(
            (
                proptest::sample::select(PORTS.to_vec()),
                proptest::sample::select(VALUES.to_vec()),
            ),
            0..3,
        ),
        proptest::collection::vec(
            (
                proptest::sample::select(PORTS.to_vec()),
                proptest::collection::vec(proptest::sample::select(Modifier::ALL.to_vec()), 0..3),
            ),
            0..2,
        ),
        proptest::collection::vec(
            (
                proptest::sample::select(PORTS.to_vec()),
                proptest::collection::vec(proptest::sample::select(Modifier::ALL.to_vec()), 0..3),
            ),
            0..2,
        ),
        proptest::sample::select(vec![Matching::Longest, Matching::Shortest, Matching::Cross]),
        any::<bool>(),
        0..10usize,
    )
        .prop_map(
            move |(t, names, values, modifiers, outputs, matching, disabled, dup)| GraphNode {
                // Now and then an id used twice.
                id: NodeId(format!("n{}", if dup == 0 { 0 } else { i })),
                node_type: t.to_owned(),
                input_names: names,
                output_names: None,
                values: values
                    .into_iter()
                    .map(|(p, v)| (p.to_owned(), Literal(v.to_owned())))
                    .collect(),
                settings: Vec::new(),
                modifiers: modifiers
                    .into_iter()
                    .map(|(p, mut m)| {
                        m.dedup();
                        (p.to_owned(), m)
                    })
                    .collect(),
                output_modifiers: outputs
                    .into_iter()
                    .map(|(p, mut m)| {
                        m.dedup();
                        (p.to_owned(), m)
                    })
                    .collect(),
                matching,
                disabled,
                subgraph: None,
            },
        )
}

fn random_graph() -> impl Strategy<Value = Graph> {
    (1..8usize)
        .prop_flat_map(|n| {
            let nodes: Vec<_> = (0..n).map(graph_node).collect();
            let wire = (port_ref(n), port_ref(n)).prop_map(|(from, to)| Wire { from, to });
            (
                nodes,
                proptest::collection::vec(wire, 0..12),
                proptest::collection::vec(("[a-c]", port_ref(n)), 0..3),
                proptest::collection::vec(("[a-c]", port_ref(n)), 0..3),
            )
        })
        .prop_map(|(nodes, wires, inputs, outputs)| Graph {
            format: locus_runtime::FORMAT_VERSION,
            name: "random".to_owned(),
            description: String::new(),
            nodes,
            wires,
            inputs: inputs
                .into_iter()
                .map(|(name, target)| GraphInput { name, target })
                .collect(),
            expected: outputs
                .iter()
                .map(|(name, _)| (name.clone(), Literal("1".to_owned())))
                .collect(),
            outputs: outputs
                .into_iter()
                .map(|(name, source)| GraphOutput { name, source })
                .collect(),
            expected_messages: Vec::new(),
        })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(512))]

    #[test]
    fn random_wiring_checks_without_panic(graph in random_graph()) {
        let text = graph.to_ron();
        prop_assert_eq!(&Graph::from_ron(&text).unwrap(), &graph);
        let from_text = check_text(&text, registry());
        let from_graph = check(&graph, registry());
        // Positions aside, checking the text and checking the graph agree.
        let messages = |r: &Result<_, Vec<locus_runtime::Diagnostic>>| match r {
            Ok(_) => Vec::new(),
            Err(d) => {
                // Only the text knows the line of an earlier duplicate id.
                let mut m: Vec<String> = d
                    .iter()
                    .map(|d| {
                        let m = d.message();
                        m.split(" (first used on line").next().unwrap_or_default().to_owned()
                    })
                    .collect();
                m.sort();
                m
            }
        };
        prop_assert_eq!(messages(&from_text), messages(&from_graph));
        if let Ok(checked) = from_graph {
            let plan = checked.plan;
            prop_assert_eq!(plan.nodes.len(), graph.nodes.len());
            let mut position = vec![usize::MAX; plan.nodes.len()];
            for (at, &i) in plan.order.iter().enumerate() {
                position[i] = at;
            }
            prop_assert!(position.iter().all(|&p| p != usize::MAX));
            for (i, node) in plan.nodes.iter().enumerate() {
                for input in &node.inputs {
                    for &(source, _) in &input.sources {
                        prop_assert!(position[source] < position[i]);
                    }
                }
            }
        }
    }
}

/// Acyclic graphs of additions whose wires run in any direction in the file.
fn acyclic_graph() -> impl Strategy<Value = Graph> {
    (2..12usize)
        .prop_flat_map(|n| {
            let rank = Just((0..n).collect::<Vec<usize>>()).prop_shuffle();
            let wires = proptest::collection::vec((0..n, 0..n, any::<bool>()), 0..20);
            (rank, wires)
        })
        .prop_map(|(rank, wires)| {
            let nodes = (0..rank.len())
                .map(|i| GraphNode {
                    id: NodeId(format!("n{i}")),
                    node_type: "math.addition".to_owned(),
                    values: vec![("A".to_owned(), Literal("1".to_owned()))],
                    ..GraphNode::default()
                })
                .collect();
            let port = |n: usize, p: &str| PortRef {
                node: NodeId(format!("n{n}")),
                port: p.to_owned(),
            };
            // A wire always runs from lower to higher rank, so there is no cycle.
            let wires = wires
                .into_iter()
                .filter(|&(a, b, _)| rank[a] < rank[b])
                .map(|(a, b, to_a)| Wire {
                    from: port(a, "R"),
                    to: port(b, if to_a { "A" } else { "B" }),
                })
                .collect();
            Graph {
                format: locus_runtime::FORMAT_VERSION,
                nodes,
                wires,
                ..Graph::default()
            }
        })
}

proptest! {
    #[test]
    fn evaluation_order_takes_the_earliest_ready_node(graph in acyclic_graph()) {
        let plan = check(&graph, registry()).map_err(|d| {
            TestCaseError::fail(format!("{:?}", d.iter().map(|d| d.message()).collect::<Vec<_>>()))
        })?.plan;
        // Reference: repeatedly take the first node in file order whose sources are placed.
        let n = graph.nodes.len();
        let mut placed = vec![false; n];
        let mut expected = Vec::new();
        while expected.len() < n {
            let next = (0..n)
                .find(|&i| {
                    !placed[i]
                        && plan.nodes[i]
                            .inputs
                            .iter()
                            .all(|input| input.sources.iter().all(|&(s, _)| placed[s]))
                })
                .expect("acyclic");
            placed[next] = true;
            expected.push(next);
        }
        prop_assert_eq!(plan.order, expected);
    }
}

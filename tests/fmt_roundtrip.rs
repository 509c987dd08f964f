//! `locus fmt`'s canonical form round trips: for random graphs (every field of the format,
//! expected messages included, texts with quotes, escapes and non-ASCII), saving, loading and
//! saving again gives the same graph and the same bytes, with a header comment and with `\r\n`
//! line endings too.

use locus_runtime::{
    Document, ExpectedMessage, Graph, GraphInput, GraphNode, GraphOutput, Level, Literal, Matching,
    Modifier, NodeId, PortRef, Wire,
};
use proptest::prelude::*;

fn text() -> impl Strategy<Value = String> {
    "[a-zA-Z0-9 _\"\\\\{};:é\t\n*/-]{0,12}"
}

fn literal() -> impl Strategy<Value = Literal> {
    proptest::sample::select(vec![
        "1",
        "2.50",
        "-1e-7",
        "[1, 2, 3]",
        "(1, 2, 3)",
        "{\"{0;1}\": [1, 2], \"{1}\": []}",
        "Vector(1, 0, 0)",
        "null",
        "\"a \\\"b\\\"\"",
        "(plane: XY, radius: 2)",
        "[]",
        "{}",
        "Brep(faces: 6, edges: 12, vertices: 8, bbox: ((0, 0, 0), (1, 1, 1)))",
    ])
    .prop_map(|s| Literal::canonical(s).expect("valid RON"))
}

fn id() -> impl Strategy<Value = String> {
    "[a-z][a-z0-9_-]{0,5}"
}

fn port_ref() -> impl Strategy<Value = PortRef> {
    (id(), "[A-Za-z][A-Za-z .]{0,4}").prop_map(|(node, port)| PortRef {
        node: NodeId(node),
        port,
    })
}

fn node() -> impl Strategy<Value = GraphNode> {
    let modifiers = proptest::sample::subsequence(Modifier::ALL.to_vec(), 0..3);
    (
        id(),
        "[a-z]{1,6}\\.[a-z_]{1,8}",
        proptest::option::of(proptest::collection::vec("[a-zA-Z]{1,3}", 0..3)),
        proptest::option::of(proptest::collection::vec("[a-zA-Z]{1,3}", 0..3)),
        proptest::collection::vec(("[A-Za-z]{1,3}", literal()), 0..3),
        proptest::collection::vec(
            (
                "[a-z]{1,6}",
                text().prop_map(|t| Literal::canonical(&format!("{t:?}")).expect("a RON string")),
            ),
            0..2,
        ),
        proptest::collection::vec(("[A-Za-z]{1,3}", modifiers.clone()), 0..2),
        proptest::collection::vec(("[A-Za-z<>]{1,3}", modifiers), 0..2),
        proptest::sample::select(vec![Matching::Longest, Matching::Shortest, Matching::Cross]),
        any::<bool>(),
    )
        .prop_map(
            |(
                id,
                node_type,
                input_names,
                output_names,
                values,
                settings,
                modifiers,
                output_modifiers,
                matching,
                disabled,
            )| {
                GraphNode {
                    id: NodeId(id),
                    node_type,
                    input_names,
                    output_names,
                    values,
                    settings,
                    modifiers,
                    output_modifiers,
                    matching,
                    disabled,
                    subgraph: None,
                }
            },
        )
}

fn graph() -> impl Strategy<Value = Graph> {
    let message = (
        id(),
        proptest::sample::select(vec![Level::Error, Level::Warning, Level::Remark]),
        text(),
    )
        .prop_map(|(node, level, text)| ExpectedMessage {
            node: NodeId(node),
            level,
            text,
        });
    (
        text(),
        text(),
        proptest::collection::vec(node(), 0..5),
        proptest::collection::vec((port_ref(), port_ref()), 0..4),
        proptest::collection::vec(("[a-z]{1,4}", port_ref()), 0..3),
        proptest::collection::vec(("[a-z]{1,4}", port_ref()), 0..3),
        proptest::collection::vec(("[a-z]{1,4}", literal()), 0..3),
        proptest::collection::vec(message, 0..3),
    )
        .prop_map(
            |(name, description, nodes, wires, inputs, outputs, expected, expected_messages)| {
                Graph {
                    format: locus_runtime::FORMAT_VERSION,
                    name,
                    description,
                    nodes,
                    wires: wires
                        .into_iter()
                        .map(|(from, to)| Wire { from, to })
                        .collect(),
                    inputs: inputs
                        .into_iter()
                        .map(|(name, target)| GraphInput { name, target })
                        .collect(),
                    outputs: outputs
                        .into_iter()
                        .map(|(name, source)| GraphOutput { name, source })
                        .collect(),
                    expected,
                    expected_messages,
                }
            },
        )
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn load_save_round_trips(graph in graph(), header in "(// [a-z*/]{0,9}[a-z]\n){0,2}", crlf in any::<bool>()) {
        let saved = graph.to_ron();
        let loaded = Graph::from_ron(&saved).map_err(|e| TestCaseError::fail(format!("{e:?}\n{saved}")))?;
        prop_assert_eq!(&loaded, &graph);
        prop_assert_eq!(loaded.to_ron(), saved.clone());

        // The file form `locus fmt` writes: a header comment kept, line endings kept.
        let mut file = format!("{header}{saved}");
        if crlf {
            file = file.replace('\n', "\r\n");
        }
        let canonical = Document::parse(&file)
            .map_err(|e| TestCaseError::fail(format!("{e:?}")))?
            .canonical()
            .map_err(|e| TestCaseError::fail(e.to_string()))?;
        prop_assert_eq!(&canonical, &file);
        let document = Document::parse(&canonical).map_err(|e| TestCaseError::fail(format!("{e:?}")))?;
        prop_assert_eq!(document.graph(), &graph);
    }
}

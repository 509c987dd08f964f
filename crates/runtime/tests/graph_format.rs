//! Graph files: canonical round trips, reading errors, and the `expected` rewrite.

mod common;

use std::path::PathBuf;

use locus_runtime::{
    Diagnostic, Document, FORMAT_VERSION, Graph, GraphInput, GraphNode, GraphOutput, Literal,
    Matching, Modifier, NodeId, PortRef, Wire, check_text,
};

fn graph_files() -> Vec<(PathBuf, String)> {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/graphs");
    let mut files: Vec<(PathBuf, String)> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "ron"))
        .map(|p| {
            let text = std::fs::read_to_string(&p).unwrap();
            (p, text)
        })
        .collect();
    files.sort();
    assert!(files.len() >= 4, "test graphs missing");
    files
}

fn messages(diagnostics: &[Diagnostic]) -> Vec<String> {
    diagnostics.iter().map(ToString::to_string).collect()
}

#[test]
fn canonical_files_load_and_save_byte_for_byte() {
    for (path, text) in graph_files() {
        let graph = Graph::from_ron(&text)
            .unwrap_or_else(|e| panic!("{}: {:?}", path.display(), messages(&e)));
        let saved = graph.to_ron();
        if saved != text {
            panic!("{} does not round-trip; saved:\n{saved}", path.display());
        }
    }
}

#[test]
fn save_then_load_gives_an_equal_graph() {
    for (path, text) in graph_files() {
        let graph = Graph::from_ron(&text).unwrap();
        let again = Graph::from_ron(&graph.to_ron()).unwrap();
        assert_eq!(again, graph, "{}", path.display());
    }
}

#[test]
fn canonical_files_pass_checking() {
    let registry = common::registry();
    for (path, text) in graph_files() {
        if let Err(e) = check_text(&text, &registry) {
            panic!("{}: {:?}", path.display(), messages(&e));
        }
    }
}

#[test]
fn canonical_files_are_ron_for_the_ron_crate() {
    for (path, text) in graph_files() {
        if let Err(e) = ron::from_str::<ron::Value>(&text) {
            panic!("{}: {e}", path.display());
        }
    }
}

fn port(node: &str, port: &str) -> PortRef {
    PortRef {
        node: NodeId::from(node),
        port: port.to_owned(),
    }
}

#[test]
fn a_graph_built_in_code_survives_save_and_load() {
    let graph = Graph {
        format: FORMAT_VERSION,
        name: "built".to_owned(),
        description: "Line one.\nLine \"two\".".to_owned(),
        nodes: vec![
            GraphNode {
                id: NodeId::from("e"),
                node_type: "math.expression".to_owned(),
                input_names: Some(vec!["x".to_owned(), "long name".to_owned()]),
                output_names: Some(vec!["r".to_owned()]),
                values: vec![("x".to_owned(), Literal("[1, 2, null]".to_owned()))],
                settings: vec![("expression".to_owned(), Literal("\"x + 1\"".to_owned()))],
                modifiers: vec![("x".to_owned(), vec![Modifier::Reverse, Modifier::Flatten])],
                output_modifiers: vec![("R".to_owned(), vec![Modifier::Graft])],
                matching: Matching::Cross,
                disabled: true,
                subgraph: None,
            },
            GraphNode {
                id: NodeId::from("p"),
                node_type: "params.point".to_owned(),
                input_names: Some(Vec::new()),
                values: vec![(
                    "Pt".to_owned(),
                    Literal(format!(
                        "[{}]",
                        (0..30)
                            .map(|i| format!("({i}, 0, 0)"))
                            .collect::<Vec<_>>()
                            .join(", ")
                    )),
                )],
                ..GraphNode::default()
            },
        ],
        wires: vec![Wire {
            from: port("p", "Pt"),
            to: port("e", "long name"),
        }],
        inputs: vec![GraphInput {
            name: "x".to_owned(),
            target: port("e", "x"),
        }],
        outputs: vec![GraphOutput {
            name: "result".to_owned(),
            source: port("e", "R"),
        }],
        expected: vec![(
            "result".to_owned(),
            Literal("{\"{0;0}\": [1, 2], \"{0;1}\": []}".to_owned()),
        )],
        expected_messages: Vec::new(),
    };
    let text = graph.to_ron();
    assert_eq!(Graph::from_ron(&text).unwrap(), graph, "{text}");
    // The long list of points is written one point per line.
    assert!(
        text.contains("\n                    (29, 0, 0),\n"),
        "{text}"
    );
}

#[test]
fn hand_written_layouts_load_and_save_canonically() {
    let loose = r#"
        // A comment that the canonical writer drops.
        Graph(
            nodes: [
                ( type : "params.point" , id:"a", values: { "Pt" : (1,2,3) } , ),
                (id: "b", type: "params.number", matching: longest, disabled: false, values: {"N": r"1"})
            ],
            format: 1,
            wires: [("a.Pt","b.N")]
        )"#;
    let graph = Graph::from_ron(loose).unwrap();
    assert_eq!(graph.nodes[1].values[0].1, Literal("\"1\"".to_owned()));
    let expected = r#"(
    format: 1,
    nodes: [
        (id: "a", type: "params.point", values: {"Pt": (1, 2, 3)}),
        (id: "b", type: "params.number", values: {"N": "1"}),
    ],
    wires: [
        ("a.Pt", "b.N"),
    ],
)
"#;
    assert_eq!(graph.to_ron(), expected);
}

fn read_errors(text: &str) -> Vec<String> {
    Document::parse(text)
        .map(|_| ())
        .map_err(|e| messages(&e))
        .unwrap_err()
}

#[test]
fn syntax_errors_have_line_and_column() {
    let text = "(\n    format: 1,\n    nodes: [\n        (id: \"a\" type: \"x\"),\n    ],\n)";
    assert_eq!(
        read_errors(text),
        ["4:18: error: syntax error: expected `,` or `)`, found `t`"]
    );
    assert_eq!(
        read_errors("(format: 1, name: \"abc)"),
        ["1:19: error: syntax error: unterminated string"]
    );
    assert_eq!(
        read_errors(""),
        ["1:1: error: syntax error: expected a value, found end of file"]
    );
}

#[test]
fn unsupported_versions_stop_reading() {
    assert_eq!(
        read_errors("(format: 2, nodes: 5, colour: red)"),
        ["1:10: error: unsupported format version 2 (this build reads version 1)"]
    );
    assert_eq!(
        read_errors("(nodes: [])"),
        ["1:1: error: missing field `format` in the graph (this build writes format 1)"]
    );
}

#[test]
fn every_structural_problem_is_reported() {
    let text = r#"(
    format: 1,
    name: 3,
    colour: "red",
    nodes: [
        (id: "a", type: "params.point", size: 2),
        (type: "params.point"),
        (id: "c", type: "params.point", matching: longest_list, disabled: 1),
        (id: "d", type: "params.point", modifiers: {"Pt": [graft, grafted, graft]}),
        "e",
    ],
    wires: [("a.Pt", "b"), ("a.Pt")],
    outputs: {"o": 5},
)"#;
    assert_eq!(
        read_errors(text),
        [
            "4:5: error: unknown field `colour` in the graph (fields: format, name, description, \
             nodes, wires, inputs, outputs, expected, expected_messages)",
            "3:11: error: expected a string in quotes for `name`, found 3",
            "6:41: error: unknown field `size` in a node (fields: id, type, inputs, outputs, values, \
             settings, modifiers, output_modifiers, matching, disabled, path, graph)",
            "7:9: error: missing field `id` in a node",
            "8:51: error: expected longest, shortest or cross for `matching`, found longest_list",
            "8:75: error: expected true or false for `disabled`, found 1",
            "9:67: error: unknown modifier grafted (modifiers: flatten, graft, simplify, \
             reverse, principal, invert, degrees, reparameterize)",
            "9:76: error: duplicate modifier graft",
            "10:9: error: expected a struct `(field: value, …)` for a node, found \"e\"",
            "12:22: error: expected \"node.port\" in a wire, found \"b\"",
            "12:28: error: expected a wire (\"node.port\", \"node.port\") for `wires`, found a \
             tuple of 1 item",
            "13:20: error: expected a string in quotes for named output \"o\", found 5",
        ]
    );
}

#[test]
fn expected_values_are_rewritten_in_place() {
    let text = "// Keep me.\n(\n    format: 1, // and me\n    nodes: [(id: \"n\", type: \"params.number\")],\n    outputs: {\"n\": \"n.N\"},\n    expected: {\"n\": 1},\n)\n";
    let doc = Document::parse(text).unwrap();
    let new = [("n".to_owned(), Literal("[2.0, 3.0]".to_owned()))];
    assert_eq!(
        doc.with_expected(&new),
        "// Keep me.\n(\n    format: 1, // and me\n    nodes: [(id: \"n\", type: \"params.number\")],\n    outputs: {\"n\": \"n.N\"},\n    expected: {\n        \"n\": [2.0, 3.0],\n    },\n)\n"
    );
    assert_eq!(
        doc.with_expected(&[]),
        "// Keep me.\n(\n    format: 1, // and me\n    nodes: [(id: \"n\", type: \"params.number\")],\n    outputs: {\"n\": \"n.N\"},\n)\n"
    );
    // Without an `expected` section one is added at the end.
    let without = Document::parse(&doc.with_expected(&[])).unwrap();
    let added = without.with_expected(&new);
    assert_eq!(Document::parse(&added).unwrap().graph().expected, new);
    assert!(
        added.ends_with("    expected: {\n        \"n\": [2.0, 3.0],\n    },\n)\n"),
        "{added}"
    );
}

/// The example of docs/graph-format.md uses the node library's types, which the runtime does not
/// know: the root package's tests/graphs.rs checks and runs it; here it must be canonical.
#[test]
fn the_documented_example_is_canonical() {
    let doc = include_str!("../../../docs/graph-format.md");
    let start = doc.find("```ron\n").unwrap() + "```ron\n".len();
    let example = &doc[start..start + doc[start..].find("```").unwrap()];
    // Saving drops the leading comment and nothing else.
    let without_comment = example.split_once('\n').unwrap().1;
    assert_eq!(Graph::from_ron(example).unwrap().to_ron(), without_comment);
}

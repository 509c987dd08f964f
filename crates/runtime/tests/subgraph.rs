//! Sub-graphs: nodes of type "graph" that run another graph, inline or from a file
//! (`docs/graph-format.md`, "Sub-graphs").

use std::path::{Path, PathBuf};

use locus_runtime::{
    CancelToken, DataTree, DataType, Diagnostic, DiagnosticKind, Document, Evaluator, Graph,
    LimitHit, Limits, LoadError, MAX_SUBGRAPH_DEPTH, NodeRegistry, NodeType, Port, Value, check,
    load_file,
};

fn registry() -> NodeRegistry {
    let mut r = NodeRegistry::new();
    r.register(
        NodeType::new("test.number", "Number", "N", "Test")
            .input(Port::new("Number", "N", DataType::Number).optional())
            .output(Port::new("Number", "N", DataType::Number))
            .lift1(|x: &f64| Ok(*x)),
    );
    r.register(
        NodeType::new("test.addition", "Addition", "A+B", "Test")
            .input(Port::new("A", "A", DataType::Number))
            .input(Port::new("B", "B", DataType::Number).default_value(0.0))
            .output(Port::new("Result", "R", DataType::Number))
            .lift2(|a: &f64, b: &f64| Ok(a + b)),
    );
    r.register(
        NodeType::new("test.multiplication", "Multiplication", "A×B", "Test")
            .input(Port::new("A", "A", DataType::Number))
            .input(Port::new("B", "B", DataType::Number).default_value(1.0))
            .output(Port::new("Result", "R", DataType::Number))
            .lift2(|a: &f64, b: &f64| Ok(a * b)),
    );
    r.register(
        NodeType::new("test.square_root", "Square Root", "Sqrt", "Test")
            .input(Port::new("Number", "x", DataType::Number))
            .output(Port::new("Result", "y", DataType::Number))
            .solve(|s| {
                let x = *s.item::<f64>(0)?;
                if x < 0.0 {
                    return Err(format!("the square root of {x} is not real").into());
                }
                s.set(0, x.sqrt());
                Ok(())
            }),
    );
    r.register(
        NodeType::new("test.series", "Series", "S", "Test")
            .input(Port::new("Count", "N", DataType::Integer))
            .output(Port::new("Series", "S", DataType::Number).list())
            .solve(|s| {
                let n = usize::try_from(*s.item::<i64>(0)?).map_err(|_| "negative count")?;
                s.set_list(0, (0..n).map(|i| i as f64).collect::<Vec<f64>>());
                Ok(())
            }),
    );
    r
}

/// `x × 2 + offset`, with `offset` 10 unless given: the sub-graph most tests use.
const SCALE_OFFSET: &str = r#"(
    format: 1,
    name: "scale_offset",
    nodes: [
        (id: "scale", type: "test.multiplication", values: {"B": 2}),
        (id: "offset", type: "test.addition", values: {"B": 10}),
        (id: "constant", type: "test.addition", values: {"A": 1, "B": 2}),
    ],
    wires: [("scale.R", "offset.A")],
    inputs: {"x": "scale.A", "offset": "offset.B"},
    outputs: {"y": "offset.R", "three": "constant.R"},
)"#;

fn inline_graph(extra_nodes: &str, extra_wires: &str) -> String {
    format!(
        r#"(
    format: 1,
    nodes: [
        (id: "n", type: "test.number", values: {{"N": [1, 2]}}),
        (id: "c", type: "graph", graph: {SCALE_OFFSET}),
        {extra_nodes}
    ],
    wires: [("n.N", "c.x"), {extra_wires}],
    inputs: {{"n": "n.N"}},
    outputs: {{"y": "c.y", "three": "c.three"}},
)"#
    )
}

fn evaluator(text: &str) -> Evaluator {
    Evaluator::from_text(text, &registry()).unwrap_or_else(|d| panic!("{d:#?}"))
}

fn check_errors(text: &str) -> Vec<Diagnostic> {
    let doc = Document::parse(text).unwrap_or_else(|d| panic!("{d:#?}"));
    match doc.check(&registry()) {
        Ok(_) => panic!("the graph checks"),
        Err(d) => d.into_iter().filter(Diagnostic::is_error).collect(),
    }
}

fn numbers(tree: Option<&DataTree>) -> Vec<f64> {
    let tree = tree.expect("the output exists");
    tree.values()
        .map(|v| match v {
            Some(Value::Number(x)) => x,
            other => panic!("not a number: {other:?}"),
        })
        .collect()
}

/// A fresh directory for the files of one test.
fn dir(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("locus-subgraph-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(dir.join("parts")).expect("creates the directory");
    dir
}

fn write(path: &Path, text: &str) {
    std::fs::write(path, text).expect("writes the file");
}

#[test]
fn an_inline_sub_graph_runs_with_its_inputs_as_ports() {
    let mut e = evaluator(&inline_graph("", ""));
    e.evaluate();
    assert_eq!(numbers(e.output("y")), [12.0, 14.0]);
    assert_eq!(numbers(e.output("three")), [3.0]);
    // Inner nodes have nested ids.
    assert!(e.plan().nodes.iter().any(|n| n.id.0 == "c/offset"));
    assert_eq!(numbers(e.node_output("c/scale", "R")), [2.0, 4.0]);
}

#[test]
fn a_value_on_a_sub_graph_input_replaces_the_inner_one() {
    let text = inline_graph("", "").replace(
        r#"(id: "c", type: "graph","#,
        r#"(id: "c", type: "graph", values: {"offset": 100},"#,
    );
    let mut e = evaluator(&text);
    e.evaluate();
    assert_eq!(numbers(e.output("y")), [102.0, 104.0]);
}

#[test]
fn a_sub_graph_round_trips_through_the_writer() {
    let graph = Graph::from_ron(&inline_graph("", "")).expect("reads");
    let text = graph.to_ron();
    assert!(text.contains("graph: ("), "{text}");
    assert_eq!(Graph::from_ron(&text).expect("reads again"), graph);
    assert_eq!(Graph::from_ron(&text).unwrap().to_ron(), text);
}

#[test]
fn sub_graphs_from_files_nest_two_deep() {
    let dir = dir("nested");
    write(&dir.join("parts/scale_offset.ron"), SCALE_OFFSET);
    write(
        &dir.join("parts/twice.ron"),
        r#"(
            format: 1,
            nodes: [
                (id: "first", type: "graph", path: "scale_offset.ron"),
                (id: "second", type: "graph", path: "scale_offset.ron", values: {"offset": 0}),
            ],
            wires: [("first.y", "second.x")],
            inputs: {"x": "first.x"},
            outputs: {"y": "second.y"},
        )"#,
    );
    let top = dir.join("top.ron");
    write(
        &top,
        r#"(
            format: 1,
            nodes: [
                (id: "n", type: "test.number", values: {"N": 1}),
                (id: "t", type: "graph", path: "parts/twice.ron"),
            ],
            wires: [("n.N", "t.x")],
            inputs: {"n": "n.N"},
            outputs: {"y": "t.y"},
        )"#,
    );
    let mut e = Evaluator::from_file(&top, &registry()).expect("loads");
    e.evaluate();
    // (1 × 2 + 10) × 2 + 0
    assert_eq!(numbers(e.output("y")), [24.0]);
    assert!(e.plan().nodes.iter().any(|n| n.id.0 == "t/second/offset"));
}

#[test]
fn changing_an_outer_input_runs_only_the_inner_nodes_that_depend_on_it() {
    let mut e = evaluator(&inline_graph(
        r#"(id: "other", type: "test.number", values: {"N": 5}),"#,
        "",
    ));
    e.evaluate();
    assert!(e.last_run().iter().any(|n| n.0 == "c/constant"));
    e.set_input_text("n", "3").expect("sets");
    e.evaluate();
    let ran: Vec<&str> = e.last_run().iter().map(|n| n.0.as_str()).collect();
    assert_eq!(ran, ["n", "c/scale", "c/offset"]);
    assert_eq!(numbers(e.output("y")), [16.0]);
    // Nothing changed: nothing runs, inside or outside.
    e.evaluate();
    assert!(e.last_run().is_empty());
}

#[test]
fn inner_messages_carry_nested_ids() {
    let text = r#"(
        format: 1,
        nodes: [
            (id: "n", type: "test.number", values: {"N": [4, -1]}),
            (id: "c", type: "graph", graph: (
                format: 1,
                nodes: [(id: "root", type: "test.square_root")],
                inputs: {"x": "root.x"},
                outputs: {"y": "root.y"},
            )),
        ],
        wires: [("n.N", "c.x")],
        outputs: {"y": "c.y"},
        expected_messages: [(node: "c/root", level: error, text: "not real")],
    )"#;
    let mut e = evaluator(text);
    e.evaluate();
    let messages: Vec<_> = e.node_messages("c/root").collect();
    assert_eq!(messages.len(), 1, "{messages:?}");
    assert!(messages[0].text.contains("-1 is not real"));
    assert_eq!(messages[0].node.0, "c/root");
}

#[test]
fn ports_take_their_types_from_the_inner_graph() {
    let text = inline_graph("", "").replace(
        r#"(id: "c", type: "graph","#,
        r#"(id: "c", type: "graph", values: {"offset": "abc"},"#,
    );
    let errors = check_errors(&text);
    assert!(
        errors.iter().any(|d| matches!(
            &d.kind,
            DiagnosticKind::BadValue { node, port, .. } if node == "c" && port == "offset"
        )),
        "{errors:#?}"
    );
    let text = inline_graph("", "").replace(r#"("n.N", "c.x")"#, r#"("n.N", "c.z")"#);
    let errors = check_errors(&text);
    assert!(
        errors
            .iter()
            .any(|d| d.message().contains("\"z\"") && d.node() == Some("c")),
        "{errors:#?}"
    );
}

#[test]
fn diagnostics_inside_name_the_nested_node() {
    let text = inline_graph("", "").replace("test.multiplication", "test.multiply");
    let errors = check_errors(&text);
    assert_eq!(errors.len(), 1, "{errors:#?}");
    assert_eq!(errors[0].node(), Some("c/scale"));
    assert!(errors[0].location.is_some());
}

#[test]
fn slashes_in_node_ids_are_refused() {
    let text = inline_graph("", "").replace(r#"id: "n""#, r#"id: "a/b""#);
    let errors = check_errors(&text);
    assert!(
        errors
            .iter()
            .any(|d| matches!(&d.kind, DiagnosticKind::InvalidNodeId { node } if node == "a/b")),
        "{errors:#?}"
    );
    assert!(errors[0].message().contains("slashes"));
}

#[test]
fn a_path_needs_a_graph_read_from_a_file() {
    let text = r#"(format: 1, nodes: [(id: "c", type: "graph", path: "parts/x.ron")])"#;
    let errors = check_errors(text);
    assert_eq!(errors.len(), 1);
    assert!(errors[0].message().contains("with_origin"), "{}", errors[0]);
    let graph = Graph::from_ron(text).expect("reads");
    let d = check(&graph, &registry()).expect_err("has no file");
    assert!(d[0].message().contains("no file"));
}

#[test]
fn a_missing_or_broken_file_is_an_error_naming_it() {
    let dir = dir("bad_path");
    write(
        &dir.join("parts/broken.ron"),
        "(format: 1, nodes: [(id: \"a\"]",
    );
    write(
        &dir.join("parts/inner_error.ron"),
        "(format: 1,\n nodes: [(id: \"a\", type: \"test.nothing\")])",
    );
    let top = dir.join("top.ron");
    write(
        &top,
        r#"(format: 1, nodes: [
            (id: "missing", type: "graph", path: "parts/missing.ron"),
            (id: "broken", type: "graph", path: "parts/broken.ron"),
            (id: "inner", type: "graph", path: "parts/inner_error.ron"),
        ])"#,
    );
    let Err(LoadError::Invalid(d)) = load_file(&top, &registry()) else {
        panic!("loads");
    };
    let text: Vec<String> = d
        .iter()
        .map(|d| d.display_in("dir/top.ron").to_string())
        .collect();
    assert_eq!(text.len(), 3, "{text:#?}");
    assert!(text[0].contains("\"missing\": cannot read \"parts/missing.ron\""));
    assert!(text[1].contains("\"parts/broken.ron\" is not a graph"));
    assert!(
        text[2].starts_with("dir/parts/inner_error.ron:2:"),
        "{}",
        text[2]
    );
    assert!(text[2].contains("\"inner/a\""), "{}", text[2]);
}

#[test]
fn a_graph_including_itself_is_an_error_naming_the_chain() {
    let dir = dir("cycle");
    let a = dir.join("a.ron");
    write(
        &a,
        r#"(format: 1, nodes: [(id: "b", type: "graph", path: "parts/b.ron")])"#,
    );
    write(
        &dir.join("parts/b.ron"),
        r#"(format: 1, nodes: [(id: "a", type: "graph", path: "../a.ron")])"#,
    );
    let Err(LoadError::Invalid(d)) = load_file(&a, &registry()) else {
        panic!("loads");
    };
    let cycle = d
        .iter()
        .find(|d| matches!(d.kind, DiagnosticKind::SubGraphCycle { .. }))
        .unwrap_or_else(|| panic!("{d:#?}"));
    let message = cycle.message();
    assert_eq!(cycle.node(), Some("b/a"));
    assert!(message.contains("a.ron -> "), "{message}");
    assert!(message.contains("b.ron -> "), "{message}");
    assert!(message.ends_with("a.ron"), "{message}");
}

#[test]
fn nesting_deeper_than_the_limit_is_an_error() {
    let dir = dir("depth");
    let levels = MAX_SUBGRAPH_DEPTH + 2;
    for k in 0..levels {
        let text = if k + 1 == levels {
            r#"(format: 1, nodes: [(id: "n", type: "test.number")])"#.to_owned()
        } else {
            format!(
                r#"(format: 1, nodes: [(id: "s", type: "graph", path: "g{}.ron")])"#,
                k + 1
            )
        };
        write(&dir.join(format!("g{k}.ron")), &text);
    }
    let Err(LoadError::Invalid(d)) = load_file(dir.join("g0.ron"), &registry()) else {
        panic!("loads");
    };
    assert_eq!(d.len(), 1, "{d:#?}");
    assert!(d[0].message().contains("MAX_SUBGRAPH_DEPTH"), "{}", d[0]);
    assert_eq!(
        d[0].node().map(|n| n.split('/').count()),
        Some(MAX_SUBGRAPH_DEPTH + 1)
    );
    // One level less checks.
    std::fs::remove_file(dir.join(format!("g{}.ron", levels - 1))).unwrap();
    write(
        &dir.join(format!("g{}.ron", levels - 2)),
        r#"(format: 1, nodes: [(id: "n", type: "test.number")])"#,
    );
    load_file(dir.join("g0.ron"), &registry()).expect("32 levels check");
}

#[test]
fn run_limits_apply_inside_sub_graphs() {
    let text = r#"(
        format: 1,
        nodes: [
            (id: "c", type: "graph", values: {"n": 1000}, graph: (
                format: 1,
                nodes: [(id: "series", type: "test.series")],
                inputs: {"n": "series.N"},
                outputs: {"s": "series.S"},
            )),
        ],
        outputs: {"s": "c.s"},
    )"#;
    let mut e = evaluator(text);
    e.set_limits(Limits {
        max_items_per_output: 100,
        ..Limits::default()
    });
    e.evaluate();
    assert!(
        e.node_messages("c/series")
            .any(|m| m.text.contains("limit")),
        "{:?}",
        e.messages().collect::<Vec<_>>()
    );
    let token = CancelToken::new();
    let mut e = evaluator(text);
    e.set_limits(Limits {
        cancel: Some(token.clone()),
        ..Limits::default()
    });
    token.cancel();
    e.evaluate();
    assert_eq!(e.limit_hit(), Some(&LimitHit::Cancelled));
    assert!(e.not_run().iter().any(|n| n.0 == "c/series"));
}

#[test]
fn sub_graph_nodes_need_exactly_one_body() {
    let malformed = |text: &str| Document::parse(text).expect_err("is malformed");
    let d = malformed(r#"(format: 1, nodes: [(id: "c", type: "graph")])"#);
    assert!(
        d[0].message().contains("needs `path` or `graph`"),
        "{}",
        d[0]
    );
    let d = malformed(r#"(format: 1, nodes: [(id: "c", type: "test.number", path: "x.ron")])"#);
    assert!(
        d[0].message().contains("only for sub-graph nodes"),
        "{}",
        d[0]
    );
}

/// A sub-graph whose body does not check, followed by nodes wired to each other, is an error
/// naming the inner fault, not a panic: its node has no type, so the including graph has no
/// plan (found by the cluster round-trip property test of `locus-ghx`).
#[test]
fn a_failing_sub_graph_before_wired_nodes_is_an_error_not_a_panic() {
    let text = r#"(
        format: 1,
        nodes: [
            (id: "x", type: "test.number", values: {"N": [2, -1]}),
            (id: "bad", type: "graph", graph: (
                format: 1,
                nodes: [
                    (id: "add", type: "test.addition"),
                ],
                inputs: {"a": "add.B"},
                outputs: {"r": "add.R"},
            )),
            (id: "m", type: "test.multiplication", values: {"B": 5}),
            (id: "n", type: "test.addition", values: {"B": -4}),
        ],
        wires: [("x.N", "bad.a"), ("x.N", "m.A"), ("m.R", "n.A")],
        outputs: {"y": "n.R"},
    )"#;
    let errors: Vec<String> = check_errors(text).iter().map(ToString::to_string).collect();
    assert_eq!(
        errors,
        ["8:26: error: input \"A\" of node \"bad/add\" has no wire, no value and no default"],
    );
}

//! The example graphs of the Vector and Transform nodes (`graphs/vector_*.ron`,
//! `graphs/transform_*.ron`), read, checked and run with the library's registry, and compared
//! with their expected outputs as `locus test` compares them, so that `cargo test` keeps them
//! working.

use std::path::PathBuf;

use locus_runtime::{COMPARE_TOLERANCE, Document, Evaluator, NodeRegistry, compare_trees};

fn graph_path(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../../graphs")
        .join(name)
}

/// The differences between the graph's outputs and its expectations (empty when it passes).
fn run_graph(name: &str) -> Vec<String> {
    let mut registry = NodeRegistry::new();
    locus_nodes::register(&mut registry);
    let text = std::fs::read_to_string(graph_path(name)).expect("the graph file is readable");
    let document =
        Document::parse(&text).unwrap_or_else(|d| panic!("{name} does not parse: {d:?}"));
    let checked = document
        .check(&registry)
        .unwrap_or_else(|d| panic!("{name} does not check: {d:?}"));
    assert!(
        checked.warnings.is_empty(),
        "{name}: {:?}",
        checked.warnings
    );
    let plan = checked.plan.clone();
    let mut evaluator = Evaluator::new(checked.plan);
    evaluator.evaluate();
    let messages: Vec<String> = evaluator.messages().map(ToString::to_string).collect();
    assert!(messages.is_empty(), "{name}: {messages:?}");
    let expected = &document.graph().expected;
    assert!(!expected.is_empty(), "{name} has no expectations");
    let mut problems = Vec::new();
    for (output, literal) in expected {
        let &(_, node, port) = plan
            .outputs
            .iter()
            .find(|(n, _, _)| n == output)
            .unwrap_or_else(|| panic!("{name}: no output {output}"));
        let data_type = plan.nodes[node].node_type.outputs[port].data_type;
        let want = literal.parse(data_type).expect("the expectation reads");
        let got = evaluator.output(output).cloned().unwrap_or_default();
        for line in compare_trees(&got, &want, COMPARE_TOLERANCE, 10) {
            problems.push(format!("{output} {line}"));
        }
    }
    problems
}

#[test]
fn vector_book_numbers() {
    let problems = run_graph("vector_book_numbers.ron");
    assert!(problems.is_empty(), "{problems:#?}");
}

#[test]
fn transform_master_matrix() {
    let problems = run_graph("transform_master_matrix.ron");
    assert!(problems.is_empty(), "{problems:#?}");
}

#[test]
fn transform_book_matrices() {
    let problems = run_graph("transform_book_matrices.ron");
    assert!(problems.is_empty(), "{problems:#?}");
}

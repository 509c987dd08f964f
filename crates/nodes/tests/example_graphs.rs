//! The example graphs `graphs/maths_*.ron`: each is read, checked against the full registry
//! and evaluated, and every named output is compared with the graph's expected value.

use std::path::Path;

use locus_runtime::{Document, Evaluator, Level, NodeRegistry};

/// Runs one graph file and returns what differs from its expectations.
fn run_graph(path: &Path, registry: &NodeRegistry) -> Vec<String> {
    let name = path.display();
    let text = std::fs::read_to_string(path).expect("the graph file is readable");
    let document = match Document::parse(&text) {
        Ok(d) => d,
        Err(diagnostics) => return vec![format!("{name}: {diagnostics:?}")],
    };
    let checked = match document.check(registry) {
        Ok(c) => c,
        Err(diagnostics) => return vec![format!("{name}: {diagnostics:?}")],
    };
    let mut problems: Vec<String> = checked
        .warnings
        .iter()
        .map(|w| format!("{name}: warning {w:?}"))
        .collect();
    let plan = checked.plan;
    let output_types: Vec<(String, locus_runtime::DataType)> = plan
        .outputs
        .iter()
        .map(|(n, node, port)| {
            (
                n.clone(),
                plan.nodes[*node].node_type.outputs[*port].data_type,
            )
        })
        .collect();
    let mut evaluator = Evaluator::new(plan);
    evaluator.evaluate();
    for m in evaluator.messages() {
        if m.level >= Level::Warning {
            problems.push(format!("{name}: {m}"));
        }
    }
    let expected = &document.graph().expected;
    if expected.is_empty() {
        problems.push(format!("{name}: no expected outputs"));
    }
    for (output, literal) in expected {
        let Some((_, data_type)) = output_types.iter().find(|(n, _)| n == output) else {
            problems.push(format!("{name}: no output {output}"));
            continue;
        };
        let want = literal
            .parse(*data_type)
            .expect("expected values were checked");
        let got = evaluator.output(output).cloned().unwrap_or_default();
        if got != want {
            problems.push(format!(
                "{name}: output {output} is\n{got}but should be\n{want}"
            ));
        }
    }
    problems
}

#[test]
fn maths_graphs_give_their_expected_outputs() {
    let mut registry = NodeRegistry::new();
    locus_nodes::register(&mut registry);
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../graphs");
    let mut files: Vec<_> = std::fs::read_dir(&dir)
        .expect("graphs/ exists")
        .filter_map(Result::ok)
        .map(|e| e.path())
        .filter(|p| {
            p.file_name()
                .and_then(|n| n.to_str())
                .is_some_and(|n| n.starts_with("maths_") && n.ends_with(".ron"))
        })
        .collect();
    files.sort();
    assert!(files.len() >= 2, "the maths example graphs are missing");
    let problems: Vec<String> = files.iter().flat_map(|f| run_graph(f, &registry)).collect();
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}

//! The example graphs `graphs/curve_*.ron`, read, checked against the full node registry,
//! evaluated, and compared with the outputs their files expect.

use std::path::{Path, PathBuf};

use locus_runtime::{Document, Evaluator, Literal, NodeRegistry};

fn registry() -> NodeRegistry {
    let mut registry = NodeRegistry::new();
    locus_nodes::register(&mut registry);
    registry
}

fn curve_graphs() -> Vec<PathBuf> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../graphs");
    let mut files: Vec<PathBuf> = std::fs::read_dir(&dir)
        .unwrap_or_else(|e| panic!("cannot read {}: {e}", dir.display()))
        .map(|entry| entry.expect("directory entry").path())
        .filter(|p| {
            p.file_name()
                .and_then(|n| n.to_str())
                .is_some_and(|n| n.starts_with("curve_") && n.ends_with(".ron"))
        })
        .collect();
    files.sort();
    files
}

#[test]
fn curve_graphs_meet_their_expectations() {
    let registry = registry();
    let files = curve_graphs();
    assert!(!files.is_empty(), "no graphs/curve_*.ron");
    for file in files {
        let name = file.display().to_string();
        let text = std::fs::read_to_string(&file).expect("readable graph");
        let doc = Document::parse(&text).unwrap_or_else(|e| panic!("{name}: {e:?}"));
        let checked = doc
            .check(&registry)
            .unwrap_or_else(|e| panic!("{name}: {e:?}"));
        let mut evaluator = Evaluator::new(checked.plan.clone());
        evaluator.evaluate();
        let messages: Vec<String> = evaluator.messages().map(|m| m.to_string()).collect();
        assert!(messages.is_empty(), "{name}: {messages:?}");
        let expected = &doc.graph().expected;
        if expected.is_empty() {
            for (output, _, _) in &checked.plan.outputs {
                let tree = evaluator.output(output).expect("output");
                eprintln!("{output}: {}", Literal::from_tree(tree).expect("literal").0);
            }
            panic!("{name} expects nothing");
        }
        for (output, literal) in expected {
            let (_, node, port) = checked
                .plan
                .outputs
                .iter()
                .find(|(n, _, _)| n == output)
                .unwrap_or_else(|| panic!("{name}: no output {output}"));
            let data_type = checked.plan.nodes[*node].node_type.outputs[*port].data_type;
            let want = literal
                .parse(data_type)
                .unwrap_or_else(|e| panic!("{name} {output}: {e:?}"));
            assert_eq!(evaluator.output(output), Some(&want), "{name}: {output}");
        }
    }
}

//! Output modifiers in real definitions: Grasshopper stores them on a component's output
//! parameters exactly as on inputs (`Mapping`, `SimplifyData`, `ReverseData`, …); the importer
//! puts them on the node's `output_modifiers` and the writer puts them back.

use locus_ghx::{Limits, export_ghx, import};
use locus_runtime::{Modifier, NodeRegistry};

fn registry() -> NodeRegistry {
    let mut r = NodeRegistry::new();
    locus_nodes::register(&mut r);
    r
}

/// Every (node, output, modifiers) of an imported file.
fn output_modifiers(file: &str) -> Vec<(String, String, Vec<Modifier>)> {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data")
        .join(file);
    let imported = import(&std::fs::read(path).unwrap(), &registry(), &Limits::default()).unwrap();
    let mut found = Vec::new();
    for node in &imported.graph.nodes {
        for (port, mods) in &node.output_modifiers {
            found.push((node.id.0.clone(), port.clone(), mods.clone()));
        }
    }
    found
}

#[test]
fn output_modifiers_of_real_files_are_imported() {
    // In the list-shifting tutorial (read from the file's param_output chunks): Sequence's
    // output S is grafted, Concatenate's R and Shift List's L are simplified.
    let found = output_modifiers("runxel__datatree_list_shifting.ghx");
    let expected = [
        ("seq", "S", vec![Modifier::Graft]),
        ("concat", "R", vec![Modifier::Simplify]),
        ("shift", "L", vec![Modifier::Simplify]),
    ];
    let expected: Vec<_> = expected
        .into_iter()
        .map(|(n, p, m)| (n.to_owned(), p.to_owned(), m))
        .collect();
    assert_eq!(found, expected);
    // Reverse on an output, from the rotate-by-length tutorial: Construct Point's point.
    let found = output_modifiers("runxel__rotate_by_length.ghx");
    assert_eq!(found.len(), 1, "{found:?}");
    assert_eq!((found[0].1.as_str(), &found[0].2[..]), ("Pt", &[Modifier::Reverse][..]));
}

#[test]
fn output_modifiers_are_written_back() {
    let registry = registry();
    let text = r#"(format: 1, nodes: [
  (id: "s", type: "sets.series", output_modifiers: {"S": [graft, reverse]}),
  (id: "b", type: "maths.larger_than", values: {"B": 1.0}, output_modifiers: {">": [invert]}),
], wires: [("s.S", "b.A")])"#;
    let graph = locus_runtime::Graph::from_ron(text).unwrap();
    let (ghx, warnings) = export_ghx(&graph, &registry).unwrap();
    assert!(warnings.is_empty(), "{warnings:?}");
    assert!(ghx.contains(r#"<item name="Mapping" type_name="gh_int32" type_code="3">2</item>"#));
    let back = import(ghx.as_bytes(), &registry, &Limits::default()).unwrap();
    let mods: Vec<_> = back
        .graph
        .nodes
        .iter()
        .map(|n| n.output_modifiers.clone())
        .collect();
    assert_eq!(
        mods,
        [
            vec![("S".to_owned(), vec![Modifier::Graft, Modifier::Reverse])],
            vec![(">".to_owned(), vec![Modifier::Invert])],
        ]
    );
}

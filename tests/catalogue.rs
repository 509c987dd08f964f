//! `docs/nodes.md` is the catalogue generated from the node library's registry.

use locus_runtime::NodeRegistry;

#[test]
fn docs_nodes_md_is_up_to_date() {
    let mut registry = NodeRegistry::new();
    locus_nodes::register(&mut registry);
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/nodes.md");
    let generated = registry.catalogue_markdown();
    if std::env::var_os("UPDATE_EXPECT").is_some() {
        std::fs::write(&path, &generated).expect("docs/nodes.md is writable");
        return;
    }
    let current = std::fs::read_to_string(&path).unwrap_or_default();
    assert!(
        current == generated,
        "docs/nodes.md is out of date: run `UPDATE_EXPECT=1 cargo test --test catalogue`"
    );
}

/// The node type ids that the graphs under `graphs/` use.
fn node_types_used_by_graphs() -> std::collections::BTreeSet<String> {
    fn visit(dir: &std::path::Path, used: &mut std::collections::BTreeSet<String>) {
        for entry in std::fs::read_dir(dir).expect("graphs/ is readable") {
            let path = entry.expect("a directory entry").path();
            if path.is_dir() {
                visit(&path, used);
            } else if path.extension().is_some_and(|e| e == "ron") {
                let text = std::fs::read_to_string(&path).expect("the graph is readable");
                let document = locus_runtime::Document::parse(&text)
                    .unwrap_or_else(|_| panic!("{} reads", path.display()));
                used.extend(document.graph().nodes.iter().map(|n| n.node_type.clone()));
            }
        }
    }
    let mut used = std::collections::BTreeSet::new();
    visit(
        &std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("graphs"),
        &mut used,
    );
    used
}

#[test]
fn every_node_type_is_used_by_a_graph() {
    let mut registry = NodeRegistry::new();
    locus_nodes::register(&mut registry);
    let used = node_types_used_by_graphs();
    let unused: Vec<&str> = registry
        .iter()
        .map(|t| t.id.as_str())
        .filter(|id| !used.contains(*id))
        .collect();
    assert!(
        unused.is_empty(),
        "node types that no graph under graphs/ uses (add them to a tutorial or example graph): \
         {unused:?}"
    );
}

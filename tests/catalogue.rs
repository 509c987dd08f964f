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

//! ghx → RON → ghx → RON gives the same graph (the canonical RON, without the provenance
//! comments, which name the Grasshopper objects of each file).

use locus_ghx::{Limits, export_ghx, import};
use locus_runtime::{Document, NodeRegistry, write_graph};

fn registry() -> NodeRegistry {
    let mut r = NodeRegistry::new();
    locus_nodes::register(&mut r);
    r
}

/// The graph with its wires in the order of their targets: only the order of the wires into
/// one input means something (Grasshopper merges them in that order), and an input
/// expression's Expression node is wired in the first import before the file's wires, in the
/// second as one of them.
fn by_target(graph: &locus_runtime::Graph) -> locus_runtime::Graph {
    let mut graph = graph.clone();
    let order: Vec<_> = graph.nodes.iter().map(|n| n.id.clone()).collect();
    let rank = |id: &locus_runtime::NodeId| order.iter().position(|n| n == id);
    graph
        .wires
        .sort_by_key(|w| (rank(&w.to.node), w.to.port.clone()));
    graph
}

#[test]
fn import_export_import_is_stable_for_every_file() {
    let registry = registry();
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data");
    let mut files: Vec<_> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| locus_ghx::is_grasshopper_path(p))
        .collect();
    files.sort();
    for f in files {
        let first = import(&std::fs::read(&f).unwrap(), &registry, &Limits::default()).unwrap();
        let ron1 = write_graph(&by_target(&first.graph));
        let (ghx, _warnings) =
            export_ghx(&first.graph, &registry).unwrap_or_else(|e| panic!("{}: {e}", f.display()));
        // The written file is a GH_IO archive this crate reads back.
        let second = import(ghx.as_bytes(), &registry, &Limits::default())
            .unwrap_or_else(|e| panic!("{}: {e}\n{ghx}", f.display()));
        let ron2 = write_graph(&by_target(&second.graph));
        assert_eq!(ron1, ron2, "{}", f.display());
        assert!(second.report.runs_whole(), "{}", f.display());
        // And the RON of the second import checks like the first.
        let checks =
            |text: &str| Document::parse(text).and_then(|d| d.check(&registry).map(|_| ()));
        assert_eq!(
            checks(&ron1).is_ok(),
            checks(&ron2).is_ok(),
            "{}",
            f.display()
        );
    }
}

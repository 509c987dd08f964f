//! The Grasshopper-file reader on arbitrary bytes: `.ghx` XML, `.gh` binary archives and the
//! clusters nested in them never panic, whatever the bytes, and a definition that imports
//! writes a graph that reads back (the RON the importer prints is a graph file).
#![no_main]

use std::sync::OnceLock;

use libfuzzer_sys::fuzz_target;
use locus_runtime::{Graph, NodeRegistry};

fn registry() -> &'static NodeRegistry {
    static REGISTRY: OnceLock<NodeRegistry> = OnceLock::new();
    REGISTRY.get_or_init(|| {
        let mut registry = NodeRegistry::new();
        locus_nodes::register(&mut registry);
        registry
    })
}

fuzz_target!(|data: &[u8]| {
    // Tight limits, so that a small input cannot ask for a large allocation.
    let limits = locus_ghx::Limits {
        max_file_bytes: 1 << 20,
        max_decompressed_bytes: 16 << 20,
        max_entries: 1_000_000,
        max_string_bytes: 1 << 20,
        ..locus_ghx::Limits::default()
    };
    let Ok(import) = locus_ghx::import(data, registry(), &limits) else {
        return;
    };
    let _ = import.report.summary();
    let text = locus_ghx::to_ron(&import);
    Graph::from_ron(&text)
        .unwrap_or_else(|e| panic!("the imported graph does not read back: {e:?}\n{text}"));
});

//! The graph-file reader on arbitrary text: reading never panics, and a graph that reads
//! writes back (canonical RON) to text that reads as the same graph and writes the same bytes.
#![no_main]

use libfuzzer_sys::fuzz_target;
use locus_runtime::{Document, Graph, Literal};

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let Ok(document) = Document::parse(text) else {
        return;
    };
    let _ = document.with_expected(&[("x".to_owned(), Literal("1".to_owned()))]);
    let _ = document.with_expected(&[]);
    let graph = document.graph();
    let written = graph.to_ron();
    let again = Graph::from_ron(&written)
        .unwrap_or_else(|e| panic!("the canonical form does not read: {e:?}\n{written}"));
    assert_eq!(
        &again, graph,
        "the canonical form reads as another graph:\n{written}"
    );
    assert_eq!(again.to_ron(), written, "the canonical form is not stable");
});

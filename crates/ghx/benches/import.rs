//! Importing a large `.ghx` (about 5 MB, written by `export_ghx` from a generated graph of
//! Number parameters feeding a chain of Additions), against the baseline of parsing the same
//! bytes with roxmltree alone, measured in the same run.
//!
//! `cargo bench -p locus-ghx --bench import`

use criterion::{Criterion, criterion_group, criterion_main};
use locus_ghx::{Limits, export_ghx, import};
use locus_runtime::{Graph, GraphNode, Literal, NodeId, NodeRegistry, PortRef, Wire};

fn big_ghx(registry: &NodeRegistry, additions: usize) -> String {
    let mut g = Graph {
        format: 1,
        name: "big".to_owned(),
        ..Graph::default()
    };
    for k in 0..additions {
        g.nodes.push(GraphNode {
            id: NodeId(format!("n{k}")),
            node_type: "params.number".to_owned(),
            values: vec![("Num".to_owned(), Literal(format!("[{k}.5, 2.0, 3.0]")))],
            ..GraphNode::default()
        });
        g.nodes.push(GraphNode {
            id: NodeId(format!("a{k}")),
            node_type: "maths.addition".to_owned(),
            ..GraphNode::default()
        });
        g.wires.push(Wire {
            from: PortRef {
                node: NodeId(format!("n{k}")),
                port: "Num".to_owned(),
            },
            to: PortRef {
                node: NodeId(format!("a{k}")),
                port: "A".to_owned(),
            },
        });
        if k > 0 {
            g.wires.push(Wire {
                from: PortRef {
                    node: NodeId(format!("a{}", k - 1)),
                    port: "R".to_owned(),
                },
                to: PortRef {
                    node: NodeId(format!("a{k}")),
                    port: "B".to_owned(),
                },
            });
        }
    }
    export_ghx(&g, registry).expect("exports").0
}

fn bench(c: &mut Criterion) {
    let mut registry = NodeRegistry::new();
    locus_nodes::register(&mut registry);
    let text = big_ghx(&registry, 1400);
    eprintln!("generated .ghx: {:.2} MB", text.len() as f64 / 1e6);
    let bytes = text.into_bytes();
    let mut group = c.benchmark_group("import_5mb_ghx");
    group.sample_size(20);
    group.bench_function("baseline: roxmltree parse only", |b| {
        b.iter(|| {
            let text = std::str::from_utf8(&bytes).unwrap();
            roxmltree::Document::parse(text)
                .unwrap()
                .root()
                .children()
                .count()
        });
    });
    group.bench_function("read archive (chunk model)", |b| {
        b.iter(|| locus_ghx::read_archive(&bytes, &Limits::default()).unwrap());
    });
    group.bench_function("import (archive + mapping onto a graph)", |b| {
        b.iter(|| {
            import(&bytes, &registry, &Limits::default())
                .unwrap()
                .graph
                .nodes
                .len()
        });
    });
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);

//! Reading, checking and writing a 1,000-node graph file (a chain of additions, each with a
//! list value and a wire from the previous node), and checking one with a warning on every
//! node.

use std::hint::black_box;

use criterion::{Criterion, criterion_group, criterion_main};
use locus_runtime::{DataType, Document, NodeRegistry, NodeType, Port};

fn chain(n: usize) -> String {
    let mut text = String::from("(\n    format: 1,\n    nodes: [\n");
    for i in 0..n {
        text.push_str(&format!(
            "        (id: \"add{i}\", type: \"math.addition\", values: {{{}\"B\": [{i}.5, 2, 3]}}),\n",
            // The first node has no wire into A, so it needs a value there.
            if i == 0 { "\"A\": 0.5, " } else { "" },
        ));
    }
    text.push_str("    ],\n    wires: [\n");
    for i in 1..n {
        text.push_str(&format!("        (\"add{}.R\", \"add{i}.A\"),\n", i - 1));
    }
    text.push_str("    ],\n)\n");
    text
}

fn registry() -> NodeRegistry {
    let mut r = NodeRegistry::new();
    r.register(
        NodeType::new("math.addition", "Addition", "A+B", "Maths")
            .input(Port::new("A", "A", DataType::Number))
            .input(Port::new("B", "B", DataType::Number))
            .output(Port::new("Result", "R", DataType::Number)),
    );
    r
}

fn graph_file(c: &mut Criterion) {
    let text = chain(1000);
    let registry = registry();
    let doc = Document::parse(&text).unwrap();
    assert_eq!(doc.graph().to_ron(), text);
    c.bench_function("read 1000-node graph", |b| {
        b.iter(|| Document::parse(black_box(&text)).unwrap());
    });
    c.bench_function("check 1000-node graph", |b| {
        b.iter(|| doc.check(black_box(&registry)).unwrap());
    });
    // A value on every wired input: 999 warnings, each located in the file.
    let warned = Document::parse(&text.replace("{\"B\"", "{\"A\": 1, \"B\"")).unwrap();
    assert_eq!(warned.check(&registry).unwrap().warnings.len(), 999);
    c.bench_function("check 1000-node graph with 999 warnings", |b| {
        b.iter(|| warned.check(black_box(&registry)).unwrap());
    });
    c.bench_function("write 1000-node graph", |b| {
        b.iter(|| black_box(doc.graph()).to_ron());
    });
}

criterion_group!(benches, graph_file);
criterion_main!(benches);

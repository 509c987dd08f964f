//! Evaluation speed: lifting item functions over a million items against hand-written loops,
//! one thread against two, and a 1,000-node chain of small nodes.
//!
//! The runtime names no concrete node, so the Move-like and Addition-like node types are
//! declared here, with the same arithmetic as the hand-written loops they are compared with.
//! Figures and the command are in the crate docs (`# Performance`).

use std::hint::black_box;

use criterion::{Criterion, criterion_group, criterion_main};
use locus_kernel::{Point3, Vector3};
use locus_runtime::{DataTree, DataType, Document, Evaluator, NodeRegistry, NodeType, Port};

const N: usize = 1_000_000;

/// Move and Addition, each declared twice: as a lifted item function (`lift2`, the runtime's
/// loop over typed columns) and as a general solve function called once per item.
fn registry() -> NodeRegistry {
    let mut r = NodeRegistry::new();
    let move_type = |id: &str| {
        NodeType::new(id, "Move", "Move", "Bench")
            .input(Port::new("Geometry", "G", DataType::Point))
            .input(Port::new("Motion", "T", DataType::Vector))
            .output(Port::new("Geometry", "G", DataType::Point))
    };
    r.register(move_type("bench.move").lift2(|p: &Point3, v: &Vector3| Ok(*p + *v)));
    r.register(move_type("bench.move_solve").solve(|s| {
        let (p, v) = (*s.item::<Point3>(0)?, *s.item::<Vector3>(1)?);
        s.set(0, p + v);
        Ok(())
    }));
    let add_type = |id: &str| {
        NodeType::new(id, "Addition", "A+B", "Bench")
            .input(Port::new("A", "A", DataType::Number))
            .input(Port::new("B", "B", DataType::Number))
            .output(Port::new("Result", "R", DataType::Number))
    };
    r.register(add_type("bench.addition").lift2(|a: &f64, b: &f64| Ok(a + b)));
    r.register(add_type("bench.addition_solve").solve(|s| {
        let (a, b) = (*s.item::<f64>(0)?, *s.item::<f64>(1)?);
        s.set(0, a + b);
        Ok(())
    }));
    r
}

fn evaluator(text: &str, registry: &NodeRegistry, threads: usize) -> Evaluator {
    let plan = Document::parse(text).unwrap().check(registry).unwrap().plan;
    let mut e = Evaluator::new(plan);
    e.set_threads(threads).unwrap();
    e
}

fn move_graph(node_type: &str) -> String {
    format!(
        r#"(
    format: 1,
    nodes: [(id: "move", type: "{node_type}", values: {{"T": (1, 2, 3)}})],
    inputs: {{"points": "move.G"}},
    outputs: {{"moved": "move.G"}},
)"#
    )
}

fn add_graph(node_type: &str) -> String {
    format!(
        r#"(
    format: 1,
    nodes: [(id: "add", type: "{node_type}")],
    inputs: {{"a": "add.A", "b": "add.B"}},
    outputs: {{"sum": "add.R"}},
)"#
    )
}

fn chain(n: usize) -> String {
    let mut text = String::from("(\n    format: 1,\n    nodes: [\n");
    for i in 0..n {
        let a = if i == 0 { "\"A\": 0.5, " } else { "" };
        text.push_str(&format!(
            "        (id: \"add{i}\", type: \"bench.addition\", values: {{{a}\"B\": 1}}),\n"
        ));
    }
    text.push_str("    ],\n    wires: [\n");
    for i in 1..n {
        text.push_str(&format!("        (\"add{}.R\", \"add{i}.A\"),\n", i - 1));
    }
    text.push_str("    ],\n)\n");
    text
}

fn points() -> Vec<Point3> {
    (0..N)
        .map(|i| Point3::new(i as f64, 0.5 * i as f64, 1.0))
        .collect()
}

fn numbers(k: f64) -> Vec<f64> {
    (0..N).map(|i| k * i as f64).collect()
}

/// Evaluates the whole graph again (every node expired), keeping the inputs.
fn rerun(e: &mut Evaluator) {
    e.expire_all();
    e.evaluate();
}

fn lifting(c: &mut Criterion) {
    let registry = registry();
    let pts = points();
    let motion = Vector3::new(1.0, 2.0, 3.0);
    let mut g = c.benchmark_group("lifting");
    g.sample_size(20);
    g.bench_function("hand loop: move 1M points", |b| {
        b.iter(|| {
            let moved: Vec<Point3> = black_box(&pts).iter().map(|&p| p + motion).collect();
            moved
        });
    });
    for (node_type, threads) in [("bench.move", 1), ("bench.move", 2), ("bench.move_solve", 1)] {
        let mut e = evaluator(&move_graph(node_type), &registry, threads);
        e.set_input("points", DataTree::from_list(pts.clone()))
            .unwrap();
        e.evaluate();
        assert_eq!(e.output("moved").unwrap().item_count(), N);
        g.bench_function(
            format!("graph: move 1M points ({node_type}), {threads} thread(s)"),
            |b| b.iter(|| rerun(&mut e)),
        );
    }
    let (a, bb) = (numbers(1.0), numbers(0.25));
    g.bench_function("hand loop: add two 1M-number lists", |b| {
        b.iter(|| {
            let sum: Vec<f64> = black_box(&a)
                .iter()
                .zip(black_box(&bb))
                .map(|(x, y)| x + y)
                .collect();
            sum
        });
    });
    for (node_type, threads) in [
        ("bench.addition", 1),
        ("bench.addition", 2),
        ("bench.addition_solve", 1),
    ] {
        let mut e = evaluator(&add_graph(node_type), &registry, threads);
        e.set_input("a", DataTree::from_list(a.clone())).unwrap();
        e.set_input("b", DataTree::from_list(bb.clone())).unwrap();
        e.evaluate();
        assert_eq!(e.output("sum").unwrap().item_count(), N);
        g.bench_function(
            format!("graph: add two 1M-number lists ({node_type}), {threads} thread(s)"),
            |b| b.iter(|| rerun(&mut e)),
        );
    }
    g.finish();
}

fn chains(c: &mut Criterion) {
    let registry = registry();
    let text = chain(1000);
    for threads in [1, 2] {
        let mut e = evaluator(&text, &registry, threads);
        e.evaluate();
        assert_eq!(e.messages().count(), 0);
        c.bench_function(&format!("evaluate 1000-node chain, {threads} thread(s)"), |b| {
            b.iter(|| rerun(&mut e));
        });
    }
}

criterion_group!(benches, lifting, chains);
criterion_main!(benches);

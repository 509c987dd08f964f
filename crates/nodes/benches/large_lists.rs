//! Library nodes on a million items, through one-node graphs of the library's registry, each
//! next to a hand-written loop over the same kernel calls in the same run, on one and two
//! threads.
//!
//! Distance and Dot Product are lifted item functions (`lift2`/`lift3`: one loop over the
//! typed columns); Larger Than has two outputs and a warning, so it runs the general solve
//! function per item; Addition takes Generic data (any operand), so its columns are `Value`s.
//! A copy of Distance declared with the general solve function shows what lifting saves.
//!
//! Run with `cargo bench -p locus-nodes --bench large_lists`; figures are in the crate docs
//! (`# Performance`).

use std::hint::black_box;

use criterion::{Criterion, criterion_group, criterion_main};
use locus_kernel::{Point3, Vector3};
use locus_runtime::{
    DataTree, DataType, Document, Evaluator, NodeError, NodeRegistry, NodeType, Port,
};

const N: usize = 1_000_000;

/// The library's registry, plus Distance declared with a general solve function (the same
/// checks and kernel call, read item by item through `Solve`).
fn registry() -> NodeRegistry {
    let mut r = NodeRegistry::new();
    locus_nodes::register(&mut r);
    let general = NodeType::new("bench.distance_solve", "Distance", "Dist", "Bench")
        .input(Port::new("Point A", "A", DataType::Point))
        .input(Port::new("Point B", "B", DataType::Point))
        .output(Port::new("Distance", "D", DataType::Number))
        .solve(|s| {
            let a = finite(*s.item::<Point3>(0)?, "point A")?;
            let b = finite(*s.item::<Point3>(1)?, "point B")?;
            s.set(0, a.distance(b));
            Ok(())
        });
    r.register(general);
    r
}

/// The node's finiteness check (`vector::finite_point`), for the hand loops.
fn finite(p: Point3, what: &str) -> Result<Point3, NodeError> {
    if p.is_finite() {
        Ok(p)
    } else {
        Err(NodeError(format!(
            "{what} has a coordinate that is not finite"
        )))
    }
}

fn evaluator(text: &str, registry: &NodeRegistry, threads: usize) -> Evaluator {
    let plan = Document::parse(text).unwrap().check(registry).unwrap().plan;
    let mut e = Evaluator::new(plan);
    e.set_threads(threads).unwrap();
    e
}

/// A graph of one node of type `node_type` with the given constant values, graph inputs and
/// graph outputs (`name` → `port` of the node).
fn graph(node_type: &str, values: &str, inputs: &[(&str, &str)], output: (&str, &str)) -> String {
    let inputs: Vec<String> = inputs
        .iter()
        .map(|(name, port)| format!("\"{name}\": \"n.{port}\""))
        .collect();
    format!(
        r#"(
    format: 1,
    nodes: [(id: "n", type: "{node_type}", values: {{{values}}})],
    inputs: {{{}}},
    outputs: {{"{}": "n.{}"}},
)"#,
        inputs.join(", "),
        output.0,
        output.1
    )
}

/// Evaluates the whole graph again (every node expired), keeping the inputs.
fn rerun(e: &mut Evaluator) {
    e.expire_all();
    e.evaluate();
}

fn points() -> Vec<Point3> {
    (0..N)
        .map(|i| {
            let a = i as f64 * 1e-3;
            Point3::new(a.cos() * 10.0, a.sin() * 10.0, a)
        })
        .collect()
}

fn vectors(k: f64) -> Vec<Vector3> {
    (0..N)
        .map(|i| {
            let a = k * i as f64 * 1e-3;
            Vector3::new(a.sin(), a.cos(), 0.5)
        })
        .collect()
}

fn numbers(k: f64) -> Vec<f64> {
    (0..N).map(|i| k * (i as f64 * 1e-3).sin()).collect()
}

/// Builds the evaluator of `text` on `threads` threads with the given graph inputs, evaluates
/// it once and checks that output `output` has a million items and no message was given.
fn ready(
    text: &str,
    registry: &NodeRegistry,
    threads: usize,
    inputs: &[(&str, DataTree)],
    output: &str,
) -> Evaluator {
    let mut e = evaluator(text, registry, threads);
    for (name, tree) in inputs {
        e.set_input(name, tree.clone()).unwrap();
    }
    e.evaluate();
    assert_eq!(e.output(output).unwrap().item_count(), N);
    assert_eq!(e.messages().count(), 0);
    e
}

fn large_lists(c: &mut Criterion) {
    let registry = registry();
    let mut g = c.benchmark_group("large_lists");
    g.sample_size(10);

    // Distance from 1M points to one point.
    let pts = points();
    let target = Point3::new(1.0, 2.0, 3.0);
    g.bench_function("hand loop: distance from 1M points to a point", |b| {
        b.iter(|| {
            let d: Vec<f64> = black_box(&pts)
                .iter()
                .map(|&p| {
                    if p.is_finite() && target.is_finite() {
                        p.distance(target)
                    } else {
                        0.0
                    }
                })
                .collect();
            d
        });
    });
    let inputs = [("points", DataTree::from_list(pts.clone()))];
    let mut first: Option<DataTree> = None;
    for (node_type, threads) in [
        ("vector.distance", 1),
        ("vector.distance", 2),
        ("bench.distance_solve", 1),
    ] {
        let text = graph(
            node_type,
            r#""B": (1, 2, 3)"#,
            &[("points", "A")],
            ("d", "D"),
        );
        let mut e = ready(&text, &registry, threads, &inputs, "d");
        // The lifted and general paths, on any thread count, give the same distances.
        let out = e.output("d").unwrap().clone();
        assert_eq!(first.get_or_insert_with(|| out.clone()), &out);
        g.bench_function(
            format!("graph: Distance, 1M points ({node_type}), {threads} thread(s)"),
            |b| b.iter(|| rerun(&mut e)),
        );
    }

    // Dot Product of 1M vector pairs.
    let (va, vb) = (vectors(1.0), vectors(0.7));
    g.bench_function("hand loop: dot products of 1M vector pairs", |b| {
        b.iter(|| {
            let d: Vec<f64> = black_box(&va)
                .iter()
                .zip(black_box(&vb))
                .map(|(&a, &b)| {
                    if a.is_finite() && b.is_finite() {
                        a.dot(b)
                    } else {
                        0.0
                    }
                })
                .collect();
            d
        });
    });
    let inputs = [
        ("a", DataTree::from_list(va.clone())),
        ("b", DataTree::from_list(vb.clone())),
    ];
    for threads in [1, 2] {
        let text = graph(
            "vector.dot_product",
            "",
            &[("a", "A"), ("b", "B")],
            ("d", "D"),
        );
        let mut e = ready(&text, &registry, threads, &inputs, "d");
        g.bench_function(
            format!("graph: Dot Product, 1M vector pairs, {threads} thread(s)"),
            |b| b.iter(|| rerun(&mut e)),
        );
    }

    // Larger Than on 1M numbers against one number (general solve: two outputs, a warning).
    let xs = numbers(1.0);
    g.bench_function("hand loop: larger than, 1M numbers", |b| {
        b.iter(|| {
            let (gt, ge): (Vec<bool>, Vec<bool>) =
                black_box(&xs).iter().map(|&a| (a > 0.5, a >= 0.5)).unzip();
            (gt, ge)
        });
    });
    let inputs = [("a", DataTree::from_list(xs.clone()))];
    for threads in [1, 2] {
        let text = graph(
            "maths.larger_than",
            r#""B": 0.5"#,
            &[("a", "A")],
            ("gt", ">"),
        );
        let mut e = ready(&text, &registry, threads, &inputs, "gt");
        g.bench_function(
            format!("graph: Larger Than, 1M numbers, {threads} thread(s)"),
            |b| b.iter(|| rerun(&mut e)),
        );
    }

    // Addition of two 1M-number lists (Generic ports: columns of `Value`s).
    let ys = numbers(0.25);
    g.bench_function("hand loop: add two 1M-number lists", |b| {
        b.iter(|| {
            let sum: Vec<f64> = black_box(&xs)
                .iter()
                .zip(black_box(&ys))
                .map(|(x, y)| x + y)
                .collect();
            sum
        });
    });
    let inputs = [
        ("a", DataTree::from_list(xs.clone())),
        ("b", DataTree::from_list(ys.clone())),
    ];
    for threads in [1, 2] {
        let text = graph("maths.addition", "", &[("a", "A"), ("b", "B")], ("r", "R"));
        let mut e = ready(&text, &registry, threads, &inputs, "r");
        g.bench_function(
            format!("graph: Addition (Generic), 1M number pairs, {threads} thread(s)"),
            |b| b.iter(|| rerun(&mut e)),
        );
    }
    g.finish();
}

criterion_group!(benches, large_lists);
criterion_main!(benches);

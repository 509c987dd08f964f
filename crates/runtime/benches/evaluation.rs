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
    // Heavier per item (a sine and a cosine): rotation of a point about the world Z axis.
    r.register(
        NodeType::new("bench.rotate", "Rotate", "Rot", "Bench")
            .input(Port::new("Geometry", "G", DataType::Point))
            .input(Port::new("Angle", "A", DataType::Number))
            .output(Port::new("Geometry", "G", DataType::Point))
            .lift2(|p: &Point3, a: &f64| Ok(rotate(*p, *a))),
    );
    r.register(add_type("bench.addition_solve").solve(|s| {
        let (a, b) = (*s.item::<f64>(0)?, *s.item::<f64>(1)?);
        s.set(0, a + b);
        Ok(())
    }));
    r
}

fn rotate(p: Point3, angle: f64) -> Point3 {
    let (sin, cos) = angle.sin_cos();
    Point3::new(p.x * cos - p.y * sin, p.x * sin + p.y * cos, p.z)
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

fn rotate_graph() -> String {
    r#"(
    format: 1,
    nodes: [(id: "rotate", type: "bench.rotate")],
    inputs: {"points": "rotate.G", "angles": "rotate.A"},
    outputs: {"rotated": "rotate.G"},
)"#
    .to_owned()
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
    for (node_type, threads) in [
        ("bench.move", 1),
        ("bench.move", 2),
        ("bench.move_solve", 1),
    ] {
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
    let angles: Vec<f64> = (0..N).map(|i| i as f64 * 1e-3).collect();
    g.bench_function("hand loop: rotate 1M points", |b| {
        b.iter(|| {
            let rotated: Vec<Point3> = black_box(&pts)
                .iter()
                .zip(black_box(&angles))
                .map(|(&p, &a)| rotate(p, a))
                .collect();
            rotated
        });
    });
    for threads in [1, 2] {
        let mut e = rotate_evaluator(&registry, &pts, &angles, threads);
        g.bench_function(
            format!("graph: rotate 1M points, {threads} thread(s)"),
            |b| {
                b.iter(|| rerun(&mut e));
            },
        );
    }
    g.finish();
}

fn rotate_evaluator(
    registry: &NodeRegistry,
    pts: &[Point3],
    angles: &[f64],
    threads: usize,
) -> Evaluator {
    let mut e = evaluator(&rotate_graph(), registry, threads);
    e.set_input("points", DataTree::from_list(pts.to_vec()))
        .unwrap();
    e.set_input("angles", DataTree::from_list(angles.to_vec()))
        .unwrap();
    e.evaluate();
    assert_eq!(e.output("rotated").unwrap().item_count(), N);
    e
}

/// The process's CPU time (user + system) in seconds, from `/proc/self/stat` (clock ticks of
/// 1/100 s, Linux's `USER_HZ`); `None` where that file does not exist.
fn cpu_seconds() -> Option<f64> {
    let stat = std::fs::read_to_string("/proc/self/stat").ok()?;
    let fields: Vec<&str> = stat.rsplit_once(')')?.1.split_whitespace().collect();
    let ticks: f64 = fields.get(11)?.parse::<f64>().ok()? + fields.get(12)?.parse::<f64>().ok()?;
    Some(ticks / 100.0)
}

/// Wall and CPU time of the rotation graph on one and two threads, printed: on a machine
/// shared with other work, wall time alone understates what two threads do, so the CPU time
/// shows whether the second thread did half of the work (CPU time about the same) or waited.
fn threads_cpu_time(_: &mut Criterion) {
    let registry = registry();
    let pts = points();
    let angles: Vec<f64> = (0..N).map(|i| i as f64 * 1e-3).collect();
    let runs = 40;
    let mut report = Vec::new();
    for threads in [1, 2] {
        let mut e = rotate_evaluator(&registry, &pts, &angles, threads);
        let (wall, cpu) = (std::time::Instant::now(), cpu_seconds());
        for _ in 0..runs {
            rerun(&mut e);
        }
        let wall = wall.elapsed().as_secs_f64() / f64::from(runs);
        let cpu = cpu
            .zip(cpu_seconds())
            .map(|(a, b)| (b - a) / f64::from(runs));
        report.push((threads, wall, cpu));
    }
    for (threads, wall, cpu) in &report {
        println!(
            "rotate 1M points, {threads} thread(s): wall {:.2} ms, CPU {} per evaluation",
            wall * 1e3,
            cpu.map_or("unknown".to_owned(), |c| format!("{:.2} ms", c * 1e3))
        );
    }
    if let [(_, w1, c1), (_, w2, c2)] = report[..] {
        println!(
            "two threads: {:.2}x faster (wall); CPU time {}",
            w1 / w2,
            c1.zip(c2).map_or("unknown".to_owned(), |(a, b)| format!(
                "{:.2}x of one thread's",
                b / a
            ))
        );
    }
}

fn chains(c: &mut Criterion) {
    let registry = registry();
    let text = chain(1000);
    for threads in [1, 2] {
        let mut e = evaluator(&text, &registry, threads);
        e.evaluate();
        assert_eq!(e.messages().count(), 0);
        c.bench_function(
            &format!("evaluate 1000-node chain, {threads} thread(s)"),
            |b| {
                b.iter(|| rerun(&mut e));
            },
        );
    }
}

/// The CPU time of the calling thread in seconds, from `/proc/thread-self/schedstat`
/// (nanoseconds); `None` where that file does not exist.
fn thread_cpu_seconds() -> Option<f64> {
    let stat = std::fs::read_to_string("/proc/thread-self/schedstat").ok()?;
    Some(stat.split_whitespace().next()?.parse::<f64>().ok()? * 1e-9)
}

/// The cost per node of chains of 1,000, 10,000 and 100,000 Additions (one thread): it must not
/// grow with the chain. Criterion times each; the wall and CPU time per node, and their ratios
/// to the 1,000-node chain's, measured in the same run, are printed at the end (on a machine
/// shared with other work the CPU time is the steadier figure).
fn chain_lengths(c: &mut Criterion) {
    let registry = registry();
    let mut group = c.benchmark_group("chain length");
    group.sample_size(10);
    let mut per_node = Vec::new();
    for n in [1_000, 10_000, 100_000] {
        let mut e = evaluator(&chain(n), &registry, 1);
        e.evaluate();
        assert_eq!(e.messages().count(), 0);
        group.bench_function(format!("evaluate {n}-node chain, 1 thread"), |b| {
            b.iter(|| rerun(&mut e));
        });
        let runs = (2_000_000 / n).max(5);
        let (started, cpu) = (std::time::Instant::now(), thread_cpu_seconds());
        for _ in 0..runs {
            rerun(&mut e);
        }
        let nodes = (runs * n) as f64;
        let cpu = cpu.zip(thread_cpu_seconds()).map(|(a, b)| (b - a) / nodes);
        per_node.push((n, started.elapsed().as_secs_f64() / nodes, cpu));
    }
    group.finish();
    let (_, wall0, cpu0) = per_node[0];
    for (n, wall, cpu) in per_node {
        println!(
            "{n}-node chain: wall {:.3} µs per node ({:.2}x the 1,000-node chain's), CPU {}",
            wall * 1e6,
            wall / wall0,
            cpu.zip(cpu0)
                .map_or("unknown".to_owned(), |(c, c0)| format!(
                    "{:.3} µs per node ({:.2}x)",
                    c * 1e6,
                    c / c0
                ))
        );
    }
}

criterion_group!(benches, lifting, chains, chain_lengths, threads_cpu_time);
criterion_main!(benches);

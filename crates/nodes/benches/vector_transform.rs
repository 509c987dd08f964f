//! Throughput of Vector and Transform nodes run through the runtime (`NodeCall`, one thread):
//! the per-item cost of the solve functions plus the runtime's iteration, typed columns and
//! the generic geometry dispatch of the Transform nodes.
//!
//! Run with `cargo bench -p locus-nodes --bench vector_transform`. Measured on the shared
//! 2-core development machine (wall clock, median of 20 samples):
//!
//! | case | time | per item |
//! | --- | --- | --- |
//! | Move, 100,000 points (generic input and output) | 209 ms | 2.1 µs |
//! | Dot Product, 100,000 vector pairs (typed columns) | 21 ms | 0.21 µs |
//! | Pull Point, 1,000 points onto a 29-span cubic | 468 ms | 468 µs |
//!
//! Move is dominated by memory traffic, not arithmetic: generic columns hold `Value`s of 152
//! bytes each, which are copied on the way in and out. Pull Point is dominated by the kernel's
//! global curve closest-point search (basis function derivatives).

use std::hint::black_box;

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use locus_kernel::{Curve, NurbsCurve, Point3, Vector3};
use locus_nodes::transform::euclidean::move_geometry;
use locus_nodes::vector::products::dot_product;
use locus_nodes::vector::pull::pull_point;
use locus_runtime::{DataTree, NodeCall, Shared, Value};

const COUNT: usize = 100_000;

fn points(n: usize) -> Vec<Point3> {
    (0..n)
        .map(|i| {
            let a = i as f64 * 0.01;
            Point3::new(a.cos() * 10.0, a.sin() * 10.0, a)
        })
        .collect()
}

fn bench(c: &mut Criterion) {
    let mut group = c.benchmark_group("nodes");
    group.sample_size(20);
    group.throughput(Throughput::Elements(COUNT as u64));

    let move_node = move_geometry();
    let geometry = DataTree::from_list(points(COUNT).into_iter().map(Value::Point).collect());
    let motion = DataTree::from_item(Vector3::new(1.0, 2.0, 3.0));
    group.bench_function("move_100k_points", |b| {
        b.iter(|| {
            let r = NodeCall::new(&move_node)
                .input(geometry.clone())
                .input(motion.clone())
                .run();
            black_box(r)
        });
    });

    let dot = dot_product();
    let a = DataTree::from_list(
        points(COUNT)
            .into_iter()
            .map(Point3::to_vector)
            .collect::<Vec<_>>(),
    );
    let b_tree = DataTree::from_item(Vector3::new(0.3, -0.2, 0.9));
    group.bench_function("dot_product_100k", |b| {
        b.iter(|| {
            let r = NodeCall::new(&dot)
                .input(a.clone())
                .input(b_tree.clone())
                .run();
            black_box(r)
        });
    });

    let pulls = 1_000;
    group.throughput(Throughput::Elements(pulls as u64));
    let control = points(32);
    let curve = NurbsCurve::create(&control, 3, false).expect("valid control points");
    let pull = pull_point();
    let test_points = DataTree::from_list(
        points(pulls)
            .into_iter()
            .map(|p| p + Vector3::new(0.5, -0.5, 0.25))
            .collect::<Vec<_>>(),
    );
    let targets = DataTree::from_list(vec![Value::Curve(Shared::new(Curve::Nurbs(curve)))]);
    group.bench_function("pull_1k_points_onto_a_cubic", |b| {
        b.iter(|| {
            let r = NodeCall::new(&pull)
                .input(test_points.clone())
                .input(targets.clone())
                .run();
            black_box(r)
        });
    });
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);

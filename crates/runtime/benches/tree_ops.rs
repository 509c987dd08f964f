//! Benchmarks of tree operations and casting on trees of a million items.

use std::hint::black_box;

use criterion::{Criterion, criterion_group, criterion_main};
use locus_kernel::Point3;
use locus_runtime::{
    Branch, DataTree, DataType, GraftMode, PathMapper, SimplifyMode, TreePath, cast_branch,
};

/// 1,000 branches `{0;r;0}` of 1,000 numbers each.
fn matrix() -> DataTree {
    let mut tree = DataTree::new();
    for r in 0..1000_u32 {
        let row: Vec<f64> = (0..1000)
            .map(|c| f64::from(r) * 1000.0 + f64::from(c) + 0.5)
            .collect();
        tree.insert(TreePath::from([0, r, 0]), Branch::from_items(row));
    }
    tree
}

fn bench(c: &mut Criterion) {
    let tree = matrix();
    let numbers = Branch::from_items(
        (0..1_000_000)
            .map(|i| f64::from(i) * 0.5)
            .collect::<Vec<_>>(),
    );
    let texts = Branch::from_items(
        (0..1_000_000)
            .map(|i| (i % 977).to_string())
            .collect::<Vec<_>>(),
    );
    let points = Branch::from_items(
        (0..1_000_000)
            .map(|i| Point3::new(f64::from(i), 1.0, 2.0))
            .collect::<Vec<_>>(),
    );

    c.bench_function("flatten 1000x1000", |b| {
        b.iter(|| {
            let mut t = tree.clone();
            t.flatten();
            black_box(t)
        });
    });
    c.bench_function("clone 1000x1000 (baseline for in-place ops)", |b| {
        b.iter(|| black_box(tree.clone()));
    });
    c.bench_function("graft 1000x1000", |b| {
        b.iter(|| {
            let mut t = tree.clone();
            t.graft(GraftMode::ALL);
            black_box(t)
        });
    });
    c.bench_function("simplify 1000x1000", |b| {
        b.iter(|| {
            let mut t = tree.clone();
            t.simplify(SimplifyMode::All);
            black_box(t)
        });
    });
    c.bench_function("flip matrix 1000x1000", |b| {
        b.iter(|| {
            let mut t = tree.clone();
            t.flip_matrix().unwrap();
            black_box(t)
        });
    });
    c.bench_function("trim 1000x1000", |b| {
        b.iter(|| {
            let mut t = tree.clone();
            t.trim(2);
            black_box(t)
        });
    });
    let swap = PathMapper::new("{A;B;C}", "{C;B;A}").unwrap();
    c.bench_function("path mapper swap 1000x1000", |b| {
        b.iter(|| black_box(swap.apply(&tree).unwrap()));
    });
    let reindex = PathMapper::new("{A;B;C}(i)", "{B}(item_count-1-i)").unwrap();
    c.bench_function("path mapper per-item 1000x1000", |b| {
        b.iter(|| black_box(reindex.apply(&tree).unwrap()));
    });
    c.bench_function("cast 1M numbers to integers", |b| {
        b.iter(|| black_box(cast_branch(&numbers, DataType::Integer)));
    });
    c.bench_function("hand loop: round 1M numbers (baseline for the cast)", |b| {
        b.iter(|| {
            let xs = numbers.slice::<f64>().unwrap_or_default();
            let out: Vec<i64> = xs.iter().map(|x| x.round_ties_even() as i64).collect();
            black_box(out)
        });
    });
    c.bench_function("cast 1M texts to numbers", |b| {
        b.iter(|| black_box(cast_branch(&texts, DataType::Number)));
    });
    c.bench_function("cast 1M points to vectors", |b| {
        b.iter(|| black_box(cast_branch(&points, DataType::Vector)));
    });
    c.bench_function("to_text 1000x1000", |b| {
        b.iter(|| black_box(tree.to_text()));
    });
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(10);
    targets = bench
}
criterion_main!(benches);

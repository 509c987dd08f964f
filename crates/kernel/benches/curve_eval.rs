//! Evaluation throughput of a degree-3 NURBS curve: 1,000,000 parameters into a preallocated
//! buffer on one thread, through the batch API and, as the baseline in the same run, through
//! one `point_at` call per parameter.
//!
//! Every case runs twice: in the group `curve_eval` with criterion's wall-clock measurement, and
//! in `curve_eval_cpu` with the CPU time of the benchmarking thread (read from
//! `/proc/thread-self/schedstat`, falling back to wall-clock time elsewhere). On a shared machine
//! the CPU time is the better measure of the code itself; wall-clock time also counts the time
//! other processes hold the core.
//!
//! Run with `cargo bench -p locus-kernel --bench curve_eval`; the results are recorded in the
//! crate documentation (`src/lib.rs`, "Performance").

use criterion::measurement::Measurement;
use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use locus_kernel::{NurbsCurve, Point3};
use std::hint::black_box;

const COUNT: usize = 1_000_000;

/// A cubic through 64 control points on a helix-like path, with uniform clamped knots
/// (61 spans), rational or not.
fn curve(rational: bool) -> NurbsCurve {
    let n = 64;
    let points: Vec<Point3> = (0..n)
        .map(|i| {
            let a = i as f64 * 0.4;
            Point3::new(10.0 * a.cos(), 10.0 * a.sin(), 0.5 * i as f64)
        })
        .collect();
    let weights = if rational {
        (0..n).map(|i| 0.75 + 0.5 * ((i % 3) as f64)).collect()
    } else {
        vec![1.0; n]
    };
    let create = NurbsCurve::create(&points, 3, false).expect("valid control points");
    NurbsCurve::new(3, points, weights, create.knots().to_vec()).expect("valid curve")
}

fn sorted_parameters(curve: &NurbsCurve) -> Vec<f64> {
    let d = curve.domain();
    (0..COUNT)
        .map(|i| d.parameter_at(i as f64 / (COUNT - 1) as f64))
        .collect()
}

/// The same parameters in a scrambled order (a fixed permutation by a multiplicative step).
fn scrambled_parameters(sorted: &[f64]) -> Vec<f64> {
    let step = 7_919usize; // prime, coprime with COUNT
    (0..sorted.len())
        .map(|i| sorted[(i * step) % sorted.len()])
        .collect()
}

#[path = "support/cpu_time.rs"]
mod cpu_time;
use cpu_time::ThreadCpuTime;

fn bench(c: &mut Criterion) {
    run(c, "curve_eval");
}

fn bench_cpu(c: &mut Criterion<ThreadCpuTime>) {
    run(c, "curve_eval_cpu");
}

fn run<M: Measurement>(c: &mut Criterion<M>, name: &str) {
    let mut group = c.benchmark_group(name);
    group.throughput(Throughput::Elements(COUNT as u64));
    group.sample_size(20);
    for rational in [false, true] {
        let curve = curve(rational);
        let kind = if rational { "rational" } else { "non_rational" };
        let sorted = sorted_parameters(&curve);
        let scrambled = scrambled_parameters(&sorted);
        let mut out = vec![Point3::ORIGIN; COUNT];
        group.bench_function(format!("{kind}/batch_sorted"), |b| {
            b.iter(|| {
                curve
                    .points_at(black_box(&sorted), &mut out)
                    .expect("equal lengths");
                black_box(&out);
            });
        });
        group.bench_function(format!("{kind}/batch_scrambled"), |b| {
            b.iter(|| {
                curve
                    .points_at(black_box(&scrambled), &mut out)
                    .expect("equal lengths");
                black_box(&out);
            });
        });
        group.bench_function(format!("{kind}/point_at_loop_baseline"), |b| {
            b.iter(|| {
                for (o, &t) in out.iter_mut().zip(black_box(&sorted)) {
                    *o = curve.point_at(t);
                }
                black_box(&out);
            });
        });
    }
    group.finish();
}

criterion_group!(benches, bench);
criterion_group! {
    name = cpu_benches;
    config = Criterion::default().with_measurement(ThreadCpuTime);
    targets = bench_cpu
}
criterion_main!(benches, cpu_benches);

//! How fast the curve nodes run on typical loads: Evaluate Curve on 100 000 parameters of one
//! NURBS curve, Divide Curve into 1 000 pieces of equal length, and Interpolate through 1 000
//! points, open and periodic.

use criterion::{Criterion, criterion_group, criterion_main};
use locus_kernel::{Curve, NurbsCurve, Point3};
use locus_nodes::curve::{analysis, division, spline};
use locus_runtime::{DataTree, NodeCall, Shared};

fn wave(n: usize) -> Vec<Point3> {
    (0..n)
        .map(|i| {
            let a = i as f64 / n as f64 * std::f64::consts::TAU;
            Point3::new(10.0 * a.cos(), 7.0 * a.sin(), (5.0 * a).sin())
        })
        .collect()
}

fn curve_nodes(c: &mut Criterion) {
    let curve: Shared<Curve> = Shared::new(
        NurbsCurve::interpolate(&wave(50), 3, locus_kernel::KnotStyle::Chord)
            .expect("interpolation")
            .into(),
    );
    let d = curve.domain();
    let ts: Vec<f64> = (0..100_000)
        .map(|i| d.parameter_at(i as f64 / 100_000.0))
        .collect();
    let evaluate = analysis::evaluate_curve();
    c.bench_function("Evaluate Curve ×100k (cubic, 52 control points)", |b| {
        b.iter(|| {
            NodeCall::new(&evaluate)
                .input(DataTree::from_item(curve.clone()))
                .input(DataTree::from_list(ts.clone()))
                .run()
        });
    });
    let end_points = analysis::end_points();
    let many: Vec<Shared<Curve>> = (0..100_000).map(|_| curve.clone()).collect();
    c.bench_function("End Points ×100k (the cost of a node iteration)", |b| {
        b.iter(|| {
            NodeCall::new(&end_points)
                .input(DataTree::from_list(many.clone()))
                .run()
        });
    });
    let divide = division::divide_curve();
    c.bench_function("Divide Curve N=1000 (cubic, 52 control points)", |b| {
        b.iter(|| {
            NodeCall::new(&divide)
                .input(DataTree::from_item(curve.clone()))
                .input(DataTree::from_item(1000_i64))
                .run()
        });
    });
    let interpolate = spline::interpolate();
    let points = wave(1000);
    for periodic in [false, true] {
        let name = format!("Interpolate 1000 points, periodic {periodic}");
        c.bench_function(&name, |b| {
            b.iter(|| {
                NodeCall::new(&interpolate)
                    .input(DataTree::from_list(points.clone()))
                    .skip_input()
                    .input(DataTree::from_item(periodic))
                    .run()
            });
        });
    }
}

criterion_group!(benches, curve_nodes);
criterion_main!(benches);

//! How fast formulas run: the bare evaluator, and the Expression node against the Addition
//! node on the same 100 000 items (what a formula costs over a built-in operator).

use std::hint::black_box;

use criterion::{Criterion, criterion_group, criterion_main};
use locus_kernel::Point3;
use locus_nodes::expression::{Operand, Program};
use locus_nodes::maths::{operators, script};
use locus_runtime::{DataTree, NodeCall, Value};

const ITEMS: usize = 100_000;

fn bare_evaluator(c: &mut Criterion) {
    let program = Program::compile("x^2 + sin(y) * 3 - if(x > y, x, y)", &["x", "y"])
        .expect("the formula parses");
    c.bench_function("evaluate x^2 + sin(y)*3 - if(…) ×100k", |b| {
        b.iter(|| {
            let mut sum = 0.0;
            for i in 0..ITEMS {
                let x = i as f64 * 1e-3;
                let r = program
                    .evaluate(|v| Ok(Operand::Number(if v == 0 { x } else { 1.0 - x })))
                    .expect("numbers evaluate");
                if let Operand::Number(n) = r.value {
                    sum += n;
                }
            }
            black_box(sum)
        });
    });
}

fn nodes(c: &mut Criterion) {
    let xs: Vec<f64> = (0..ITEMS).map(|i| i as f64).collect();
    let ys: Vec<f64> = (0..ITEMS).map(|i| (i % 7) as f64).collect();
    let addition = operators::addition();
    let expression = script::expression();
    c.bench_function("Addition node ×100k", |b| {
        b.iter(|| {
            NodeCall::new(&addition)
                .input(DataTree::from_list(xs.clone()))
                .input(DataTree::from_list(ys.clone()))
                .run()
        });
    });
    c.bench_function("Expression x + y ×100k", |b| {
        b.iter(|| {
            NodeCall::new(&expression)
                .input(DataTree::from_list(xs.clone()))
                .input(DataTree::from_list(ys.clone()))
                .run()
        });
    });
    let ts: Vec<f64> = (0..ITEMS).map(|i| i as f64 / ITEMS as f64).collect();
    c.bench_function("Expression A + t*(B-A) ×100k", |b| {
        b.iter(|| {
            NodeCall::new(&expression)
                .input_names(&["A", "B", "t"])
                .setting("expression", Value::Text("A + t*(B-A)".to_owned()))
                .input(DataTree::from_item(Point3::new(0.0, 0.0, 0.0)))
                .input(DataTree::from_item(Point3::new(10.0, 4.0, 2.0)))
                .input(DataTree::from_list(ts.clone()))
                .run()
        });
    });
}

criterion_group!(benches, bare_evaluator, nodes);
criterion_main!(benches);

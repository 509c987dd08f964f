//! The node library against hand-written loops: each node as a one-node graph of the library's
//! node type on 1e3, 1e5 and 1e6 items, beside a hand-written loop doing the same arithmetic
//! and checks, in the same run, on one and two threads (a rayon pool built per case), with the
//! peak memory of the graph's evaluation.
//!
//! Run with `cargo bench -p locus-nodes --bench library` (a filter argument keeps the cases
//! whose name contains it: `-- Move`). Criterion times every case (small sample counts, so the
//! whole suite takes a few minutes on the shared 2-core machine); then the suite times each
//! case again (the fastest of a few runs) and prints a table of ratios to the one-thread hand
//! loop of the same run, which is what `docs/performance.md` keeps. `LIBRARY_TABLE_ONLY=1`
//! skips the criterion pass.
//!
//! Peak memory is counted by a counting global allocator (`peak_alloc`): the bytes the
//! evaluation held at its peak, including its input trees, divided by the bytes of its input and
//! output trees once it is done.

use std::hint::black_box;
use std::sync::Arc;
use std::time::{Duration, Instant};

use criterion::Criterion;
use locus_kernel::{Curve, NurbsCurve, Plane, Point3, Transform, Vector3};
use locus_runtime::{DataTree, Evaluator, Matching, NodeId, NodeType, Plan, PlanInput, PlanNode};
use peak_alloc::PeakAlloc;
use rayon::prelude::*;

#[global_allocator]
static ALLOCATOR: PeakAlloc = PeakAlloc;

/// A hand-written loop: runs once (in parallel when asked) and returns something to keep.
type Hand = Box<dyn Fn(bool) -> usize + Send + Sync>;

/// One node at one size: the node type, its input trees (`None` for the port's default) and
/// the hand loop over the same data.
struct Case {
    name: &'static str,
    items: usize,
    node: NodeType,
    inputs: Vec<Option<DataTree>>,
    /// The outputs the graph reads (named outputs): all but the transform of Move and Rotate,
    /// whose geometry is what a graph uses.
    read: &'static [usize],
    hand: Hand,
}

/// A graph of one node of type `node_type` whose inputs hold the given trees (or their
/// defaults), on `threads` threads.
fn one_node(case: &Case, threads: usize) -> Evaluator {
    let (node_type, inputs) = (&case.node, &case.inputs);
    let ports = node_type.resolve_inputs(None);
    let inputs = ports
        .into_iter()
        .enumerate()
        .map(|(k, port)| {
            let value = inputs
                .get(k)
                .cloned()
                .flatten()
                .or_else(|| port.default.clone().map(DataTree::from_value));
            PlanInput {
                port,
                sources: Vec::new(),
                value,
                modifiers: Vec::new(),
            }
        })
        .collect();
    let plan = Plan {
        nodes: vec![PlanNode {
            id: NodeId::from("n"),
            node_type: Arc::new(node_type.clone()),
            inputs,
            output_modifiers: Vec::new(),
            settings: Vec::new(),
            matching: Matching::Longest,
            disabled: false,
        }],
        order: vec![0],
        inputs: Vec::new(),
        outputs: case
            .read
            .iter()
            .map(|&k| (format!("out{k}"), 0, k))
            .collect(),
    };
    let mut e = Evaluator::new(plan);
    e.set_threads(threads).expect("a thread pool");
    e
}

/// Evaluates the graph again (its node expired), keeping the inputs.
fn rerun(e: &mut Evaluator) {
    e.expire_all();
    e.evaluate();
}

/// The outputs the graph reads.
fn outputs(e: &Evaluator) -> Vec<DataTree> {
    e.outputs().map(|(_, tree)| tree.clone()).collect()
}

fn points(n: usize, k: f64) -> Vec<Point3> {
    (0..n)
        .map(|i| {
            let a = k * i as f64 * 1e-3;
            Point3::new(a.cos() * 10.0, a.sin() * 10.0, a)
        })
        .collect()
}

fn numbers(n: usize, k: f64) -> Vec<f64> {
    (0..n).map(|i| k * (i as f64 * 1e-3).sin()).collect()
}

/// `xs.map(f)` collected, over threads when `parallel`.
fn map<T: Sync, O: Send>(parallel: bool, xs: &[T], f: impl Fn(&T) -> O + Sync + Send) -> Vec<O> {
    if parallel {
        xs.par_iter().map(f).collect()
    } else {
        xs.iter().map(f).collect()
    }
}

/// `(xs, ys).map(f)` collected, over threads when `parallel`.
fn map2<A: Sync, B: Sync, O: Send>(
    parallel: bool,
    xs: &[A],
    ys: &[B],
    f: impl Fn(&A, &B) -> O + Sync + Send,
) -> Vec<O> {
    if parallel {
        xs.par_iter().zip(ys).map(|(x, y)| f(x, y)).collect()
    } else {
        xs.iter().zip(ys).map(|(x, y)| f(x, y)).collect()
    }
}

/// The nodes' finiteness checks, for the hand loops: an error becomes a null (here a zero).
fn finite_or_zero(p: Point3) -> Point3 {
    if p.is_finite() { p } else { Point3::ORIGIN }
}

fn move_case(n: usize) -> Case {
    let pts = points(n, 1.0);
    let motion = Vector3::new(1.0, 2.0, 3.0);
    let inputs = vec![
        Some(DataTree::from_list(pts.clone())),
        Some(DataTree::from_item(motion)),
    ];
    Case {
        name: "Move (one vector)",
        items: n,
        read: &[0],
        node: locus_nodes::transform::euclidean::move_geometry(),
        inputs,
        hand: Box::new(move |par| {
            let t = Transform::translation(motion);
            map(par, &pts, |&p| finite_or_zero(t.transform_point(p))).len()
        }),
    }
}

fn rotate_case(n: usize) -> Case {
    let pts = points(n, 1.0);
    let angles = numbers(n, 3.0);
    let inputs = vec![
        Some(DataTree::from_list(pts.clone())),
        Some(DataTree::from_list(angles.clone())),
    ];
    Case {
        name: "Rotate (angle per point)",
        items: n,
        read: &[0],
        node: locus_nodes::transform::euclidean::rotate(),
        inputs,
        hand: Box::new(move |par| {
            let plane = Plane::WORLD_XY;
            map2(par, &pts, &angles, |&p, &a| {
                Transform::rotation(a, plane.normal(), plane.origin)
                    .map(|t| finite_or_zero(t.transform_point(p)))
                    .unwrap_or(Point3::ORIGIN)
            })
            .len()
        }),
    }
}

fn larger_than_case(n: usize) -> Case {
    let xs = numbers(n, 1.0);
    let inputs = vec![
        Some(DataTree::from_list(xs.clone())),
        Some(DataTree::from_item(0.5)),
    ];
    Case {
        name: "Larger Than",
        items: n,
        read: &[0, 1],
        node: locus_nodes::maths::comparison::larger_than(),
        inputs,
        hand: Box::new(move |par| {
            let b = 0.5;
            let (gt, ge): (Vec<bool>, Vec<bool>) = if par {
                xs.par_iter().map(|&a| (a > b, a >= b)).unzip()
            } else {
                xs.iter().map(|&a| (a > b, a >= b)).unzip()
            };
            gt.len() + ge.len()
        }),
    }
}

fn vector_2pt_case(n: usize) -> Case {
    let (a, b) = (points(n, 1.0), points(n, 0.7));
    let inputs = vec![
        Some(DataTree::from_list(a.clone())),
        Some(DataTree::from_list(b.clone())),
    ];
    Case {
        name: "Vector 2Pt",
        items: n,
        read: &[0, 1],
        node: locus_nodes::vector::vectors::vector_2pt(),
        inputs,
        hand: Box::new(move |par| {
            let f = |p: &Point3, q: &Point3| {
                let v = finite_or_zero(*q) - finite_or_zero(*p);
                (v, v.length())
            };
            let (v, l): (Vec<Vector3>, Vec<f64>) = if par {
                a.par_iter().zip(&b).map(|(p, q)| f(p, q)).unzip()
            } else {
                a.iter().zip(&b).map(|(p, q)| f(p, q)).unzip()
            };
            v.len() + l.len()
        }),
    }
}

fn deconstruct_point_case(n: usize) -> Case {
    let pts = points(n, 1.0);
    let inputs = vec![Some(DataTree::from_list(pts.clone()))];
    Case {
        name: "Deconstruct Point",
        items: n,
        read: &[0, 1, 2],
        node: locus_nodes::vector::point::deconstruct_point(),
        inputs,
        hand: Box::new(move |par| {
            let x = map(par, &pts, |p| p.x);
            let y = map(par, &pts, |p| p.y);
            let z = map(par, &pts, |p| p.z);
            black_box(pts.iter().all(|p| p.is_finite()));
            x.len() + y.len() + z.len()
        }),
    }
}

fn distance_case(n: usize) -> Case {
    let pts = points(n, 1.0);
    let target = Point3::new(1.0, 2.0, 3.0);
    let inputs = vec![
        Some(DataTree::from_list(pts.clone())),
        Some(DataTree::from_item(target)),
    ];
    Case {
        name: "Distance (to one point)",
        items: n,
        read: &[0],
        node: locus_nodes::vector::point::distance(),
        inputs,
        hand: Box::new(move |par| {
            map(par, &pts, |&p| {
                if p.is_finite() && target.is_finite() {
                    p.distance(target)
                } else {
                    0.0
                }
            })
            .len()
        }),
    }
}

fn addition_case(n: usize) -> Case {
    let (xs, ys) = (numbers(n, 1.0), numbers(n, 0.25));
    let inputs = vec![
        Some(DataTree::from_list(xs.clone())),
        Some(DataTree::from_list(ys.clone())),
    ];
    Case {
        name: "Addition (numbers)",
        items: n,
        read: &[0],
        node: locus_nodes::maths::operators::addition(),
        inputs,
        hand: Box::new(move |par| {
            map2(par, &xs, &ys, |x, y| {
                let s = x + y;
                if s.is_finite() { s } else { f64::NAN }
            })
            .len()
        }),
    }
}

fn cubic() -> Curve {
    let control: Vec<Point3> = points(32, 100.0);
    Curve::Nurbs(NurbsCurve::create(&control, 3, false).expect("valid control points"))
}

fn pull_point_case(n: usize) -> Case {
    let pts: Vec<Point3> = points(n, 50.0)
        .into_iter()
        .map(|p| p + Vector3::new(0.5, -0.5, 0.25))
        .collect();
    let curve = cubic();
    let inputs = vec![
        Some(DataTree::from_list(pts.clone())),
        Some(DataTree::from_list(vec![locus_runtime::Value::Curve(
            locus_runtime::Shared::new(curve.clone()),
        )])),
    ];
    Case {
        name: "Pull Point (onto a cubic)",
        items: n,
        read: &[0, 1],
        node: locus_nodes::vector::pull::pull_point(),
        inputs,
        hand: Box::new(move |par| {
            map(par, &pts, |&p| {
                curve.closest_point(p).map_or(0.0, |c| c.point.distance(p))
            })
            .len()
        }),
    }
}

fn evaluate_curve_case(n: usize) -> Case {
    let curves: Vec<locus_runtime::Shared<Curve>> = (0..n.min(64))
        .map(|i| {
            let control: Vec<Point3> = points(8, 300.0 + i as f64);
            locus_runtime::Shared::new(Curve::Nurbs(
                NurbsCurve::create(&control, 3, false).expect("valid control points"),
            ))
        })
        .collect();
    let curves: Vec<locus_runtime::Shared<Curve>> =
        (0..n).map(|i| curves[i % curves.len()].clone()).collect();
    let ts: Vec<f64> = curves
        .iter()
        .enumerate()
        .map(|(i, c)| {
            let d = c.domain();
            d.t0 + d.length() * ((i * 37) % 101) as f64 / 100.0
        })
        .collect();
    let inputs = vec![
        Some(DataTree::from_list(curves.clone())),
        Some(DataTree::from_list(ts.clone())),
    ];
    Case {
        name: "Evaluate Curve (many curves)",
        items: n,
        read: &[0, 1, 2],
        node: locus_nodes::curve::analysis::evaluate_curve(),
        inputs,
        hand: Box::new(move |par| {
            map2(par, &curves, &ts, |c, &t| {
                let p = c.point_at(t);
                let k = c.tangent_and_kink_angle_at(t).ok();
                (p, k)
            })
            .len()
        }),
    }
}

/// Every case of the suite, in table order.
fn cases() -> Vec<Case> {
    let sizes = [1_000, 100_000, 1_000_000];
    let mut all = Vec::new();
    for make in [
        move_case,
        rotate_case,
        larger_than_case,
        vector_2pt_case,
        deconstruct_point_case,
        distance_case,
        addition_case,
    ] {
        all.extend(sizes.iter().map(|&n| make(n)));
    }
    all.extend([100, 1_000].map(pull_point_case));
    all.extend([1_000, 100_000].map(evaluate_curve_case));
    all
}

/// The fastest of a few runs of `f` (at least three, about a quarter of a second in all).
fn fastest(mut f: impl FnMut()) -> Duration {
    f();
    let started = Instant::now();
    let mut best = Duration::MAX;
    let mut runs = 0;
    while runs < 3 || (runs < 50 && started.elapsed() < Duration::from_millis(250)) {
        let t = Instant::now();
        f();
        best = best.min(t.elapsed());
        runs += 1;
    }
    best
}

fn pool(threads: usize) -> rayon::ThreadPool {
    rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .expect("a thread pool")
}

/// The peak bytes of an evaluation (its input trees included) in MB, and their ratio to the
/// bytes of its input and output trees.
fn peak_memory(case: &Case) -> (f64, f64) {
    let before = ALLOCATOR.current_usage();
    let mut e = one_node(case, 1);
    ALLOCATOR.reset_peak_usage();
    e.evaluate();
    let peak = ALLOCATOR.peak_usage().saturating_sub(before);
    let held = ALLOCATOR.current_usage().saturating_sub(before).max(1);
    drop(e);
    (peak as f64 / 1e6, peak as f64 / held as f64)
}

fn ms(d: Duration) -> f64 {
    d.as_secs_f64() * 1e3
}

fn main() {
    let filter: Option<String> = std::env::args().skip(1).find(|a| !a.starts_with('-'));
    let cases: Vec<Case> = cases()
        .into_iter()
        .filter(|c| filter.as_ref().is_none_or(|f| c.name.contains(f.as_str())))
        .collect();
    let pools = [pool(1), pool(2)];
    if std::env::var_os("LIBRARY_TABLE_ONLY").is_none() {
        let mut c = Criterion::default()
            .sample_size(10)
            .warm_up_time(Duration::from_millis(100))
            .measurement_time(Duration::from_millis(300))
            .configure_from_args();
        for case in &cases {
            for (t, pool) in [1, 2].into_iter().zip(&pools) {
                let id = format!("library/{}/{}/{t} thread(s)", case.name, case.items);
                c.bench_function(&format!("{id}/hand loop"), |b| {
                    b.iter(|| {
                        if t == 1 {
                            (case.hand)(false)
                        } else {
                            pool.install(|| (case.hand)(true))
                        }
                    });
                });
                let mut e = one_node(case, t);
                c.bench_function(&format!("{id}/node"), |b| b.iter(|| rerun(&mut e)));
            }
        }
        c.final_summary();
    }
    println!(
        "\n| node | items | hand loop, 1 thread | node, 1 thread | hand loop, 2 threads | \
         node, 2 threads | node 1 → 2 threads | peak memory (× inputs + outputs) |"
    );
    println!("| --- | --- | --- | --- | --- | --- | --- | --- |");
    for case in &cases {
        let hand = [1, 2].map(|t| {
            fastest(|| {
                // One thread: on this thread, as the evaluator's serial mode runs.
                black_box(if t == 1 {
                    (case.hand)(false)
                } else {
                    pools[1].install(|| (case.hand)(true))
                });
            })
        });
        let mut node = [Duration::ZERO; 2];
        let mut results = Vec::new();
        for t in [1, 2] {
            let mut e = one_node(case, t);
            node[t - 1] = fastest(|| rerun(&mut e));
            results.push(outputs(&e));
        }
        assert_eq!(
            results[0], results[1],
            "{}: the outputs differ between one and two threads",
            case.name
        );
        let (peak_mb, peak_ratio) = peak_memory(case);
        let base = ms(hand[0]);
        println!(
            "| {} | {} | {:.3} ms | {:.2}× | {:.2}× | {:.2}× | {:.2}× faster | {:.1} MB ({:.1}×) |",
            case.name,
            case.items,
            base,
            ms(node[0]) / base,
            ms(hand[1]) / base,
            ms(node[1]) / base,
            ms(node[0]) / ms(node[1]),
            peak_mb,
            peak_ratio
        );
    }
}

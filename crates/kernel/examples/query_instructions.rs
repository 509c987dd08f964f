//! The closest-point queries of `benches/queries.rs`, run once each, for counting instructions
//! with cachegrind: on a shared machine, times swing by 2× from run to run, while instruction
//! counts do not.
//!
//! ```sh
//! cargo build --release -p locus-kernel --example query_instructions
//! for op in none point_at closest; do
//!   CASE=bicubic OP=$op valgrind --tool=cachegrind --cache-sim=no \
//!     --cachegrind-out-file=/dev/null target/release/examples/query_instructions
//! done
//! ```
//!
//! `CASE` is `curve`, `curve_rational`, `bicubic` or `sphere` (the benchmark's curves, 1,000
//! queries, and surfaces, 100 queries); `OP` is `closest`, `point_at` (one evaluation per
//! query, the baseline) or `none` (the set-up alone, to subtract); `REPS` repeats the queries.
//! The figures are in `docs/performance-kernel.md`.

use std::hint::black_box;

use locus_kernel::{Point3, Sphere};

#[path = "../benches/support/query_fixtures.rs"]
mod query_fixtures;
use query_fixtures::{bicubic, curve, queries};

fn main() {
    let var = |name: &str| std::env::var(name).unwrap_or_default();
    let (case, op) = (var("CASE"), var("OP"));
    let reps: usize = var("REPS").parse().unwrap_or(1);
    match case.as_str() {
        "curve" | "curve_rational" => {
            let curve = curve(case == "curve_rational");
            let tests = queries(
                1_000,
                Point3::new(-14.0, -14.0, -4.0),
                Point3::new(14.0, 14.0, 36.0),
                16,
            );
            let d = curve.domain();
            for _ in 0..reps {
                for (k, &p) in tests.iter().enumerate() {
                    match op.as_str() {
                        "closest" => {
                            black_box(curve.closest_point(black_box(p)).expect("finite"));
                        }
                        "point_at" => {
                            let t = d.parameter_at(k as f64 / tests.len() as f64);
                            black_box(curve.point_at(black_box(t)).distance(p));
                        }
                        _ => {}
                    }
                }
            }
        }
        "bicubic" | "sphere" => {
            let (surface, lo, hi) = if case == "sphere" {
                let sphere = Sphere::new(Point3::ORIGIN, 2.0).expect("a sphere");
                let c = 4.0;
                (
                    sphere.to_nurbs().expect("its surface"),
                    Point3::new(-c, -c, -c),
                    Point3::new(c, c, c),
                )
            } else {
                (
                    bicubic(),
                    Point3::new(-1.0, -1.0, -2.0),
                    Point3::new(8.0, 8.0, 2.0),
                )
            };
            let tests = queries(100, lo, hi, 4);
            let (du, dv) = (surface.domain_u(), surface.domain_v());
            for _ in 0..reps {
                for (k, &p) in tests.iter().enumerate() {
                    match op.as_str() {
                        "closest" => {
                            black_box(surface.closest_point(black_box(p)).expect("finite"));
                        }
                        "point_at" => {
                            let s = k as f64 / tests.len() as f64;
                            let q = surface.point_at(du.parameter_at(s), dv.parameter_at(1.0 - s));
                            black_box(q.distance(p));
                        }
                        _ => {}
                    }
                }
            }
        }
        _ => {
            eprintln!("CASE must be curve, curve_rational, bicubic or sphere");
            std::process::exit(2);
        }
    }
}

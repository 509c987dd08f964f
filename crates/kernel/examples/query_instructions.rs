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

use locus_kernel::{NurbsCurve, NurbsSurface, Point3, Sphere};

/// A fixed linear congruential sequence in `[0, 1)`.
fn uniform(seed: u64) -> impl FnMut() -> f64 {
    let mut state = seed;
    move || {
        state = state
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        (state >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// `count` points uniformly in the box `lo` to `hi`.
fn queries(count: usize, lo: Point3, hi: Point3, seed: u64) -> Vec<Point3> {
    let mut r = uniform(seed);
    (0..count)
        .map(|_| {
            Point3::new(
                lo.x + (hi.x - lo.x) * r(),
                lo.y + (hi.y - lo.y) * r(),
                lo.z + (hi.z - lo.z) * r(),
            )
        })
        .collect()
}

/// The benchmark's cubic through 64 control points on a helix (61 spans).
fn helix(rational: bool) -> NurbsCurve {
    let points: Vec<Point3> = (0..64)
        .map(|i| {
            let a = i as f64 * 0.4;
            Point3::new(10.0 * a.cos(), 10.0 * a.sin(), 0.5 * i as f64)
        })
        .collect();
    let weights = if rational {
        (0..64).map(|i| 0.75 + 0.5 * ((i % 3) as f64)).collect()
    } else {
        vec![1.0; 64]
    };
    let create = NurbsCurve::create(&points, 3, false).expect("valid control points");
    NurbsCurve::new(3, points, weights, create.knots().to_vec()).expect("a valid curve")
}

/// The benchmark's rational bicubic surface on an 8 × 8 grid with uneven knots.
fn bicubic() -> NurbsSurface {
    let points = (0..8)
        .map(|i| {
            (0..8)
                .map(|j| {
                    let (x, y) = (i as f64, j as f64);
                    Point3::new(x, y, (0.7 * x).sin() * (0.5 * y).cos())
                })
                .collect()
        })
        .collect();
    let weights = (0..8)
        .map(|i| {
            (0..8)
                .map(|j| 1.0 + 0.25 * ((i + 2 * j) % 3) as f64)
                .collect()
        })
        .collect();
    let knots = vec![0.0, 0.0, 0.0, 0.1, 0.3, 0.45, 0.7, 1.0, 1.0, 1.0];
    NurbsSurface::new(3, 3, points, weights, knots.clone(), knots).expect("a valid surface")
}

fn main() {
    let var = |name: &str| std::env::var(name).unwrap_or_default();
    let (case, op) = (var("CASE"), var("OP"));
    let reps: usize = var("REPS").parse().unwrap_or(1);
    match case.as_str() {
        "curve" | "curve_rational" => {
            let curve = helix(case == "curve_rational");
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

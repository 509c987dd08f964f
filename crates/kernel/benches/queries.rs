//! Divisions, closest points and sphere construction, each beside a baseline measured in the
//! same run (issue 16, parts 2 and 4).
//!
//! - `divide`: a cubic NURBS curve (64 control points on a helix, 61 spans, as in
//!   `curve_eval`) divided into `DIVISIONS` pieces by count and by length, against the batch
//!   evaluation of as many points of the same curve (`points_at`, the baseline).
//! - `curve_closest_point`: 1,000 random queries around the same curve (plain and rational),
//!   against one `point_at` per query (the baseline: the cost of one evaluation), and the
//!   search of every span without pruning (`closest_point_exhaustive`) for reference.
//! - `surface_closest_point`: 100 queries on a rational bicubic 8 × 8 surface and on a sphere,
//!   against one `point_at` per query.
//! - `sphere`: building 10,000 spheres' NURBS surfaces (what the Sphere node outputs per item),
//!   against copying a 45-point control grid per item.
//! - `brep_brep`: the intersection of two crossing spheres and of a bicubic free-form surface
//!   with a planar sheet, against the section of the same free-form surface by the sheet's
//!   plane (`intersect_plane`, the baseline: the same curves by a cheaper algorithm).
//!
//! Every time is the CPU time of the benchmarking thread (see `support/cpu_time.rs`): the
//! machine these figures come from is shared, and wall-clock times there count the time other
//! processes hold the core.
//!
//! Run with `cargo bench -p locus-kernel --bench queries`; set `LOCUS_BENCH_DIVISIONS` to
//! divide into fewer pieces (the default is 1,000,000). The figures are recorded in
//! `docs/performance-kernel.md`.

use std::hint::black_box;

use criterion::{BatchSize, Criterion, Throughput, criterion_group, criterion_main};

#[path = "support/cpu_time.rs"]
mod cpu_time;
#[path = "support/query_fixtures.rs"]
mod query_fixtures;
use cpu_time::ThreadCpuTime;
use locus_kernel::{Brep, NurbsSurface, Plane, Point3, Sphere, Vector3};
use query_fixtures::{bicubic, curve, queries};

/// The default number of divisions.
const DIVISIONS: usize = 1_000_000;

fn divisions() -> usize {
    std::env::var("LOCUS_BENCH_DIVISIONS")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(DIVISIONS)
}

fn bench_divide(c: &mut Criterion<ThreadCpuTime>) {
    let n = divisions();
    let mut group = c.benchmark_group("divide");
    group.sample_size(10);
    group.throughput(Throughput::Elements(n as u64));
    let curve = curve(false);
    let d = curve.domain();
    let params: Vec<f64> = (0..=n)
        .map(|i| d.parameter_at(i as f64 / n as f64))
        .collect();
    let mut out = vec![Point3::ORIGIN; params.len()];
    group.bench_function(format!("cubic_{n}/points_at_baseline"), |b| {
        b.iter(|| {
            curve
                .points_at(black_box(&params), &mut out)
                .expect("equal lengths");
            black_box(&out);
        });
    });
    group.bench_function(format!("cubic_{n}/by_count"), |b| {
        b.iter(|| black_box(curve.divide_by_count(black_box(n)).expect("a division")));
    });
    let length = curve.length() / n as f64 * (1.0 - 1e-9);
    group.bench_function(format!("cubic_{n}/by_length"), |b| {
        b.iter(|| {
            black_box(
                curve
                    .divide_by_length(black_box(length))
                    .expect("a division"),
            )
        });
    });
    group.finish();
}

fn bench_curve_closest(c: &mut Criterion<ThreadCpuTime>) {
    let mut group = c.benchmark_group("curve_closest_point");
    group.sample_size(10);
    let tests = queries(
        1_000,
        Point3::new(-14.0, -14.0, -4.0),
        Point3::new(14.0, 14.0, 36.0),
        16,
    );
    group.throughput(Throughput::Elements(tests.len() as u64));
    for rational in [false, true] {
        let curve = curve(rational);
        let kind = if rational { "rational" } else { "non_rational" };
        let d = curve.domain();
        group.bench_function(format!("{kind}/point_at_baseline"), |b| {
            b.iter(|| {
                for (k, p) in tests.iter().enumerate() {
                    let t = d.parameter_at(k as f64 / tests.len() as f64);
                    black_box(curve.point_at(black_box(t)).distance(*p));
                }
            });
        });
        group.bench_function(format!("{kind}/closest_point"), |b| {
            b.iter(|| {
                for &p in &tests {
                    black_box(curve.closest_point(black_box(p)).expect("closest point"));
                }
            });
        });
        group.bench_function(format!("{kind}/every_span_reference"), |b| {
            b.iter(|| {
                for &p in &tests {
                    black_box(
                        curve
                            .closest_point_exhaustive(black_box(p))
                            .expect("closest point"),
                    );
                }
            });
        });
    }
    group.finish();
}

fn bench_surface_closest(c: &mut Criterion<ThreadCpuTime>) {
    let mut group = c.benchmark_group("surface_closest_point");
    group.sample_size(10);
    let sphere = Sphere::new(Point3::ORIGIN, 2.0)
        .expect("sphere")
        .to_nurbs()
        .expect("sphere surface");
    for (label, surface, lo, hi) in [
        (
            "bicubic_rational_8x8",
            bicubic(),
            Point3::new(-1.0, -1.0, -2.0),
            Point3::new(8.0, 8.0, 2.0),
        ),
        (
            "sphere",
            sphere,
            Point3::new(-4.0, -4.0, -4.0),
            Point3::new(4.0, 4.0, 4.0),
        ),
    ] {
        let tests = queries(100, lo, hi, 4);
        group.throughput(Throughput::Elements(tests.len() as u64));
        let (du, dv) = (surface.domain_u(), surface.domain_v());
        group.bench_function(format!("{label}/point_at_baseline"), |b| {
            b.iter(|| {
                for (k, p) in tests.iter().enumerate() {
                    let s = k as f64 / tests.len() as f64;
                    let q = surface.point_at(du.parameter_at(s), dv.parameter_at(1.0 - s));
                    black_box(q.distance(*p));
                }
            });
        });
        group.bench_function(format!("{label}/closest_point"), |b| {
            b.iter(|| {
                for &p in &tests {
                    black_box(surface.closest_point(black_box(p)).expect("closest point"));
                }
            });
        });
    }
    group.finish();
}

fn bench_sphere(c: &mut Criterion<ThreadCpuTime>) {
    const COUNT: usize = 10_000;
    let mut group = c.benchmark_group("sphere");
    group.sample_size(10);
    group.throughput(Throughput::Elements(COUNT as u64));
    let centres = queries(
        COUNT,
        Point3::new(-10.0, -10.0, -10.0),
        Point3::new(10.0, 10.0, 10.0),
        9,
    );
    let grid = vec![Point3::ORIGIN; 45];
    group.bench_function("copy_45_points_baseline", |b| {
        b.iter_batched(
            || Vec::with_capacity(COUNT),
            |mut out: Vec<Vec<Point3>>| {
                for c in &centres {
                    let mut g = grid.clone();
                    g[0] = *c;
                    out.push(g);
                }
                out
            },
            BatchSize::LargeInput,
        );
    });
    group.bench_function("to_nurbs", |b| {
        b.iter_batched(
            || Vec::with_capacity(COUNT),
            |mut out: Vec<NurbsSurface>| {
                for &c in &centres {
                    out.push(
                        Sphere::new(c, 0.5)
                            .expect("sphere")
                            .to_nurbs()
                            .expect("sphere surface"),
                    );
                }
                out
            },
            BatchSize::LargeInput,
        );
    });
    group.finish();
}

fn bench_brep_brep(c: &mut Criterion<ThreadCpuTime>) {
    let mut group = c.benchmark_group("brep_brep");
    group.sample_size(10);
    let sphere = |x: f64, r: f64| {
        Brep::from_sphere(&Sphere::new(Point3::new(x, 0.3, -0.2), r).expect("sphere"))
            .expect("sphere brep")
    };
    let (a, b) = (sphere(0.0, 2.0), sphere(1.5, 1.3));
    // A bicubic graph over [0, 3]² with heights in [−1, 1], and a sheet through its middle.
    let heights = [
        0.3, -0.8, 0.5, 0.1, -0.4, 0.9, -0.2, 0.6, 0.7, -0.5, 0.2, -0.9, -0.1, 0.4, -0.6, 0.8,
    ];
    let points = (0..4)
        .map(|i| {
            (0..4)
                .map(|j| Point3::new(i as f64, j as f64, heights[4 * i + j]))
                .collect()
        })
        .collect();
    let knots = vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0];
    let free_form = Brep::from_surface(
        NurbsSurface::non_rational(3, 3, points, knots.clone(), knots).expect("surface"),
    )
    .expect("surface brep");
    let plane = Plane::from_normal(Point3::new(1.5, 1.5, 0.05), Vector3::new(0.1, -0.2, 1.0))
        .expect("plane");
    let corner = |x: f64, y: f64| plane.point_at(x, y, 0.0);
    let sheet = Brep::from_surface(
        NurbsSurface::non_rational(
            1,
            1,
            vec![
                vec![corner(-9.0, -9.0), corner(-9.0, 9.0)],
                vec![corner(9.0, -9.0), corner(9.0, 9.0)],
            ],
            vec![0.0, 1.0],
            vec![0.0, 1.0],
        )
        .expect("sheet"),
    )
    .expect("sheet brep");
    group.bench_function("free_form_plane_section_baseline", |bench| {
        bench.iter(|| black_box(free_form.intersect_plane(&plane, 1e-6).expect("section")));
    });
    group.bench_function("free_form_sheet", |bench| {
        bench.iter(|| {
            black_box(
                free_form
                    .intersect_brep(&sheet, 1e-6)
                    .expect("intersection"),
            )
        });
    });
    group.bench_function("two_spheres", |bench| {
        bench.iter(|| black_box(a.intersect_brep(&b, 1e-6).expect("intersection")));
    });
    group.finish();
}

criterion_group! {
    name = benches;
    config = Criterion::default().with_measurement(ThreadCpuTime);
    targets = bench_divide, bench_curve_closest, bench_surface_closest, bench_sphere,
        bench_brep_brep
}
criterion_main!(benches);

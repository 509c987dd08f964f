//! Evaluating a bicubic NURBS surface on a 1000 × 1000 grid of parameters, one thread.
//!
//! `grid` is [`NurbsSurface::points_on_grid`], which reuses the `v` basis functions per column
//! and the row curve per row; `pointwise` is the naive baseline, [`NurbsSurface::point_at`] at
//! every grid point (two span searches, two sets of basis functions and 16 control points per
//! point). Both write into the same preallocated buffer. Criterion reports the throughput in
//! points per second (elements/s); the target for `grid` is 60 million points per second.
//!
//! Run with `cargo bench -p locus-kernel --bench surface_eval`. Results on the shared 2-core
//! development machine (load average 8 to 12; CPU time of the evaluating thread in brackets):
//!
//! | benchmark | result |
//! | --- | --- |
//! | `bicubic/grid` | 49–97 M points/s (176 M points/s CPU) |
//! | `bicubic/pointwise` | 2.0–4.6 M points/s (9.2 M points/s CPU): grid/pointwise 19× |
//! | `bicubic_rational/grid` | 28–73 M points/s (111 M points/s CPU) |
//! | `bicubic_rational/pointwise` | 2.0–4.6 M points/s (7.5 M points/s CPU): 15× |
//! | `brep_mass/sphere/area` | 1.3–4.7 ms (0.45 ms CPU) |
//! | `brep_mass/sphere/volume` | 1.2–4.9 ms (0.41 ms CPU) |
//! | `brep_mass/capped_cylinder/volume` | 2.7–6.7 ms (1.9 ms CPU) |
//! | `surface_closest_point/bicubic_rational_8x8` | 5.3–7.0 K queries/s (14 K queries/s CPU) |

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use locus_kernel::{Brep, Cylinder, NurbsSurface, Plane, Point3, Sphere};
use std::hint::black_box;

const N: usize = 1000;

/// A bicubic surface on an 8 × 8 control grid with uneven interior knots, so that the grid
/// crosses several spans in each direction.
fn bicubic(rational: bool) -> NurbsSurface {
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
                .map(|j| {
                    if rational {
                        1.0 + 0.25 * ((i + 2 * j) % 3) as f64
                    } else {
                        1.0
                    }
                })
                .collect()
        })
        .collect();
    let knots = vec![0.0, 0.0, 0.0, 0.1, 0.3, 0.45, 0.7, 1.0, 1.0, 1.0];
    NurbsSurface::new(3, 3, points, weights, knots.clone(), knots).expect("a valid surface")
}

fn bench(c: &mut Criterion) {
    let params: Vec<f64> = (0..N).map(|i| i as f64 / (N - 1) as f64).collect();
    let mut out = vec![Point3::ORIGIN; N * N];
    let mut group = c.benchmark_group("surface_eval_1000x1000");
    group.throughput(Throughput::Elements((N * N) as u64));
    group.sample_size(20);
    for (label, rational) in [("bicubic", false), ("bicubic_rational", true)] {
        let surface = bicubic(rational);
        group.bench_function(format!("{label}/grid"), |b| {
            b.iter(|| {
                surface
                    .points_on_grid(black_box(&params), black_box(&params), &mut out)
                    .expect("valid grid");
                black_box(&out);
            });
        });
        group.bench_function(format!("{label}/pointwise"), |b| {
            b.iter(|| {
                for (row, &u) in out.chunks_exact_mut(N).zip(black_box(&params)) {
                    for (o, &v) in row.iter_mut().zip(black_box(&params)) {
                        *o = surface.point_at(u, v);
                    }
                }
                black_box(&out);
            });
        });
    }
    group.finish();
}

/// Area and volume of B-reps by adaptive Gauss–Legendre quadrature, and closest points on
/// the bicubic surface, for scale.
fn bench_brep(c: &mut Criterion) {
    let mut group = c.benchmark_group("brep_mass");
    group.sample_size(20);
    let sphere =
        Brep::from_sphere(&Sphere::new(Point3::ORIGIN, 2.0).expect("sphere")).expect("sphere brep");
    let cylinder = Brep::from_cylinder(
        &Cylinder::new(Plane::WORLD_XY, 1.5, 4.0).expect("cylinder"),
        true,
    )
    .expect("cylinder brep");
    group.bench_function("sphere/area", |b| {
        b.iter(|| black_box(&sphere).area_properties().expect("area"));
    });
    group.bench_function("sphere/volume", |b| {
        b.iter(|| black_box(&sphere).volume_properties().expect("volume"));
    });
    group.bench_function("capped_cylinder/volume", |b| {
        b.iter(|| black_box(&cylinder).volume_properties().expect("volume"));
    });
    group.finish();

    let mut group = c.benchmark_group("surface_closest_point");
    let surface = bicubic(true);
    let tests: Vec<Point3> = (0..100)
        .map(|k| {
            let t = k as f64 * 0.37;
            Point3::new(
                7.0 * (0.5 + 0.5 * t.sin()),
                7.0 * (0.5 + 0.5 * (1.3 * t).cos()),
                2.0 * (0.7 * t).sin(),
            )
        })
        .collect();
    group.throughput(Throughput::Elements(tests.len() as u64));
    group.bench_function("bicubic_rational_8x8", |b| {
        b.iter(|| {
            for &p in &tests {
                black_box(surface.closest_point(black_box(p)).expect("closest point"));
            }
        });
    });
    group.finish();
}

criterion_group!(benches, bench, bench_brep);
criterion_main!(benches);

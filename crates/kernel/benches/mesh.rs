//! Meshing at the default meshing parameters, in triangles per second: a bicubic NURBS surface
//! of 100 × 100 spans (a gentle wave, so that most spans need one or two pieces) and a sphere.
//!
//! Each is measured against a baseline in the same run: evaluating the surface at as many
//! points as the mesh has vertices with [`NurbsSurface::points_on_grid`] (the fastest way the
//! kernel has to put points on a surface), so the ratio says what the sampling, the
//! triangulation and the normals cost on top of evaluation.
//!
//! Run with `cargo bench -p locus-kernel --bench mesh`. The shared 2-core development machine
//! times the same build 1.5× apart from one run to the next, so the figures below are a
//! typical run; the changes to the mesher are compared by instruction counts (valgrind's
//! cachegrind on a program that meshes each shape once, the same build for both), which do not
//! depend on the neighbours:
//!
//! | benchmark | result |
//! | --- | --- |
//! | `mesh/wave_100x100/mesh` | 20.0 K triangles in 34 ms: 590 K triangles/s |
//! | `mesh/wave_100x100/baseline_points_on_grid` | 0.14 ms: meshing costs 240× evaluation |
//! | `mesh/sphere/mesh` | 11.4 K triangles in 7 ms: 1.6 M triangles/s |
//! | `mesh/sphere/baseline_points_on_grid` | 0.035 ms: meshing costs 200× evaluation |
//!
//! Instructions to mesh each shape once, before and after the sampler probed isocurves through
//! the kernel's `surface/across.rs` (one row curve per probe instead of a full evaluation per
//! point) and the interior grid was sheared off Delaunay ties: the wave 746 M → 232 M (3.2×),
//! the sphere 152 M → 73 M (2.1×), with the same triangles and vertices.
//!
//! Queries on a 200 × 200-quad mesh (80,000 triangles), 1,000 each, through the spatial index
//! (`cargo bench -p locus-kernel --bench mesh -- queries`; load average 10 from other builds):
//!
//! | benchmark | result |
//! | --- | --- |
//! | `mesh/queries_200x200/closest_point` | 27.5 ms: 27.5 µs per query |
//! | `mesh/queries_200x200/ray` | 11.4 ms: 11.4 µs per ray |
//! | `mesh/queries_200x200/baseline_pass_over_vertices` | 164 ms: a query through the index costs 1/6 of one pass over the vertices (and far less than a pass over the faces) |
//! | `mesh/queries_200x200/build_index` | 198 ms, once per mesh |

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use locus_kernel::{Brep, Mesh, MeshingParameters, NurbsSurface, Point3, Sphere};
use std::hint::black_box;

/// A bicubic surface with 103 × 103 control points (100 × 100 spans) on a gentle wave.
fn wave() -> NurbsSurface {
    let n = 103;
    let points = (0..n)
        .map(|i| {
            (0..n)
                .map(|j| {
                    let (x, y) = (i as f64, j as f64);
                    Point3::new(x, y, 0.8 * (0.21 * x).sin() * (0.17 * y).cos())
                })
                .collect()
        })
        .collect();
    let weights = vec![vec![1.0; n]; n];
    let mut knots = vec![0.0; 2];
    knots.extend((0..=100).map(|k| k as f64));
    knots.extend([100.0; 2]);
    NurbsSurface::new(3, 3, points, weights, knots.clone(), knots).expect("a valid surface")
}

fn bench_one(c: &mut Criterion, name: &str, brep: &Brep, surface: &NurbsSurface) {
    let parameters = MeshingParameters::default();
    let mesh = Mesh::from_brep(brep, &parameters).expect("meshes");
    let triangles = mesh.triangle_count() as u64;
    let vertices = mesh.vertices().len();
    // The baseline grid: as many points as the mesh has vertices.
    let side = (vertices as f64).sqrt().ceil() as usize;
    let (du, dv) = (surface.domain_u(), surface.domain_v());
    let us: Vec<f64> = (0..side)
        .map(|i| du.t0 + du.length() * i as f64 / (side - 1) as f64)
        .collect();
    let vs: Vec<f64> = (0..side)
        .map(|i| dv.t0 + dv.length() * i as f64 / (side - 1) as f64)
        .collect();
    let mut out = vec![Point3::ORIGIN; side * side];
    let mut group = c.benchmark_group(format!("mesh/{name}"));
    group.throughput(Throughput::Elements(triangles));
    group.sample_size(10);
    group.bench_function("mesh", |b| {
        b.iter(|| black_box(Mesh::from_brep(black_box(brep), &parameters).unwrap()));
    });
    group.bench_function("baseline_points_on_grid", |b| {
        b.iter(|| {
            surface.points_on_grid(&us, &vs, &mut out).unwrap();
            black_box(&out);
        });
    });
    group.finish();
}

/// Closest points and ray hits on a mesh of 200 × 200 quads (80,000 triangles), 1,000 queries,
/// through the mesh's spatial index, against a baseline in the same run: one pass over the
/// vertices per query, measuring each distance (less than any face-by-face search does).
fn bench_queries(c: &mut Criterion) {
    let n = 200;
    let mesh = Mesh::quad_grid(n, n, |i, j| {
        let (x, y) = (i as f64, j as f64);
        Point3::new(x, y, 3.0 * (0.1 * x).sin() * (0.07 * y).cos())
    })
    .expect("a grid");
    let queries: Vec<Point3> = (0..1000)
        .map(|k| {
            let t = k as f64;
            Point3::new(
                (t * 7.31) % 200.0,
                (t * 3.17) % 200.0,
                5.0 * (t * 0.37).sin(),
            )
        })
        .collect();
    // Build the index before measuring (it is built on a mesh's second query).
    mesh.closest_point(Point3::ORIGIN);
    mesh.closest_point(Point3::ORIGIN);
    let mut group = c.benchmark_group("mesh/queries_200x200");
    group.throughput(Throughput::Elements(queries.len() as u64));
    group.sample_size(10);
    group.bench_function("closest_point", |b| {
        b.iter(|| {
            for &q in &queries {
                black_box(mesh.closest_point(black_box(q)));
            }
        });
    });
    let down = locus_kernel::Vector3::new(0.0, 0.0, -1.0);
    group.bench_function("ray", |b| {
        b.iter(|| {
            for &q in &queries {
                let start = Point3::new(q.x, q.y, 10.0);
                black_box(locus_kernel::mesh_ray(&mesh, black_box(start), down));
            }
        });
    });
    group.bench_function("baseline_pass_over_vertices", |b| {
        b.iter(|| {
            for &q in &queries {
                let nearest = mesh
                    .vertices()
                    .iter()
                    .map(|v| v.distance(q))
                    .fold(f64::INFINITY, f64::min);
                black_box(nearest);
            }
        });
    });
    group.bench_function("build_index", |b| {
        b.iter(|| {
            let fresh = mesh.clone();
            fresh.closest_point(Point3::ORIGIN);
            black_box(fresh.closest_point(Point3::ORIGIN));
        });
    });
    group.finish();
}

fn bench(c: &mut Criterion) {
    bench_queries(c);
    let surface = wave();
    let brep = Brep::from_surface(surface.clone()).expect("a face");
    bench_one(c, "wave_100x100", &brep, &surface);
    let sphere = Sphere::new(Point3::ORIGIN, 10.0).unwrap();
    let brep = Brep::from_sphere(&sphere).unwrap();
    let surface = sphere.to_nurbs().unwrap();
    bench_one(c, "sphere", &brep, &surface);
}

criterion_group!(benches, bench);
criterion_main!(benches);

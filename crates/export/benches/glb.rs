//! Exporting 1,000,000 triangles to binary glTF (`.glb`), in MB/s of the file written, against a
//! baseline in the same run: copying the same number of bytes into a `Vec` (what writing the
//! finished file to memory costs at the least).
//!
//! The scene is one item: a flat 500 × 1000 grid of quads (1,000,000 triangles once split) with
//! vertex normals, as Mesh Plane makes it. Run with
//! `cargo bench -p locus-export --bench glb -- --warm-up-time 1 --measurement-time 5`. Results
//! on the shared 2-core development machine (other builds running):
//!
//! | benchmark | result |
//! | --- | --- |
//! | `glb_1m_triangles/to_glb` | 40.2 ms for a 22.9 MiB file: 570 MiB/s |
//! | `glb_1m_triangles/baseline_copy_to_vec` | 1.48 ms: 15.2 GiB/s; export costs 27× the copy |

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use locus_export::{GltfOptions, Scene, SceneObject, to_glb};
use locus_kernel::{Mesh, Point3};
use locus_runtime::TreePath;
use std::hint::black_box;

/// Quads along x and y: 500 × 1000 quads are 1,000,000 triangles.
const COLUMNS: usize = 500;
const ROWS: usize = 1000;

fn scene() -> Scene {
    let mesh = Mesh::quad_grid(COLUMNS, ROWS, |i, j| {
        Point3::new(
            i as f64 * 0.01,
            j as f64 * 0.01,
            ((i + j) % 7) as f64 * 0.001,
        )
    })
    .expect("grid")
    .with_computed_normals();
    assert_eq!(mesh.triangle_count(), 1_000_000);
    let mut scene = Scene::new();
    scene.objects.push(SceneObject {
        output: "grid".into(),
        path: TreePath::zero(),
        index: 0,
        label: "grid".into(),
        mesh: Some(mesh),
        lines: Vec::new(),
        points: Vec::new(),
        color: None,
    });
    scene
}

fn glb(c: &mut Criterion) {
    let scene = scene();
    let options = GltfOptions::default();
    let bytes = to_glb(&scene, &options).expect("glb");
    let mut group = c.benchmark_group("glb_1m_triangles");
    group.sample_size(10);
    group.throughput(Throughput::Bytes(bytes.len() as u64));
    group.bench_function("to_glb", |b| {
        b.iter(|| to_glb(black_box(&scene), &options).expect("glb"));
    });
    group.bench_function("baseline_copy_to_vec", |b| {
        b.iter(|| {
            let mut out = Vec::with_capacity(bytes.len());
            out.extend_from_slice(black_box(&bytes));
            out
        });
    });
    group.finish();
}

criterion_group!(benches, glb);
criterion_main!(benches);

//! Encoding and decoding a 200 × 500 grid mesh (100,000 vertices with normals and colours),
//! against a baseline in the same run: building the same mesh from its vectors with the
//! kernel's validating constructors (the work any reader must do at least).

use criterion::{Criterion, criterion_group, criterion_main};
use locus_kernel::{Color, Mesh, MeshFace, Point3, Vector3};
use locus_opennurbs_archive::{Geometry, decode, encode};
use std::hint::black_box;

fn parts() -> (Vec<Point3>, Vec<MeshFace>, Vec<Vector3>, Vec<Color>) {
    let (nu, nv) = (200u32, 500u32);
    let vs = (0..nu * nv)
        .map(|k| {
            let (i, j) = (f64::from(k / nv), f64::from(k % nv));
            Point3::new(i * 0.1, j * 0.1, (i * 0.05).sin() * (j * 0.03).cos())
        })
        .collect();
    let mut fs = Vec::new();
    for i in 0..nu - 1 {
        for j in 0..nv - 1 {
            let a = i * nv + j;
            fs.push(MeshFace::quad(a, a + nv, a + nv + 1, a + 1));
        }
    }
    let n = (nu * nv) as usize;
    let ns = vec![Vector3::new(0.0, 0.6, 0.8); n];
    let cs = (0..n)
        .map(|k| Color::rgb(k as u8, (k >> 3) as u8, 7))
        .collect();
    (vs, fs, ns, cs)
}

fn bench(c: &mut Criterion) {
    let (vs, fs, ns, cs) = parts();
    let build = || {
        Mesh::new(vs.clone(), fs.clone())
            .and_then(|m| m.with_normals(ns.clone()))
            .and_then(|m| m.with_colors(cs.clone()))
            .unwrap()
    };
    let g = Geometry::Mesh(build());
    let bytes = encode(&g).unwrap();
    let mut group = c.benchmark_group("mesh_100k");
    group.sample_size(10);
    group.bench_function("baseline: Mesh::new from vectors", |b| {
        b.iter(|| black_box(build()));
    });
    group.bench_function("encode", |b| {
        b.iter(|| black_box(encode(black_box(&g)).unwrap()));
    });
    group.bench_function("decode", |b| {
        b.iter(|| black_box(decode(black_box(&bytes)).unwrap()));
    });
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);

//! The curves, surfaces and random queries of the `queries` benchmark, shared with the
//! `query_instructions` example that counts the same queries' instructions.

use locus_kernel::{NurbsCurve, NurbsSurface, Point3};

/// A cubic through 64 control points on a helix-like path, uniform clamped knots (61 spans),
/// rational or not: the curve of the `curve_eval` benchmark.
pub fn curve(rational: bool) -> NurbsCurve {
    let n = 64;
    let points: Vec<Point3> = (0..n)
        .map(|i| {
            let a = i as f64 * 0.4;
            Point3::new(10.0 * a.cos(), 10.0 * a.sin(), 0.5 * i as f64)
        })
        .collect();
    let weights = if rational {
        (0..n).map(|i| 0.75 + 0.5 * ((i % 3) as f64)).collect()
    } else {
        vec![1.0; n]
    };
    let create = NurbsCurve::create(&points, 3, false).expect("valid control points");
    NurbsCurve::new(3, points, weights, create.knots().to_vec()).expect("valid curve")
}

/// A rational bicubic surface on an 8 × 8 control grid with uneven interior knots (the surface
/// of `surface_eval`).
pub fn bicubic() -> NurbsSurface {
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

/// A fixed linear congruential sequence in `[0, 1)`.
pub fn uniform(seed: u64) -> impl FnMut() -> f64 {
    let mut state = seed;
    move || {
        state = state
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        (state >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// `count` points uniformly in the box `lo` to `hi`.
pub fn queries(count: usize, lo: Point3, hi: Point3, seed: u64) -> Vec<Point3> {
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

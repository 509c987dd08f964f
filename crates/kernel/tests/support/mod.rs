//! Shared helpers for the kernel's integration tests: loading the oracle files (located by
//! `locus_test_data`, the one place that knows where test data lives) and comparing numbers.

#![allow(
    dead_code,
    reason = "each test binary uses its own subset of the helpers"
)]

pub mod breps;

use locus_kernel::{Brep, Curve, Plane, Point3};
use serde_json::Value;

/// Loads one oracle file (`opennurbs-cases.json` or `occt-cases.json`) as JSON, from the
/// repository's checked-in copy (`tests/data/oracle/`, through `locus_test_data`).
pub fn load_oracle(file: &str) -> Value {
    locus_test_data::load_oracle(file)
}

/// A JSON number as `f64`.
pub fn num(v: &Value) -> f64 {
    v.as_f64()
        .unwrap_or_else(|| panic!("expected a number, got {v}"))
}

/// A JSON array of three numbers.
pub fn triple(v: &Value) -> [f64; 3] {
    let a = v
        .as_array()
        .unwrap_or_else(|| panic!("expected an array, got {v}"));
    assert_eq!(a.len(), 3, "expected three numbers, got {v}");
    [num(&a[0]), num(&a[1]), num(&a[2])]
}

/// A JSON array of numbers.
pub fn numbers(v: &Value) -> Vec<f64> {
    v.as_array()
        .unwrap_or_else(|| panic!("expected an array, got {v}"))
        .iter()
        .map(num)
        .collect()
}

/// Whether `a` and `b` agree within `rel` relative to `max(1, |b|)`.
pub fn close(a: f64, b: f64, rel: f64) -> bool {
    (a - b).abs() <= rel * b.abs().max(1.0)
}

/// Whether two 3-vectors agree within `rel` relative to `max(1, |b|)` (Euclidean norm).
pub fn close3(a: [f64; 3], b: [f64; 3], rel: f64) -> bool {
    let d = ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2) + (a[2] - b[2]).powi(2)).sqrt();
    let n = (b[0].powi(2) + b[1].powi(2) + b[2].powi(2)).sqrt();
    d <= rel * n.max(1.0)
}

/// Collects failures so that a test can report all of them, each naming its case.
#[derive(Debug, Default)]
pub struct Failures(Vec<String>);

impl Failures {
    /// Records a failure.
    pub fn push(&mut self, message: String) {
        self.0.push(message);
    }

    /// Records a failure when `ok` is false.
    pub fn check(&mut self, ok: bool, message: impl FnOnce() -> String) {
        if !ok {
            self.0.push(message());
        }
    }

    /// Panics with every recorded failure, or does nothing when there are none.
    pub fn finish(self, what: &str) {
        if !self.0.is_empty() {
            panic!(
                "{} {what} failure(s):\n  {}",
                self.0.len(),
                self.0.join("\n  ")
            );
        }
    }
}

/// The signed area a closed planar curve encloses, by Green's theorem in the plane's
/// coordinates (positive when the curve runs counter-clockwise about the plane's normal):
/// Gauss–Legendre quadrature (16 points) on quarters of every span.
pub fn signed_area(c: &Curve, plane: &Plane) -> f64 {
    const X: [f64; 8] = [
        0.0950125098376374,
        0.2816035507792589,
        0.4580167776572274,
        0.6178762444026438,
        0.755_404_408_355_003,
        0.8656312023878318,
        0.9445750230732326,
        0.9894009349916499,
    ];
    const W: [f64; 8] = [
        0.1894506104550685,
        0.1826034150449236,
        0.1691565193950025,
        0.1495959888165767,
        0.1246289712555339,
        0.0951585116824928,
        0.0622535239386479,
        0.0271524594117541,
    ];
    let nurbs = c.to_nurbs();
    let breaks = nurbs.span_breaks();
    let mut sum = 0.0;
    for w in breaks.windows(2) {
        for q in 0..4 {
            let a = w[0] + (w[1] - w[0]) * q as f64 / 4.0;
            let b = w[0] + (w[1] - w[0]) * (q + 1) as f64 / 4.0;
            let (m, h) = (0.5 * (a + b), 0.5 * (b - a));
            for (x, wt) in X.iter().zip(W) {
                for t in [m - h * x, m + h * x] {
                    let d = nurbs.derivatives_at(t, 1);
                    let p = Point3::from_vector(d[0]) - plane.origin;
                    let (px, py) = (p.dot(plane.x_axis), p.dot(plane.y_axis));
                    let (dx, dy) = (d[1].dot(plane.x_axis), d[1].dot(plane.y_axis));
                    sum += wt * h * 0.5 * (px * dy - py * dx);
                }
            }
        }
    }
    sum
}

/// The area a closed planar curve encloses ([`signed_area`] without its sign).
pub fn enclosed_area(c: &Curve, plane: &Plane) -> f64 {
    signed_area(c, plane).abs()
}

/// The largest distance from points along the curves (65 per curve) to the B-rep's faces.
pub fn worst_distance(curves: &[Curve], brep: &Brep) -> f64 {
    let mut worst: f64 = 0.0;
    for c in curves {
        for k in 0..=64 {
            let p = c.point_at(c.domain().parameter_at(k as f64 / 64.0));
            let d = brep
                .faces()
                .iter()
                .filter_map(|f| f.surface.closest_point(p).ok())
                .map(|cp| cp.distance)
                .fold(f64::INFINITY, f64::min);
            worst = worst.max(d);
        }
    }
    worst
}

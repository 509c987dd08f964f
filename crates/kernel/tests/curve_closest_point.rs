//! The closest point of NURBS curves against dense sampling on 10,000 random queries (fixed
//! seed): no answer may be farther than the nearest of the samples, and the pruned search must
//! answer as the search of every span does.

use locus_kernel::{Circle, NurbsCurve, Plane, Point3, Polyline};

/// Samples per curve for the dense reference.
const DENSE_SAMPLES: usize = 40_000;
/// Queries in all, shared out over the curves.
const QUERIES: usize = 10_000;
/// How much farther than the nearest sample an answer may be, relative to the size of the
/// scene: 1e-12 (rounding only; the true minimum is never farther than a sample).
const SLACK: f64 = 1e-12;

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

/// A helix-like cubic through 64 control points (61 spans), rational or not.
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
    NurbsCurve::new(3, points, weights, create.knots().to_vec()).expect("valid curve")
}

/// A quintic that folds back on itself, with random rational weights.
fn folded(r: &mut impl FnMut() -> f64) -> NurbsCurve {
    let points: Vec<Point3> = (0..12)
        .map(|i| {
            let a = i as f64 * 0.9;
            Point3::new(4.0 * a.sin(), 3.0 * (1.7 * a).cos(), 2.0 * (0.5 * a).sin())
        })
        .collect();
    let weights = (0..12).map(|_| 0.4 + 2.0 * r()).collect();
    let create = NurbsCurve::create(&points, 5, false).expect("valid control points");
    NurbsCurve::new(5, points, weights, create.knots().to_vec()).expect("valid curve")
}

fn curves() -> Vec<NurbsCurve> {
    let mut r = uniform(7);
    let zigzag = Polyline::new(
        (0..30)
            .map(|i| Point3::new(i as f64, if i % 2 == 0 { 0.0 } else { 2.0 }, 0.0))
            .collect(),
    )
    .expect("a polyline")
    .to_nurbs();
    vec![
        helix(false),
        helix(true),
        folded(&mut r),
        Circle::new(Plane::WORLD_XY, 3.0)
            .expect("a circle")
            .to_nurbs(),
        zigzag,
    ]
}

#[test]
fn no_answer_is_farther_than_dense_sampling() {
    let curves = curves();
    let mut r = uniform(16);
    let per_curve = QUERIES / curves.len();
    for (index, curve) in curves.iter().enumerate() {
        let d = curve.domain();
        let ts: Vec<f64> = (0..=DENSE_SAMPLES)
            .map(|i| d.parameter_at(i as f64 / DENSE_SAMPLES as f64))
            .collect();
        let mut dense = vec![Point3::ORIGIN; ts.len()];
        curve.points_at(&ts, &mut dense).expect("equal lengths");
        let (mut lo, mut hi) = (dense[0], dense[0]);
        for q in &dense {
            lo = Point3::new(lo.x.min(q.x), lo.y.min(q.y), lo.z.min(q.z));
            hi = Point3::new(hi.x.max(q.x), hi.y.max(q.y), hi.z.max(q.z));
        }
        let size = lo.distance(hi);
        for _ in 0..per_curve {
            // Queries in the curve's box grown by half its size on every side.
            let mut coordinate = |a: f64, b: f64| {
                let grow = 0.5 * size;
                a - grow + (b - a + 2.0 * grow) * r()
            };
            let p = Point3::new(
                coordinate(lo.x, hi.x),
                coordinate(lo.y, hi.y),
                coordinate(lo.z, hi.z),
            );
            let cp = curve.closest_point(p).expect("a finite query");
            let nearest = dense
                .iter()
                .map(|q| q.distance(p))
                .fold(f64::INFINITY, f64::min);
            assert!(
                cp.distance <= nearest + SLACK * size,
                "curve {index}, query {p:?}: {} is farther than a sample at {nearest}",
                cp.distance
            );
            let every = curve.closest_point_exhaustive(p).expect("a finite query");
            assert!(
                (cp.distance - every.distance).abs() <= SLACK * size,
                "curve {index}, query {p:?}: pruned {cp:?}, every span {every:?}"
            );
        }
    }
}

//! Tight bounding boxes of NURBS curves.
//!
//! A curve's extremes in a coordinate are at its ends or where `C_k'(t) = 0`: each polynomial
//! span is sampled, then the best samples are polished with Newton's method confined to the
//! span, so the boxes are tight to rounding rather than the loose boxes of the control points.

use crate::{BoundingBox, NurbsCurve, Point3};

/// Samples per span and direction before Newton's method takes over.
pub(crate) const SAMPLES: usize = 9;
/// The most Newton steps per start.
pub(crate) const MAX_ITERATIONS: usize = 50;

impl NurbsCurve {
    /// The tight axis-aligned bounding box of the curve: its ends and the points where a
    /// coordinate's derivative vanishes (as for B-rep edges).
    pub fn bounding_box(&self) -> BoundingBox {
        let mut bbox = BoundingBox::EMPTY;
        include_curve(self, &mut bbox);
        bbox
    }
}

/// Grows `bbox` to the tight box of a NURBS curve: its ends and the points where a
/// coordinate's derivative vanishes.
pub(crate) fn include_curve(curve: &NurbsCurve, bbox: &mut BoundingBox) {
    bbox.include_point(curve.start_point());
    bbox.include_point(curve.end_point());
    let breaks = curve.span_breaks();
    for w in breaks.windows(2) {
        let (a, b) = (w[0], w[1]);
        let at = |k: usize| a + (b - a) * k as f64 / (SAMPLES - 1) as f64;
        let samples: Vec<Point3> = (0..SAMPLES).map(|k| curve.point_at(at(k))).collect();
        for axis in 0..3 {
            for sign in [1.0, -1.0] {
                let value = |p: Point3| sign * p.to_array()[axis];
                let (mut k_best, mut best) = (0, f64::NEG_INFINITY);
                for (k, &p) in samples.iter().enumerate() {
                    if value(p) > best {
                        best = value(p);
                        k_best = k;
                    }
                }
                let mut t = at(k_best);
                let mut f = best;
                for _ in 0..MAX_ITERATIONS {
                    let (_, d1, d2) = curve.point_and_derivatives_at(t);
                    let g = sign * d1.to_array()[axis];
                    let h = sign * d2.to_array()[axis];
                    let mut s = if h < 0.0 {
                        -g / h
                    } else {
                        0.1 * (b - a) * g.signum()
                    };
                    if g == 0.0 {
                        break;
                    }
                    let mut moved = false;
                    for _ in 0..40 {
                        let nt = (t + s).clamp(a, b);
                        let nf = value(curve.point_at(nt));
                        if nf >= f {
                            moved = (nt - t).abs() > 4.0 * f64::EPSILON * (1.0 + t.abs());
                            t = nt;
                            f = nf;
                            break;
                        }
                        s *= 0.5;
                    }
                    if !moved {
                        break;
                    }
                }
                bbox.include_point(curve.point_at(t));
            }
        }
    }
}

//! Curves through points traced on an intersection: piecewise cubic Hermite interpolation with
//! circle-matching tangent lengths.
//!
//! Between two traced points `A`, `B` with unit tangents `Ta`, `Tb` the segment is the cubic
//! Bézier `A, A + h·Ta, B − h·Tb, B` with `h = |AB| / (3 cos²(θ/4))`, `θ` the angle between the
//! tangents: the length that makes the cubic the best approximation of a circular arc with
//! those ends and tangents (`h = 4/3 · tan(θ/4) · r`), and `|AB| / 3` for a straight piece. The
//! error is of sixth order in the segment's length for smooth curves (a 5° arc of a circle is
//! off by 1e-11 of its radius), so a tracer that keeps the turning of each segment small and
//! checks the middle of each segment against the true curve gets curves far within the
//! tolerance. The segments join with a triple knot (shared end points, matching tangent
//! directions), the knots spaced by chord length.

use crate::{NurbsCurve, Point3, Result, Vector3};

/// A point on an intersection curve with its unit tangent along the curve.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct TracePoint {
    /// The point.
    pub(crate) point: Point3,
    /// The unit tangent, in the direction of the trace.
    pub(crate) tangent: Vector3,
}

/// The control points of the Hermite segment from `a` to `b` (see the module documentation).
pub(crate) fn hermite_segment(a: &TracePoint, b: &TracePoint) -> [Point3; 4] {
    let chord = a.point.distance(b.point);
    let cosine = a.tangent.dot(b.tangent).clamp(-1.0, 1.0);
    // cos²(θ/4) from cos θ: cos²(θ/4) = (1 + cos(θ/2)) / 2, cos(θ/2) = √((1 + cos θ) / 2).
    let half = ((1.0 + cosine) / 2.0).sqrt();
    let quarter_squared = (1.0 + half) / 2.0;
    let h = chord / (3.0 * quarter_squared);
    [
        a.point,
        a.point + a.tangent * h,
        b.point - b.tangent * h,
        b.point,
    ]
}

/// The point of the cubic Bézier `c` at `s`.
pub(crate) fn bezier_point(c: &[Point3; 4], s: f64) -> Point3 {
    let r = 1.0 - s;
    let (b0, b1, b2, b3) = (r * r * r, 3.0 * r * r * s, 3.0 * r * s * s, s * s * s);
    Point3::from_vector(
        c[0].to_vector() * b0
            + c[1].to_vector() * b1
            + c[2].to_vector() * b2
            + c[3].to_vector() * b3,
    )
}

/// The distance from `p` to the cubic Bézier `c` (its closest point by a few samples and
/// Newton's method).
pub(crate) fn distance_to_segment(c: &[Point3; 4], p: Point3) -> f64 {
    let mut best = (0.0, f64::INFINITY);
    for k in 0..=8 {
        let s = k as f64 / 8.0;
        let d = bezier_point(c, s).distance_squared(p);
        if d < best.1 {
            best = (s, d);
        }
    }
    let mut s = best.0;
    let v = c.map(Point3::to_vector);
    for _ in 0..8 {
        let r = 1.0 - s;
        let d1 = (v[1] - v[0]) * (3.0 * r * r)
            + (v[2] - v[1]) * (6.0 * r * s)
            + (v[3] - v[2]) * (3.0 * s * s);
        let d2 = (v[2] - v[1] * 2.0 + v[0]) * (6.0 * r) + (v[3] - v[2] * 2.0 + v[1]) * (6.0 * s);
        let e = bezier_point(c, s) - p;
        let g = e.dot(d1);
        let h = d1.dot(d1) + e.dot(d2);
        if h.is_nan() || h <= 0.0 {
            break;
        }
        let next = (s - g / h).clamp(0.0, 1.0);
        if next == s {
            break;
        }
        s = next;
    }
    bezier_point(c, s).distance(p).min(best.1.sqrt())
}

/// The curve through `points` (at least two), one Hermite segment between each consecutive
/// pair.
///
/// # Errors
/// The NURBS constructor's, for points that are not finite.
pub(crate) fn fit(points: &[TracePoint]) -> Result<NurbsCurve> {
    let mut control = Vec::with_capacity(3 * points.len());
    let mut knots = Vec::with_capacity(3 * points.len() + 3);
    let mut t = 0.0;
    knots.extend([t; 3]);
    control.push(points[0].point);
    for pair in points.windows(2) {
        let c = hermite_segment(&pair[0], &pair[1]);
        control.extend_from_slice(&c[1..]);
        let step = pair[0].point.distance(pair[1].point);
        // A segment of no length still needs an increasing knot.
        t += if step > 0.0 {
            step
        } else {
            f64::EPSILON.max(t * f64::EPSILON)
        };
        knots.extend([t; 3]);
    }
    NurbsCurve::new_non_rational(3, control, knots)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_quarter_circle_in_five_degree_pieces_is_within_1e_11() {
        let n = 18;
        let points: Vec<TracePoint> = (0..=n)
            .map(|k| {
                let a = std::f64::consts::FRAC_PI_2 * k as f64 / n as f64;
                TracePoint {
                    point: Point3::new(a.cos(), a.sin(), 0.0),
                    tangent: Vector3::new(-a.sin(), a.cos(), 0.0),
                }
            })
            .collect();
        let c = fit(&points).unwrap();
        let d = c.domain();
        for k in 0..=400 {
            let p = c.point_at(d.parameter_at(k as f64 / 400.0));
            let r = p.to_vector().length();
            assert!((r - 1.0).abs() < 1e-11, "{r}");
        }
        let segment = hermite_segment(&points[0], &points[1]);
        let off = Point3::new(0.5, 0.0, 0.0);
        assert!((distance_to_segment(&segment, off) - 0.5).abs() < 1e-3);
    }

    #[test]
    fn straight_points_give_a_straight_curve() {
        let t = Vector3::new(1.0, 1.0, 0.0).normalize_or_zero();
        let points: Vec<TracePoint> = (0..3)
            .map(|k| TracePoint {
                point: Point3::new(k as f64, k as f64, 0.0),
                tangent: t,
            })
            .collect();
        let c = fit(&points).unwrap();
        let p = c.point_at(0.3 * c.domain().t1);
        assert!((p.x - p.y).abs() < 1e-15);
    }
}

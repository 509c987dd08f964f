//! The closest pair of points of a curve piece and a surface patch near a start:
//! Gauss–Newton on `F(t, u, v) = ½|C(t) − S(u, v)|²`, confined to a parameter box.
//!
//! Where the curve crosses the surface, `C − S` has a regular Jacobian `[C′, −Su, −Sv]` and the
//! iteration converges quadratically to the crossing. Where the curve touches the surface (a
//! tangency) or the surface is singular there (a pole), the Jacobian is singular: the normal
//! equations are damped a little and the convergence is linear, so the iteration runs until the
//! steps reach rounding level rather than for a fixed count. A coordinate at a bound of the box
//! whose gradient points outwards is held there (an active set), so that crossings on the
//! surface's edges, at its corners and at the curve's ends are found exactly. A backtracking line
//! search keeps `F` from rising by more than its rounding.

use crate::geometry::small_linear::solve_dense;
use crate::intersect::patch::Patch;
use crate::intersect::piece::Piece;
use crate::{Point3, Vector3};

/// At most this many Newton steps (linear convergence at tangencies needs a few dozen).
const MAX_STEPS: usize = 100;
/// At most this many halvings of a step.
const MAX_HALVINGS: usize = 30;

/// A curve parameter, surface parameters and the distance between their points.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct CurveSurfacePoint {
    /// The curve parameter.
    pub(crate) t: f64,
    /// The surface parameters.
    pub(crate) u: f64,
    pub(crate) v: f64,
    /// `C(t)`.
    pub(crate) on_curve: Point3,
    /// `S(u, v)`.
    pub(crate) on_surface: Point3,
    /// `|C(t) − S(u, v)|`.
    pub(crate) distance: f64,
}

/// The local minimum of `|C(t) − S(u, v)|` reached from `start = (t, u, v)` with `t` in the
/// piece's range and `(u, v)` in the patch's rectangle.
pub(crate) fn closest_curve_surface(
    curve: &Piece,
    patch: &Patch,
    start: [f64; 3],
) -> CurveSurfacePoint {
    let lo = [curve.a, patch.u[0], patch.v[0]];
    let hi = [curve.b, patch.u[1], patch.v[1]];
    let mut x: [f64; 3] = std::array::from_fn(|k| start[k].clamp(lo[k], hi[k]));
    let eval = |x: &[f64; 3]| -> ([Vector3; 4], Vector3) {
        let c = curve.derivatives(x[0]);
        let s = patch.derivatives(x[1], x[2]);
        ([c[0], c[1], s[1], s[2]], c[0] - s[0])
    };
    let (mut d, mut r) = eval(&x);
    let mut f = r.length_squared();
    let scale = d[0].length().max((d[0] - r).length()).max(1.0);
    let noise = (8.0 * f64::EPSILON * scale).powi(2);
    let eps: [f64; 3] = std::array::from_fn(|k| {
        4.0 * f64::EPSILON * lo[k].abs().max(hi[k].abs()).max(hi[k] - lo[k])
    });
    for _ in 0..MAX_STEPS {
        if f == 0.0 {
            break;
        }
        // The Jacobian of C − S by columns, and the gradient of F.
        let columns = [d[1], -d[2], -d[3]];
        let g: [f64; 3] = std::array::from_fn(|k| r.dot(columns[k]));
        let free: [bool; 3] = std::array::from_fn(|k| {
            hi[k] > lo[k] && !((x[k] <= lo[k] && g[k] > 0.0) || (x[k] >= hi[k] && g[k] < 0.0))
        });
        let Some(step) = damped_step(&columns, &g, &free) else {
            break;
        };
        let mut lambda = 1.0;
        let mut accepted = false;
        for _ in 0..MAX_HALVINGS {
            let xn: [f64; 3] =
                std::array::from_fn(|k| (x[k] + lambda * step[k]).clamp(lo[k], hi[k]));
            let (nd, nr) = eval(&xn);
            let nf = nr.length_squared();
            if nf <= f + noise {
                let small = (0..3).all(|k| (xn[k] - x[k]).abs() <= eps[k]);
                x = xn;
                d = nd;
                r = nr;
                f = nf;
                accepted = !small;
                break;
            }
            lambda *= 0.5;
        }
        if !accepted {
            break;
        }
    }
    CurveSurfacePoint {
        t: x[0],
        u: x[1],
        v: x[2],
        on_curve: Point3::from_vector(d[0]),
        on_surface: Point3::from_vector(d[0] - r),
        distance: f.sqrt(),
    }
}

/// The Gauss–Newton step on the free coordinates: `(JᵀJ + δ) s = −g`, with a little damping
/// `δ` so that singular Jacobians (tangencies, poles) still give a step; `None` when nothing
/// can move.
fn damped_step(columns: &[Vector3; 3], g: &[f64; 3], free: &[bool; 3]) -> Option<[f64; 3]> {
    let index: Vec<usize> = (0..3).filter(|&k| free[k]).collect();
    let n = index.len();
    if n == 0 {
        return None;
    }
    let mut m = [[0.0; 3]; 3];
    let mut b = [0.0; 3];
    let mut trace = 0.0;
    for (i, &a) in index.iter().enumerate() {
        for (j, &c) in index.iter().enumerate() {
            m[i][j] = columns[a].dot(columns[c]);
        }
        trace += m[i][i];
        b[i] = -g[a];
    }
    if trace.is_nan() || trace <= 0.0 {
        return None;
    }
    let damping = 1e-12 * trace + f64::MIN_POSITIVE;
    for (i, row) in m.iter_mut().enumerate().take(n) {
        row[i] += damping;
    }
    // The fixed coordinates' rows and columns are the identity, so their solution is zero.
    for (i, row) in m.iter_mut().enumerate().skip(n) {
        row[i] = 1.0;
    }
    let solution = solve_dense(m, b, 0.0)?;
    let mut step = [0.0; 3];
    for (i, &a) in index.iter().enumerate() {
        step[a] = solution[i];
    }
    step.iter().all(|s| s.is_finite()).then_some(step)
}

/// A start for [`closest_curve_surface`] on a nearly straight piece and a nearly flat patch:
/// where the chord of the piece meets the plane of the patch's corners, and that point's
/// coordinates on the parallelogram of the corners, mapped onto the parameter ranges.
pub(crate) fn flat_estimate(curve: &Piece, patch: &Patch) -> [f64; 3] {
    let (p0, p1) = (curve.start(), curve.end());
    let (nu, nv) = (patch.nu, patch.nv);
    let c00 = patch.point(0, 0);
    let eu = patch.point(nu - 1, 0) - c00;
    let ev = patch.point(0, nv - 1) - c00;
    let diagonal_a = patch.point(nu - 1, nv - 1) - c00;
    let diagonal_b = patch.point(0, nv - 1) - patch.point(nu - 1, 0);
    let normal = diagonal_a.cross(diagonal_b);
    let chord = p1 - p0;
    let denominator = normal.dot(chord);
    let s = if denominator.abs() > 1e-300 {
        (normal.dot(c00 - p0) / denominator).clamp(0.0, 1.0)
    } else {
        0.5
    };
    let q = p0 + chord * s - c00;
    // Least-squares coordinates of q on the parallelogram c00 + a·eu + b·ev.
    let (uu, uv, vv) = (eu.dot(eu), eu.dot(ev), ev.dot(ev));
    let (qu, qv) = (q.dot(eu), q.dot(ev));
    let det = uu * vv - uv * uv;
    let (a, b) = if det > 1e-14 * uu * vv && det > 0.0 {
        (
            ((qu * vv - qv * uv) / det).clamp(0.0, 1.0),
            ((qv * uu - qu * uv) / det).clamp(0.0, 1.0),
        )
    } else {
        (0.5, 0.5)
    };
    [
        curve.a + s * (curve.b - curve.a),
        patch.u[0] + a * (patch.u[1] - patch.u[0]),
        patch.v[0] + b * (patch.v[1] - patch.v[0]),
    ]
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{NurbsCurve, Sphere};

    #[test]
    fn a_line_through_a_sphere_meets_it_exactly() {
        let s = Sphere::new(Point3::new(0.0, 0.0, 0.0), 2.0)
            .unwrap()
            .to_nurbs()
            .unwrap();
        let line = NurbsCurve::new_non_rational(
            1,
            vec![Point3::new(-1.0, 0.5, -5.0), Point3::new(-1.0, 0.5, 5.0)],
            vec![0.0, 1.0],
        )
        .unwrap();
        let piece = Piece::all(&line)[0];
        let mut best = f64::INFINITY;
        for patch in Patch::all(&s) {
            let x = closest_curve_surface(&piece, &patch, flat_estimate(&piece, &patch));
            best = best.min(x.distance);
            if x.distance < 1e-12 {
                assert!(x.on_curve.distance(s.point_at(x.u, x.v)) < 1e-12);
            }
        }
        assert!(best < 1e-14, "{best}");
    }
}

//! The closest pair of points of two curve pieces near a start: Newton's method on
//! `F(s, t) = ½|A(s) − B(t)|²`, confined to a parameter rectangle.
//!
//! Where the curves cross, `F` has a zero of second order and Newton's method converges
//! quadratically (Gauss–Newton would too); where they touch (a tangency), the zero is of fourth
//! order along the common tangent and the convergence is linear, so the iteration runs until the
//! steps reach rounding level rather than for a fixed count. The Hessian of `F` is used where
//! it is positive definite, and the Gauss–Newton matrix `JᵀJ` (with a little damping) where it
//! is not, far from a minimum. A coordinate at a bound of the rectangle whose gradient points
//! outwards is held there (an active set), so that minima at the ends of pieces, where the
//! curves meet end to end or one ends on the other, are found exactly. A backtracking line
//! search keeps `F` from rising by more than its rounding.

use crate::intersect::piece::Piece;
use crate::{Point3, Vector3};

/// At most this many Newton steps (linear convergence at tangencies needs a few dozen).
const MAX_STEPS: usize = 100;
/// At most this many halvings of a step.
const MAX_HALVINGS: usize = 30;

/// A pair of parameters and the distance between their points.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct PairPoint {
    /// The parameter on A.
    pub(crate) s: f64,
    /// The parameter on B.
    pub(crate) t: f64,
    /// `A(s)`.
    pub(crate) a: Point3,
    /// `B(t)`.
    pub(crate) b: Point3,
    /// `|A(s) − B(t)|`.
    pub(crate) distance: f64,
}

/// The local minimum of `|A(s) − B(t)|` reached from `(s0, t0)` with `s` in `ra` and `t` in
/// `rb`; `a` and `b` evaluate the curves (point and two derivatives) anywhere in their ranges.
pub(crate) fn closest_pair(
    a: &Piece,
    ra: [f64; 2],
    b: &Piece,
    rb: [f64; 2],
    s0: f64,
    t0: f64,
) -> PairPoint {
    let mut s = s0.clamp(ra[0], ra[1]);
    let mut t = t0.clamp(rb[0], rb[1]);
    let mut da = a.derivatives(s);
    let mut db = b.derivatives(t);
    let mut r = da[0] - db[0];
    let mut f = r.length_squared();
    let scale = da[0].length().max(db[0].length()).max(1.0);
    // The rounding of |r|² where r is near zero: the points carry about 4 ulps of `scale`.
    let noise = (8.0 * f64::EPSILON * scale).powi(2);
    let eps_s = 4.0 * f64::EPSILON * (ra[0].abs().max(ra[1].abs()).max(ra[1] - ra[0]));
    let eps_t = 4.0 * f64::EPSILON * (rb[0].abs().max(rb[1].abs()).max(rb[1] - rb[0]));
    for _ in 0..MAX_STEPS {
        if f == 0.0 {
            break;
        }
        let (a1, a2, b1, b2) = (da[1], da[2], db[1], db[2]);
        let g = [r.dot(a1), -r.dot(b1)];
        let (gn_ss, gn_tt, cross) = (a1.dot(a1), b1.dot(b1), -a1.dot(b1));
        let (h_ss, h_tt) = (gn_ss + r.dot(a2), gn_tt - r.dot(b2));
        // Which coordinates may move: not one at a bound with its gradient pointing outwards.
        let free_s = !((s <= ra[0] && g[0] > 0.0) || (s >= ra[1] && g[0] < 0.0)) && ra[1] > ra[0];
        let free_t = !((t <= rb[0] && g[1] > 0.0) || (t >= rb[1] && g[1] < 0.0)) && rb[1] > rb[0];
        let (ds, dt) = match (free_s, free_t) {
            (true, true) => {
                let det = h_ss * h_tt - cross * cross;
                if h_ss > 0.0 && det > 0.0 {
                    (
                        -(h_tt * g[0] - cross * g[1]) / det,
                        -(h_ss * g[1] - cross * g[0]) / det,
                    )
                } else {
                    let damping = 1e-9 * (gn_ss + gn_tt) + f64::MIN_POSITIVE;
                    let (m_ss, m_tt) = (gn_ss + damping, gn_tt + damping);
                    let det = m_ss * m_tt - cross * cross;
                    if det.is_nan() || det <= 0.0 {
                        break;
                    }
                    (
                        -(m_tt * g[0] - cross * g[1]) / det,
                        -(m_ss * g[1] - cross * g[0]) / det,
                    )
                }
            }
            (true, false) => (step_1d(g[0], h_ss, gn_ss), 0.0),
            (false, true) => (0.0, step_1d(g[1], h_tt, gn_tt)),
            (false, false) => break,
        };
        if !(ds.is_finite() && dt.is_finite()) {
            break;
        }
        let mut lambda = 1.0;
        let mut accepted = false;
        for _ in 0..MAX_HALVINGS {
            let sn = (s + lambda * ds).clamp(ra[0], ra[1]);
            let tn = (t + lambda * dt).clamp(rb[0], rb[1]);
            let (na, nb) = (a.derivatives(sn), b.derivatives(tn));
            let nr = na[0] - nb[0];
            let nf = nr.length_squared();
            if nf <= f + noise {
                let small = (sn - s).abs() <= eps_s && (tn - t).abs() <= eps_t;
                s = sn;
                t = tn;
                da = na;
                db = nb;
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
    PairPoint {
        s,
        t,
        a: Point3::from_vector(da[0]),
        b: Point3::from_vector(db[0]),
        distance: f.sqrt(),
    }
}

/// A one-dimensional Newton step on a gradient `g` with curvature `h`, falling back to the
/// Gauss–Newton curvature `gn` where `h` is not positive.
fn step_1d(g: f64, h: f64, gn: f64) -> f64 {
    if h > 0.0 {
        -g / h
    } else if gn > 0.0 {
        -g / gn
    } else {
        0.0
    }
}

/// The parameters on two nearly straight pieces where their chords come closest, as the start
/// of [`closest_pair`]: each chord's parameter mapped linearly onto its piece's range.
pub(crate) fn chord_estimate(a: &Piece, b: &Piece) -> (f64, f64) {
    let (p0, p1, q0, q1) = (a.start(), a.end(), b.start(), b.end());
    let (u, v) = segment_segment(p0, p1 - p0, q0, q1 - q0);
    (a.a + u * (a.b - a.a), b.a + v * (b.b - b.a))
}

/// The parameters in `[0, 1]²` of the closest points of the segments `p + u·d` and `q + v·e`.
fn segment_segment(p: Point3, d: Vector3, q: Point3, e: Vector3) -> (f64, f64) {
    let r = p - q;
    let (dd, ee, de) = (d.dot(d), e.dot(e), d.dot(e));
    let (dr, er) = (d.dot(r), e.dot(r));
    if dd <= 0.0 && ee <= 0.0 {
        return (0.0, 0.0);
    }
    if dd <= 0.0 {
        return (0.0, (er / ee).clamp(0.0, 1.0));
    }
    if ee <= 0.0 {
        return ((-dr / dd).clamp(0.0, 1.0), 0.0);
    }
    let det = dd * ee - de * de;
    let mut u = if det > 1e-14 * dd * ee {
        ((de * er - ee * dr) / det).clamp(0.0, 1.0)
    } else {
        0.5
    };
    let mut v = (de * u + er) / ee;
    if v < 0.0 {
        v = 0.0;
        u = (-dr / dd).clamp(0.0, 1.0);
    } else if v > 1.0 {
        v = 1.0;
        u = ((de - dr) / dd).clamp(0.0, 1.0);
    }
    (u, v)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::NurbsCurve;

    fn line(p: [f64; 3], q: [f64; 3]) -> Piece {
        let c = NurbsCurve::new_non_rational(
            1,
            vec![Point3::from_array(p), Point3::from_array(q)],
            vec![0.0, 1.0],
        )
        .unwrap();
        Piece::all(&c)[0]
    }

    #[test]
    fn crossing_lines_meet_exactly() {
        let a = line([0.0, 0.0, 0.0], [4.0, 0.0, 0.0]);
        let b = line([1.0, -1.0, 0.0], [1.0, 3.0, 0.0]);
        let (s0, t0) = chord_estimate(&a, &b);
        let r = closest_pair(&a, [0.0, 1.0], &b, [0.0, 1.0], s0, t0);
        assert!(
            (r.s - 0.25).abs() < 1e-15 && (r.t - 0.25).abs() < 1e-15,
            "{r:?}"
        );
        assert!(r.distance < 1e-15);
        // From a poor start too.
        let r = closest_pair(&a, [0.0, 1.0], &b, [0.0, 1.0], 0.9, 0.9);
        assert!(r.distance < 1e-15, "{r:?}");
    }

    #[test]
    fn a_minimum_at_the_ends_is_exact() {
        let a = line([0.0, 0.0, 0.0], [1.0, 0.0, 0.0]);
        let b = line([2.0, 1.0, 0.0], [3.0, 5.0, 0.0]);
        let r = closest_pair(&a, [0.0, 1.0], &b, [0.0, 1.0], 0.5, 0.5);
        assert_eq!((r.s, r.t), (1.0, 0.0));
        assert!((r.distance - 2f64.sqrt()).abs() < 1e-15);
    }
}

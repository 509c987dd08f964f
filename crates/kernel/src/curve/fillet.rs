//! Filleting the corners of a curve with arcs of one radius (Grasshopper's *Fillet* with a
//! curve and a radius, Rhino's `Curve.CreateFilletCornersCurve`), or with arcs that start a
//! given distance from each corner (Grasshopper's *Fillet Distance*).
//!
//! The curve is cut at its kinks (tangent breaks above [`KINK_ANGLE_TOLERANCE`], and the seam
//! of a closed curve when it is one) into smooth pieces. At each corner, between the piece
//! before it (`A`) and the piece after it (`B`), the fillet is the arc of radius `r` tangent to
//! both: its centre lies at distance `r` from both pieces on the inner side of the turn. With
//! `n̂` the unit normal of the corner's plane (`T_A × T_B` at the corner) and `T` the unit
//! tangent, the centre seen from `A` at `s` is `A(s) + r n̂ × T_A(s)`, seen from `B` at `t` it is
//! `B(t) + r n̂ × T_B(t)`, and Gauss–Newton on `(s, t)` makes the two agree. Straight pieces
//! converge in one step to the classical `r tan(φ/2)` set-back from the corner (`φ` the turning
//! angle). The arc runs from `A(s)` to `B(t)`, leaving along `T_A(s)`. Filleting by distance
//! takes at each corner the radius `d / tan(φ/2)` whose set-back is `d`, exactly `d` along
//! straight pieces and close to it along curved ones.
//!
//! A corner whose arc does not fit is left sharp and reported: when the arc would need more of
//! a piece than it has (the radius is too large for the segments beside the corner, or the
//! fillet of the previous corner already used that part), when the curve turns straight back
//! (a cusp), or when no arc touches both pieces (curves that are not planar at the corner).
//! Corners are taken in order along the curve, the seam first, so that which corner stays sharp
//! does not depend on anything but the curve. The pieces, cut back to the arcs, and the arcs are
//! joined into one curve.

use crate::curve::kinks::KINK_ANGLE_TOLERANCE;
use crate::{Arc, Curve, Error, Interval, Point3, Result, Vector3};

/// How many Gauss–Newton steps one corner may take.
const MAX_STEPS: usize = 60;

/// A corner left sharp by [`Curve::fillet_corners`], and why.
#[derive(Clone, Debug, PartialEq)]
pub struct SharpCorner {
    /// The corner's number: the index of the smooth piece that starts there, so that the
    /// corners of a polyline are numbered as its vertices (the seam of a closed curve is 0).
    pub index: usize,
    /// The corner's point.
    pub point: Point3,
    /// Why no fillet was made, in words.
    pub reason: String,
}

/// The result of [`Curve::fillet_corners`]: the filleted curve and the corners left sharp.
#[derive(Clone, Debug, PartialEq)]
pub struct CurveFillet {
    /// The curve with its corners rounded (the curve itself when it has no corner).
    pub curve: Curve,
    /// The corners left sharp, in order.
    pub sharp: Vec<SharpCorner>,
}

/// The fillet at one corner: the parameters where it leaves `A` and reaches `B`, and the arc.
struct CornerFillet {
    s: f64,
    t: f64,
    arc: Arc,
}

/// Point, first and second derivative of `c` at `u`.
fn derivatives(c: &Curve, u: f64) -> (Point3, Vector3, Vector3) {
    c.point_and_derivatives_at(u)
}

/// The centre seen from the curve at `u`, `C(u) + r n̂ × T(u)`, and its derivative in `u`.
fn centre_and_derivative(c: &Curve, u: f64, normal: Vector3, r: f64) -> Option<(Point3, Vector3)> {
    let (p, d1, d2) = derivatives(c, u);
    let speed = d1.length();
    if !(speed.is_finite() && speed > 0.0) {
        return None;
    }
    let t = d1 * (1.0 / speed);
    // dT/du = (C'' − (C''·T) T) / |C'|.
    let dt = (d2 - t * d2.dot(t)) * (1.0 / speed);
    Some((p + normal.cross(t) * r, d1 + normal.cross(dt) * r))
}

/// How big the fillets are: one radius, or one distance from each corner to the arc's ends.
#[derive(Clone, Copy)]
enum FilletSize {
    Radius(f64),
    Distance(f64),
}

/// Solves for the fillet of the given size between the end of `a` and the start of `b`.
fn corner_fillet(
    a: &Curve,
    b: &Curve,
    size: FilletSize,
    tolerance: f64,
) -> std::result::Result<CornerFillet, String> {
    let (da, db) = (a.domain(), b.domain());
    let corner = a.end_point();
    let (Some(ta), Some(tb)) = (a.tangent_at(da.t1), b.tangent_at(db.t0)) else {
        return Err("the curve has no tangent there".into());
    };
    let cross = ta.cross(tb);
    let Some(normal) = cross.try_normalize() else {
        return Err("the curve turns straight back on itself there".into());
    };
    let phi = ta.dot(tb).clamp(-1.0, 1.0).acos();
    let r = match size {
        FilletSize::Radius(r) => r,
        FilletSize::Distance(d) => d / (phi / 2.0).tan(),
    };
    let setback = r * (phi / 2.0).tan();
    if !setback.is_finite() || !r.is_finite() {
        return Err("the curve turns straight back on itself there".into());
    }
    // Start where straight pieces would have the tangent points.
    let speed_a = a.derivatives_at(da.t1, 1)[1].length();
    let speed_b = b.derivatives_at(db.t0, 1)[1].length();
    if !(speed_a > 0.0 && speed_b > 0.0) {
        return Err("the curve has no tangent there".into());
    }
    let mut s = (da.t1 - setback / speed_a).clamp(da.t0, da.t1);
    let mut t = (db.t0 + setback / speed_b).clamp(db.t0, db.t1);
    let scale = 1.0 + r + corner.to_vector().length();
    for _ in 0..MAX_STEPS {
        let (Some((ca, ja)), Some((cb, jb))) = (
            centre_and_derivative(a, s, normal, r),
            centre_and_derivative(b, t, normal, r),
        ) else {
            return Err("the curve has no tangent there".into());
        };
        // F(s, t) = ca(s) − cb(t); J = [ja, −jb]. Solve the normal equations JᵀJ δ = −JᵀF.
        let f = ca - cb;
        let jb = -jb;
        let (m11, m12, m22) = (ja.dot(ja), ja.dot(jb), jb.dot(jb));
        let (g1, g2) = (ja.dot(f), jb.dot(f));
        let det = m11 * m22 - m12 * m12;
        if !(det.is_finite() && det.abs() > 1e-300) {
            break;
        }
        let ds = -(m22 * g1 - m12 * g2) / det;
        let dt = -(m11 * g2 - m12 * g1) / det;
        if !ds.is_finite() || !dt.is_finite() {
            break;
        }
        let (s1, t1) = ((s + ds).clamp(da.t0, da.t1), (t + dt).clamp(db.t0, db.t1));
        let moved = (s1 - s).abs() + (t1 - t).abs();
        s = s1;
        t = t1;
        if moved <= 1e-15 * (1.0 + s.abs() + t.abs()) {
            break;
        }
    }
    let residual = match (
        centre_and_derivative(a, s, normal, r),
        centre_and_derivative(b, t, normal, r),
    ) {
        (Some((ca, _)), Some((cb, _))) => ca.distance(cb),
        _ => f64::INFINITY,
    };
    if residual > tolerance.max(1e-12 * scale) {
        let at_far_end = s <= da.t0 || t >= db.t1;
        return Err(if at_far_end {
            "the radius is too large for the segments beside it".into()
        } else {
            "no arc of that radius touches the curve on both sides".into()
        });
    }
    if s >= da.t1 || t <= db.t0 {
        return Err("no arc of that radius touches the curve on both sides".into());
    }
    let start = a.point_at(s);
    let Some(tangent) = a.tangent_at(s) else {
        return Err("the curve has no tangent there".into());
    };
    let arc = Arc::from_start_tangent_end(start, tangent, b.point_at(t))
        .map_err(|e| format!("the fillet arc cannot be made: {e}"))?;
    Ok(CornerFillet { s, t, arc })
}

impl Curve {
    /// The curve with every corner (kink) rounded by a tangent arc of radius `radius`; see the
    /// module documentation. Corners where the arc does not fit stay sharp and are listed in
    /// [`CurveFillet::sharp`]. A radius of zero, or a curve without corners, gives the curve
    /// unchanged. `tolerance` is how far apart the arc's centre may be from the two pieces'
    /// offsets (and the pieces' ends from the arc's) for a fillet to count as found.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] for a negative or non-finite radius or tolerance, or an invalid
    /// curve; the errors of cutting and joining the pieces.
    pub fn fillet_corners(&self, radius: f64, tolerance: f64) -> Result<CurveFillet> {
        if !radius.is_finite() || radius < 0.0 {
            return Err(Error::InvalidInput(format!(
                "fillet radius {radius} is not a non-negative number"
            )));
        }
        self.fillet_with(FilletSize::Radius(radius), tolerance)
    }

    /// As [`Curve::fillet_corners`], with at each corner the arc whose ends lie `distance` from
    /// the corner (exactly along straight pieces), so of radius `distance / tan(φ/2)` for a
    /// turn of `φ`.
    ///
    /// # Errors
    /// As [`Curve::fillet_corners`], for a negative or non-finite distance.
    pub fn fillet_corners_by_distance(&self, distance: f64, tolerance: f64) -> Result<CurveFillet> {
        if !distance.is_finite() || distance < 0.0 {
            return Err(Error::InvalidInput(format!(
                "fillet distance {distance} is not a non-negative number"
            )));
        }
        self.fillet_with(FilletSize::Distance(distance), tolerance)
    }

    /// The fillets of every corner, of the given size.
    fn fillet_with(&self, size: FilletSize, tolerance: f64) -> Result<CurveFillet> {
        let (FilletSize::Radius(radius) | FilletSize::Distance(radius)) = size;
        if !tolerance.is_finite() || tolerance <= 0.0 {
            return Err(Error::InvalidInput(format!(
                "fillet tolerance {tolerance} is not a positive distance"
            )));
        }
        if !self.is_valid() {
            return Err(Error::InvalidInput("the curve is not valid".into()));
        }
        let unchanged = || CurveFillet {
            curve: self.clone(),
            sharp: Vec::new(),
        };
        let d = self.domain();
        let kinks = self.kinks(KINK_ANGLE_TOLERANCE)?;
        let closed = self.is_closed();
        let seam_kink = closed
            && match (self.tangent_from_left(d.t1)?, self.tangent_at(d.t0)) {
                (Some(end), Some(start)) => {
                    end.angle_to(start).is_ok_and(|a| a > KINK_ANGLE_TOLERANCE)
                }
                _ => true,
            };
        if radius == 0.0 || (kinks.is_empty() && !seam_kink) {
            return Ok(unchanged());
        }
        let mut bounds = Vec::with_capacity(kinks.len() + 2);
        bounds.push(d.t0);
        bounds.extend_from_slice(&kinks);
        bounds.push(d.t1);
        let pieces: Vec<Curve> = bounds
            .windows(2)
            .map(|w| self.trim(Interval::new(w[0], w[1])))
            .collect::<Result<_>>()?;
        let n = pieces.len();
        // Corner k lies between piece k − 1 and piece k; corner 0 is the seam.
        let corners: Vec<usize> = if seam_kink {
            (0..n).collect()
        } else {
            (1..n).collect()
        };
        // The part of each piece still free: fillets cut its start up and its end back.
        let mut free: Vec<Interval> = pieces.iter().map(Curve::domain).collect();
        let mut arcs: Vec<Option<Arc>> = vec![None; n];
        let mut sharp = Vec::new();
        for k in corners {
            let before = (k + n - 1) % n;
            let (a, b) = (&pieces[before], &pieces[k]);
            let point = b.start_point();
            let fillet = corner_fillet(a, b, size, tolerance).and_then(|f| {
                let slack = 1e-12 * (1.0 + f.s.abs().max(f.t.abs()));
                if f.s < free[before].t0 - slack || f.t > free[k].t1 + slack {
                    Err("the radius is too large for the segments beside it".into())
                } else {
                    Ok(f)
                }
            });
            match fillet {
                Ok(f) => {
                    free[before].t1 = f.s.max(free[before].t0);
                    free[k].t0 = f.t.min(free[k].t1);
                    arcs[k] = Some(f.arc);
                }
                Err(reason) => sharp.push(SharpCorner {
                    index: k,
                    point,
                    reason,
                }),
            }
        }
        if arcs.iter().all(Option::is_none) {
            return Ok(CurveFillet {
                curve: self.clone(),
                sharp,
            });
        }
        let mut parts: Vec<Curve> = Vec::with_capacity(2 * n);
        for (k, piece) in pieces.iter().enumerate() {
            if k > 0
                && let Some(arc) = arcs[k]
            {
                parts.push(arc.into());
            }
            let iv = free[k];
            let dk = piece.domain();
            if iv.t1 - iv.t0 > 1e-12 * (1.0 + dk.t0.abs().max(dk.t1.abs())) {
                let part = if iv == dk {
                    piece.clone()
                } else {
                    piece.trim(iv)?
                };
                if part.length() > tolerance * 1e-3 {
                    parts.push(part);
                }
            }
        }
        if let Some(arc) = arcs[0] {
            parts.push(arc.into());
        }
        let mut joined = Curve::join(&parts, tolerance, true)?;
        if joined.len() != 1 {
            return Err(Error::InvalidInput(format!(
                "the filleted pieces did not join into one curve ({} curves)",
                joined.len()
            )));
        }
        Ok(CurveFillet {
            curve: joined.remove(0),
            sharp,
        })
    }
}

#[cfg(test)]
mod tests {
    use std::f64::consts::{FRAC_PI_2, PI};

    use proptest::prelude::*;

    use super::*;
    use crate::Polyline;

    fn p(x: f64, y: f64) -> Point3 {
        Point3::new(x, y, 0.0)
    }

    fn polyline(points: &[(f64, f64)]) -> Curve {
        Polyline::new(points.iter().map(|&(x, y)| p(x, y)).collect())
            .unwrap()
            .into()
    }

    #[test]
    fn square_corners_become_quarter_circles() {
        let square = polyline(&[(0.0, 0.0), (4.0, 0.0), (4.0, 4.0), (0.0, 4.0), (0.0, 0.0)]);
        let f = square.fillet_corners(1.0, 1e-9).unwrap();
        assert!(f.sharp.is_empty(), "{:?}", f.sharp);
        // Four sides of 2 and four quarter circles of radius 1.
        assert!((f.curve.length() - (8.0 + 2.0 * PI)).abs() < 1e-9);
        assert!(f.curve.is_closed());
        assert!(f.curve.kinks(KINK_ANGLE_TOLERANCE).unwrap().is_empty());
        // The corner (0, 0) is √2 − 1 from the arc about (1, 1).
        let cp = f.curve.closest_point(p(0.0, 0.0)).unwrap();
        assert!((cp.point.distance(p(0.0, 0.0)) - (2.0f64.sqrt() - 1.0)).abs() < 1e-9);
    }

    #[test]
    fn open_polyline_keeps_its_ends() {
        let c = polyline(&[(0.0, 0.0), (2.0, 0.0), (2.0, 2.0)]);
        let f = c.fillet_corners(0.5, 1e-9).unwrap();
        assert!(f.sharp.is_empty());
        assert_eq!(f.curve.start_point(), p(0.0, 0.0));
        assert!(f.curve.end_point().distance(p(2.0, 2.0)) < 1e-12);
        assert!((f.curve.length() - (3.0 + 0.25 * PI)).abs() < 1e-9);
    }

    #[test]
    fn too_large_a_radius_leaves_the_corner_sharp() {
        let c = polyline(&[(0.0, 0.0), (1.0, 0.0), (1.0, 5.0), (6.0, 5.0)]);
        let f = c.fillet_corners(2.0, 1e-9).unwrap();
        // Corner 1 needs 2 of the first segment, which has 1; corner 2 fits.
        assert_eq!(f.sharp.len(), 1);
        assert_eq!(f.sharp[0].index, 1);
        assert_eq!(f.sharp[0].point, p(1.0, 0.0));
        assert!(f.sharp[0].reason.contains("too large"), "{:?}", f.sharp);
        assert!((f.curve.length() - (1.0 + 3.0 + 3.0 + PI)).abs() < 1e-9);
    }

    #[test]
    fn neighbouring_fillets_share_a_segment() {
        // The middle segment has length 2: two fillets that each need 1 just fit, two that need
        // more do not both fit, and the first corner wins.
        let c = polyline(&[(0.0, 0.0), (5.0, 0.0), (5.0, 2.0), (0.0, 2.0)]);
        let f = c.fillet_corners(1.0, 1e-9).unwrap();
        assert!(f.sharp.is_empty(), "{:?}", f.sharp);
        assert!((f.curve.length() - (8.0 + PI)).abs() < 1e-9);
        let f = c.fillet_corners(1.5, 1e-9).unwrap();
        assert_eq!(f.sharp.iter().map(|s| s.index).collect::<Vec<_>>(), [2]);
    }

    #[test]
    fn zero_radius_and_smooth_curves_are_unchanged() {
        let c = polyline(&[(0.0, 0.0), (2.0, 0.0), (2.0, 2.0)]);
        assert_eq!(c.fillet_corners(0.0, 1e-9).unwrap().curve, c);
        let arc: Curve = Arc::new(
            crate::Circle::new(crate::Plane::WORLD_XY, 1.0).unwrap(),
            Interval::new(0.0, FRAC_PI_2),
        )
        .unwrap()
        .into();
        assert_eq!(arc.fillet_corners(0.3, 1e-9).unwrap().curve, arc);
        assert!(c.fillet_corners(-1.0, 1e-9).is_err());
        assert!(c.fillet_corners(f64::NAN, 1e-9).is_err());
    }

    #[test]
    fn fillets_by_distance_start_that_far_from_the_corners() {
        // A right angle and a 135° turn: set-backs of 1 on every straight side.
        let c = polyline(&[(0.0, 0.0), (4.0, 0.0), (4.0, 4.0), (0.0, 0.0)]);
        let f = c.fillet_corners_by_distance(1.0, 1e-9).unwrap();
        assert!(f.sharp.is_empty(), "{:?}", f.sharp);
        assert!(f.curve.kinks(KINK_ANGLE_TOLERANCE).unwrap().is_empty());
        // Straight parts: 4 − 1 − 1, 4 − 1 − 1, √32 − 1 − 1; arcs r φ with r = 1 / tan(φ/2).
        let arcs: f64 = [FRAC_PI_2, 0.75 * PI, 0.75 * PI]
            .iter()
            .map(|phi| phi / (phi / 2.0).tan())
            .sum();
        let expected = 2.0 + 2.0 + (32.0f64.sqrt() - 2.0) + arcs;
        assert!(
            (f.curve.length() - expected).abs() < 1e-9,
            "{}",
            f.curve.length()
        );
        assert!(c.fillet_corners_by_distance(-1.0, 1e-9).is_err());
        let f = c.fillet_corners_by_distance(3.0, 1e-9).unwrap();
        assert!(!f.sharp.is_empty());
    }

    #[test]
    fn cusp_is_reported() {
        let c = polyline(&[(0.0, 0.0), (2.0, 0.0), (1.0, 0.0)]);
        let f = c.fillet_corners(0.1, 1e-9).unwrap();
        assert_eq!(f.sharp.len(), 1);
        assert!(f.sharp[0].reason.contains("back"), "{:?}", f.sharp);
    }

    #[test]
    fn curved_pieces_get_tangent_arcs() {
        // A quarter circle of radius 4 about the origin from (4, 0) to (0, 4), then a line
        // straight down from (0, 4) to (0, 0): the fillet's centre is 1 from both.
        let quarter = Arc::new(
            crate::Circle::new(crate::Plane::WORLD_XY, 4.0).unwrap(),
            Interval::new(0.0, FRAC_PI_2),
        )
        .unwrap();
        let pieces: Vec<Curve> = vec![
            quarter.into(),
            crate::Line::new(p(0.0, 4.0), p(0.0, 0.0)).into(),
        ];
        let joined = Curve::join(&pieces, 1e-9, true).unwrap().remove(0);
        let f = joined.fillet_corners(1.0, 1e-9).unwrap();
        assert!(f.sharp.is_empty(), "{:?}", f.sharp);
        assert!(f.curve.kinks(KINK_ANGLE_TOLERANCE).unwrap().is_empty());
        // The centre is at x = −1 (1 from the line, inside the turn) and 3 from the origin
        // (1 inside the circle): (−1, √8).
        let centre = p(-1.0, 8.0f64.sqrt());
        let on_line = f.curve.closest_point(centre).unwrap();
        assert!(
            (on_line.point.distance(centre) - 1.0).abs() < 1e-7,
            "{on_line:?}"
        );
    }

    proptest! {
        /// Filleting a polyline whose segments are long enough for every corner removes every
        /// kink and shortens it by 2 r tan(φ/2) − r φ at each corner of turning angle φ.
        #[test]
        fn polyline_fillets_shorten_by_the_formula(
            turns in prop::collection::vec(0.2f64..2.6, 1..6),
            lengths in prop::collection::vec(5.0f64..20.0, 7),
            radius in 0.05f64..1.0,
        ) {
            // Long enough: each segment holds the trims r·tan(φ/2) of the corners at its ends
            // (turns near 2.6 with a radius near 1 trim 3.4 each, more than a 5-long segment).
            let trim = |i: usize| turns.get(i).map_or(0.0, |phi| radius * (phi / 2.0).tan());
            for (i, length) in lengths.iter().enumerate().take(turns.len() + 1) {
                let before = if i == 0 { 0.0 } else { trim(i - 1) };
                prop_assume!(before + trim(i) < *length);
            }
            let mut points = vec![p(0.0, 0.0)];
            let mut heading = 0.0f64;
            let mut at = p(0.0, 0.0);
            for (i, turn) in turns.iter().enumerate() {
                at += Vector3::new(heading.cos(), heading.sin(), 0.0) * lengths[i];
                points.push(at);
                heading += if i % 2 == 0 { *turn } else { -*turn };
            }
            at += Vector3::new(heading.cos(), heading.sin(), 0.0) * lengths[turns.len()];
            points.push(at);
            let c: Curve = Polyline::new(points).unwrap().into();
            let f = c.fillet_corners(radius, 1e-9).unwrap();
            prop_assert!(f.sharp.is_empty(), "{:?}", f.sharp);
            prop_assert!(f.curve.kinks(KINK_ANGLE_TOLERANCE).unwrap().is_empty());
            let saved: f64 = turns
                .iter()
                .map(|phi| 2.0 * radius * (phi / 2.0).tan() - radius * phi)
                .sum();
            prop_assert!((c.length() - f.curve.length() - saved).abs() < 1e-7);
        }
    }
}

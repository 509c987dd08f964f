//! Where a curve meets itself (Rhino's `Intersection.CurveSelf`): the points where it crosses or
//! touches itself, each with its two parameters, and the stretches where it runs back over
//! itself.
//!
//! The curve's NURBS form is cut into pieces that cannot meet themselves: each span is halved
//! until it runs one way (some direction has a positive component along all differences of its
//! control points, so the piece's projection on that direction is strictly monotone, see
//! [`Piece::is_monotone`]). Every pair of pieces is then searched as two curves are
//! (`curve_curve.rs`), with Newton's method confined to the two pieces so that it cannot slide
//! to the trivial solution `s = t`. Neighbouring pieces share an end (and on a closed curve the
//! last piece meets the first): the point there, found with both parameters at the shared end,
//! is not an intersection and is dropped.

use crate::intersect::curve_curve::{
    CurveCurveIntersections, Raw, Side, check_tolerance, finish, nurbs_form, search_segments,
};
use crate::intersect::pair_newton::PairPoint;
use crate::intersect::piece::{Piece, boxes_meet, diagonal};
use crate::{Curve, Result};

/// How many times a span may be halved to make its pieces run one way (a cusp, where the
/// derivative vanishes, never does; its pieces are searched as they are).
const MAX_PIECE_DEPTH: usize = 12;

impl Curve {
    /// Where the curve meets itself: points (with `t_a < t_b`, both the curve's own parameters)
    /// and overlaps where it runs back over itself, within `tolerance` (see the module
    /// documentation). A closed curve's seam is not an intersection.
    ///
    /// # Errors
    /// As [`Curve::intersect_curve`].
    ///
    /// # Examples
    /// ```
    /// use locus_kernel::{Curve, NurbsCurve, Point3};
    /// // A cubic with a loop.
    /// let c: Curve = NurbsCurve::new_non_rational(
    ///     3,
    ///     vec![
    ///         Point3::new(0.0, 0.0, 0.0),
    ///         Point3::new(3.0, 2.0, 0.0),
    ///         Point3::new(-1.0, 2.0, 0.0),
    ///         Point3::new(2.0, 0.0, 0.0),
    ///     ],
    ///     vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0],
    /// )
    /// .unwrap()
    /// .into();
    /// let x = c.self_intersections(1e-9).unwrap();
    /// assert_eq!(x.points.len(), 1);
    /// let hit = x.points[0];
    /// assert!(hit.t_a < hit.t_b && hit.point_a.distance(hit.point_b) < 1e-12);
    /// ```
    pub fn self_intersections(&self, tolerance: f64) -> Result<CurveCurveIntersections> {
        check_tolerance(tolerance)?;
        let nurbs = nurbs_form(self, tolerance)?;
        let mut pieces = Vec::new();
        for span in Piece::all(&nurbs) {
            monotone_pieces(span, 0, tolerance, &mut pieces);
        }
        let closed = nurbs.is_closed();
        let n = pieces.len();
        let boxes: Vec<_> = pieces.iter().map(Piece::aabb).collect();
        let mut raw = Raw::default();
        for i in 0..n {
            for j in i + 1..n {
                if !boxes_meet(&boxes[i], &boxes[j], tolerance) {
                    continue;
                }
                let (a, b) = (&pieces[i], &pieces[j]);
                // The shared end of neighbours, as (parameter on a, parameter on b).
                let joint = if j == i + 1 && a.b == b.a {
                    Some((a.b, b.a))
                } else if closed && i == 0 && j == n - 1 {
                    Some((a.a, b.b))
                } else {
                    None
                };
                let mut found = Raw::default();
                search_segments(a, b, tolerance, &mut found);
                if let Some((sj, tj)) = joint {
                    found
                        .points
                        .retain(|p| !at_joint(p, a, sj, b, tj, tolerance));
                    found.overlaps.retain(|o| {
                        let len = a.point_at(o.a[0]).distance(a.point_at(o.a[1]));
                        len > tolerance
                    });
                }
                raw.points.extend(found.points);
                raw.overlaps.extend(found.overlaps);
            }
        }
        let side = Side::of(&nurbs);
        let mut out = finish(&raw, side.clone(), side, true, tolerance);
        for hit in &mut out.points {
            if hit.t_b < hit.t_a {
                std::mem::swap(&mut hit.t_a, &mut hit.t_b);
                std::mem::swap(&mut hit.point_a, &mut hit.point_b);
            }
        }
        out.points
            .sort_by(|x, y| x.t_a.total_cmp(&y.t_a).then(x.t_b.total_cmp(&y.t_b)));
        if matches!(self, Self::Circle { .. } | Self::Arc { .. }) {
            // A circle or arc never meets itself; its NURBS form has no other points either.
            out.points.clear();
        }
        Ok(out)
    }
}

/// Appends the pieces of `piece` that run one way, in order.
/// Halves `piece` until its pieces run one way. A piece that fits within `tolerance` (a
/// zero-length span, whose control points coincide) is kept whole: halving never makes it
/// monotone, and its 2^12 pieces would be searched pair by pair.
fn monotone_pieces(piece: Piece, depth: usize, tolerance: f64, out: &mut Vec<Piece>) {
    if depth >= MAX_PIECE_DEPTH || piece.is_monotone() || diagonal(&piece.aabb()) <= tolerance {
        out.push(piece);
        return;
    }
    let (l, r) = piece.halve();
    monotone_pieces(l, depth + 1, tolerance, out);
    monotone_pieces(r, depth + 1, tolerance, out);
}

/// Whether a point found on two neighbouring pieces is their shared end: both parameters lie
/// within the tolerance (measured along the curve, at its speed there) of the joint.
fn at_joint(p: &PairPoint, a: &Piece, sj: f64, b: &Piece, tj: f64, tolerance: f64) -> bool {
    let speed_a = a.derivatives(sj)[1].length();
    let speed_b = b.derivatives(tj)[1].length();
    (p.s - sj).abs() * speed_a <= 4.0 * tolerance && (p.t - tj).abs() * speed_b <= 4.0 * tolerance
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Circle, NurbsCurve, Plane, Point3, Polyline};

    fn p(x: f64, y: f64) -> Point3 {
        Point3::new(x, y, 0.0)
    }

    #[test]
    fn a_zero_length_segment_is_one_piece_not_thousands() {
        // Halving a span whose control points coincide never makes it run one way: it used to
        // become 4096 pieces and 8 million pair searches (12 s). Kept whole, it is quick.
        let c: Curve = Polyline::new(vec![p(0.0, 0.0), p(0.0, 0.0), p(1.0, 0.0)])
            .unwrap()
            .into();
        let nurbs = nurbs_form(&c, 1e-9).unwrap();
        let mut pieces = Vec::new();
        for span in Piece::all(&nurbs) {
            monotone_pieces(span, 0, 1e-9, &mut pieces);
        }
        assert!(pieces.len() <= 3, "{}", pieces.len());
        assert!(c.self_intersections(1e-9).is_ok());
    }

    #[test]
    fn a_figure_eight_polyline_crosses_itself_once() {
        let c: Curve = Polyline::new(vec![p(0.0, 0.0), p(2.0, 2.0), p(2.0, 0.0), p(0.0, 2.0)])
            .unwrap()
            .into();
        let x = c.self_intersections(1e-9).unwrap();
        assert_eq!(x.points.len(), 1, "{x:?}");
        let h = x.points[0];
        assert!(
            (h.t_a - 0.5).abs() < 1e-15 && (h.t_b - 2.5).abs() < 1e-15,
            "{h:?}"
        );
        assert!(h.point_a.distance(p(1.0, 1.0)) < 1e-15);
    }

    #[test]
    fn simple_and_closed_curves_do_not_meet_themselves() {
        let square: Curve = Polyline::new(vec![
            p(0.0, 0.0),
            p(1.0, 0.0),
            p(1.0, 1.0),
            p(0.0, 1.0),
            p(0.0, 0.0),
        ])
        .unwrap()
        .into();
        assert!(square.self_intersections(1e-9).unwrap().points.is_empty());
        let circle: Curve = Circle::new(Plane::WORLD_XY, 2.0).unwrap().into();
        assert!(circle.self_intersections(1e-9).unwrap().points.is_empty());
        let periodic: Curve = NurbsCurve::create(
            &[p(0.0, 0.0), p(3.0, 0.0), p(3.0, 2.0), p(0.0, 2.0)],
            3,
            true,
        )
        .unwrap()
        .into();
        let x = periodic.self_intersections(1e-9).unwrap();
        assert!(x.points.is_empty() && x.overlaps.is_empty(), "{x:?}");
    }

    #[test]
    fn a_polyline_running_back_overlaps_itself() {
        let c: Curve = Polyline::new(vec![p(0.0, 0.0), p(2.0, 0.0), p(1.0, 0.0)])
            .unwrap()
            .into();
        let x = c.self_intersections(1e-9).unwrap();
        assert_eq!(x.overlaps.len(), 1, "{x:?}");
        let o = x.overlaps[0];
        assert_eq!((o.a.t0, o.a.t1), (0.5, 1.0));
        assert_eq!((o.b.t0, o.b.t1), (2.0, 1.0));
    }
}

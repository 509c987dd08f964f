//! Where a curve meets a plane (Rhino's `Intersection.CurvePlane`) or an infinite line
//! (`Intersection.CurveLine`): points, with their curve parameters, and overlaps, the parameter
//! intervals where the curve lies in the plane (or on the line).
//!
//! The curve's NURBS form is searched span by span. On each span the signed distance from the
//! plane is a rational function in Bernstein form, the distances of the Bézier control points
//! weighted by their weights; `bernstein::roots` isolates its roots and the places where it
//! comes within the tolerance without crossing (tangencies and touching kinks). A span whose
//! control points all lie within the tolerance of the plane lies in it (a polynomial is either
//! zero on the whole span or on finitely many points of it), and is an overlap. Each root is
//! polished by Newton's method on the curve itself; events closer than the tolerance to each
//! other are reported once, points at the ends of an overlap belong to the overlap, and on a
//! closed curve a point at the seam is reported once, at the domain's start.
//!
//! A line is two planes through it, at right angles: the curve meets the line where it meets
//! one plane at a point within the tolerance of the other; the plane in which the curve lies
//! less (with fewer overlaps) leads.

use super::bernstein;
use crate::curve::nurbs::basis::MAX_ORDER;
use crate::{Curve, Error, Interval, Line, NurbsCurve, Plane, Point3, Result};

/// One point where a curve meets a plane, a line or another curve.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CurveHit {
    /// The curve parameter.
    pub t: f64,
    /// The point, `C(t)`.
    pub point: Point3,
    /// Whether the curve touches the other object there without crossing it (a tangency, a
    /// kink touching it, or a near miss within the tolerance).
    pub tangential: bool,
}

/// What a curve has in common with a plane or a line.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct CurveIntersections {
    /// The points, in increasing order of the parameter.
    pub points: Vec<CurveHit>,
    /// The parameter intervals where the curve lies in the plane (on the line), in increasing
    /// order; their end points are not listed in `points`.
    pub overlaps: Vec<Interval>,
}

impl Curve {
    /// Where the curve meets `plane`: points within `tolerance` of it and intervals lying in it
    /// (see the module documentation). Parameters are the curve's own (a circle's angle mapped
    /// to its domain, as for every other query).
    ///
    /// # Errors
    /// [`Error::NotFinite`] for a curve, plane or tolerance that is not finite (or a tolerance
    /// that is not positive), [`Error::InvalidInput`] for a curve without a valid NURBS form.
    pub fn intersect_plane(&self, plane: &Plane, tolerance: f64) -> Result<CurveIntersections> {
        check_tolerance(tolerance)?;
        if !plane.is_valid() {
            return Err(Error::NotFinite { what: "plane" });
        }
        let nurbs = self.nurbs_form()?;
        let mut out = nurbs_plane(&nurbs, plane, tolerance);
        finish(&nurbs, &mut out, tolerance);
        self.to_own_parameters(&mut out);
        Ok(out)
    }

    /// Where the curve meets the infinite `line`: points within `tolerance` of it and intervals
    /// lying on it.
    ///
    /// # Errors
    /// As [`Curve::intersect_plane`], and [`Error::ZeroLength`] for a line of no length.
    pub fn intersect_line(&self, line: &Line, tolerance: f64) -> Result<CurveIntersections> {
        check_tolerance(tolerance)?;
        if !line.is_finite() {
            return Err(Error::NotFinite { what: "line" });
        }
        let direction = line
            .unit_direction()
            .ok_or(Error::ZeroLength { what: "line" })?;
        let nurbs = self.nurbs_form()?;
        let first = crate::perpendicular_to(direction).normalize_or_zero();
        let second = direction.cross(first);
        let planes = [
            Plane::from_normal(line.from, first)?,
            Plane::from_normal(line.from, second)?,
        ];
        let found = planes.map(|p| nurbs_plane(&nurbs, &p, tolerance));
        let overlap_length =
            |r: &CurveIntersections| -> f64 { r.overlaps.iter().map(|o| o.t1 - o.t0).sum() };
        let lead = usize::from(overlap_length(&found[1]) < overlap_length(&found[0]));
        let other = 1 - lead;
        let near_other = |p: Point3| planes[other].signed_distance_to(p).abs() <= tolerance;
        let mut out = CurveIntersections::default();
        out.points.extend(
            found[lead]
                .points
                .iter()
                .filter(|h| near_other(h.point))
                .copied(),
        );
        // Inside the leading plane's overlaps the curve lies in that plane: it meets the line
        // where it meets the other plane there.
        for o in &found[lead].overlaps {
            out.points.extend(
                found[other]
                    .points
                    .iter()
                    .filter(|h| h.t >= o.t0 && h.t <= o.t1)
                    .copied(),
            );
            for p in &found[other].overlaps {
                let (t0, t1) = (o.t0.max(p.t0), o.t1.min(p.t1));
                if t0 < t1 {
                    out.overlaps.push(Interval::new(t0, t1));
                }
            }
        }
        out.points.sort_by(|a, b| a.t.total_cmp(&b.t));
        finish(&nurbs, &mut out, tolerance);
        self.to_own_parameters(&mut out);
        Ok(out)
    }

    /// The NURBS form that the searches run on, checked.
    fn nurbs_form(&self) -> Result<NurbsCurve> {
        let nurbs = self.to_nurbs();
        if !nurbs.is_valid() {
            return Err(Error::InvalidInput(
                "the curve has no valid NURBS form".into(),
            ));
        }
        Ok(nurbs)
    }

    /// Maps parameters of the NURBS form to the curve's own: they are equal for lines,
    /// polylines and NURBS curves, and at the knots; a circle's or arc's angle is found from
    /// the point.
    fn to_own_parameters(&self, out: &mut CurveIntersections) {
        if matches!(self, Self::Circle { .. } | Self::Arc { .. }) {
            for hit in &mut out.points {
                if let Ok(cp) = self.closest_point(hit.point) {
                    hit.t = cp.t;
                }
            }
            out.points.sort_by(|a, b| a.t.total_cmp(&b.t));
        }
    }
}

fn check_tolerance(tolerance: f64) -> Result<()> {
    if tolerance.is_finite() && tolerance > 0.0 {
        Ok(())
    } else {
        Err(Error::NotFinite { what: "tolerance" })
    }
}

/// The raw events of a NURBS curve and a plane, span by span: roots polished, overlaps per
/// span; not yet merged (see [`finish`]).
pub(crate) fn nurbs_plane(curve: &NurbsCurve, plane: &Plane, tolerance: f64) -> CurveIntersections {
    let normal = plane.z_axis;
    let distance = |p: Point3| (p - plane.origin).dot(normal);
    let mut out = CurveIntersections::default();
    for span in curve.span_indices() {
        let piece = curve.bezier_piece(span);
        let h = piece.homogeneous();
        let len = h.len();
        let mut numerator = [0.0; MAX_ORDER];
        let mut weight = [0.0; MAX_ORDER];
        let mut inside = true;
        for (j, q) in h.iter().enumerate() {
            let d = distance(Point3::new(q[0] / q[3], q[1] / q[3], q[2] / q[3]));
            inside &= d.abs() <= tolerance;
            numerator[j] = d * q[3];
            weight[j] = q[3];
        }
        let (a, b) = (piece.a, piece.b);
        if inside {
            out.overlaps.push(Interval::new(a, b));
            continue;
        }
        for root in bernstein::roots(&numerator[..len], &weight[..len], tolerance) {
            let t = if root.s >= 1.0 {
                b
            } else {
                a + (b - a) * root.s
            };
            let f = |t: f64| -> [f64; 3] {
                let d = curve.derivatives_at(t, 2);
                [
                    distance(Point3::from_vector(d[0])),
                    d[1].dot(normal),
                    d[2].dot(normal),
                ]
            };
            let t = polish(t, a, b, root.touching, f);
            let point = curve.point_at(t);
            if distance(point).abs() <= tolerance {
                // A root at the end of a span may be a crossing or a kink touching the plane:
                // only the spans on both sides can tell.
                let at_end = root.s <= 0.0 || root.s >= 1.0;
                let tangential = if at_end {
                    touches_at(curve, t, &distance)
                } else {
                    root.touching
                };
                out.points.push(CurveHit {
                    t,
                    point,
                    tangential,
                });
            }
        }
    }
    out
}

/// Whether the curve touches the plane at `t` (a root at a knot or an end) without crossing it:
/// the distance has the same sign just before and just after `t` (a relative step of 1e-7 of
/// the domain); at an end of an open curve, whether the curve leaves the plane along it (its
/// tangent is parallel to the plane to within 1e-9).
fn touches_at(curve: &NurbsCurve, t: f64, distance: &impl Fn(Point3) -> f64) -> bool {
    let domain = curve.domain();
    let h = 1e-7 * domain.length();
    let (before, after) = (t - h, t + h);
    if before >= domain.t0 && after <= domain.t1 {
        let (d0, d1) = (
            distance(curve.point_at(before)),
            distance(curve.point_at(after)),
        );
        return d0 != 0.0 && d1 != 0.0 && d0.signum() == d1.signum();
    }
    let d = curve.derivatives_at(t, 1);
    let along = distance(Point3::from_vector(d[1])) - distance(Point3::ORIGIN);
    along.abs() <= 1e-9 * d[1].length()
}

/// A few safeguarded Newton steps on the distance (for a crossing) or on its derivative (for a
/// touching point, where the distance is extremal), kept inside `[a, b]` and taken only while
/// they do not make the distance larger.
fn polish(mut t: f64, a: f64, b: f64, touching: bool, f: impl Fn(f64) -> [f64; 3]) -> f64 {
    let mut current = f(t);
    for _ in 0..4 {
        let (g, dg) = if touching {
            (current[1], current[2])
        } else {
            (current[0], current[1])
        };
        if g == 0.0 || dg == 0.0 || !dg.is_finite() {
            break;
        }
        let next = (t - g / dg).clamp(a, b);
        let value = f(next);
        if value[0].is_nan() || value[0].abs() > current[0].abs() || next == t {
            break;
        }
        t = next;
        current = value;
    }
    t
}

/// Merges what the spans found: adjacent overlaps join, points inside or at the ends of an
/// overlap go, points within the tolerance of each other are reported once (the first; it is
/// tangential if either was), and on a closed curve a point at the end that is also at the start
/// is dropped.
pub(crate) fn finish(curve: &NurbsCurve, out: &mut CurveIntersections, tolerance: f64) {
    out.overlaps.sort_by(|a, b| a.t0.total_cmp(&b.t0));
    let mut overlaps: Vec<Interval> = Vec::with_capacity(out.overlaps.len());
    for o in out.overlaps.drain(..) {
        match overlaps.last_mut() {
            Some(last) if o.t0 <= last.t1 => last.t1 = last.t1.max(o.t1),
            _ => overlaps.push(o),
        }
    }
    let domain = curve.domain();
    let in_overlap = |hit: &CurveHit| {
        overlaps.iter().any(|o| {
            (hit.t >= o.t0 && hit.t <= o.t1)
                || hit.point.distance(curve.point_at(o.t0)) <= tolerance
                || hit.point.distance(curve.point_at(o.t1)) <= tolerance
        })
    };
    out.points.sort_by(|a, b| a.t.total_cmp(&b.t));
    let mut points: Vec<CurveHit> = Vec::with_capacity(out.points.len());
    for hit in out.points.drain(..) {
        if in_overlap(&hit) {
            continue;
        }
        match points.last_mut() {
            Some(last) if last.point.distance(hit.point) <= tolerance => {
                last.tangential |= hit.tangential;
            }
            _ => points.push(hit),
        }
    }
    if curve.is_closed()
        && points.len() > 1
        && points[points.len() - 1]
            .point
            .distance(points[0].point)
            .le(&tolerance)
    {
        points.pop();
    }
    // A single point at the very end of a closed curve is its seam: report it at the start.
    if curve.is_closed()
        && let Some(last) = points.last_mut()
        && last.t == domain.t1
    {
        last.t = domain.t0;
        points.rotate_right(1);
    }
    out.points = points;
    out.overlaps = overlaps;
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Arc, Circle, Polyline, Vector3};

    fn p(x: f64, y: f64, z: f64) -> Point3 {
        Point3::new(x, y, z)
    }

    fn xy_at(z: f64) -> Plane {
        Plane::from_normal(p(0.0, 0.0, z), Vector3::new(0.0, 0.0, 1.0)).unwrap()
    }

    #[test]
    fn a_circle_standing_on_a_plane_crosses_it_twice() {
        let circle = Circle::new(
            Plane::from_normal(p(0.0, 0.0, 0.0), Vector3::new(0.0, 1.0, 0.0)).unwrap(),
            2.0,
        )
        .unwrap();
        let c: Curve = circle.into();
        let r = c.intersect_plane(&xy_at(1.0), 1e-9).unwrap();
        assert_eq!(r.points.len(), 2, "{r:?}");
        for hit in &r.points {
            assert!((hit.point.z - 1.0).abs() < 1e-12);
            assert!(c.point_at(hit.t).distance(hit.point) < 1e-12);
            assert!(!hit.tangential);
        }
        let touch = c.intersect_plane(&xy_at(2.0), 1e-9).unwrap();
        assert_eq!(touch.points.len(), 1, "{touch:?}");
        assert!(touch.points[0].tangential);
        assert!(touch.points[0].point.distance(p(0.0, 0.0, 2.0)) < 1e-6);
        assert!(
            c.intersect_plane(&xy_at(2.001), 1e-9)
                .unwrap()
                .points
                .is_empty()
        );
        let flat = c
            .intersect_plane(
                &Plane::from_normal(p(0.0, 0.0, 0.0), Vector3::new(0.0, 1.0, 0.0)).unwrap(),
                1e-9,
            )
            .unwrap();
        assert!(flat.points.is_empty());
        assert_eq!(flat.overlaps, vec![c.domain()]);
    }

    #[test]
    fn a_polyline_with_a_segment_in_the_plane_overlaps_it() {
        let c: Curve = Polyline::new(vec![
            p(0.0, 0.0, -1.0),
            p(1.0, 0.0, 0.0),
            p(2.0, 0.0, 0.0),
            p(3.0, 0.0, 1.0),
            p(4.0, 0.0, -1.0),
        ])
        .unwrap()
        .into();
        let r = c.intersect_plane(&xy_at(0.0), 1e-9).unwrap();
        assert_eq!(r.overlaps, vec![Interval::new(1.0, 2.0)]);
        assert_eq!(r.points.len(), 1, "{r:?}");
        assert!((r.points[0].t - 3.5).abs() < 1e-15);
    }

    #[test]
    fn an_arc_reports_its_angle_parameters() {
        let circle = Circle::new(xy_at(0.0), 1.0).unwrap();
        let c: Curve = Arc::new(circle, Interval::new(0.0, 3.0)).unwrap().into();
        let plane = Plane::from_normal(p(0.5, 0.0, 0.0), Vector3::new(1.0, 0.0, 0.0)).unwrap();
        let r = c.intersect_plane(&plane, 1e-9).unwrap();
        assert_eq!(r.points.len(), 1, "{r:?}");
        assert!((r.points[0].t - std::f64::consts::FRAC_PI_3).abs() < 1e-12);
    }

    #[test]
    fn a_line_through_a_circle_meets_it_twice_and_a_tangent_once() {
        let c: Curve = Circle::new(xy_at(0.0), 1.0).unwrap().into();
        let through = Line::new(p(-2.0, 0.5, 0.0), p(2.0, 0.5, 0.0));
        let r = c.intersect_line(&through, 1e-9).unwrap();
        assert_eq!(r.points.len(), 2, "{r:?}");
        for hit in &r.points {
            assert!((hit.point.y - 0.5).abs() < 1e-12 && hit.point.z.abs() < 1e-12);
        }
        let tangent = Line::new(p(-2.0, 1.0, 0.0), p(2.0, 1.0, 0.0));
        let r = c.intersect_line(&tangent, 1e-9).unwrap();
        assert_eq!(r.points.len(), 1, "{r:?}");
        let above = Line::new(p(0.0, 0.0, 1.0), p(1.0, 0.0, 1.0));
        assert!(c.intersect_line(&above, 1e-9).unwrap().points.is_empty());
        let skew = Line::new(p(0.0, 1.0, -1.0), p(0.0, 1.0, 1.0));
        let r = c.intersect_line(&skew, 1e-9).unwrap();
        assert_eq!(r.points.len(), 1, "{r:?}");
        assert!(r.points[0].point.distance(p(0.0, 1.0, 0.0)) < 1e-12);
    }

    #[test]
    fn a_line_along_a_polyline_segment_overlaps_it() {
        let c: Curve = Polyline::new(vec![p(0.0, 0.0, 0.0), p(1.0, 0.0, 0.0), p(1.0, 1.0, 0.0)])
            .unwrap()
            .into();
        let r = c
            .intersect_line(&Line::new(p(5.0, 0.0, 0.0), p(6.0, 0.0, 0.0)), 1e-9)
            .unwrap();
        assert_eq!(r.overlaps, vec![Interval::new(0.0, 1.0)]);
        assert!(r.points.is_empty(), "{r:?}");
        let r = c
            .intersect_line(&Line::new(p(0.0, 0.5, 0.0), p(2.0, 0.5, 0.0)), 1e-9)
            .unwrap();
        assert_eq!(r.points.len(), 1, "{r:?}");
        assert!((r.points[0].t - 1.5).abs() < 1e-15);
    }

    #[test]
    fn bad_input_is_an_error() {
        let c: Curve = Circle::new(xy_at(0.0), 1.0).unwrap().into();
        assert!(c.intersect_plane(&xy_at(0.0), f64::NAN).is_err());
        assert!(c.intersect_plane(&xy_at(0.0), 0.0).is_err());
        let point = Line::new(p(0.0, 0.0, 0.0), p(0.0, 0.0, 0.0));
        assert!(c.intersect_line(&point, 1e-9).is_err());
    }
}

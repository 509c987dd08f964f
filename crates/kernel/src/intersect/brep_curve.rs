//! Where a curve meets a B-rep (Rhino's `Intersection.CurveBrep`, Grasshopper's Brep | Curve
//! and Brep | Line): points, each with its curve parameter, face and surface parameters, and
//! overlaps, the curve intervals that lie in a face.
//!
//! Every face is searched as a surface (`curve_surface.rs`), keeping only what lies on the face:
//! candidates inside its trim loops or on its edges (`face_region.rs`), overlaps extended up to
//! where the curve meets the face's edges. A point on an edge or at a vertex is found on every
//! face that meets there and is reported once, on the first of them; points inside or at the
//! ends of an overlap belong to it, and overlaps on neighbouring faces join.

use crate::intersect::curve_curve::{check_tolerance, nurbs_form};
use crate::intersect::curve_surface::{
    CurveSurfaceHit, CurveSurfaceOverlap, Target, check_surface, clipped_line, events, raw_points,
    to_own_parameters,
};
use crate::intersect::face_region::FaceRegion;
use crate::{Brep, Curve, Interval, Line, NurbsCurve, NurbsSurface, Point3, Result};

/// One point where a curve meets a B-rep.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BrepCurveHit {
    /// The index of the face it was found on (the first, where it lies on several).
    pub face: usize,
    /// The curve parameter, the face's surface parameters, the point and whether the curve
    /// touches the face there.
    pub hit: CurveSurfaceHit,
}

/// A stretch of the curve that lies on the B-rep.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BrepCurveOverlap {
    /// The index of the first face it lies on.
    pub face: usize,
    /// The curve interval, increasing.
    pub t: Interval,
}

/// What a curve has in common with a B-rep.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct BrepCurveIntersections {
    /// The points, in increasing order of the curve parameter.
    pub points: Vec<BrepCurveHit>,
    /// The overlaps, in increasing order; their end points are not listed in `points`.
    pub overlaps: Vec<BrepCurveOverlap>,
}

/// A B-rep face, inside its trims.
#[derive(Debug)]
struct FaceTarget<'a> {
    brep: &'a Brep,
    face: usize,
    region: FaceRegion,
    tolerance: f64,
}

impl Target for FaceTarget<'_> {
    fn contains(&self, p: Point3, uv: Option<(f64, f64)>) -> bool {
        self.region
            .contains(self.brep, self.surface(), p, uv, self.tolerance)
    }

    fn boundary(&self) -> Vec<NurbsCurve> {
        self.region
            .edges()
            .iter()
            .map(|&e| self.brep.edges()[e].curve.clone())
            .collect()
    }

    fn surface(&self) -> &NurbsSurface {
        &self.brep.faces()[self.face].surface
    }
}

impl Brep {
    /// Where `curve` meets the B-rep: points within `tolerance` of a face and the stretches of
    /// the curve lying on faces (see the module documentation). Curve parameters are the
    /// curve's own.
    ///
    /// # Errors
    /// As [`NurbsSurface::intersect_curve`], for the curve and every face's surface.
    ///
    /// # Examples
    /// ```
    /// use locus_kernel::{Brep, Curve, Interval, Line, OrientedBox, Plane, Point3};
    /// let b = Brep::from_box(&OrientedBox::new(
    ///     Plane::WORLD_XY,
    ///     Interval::new(0.0, 1.0),
    ///     Interval::new(0.0, 1.0),
    ///     Interval::new(0.0, 1.0),
    /// ))
    /// .unwrap();
    /// let line: Curve = Line::new(Point3::new(0.5, 0.5, -1.0), Point3::new(0.5, 0.5, 2.0)).into();
    /// let x = b.intersect_curve(&line, 1e-9).unwrap();
    /// assert_eq!(x.points.len(), 2);
    /// assert!((x.points[1].hit.point.z - 1.0).abs() < 1e-12);
    /// ```
    pub fn intersect_curve(&self, curve: &Curve, tolerance: f64) -> Result<BrepCurveIntersections> {
        check_tolerance(tolerance)?;
        for face in self.faces() {
            check_surface(&face.surface)?;
        }
        let nurbs = nurbs_form(curve, tolerance)?;
        let mut points: Vec<BrepCurveHit> = Vec::new();
        let mut overlaps: Vec<BrepCurveOverlap> = Vec::new();
        for f in 0..self.faces().len() {
            let target = FaceTarget {
                brep: self,
                face: f,
                region: FaceRegion::new(self, f),
                tolerance,
            };
            let raw = raw_points(&nurbs, target.surface(), tolerance);
            if raw.is_empty() {
                continue;
            }
            let (found, spans) = events(&nurbs, &target, raw, tolerance);
            points.extend(found.into_iter().map(|(p, tangential)| BrepCurveHit {
                face: f,
                hit: CurveSurfaceHit {
                    t: p.t,
                    u: p.u,
                    v: p.v,
                    point: p.on_curve,
                    tangential,
                },
            }));
            overlaps.extend(spans.into_iter().map(|[t0, t1]| BrepCurveOverlap {
                face: f,
                t: Interval::new(t0, t1),
            }));
        }
        let mut out = merge(&nurbs, points, overlaps, tolerance);
        let mut hits: Vec<CurveSurfaceHit> = out.points.iter().map(|p| p.hit).collect();
        let mut spans: Vec<CurveSurfaceOverlap> = out
            .overlaps
            .iter()
            .map(|o| CurveSurfaceOverlap { t: o.t })
            .collect();
        to_own_parameters(curve, &mut hits, &mut spans);
        for (p, h) in out.points.iter_mut().zip(hits) {
            p.hit = h;
        }
        for (o, s) in out.overlaps.iter_mut().zip(spans) {
            o.t = s.t;
        }
        Ok(out)
    }

    /// Where the infinite `line` meets the B-rep; parameters are the line's
    /// (`line.point_at(t)`, 0 at `from` and 1 at `to`).
    ///
    /// # Errors
    /// As [`Brep::intersect_curve`], and [`crate::Error::ZeroLength`] for a line of no length.
    pub fn intersect_line(&self, line: &Line, tolerance: f64) -> Result<BrepCurveIntersections> {
        check_tolerance(tolerance)?;
        match clipped_line(line, &self.bounding_box(), tolerance)? {
            Some(segment) => self.intersect_curve(&segment, tolerance),
            None => Ok(BrepCurveIntersections::default()),
        }
    }
}

/// Joins the faces' findings: overlaps that touch become one, points in or at the ends of an
/// overlap are dropped, and points within the tolerance of each other are reported once.
fn merge(
    curve: &NurbsCurve,
    mut points: Vec<BrepCurveHit>,
    mut overlaps: Vec<BrepCurveOverlap>,
    tolerance: f64,
) -> BrepCurveIntersections {
    overlaps.sort_by(|a, b| a.t.t0.total_cmp(&b.t.t0));
    let mut joined: Vec<BrepCurveOverlap> = Vec::with_capacity(overlaps.len());
    for o in overlaps {
        if let Some(last) = joined.last_mut()
            && (o.t.t0 <= last.t.t1
                || curve.point_at(o.t.t0).distance(curve.point_at(last.t.t1)) <= tolerance)
        {
            last.t = Interval::new(last.t.t0, last.t.t1.max(o.t.t1));
            continue;
        }
        joined.push(o);
    }
    let ends: Vec<[Point3; 2]> = joined
        .iter()
        .map(|o| [curve.point_at(o.t.t0), curve.point_at(o.t.t1)])
        .collect();
    points.retain(|p| {
        !joined.iter().zip(&ends).any(|(o, e)| {
            (p.hit.t >= o.t.t0 && p.hit.t <= o.t.t1)
                || e.iter().any(|q| q.distance(p.hit.point) <= tolerance)
        })
    });
    // Points in face order; the first face's copy of a point wins.
    let mut kept: Vec<BrepCurveHit> = Vec::with_capacity(points.len());
    for p in points {
        if !kept
            .iter()
            .any(|k| k.hit.point.distance(p.hit.point) <= tolerance)
        {
            kept.push(p);
        }
    }
    kept.sort_by(|a, b| a.hit.t.total_cmp(&b.hit.t));
    BrepCurveIntersections {
        points: kept,
        overlaps: joined,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Cylinder, OrientedBox, Plane};

    fn unit_box() -> Brep {
        Brep::from_box(&OrientedBox::new(
            Plane::WORLD_XY,
            Interval::new(0.0, 1.0),
            Interval::new(0.0, 1.0),
            Interval::new(0.0, 1.0),
        ))
        .unwrap()
    }

    #[test]
    fn a_line_through_an_edge_and_a_vertex_is_reported_once() {
        let b = unit_box();
        let diagonal = Line::new(Point3::new(-1.0, -1.0, -1.0), Point3::new(2.0, 2.0, 2.0));
        let x = b.intersect_line(&diagonal, 1e-9).unwrap();
        assert_eq!(x.points.len(), 2, "{x:?}");
        assert!((x.points[0].hit.t - 1.0 / 3.0).abs() < 1e-12);
        assert!((x.points[1].hit.t - 2.0 / 3.0).abs() < 1e-12);
        let on_face: Curve =
            Line::new(Point3::new(-1.0, 0.5, 1.0), Point3::new(2.0, 0.5, 1.0)).into();
        let x = b.intersect_curve(&on_face, 1e-9).unwrap();
        assert!(x.points.is_empty(), "{x:?}");
        assert_eq!(x.overlaps.len(), 1, "{x:?}");
        assert!(
            (x.overlaps[0].t.t0 - 1.0).abs() < 1e-12 && (x.overlaps[0].t.t1 - 2.0).abs() < 1e-12
        );
    }

    #[test]
    fn a_capped_cylinder_keeps_its_cap_discs_only() {
        let c = Cylinder::new(Plane::WORLD_XY, 1.0, 2.0).unwrap();
        let b = Brep::from_cylinder(&c, true).unwrap();
        // Through the cap's square but outside its disc: misses.
        let miss = Line::new(Point3::new(0.95, 0.95, -1.0), Point3::new(0.95, 0.95, 3.0));
        assert!(b.intersect_line(&miss, 1e-9).unwrap().points.is_empty());
        let hit = Line::new(Point3::new(0.5, 0.1, -1.0), Point3::new(0.5, 0.1, 3.0));
        let x = b.intersect_line(&hit, 1e-9).unwrap();
        assert_eq!(x.points.len(), 2, "{x:?}");
    }
}

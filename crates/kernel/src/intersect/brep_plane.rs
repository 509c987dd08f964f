//! Sections of B-reps (Rhino's `Intersection.BrepPlane`, Grasshopper's Brep | Plane) and series
//! of parallel sections (Grasshopper's Contour).
//!
//! A section is found face by face and then joined across the edges:
//!
//! - every edge is intersected with the plane once (`curve_plane.rs`): its crossing points,
//!   and the stretches that lie in the plane, which are parts of the section themselves;
//! - a **planar face** (control points within 1/1000 of the tolerance of a plane) meets the
//!   plane along a straight line: the crossing points of the face's edges lie on it, and
//!   between two consecutive ones the line is on the face where its midpoint is (its trim
//!   loops, `face_region.rs`). The pieces are exact lines. A planar face lying in the plane
//!   contributes its edges;
//! - any other face is sectioned over its whole surface (`surface_plane.rs`) and the traced
//!   arcs are fitted (`hermite_fit.rs`); on a trimmed face the arcs are cut where they leave
//!   the trim loops, at the crossing point of the face's edges nearest to where they leave;
//! - pieces found twice (an edge shared by two faces lying in the plane, a seam) are kept
//!   once, and the pieces are joined end to end within the tolerance ([`Curve::join`]); a chain
//!   that comes back to its start is closed;
//! - points where the shape only touches the plane (a vertex, a tangent face) are reported
//!   separately, unless they lie on a section curve.

use crate::intersect::curve_curve::check_tolerance;
use crate::intersect::curve_plane::{finish, nurbs_plane};
use crate::intersect::face_region::{FaceRegion, planar_surface};
use crate::intersect::hermite_fit::{TracePoint, fit};
use crate::intersect::linear::plane_plane;
use crate::intersect::surface_plane::{SectionPoint, surface_plane};
use crate::{
    Brep, Curve, CurveIntersections, Error, Interval, Line, Plane, Point3, Result, Vector3,
};

/// A face is planar when its control points lie within this fraction of the tolerance of a
/// plane.
const PLANAR: f64 = 1e-3;

/// At most this many parallel sections in one contour.
pub const MAX_CONTOUR_PLANES: usize = 100_000;

/// The section of a B-rep by a plane.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct BrepSection {
    /// The section curves, joined across the B-rep's edges; closed where the section closes.
    pub curves: Vec<Curve>,
    /// Points where the B-rep touches the plane without a curve through them.
    pub points: Vec<Point3>,
}

/// One plane of a contour and its section.
#[derive(Clone, Debug, PartialEq)]
pub struct ContourSection {
    /// The plane's index `k`: its origin is the contour's start point plus `k` times the
    /// distance along the direction.
    pub index: i64,
    /// The plane.
    pub plane: Plane,
    /// Its section.
    pub section: BrepSection,
}

impl Brep {
    /// The section of the B-rep by `plane` within `tolerance` (see the module documentation).
    ///
    /// # Errors
    /// [`Error::NotFinite`] for a plane that is not valid or a tolerance that is not finite and
    /// positive; the errors of fitting and joining curves (for non-finite geometry).
    ///
    /// # Examples
    /// ```
    /// use locus_kernel::{Brep, Interval, OrientedBox, Plane, Point3, Vector3};
    /// let b = Brep::from_box(&OrientedBox::new(
    ///     Plane::WORLD_XY,
    ///     Interval::new(0.0, 2.0),
    ///     Interval::new(0.0, 3.0),
    ///     Interval::new(0.0, 4.0),
    /// ))
    /// .unwrap();
    /// let cut = Plane::from_normal(Point3::new(0.0, 0.0, 1.0), Vector3::Z).unwrap();
    /// let s = b.intersect_plane(&cut, 1e-9).unwrap();
    /// assert_eq!(s.curves.len(), 1);
    /// assert!(s.curves[0].is_closed());
    /// assert!((s.curves[0].length() - 10.0).abs() < 1e-12);
    /// ```
    pub fn intersect_plane(&self, plane: &Plane, tolerance: f64) -> Result<BrepSection> {
        check_tolerance(tolerance)?;
        if !plane.is_valid() {
            return Err(Error::NotFinite { what: "plane" });
        }
        let edge_hits: Vec<CurveIntersections> = self
            .edges()
            .iter()
            .map(|e| {
                let mut hits = nurbs_plane(&e.curve, plane, tolerance);
                finish(&e.curve, &mut hits, tolerance);
                hits
            })
            .collect();
        let mut pieces: Vec<Curve> = Vec::new();
        let mut lone: Vec<Point3> = Vec::new();
        for f in 0..self.faces().len() {
            let region = FaceRegion::new(self, f);
            let surface = &self.faces()[f].surface;
            match planar_surface(surface, PLANAR * tolerance) {
                Some(face_plane) => self.planar_face_section(
                    f,
                    &region,
                    &face_plane,
                    plane,
                    &edge_hits,
                    tolerance,
                    &mut pieces,
                    &mut lone,
                )?,
                None => self.curved_face_section(
                    f,
                    &region,
                    plane,
                    &edge_hits,
                    tolerance,
                    &mut pieces,
                    &mut lone,
                )?,
            }
        }
        let pieces = without_duplicates(pieces, tolerance);
        let curves = Curve::join(&pieces, tolerance, false)?;
        let mut points: Vec<Point3> = Vec::new();
        for p in lone {
            let on_curve = curves
                .iter()
                .any(|c| c.closest_point(p).is_ok_and(|cp| cp.distance <= tolerance));
            if !on_curve && !points.iter().any(|q| q.distance(p) <= tolerance) {
                points.push(p);
            }
        }
        Ok(BrepSection { curves, points })
    }

    /// Parallel sections (Grasshopper's Contour): the planes through `point + k·distance·n̂`
    /// normal to `n̂ = direction / |direction|`, for every integer `k` whose plane meets the
    /// B-rep's bounding box, in increasing `k`.
    ///
    /// # Errors
    /// [`Error::NotFinite`] for non-finite input, [`Error::ZeroLength`] for a zero direction,
    /// [`Error::InvalidInput`] for a distance that is not positive or that would need more than
    /// [`MAX_CONTOUR_PLANES`] planes; the errors of [`Brep::intersect_plane`].
    pub fn contour(
        &self,
        point: Point3,
        direction: Vector3,
        distance: f64,
        tolerance: f64,
    ) -> Result<Vec<ContourSection>> {
        let planes = contour_planes(self.bounding_box(), point, direction, distance)?;
        planes
            .into_iter()
            .map(|(index, plane)| {
                Ok(ContourSection {
                    index,
                    plane,
                    section: self.intersect_plane(&plane, tolerance)?,
                })
            })
            .collect()
    }

    /// The section of a planar face: segments of the line where its plane meets `plane`.
    #[allow(
        clippy::too_many_arguments,
        reason = "one face's share of one section's state"
    )]
    fn planar_face_section(
        &self,
        f: usize,
        region: &FaceRegion,
        face_plane: &Plane,
        plane: &Plane,
        edge_hits: &[CurveIntersections],
        tolerance: f64,
        pieces: &mut Vec<Curve>,
        lone: &mut Vec<Point3>,
    ) -> Result<()> {
        let parallel = face_plane.z_axis.cross(plane.z_axis).length() <= 1e-12;
        if parallel {
            if plane.signed_distance_to(face_plane.origin).abs() <= tolerance {
                for &e in region.edges() {
                    pieces.push(Curve::Nurbs(self.edges()[e].curve.clone()));
                }
            }
            return Ok(());
        }
        let Some(line) = plane_plane(face_plane, plane) else {
            return Ok(());
        };
        let Some(direction) = line.unit_direction() else {
            return Ok(());
        };
        let origin = line.from;
        // The crossings of the face's edges, by their place along the line.
        let mut crossings: Vec<(f64, Point3)> = Vec::new();
        for &e in region.edges() {
            let curve = &self.edges()[e].curve;
            for hit in &edge_hits[e].points {
                crossings.push(((hit.point - origin).dot(direction), hit.point));
            }
            for o in &edge_hits[e].overlaps {
                pieces.push(Curve::Nurbs(curve.trim(Interval::new(o.t0, o.t1))?));
                for t in [o.t0, o.t1] {
                    let p = curve.point_at(t);
                    crossings.push(((p - origin).dot(direction), p));
                }
            }
        }
        crossings.sort_by(|a, b| a.0.total_cmp(&b.0));
        crossings.dedup_by(|b, a| a.1.distance(b.1) <= tolerance);
        let surface = &self.faces()[f].surface;
        let mut used = vec![false; crossings.len()];
        for k in 0..crossings.len().saturating_sub(1) {
            let (a, b) = (crossings[k].1, crossings[k + 1].1);
            if a.distance(b) <= tolerance {
                continue;
            }
            let mid = a.midpoint(b);
            if region.contains(self, surface, mid, None, tolerance) {
                pieces.push(Line::new(a, b).into());
                used[k] = true;
                used[k + 1] = true;
            }
        }
        lone.extend(
            crossings
                .iter()
                .zip(&used)
                .filter(|(_, used)| !**used)
                .map(|(c, _)| c.1),
        );
        Ok(())
    }

    /// The section of a curved face: the traced arcs of its surface, cut to its trim loops.
    #[allow(
        clippy::too_many_arguments,
        reason = "one face's share of one section's state"
    )]
    fn curved_face_section(
        &self,
        f: usize,
        region: &FaceRegion,
        plane: &Plane,
        edge_hits: &[CurveIntersections],
        tolerance: f64,
        pieces: &mut Vec<Curve>,
        lone: &mut Vec<Point3>,
    ) -> Result<()> {
        let surface = &self.faces()[f].surface;
        let section = surface_plane(surface, plane, tolerance);
        for (uv, p) in &section.touching {
            if region.contains(self, surface, *p, Some(*uv), tolerance) {
                lone.push(*p);
            }
        }
        if region.is_untrimmed() {
            for arc in &section.arcs {
                let points: Vec<TracePoint> = arc.iter().map(|p| p.trace).collect();
                pieces.push(Curve::Nurbs(fit(&points)?));
            }
            return Ok(());
        }
        let crossings: Vec<Point3> = region
            .edges()
            .iter()
            .flat_map(|&e| edge_hits[e].points.iter().map(|h| h.point))
            .collect();
        for arc in &section.arcs {
            for run in inside_runs(arc, region, self, surface, &crossings, tolerance) {
                if run.len() >= 2 {
                    pieces.push(Curve::Nurbs(fit(&run)?));
                }
            }
        }
        Ok(())
    }
}

/// The parts of a traced arc that lie on a trimmed face, each cut where it leaves the face at
/// the nearest crossing of the face's edges with the plane.
fn inside_runs(
    arc: &[SectionPoint],
    region: &FaceRegion,
    brep: &Brep,
    surface: &crate::NurbsSurface,
    crossings: &[Point3],
    tolerance: f64,
) -> Vec<Vec<TracePoint>> {
    let inside: Vec<bool> = arc
        .iter()
        .map(|p| region.contains(brep, surface, p.trace.point, Some(p.uv), tolerance))
        .collect();
    let trace: Vec<TracePoint> = arc.iter().map(|p| p.trace).collect();
    runs_inside(&trace, &inside, crossings, tolerance)
}

/// The runs of consecutive traced points flagged inside, each extended to the crossing
/// (of the boundary with the other shape) nearest the segment where it enters or leaves.
pub(crate) fn runs_inside(
    arc: &[TracePoint],
    inside: &[bool],
    crossings: &[Point3],
    tolerance: f64,
) -> Vec<Vec<TracePoint>> {
    // The crossing nearest the segment between two traced points, as a traced point with the
    // segment's direction.
    let cut = |a: &TracePoint, b: &TracePoint| -> Option<TracePoint> {
        let (p, q) = (a.point, b.point);
        let d = q - p;
        let best = crossings
            .iter()
            .min_by(|x, y| segment_distance(**x, p, d).total_cmp(&segment_distance(**y, p, d)))?;
        Some(TracePoint {
            point: *best,
            tangent: d.normalize_or_zero(),
        })
    };
    let mut runs: Vec<Vec<TracePoint>> = Vec::new();
    let mut current: Vec<TracePoint> = Vec::new();
    for k in 0..arc.len() {
        if inside[k] {
            if current.is_empty() && k > 0 && !inside[k - 1] {
                current.extend(cut(&arc[k - 1], &arc[k]));
            }
            current.push(arc[k]);
        } else if !current.is_empty() {
            current.extend(cut(&arc[k - 1], &arc[k]));
            runs.push(std::mem::take(&mut current));
        }
    }
    if !current.is_empty() {
        runs.push(current);
    }
    for run in &mut runs {
        run.dedup_by(|b, a| a.point.distance(b.point) <= tolerance * 1e-3);
    }
    runs
}

/// The distance from `x` to the segment from `p` along `d`.
pub(crate) fn segment_distance(x: Point3, p: Point3, d: Vector3) -> f64 {
    let l = d.length_squared();
    let t = if l > 0.0 {
        ((x - p).dot(d) / l).clamp(0.0, 1.0)
    } else {
        0.0
    };
    (p + d * t).distance(x)
}

/// The pieces, each kept once: a piece whose ends match another's (in either direction) and
/// whose quarter points lie within the tolerance of it is the same piece.
pub(crate) fn without_duplicates(pieces: Vec<Curve>, tolerance: f64) -> Vec<Curve> {
    let mut kept: Vec<Curve> = Vec::with_capacity(pieces.len());
    for c in pieces {
        let (s, e) = (c.start_point(), c.end_point());
        let same = kept.iter().any(|k| {
            let (ks, ke) = (k.start_point(), k.end_point());
            let ends = (ks.distance(s) <= tolerance && ke.distance(e) <= tolerance)
                || (ks.distance(e) <= tolerance && ke.distance(s) <= tolerance);
            ends && [0.25, 0.5, 0.75].iter().all(|&f| {
                let p = c.point_at(c.domain().parameter_at(f));
                k.closest_point(p).is_ok_and(|cp| cp.distance <= tolerance)
            })
        });
        if !same {
            kept.push(c);
        }
    }
    kept
}

/// The contour planes `(k, plane)` that meet a bounding box: the planes through
/// `point + k·distance·n̂` normal to `n̂ = direction / |direction|`, in increasing `k` (see
/// [`Brep::contour`]; meshes are contoured through the same planes).
///
/// # Errors
/// As [`Brep::contour`]: non-finite input, a zero direction, a distance that is not positive
/// or that needs more than [`MAX_CONTOUR_PLANES`] planes.
pub fn contour_planes(
    bbox: crate::BoundingBox,
    point: Point3,
    direction: Vector3,
    distance: f64,
) -> Result<Vec<(i64, Plane)>> {
    if !point.is_finite() || !direction.is_finite() || !distance.is_finite() {
        return Err(Error::NotFinite {
            what: "contour point, direction or distance",
        });
    }
    let n = direction.try_normalize().ok_or(Error::ZeroLength {
        what: "contour direction",
    })?;
    if distance <= 0.0 {
        return Err(Error::InvalidInput(format!(
            "the contour distance must be positive, got {distance}"
        )));
    }
    if bbox.is_empty() {
        return Ok(Vec::new());
    }
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for c in bbox.corners() {
        let h = (c - point).dot(n);
        lo = lo.min(h);
        hi = hi.max(h);
    }
    let (first, last) = ((lo / distance).ceil(), (hi / distance).floor());
    if last < first {
        return Ok(Vec::new());
    }
    let count = last - first + 1.0;
    if count.is_nan() || count > MAX_CONTOUR_PLANES as f64 {
        return Err(Error::InvalidInput(format!(
            "a contour distance of {distance} needs {count} planes across the shape, more than \
             {MAX_CONTOUR_PLANES}"
        )));
    }
    (first as i64..=last as i64)
        .map(|k| Ok((k, Plane::from_normal(point + n * (k as f64 * distance), n)?)))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Cylinder, OrientedBox, Sphere};

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
    fn a_box_cut_through_three_corners_gives_a_triangle() {
        let b = unit_box();
        let plane =
            Plane::from_normal(Point3::new(1.0, 0.0, 0.0), Vector3::new(1.0, 1.0, 1.0)).unwrap();
        let s = b.intersect_plane(&plane, 1e-9).unwrap();
        assert_eq!(s.curves.len(), 1, "{s:?}");
        assert!(s.curves[0].is_closed());
        let length = s.curves[0].length();
        assert!((length - 3.0 * 2f64.sqrt()).abs() < 1e-12, "{length}");
        assert!(s.points.is_empty(), "{:?}", s.points);
    }

    #[test]
    fn a_plane_on_a_box_face_gives_its_boundary_and_a_corner_touch_a_point() {
        let b = unit_box();
        let top = Plane::from_normal(Point3::new(0.0, 0.0, 1.0), Vector3::Z).unwrap();
        let s = b.intersect_plane(&top, 1e-9).unwrap();
        assert_eq!(s.curves.len(), 1, "{s:?}");
        assert!(s.curves[0].is_closed());
        assert!((s.curves[0].length() - 4.0).abs() < 1e-12);
        let corner =
            Plane::from_normal(Point3::new(1.0, 1.0, 1.0), Vector3::new(1.0, 1.0, 1.0)).unwrap();
        let s = b.intersect_plane(&corner, 1e-9).unwrap();
        assert!(s.curves.is_empty(), "{s:?}");
        assert_eq!(s.points.len(), 1);
        assert!(s.points[0].distance(Point3::new(1.0, 1.0, 1.0)) < 1e-12);
    }

    #[test]
    fn a_sphere_section_is_a_closed_circle() {
        let b = Brep::from_sphere(&Sphere::new(Point3::new(1.0, 2.0, 3.0), 2.0).unwrap()).unwrap();
        let plane =
            Plane::from_normal(Point3::new(1.0, 2.0, 4.0), Vector3::new(0.2, 0.1, 1.0)).unwrap();
        let s = b.intersect_plane(&plane, 1e-9).unwrap();
        assert_eq!(s.curves.len(), 1, "{s:?}");
        assert!(s.curves[0].is_closed());
        let d = plane.signed_distance_to(Point3::new(1.0, 2.0, 3.0));
        let r = (4.0 - d * d).sqrt();
        let length = s.curves[0].length();
        assert!(
            (length / (std::f64::consts::TAU * r) - 1.0).abs() < 1e-10,
            "{length}"
        );
    }

    #[test]
    fn a_capped_cylinder_cut_along_its_axis_gives_a_rectangle() {
        let c = Cylinder::new(Plane::WORLD_XY, 1.0, 3.0).unwrap();
        let b = Brep::from_cylinder(&c, true).unwrap();
        let plane = Plane::from_normal(Point3::ORIGIN, Vector3::new(1.0, -1.0, 0.0)).unwrap();
        let s = b.intersect_plane(&plane, 1e-9).unwrap();
        assert_eq!(s.curves.len(), 1, "{s:?}");
        assert!(s.curves[0].is_closed());
        assert!((s.curves[0].length() - 10.0).abs() < 1e-10);
    }

    #[test]
    fn contour_planes_cover_the_box() {
        let b = unit_box();
        let c = b
            .contour(Point3::ORIGIN, Vector3::new(0.0, 0.0, 2.0), 0.25, 1e-9)
            .unwrap();
        assert_eq!(
            c.iter().map(|s| s.index).collect::<Vec<_>>(),
            vec![0, 1, 2, 3, 4]
        );
        for s in &c[1..4] {
            assert_eq!(s.section.curves.len(), 1);
            assert!((s.section.curves[0].length() - 4.0).abs() < 1e-12);
        }
        assert!(
            b.contour(Point3::ORIGIN, Vector3::ZERO, 0.25, 1e-9)
                .is_err()
        );
        assert!(b.contour(Point3::ORIGIN, Vector3::Z, 1e-9, 1e-9).is_err());
        assert!(b.intersect_plane(&Plane::WORLD_XY, f64::NAN).is_err());
    }
}

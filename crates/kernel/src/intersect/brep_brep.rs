//! Where two B-reps meet (Rhino's `Intersection.BrepBrep`, Grasshopper's Brep | Brep): the
//! intersection curves and the points where they only touch.
//!
//! Every pair of faces whose boxes meet is intersected over their whole surfaces
//! (`surface_surface.rs`) and the traced curves are kept where they lie on both faces: a point
//! is on a face when it lies on its border (within the tolerance of an edge) or inside its trim
//! loops (`face_region.rs`). A curve that leaves a trimmed face is cut at the nearest point
//! where an edge of either face crosses the other face's surface (`curve_surface.rs`), so that
//! the pieces end exactly on the edges and join across them. Pieces found twice (along an edge
//! shared by two faces) are kept once and the pieces are joined end to end within the
//! tolerance ([`Curve::join`]); a chain that comes back to its start is closed. Points where the
//! surfaces touch tangentially on both faces are reported unless they lie on a curve, once
//! per cluster (`touching_radius`).
//!
//! Regions where the two B-reps coincide (overlapping faces) are not traced (see
//! `surface_surface.rs`) but flagged ([`BrepIntersection::coincident`]); their faces still meet
//! the other faces along curves.

use crate::intersect::brep_plane::{runs_inside, without_duplicates};
use crate::intersect::curve_curve::check_tolerance;
use crate::intersect::curve_surface::check_surface;
use crate::intersect::face_region::FaceRegion;
use crate::intersect::hermite_fit::{TracePoint, fit};
use crate::intersect::surface_surface::{surface_surface, touching_radius};
use crate::{Brep, Curve, NurbsSurface, Point3, Result};

/// Where two B-reps meet.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct BrepIntersection {
    /// The intersection curves, joined across the B-reps' edges; closed where they go round.
    pub curves: Vec<Curve>,
    /// Points where the B-reps touch without a curve through them.
    pub points: Vec<Point3>,
    /// Whether the B-reps coincide over some region (faces lying on each other): such regions
    /// give neither curves nor points.
    pub coincident: bool,
}

/// One face of one of the two B-reps, with what the intersection needs of it.
pub(crate) struct Face<'a> {
    pub(crate) brep: &'a Brep,
    pub(crate) surface: &'a NurbsSurface,
    pub(crate) region: FaceRegion,
}

impl Face<'_> {
    pub(crate) fn contains(&self, p: Point3, uv: (f64, f64), tolerance: f64) -> bool {
        self.region
            .contains(self.brep, self.surface, p, Some(uv), tolerance)
    }

    /// The points where this face's edges cross `surface`, and the ends of the stretches that
    /// lie in it.
    pub(crate) fn edge_crossings(&self, surface: &NurbsSurface, tolerance: f64) -> Vec<Point3> {
        let mut out = Vec::new();
        for &e in self.region.edges() {
            let edge = Curve::Nurbs(self.brep.edges()[e].curve.clone());
            if let Ok(hits) = surface.intersect_curve(&edge, tolerance) {
                out.extend(hits.points.iter().map(|h| h.point));
                for o in &hits.overlaps {
                    out.push(edge.point_at(o.t.t0));
                    out.push(edge.point_at(o.t.t1));
                }
            }
        }
        out
    }
}

impl Brep {
    /// Where the B-rep meets `other` within `tolerance` (see the module documentation).
    ///
    /// # Errors
    /// [`crate::Error::NotFinite`] for a tolerance that is not finite and positive or a face
    /// that is not finite; the errors of fitting and joining curves.
    ///
    /// # Examples
    /// ```
    /// use locus_kernel::{Brep, Point3, Sphere};
    /// let a = Brep::from_sphere(&Sphere::new(Point3::new(0.0, 0.0, 0.0), 2.0).unwrap()).unwrap();
    /// let b = Brep::from_sphere(&Sphere::new(Point3::new(2.0, 0.0, 0.0), 2.0).unwrap()).unwrap();
    /// let x = a.intersect_brep(&b, 1e-9).unwrap();
    /// assert_eq!(x.curves.len(), 1);
    /// assert!(x.curves[0].is_closed());
    /// // The circle x = 1, radius √3.
    /// let length = 2.0 * std::f64::consts::PI * 3.0f64.sqrt();
    /// assert!((x.curves[0].length() - length).abs() < 1e-8);
    /// ```
    pub fn intersect_brep(&self, other: &Brep, tolerance: f64) -> Result<BrepIntersection> {
        check_tolerance(tolerance)?;
        for face in self.faces().iter().chain(other.faces()) {
            check_surface(&face.surface)?;
        }
        let (faces_a, faces_b) = (faces_of(self), faces_of(other));
        let boxes = |fs: &[Face]| -> Vec<crate::BoundingBox> {
            fs.iter().map(|f| f.surface.bounding_box()).collect()
        };
        let (boxes_a, boxes_b) = (boxes(&faces_a), boxes(&faces_b));
        let mut pieces: Vec<Curve> = Vec::new();
        let mut lone: Vec<Point3> = Vec::new();
        let mut coincident = false;
        for (fa, box_a) in faces_a.iter().zip(&boxes_a) {
            for (fb, box_b) in faces_b.iter().zip(&boxes_b) {
                if !boxes_meet(box_a, box_b, tolerance) {
                    continue;
                }
                coincident |= face_pair(fa, fb, tolerance, &mut pieces, &mut lone)?;
            }
        }
        let pieces = without_duplicates(pieces, tolerance);
        let curves = Curve::join(&pieces, tolerance, false)?;
        let size = self
            .bounding_box()
            .union(&other.bounding_box())
            .diagonal()
            .length();
        let radius = touching_radius(tolerance, size);
        let mut points: Vec<Point3> = Vec::new();
        for p in lone {
            let on_curve = curves
                .iter()
                .any(|c| c.closest_point(p).is_ok_and(|cp| cp.distance <= tolerance));
            if !on_curve && !points.iter().any(|q| q.distance(p) <= radius) {
                points.push(p);
            }
        }
        Ok(BrepIntersection {
            curves,
            points,
            coincident,
        })
    }
}

pub(crate) fn faces_of(brep: &Brep) -> Vec<Face<'_>> {
    (0..brep.faces().len())
        .map(|f| Face {
            brep,
            surface: &brep.faces()[f].surface,
            region: FaceRegion::new(brep, f),
        })
        .collect()
}

pub(crate) fn boxes_meet(a: &crate::BoundingBox, b: &crate::BoundingBox, gap: f64) -> bool {
    let (a0, a1, b0, b1) = (a.min, a.max, b.min, b.max);
    a0.x <= b1.x + gap
        && b0.x <= a1.x + gap
        && a0.y <= b1.y + gap
        && b0.y <= a1.y + gap
        && a0.z <= b1.z + gap
        && b0.z <= a1.z + gap
}

/// The share of one pair of faces: pieces of curves on both, and touching points; whether the
/// faces' surfaces coincide somewhere.
fn face_pair(
    fa: &Face,
    fb: &Face,
    tolerance: f64,
    pieces: &mut Vec<Curve>,
    lone: &mut Vec<Point3>,
) -> Result<bool> {
    let x = surface_surface(fa.surface, fb.surface, tolerance);
    let coincident = x.coincident;
    for t in &x.touching {
        let p = t.trace.point;
        if fa.contains(p, t.a, tolerance) && fb.contains(p, t.b, tolerance) {
            lone.push(p);
        }
    }
    if x.arcs.is_empty() {
        return Ok(coincident);
    }
    if fa.region.is_untrimmed() && fb.region.is_untrimmed() {
        for arc in &x.arcs {
            let points: Vec<TracePoint> = arc.iter().map(|p| p.trace).collect();
            pieces.push(Curve::Nurbs(fit(&points)?));
        }
        return Ok(coincident);
    }
    let mut crossings = fa.edge_crossings(fb.surface, tolerance);
    crossings.extend(fb.edge_crossings(fa.surface, tolerance));
    for arc in &x.arcs {
        let trace: Vec<TracePoint> = arc.iter().map(|p| p.trace).collect();
        let inside: Vec<bool> = arc
            .iter()
            .map(|p| {
                fa.contains(p.trace.point, p.a, tolerance)
                    && fb.contains(p.trace.point, p.b, tolerance)
            })
            .collect();
        for run in runs_inside(&trace, &inside, &crossings, tolerance) {
            if run.len() >= 2 {
                pieces.push(Curve::Nurbs(fit(&run)?));
            }
        }
    }
    Ok(coincident)
}

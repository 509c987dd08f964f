//! Whether a point lies inside a closed B-rep (Rhino's `Brep.IsPointInside`, Grasshopper's
//! Point In Brep), by the parity of a ray's crossings.
//!
//! A ray from the point is intersected with the B-rep ([`Brep::intersect_line`]); the point is
//! inside when the ray crosses the boundary an odd number of times. A crossing at the point
//! itself (within the tolerance) puts the point on the boundary. A ray whose count could be
//! wrong (it touches a face tangentially, runs along one, or passes within the tolerance of an
//! edge, where two faces would both report the same crossing) is thrown away and the next of a
//! fixed list of directions is tried, so the answer never depends on chance or on the thread.

use crate::intersect::face_region::FaceRegion;
use crate::{Brep, Error, Line, Point3, Result, Vector3};

/// Where a point lies with respect to a closed B-rep.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum BrepContainment {
    /// Strictly inside the enclosed volume.
    Inside,
    /// Strictly outside.
    Outside,
    /// Within the tolerance of the boundary.
    OnBoundary,
}

/// Where a point lies, with the face it lies on when it is on the boundary.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Located {
    Inside,
    Outside,
    /// On face `face` at the surface parameters `(u, v)`.
    On {
        face: usize,
        u: f64,
        v: f64,
    },
}

/// The ray directions tried in turn: unit vectors in no special position relative to axes,
/// planes or the diagonals of boxes.
const DIRECTIONS: [[f64; 3]; 8] = [
    [0.5773, 0.6118, 0.5406],
    [-0.3162, 0.8507, -0.4198],
    [0.7072, -0.2236, 0.6707],
    [-0.6402, -0.5385, 0.5477],
    [0.1304, 0.4472, -0.8849],
    [0.9113, 0.3568, -0.2054],
    [-0.2618, -0.9142, -0.3090],
    [0.4364, -0.6180, -0.6547],
];

impl Brep {
    /// Where `point` lies with respect to the volume this closed B-rep encloses, within
    /// `tolerance` of the boundary (see the module documentation).
    ///
    /// # Errors
    /// [`Error::InvalidInput`] for a B-rep that is not closed ([`Brep::is_solid`]);
    /// [`Error::NotFinite`] for a point or tolerance that is not finite; the errors of
    /// [`Brep::intersect_line`].
    ///
    /// # Examples
    /// ```
    /// use locus_kernel::{Brep, BrepContainment, Point3, Sphere};
    /// let ball = Brep::from_sphere(&Sphere::new(Point3::ORIGIN, 2.0).unwrap()).unwrap();
    /// let at = |x| ball.contains_point(Point3::new(x, 0.0, 0.0), 1e-9).unwrap();
    /// assert_eq!(at(1.0), BrepContainment::Inside);
    /// assert_eq!(at(2.0), BrepContainment::OnBoundary);
    /// assert_eq!(at(3.0), BrepContainment::Outside);
    /// ```
    pub fn contains_point(&self, point: Point3, tolerance: f64) -> Result<BrepContainment> {
        if !self.is_solid() {
            return Err(Error::InvalidInput(
                "the B-rep is not closed, so it has no inside".into(),
            ));
        }
        Ok(match self.locate(point, tolerance)? {
            Located::Inside => BrepContainment::Inside,
            Located::Outside => BrepContainment::Outside,
            Located::On { .. } => BrepContainment::OnBoundary,
        })
    }

    /// Where `point` lies, with the face under it when it is on the boundary. The B-rep is
    /// taken as closed.
    pub(crate) fn locate(&self, point: Point3, tolerance: f64) -> Result<Located> {
        if !point.is_finite() {
            return Err(Error::NotFinite { what: "point" });
        }
        let b = self.bounding_box();
        let outside_box = point.x < b.min.x - tolerance
            || point.y < b.min.y - tolerance
            || point.z < b.min.z - tolerance
            || point.x > b.max.x + tolerance
            || point.y > b.max.y + tolerance
            || point.z > b.max.z + tolerance;
        if outside_box {
            return Ok(Located::Outside);
        }
        let regions: Vec<FaceRegion> = (0..self.faces().len())
            .map(|f| FaceRegion::new(self, f))
            .collect();
        let mut fallback = Located::Outside;
        for (k, d) in DIRECTIONS.iter().enumerate() {
            let direction = Vector3::new(d[0], d[1], d[2]).normalize_or_zero();
            let line = Line::new(point, point + direction);
            let hits = self.intersect_line(&line, tolerance)?;
            if let Some(h) = hits
                .points
                .iter()
                .find(|h| h.hit.point.distance(point) <= tolerance)
            {
                return Ok(Located::On {
                    face: h.face,
                    u: h.hit.u,
                    v: h.hit.v,
                });
            }
            if let Some(o) = hits
                .overlaps
                .iter()
                .find(|o| o.t.t0 <= 0.0 && o.t.t1 >= 0.0)
            {
                let s = &self.faces()[o.face].surface;
                if let Ok(c) = s.closest_point(point) {
                    return Ok(Located::On {
                        face: o.face,
                        u: c.u,
                        v: c.v,
                    });
                }
            }
            let ahead = hits.points.iter().filter(|h| h.hit.t > 0.0);
            let crossings = ahead.clone().count();
            let parity = if crossings % 2 == 1 {
                Located::Inside
            } else {
                Located::Outside
            };
            let doubtful = !hits.overlaps.is_empty()
                || ahead.clone().any(|h| {
                    h.hit.tangential || regions[h.face].on_border(self, h.hit.point, tolerance)
                });
            if !doubtful {
                return Ok(parity);
            }
            if k == 0 {
                fallback = parity;
            }
        }
        Ok(fallback)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Interval, OrientedBox, Plane, Sphere};

    fn unit_box() -> Brep {
        let i = Interval::new(0.0, 1.0);
        Brep::from_box(&OrientedBox::new(Plane::WORLD_XY, i, i, i)).unwrap()
    }

    #[test]
    fn points_of_a_box_are_inside_outside_or_on_it() {
        let b = unit_box();
        let at = |x, y, z| b.contains_point(Point3::new(x, y, z), 1e-9).unwrap();
        assert_eq!(at(0.5, 0.5, 0.5), BrepContainment::Inside);
        assert_eq!(at(0.999, 0.001, 0.5), BrepContainment::Inside);
        assert_eq!(at(1.5, 0.5, 0.5), BrepContainment::Outside);
        assert_eq!(at(0.5, 0.5, -0.25), BrepContainment::Outside);
        assert_eq!(at(1.0, 0.5, 0.5), BrepContainment::OnBoundary);
        assert_eq!(at(1.0, 1.0, 1.0), BrepContainment::OnBoundary);
        assert_eq!(at(0.5, 0.0, 0.0), BrepContainment::OnBoundary);
    }

    #[test]
    fn a_point_level_with_a_spheres_poles_and_seam_is_classified() {
        let ball = Brep::from_sphere(&Sphere::new(Point3::ORIGIN, 1.0).unwrap()).unwrap();
        let at = |x, y, z| ball.contains_point(Point3::new(x, y, z), 1e-9).unwrap();
        assert_eq!(at(0.0, 0.0, 0.999), BrepContainment::Inside);
        assert_eq!(at(0.0, 0.0, 1.0), BrepContainment::OnBoundary);
        assert_eq!(at(0.999, 0.0, 0.0), BrepContainment::Inside);
        assert_eq!(at(0.8, 0.8, 0.0), BrepContainment::Outside);
    }

    #[test]
    fn an_open_brep_or_a_point_not_finite_is_an_error() {
        let b = unit_box();
        let face = b.extract_face(0).unwrap();
        assert!(face.contains_point(Point3::ORIGIN, 1e-9).is_err());
        assert!(
            b.contains_point(Point3::new(f64::NAN, 0.0, 0.0), 1e-9)
                .is_err()
        );
    }
}

//! Capping the planar holes of a B-rep (Rhino's `Brep.CapPlanarHoles`, Grasshopper's Cap
//! Holes): naked edges are chained end to end into closed loops, each loop that is planar
//! becomes a planar face bounded by those edge curves ([`Brep::from_planar_loops`]), and the
//! caps are joined to the B-rep.

use crate::{Brep, EdgeKind, Error, NurbsCurve, Result};

impl Brep {
    /// The B-rep with a planar face on every closed, planar loop of naked edges (within
    /// `tolerance`), joined; and the number of caps added. Loops that are not closed or not
    /// planar stay open. A B-rep without naked edges is returned unchanged.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] for a negative or NaN tolerance, or when the caps do not join
    /// the B-rep into one.
    pub fn cap_planar_holes(&self, tolerance: f64) -> Result<(Self, usize)> {
        if !tolerance.is_finite() || tolerance < 0.0 {
            return Err(Error::InvalidInput(format!(
                "tolerance must be finite and not negative, got {tolerance}"
            )));
        }
        let naked = self.edges_of_kind(EdgeKind::Naked);
        let mut used = vec![false; naked.len()];
        let mut caps = Vec::new();
        let point = |v: usize| self.vertices[v].point;
        for first in 0..naked.len() {
            if used[first] {
                continue;
            }
            used[first] = true;
            let edge = &self.edges[naked[first]];
            let start = point(edge.vertices[0]);
            let mut end = point(edge.vertices[1]);
            let mut curves: Vec<NurbsCurve> = vec![edge.curve.clone()];
            let mut closed = start.distance(end) <= tolerance;
            while !closed {
                let next = (0..naked.len()).find_map(|k| {
                    if used[k] {
                        return None;
                    }
                    let e = &self.edges[naked[k]];
                    let (a, b) = (point(e.vertices[0]), point(e.vertices[1]));
                    if a.distance(end) <= tolerance {
                        Some((k, false, b))
                    } else if b.distance(end) <= tolerance {
                        Some((k, true, a))
                    } else {
                        None
                    }
                });
                let Some((k, backwards, other)) = next else {
                    break;
                };
                used[k] = true;
                let c = &self.edges[naked[k]].curve;
                curves.push(if backwards { c.reversed() } else { c.clone() });
                end = other;
                closed = start.distance(end) <= tolerance;
            }
            if closed && let Ok(cap) = Brep::from_planar_loops(&[curves], tolerance) {
                caps.push(cap);
            }
        }
        if caps.is_empty() {
            return Ok((self.clone(), 0));
        }
        let count = caps.len();
        let mut parts = vec![self.clone()];
        parts.extend(caps);
        let mut joined = Brep::join(&parts, tolerance)?;
        if joined.len() != 1 {
            return Err(Error::InvalidInput(format!(
                "the caps did not join the brep into one ({} parts)",
                joined.len()
            )));
        }
        Ok((joined.remove(0), count))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Curve, Cylinder, Plane, Point3, Polyline, Vector3};

    #[test]
    fn an_open_cylinder_and_an_open_box_are_capped() {
        let tube =
            Brep::from_cylinder(&Cylinder::new(Plane::WORLD_XY, 1.0, 2.0).unwrap(), false).unwrap();
        let (capped, count) = tube.cap_planar_holes(1e-9).unwrap();
        assert_eq!(count, 2);
        assert!(capped.is_solid());
        assert!((capped.volume().unwrap() - 2.0 * std::f64::consts::PI).abs() < 1e-9);

        let square = Curve::from(
            Polyline::new(vec![
                Point3::ORIGIN,
                Point3::new(2.0, 0.0, 0.0),
                Point3::new(2.0, 2.0, 0.0),
                Point3::new(0.0, 2.0, 0.0),
                Point3::ORIGIN,
            ])
            .unwrap(),
        );
        // The four sides of a box without top and bottom: an open extrusion of the square.
        let sides: Vec<Brep> = crate::brep::planar::split_at_kinks(&square)
            .unwrap()
            .iter()
            .map(|c| {
                Brep::from_surface(
                    crate::NurbsSurface::extrusion(c, Vector3::new(0.0, 0.0, 3.0)).unwrap(),
                )
                .unwrap()
            })
            .collect();
        let walls = Brep::join(&sides, 1e-9).unwrap().remove(0);
        let (capped, count) = walls.cap_planar_holes(1e-9).unwrap();
        assert_eq!(count, 2);
        assert!(capped.is_solid());
        assert!((capped.volume().unwrap() - 12.0).abs() < 1e-12);
        // A closed B-rep is unchanged.
        let (again, none) = capped.cap_planar_holes(1e-9).unwrap();
        assert_eq!((none, again.faces().len()), (0, 6));
        assert!(walls.cap_planar_holes(f64::NAN).is_err());
    }
}

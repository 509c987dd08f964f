//! Extrusions as B-reps (Grasshopper's Extrude and Extrude Point).
//!
//! A curve is split at its kinks and each piece swept into one face (a polyline of four
//! segments gives four faces, as in Rhino); the faces are joined along their shared side
//! edges. A closed planar curve extruded out of its plane is capped at both ends by planar
//! faces bounded by the same pieces ([`Brep::from_planar_loops`]) and so becomes a closed
//! solid, as Grasshopper's Extrude does; extruded to a point it is capped at its base.
//! A B-rep is extruded by joining its faces, a moved copy, and the sweep of every naked edge.

use crate::brep::planar::split_at_kinks;
use crate::curve::loop_plane::loop_plane;
use crate::{Brep, Curve, EdgeKind, Error, NurbsSurface, Point3, Result, Transform, Vector3};

/// The smallest sine of the angle between an extrusion direction and a closed curve's plane
/// for the extrusion to be capped (below it the caps would be edge-on).
const CAP_MIN_SINE: f64 = 1e-9;

/// Joins the faces into one B-rep, or says why not.
fn join_one(faces: &[Brep], tolerance: f64, what: &str) -> Result<Brep> {
    let mut joined = Brep::join(faces, tolerance)?;
    if joined.len() != 1 {
        return Err(Error::InvalidInput(format!(
            "the faces of the {what} did not join into one brep ({} parts)",
            joined.len()
        )));
    }
    Ok(joined.remove(0))
}

fn check_tolerance(tolerance: f64) -> Result<()> {
    if !tolerance.is_finite() || tolerance < 0.0 {
        return Err(Error::InvalidInput(format!(
            "tolerance must be finite and not negative, got {tolerance}"
        )));
    }
    Ok(())
}

impl Brep {
    /// The curve extruded along `direction`: one face per kink-free piece, joined; a closed
    /// curve that is planar within `tolerance` and not parallel to `direction` is capped at
    /// both ends, giving a closed solid.
    ///
    /// # Errors
    /// [`Error::NotFinite`] for non-finite input, [`Error::ZeroLength`] for a zero direction,
    /// and the errors of joining.
    pub fn from_curve_extrusion(curve: &Curve, direction: Vector3, tolerance: f64) -> Result<Self> {
        check_tolerance(tolerance)?;
        let pieces = split_at_kinks(curve)?;
        let mut faces = Vec::with_capacity(pieces.len() + 2);
        for p in &pieces {
            faces.push(Brep::from_surface(NurbsSurface::extrusion(p, direction)?)?);
        }
        let closed = curve.start_point().distance(curve.end_point()) <= tolerance;
        if closed && let Ok(plane) = loop_plane(&pieces, tolerance) {
            let sine = plane.z_axis.dot(direction).abs() / direction.length();
            if sine > CAP_MIN_SINE {
                let shift = Transform::translation(direction);
                let top: Vec<_> = pieces
                    .iter()
                    .map(|p| p.transformed(&shift))
                    .collect::<Result<_>>()?;
                faces.push(Brep::from_planar_loops(&[pieces], tolerance)?);
                faces.push(Brep::from_planar_loops(&[top], tolerance)?);
            }
        }
        join_one(&faces, tolerance, "extrusion")
    }

    /// The curve extruded to the point `apex`: the lines from the curve to the apex, one face
    /// per kink-free piece, joined; a closed curve that is planar within `tolerance`, with the
    /// apex off its plane, is capped at its base, giving a closed solid.
    ///
    /// # Errors
    /// [`Error::NotFinite`] for non-finite input, and the errors of joining.
    pub fn from_point_extrusion(curve: &Curve, apex: Point3, tolerance: f64) -> Result<Self> {
        check_tolerance(tolerance)?;
        let pieces = split_at_kinks(curve)?;
        let mut faces = Vec::with_capacity(pieces.len() + 1);
        for p in &pieces {
            faces.push(Brep::from_surface(NurbsSurface::extrusion_to_point(
                p, apex,
            )?)?);
        }
        let closed = curve.start_point().distance(curve.end_point()) <= tolerance;
        if closed
            && let Ok(plane) = loop_plane(&pieces, tolerance)
            && plane.distance_to(apex) > tolerance
        {
            faces.push(Brep::from_planar_loops(&[pieces], tolerance)?);
        }
        join_one(&faces, tolerance, "extrusion")
    }

    /// The B-rep extruded along `direction`: its faces, their copies moved by `direction`,
    /// and the sweep of every naked edge, joined. An open surface gives a closed solid.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] for a B-rep without naked edges (a closed solid) or without
    /// faces; the errors of [`Brep::from_curve_extrusion`] and of joining.
    pub fn extruded(&self, direction: Vector3, tolerance: f64) -> Result<Self> {
        check_tolerance(tolerance)?;
        if !direction.is_finite() {
            return Err(Error::NotFinite {
                what: "extrusion direction",
            });
        }
        if self.faces.is_empty() {
            return Err(Error::InvalidInput("the brep has no faces".into()));
        }
        let naked = self.edges_of_kind(EdgeKind::Naked);
        if naked.is_empty() {
            return Err(Error::InvalidInput(
                "the brep is closed: it has no naked edges to extrude".into(),
            ));
        }
        let mut parts = vec![
            self.clone(),
            self.transformed(&Transform::translation(direction))?,
        ];
        for e in naked {
            let curve = &self.edges[e].curve;
            parts.push(Brep::from_surface(NurbsSurface::extrusion(
                curve, direction,
            )?)?);
        }
        join_one(&parts, tolerance, "extrusion")
    }

    /// The B-rep extruded to the point `apex`: its faces and the lines from every naked edge
    /// to the apex, joined. An open planar surface gives a closed solid (a pyramid or cone).
    ///
    /// # Errors
    /// As [`Brep::extruded`].
    pub fn extruded_to_point(&self, apex: Point3, tolerance: f64) -> Result<Self> {
        check_tolerance(tolerance)?;
        if self.faces.is_empty() {
            return Err(Error::InvalidInput("the brep has no faces".into()));
        }
        let naked = self.edges_of_kind(EdgeKind::Naked);
        if naked.is_empty() {
            return Err(Error::InvalidInput(
                "the brep is closed: it has no naked edges to extrude".into(),
            ));
        }
        let mut parts = vec![self.clone()];
        for e in naked {
            let curve = &self.edges[e].curve;
            parts.push(Brep::from_surface(NurbsSurface::extrusion_to_point(
                curve, apex,
            )?)?);
        }
        join_one(&parts, tolerance, "extrusion")
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Circle, Plane, Polyline};
    use std::f64::consts::PI;

    const TOL: f64 = 1e-9;

    fn unit_square() -> Curve {
        Curve::from(
            Polyline::new(vec![
                Point3::ORIGIN,
                Point3::new(1.0, 0.0, 0.0),
                Point3::new(1.0, 1.0, 0.0),
                Point3::new(0.0, 1.0, 0.0),
                Point3::ORIGIN,
            ])
            .unwrap(),
        )
    }

    fn rel(a: f64, b: f64) -> f64 {
        (a - b).abs() / b.abs().max(1.0)
    }

    #[test]
    fn a_square_extruded_is_a_closed_box() {
        let b =
            Brep::from_curve_extrusion(&unit_square(), Vector3::new(0.0, 0.0, 2.0), TOL).unwrap();
        assert_eq!(b.faces().len(), 6);
        assert_eq!(b.edges().len(), 12);
        assert_eq!(b.vertices().len(), 8);
        assert!(b.is_solid());
        assert!(rel(b.volume().unwrap(), 2.0) < 1e-12);
        assert!(rel(b.area().unwrap(), 10.0) < 1e-12);
        // Clockwise squares and downward directions still give positive volumes.
        let down = Brep::from_curve_extrusion(
            &unit_square().reversed(),
            Vector3::new(0.0, 0.0, -2.0),
            TOL,
        )
        .unwrap();
        assert!(rel(down.volume().unwrap(), 2.0) < 1e-12);
    }

    #[test]
    fn a_circle_extruded_is_a_capped_cylinder() {
        let c = Curve::from(Circle::new(Plane::WORLD_XY, 1.0).unwrap());
        let b = Brep::from_curve_extrusion(&c, Vector3::new(0.0, 1.0, 3.0), TOL).unwrap();
        assert!(b.is_solid());
        assert_eq!(b.faces().len(), 3);
        // An oblique cylinder: base area × height.
        assert!(rel(b.volume().unwrap(), PI * 3.0) < 1e-9);
    }

    #[test]
    fn open_curves_and_in_plane_directions_are_not_capped() {
        let line =
            Curve::from(Polyline::new(vec![Point3::ORIGIN, Point3::new(3.0, 0.0, 0.0)]).unwrap());
        let b = Brep::from_curve_extrusion(&line, Vector3::new(0.0, 0.0, 2.0), TOL).unwrap();
        assert_eq!(b.faces().len(), 1);
        assert!(rel(b.area().unwrap(), 6.0) < 1e-12);
        let flat = Brep::from_curve_extrusion(&unit_square(), Vector3::new(1.0, 0.0, 0.0), TOL);
        assert!(!flat.map(|b| b.is_solid()).unwrap_or(false));
        assert!(Brep::from_curve_extrusion(&line, Vector3::ZERO, TOL).is_err());
    }

    #[test]
    fn a_square_to_a_point_is_a_pyramid() {
        let b =
            Brep::from_point_extrusion(&unit_square(), Point3::new(0.5, 0.5, 3.0), TOL).unwrap();
        assert_eq!(b.faces().len(), 5);
        assert!(b.is_solid());
        assert!(rel(b.volume().unwrap(), 1.0) < 1e-12);
    }

    #[test]
    fn a_square_surface_extruded_is_a_box() {
        let face = Brep::from_planar_polyline(
            &[
                Point3::ORIGIN,
                Point3::new(2.0, 0.0, 0.0),
                Point3::new(2.0, 3.0, 0.0),
                Point3::new(0.0, 3.0, 0.0),
            ],
            TOL,
        )
        .unwrap();
        let b = face.extruded(Vector3::new(0.0, 0.0, 4.0), TOL).unwrap();
        assert!(b.is_solid());
        assert_eq!(b.faces().len(), 6);
        assert!(rel(b.volume().unwrap(), 24.0) < 1e-12);
        assert!(b.extruded(Vector3::new(0.0, 0.0, 1.0), TOL).is_err());
        let cone = face
            .extruded_to_point(Point3::new(1.0, 1.0, 5.0), TOL)
            .unwrap();
        assert!(cone.is_solid());
        assert!(rel(cone.volume().unwrap(), 10.0) < 1e-12);
    }
}

//! Pipes: a circle swept along a rail and capped (Grasshopper's Pipe, Rhino's
//! `Brep.CreatePipe`).
//!
//! The circle has the given radius, its centre on the rail's start, in the plane perpendicular
//! to the rail there, and is carried along the rail's perpendicular frames
//! ([`Brep::sweep`]'s machinery, `brep/sweep.rs`): one face per kink-free piece of the rail,
//! mitred at kinks (the pieces end on the plane bisecting the kink, as Rhino's pipes around
//! polylines do). Straight pieces give exact cylinders and arcs exact tori (rational); other
//! pieces are fitted within the tolerance. A closed rail gives a closed tube without caps;
//! an open rail's ends are left open, capped with planar discs, or capped with hemispheres.

use std::f64::consts::{FRAC_PI_2, TAU};

use crate::brep::Brep;
use crate::brep::sweep::{SweepMiter, sweep_faces};
use crate::{
    Arc, Circle, Curve, Error, Interval, NurbsCurve, NurbsSurface, Plane, Result, SurfaceDirection,
    Vector3,
};

/// How the ends of a pipe are closed (Grasshopper's Pipe Caps input, Rhino's `PipeCapMode`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum PipeCaps {
    /// Open ends.
    None,
    /// Planar discs.
    Flat,
    /// Hemispheres.
    Round,
}

impl Brep {
    /// The pipe of `radius` around `rail` (see the module documentation), its faces fitted and
    /// joined within `tolerance`: one closed B-rep for a closed rail or capped ends, usually
    /// one B-rep in all.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] for a radius or tolerance that is not positive and finite, an
    /// invalid rail, a rail that turns back on itself; the errors of the sweep.
    pub fn pipe(rail: &Curve, radius: f64, caps: PipeCaps, tolerance: f64) -> Result<Vec<Brep>> {
        if !(radius > 0.0 && radius.is_finite()) {
            return Err(Error::InvalidInput(format!(
                "the pipe radius must be positive, got {radius}"
            )));
        }
        if !rail.is_valid() {
            return Err(Error::InvalidInput("the rail is not a valid curve".into()));
        }
        let d = rail.domain();
        let frame = rail.perpendicular_frame_at(d.t0)?;
        let profile = Circle::new(frame, radius)?.to_nurbs();
        let swept = sweep_faces(
            rail,
            std::slice::from_ref(&profile),
            &[d.t0],
            SweepMiter::Trim,
            tolerance,
        )?;
        let mut faces = Vec::with_capacity(swept.surfaces.len() + 2);
        let closed = rail.is_closed();
        if !closed && caps != PipeCaps::None {
            let first = &swept.surfaces[0];
            let last = &swept.surfaces[swept.surfaces.len() - 1];
            let start = first.isocurve(SurfaceDirection::U, first.domain_v().t0)?;
            let end = last.isocurve(SurfaceDirection::U, last.domain_v().t1)?;
            let start_dir = -rail
                .tangent_at(d.t0)
                .ok_or(Error::Degenerate { what: "pipe rail" })?;
            let end_dir = rail
                .tangent_from_left(d.t1)?
                .ok_or(Error::Degenerate { what: "pipe rail" })?;
            for (rim, centre, outward) in [
                (start, rail.point_at(d.t0), start_dir),
                (end, rail.point_at(d.t1), end_dir),
            ] {
                faces.push(match caps {
                    PipeCaps::Flat => Brep::from_planar_loops(&[vec![rim]], tolerance)?,
                    _ => Brep::from_surface(hemisphere(&rim, centre, outward, radius)?)?,
                });
            }
        }
        for s in swept.surfaces {
            faces.push(Brep::from_surface(s)?);
        }
        Brep::join(&faces, tolerance)
    }
}

/// The hemisphere on the circle `rim` (centred at `centre`, radius `radius`) bulging along the
/// unit vector `outward`: the quarter meridian from the rim's start point to the pole revolved
/// a full turn about the axis, so that its edge is the rim and its pole a singular side.
fn hemisphere(
    rim: &NurbsCurve,
    centre: crate::Point3,
    outward: Vector3,
    radius: f64,
) -> Result<NurbsSurface> {
    let x = (rim.start_point() - centre)
        .try_normalize()
        .ok_or(Error::Degenerate { what: "pipe cap" })?;
    let plane = Plane {
        origin: centre,
        x_axis: x,
        y_axis: outward,
        z_axis: x.cross(outward),
    };
    let meridian = Arc::new(Circle::new(plane, radius)?, Interval::new(0.0, FRAC_PI_2))?;
    NurbsSurface::revolution(
        &meridian.to_nurbs(),
        centre,
        outward,
        Interval::new(0.0, TAU),
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Line, NurbsCurve, Point3, Polyline};
    use std::f64::consts::PI;

    #[test]
    fn a_pipe_around_a_line_is_a_cylinder() {
        let rail = Curve::from(Line::new(Point3::ORIGIN, Point3::new(3.0, 0.0, 4.0)));
        let r = 0.5;
        let none = Brep::pipe(&rail, r, PipeCaps::None, 1e-9).unwrap();
        assert_eq!(none.len(), 1);
        assert!(!none[0].is_solid());
        assert!((none[0].area().unwrap() - 2.0 * PI * r * 5.0).abs() < 1e-12);
        let flat = Brep::pipe(&rail, r, PipeCaps::Flat, 1e-9).unwrap();
        assert_eq!(flat.len(), 1);
        assert_eq!(flat[0].faces().len(), 3);
        assert!(flat[0].is_solid());
        assert!((flat[0].volume().unwrap() - PI * r * r * 5.0).abs() < 1e-12);
        let round = Brep::pipe(&rail, r, PipeCaps::Round, 1e-9).unwrap();
        assert!(round[0].is_solid());
        // A capsule: the cylinder and a ball.
        let v = PI * r * r * 5.0 + 4.0 / 3.0 * PI * r * r * r;
        assert!((round[0].volume().unwrap() - v).abs() < 1e-11);
        let a = 2.0 * PI * r * 5.0 + 4.0 * PI * r * r;
        assert!((round[0].area().unwrap() - a).abs() < 1e-11);
    }

    #[test]
    fn a_pipe_around_a_circle_is_a_torus() {
        let rail = Curve::from(Circle::new(Plane::WORLD_XY, 3.0).unwrap());
        let r = 0.5;
        let b = Brep::pipe(&rail, r, PipeCaps::Flat, 1e-9).unwrap();
        assert_eq!(b.len(), 1);
        assert!(b[0].is_solid());
        assert_eq!(b[0].faces().len(), 1);
        let area = b[0].area().unwrap();
        assert!((area - 4.0 * PI * PI * 3.0 * r).abs() < 1e-9, "{area}");
        let volume = b[0].volume().unwrap();
        assert!(
            (volume - 2.0 * PI * PI * 3.0 * r * r).abs() < 1e-9,
            "{volume}"
        );
    }

    #[test]
    fn a_pipe_around_a_closed_polyline_is_mitred_and_closed() {
        let rail = Curve::from(
            Polyline::new(vec![
                Point3::ORIGIN,
                Point3::new(4.0, 0.0, 0.0),
                Point3::new(4.0, 3.0, 0.0),
                Point3::new(0.0, 3.0, 0.0),
                Point3::ORIGIN,
            ])
            .unwrap(),
        );
        let r = 0.25;
        let b = Brep::pipe(&rail, r, PipeCaps::Round, 1e-9).unwrap();
        assert_eq!(b.len(), 1);
        assert_eq!(b[0].faces().len(), 4);
        assert!(b[0].is_solid());
        // Mitred cylinders: the area and volume of a tube along the perimeter 14.
        assert!((b[0].area().unwrap() - 2.0 * PI * r * 14.0).abs() < 1e-9);
        assert!((b[0].volume().unwrap() - PI * r * r * 14.0).abs() < 1e-9);
    }

    #[test]
    fn a_fitted_pipe_has_the_tube_s_area_and_volume() {
        let rail = Curve::from(
            NurbsCurve::create(
                &[
                    Point3::new(0.0, 0.0, 0.0),
                    Point3::new(2.0, 1.0, 1.0),
                    Point3::new(4.0, -1.0, 2.0),
                    Point3::new(6.0, 2.0, 1.0),
                ],
                3,
                false,
            )
            .unwrap(),
        );
        let r = 0.2;
        let b = Brep::pipe(&rail, r, PipeCaps::Flat, 1e-9).unwrap();
        assert_eq!(b.len(), 1);
        let length = rail.length();
        let area = b[0].area().unwrap();
        assert!(
            (area - (2.0 * PI * r * length + 2.0 * PI * r * r)).abs() < 1e-7 * area,
            "{area}"
        );
        let volume = b[0].volume().unwrap();
        assert!(
            (volume - PI * r * r * length).abs() < 1e-7 * volume,
            "{volume}"
        );
    }

    #[test]
    fn bad_pipes_are_errors() {
        let rail = Curve::from(Line::new(Point3::ORIGIN, Point3::new(1.0, 0.0, 0.0)));
        assert!(Brep::pipe(&rail, 0.0, PipeCaps::None, 1e-9).is_err());
        assert!(Brep::pipe(&rail, f64::NAN, PipeCaps::None, 1e-9).is_err());
        assert!(Brep::pipe(&rail, 1.0, PipeCaps::None, -1.0).is_err());
        let back = Curve::from(
            Polyline::new(vec![
                Point3::ORIGIN,
                Point3::new(1.0, 0.0, 0.0),
                Point3::new(0.5, 0.0, 0.0),
            ])
            .unwrap(),
        );
        assert!(Brep::pipe(&back, 0.1, PipeCaps::None, 1e-9).is_err());
    }
}

//! Sweeps as B-reps (Grasshopper's Sweep1, and the surfaces of Pipe): profiles carried along a
//! rail on its perpendicular frames, one face per kink-free piece of the rail, joined.
//!
//! The surfaces are `surface/sweep.rs`'s, fitted to a tolerance, with two exact cases: a piece
//! of the rail that is straight (the profile moved along it: degree 1 across) and a piece that
//! is a circular arc with square ends (the profile revolved about the arc's axis, rational).
//! Both need one profile and frames without the closing twist of a closed rail.
//!
//! **Kinks** (Rhino's mitre types): the rail is cut where its tangent turns by more than
//! [`ANGLE_TOLERANCE`]. With [`SweepMiter::Trim`] both pieces end on the plane that bisects the
//! kink, the profile's points moved along each piece's tangent onto it (exactly the mitred
//! extension for straight pieces; on a curved piece the last span is moved along the end
//! tangent, which leaves the exact trimmed sweep by about `κ d² / 2` for a point moved by `d`);
//! the two ends then coincide point for point and join. With [`SweepMiter::Rotate`] the profile
//! is turned onto the bisecting plane (not stretched), and the ends join too. With
//! [`SweepMiter::None`] each piece ends with the profile square to it, and the pieces are left
//! apart where they do not meet.

use crate::brep::Brep;
use crate::geometry::tolerance::ANGLE_TOLERANCE;
use crate::surface::sweep::{SweepEnd, SweepRail, SweepShape, sweep_piece};
use crate::{Curve, Error, Interval, NurbsCurve, NurbsSurface, Point3, Result, Vector3};

/// The most profiles a sweep takes.
pub const MAX_SWEEP_PROFILES: usize = 10_000;

/// Samples per span of a profile for its centre, which places it on the rail.
const CENTRE_SAMPLES_PER_SPAN: usize = 8;

/// What a sweep does where its rail kinks (Grasshopper's Sweep1 Miter input, Rhino's
/// `SweepOneRail.MiterType`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum SweepMiter {
    /// The profile stays square to each piece; the pieces do not meet at the kink.
    None,
    /// Both pieces end on the plane bisecting the kink, the profile stretched onto it.
    Trim,
    /// The profile is turned onto the plane bisecting the kink.
    Rotate,
}

/// The faces of a sweep, before joining, and whether the rail closes smoothly.
pub(crate) struct SweptFaces {
    pub(crate) surfaces: Vec<NurbsSurface>,
}

/// The end treatment at a kink with incoming tangent `zin` and outgoing `zout` at `point`.
fn kink_end(
    miter: SweepMiter,
    point: Point3,
    zin: Vector3,
    zout: Vector3,
    t: f64,
) -> Result<SweepEnd> {
    let normal = (zin + zout)
        .try_normalize()
        .ok_or_else(|| Error::InvalidInput(format!("the rail turns back on itself at {t}")))?;
    Ok(match miter {
        SweepMiter::None => SweepEnd::Square,
        SweepMiter::Trim => SweepEnd::Projected { point, normal },
        SweepMiter::Rotate => SweepEnd::Rotated { point, normal },
    })
}

/// Whether all control points of the curve lie on one line through its ends (within a
/// rounding-level tolerance of its size).
fn is_straight(curve: &NurbsCurve) -> bool {
    let (a, b) = (curve.start_point(), curve.end_point());
    let Some(dir) = (b - a).try_normalize() else {
        return false;
    };
    let size = a.distance(b);
    curve
        .points()
        .iter()
        .all(|&p| (p - a).cross(dir).length() <= 1e-12 * size)
}

/// Sweeps `profiles`, placed at the increasing rail parameters `params`, along `rail`: one
/// surface per kink-free piece (see the module documentation).
pub(crate) fn sweep_faces(
    rail: &Curve,
    profiles: &[NurbsCurve],
    params: &[f64],
    miter: SweepMiter,
    tolerance: f64,
) -> Result<SweptFaces> {
    if !(tolerance > 0.0 && tolerance.is_finite()) {
        return Err(Error::InvalidInput(format!(
            "the sweep tolerance must be positive, got {tolerance}"
        )));
    }
    let nurbs = rail.to_nurbs();
    let wrapper = Curve::Nurbs(nurbs.clone());
    let sweep = SweepRail::new(&nurbs, &wrapper)?;
    let shape = SweepShape::new(&sweep, profiles, params)?;
    let d = nurbs.domain();
    let kinks = wrapper.kinks(ANGLE_TOLERANCE)?;
    let closed = wrapper.is_closed();
    let track = &sweep.track;
    let seam_kink = closed && {
        let (zin, _) = track.axes_from_left(d.t1)?;
        let (zout, _) = track.axes_at(d.t0)?;
        zin.dot(zout) < ANGLE_TOLERANCE.cos()
    };
    let mut bounds = vec![d.t0];
    bounds.extend(&kinks);
    bounds.push(d.t1);
    let pieces = bounds.len() - 1;
    let mut surfaces = Vec::with_capacity(pieces);
    let end_at = |t: f64, seam: bool| -> Result<SweepEnd> {
        let (zin, zout) = if seam {
            (track.axes_from_left(d.t1)?.0, track.axes_at(d.t0)?.0)
        } else {
            (track.axes_from_left(t)?.0, track.axes_at(t)?.0)
        };
        kink_end(miter, nurbs.point_at(t), zin, zout, t)
    };
    let single = profiles.len() == 1;
    for (k, w) in bounds.windows(2).enumerate() {
        let interval = Interval::new(w[0], w[1]);
        let start = if k > 0 {
            end_at(w[0], false)?
        } else if seam_kink {
            end_at(w[0], true)?
        } else {
            SweepEnd::Square
        };
        let end = if k + 1 < pieces {
            end_at(w[1], false)?
        } else if seam_kink {
            end_at(w[1], true)?
        } else {
            SweepEnd::Square
        };
        let piece = wrapper.trim(interval)?;
        let piece_nurbs = piece.to_nurbs();
        let exact = single && sweep.twist_rate == 0.0;
        let surface = if exact && is_straight(&piece_nurbs) {
            straight_piece(&shape, &sweep, interval, [start, end])?
        } else if let (true, SweepEnd::Square, SweepEnd::Square, Some(arc)) = (
            exact,
            start,
            end,
            piece.try_arc(1e-12 * (1.0 + piece_nurbs.bounding_box().diagonal().length())),
        ) {
            let profile = shape.profile_at(&sweep, w[0])?;
            let axis = arc.circle.normal();
            NurbsSurface::revolution(
                &profile,
                arc.center(),
                axis,
                Interval::new(0.0, arc.sweep()),
            )?
            .transposed()
            .reparameterized(profile.domain(), interval)?
        } else {
            let closes = closed && !seam_kink && pieces == 1;
            sweep_piece(&sweep, &shape, interval, [start, end], closes, tolerance)?
        };
        surfaces.push(surface);
    }
    Ok(SweptFaces { surfaces })
}

/// The straight piece `interval` of the rail swept exactly: the profile at both ends (finished),
/// joined by straight lines (degree 1 across).
fn straight_piece(
    shape: &SweepShape,
    sweep: &SweepRail<'_>,
    interval: Interval,
    ends: [SweepEnd; 2],
) -> Result<NurbsSurface> {
    let a = shape.finished_profile_at(sweep, interval.t0, false, ends[0])?;
    let b = shape.finished_profile_at(sweep, interval.t1, true, ends[1])?;
    let count_u = a.point_count();
    let mut points = Vec::with_capacity(2 * count_u);
    let mut weights = Vec::with_capacity(2 * count_u);
    for i in 0..count_u {
        points.push(a.points()[i]);
        points.push(b.points()[i]);
        weights.push(a.weights()[i]);
        weights.push(a.weights()[i]);
    }
    NurbsSurface::from_flat(
        [a.degree(), 1],
        [count_u, 2],
        points,
        weights,
        [a.knots().to_vec(), vec![interval.t0, interval.t1]],
    )
}

/// The point a profile's samples average to, which places it on the rail.
fn centre(profile: &NurbsCurve) -> Point3 {
    let n = (profile.span_count() * CENTRE_SAMPLES_PER_SPAN).max(CENTRE_SAMPLES_PER_SPAN);
    let d = profile.domain();
    let closed = profile.is_closed();
    let count = if closed { n } else { n + 1 };
    let sum = (0..count).fold(Vector3::ZERO, |s, k| {
        s + profile
            .point_at(d.parameter_at(k as f64 / n as f64))
            .to_vector()
    });
    Point3::from_vector(sum / count as f64)
}

impl Brep {
    /// Sweeps profile curves along a rail (Grasshopper's Sweep1): each profile is placed at the
    /// rail point closest to its centre (the average of points along it), its control points
    /// are carried along the rail's perpendicular frames (blended between profiles when there
    /// are several), and every kink-free piece of the rail becomes a face, fitted within
    /// `tolerance` (exact on straight pieces and on arcs); the faces are joined within
    /// `tolerance`. Kinks are handled by `miter` (see the module documentation). Surfaces have
    /// `u` along the profile and `v` along the rail on the rail's parameters.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] for no profiles or more than [`MAX_SWEEP_PROFILES`], two
    /// profiles at the same place on the rail, a rail that turns back on itself, a
    /// non-positive tolerance; [`Error::NotFinite`] for non-finite input; the errors of the
    /// frames and the fit.
    pub fn sweep(
        rail: &Curve,
        profiles: &[Curve],
        miter: SweepMiter,
        tolerance: f64,
    ) -> Result<Vec<Brep>> {
        if profiles.is_empty() || profiles.len() > MAX_SWEEP_PROFILES {
            return Err(Error::InvalidInput(format!(
                "a sweep needs from 1 to {MAX_SWEEP_PROFILES} profiles, got {}",
                profiles.len()
            )));
        }
        if !rail.is_valid() {
            return Err(Error::InvalidInput("the rail is not a valid curve".into()));
        }
        let mut placed = Vec::with_capacity(profiles.len());
        for (k, p) in profiles.iter().enumerate() {
            if !p.is_valid() {
                return Err(Error::InvalidInput(format!(
                    "profile {k} is not a valid curve"
                )));
            }
            let nurbs = p.to_nurbs();
            let t = rail.closest_point(centre(&nurbs))?.t;
            placed.push((t, nurbs));
        }
        placed.sort_by(|a, b| a.0.total_cmp(&b.0));
        let params: Vec<f64> = placed.iter().map(|p| p.0).collect();
        let curves: Vec<NurbsCurve> = placed.into_iter().map(|p| p.1).collect();
        let swept = sweep_faces(rail, &curves, &params, miter, tolerance)?;
        let faces = swept
            .surfaces
            .into_iter()
            .map(Brep::from_surface)
            .collect::<Result<Vec<_>>>()?;
        Brep::join(&faces, tolerance)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Circle, Line, Plane, Polyline};
    use std::f64::consts::PI;

    fn square_profile(half: f64, plane: Plane) -> Curve {
        let corner = |x: f64, y: f64| plane.origin + plane.x_axis * x + plane.y_axis * y;
        Curve::from(
            Polyline::new(vec![
                corner(-half, -half),
                corner(half, -half),
                corner(half, half),
                corner(-half, half),
                corner(-half, -half),
            ])
            .unwrap(),
        )
    }

    #[test]
    fn a_square_swept_along_a_line_is_a_box_tube() {
        let rail = Curve::from(Line::new(Point3::ORIGIN, Point3::new(0.0, 0.0, 3.0)));
        let profile = square_profile(0.5, Plane::WORLD_XY);
        let b = Brep::sweep(&rail, &[profile], SweepMiter::Trim, 1e-9).unwrap();
        assert_eq!(b.len(), 1);
        assert_eq!(b[0].faces().len(), 1);
        assert!((b[0].area().unwrap() - 4.0 * 3.0).abs() < 1e-12);
    }

    #[test]
    fn mitred_sweep_around_a_corner_joins() {
        // An L rail; a circle profile. Trimmed: one B-rep of two faces meeting on the bisecting
        // plane, each a cylinder of length 2 (its axis is cut at the corner), area 2π r · 4.
        let rail = Curve::from(
            Polyline::new(vec![
                Point3::ORIGIN,
                Point3::new(2.0, 0.0, 0.0),
                Point3::new(2.0, 2.0, 0.0),
            ])
            .unwrap(),
        );
        let circle = Curve::from(Circle::new(Plane::WORLD_YZ, 0.25).unwrap());
        let b = Brep::sweep(&rail, std::slice::from_ref(&circle), SweepMiter::Trim, 1e-9).unwrap();
        assert_eq!(b.len(), 1);
        assert_eq!(b[0].faces().len(), 2);
        let area = b[0].area().unwrap();
        assert!((area - 2.0 * PI * 0.25 * 4.0).abs() < 1e-9, "{area}");
        // Not mitred the two tubes stay apart.
        let apart =
            Brep::sweep(&rail, std::slice::from_ref(&circle), SweepMiter::None, 1e-9).unwrap();
        assert_eq!(apart.len(), 2);
        // Rotated the profile keeps its size on the bisecting plane; the faces join.
        let rotated = Brep::sweep(&rail, &[circle], SweepMiter::Rotate, 1e-9).unwrap();
        assert_eq!(rotated.len(), 1);
    }

    #[test]
    fn a_profile_along_an_arc_is_a_surface_of_revolution() {
        let arc_plane = Plane::WORLD_XY;
        let arc =
            crate::Arc::new(Circle::new(arc_plane, 3.0).unwrap(), Interval::new(0.0, PI)).unwrap();
        let rail = Curve::from(arc);
        // A unit square profile at the arc's start, in the plane through the axis.
        let profile = square_profile(
            0.5,
            Plane {
                origin: Point3::new(3.0, 0.0, 0.0),
                x_axis: Vector3::X,
                y_axis: Vector3::Z,
                z_axis: -Vector3::Y,
            },
        );
        let b = Brep::sweep(&rail, &[profile], SweepMiter::Trim, 1e-9).unwrap();
        // Pappus: the square's perimeter 4 swept by its centroid's path π·3: area 12π; the
        // faces are exact (rational), so the area is to rounding.
        let area = b[0].area().unwrap();
        assert!((area - 12.0 * PI).abs() < 1e-9, "{area}");
    }

    #[test]
    fn bad_sweeps_are_errors() {
        let rail = Curve::from(Line::new(Point3::ORIGIN, Point3::new(0.0, 0.0, 3.0)));
        assert!(Brep::sweep(&rail, &[], SweepMiter::Trim, 1e-9).is_err());
        let profile = square_profile(0.5, Plane::WORLD_XY);
        assert!(
            Brep::sweep(
                &rail,
                &[profile.clone(), profile.clone()],
                SweepMiter::Trim,
                1e-9
            )
            .is_err()
        );
        assert!(Brep::sweep(&rail, &[profile], SweepMiter::Trim, 0.0).is_err());
    }
}

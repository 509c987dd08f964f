//! Surfaces of revolution: a profile curve swept about an axis through an angle, in exact
//! rational form (Grasshopper's Revolution, Rhino's `RevSurface` as NURBS).
//!
//! `u` is the angle, on the given angle interval, and `v` the profile's parameter. Every
//! control point of the profile sweeps an exact circular arc about the axis, made of
//! `⌈|angle| / 90°⌉` rational quadratic pieces of equal angle (The NURBS Book, A7.1 and A8.1);
//! the middle point of each piece lies `1 / cos(Δ/2)` farther out and carries the weight
//! `cos(Δ/2)` times the profile weight.

use std::f64::consts::{FRAC_PI_2, TAU};

use crate::{Error, Interval, NurbsCurve, NurbsSurface, Point3, Result, Vector3};

impl NurbsSurface {
    /// The profile revolved about the axis through `origin` along `axis` by the angles of
    /// `angle` (radians, counter-clockwise about `axis`; `0..2π` for a full turn). `u` runs
    /// over `angle` and `v` over the profile's domain.
    ///
    /// # Errors
    /// [`Error::NotFinite`] for non-finite input; [`Error::ZeroLength`] for a zero axis;
    /// [`Error::InvalidInput`] for an angle interval that is empty, decreasing or longer than
    /// a full turn.
    pub fn revolution(
        profile: &NurbsCurve,
        origin: Point3,
        axis: Vector3,
        angle: Interval,
    ) -> Result<Self> {
        if !origin.is_finite() || !axis.is_finite() || !angle.is_finite() {
            return Err(Error::NotFinite {
                what: "revolution axis or angle",
            });
        }
        let dir = axis.try_normalize().ok_or(Error::ZeroLength {
            what: "revolution axis",
        })?;
        let sweep = angle.t1 - angle.t0;
        if !(sweep > 0.0 && sweep <= TAU * (1.0 + 1e-12)) {
            return Err(Error::InvalidInput(format!(
                "the revolution angle must increase by more than 0 and at most 2π, got {} to {}",
                angle.t0, angle.t1
            )));
        }
        let arcs = ((sweep / FRAC_PI_2) - 1e-9).ceil().max(1.0) as usize;
        let delta = sweep / arcs as f64;
        let wm = (delta / 2.0).cos();
        let ring = 2 * arcs + 1;
        let count_v = profile.point_count();
        let mut points = vec![Point3::ORIGIN; ring * count_v];
        let mut weights = vec![1.0; ring * count_v];
        for (j, (&p, &w)) in profile.points().iter().zip(profile.weights()).enumerate() {
            let on_axis = origin + dir * (p - origin).dot(dir);
            let out = p - on_axis;
            let r = out.length();
            let x = if r > 0.0 { out / r } else { Vector3::ZERO };
            let y = dir.cross(x);
            for i in 0..ring {
                let a = angle.t0 + delta * i as f64 / 2.0;
                let (reach, weight) = if i % 2 == 0 { (r, w) } else { (r / wm, w * wm) };
                points[i * count_v + j] = on_axis + (x * a.cos() + y * a.sin()) * reach;
                weights[i * count_v + j] = weight;
            }
        }
        let mut knots_u = vec![angle.t0; 2];
        for k in 1..arcs {
            let t = angle.t0 + delta * k as f64;
            knots_u.extend([t, t]);
        }
        knots_u.extend([angle.t1, angle.t1]);
        Self::from_flat(
            [2, profile.degree()],
            [ring, count_v],
            points,
            weights,
            [knots_u, profile.knots().to_vec()],
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Arc, Circle, Line, Plane, SurfaceDirection};
    use std::f64::consts::PI;

    #[test]
    fn a_revolved_line_is_a_cylinder() {
        let line = Line::new(Point3::new(1.0, 0.0, 0.0), Point3::new(1.0, 0.0, 2.0))
            .to_nurbs()
            .unwrap();
        let s =
            NurbsSurface::revolution(&line, Point3::ORIGIN, Vector3::Z, Interval::new(0.0, TAU))
                .unwrap();
        for k in 0..=16 {
            let u = TAU * k as f64 / 16.0;
            let p = s.point_at(u, 0.5);
            assert!((p.x.hypot(p.y) - 1.0).abs() < 1e-12);
            // At the quarter-turn knots the angle is exact (in between the rational
            // parameterization is not proportional to the angle).
            if k % 4 == 0 {
                assert!((p.x - u.cos()).abs() < 1e-12 && (p.y - u.sin()).abs() < 1e-12);
            }
        }
        let area = s.area_properties().unwrap().area;
        assert!((area - 4.0 * PI).abs() < 1e-9, "{area}");
        // A quarter turn has a quarter of the area.
        let quarter = NurbsSurface::revolution(
            &line,
            Point3::ORIGIN,
            Vector3::Z,
            Interval::new(0.0, PI / 2.0),
        )
        .unwrap();
        assert!((quarter.area_properties().unwrap().area - PI).abs() < 1e-9);
    }

    #[test]
    fn a_revolved_half_circle_is_a_sphere() {
        // From the south pole through (2, 0, 0) to the north pole, in the plane y = 0.
        let plane = Plane::from_frame(Point3::ORIGIN, Vector3::X, Vector3::Z).unwrap();
        let circle = Circle::new(plane, 2.0).unwrap();
        let arc = Arc::new(circle, Interval::new(-PI / 2.0, PI / 2.0))
            .unwrap()
            .to_nurbs();
        let s = NurbsSurface::revolution(&arc, Point3::ORIGIN, Vector3::Z, Interval::new(0.0, TAU))
            .unwrap();
        let area = s.area_properties().unwrap().area;
        assert!((area - 16.0 * PI).abs() < 1e-8, "{area}");
        let iso = s.isocurve(SurfaceDirection::V, 1.0).unwrap();
        assert!((iso.point_at(0.3).to_vector().length() - 2.0).abs() < 1e-12);
    }

    #[test]
    fn bad_revolutions_are_errors() {
        let c = Circle::new(Plane::WORLD_XY, 1.0).unwrap().to_nurbs();
        let full = Interval::new(0.0, TAU);
        assert!(NurbsSurface::revolution(&c, Point3::ORIGIN, Vector3::ZERO, full).is_err());
        assert!(
            NurbsSurface::revolution(&c, Point3::ORIGIN, Vector3::Z, Interval::new(0.0, 7.0))
                .is_err()
        );
        assert!(
            NurbsSurface::revolution(&c, Point3::ORIGIN, Vector3::Z, Interval::new(1.0, 1.0))
                .is_err()
        );
    }
}

//! Perpendicular frames along a curve: planes whose normal (`z`) is the curve's tangent, with
//! the x axis carried along the curve so that it turns as little as possible (rotation-minimizing
//! or "parallel transport" frames, Rhino's `Curve.GetPerpendicularFrames`, Grasshopper's Perp
//! Frame and Perp Frames).
//!
//! A rotation-minimizing x axis satisfies `x' = −(x · T') T`: it never turns about the tangent.
//! It is computed by the double reflection method (Wang, Jüttler, Zheng and Liu, *Computation of
//! Rotation Minimizing Frames*, ACM Transactions on Graphics 27(1), 2008): from one sample to
//! the next, the frame is reflected in the plane bisecting the chord between the two points, then
//! in the plane that takes the reflected tangent onto the new tangent. Its global error is of
//! fourth order in the step; the steps are chosen so that the tangent turns by at most
//! [`MAX_STEP_TURN`] between samples, with at least [`MIN_STEPS_PER_SPAN`] per span, which keeps
//! the frames within about 1e-10 of the exact transport (tested against a fine march below).
//! At a kink the frame is turned by the smallest rotation that takes the incoming tangent onto
//! the outgoing one.
//!
//! **The first frame** (a decision; Rhino's own rule is not published): its x axis points
//! towards the centre of curvature at the start when the curve is curved there, as Curve
//! Frame's y axis does; on a planar curve that starts straight it lies in the curve's plane
//! (`normal × tangent`); otherwise it is [`perpendicular_to`] the tangent, the axis
//! [`Plane::from_normal`] picks. A planar curve therefore keeps its frames' y axis (or x axis)
//! along the plane normal all the way.

use crate::geometry::tolerance::ZERO_TOLERANCE;
use crate::{Curve, Error, Plane, Point3, Result, Vector3, perpendicular_to};

/// The largest angle in radians by which the tangent turns between two samples of the march:
/// 0.2°.
pub const MAX_STEP_TURN: f64 = 0.2 * std::f64::consts::PI / 180.0;

/// The fewest samples per span (per segment of a polyline, per NURBS span).
pub const MIN_STEPS_PER_SPAN: usize = 4;

/// The most samples one march takes (about a million: 2,900 full turns of the tangent).
pub const MAX_FRAME_STEPS: usize = 1 << 20;

/// A curvature below this times the reciprocal of the curve's length counts as straight when
/// the first frame is chosen.
const STRAIGHT_CURVATURE: f64 = 1e-9;

impl Curve {
    /// The perpendicular (rotation-minimizing) frames at `parameters`, in their order: origin on
    /// the curve, z axis the unit tangent (the outgoing one at a kink), x axis carried from the
    /// first frame at the start of the domain without turning about the tangent (see the module
    /// documentation), y axis `z × x`.
    ///
    /// # Errors
    /// [`Error::NotFinite`] for a NaN parameter, [`Error::InvalidInput`] for a parameter outside
    /// the domain or a curve that needs more than [`MAX_FRAME_STEPS`] samples, and
    /// [`Error::Degenerate`] where the curve has no tangent.
    pub fn perpendicular_frames(&self, parameters: &[f64]) -> Result<Vec<Plane>> {
        let d = self.domain();
        for &t in parameters {
            if !t.is_finite() {
                return Err(Error::NotFinite { what: "parameter" });
            }
            if !d.contains(t) {
                return Err(Error::InvalidInput(format!(
                    "parameter {t} is outside the curve's domain {} to {}",
                    d.t0, d.t1
                )));
            }
        }
        let track = FrameTrack::new(self)?;
        parameters
            .iter()
            .map(|&t| {
                let (z, x) = track.axes_at(t)?;
                Ok(Plane {
                    origin: self.point_at(t),
                    x_axis: x,
                    y_axis: z.cross(x),
                    z_axis: z,
                })
            })
            .collect()
    }

    /// The perpendicular frame at `t`: the frame of [`Curve::perpendicular_frames`] carried from
    /// the start of the domain to `t`.
    ///
    /// # Errors
    /// As [`Curve::perpendicular_frames`].
    pub fn perpendicular_frame_at(&self, t: f64) -> Result<Plane> {
        Ok(self.perpendicular_frames(&[t])?[0])
    }

    /// The frame at `t` with z along the tangent and x towards the centre of curvature, found
    /// at `t` alone (no transport): Perp Frames' frames when they are not aligned. On straight
    /// pieces the x axis is [`perpendicular_to`] the tangent.
    ///
    /// # Errors
    /// [`Error::NotFinite`] for a NaN `t`, [`Error::Degenerate`] where there is no tangent.
    pub fn curvature_perpendicular_frame_at(&self, t: f64) -> Result<Plane> {
        if !t.is_finite() {
            return Err(Error::NotFinite { what: "parameter" });
        }
        let z = self.tangent_at(t).ok_or(Error::Degenerate {
            what: "curve tangent",
        })?;
        let x = self
            .curvature_at(t)
            .and_then(|k| (k - z * k.dot(z)).try_normalize())
            .or_else(|| perpendicular_to(z).try_normalize())
            .ok_or(Error::Degenerate {
                what: "curve tangent",
            })?;
        Ok(Plane {
            origin: self.point_at(t),
            x_axis: x,
            y_axis: z.cross(x),
            z_axis: z,
        })
    }

    /// The x axis of the first perpendicular frame, at the start of the domain (see the module
    /// documentation), with the unit tangent there.
    pub(crate) fn first_perpendicular_axes(&self) -> Result<(Vector3, Vector3)> {
        let t0 = self.domain().t0;
        let z = self.tangent_at(t0).ok_or(Error::Degenerate {
            what: "curve tangent",
        })?;
        let length = self.length();
        let curved = self
            .curvature_at(t0)
            .filter(|k| k.length() * length > STRAIGHT_CURVATURE)
            .and_then(|k| (k - z * k.dot(z)).try_normalize());
        let x = curved
            .or_else(|| plane_normal(self).and_then(|n| n.cross(z).try_normalize()))
            .or_else(|| perpendicular_to(z).try_normalize())
            .ok_or(Error::Degenerate {
                what: "curve tangent",
            })?;
        Ok((z, x))
    }

    /// The parameters where the march restarts: the kinks and the ends of spans, segments and
    /// quarter turns of circles, increasing, strictly inside the domain.
    fn march_breaks(&self, kinks: &[f64]) -> Vec<f64> {
        let d = self.domain();
        let mut breaks: Vec<f64> = match self {
            Curve::Nurbs(c) => c.span_breaks(),
            Curve::Polyline { polyline, .. } => {
                let n = polyline.segment_count();
                (0..=n)
                    .map(|i| d.parameter_at(i as f64 / n as f64))
                    .collect()
            }
            Curve::Line { .. } | Curve::Circle { .. } | Curve::Arc { .. } => (0..=4)
                .map(|i| d.parameter_at(f64::from(i) / 4.0))
                .collect(),
        };
        breaks.extend_from_slice(kinks);
        breaks.retain(|&b| b > d.t0 && b < d.t1);
        breaks.sort_by(f64::total_cmp);
        breaks.dedup();
        breaks
    }

    /// The grid points after `a` up to `b` (included) of a piece without breaks, whose tangent
    /// at `a` is `z`: [`MIN_STEPS_PER_SPAN`] probes measure how far the tangent turns, and the
    /// piece is cut into equal steps of at most [`MAX_STEP_TURN`].
    fn piece_grid(&self, a: f64, b: f64, z: Vector3) -> Result<Vec<f64>> {
        let mut turn = 0.0;
        let mut previous = z;
        for i in 1..=MIN_STEPS_PER_SPAN {
            let t = a + (b - a) * i as f64 / MIN_STEPS_PER_SPAN as f64;
            let tangent = if i == MIN_STEPS_PER_SPAN {
                self.tangent_from_left(b)?
            } else {
                self.tangent_at(t)
            }
            .ok_or(Error::Degenerate {
                what: "curve tangent",
            })?;
            turn += angle_between(previous, tangent);
            previous = tangent;
        }
        let n =
            ((turn / MAX_STEP_TURN).ceil() as usize).clamp(MIN_STEPS_PER_SPAN, MAX_FRAME_STEPS + 1);
        Ok((1..=n)
            .map(|i| {
                if i == n {
                    b
                } else {
                    a + (b - a) * i as f64 / n as f64
                }
            })
            .collect())
    }
}

/// The perpendicular frames of a curve on its march grid, which depends on the curve alone (its
/// breaks, each piece cut into steps by the turn of its tangent), so that a frame does not
/// depend on which other parameters are asked for: a parameter between two grid points is
/// reached by one more step from the grid point before it.
pub(crate) struct FrameTrack<'a> {
    curve: &'a Curve,
    /// Grid parameters, increasing, from the start to the end of the domain.
    ts: Vec<f64>,
    /// Points, tangents and x axes at the grid parameters: at a kink the outgoing tangent and
    /// the turned axis, at the end of the domain the incoming tangent.
    points: Vec<Point3>,
    zs: Vec<Vector3>,
    xs: Vec<Vector3>,
    /// The kinks with the incoming tangent and x axis (before the turn).
    kinks: Vec<(f64, Vector3, Vector3)>,
}

impl<'a> FrameTrack<'a> {
    /// Marches the frames along `curve`.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] for a curve that needs more than [`MAX_FRAME_STEPS`] samples,
    /// [`Error::Degenerate`] where it has no tangent.
    pub(crate) fn new(curve: &'a Curve) -> Result<Self> {
        let d = curve.domain();
        let (mut z, mut x) = curve.first_perpendicular_axes()?;
        let mut p = curve.point_at(d.t0);
        let mut t = d.t0;
        let kink_ts = curve.kinks(0.0)?;
        let mut breaks = curve.march_breaks(&kink_ts);
        breaks.push(d.t1);
        let mut track = Self {
            curve,
            ts: vec![t],
            points: vec![p],
            zs: vec![z],
            xs: vec![x],
            kinks: Vec::with_capacity(kink_ts.len()),
        };
        let mut next_kink = 0usize;
        for &end in &breaks {
            let grid = curve.piece_grid(t, end, z)?;
            if track.ts.len() + grid.len() > MAX_FRAME_STEPS {
                return Err(Error::InvalidInput(format!(
                    "the curve turns too much for perpendicular frames (more than \
                     {MAX_FRAME_STEPS} samples)"
                )));
            }
            for &g in &grid {
                let q = curve.point_at(g);
                let zq = if g == end {
                    curve.tangent_from_left(g)?
                } else {
                    curve.tangent_at(g)
                }
                .ok_or(Error::Degenerate {
                    what: "curve tangent",
                })?;
                x = double_reflection(p, z, x, q, zq);
                (z, p, t) = (zq, q, g);
                track.ts.push(g);
                track.points.push(p);
                track.zs.push(z);
                track.xs.push(x);
            }
            while next_kink < kink_ts.len() && kink_ts[next_kink] < t {
                next_kink += 1;
            }
            if next_kink < kink_ts.len() && kink_ts[next_kink] == t {
                let outgoing = curve.tangent_at(t).ok_or(Error::Degenerate {
                    what: "curve tangent",
                })?;
                track.kinks.push((t, z, x));
                x = turned(x, z, outgoing);
                z = outgoing;
                let last = track.ts.len() - 1;
                track.zs[last] = z;
                track.xs[last] = x;
                next_kink += 1;
            }
        }
        Ok(track)
    }

    /// The tangent and x axis at `t` (on the domain): the outgoing ones at a kink.
    pub(crate) fn axes_at(&self, t: f64) -> Result<(Vector3, Vector3)> {
        let i = self.ts.partition_point(|&g| g <= t).max(1) - 1;
        if self.ts[i] == t {
            return Ok((self.zs[i], self.xs[i]));
        }
        let zq = self.curve.tangent_at(t).ok_or(Error::Degenerate {
            what: "curve tangent",
        })?;
        let x = double_reflection(
            self.points[i],
            self.zs[i],
            self.xs[i],
            self.curve.point_at(t),
            zq,
        );
        Ok((zq, x))
    }

    /// The tangent and x axis at `t` arriving from below: the incoming ones at a kink, else as
    /// [`FrameTrack::axes_at`].
    pub(crate) fn axes_from_left(&self, t: f64) -> Result<(Vector3, Vector3)> {
        match self.kinks.iter().find(|k| k.0 == t) {
            Some(&(_, z, x)) => Ok((z, x)),
            None => self.axes_at(t),
        }
    }
}

/// The angle between two unit vectors, accurate for small angles.
fn angle_between(a: Vector3, b: Vector3) -> f64 {
    a.cross(b).length().atan2(a.dot(b))
}

/// One double-reflection step: the axis `x` (perpendicular to the unit tangent `z` at `p`)
/// carried to the point `q` with unit tangent `zq`.
fn double_reflection(p: Point3, z: Vector3, x: Vector3, q: Point3, zq: Vector3) -> Vector3 {
    let v1 = q - p;
    let c1 = v1.length_squared();
    let (xl, zl) = if c1 > 0.0 {
        (
            x - v1 * (2.0 * v1.dot(x) / c1),
            z - v1 * (2.0 * v1.dot(z) / c1),
        )
    } else {
        (x, z)
    };
    let v2 = zq - zl;
    let c2 = v2.length_squared();
    let xr = if c2 > 0.0 {
        xl - v2 * (2.0 * v2.dot(xl) / c2)
    } else {
        xl
    };
    // Keep the axis exactly perpendicular and of unit length against rounding.
    (xr - zq * xr.dot(zq)).try_normalize().unwrap_or(xr)
}

/// `x` turned by the smallest rotation that takes the unit vector `from` onto `to`, kept
/// perpendicular to `to` and of unit length.
pub(crate) fn turned(x: Vector3, from: Vector3, to: Vector3) -> Vector3 {
    let rotated = rotated_minimally(x, from, to);
    (rotated - to * rotated.dot(to))
        .try_normalize()
        .unwrap_or(rotated)
}

/// `v` rotated by the smallest rotation that takes the unit vector `from` onto the unit
/// vector `to` (Rodrigues' formula about `from × to`); unchanged when they are parallel, or
/// opposite (no smallest rotation exists).
pub(crate) fn rotated_minimally(v: Vector3, from: Vector3, to: Vector3) -> Vector3 {
    let axis = from.cross(to);
    let sin = axis.length();
    let cos = from.dot(to);
    let Some(k) = axis.try_normalize() else {
        return v;
    };
    v * cos + k.cross(v) * sin + k * (k.dot(v) * (1.0 - cos))
}

/// The normal of the plane the curve lies in, or `None` for a curve that is straight or not
/// planar (control points farther than 1e-10 of the curve's size from their plane).
pub(crate) fn plane_normal(curve: &Curve) -> Option<Vector3> {
    if let Curve::Circle { circle, .. } = curve {
        return Some(circle.plane.z_axis);
    }
    if let Curve::Arc { arc, .. } = curve {
        return Some(arc.circle.plane.z_axis);
    }
    let nurbs = curve.to_nurbs();
    let points = nurbs.points();
    let n = points.len() as f64;
    let centre = points.iter().fold(Vector3::ZERO, |s, p| s + p.to_vector()) / n;
    let centre = Point3::from_vector(centre);
    let size = points.iter().fold(0.0f64, |m, p| m.max(p.distance(centre)));
    if !(size > 0.0 && size.is_finite()) {
        return None;
    }
    // Newell's normal of the control polygon, closed; a zigzag can cancel it, so fall back on
    // the largest cross product from the centre.
    let mut normal = Vector3::ZERO;
    for (i, p) in points.iter().enumerate() {
        let q = points[(i + 1) % points.len()];
        normal += (*p - centre).cross(q - centre);
    }
    if normal.length() <= 1e-6 * size * size {
        let step = (points.len() / 64).max(1);
        for p in points.iter().step_by(step) {
            for q in points.iter().step_by(step) {
                let c = (*p - centre).cross(*q - centre);
                if c.length() > normal.length() {
                    normal = c;
                }
            }
        }
    }
    if normal.length() <= ZERO_TOLERANCE * size * size {
        return None;
    }
    let normal = normal.try_normalize()?;
    let flat = points
        .iter()
        .all(|p| (*p - centre).dot(normal).abs() <= 1e-10 * size);
    flat.then_some(normal)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Circle, Line, NurbsCurve, Polyline};
    use proptest::prelude::*;
    use std::f64::consts::TAU;

    fn assert_frame(f: &Plane) {
        assert!((f.x_axis.length() - 1.0).abs() < 1e-12);
        assert!(f.x_axis.dot(f.z_axis).abs() < 1e-12);
        assert!((f.x_axis.cross(f.y_axis) - f.z_axis).length() < 1e-12);
    }

    /// A wavy, non-planar cubic.
    fn space_curve() -> Curve {
        let pts = [
            Point3::new(0.0, 0.0, 0.0),
            Point3::new(1.0, 2.0, 0.5),
            Point3::new(3.0, -1.0, 1.5),
            Point3::new(4.0, 1.0, -1.0),
            Point3::new(6.0, 3.0, 0.0),
            Point3::new(7.0, 0.0, 2.0),
        ];
        Curve::from(NurbsCurve::create(&pts, 3, false).unwrap())
    }

    #[test]
    fn frames_on_a_circle_keep_the_plane_normal() {
        let c = Curve::from(Circle::new(Plane::WORLD_XY, 2.0).unwrap());
        let ts: Vec<f64> = (0..=12).map(|i| TAU * f64::from(i) / 12.0).collect();
        let frames = c.perpendicular_frames(&ts).unwrap();
        for (f, &t) in frames.iter().zip(&ts) {
            assert_frame(f);
            // x towards the centre, y along +Z: the start rule carried around a planar curve.
            let inward = Vector3::new(-t.cos(), -t.sin(), 0.0);
            assert!((f.x_axis - inward).length() < 1e-9, "{t}: {:?}", f.x_axis);
            assert!((f.y_axis - Vector3::Z).length() < 1e-9);
            assert!(f.origin.distance(c.point_at(t)) < 1e-15);
        }
    }

    #[test]
    fn frames_on_a_line_and_a_polyline() {
        let line = Curve::from(Line::new(Point3::ORIGIN, Point3::new(0.0, 0.0, 5.0)));
        let f = line.perpendicular_frame_at(2.0).unwrap();
        // Straight and not planar: the x axis of Plane::from_normal.
        assert_eq!(f.x_axis, Vector3::X);
        assert_eq!(f.z_axis, Vector3::Z);
        // An L in the XY plane: x stays in the plane and turns with the corner.
        let l = Curve::from(
            Polyline::new(vec![
                Point3::ORIGIN,
                Point3::new(2.0, 0.0, 0.0),
                Point3::new(2.0, 3.0, 0.0),
            ])
            .unwrap(),
        );
        let frames = l.perpendicular_frames(&[0.0, 0.5, 1.0, 1.5, 2.0]).unwrap();
        assert!((frames[0].x_axis - Vector3::Y).length() < 1e-12);
        assert!((frames[1].x_axis - Vector3::Y).length() < 1e-12);
        // After the corner (the outgoing tangent at the vertex) x has turned a quarter.
        assert!((frames[2].z_axis - Vector3::Y).length() < 1e-12);
        assert!((frames[2].x_axis + Vector3::X).length() < 1e-12);
        assert!((frames[4].x_axis + Vector3::X).length() < 1e-12);
        for f in &frames {
            assert!((f.y_axis - Vector3::Z).length() < 1e-12);
        }
    }

    #[test]
    fn order_of_parameters_does_not_matter() {
        let c = space_curve();
        let d = c.domain();
        let ts = [d.parameter_at(0.7), d.t0, d.parameter_at(0.2), d.t1];
        let frames = c.perpendicular_frames(&ts).unwrap();
        for (f, &t) in frames.iter().zip(&ts) {
            let single = c.perpendicular_frame_at(t).unwrap();
            assert_eq!(f.x_axis, single.x_axis);
            assert_frame(f);
            assert!((f.z_axis - c.tangent_at(t).unwrap()).length() < 1e-15);
        }
    }

    #[test]
    fn frames_agree_with_a_much_finer_march() {
        // The same transport with a hundred times more samples (an independent reference for
        // the march's own error).
        let c = space_curve();
        let d = c.domain();
        let (mut z, mut x) = c.first_perpendicular_axes().unwrap();
        let n = 200_000;
        let mut p = c.point_at(d.t0);
        for i in 1..=n {
            let t = d.parameter_at(f64::from(i) / f64::from(n));
            let (q, zq) = (c.point_at(t), c.tangent_at(t).unwrap());
            x = double_reflection(p, z, x, q, zq);
            (p, z) = (q, zq);
        }
        let end = c.perpendicular_frame_at(d.t1).unwrap();
        assert!(
            (end.x_axis - x).length() < 1e-9,
            "{:?} vs {x:?}",
            end.x_axis
        );
    }

    #[test]
    fn unaligned_frames_follow_the_curvature() {
        let c = space_curve();
        let t = c.domain().parameter_at(0.3);
        let f = c.curvature_perpendicular_frame_at(t).unwrap();
        assert_frame(&f);
        let k = c.curvature_at(t).unwrap();
        assert!(f.x_axis.dot(k) > 0.0 && f.x_axis.cross(k).length() < 1e-9 * k.length());
    }

    #[test]
    fn bad_parameters_are_errors() {
        let c = space_curve();
        assert!(matches!(
            c.perpendicular_frame_at(f64::NAN),
            Err(Error::NotFinite { .. })
        ));
        assert!(matches!(
            c.perpendicular_frame_at(c.domain().t1 + 1.0),
            Err(Error::InvalidInput(_))
        ));
    }

    proptest! {
        /// The x axis does not turn about the tangent: `x' · y = 0`, by central differences.
        #[test]
        fn frames_minimize_rotation(
            wiggle in proptest::collection::vec(-2.0f64..2.0, 18),
            s in 0.05f64..0.95,
        ) {
            let pts: Vec<Point3> = (0..6)
                .map(|i| Point3::new(i as f64 * 1.5 + wiggle[3 * i], wiggle[3 * i + 1],
                    wiggle[3 * i + 2]))
                .collect();
            let c = Curve::from(NurbsCurve::create(&pts, 3, false).unwrap());
            let d = c.domain();
            let t = d.parameter_at(s);
            let h = 2e-4 * d.length();
            let f = c.perpendicular_frames(&[t - 2.0 * h, t - h, t, t + h, t + 2.0 * h]).unwrap();
            // Fourth-order central differences.
            let diff = |a: Vector3, b: Vector3, c: Vector3, e: Vector3| {
                ((c - b) * 8.0 - (e - a)) / (12.0 * h)
            };
            let dx = diff(f[0].x_axis, f[1].x_axis, f[3].x_axis, f[4].x_axis);
            let dz = diff(f[0].z_axis, f[1].z_axis, f[3].z_axis, f[4].z_axis);
            let f = &f[1..4];
            // dx lies along the tangent: its y component vanishes, to the error of the frames
            // (about 1e-12) over h and the scheme's h⁴ error, while the tangent turns at |dz|.
            let slack = 1e-7 * (1.0 + dz.length() * dz.length());
            prop_assert!(dx.dot(f[1].y_axis).abs() <= slack,
                "twist {} with turn {}", dx.dot(f[1].y_axis), dz.length());
            prop_assert!((dx.dot(f[1].z_axis) + f[1].x_axis.dot(dz)).abs() <= slack);
        }
    }
}

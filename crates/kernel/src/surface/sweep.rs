//! Sweeps: profile curves carried along a rail on its perpendicular frames (the surfaces of
//! Grasshopper's Sweep1 and Pipe).
//!
//! **The exact surface.** Each control point `P` of a profile has coordinates `(α, β, γ)` in the
//! rail's perpendicular frame `(x, y, z)` at the rail parameter where the profile sits
//! (`curve/frames.rs`: `z` the tangent, `x` carried without turning). Moving the frame along the
//! rail carries the point to `Q(t) = C(t) + α x(t) + β y(t) + γ z(t)`, so every isocurve of
//! constant `t` is the profile moved rigidly, with the profile's knots and weights. With several
//! profiles the coordinates are blended along the rail by cubic Hermite pieces through the
//! profiles (slopes by central differences, as Catmull–Rom), and stay those of the first (last)
//! profile before (after) it. On a closed rail whose frames do not return to themselves the
//! closing angle is spread evenly over the rail parameter, so that the sweep closes.
//!
//! **Its NURBS form.** The surface has `u` along the profile (its degree, knots and weights) and
//! `v` along the rail on the rail's parameters, cubic: between consecutive rail parameters every
//! control point follows the cubic Hermite curve through `Q` and its derivative
//! `Q' = C' + α x' + β y' + γ T' (+ α' x + β' y + γ' z)`, with `x' = −(x · T') T`,
//! `T' = (C'' − (C'' · T) T) / |C'|`. Because the weights do not change along `v`, a surface
//! point is a convex combination of these control points, so it lies within the largest control
//! point error of the exact sweep. The rail is cut at its spans (and at the profiles), and each
//! piece is halved until the Hermite curves are within the tolerance of `Q` at a quarter, half
//! and three quarters of it (the error of a cubic Hermite piece is largest in its middle and
//! falls as the fourth power of its length). Joints where the derivatives agree on both sides
//! become double knots (C¹); the others stay triple.
//!
//! **Ends.** A piece ends square (the profile where the frame puts it), projected along the
//! rail's tangent onto a plane (a mitre: exact for straight pieces, the trimmed extension of
//! the sweep), or rotated about the rail point onto a plane.

use crate::curve::frames::FrameTrack;
use crate::curve::nurbs::basis;
use crate::geometry::tolerance::ZERO_TOLERANCE;
use crate::{Curve, Error, Interval, NurbsCurve, NurbsSurface, Point3, Result, Vector3};

/// The most spans (in `v`) a swept surface gets.
pub const MAX_SWEEP_SPANS: usize = 100_000;

/// How many times a piece of the rail is halved at most.
const MAX_HALVINGS: u32 = 40;

/// How one end of a swept piece is finished.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum SweepEnd {
    /// The profile where the frame puts it, perpendicular to the rail.
    Square,
    /// The profile's control points moved along the rail's tangent onto the plane through
    /// `point` with normal `normal` (a mitre at a kink).
    Projected {
        /// A point of the plane (the kink).
        point: Point3,
        /// The plane's normal.
        normal: Vector3,
    },
    /// The profile turned about `point` by the smallest rotation that takes the rail's tangent
    /// onto `normal`, so that it lies in the plane with that normal.
    Rotated {
        /// The centre of the rotation (the kink).
        point: Point3,
        /// The unit normal of the plane the profile is turned onto.
        normal: Vector3,
    },
}

impl SweepEnd {
    /// The control point `q` finished at a rail point with unit tangent `z`.
    fn apply(self, q: Point3, z: Vector3) -> Point3 {
        match self {
            SweepEnd::Square => q,
            SweepEnd::Projected { point, normal } => {
                let along = z.dot(normal);
                if along.abs() <= ZERO_TOLERANCE {
                    return q;
                }
                q - z * ((q - point).dot(normal) / along)
            }
            SweepEnd::Rotated { point, normal } => {
                point + crate::curve::frames::rotated_minimally(q - point, z, normal)
            }
        }
    }
}

/// The profiles of a sweep in the rail's frames: the shared NURBS structure (degree, knots,
/// weights in `u`) and the local coordinates of every control point at each profile's rail
/// parameter.
#[derive(Clone, Debug)]
pub(crate) struct SweepShape {
    degree: usize,
    knots: Vec<f64>,
    weights: Vec<f64>,
    /// Rail parameters of the profiles, increasing.
    params: Vec<f64>,
    /// Per profile, the local coordinates `(α, β, γ)` of its control points.
    coords: Vec<Vec<Vector3>>,
    /// Per profile, the slopes of the coordinates along the rail parameter.
    slopes: Vec<Vec<Vector3>>,
}

/// The rail of a sweep: its NURBS form, its perpendicular frames and the closing twist.
pub(crate) struct SweepRail<'a> {
    pub(crate) curve: &'a NurbsCurve,
    pub(crate) track: FrameTrack<'a>,
    /// Radians of extra turn about the tangent per unit of rail parameter.
    pub(crate) twist_rate: f64,
}

/// Values of one row of control points: positions and derivatives along the rail.
#[derive(Clone)]
struct Row {
    points: Vec<Point3>,
    derivatives: Vec<Vector3>,
    /// The rail's unit tangent.
    z: Vector3,
}

impl<'a> SweepRail<'a> {
    /// The rail `curve` (wrapped as `wrapper`, the [`Curve`] whose frames are marched), with the
    /// closing twist when the rail is closed and smooth at its seam.
    pub(crate) fn new(curve: &'a NurbsCurve, wrapper: &'a Curve) -> Result<Self> {
        let track = FrameTrack::new(wrapper)?;
        let d = curve.domain();
        let mut twist_rate = 0.0;
        if wrapper.is_closed() {
            let (z0, x0) = track.axes_at(d.t0)?;
            let (z1, x1) = track.axes_at(d.t1)?;
            if z0.dot(z1) > 1.0 - 1e-12 {
                // The angle from the end frame's x to the start frame's, about the tangent.
                let angle = z1.dot(x1.cross(x0)).atan2(x1.dot(x0));
                twist_rate = angle / d.length();
            }
        }
        Ok(Self {
            curve,
            track,
            twist_rate,
        })
    }

    /// The frame `(x, y, z)` at `t` with the twist, its derivatives `(x', y')` and `T'`, the
    /// rail point and `C'`, with one-sided values from span `span` (and from the left at a
    /// kink when `left`).
    fn frame(&self, t: f64, span: usize, left: bool) -> Result<RailFrame> {
        let mut d = [Vector3::ZERO; 3];
        self.curve.derivatives_in_span(span, t, &mut d);
        let (z, x) = if left {
            self.track.axes_from_left(t)?
        } else {
            self.track.axes_at(t)?
        };
        let y = z.cross(x);
        let phi = self.twist_rate * (t - self.curve.domain().t0);
        let (sin, cos) = phi.sin_cos();
        let (x, y) = (x * cos + y * sin, y * cos - x * sin);
        let speed = d[1].length();
        if speed.is_nan() || speed <= 0.0 {
            return Err(Error::Degenerate { what: "sweep rail" });
        }
        let dz = (d[2] - z * d[2].dot(z)) / speed;
        let w = self.twist_rate;
        Ok(RailFrame {
            point: Point3::from_vector(d[0]),
            velocity: d[1],
            x,
            y,
            z,
            dx: y * w - z * x.dot(dz),
            dy: -(x * w) - z * y.dot(dz),
            dz,
        })
    }
}

/// The frame of a rail at one parameter with its derivatives.
struct RailFrame {
    point: Point3,
    velocity: Vector3,
    x: Vector3,
    y: Vector3,
    z: Vector3,
    dx: Vector3,
    dy: Vector3,
    dz: Vector3,
}

impl SweepShape {
    /// The shape of `profiles` placed at the rail parameters `params` (increasing): the profiles
    /// are made compatible and their control points expressed in the rail's frames there.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] for no profiles or parameters that do not increase; the errors of
    /// [`NurbsCurve::make_compatible`] and of the frames.
    pub(crate) fn new(
        rail: &SweepRail<'_>,
        profiles: &[NurbsCurve],
        params: &[f64],
    ) -> Result<Self> {
        if profiles.is_empty() || profiles.len() != params.len() {
            return Err(Error::InvalidInput(
                "a sweep needs one rail parameter per profile".into(),
            ));
        }
        if params.windows(2).any(|w| w[1] <= w[0]) {
            return Err(Error::InvalidInput(
                "two sweep profiles sit at the same place on the rail".into(),
            ));
        }
        let curves = if profiles.len() == 1 {
            vec![profiles[0].clone()]
        } else {
            NurbsCurve::make_compatible(profiles)?
        };
        let mut coords = Vec::with_capacity(curves.len());
        for (c, &t) in curves.iter().zip(params) {
            let span = basis::span_index(rail.curve.degree(), rail.curve.knots(), t);
            let f = rail.frame(t, span, false)?;
            coords.push(
                c.points()
                    .iter()
                    .map(|&p| {
                        let v = p - f.point;
                        Vector3::new(v.dot(f.x), v.dot(f.y), v.dot(f.z))
                    })
                    .collect::<Vec<_>>(),
            );
        }
        let n = params.len();
        let slopes = (0..n)
            .map(|k| {
                let (a, b) = (k.saturating_sub(1), (k + 1).min(n - 1));
                if a == b {
                    return vec![Vector3::ZERO; coords[k].len()];
                }
                let h = params[b] - params[a];
                coords[a]
                    .iter()
                    .zip(&coords[b])
                    .map(|(&p, &q)| (q - p) / h)
                    .collect()
            })
            .collect();
        Ok(Self {
            degree: curves[0].degree(),
            knots: curves[0].knots().to_vec(),
            weights: curves[0].weights().to_vec(),
            params: params.to_vec(),
            coords,
            slopes,
        })
    }

    /// The profile parameters strictly inside `interval`.
    fn breaks_in(&self, interval: Interval) -> impl Iterator<Item = f64> + '_ {
        self.params
            .iter()
            .copied()
            .filter(move |&t| t > interval.t0 && t < interval.t1)
    }

    /// The local coordinates and their derivatives at `t`, from the left of a profile's
    /// parameter when `left`.
    fn at(&self, t: f64, left: bool) -> (Vec<Vector3>, Vec<Vector3>) {
        let n = self.params.len();
        let count = self.coords[0].len();
        let zero = vec![Vector3::ZERO; count];
        if n == 1 || t < self.params[0] || (t == self.params[0] && left) {
            return (self.coords[0].clone(), zero);
        }
        if t > self.params[n - 1] || (t == self.params[n - 1] && !left) {
            return (self.coords[n - 1].clone(), zero);
        }
        // The piece [params[k], params[k + 1]] holding t (the one before it when at a profile
        // from the left).
        let mut k = self.params.partition_point(|&p| p <= t).saturating_sub(1);
        if left && t == self.params[k] && k > 0 {
            k -= 1;
        }
        k = k.min(n - 2);
        let h = self.params[k + 1] - self.params[k];
        let s = (t - self.params[k]) / h;
        let (h00, h10, h01, h11) = hermite(s);
        let (d00, d10, d01, d11) = hermite_slope(s);
        let mut values = Vec::with_capacity(count);
        let mut slopes = Vec::with_capacity(count);
        for i in 0..count {
            let (p0, p1) = (self.coords[k][i], self.coords[k + 1][i]);
            let (m0, m1) = (self.slopes[k][i] * h, self.slopes[k + 1][i] * h);
            values.push(p0 * h00 + m0 * h10 + p1 * h01 + m1 * h11);
            slopes.push((p0 * d00 + m0 * d10 + p1 * d01 + m1 * d11) / h);
        }
        (values, slopes)
    }

    /// The control points of the swept profile at `t` and their derivatives along the rail.
    fn row(&self, rail: &SweepRail<'_>, t: f64, span: usize, left: bool) -> Result<Row> {
        let f = rail.frame(t, span, left)?;
        let (c, dc) = self.at(t, left);
        let mut points = Vec::with_capacity(c.len());
        let mut derivatives = Vec::with_capacity(c.len());
        for (v, dv) in c.iter().zip(&dc) {
            points.push(f.point + f.x * v.x + f.y * v.y + f.z * v.z);
            derivatives.push(
                f.velocity
                    + f.dx * v.x
                    + f.dy * v.y
                    + f.dz * v.z
                    + f.x * dv.x
                    + f.y * dv.y
                    + f.z * dv.z,
            );
        }
        Ok(Row {
            points,
            derivatives,
            z: f.z,
        })
    }

    /// The profile as the sweep carries it to `t` (from the left of a kink when `left`),
    /// finished by `end`.
    pub(crate) fn finished_profile_at(
        &self,
        rail: &SweepRail<'_>,
        t: f64,
        left: bool,
        end: SweepEnd,
    ) -> Result<NurbsCurve> {
        let c = rail.curve;
        let span = if left {
            // The span that ends at t.
            let span = basis::span_index(c.degree(), c.knots(), t);
            let mut s = span;
            while s > c.degree() - 1 && c.knots()[s] >= t {
                s -= 1;
            }
            if c.knots()[s] < t { s } else { span }
        } else {
            basis::span_index(c.degree(), c.knots(), t)
        };
        let row = self.row(rail, t, span, left)?;
        let points = row.points.iter().map(|&p| end.apply(p, row.z)).collect();
        NurbsCurve::new(
            self.degree,
            points,
            self.weights.clone(),
            self.knots.clone(),
        )
    }

    /// The profile as the sweep carries it to `t`.
    pub(crate) fn profile_at(&self, rail: &SweepRail<'_>, t: f64) -> Result<NurbsCurve> {
        self.finished_profile_at(rail, t, false, SweepEnd::Square)
    }

    /// The control points of the swept profile at `t` (inside a span).
    fn points_at(&self, rail: &SweepRail<'_>, t: f64, span: usize) -> Result<Vec<Point3>> {
        Ok(self.row(rail, t, span, false)?.points)
    }
}

/// The cubic Hermite basis `(h00, h10, h01, h11)` at `s`.
fn hermite(s: f64) -> (f64, f64, f64, f64) {
    let (s2, s3) = (s * s, s * s * s);
    (
        2.0 * s3 - 3.0 * s2 + 1.0,
        s3 - 2.0 * s2 + s,
        3.0 * s2 - 2.0 * s3,
        s3 - s2,
    )
}

/// The derivatives of the Hermite basis at `s`.
fn hermite_slope(s: f64) -> (f64, f64, f64, f64) {
    let s2 = s * s;
    (
        6.0 * s2 - 6.0 * s,
        3.0 * s2 - 4.0 * s + 1.0,
        6.0 * s - 6.0 * s2,
        3.0 * s2 - 2.0 * s,
    )
}

/// One accepted piece of the fit: its parameters and the rows at its ends (start from the
/// right, end from the left).
struct Fitted {
    t0: f64,
    t1: f64,
    start: Row,
    end: Row,
}

/// Sweeps `shape` along the piece `interval` of `rail` (no kinks inside), within `tolerance`,
/// with the given ends: `u` along the profile, `v` on `interval`.
///
/// # Errors
/// [`Error::InvalidInput`] for a non-positive tolerance or more than [`MAX_SWEEP_SPANS`] spans;
/// [`Error::Degenerate`] where the rail stops (zero derivative).
pub(crate) fn sweep_piece(
    rail: &SweepRail<'_>,
    shape: &SweepShape,
    interval: Interval,
    ends: [SweepEnd; 2],
    closed: bool,
    tolerance: f64,
) -> Result<NurbsSurface> {
    if !(tolerance > 0.0 && tolerance.is_finite()) {
        return Err(Error::InvalidInput(format!(
            "the sweep tolerance must be positive, got {tolerance}"
        )));
    }
    let c = rail.curve;
    let mut breaks: Vec<f64> = c
        .span_breaks()
        .into_iter()
        .chain(shape.breaks_in(interval))
        .filter(|&t| t > interval.t0 && t < interval.t1)
        .collect();
    breaks.push(interval.t0);
    breaks.push(interval.t1);
    breaks.sort_by(f64::total_cmp);
    breaks.dedup();
    let mut fitted: Vec<Fitted> = Vec::new();
    for w in breaks.windows(2) {
        let span = basis::span_index(c.degree(), c.knots(), 0.5 * (w[0] + w[1]));
        let start = shape.row(rail, w[0], span, false)?;
        let end = shape.row(rail, w[1], span, true)?;
        // Depth-first halving, left half first, so that the pieces come out in order.
        let mut stack = vec![(w[0], w[1], start, end, 0u32)];
        while let Some((t0, t1, start, end, depth)) = stack.pop() {
            let h = t1 - t0;
            let mut error = 0.0f64;
            for s in [0.25, 0.5, 0.75] {
                let exact = shape.points_at(rail, t0 + s * h, span)?;
                let (h00, h10, h01, h11) = hermite(s);
                for (i, q) in exact.iter().enumerate() {
                    let guess = start.points[i].to_vector() * h00
                        + start.derivatives[i] * (h * h10)
                        + end.points[i].to_vector() * h01
                        + end.derivatives[i] * (h * h11);
                    error = error.max(Point3::from_vector(guess).distance(*q));
                }
            }
            if error <= tolerance || depth >= MAX_HALVINGS {
                fitted.push(Fitted { t0, t1, start, end });
                if fitted.len() > MAX_SWEEP_SPANS {
                    return Err(Error::InvalidInput(format!(
                        "the sweep needs more than {MAX_SWEEP_SPANS} spans for the tolerance \
                         {tolerance}"
                    )));
                }
                continue;
            }
            let mid = t0 + 0.5 * h;
            let m_left = shape.row(rail, mid, span, false)?;
            let m_right = m_left.clone();
            stack.push((mid, t1, m_right, end, depth + 1));
            stack.push((t0, mid, start, m_left, depth + 1));
        }
    }
    assemble(shape, &mut fitted, ends, closed)
}

/// The surface through the fitted pieces: Bézier rows per piece, joints with agreeing
/// derivatives reduced to double knots, ends finished.
fn assemble(
    shape: &SweepShape,
    fitted: &mut [Fitted],
    ends: [SweepEnd; 2],
    closed: bool,
) -> Result<NurbsSurface> {
    let count_u = shape.coords[0].len();
    let last = fitted.len() - 1;
    // Finish the ends: positions moved, derivatives kept (so that straight pieces keep straight
    // rulings).
    let (z0, z1) = (fitted[0].start.z, fitted[last].end.z);
    for p in &mut fitted[0].start.points {
        *p = ends[0].apply(*p, z0);
    }
    for p in &mut fitted[last].end.points {
        *p = ends[1].apply(*p, z1);
    }
    if closed {
        fitted[last].end.points = fitted[0].start.points.clone();
        fitted[last].end.derivatives = fitted[0].start.derivatives.clone();
    }
    let scale = fitted
        .iter()
        .flat_map(|f| f.start.points.iter())
        .fold(1.0f64, |m, p| m.max(p.to_vector().length()));
    let mut rows: Vec<Vec<Point3>> = Vec::with_capacity(2 * fitted.len() + 2);
    let mut knots = vec![fitted[0].t0; 3];
    rows.push(fitted[0].start.points.clone());
    for (k, f) in fitted.iter().enumerate() {
        let h = f.t1 - f.t0;
        rows.push(
            f.start
                .points
                .iter()
                .zip(&f.start.derivatives)
                .map(|(&p, &d)| p + d * (h / 3.0))
                .collect(),
        );
        rows.push(
            f.end
                .points
                .iter()
                .zip(&f.end.derivatives)
                .map(|(&p, &d)| p - d * (h / 3.0))
                .collect(),
        );
        if k == last {
            rows.push(f.end.points.clone());
            knots.extend([f.t1; 3]);
        } else {
            let next = &fitted[k + 1];
            let smooth = f
                .end
                .derivatives
                .iter()
                .zip(&next.start.derivatives)
                .all(|(a, b)| (*a - *b).length() <= 1e-12 * scale / (f.t1 - f.t0).max(1e-300));
            if smooth {
                knots.extend([f.t1; 2]);
            } else {
                rows.push(next.start.points.clone());
                knots.extend([f.t1; 3]);
            }
        }
    }
    let count_v = rows.len();
    let mut points = Vec::with_capacity(count_u * count_v);
    let mut weights = Vec::with_capacity(count_u * count_v);
    for i in 0..count_u {
        for row in &rows {
            points.push(row[i]);
            weights.push(shape.weights[i]);
        }
    }
    NurbsSurface::from_flat(
        [shape.degree, 3],
        [count_u, count_v],
        points,
        weights,
        [shape.knots.clone(), knots],
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Circle, Plane, SurfaceDirection};
    use std::f64::consts::TAU;

    fn wavy_rail() -> NurbsCurve {
        NurbsCurve::create(
            &[
                Point3::new(0.0, 0.0, 0.0),
                Point3::new(2.0, 1.0, 1.0),
                Point3::new(4.0, -1.0, 2.0),
                Point3::new(6.0, 2.0, 1.0),
                Point3::new(8.0, 0.0, 3.0),
            ],
            3,
            false,
        )
        .unwrap()
    }

    /// A circle of radius `r` around the rail's start, perpendicular to it.
    fn start_circle(rail: &NurbsCurve, r: f64) -> NurbsCurve {
        let wrapper = Curve::from(rail.clone());
        let f = wrapper.perpendicular_frame_at(rail.domain().t0).unwrap();
        Circle::new(f, r).unwrap().to_nurbs()
    }

    #[test]
    fn a_pipe_surface_stays_at_its_radius() {
        let rail = wavy_rail();
        let wrapper = Curve::from(rail.clone());
        let r = 0.3;
        let sweep = SweepRail::new(&rail, &wrapper).unwrap();
        let shape =
            SweepShape::new(&sweep, &[start_circle(&rail, r)], &[rail.domain().t0]).unwrap();
        let tol = 1e-7;
        let s = sweep_piece(
            &sweep,
            &shape,
            rail.domain(),
            [SweepEnd::Square; 2],
            false,
            tol,
        )
        .unwrap();
        // Every surface point at v = t lies at the radius from C(t), in the normal plane there.
        let (du, dv) = (s.domain_u(), s.domain_v());
        assert_eq!(dv, rail.domain());
        let mut worst = 0.0f64;
        for i in 0..=40 {
            let t = dv.parameter_at(f64::from(i) / 40.0);
            let c = rail.point_at(t);
            let z = rail.tangent_at(t).unwrap();
            for j in 0..=16 {
                let p = s.point_at(du.parameter_at(f64::from(j) / 16.0), t);
                worst = worst.max(((p - c).length() - r).abs());
                worst = worst.max((p - c).dot(z).abs());
            }
        }
        assert!(worst < tol, "{worst}");
        // The first row is the profile itself.
        let first = s.isocurve(SurfaceDirection::U, dv.t0).unwrap();
        assert!(
            first
                .point_at(1.0)
                .distance(start_circle(&rail, r).point_at(1.0))
                < 1e-12
        );
    }

    #[test]
    fn a_straight_rail_with_mitred_ends_is_exact() {
        let rail =
            NurbsCurve::create(&[Point3::ORIGIN, Point3::new(0.0, 0.0, 4.0)], 1, false).unwrap();
        let wrapper = Curve::from(rail.clone());
        let sweep = SweepRail::new(&rail, &wrapper).unwrap();
        let square = crate::Polyline::new(vec![
            Point3::new(-1.0, -1.0, 0.0),
            Point3::new(1.0, -1.0, 0.0),
            Point3::new(1.0, 1.0, 0.0),
            Point3::new(-1.0, 1.0, 0.0),
            Point3::new(-1.0, -1.0, 0.0),
        ])
        .unwrap()
        .to_nurbs();
        let shape = SweepShape::new(&sweep, &[square], &[0.0]).unwrap();
        let normal = Vector3::new(0.0, 1.0, 1.0).try_normalize().unwrap();
        let end = SweepEnd::Projected {
            point: Point3::new(0.0, 0.0, 4.0),
            normal,
        };
        let s = sweep_piece(
            &sweep,
            &shape,
            rail.domain(),
            [SweepEnd::Square, end],
            false,
            1e-9,
        )
        .unwrap();
        assert_eq!(s.count_v(), 4, "one span");
        // The end edge lies in the mitre plane; the sides stay vertical.
        let top = s.isocurve(SurfaceDirection::U, 1.0).unwrap();
        for k in 0..=8 {
            let p = top.point_at(top.domain().parameter_at(f64::from(k) / 8.0));
            assert!((p - Point3::new(0.0, 0.0, 4.0)).dot(normal).abs() < 1e-12);
        }
        let p = s.point_at(0.5, 0.5);
        assert!((p.x - 0.0).abs() < 1e-12 && (p.y + 1.0).abs() < 1e-12);
    }

    #[test]
    fn a_closed_rail_gives_a_closed_sweep() {
        // A closed, non-planar periodic cubic: its frames do not return to themselves, the
        // twist spreads the difference.
        let pts = [
            Point3::new(3.0, 0.0, 0.0),
            Point3::new(0.0, 3.0, 1.0),
            Point3::new(-3.0, 0.0, 0.0),
            Point3::new(0.0, -3.0, -1.0),
        ];
        let rail = NurbsCurve::create(&pts, 3, true).unwrap();
        let wrapper = Curve::from(rail.clone());
        let sweep = SweepRail::new(&rail, &wrapper).unwrap();
        assert!(sweep.twist_rate != 0.0);
        let shape =
            SweepShape::new(&sweep, &[start_circle(&rail, 0.2)], &[rail.domain().t0]).unwrap();
        let s = sweep_piece(
            &sweep,
            &shape,
            rail.domain(),
            [SweepEnd::Square; 2],
            true,
            1e-8,
        )
        .unwrap();
        assert!(s.is_closed(SurfaceDirection::V, 1e-12));
        assert!(s.is_closed(SurfaceDirection::U, 1e-12));
        let _ = (TAU, Plane::WORLD_XY);
    }

    #[test]
    fn two_profiles_blend() {
        let rail = wavy_rail();
        let wrapper = Curve::from(rail.clone());
        let sweep = SweepRail::new(&rail, &wrapper).unwrap();
        let d = rail.domain();
        let a = start_circle(&rail, 0.2);
        let f = wrapper.perpendicular_frame_at(d.t1).unwrap();
        let b = Circle::new(f, 0.6).unwrap().to_nurbs();
        let shape = SweepShape::new(&sweep, &[a, b], &[d.t0, d.t1]).unwrap();
        let s = sweep_piece(&sweep, &shape, d, [SweepEnd::Square; 2], false, 1e-8).unwrap();
        // The radius grows linearly from 0.2 to 0.6 along the rail parameter.
        for k in 0..=4 {
            let t = d.parameter_at(f64::from(k) / 4.0);
            let p = s.point_at(s.domain_u().t0, t);
            let r = p.distance(rail.point_at(t));
            assert!(
                (r - (0.2 + 0.4 * f64::from(k) / 4.0)).abs() < 1e-7,
                "{k}: {r}"
            );
        }
    }
}

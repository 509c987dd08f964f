//! The curve value that the runtime stores in data trees: an enum over the kernel's curve types.
//!
//! Lines, polylines, circles and arcs keep their exact representation (and exact evaluation,
//! lengths and closest points); everything else is a NURBS curve. Bézier and Hermite curves
//! convert to NURBS. Each non-NURBS variant carries its curve domain, mapped linearly onto its
//! natural parameter (the line's `[0, 1]`, the polyline's vertex index, the circle's and arc's
//! angle), so every curve can be reparameterized as in Rhino, where a line has the domain
//! `[0, length]`, a polyline `[0, n − 1]`, a circle `[0, 2π]` and an arc its angle interval.
//!
//! Measurements (length, division, closest point) are in `curve_measure.rs`.

pub(crate) mod arc;
pub(crate) mod arc_fit;
pub(crate) mod arc_length;
pub(crate) mod bezier;
pub(crate) mod bezier_piece;
pub(crate) mod circle;
pub(crate) mod circle_fit;
pub(crate) mod closest_point;
pub(crate) mod containment;
pub(crate) mod continuity;
pub(crate) mod ellipse;
pub(crate) mod equidistant;
pub(crate) mod extend;
pub(crate) mod fillet;
pub(crate) mod fit;
pub(crate) mod frames;
pub(crate) mod hermite;
pub(crate) mod join;
pub(crate) mod kinks;
pub(crate) mod length_table;
pub(crate) mod line;
pub(crate) mod loop_plane;
pub(crate) mod measure;
pub(crate) mod nurbs;
pub(crate) mod offset;
pub(crate) mod polyline;
pub(crate) mod region;
pub(crate) mod split;

use std::f64::consts::{FRAC_PI_2, TAU};

use crate::curve::nurbs::{curvature_vector, frame_from, signed_curvature};
use crate::{
    Arc, Bezier, Circle, CubicHermite, Error, Interval, Line, NurbsCurve, Plane, Point3, Polyline,
    Result, Transform, Vector3,
};

/// A curve of any kind the kernel supports.
#[derive(Clone, Debug, PartialEq)]
pub enum Curve {
    /// A line segment; its natural parameter `[0, 1]` is mapped onto `domain`.
    Line {
        /// The segment.
        line: Line,
        /// The curve domain, `[0, length]` by default.
        domain: Interval,
    },
    /// A polyline; its vertex index is mapped onto `domain`.
    Polyline {
        /// The polyline.
        polyline: Polyline,
        /// The curve domain, `[0, n − 1]` by default.
        domain: Interval,
    },
    /// A full circle; its angle `[0, 2π]` is mapped onto `domain`.
    Circle {
        /// The circle.
        circle: Circle,
        /// The curve domain, `[0, 2π]` by default.
        domain: Interval,
    },
    /// A circular arc; its angle interval is mapped onto `domain`.
    Arc {
        /// The arc.
        arc: Arc,
        /// The curve domain, the arc's angle interval by default.
        domain: Interval,
    },
    /// A NURBS curve (its own knots define its domain).
    Nurbs(NurbsCurve),
}

impl From<Line> for Curve {
    fn from(line: Line) -> Self {
        Self::Line {
            line,
            domain: line.curve_domain(),
        }
    }
}

impl From<Polyline> for Curve {
    fn from(polyline: Polyline) -> Self {
        let domain = polyline.domain();
        Self::Polyline { polyline, domain }
    }
}

impl From<Circle> for Curve {
    fn from(circle: Circle) -> Self {
        Self::Circle {
            circle,
            domain: circle.domain(),
        }
    }
}

impl From<Arc> for Curve {
    fn from(arc: Arc) -> Self {
        Self::Arc {
            arc,
            domain: arc.domain(),
        }
    }
}

impl From<NurbsCurve> for Curve {
    fn from(curve: NurbsCurve) -> Self {
        Self::Nurbs(curve)
    }
}

impl From<Bezier> for Curve {
    fn from(curve: Bezier) -> Self {
        Self::Nurbs(curve.to_nurbs())
    }
}

impl TryFrom<CubicHermite> for Curve {
    type Error = Error;

    /// The Hermite cubic's NURBS form; fails for non-finite input.
    fn try_from(curve: CubicHermite) -> Result<Self> {
        Ok(Self::Nurbs(curve.to_nurbs()?))
    }
}

/// The natural parameter interval of a non-NURBS variant and its curve domain.
#[derive(Clone, Copy, Debug)]
pub(crate) struct ParameterMap {
    pub(crate) natural: Interval,
    pub(crate) domain: Interval,
}

impl ParameterMap {
    /// The natural parameter at curve parameter `t`.
    #[inline]
    pub(crate) fn to_natural(self, t: f64) -> f64 {
        self.natural
            .parameter_at((t - self.domain.t0) / self.domain.length())
    }

    /// The curve parameter at natural parameter `s`.
    #[inline]
    pub(crate) fn to_curve(self, s: f64) -> f64 {
        self.domain
            .parameter_at((s - self.natural.t0) / self.natural.length())
    }

    /// `ds/dt`.
    #[inline]
    pub(crate) fn scale(self) -> f64 {
        self.natural.length() / self.domain.length()
    }
}

impl Curve {
    /// The curve domain.
    pub fn domain(&self) -> Interval {
        match self {
            Self::Line { domain, .. }
            | Self::Polyline { domain, .. }
            | Self::Circle { domain, .. }
            | Self::Arc { domain, .. } => *domain,
            Self::Nurbs(c) => c.domain(),
        }
    }

    /// The map between curve parameters and natural parameters (`None` for NURBS curves).
    pub(crate) fn parameter_map(&self) -> Option<ParameterMap> {
        let (natural, domain) = match self {
            Self::Line { domain, .. } => (Interval::UNIT, *domain),
            Self::Polyline { polyline, domain } => (polyline.domain(), *domain),
            Self::Circle { domain, .. } => (Interval::new(0.0, TAU), *domain),
            Self::Arc { arc, domain } => (arc.angle, *domain),
            Self::Nurbs(_) => return None,
        };
        Some(ParameterMap { natural, domain })
    }

    /// Whether the curve's data are finite and its domain increasing.
    pub fn is_valid(&self) -> bool {
        let d = self.domain();
        if !(d.is_finite() && d.t0 < d.t1) {
            return false;
        }
        match self {
            Self::Line { line, .. } => line.is_finite(),
            Self::Polyline { polyline, .. } => polyline.points().iter().all(|p| p.is_finite()),
            Self::Circle { circle, .. } => circle.plane.is_finite() && circle.radius > 0.0,
            Self::Arc { arc, .. } => {
                arc.circle.plane.is_finite() && arc.circle.radius > 0.0 && arc.angle.is_finite()
            }
            Self::Nurbs(c) => c.is_valid(),
        }
    }

    /// The degree of the curve's NURBS form (1 for lines and polylines, 2 for circles and
    /// arcs).
    pub fn degree(&self) -> usize {
        match self {
            Self::Line { .. } | Self::Polyline { .. } => 1,
            Self::Circle { .. } | Self::Arc { .. } => 2,
            Self::Nurbs(c) => c.degree(),
        }
    }

    /// The point at `t`.
    pub fn point_at(&self, t: f64) -> Point3 {
        match self {
            Self::Line { line, domain } => line.point_at((t - domain.t0) / domain.length()),
            Self::Polyline { polyline, .. } => polyline.point_at(self.map_natural(t)),
            Self::Circle { circle, .. } => circle.point_at(self.map_natural(t)),
            Self::Arc { arc, .. } => arc.point_at(self.map_natural(t)),
            Self::Nurbs(c) => c.point_at(t),
        }
    }

    fn map_natural(&self, t: f64) -> f64 {
        self.parameter_map().map_or(t, |m| m.to_natural(t))
    }

    /// Evaluates the curve at every parameter of `ts` into `out` (NURBS curves through the
    /// span-reusing batch path of [`NurbsCurve::points_at`]).
    ///
    /// # Errors
    /// [`Error::InvalidInput`] when `ts` and `out` have different lengths.
    pub fn points_at(&self, ts: &[f64], out: &mut [Point3]) -> Result<()> {
        if let Self::Nurbs(c) = self {
            return c.points_at(ts, out);
        }
        if ts.len() != out.len() {
            return Err(Error::InvalidInput(format!(
                "{} parameters for an output buffer of {} points",
                ts.len(),
                out.len()
            )));
        }
        for (o, &t) in out.iter_mut().zip(ts) {
            *o = self.point_at(t);
        }
        Ok(())
    }

    /// The point at the start of the domain.
    pub fn start_point(&self) -> Point3 {
        self.point_at(self.domain().t0)
    }

    /// The point at the end of the domain.
    pub fn end_point(&self) -> Point3 {
        self.point_at(self.domain().t1)
    }

    /// The point and derivatives up to `order` at `t`: element 0 is the point (as a vector from
    /// the origin), element `k` the `k`-th derivative with respect to the curve parameter.
    /// At a polyline vertex or a NURBS knot the derivatives are those from the right (from the
    /// left at the end of the domain).
    pub fn derivatives_at(&self, t: f64, order: usize) -> Vec<Vector3> {
        let mut out = vec![Vector3::ZERO; order + 1];
        match self {
            Self::Nurbs(c) => c.derivatives_into(t, &mut out),
            Self::Line { line, .. } => {
                let map = self.parameter_map().expect("line");
                out[0] = line.point_at(map.to_natural(t)).to_vector();
                if order >= 1 {
                    out[1] = line.direction() * map.scale();
                }
            }
            Self::Polyline { polyline, .. } => {
                let map = self.parameter_map().expect("polyline");
                let s = map.to_natural(t);
                let (i, _) = polyline.segment_parameter(s);
                out[0] = polyline.point_at(s).to_vector();
                if order >= 1 {
                    out[1] = polyline.segment(i).direction() * map.scale();
                }
            }
            Self::Circle { circle, .. }
            | Self::Arc {
                arc: Arc { circle, .. },
                ..
            } => {
                let map = self.parameter_map().expect("circle");
                let s = map.to_natural(t);
                let k = map.scale();
                out[0] = circle.point_at(s).to_vector();
                let (x, y, r) = (circle.plane.x_axis, circle.plane.y_axis, circle.radius);
                let mut factor = 1.0;
                for (n, d) in out.iter_mut().enumerate().skip(1) {
                    factor *= k;
                    // d^n/ds^n (r cos s, r sin s) = r (cos(s + nπ/2), sin(s + nπ/2)).
                    let (sin, cos) = (s + n as f64 * FRAC_PI_2).sin_cos();
                    *d = (x * cos + y * sin) * (r * factor);
                }
            }
        }
        out
    }

    /// The point and first and second derivatives at `t`.
    pub fn point_and_derivatives_at(&self, t: f64) -> (Point3, Vector3, Vector3) {
        if let Self::Nurbs(c) = self {
            return c.point_and_derivatives_at(t);
        }
        let d = self.derivatives_at(t, 2);
        (Point3::from_vector(d[0]), d[1], d[2])
    }

    /// The unit tangent at `t`, or `None` where it is undefined (a zero-length segment, a
    /// collapsed NURBS curve).
    pub fn tangent_at(&self, t: f64) -> Option<Vector3> {
        match self {
            Self::Nurbs(c) => c.tangent_at(t),
            _ => self.point_and_derivatives_at(t).1.try_normalize(),
        }
    }

    /// The curvature vector at `t` (towards the centre of curvature, length `1/r`; zero on
    /// straight pieces), or `None` where the tangent is undefined.
    pub fn curvature_at(&self, t: f64) -> Option<Vector3> {
        match self {
            Self::Nurbs(c) => c.curvature_at(t),
            Self::Line { .. } | Self::Polyline { .. } => self.tangent_at(t).map(|_| Vector3::ZERO),
            Self::Circle { circle, .. }
            | Self::Arc {
                arc: Arc { circle, .. },
                ..
            } => Some(circle.curvature_at(self.map_natural(t))),
        }
    }

    /// The signed curvature at `t` about `normal` (positive when the curve turns
    /// counter-clockwise seen from the normal's side), or `None` where undefined.
    pub fn signed_curvature_at(&self, t: f64, normal: Vector3) -> Option<f64> {
        let (_, d1, d2) = self.point_and_derivatives_at(t);
        signed_curvature(d1, d2, normal)
    }

    /// The frame at `t`: x along the tangent, y towards the centre of curvature (or a
    /// perpendicular where the curvature is zero). `None` where the tangent is undefined.
    pub fn frame_at(&self, t: f64) -> Option<Plane> {
        let (p, d1, d2) = self.point_and_derivatives_at(t);
        let tangent = self.tangent_at(t)?;
        frame_from(p, tangent, curvature_vector(d1, d2))
    }

    /// Whether the curve is closed (its end meets its start).
    pub fn is_closed(&self) -> bool {
        match self {
            Self::Line { .. } => false,
            Self::Polyline { polyline, .. } => polyline.is_closed(),
            Self::Circle { .. } => true,
            Self::Arc { arc, .. } => arc.is_circle(),
            Self::Nurbs(c) => c.is_closed(),
        }
    }

    /// Whether the curve is periodic (closed and smooth at its seam, as Rhino's `IsPeriodic`):
    /// circles, full arcs and periodic NURBS curves.
    pub fn is_periodic(&self) -> bool {
        match self {
            Self::Line { .. } | Self::Polyline { .. } => false,
            Self::Circle { .. } => true,
            Self::Arc { arc, .. } => arc.is_circle(),
            Self::Nurbs(c) => c.is_periodic(),
        }
    }

    /// The same curve on the domain `domain`.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] when `domain` is not finite and increasing.
    pub fn reparameterized(&self, domain: Interval) -> Result<Self> {
        if !domain.is_finite() || domain.t0 >= domain.t1 {
            return Err(Error::InvalidInput(format!(
                "domain {} to {} is not increasing",
                domain.t0, domain.t1
            )));
        }
        Ok(match self {
            Self::Line { line, .. } => Self::Line {
                line: *line,
                domain,
            },
            Self::Polyline { polyline, .. } => Self::Polyline {
                polyline: polyline.clone(),
                domain,
            },
            Self::Circle { circle, .. } => Self::Circle {
                circle: *circle,
                domain,
            },
            Self::Arc { arc, .. } => Self::Arc { arc: *arc, domain },
            Self::Nurbs(c) => Self::Nurbs(c.reparameterized(domain)?),
        })
    }

    /// The same curve traced backwards; the domain `[t0, t1]` becomes `[−t1, −t0]`, so the point
    /// at `t` moves to `−t`, as Rhino's `Reverse`.
    pub fn reversed(&self) -> Self {
        let d = self.domain();
        let domain = Interval::new(-d.t1, -d.t0);
        match self {
            Self::Line { line, .. } => Self::Line {
                line: line.reversed(),
                domain,
            },
            Self::Polyline { polyline, .. } => Self::Polyline {
                polyline: polyline.reversed(),
                domain,
            },
            Self::Circle { circle, .. } => Self::Circle {
                circle: circle.reversed(),
                domain,
            },
            Self::Arc { arc, .. } => Self::Arc {
                arc: arc.reversed(),
                domain,
            },
            Self::Nurbs(c) => Self::Nurbs(c.reversed()),
        }
    }

    /// The curve mapped by `transform`, keeping its domain. Circles and arcs stay circles and
    /// arcs under similarities and become NURBS curves otherwise.
    ///
    /// # Errors
    /// [`Error::NotFinite`] for a non-finite transform; the errors of
    /// [`NurbsCurve::transformed`] for projective transforms.
    pub fn transformed(&self, transform: &Transform) -> Result<Self> {
        if !transform.is_finite() {
            return Err(Error::NotFinite { what: "transform" });
        }
        let domain = self.domain();
        Ok(match self {
            Self::Line { line, .. } if is_affine(transform) => Self::Line {
                line: line.transformed(transform),
                domain,
            },
            Self::Polyline { polyline, .. } if is_affine(transform) => Self::Polyline {
                polyline: polyline.transformed(transform),
                domain,
            },
            Self::Circle { circle, .. } => match circle.transformed(transform) {
                Ok(circle) => Self::Circle { circle, domain },
                Err(_) => Self::Nurbs(self.to_nurbs().transformed(transform)?),
            },
            Self::Arc { arc, .. } => match arc.transformed(transform) {
                Ok(arc) => Self::Arc { arc, domain },
                Err(_) => Self::Nurbs(self.to_nurbs().transformed(transform)?),
            },
            _ => Self::Nurbs(self.to_nurbs().transformed(transform)?),
        })
    }

    /// The exact NURBS form on the curve's domain (Rhino's `ToNurbsCurve`): for circles and
    /// arcs Rhino's rational quadratic form, whose knots are mapped onto the domain.
    pub fn to_nurbs(&self) -> NurbsCurve {
        let base = match self {
            Self::Nurbs(c) => return c.clone(),
            Self::Line { line, .. } => line.to_nurbs().unwrap_or_else(|_| {
                // A non-finite line still needs a value; its NURBS form is the degenerate
                // segment at the origin, which callers detect through `is_valid`.
                Line::new(Point3::ORIGIN, Point3::ORIGIN)
                    .to_nurbs()
                    .expect("a finite line has a NURBS form")
            }),
            Self::Polyline { polyline, .. } => polyline.to_nurbs(),
            Self::Circle { circle, .. } => circle.to_nurbs(),
            Self::Arc { arc, .. } => arc.to_nurbs(),
        };
        let domain = self.domain();
        if base.domain() == domain {
            base
        } else {
            base.reparameterized(domain).unwrap_or(base)
        }
    }
}

/// Whether the last row of the matrix is `[0, 0, 0, 1]`.
fn is_affine(t: &Transform) -> bool {
    t.to_rows()[3] == [0.0, 0.0, 0.0, 1.0]
}

#[cfg(test)]
mod tests {
    use super::*;

    fn samples() -> Vec<Curve> {
        let circle = Circle::new(
            Plane::from_normal(Point3::new(1.0, 2.0, 3.0), Vector3::new(0.2, -0.3, 1.0)).unwrap(),
            2.5,
        )
        .unwrap();
        vec![
            Line::new(Point3::new(1.0, 1.0, 0.0), Point3::new(4.0, 5.0, 2.0)).into(),
            Polyline::new(vec![
                Point3::new(0.0, 0.0, 0.0),
                Point3::new(3.0, 0.0, 0.0),
                Point3::new(3.0, 2.0, 1.0),
                Point3::new(-1.0, 2.0, 1.0),
            ])
            .unwrap()
            .into(),
            circle.into(),
            Arc::new(circle, Interval::new(0.3, 4.0)).unwrap().into(),
            NurbsCurve::create(
                &[
                    Point3::new(0.0, 0.0, 0.0),
                    Point3::new(1.0, 3.0, 0.0),
                    Point3::new(4.0, 2.0, 1.0),
                    Point3::new(6.0, 5.0, 0.0),
                    Point3::new(7.0, 1.0, 2.0),
                ],
                3,
                false,
            )
            .unwrap()
            .into(),
        ]
    }

    #[test]
    fn nurbs_forms_trace_the_same_points_at_the_knots() {
        for c in samples() {
            let n = c.to_nurbs();
            assert_eq!(n.domain(), c.domain());
            assert!(n.start_point().distance(c.start_point()) < 1e-12);
            assert!(n.end_point().distance(c.end_point()) < 1e-12);
            for &k in n.knots() {
                assert!(
                    n.point_at(k).distance(c.point_at(k)) < 1e-12,
                    "{c:?} at {k}"
                );
            }
        }
    }

    #[test]
    fn derivatives_match_finite_differences() {
        for c in samples() {
            let c = c.reparameterized(Interval::new(-1.0, 2.0)).unwrap();
            let d = c.domain();
            for i in 1..10 {
                let t = d.parameter_at(i as f64 / 10.0 + 0.013);
                let h = 1e-6;
                let ders = c.derivatives_at(t, 3);
                let fd1 = (c.point_at(t + h) - c.point_at(t - h)) / (2.0 * h);
                assert!(
                    (ders[1] - fd1).length() < 1e-6 * ders[1].length().max(1.0),
                    "{c:?} {t}"
                );
                let fd2 =
                    (c.derivatives_at(t + h, 1)[1] - c.derivatives_at(t - h, 1)[1]) / (2.0 * h);
                assert!(
                    (ders[2] - fd2).length() < 1e-5 * ders[2].length().max(1.0),
                    "{c:?} {t}"
                );
                let fd3 =
                    (c.derivatives_at(t + h, 2)[2] - c.derivatives_at(t - h, 2)[2]) / (2.0 * h);
                assert!(
                    (ders[3] - fd3).length() < 1e-4 * ders[3].length().max(1.0),
                    "{c:?} {t}"
                );
            }
        }
    }

    #[test]
    fn reparameterize_reverse_and_transform_keep_points() {
        let m = Transform::translation(Vector3::new(1.0, -2.0, 0.5));
        for c in samples() {
            let d = c.domain();
            let r = c.reparameterized(Interval::new(0.0, 1.0)).unwrap();
            let v = c.reversed();
            let moved = c.transformed(&m).unwrap();
            assert_eq!(moved.domain(), d);
            assert_eq!(v.domain(), Interval::new(-d.t1, -d.t0));
            for i in 0..=20 {
                let s = i as f64 / 20.0;
                let t = d.parameter_at(s);
                let p = c.point_at(t);
                assert!(r.point_at(s).distance(p) < 1e-12);
                assert!(v.point_at(-t).distance(p) < 1e-12);
                assert!(moved.point_at(t).distance(m.transform_point(p)) < 1e-12);
            }
        }
        assert!(
            samples()[0]
                .reparameterized(Interval::new(1.0, 0.0))
                .is_err()
        );
    }

    #[test]
    fn closedness_and_curvature() {
        let s = samples();
        assert!(!s[0].is_closed());
        assert!(s[2].is_closed() && s[2].is_periodic());
        assert!(!s[3].is_closed());
        assert_eq!(s[0].curvature_at(0.5), Some(Vector3::ZERO));
        let k = s[2].curvature_at(1.0).unwrap();
        assert!((k.length() - 0.4).abs() < 1e-14);
        let n = s[2].to_nurbs();
        let kn = n.curvature_at(1.0).unwrap();
        assert!((kn.length() - 0.4).abs() < 1e-12);
        let f = s[3].frame_at(2.0).unwrap();
        let toward_center = s[2].curvature_at(2.0).unwrap().try_normalize().unwrap();
        assert!(f.y_axis.dot(toward_center) > 1.0 - 1e-12);
    }

    #[test]
    fn batch_points_and_hermite_conversion() {
        for c in samples() {
            let d = c.domain();
            let ts: Vec<f64> = (0..=50).map(|i| d.parameter_at(i as f64 / 50.0)).collect();
            let mut out = vec![Point3::ORIGIN; ts.len()];
            c.points_at(&ts, &mut out).unwrap();
            for (&t, p) in ts.iter().zip(&out) {
                assert!(p.distance(c.point_at(t)) < 1e-12);
            }
            assert!(c.points_at(&ts, &mut out[1..]).is_err());
        }
        let h = CubicHermite::new(
            Point3::ORIGIN,
            Vector3::X,
            Point3::new(1.0, 1.0, 0.0),
            Vector3::Y,
        );
        let c = Curve::try_from(h).unwrap();
        assert!(c.point_at(0.5).distance(h.point_at(0.5)) < 1e-15);
        let bad = CubicHermite::new(
            Point3::ORIGIN,
            Vector3::new(f64::NAN, 0.0, 0.0),
            Point3::ORIGIN,
            Vector3::Y,
        );
        assert!(Curve::try_from(bad).is_err());
    }

    #[test]
    fn non_similarity_turns_circles_into_nurbs() {
        let squash = Transform::from_rows([
            [2.0, 0.0, 0.0, 0.0],
            [0.0, 1.0, 0.0, 0.0],
            [0.0, 0.0, 1.0, 0.0],
            [0.0, 0.0, 0.0, 1.0],
        ]);
        let c: Curve = Circle::new(Plane::WORLD_XY, 1.0).unwrap().into();
        let e = c.transformed(&squash).unwrap();
        assert!(matches!(e, Curve::Nurbs(_)));
        assert!(e.point_at(0.0).distance(Point3::new(2.0, 0.0, 0.0)) < 1e-15);
    }
}

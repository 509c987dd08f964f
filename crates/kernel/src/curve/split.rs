//! Cutting curves into pieces: the part on a sub-interval ([`Curve::trim`]), two pieces at one
//! parameter ([`Curve::split_at`]) and many pieces at a list of parameters
//! ([`Curve::split_at_parameters`], Grasshopper's *Shatter*).
//!
//! Pieces keep the kind of their curve where it can represent them (a piece of a line is a line,
//! of a circle or an arc an arc, of a polyline a polyline when it is cut at vertices) and keep
//! their parameters: the piece on `[a, b]` has the domain `[a, b]` and the same point at every
//! parameter as the curve it came from. A polyline cut between vertices becomes a degree-1 NURBS
//! curve whose knots are the original parameters of its vertices, which keeps that promise.
//!
//! On a closed curve the seam is not a cut: the piece that runs through it is one curve, from
//! the last cut, across the seam, to the first cut, with the domain continuing past the end
//! (`[a_k, a_1 + period]`).

use crate::curve::ParameterMap;
use crate::curve::kinks::is_interior;
use crate::geometry::tolerance::ZERO_TOLERANCE;
use crate::{Arc, Curve, Error, Interval, Line, NurbsCurve, Point3, Polyline, Result};

impl Curve {
    /// The part of the curve on `interval`, with `interval` as its domain (see the module
    /// documentation for the kind of the result). An interval reaching past the domain by no
    /// more than a relative [`ZERO_TOLERANCE`] is clamped to it.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] when the interval is not finite and increasing or not inside the
    /// domain.
    pub fn trim(&self, interval: Interval) -> Result<Curve> {
        let d = self.domain();
        if !interval.is_finite() || interval.t0 >= interval.t1 {
            return Err(Error::InvalidInput(format!(
                "sub-domain {} to {} is not increasing",
                interval.t0, interval.t1
            )));
        }
        let slack = ZERO_TOLERANCE * d.t0.abs().max(d.t1.abs()).max(1.0);
        if interval.t0 < d.t0 - slack || interval.t1 > d.t1 + slack {
            return Err(Error::InvalidInput(format!(
                "sub-domain {} to {} is not inside the domain {} to {}",
                interval.t0, interval.t1, d.t0, d.t1
            )));
        }
        let interval = Interval::new(interval.t0.max(d.t0), interval.t1.min(d.t1));
        if let Self::Nurbs(c) = self {
            return Ok(Self::Nurbs(c.trim(interval)?));
        }
        let map = self.parameter_map().expect("not a nurbs curve");
        let (s0, s1) = (map.to_natural(interval.t0), map.to_natural(interval.t1));
        Ok(match self {
            Self::Line { line, .. } => Self::Line {
                line: Line::new(line.point_at(s0), line.point_at(s1)),
                domain: interval,
            },
            Self::Polyline { polyline, .. } => polyline_piece(polyline, map, s0, s1, 0.0)?,
            Self::Circle { circle, .. } => Self::Arc {
                arc: Arc::new(*circle, Interval::new(s0, s1))?,
                domain: interval,
            },
            Self::Arc { arc, .. } => Self::Arc {
                arc: Arc::new(arc.circle, Interval::new(s0, s1))?,
                domain: interval,
            },
            Self::Nurbs(_) => unreachable!("handled above"),
        })
    }

    /// The two pieces on either side of `t`: on `[t0, t]` and on `[t, t1]` (closed curves too).
    ///
    /// # Errors
    /// [`Error::NotFinite`] for a NaN or infinite `t`; [`Error::InvalidInput`] when `t` is not
    /// strictly inside the domain.
    pub fn split_at(&self, t: f64) -> Result<(Curve, Curve)> {
        if !t.is_finite() {
            return Err(Error::NotFinite { what: "parameter" });
        }
        let d = self.domain();
        if !is_interior(d, t) {
            return Err(Error::InvalidInput(format!(
                "parameter {t} is not inside the domain {} to {}",
                d.t0, d.t1
            )));
        }
        Ok((
            self.trim(Interval::new(d.t0, t))?,
            self.trim(Interval::new(t, d.t1))?,
        ))
    }

    /// The pieces between the given parameters, in order (Grasshopper's *Shatter*).
    ///
    /// The parameters are sorted; those not strictly inside the domain are ignored, and so are
    /// repeats (within a relative [`ZERO_TOLERANCE`]). No parameter at all gives no piece;
    /// parameters that are all ignored give the whole curve. On a closed curve the last piece
    /// runs from the last parameter across the seam to the first one (see the module
    /// documentation), so `k` parameters give `k` pieces; on an open curve they give `k + 1`.
    ///
    /// # Errors
    /// [`Error::NotFinite`] for a NaN parameter; the errors of [`Curve::trim`].
    pub fn split_at_parameters(&self, parameters: &[f64]) -> Result<Vec<Curve>> {
        if parameters.iter().any(|t| t.is_nan()) {
            return Err(Error::NotFinite { what: "parameter" });
        }
        if parameters.is_empty() {
            return Ok(Vec::new());
        }
        let d = self.domain();
        let slack = ZERO_TOLERANCE * d.t0.abs().max(d.t1.abs()).max(1.0);
        let mut cuts: Vec<f64> = parameters
            .iter()
            .copied()
            .filter(|&t| is_interior(d, t))
            .collect();
        cuts.sort_by(f64::total_cmp);
        cuts.dedup_by(|b, a| *b - *a <= slack);
        if cuts.is_empty() {
            return Ok(vec![self.clone()]);
        }
        let closed = self.is_closed();
        let mut bounds = Vec::with_capacity(cuts.len() + 2);
        if !closed {
            bounds.push(d.t0);
        }
        bounds.extend_from_slice(&cuts);
        if !closed {
            bounds.push(d.t1);
        }
        let mut pieces: Vec<Curve> = bounds
            .windows(2)
            .map(|w| self.trim(Interval::new(w[0], w[1])))
            .collect::<Result<_>>()?;
        if closed {
            pieces.push(self.across_seam(cuts[cuts.len() - 1], cuts[0])?);
        }
        Ok(pieces)
    }

    /// The piece of a closed curve from `from` to the end, continued from the start to `to`, on
    /// the domain `[from, to + period]`.
    fn across_seam(&self, from: f64, to: f64) -> Result<Curve> {
        let d = self.domain();
        let period = d.length();
        let domain = Interval::new(from, to + period);
        match self {
            Self::Circle { circle, .. }
            | Self::Arc {
                arc: Arc { circle, .. },
                ..
            } => {
                let map = self.parameter_map().expect("circle");
                let sweep = map.natural.length();
                let angle = Interval::new(map.to_natural(from), map.to_natural(to) + sweep);
                Ok(Self::Arc {
                    arc: Arc::new(*circle, angle)?,
                    domain,
                })
            }
            Self::Polyline { polyline, .. } => {
                let map = self.parameter_map().expect("polyline");
                let last = map.natural.t1;
                polyline_piece(
                    polyline,
                    ParameterMap {
                        natural: Interval::new(map.natural.t0, last + last),
                        domain: Interval::new(d.t0, d.t1 + period),
                    },
                    map.to_natural(from),
                    map.to_natural(to) + last,
                    last,
                )
            }
            Self::Nurbs(c) => {
                let before = c.trim(Interval::new(from, d.t1))?;
                let after = c.trim(Interval::new(d.t0, to))?;
                Ok(Self::Nurbs(join_clamped(&before, &after)?))
            }
            Self::Line { .. } => Err(Error::InvalidInput("a line is never closed".into())),
        }
    }
}

/// The piece of a polyline between the natural parameters `s0 < s1` (vertex `i` at `i`), where
/// parameters beyond the last vertex wrap around a closed polyline with period `wrap` (0 for
/// no wrapping). `map` relates the natural parameters to curve parameters.
fn polyline_piece(
    polyline: &Polyline,
    map: ParameterMap,
    s0: f64,
    s1: f64,
    wrap: f64,
) -> Result<Curve> {
    let point_at = |s: f64| {
        if wrap > 0.0 && s > wrap {
            polyline.point_at(s - wrap)
        } else {
            polyline.point_at(s)
        }
    };
    let mut naturals = vec![s0];
    let first_vertex = s0.floor() + 1.0;
    let mut v = first_vertex;
    while v < s1 {
        naturals.push(v);
        v += 1.0;
    }
    naturals.push(s1);
    let points: Vec<Point3> = naturals.iter().map(|&s| point_at(s)).collect();
    let domain = Interval::new(map.to_curve(s0), map.to_curve(s1));
    if s0 == s0.floor() && s1 == s1.floor() {
        return Ok(Curve::Polyline {
            polyline: Polyline::new(points)?,
            domain,
        });
    }
    let mut knots: Vec<f64> = naturals.iter().map(|&s| map.to_curve(s)).collect();
    // The ends are the requested parameters exactly.
    let last = knots.len() - 1;
    knots[0] = domain.t0;
    knots[last] = domain.t1;
    Ok(Curve::Nurbs(NurbsCurve::new_non_rational(
        1, points, knots,
    )?))
}

/// The curve that traces `a` and then `b`, two clamped curves of the same degree where `b`
/// starts (in space) where `a` ends. `b`'s knots are shifted to continue `a`'s domain; the joint
/// is a knot of full multiplicity.
pub(crate) fn join_clamped(a: &NurbsCurve, b: &NurbsCurve) -> Result<NurbsCurve> {
    let p = a.degree();
    if b.degree() != p {
        return Err(Error::InvalidInput(format!(
            "cannot join curves of degrees {p} and {}",
            b.degree()
        )));
    }
    let joint = a.domain().t1;
    let shift = joint - b.domain().t0;
    let mut cvs = a.homogeneous_points();
    let bh = b.homogeneous_points();
    // Scaling homogeneous points keeps the curve; make the joint weights agree.
    let scale = cvs[cvs.len() - 1][3] / bh[0][3];
    cvs.extend(
        bh[1..]
            .iter()
            .map(|h| [h[0] * scale, h[1] * scale, h[2] * scale, h[3] * scale]),
    );
    let mut knots = a.knots().to_vec();
    knots.extend(b.knots()[p..].iter().map(|&k| k + shift));
    // The joint knots equal the joint exactly, whatever the rounding of the shift.
    let tol = ZERO_TOLERANCE * joint.abs().max(1.0);
    let first_of_b = a.knots().len();
    for k in &mut knots[first_of_b..] {
        if (*k - joint).abs() > tol {
            break;
        }
        *k = joint;
    }
    NurbsCurve::from_homogeneous(p, &cvs, knots)
}

#[cfg(test)]
mod tests {
    use std::f64::consts::{PI, TAU};

    use super::*;
    use crate::{Circle, Plane, Vector3};

    fn assert_traces(piece: &Curve, whole: &Curve) {
        let d = piece.domain();
        let period = whole.domain().length();
        for i in 0..=16 {
            let t = d.parameter_at(i as f64 / 16.0);
            let tw = if t > whole.domain().t1 { t - period } else { t };
            let (a, b) = (piece.point_at(t), whole.point_at(tw));
            assert!(a.distance(b) < 1e-12, "{piece:?} at {t}: {a:?} vs {b:?}");
        }
    }

    fn open_nurbs() -> Curve {
        NurbsCurve::create(
            &[
                Point3::new(0.0, 0.0, 0.0),
                Point3::new(1.0, 3.0, 0.0),
                Point3::new(3.0, 4.0, 1.0),
                Point3::new(5.0, 2.0, 0.0),
                Point3::new(7.0, 5.0, 2.0),
            ],
            3,
            false,
        )
        .unwrap()
        .into()
    }

    #[test]
    fn trims_keep_kind_and_parameters() {
        let line: Curve = Line::new(Point3::ORIGIN, Point3::new(10.0, 0.0, 0.0)).into();
        let piece = line.trim(Interval::new(2.0, 5.0)).unwrap();
        assert!(matches!(piece, Curve::Line { .. }));
        assert_eq!(piece.domain(), Interval::new(2.0, 5.0));
        assert_traces(&piece, &line);

        let circle: Curve = Circle::new(Plane::WORLD_XY, 2.0).unwrap().into();
        let arc = circle.trim(Interval::new(1.0, 4.0)).unwrap();
        assert!(matches!(arc, Curve::Arc { .. }));
        assert_traces(&arc, &circle);

        let poly: Curve = Polyline::new(vec![
            Point3::new(0.0, 0.0, 0.0),
            Point3::new(1.0, 0.0, 0.0),
            Point3::new(1.0, 1.0, 0.0),
            Point3::new(2.0, 1.0, 0.0),
        ])
        .unwrap()
        .into();
        let at_vertices = poly.trim(Interval::new(1.0, 3.0)).unwrap();
        assert!(matches!(at_vertices, Curve::Polyline { .. }));
        assert_traces(&at_vertices, &poly);
        let between = poly.trim(Interval::new(0.5, 2.25)).unwrap();
        assert!(matches!(between, Curve::Nurbs(_)));
        assert_traces(&between, &poly);

        let n = open_nurbs();
        let piece = n.trim(Interval::new(0.3, 1.7)).unwrap();
        assert_eq!(piece.domain(), Interval::new(0.3, 1.7));
        assert_traces(&piece, &n);
    }

    #[test]
    fn trim_rejects_bad_intervals() {
        let n = open_nurbs();
        assert!(n.trim(Interval::new(1.0, 0.5)).is_err());
        assert!(n.trim(Interval::new(-1.0, 0.5)).is_err());
        assert!(n.trim(Interval::new(f64::NAN, 0.5)).is_err());
        assert!(n.split_at(0.0).is_err());
        assert!(n.split_at(f64::NAN).is_err());
        let (a, b) = n.split_at(1.25).unwrap();
        assert_traces(&a, &n);
        assert_traces(&b, &n);
        assert_eq!(a.domain().t1, 1.25);
        assert_eq!(b.domain().t0, 1.25);
    }

    #[test]
    fn shatter_open_curves() {
        let n = open_nurbs();
        let pieces = n
            .split_at_parameters(&[1.5, 0.5, 1.5, -3.0, 2.0, 7.0])
            .unwrap();
        // 2.0 is the end of the domain and ignored, like -3 and 7; 1.5 repeats.
        let domains: Vec<Interval> = pieces.iter().map(Curve::domain).collect();
        assert_eq!(
            domains,
            vec![
                Interval::new(0.0, 0.5),
                Interval::new(0.5, 1.5),
                Interval::new(1.5, 2.0)
            ]
        );
        for p in &pieces {
            assert_traces(p, &n);
        }
        assert!(n.split_at_parameters(&[]).unwrap().is_empty());
        assert_eq!(n.split_at_parameters(&[0.0, 2.0]).unwrap(), vec![n.clone()]);
        assert!(n.split_at_parameters(&[0.5, f64::NAN]).is_err());
    }

    #[test]
    fn shatter_closed_curves_joins_across_the_seam() {
        let circle: Curve = Circle::new(Plane::WORLD_XY, 1.0).unwrap().into();
        let pieces = circle.split_at_parameters(&[PI, 0.5 * PI]).unwrap();
        assert_eq!(pieces.len(), 2);
        assert_eq!(pieces[0].domain(), Interval::new(0.5 * PI, PI));
        assert_eq!(pieces[1].domain(), Interval::new(PI, 0.5 * PI + TAU));
        assert!((pieces[1].length() - 1.5 * PI).abs() < 1e-12);
        for p in &pieces {
            assert_traces(p, &circle);
        }

        let square: Curve = Polyline::new(vec![
            Point3::new(0.0, 0.0, 0.0),
            Point3::new(1.0, 0.0, 0.0),
            Point3::new(1.0, 1.0, 0.0),
            Point3::new(0.0, 1.0, 0.0),
            Point3::new(0.0, 0.0, 0.0),
        ])
        .unwrap()
        .into();
        let pieces = square.split_at_parameters(&[1.0, 3.5]).unwrap();
        assert_eq!(pieces.len(), 2);
        assert!(matches!(pieces[0], Curve::Nurbs(_)));
        assert!((pieces[0].length() - 2.5).abs() < 1e-12);
        assert!((pieces[1].length() - 1.5).abs() < 1e-12);
        assert_eq!(pieces[1].domain(), Interval::new(3.5, 5.0));
        for p in &pieces {
            assert_traces(p, &square);
        }
        let at_vertices = square.split_at_parameters(&[1.0, 3.0]).unwrap();
        assert!(matches!(at_vertices[1], Curve::Polyline { .. }));
        assert_eq!(at_vertices[1].start_point(), Point3::new(0.0, 1.0, 0.0));
        assert_eq!(at_vertices[1].end_point(), Point3::new(1.0, 0.0, 0.0));

        let periodic: Curve = NurbsCurve::create(
            &[
                Point3::new(0.0, 0.0, 0.0),
                Point3::new(10.0, 0.0, 0.0),
                Point3::new(10.0, 10.0, 0.0),
                Point3::new(0.0, 10.0, 0.0),
            ],
            3,
            true,
        )
        .unwrap()
        .into();
        let pieces = periodic.split_at_parameters(&[0.5, 2.5]).unwrap();
        assert_eq!(pieces.len(), 2);
        assert_eq!(pieces[1].domain(), Interval::new(2.5, 4.5));
        let total: f64 = pieces.iter().map(Curve::length).sum();
        assert!((total - periodic.length()).abs() < 1e-9 * total);
        for p in &pieces {
            assert_traces(p, &periodic);
        }
        // The piece across the seam is smooth there: the seam is not a kink.
        let seam = pieces[1].kink_angle_at(4.0).unwrap().unwrap();
        assert!(seam < 1e-9, "{seam}");
        assert!(pieces[1].tangent_at(4.0).unwrap().dot(Vector3::X) > 0.0);
    }

    #[test]
    fn joining_rational_pieces_keeps_the_shape() {
        let arc: Curve = Arc::new(
            Circle::new(Plane::WORLD_XY, 3.0).unwrap(),
            Interval::new(0.0, 3.0),
        )
        .unwrap()
        .into();
        let n = arc.to_nurbs();
        let (a, b) = n.split_at(1.0).unwrap();
        let joined = join_clamped(&a, &b).unwrap();
        assert_eq!(joined.domain(), n.domain());
        for i in 0..=30 {
            let t = i as f64 / 10.0;
            assert!(joined.point_at(t).distance(n.point_at(t)) < 1e-12);
        }
    }
}

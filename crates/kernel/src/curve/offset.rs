//! Offsetting curves in a plane (Rhino's `Curve.Offset`).
//!
//! A point at `t` moves by `distance` along `T(t) × N`, the unit tangent crossed with the plane's
//! normal: to the right of the direction of travel seen from the normal's side, so a
//! counter-clockwise circle grows for a positive distance and shrinks for a negative one.
//!
//! - Lines move as a whole; circles and arcs in planes parallel to the offset plane change their
//!   radius (an offset that takes the radius to zero or below is an error). NURBS curves that
//!   trace an arc or circle within [`ARC_OFFSET_TOLERANCE`] (Rhino's rational quadratic form,
//!   recognized by [`Curve::try_arc`]) are scaled about the centre, which changes the radius at
//!   every parameter. These are exact.
//! - Polylines (and degree-1 NURBS curves, through their control polygons) offset each segment
//!   and fill each corner on the outside of the turn according to [`OffsetCorners`]; on the
//!   inside of a turn the segments are trimmed to meet (a sharp corner). Also exact.
//! - Other curves are approximated: the exact offset points are sampled, interpolated by a
//!   cubic (periodic for closed smooth curves; with the offset's end tangents for open ones),
//!   and the samples are doubled until the fit is
//!   within half the tolerance at the points between samples. Curves with kinks are offset piece by
//!   piece and the pieces joined with corners as polylines are; on the inside of a kink the two
//!   offset pieces are trimmed where they cross (found by Newton's method from their ends; where
//!   it finds no crossing they are bridged by a line, with a warning).
//!
//! Where the offset turns back on itself locally (a segment trimmed past its length, a
//! distance beyond the radius of curvature on the inside of a bend) a warning is given;
//! intersections between distant parts of the offset are not looked for.

use crate::curve::nurbs::interpolate::{EndTangents, KnotStyle};
use crate::geometry::tolerance::{ARC_OFFSET_TOLERANCE, ZERO_TOLERANCE};
use crate::{
    Arc, Circle, CubicHermite, Curve, Error, Interval, Line, NurbsCurve, Plane, Point3, Polyline,
    Result, Vector3,
};

/// The most samples a curve offset takes before giving up on its tolerance.
pub const MAX_OFFSET_SAMPLES: usize = 4096;

/// How an offset fills the corners on the outside of a polyline's turns: Grasshopper's Corners
/// input (0 to 4).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum OffsetCorners {
    /// No fill: the offset segments are extended to meet, as [`OffsetCorners::Sharp`] (Rhino
    /// treats `None` so for polylines).
    None,
    /// The offset segments extended until they meet.
    Sharp,
    /// An arc about the corner, of radius the distance.
    Round,
    /// A cubic blend tangent to both segments.
    Smooth,
    /// A straight segment between the ends of the offset segments.
    Chamfer,
}

/// An offset curve and the warnings about it.
#[derive(Clone, Debug, PartialEq)]
pub struct CurveOffset {
    /// The offset curve.
    pub curve: Curve,
    /// What may be wrong with it (self-intersections, an unmet tolerance).
    pub warnings: Vec<String>,
}

impl Curve {
    /// The curve offset by `distance` in `plane` (see the module documentation), approximated
    /// within `tolerance` where it is not exact.
    ///
    /// # Errors
    /// [`Error::NotFinite`] for a non-finite distance, plane or tolerance;
    /// [`Error::InvalidInput`] for a non-positive tolerance, a curve running along the plane's
    /// normal, or a circle or arc that the offset collapses.
    pub fn offset(
        &self,
        distance: f64,
        plane: &Plane,
        corners: OffsetCorners,
        tolerance: f64,
    ) -> Result<CurveOffset> {
        if !distance.is_finite() || !plane.is_finite() || !tolerance.is_finite() {
            return Err(Error::NotFinite {
                what: "offset input",
            });
        }
        if tolerance <= 0.0 {
            return Err(Error::InvalidInput(format!(
                "offset tolerance {tolerance} is not positive"
            )));
        }
        let n = plane.normal();
        let exact = |curve: Curve| CurveOffset {
            curve,
            warnings: Vec::new(),
        };
        if distance == 0.0 {
            return Ok(exact(self.clone()));
        }
        match self {
            Self::Line { line, domain } => {
                let u = side(line.direction(), n)?;
                let m = u * distance;
                Ok(exact(Self::Line {
                    line: Line::new(line.from + m, line.to + m),
                    domain: *domain,
                }))
            }
            Self::Circle { circle, domain } if parallel(circle.normal(), n) => {
                let circle = offset_circle(circle, distance, n)?;
                Ok(exact(Self::Circle {
                    circle,
                    domain: *domain,
                }))
            }
            Self::Arc { arc, domain } if parallel(arc.circle.normal(), n) => {
                let circle = offset_circle(&arc.circle, distance, n)?;
                Ok(exact(Self::Arc {
                    arc: Arc::new(circle, arc.angle)?,
                    domain: *domain,
                }))
            }
            Self::Polyline { polyline, .. } => {
                offset_polyline(polyline.points(), distance, n, corners)
            }
            Self::Nurbs(c) if c.degree() == 1 => offset_polyline(c.points(), distance, n, corners),
            Self::Nurbs(c)
                if let Some(arc) = self.try_arc(tolerance.min(ARC_OFFSET_TOLERANCE))
                    && parallel(arc.circle.normal(), n) =>
            {
                Ok(exact(Self::Nurbs(offset_nurbs_arc(c, &arc, distance, n)?)))
            }
            _ => {
                let pieces = self.explode(true)?;
                if pieces.len() == 1 {
                    return offset_smooth(self, distance, n, tolerance);
                }
                offset_pieces(self, &pieces, distance, n, corners, tolerance)
            }
        }
    }
}

/// Whether two unit vectors are parallel or antiparallel.
fn parallel(a: Vector3, b: Vector3) -> bool {
    a.cross(b).length() <= 1e-12
}

/// The unit offset direction `T × N` for a direction of travel `t`.
fn side(t: Vector3, n: Vector3) -> Result<Vector3> {
    t.cross(n)
        .try_normalize()
        .ok_or_else(|| Error::InvalidInput("the curve runs along the offset plane's normal".into()))
}

/// A circle with its radius changed by the offset.
fn offset_circle(circle: &Circle, distance: f64, n: Vector3) -> Result<Circle> {
    let sign = circle.normal().dot(n).signum();
    let radius = circle.radius + sign * distance;
    if radius <= ZERO_TOLERANCE {
        return Err(Error::InvalidInput(format!(
            "the offset by {distance} collapses the circle of radius {}",
            circle.radius
        )));
    }
    Circle::new(circle.plane, radius)
}

/// The offset of a NURBS curve that traces an arc or circle: its control points scaled about
/// the centre by the new radius over the old, weights and knots kept. Scaling about the centre
/// moves every point of the arc radially by the offset distance at the same parameter, so the
/// result is exact (Rhino's rational form stays rational, a fitted arc keeps its
/// parameterization).
fn offset_nurbs_arc(c: &NurbsCurve, arc: &Arc, distance: f64, n: Vector3) -> Result<NurbsCurve> {
    let circle = offset_circle(&arc.circle, distance, n)?;
    let factor = circle.radius / arc.circle.radius;
    let centre = arc.circle.center();
    let points = c
        .points()
        .iter()
        .map(|&p| centre + (p - centre) * factor)
        .collect();
    NurbsCurve::new(c.degree(), points, c.weights().to_vec(), c.knots().to_vec())
}

/// One straight segment of a polyline being offset.
struct Segment {
    from: Point3,
    to: Point3,
    tangent: Vector3,
    side: Vector3,
}

/// The exact offset of the polyline through `points` (see the module documentation).
fn offset_polyline(
    points: &[Point3],
    distance: f64,
    n: Vector3,
    corners: OffsetCorners,
) -> Result<CurveOffset> {
    let mut vertices: Vec<Point3> = Vec::with_capacity(points.len());
    for &p in points {
        if vertices
            .last()
            .is_none_or(|q| q.distance(p) > ZERO_TOLERANCE)
        {
            vertices.push(p);
        }
    }
    if vertices.len() < 2 {
        return Err(Error::InvalidInput("the polyline has no length".into()));
    }
    let closed =
        vertices.len() >= 4 && vertices[0].distance(vertices[vertices.len() - 1]) <= ZERO_TOLERANCE;
    let mut segments = Vec::with_capacity(vertices.len() - 1);
    for w in vertices.windows(2) {
        let tangent = (w[1] - w[0]).try_normalize().expect("distinct vertices");
        segments.push(Segment {
            from: w[0],
            to: w[1],
            tangent,
            side: side(tangent, n)? * distance,
        });
    }
    let lines: Vec<(Point3, Point3, Vector3)> = segments
        .iter()
        .map(|s| (s.from + s.side, s.to + s.side, s.tangent))
        .collect();
    joined_with_corners(
        &lines,
        &segments_corners(&segments, closed),
        distance,
        n,
        corners,
        closed,
    )
}

/// For each joint (between segment `k` and `k + 1`, and between the last and the first when
/// `closed`) the corner vertex.
fn segments_corners(segments: &[Segment], closed: bool) -> Vec<Point3> {
    let mut out: Vec<Point3> = segments.windows(2).map(|w| w[0].to).collect();
    if closed {
        out.push(segments[segments.len() - 1].to);
    }
    out
}

/// Joins offset pieces given by their ends and end tangents, in order, filling the corners.
/// `pieces[k]` is `(start, end, tangent)` of a line; `vertices[k]` the original corner after
/// piece `k`.
fn joined_with_corners(
    lines: &[(Point3, Point3, Vector3)],
    vertices: &[Point3],
    distance: f64,
    n: Vector3,
    corners: OffsetCorners,
    closed: bool,
) -> Result<CurveOffset> {
    let count = lines.len();
    let mut starts: Vec<Point3> = lines.iter().map(|l| l.0).collect();
    let mut ends: Vec<Point3> = lines.iter().map(|l| l.1).collect();
    let mut fills: Vec<Option<Curve>> = vec![None; vertices.len()];
    for (j, &v) in vertices.iter().enumerate() {
        let (a, b) = (j, (j + 1) % count);
        let (t1, t2) = (lines[a].2, lines[b].2);
        let turn = t1.cross(t2).dot(n);
        let outside = turn * distance > 0.0;
        let u1 = (lines[a].1 - v) / distance;
        let u2 = (lines[b].0 - v) / distance;
        let denominator = 1.0 + u1.dot(u2);
        let sharp = matches!(corners, OffsetCorners::Sharp | OffsetCorners::None) || !outside;
        if turn.abs() <= 1e-12 && t1.dot(t2) > 0.0 {
            continue; // Straight on: the offset ends already meet.
        }
        if sharp && denominator > 1e-9 {
            let m = v + (u1 + u2) * (distance / denominator);
            ends[a] = m;
            starts[b] = m;
            continue;
        }
        let (p, q) = (lines[a].1, lines[b].0);
        fills[j] = Some(match corners {
            OffsetCorners::Round => Arc::from_start_tangent_end(p, t1, q)?.into(),
            OffsetCorners::Smooth => {
                let l = p.distance(q);
                Curve::try_from(CubicHermite::new(p, t1 * l, q, t2 * l))?
            }
            _ => Line::new(p, q).into(),
        });
    }
    let mut warnings = Vec::new();
    for k in 0..count {
        if (ends[k] - starts[k]).dot(lines[k].2) <= 0.0 {
            warnings.push(format!(
                "offset segment {k} is trimmed past its length: the offset intersects itself"
            ));
        }
    }
    if fills.iter().all(Option::is_none) {
        let mut points = starts.clone();
        if closed {
            points.push(starts[0]);
        } else {
            points.push(ends[count - 1]);
        }
        return Ok(CurveOffset {
            curve: Polyline::new(points)?.into(),
            warnings,
        });
    }
    let mut pieces: Vec<Curve> = Vec::with_capacity(2 * count);
    for k in 0..count {
        if starts[k].distance(ends[k]) > ZERO_TOLERANCE {
            pieces.push(Line::new(starts[k], ends[k]).into());
        }
        if let Some(Some(fill)) = fills.get(k) {
            pieces.push(fill.clone());
        }
    }
    Ok(CurveOffset {
        curve: Curve::join_ordered(&pieces, closed)?,
        warnings,
    })
}

/// The offset point and whether the offset has a cusp there (the distance beyond the radius of
/// curvature on the inside of the bend).
fn offset_point(curve: &Curve, t: f64, distance: f64, n: Vector3) -> Option<(Point3, bool)> {
    let tangent = curve.tangent_at(t)?;
    let u = tangent.cross(n).try_normalize()?;
    let cusp = curve
        .signed_curvature_at(t, n)
        .is_some_and(|k| 1.0 + distance * k <= 0.0);
    Some((curve.point_at(t) + u * distance, cusp))
}

/// The unit tangent of the offset at `t`: the curve's, reversed past a cusp.
fn offset_tangent(curve: &Curve, t: f64, distance: f64, n: Vector3) -> Option<Vector3> {
    let tangent = curve.tangent_at(t)?;
    let flipped = curve
        .signed_curvature_at(t, n)
        .is_some_and(|k| 1.0 + distance * k < 0.0);
    Some(if flipped { -tangent } else { tangent })
}

/// The approximate offset of a curve without kinks.
fn offset_smooth(curve: &Curve, distance: f64, n: Vector3, tolerance: f64) -> Result<CurveOffset> {
    let d = curve.domain();
    let closed = curve.is_closed();
    let breaks: Vec<f64> = match curve {
        Curve::Nurbs(c) => c.span_breaks(),
        _ => vec![d.t0, d.t1],
    };
    let mut per_span = (16 / (breaks.len() - 1)).max(2);
    let mut warnings = Vec::new();
    loop {
        let ts: Vec<f64> = breaks
            .windows(2)
            .flat_map(|w| {
                (0..per_span).map(move |i| w[0] + (w[1] - w[0]) * i as f64 / per_span as f64)
            })
            .chain(std::iter::once(d.t1))
            .collect();
        let mut points = Vec::with_capacity(ts.len());
        let mut cusp = false;
        for &t in &ts {
            let (p, c) = offset_point(curve, t, distance, n).ok_or_else(|| {
                Error::InvalidInput(format!(
                    "the curve has no tangent in the offset plane at {t}"
                ))
            })?;
            cusp |= c;
            points.push(p);
        }
        let fitted = if closed {
            points.pop();
            NurbsCurve::interpolate_periodic(&points, 3, KnotStyle::Chord)?
        } else {
            // The ends are fitted with the offset's own tangents there: natural end conditions
            // (no bending at the ends) would leave an error there that shrinks only with the
            // square of the sample spacing.
            let tangents = EndTangents {
                start: offset_tangent(curve, d.t0, distance, n),
                end: offset_tangent(curve, d.t1, distance, n),
            };
            NurbsCurve::interpolate_with_tangents(&points, 3, KnotStyle::Chord, tangents)?
        };
        let fitted: Curve = fitted.into();
        let mut error: f64 = 0.0;
        for w in ts.windows(2) {
            let t = 0.5 * (w[0] + w[1]);
            if let Some((p, _)) = offset_point(curve, t, distance, n) {
                error = error.max(fitted.closest_point(p)?.point.distance(p));
            }
        }
        let samples = ts.len();
        // Half the tolerance at the midpoints leaves room for the error between them.
        if error <= 0.5 * tolerance || 2 * samples > MAX_OFFSET_SAMPLES {
            if cusp {
                warnings.push(format!(
                    "the offset distance {distance} exceeds the radius of curvature on the inside \
                     of a bend: the offset intersects itself"
                ));
            }
            if error > 0.5 * tolerance {
                warnings.push(format!(
                    "the offset is within {error:.3e} of exact, not the tolerance {tolerance}"
                ));
            }
            return Ok(CurveOffset {
                curve: fitted,
                warnings,
            });
        }
        per_span *= 2;
    }
}

/// What joins the offsets of two consecutive pieces of a kinked curve.
enum Joint {
    /// Nothing: their ends meet, or they were trimmed to where they cross.
    Met,
    /// A corner fill (or, where trimming failed, a bridging line).
    Fill(Curve),
}

/// How many Newton steps [`crossing_near_ends`] takes at most.
const CROSSING_ITERATIONS: usize = 50;

/// Where the end part of `a` crosses the start part of `b` in the plane with normal `n`: the
/// parameters `(s, t)` with `a(s) = b(t)`, found by Newton's method on the two in-plane
/// coordinates from `(end of a, start of b)`. `None` when it does not converge inside both
/// domains (the pieces are too short, or do not cross there).
fn crossing_near_ends(a: &Curve, b: &Curve, n: Vector3) -> Option<(f64, f64)> {
    let frame = Plane::from_normal(Point3::ORIGIN, n).ok()?;
    let (e1, e2) = (frame.x_axis, frame.y_axis);
    let (da, db) = (a.domain(), b.domain());
    let (mut s, mut t) = (da.t1, db.t0);
    let scale = a.end_point().to_vector().length().max(1.0);
    for _ in 0..CROSSING_ITERATIONS {
        let (p, dp, _) = a.point_and_derivatives_at(s);
        let (q, dq, _) = b.point_and_derivatives_at(t);
        let f = p - q;
        let (f1, f2) = (f.dot(e1), f.dot(e2));
        if f1.hypot(f2) <= 4.0 * f64::EPSILON * scale {
            return Some((s, t));
        }
        // [dp, -dq] (ds, dt) = -f in the plane's coordinates.
        let (a11, a21, a12, a22) = (dp.dot(e1), dp.dot(e2), -dq.dot(e1), -dq.dot(e2));
        let det = a11 * a22 - a12 * a21;
        if det.abs() <= f64::MIN_POSITIVE || !det.is_finite() {
            return None;
        }
        let ds = (-f1 * a22 + f2 * a12) / det;
        let dt = (-a11 * f2 + a21 * f1) / det;
        s = (s + ds).clamp(da.t0, da.t1);
        t = (t + dt).clamp(db.t0, db.t1);
    }
    let gap = a.point_at(s) - b.point_at(t);
    (gap.dot(e1).hypot(gap.dot(e2)) <= 1e-9 * scale).then_some((s, t))
}

/// The offset of a curve with kinks: its pieces offset one by one, trimmed where they cross on
/// the inside of a kink, and joined with corners on the outside.
fn offset_pieces(
    curve: &Curve,
    pieces: &[Curve],
    distance: f64,
    n: Vector3,
    corners: OffsetCorners,
    tolerance: f64,
) -> Result<CurveOffset> {
    let closed = curve.is_closed();
    let mut offsets = Vec::with_capacity(pieces.len());
    let mut warnings = Vec::new();
    for piece in pieces {
        let o = piece.offset(
            distance,
            &Plane::from_normal(Point3::ORIGIN, n)?,
            corners,
            tolerance,
        )?;
        warnings.extend(o.warnings);
        offsets.push(o.curve);
    }
    let count = pieces.len();
    let joints = if closed { count } else { count - 1 };
    // The part of each offset piece that is kept, narrowed by the trims at inside kinks.
    let mut kept: Vec<Interval> = offsets.iter().map(Curve::domain).collect();
    let mut fills = Vec::with_capacity(joints);
    for k in 0..joints {
        let next = (k + 1) % count;
        let (p, q) = (offsets[k].end_point(), offsets[next].start_point());
        if p.distance(q) <= tolerance {
            fills.push(Joint::Met);
            continue;
        }
        let d1 = pieces[k].domain();
        let d2 = pieces[next].domain();
        let (Some(t1), Some(t2)) = (pieces[k].tangent_at(d1.t1), pieces[next].tangent_at(d2.t0))
        else {
            fills.push(Joint::Fill(Line::new(p, q).into()));
            continue;
        };
        let outside = t1.cross(t2).dot(n) * distance > 0.0;
        let fill: Curve = match corners {
            _ if !outside => {
                if let Some((s, t)) = crossing_near_ends(&offsets[k], &offsets[next], n) {
                    kept[k].t1 = s;
                    kept[next].t0 = t;
                    fills.push(Joint::Met);
                    continue;
                }
                warnings.push(format!(
                    "the offsets on the inside of the kink after piece {k} do not cross near \
                     their ends: they are bridged by a line"
                ));
                Line::new(p, q).into()
            }
            OffsetCorners::Round => Arc::from_start_tangent_end(p, t1, q)?.into(),
            OffsetCorners::Smooth => {
                let l = p.distance(q);
                Curve::try_from(CubicHermite::new(p, t1 * l, q, t2 * l))?
            }
            OffsetCorners::Sharp | OffsetCorners::None => {
                // Extend both ends along their tangents to where the tangent lines meet.
                let v = pieces[k].end_point();
                let u1 = (p - v) / distance;
                let u2 = (q - v) / distance;
                let m = v + (u1 + u2) * (distance / (1.0 + u1.dot(u2)).max(1e-9));
                Polyline::new(vec![p, m, q])?.into()
            }
            OffsetCorners::Chamfer => Line::new(p, q).into(),
        };
        fills.push(Joint::Fill(fill));
    }
    let mut out: Vec<Curve> = Vec::with_capacity(2 * count);
    for k in 0..count {
        let domain = offsets[k].domain();
        if kept[k] == domain {
            out.push(offsets[k].clone());
        } else if kept[k].t0 < kept[k].t1 {
            out.push(offsets[k].trim(kept[k])?);
        } else {
            warnings.push(format!(
                "offset piece {k} is trimmed past its length: the offset intersects itself"
            ));
        }
        if let Some(Joint::Fill(fill)) = fills.get(k) {
            out.push(fill.clone());
        }
    }
    let curve = Curve::join_ordered(&out, closed)?;
    Ok(CurveOffset { curve, warnings })
}

#[cfg(test)]
mod tests;

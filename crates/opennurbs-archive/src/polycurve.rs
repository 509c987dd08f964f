//! Joining the segments of an `ON_PolyCurve` into one NURBS curve, since the kernel has no
//! polycurve type.
//!
//! Each segment is put on its polycurve sub-domain, split into rational Bézier spans (knot
//! insertion), raised to the highest segment degree (exact degree elevation of each span in
//! homogeneous coordinates), and the spans are chained with full-multiplicity knots at their
//! breaks. The result traces the same points at the same parameters as the polycurve.

use locus_kernel::{Interval, NurbsCurve, Point3, basis::MAX_DEGREE};

use crate::{Error, Result};

/// Consecutive segments whose end and start are further apart than this (relative to the
/// curve's size, with 1 as the smallest size) do not make one curve; openNURBS's own
/// polycurve check is looser, but the joined curve passes through the earlier segment's end.
pub const SEGMENT_GAP_TOLERANCE: f64 = 1e-8;

type H = [f64; 4];

fn homogeneous(c: &NurbsCurve) -> Vec<H> {
    c.points()
        .iter()
        .zip(c.weights())
        .map(|(p, &w)| [p.x * w, p.y * w, p.z * w, w])
        .collect()
}

fn euclidean(h: &H) -> Point3 {
    Point3::new(h[0] / h[3], h[1] / h[3], h[2] / h[3])
}

/// Splits a curve into Bézier spans of its own degree: the homogeneous points of each span
/// and the breaks between them.
fn bezier_spans(c: &NurbsCurve) -> Result<(Vec<Vec<H>>, Vec<f64>)> {
    let p = c.degree();
    let mut c = c.clamped();
    let d = c.domain();
    let mut interior: Vec<f64> = c
        .knots()
        .iter()
        .copied()
        .filter(|&k| k > d.t0 && k < d.t1)
        .collect();
    interior.dedup();
    for &k in &interior {
        let m = c.knot_multiplicity(k);
        if m < p {
            c = c.insert_knot(k, p - m).map_err(|source| Error::Geometry {
                what: "ON_PolyCurve segment",
                source,
            })?;
        }
    }
    let h = homogeneous(&c);
    let spans = (h.len() - 1) / p;
    let beziers = (0..spans).map(|s| h[s * p..=s * p + p].to_vec()).collect();
    let mut breaks = Vec::with_capacity(spans + 1);
    breaks.push(d.t0);
    breaks.extend(interior);
    breaks.push(d.t1);
    Ok((beziers, breaks))
}

/// Raises a homogeneous Bézier span by one degree.
fn elevate(b: &[H]) -> Vec<H> {
    let p = b.len() - 1;
    let mut out = Vec::with_capacity(p + 2);
    out.push(b[0]);
    for i in 1..=p {
        let a = i as f64 / (p + 1) as f64;
        out.push(std::array::from_fn(|k| {
            a * b[i - 1][k] + (1.0 - a) * b[i][k]
        }));
    }
    out.push(b[p]);
    out
}

/// Joins `segments`, the `i`-th on the sub-domain `t[i]` to `t[i + 1]`, into one curve.
///
/// # Errors
/// [`Error::Invalid`] for parameters that do not increase or segments that do not meet,
/// [`Error::Geometry`] when the kernel refuses a step.
pub fn join(segments: &[NurbsCurve], t: &[f64]) -> Result<NurbsCurve> {
    if segments.is_empty() || t.len() != segments.len() + 1 {
        return Err(Error::Invalid(
            "a polycurve needs one more parameter than segments".into(),
        ));
    }
    let degree = segments.iter().map(NurbsCurve::degree).max().unwrap_or(1);
    if degree > MAX_DEGREE {
        return Err(Error::Invalid(format!(
            "polycurve degree {degree} is too high"
        )));
    }
    let scale = segments
        .iter()
        .flat_map(|s| s.points())
        .map(|p| p.x.abs().max(p.y.abs()).max(p.z.abs()))
        .fold(1.0_f64, f64::max);
    let mut points: Vec<H> = Vec::new();
    let mut breaks: Vec<f64> = Vec::new();
    for (i, seg) in segments.iter().enumerate() {
        let domain = Interval::new(t[i], t[i + 1]);
        let seg = seg
            .reparameterized(domain)
            .map_err(|source| Error::Geometry {
                what: "ON_PolyCurve segment domain",
                source,
            })?;
        let (beziers, b) = bezier_spans(&seg)?;
        for (j, mut bez) in beziers.into_iter().enumerate() {
            while bez.len() < degree + 1 {
                bez = elevate(&bez);
            }
            if let Some(last) = points.last().copied() {
                let gap = euclidean(&last).distance(euclidean(&bez[0]));
                if gap.is_nan() || gap > SEGMENT_GAP_TOLERANCE * scale {
                    return Err(Error::Invalid(format!(
                        "ON_PolyCurve segment {i} starts {gap} away from where segment {} \
                         ends",
                        i.saturating_sub(1)
                    )));
                }
                // Scale the span's homogeneous points (which leaves its shape alone) so that
                // the shared point has one weight.
                let f = last[3] / bez[0][3];
                points.extend(bez[1..].iter().map(|h| h.map(|x| x * f)));
            } else {
                breaks.push(b[0]);
                points.extend(bez);
            }
            breaks.push(b[j + 1]);
        }
    }
    let knots: Vec<f64> = breaks
        .iter()
        .flat_map(|&k| std::iter::repeat_n(k, degree))
        .collect();
    let weights: Vec<f64> = points.iter().map(|h| h[3]).collect();
    let pts: Vec<Point3> = points.iter().map(euclidean).collect();
    NurbsCurve::new(degree, pts, weights, knots).map_err(|source| Error::Geometry {
        what: "ON_PolyCurve",
        source,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use locus_kernel::{Arc, Circle, Line, Plane};

    #[test]
    fn a_line_and_an_arc_join_into_one_curve_through_the_same_points() {
        let line = Line {
            from: Point3::new(-2.0, 0.0, 0.0),
            to: Point3::new(1.0, 0.0, 0.0),
        }
        .to_nurbs()
        .unwrap();
        let arc = Arc::new(
            Circle::new(Plane::WORLD_XY, 1.0).unwrap(),
            locus_kernel::Interval::new(0.0, 2.0),
        )
        .unwrap()
        .to_nurbs();
        let t = [0.0, 3.0, 5.0];
        let joined = join(&[line.clone(), arc.clone()], &t).unwrap();
        assert_eq!(joined.degree(), 2);
        assert_eq!(joined.domain(), Interval::new(0.0, 5.0));
        for k in 0..=10 {
            let s = k as f64 / 10.0;
            let a = line.point_at(line.domain().parameter_at(s));
            let b = joined.point_at(3.0 * s);
            assert!(a.distance(b) < 1e-12, "{a:?} {b:?}");
            let a = arc.point_at(arc.domain().parameter_at(s));
            let b = joined.point_at(3.0 + 2.0 * s);
            assert!(a.distance(b) < 1e-12, "{a:?} {b:?}");
        }
    }

    #[test]
    fn segments_that_do_not_meet_are_refused() {
        let a = Line {
            from: Point3::new(0.0, 0.0, 0.0),
            to: Point3::new(1.0, 0.0, 0.0),
        }
        .to_nurbs()
        .unwrap();
        let b = Line {
            from: Point3::new(2.0, 0.0, 0.0),
            to: Point3::new(3.0, 0.0, 0.0),
        }
        .to_nurbs()
        .unwrap();
        assert!(join(&[a, b], &[0.0, 1.0, 2.0]).is_err());
    }
}

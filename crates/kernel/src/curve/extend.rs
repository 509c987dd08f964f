//! Extending curves by a length at either end (Rhino's `Curve.Extend`, Grasshopper's Extend
//! Curve).
//!
//! An extension continues the curve from its end in the direction it arrives there:
//! - [`CurveExtension::Line`]: a straight segment along the end tangent;
//! - [`CurveExtension::Arc`]: a circular arc tangent to the curve with the curvature it has at
//!   the end (a segment where that is zero);
//! - [`CurveExtension::Smooth`]: the curve's own last piece continued: the polynomial (or
//!   rational) span at the end extrapolated, found by blossoming its Bézier form, so the
//!   curve stays smooth to every order across the join; a line stays a line and an arc an
//!   arc.
//!
//! The extension's length is measured along it (for the smooth one the span's parameter is
//! found by bisection on the arc length, to [`EXTENSION_LENGTH_TOLERANCE`]). A negative
//! length shortens the curve by that much instead. The pieces are joined into one curve
//! (lines into a polyline or a longer line).

use crate::curve::nurbs::basis;
use crate::{
    Arc, Circle, Curve, Error, Interval, Line, NurbsCurve, Plane, Point3, Result, Vector3,
};

/// The relative accuracy of a smooth extension's length.
pub const EXTENSION_LENGTH_TOLERANCE: f64 = 1e-12;

/// How a curve is continued past its end.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum CurveExtension {
    /// A straight segment along the end tangent (Grasshopper's type 0).
    Line,
    /// A tangent arc with the end's curvature (type 1).
    Arc,
    /// The end span continued (type 2).
    Smooth,
}

impl Curve {
    /// The curve extended by `start` at its start and `end` at its end (lengths along the
    /// extensions; negative lengths shorten the curve), see the module documentation.
    ///
    /// # Errors
    /// [`Error::NotFinite`] for a non-finite length, [`Error::InvalidInput`] for a closed curve
    /// or a shortening as long as the curve; [`Error::Degenerate`] where the curve has no
    /// tangent at an end; the errors of joining.
    pub fn extended(&self, start: f64, end: f64, style: CurveExtension) -> Result<Curve> {
        if !start.is_finite() || !end.is_finite() {
            return Err(Error::NotFinite {
                what: "extension length",
            });
        }
        if self.is_closed() {
            return Err(Error::InvalidInput(
                "a closed curve cannot be extended".into(),
            ));
        }
        let length = self.length();
        let cut = start.min(0.0).abs() + end.min(0.0).abs();
        if cut >= length {
            return Err(Error::InvalidInput(format!(
                "shortening by {cut} leaves nothing of a curve of length {length}"
            )));
        }
        // Shorten first, on the original curve.
        let d = self.domain();
        let t0 = if start < 0.0 {
            self.parameter_at_length(-start)?
        } else {
            d.t0
        };
        let t1 = if end < 0.0 {
            self.parameter_at_length(length + end)?
        } else {
            d.t1
        };
        let mut core = if t0 > d.t0 || t1 < d.t1 {
            self.trim(Interval::new(t0, t1))?
        } else {
            self.clone()
        };
        if start > 0.0 {
            let piece = core.reversed().extension(start, style)?;
            match piece {
                Extension::Replace(c) => core = c.reversed(),
                Extension::Append(p) => {
                    core = Curve::join_ordered(&[p.reversed(), core], false)?;
                }
            }
        }
        if end > 0.0 {
            match core.extension(end, style)? {
                Extension::Replace(c) => core = c,
                Extension::Append(p) => core = Curve::join_ordered(&[core, p], false)?,
            }
        }
        Ok(core)
    }

    /// The piece that continues the curve past its end by `length` (positive), or the whole
    /// curve extended where it stays one primitive.
    fn extension(&self, length: f64, style: CurveExtension) -> Result<Extension> {
        let d = self.domain();
        let p = self.end_point();
        let tangent = self.tangent_from_left(d.t1)?.ok_or(Error::Degenerate {
            what: "curve tangent at the end",
        })?;
        let line = || Extension::Append(Curve::from(Line::new(p, p + tangent * length)));
        Ok(match (style, self) {
            (CurveExtension::Line, _)
            | (CurveExtension::Smooth, Curve::Line { .. } | Curve::Polyline { .. }) => line(),
            (CurveExtension::Smooth, Curve::Arc { arc, .. }) => {
                let angle = arc.angle.t1 + length / arc.radius();
                if angle - arc.angle.t0 >= std::f64::consts::TAU {
                    return Err(Error::InvalidInput(
                        "the arc extended that far would close on itself".into(),
                    ));
                }
                Extension::Replace(Curve::from(Arc::new(
                    arc.circle,
                    Interval::new(arc.angle.t0, angle),
                )?))
            }
            (CurveExtension::Arc, _) => {
                let k = self.curvature_at_end()?;
                let curvature = k.length();
                if curvature * length <= 1e-12 {
                    line()
                } else {
                    let r = 1.0 / curvature;
                    let centre = p + k * (r * r);
                    let x = (p - centre) / r;
                    let plane = Plane {
                        origin: centre,
                        x_axis: x,
                        y_axis: tangent,
                        z_axis: x.cross(tangent),
                    };
                    let sweep = (length / r).min(std::f64::consts::TAU * (1.0 - 1e-12));
                    Extension::Append(Curve::from(Arc::new(
                        Circle::new(plane, r)?,
                        Interval::new(0.0, sweep),
                    )?))
                }
            }
            (CurveExtension::Smooth, _) => {
                Extension::Append(Curve::Nurbs(smooth_piece(&self.to_nurbs(), length)?))
            }
        })
    }

    /// The curvature vector at the end, approached from inside the curve.
    fn curvature_at_end(&self) -> Result<Vector3> {
        let d = self.domain();
        let k = match self {
            Curve::Nurbs(c) => {
                let span = basis::span_index(c.degree(), c.knots(), d.t1);
                let mut der = [Vector3::ZERO; 3];
                c.derivatives_in_span(span, d.t1, &mut der);
                crate::curve::nurbs::curvature_vector(der[1], der[2])
            }
            _ => self.curvature_at(d.t1),
        };
        k.ok_or(Error::Degenerate {
            what: "curve tangent at the end",
        })
    }
}

/// An extension: a piece to join after the curve, or the curve itself made longer.
enum Extension {
    Append(Curve),
    Replace(Curve),
}

/// The blossom of the Bézier curve with homogeneous control points `cvs` at `us` (one value
/// per degree): de Casteljau's algorithm with a different parameter at each level.
fn blossom(cvs: &[[f64; 4]], us: &[f64]) -> [f64; 4] {
    let mut work = cvs.to_vec();
    for (level, &u) in us.iter().enumerate() {
        for i in 0..work.len() - 1 - level {
            let next = work[i + 1];
            for (c, value) in work[i].iter_mut().enumerate() {
                *value = (1.0 - u) * *value + u * next[c];
            }
        }
    }
    work[0]
}

/// The last span of `curve` continued from its end by the arc length `length`: a Bézier
/// curve of the curve's degree on the span's parameters extrapolated.
fn smooth_piece(curve: &NurbsCurve, length: f64) -> Result<NurbsCurve> {
    let d = curve.domain();
    let p = curve.degree();
    // The last span as a Bézier curve on [a, b] = [a, d.t1].
    let span = basis::span_index(p, curve.knots(), d.t1);
    let a = curve.knots()[span];
    let last = curve.trim(Interval::new(a, d.t1))?;
    let cvs = last.homogeneous_points();
    let piece = |s: f64| -> Result<NurbsCurve> {
        // Bézier parameter 1 is the end; s > 1 extrapolates.
        let mut points = Vec::with_capacity(p + 1);
        let mut weights = Vec::with_capacity(p + 1);
        for i in 0..=p {
            let us: Vec<f64> = std::iter::repeat_n(1.0, p - i)
                .chain(std::iter::repeat_n(s, i))
                .collect();
            let h = blossom(&cvs, &us);
            if h[3].is_nan() || h[3] <= 0.0 {
                return Err(Error::InvalidInput(
                    "the smooth extension runs past where the curve's end span is defined".into(),
                ));
            }
            points.push(Point3::new(h[0] / h[3], h[1] / h[3], h[2] / h[3]));
            weights.push(h[3]);
        }
        let scale = d.t1 - a;
        let mut knots = vec![d.t1; p];
        knots.extend(std::iter::repeat_n(d.t1 + (s - 1.0) * scale, p));
        NurbsCurve::new(p, points, weights, knots)
    };
    // Bracket the parameter reach by doubling, then bisect on the length.
    let speed = curve.derivative_at(d.t1).length() * (d.t1 - a);
    let mut hi = 1.0 + (length / speed.max(f64::MIN_POSITIVE)).max(1e-9);
    let mut lo = 1.0;
    for _ in 0..200 {
        if piece(hi)?.length() >= length {
            break;
        }
        lo = hi;
        hi = 1.0 + 2.0 * (hi - 1.0);
    }
    let mut best = piece(hi)?;
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        let c = piece(mid)?;
        let l = c.length();
        if (l - length).abs() <= EXTENSION_LENGTH_TOLERANCE * length {
            return Ok(c);
        }
        if l < length {
            lo = mid;
        } else {
            hi = mid;
            best = c;
        }
        if hi - lo <= f64::EPSILON * hi {
            break;
        }
    }
    Ok(best)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Polyline;
    use proptest::prelude::*;
    use std::f64::consts::PI;

    fn cubic() -> Curve {
        Curve::from(
            NurbsCurve::create(
                &[
                    Point3::new(0.0, 0.0, 0.0),
                    Point3::new(1.0, 2.0, 0.0),
                    Point3::new(3.0, 2.0, 1.0),
                    Point3::new(4.0, 0.0, 0.0),
                    Point3::new(6.0, 1.0, 0.0),
                ],
                3,
                false,
            )
            .unwrap(),
        )
    }

    fn contains(extended: &Curve, original: &Curve) -> bool {
        let d = original.domain();
        (0..=20).all(|k| {
            let p = original.point_at(d.parameter_at(f64::from(k) / 20.0));
            extended.closest_point(p).unwrap().distance < 1e-9
        })
    }

    #[test]
    fn a_line_extended_by_lines() {
        let line = Curve::from(Line::new(Point3::ORIGIN, Point3::new(2.0, 0.0, 0.0)));
        let e = line.extended(1.0, 0.5, CurveExtension::Line).unwrap();
        assert!((e.length() - 3.5).abs() < 1e-14);
        assert_eq!(e.start_point(), Point3::new(-1.0, 0.0, 0.0));
        assert_eq!(e.end_point(), Point3::new(2.5, 0.0, 0.0));
        // Shortened.
        let s = line.extended(-0.5, 0.0, CurveExtension::Smooth).unwrap();
        assert!((s.length() - 1.5).abs() < 1e-14);
        assert!(line.extended(-1.0, -1.0, CurveExtension::Line).is_err());
    }

    #[test]
    fn an_arc_extended_smoothly_stays_an_arc() {
        let arc = Arc::new(
            Circle::new(Plane::WORLD_XY, 2.0).unwrap(),
            Interval::new(0.0, 1.0),
        )
        .unwrap();
        let c = Curve::from(arc);
        let e = c.extended(0.0, 2.0, CurveExtension::Smooth).unwrap();
        assert!(matches!(e, Curve::Arc { .. }));
        assert!((e.length() - 4.0).abs() < 1e-12);
        // The arc extension of a NURBS arc follows the same circle.
        let n = Curve::from(arc.to_nurbs());
        let e = n.extended(0.0, 2.0, CurveExtension::Arc).unwrap();
        assert!((e.length() - 4.0).abs() < 1e-9);
        assert!((e.end_point().to_vector().length() - 2.0).abs() < 1e-12);
        let angle: f64 = 2.0;
        assert!(
            e.end_point()
                .distance(Point3::new(2.0 * angle.cos(), 2.0 * angle.sin(), 0.0))
                < 1e-12
        );
        let _ = PI;
    }

    #[test]
    fn smooth_extension_continues_the_polynomial() {
        let c = cubic();
        let e = c.extended(0.7, 1.3, CurveExtension::Smooth).unwrap();
        assert!((e.length() - (c.length() + 2.0)).abs() < 1e-9);
        assert!(contains(&e, &c));
        // The end span's polynomial, evaluated past the end, lies on the extension.
        let n = c.to_nurbs();
        let d = n.domain();
        let beyond = n.point_at(d.t1 + 0.05 * d.length());
        assert!(e.closest_point(beyond).unwrap().distance < 1e-9);
    }

    #[test]
    fn polylines_and_closed_curves() {
        let l = Curve::from(
            Polyline::new(vec![
                Point3::ORIGIN,
                Point3::new(1.0, 0.0, 0.0),
                Point3::new(1.0, 1.0, 0.0),
            ])
            .unwrap(),
        );
        let e = l.extended(0.0, 1.0, CurveExtension::Arc).unwrap();
        assert_eq!(e.end_point(), Point3::new(1.0, 2.0, 0.0));
        let circle = Curve::from(Circle::new(Plane::WORLD_XY, 1.0).unwrap());
        assert!(circle.extended(1.0, 1.0, CurveExtension::Line).is_err());
        assert!(l.extended(f64::NAN, 1.0, CurveExtension::Line).is_err());
    }

    proptest! {
        /// An extended curve contains the original and is longer by the two lengths.
        #[test]
        fn extensions_contain_the_original(
            a in 0.0f64..3.0,
            b in 0.0f64..3.0,
            style in 0usize..3,
        ) {
            let style = [CurveExtension::Line, CurveExtension::Arc, CurveExtension::Smooth][style];
            let c = cubic();
            let e = c.extended(a, b, style).unwrap();
            prop_assert!(contains(&e, &c));
            prop_assert!((e.length() - (c.length() + a + b)).abs() < 1e-8 * (1.0 + a + b));
            // It leaves each end along the end tangent.
            let d = c.domain();
            let t = c.tangent_at(d.t1).unwrap();
            if b > 1e-3 {
                let cp = e.closest_point(c.end_point()).unwrap();
                let te = e.tangent_at(cp.t).unwrap();
                prop_assert!((te - t).length() < 1e-6);
            }
        }
    }
}

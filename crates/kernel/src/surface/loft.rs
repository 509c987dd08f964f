//! Lofts: a surface through (or, loose, near) a sequence of section curves.
//!
//! The sections are made compatible ([`NurbsCurve::make_compatible`]), which gives every section
//! the same knots in `u` (domain `0..1`) and the same number of control points. Section `k`
//! gets the parameter `v_k`, normalized to `0..1`: the averaged chord length between
//! consecutive sections' control points (The NURBS Book, eq. 9.18 on the control polygons) for
//! [`LoftType::Normal`], [`LoftType::Loose`] and [`LoftType::Straight`]; the averaged square
//! roots of those chords (centripetal, eq. 9.6) for [`LoftType::Tight`], which keeps the
//! surface closer to the sections where they turn sharply; equal steps for
//! [`LoftType::Uniform`]. Each column of control points (the `i`-th point of every section) is
//! then interpolated in homogeneous form by a curve of degree `min(3, sections − 1)` (degree 1
//! for straight lofts) with knots by averaging (eq. 9.8), so that the isocurve at `v_k` is
//! section `k` exactly. A loose loft uses the columns as control points instead (same degree
//! and knots): the surface follows the sections' control net and passes through the first and
//! last sections only. A closed loft repeats the first section at the end (`v = 1`); the
//! surface is then closed but, except for straight lofts, only continuous (not smooth) across
//! that seam.
//!
//! [`align_loft_sections`] is Rhino's seam adjustment: closed sections turned to run the way of
//! the first, each with its seam moved to the point nearest the previous section's seam.

use crate::curve::nurbs::compatible::solve_collocation;
use crate::{Curve, Error, NurbsCurve, NurbsSurface, Result, Vector3};

/// The way a loft passes between its sections.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LoftType {
    /// A smooth surface through the sections: cubic (or of degree sections − 1 if there are
    /// fewer than 4) across them, at chord-length parameters.
    Normal,
    /// A smooth surface whose control points are the sections' control points: it passes
    /// through the first and last sections and near the others.
    Loose,
    /// As normal, at centripetal parameters: closer to the sections where they turn sharply.
    Tight,
    /// Straight (ruled) strips between consecutive sections: degree 1 across them.
    Straight,
    /// As normal, at equally spaced parameters.
    Uniform,
}

/// The most sections a loft takes.
pub const MAX_LOFT_SECTIONS: usize = 10_000;

impl NurbsSurface {
    /// The loft through `sections` (at least two curves), of the given type, optionally closed
    /// (the last section joined back to the first). `u` runs along the sections (domain `0..1`)
    /// and `v` across them (domain `0..1`); the isocurve at each section's `v` is that section.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] for fewer than two sections (three when closed) or more than
    /// [`MAX_LOFT_SECTIONS`], and when two consecutive sections coincide
    /// in every control point; the errors of [`NurbsCurve::make_compatible`].
    pub fn loft(sections: &[NurbsCurve], kind: LoftType, closed: bool) -> Result<Self> {
        let needed = if closed { 3 } else { 2 };
        if sections.len() < needed || sections.len() > MAX_LOFT_SECTIONS {
            return Err(Error::InvalidInput(format!(
                "a{} loft needs at least {needed} and at most {MAX_LOFT_SECTIONS} sections, got {}",
                if closed { " closed" } else { "n open" },
                sections.len()
            )));
        }
        let mut curves = NurbsCurve::make_compatible(sections)?;
        if closed {
            curves.push(curves[0].clone());
        }
        let n = curves.len();
        let count_u = curves[0].point_count();
        let params = match kind {
            LoftType::Tight => section_parameters(&curves, 0.5)?,
            LoftType::Uniform => (0..n).map(|k| k as f64 / (n - 1) as f64).collect(),
            _ => section_parameters(&curves, 1.0)?,
        };
        let degree = match kind {
            LoftType::Straight => 1,
            _ => 3.min(n - 1),
        };
        let knots = averaged_knots(&params, degree);
        let homogeneous: Vec<Vec<[f64; 4]>> =
            curves.iter().map(NurbsCurve::homogeneous_points).collect();
        let mut points = Vec::with_capacity(count_u * n);
        let mut weights = Vec::with_capacity(count_u * n);
        for i in 0..count_u {
            let column: Vec<[f64; 4]> = homogeneous.iter().map(|h| h[i]).collect();
            let cvs = if degree == 1 || kind == LoftType::Loose {
                column
            } else {
                solve_collocation(degree, &knots, &params, column)?
            };
            for h in cvs {
                points.push(crate::Point3::new(h[0] / h[3], h[1] / h[3], h[2] / h[3]));
                weights.push(h[3]);
            }
        }
        if curves.iter().all(|c| !c.is_rational()) {
            weights.fill(1.0);
        }
        Self::from_flat(
            [curves[0].degree(), degree],
            [count_u, n],
            points,
            weights,
            [curves[0].knots().to_vec(), knots],
        )
    }
}

/// The parameters of the sections: averaged chord lengths between their control polygons, each
/// raised to `power` (1 for chord length, ½ for centripetal), normalized to `0..1`.
fn section_parameters(curves: &[NurbsCurve], power: f64) -> Result<Vec<f64>> {
    let n = curves.len();
    let count = curves[0].point_count();
    let mut sum = vec![0.0; n];
    let mut used = 0usize;
    for i in 0..count {
        let chords: Vec<f64> = curves
            .windows(2)
            .map(|w| w[0].points()[i].distance(w[1].points()[i]).powf(power))
            .collect();
        let total: f64 = chords.iter().sum();
        if total.is_nan() || total <= 0.0 {
            continue;
        }
        used += 1;
        let mut acc = 0.0;
        for (k, c) in chords.iter().enumerate() {
            acc += c;
            sum[k + 1] += acc / total;
        }
    }
    if used == 0 {
        return Err(Error::InvalidInput(
            "the loft's sections all coincide".into(),
        ));
    }
    let mut params: Vec<f64> = sum.iter().map(|x| x / used as f64).collect();
    params[0] = 0.0;
    params[n - 1] = 1.0;
    if params.windows(2).any(|w| w[1] <= w[0]) {
        return Err(Error::InvalidInput(
            "two consecutive loft sections coincide".into(),
        ));
    }
    Ok(params)
}

/// Rhino's seam adjustment of closed loft sections: each closed section after the first is
/// reversed when it turns the other way about the axis of the sections (its area vector
/// points against the previous closed section's), then its seam is moved to its point nearest
/// the previous section's start. Open sections are left as they are.
///
/// # Errors
/// The errors of the closest-point query and of splitting a section at its new seam.
pub fn align_loft_sections(sections: &[NurbsCurve]) -> Result<Vec<NurbsCurve>> {
    let mut out: Vec<NurbsCurve> = Vec::with_capacity(sections.len());
    let mut previous_area: Option<Vector3> = None;
    for section in sections {
        if !section.is_closed() {
            out.push(section.clone());
            continue;
        }
        let mut curve = Curve::from(section.clone());
        let area = area_vector(section);
        if let Some(before) = previous_area
            && before.dot(area) < 0.0
        {
            curve = curve.reversed();
        }
        previous_area = Some(area_vector(&curve.to_nurbs()));
        if let Some(before) = out.last() {
            let target = before.point_at(before.domain().t0);
            let t = curve.closest_point(target)?.t;
            let d = curve.domain();
            let slack = 1e-12 * (1.0 + d.t0.abs().max(d.t1.abs()));
            if t - d.t0 > slack && d.t1 - t > slack {
                let mut pieces = curve.split_at_parameters(&[t])?;
                if let Some(moved) = pieces.pop() {
                    curve = moved;
                }
            }
        }
        out.push(curve.to_nurbs());
    }
    Ok(out)
}

/// The area vector of a closed curve (Newell's, on samples): its direction says which way the
/// curve turns.
fn area_vector(curve: &NurbsCurve) -> Vector3 {
    let d = curve.domain();
    let samples: Vec<crate::Point3> = (0..64)
        .map(|k| curve.point_at(d.t0 + d.length() * k as f64 / 64.0))
        .collect();
    let mut area = Vector3::ZERO;
    for (k, p) in samples.iter().enumerate() {
        let q = samples[(k + 1) % samples.len()];
        area += p.to_vector().cross(q.to_vector());
    }
    area
}

/// Knots in Rhino form by averaging the parameters (The NURBS Book, eq. 9.8).
fn averaged_knots(params: &[f64], degree: usize) -> Vec<f64> {
    let n = params.len() - 1;
    let mut knots = vec![params[0]; degree];
    for j in 1..=n - degree {
        knots.push(params[j..j + degree].iter().sum::<f64>() / degree as f64);
    }
    knots.extend(std::iter::repeat_n(params[n], degree));
    knots
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Circle, Interval, Plane, Point3, SurfaceDirection, Vector3};
    use proptest::prelude::*;

    fn circle(z: f64, r: f64) -> NurbsCurve {
        let plane = Plane::WORLD_XY.translated(Vector3::new(0.0, 0.0, z));
        Circle::new(plane, r).unwrap().to_nurbs()
    }

    /// The isocurve at `v` matches `section` within `tol` at many parameters.
    fn passes_through(s: &NurbsSurface, v: f64, section: &NurbsCurve, tol: f64) -> bool {
        let iso = s.isocurve(SurfaceDirection::U, v).unwrap();
        (0..=32).all(|k| {
            let f = k as f64 / 32.0;
            let a = iso.point_at(iso.domain().parameter_at(f));
            let b = section.point_at(section.domain().parameter_at(f));
            a.distance(b) < tol
        })
    }

    /// The distinct `v` knots: the section parameters of a straight loft.
    fn section_vs(s: &NurbsSurface) -> Vec<f64> {
        let mut vs: Vec<f64> = s.knots_v().to_vec();
        vs.dedup();
        vs
    }

    #[test]
    fn straight_loft_of_circles_is_a_stack_of_cones() {
        let sections = [circle(0.0, 1.0), circle(1.0, 2.0), circle(3.0, 2.0)];
        let s = NurbsSurface::loft(&sections, LoftType::Straight, false).unwrap();
        assert_eq!(s.degree_v(), 1);
        assert_eq!(s.domain_v(), Interval::UNIT);
        let vs = section_vs(&s);
        assert_eq!(vs.len(), 3);
        for (v, c) in vs.iter().zip(&sections) {
            assert!(passes_through(&s, *v, c, 1e-12));
        }
    }

    #[test]
    fn normal_loft_passes_through_four_sections() {
        let sections = [
            circle(0.0, 1.0),
            circle(1.0, 2.0),
            circle(2.0, 1.5),
            circle(4.0, 3.0),
        ];
        let s = NurbsSurface::loft(&sections, LoftType::Normal, false).unwrap();
        assert_eq!(s.degree_v(), 3);
        let curves = NurbsCurve::make_compatible(&sections).unwrap();
        let params = section_parameters(&curves, 1.0).unwrap();
        for (v, c) in params.iter().zip(&sections) {
            assert!(passes_through(&s, *v, c, 1e-10));
        }
        // Closed: the seam returns to the first section.
        let closed = NurbsSurface::loft(&sections, LoftType::Normal, true).unwrap();
        assert!(passes_through(&closed, 0.0, &sections[0], 1e-12));
        assert!(passes_through(&closed, 1.0, &sections[0], 1e-10));
    }

    fn four_circles() -> [NurbsCurve; 4] {
        [
            circle(0.0, 1.0),
            circle(1.0, 2.0),
            circle(1.2, 1.5),
            circle(4.0, 3.0),
        ]
    }

    #[test]
    fn loose_lofts_take_the_sections_control_points() {
        let sections = four_circles();
        let s = NurbsSurface::loft(&sections, LoftType::Loose, false).unwrap();
        assert_eq!(s.degree_v(), 3);
        let curves = NurbsCurve::make_compatible(&sections).unwrap();
        let count_u = curves[0].point_count();
        for (k, c) in curves.iter().enumerate() {
            for i in 0..count_u {
                assert!(s.control_point(i, k).unwrap().distance(c.points()[i]) < 1e-12);
            }
        }
        // Through the first and last sections, not through the middle ones.
        assert!(passes_through(&s, 0.0, &sections[0], 1e-12));
        assert!(passes_through(&s, 1.0, &sections[3], 1e-12));
        let params = section_parameters(&curves, 1.0).unwrap();
        assert!(!passes_through(&s, params[1], &sections[1], 1e-3));
    }

    #[test]
    fn tight_and_uniform_lofts_pass_through_their_sections_at_their_parameters() {
        let sections = four_circles();
        let curves = NurbsCurve::make_compatible(&sections).unwrap();
        let chord = section_parameters(&curves, 1.0).unwrap();
        let centripetal = section_parameters(&curves, 0.5).unwrap();
        // The short step between the second and third sections gets a larger share.
        assert!(centripetal[2] - centripetal[1] > chord[2] - chord[1]);
        let tight = NurbsSurface::loft(&sections, LoftType::Tight, false).unwrap();
        for (v, c) in centripetal.iter().zip(&sections) {
            assert!(passes_through(&tight, *v, c, 1e-10));
        }
        let uniform = NurbsSurface::loft(&sections, LoftType::Uniform, false).unwrap();
        for (k, c) in sections.iter().enumerate() {
            assert!(passes_through(&uniform, k as f64 / 3.0, c, 1e-10));
        }
    }

    #[test]
    fn seams_and_directions_are_aligned() {
        let base = circle(0.0, 1.0);
        // The second circle runs the other way, the third starts half a turn round.
        let reversed = Curve::from(circle(1.0, 1.0)).reversed().to_nurbs();
        let turned = {
            let c = Curve::from(circle(2.0, 1.0));
            let d = c.domain();
            let mut pieces = c.split_at_parameters(&[d.t0 + 0.5 * d.length()]).unwrap();
            pieces.pop().unwrap().to_nurbs()
        };
        let open = NurbsCurve::create(
            &[Point3::new(0.0, 0.0, 3.0), Point3::new(1.0, 0.0, 3.0)],
            1,
            false,
        )
        .unwrap();
        let aligned = align_loft_sections(&[base.clone(), reversed, turned, open.clone()]).unwrap();
        let z = area_vector(&aligned[0]);
        for c in &aligned[..3] {
            assert!(area_vector(c).dot(z) > 0.0);
            let start = c.point_at(c.domain().t0);
            assert!(start.x > 0.999 && start.y.abs() < 1e-9, "{start:?}");
        }
        assert_eq!(aligned[3], open);
    }

    #[test]
    fn bad_lofts_are_errors() {
        let c = circle(0.0, 1.0);
        assert!(NurbsSurface::loft(std::slice::from_ref(&c), LoftType::Normal, false).is_err());
        assert!(NurbsSurface::loft(&[c.clone(), c.clone()], LoftType::Normal, false).is_err());
        assert!(
            NurbsSurface::loft(&[c.clone(), circle(1.0, 1.0)], LoftType::Normal, true).is_err()
        );
    }

    proptest! {
        /// Any loft of cubic sections passes through its sections.
        #[test]
        fn lofts_pass_through_their_sections(
            heights in proptest::collection::vec(0.5f64..3.0, 1..6),
            wiggle in proptest::collection::vec(-1.0f64..1.0, 5 * 6),
            straight in any::<bool>(),
        ) {
            let mut z = 0.0;
            let mut sections = Vec::new();
            for (k, h) in std::iter::once(0.0).chain(heights.iter().copied()).enumerate() {
                z += h;
                let pts: Vec<Point3> = (0..5)
                    .map(|i| Point3::new(i as f64, wiggle[k * 5 + i], z))
                    .collect();
                // Alternate degrees to exercise elevation and knot merging.
                let degree = if k % 2 == 0 { 3 } else { 2 };
                sections.push(NurbsCurve::create(&pts, degree, false).unwrap());
            }
            let kind = if straight { LoftType::Straight } else { LoftType::Normal };
            let s = NurbsSurface::loft(&sections, kind, false).unwrap();
            let curves = NurbsCurve::make_compatible(&sections).unwrap();
            let params = section_parameters(&curves, 1.0).unwrap();
            for (v, c) in params.iter().zip(&sections) {
                prop_assert!(passes_through(&s, *v, c, 1e-9));
            }
        }
    }
}

//! Curve › Util: Flip Curve, Split Curve, Fillet, Fillet Distance, Seam and Fit Curve.

use locus_kernel::Curve;
use locus_kernel::tolerance::{DEFAULT_TOLERANCE, DOCUMENT_TOLERANCE};
use locus_runtime::{DataType, NodeRegistry, NodeType, Port, Shared};

use super::{curve_input, degree_from, finite_parameter};

/// Id of [`flip_curve`].
pub const FLIP_CURVE: &str = "curve.flip_curve";
/// Id of [`split_curve`].
pub const SPLIT_CURVE: &str = "curve.split_curve";
/// Id of [`fillet`].
pub const FILLET: &str = "curve.fillet";
/// Id of [`fillet_distance`].
pub const FILLET_DISTANCE: &str = "curve.fillet_distance";
/// Id of [`seam`].
pub const SEAM: &str = "curve.seam";
/// Id of [`fit_curve`].
pub const FIT_CURVE: &str = "curve.fit_curve";

/// The number of places along a curve where its direction is compared with a guide's.
const DIRECTION_SAMPLES: usize = 16;

/// Registers the utility nodes.
pub fn register(registry: &mut NodeRegistry) {
    for t in [
        flip_curve(),
        split_curve(),
        fillet(),
        fillet_distance(),
        seam(),
        fit_curve(),
    ] {
        registry.register(t);
    }
}

fn util(id: &str, name: &str, nickname: &str) -> NodeType {
    NodeType::new(id, name, nickname, "Curve").subcategory("Util")
}

/// Whether `curve` runs against `guide`: at evenly spaced parameters of `curve`, the tangent
/// is compared (dot product) with the guide's tangent at the guide's closest point, and the
/// sum of the comparisons is negative.
fn runs_against(curve: &Curve, guide: &Curve) -> Result<bool, locus_kernel::Error> {
    let d = curve.domain();
    let mut agreement = 0.0;
    for i in 0..DIRECTION_SAMPLES {
        let t = d.parameter_at((i as f64 + 0.5) / DIRECTION_SAMPLES as f64);
        let Some(tangent) = curve.tangent_at(t) else {
            continue;
        };
        let cp = guide.closest_point(curve.point_at(t))?;
        if let Some(g) = guide.tangent_at(cp.t) {
            agreement += tangent.dot(g);
        }
    }
    Ok(agreement < 0.0)
}

/// Flip Curve \[Flip\]: a curve reversed, optionally only when it runs against a guide.
pub fn flip_curve() -> NodeType {
    util(FLIP_CURVE, "Flip Curve", "Flip")
        .gh_guid("22990b1f-9be6-477c-ad89-f775cd347105")
        .description(
            "Reverses the direction of a curve, as Rhino's Flip: the domain t0 to t1 becomes \
             −t1 to −t0, so the point at t moves to −t. With a guide curve the curve is reversed \
             only when it runs against the guide (its tangents, compared with the guide's at \
             the closest points of 16 evenly spaced samples, mostly point the other way).",
        )
        .input(Port::new("Curve", "C", DataType::Curve).doc("Curve to flip."))
        .input(
            Port::new("Guide", "G", DataType::Curve)
                .doc("Optional guide curve whose direction the result follows.")
                .optional(),
        )
        .output(Port::new("Curve", "C", DataType::Curve).doc("The flipped (or unchanged) curve."))
        .output(Port::new("Flag", "F", DataType::Boolean).doc("True when the curve was reversed."))
        .solve(|s| {
            let curve = curve_input(s, 0)?;
            let flip = if s.value(1).is_some() {
                let guide = curve_input(s, 1)?;
                runs_against(&curve, &guide)?
            } else {
                true
            };
            let out = if flip {
                Shared::new(curve.reversed())
            } else {
                curve
            };
            s.set(0, out);
            s.set(1, flip);
            Ok(())
        })
}

/// Split Curve \[Split\]: the two pieces of a curve on either side of a parameter.
pub fn split_curve() -> NodeType {
    util(SPLIT_CURVE, "Split Curve", "Split")
        .description(
            "Cuts a curve at one parameter into the piece before it (domain t0 to t) and the \
             piece after it (t to t1), closed curves included (their seam stays an end). \
             Grasshopper has no single-cut component (it uses Shatter); this one gives the two \
             pieces on separate outputs. Pieces keep their parameters and, where possible, the \
             kind of their curve.",
        )
        .input(Port::new("Curve", "C", DataType::Curve).doc("Curve to cut."))
        .input(
            Port::new("Parameter", "t", DataType::Number)
                .doc("Parameter to cut at, strictly inside the curve's domain."),
        )
        .output(Port::new("Curve A", "A", DataType::Curve).doc("The piece from t0 to t."))
        .output(Port::new("Curve B", "B", DataType::Curve).doc("The piece from t to t1."))
        .solve(|s| {
            let curve = curve_input(s, 0)?;
            let t = finite_parameter(*s.item::<f64>(1)?, "t")?;
            let (a, b) = curve.split_at(t)?;
            s.set(0, Shared::new(a));
            s.set(1, Shared::new(b));
            Ok(())
        })
}

/// Fillet \[Fillet\]: every corner of a curve rounded by a tangent arc of one radius.
pub fn fillet() -> NodeType {
    util(FILLET, "Fillet", "Fillet")
        .gh_guid("2f407944-81c3-4062-a485-276454ec4b8c")
        .description(
            "Rounds the sharp corners of a curve (its kinks, and the seam of a closed curve when \
             it is one) with arcs of the given radius, tangent to the curve on both sides, as \
             Rhino's CreateFilletCornersCurve: straight segments are cut back by r·tan(φ/2) \
             for a turn of φ, curved pieces where the arc's centre is r from both. A corner \
             whose arc does not fit (the radius is too large for the segments beside it, or \
             the previous corner's fillet already used them; the curve turns straight back; \
             the curve is not planar there) stays sharp, with a warning naming it: corner k is \
             where the k-th smooth piece starts, the vertex k of a polyline. A radius of 0 \
             gives the curve unchanged. The result is one curve.",
        )
        .input(Port::new("Curve", "C", DataType::Curve).doc("Curve to fillet."))
        .input(
            Port::new("Radius", "R", DataType::Number)
                .doc("Radius of the fillets, in model units, zero or positive. Default 1.")
                .default_value(1.0),
        )
        .output(
            Port::new("Curve", "C", DataType::Curve).doc("The curve with its corners filleted."),
        )
        .solve(|s| {
            let curve = curve_input(s, 0)?;
            let radius = *s.item::<f64>(1)?;
            if !radius.is_finite() || radius < 0.0 {
                return Err(format!(
                    "input R: the radius must be zero or a positive number, got {radius}"
                )
                .into());
            }
            let res = curve.fillet_corners(radius, DEFAULT_TOLERANCE)?;
            set_fillet(s, res);
            Ok(())
        })
}

/// Writes a fillet's curve to output 0, with a warning for each corner left sharp.
pub(crate) fn set_fillet(s: &mut locus_runtime::Solve<'_>, res: locus_kernel::CurveFillet) {
    for corner in &res.sharp {
        let p = corner.point;
        s.warning(format!(
            "corner {} at ({}, {}, {}) left sharp: {}",
            corner.index, p.x, p.y, p.z, corner.reason
        ));
    }
    s.set(0, Shared::new(res.curve));
}

/// Fillet Distance \[Fillet\]: every corner of a curve rounded by an arc starting a distance
/// from it.
pub fn fillet_distance() -> NodeType {
    util(FILLET_DISTANCE, "Fillet Distance", "Fillet")
        .gh_guid("6fb21315-a032-400e-a80f-248687f5507f")
        .description(
            "Rounds the sharp corners of a curve as Fillet does, but sizes each fillet by the \
             distance from the corner to where the arc starts and ends, rather than by its \
             radius: a turn of φ gets the radius D / tan(φ/2), so the arc leaves a straight \
             segment exactly D before the corner (close to D along curved pieces). Corners \
             whose arc does not fit stay sharp, with a warning naming them (corner k is where \
             the k-th smooth piece starts, the vertex k of a polyline). A distance of 0 gives \
             the curve unchanged.",
        )
        .input(Port::new("Curve", "C", DataType::Curve).doc("Curve to fillet."))
        .input(
            Port::new("Distance", "D", DataType::Number)
                .doc("Distance from each corner to the start of its fillet, in model units, zero or positive. Default 1.")
                .default_value(1.0),
        )
        .output(
            Port::new("Curve", "C", DataType::Curve).doc("The curve with its corners filleted."),
        )
        .solve(|s| {
            let curve = curve_input(s, 0)?;
            let distance = *s.item::<f64>(1)?;
            if !distance.is_finite() || distance < 0.0 {
                return Err(format!(
                    "input D: the distance must be zero or a positive number, got {distance}"
                )
                .into());
            }
            let res = curve.fillet_corners_by_distance(distance, DEFAULT_TOLERANCE)?;
            set_fillet(s, res);
            Ok(())
        })
}

/// Seam \[Seam\]: a closed curve with its seam moved to a parameter.
pub fn seam() -> NodeType {
    util(SEAM, "Seam", "Seam")
        .gh_guid("42ad8dc1-b0c0-40df-91f5-2c46e589e6c2")
        .description(
            "Moves the seam (start and end point) of a closed curve to the point at parameter \
             t, as Rhino's ChangeClosedCurveSeam: the curve keeps its shape and direction, and \
             its domain becomes t to t plus the old domain's length, so every point keeps its \
             parameter (or that parameter plus the period). A parameter outside the domain is \
             taken modulo its length; one at the present seam leaves the curve as it is. An \
             open curve is an error.",
        )
        .input(Port::new("Curve", "C", DataType::Curve).doc("Closed curve to adjust."))
        .input(Port::new("Seam", "t", DataType::Number).doc("Parameter of the new seam."))
        .output(Port::new("Curve", "C", DataType::Curve).doc("The curve with its new seam."))
        .solve(|s| {
            let curve = curve_input(s, 0)?;
            let t = finite_parameter(*s.item::<f64>(1)?, "t")?;
            if !curve.is_closed() {
                return Err("input C: the curve is not closed, so it has no seam to move".into());
            }
            let d = curve.domain();
            let period = d.length();
            let wrapped = d.t0 + (t - d.t0).rem_euclid(period);
            let slack = 1e-12 * (1.0 + d.t0.abs().max(d.t1.abs()));
            if wrapped - d.t0 <= slack || d.t1 - wrapped <= slack {
                s.set(0, curve);
                return Ok(());
            }
            let mut pieces = curve.split_at_parameters(&[wrapped])?;
            let Some(moved) = pieces.pop() else {
                return Err("the seam could not be moved".into());
            };
            let moved = if wrapped == t {
                moved
            } else {
                moved.reparameterized(locus_kernel::Interval::new(t, t + period))?
            };
            s.set(0, Shared::new(moved));
            Ok(())
        })
}

/// Fit Curve \[Fit\]: a curve of a chosen degree within a tolerance of another.
pub fn fit_curve() -> NodeType {
    util(FIT_CURVE, "Fit Curve", "Fit")
        .gh_guid("a3f9f19e-3e6c-4ac7-97c3-946de32c3e8e")
        .description(
            "Fits a non-rational NURBS curve of a chosen degree along a curve, within a \
             tolerance: a least-squares fit on uniform knots over the curve's domain, with the \
             curve's end points, whose number of spans doubles until the fit is within the \
             tolerance of the curve at every sample parameter and halfway between them (up to \
             1024 spans; beyond that it is an error). The fit keeps the domain; kinks are \
             rounded off within the tolerance. Rhino's Fit may place its knots differently.",
        )
        .input(Port::new("Curve", "C", DataType::Curve).doc("Curve to fit."))
        .input(
            Port::new("Degree", "D", DataType::Integer)
                .optional()
                .doc("Degree of the fit, 1 to 15; when omitted, the curve's own degree."),
        )
        .input(
            Port::new("Tolerance", "Ft", DataType::Number)
                .optional()
                .doc("Largest distance allowed from the curve, positive; when omitted, the document tolerance 0.001."),
        )
        .output(Port::new("Curve", "C", DataType::Curve).doc("The fitted curve."))
        .solve(|s| {
            let curve = curve_input(s, 0)?;
            let degree = match s.item_opt::<i64>(1) {
                Some(&d) => degree_from(d).map_err(|e| format!("input D: {e}"))?,
                None => curve.degree(),
            };
            let tolerance = match s.item_opt::<f64>(2) {
                Some(&t) if t.is_finite() && t > 0.0 => t,
                Some(&t) => {
                    return Err(format!(
                        "input Ft: the tolerance must be a positive number, got {t}"
                    )
                    .into());
                }
                None => DOCUMENT_TOLERANCE,
            };
            let fit = curve.fit(degree, tolerance)?;
            s.set(0, Shared::new(Curve::from(fit)));
            Ok(())
        })
}

#[cfg(test)]
mod tests {
    use locus_kernel::{Circle, Interval, Line, Plane, Point3};
    use locus_runtime::{DataTree, NodeCall, Value};

    use super::*;
    use crate::curve::test_support::*;

    fn line(a: (f64, f64), b: (f64, f64)) -> Curve {
        Line::new(Point3::new(a.0, a.1, 0.0), Point3::new(b.0, b.1, 0.0)).into()
    }

    #[test]
    fn flip_without_guide_reverses() {
        let r = NodeCall::new(&flip_curve())
            .input(curve_tree(line((0.0, 0.0), (4.0, 0.0))))
            .run();
        let c = curves(&r.outputs[0])[0].clone();
        assert_eq!(c.domain(), Interval::new(-4.0, 0.0));
        assert_eq!(c.start_point(), Point3::new(4.0, 0.0, 0.0));
        assert_eq!(values(&r.outputs[1]), vec![Some(Value::Boolean(true))]);
    }

    #[test]
    fn flip_follows_a_guide() {
        let guide = line((0.0, 1.0), (10.0, 1.5));
        let r = NodeCall::new(&flip_curve())
            .input(DataTree::from_list(vec![
                Shared::new(line((0.0, 0.0), (4.0, 0.0))),
                Shared::new(line((4.0, 0.0), (0.0, 0.0))),
            ]))
            .input(curve_tree(guide))
            .run();
        assert_eq!(
            values(&r.outputs[1]),
            vec![Some(Value::Boolean(false)), Some(Value::Boolean(true))]
        );
        for c in curves(&r.outputs[0]) {
            assert_eq!(c.start_point(), Point3::ORIGIN);
        }
    }

    #[test]
    fn flip_bad_input() {
        let r = NodeCall::new(&flip_curve())
            .input(curve_tree(line((0.0, 0.0), (4.0, 0.0))))
            .input(DataTree::from_item(Point3::ORIGIN))
            .run();
        assert!(single_error(&r).contains("invalid cast: Point"));
    }

    #[test]
    fn split_a_circle() {
        let r = NodeCall::new(&split_curve())
            .input(curve_tree(Circle::new(Plane::WORLD_XY, 1.0).unwrap()))
            .input(DataTree::from_list(vec![1.0, 0.0, 7.0, f64::NAN]))
            .run();
        let a = values(&r.outputs[0]);
        let b = values(&r.outputs[1]);
        let (Some(Value::Curve(a0)), Some(Value::Curve(b0))) = (&a[0], &b[0]) else {
            panic!("{a:?}")
        };
        assert!(matches!(**a0, Curve::Arc { .. }));
        assert_eq!(a0.domain(), Interval::new(0.0, 1.0));
        assert_eq!(b0.domain(), Interval::new(1.0, std::f64::consts::TAU));
        assert!((a0.length() + b0.length() - std::f64::consts::TAU).abs() < 1e-14);
        assert_eq!(a[1..], [None, None, None]);
        let errors = messages(&r, locus_runtime::Level::Error);
        assert_eq!(errors.len(), 3);
        assert!(errors[0].contains("not inside the domain"), "{errors:?}");
    }

    fn polyline(points: &[(f64, f64)]) -> Curve {
        locus_kernel::Polyline::new(
            points
                .iter()
                .map(|&(x, y)| Point3::new(x, y, 0.0))
                .collect(),
        )
        .unwrap()
        .into()
    }

    #[test]
    fn fillet_rounds_a_rectangle() {
        let rect = polyline(&[(0.0, 0.0), (6.0, 0.0), (6.0, 4.0), (0.0, 4.0), (0.0, 0.0)]);
        let r = NodeCall::new(&fillet())
            .input(curve_tree(rect))
            .input(DataTree::from_list(vec![1.0, 0.0]))
            .run();
        assert!(r.messages.is_empty(), "{:?}", r.messages);
        let out = curves(&r.outputs[0]);
        assert!((out[0].length() - (12.0 + 2.0 * std::f64::consts::PI)).abs() < 1e-9);
        assert!(out[0].is_closed());
        assert!((out[1].length() - 20.0).abs() < 1e-12);
    }

    #[test]
    fn fillet_warns_about_corners_left_sharp() {
        let c = polyline(&[(0.0, 0.0), (1.0, 0.0), (1.0, 5.0), (6.0, 5.0)]);
        let r = NodeCall::new(&fillet())
            .input(curve_tree(c))
            .input(DataTree::from_item(2.0))
            .run();
        let warnings = messages(&r, locus_runtime::Level::Warning);
        assert_eq!(
            warnings,
            [
                "corner 1 at (1, 0, 0) left sharp: the radius is too large for the segments beside it"
            ]
        );
        assert_eq!(curves(&r.outputs[0]).len(), 1);
    }

    #[test]
    fn fillet_distance_sets_back_by_the_distance() {
        let rect = polyline(&[(0.0, 0.0), (6.0, 0.0), (6.0, 4.0), (0.0, 4.0), (0.0, 0.0)]);
        let r = NodeCall::new(&fillet_distance())
            .input(curve_tree(rect.clone()))
            .input(DataTree::from_item(0.5))
            .run();
        assert!(r.messages.is_empty(), "{:?}", r.messages);
        // Right angles: radius 0.5, sides shortened by 1 each, four quarter circles.
        let c = curves(&r.outputs[0])[0].clone();
        assert!((c.length() - (16.0 + std::f64::consts::PI)).abs() < 1e-9);
        let r = NodeCall::new(&fillet_distance())
            .input(curve_tree(rect))
            .input(DataTree::from_item(-0.5))
            .run();
        assert!(single_error(&r).contains("input D"), "{:?}", r.messages);
    }

    #[test]
    fn fillet_bad_input_names_the_port() {
        let c = polyline(&[(0.0, 0.0), (1.0, 0.0), (1.0, 5.0)]);
        for bad in [-1.0, f64::NAN, f64::INFINITY] {
            let r = NodeCall::new(&fillet())
                .input(curve_tree(c.clone()))
                .input(DataTree::from_item(bad))
                .run();
            assert!(single_error(&r).contains("input R"), "{:?}", r.messages);
        }
        let r = NodeCall::new(&fillet())
            .input(DataTree::from_item(Point3::ORIGIN))
            .run();
        assert!(!messages(&r, locus_runtime::Level::Error).is_empty());
    }

    #[test]
    fn seam_moves_along_a_closed_polyline() {
        let square = polyline(&[(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0), (0.0, 0.0)]);
        let r = NodeCall::new(&seam())
            .input(curve_tree(square.clone()))
            .input(DataTree::from_list(vec![2.0, 1.5, 6.0, 0.0]))
            .run();
        assert!(r.messages.is_empty(), "{:?}", r.messages);
        let out = curves(&r.outputs[0]);
        assert_eq!(out[0].start_point(), Point3::new(1.0, 1.0, 0.0));
        assert_eq!(out[0].domain(), Interval::new(2.0, 6.0));
        assert!(close(
            out[1].start_point(),
            Point3::new(1.0, 0.5, 0.0),
            1e-15
        ));
        assert!(close(
            out[1].point_at(2.0),
            Point3::new(1.0, 1.0, 0.0),
            1e-15
        ));
        // 6 is 2 modulo the period 4, with the domain starting at 6.
        assert_eq!(out[2].domain(), Interval::new(6.0, 10.0));
        assert!(close(
            out[2].start_point(),
            Point3::new(1.0, 1.0, 0.0),
            1e-15
        ));
        assert_eq!(*out[3], square);
        for c in &out {
            assert!(c.is_closed());
            assert!((c.length() - 4.0).abs() < 1e-12);
        }
    }

    #[test]
    fn seam_on_a_circle_and_on_open_curves() {
        let r = NodeCall::new(&seam())
            .input(curve_tree(Circle::new(Plane::WORLD_XY, 2.0).unwrap()))
            .input(DataTree::from_item(std::f64::consts::FRAC_PI_2))
            .run();
        let c = curves(&r.outputs[0])[0].clone();
        assert!(close(c.start_point(), Point3::new(0.0, 2.0, 0.0), 1e-15));
        assert!((c.length() - 4.0 * std::f64::consts::PI).abs() < 1e-12);
        let r = NodeCall::new(&seam())
            .input(curve_tree(line((0.0, 0.0), (4.0, 0.0))))
            .input(DataTree::from_item(1.0))
            .run();
        assert!(single_error(&r).contains("input C"), "{:?}", r.messages);
        let r = NodeCall::new(&seam())
            .input(curve_tree(Circle::new(Plane::WORLD_XY, 2.0).unwrap()))
            .input(DataTree::from_item(f64::NAN))
            .run();
        assert!(single_error(&r).contains("parameter t"), "{:?}", r.messages);
    }

    #[test]
    fn fit_curve_keeps_the_degree_or_takes_another() {
        let circle = Circle::new(Plane::WORLD_XY, 5.0).unwrap();
        let r = NodeCall::new(&fit_curve()).input(curve_tree(circle)).run();
        assert!(r.messages.is_empty(), "{:?}", r.messages);
        let c = curves(&r.outputs[0])[0].clone();
        assert_eq!(c.degree(), 2);
        let Curve::Nurbs(n) = &*c else {
            panic!("{c:?}")
        };
        assert!(!n.is_rational());
        for k in 0..50 {
            let t = c.domain().parameter_at(k as f64 / 50.0);
            assert!((c.point_at(t).distance(Point3::ORIGIN) - 5.0).abs() <= DOCUMENT_TOLERANCE);
        }
        let r = NodeCall::new(&fit_curve())
            .input(curve_tree(line((0.0, 0.0), (4.0, 0.0))))
            .input(DataTree::from_item(3_i64))
            .input(DataTree::from_item(1e-6))
            .run();
        assert_eq!(curves(&r.outputs[0])[0].degree(), 3);
    }

    #[test]
    fn fit_curve_bad_input_names_the_port() {
        let r = NodeCall::new(&fit_curve())
            .input(curve_tree(line((0.0, 0.0), (4.0, 0.0))))
            .input(DataTree::from_item(0_i64))
            .run();
        assert!(single_error(&r).contains("input D"), "{:?}", r.messages);
        for bad in [0.0, -1.0, f64::NAN] {
            let r = NodeCall::new(&fit_curve())
                .input(curve_tree(line((0.0, 0.0), (4.0, 0.0))))
                .skip_input()
                .input(DataTree::from_item(bad))
                .run();
            assert!(single_error(&r).contains("input Ft"), "{:?}", r.messages);
        }
    }
}

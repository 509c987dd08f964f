//! Curve › Analysis: Control Points, Evaluate Curve, Curvature, Curve Domain, End Points,
//! Length, Evaluate Length, Curve Closest Point and Curve Continuity.

use locus_kernel::{Circle, Continuity, Curve, Interval, Plane, Point3, continuity};
use locus_runtime::{DataType, NodeError, NodeRegistry, NodeType, Port, Shared, Solve};

use super::{curve_input, finite_parameter, valid_curve};

/// Id of [`control_points`].
pub const CONTROL_POINTS: &str = "curve.control_points";
/// Id of [`evaluate_curve`].
pub const EVALUATE_CURVE: &str = "curve.evaluate_curve";
/// Id of [`curvature`].
pub const CURVATURE: &str = "curve.curvature";
/// Id of [`curve_domain`].
pub const CURVE_DOMAIN: &str = "curve.curve_domain";
/// Id of [`end_points`].
pub const END_POINTS: &str = "curve.end_points";
/// Id of [`length`].
pub const LENGTH: &str = "curve.length";
/// Id of [`evaluate_length`].
pub const EVALUATE_LENGTH: &str = "curve.evaluate_length";
/// Id of [`curve_closest_point`].
pub const CURVE_CLOSEST_POINT: &str = "curve.curve_closest_point";
/// Id of [`curve_continuity`].
pub const CURVE_CONTINUITY: &str = "curve.continuity";

/// Registers the analysis nodes.
pub fn register(registry: &mut NodeRegistry) {
    for t in [
        control_points(),
        evaluate_curve(),
        curvature(),
        curve_domain(),
        end_points(),
        length(),
        evaluate_length(),
        curve_closest_point(),
        curve_continuity(),
    ] {
        registry.register(t);
    }
}

fn analysis(id: &str, name: &str, nickname: &str) -> NodeType {
    NodeType::new(id, name, nickname, "Curve").subcategory("Analysis")
}

fn curve_port(doc: &str) -> Port {
    Port::new("Curve", "C", DataType::Curve).doc(doc)
}

fn parameter_port() -> Port {
    Port::new("Parameter", "t", DataType::Number)
        .doc("Parameter on the curve's domain to evaluate at.")
}

/// Reads parameter input `input` and warns when it lies outside the curve's domain (the curve
/// is then evaluated on its extension, as Rhino does).
pub(super) fn parameter_on(
    s: &mut Solve<'_>,
    input: usize,
    curve: &Curve,
) -> Result<f64, NodeError> {
    let t = finite_parameter(*s.item::<f64>(input)?, "t")?;
    let d = curve.domain();
    let slack = 1e-12 * d.t0.abs().max(d.t1.abs()).max(d.length());
    if t < d.t0 - slack || t > d.t1 + slack {
        s.warning(format!(
            "parameter {t} is outside the domain {} to {}; the curve is extended",
            d.t0, d.t1
        ));
    }
    Ok(t)
}

/// Control Points \[CP\]: the control points, weights and knots of a curve's NURBS form.
pub fn control_points() -> NodeType {
    analysis(CONTROL_POINTS, "Control Points", "CP")
        .gh_guid("424eb433-2b3a-4859-beaf-804d8af0afd7")
        .description(
            "Extracts the control points, weights and knots of the NURBS form of a curve (the \
             exact form Rhino gives lines, polylines, circles and arcs). Knots are in Rhino's \
             form, |P| + degree − 1 of them, so the three lists rebuild the curve with Nurbs \
             Curve PWK.",
        )
        .input(curve_port("Curve to evaluate."))
        .output(
            Port::new("Points", "P", DataType::Point)
                .doc("Control points of the NURBS form (Euclidean).")
                .list(),
        )
        .output(
            Port::new("Weights", "W", DataType::Number)
                .doc("Weights of the control points.")
                .list(),
        )
        .output(
            Port::new("Knots", "K", DataType::Number)
                .doc("Knot vector of the NURBS form.")
                .list(),
        )
        .solve(|s| {
            let curve = curve_input(s, 0)?;
            let nurbs = curve.to_nurbs();
            s.set_list(0, nurbs.points().to_vec());
            s.set_list(1, nurbs.weights().to_vec());
            s.set_list(2, nurbs.knots().to_vec());
            Ok(())
        })
}

/// Evaluate Curve \[Eval\]: point, tangent and kink angle at a parameter.
pub fn evaluate_curve() -> NodeType {
    analysis(EVALUATE_CURVE, "Evaluate Curve", "Eval")
        .gh_guid("fc6979e4-7e91-4508-8e05-37c680779751")
        .description(
            "Evaluates a curve at a parameter: the point, the unit tangent, and the angle \
             between the incoming and the outgoing direction (zero where the curve is smooth, \
             the kink angle at a corner). At a corner the tangent is the outgoing one. A \
             parameter outside the domain evaluates the curve's extension, with a warning.",
        )
        .input(curve_port("Curve to evaluate."))
        .input(parameter_port())
        .output(Port::new("Point", "P", DataType::Point).doc("Point on the curve at t."))
        .output(
            Port::new("Tangent", "T", DataType::Vector)
                .doc("Unit tangent at t; null where the curve has no direction."),
        )
        .output(
            Port::new("Angle", "A", DataType::Number)
                .doc("Angle in radians between the incoming and outgoing tangents at t."),
        )
        .solve(|s| {
            let curve = curve_input(s, 0)?;
            let t = parameter_on(s, 1, &curve)?;
            s.set(0, curve.point_at(t));
            match curve.tangent_and_kink_angle_at(t)? {
                (Some(tangent), Some(angle)) => {
                    s.set(1, tangent);
                    s.set(2, angle);
                }
                _ => s.warning(format!("the curve has no tangent at {t}")),
            }
            Ok(())
        })
}

/// Curvature \[Curvature\]: curvature vector and osculating circle at a parameter.
pub fn curvature() -> NodeType {
    analysis(CURVATURE, "Curvature", "Curvature")
        .gh_guid("aaa665bd-fd6e-4ccb-8d2c-c5b33072125d")
        .description(
            "Evaluates the curvature of a curve at a parameter: the curvature vector points \
             towards the centre of the osculating circle and its length is the curvature, \
             1/radius. The osculating (curvature) circle touches the curve at the point, in the \
             plane of the tangent and the curvature vector, and runs in the curve's direction. \
             Where the curve is straight the vector is zero and there is no circle (a null, \
             with a remark).",
        )
        .input(curve_port("Curve to evaluate."))
        .input(parameter_port())
        .output(Port::new("Point", "P", DataType::Point).doc("Point on the curve at t."))
        .output(
            Port::new("Curvature", "K", DataType::Vector)
                .doc("Curvature vector at t, in 1/model units."),
        )
        .output(
            Port::new("Curvature", "C", DataType::Circle)
                .doc("Osculating circle at t; null where the curve is straight."),
        )
        .solve(|s| {
            let curve = curve_input(s, 0)?;
            let t = parameter_on(s, 1, &curve)?;
            let point = curve.point_at(t);
            s.set(0, point);
            let (Some(k), Some(tangent)) = (curve.curvature_at(t), curve.tangent_at(t)) else {
                s.warning(format!("the curve has no tangent at {t}"));
                return Ok(());
            };
            s.set(1, k);
            let kk = k.length_squared();
            let Some(inward) = k.try_normalize() else {
                s.remark(format!("the curve is straight at {t}: no curvature circle"));
                return Ok(());
            };
            let center = point + k / kk;
            let plane = Plane::from_frame(center, -inward, tangent)?;
            s.set(2, Circle::new(plane, 1.0 / kk.sqrt())?);
            Ok(())
        })
}

/// Curve Domain \[CrvDom\]: a curve's domain, and the curve with a new one.
pub fn curve_domain() -> NodeType {
    analysis(CURVE_DOMAIN, "Curve Domain", "CrvDom")
        .description(
            "Measures the domain of a curve and, when a domain is given, gives the same curve \
             with that domain (every point keeps its place; parameters are mapped linearly). \
             With D = 0 to 1 this reparameterizes the curve, like Grasshopper's Reparameterize \
             input option, which has no component of its own.",
        )
        .input(curve_port("Curve to measure or modify."))
        .input(
            Port::new("Domain", "D", DataType::Domain)
                .doc("Optional new domain, increasing. When omitted the curve is unchanged.")
                .optional(),
        )
        .output(
            Port::new("Curve", "C", DataType::Curve)
                .doc("The curve with the new domain (or unchanged)."),
        )
        .output(Port::new("Domain", "D", DataType::Domain).doc("Domain of the original curve."))
        .solve(|s| {
            let curve = curve_input(s, 0)?;
            let domain = curve.domain();
            let out = match s.item_opt::<Interval>(1) {
                Some(&d) => Shared::new(curve.reparameterized(d)?),
                None => curve,
            };
            s.set(0, out);
            s.set(1, domain);
            Ok(())
        })
}

/// End Points \[End\]: the start and end points of a curve.
pub fn end_points() -> NodeType {
    analysis(END_POINTS, "End Points", "End")
        .gh_guid("11bbd48b-bb0a-4f1b-8167-fa297590390d")
        .description("Extracts the points at the start and the end of a curve's domain.")
        .input(curve_port("Curve to evaluate."))
        .output(Port::new("Start", "S", DataType::Point).doc("Curve start point."))
        .output(Port::new("End", "E", DataType::Point).doc("Curve end point."))
        .solve(|s| {
            let curve = curve_input(s, 0)?;
            s.set(0, curve.start_point());
            s.set(1, curve.end_point());
            Ok(())
        })
}

/// Length \[Len\]: the length of a curve.
pub fn length() -> NodeType {
    analysis(LENGTH, "Length", "Len")
        .gh_guid("c75b62fa-0a33-4da7-a5bd-03fd0068fd93")
        .description(
            "Measures the length of a curve: exactly for lines, polylines, circles and arcs, to \
             a relative 1e-12 for NURBS curves.",
        )
        .input(curve_port("Curve to measure."))
        .output(Port::new("Length", "L", DataType::Number).doc("Curve length, in model units."))
        .lift1(|curve: &Shared<Curve>| {
            valid_curve(curve, "C")?;
            Ok(curve.length())
        })
}

/// Evaluate Length \[Eval\]: point, tangent and parameter at a length along a curve.
pub fn evaluate_length() -> NodeType {
    analysis(EVALUATE_LENGTH, "Evaluate Length", "Eval")
        .gh_guid("6b021f56-b194-4210-b9a1-6cef3b7d0848")
        .description(
            "Evaluates a curve at a length along it, measured from the start, either as a \
             fraction of the whole length (normalized, 0 to 1) or in model units.",
        )
        .input(curve_port("Curve to evaluate."))
        .input(Port::new("Length", "L", DataType::Number).doc(
            "Length along the curve: a fraction from 0 to 1 when normalized, otherwise \
                 model units from 0 to the curve's length.",
        ))
        .input(
            Port::new("Normalized", "N", DataType::Boolean)
                .doc("Whether L is a fraction of the curve's length. Default true.")
                .default_value(true),
        )
        .output(Port::new("Point", "P", DataType::Point).doc("Point at the length."))
        .output(Port::new("Tangent", "T", DataType::Vector).doc("Unit tangent at the length."))
        .output(Port::new("Parameter", "t", DataType::Number).doc("Curve parameter at the length."))
        .solve(|s| {
            let curve = curve_input(s, 0)?;
            let length = finite_parameter(*s.item::<f64>(1)?, "L")?;
            let normalized: bool = *s.item(2)?;
            let t = if normalized {
                curve.parameter_at_normalized_length(length)?
            } else {
                curve.parameter_at_length(length)?
            };
            s.set(0, curve.point_at(t));
            match curve.tangent_at(t) {
                Some(tangent) => s.set(1, tangent),
                None => s.warning(format!("the curve has no tangent at {t}")),
            }
            s.set(2, t);
            Ok(())
        })
}

/// Curve Closest Point \[Crv CP\]: the point of a curve closest to a point.
pub fn curve_closest_point() -> NodeType {
    analysis(CURVE_CLOSEST_POINT, "Curve Closest Point", "Crv CP")
        .gh_guid("2dc44b22-b1dd-460a-a704-6462d6e91096")
        .description(
            "Finds the point of a curve closest to a given point, over the whole curve (its \
             ends, corners and seam included), with its parameter and distance. Where several \
             points are equally close, the one with the smallest parameter is given.",
        )
        .input(Port::new("Point", "P", DataType::Point).doc("Point to project onto the curve."))
        .input(curve_port("Curve to project onto."))
        .output(
            Port::new("Point", "P", DataType::Point)
                .doc("Point on the curve closest to the base point."),
        )
        .output(
            Port::new("Parameter", "t", DataType::Number)
                .doc("Parameter of the closest point on the curve's domain."),
        )
        .output(
            Port::new("Distance", "D", DataType::Number)
                .doc("Distance between the base point and the curve."),
        )
        .solve(|s| {
            let p: Point3 = *s.item(0)?;
            let curve = curve_input(s, 1)?;
            let cp = curve.closest_point(p)?;
            s.set(0, cp.point);
            s.set(1, cp.t);
            s.set(2, cp.distance);
            Ok(())
        })
}

/// The text of a continuity level, as the book's tutorial writes it.
fn continuity_text(level: Continuity) -> &'static str {
    match level {
        Continuity::None => "none",
        Continuity::G0 => "G0",
        Continuity::G1 => "G1",
        Continuity::G2 => "G2",
    }
}

/// Curve Continuity \[Cont\]: how smoothly one curve continues into the next.
pub fn curve_continuity() -> NodeType {
    analysis(CURVE_CONTINUITY, "Curve Continuity", "Cont")
        .description(
            "Measures the geometric continuity between the end of curve A and the start of \
             curve B, as in the book's continuity tutorial (there is no single Grasshopper \
             component for it): G0 when the end points meet (within 1e-9 model units), G1 when \
             the unit tangents also agree (within 1e-9 radians), G2 when the curvature vectors \
             also agree (within a relative 1e-9), otherwise none. The gap, the angle between the \
             tangents and the difference of the curvature vectors are output as measured.",
        )
        .input(
            Port::new("Curve A", "A", DataType::Curve).doc("The first curve; its end is compared."),
        )
        .input(
            Port::new("Curve B", "B", DataType::Curve)
                .doc("The second curve; its start is compared."),
        )
        .output(
            Port::new("Continuity", "C", DataType::Text)
                .doc("The level reached: G0, G1, G2 or none."),
        )
        .output(
            Port::new("Gap", "G", DataType::Number)
                .doc("Distance from the end of A to the start of B, in model units."),
        )
        .output(Port::new("Angle", "A", DataType::Number).doc(
            "Angle between the tangents at the end of A and the start of B, in radians; \
                 null where a tangent is undefined.",
        ))
        .output(Port::new("Curvature", "K", DataType::Number).doc(
            "Length of the difference between the curvature vectors there, in 1/model \
                 units; null where a curvature is undefined.",
        ))
        .solve(|s| {
            let a = curve_input(s, 0)?;
            let b = curve_input(s, 1)?;
            let (t1, t0) = (a.domain().t1, b.domain().t0);
            s.set(0, continuity_text(continuity(&a, &b)).to_owned());
            s.set(1, a.point_at(t1).distance(b.point_at(t0)));
            if let (Some(ta), Some(tb)) = (a.tangent_at(t1), b.tangent_at(t0)) {
                s.set(2, ta.cross(tb).length().atan2(ta.dot(tb)));
            }
            if let (Some(ka), Some(kb)) = (a.curvature_at(t1), b.curvature_at(t0)) {
                s.set(3, (ka - kb).length());
            }
            Ok(())
        })
}

#[cfg(test)]
mod tests {
    use std::f64::consts::{FRAC_PI_2, PI};

    use locus_kernel::{Arc, Line, NurbsCurve, Polyline, Vector3};
    use locus_runtime::{DataTree, Level, NodeCall, Value};

    use super::*;
    use crate::curve::test_support::*;

    fn book_curve() -> Curve {
        NurbsCurve::new_non_rational(
            3,
            vec![
                Point3::new(0.0, 0.0, 0.0),
                Point3::new(1.0, 3.0, 0.0),
                Point3::new(3.0, 4.0, 1.0),
                Point3::new(5.0, 2.0, 0.0),
                Point3::new(7.0, 5.0, 2.0),
                Point3::new(9.0, 1.0, 0.0),
                Point3::new(10.0, 4.0, 1.0),
            ],
            vec![0.0, 0.0, 0.0, 0.25, 0.5, 0.75, 1.0, 1.0, 1.0],
        )
        .unwrap()
        .into()
    }

    fn corner() -> Curve {
        Polyline::new(vec![
            Point3::new(0.0, 0.0, 0.0),
            Point3::new(2.0, 0.0, 0.0),
            Point3::new(2.0, 3.0, 0.0),
        ])
        .unwrap()
        .into()
    }

    fn eval(node: &NodeType, curve: Curve, t: f64) -> locus_runtime::NodeCallResult {
        NodeCall::new(node)
            .input(curve_tree(curve))
            .input(DataTree::from_item(t))
            .run()
    }

    #[test]
    fn control_points_of_circles_and_nurbs() {
        let r = NodeCall::new(&control_points())
            .input(DataTree::from_item(
                Circle::new(Plane::WORLD_XY, 10.0).unwrap(),
            ))
            .run();
        assert_eq!(points(&r.outputs[0]).len(), 9);
        let w = numbers(&r.outputs[1]);
        assert_eq!(w[0], 1.0);
        assert!((w[1] - std::f64::consts::FRAC_1_SQRT_2).abs() < 1e-15);
        let k = numbers(&r.outputs[2]);
        assert_eq!(k.len(), 10);
        assert_eq!(k[9], 2.0 * PI);
        let r = NodeCall::new(&control_points())
            .input(curve_tree(book_curve()))
            .run();
        assert_eq!(
            numbers(&r.outputs[2]),
            vec![0.0, 0.0, 0.0, 0.25, 0.5, 0.75, 1.0, 1.0, 1.0]
        );
    }

    #[test]
    fn evaluate_curve_de_boor_and_oracle_tangent() {
        let r = eval(&evaluate_curve(), book_curve(), 0.4);
        assert!(r.messages.is_empty(), "{:?}", r.messages);
        let p = points(&r.outputs[0])[0];
        assert!(close(
            p,
            Point3::new(4.189333333333334, 2.942666666666667, 0.4813333333333334),
            1e-14
        ));
        // openNURBS: unit tangent at u = 0.4.
        let t = vectors(&r.outputs[1])[0];
        let want = Vector3::new(
            0.9240885677443715,
            -0.36430414689922325,
            -0.1155110709680464,
        );
        assert!((t - want).length() < 1e-12);
        assert_eq!(numbers(&r.outputs[2]), vec![0.0]);
    }

    #[test]
    fn evaluate_curve_reports_corner_angles() {
        let r = eval(&evaluate_curve(), corner(), 1.0);
        assert_eq!(vectors(&r.outputs[1]), vec![Vector3::new(0.0, 1.0, 0.0)]);
        assert_eq!(numbers(&r.outputs[2]), vec![FRAC_PI_2]);
        let r = eval(&evaluate_curve(), corner(), 0.5);
        assert_eq!(numbers(&r.outputs[2]), vec![0.0]);
    }

    #[test]
    fn evaluate_curve_outside_domain_and_nan() {
        let r = eval(
            &evaluate_curve(),
            Line::new(Point3::ORIGIN, Point3::new(4.0, 0.0, 0.0)).into(),
            6.0,
        );
        assert_eq!(points(&r.outputs[0]), vec![Point3::new(6.0, 0.0, 0.0)]);
        assert!(messages(&r, Level::Warning)[0].contains("outside the domain"));
        let r = eval(&evaluate_curve(), book_curve(), f64::NAN);
        assert!(single_error(&r).contains("not a finite number"));
        assert_eq!(values(&r.outputs[0]), vec![None]);
    }

    #[test]
    fn curve_inputs_accept_lines_circles_and_arcs() {
        let arc = Arc::new(
            Circle::new(Plane::WORLD_XY, 2.0).unwrap(),
            Interval::new(0.0, PI),
        )
        .unwrap();
        let r = NodeCall::new(&evaluate_curve())
            .input(DataTree::from_item(arc))
            .input(DataTree::from_item(FRAC_PI_2))
            .run();
        assert!(close(
            points(&r.outputs[0])[0],
            Point3::new(0.0, 2.0, 0.0),
            1e-15
        ));
        let r = NodeCall::new(&evaluate_curve())
            .input(DataTree::from_item(3.0))
            .input(DataTree::from_item(0.0))
            .run();
        assert!(single_error(&r).contains("invalid cast: Number"));
        assert_eq!(values(&r.outputs[0]), vec![None]);
    }

    #[test]
    fn curvature_of_a_circle_and_a_line() {
        let circle = Circle::new(
            Plane::from_normal(Point3::new(1.0, 2.0, 3.0), Vector3::new(0.0, 1.0, 1.0)).unwrap(),
            4.0,
        )
        .unwrap();
        let r = NodeCall::new(&curvature())
            .input(DataTree::from_item(circle))
            .input(DataTree::from_item(1.0))
            .run();
        let p = points(&r.outputs[0])[0];
        let k = vectors(&r.outputs[1])[0];
        assert!((k.length() - 0.25).abs() < 1e-15);
        let Some(Value::Circle(osc)) = values(&r.outputs[2])[0].clone() else {
            panic!()
        };
        assert!((osc.radius - 4.0).abs() < 1e-13);
        assert!(close(osc.center(), circle.center(), 1e-13));
        assert!(close(osc.point_at(0.0), p, 1e-13));
        // Same direction as the curve.
        assert!(osc.tangent_at(0.0).dot(circle.tangent_at(1.0)) > 1.0 - 1e-12);

        let r = eval(
            &curvature(),
            Line::new(Point3::ORIGIN, Point3::new(1.0, 1.0, 0.0)).into(),
            0.5,
        );
        assert_eq!(vectors(&r.outputs[1]), vec![Vector3::ZERO]);
        assert_eq!(values(&r.outputs[2]), vec![None]);
        assert_eq!(messages(&r, Level::Remark).len(), 1);
    }

    #[test]
    fn curvature_matches_opennurbs() {
        let r = eval(&curvature(), book_curve(), 0.4);
        let k = vectors(&r.outputs[1])[0];
        let want = Vector3::new(
            0.11163917500557083,
            0.24066937727331614,
            0.13407921018257002,
        );
        assert!((k - want).length() < 1e-12);
        let Some(Value::Circle(osc)) = values(&r.outputs[2])[0].clone() else {
            panic!()
        };
        assert!((osc.radius * want.length() - 1.0).abs() < 1e-12);
    }

    #[test]
    fn curve_domain_measures_and_reparameterizes() {
        let r = NodeCall::new(&curve_domain())
            .input(curve_tree(Line::new(
                Point3::ORIGIN,
                Point3::new(0.0, 5.0, 0.0),
            )))
            .run();
        assert_eq!(domains(&r.outputs[1]), vec![Interval::new(0.0, 5.0)]);
        assert_eq!(curves(&r.outputs[0])[0].domain(), Interval::new(0.0, 5.0));
        let r = NodeCall::new(&curve_domain())
            .input(curve_tree(book_curve()))
            .input(DataTree::from_list(vec![
                Interval::new(2.0, 4.0),
                Interval::new(1.0, -1.0),
            ]))
            .run();
        let out = values(&r.outputs[0]);
        let Some(Value::Curve(c)) = &out[0] else {
            panic!("{out:?}")
        };
        assert_eq!(c.domain(), Interval::new(2.0, 4.0));
        assert!(close(c.point_at(2.8), book_curve().point_at(0.4), 1e-14));
        assert_eq!(out[1], None);
        assert!(single_error(&r).contains("not increasing"));
    }

    #[test]
    fn end_points_and_length() {
        let r = NodeCall::new(&end_points())
            .input(curve_tree(corner()))
            .run();
        assert_eq!(points(&r.outputs[0]), vec![Point3::ORIGIN]);
        assert_eq!(points(&r.outputs[1]), vec![Point3::new(2.0, 3.0, 0.0)]);
        let r = NodeCall::new(&length())
            .input(DataTree::from_list(vec![
                Shared::new(corner()),
                Shared::new(Circle::new(Plane::WORLD_XY, 1.0).unwrap().into()),
            ]))
            .run();
        assert_eq!(numbers(&r.outputs[0]), vec![5.0, 2.0 * PI]);
    }

    #[test]
    fn evaluate_length_normalized_and_absolute() {
        let r = NodeCall::new(&evaluate_length())
            .input(curve_tree(corner()))
            .input(DataTree::from_list(vec![0.2, 0.6]))
            .run();
        let p = points(&r.outputs[0]);
        assert!(close(p[0], Point3::new(1.0, 0.0, 0.0), 1e-15));
        assert!(close(p[1], Point3::new(2.0, 1.0, 0.0), 1e-15));
        assert_eq!(
            vectors(&r.outputs[1]),
            vec![Vector3::new(1.0, 0.0, 0.0), Vector3::new(0.0, 1.0, 0.0)]
        );
        let t = numbers(&r.outputs[2]);
        assert!((t[0] - 0.5).abs() < 1e-15 && (t[1] - 4.0 / 3.0).abs() < 1e-15);
        let r = NodeCall::new(&evaluate_length())
            .input(curve_tree(corner()))
            .input(DataTree::from_list(vec![3.5, 6.0, -1.0, f64::NAN]))
            .input(DataTree::from_item(false))
            .run();
        assert_eq!(
            values(&r.outputs[0])[0],
            Some(Value::Point(Point3::new(2.0, 1.5, 0.0)))
        );
        assert_eq!(values(&r.outputs[0])[1..], [None, None, None]);
        assert_eq!(messages(&r, Level::Error).len(), 3);
    }

    #[test]
    fn closest_point_on_a_curve() {
        let r = NodeCall::new(&curve_closest_point())
            .input(DataTree::from_list(vec![
                Point3::new(1.0, -2.0, 0.0),
                Point3::new(5.0, 1.0, 0.0),
                Point3::new(f64::NAN, 0.0, 0.0),
            ]))
            .input(curve_tree(corner()))
            .run();
        let p = values(&r.outputs[0]);
        assert_eq!(p[0], Some(Value::Point(Point3::new(1.0, 0.0, 0.0))));
        let Some(Value::Point(p1)) = p[1] else {
            panic!("{p:?}")
        };
        assert!(close(p1, Point3::new(2.0, 1.0, 0.0), 1e-15));
        assert_eq!(p[2], None);
        let t = values(&r.outputs[1]);
        assert_eq!(t[0], Some(Value::Number(0.5)));
        let d = values(&r.outputs[2]);
        let Some(Value::Number(d1)) = d[1] else {
            panic!("{d:?}")
        };
        assert!((d1 - 3.0).abs() < 1e-15);
        assert!(single_error(&r).contains("not finite"));
    }

    #[test]
    fn continuity_levels_and_measures() {
        let unit = |a0: f64, a1: f64| -> Curve {
            Arc::new(
                Circle::new(Plane::WORLD_XY, 1.0).unwrap(),
                Interval::new(a0, a1),
            )
            .unwrap()
            .into()
        };
        let run = |a: Curve, b: Curve| {
            NodeCall::new(&curve_continuity())
                .input(curve_tree(a))
                .input(curve_tree(b))
                .run()
        };
        let text = |r: &locus_runtime::NodeCallResult| match values(&r.outputs[0])[0].clone() {
            Some(Value::Text(t)) => t,
            other => panic!("{other:?}"),
        };
        // Two arcs of one circle: G2.
        let r = run(unit(0.0, 1.0), unit(1.0, 2.0));
        assert_eq!(text(&r), "G2");
        assert!(numbers(&r.outputs[3])[0] < 1e-12);
        // An arc followed by its tangent line: G1, curvature differs by 1.
        let end = Point3::new(1.0f64.cos(), 1.0f64.sin(), 0.0);
        let tangent = Vector3::new(-1.0f64.sin(), 1.0f64.cos(), 0.0);
        let line: Curve = Line::new(end, end + tangent).into();
        let r = run(unit(0.0, 1.0), line.clone());
        assert_eq!(text(&r), "G1");
        assert!((numbers(&r.outputs[3])[0] - 1.0).abs() < 1e-12);
        // A corner: G0, with its angle.
        let r = run(
            corner(),
            Line::new(Point3::new(2.0, 3.0, 0.0), Point3::new(5.0, 3.0, 0.0)).into(),
        );
        assert_eq!(text(&r), "G0");
        assert!((numbers(&r.outputs[2])[0] - FRAC_PI_2).abs() < 1e-15);
        // A gap.
        let r = run(corner(), line);
        assert_eq!(text(&r), "none");
        assert!(numbers(&r.outputs[1])[0] > 1.0);
    }
}

//! Curve › Util and Spline: Extend Curve, Tween Curve, and Discontinuity (Curve › Analysis),
//! curves lengthened, blended and inspected at their joints.

use locus_kernel::{Curve, CurveExtension, NurbsCurve, ParametricContinuity};
use locus_runtime::{DataType, NodeError, NodeRegistry, NodeType, Port, Shared};

use super::curve_input;

/// Id of [`extend_curve`].
pub const EXTEND_CURVE: &str = "curve.extend_curve";
/// Id of [`tween_curve`].
pub const TWEEN_CURVE: &str = "curve.tween_curve";
/// Id of [`discontinuity`].
pub const DISCONTINUITY: &str = "curve.discontinuity";

/// Registers Extend Curve, Tween Curve and Discontinuity.
pub fn register(registry: &mut NodeRegistry) {
    registry.register(extend_curve());
    registry.register(tween_curve());
    registry.register(discontinuity());
}

/// Extend Curve \[Ext\]: a curve lengthened at both ends.
pub fn extend_curve() -> NodeType {
    NodeType::new(EXTEND_CURVE, "Extend Curve", "Ext", "Curve")
        .subcategory("Util")
        .gh_guid("62cc9684-6a39-422e-aefa-ed44643557b9")
        .description(
            "Extends an open curve by lengths at its start and end, measured along the \
             extensions: type 0 continues along the end tangents with straight segments, 1 \
             with tangent arcs of the curvature at the ends (segments where it is zero), 2 \
             smoothly, continuing the end spans themselves (a line stays a line, an arc an \
             arc). A negative length shortens the curve at that end instead. The pieces are \
             joined into one curve. Closed curves cannot be extended.",
        )
        .input(Port::new("Curve", "C", DataType::Curve).doc("The curve to extend."))
        .input(
            Port::new("Type", "T", DataType::Integer)
                .default_value(0i64)
                .doc("Extension type: 0 line (the default), 1 arc, 2 smooth."),
        )
        .input(
            Port::new("Start", "L0", DataType::Number)
                .default_value(1.0)
                .doc("Length added at the start (negative shortens). Default 1."),
        )
        .input(
            Port::new("End", "L1", DataType::Number)
                .default_value(1.0)
                .doc("Length added at the end (negative shortens). Default 1."),
        )
        .output(Port::new("Curve", "C", DataType::Curve).doc("The extended curve."))
        .solve(|s| {
            let curve = curve_input(s, 0)?;
            let style = match *s.item::<i64>(1)? {
                0 => CurveExtension::Line,
                1 => CurveExtension::Arc,
                2 => CurveExtension::Smooth,
                other => {
                    return Err(format!(
                        "input T: extension type {other} is not 0 (line), 1 (arc) or 2 (smooth)"
                    )
                    .into());
                }
            };
            let (start, end) = (*s.item::<f64>(2)?, *s.item::<f64>(3)?);
            s.set(0, Shared::new(curve.extended(start, end, style)?));
            Ok(())
        })
}

/// Tween Curve \[TweenCrv\]: a curve between two curves.
pub fn tween_curve() -> NodeType {
    NodeType::new(TWEEN_CURVE, "Tween Curve", "TweenCrv", "Curve")
        .subcategory("Spline")
        .gh_guid("139619d2-8b18-47b6-b3b9-bf4fec0d6eb1")
        .description(
            "Creates a curve between two curves: both are made compatible (domain 0 to 1, the \
             higher degree, all knots of both) and their control points and weights blended, \
             (1 − F) A + F B in homogeneous form, so that factor 0 gives A, 1 gives B and 0.5 \
             the curve halfway, point for point at equal normalized parameters (for \
             non-rational curves). Curve directions and seams are used as given; factors \
             outside 0 to 1 extrapolate.",
        )
        .input(Port::new("Curve A", "A", DataType::Curve).doc("The first curve (factor 0)."))
        .input(Port::new("Curve B", "B", DataType::Curve).doc("The second curve (factor 1)."))
        .input(
            Port::new("Factor", "F", DataType::Number)
                .default_value(0.5)
                .doc("Where between A (0) and B (1). Default 0.5."),
        )
        .output(Port::new("Tween", "T", DataType::Curve).doc("The tween curve."))
        .solve(|s| {
            let a = curve_input(s, 0)?;
            let b = curve_input(s, 1)?;
            let f: f64 = *s.item(2)?;
            if !f.is_finite() {
                return Err(format!("input F: the factor {f} is not finite").into());
            }
            let tween = NurbsCurve::tween(&a.to_nurbs(), &b.to_nurbs(), f)?;
            s.set(0, Shared::new(Curve::Nurbs(tween)));
            Ok(())
        })
}

/// Discontinuity \[Disc\]: where a curve stops being smooth.
pub fn discontinuity() -> NodeType {
    NodeType::new(DISCONTINUITY, "Discontinuity", "Disc", "Curve")
        .subcategory("Analysis")
        .gh_guid("269eaa85-9997-4d77-a9ba-4c58cb45c9d3")
        .description(
            "Finds the places inside a curve where its derivatives jump (parametric \
             continuity): level 1 where the first derivative does (kinks, and joints where the \
             speed changes), 2 also where the second does (curvature jumps), 3 where any \
             derivative does. Polyline corners and NURBS knots are the candidates; lines, \
             circles and arcs have none, and a closed curve's seam is not inside it.",
        )
        .input(Port::new("Curve", "C", DataType::Curve).doc("The curve to inspect."))
        .input(
            Port::new("Level", "L", DataType::Integer)
                .default_value(1i64)
                .doc("Continuity to test for: 1 C1 (the default), 2 C2, 3 C-infinity."),
        )
        .output(
            Port::new("Points", "P", DataType::Point)
                .list()
                .doc("The points where the curve is less smooth."),
        )
        .output(
            Port::new("Parameters", "t", DataType::Number)
                .list()
                .doc("Their curve parameters."),
        )
        .solve(|s| {
            let curve = curve_input(s, 0)?;
            let level = match *s.item::<i64>(1)? {
                1 => ParametricContinuity::C1,
                2 => ParametricContinuity::C2,
                3 => ParametricContinuity::Infinite,
                other => {
                    return Err(NodeError(format!(
                        "input L: level {other} is not 1 (C1), 2 (C2) or 3 (C-infinity)"
                    )));
                }
            };
            let ts = curve.discontinuities(level);
            s.set_list(0, ts.iter().map(|&t| curve.point_at(t)).collect());
            s.set_list(1, ts);
            Ok(())
        })
}

#[cfg(test)]
mod tests {
    use locus_kernel::{Line, Point3, Polyline};
    use locus_runtime::{DataTree, NodeCall};

    use super::*;
    use crate::curve::test_support::*;

    fn line() -> Curve {
        Curve::from(Line::new(Point3::ORIGIN, Point3::new(2.0, 0.0, 0.0)))
    }

    #[test]
    fn extend_a_line() {
        let r = NodeCall::new(&extend_curve())
            .input(curve_tree(line()))
            .input(DataTree::from_item(0i64))
            .input(DataTree::from_item(1.0))
            .input(DataTree::from_item(0.5))
            .run();
        assert_clean(&r);
        let c = &curves(&r.outputs[0])[0];
        assert!((c.length() - 3.5).abs() < 1e-12);
        assert_eq!(c.start_point(), Point3::new(-1.0, 0.0, 0.0));
        let r = NodeCall::new(&extend_curve())
            .input(curve_tree(line()))
            .input(DataTree::from_item(5i64))
            .run();
        assert_error(&r, "input T");
        let r = NodeCall::new(&extend_curve())
            .input(curve_tree(line()))
            .input(DataTree::from_item(0i64))
            .input(DataTree::from_item(-1.5))
            .input(DataTree::from_item(-1.0))
            .run();
        assert_error(&r, "leaves nothing");
    }

    #[test]
    fn tween_of_two_lines() {
        let b = Curve::from(Line::new(
            Point3::new(0.0, 2.0, 0.0),
            Point3::new(2.0, 4.0, 0.0),
        ));
        let r = NodeCall::new(&tween_curve())
            .input(curve_tree(line()))
            .input(curve_tree(b))
            .input(DataTree::from_item(0.25))
            .run();
        assert_clean(&r);
        let t = &curves(&r.outputs[0])[0];
        assert!(close(t.start_point(), Point3::new(0.0, 0.5, 0.0), 1e-15));
        assert!(close(t.end_point(), Point3::new(2.0, 1.0, 0.0), 1e-15));
        let r = NodeCall::new(&tween_curve())
            .input(curve_tree(line()))
            .input(curve_tree(line()))
            .input(DataTree::from_item(f64::INFINITY))
            .run();
        assert_error(&r, "input F");
    }

    #[test]
    fn discontinuities_of_a_polyline() {
        let l = Polyline::new(vec![
            Point3::ORIGIN,
            Point3::new(1.0, 0.0, 0.0),
            Point3::new(1.0, 1.0, 0.0),
        ])
        .unwrap();
        let r = NodeCall::new(&discontinuity())
            .input(curve_tree(l.clone()))
            .run();
        assert_eq!(points(&r.outputs[0]), vec![Point3::new(1.0, 0.0, 0.0)]);
        assert_eq!(numbers(&r.outputs[1]), vec![1.0]);
        let r = NodeCall::new(&discontinuity())
            .input(curve_tree(l))
            .input(DataTree::from_item(0i64))
            .run();
        assert_error(&r, "input L");
    }
}

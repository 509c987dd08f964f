//! Curve › Primitive: Line, Circle, Arc and Ellipse.

use std::f64::consts::PI;

use locus_kernel::{Arc, Circle, Curve, Ellipse, Interval, Line, Plane, Point3};
use locus_runtime::{DataType, NodeError, NodeRegistry, NodeType, Port, Shared};

/// Id of [`line`].
pub const LINE: &str = "curve.line";
/// Id of [`circle`].
pub const CIRCLE: &str = "curve.circle";
/// Id of [`arc`].
pub const ARC: &str = "curve.arc";
/// Id of [`ellipse`].
pub const ELLIPSE: &str = "curve.ellipse";

/// Registers the primitive nodes.
pub fn register(registry: &mut NodeRegistry) {
    for t in [line(), circle(), arc(), ellipse()] {
        registry.register(t);
    }
}

fn primitive(id: &str, name: &str, nickname: &str) -> NodeType {
    NodeType::new(id, name, nickname, "Curve").subcategory("Primitive")
}

/// Line \[Ln\]: the segment between two points.
pub fn line() -> NodeType {
    primitive(LINE, "Line", "Ln")
        .gh_guid("4c4e56eb-2f04-43f9-95a3-cc46a14f495a")
        .description(
            "Creates the line segment from a start point to an end point. As a curve its domain \
             is 0 to its length.",
        )
        .input(Port::new("Start Point", "A", DataType::Point).doc("Line start point."))
        .input(Port::new("End Point", "B", DataType::Point).doc("Line end point."))
        .output(Port::new("Line", "L", DataType::Line).doc("The line segment from A to B."))
        .lift2(|a: &Point3, b: &Point3| {
            if !a.is_finite() || !b.is_finite() {
                return Err("line end points must be finite".into());
            }
            if a == b {
                return Err("start and end points coincide: the line has no length".into());
            }
            Ok(Line::new(*a, *b))
        })
}

/// Circle \[Cir\]: a circle from its plane and radius.
pub fn circle() -> NodeType {
    primitive(CIRCLE, "Circle", "Cir")
        .gh_guid("807b86e3-be8d-4970-92b5-f8cdcb45b06b")
        .description(
            "Creates the circle about the origin of a plane, in that plane. It starts on the \
             plane's x axis and turns towards its y axis; its domain is 0 to 2π.",
        )
        .input(
            Port::new("Plane", "P", DataType::Plane)
                .doc("Base plane of the circle; its origin is the centre. Default World XY.")
                .default_value(Plane::WORLD_XY),
        )
        .input(
            Port::new("Radius", "R", DataType::Number)
                .doc("Radius of the circle, in model units, positive. Default 1.")
                .default_value(1.0)
                .constraint(crate::constraints::positive_radius),
        )
        .output(Port::new("Circle", "C", DataType::Circle).doc("The circle."))
        .lift2(|plane: &Plane, radius: &f64| Ok(Circle::new(*plane, *radius)?))
}

/// Arc \[Arc\]: an arc from a plane, a radius and an angle domain.
pub fn arc() -> NodeType {
    primitive(ARC, "Arc", "Arc")
        .gh_guid("bb59bffc-f54c-4682-9778-f6c3fe74fce3")
        .description(
            "Creates the arc of the circle about the origin of a plane between two angles, \
             measured in radians from the plane's x axis towards its y axis. A decreasing angle \
             domain runs the other way round: the arc then lies on the plane with its normal \
             reversed, between the negated angles, as in Grasshopper. The arc's domain is its \
             angle interval.",
        )
        .input(
            Port::new("Plane", "P", DataType::Plane)
                .doc("Base plane of the arc; its origin is the centre. Default World XY.")
                .default_value(Plane::WORLD_XY),
        )
        .input(
            Port::new("Radius", "R", DataType::Number)
                .doc("Radius of the arc, in model units, positive. Default 1.")
                .default_value(1.0)
                .constraint(crate::constraints::positive_radius),
        )
        .input(
            Port::new("Angle", "A", DataType::Domain)
                .doc(
                    "Angle domain in radians; its length is at most 2π and not zero. \
                     Default 0 to π.",
                )
                .default_value(Interval::new(0.0, PI)),
        )
        .output(Port::new("Arc", "A", DataType::Arc).doc("The arc."))
        .output(Port::new("Length", "L", DataType::Number).doc("Length of the arc."))
        .solve(|s| {
            let plane: Plane = *s.item(0)?;
            let radius: f64 = *s.item(1)?;
            let angle: Interval = *s.item(2)?;
            let (plane, angle) = if angle.t0 > angle.t1 {
                let reversed = Plane {
                    origin: plane.origin,
                    x_axis: plane.x_axis,
                    y_axis: -plane.y_axis,
                    z_axis: -plane.z_axis,
                };
                (reversed, Interval::new(-angle.t0, -angle.t1))
            } else {
                (plane, angle)
            };
            let arc = Arc::new(Circle::new(plane, radius)?, angle)?;
            s.set(0, arc);
            s.set(1, arc.length());
            Ok(())
        })
}

/// A radius from input `nickname`: a finite, positive number.
fn positive(r: f64, nickname: &str) -> Result<f64, NodeError> {
    if r.is_finite() && r > 0.0 {
        Ok(r)
    } else {
        Err(format!("input {nickname}: the radius must be a positive number, got {r}").into())
    }
}

/// Ellipse \[Ellipse\]: an ellipse from its plane and two radii, with its foci.
pub fn ellipse() -> NodeType {
    primitive(ELLIPSE, "Ellipse", "Ellipse")
        .gh_guid("46b5564d-d3eb-4bf1-ae16-15ed132cfd88")
        .description(
            "Creates the ellipse about the origin of a plane with one radius along the plane's \
             x axis and the other along its y axis, as Rhino's exact rational NURBS form: \
             degree 2, nine control points, weights 1 and 1/√2, domain 0 to 2π, starting on \
             the x axis and turning towards the y axis. Also gives the two foci, on the major \
             axis at √(a² − b²) either side of the centre (first on its positive side); a \
             circle's foci are both its centre.",
        )
        .input(
            Port::new("Plane", "P", DataType::Plane)
                .doc("Base plane of the ellipse; its origin is the centre. Default World XY.")
                .default_value(Plane::WORLD_XY),
        )
        .input(
            Port::new("Radius 1", "R1", DataType::Number)
                .doc("Radius along the plane's x axis, in model units, positive. Default 1.")
                .default_value(1.0)
                .constraint(crate::constraints::positive_radius),
        )
        .input(
            Port::new("Radius 2", "R2", DataType::Number)
                .doc("Radius along the plane's y axis, in model units, positive. Default 1.")
                .default_value(1.0)
                .constraint(crate::constraints::positive_radius),
        )
        .output(Port::new("Ellipse", "E", DataType::Curve).doc("The ellipse."))
        .output(
            Port::new("Focus 1", "F1", DataType::Point)
                .doc("The focus on the positive side of the major axis."),
        )
        .output(
            Port::new("Focus 2", "F2", DataType::Point)
                .doc("The focus on the negative side of the major axis."),
        )
        .solve(|s| {
            let plane: Plane = *s.item(0)?;
            let r1 = positive(*s.item::<f64>(1)?, "R1")?;
            let r2 = positive(*s.item::<f64>(2)?, "R2")?;
            if !plane.is_finite() {
                return Err("input P: the plane is not finite".into());
            }
            let e = Ellipse::new(plane, r1, r2)?;
            let (f1, f2) = e.foci();
            s.set(0, Shared::new(Curve::from(e.to_nurbs())));
            s.set(1, f1);
            s.set(2, f2);
            Ok(())
        })
}

#[cfg(test)]
mod tests {
    use std::f64::consts::FRAC_PI_2;

    use locus_kernel::{Curve, Vector3};
    use locus_runtime::{DataTree, NodeCall, Value};

    use super::*;
    use crate::curve::test_support::*;

    #[test]
    fn line_between_two_points() {
        let r = NodeCall::new(&line())
            .input(DataTree::from_item(Point3::new(1.0, 2.0, 3.0)))
            .input(DataTree::from_list(vec![
                Point3::new(4.0, 6.0, 3.0),
                Point3::new(1.0, 2.0, 3.0),
                Point3::new(f64::NAN, 0.0, 0.0),
            ]))
            .run();
        let out = values(&r.outputs[0]);
        let Some(Value::Line(l)) = &out[0] else {
            panic!("{out:?}")
        };
        assert_eq!(l.length(), 5.0);
        assert_eq!(Curve::from(*l).domain(), Interval::new(0.0, 5.0));
        assert_eq!(out[1], None);
        assert_eq!(out[2], None);
        let errors = messages(&r, locus_runtime::Level::Error);
        assert_eq!(errors.len(), 2);
        assert!(errors[0].contains("coincide"), "{errors:?}");
        assert!(errors[1].contains("finite"), "{errors:?}");
    }

    #[test]
    fn circle_defaults_and_bad_radius() {
        let r = NodeCall::new(&circle()).run();
        let out = values(&r.outputs[0]);
        assert_eq!(
            out,
            vec![Some(Value::Circle(
                Circle::new(Plane::WORLD_XY, 1.0).unwrap()
            ))]
        );
        for bad in [0.0, -2.0, f64::NAN] {
            let r = NodeCall::new(&circle())
                .skip_input()
                .input(DataTree::from_item(bad))
                .run();
            assert_eq!(values(&r.outputs[0]), vec![None]);
            let e = single_error(&r);
            assert!(e.contains("radius") || e.contains("finite"), "{e}");
        }
    }

    #[test]
    fn arc_defaults_to_a_half_circle() {
        let r = NodeCall::new(&arc()).run();
        let Some(Value::Arc(a)) = values(&r.outputs[0])[0].clone() else {
            panic!()
        };
        assert_eq!(a.angle, Interval::new(0.0, PI));
        assert_eq!(numbers(&r.outputs[1]), vec![PI]);
        assert!(close(a.end_point(), Point3::new(-1.0, 0.0, 0.0), 1e-15));
    }

    #[test]
    fn decreasing_angles_run_clockwise() {
        let r = NodeCall::new(&arc())
            .skip_input()
            .input(DataTree::from_item(2.0))
            .input(DataTree::from_item(Interval::new(FRAC_PI_2, 0.0)))
            .run();
        let Some(Value::Arc(a)) = values(&r.outputs[0])[0].clone() else {
            panic!("{:?}", r.messages)
        };
        // From (0, 2) clockwise to (2, 0), through the first quadrant.
        assert!(close(a.start_point(), Point3::new(0.0, 2.0, 0.0), 1e-15));
        assert!(close(a.end_point(), Point3::new(2.0, 0.0, 0.0), 1e-15));
        let mid = a.mid_point();
        assert!(mid.x > 0.0 && mid.y > 0.0);
        assert_eq!(a.circle.normal(), Vector3::new(0.0, 0.0, -1.0));
        assert!((numbers(&r.outputs[1])[0] - PI).abs() < 1e-15);
    }

    #[test]
    fn arc_rejects_empty_and_overlong_angles() {
        for bad in [
            Interval::new(1.0, 1.0),
            Interval::new(0.0, 7.0),
            Interval::new(f64::NAN, 1.0),
        ] {
            let r = NodeCall::new(&arc())
                .skip_input()
                .skip_input()
                .input(DataTree::from_item(bad))
                .run();
            assert_eq!(values(&r.outputs[0]), vec![None]);
            single_error(&r);
        }
    }

    #[test]
    fn ellipse_and_its_foci() {
        let r = NodeCall::new(&ellipse())
            .skip_input()
            .input(DataTree::from_item(5.0))
            .input(DataTree::from_item(3.0))
            .run();
        assert!(r.messages.is_empty(), "{:?}", r.messages);
        let c = curves(&r.outputs[0])[0].clone();
        assert_eq!(c.domain(), Interval::new(0.0, std::f64::consts::TAU));
        assert!(c.is_closed());
        assert!(close(
            c.point_at(FRAC_PI_2),
            Point3::new(0.0, 3.0, 0.0),
            1e-14
        ));
        assert_eq!(
            values(&r.outputs[1]),
            vec![Some(Value::Point(Point3::new(4.0, 0.0, 0.0)))]
        );
        assert_eq!(
            values(&r.outputs[2]),
            vec![Some(Value::Point(Point3::new(-4.0, 0.0, 0.0)))]
        );
    }

    #[test]
    fn ellipse_bad_radii_name_the_port() {
        for (r1, r2, port) in [(0.0, 1.0, "R1"), (1.0, f64::NAN, "R2"), (-1.0, 2.0, "R1")] {
            let r = NodeCall::new(&ellipse())
                .skip_input()
                .input(DataTree::from_item(r1))
                .input(DataTree::from_item(r2))
                .run();
            assert_eq!(values(&r.outputs[0]), vec![None]);
            let e = single_error(&r);
            assert!(e.contains(port), "{e}");
        }
    }
}

//! Curve › Primitive, from points and directions: Line SDL, Circle CNR, Circle 3Pt, Circle
//! Fit, Arc 3Pt, Arc SED, Polygon and Rectangle; and Curve › Analysis › Curve Middle.
//!
//! The constructions are the kernel's (`Circle::from_three_points`, `Arc::from_three_points`,
//! `Arc::from_start_tangent_end`, `Circle::from_center_normal`), which reject degenerate input
//! (collinear points, zero vectors, non-finite numbers) with a reason. Polygon and Rectangle
//! make closed polylines; with a corner (fillet) radius above 0 each corner is rounded by the
//! tangent arc of that radius (`Curve::fillet_corners`), which makes the closed curve one NURBS
//! curve of lines and arcs (Rhino's is a polycurve of the same pieces).

use std::f64::consts::TAU;

use locus_kernel::{Arc, Circle, Curve, Interval, Line, Plane, Point3, Polyline, Vector3};
use locus_runtime::{DataType, NodeError, NodeRegistry, NodeType, Port, Shared, Solve};

use super::curve_input;
use crate::maths::sequence::MAX_SEQUENCE_LENGTH;

/// Id of [`line_sdl`].
pub const LINE_SDL: &str = "curve.line_sdl";
/// Id of [`circle_cnr`].
pub const CIRCLE_CNR: &str = "curve.circle_cnr";
/// Id of [`circle_3pt`].
pub const CIRCLE_3PT: &str = "curve.circle_3pt";
/// Id of [`circle_fit`].
pub const CIRCLE_FIT: &str = "curve.circle_fit";
/// Id of [`arc_3pt`].
pub const ARC_3PT: &str = "curve.arc_3pt";
/// Id of [`arc_sed`].
pub const ARC_SED: &str = "curve.arc_sed";
/// Id of [`polygon`].
pub const POLYGON: &str = "curve.polygon";
/// Id of [`rectangle`].
pub const RECTANGLE: &str = "curve.rectangle";
/// Id of [`curve_middle`].
pub const CURVE_MIDDLE: &str = "curve.curve_middle";

/// Registers the nodes of this module.
pub fn register(registry: &mut NodeRegistry) {
    for t in [
        line_sdl(),
        circle_cnr(),
        circle_3pt(),
        circle_fit(),
        arc_3pt(),
        arc_sed(),
        polygon(),
        rectangle(),
        curve_middle(),
    ] {
        registry.register(t);
    }
}

fn primitive(id: &str, name: &str, nickname: &str) -> NodeType {
    NodeType::new(id, name, nickname, "Curve").subcategory("Primitive")
}

fn point_in(name: &str, nickname: &str, doc: &str) -> Port {
    Port::new(name, nickname, DataType::Point).doc(doc)
}

/// Line SDL \[Line\]: a line from a start point, a direction and a length.
pub fn line_sdl() -> NodeType {
    primitive(LINE_SDL, "Line SDL", "Line")
        .gh_guid("4c619bc9-39fd-4717-82a6-1e07ea237bbe")
        .description(
            "Creates the line segment that starts at S and runs along the direction D for the \
             length L (a negative length runs against D). A zero or non-finite direction, and \
             a zero or non-finite length, are errors.",
        )
        .input(point_in("Start", "S", "The start point."))
        .input(
            Port::new("Direction", "D", DataType::Vector)
                .doc("The direction of the line; only its direction counts; default Z.")
                .default_value(Vector3::new(0.0, 0.0, 1.0)),
        )
        .input(
            Port::new("Length", "L", DataType::Number)
                .doc("The length of the line; default 1.")
                .default_value(1.0),
        )
        .output(Port::new("Line", "L", DataType::Line).doc("The line segment."))
        .lift3(|s: &Point3, d: &Vector3, l: &f64| {
            let unit = d
                .try_normalize()
                .ok_or_else(|| NodeError("direction D has no direction".into()))?;
            if !(s.is_finite() && l.is_finite() && *l != 0.0) {
                return Err(NodeError(format!(
                    "the start must be finite and the length finite and not zero (it is {l})"
                )));
            }
            Ok(Line::new(*s, *s + unit * *l))
        })
}

/// Circle CNR \[Circle\]: a circle from its centre, normal and radius.
pub fn circle_cnr() -> NodeType {
    primitive(CIRCLE_CNR, "Circle CNR", "Circle")
        .gh_guid("d114323a-e6ee-4164-946b-e4ca0ce15efa")
        .description(
            "Creates the circle about the centre C in the plane normal to N, with radius R; its \
             plane is the kernel's plane from a normal (Rhino's), so the circle starts on that \
             plane's x axis. A zero normal or a radius that is not positive is an error.",
        )
        .input(point_in("Center", "C", "The centre of the circle."))
        .input(
            Port::new("Normal", "N", DataType::Vector)
                .doc("The normal of the circle's plane; default Z.")
                .default_value(Vector3::new(0.0, 0.0, 1.0)),
        )
        .input(
            Port::new("Radius", "R", DataType::Number)
                .doc("The radius; default 1.")
                .default_value(1.0),
        )
        .output(Port::new("Circle", "C", DataType::Circle).doc("The circle."))
        .lift3(|c: &Point3, n: &Vector3, r: &f64| Ok(Circle::from_center_normal(*c, *n, *r)?))
}

/// Circle 3Pt \[Circle\]: the circle through three points.
pub fn circle_3pt() -> NodeType {
    primitive(CIRCLE_3PT, "Circle 3Pt", "Circle")
        .gh_guid("47886835-e3ff-4516-a3ed-1b419f055464")
        .description(
            "Creates the circle through three points, with its plane and radius. Collinear or \
             coincident points have no circle and are an error.",
        )
        .input(point_in("Point A", "A", "The first point on the circle."))
        .input(point_in("Point B", "B", "The second point on the circle."))
        .input(point_in("Point C", "C", "The third point on the circle."))
        .output(Port::new("Circle", "C", DataType::Circle).doc("The circle through A, B and C."))
        .output(Port::new("Plane", "P", DataType::Plane).doc("The circle's plane, at its centre."))
        .output(Port::new("Radius", "R", DataType::Number).doc("The circle's radius."))
        .solve(|s| {
            let (a, b, c) = (
                *s.item::<Point3>(0)?,
                *s.item::<Point3>(1)?,
                *s.item::<Point3>(2)?,
            );
            let circle = Circle::from_three_points(a, b, c)?;
            s.set(0, circle);
            s.set(1, circle.plane);
            s.set(2, circle.radius);
            Ok(())
        })
}

/// Circle Fit \[Circle Fit\]: the circle that fits a list of points best.
pub fn circle_fit() -> NodeType {
    primitive(CIRCLE_FIT, "Circle Fit", "Circle Fit")
        .gh_guid("be52336f-a2e1-43b1-b5f5-178ba489508a")
        .description(
            "Fits a circle to a list of points (Rhino's Circle.TryFitCircleToPoints): in the \
             plane that fits the points best, the circle that minimises the sum of squared \
             distances from the points (algebraic fit refined by Gauss–Newton), exact for \
             points on a circle. Gives the circle, its radius and the largest distance from a \
             point to it. Fewer than three points, or points on one line, are an error; empty \
             items are skipped.",
        )
        .input(
            Port::new("Points", "P", DataType::Point)
                .doc("The points to fit, at least three not on one line.")
                .list(),
        )
        .output(Port::new("Circle", "C", DataType::Circle).doc("The fitted circle."))
        .output(Port::new("Radius", "R", DataType::Number).doc("Its radius."))
        .output(
            Port::new("Deviation", "D", DataType::Number)
                .doc("The largest distance from one of the points to the circle."),
        )
        .solve(|s| {
            let points: Vec<Point3> = s.list::<Point3>(0)?.present().copied().collect();
            let fit = Circle::fit(&points)?;
            s.set(0, fit.circle);
            s.set(1, fit.circle.radius);
            s.set(2, fit.deviation);
            Ok(())
        })
}

/// Arc 3Pt \[Arc\]: the arc through three points.
pub fn arc_3pt() -> NodeType {
    primitive(ARC_3PT, "Arc 3Pt", "Arc")
        .gh_guid("9fa1b081-b1c7-4a12-a163-0aa8da9ff6c4")
        .description(
            "Creates the arc that starts at A, passes through B and ends at C, with its plane \
             and radius. Collinear or coincident points have no arc and are an error.",
        )
        .input(point_in("Point A", "A", "The start point."))
        .input(point_in("Point B", "B", "A point the arc passes through."))
        .input(point_in("Point C", "C", "The end point."))
        .output(Port::new("Arc", "A", DataType::Arc).doc("The arc."))
        .output(Port::new("Plane", "P", DataType::Plane).doc("The arc's plane, at its centre."))
        .output(Port::new("Radius", "R", DataType::Number).doc("The arc's radius."))
        .solve(|s| {
            let (a, b, c) = (
                *s.item::<Point3>(0)?,
                *s.item::<Point3>(1)?,
                *s.item::<Point3>(2)?,
            );
            let arc = Arc::from_three_points(a, b, c)?;
            s.set(0, arc);
            s.set(1, arc.circle.plane);
            s.set(2, arc.radius());
            Ok(())
        })
}

/// Arc SED \[Arc\]: the arc from a start point, a tangent there and an end point.
pub fn arc_sed() -> NodeType {
    primitive(ARC_SED, "Arc SED", "Arc")
        .gh_guid("9d2583dd-6cf5-497c-8c40-c9a290598396")
        .description(
            "Creates the arc that starts at S tangent to the direction D and ends at E, with \
             its plane and radius. A zero direction, coincident points, or an end point on the \
             tangent line (no arc) are errors.",
        )
        .input(point_in("Start", "S", "The start point."))
        .input(point_in("End", "E", "The end point."))
        .input(
            Port::new("Direction", "D", DataType::Vector)
                .doc("The tangent at the start; default X.")
                .default_value(Vector3::new(1.0, 0.0, 0.0)),
        )
        .output(Port::new("Arc", "A", DataType::Arc).doc("The arc."))
        .output(Port::new("Plane", "P", DataType::Plane).doc("The arc's plane, at its centre."))
        .output(Port::new("Radius", "R", DataType::Number).doc("The arc's radius."))
        .solve(|s| {
            let (start, end) = (*s.item::<Point3>(0)?, *s.item::<Point3>(1)?);
            let d = *s.item::<Vector3>(2)?;
            let arc = Arc::from_start_tangent_end(start, d, end)?;
            s.set(0, arc);
            s.set(1, arc.circle.plane);
            s.set(2, arc.radius());
            Ok(())
        })
}

/// Sets outputs 0 and 1 to the closed polyline with its corners rounded by tangent arcs of
/// radius `r` (the polyline itself for 0) and its length. A radius above `largest` (the
/// largest whose arcs fit the shape's sides) is reduced to it, with a warning; a corner an arc
/// still does not fit stays sharp, with a warning. `port` names the radius input in messages.
pub(crate) fn set_rounded(
    s: &mut Solve<'_>,
    poly: Polyline,
    r: f64,
    largest: f64,
    port: &str,
) -> Result<(), NodeError> {
    if !(r.is_finite() && r >= 0.0) {
        return Err(NodeError(format!(
            "the corner radius {port} must be 0 or more, not {r}"
        )));
    }
    let r = if r > largest {
        s.warning(format!(
            "the corner radius {port} = {r} does not fit the sides: the largest that does, \
             {largest}, is used"
        ));
        largest
    } else {
        r
    };
    if r == 0.0 {
        let length = poly.length();
        s.set(0, curve_of(poly));
        s.set(1, length);
        return Ok(());
    }
    let size = poly.length().max(1.0);
    let rounded = Curve::from(poly).fillet_corners(r, FILLET_TOLERANCE * size)?;
    let length = rounded.curve.length();
    super::util::set_fillet(s, rounded);
    s.set(1, length);
    Ok(())
}

/// How closely a rounded corner's arc meets the sides, relative to the outline's length.
const FILLET_TOLERANCE: f64 = 1e-10;

pub(crate) fn curve_of(p: Polyline) -> Shared<Curve> {
    Shared::new(Curve::from(p))
}

/// Polygon \[Polygon\]: a regular polygon.
pub fn polygon() -> NodeType {
    primitive(POLYGON, "Polygon", "Polygon")
        .gh_guid("845527a6-5cea-4ae9-a667-96ae1667a4e8")
        .description(
            "Creates the regular polygon with S sides inscribed in the circle of radius R about \
             the origin of plane P: its first corner is on the plane's x axis and the corners \
             turn towards its y axis. It is a closed polyline. S must be at least 3; R must be \
             positive. With a fillet radius Rf above 0 each corner is rounded by the tangent \
             arc of radius Rf (up to the inscribed circle's radius R cos(π/S), where the \
             polygon becomes that circle; a larger Rf is reduced to it, with a warning); the \
             polygon is then one closed curve of lines and arcs.",
        )
        .input(
            Port::new("Plane", "P", DataType::Plane)
                .doc("The polygon's plane, its origin the centre; default World XY.")
                .default_value(Plane::WORLD_XY),
        )
        .input(
            Port::new("Radius", "R", DataType::Number)
                .doc("The radius of the circumscribed circle; default 1.")
                .default_value(1.0),
        )
        .input(
            Port::new("Segments", "S", DataType::Integer)
                .doc(&format!(
                    "The number of sides, 3 to {MAX_SEQUENCE_LENGTH}; default 6."
                ))
                .default_value(6_i64),
        )
        .input(
            Port::new("Fillet Radius", "Rf", DataType::Number)
                .doc("The corner radius; 0 (the default) for sharp corners.")
                .default_value(0.0),
        )
        .output(
            Port::new("Polygon", "P", DataType::Curve)
                .doc("The polygon: a closed polyline, or with rounded corners a closed curve."),
        )
        .output(Port::new("Length", "L", DataType::Number).doc("The perimeter."))
        .solve(|s| {
            let plane = *s.item::<Plane>(0)?;
            let r = *s.item::<f64>(1)?;
            let n = *s.item::<i64>(2)?;
            let fillet = *s.item::<f64>(3)?;
            let sides = usize::try_from(n)
                .ok()
                .filter(|n| (3..=MAX_SEQUENCE_LENGTH).contains(n))
                .ok_or_else(|| {
                    NodeError(format!(
                        "segments S must be 3 to {MAX_SEQUENCE_LENGTH}, not {n}"
                    ))
                })?;
            let circle = Circle::new(plane, r)?;
            let mut pts: Vec<Point3> = (0..sides)
                .map(|k| circle.point_at(TAU * k as f64 / sides as f64))
                .collect();
            pts.push(pts[0]);
            let inscribed = r.abs() * (std::f64::consts::PI / sides as f64).cos();
            set_rounded(s, Polyline::new(pts)?, fillet, inscribed, "Rf")
        })
}

/// Rectangle \[Rectangle\]: a rectangle on a plane from two domains.
pub fn rectangle() -> NodeType {
    primitive(RECTANGLE, "Rectangle", "Rectangle")
        .gh_guid("d93100b6-d50b-40b2-831a-814659dc38e3")
        .description(
            "Creates the rectangle on plane P spanning the domains X and Y along the plane's \
             axes (a number x is the domain 0 to x; the defaults are 0 to 1). It is a closed \
             polyline from the corner (X.t0, Y.t0) towards +X; decreasing domains are made \
             increasing. A domain of zero length is an error. With a corner radius R above 0 \
             each corner is rounded by the tangent arc of radius R (up to half the shorter \
             side; a larger radius is reduced to it, with a warning), and the rectangle is one \
             closed curve of lines and arcs.",
        )
        .input(
            Port::new("Plane", "P", DataType::Plane)
                .doc("The rectangle's plane; default World XY.")
                .default_value(Plane::WORLD_XY),
        )
        .input(
            Port::new("X Size", "X", DataType::Domain)
                .doc("The extent along the plane's x axis; default 0 to 1.")
                .default_value(Interval::UNIT),
        )
        .input(
            Port::new("Y Size", "Y", DataType::Domain)
                .doc("The extent along the plane's y axis; default 0 to 1.")
                .default_value(Interval::UNIT),
        )
        .input(
            Port::new("Radius", "R", DataType::Number)
                .doc("The corner radius; 0 (the default) for sharp corners.")
                .default_value(0.0),
        )
        .output(Port::new("Rectangle", "R", DataType::Curve).doc(
            "The rectangle: a closed polyline of four sides, or with rounded corners a \
                 closed curve.",
        ))
        .output(Port::new("Length", "L", DataType::Number).doc("The perimeter."))
        .solve(|s| {
            let plane = *s.item::<Plane>(0)?;
            let (x, y) = (*s.item::<Interval>(1)?, *s.item::<Interval>(2)?);
            let radius = *s.item::<f64>(3)?;
            if !plane.is_valid() {
                return Err(NodeError("plane P is not valid".into()));
            }
            let (x0, x1) = (x.t0.min(x.t1), x.t0.max(x.t1));
            let (y0, y1) = (y.t0.min(y.t1), y.t0.max(y.t1));
            if !(x0.is_finite() && x1.is_finite() && y0.is_finite() && y1.is_finite())
                || x0 == x1
                || y0 == y1
            {
                return Err(NodeError(format!(
                    "the sizes {x0} to {x1} and {y0} to {y1} must be finite and not empty"
                )));
            }
            let at = |u: f64, v: f64| plane.origin + plane.x_axis * u + plane.y_axis * v;
            let poly = Polyline::new(vec![
                at(x0, y0),
                at(x1, y0),
                at(x1, y1),
                at(x0, y1),
                at(x0, y0),
            ])?;
            let half = 0.5 * (x1 - x0).min(y1 - y0);
            set_rounded(s, poly, radius, half, "R")
        })
}

/// Curve Middle \[MidPt\]: the point halfway along a curve.
pub fn curve_middle() -> NodeType {
    NodeType::new(CURVE_MIDDLE, "Curve Middle", "MidPt", "Curve")
        .subcategory("Analysis")
        .gh_guid("ccc7b468-e743-4049-891f-299432545898")
        .description(
            "Finds the point in the middle of a curve: halfway along its length (not at the \
             middle of its domain). A curve of zero length is an error.",
        )
        .input(Port::new("Curve", "C", DataType::Curve).doc("The curve."))
        .output(Port::new("Midpoint", "M", DataType::Point).doc("The point halfway along C."))
        .solve(|s| {
            let curve = curve_input(s, 0)?;
            let t = curve.parameter_at_normalized_length(0.5)?;
            s.set(0, curve.point_at(t));
            Ok(())
        })
}

#[cfg(test)]
mod tests {
    use std::f64::consts::PI;

    use locus_runtime::{DataTree, Level, NodeCall, Value};

    use super::*;
    use crate::test_support::{messages, only};

    fn p(x: f64, y: f64, z: f64) -> Point3 {
        Point3::new(x, y, z)
    }

    fn close(a: Point3, b: Point3) -> bool {
        (a - b).length() < 1e-12
    }

    #[test]
    fn line_sdl_runs_along_the_direction() {
        let r = NodeCall::new(&line_sdl())
            .input(DataTree::from_item(p(1.0, 1.0, 0.0)))
            .input(DataTree::from_item(Vector3::new(0.0, 2.0, 0.0)))
            .input(DataTree::from_list(vec![3.0, -1.0]))
            .run();
        let lines: Vec<Line> = crate::test_support::all(&r.outputs[0]);
        assert_eq!(lines[0], Line::new(p(1.0, 1.0, 0.0), p(1.0, 4.0, 0.0)));
        assert_eq!(lines[1], Line::new(p(1.0, 1.0, 0.0), p(1.0, 0.0, 0.0)));
        let r = NodeCall::new(&line_sdl())
            .input(DataTree::from_item(p(0.0, 0.0, 0.0)))
            .input(DataTree::from_item(Vector3::ZERO))
            .run();
        assert_eq!(messages(&r, Level::Error), ["direction D has no direction"]);
        let r = NodeCall::new(&line_sdl())
            .input(DataTree::from_item(p(0.0, 0.0, 0.0)))
            .skip_input()
            .input(DataTree::from_item(0.0))
            .run();
        assert_eq!(messages(&r, Level::Error).len(), 1);
    }

    #[test]
    fn circles_from_centre_normal_radius_and_three_points() {
        let r = NodeCall::new(&circle_cnr())
            .input(DataTree::from_item(p(1.0, 2.0, 3.0)))
            .input(DataTree::from_item(Vector3::new(0.0, 0.0, 5.0)))
            .input(DataTree::from_item(2.0))
            .run();
        let c = only::<Circle>(&r, 0);
        assert!(close(c.center(), p(1.0, 2.0, 3.0)));
        assert_eq!(c.radius, 2.0);
        let r = NodeCall::new(&circle_3pt())
            .input(DataTree::from_item(p(1.0, 0.0, 0.0)))
            .input(DataTree::from_item(p(0.0, 1.0, 0.0)))
            .input(DataTree::from_item(p(-1.0, 0.0, 0.0)))
            .run();
        let c = only::<Circle>(&r, 0);
        assert!(close(c.center(), Point3::ORIGIN));
        assert!((only::<f64>(&r, 2) - 1.0).abs() < 1e-12);
        let r = NodeCall::new(&circle_3pt())
            .input(DataTree::from_item(p(0.0, 0.0, 0.0)))
            .input(DataTree::from_item(p(1.0, 0.0, 0.0)))
            .input(DataTree::from_item(p(2.0, 0.0, 0.0)))
            .run();
        assert_eq!(messages(&r, Level::Error).len(), 1);
        let r = NodeCall::new(&circle_cnr())
            .input(DataTree::from_item(p(0.0, 0.0, 0.0)))
            .input(DataTree::from_item(Vector3::ZERO))
            .run();
        assert_eq!(messages(&r, Level::Error).len(), 1);
    }

    #[test]
    fn circle_fit_gives_back_a_circle_and_reports_bad_points() {
        // Six points on the circle of radius 2 about (1, -1, 4) in a tilted plane.
        let c = Circle::from_center_normal(p(1.0, -1.0, 4.0), Vector3::new(1.0, 1.0, 2.0), 2.0)
            .unwrap();
        let points: Vec<Point3> = [0.2, 1.1, 1.9, 3.0, 4.4, 5.5]
            .iter()
            .map(|&t: &f64| {
                c.plane.origin + (c.plane.x_axis * t.cos() + c.plane.y_axis * t.sin()) * 2.0
            })
            .collect();
        let r = NodeCall::new(&circle_fit())
            .input(DataTree::from_list(points))
            .run();
        let fitted = only::<Circle>(&r, 0);
        assert!(close(fitted.center(), p(1.0, -1.0, 4.0)));
        assert!((only::<f64>(&r, 1) - 2.0).abs() < 1e-12);
        assert!(only::<f64>(&r, 2) < 1e-12);

        let r = NodeCall::new(&circle_fit())
            .input(DataTree::from_list(vec![
                p(0.0, 0.0, 0.0),
                p(1.0, 1.0, 0.0),
            ]))
            .run();
        assert_eq!(messages(&r, Level::Error).len(), 1);
        let r = NodeCall::new(&circle_fit())
            .input(DataTree::from_list(vec![
                p(0.0, 0.0, 0.0),
                p(1.0, 0.0, 0.0),
                p(3.0, 0.0, 0.0),
            ]))
            .run();
        assert_eq!(messages(&r, Level::Error).len(), 1);
    }

    #[test]
    fn arcs_through_points_and_from_a_tangent() {
        let r = NodeCall::new(&arc_3pt())
            .input(DataTree::from_item(p(1.0, 0.0, 0.0)))
            .input(DataTree::from_item(p(0.0, 1.0, 0.0)))
            .input(DataTree::from_item(p(-1.0, 0.0, 0.0)))
            .run();
        let a = only::<Arc>(&r, 0);
        assert!(close(a.start_point(), p(1.0, 0.0, 0.0)));
        assert!(close(a.end_point(), p(-1.0, 0.0, 0.0)));
        assert!((a.length() - std::f64::consts::PI).abs() < 1e-12);
        let r = NodeCall::new(&arc_sed())
            .input(DataTree::from_item(p(0.0, 0.0, 0.0)))
            .input(DataTree::from_item(p(2.0, 0.0, 0.0)))
            .input(DataTree::from_item(Vector3::new(0.0, 1.0, 0.0)))
            .run();
        let a = only::<Arc>(&r, 0);
        assert!((a.radius() - 1.0).abs() < 1e-12);
        assert!(close(a.mid_point(), p(1.0, 1.0, 0.0)));
        let r = NodeCall::new(&arc_sed())
            .input(DataTree::from_item(p(0.0, 0.0, 0.0)))
            .input(DataTree::from_item(p(2.0, 0.0, 0.0)))
            .input(DataTree::from_item(Vector3::new(1.0, 0.0, 0.0)))
            .run();
        assert_eq!(messages(&r, Level::Error).len(), 1);
    }

    #[test]
    fn polygon_and_rectangle_are_closed_polylines() {
        let r = NodeCall::new(&polygon())
            .skip_input()
            .input(DataTree::from_item(2.0))
            .input(DataTree::from_item(4_i64))
            .run();
        let c = only::<Shared<Curve>>(&r, 0);
        assert!(c.is_closed());
        assert!(close(c.start_point(), p(2.0, 0.0, 0.0)));
        assert!((only::<f64>(&r, 1) - 4.0 * 8.0_f64.sqrt()).abs() < 1e-12);
        let r = NodeCall::new(&rectangle())
            .skip_input()
            .input(DataTree::from_item(Interval::new(3.0, 0.0)))
            .input(DataTree::from_item(Interval::new(-1.0, 1.0)))
            .run();
        let c = only::<Shared<Curve>>(&r, 0);
        assert!(crate::params::shapes::not_a_rectangle(&c).is_none());
        assert!(close(c.start_point(), p(0.0, -1.0, 0.0)));
        assert_eq!(only::<f64>(&r, 1), 10.0);
        for bad in [
            NodeCall::new(&polygon())
                .skip_input()
                .skip_input()
                .input(DataTree::from_item(2_i64))
                .run(),
            NodeCall::new(&polygon())
                .skip_input()
                .skip_input()
                .skip_input()
                .input(DataTree::from_item(-0.5))
                .run(),
            NodeCall::new(&rectangle())
                .skip_input()
                .input(DataTree::from_item(Interval::new(1.0, 1.0)))
                .run(),
            NodeCall::new(&rectangle())
                .input(DataTree::from_value(Value::Plane(Plane {
                    x_axis: Vector3::ZERO,
                    ..Plane::WORLD_XY
                })))
                .run(),
        ] {
            assert_eq!(messages(&bad, Level::Error).len(), 1, "{:?}", bad.messages);
        }
    }

    /// A hexagon of radius 1 with corners of radius 0.2: each corner turns by π/3, so it trades
    /// 2 · 0.2 tan(π/6) of side for an arc, and the arcs make one full turn: the length is
    /// 6 − 12 · 0.2 tan(π/6) + 2π · 0.2. A fillet radius above the inscribed radius cos(π/6)
    /// is reduced to it, which makes the inscribed circle.
    #[test]
    fn rounded_polygon() {
        let run = |fillet: f64| {
            NodeCall::new(&polygon())
                .skip_input()
                .skip_input()
                .skip_input()
                .input(DataTree::from_item(fillet))
                .run()
        };
        let r = run(0.2);
        assert!(r.messages.is_empty(), "{:?}", r.messages);
        let want = 6.0 - 12.0 * 0.2 * (PI / 6.0).tan() + TAU * 0.2;
        assert!((only::<f64>(&r, 1) - want).abs() < 1e-12);
        let r = run(2.0);
        let inscribed = (PI / 6.0).cos();
        assert!(
            (only::<f64>(&r, 1) - TAU * inscribed).abs() < 1e-9,
            "{}",
            only::<f64>(&r, 1)
        );
        assert_eq!(r.messages.len(), 1, "{:?}", r.messages);
        let c = only::<Shared<Curve>>(&r, 0);
        for k in 0..100 {
            let q = c.point_at(c.domain().t0 + c.domain().length() * k as f64 / 100.0);
            assert!(
                ((q - Point3::ORIGIN).length() - inscribed).abs() < 1e-9,
                "{q:?}"
            );
        }
    }

    #[test]
    fn curve_middle_is_halfway_along_the_length() {
        let poly =
            Polyline::new(vec![p(0.0, 0.0, 0.0), p(1.0, 0.0, 0.0), p(1.0, 3.0, 0.0)]).unwrap();
        let r = NodeCall::new(&curve_middle())
            .input(DataTree::from_item(Shared::new(Curve::from(poly))))
            .run();
        // Length 4: halfway is 1 along the second segment, not the domain's middle vertex.
        assert!(close(only::<Point3>(&r, 0), p(1.0, 1.0, 0.0)));
    }
}

//! Intersect › Mathematical: lines, planes and curves against lines and planes (Line | Line,
//! Line | Plane, Plane | Plane, Plane | Plane | Plane, Curve | Plane, Curve | Line).
//!
//! Lines are infinite, as in Rhino's `Intersection` functions that these components call:
//! parameters outside `[0, 1]` are reported. Inputs that do not meet (parallel lines and
//! planes) give a warning and null outputs for that item.

use locus_kernel::{
    Curve, CurveIntersections, Line, Plane, Point3, line_line, line_plane, plane_plane,
    plane_plane_plane,
};
use locus_runtime::{DataType, NodeError, NodeRegistry, NodeType, Port, Shared, Solve};

use super::INTERSECTION_TOLERANCE;
use crate::curve::curve_input;

/// Id of [`line_line_node`].
pub const LINE_LINE: &str = "intersect.line_line";
/// Id of [`line_plane_node`].
pub const LINE_PLANE: &str = "intersect.line_plane";
/// Id of [`plane_plane_node`].
pub const PLANE_PLANE: &str = "intersect.plane_plane";
/// Id of [`plane_plane_plane_node`].
pub const PLANE_PLANE_PLANE: &str = "intersect.plane_plane_plane";
/// Id of [`curve_plane_node`].
pub const CURVE_PLANE: &str = "intersect.curve_plane";
/// Id of [`curve_line_node`].
pub const CURVE_LINE: &str = "intersect.curve_line";

/// Registers the Mathematical intersection nodes.
pub fn register(registry: &mut NodeRegistry) {
    for t in [
        line_line_node(),
        line_plane_node(),
        plane_plane_node(),
        plane_plane_plane_node(),
        curve_plane_node(),
        curve_line_node(),
    ] {
        registry.register(t);
    }
}

fn mathematical(id: &str, name: &str, nickname: &str) -> NodeType {
    NodeType::new(id, name, nickname, "Intersect").subcategory("Mathematical")
}

/// A line input, checked finite and of some length.
fn line_input(s: &Solve<'_>, input: usize, name: &str) -> Result<Line, NodeError> {
    let line = *s.item::<Line>(input)?;
    if !line.is_finite() {
        return Err(format!("line {name} is not finite").into());
    }
    if line.unit_direction().is_none() {
        return Err(format!("line {name} has no length").into());
    }
    Ok(line)
}

/// A plane input, checked valid (finite, unit orthogonal axes).
fn plane_input(s: &Solve<'_>, input: usize, name: &str) -> Result<Plane, NodeError> {
    let plane = *s.item::<Plane>(input)?;
    if !plane.is_valid() {
        return Err(format!("plane {name} is not a valid plane").into());
    }
    Ok(plane)
}

/// The plane coordinates of a point as the point `(u, v, 0)`.
fn plane_uv(plane: &Plane, p: Point3) -> Point3 {
    let (u, v) = plane.closest_parameter(p);
    Point3::new(u, v, 0.0)
}

/// Line | Line \[LLX\]: the closest points of two infinite lines.
pub fn line_line_node() -> NodeType {
    mathematical(LINE_LINE, "Line | Line", "LLX")
        .gh_guid("6d4b82a7-8c1d-4bec-af7b-ca321ba4beb1")
        .description(
            "Solves the intersection of two lines, taken as infinite: the parameters and points \
             where they come closest (where they cross, when they lie in one plane). Parallel \
             lines have no answer and give a warning.",
        )
        .input(Port::new("Line A", "A", DataType::Line).doc("The first line."))
        .input(Port::new("Line B", "B", DataType::Line).doc("The second line."))
        .output(
            Port::new("Param A", "tA", DataType::Number)
                .doc("The parameter on A (0 at its start, 1 at its end)."),
        )
        .output(
            Port::new("Param B", "tB", DataType::Number)
                .doc("The parameter on B (0 at its start, 1 at its end)."),
        )
        .output(Port::new("Point A", "pA", DataType::Point).doc("The point on A."))
        .output(Port::new("Point B", "pB", DataType::Point).doc("The point on B."))
        .solve(|s| {
            let a = line_input(s, 0, "A")?;
            let b = line_input(s, 1, "B")?;
            let Some((ta, tb)) = line_line(&a, &b) else {
                s.warning("the lines are parallel: they have no single closest point");
                return Ok(());
            };
            s.set(0, ta);
            s.set(1, tb);
            s.set(2, a.point_at(ta));
            s.set(3, b.point_at(tb));
            Ok(())
        })
}

/// Line | Plane \[PLX\]: where an infinite line crosses a plane.
pub fn line_plane_node() -> NodeType {
    mathematical(LINE_PLANE, "Line | Plane", "PLX")
        .gh_guid("75d0442c-1aa3-47cf-bd94-457b42c16e9f")
        .description(
            "Solves the intersection of a line, taken as infinite, and a plane: the point, its \
             parameter on the line and its coordinates in the plane. A line parallel to the \
             plane has no answer and gives a warning.",
        )
        .input(Port::new("Line", "L", DataType::Line).doc("The line."))
        .input(
            Port::new("Plane", "P", DataType::Plane)
                .doc("The plane. Default the world XY plane.")
                .default_value(Plane::WORLD_XY),
        )
        .output(Port::new("Point", "P", DataType::Point).doc("The intersection point."))
        .output(
            Port::new("Param", "t", DataType::Number)
                .doc("The parameter on the infinite line (0 at its start, 1 at its end)."),
        )
        .output(
            Port::new("Param UV", "uv", DataType::Point)
                .doc("The point's plane coordinates, as the point (u, v, 0)."),
        )
        .solve(|s| {
            let line = line_input(s, 0, "L")?;
            let plane = plane_input(s, 1, "P")?;
            let Some(t) = line_plane(&line, &plane) else {
                s.warning("the line is parallel to the plane");
                return Ok(());
            };
            let p = line.point_at(t);
            s.set(0, p);
            s.set(1, t);
            s.set(2, plane_uv(&plane, p));
            Ok(())
        })
}

/// Plane | Plane \[PPX\]: the line where two planes meet.
pub fn plane_plane_node() -> NodeType {
    mathematical(PLANE_PLANE, "Plane | Plane", "PPX")
        .gh_guid("290cf9c4-0711-4704-851e-4c99e3343ac5")
        .description(
            "Solves the intersection of two planes: Rhino's line, from the point of both planes \
             nearest the midpoint of their origins, along B's normal × A's normal, of length \
             the sine of the angle between them. Parallel planes give a warning.",
        )
        .input(Port::new("Plane A", "A", DataType::Plane).doc("The first plane."))
        .input(Port::new("Plane B", "B", DataType::Plane).doc("The second plane."))
        .output(Port::new("Line", "L", DataType::Line).doc("The intersection line."))
        .solve(|s| {
            let a = plane_input(s, 0, "A")?;
            let b = plane_input(s, 1, "B")?;
            match plane_plane(&a, &b) {
                Some(line) => s.set(0, line),
                None => s.warning("the planes are parallel"),
            }
            Ok(())
        })
}

/// Plane | Plane | Plane \[3PX\]: the point where three planes meet.
pub fn plane_plane_plane_node() -> NodeType {
    mathematical(PLANE_PLANE_PLANE, "Plane | Plane | Plane", "3PX")
        .gh_guid("f1ea5a4b-1a4f-4cf4-ad94-1ecfb9302b6e")
        .description(
            "Solves the intersection of three planes: their common point and the lines where \
             each pair meets. Planes with dependent normals have no single point and give a \
             warning; the lines of the pairs that do meet are still given.",
        )
        .input(Port::new("Plane A", "A", DataType::Plane).doc("The first plane."))
        .input(Port::new("Plane B", "B", DataType::Plane).doc("The second plane."))
        .input(Port::new("Plane C", "C", DataType::Plane).doc("The third plane."))
        .output(Port::new("Point", "Pt", DataType::Point).doc("The common point."))
        .output(Port::new("Line AB", "AB", DataType::Line).doc("Where A and B meet."))
        .output(Port::new("Line AC", "AC", DataType::Line).doc("Where A and C meet."))
        .output(Port::new("Line BC", "BC", DataType::Line).doc("Where B and C meet."))
        .solve(|s| {
            let a = plane_input(s, 0, "A")?;
            let b = plane_input(s, 1, "B")?;
            let c = plane_input(s, 2, "C")?;
            match plane_plane_plane(&a, &b, &c) {
                Some(p) => s.set(0, p),
                None => s.warning("the three planes have no single common point"),
            }
            for (output, (p, q)) in [(1, (a, b)), (2, (a, c)), (3, (b, c))] {
                if let Some(line) = plane_plane(&p, &q) {
                    s.set(output, line);
                }
            }
            Ok(())
        })
}

/// The points of an intersection, with the ends of its overlaps (where the curve lies in the
/// plane or on the line), in parameter order, and a remark naming the overlaps.
fn points_and_overlap_ends(
    s: &mut Solve<'_>,
    curve: &Curve,
    found: &CurveIntersections,
) -> Vec<(f64, Point3)> {
    let mut events: Vec<(f64, Point3)> = found.points.iter().map(|h| (h.t, h.point)).collect();
    for o in &found.overlaps {
        events.push((o.t0, curve.point_at(o.t0)));
        events.push((o.t1, curve.point_at(o.t1)));
    }
    events.sort_by(|a, b| a.0.total_cmp(&b.0));
    if !found.overlaps.is_empty() {
        let list: Vec<String> = found
            .overlaps
            .iter()
            .map(|o| format!("[{}, {}]", o.t0, o.t1))
            .collect();
        s.remark(format!(
            "the curve overlaps on {}: the ends of each overlap are given as points",
            list.join(", ")
        ));
    }
    events
}

/// Curve | Plane \[PCX\]: where a curve meets a plane.
pub fn curve_plane_node() -> NodeType {
    mathematical(CURVE_PLANE, "Curve | Plane", "PCX")
        .gh_guid("b7c12ed1-b09a-4e15-996f-3fa9f3f16b1c")
        .description(
            "Solves the intersection of a curve and a plane: every point where the curve \
             crosses or touches the plane (tangencies and kinks included, a seam once), within \
             the intersection tolerance (0.001). Where a part of the curve lies in the plane, \
             the ends of that part are given as points, with a remark.",
        )
        .input(Port::new("Curve", "C", DataType::Curve).doc("The curve."))
        .input(
            Port::new("Plane", "P", DataType::Plane)
                .doc("The plane. Default the world XY plane.")
                .default_value(Plane::WORLD_XY),
        )
        .output(
            Port::new("Points", "P", DataType::Point)
                .doc("The intersection points, in curve order.")
                .list(),
        )
        .output(
            Port::new("Params C", "t", DataType::Number)
                .doc("The curve parameters of the points.")
                .list(),
        )
        .output(
            Port::new("Params P", "uv", DataType::Point)
                .doc("The plane coordinates of the points, as points (u, v, 0).")
                .list(),
        )
        .solve(|s| {
            let curve: Shared<Curve> = curve_input(s, 0)?;
            let plane = plane_input(s, 1, "P")?;
            let found = curve.intersect_plane(&plane, INTERSECTION_TOLERANCE)?;
            let events = points_and_overlap_ends(s, &curve, &found);
            s.set_list(0, events.iter().map(|e| e.1).collect());
            s.set_list(1, events.iter().map(|e| e.0).collect());
            s.set_list(2, events.iter().map(|e| plane_uv(&plane, e.1)).collect());
            Ok(())
        })
}

/// Curve | Line \[CLX\]: where a curve meets an infinite line.
pub fn curve_line_node() -> NodeType {
    mathematical(CURVE_LINE, "Curve | Line", "CLX")
        .gh_guid("0e3173b6-91c6-4845-a748-e45d4fdbc262")
        .description(
            "Solves the intersection of a curve and a line, taken as infinite: every point \
             where the curve crosses or touches the line, within the intersection tolerance \
             (0.001). Where a part of the curve lies on the line, the ends of that part are \
             given as points, with a remark.",
        )
        .input(Port::new("Curve", "C", DataType::Curve).doc("The curve."))
        .input(Port::new("Line", "L", DataType::Line).doc("The line."))
        .output(
            Port::new("Points", "P", DataType::Point)
                .doc("The intersection points, in curve order.")
                .list(),
        )
        .output(
            Port::new("Params", "t", DataType::Number)
                .doc("The curve parameters of the points.")
                .list(),
        )
        .output(
            Port::new("Count", "N", DataType::Integer).doc("The number of intersection points."),
        )
        .solve(|s| {
            let curve: Shared<Curve> = curve_input(s, 0)?;
            let line = line_input(s, 1, "L")?;
            let found = curve.intersect_line(&line, INTERSECTION_TOLERANCE)?;
            let events = points_and_overlap_ends(s, &curve, &found);
            s.set(2, events.len() as i64);
            s.set_list(0, events.iter().map(|e| e.1).collect());
            s.set_list(1, events.iter().map(|e| e.0).collect());
            Ok(())
        })
}

#[cfg(test)]
mod tests {
    use locus_kernel::{Circle, Polyline, Vector3};
    use locus_runtime::{DataTree, Level, NodeCall};

    use super::*;
    use crate::test_support::{
        all, assert_clean, assert_error, is_null, messages, numbers, only, points,
    };

    fn p(x: f64, y: f64, z: f64) -> Point3 {
        Point3::new(x, y, z)
    }

    fn curve(c: impl Into<Curve>) -> Shared<Curve> {
        Shared::new(c.into())
    }

    #[test]
    fn line_line_gives_the_crossing() {
        let r = NodeCall::new(&line_line_node())
            .input(DataTree::from_item(Line::new(
                p(0.0, 0.0, 0.0),
                p(4.0, 0.0, 0.0),
            )))
            .input(DataTree::from_item(Line::new(
                p(1.0, -1.0, 0.0),
                p(1.0, 1.0, 0.0),
            )))
            .run();
        assert_clean(&r);
        assert_eq!(only::<f64>(&r, 0), 0.25);
        assert_eq!(only::<f64>(&r, 1), 0.5);
        assert_eq!(only::<Point3>(&r, 2), p(1.0, 0.0, 0.0));
        assert_eq!(only::<Point3>(&r, 3), p(1.0, 0.0, 0.0));
    }

    #[test]
    fn parallel_lines_warn_and_give_nulls() {
        let r = NodeCall::new(&line_line_node())
            .input(DataTree::from_item(Line::new(
                p(0.0, 0.0, 0.0),
                p(1.0, 0.0, 0.0),
            )))
            .input(DataTree::from_item(Line::new(
                p(0.0, 1.0, 0.0),
                p(3.0, 1.0, 0.0),
            )))
            .run();
        assert_eq!(messages(&r, Level::Warning).len(), 1);
        assert!(is_null(&r, 0) && is_null(&r, 2));
        let r = NodeCall::new(&line_line_node())
            .input(DataTree::from_item(Line::new(
                p(0.0, 0.0, 0.0),
                p(0.0, 0.0, 0.0),
            )))
            .input(DataTree::from_item(Line::new(
                p(0.0, 1.0, 0.0),
                p(3.0, 1.0, 0.0),
            )))
            .run();
        assert_error(&r, "no length");
    }

    #[test]
    fn line_plane_reports_parameter_and_plane_coordinates() {
        let plane = Plane::WORLD_XY.translated(Vector3::new(0.0, 0.0, 2.0));
        let r = NodeCall::new(&line_plane_node())
            .input(DataTree::from_item(Line::new(
                p(1.0, 2.0, 0.0),
                p(1.0, 2.0, 1.0),
            )))
            .input(DataTree::from_item(plane))
            .run();
        assert_clean(&r);
        assert_eq!(only::<Point3>(&r, 0), p(1.0, 2.0, 2.0));
        assert_eq!(only::<f64>(&r, 1), 2.0);
        assert_eq!(only::<Point3>(&r, 2), p(1.0, 2.0, 0.0));
        let r = NodeCall::new(&line_plane_node())
            .input(DataTree::from_item(Line::new(
                p(1.0, 2.0, 0.0),
                p(3.0, 2.0, 0.0),
            )))
            .run();
        assert!(messages(&r, Level::Warning)[0].contains("parallel"));
    }

    #[test]
    fn plane_nodes_meet_in_lines_and_a_point() {
        let r = NodeCall::new(&plane_plane_plane_node())
            .input(DataTree::from_item(Plane::WORLD_XY))
            .input(DataTree::from_item(Plane::WORLD_YZ))
            .input(DataTree::from_item(Plane::WORLD_ZX))
            .run();
        assert_clean(&r);
        assert_eq!(only::<Point3>(&r, 0), p(0.0, 0.0, 0.0));
        let ab = only::<Line>(&r, 1);
        assert!(ab.unit_direction().unwrap().cross(Vector3::Y).length() < 1e-15);
        let r = NodeCall::new(&plane_plane_node())
            .input(DataTree::from_item(Plane::WORLD_XY))
            .input(DataTree::from_item(
                Plane::WORLD_XY.translated(Vector3::new(0.0, 0.0, 1.0)),
            ))
            .run();
        assert!(messages(&r, Level::Warning)[0].contains("parallel"));
        assert!(is_null(&r, 0));
        let bad = Plane {
            z_axis: Vector3::new(f64::NAN, 0.0, 0.0),
            ..Plane::WORLD_XY
        };
        let r = NodeCall::new(&plane_plane_node())
            .input(DataTree::from_item(bad))
            .input(DataTree::from_item(Plane::WORLD_XY))
            .run();
        assert_error(&r, "not a valid plane");
    }

    #[test]
    fn curve_plane_finds_crossings_and_overlap_ends() {
        let circle = Circle::new(Plane::WORLD_ZX, 2.0).unwrap();
        let r = NodeCall::new(&curve_plane_node())
            .input(DataTree::from_item(curve(circle)))
            .input(DataTree::from_item(
                Plane::WORLD_XY.translated(Vector3::new(0.0, 0.0, 1.0)),
            ))
            .run();
        assert_clean(&r);
        let pts = points(&r.outputs[0]);
        assert_eq!(pts.len(), 2);
        assert!(pts.iter().all(|q| (q.z - 1.0).abs() < 1e-12));
        let uv = points(&r.outputs[2]);
        assert!((uv[0].x.abs() - 3f64.sqrt()).abs() < 1e-12);
        let square = Polyline::new(vec![
            p(0.0, 0.0, -1.0),
            p(0.0, 0.0, 0.0),
            p(1.0, 0.0, 0.0),
            p(1.0, 0.0, 1.0),
        ])
        .unwrap();
        let r = NodeCall::new(&curve_plane_node())
            .input(DataTree::from_item(curve(square)))
            .run();
        assert_eq!(numbers(&r.outputs[1]), vec![1.0, 2.0]);
        assert!(messages(&r, Level::Remark)[0].contains("overlaps on [1, 2]"));
    }

    #[test]
    fn curve_line_counts_its_points() {
        let circle = Circle::new(Plane::WORLD_XY, 1.0).unwrap();
        let r = NodeCall::new(&curve_line_node())
            .input(DataTree::from_item(curve(circle)))
            .input(DataTree::from_item(Line::new(
                p(-5.0, 0.0, 0.0),
                p(5.0, 0.0, 0.0),
            )))
            .run();
        assert_clean(&r);
        assert_eq!(only::<i64>(&r, 2), 2);
        let ts = numbers(&r.outputs[1]);
        assert!((ts[0] - 0.0).abs() < 1e-12 && (ts[1] - std::f64::consts::PI).abs() < 1e-12);
        let r = NodeCall::new(&curve_line_node())
            .input(DataTree::from_item(curve(circle)))
            .input(DataTree::from_item(Line::new(
                p(-5.0, 3.0, 0.0),
                p(5.0, 3.0, 0.0),
            )))
            .run();
        assert_eq!(only::<i64>(&r, 2), 0);
        assert!(all::<Point3>(&r.outputs[0]).is_empty());
    }
}

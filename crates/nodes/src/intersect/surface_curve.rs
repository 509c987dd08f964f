//! Intersect › Mathematical and Physical, on surfaces and B-reps against lines and curves:
//! Surface | Line, Surface | Curve, Brep | Line and Brep | Curve.
//!
//! The kernel ([`NurbsSurface::intersect_curve`], [`NurbsSurface::intersect_line`],
//! [`Brep::intersect_curve`], [`Brep::intersect_line`]) finds every point within the
//! intersection tolerance, polished to full precision, and the stretches where the curve lies in
//! the surface, which come out as overlap curves (the piece of the curve). Lines are infinite,
//! as for the other Mathematical line intersections.

use locus_kernel::{
    Brep, BrepCurveIntersections, Curve, CurveSurfaceIntersections, Interval, Line, NurbsSurface,
    Point3, Vector3,
};
use locus_runtime::{DataType, NodeError, NodeRegistry, NodeType, Port, Shared, Solve};

use super::INTERSECTION_TOLERANCE;
use crate::curve::curve_input;
use crate::surface::analysis::surface_input;
use crate::surface::brep::brep_item;

/// Id of [`surface_line_node`].
pub const SURFACE_LINE: &str = "intersect.surface_line";
/// Id of [`surface_curve_node`].
pub const SURFACE_CURVE: &str = "intersect.surface_curve";
/// Id of [`brep_line_node`].
pub const BREP_LINE: &str = "intersect.brep_line";
/// Id of [`brep_curve_node`].
pub const BREP_CURVE: &str = "intersect.brep_curve";

/// Registers the four nodes.
pub fn register(registry: &mut NodeRegistry) {
    registry.register(surface_line_node());
    registry.register(surface_curve_node());
    registry.register(brep_line_node());
    registry.register(brep_curve_node());
}

fn node(id: &str, name: &str, nickname: &str, subcategory: &str) -> NodeType {
    NodeType::new(id, name, nickname, "Intersect").subcategory(subcategory)
}

/// A line input, checked finite and of some length.
fn line_input(s: &Solve<'_>, input: usize) -> Result<Line, NodeError> {
    let line = *s.item::<Line>(input)?;
    if !line.is_finite() {
        return Err("line L is not finite".into());
    }
    if line.unit_direction().is_none() {
        return Err("line L has no length".into());
    }
    Ok(line)
}

/// The pieces of `curve` on the overlap intervals, as curves.
fn overlap_curves(curve: &Curve, intervals: impl Iterator<Item = Interval>) -> Vec<Shared<Curve>> {
    intervals
        .filter_map(|i| curve.trim(i).ok())
        .map(Shared::new)
        .collect()
}

/// The segments of the infinite `line` on the overlap intervals (line parameters), as curves.
fn overlap_lines(line: &Line, intervals: impl Iterator<Item = Interval>) -> Vec<Shared<Curve>> {
    intervals
        .map(|i| {
            Shared::new(Curve::from(Line::new(
                line.point_at(i.t0),
                line.point_at(i.t1),
            )))
        })
        .collect()
}

/// The surface outputs of a surface search: points, `uv` points and normals.
fn surface_events(
    surface: &NurbsSurface,
    found: &CurveSurfaceIntersections,
) -> (Vec<Point3>, Vec<Point3>, Vec<Vector3>) {
    let points = found.points.iter().map(|h| h.point).collect();
    let uv = found
        .points
        .iter()
        .map(|h| Point3::new(h.u, h.v, 0.0))
        .collect();
    let normals = found
        .points
        .iter()
        .map(|h| surface.normal_at(h.u, h.v).unwrap_or(Vector3::ZERO))
        .collect();
    (points, uv, normals)
}

fn surface_ports(t: NodeType) -> NodeType {
    t.output(
        Port::new("Curves", "C", DataType::Curve)
            .doc("The overlap curves: the parts of the curve that lie in the surface.")
            .list(),
    )
    .output(
        Port::new("Points", "P", DataType::Point)
            .doc("The intersection points, in order along the curve.")
            .list(),
    )
    .output(
        Port::new("UV Points", "uv", DataType::Point)
            .doc("The surface parameters {u, v, 0} of each point.")
            .list(),
    )
    .output(
        Port::new("Normal", "N", DataType::Vector)
            .doc("The unit surface normal at each point (zero where it is not defined, at a pole).")
            .list(),
    )
}

/// Surface | Line \[SLX\]: where a surface meets an infinite line.
pub fn surface_line_node() -> NodeType {
    surface_ports(
        node(SURFACE_LINE, "Surface | Line", "SLX", "Mathematical")
            .gh_guid("a834e823-ae01-44d8-9066-c138eeb6f391")
            .description(
                "Solves the intersection of a surface and a line, taken as infinite: every \
                 point where the line crosses or touches the surface (its edges, corners and \
                 creases included), within the intersection tolerance (0.001), with its \
                 surface parameters and normal. Where the line lies in the surface, that \
                 segment is given as an overlap curve.",
            )
            .input(
                Port::new("Surface", "S", DataType::Surface)
                    .doc("The surface. A B-rep of one face is taken as its surface."),
            )
            .input(Port::new("Line", "L", DataType::Line).doc("The line, taken as infinite.")),
    )
    .solve(|s| {
        let surface = surface_input(s, 0)?;
        let line = line_input(s, 1)?;
        let found = surface.intersect_line(&line, INTERSECTION_TOLERANCE)?;
        let (points, uv, normals) = surface_events(&surface, &found);
        s.set_list(0, overlap_lines(&line, found.overlaps.iter().map(|o| o.t)));
        s.set_list(1, points);
        s.set_list(2, uv);
        s.set_list(3, normals);
        Ok(())
    })
}

/// Surface | Curve \[SCX\]: where a surface meets a curve.
pub fn surface_curve_node() -> NodeType {
    surface_ports(
        node(SURFACE_CURVE, "Surface | Curve", "SCX", "Physical")
            .gh_guid("68546dd0-aa82-471c-87e9-81cb16ac50ed")
            .description(
                "Solves the intersection of a surface and a curve: every point where the curve \
                 crosses or touches the surface (tangencies, the curve's ends and kinks, the \
                 surface's edges included), within the intersection tolerance (0.001), with its \
                 surface parameters, normal, curve parameter and tangent. Where the curve lies \
                 in the surface, that part of it is given as an overlap curve.",
            )
            .input(
                Port::new("Surface", "S", DataType::Surface)
                    .doc("The surface. A B-rep of one face is taken as its surface."),
            )
            .input(Port::new("Curve", "C", DataType::Curve).doc("The curve.")),
    )
    .output(
        Port::new("Parameters", "t", DataType::Number)
            .doc("The curve parameter of each point.")
            .list(),
    )
    .output(
        Port::new("Tangents", "T", DataType::Vector)
            .doc("The unit curve tangent at each point.")
            .list(),
    )
    .solve(|s| {
        let surface = surface_input(s, 0)?;
        let curve: Shared<Curve> = curve_input(s, 1)?;
        let found = surface.intersect_curve(&curve, INTERSECTION_TOLERANCE)?;
        let (points, uv, normals) = surface_events(&surface, &found);
        s.set_list(
            0,
            overlap_curves(&curve, found.overlaps.iter().map(|o| o.t)),
        );
        s.set_list(1, points);
        s.set_list(2, uv);
        s.set_list(3, normals);
        s.set_list(4, found.points.iter().map(|h| h.t).collect());
        s.set_list(
            5,
            found
                .points
                .iter()
                .map(|h| curve.tangent_at(h.t).unwrap_or(Vector3::ZERO))
                .collect(),
        );
        Ok(())
    })
}

fn brep_ports(t: NodeType) -> NodeType {
    t.input(
        Port::new("Brep", "B", DataType::Brep)
            .doc("The B-rep. Boxes and surfaces are taken as B-reps."),
    )
    .output(
        Port::new("Curves", "C", DataType::Curve)
            .doc("The overlap curves: the parts of the curve that lie on faces.")
            .list(),
    )
    .output(
        Port::new("Points", "P", DataType::Point)
            .doc(
                "The intersection points, in order along the curve; a point on an edge or at a \
                 vertex is given once.",
            )
            .list(),
    )
}

fn set_brep_points(s: &mut Solve<'_>, found: &BrepCurveIntersections) {
    s.set_list(1, found.points.iter().map(|h| h.hit.point).collect());
}

/// Brep | Line \[BLX\]: where a B-rep meets an infinite line.
pub fn brep_line_node() -> NodeType {
    brep_ports(
        node(BREP_LINE, "Brep | Line", "BLX", "Mathematical")
            .gh_guid("ed0742f9-6647-4d95-9dfd-9ad17080ae9c")
            .description(
                "Solves the intersection of a B-rep and a line, taken as infinite: every point \
                 where the line crosses or touches a face inside its trims, within the \
                 intersection tolerance (0.001); a point on an edge or at a vertex is given \
                 once. Where the line lies on a face, that segment is given as an overlap curve.",
            ),
    )
    .input(Port::new("Line", "L", DataType::Line).doc("The line, taken as infinite."))
    .solve(|s| {
        let brep: Shared<Brep> = brep_item(s, 0)?;
        let line = line_input(s, 1)?;
        let found = brep.intersect_line(&line, INTERSECTION_TOLERANCE)?;
        s.set_list(0, overlap_lines(&line, found.overlaps.iter().map(|o| o.t)));
        set_brep_points(s, &found);
        Ok(())
    })
}

/// Brep | Curve \[BCX\]: where a B-rep meets a curve.
pub fn brep_curve_node() -> NodeType {
    brep_ports(
        node(BREP_CURVE, "Brep | Curve", "BCX", "Physical")
            .gh_guid("20ef81e8-df15-4a0c-acf1-993a7607cafb")
            .description(
                "Solves the intersection of a B-rep and a curve: every point where the curve \
                 crosses or touches a face inside its trims (tangencies, the curve's ends and \
                 kinks included), within the intersection tolerance (0.001); a point on an edge \
                 or at a vertex is given once. Where the curve lies on a face, that part of it \
                 is given as an overlap curve.",
            ),
    )
    .input(Port::new("Curve", "C", DataType::Curve).doc("The curve."))
    .solve(|s| {
        let brep: Shared<Brep> = brep_item(s, 0)?;
        let curve: Shared<Curve> = curve_input(s, 1)?;
        let found = brep.intersect_curve(&curve, INTERSECTION_TOLERANCE)?;
        s.set_list(
            0,
            overlap_curves(&curve, found.overlaps.iter().map(|o| o.t)),
        );
        set_brep_points(s, &found);
        Ok(())
    })
}

#[cfg(test)]
mod tests {
    use locus_kernel::{Cylinder, Interval, OrientedBox, Plane, Sphere};
    use locus_runtime::{DataTree, NodeCall, Value};

    use super::*;
    use crate::test_support::{assert_clean, assert_error, numbers, points};

    fn p(x: f64, y: f64, z: f64) -> Point3 {
        Point3::new(x, y, z)
    }

    fn sphere() -> DataTree {
        let s = Sphere::new(p(0.0, 0.0, 0.0), 2.0)
            .unwrap()
            .to_nurbs()
            .unwrap();
        DataTree::from_item(Shared::new(s))
    }

    fn unit_box() -> DataTree {
        let b = Brep::from_box(&OrientedBox::new(
            Plane::WORLD_XY,
            Interval::new(0.0, 1.0),
            Interval::new(0.0, 1.0),
            Interval::new(0.0, 1.0),
        ))
        .unwrap();
        DataTree::from_item(Shared::new(b))
    }

    fn line(a: Point3, b: Point3) -> DataTree {
        DataTree::from_item(Line::new(a, b))
    }

    fn curve(c: impl Into<Curve>) -> DataTree {
        DataTree::from_item(Shared::new(c.into()))
    }

    #[test]
    fn a_line_through_a_sphere_gives_two_points_with_outward_normals() {
        // The line is infinite: the short segment inside the sphere still meets it twice.
        let r = NodeCall::new(&surface_line_node())
            .input(sphere())
            .input(line(p(0.0, 0.0, -0.5), p(0.0, 0.0, 0.5)))
            .run();
        assert_clean(&r);
        let pts = points(&r.outputs[1]);
        assert_eq!(pts.len(), 2);
        assert!(pts[0].distance(p(0.0, 0.0, -2.0)) < 1e-12, "{pts:?}");
        assert!(pts[1].distance(p(0.0, 0.0, 2.0)) < 1e-12, "{pts:?}");
        assert_eq!(r.outputs[0].item_count(), 0);
    }

    #[test]
    fn a_curve_along_a_cylinder_is_an_overlap_curve() {
        let c = Cylinder::new(Plane::WORLD_XY, 1.0, 2.0)
            .unwrap()
            .to_nurbs()
            .unwrap();
        let r = NodeCall::new(&surface_curve_node())
            .input(DataTree::from_item(Shared::new(c)))
            .input(curve(Line::new(p(0.0, 1.0, -1.0), p(0.0, 1.0, 3.0))))
            .run();
        assert_clean(&r);
        assert_eq!(r.outputs[0].item_count(), 1);
        assert!(points(&r.outputs[1]).is_empty());
        let crossing = NodeCall::new(&surface_curve_node())
            .input(sphere())
            .input(curve(Line::new(p(0.0, 0.0, 0.0), p(0.0, 0.0, 4.0))))
            .run();
        assert_clean(&crossing);
        assert_eq!(numbers(&crossing.outputs[4]), vec![2.0]);
    }

    #[test]
    fn a_box_is_crossed_twice_and_edges_count_once() {
        let r = NodeCall::new(&brep_line_node())
            .input(unit_box())
            .input(line(p(-1.0, -1.0, -1.0), p(2.0, 2.0, 2.0)))
            .run();
        assert_clean(&r);
        assert_eq!(points(&r.outputs[1]).len(), 2);
        let r = NodeCall::new(&brep_curve_node())
            .input(unit_box())
            .input(curve(Line::new(p(-1.0, 0.5, 1.0), p(2.0, 0.5, 1.0))))
            .run();
        assert_clean(&r);
        assert_eq!(r.outputs[0].item_count(), 1);
        assert!(points(&r.outputs[1]).is_empty());
    }

    #[test]
    fn bad_input_is_an_error() {
        let r = NodeCall::new(&surface_line_node())
            .input(sphere())
            .input(line(p(1.0, 1.0, 1.0), p(1.0, 1.0, 1.0)))
            .run();
        assert_error(&r, "line L has no length");
        let r = NodeCall::new(&surface_line_node())
            .input(sphere())
            .input(line(p(f64::NAN, 1.0, 1.0), p(1.0, 1.0, 1.0)))
            .run();
        assert_error(&r, "line L is not finite");
        let r = NodeCall::new(&brep_curve_node())
            .input(unit_box())
            .input(DataTree::from_item(Value::Number(3.0)))
            .run();
        assert_error(&r, "input C");
        let r = NodeCall::new(&surface_curve_node())
            .input(DataTree::from_item(Value::Text("x".into())))
            .input(curve(Line::new(p(0.0, 0.0, 0.0), p(1.0, 0.0, 0.0))))
            .run();
        assert_error(&r, "input S");
        // A null input gives no output and no panic.
        let r = NodeCall::new(&brep_line_node())
            .input(DataTree::new())
            .input(line(p(0.0, 0.0, 0.0), p(1.0, 0.0, 0.0)))
            .run();
        assert_eq!(r.outputs[1].item_count(), 0);
    }
}

//! Curve › Analysis: closed curves as regions — Polygon Center and Point In Curve.

use locus_kernel::{Curve, Point3, Polyline};
use locus_runtime::{DataType, NodeError, NodeRegistry, NodeType, Port};

use super::curve_input;

/// Id of [`polygon_center`].
pub const POLYGON_CENTER: &str = "curve.polygon_center";
/// Id of [`point_in_curve`].
pub const POINT_IN_CURVE: &str = "curve.point_in_curve";

/// The distance within which Point In Curve counts a point as on the curve: 0.001 model
/// units, Rhino's default document tolerance, which Grasshopper uses.
pub const CONTAINMENT_TOLERANCE: f64 = 0.001;

/// Registers the region nodes.
pub fn register(registry: &mut NodeRegistry) {
    registry.register(polygon_center());
    registry.register(point_in_curve());
}

/// The polyline a curve is: a polyline, a line, or a NURBS curve of degree 1 (its control
/// points).
fn as_polyline(curve: &Curve) -> Option<Polyline> {
    match curve {
        Curve::Polyline { polyline, .. } => Some(polyline.clone()),
        Curve::Line { line, .. } => Polyline::new(vec![line.from, line.to]).ok(),
        Curve::Nurbs(c) if c.degree() == 1 => Polyline::new(c.points().to_vec()).ok(),
        _ => None,
    }
}

/// Polygon Center \[PCen\]: the vertex, edge and area centres of a polyline.
pub fn polygon_center() -> NodeType {
    NodeType::new(POLYGON_CENTER, "Polygon Center", "PCen", "Curve")
        .subcategory("Analysis")
        .gh_guid("59e94548-cefd-4774-b3de-48142fc783fb")
        .description(
            "Finds three centres of a polyline: the average of its vertices (the closing vertex \
             of a closed polyline counted once), the centroid of its edges as a wire (their \
             midpoints weighted by their lengths), and, for a closed polyline, the centroid of \
             the area it bounds (in its plane; for a polygon out of plane the triangles from \
             the vertex average weighted by their areas along its mean normal). Open \
             polylines have no area centre (null, with a remark). Lines and curves of degree 1 \
             count as polylines; other curves are an error.",
        )
        .input(Port::new("Polyline", "P", DataType::Curve).doc("The polyline."))
        .output(Port::new("Center Vertices", "Cv", DataType::Point).doc("Average of the vertices."))
        .output(Port::new("Center Edges", "Ce", DataType::Point).doc("Centroid of the edges."))
        .output(
            Port::new("Center Area", "Ca", DataType::Point)
                .doc("Centroid of the enclosed area; null for an open polyline."),
        )
        .solve(|s| {
            let curve = curve_input(s, 0)?;
            let polyline = as_polyline(&curve).ok_or_else(|| {
                NodeError::from("input P: the curve is not a polyline (degree 1)")
            })?;
            s.set(0, polyline.vertex_average());
            s.set(1, polyline.wire_centroid());
            match polyline.area_centroid() {
                Some(c) => s.set(2, c),
                None => {
                    s.set_value(2, None);
                    s.remark("the polyline is open or encloses no area: no area centre");
                }
            }
            Ok(())
        })
}

/// Point In Curve \[InCurve\]: whether a point lies inside a closed planar curve.
pub fn point_in_curve() -> NodeType {
    NodeType::new(POINT_IN_CURVE, "Point In Curve", "InCurve", "Curve")
        .subcategory("Analysis")
        .gh_guid("a72b0bd3-c7a7-458e-875d-09ae1624638c")
        .description(
            "Tests a point against a closed planar curve, in the curve's plane: 0 outside, 1 on \
             the curve (within 0.001), 2 inside. The point is first projected onto the plane \
             along its normal; the projection is the second output. Curves that are open or \
             not planar are an error.",
        )
        .input(Port::new("Point", "P", DataType::Point).doc("The point to test."))
        .input(Port::new("Curve", "C", DataType::Curve).doc("A closed planar curve."))
        .output(
            Port::new("Relationship", "R", DataType::Integer)
                .doc("0 outside, 1 on the curve, 2 inside."),
        )
        .output(
            Port::new("Point", "P'", DataType::Point)
                .doc("The point projected onto the curve's plane."),
        )
        .solve(|s| {
            let p = *s.item::<Point3>(0)?;
            if !p.is_finite() {
                return Err("input P: the point is not finite".into());
            }
            let curve = curve_input(s, 1)?;
            let (relation, projected) = curve.contains_point(p, CONTAINMENT_TOLERANCE)?;
            s.set(0, relation as i64);
            s.set(1, projected);
            Ok(())
        })
}

#[cfg(test)]
mod tests {
    use locus_kernel::{Circle, NurbsCurve, Plane};
    use locus_runtime::{DataTree, NodeCall, Shared};

    use super::*;
    use crate::curve::test_support::*;

    fn trapezoid() -> Polyline {
        Polyline::new(vec![
            Point3::new(0.0, 0.0, 0.0),
            Point3::new(4.0, 0.0, 0.0),
            Point3::new(4.0, 2.0, 0.0),
            Point3::new(0.0, 4.0, 0.0),
            Point3::new(0.0, 0.0, 0.0),
        ])
        .unwrap()
    }

    #[test]
    fn polygon_centres() {
        let r = NodeCall::new(&polygon_center())
            .input(curve_tree(trapezoid()))
            .run();
        assert_clean(&r);
        let cv: Point3 = only(&r, 0);
        assert!(close(cv, Point3::new(2.0, 1.5, 0.0), 1e-15));
        let ca: Point3 = only(&r, 2);
        let want = Point3::new(64.0 / 36.0, 56.0 / 36.0, 0.0);
        assert!(close(ca, want, 1e-14), "{ca:?}");
        // Open: no area centre.
        let open = Polyline::new(trapezoid().points()[..3].to_vec()).unwrap();
        let r = NodeCall::new(&polygon_center())
            .input(curve_tree(open))
            .run();
        assert!(is_null(&r, 2));
        assert!(!messages(&r, locus_runtime::Level::Remark).is_empty());
    }

    #[test]
    fn polygon_center_needs_a_polyline() {
        let circle = Circle::new(Plane::WORLD_XY, 1.0).unwrap();
        let r = NodeCall::new(&polygon_center())
            .input(curve_tree(circle))
            .run();
        assert_error(&r, "not a polyline");
        let degree_one = NurbsCurve::create(trapezoid().points(), 1, false).unwrap();
        let r = NodeCall::new(&polygon_center())
            .input(curve_tree(degree_one))
            .run();
        assert_clean(&r);
    }

    #[test]
    fn points_in_and_out_of_a_circle() {
        let circle = Shared::new(Curve::from(Circle::new(Plane::WORLD_XY, 2.0).unwrap()));
        let run = |p: Point3| {
            NodeCall::new(&point_in_curve())
                .input(DataTree::from_item(p))
                .input(DataTree::from_item(circle.clone()))
                .run()
        };
        let r = run(Point3::new(0.5, 0.5, 3.0));
        assert_eq!(only::<i64>(&r, 0), 2);
        assert_eq!(only::<Point3>(&r, 1), Point3::new(0.5, 0.5, 0.0));
        assert_eq!(only::<i64>(&run(Point3::new(2.0005, 0.0, 0.0)), 0), 1);
        assert_eq!(only::<i64>(&run(Point3::new(3.0, 0.0, 0.0)), 0), 0);
        let r = run(Point3::new(f64::NAN, 0.0, 0.0));
        assert_error(&r, "input P");
        let open = Shared::new(Curve::from(
            Polyline::new(trapezoid().points()[..3].to_vec()).unwrap(),
        ));
        let r = NodeCall::new(&point_in_curve())
            .input(DataTree::from_item(Point3::ORIGIN))
            .input(DataTree::from_item(open))
            .run();
        assert_error(&r, "closed");
    }
}

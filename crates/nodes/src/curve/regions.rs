//! Closed curves as regions: Polygon Center and Point In Curve (Curve › Analysis), and the
//! region booleans Region Union, Region Intersection and Region Difference (Intersect › Shape).

use locus_kernel::tolerance::DOCUMENT_TOLERANCE;
use locus_kernel::{Curve, Plane, Point3, Polyline, RegionOperation};
use locus_runtime::{DataType, NodeError, NodeRegistry, NodeType, Port, Shared, Solve};

use super::curve_input;
use super::edit::curve_list;

/// Id of [`polygon_center`].
pub const POLYGON_CENTER: &str = "curve.polygon_center";
/// Id of [`point_in_curve`].
pub const POINT_IN_CURVE: &str = "curve.point_in_curve";
/// Id of [`region_union`].
pub const REGION_UNION: &str = "intersect.region_union";
/// Id of [`region_intersection`].
pub const REGION_INTERSECTION: &str = "intersect.region_intersection";
/// Id of [`region_difference`].
pub const REGION_DIFFERENCE: &str = "intersect.region_difference";

/// The distance within which Point In Curve counts a point as on the curve: 0.001 model
/// units, Rhino's default document tolerance, which Grasshopper uses.
pub const CONTAINMENT_TOLERANCE: f64 = 0.001;

/// Registers the region nodes.
pub fn register(registry: &mut NodeRegistry) {
    registry.register(polygon_center());
    registry.register(point_in_curve());
    registry.register(region_union());
    registry.register(region_intersection());
    registry.register(region_difference());
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

/// What every region boolean's description says about how it works.
macro_rules! region_method {
    () => {
        "A set of curves bounds the region inside any of them. The curves \
     are projected onto the plane P (by default the plane of the first curve), intersected \
     with each other and split there; a piece is kept where the result lies on one side of it \
     and not the other, and the pieces are joined. Shared edges are resolved: squares sharing \
     an edge unite into one rectangle. Outer boundaries run counter-clockwise about the \
     plane's normal and holes clockwise, whatever the direction of the inputs. Works within \
     0.001 model units (the document tolerance). A curve that is open or bounds no area in \
     the plane is an error naming it; nulls are left out with a warning."
    };
}

fn region_plane_port() -> Port {
    Port::new("Plane", "P", DataType::Plane)
        .optional()
        .doc("The plane to work in; when absent, the plane of the first curve.")
}

fn region_result_port() -> Port {
    Port::new("Result", "R", DataType::Curve)
        .list()
        .doc("The boundaries of the result: outer ones counter-clockwise, holes clockwise.")
}

fn region_node(id: &str, name: &str, nickname: &str) -> NodeType {
    NodeType::new(id, name, nickname, "Intersect").subcategory("Shape")
}

/// Runs a region boolean on the curves of inputs `a` and `b` (none for a union) in the plane
/// of input `plane`.
fn solve_region(
    s: &mut Solve<'_>,
    a: usize,
    b: Option<usize>,
    plane: usize,
    operation: RegionOperation,
) -> Result<(), NodeError> {
    let first: Vec<Curve> = curve_list(s, a)?.iter().map(|c| (**c).clone()).collect();
    let second: Vec<Curve> = match b {
        Some(b) => curve_list(s, b)?.iter().map(|c| (**c).clone()).collect(),
        None => Vec::new(),
    };
    let plane = match s.item_opt::<Plane>(plane).copied() {
        Some(p) if p.is_valid() => p,
        Some(_) => return Err("input P: the plane is not valid".into()),
        None => match first.first().or(second.first()) {
            Some(c) => c.region_plane(DOCUMENT_TOLERANCE).map_err(|e| {
                NodeError::from(format!(
                    "input P is absent and the first curve has no plane: {e}"
                ))
            })?,
            None => {
                s.set_list(0, Vec::<Shared<Curve>>::new());
                return Ok(());
            }
        },
    };
    let result = Curve::region_boolean(&first, &second, operation, &plane, DOCUMENT_TOLERANCE)?;
    let open = result.iter().filter(|c| !c.is_closed()).count();
    if open > 0 {
        s.warning(format!(
            "{open} boundary piece(s) did not close into a loop (curves that nearly touch \
             within the tolerance); they are given as they are"
        ));
    }
    s.set_list(0, result.into_iter().map(Shared::new).collect());
    Ok(())
}

/// Region Union \[RUnion\]: the union of the regions inside closed planar curves.
pub fn region_union() -> NodeType {
    region_node(REGION_UNION, "Region Union", "RUnion")
        .gh_guid("1222394f-0d33-4f31-9101-7281bde89fe5")
        .description(concat!(
            "The boundaries of the region inside any of the curves. ",
            region_method!()
        ))
        .input(
            Port::new("Curves", "C", DataType::Curve)
                .list()
                .doc("Closed planar curves."),
        )
        .input(region_plane_port())
        .output(region_result_port())
        .solve(|s| solve_region(s, 0, None, 1, RegionOperation::Union))
}

/// Region Intersection \[RInt\]: the region inside both sets of closed planar curves.
pub fn region_intersection() -> NodeType {
    region_node(REGION_INTERSECTION, "Region Intersection", "RInt")
        .gh_guid("477c2e7b-c5e5-421e-b8b2-ba60cdf5398b")
        .description(concat!(
            "The boundaries of the region inside a curve of A and inside a curve of B. ",
            region_method!()
        ))
        .input(
            Port::new("Curves A", "A", DataType::Curve)
                .list()
                .doc("The first set of closed planar curves."),
        )
        .input(
            Port::new("Curves B", "B", DataType::Curve)
                .list()
                .doc("The second set of closed planar curves."),
        )
        .input(region_plane_port())
        .output(region_result_port())
        .solve(|s| solve_region(s, 0, Some(1), 2, RegionOperation::Intersection))
}

/// Region Difference \[RDiff\]: the region inside the curves of A and outside those of B.
pub fn region_difference() -> NodeType {
    region_node(REGION_DIFFERENCE, "Region Difference", "RDiff")
        .gh_guid("f72c480b-7ee6-42ef-9821-c371e9203b44")
        .description(concat!(
            "The boundaries of the region inside a curve of A and outside every curve of B \
             (B cut out of A). ",
            region_method!()
        ))
        .input(
            Port::new("Curves A", "A", DataType::Curve)
                .list()
                .doc("Closed planar curves to cut from."),
        )
        .input(
            Port::new("Curves B", "B", DataType::Curve)
                .list()
                .doc("Closed planar curves to cut out."),
        )
        .input(region_plane_port())
        .output(region_result_port())
        .solve(|s| solve_region(s, 0, Some(1), 2, RegionOperation::Difference))
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

    fn square(x0: f64, y0: f64, side: f64) -> Shared<Curve> {
        let p = |x: f64, y: f64| Point3::new(x, y, 0.0);
        Shared::new(Curve::from(
            Polyline::new(vec![
                p(x0, y0),
                p(x0 + side, y0),
                p(x0 + side, y0 + side),
                p(x0, y0 + side),
                p(x0, y0),
            ])
            .unwrap(),
        ))
    }

    fn curve_list_tree(curves: Vec<Shared<Curve>>) -> DataTree {
        DataTree::from_list(curves)
    }

    fn results(r: &locus_runtime::NodeCallResult) -> Vec<Shared<Curve>> {
        crate::test_support::curves(&r.outputs[0])
    }

    #[test]
    fn region_booleans_of_two_squares() {
        let (a, b) = (square(0.0, 0.0, 2.0), square(1.0, 1.0, 2.0));
        let r = NodeCall::new(&region_union())
            .input(curve_list_tree(vec![a.clone(), b.clone()]))
            .skip_input()
            .run();
        assert_clean(&r);
        let u = results(&r);
        assert_eq!(u.len(), 1);
        // The union's outline has eight corners (and the closing vertex).
        assert_eq!(u[0].to_nurbs().points().len(), 9);
        for (node, count) in [(region_intersection(), 1), (region_difference(), 1)] {
            let r = NodeCall::new(&node)
                .input(curve_list_tree(vec![a.clone()]))
                .input(curve_list_tree(vec![b.clone()]))
                .skip_input()
                .run();
            assert_clean(&r);
            assert_eq!(results(&r).len(), count);
        }
    }

    #[test]
    fn region_booleans_report_bad_curves() {
        let open = Shared::new(Curve::from(
            Polyline::new(trapezoid().points()[..3].to_vec()).unwrap(),
        ));
        let r = NodeCall::new(&region_difference())
            .input(curve_list_tree(vec![square(0.0, 0.0, 1.0)]))
            .input(curve_list_tree(vec![open]))
            .skip_input()
            .run();
        assert_error(&r, "curve 0 of B is not closed");
        // An invalid plane is named; no curves give no result.
        let r = NodeCall::new(&region_union())
            .input(curve_list_tree(vec![square(0.0, 0.0, 1.0)]))
            .input(DataTree::from_item(Plane {
                x_axis: locus_kernel::Vector3::ZERO,
                ..Plane::WORLD_XY
            }))
            .run();
        assert_error(&r, "input P");
        let r = NodeCall::new(&region_union())
            .input(curve_list_tree(Vec::new()))
            .skip_input()
            .run();
        assert_clean(&r);
        assert!(results(&r).is_empty());
    }
}

//! Mesh › Triangulation: Delaunay Mesh, Delaunay Edges, Voronoi and Convex Hull, planar
//! constructions on a list of points through the kernel's [`PlanarTriangulation`].
//!
//! Each takes its points in a plane: the Plane input when given, else the points' best-fit
//! (least-squares) plane, as Grasshopper does. Points that repeat an earlier point's position
//! in the plane take no part (the first stands for them), with a warning naming them.

use locus_kernel::{Curve, PlanarTriangulation, Plane, Point3, Polyline};
use locus_runtime::{
    Branch, DataTree, DataType, NodeError, NodeRegistry, NodeType, Port, Shared, Solve,
};

use super::mesh_node;

/// Id of [`delaunay_mesh`].
pub const DELAUNAY_MESH: &str = "mesh.delaunay_mesh";
/// Id of [`delaunay_edges`].
pub const DELAUNAY_EDGES: &str = "mesh.delaunay_edges";
/// Id of [`voronoi`].
pub const VORONOI: &str = "mesh.voronoi";
/// Id of [`convex_hull`].
pub const CONVEX_HULL: &str = "mesh.convex_hull";

/// How far Voronoi's automatic boundary reaches past the points, as a fraction of the larger
/// side of their bounding rectangle in the plane: 0.1.
pub const VORONOI_MARGIN: f64 = 0.1;

/// Registers the Triangulation nodes.
pub fn register(registry: &mut NodeRegistry) {
    registry.register(delaunay_mesh());
    registry.register(delaunay_edges());
    registry.register(voronoi());
    registry.register(convex_hull());
}

fn points_port() -> Port {
    Port::new("Points", "P", DataType::Point)
        .list()
        .doc("The points to triangulate.")
}

fn plane_port() -> Port {
    Port::new("Plane", "Pl", DataType::Plane).optional().doc(
        "The plane to triangulate in; when absent, the plane that fits the points best \
         (least squares, facing up).",
    )
}

/// The triangulation of the points of input 0 in the plane of input `plane` (or their best
/// fit), with a warning for repeated points.
fn triangulate(s: &mut Solve<'_>, plane: usize) -> Result<PlanarTriangulation, NodeError> {
    let list = s.list::<Point3>(0)?;
    let nulls = list.len() - list.present().count();
    let points: Vec<Point3> = list.present().copied().collect();
    if nulls > 0 {
        s.warning(format!(
            "{nulls} null point(s) were left out; indices count the points that remain"
        ));
    }
    let plane = s.item_opt::<Plane>(plane).copied();
    if let Some(p) = &plane
        && !p.is_valid()
    {
        return Err("the plane Pl is not valid".into());
    }
    let t = PlanarTriangulation::new(&points, plane.as_ref())
        .map_err(|e| NodeError(format!("points P: {e}")))?;
    let duplicates = t.duplicates();
    if !duplicates.is_empty() {
        let shown: Vec<String> = duplicates.iter().take(8).map(|i| i.to_string()).collect();
        let more = if duplicates.len() > 8 { ", …" } else { "" };
        s.warning(format!(
            "{} point(s) repeat an earlier point's position in the plane and were left out \
             (indices {}{more})",
            duplicates.len(),
            shown.join(", ")
        ));
    }
    Ok(t)
}

/// Delaunay Mesh \[Del\]: the Delaunay triangulation of points as a mesh.
pub fn delaunay_mesh() -> NodeType {
    mesh_node(DELAUNAY_MESH, "Delaunay Mesh", "Del", "Triangulation")
        .gh_guid("1eb4f6ff-3547-4184-bead-1b01e7cfd668")
        .description(
            "Triangulates points by Delaunay's rule in a plane: no point lies inside the \
             circumcircle of a triangle. The mesh's vertices are the points where they are \
             (a terrain survey triangulated in the XY plane gives a terrain mesh), in input \
             order without repeats; its triangles turn counter-clockwise about the plane's \
             normal.",
        )
        .input(points_port())
        .input(plane_port())
        .output(Port::new("Mesh", "M", DataType::Mesh).doc("The triangulated mesh."))
        .solve(|s| {
            let t = triangulate(s, 1)?;
            s.set(0, Shared::new(t.mesh()?));
            Ok(())
        })
}

/// Delaunay Edges \[Con\]: the edges of the Delaunay triangulation and each point's neighbours.
pub fn delaunay_edges() -> NodeType {
    mesh_node(DELAUNAY_EDGES, "Delaunay Edges", "Con", "Triangulation")
        .description(
            "The edges of the Delaunay triangulation of points in a plane, and for every point \
             the indices of the points it is joined to (its natural neighbours).",
        )
        .input(points_port())
        .input(plane_port())
        .output(
            Port::new("Connectivity", "C", DataType::Integer)
                .list()
                .doc("Per point (one branch each, {path;i}), the indices of its neighbours, ascending."),
        )
        .output(
            Port::new("Edges", "E", DataType::Line)
                .list()
                .doc("The edges as lines from the lower to the higher point index, sorted."),
        )
        .solve(|s| {
            let t = triangulate(s, 1)?;
            let points: Vec<Point3> = s.list::<Point3>(0)?.present().copied().collect();
            let base = s.path().clone();
            let branches: Vec<_> = t
                .connectivity()
                .into_iter()
                .enumerate()
                .map(|(i, n)| {
                    let mut b = Branch::new(DataType::Integer);
                    for j in n {
                        b.push(j as i64);
                    }
                    (base.with_appended(i as u32), b)
                })
                .collect();
            s.set_tree(0, DataTree::from_branches(branches));
            let lines = t
                .edges()
                .into_iter()
                .map(|(i, j)| locus_kernel::Line::new(points[i], points[j]))
                .collect::<Vec<_>>();
            s.set_list(1, lines);
            Ok(())
        })
}

/// Voronoi \[Voronoi\]: the planar Voronoi cells of points.
pub fn voronoi() -> NodeType {
    mesh_node(VORONOI, "Voronoi", "Voronoi", "Triangulation")
        .gh_guid("a4011be0-1c91-45bd-8280-17dd3a9f46f1")
        .description(
            "The Voronoi diagram of points in a plane: for every point, the region nearer to \
             it than to any other point, clipped to a convex boundary, as a closed polyline \
             in the plane (counter-clockwise). Without a boundary, the points' bounding \
             rectangle in the plane enlarged by a tenth of its larger side each way. A point \
             that repeats another, or lies outside the boundary, has no cell (a null item).",
        )
        .input(points_port())
        .input(Port::new("Radius", "R", DataType::Number).optional().doc(
            "Grasshopper's cell radius (cells rounded by circles about their points); not \
             supported yet: leave it empty.",
        ))
        .input(Port::new("Boundary", "B", DataType::Curve).optional().doc(
            "A convex closed polyline or rectangle to clip the cells to, projected onto the \
             plane.",
        ))
        .input(plane_port())
        .output(
            Port::new("Cells", "C", DataType::Curve)
                .list()
                .doc("The cells, one per point, in the order of the points."),
        )
        .solve(|s| {
            if s.item_opt::<f64>(1).is_some() {
                return Err(
                    "the cell radius R is not supported yet (cells bounded by circles need \
                     arcs in polycurves); leave R empty"
                        .into(),
                );
            }
            let t = triangulate(s, 3)?;
            let boundary = match s.item_opt::<Shared<Curve>>(2) {
                Some(curve) => boundary_corners(curve, t.plane())?,
                None => t.bounding_rectangle(VORONOI_MARGIN).to_vec(),
            };
            let cells = t
                .voronoi_cells(&boundary)
                .map_err(|e| NodeError(format!("boundary B: {e}")))?;
            let values = cells
                .into_iter()
                .map(|c| c.map(|p| locus_runtime::Value::Curve(Shared::new(Curve::from(p)))))
                .collect();
            s.set_list_values(0, values);
            Ok(())
        })
}

/// The corners of a boundary curve in the plane's coordinates, counter-clockwise.
fn boundary_corners(curve: &Curve, plane: &Plane) -> Result<Vec<(f64, f64)>, NodeError> {
    let points = match curve {
        Curve::Polyline { polyline, .. } => polyline.points().to_vec(),
        Curve::Nurbs(n) if n.degree() == 1 => n.points().to_vec(),
        _ => {
            return Err(
                "boundary B: give a closed polyline or rectangle (straight segments)".into(),
            );
        }
    };
    if points.len() < 4 || points.first() != points.last() {
        return Err("boundary B: the polyline must be closed".into());
    }
    let mut corners: Vec<(f64, f64)> = points[..points.len() - 1]
        .iter()
        .map(|&p| {
            let [u, v, _] = plane.local_coordinates(p);
            (u, v)
        })
        .collect();
    let twice_area: f64 = (0..corners.len())
        .map(|k| {
            let (a, b) = (corners[k], corners[(k + 1) % corners.len()]);
            a.0 * b.1 - b.0 * a.1
        })
        .sum();
    if twice_area < 0.0 {
        corners.reverse();
    }
    Ok(corners)
}

/// Convex Hull \[Hull\]: the convex hull of points in a plane.
pub fn convex_hull() -> NodeType {
    mesh_node(CONVEX_HULL, "Convex Hull", "Hull", "Triangulation")
        .gh_guid("9d0c5284-ea24-4f9f-a183-ef57fc48b5b8")
        .description(
            "The convex hull of points in a plane: the smallest convex polygon holding them. \
             Its corners turn counter-clockwise about the plane's normal, starting at the \
             corner with the lowest index; points in the middle of a hull side are not \
             corners.",
        )
        .input(points_port())
        .input(plane_port())
        .output(
            Port::new("Hull", "H", DataType::Curve)
                .doc("The hull as a closed polyline through the corner points where they are."),
        )
        .output(
            Port::new("Hull Z", "Hz", DataType::Curve)
                .doc("The same hull projected onto the plane."),
        )
        .output(
            Port::new("Indices", "I", DataType::Integer)
                .list()
                .doc("The indices of the corner points, in hull order."),
        )
        .solve(|s| {
            let t = triangulate(s, 1)?;
            let points: Vec<Point3> = s.list::<Point3>(0)?.present().copied().collect();
            let hull = t.convex_hull();
            let closed = |corners: Vec<Point3>| -> Result<Shared<Curve>, NodeError> {
                let mut corners = corners;
                corners.push(corners[0]);
                Ok(Shared::new(Curve::from(Polyline::new(corners)?)))
            };
            let spatial = closed(hull.iter().map(|&i| points[i]).collect())?;
            let plane = *t.plane();
            let flat = closed(
                hull.iter()
                    .map(|&i| {
                        let (u, v) = t.uv(i);
                        plane.point_at(u, v, 0.0)
                    })
                    .collect(),
            )?;
            s.set(0, spatial);
            s.set(1, flat);
            s.set_list(2, hull.into_iter().map(|i| i as i64).collect::<Vec<_>>());
            Ok(())
        })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_support::{all, assert_clean, assert_error, messages, only};
    use locus_kernel::{Mesh, Vector3};
    use locus_runtime::{Level, NodeCall, TreePath, Value};

    fn points(xy: &[(f64, f64, f64)]) -> DataTree {
        DataTree::from_list(xy.iter().map(|&(x, y, z)| Point3::new(x, y, z)).collect())
    }

    fn five() -> DataTree {
        points(&[
            (0.0, 0.0, 0.0),
            (4.0, 0.0, 0.0),
            (4.0, 3.0, 0.0),
            (0.0, 3.0, 0.0),
            (1.5, 1.2, 2.0),
        ])
    }

    #[test]
    fn delaunay_mesh_keeps_heights_and_faces_the_plane() {
        let r = NodeCall::new(&delaunay_mesh()).input(five()).run();
        assert_clean(&r);
        let m = only::<Shared<Mesh>>(&r, 0);
        assert_eq!(m.faces().len(), 4);
        assert_eq!(m.vertices()[4], Point3::new(1.5, 1.2, 2.0));
        // In the XY plane every triangle turns counter-clockwise seen from +z.
        let r = NodeCall::new(&delaunay_mesh())
            .input(five())
            .input(DataTree::from_value(Value::Plane(Plane::WORLD_XY)))
            .run();
        let m = only::<Shared<Mesh>>(&r, 0);
        for f in m.faces() {
            let [a, b, c] = [0, 1, 2].map(|k| m.vertices()[f.vertices[k] as usize]);
            let n: Vector3 = (b - a).cross(c - a);
            assert!(n.z > 0.0);
        }
    }

    #[test]
    fn repeated_and_null_points_are_reported_and_left_out() {
        let mut tree = five();
        tree.branch_mut(&TreePath::new([0]))
            .unwrap()
            .push(Point3::new(4.0, 0.0, 0.0));
        let r = NodeCall::new(&delaunay_mesh()).input(tree).run();
        let warnings = messages(&r, Level::Warning);
        assert_eq!(warnings.len(), 1, "{:?}", r.messages);
        assert!(warnings[0].contains("indices 5"), "{}", warnings[0]);
        assert_eq!(only::<Shared<Mesh>>(&r, 0).vertices().len(), 5);
    }

    #[test]
    fn bad_points_and_planes_are_errors() {
        let line = points(&[(0.0, 0.0, 0.0), (1.0, 1.0, 0.0), (2.0, 2.0, 0.0)]);
        for node in [delaunay_mesh(), delaunay_edges(), voronoi(), convex_hull()] {
            let r = NodeCall::new(&node).input(line.clone()).run();
            assert_error(&r, "points P");
            let r = NodeCall::new(&node).input(points(&[(0.0, 0.0, 0.0)])).run();
            assert_error(&r, "points P");
            let nan = points(&[(0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (f64::NAN, 1.0, 0.0)]);
            let r = NodeCall::new(&node).input(nan).run();
            assert_error(&r, "points P");
        }
        let mut bad_plane = Plane::WORLD_XY;
        bad_plane.z_axis = Vector3::ZERO;
        let r = NodeCall::new(&delaunay_mesh())
            .input(five())
            .input(DataTree::from_value(Value::Plane(bad_plane)))
            .run();
        assert_error(&r, "plane Pl");
    }

    #[test]
    fn edges_and_connectivity_of_the_fan() {
        let r = NodeCall::new(&delaunay_edges()).input(five()).run();
        assert_clean(&r);
        let c = &r.outputs[0];
        assert_eq!(c.branch_count(), 5);
        let e = c.branch(&TreePath::new([0, 4])).unwrap();
        assert_eq!(
            DataTree::from_branches([(TreePath::new([0]), e.clone())]),
            DataTree::from_list(vec![0i64, 1, 2, 3])
        );
        let lines = all::<locus_kernel::Line>(&r.outputs[1]);
        assert_eq!(lines.len(), 8);
        assert_eq!(lines[0].from, Point3::ORIGIN);
        assert_eq!(lines[0].to, Point3::new(4.0, 0.0, 0.0));
    }

    #[test]
    fn convex_hull_in_space_and_in_the_plane() {
        let r = NodeCall::new(&convex_hull())
            .input(points(&[
                (1.0, 1.0, 0.0),
                (0.0, 0.0, 1.0),
                (2.0, 0.0, 0.0),
                (2.0, 2.0, 0.0),
                (0.0, 2.0, 0.0),
            ]))
            .input(DataTree::from_value(Value::Plane(Plane::WORLD_XY)))
            .run();
        assert_clean(&r);
        assert_eq!(all::<i64>(&r.outputs[2]), vec![1, 2, 3, 4]);
        let hull = only::<Shared<Curve>>(&r, 0);
        assert_eq!(hull.start_point(), Point3::new(0.0, 0.0, 1.0));
        assert!(hull.is_closed());
        let flat = only::<Shared<Curve>>(&r, 1);
        assert_eq!(flat.start_point(), Point3::ORIGIN);
    }

    #[test]
    fn voronoi_cells_and_their_refusals() {
        let r = NodeCall::new(&voronoi()).input(five()).run();
        assert_clean(&r);
        let cells = all::<Shared<Curve>>(&r.outputs[0]);
        assert_eq!(cells.len(), 5);
        assert!(cells.iter().all(|c| c.is_closed()));
        // Radius is not supported: an error saying so.
        let r = NodeCall::new(&voronoi())
            .input(five())
            .input(DataTree::from_value(Value::Number(1.0)))
            .run();
        assert_error(&r, "radius R");
        // A boundary that is not a polyline, or not convex.
        let circle = locus_kernel::Circle {
            plane: Plane::WORLD_XY,
            radius: 10.0,
        };
        let r = NodeCall::new(&voronoi())
            .input(five())
            .input(DataTree::new())
            .input(DataTree::from_value(Value::Curve(Shared::new(
                Curve::from(circle),
            ))))
            .run();
        assert_error(&r, "boundary B");
        let dart = Polyline::new(
            [(0.0, 0.0), (8.0, 0.0), (2.0, 2.0), (0.0, 8.0), (0.0, 0.0)]
                .iter()
                .map(|&(x, y)| Point3::new(x, y, 0.0))
                .collect(),
        )
        .unwrap();
        let r = NodeCall::new(&voronoi())
            .input(five())
            .input(DataTree::new())
            .input(DataTree::from_value(Value::Curve(Shared::new(
                Curve::from(dart),
            ))))
            .run();
        assert_error(&r, "convex");
    }
}

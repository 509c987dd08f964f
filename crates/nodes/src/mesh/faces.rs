//! Mesh › Analysis: Face Boundaries (each face as a closed polyline) and Mesh Closest Point.
//!
//! locus has no Mesh Point value yet (Rhino's `MeshPoint`: a face index and barycentric
//! weights), so Mesh Closest Point's Parameter is the text `F[t0,t1,t2,t3]`: the face index
//! and the weights of its four corners, as the panel shows a mesh parameter.

use locus_kernel::{Curve, Mesh, Point3, Polyline};
use locus_runtime::{DataType, NodeError, NodeRegistry, NodeType, Port, Shared, Value};

use super::{mesh_item, mesh_node};

/// Id of [`face_boundaries`].
pub const FACE_BOUNDARIES: &str = "mesh.face_boundaries";
/// Id of [`mesh_closest_point`].
pub const MESH_CLOSEST_POINT: &str = "mesh.mesh_closest_point";

/// Registers Face Boundaries and Mesh Closest Point.
pub fn register(registry: &mut NodeRegistry) {
    registry.register(face_boundaries());
    registry.register(mesh_closest_point());
}

/// The closed polyline around each face, in face order (`None` for a face whose corners do not
/// make a polyline, which a mesh's checks already exclude).
fn boundaries(m: &Mesh) -> Vec<Option<Value>> {
    let v = m.vertices();
    m.faces()
        .iter()
        .map(|f| {
            let mut pts: Vec<Point3> = f.corners().iter().map(|&i| v[i as usize]).collect();
            pts.push(pts[0]);
            Polyline::new(pts)
                .ok()
                .map(|p| Value::Curve(Shared::new(Curve::from(p))))
        })
        .collect()
}

/// Face Boundaries \[FaceB\]: the outline of every face.
pub fn face_boundaries() -> NodeType {
    mesh_node(FACE_BOUNDARIES, "Face Boundaries", "FaceB", "Analysis")
        .gh_guid("08d45f16-c708-4ede-8fd3-b70a0a7abd8f")
        .gh_guid("0b4ac802-fc4a-4201-9c66-0078b837c1eb")
        .description(
            "Converts every face of a mesh into a closed polyline through its corners (four \
             segments for a quad, three for a triangle), in face order, in the face's vertex \
             order.",
        )
        .input(Port::new("Mesh", "M", DataType::Mesh).doc("The mesh."))
        .output(
            Port::new("Boundaries", "B", DataType::Curve)
                .list()
                .doc("The face outlines, closed polylines."),
        )
        .solve(|s| {
            let m = mesh_item(s, 0)?;
            s.set_list_values(0, boundaries(&m));
            Ok(())
        })
}

/// The text of a mesh parameter: `face[t0,t1,t2,t3]`.
pub fn mesh_parameter_text(face: usize, weights: [f64; 4]) -> String {
    let [a, b, c, d] = weights;
    format!("{face}[{a},{b},{c},{d}]")
}

/// Mesh Closest Point \[MeshCP\]: the point of a mesh closest to a point.
pub fn mesh_closest_point() -> NodeType {
    mesh_node(
        MESH_CLOSEST_POINT,
        "Mesh Closest Point",
        "MeshCP",
        "Analysis",
    )
    .description(
        "Finds the point of a mesh closest to a sample point, the index of the face it is \
             on, and its mesh parameter: the text face[t0,t1,t2,t3], the weights of the \
             face's four corners (a triangle's fourth is 0), which sum to 1 (locus has no \
             Mesh Point value yet). Every face is tested. A mesh without faces is an error. \
             Its Grasshopper GUID is not in the project's table, so files cannot name it \
             yet.",
    )
    .input(Port::new("Point", "P", DataType::Point).doc("The point to search from."))
    .input(Port::new("Mesh", "M", DataType::Mesh).doc("The mesh to search."))
    .output(Port::new("Point", "P", DataType::Point).doc("The closest point on the mesh."))
    .output(Port::new("Index", "I", DataType::Integer).doc("The index of its face."))
    .output(Port::new("Parameter", "Par", DataType::Text).doc(
        "The mesh parameter: face[t0,t1,t2,t3] (Grasshopper's nickname is P, as the \
                 point's; locus keeps nicknames unique).",
    ))
    .solve(|s| {
        let p = *s.item::<Point3>(0)?;
        let m = mesh_item(s, 1)?;
        if !p.is_finite() {
            return Err("the point is not finite".into());
        }
        let hit = m
            .closest_point(p)
            .ok_or_else(|| NodeError::from("the mesh has no faces"))?;
        s.set(0, hit.point);
        s.set(1, hit.face as i64);
        s.set(2, mesh_parameter_text(hit.face, hit.weights));
        Ok(())
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_support::{assert_clean, assert_error, curves, only};
    use locus_kernel::MeshFace;
    use locus_runtime::{DataTree, NodeCall};

    fn strip() -> Mesh {
        // A quad (0,0)–(1,1) and a triangle on its right side up to (2,0.5).
        let p = |x: f64, y: f64| Point3::new(x, y, 0.0);
        Mesh::new(
            vec![
                p(0.0, 0.0),
                p(1.0, 0.0),
                p(1.0, 1.0),
                p(0.0, 1.0),
                p(2.0, 0.5),
            ],
            vec![MeshFace::quad(0, 1, 2, 3), MeshFace::triangle(1, 4, 2)],
        )
        .unwrap()
    }

    fn mesh(m: Mesh) -> DataTree {
        DataTree::from_value(Value::Mesh(Shared::new(m)))
    }

    #[test]
    fn face_boundaries_are_closed_polylines() {
        let r = NodeCall::new(&face_boundaries()).input(mesh(strip())).run();
        assert_clean(&r);
        let c = curves(&r.outputs[0]);
        assert_eq!(c.len(), 2);
        // The quad's outline is 4 long, the triangle's 1 + 2 · √(1 + 0.25).
        assert!((c[0].length() - 4.0).abs() < 1e-12);
        assert!((c[1].length() - (1.0 + 2.0 * 1.25f64.sqrt())).abs() < 1e-12);
        assert!(c.iter().all(|c| c.is_closed()));
    }

    #[test]
    fn closest_point_finds_the_face_and_weights() {
        let run = |p: Point3| {
            NodeCall::new(&mesh_closest_point())
                .input(DataTree::from_value(Value::Point(p)))
                .input(mesh(strip()))
                .run()
        };
        // Above the triangle's centroid (4/3, 0.5): weights 1/3 each.
        let r = run(Point3::new(4.0 / 3.0, 0.5, 1.0));
        assert_clean(&r);
        assert!(only::<Point3>(&r, 0).distance(Point3::new(4.0 / 3.0, 0.5, 0.0)) < 1e-12);
        assert_eq!(only::<i64>(&r, 1), 1);
        let text = only::<String>(&r, 2);
        assert!(text.starts_with("1[0.333"), "{text}");
        // Beside the quad on the left: its edge x = 0.
        let r = run(Point3::new(-1.0, 0.5, 0.0));
        assert_eq!(only::<Point3>(&r, 0), Point3::new(0.0, 0.5, 0.0));
        assert_eq!(only::<i64>(&r, 1), 0);
        assert_eq!(only::<String>(&r, 2), "0[0.5,0,0,0.5]");
        let r = NodeCall::new(&mesh_closest_point())
            .input(DataTree::from_value(Value::Point(Point3::ORIGIN)))
            .input(mesh(Mesh::default()))
            .run();
        assert_error(&r, "no faces");
    }
}

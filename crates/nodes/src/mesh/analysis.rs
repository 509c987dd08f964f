//! Mesh › Analysis: Mesh Area, Mesh Volume and Face Normals.

use locus_kernel::{Mesh, Point3, Vector3};
use locus_runtime::{DataType, NodeError, NodeRegistry, NodeType, Port, Shared};

use super::{mesh_item, mesh_node};

/// Id of [`mesh_area`].
pub const MESH_AREA: &str = "mesh.mesh_area";
/// Id of [`mesh_volume`].
pub const MESH_VOLUME: &str = "mesh.mesh_volume";
/// Id of [`face_normals`].
pub const FACE_NORMALS: &str = "mesh.face_normals";

/// Registers Mesh Area, Mesh Volume and Face Normals.
pub fn register(registry: &mut NodeRegistry) {
    registry.register(mesh_area());
    registry.register(mesh_volume());
    registry.register(face_normals());
}

fn mesh_input() -> Port {
    Port::new("Mesh", "M", DataType::Mesh)
        .doc("The mesh. B-reps, surfaces and boxes are meshed with the default parameters.")
}

/// Mesh Area \[MArea\]: the area and area centroid of a mesh.
pub fn mesh_area() -> NodeType {
    mesh_node(MESH_AREA, "Mesh Area", "MArea", "Analysis")
        .description(
            "Solves the area of a mesh (the sum of its triangles' areas, quads split along \
             their first diagonal) and the centroid of that area. A mesh without area is an \
             error.",
        )
        .input(mesh_input())
        .output(Port::new("Area", "A", DataType::Number).doc("The area, in square model units."))
        .output(Port::new("Centroid", "C", DataType::Point).doc("The area centroid."))
        .solve(|s| {
            let m = mesh_item(s, 0)?;
            let c = m
                .area_centroid()
                .ok_or_else(|| NodeError::from("the mesh has no area"))?;
            s.set(0, m.area());
            s.set(1, c);
            Ok(())
        })
}

/// Mesh Volume \[MVolume\]: the volume and volume centroid of a closed mesh.
pub fn mesh_volume() -> NodeType {
    mesh_node(MESH_VOLUME, "Mesh Volume", "MVolume", "Analysis")
        .description(
            "Solves the volume enclosed by a closed mesh (by the divergence theorem over its \
             triangles; positive when the faces point out) and the centroid of that volume. \
             An open mesh (with naked edges) has no volume and is an error, as in \
             Grasshopper.",
        )
        .input(mesh_input())
        .output(Port::new("Volume", "V", DataType::Number).doc("The volume, in cubic model units."))
        .output(Port::new("Centroid", "C", DataType::Point).doc("The volume centroid."))
        .solve(|s| {
            let m = mesh_item(s, 0)?;
            let naked = m.naked_edge_count();
            if m.is_empty() || naked > 0 {
                return Err(format!(
                    "the mesh is not closed ({naked} naked edges), so it has no volume"
                )
                .into());
            }
            let c = m
                .volume_centroid()
                .ok_or_else(|| NodeError::from("the mesh encloses no volume"))?;
            s.set(0, m.volume());
            s.set(1, c);
            Ok(())
        })
}

/// The centre (mean of the corners) of each face.
fn face_centres(m: &Mesh) -> Vec<Point3> {
    let v = m.vertices();
    m.faces()
        .iter()
        .map(|f| {
            let c = f.corners();
            let sum = c
                .iter()
                .fold(Vector3::ZERO, |s, &i| s + v[i as usize].to_vector());
            Point3::from_vector(sum / c.len() as f64)
        })
        .collect()
}

/// Face Normals \[FaceNormals\]: the centre and normal of every face.
pub fn face_normals() -> NodeType {
    mesh_node(FACE_NORMALS, "Face Normals", "FaceNormals", "Analysis")
        .description(
            "Extracts the centre (mean of its corners) and the unit normal (Newell's normal, \
             so non-planar quads get their average) of every face of a mesh, in face order. \
             A face of zero area has a null normal and a warning.",
        )
        .input(mesh_input())
        .output(
            Port::new("Centers", "C", DataType::Point)
                .list()
                .doc("The face centres."),
        )
        .output(
            Port::new("Normals", "N", DataType::Vector)
                .list()
                .doc("The face normals."),
        )
        .solve(|s| {
            let m: Shared<Mesh> = mesh_item(s, 0)?;
            s.set_list(0, face_centres(&m));
            let normals = m.face_normals();
            let degenerate = normals.iter().filter(|n| n.is_none()).count();
            if degenerate > 0 {
                s.warning(format!("{degenerate} faces have zero area and no normal"));
            }
            s.set_list_values(
                1,
                normals
                    .into_iter()
                    .map(|n| n.map(locus_runtime::Value::Vector))
                    .collect(),
            );
            Ok(())
        })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_support::{assert_clean, assert_error, only, points, vectors};
    use locus_kernel::MeshFace;
    use locus_runtime::{DataTree, NodeCall, Value};

    fn mesh(m: Mesh) -> DataTree {
        DataTree::from_value(Value::Mesh(Shared::new(m)))
    }

    fn square() -> Mesh {
        let p = |x: f64, y: f64| Point3::new(x, y, 0.0);
        Mesh::new(
            vec![p(0.0, 0.0), p(2.0, 0.0), p(2.0, 2.0), p(0.0, 2.0)],
            vec![MeshFace::quad(0, 1, 2, 3)],
        )
        .unwrap()
    }

    #[test]
    fn area_and_centroid_of_a_square() {
        let r = NodeCall::new(&mesh_area()).input(mesh(square())).run();
        assert_clean(&r);
        assert_eq!(only::<f64>(&r, 0), 4.0);
        assert_eq!(only::<Point3>(&r, 1), Point3::new(1.0, 1.0, 0.0));
        let r = NodeCall::new(&mesh_area())
            .input(mesh(Mesh::default()))
            .run();
        assert_error(&r, "no area");
    }

    #[test]
    fn volume_needs_a_closed_mesh() {
        let r = NodeCall::new(&mesh_volume()).input(mesh(square())).run();
        assert_error(&r, "not closed");
        let b = locus_kernel::OrientedBox::new(
            locus_kernel::Plane::WORLD_XY,
            locus_kernel::Interval::new(0.0, 1.0),
            locus_kernel::Interval::new(0.0, 2.0),
            locus_kernel::Interval::new(0.0, 3.0),
        );
        // A box wired into the Mesh port is meshed first.
        let r = NodeCall::new(&mesh_volume())
            .input(DataTree::from_value(Value::Box(b)))
            .run();
        assert_clean(&r);
        assert!((only::<f64>(&r, 0) - 6.0).abs() < 1e-12);
        assert!(only::<Point3>(&r, 1).distance(Point3::new(0.5, 1.0, 1.5)) < 1e-12);
    }

    #[test]
    fn face_normals_of_a_square() {
        let r = NodeCall::new(&face_normals()).input(mesh(square())).run();
        assert_clean(&r);
        assert_eq!(points(&r.outputs[0]), vec![Point3::new(1.0, 1.0, 0.0)]);
        assert_eq!(vectors(&r.outputs[1]), vec![Vector3::Z]);
    }
}

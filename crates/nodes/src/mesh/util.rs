//! Mesh › Util: Flip Mesh and Mesh Join.

use locus_kernel::Mesh;
use locus_runtime::{DataType, NodeRegistry, NodeType, Port, Shared};

use super::{mesh_item, mesh_node};

/// Id of [`flip_mesh`].
pub const FLIP_MESH: &str = "mesh.flip_mesh";
/// Id of [`mesh_join`].
pub const MESH_JOIN: &str = "mesh.mesh_join";

/// Registers Flip Mesh and Mesh Join.
pub fn register(registry: &mut NodeRegistry) {
    registry.register(flip_mesh());
    registry.register(mesh_join());
}

/// Flip Mesh \[FlipM\]: a mesh with every face reversed.
pub fn flip_mesh() -> NodeType {
    mesh_node(FLIP_MESH, "Flip Mesh", "FlipM", "Util")
        .gh_guid("47fbc929-e88a-4a13-882e-dad84763256d")
        .description(
            "Flips the normals of a mesh: every face's vertex order is reversed and every \
             vertex normal negated, so a closed mesh's volume changes sign.",
        )
        .input(Port::new("Mesh", "M", DataType::Mesh).doc("The mesh to flip."))
        .output(Port::new("Mesh", "M", DataType::Mesh).doc("The flipped mesh."))
        .solve(|s| {
            let m = mesh_item(s, 0)?;
            s.set(0, Shared::new(m.flipped()));
            Ok(())
        })
}

/// Mesh Join \[MJoin\]: one mesh of a list of meshes.
pub fn mesh_join() -> NodeType {
    mesh_node(MESH_JOIN, "Mesh Join", "MJoin", "Util")
        .gh_guid("4bc9dbbf-fec8-4348-a3af-e33e7edc8e7b")
        .description(
            "Joins a list of meshes into one mesh: the vertices and faces of each follow \
             those of the meshes before it (vertices are not welded). Vertex normals and \
             colours are kept only when every mesh has them. Nulls are skipped.",
        )
        .input(
            Port::new("Meshes", "M", DataType::Mesh)
                .list()
                .doc("The meshes to join."),
        )
        .output(Port::new("Mesh", "M", DataType::Mesh).doc("The joined mesh."))
        .solve(|s| {
            let meshes = s.list::<Shared<Mesh>>(0)?;
            let mut joined: Option<Mesh> = None;
            for m in meshes.present() {
                match &mut joined {
                    None => joined = Some((**m).clone()),
                    Some(j) => j.append(m),
                }
            }
            s.set(0, Shared::new(joined.unwrap_or_default()));
            Ok(())
        })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_support::{assert_clean, only};
    use locus_kernel::{MeshFace, Point3};
    use locus_runtime::{Branch, DataTree, NodeCall, TreePath, Value};

    fn triangle(z: f64) -> Mesh {
        let p = |x: f64, y: f64| Point3::new(x, y, z);
        Mesh::new(
            vec![p(0.0, 0.0), p(1.0, 0.0), p(0.0, 1.0)],
            vec![MeshFace::triangle(0, 1, 2)],
        )
        .unwrap()
    }

    #[test]
    fn flip_reverses_faces() {
        let r = NodeCall::new(&flip_mesh())
            .input(DataTree::from_value(Value::Mesh(Shared::new(triangle(
                0.0,
            )))))
            .run();
        assert_clean(&r);
        let m = only::<Shared<Mesh>>(&r, 0);
        assert_eq!(m.faces()[0], MeshFace::triangle(0, 2, 1));
        // Not a mesh: an error.
        let r = NodeCall::new(&flip_mesh())
            .input(DataTree::from_value(Value::Text("no".into())))
            .run();
        assert!(!r.messages.is_empty());
    }

    #[test]
    fn join_appends_and_skips_nulls() {
        let mut branch = Branch::new(DataType::Mesh);
        branch.push_option(Some(Value::Mesh(Shared::new(triangle(0.0)))));
        branch.push_option(None);
        branch.push_option(Some(Value::Mesh(Shared::new(triangle(1.0)))));
        let mut tree = DataTree::new();
        tree.insert(TreePath::zero(), branch);
        let r = NodeCall::new(&mesh_join()).input(tree).run();
        let m = only::<Shared<Mesh>>(&r, 0);
        assert_eq!(m.vertices().len(), 6);
        assert_eq!(m.faces()[1], MeshFace::triangle(3, 4, 5));
        let r = NodeCall::new(&mesh_join()).input(DataTree::new()).run();
        let _ = r;
    }
}

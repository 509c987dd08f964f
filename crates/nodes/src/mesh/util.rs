//! Mesh › Util: Flip Mesh, Mesh Join, Weld Mesh and Unweld Mesh.

use locus_kernel::Mesh;
use locus_runtime::{DataType, NodeError, NodeRegistry, NodeType, Port, Shared, Solve};

use super::{mesh_item, mesh_node};

/// Id of [`flip_mesh`].
pub const FLIP_MESH: &str = "mesh.flip_mesh";
/// Id of [`mesh_join`].
pub const MESH_JOIN: &str = "mesh.mesh_join";
/// Id of [`weld_mesh`].
pub const WELD_MESH: &str = "mesh.weld_mesh";
/// Id of [`unweld_mesh`].
pub const UNWELD_MESH: &str = "mesh.unweld_mesh";

/// Registers Flip Mesh, Mesh Join, Weld Mesh and Unweld Mesh.
pub fn register(registry: &mut NodeRegistry) {
    registry.register(flip_mesh());
    registry.register(mesh_join());
    registry.register(weld_mesh());
    registry.register(unweld_mesh());
}

/// The angle input of Weld and Unweld, in radians.
fn weld_angle(s: &Solve<'_>, input: usize) -> Result<f64, NodeError> {
    let angle = *s.item::<f64>(input)?;
    if angle.is_nan() || angle < 0.0 {
        return Err(format!("the angle must be 0 or more, got {angle}").into());
    }
    Ok(angle)
}

/// Weld Mesh \[Weld\]: coincident vertices merged where the faces agree.
pub fn weld_mesh() -> NodeType {
    mesh_node(WELD_MESH, "Weld Mesh", "Weld", "Util")
        .gh_guid("9f6d85c9-1143-4538-bca7-69dcb11a74ef")
        .description(
            "Welds the creases of a mesh: vertices at one point (within WELD_DISTANCE = 1e-9) \
             become one vertex where the normals of the faces that use them differ by at most \
             the angle, so edges sharper than the angle stay creased. Faces left with a \
             repeated vertex are removed. Vertex colours are kept and vertex normals, when \
             the mesh has them, computed again.",
        )
        .input(Port::new("Mesh", "M", DataType::Mesh).doc("The mesh to weld."))
        .input(
            Port::new("Angle", "A", DataType::Number)
                .default_value(std::f64::consts::PI)
                .doc("The largest angle between face normals to weld across, in radians (default π: every coincident vertex)."),
        )
        .output(Port::new("Result", "R", DataType::Mesh).doc("The welded mesh."))
        .solve(|s| {
            let m = mesh_item(s, 0)?;
            let angle = weld_angle(s, 1)?;
            s.set(0, Shared::new(m.welded(angle)));
            Ok(())
        })
}

/// Unweld Mesh \[Unweld\]: vertices split along sharp edges.
pub fn unweld_mesh() -> NodeType {
    mesh_node(UNWELD_MESH, "Unweld Mesh", "Unweld", "Util")
        .description(
            "Unwelds the edges of a mesh whose two faces' normals differ by more than the \
             angle: each vertex is split into one vertex per fan of faces around it joined \
             across gentler edges, so that sharp edges shade as creases. Vertex colours are \
             kept and vertex normals, when the mesh has them, computed again. Its \
             Grasshopper GUID is not in the project's table, so files cannot name it yet.",
        )
        .input(Port::new("Mesh", "M", DataType::Mesh).doc("The mesh to unweld."))
        .input(
            Port::new("Angle", "A", DataType::Number)
                .default_value(0.0)
                .doc("The largest angle between face normals that stays welded, in radians (default 0: only flat edges)."),
        )
        .output(Port::new("Result", "R", DataType::Mesh).doc("The unwelded mesh."))
        .solve(|s| {
            let m = mesh_item(s, 0)?;
            let angle = weld_angle(s, 1)?;
            s.set(0, Shared::new(m.unwelded(angle)));
            Ok(())
        })
}

/// Flip Mesh \[FlipM\]: a mesh with its faces reversed and its vertex normals negated.
pub fn flip_mesh() -> NodeType {
    let flag = |name: &str, nickname: &str, doc: &str| {
        Port::new(name, nickname, DataType::Boolean)
            .default_value(true)
            .doc(doc)
    };
    mesh_node(FLIP_MESH, "Flip Mesh", "FlipM", "Util")
        .gh_guid("47fbc929-e88a-4a13-882e-dad84763256d")
        .description(
            "Flips the normals of a mesh, as Rhino's Mesh.Flip: Vertex Normals negates the \
             stored vertex normals, Face Orientation reverses every face's vertex order (so a \
             closed mesh's volume changes sign). locus derives face normals from the face \
             orientation, so Face Normals follows Face Orientation; a different choice is \
             reported.",
        )
        .input(Port::new("Mesh", "M", DataType::Mesh).doc("The mesh to flip."))
        .input(flag("Vertex Normals", "Vn", "Negate the vertex normals."))
        .input(flag(
            "Face Normals",
            "Fn",
            "Flip the face normals (they follow Fo in locus).",
        ))
        .input(flag(
            "Face Orientation",
            "Fo",
            "Reverse the vertex order of every face.",
        ))
        .output(Port::new("Result", "R", DataType::Mesh).doc("The flipped mesh."))
        .solve(|s| {
            let m = mesh_item(s, 0)?;
            let (normals, faces, orientation) = (
                *s.item::<bool>(1)?,
                *s.item::<bool>(2)?,
                *s.item::<bool>(3)?,
            );
            if faces != orientation {
                s.warning(format!(
                    "Face Normals is {faces} but Face Orientation is {orientation}: locus \
                     derives face normals from the orientation, so they follow Fo"
                ));
            }
            s.set(0, Shared::new(m.flipped_parts(normals, orientation)));
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
    use crate::test_support::{assert_clean, assert_error, only};
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
    fn flip_can_keep_the_faces_or_the_normals() {
        let mesh = || {
            let m = triangle(0.0).with_computed_normals();
            DataTree::from_value(Value::Mesh(Shared::new(m)))
        };
        let flag = |b: bool| DataTree::from_value(Value::Boolean(b));
        // Vertex normals only: the faces keep their order, the normals point down.
        let r = NodeCall::new(&flip_mesh())
            .input(mesh())
            .input(flag(true))
            .input(flag(false))
            .input(flag(false))
            .run();
        assert_clean(&r);
        let m = only::<Shared<Mesh>>(&r, 0);
        assert_eq!(m.faces()[0], MeshFace::triangle(0, 1, 2));
        assert!(m.normals().unwrap().iter().all(|n| n.z == -1.0));
        // Orientation only: faces reversed, normals kept.
        let r = NodeCall::new(&flip_mesh())
            .input(mesh())
            .input(flag(false))
            .input(flag(true))
            .input(flag(true))
            .run();
        assert_clean(&r);
        let m = only::<Shared<Mesh>>(&r, 0);
        assert_eq!(m.faces()[0], MeshFace::triangle(0, 2, 1));
        assert!(m.normals().unwrap().iter().all(|n| n.z == 1.0));
        // Face normals without the orientation: done as Fo says, with a warning.
        let r = NodeCall::new(&flip_mesh())
            .input(mesh())
            .input(flag(true))
            .input(flag(true))
            .input(flag(false))
            .run();
        assert_eq!(r.messages.len(), 1, "{:?}", r.messages);
        assert!(r.messages[0].text.contains("follow Fo"));
        assert_eq!(
            only::<Shared<Mesh>>(&r, 0).faces()[0],
            MeshFace::triangle(0, 1, 2)
        );
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

    /// Two triangles at a right angle sharing the edge (0,0,0)–(1,0,0), each with its own
    /// vertices.
    fn hinge() -> Mesh {
        let p = Point3::new;
        Mesh::new(
            vec![
                p(0.0, 0.0, 0.0),
                p(1.0, 0.0, 0.0),
                p(0.0, 1.0, 0.0),
                p(1.0, 0.0, 0.0),
                p(0.0, 0.0, 0.0),
                p(0.0, 0.0, 1.0),
            ],
            vec![MeshFace::triangle(0, 1, 2), MeshFace::triangle(3, 4, 5)],
        )
        .unwrap()
    }

    fn weld(node: &NodeType, m: Mesh, angle: f64) -> locus_runtime::NodeCallResult {
        NodeCall::new(node)
            .input(DataTree::from_value(Value::Mesh(Shared::new(m))))
            .input(DataTree::from_value(Value::Number(angle)))
            .run()
    }

    #[test]
    fn weld_and_unweld_follow_the_angle() {
        // The faces' normals (Z and Y) are 90° apart.
        let r = weld(&weld_mesh(), hinge(), std::f64::consts::PI);
        assert_clean(&r);
        let welded = only::<Shared<Mesh>>(&r, 0);
        assert_eq!(welded.vertices().len(), 4);
        assert_eq!(welded.faces()[1], MeshFace::triangle(1, 0, 3));
        let r = weld(&weld_mesh(), hinge(), 1.0);
        assert_eq!(only::<Shared<Mesh>>(&r, 0).vertices().len(), 6);
        let r = weld(&unweld_mesh(), (*welded).clone(), 1.0);
        assert_eq!(only::<Shared<Mesh>>(&r, 0).vertices().len(), 6);
        let r = weld(&unweld_mesh(), (*welded).clone(), 2.0);
        assert_eq!(only::<Shared<Mesh>>(&r, 0).vertices().len(), 4);
        assert_error(&weld(&weld_mesh(), hinge(), -1.0), "0 or more");
        assert_error(&weld(&unweld_mesh(), hinge(), f64::NAN), "0 or more");
    }
}

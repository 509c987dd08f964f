//! Mesh › Analysis: Mesh Edges, a mesh's edges as lines sorted by how many faces use them.
//!
//! The edges are the kernel's topological edges ([`locus_kernel::Mesh::topology_edges`]):
//! vertices at the same point count as one, as Rhino's topology vertices do, so an unwelded
//! mesh has the same edges as the welded one. Each list keeps the order in which the faces
//! first use the edges.

use locus_kernel::Line;
use locus_runtime::{DataType, NodeRegistry, NodeType, Port};

use super::{mesh_item, mesh_node};

/// Id of [`mesh_edges`].
pub const MESH_EDGES: &str = "mesh.mesh_edges";

/// Registers Mesh Edges.
pub fn register(registry: &mut NodeRegistry) {
    registry.register(mesh_edges());
}

/// Mesh Edges \[MEdges\]: naked, interior and non-manifold edges.
pub fn mesh_edges() -> NodeType {
    mesh_node(MESH_EDGES, "Mesh Edges", "MEdges", "Analysis")
        .gh_guid("2b9bf01d-5fe5-464c-b0b3-b469eb5f2efb")
        .description(
            "Gets the edges of a mesh as lines: naked edges (used by one face), interior edges \
             (two faces) and non-manifold edges (three or more). Vertices at the same point \
             count as one.",
        )
        .input(
            Port::new("Mesh", "M", DataType::Mesh).doc(
                "The mesh. B-reps, surfaces and boxes are meshed with the default parameters.",
            ),
        )
        .output(
            Port::new("Naked Edges", "E1", DataType::Line)
                .list()
                .doc("The edges used by one face only."),
        )
        .output(
            Port::new("Interior Edges", "E2", DataType::Line)
                .list()
                .doc("The edges shared by two faces."),
        )
        .output(
            Port::new("Non-Manifold Edges", "E3", DataType::Line)
                .list()
                .doc("The edges shared by three faces or more."),
        )
        .solve(|s| {
            let mesh = mesh_item(s, 0)?;
            let mut lists: [Vec<Line>; 3] = Default::default();
            for edge in mesh.topology_edges() {
                lists[edge.valence.clamp(1, 3) - 1].push(edge.line);
            }
            let [naked, interior, non_manifold] = lists;
            s.set_list(0, naked);
            s.set_list(1, interior);
            s.set_list(2, non_manifold);
            Ok(())
        })
}

#[cfg(test)]
mod tests {
    use locus_kernel::{Mesh, MeshFace, Point3};
    use locus_runtime::{DataTree, NodeCall, Shared};

    use super::*;
    use crate::test_support::{all, assert_clean};

    #[test]
    fn a_two_quad_strip_has_six_naked_edges_and_one_interior() {
        let p = |x: f64, y: f64| Point3::new(x, y, 0.0);
        let mesh = Mesh::new(
            vec![
                p(0.0, 0.0),
                p(1.0, 0.0),
                p(2.0, 0.0),
                p(0.0, 1.0),
                p(1.0, 1.0),
                p(2.0, 1.0),
            ],
            vec![MeshFace::quad(0, 1, 4, 3), MeshFace::quad(1, 2, 5, 4)],
        )
        .unwrap();
        let r = NodeCall::new(&mesh_edges())
            .input(DataTree::from_item(Shared::new(mesh)))
            .run();
        assert_clean(&r);
        let naked: Vec<Line> = all(&r.outputs[0]);
        let interior: Vec<Line> = all(&r.outputs[1]);
        assert_eq!(naked.len(), 6);
        assert_eq!(interior, [Line::new(p(1.0, 0.0), p(1.0, 1.0))]);
        assert_eq!(r.outputs[2].item_count(), 0);
        assert_eq!(naked[0], Line::new(p(0.0, 0.0), p(1.0, 0.0)));
    }
}

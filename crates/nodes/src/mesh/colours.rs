//! Mesh › Primitive: Mesh Colours, a repeating pattern of vertex colours.

use locus_kernel::{Color, Mesh};
use locus_runtime::{DataType, NodeError, NodeRegistry, NodeType, Port, Shared};

use super::{mesh_item, mesh_node};

/// Id of [`mesh_colours`].
pub const MESH_COLOURS: &str = "mesh.mesh_colours";

/// Registers Mesh Colours.
pub fn register(registry: &mut NodeRegistry) {
    registry.register(mesh_colours());
}

/// Mesh Colours \[MCol\]: a mesh with vertex colours.
pub fn mesh_colours() -> NodeType {
    mesh_node(MESH_COLOURS, "Mesh Colours", "MCol", "Primitive")
        .gh_guid("d2cedf38-1149-4adc-8dbf-b06571cb5106")
        .description(
            "Assigns a repeating colour pattern to a mesh: vertex i gets colour i modulo the \
             number of colours, replacing any colours it had. Nulls in the list are skipped; \
             an empty list is an error.",
        )
        .input(
            Port::new("Mesh", "M", DataType::Mesh).doc(
                "The mesh. B-reps, surfaces and boxes are meshed with the default parameters.",
            ),
        )
        .input(
            Port::new("Colours", "C", DataType::Colour)
                .list()
                .doc("The colours, repeated over the vertices in order."),
        )
        .output(Port::new("Mesh", "M", DataType::Mesh).doc("The coloured mesh."))
        .solve(|s| {
            let mesh = mesh_item(s, 0)?;
            let colours: Vec<Color> = s.list::<Color>(1)?.present().copied().collect();
            if colours.is_empty() {
                return Err(NodeError("colours C has no colour".into()));
            }
            let n = mesh.vertices().len();
            let pattern = (0..n).map(|i| colours[i % colours.len()]).collect();
            let coloured: Mesh = (*mesh).clone().with_colors(pattern)?;
            s.set(0, Shared::new(coloured));
            Ok(())
        })
}

#[cfg(test)]
mod tests {
    use locus_kernel::{MeshFace, Point3};
    use locus_runtime::{DataTree, NodeCall};

    use super::*;
    use crate::test_support::only;

    fn triangle() -> DataTree {
        let mesh = Mesh::new(
            vec![
                Point3::ORIGIN,
                Point3::new(1.0, 0.0, 0.0),
                Point3::new(0.0, 1.0, 0.0),
            ],
            vec![MeshFace::triangle(0, 1, 2)],
        )
        .unwrap();
        DataTree::from_item(Shared::new(mesh))
    }

    #[test]
    fn colours_repeat_over_the_vertices() {
        let (red, blue) = (Color::rgb(255, 0, 0), Color::rgb(0, 0, 255));
        let r = NodeCall::new(&mesh_colours())
            .input(triangle())
            .input(DataTree::from_list(vec![red, blue]))
            .run();
        let m = only::<Shared<Mesh>>(&r, 0);
        assert_eq!(m.colors(), Some(&[red, blue, red][..]));
        let r = NodeCall::new(&mesh_colours())
            .input(triangle())
            .input(DataTree::from_list(Vec::<Color>::new()))
            .run();
        // An empty list is no data: the node leaves its output empty, or reports why.
        assert!(r.outputs[0].values().all(|v| v.is_none()) || !r.messages.is_empty());
    }
}

//! Params › Geometry › Mesh and Params › Primitive › Colour: containers of meshes and colours.
//!
//! - **Mesh** takes meshes, and B-reps, surfaces and boxes meshed with the kernel's default
//!   meshing parameters (as Grasshopper's Mesh parameter meshes what is wired into it).
//! - **Colour** takes colours, texts `#RRGGBB`, `#AARRGGBB`, `R,G,B` or `A,R,G,B`, and ARGB
//!   integers.

use locus_runtime::{DataType, NodeRegistry, NodeType, Port, Solve, cast_value};

/// Id of [`mesh`].
pub const MESH: &str = "params.mesh";
/// Id of [`colour`].
pub const COLOUR: &str = "params.colour";

/// Registers the Mesh and Colour parameters.
pub fn register(registry: &mut NodeRegistry) {
    registry.register(mesh());
    registry.register(colour());
}

/// Passes the branch through, casting items the runtime has not cast (a branch given to the
/// node directly); failures are errors naming the item and become nulls.
fn pass_cast(s: &mut Solve<'_>, to: DataType) {
    let Some(branch) = s.branch(0) else {
        return;
    };
    if branch.data_type() == to || branch.is_empty() {
        let branch = branch.clone();
        s.set_branch(0, branch);
        return;
    }
    let mut out = Vec::with_capacity(branch.len());
    let mut errors = Vec::new();
    for (i, value) in branch.values().enumerate() {
        match value.map(|v| cast_value(&v, to)) {
            None => out.push(None),
            Some(Ok(v)) => out.push(Some(v)),
            Some(Err(e)) => {
                errors.push(format!("{e} (item {i})"));
                out.push(None);
            }
        }
    }
    for e in errors {
        s.error(e);
    }
    s.set_list_values(0, out);
}

/// Mesh \[Mesh\]: a container of meshes.
pub fn mesh() -> NodeType {
    NodeType::new(MESH, "Mesh", "Mesh", "Params")
        .subcategory("Geometry")
        .gh_guid("1e936df3-0eea-4246-8549-514cb8862b7a")
        .description(
            "Contains a collection of polygon meshes. A parameter passes its data through \
             unchanged (paths, empty branches and nulls included) after casting every item to \
             its type; a graph uses it to declare a named input. Meshes pass as they are; \
             B-reps, surfaces and boxes are meshed with the default meshing parameters \
             (closed B-reps give closed meshes). Items that do not cast are errors and \
             become null.",
        )
        .input(Port::new("Mesh", "Mesh", DataType::Mesh).list().doc(
            "The meshes, given in the graph or wired in: meshes, B-reps, surfaces or boxes. \
             No default; a parameter without data warns that it failed to collect data.",
        ))
        .output(
            Port::new("Mesh", "Mesh", DataType::Mesh)
                .list()
                .doc("The same meshes, cast."),
        )
        .solve(|s| {
            pass_cast(s, DataType::Mesh);
            Ok(())
        })
}

/// Colour \[Col\]: a container of colours.
pub fn colour() -> NodeType {
    NodeType::new(COLOUR, "Colour", "Col", "Params")
        .subcategory("Primitive")
        .gh_guid("203a91c3-287a-43b6-a9c5-ebb96240a650")
        .description(
            "Contains a collection of colours (red, green, blue and alpha, 0 to 255 each). A \
             parameter passes its data through unchanged after casting every item to its \
             type. Texts `#RRGGBB`, `#AARRGGBB`, `R,G,B` and `A,R,G,B` and ARGB integers (as \
             .NET's Color.ToArgb) become colours; other items are errors and become null.",
        )
        .input(Port::new("Colour", "Col", DataType::Colour).list().doc(
            "The colours, given in the graph or wired in. No default; a parameter without data \
             warns that it failed to collect data.",
        ))
        .output(
            Port::new("Colour", "Col", DataType::Colour)
                .list()
                .doc("The same colours, cast."),
        )
        .solve(|s| {
            pass_cast(s, DataType::Colour);
            Ok(())
        })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_support::{assert_clean, assert_error, only};
    use locus_kernel::Color;
    use locus_runtime::{DataTree, NodeCall, Value};

    #[test]
    fn colours_cast_from_text_and_bad_text_is_an_error() {
        let r = NodeCall::new(&colour())
            .input(DataTree::from_value(Value::Colour(Color::rgb(1, 2, 3))))
            .run();
        assert_clean(&r);
        assert_eq!(only::<Color>(&r, 0), Color::rgb(1, 2, 3));
        let r = NodeCall::new(&colour())
            .input(DataTree::from_value(Value::Text("#FF0000".into())))
            .run();
        assert_eq!(only::<Color>(&r, 0), Color::rgb(255, 0, 0));
        let r = NodeCall::new(&colour())
            .input(DataTree::from_value(Value::Text("teal-ish".into())))
            .run();
        assert_error(&r, "Colour");
    }

    #[test]
    fn breps_become_meshes() {
        let b = locus_kernel::OrientedBox::new(
            locus_kernel::Plane::WORLD_XY,
            locus_kernel::Interval::UNIT,
            locus_kernel::Interval::UNIT,
            locus_kernel::Interval::UNIT,
        );
        let r = NodeCall::new(&mesh())
            .input(DataTree::from_value(Value::Box(b)))
            .run();
        let m = only::<locus_runtime::Shared<locus_kernel::Mesh>>(&r, 0);
        assert!(m.is_closed_and_oriented());
        let r = NodeCall::new(&mesh())
            .input(DataTree::from_value(Value::Number(3.0)))
            .run();
        assert_error(&r, "Mesh");
    }
}

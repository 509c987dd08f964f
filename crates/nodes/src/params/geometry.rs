//! Params › Geometry: the Point, Vector and Plane containers.
//!
//! A container has one list input and one list output of its type, both named after the type
//! with Grasshopper's nickname. It passes each branch through unchanged, nulls included; what
//! it adds is the cast of incoming data to its type (a point into a Vector container becomes
//! its position vector, and so on), which the runtime does on the way in.

use locus_runtime::{DataType, NodeRegistry, NodeType, Port};

/// Id of [`point`].
pub const POINT: &str = "params.point";
/// Id of [`vector`].
pub const VECTOR: &str = "params.vector";
/// Id of [`plane`].
pub const PLANE: &str = "params.plane";

/// Registers the geometry containers.
pub fn register(registry: &mut NodeRegistry) {
    for t in [point(), vector(), plane()] {
        registry.register(t);
    }
}

/// A container node for `data_type`, named `name` with nickname `nickname`.
fn container(id: &str, name: &str, nickname: &str, data_type: DataType, what: &str) -> NodeType {
    NodeType::new(id, name, nickname, "Params")
        .subcategory("Geometry")
        .description(&format!(
            "Contains a collection of {what}. Data flowing in is cast to {what}; items that \
             cannot be cast become nulls with an error. Branches and nulls pass through \
             unchanged."
        ))
        .input(
            Port::new(name, nickname, data_type)
                .doc(&format!(
                    "The {what} to hold, given in the graph or wired in (a list per branch). No \
                     default; a container without data warns that it failed to collect data."
                ))
                .list(),
        )
        .output(
            Port::new(name, nickname, data_type)
                .doc(&format!("The same {what}, branch by branch."))
                .list(),
        )
        .solve(|s| {
            if let Some(branch) = s.branch(0) {
                let branch = branch.clone();
                s.set_branch(0, branch);
            }
            Ok(())
        })
}

/// Point \[Pt\]: a container of points.
pub fn point() -> NodeType {
    container(POINT, "Point", "Pt", DataType::Point, "points")
        .gh_guid("fbac3e32-f100-4292-8692-77240a42fd1a")
}

/// Vector \[Vec\]: a container of vectors.
pub fn vector() -> NodeType {
    container(VECTOR, "Vector", "Vec", DataType::Vector, "vectors")
        .gh_guid("16ef3e75-e315-4899-b531-d3166b42dac9")
}

/// Plane \[Pln\]: a container of planes.
pub fn plane() -> NodeType {
    container(PLANE, "Plane", "Pln", DataType::Plane, "planes")
        .gh_guid("4f8984c4-7c7a-4d69-b0a2-183cbb330d20")
}

#[cfg(test)]
mod tests {
    use locus_kernel::{Plane, Point3, Vector3};
    use locus_runtime::{Branch, DataTree, Level, NodeCall, TreePath, Value};

    use super::*;
    use crate::vector::test_support::{assert_clean, items, messages};

    #[test]
    fn containers_pass_branches_through() {
        let mut tree = DataTree::new();
        let mut b = Branch::new(DataType::Point);
        b.push(Point3::new(1.0, 2.0, 3.0));
        b.push_null();
        b.push(Point3::ORIGIN);
        tree.insert(TreePath::new(vec![0, 2]), b);
        tree.insert(
            TreePath::new(vec![1]),
            Branch::from_items(vec![Point3::new(5.0, 5.0, 5.0)]),
        );
        let r = NodeCall::new(&point()).input(tree.clone()).run();
        assert_clean(&r);
        assert_eq!(r.outputs[0], tree);
        assert_eq!(
            items::<Point3>(&r.outputs[0]),
            vec![
                Some(Point3::new(1.0, 2.0, 3.0)),
                None,
                Some(Point3::ORIGIN),
                Some(Point3::new(5.0, 5.0, 5.0)),
            ]
        );
    }

    #[test]
    fn vector_and_plane_containers() {
        let vectors = DataTree::from_list(vec![Vector3::X, Vector3::Z]);
        let r = NodeCall::new(&vector()).input(vectors.clone()).run();
        assert_eq!(r.outputs[0], vectors);
        let planes = DataTree::from_list(vec![Plane::WORLD_XY, Plane::WORLD_YZ]);
        let r = NodeCall::new(&plane()).input(planes.clone()).run();
        assert_eq!(r.outputs[0], planes);
    }

    #[test]
    fn an_empty_container_warns_and_outputs_nothing() {
        let r = NodeCall::new(&point()).run();
        assert_eq!(messages(&r, Level::Warning).len(), 1, "{:?}", r.messages);
        assert!(messages(&r, Level::Error).is_empty());
        assert_eq!(r.outputs[0].item_count(), 0);
    }

    #[test]
    fn containers_cast_what_flows_in() {
        // Points into a Vector container become position vectors; text is parsed; what
        // cannot be cast becomes a null with an error.
        let mut b = Branch::new(DataType::Generic);
        b.push_value(Value::Point(Point3::new(1.0, 2.0, 3.0)));
        b.push_value(Value::Text("4, 5, 6".into()));
        b.push_value(Value::Number(1.0));
        let mut tree = DataTree::new();
        tree.insert(TreePath::zero(), b);
        let r = NodeCall::new(&vector()).input(tree).run();
        assert_eq!(
            items::<Vector3>(&r.outputs[0]),
            vec![
                Some(Vector3::new(1.0, 2.0, 3.0)),
                Some(Vector3::new(4.0, 5.0, 6.0)),
                None
            ]
        );
        assert_eq!(messages(&r, Level::Error).len(), 1, "{:?}", r.messages);
        // A point into a Plane container is the XY plane through it.
        let r = NodeCall::new(&plane())
            .input(DataTree::from_item(Point3::new(1.0, 2.0, 3.0)))
            .run();
        assert_eq!(
            items::<Plane>(&r.outputs[0]),
            vec![Some(
                Plane::WORLD_XY.translated(Vector3::new(1.0, 2.0, 3.0))
            )]
        );
    }

    #[test]
    fn ports_are_named_after_the_type() {
        for (node, name, nickname) in [
            (point(), "Point", "Pt"),
            (vector(), "Vector", "Vec"),
            (plane(), "Plane", "Pln"),
        ] {
            assert_eq!(
                (
                    node.inputs[0].name.as_str(),
                    node.inputs[0].nickname.as_str()
                ),
                (name, nickname)
            );
            assert_eq!(
                (
                    node.outputs[0].name.as_str(),
                    node.outputs[0].nickname.as_str()
                ),
                (name, nickname)
            );
            assert_eq!(node.inputs[0].access, locus_runtime::Access::List);
        }
    }
}

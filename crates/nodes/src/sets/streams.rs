//! Sets › Tree, combining and taking apart trees: Merge, Entwine, Explode Tree, Tree Branch,
//! Tree Item and Tree Statistics.
//!
//! Merge and Entwine have a variable number of inputs, named by the graph
//! (`inputs: ["D1", "D2", "D3"]`); Explode Tree has a variable number of outputs, one per
//! branch it shows (`outputs: ["0", "1", "2"]`), and warns about branches it cannot show.

use locus_runtime::{DataTree, DataType, NodeError, NodeRegistry, NodeType, Port, TreePath, Value};

use super::tree::{tree_node, tree_port};
use super::{parse_path, pick_index};

/// Id of [`merge`].
pub const MERGE: &str = "sets.merge";
/// Id of [`entwine`].
pub const ENTWINE: &str = "sets.entwine";
/// Id of [`explode_tree`].
pub const EXPLODE_TREE: &str = "sets.explode_tree";
/// Id of [`tree_branch`].
pub const TREE_BRANCH: &str = "sets.tree_branch";
/// Id of [`tree_item`].
pub const TREE_ITEM: &str = "sets.tree_item";
/// Id of [`tree_statistics`].
pub const TREE_STATISTICS: &str = "sets.tree_statistics";

/// Registers the stream and tree access nodes.
pub fn register(registry: &mut NodeRegistry) {
    for t in [
        merge(),
        entwine(),
        explode_tree(),
        tree_branch(),
        tree_item(),
        tree_statistics(),
    ] {
        registry.register(t);
    }
}

/// Merge \[Merge\]: several trees merged branch by branch.
pub fn merge() -> NodeType {
    tree_node(MERGE, "Merge", "Merge")
        .gh_guid("3cadddef-1e2b-4c09-9390-0e8f78f7609f")
        .description(
            "Merges data streams into one tree: branches at a path that only one input has are \
             copied, and the items of branches at the same path are joined in input order \
             (D1's first). Inputs without data are skipped. The graph may name more inputs.",
        )
        .variable_inputs(
            Port::new("Data", "D", DataType::Generic)
                .tree()
                .optional()
                .doc("A data stream to merge, of any type; optional."),
            &["D1", "D2"],
        )
        .output(tree_port("Result", "R", "The merged tree."))
        .solve(|s| {
            let mut out = DataTree::new();
            for k in 0..s.input_count() {
                out.merge(s.tree(k)?);
            }
            s.set_tree(0, out);
            Ok(())
        })
}

/// Entwine \[Entwine\]: several trees side by side, input k under `{0;k}`.
pub fn entwine() -> NodeType {
    tree_node(ENTWINE, "Entwine", "Entwine")
        .gh_guid("c9785b8e-2f30-4f90-8ee3-cca710f82402")
        .description(
            "Combines data streams into one tree with a branch per input: the items of input k \
             (in path order) go to branch {0;k}. With the flatten setting off, the structure \
             of each input is kept instead: its branch {p} goes to {0;k;p}. Inputs without data \
             give no branch. The graph may name more inputs.",
        )
        .variable_inputs(
            Port::new("Branch", "{0;0}", DataType::Generic)
                .tree()
                .optional()
                .doc("A data stream to entwine, of any type; optional."),
            &["{0;0}", "{0;1}", "{0;2}"],
        )
        .output(tree_port("Result", "R", "The entwined tree."))
        .setting(
            "flatten",
            DataType::Boolean,
            Some(Value::Boolean(true)),
            "Whether each input is flattened into its branch {0;k} (Grasshopper's default \
             Flatten on Entwine's inputs); when false, input branch {p} goes to {0;k;p}. \
             Default true.",
        )
        .solve(|s| {
            let flatten = !matches!(s.setting("flatten"), Some(Value::Boolean(false)));
            let mut branches = Vec::new();
            for k in 0..s.input_count() {
                let input = s.tree(k)?;
                if input.is_empty() {
                    continue;
                }
                let k = u32::try_from(k).unwrap_or(u32::MAX);
                if flatten {
                    let mut t = input.clone();
                    t.flatten_to(TreePath::from([0, k]));
                    branches.extend(t.into_branches());
                } else {
                    for (path, branch) in input.branches() {
                        let mut indices = vec![0, k];
                        indices.extend_from_slice(path.indices());
                        branches.push((TreePath::new(indices), branch.clone()));
                    }
                }
            }
            s.set_tree(0, DataTree::from_branches(branches));
            Ok(())
        })
}

/// Explode Tree \[BANG!\]: each branch of a tree on an output of its own.
pub fn explode_tree() -> NodeType {
    tree_node(EXPLODE_TREE, "Explode Tree", "BANG!")
        .gh_guid("74cad441-2264-45fe-a57d-85034751208a")
        .description(
            "Extracts the branches of a tree: branch k (in path order) goes, at its path, to \
             output k. The outputs are variable, 0, 1, … as Grasshopper names them (two by \
             default; a graph adds one per branch it wants, as a Grasshopper user does by \
             zooming in on the component); a tree with more branches than outputs gives a \
             warning naming the branches left out. Outputs without a branch are empty.",
        )
        .input(tree_port("Data", "D", "The tree to explode, of any type."))
        .variable_outputs(
            tree_port(
                "Branch",
                "0",
                "The branch at this output's position (0, 1, …), at its path.",
            ),
            &["0", "1"],
        )
        .solve(|s| {
            let outputs = s.output_count();
            let tree = s.tree(0)?;
            let parts = tree.explode();
            let n = parts.len();
            for (k, part) in parts.into_iter().take(outputs).enumerate() {
                s.set_tree(k, part);
            }
            if n > outputs {
                s.warning(format!(
                    "the tree has {n} branches but the node has {outputs} outputs: \
                     branches {} to {} are left out",
                    tree.branches()[outputs].0,
                    tree.branches()[n - 1].0
                ));
            }
            Ok(())
        })
}

/// Tree Branch \[Branch\]: the branch of a tree at a path.
pub fn tree_branch() -> NodeType {
    tree_node(TREE_BRANCH, "Tree Branch", "Branch")
        .gh_guid("3a710c1e-1809-4e19-8c15-82adce31cd62")
        .description(
            "Retrieves the branch of a tree at path P, keeping its path. A path the tree does \
             not have is an error naming it.",
        )
        .input(tree_port("Tree", "T", "The tree, of any type."))
        .input(
            Port::new("Path", "P", DataType::Text)
                .doc("The path of the branch, written {0;1} (an integer n is {n})."),
        )
        .output(tree_port("Branch", "B", "The branch at P."))
        .solve(|s| {
            let path = parse_path(s.item::<String>(1)?, "P")?;
            let tree = s.tree(0)?;
            let branch = tree.branch(&path).ok_or_else(|| no_branch(&path))?;
            s.set_tree(0, DataTree::from_branches([(path, branch.clone())]));
            Ok(())
        })
}

fn no_branch(path: &TreePath) -> NodeError {
    NodeError(format!("the tree has no branch {path}"))
}

/// Tree Item \[Item\]: the item of a tree at a path and index.
pub fn tree_item() -> NodeType {
    tree_node(TREE_ITEM, "Tree Item", "Item")
        .gh_guid("c1ec65a3-bda4-4fad-87d0-edf86ed9d81c")
        .description(
            "Retrieves item i of the branch of a tree at path P. With Wrap, indices wrap around \
             the branch; without, an index outside it gives a null and a warning naming it. A \
             path the tree does not have is an error naming it; an empty branch gives a null.",
        )
        .input(tree_port("Tree", "T", "The tree, of any type."))
        .input(
            Port::new("Path", "P", DataType::Text)
                .doc("The path of the branch, written {0;1} (an integer n is {n})."),
        )
        .input(
            Port::new("Index", "i", DataType::Integer)
                .doc("The index of the item in the branch, from 0; default 0.")
                .default_value(0_i64),
        )
        .input(
            Port::new("Wrap", "W", DataType::Boolean)
                .doc("Whether indices wrap around the branch bounds; default true.")
                .default_value(true),
        )
        .output(Port::new("Element", "E", DataType::Generic).doc("The item at {P}(i)."))
        .solve(|s| {
            let path = parse_path(s.item::<String>(1)?, "P")?;
            let index = *s.item::<i64>(2)?;
            let wrap = *s.item::<bool>(3)?;
            let tree = s.tree(0)?;
            let branch = tree.branch(&path).ok_or_else(|| no_branch(&path))?;
            if branch.is_empty() {
                s.warning(format!("branch {path} is empty"));
                s.set_value(0, None);
                return Ok(());
            }
            match pick_index(index, branch.len(), wrap) {
                Ok(i) => s.set_value(0, branch.value(i)),
                Err(why) => {
                    s.warning(format!("{why} at branch {path}"));
                    s.set_value(0, None);
                }
            }
            Ok(())
        })
}

/// Tree Statistics \[TStat\]: the paths, branch lengths and branch count of a tree.
pub fn tree_statistics() -> NodeType {
    tree_node(TREE_STATISTICS, "Tree Statistics", "TStat")
        .gh_guid("99bee19d-588c-41a0-b9b9-1d00fb03ea1a")
        .description(
            "Lists the paths of a tree in order, the number of items of each branch (nulls \
             included) and the number of branches.",
        )
        .input(tree_port("Tree", "T", "The tree to analyse, of any type.").optional())
        .output(
            Port::new("Paths", "P", DataType::Text)
                .list()
                .doc("The paths of the tree, written {0;1}, in order."),
        )
        .output(
            Port::new("Length", "L", DataType::Integer)
                .list()
                .doc("The number of items of each branch, nulls included."),
        )
        .output(
            Port::new("Count", "C", DataType::Integer).doc("The number of branches of the tree."),
        )
        .solve(|s| {
            let tree = s.tree(0)?;
            let paths: Vec<String> = tree.paths().map(ToString::to_string).collect();
            let lengths: Vec<i64> = tree
                .branches()
                .iter()
                .map(|(_, b)| i64::try_from(b.len()).unwrap_or(i64::MAX))
                .collect();
            let count = i64::try_from(tree.branch_count()).unwrap_or(i64::MAX);
            s.set_list(0, paths);
            s.set_list(1, lengths);
            s.set(2, count);
            Ok(())
        })
}

#[cfg(test)]
mod tests {
    use locus_runtime::{Level, NodeCall};

    use super::*;
    use crate::sets::test_support::{assert_clean, generic, messages, tree};

    #[test]
    fn merge_joins_equal_paths_in_input_order() {
        let r = NodeCall::new(&merge())
            .input(tree("{0}:[1, 2] {1}:[3]"))
            .input(tree("{0}:[4] {0;1}:[5] {2}:[]"))
            .run();
        assert_clean(&r);
        assert_eq!(
            r.outputs[0].to_text(),
            "{0}:[1, 2, 4] {0;1}:[5] {1}:[3] {2}:[]"
        );
        let b = r.outputs[0].branch(&TreePath::zero()).unwrap();
        assert_eq!(b.data_type(), DataType::Number);
    }

    #[test]
    fn merge_of_mixed_types_nulls_and_more_inputs() {
        let r = NodeCall::new(&merge())
            .input_names(&["D1", "D2", "D3"])
            .input(generic("{0}:[\"a\", null]"))
            .skip_input()
            .input(tree("{0}:[1]"))
            .run();
        assert_clean(&r);
        assert_eq!(r.outputs[0].to_text(), "{0}:[\"a\", null, 1]");
        let r = NodeCall::new(&merge()).run();
        assert_clean(&r);
        assert!(r.outputs[0].is_empty());
    }

    #[test]
    fn entwine_puts_input_k_on_branch_0_k() {
        let r = NodeCall::new(&entwine())
            .input(tree("{0}:[1, 2] {1}:[3]"))
            .skip_input()
            .input(generic("{0}:[\"x\", null]"))
            .run();
        assert_clean(&r);
        assert_eq!(
            r.outputs[0].to_text(),
            "{0;0}:[1, 2, 3] {0;2}:[\"x\", null]"
        );
        let r = NodeCall::new(&entwine())
            .setting("flatten", Value::Boolean(false))
            .input(tree("{0}:[1, 2] {1}:[3]"))
            .input(tree("{0;5}:[4]"))
            .run();
        assert_eq!(
            r.outputs[0].to_text(),
            "{0;0;0}:[1, 2] {0;0;1}:[3] {0;1;0;5}:[4]"
        );
    }

    #[test]
    fn explode_tree_gives_branches_and_warns_about_the_rest() {
        let r = NodeCall::new(&explode_tree())
            .input(tree("{0;0}:[1] {0;1}:[2, null]"))
            .run();
        assert_clean(&r);
        assert_eq!(r.outputs[0].to_text(), "{0;0}:[1]");
        assert_eq!(r.outputs[1].to_text(), "{0;1}:[2, null]");
        let r = NodeCall::new(&explode_tree())
            .input(tree("{0}:[1] {1}:[] {2}:[3] {3}:[4]"))
            .run();
        assert_eq!(r.outputs[1].to_text(), "{1}:[]");
        assert_eq!(
            messages(&r, Level::Warning),
            [
                "the tree has 4 branches but the node has 2 outputs: branches {2} to {3} are left out"
            ]
        );
        let r = NodeCall::new(&explode_tree()).input(tree("{4}:[1]")).run();
        assert_eq!(r.outputs[0].to_text(), "{4}:[1]");
        assert!(r.outputs[1].is_empty());
        // As many outputs as the graph names: every branch shows.
        let r = NodeCall::new(&explode_tree())
            .input(tree("{0}:[1] {1}:[] {2}:[3] {3}:[4]"))
            .output_names(&["0", "1", "2", "3"])
            .run();
        assert_clean(&r);
        assert_eq!(r.outputs[3].to_text(), "{3}:[4]");
    }

    #[test]
    fn tree_branch_by_path_text_or_integer() {
        let t = "{0;0}:[1, 2] {0;1}:[3] {1}:[4]";
        let r = NodeCall::new(&tree_branch())
            .input(tree(t))
            .input(DataTree::from_list(vec![
                "{0;1}".to_owned(),
                "0;0".to_owned(),
            ]))
            .run();
        assert_clean(&r);
        assert_eq!(r.outputs[0].to_text(), "{0;0}:[1, 2] {0;1}:[3]");
        let r = NodeCall::new(&tree_branch())
            .input(tree(t))
            .input(DataTree::from_item(1_i64))
            .run();
        assert_clean(&r);
        assert_eq!(r.outputs[0].to_text(), "{1}:[4]");
        let r = NodeCall::new(&tree_branch())
            .input(tree(t))
            .input(DataTree::from_item("{7}".to_owned()))
            .run();
        assert_eq!(messages(&r, Level::Error), ["the tree has no branch {7}"]);
    }

    fn tree_item_at(path: &str, index: i64, wrap: bool) -> locus_runtime::NodeCallResult {
        NodeCall::new(&tree_item())
            .input(generic("{0;0}:[1, \"b\", null] {0;1}:[]"))
            .input(DataTree::from_item(path.to_owned()))
            .input(DataTree::from_item(index))
            .input(DataTree::from_item(wrap))
            .run()
    }

    #[test]
    fn tree_item_picks_wraps_and_warns() {
        let r = tree_item_at("{0;0}", 1, true);
        assert_clean(&r);
        assert_eq!(r.outputs[0].to_text(), "{0}:[\"b\"]");
        assert_eq!(
            tree_item_at("{0;0}", 5, true).outputs[0].to_text(),
            "{0}:[null]"
        );
        assert_eq!(
            tree_item_at("{0;0}", -3, true).outputs[0].to_text(),
            "{0}:[1]"
        );
        let r = tree_item_at("{0;0}", 3, false);
        assert_eq!(r.outputs[0].to_text(), "{0}:[null]");
        assert_eq!(
            messages(&r, Level::Warning),
            ["index 3 is out of range for a list of 3 items (0 to 2) at branch {0;0}"]
        );
        let r = tree_item_at("{0;1}", 0, true);
        assert_eq!(messages(&r, Level::Warning), ["branch {0;1} is empty"]);
        let r = tree_item_at("{9}", 0, true);
        assert_eq!(messages(&r, Level::Error), ["the tree has no branch {9}"]);
        let r = tree_item_at("{x}", 0, true);
        assert_eq!(messages(&r, Level::Error).len(), 1);
    }

    #[test]
    fn tree_statistics_of_a_tree_and_of_nothing() {
        let r = NodeCall::new(&tree_statistics())
            .input(tree("{0;0}:[1, null] {0;1}:[] {2}:[3]"))
            .run();
        assert_clean(&r);
        assert_eq!(
            r.outputs[0].to_text(),
            "{0}:[\"{0;0}\", \"{0;1}\", \"{2}\"]"
        );
        assert_eq!(r.outputs[1].to_text(), "{0}:[2, 0, 1]");
        assert_eq!(r.outputs[2].to_text(), "{0}:[3]");
        let r = NodeCall::new(&tree_statistics()).run();
        assert_clean(&r);
        assert_eq!(r.outputs[0].to_text(), "{0}:[]");
        assert_eq!(r.outputs[2].to_text(), "{0}:[0]");
    }
}

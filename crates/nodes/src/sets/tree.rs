//! Sets › Tree, the structure operations: Graft Tree, Flatten Tree, Simplify Tree, Trim Tree,
//! Prune Tree, Shift Paths, Flip Matrix and Path Mapper.
//!
//! Each node calls the runtime's tree operation of the same name (`docs/data-trees.md` has
//! their rules); the nodes add the ports, defaults and messages.

use std::sync::Arc;

use locus_runtime::{
    DataTree, DataType, GraftMode, NodeError, NodeRegistry, NodeType, PathMapper, Port, Prepared,
    SimplifyMode, Value,
};

use super::parse_path;

/// Id of [`graft_tree`].
pub const GRAFT_TREE: &str = "sets.graft_tree";
/// Id of [`flatten_tree`].
pub const FLATTEN_TREE: &str = "sets.flatten_tree";
/// Id of [`simplify_tree`].
pub const SIMPLIFY_TREE: &str = "sets.simplify_tree";
/// Id of [`trim_tree`].
pub const TRIM_TREE: &str = "sets.trim_tree";
/// Id of [`prune_tree`].
pub const PRUNE_TREE: &str = "sets.prune_tree";
/// Id of [`shift_paths`].
pub const SHIFT_PATHS: &str = "sets.shift_paths";
/// Id of [`flip_matrix`].
pub const FLIP_MATRIX: &str = "sets.flip_matrix";
/// Id of [`path_mapper`].
pub const PATH_MAPPER: &str = "sets.path_mapper";

/// Registers the tree structure nodes.
pub fn register(registry: &mut NodeRegistry) {
    for t in [
        graft_tree(),
        flatten_tree(),
        simplify_tree(),
        trim_tree(),
        prune_tree(),
        shift_paths(),
        flip_matrix(),
        path_mapper(),
    ] {
        registry.register(t);
    }
}

pub(crate) fn tree_node(id: &str, name: &str, nickname: &str) -> NodeType {
    NodeType::new(id, name, nickname, "Sets").subcategory("Tree")
}

pub(crate) fn tree_port(name: &str, nickname: &str, doc: &str) -> Port {
    Port::new(name, nickname, DataType::Generic).tree().doc(doc)
}

/// Graft Tree \[Graft\]: every item on a branch of its own.
pub fn graft_tree() -> NodeType {
    tree_node(GRAFT_TREE, "Graft Tree", "Graft")
        .gh_guid("87e1d9ef-088b-4d30-9dda-8a7448a17329")
        .description(
            "Grafts a tree: item i of branch {p} moves to a branch {p;i} of its own. Null items \
             get a branch holding the null, and an empty branch {p} becomes an empty {p;0}, so \
             every path grows by one index.",
        )
        .input(tree_port("Tree", "T", "The tree to graft, of any type."))
        .output(tree_port("Tree", "T", "The grafted tree."))
        .solve(|s| {
            let mut t = s.tree(0)?.clone();
            t.graft(GraftMode::ALL);
            s.set_tree(0, t);
            Ok(())
        })
}

/// Flatten Tree \[Flatten\]: all items on one branch.
pub fn flatten_tree() -> NodeType {
    tree_node(FLATTEN_TREE, "Flatten Tree", "Flatten")
        .gh_guid("f80cfe18-9510-4b89-8301-8e58faf423bb")
        .description(
            "Flattens a tree: all items of all branches, in path order, on one branch at path \
             P. A tree with branches but no items gives one empty branch; a tree without \
             branches stays empty.",
        )
        .input(tree_port("Tree", "T", "The tree to flatten, of any type."))
        .input(
            Port::new("Path", "P", DataType::Text)
                .doc("The path of the flattened branch, written {0;1}; default {0}.")
                .default_value("{0}".to_owned()),
        )
        .output(tree_port("Tree", "T", "The flattened tree."))
        .solve(|s| {
            let path = parse_path(s.item::<String>(1)?, "P")?;
            let mut t = s.tree(0)?.clone();
            t.flatten_to(path);
            s.set_tree(0, t);
            Ok(())
        })
}

/// Simplify Tree \[Simplify\]: the path indices all branches share removed.
pub fn simplify_tree() -> NodeType {
    tree_node(SIMPLIFY_TREE, "Simplify Tree", "Simplify")
        .gh_guid("1303da7b-e339-4e65-a051-82c4dce8224d")
        .description(
            "Simplifies a tree by removing the path indices shared by all branches: {0;0;1} \
             {0;0;2} becomes {1} {2}. With Front, only shared indices at the start of the paths \
             go. A tree with one branch is left as it is, and no path is ever emptied.",
        )
        .input(tree_port("Tree", "T", "The tree to simplify, of any type."))
        .input(
            Port::new("Front", "F", DataType::Boolean)
                .doc("Limit the removal to indices at the start of the paths; default false.")
                .default_value(false),
        )
        .output(tree_port("Tree", "T", "The simplified tree."))
        .solve(|s| {
            let mode = if *s.item::<bool>(1)? {
                SimplifyMode::Leading
            } else {
                SimplifyMode::All
            };
            let mut t = s.tree(0)?.clone();
            t.simplify(mode);
            s.set_tree(0, t);
            Ok(())
        })
}

/// Trim Tree \[Trim\]: the outermost path indices removed, their branches merged.
pub fn trim_tree() -> NodeType {
    tree_node(TRIM_TREE, "Trim Tree", "Trim")
        .gh_guid("1177d6ee-3993-4226-9558-52b7fd63e1e3")
        .description(
            "Reduces the depth of a tree by removing the last D indices of every path and \
             merging the branches that then share a path, in path order. A path with D indices \
             or fewer becomes {0}, so trimming deeper than the tree flattens it.",
        )
        .input(tree_port("Tree", "T", "The tree to trim, of any type."))
        .input(
            Port::new("Depth", "D", DataType::Integer)
                .doc("The number of outermost path indices to remove, 0 or more; default 1.")
                .default_value(1_i64),
        )
        .output(tree_port("Tree", "T", "The trimmed tree."))
        .solve(|s| {
            let depth = *s.item::<i64>(1)?;
            let Ok(depth) = usize::try_from(depth) else {
                return Err(NodeError(format!(
                    "depth D must be at least 0, not {depth}"
                )));
            };
            let mut t = s.tree(0)?.clone();
            t.trim(depth);
            s.set_tree(0, t);
            Ok(())
        })
}

/// Prune Tree \[Prune\]: branches with too few or too many items removed.
pub fn prune_tree() -> NodeType {
    tree_node(PRUNE_TREE, "Prune Tree", "Prune")
        .description(
            "Removes the branches of a tree that have fewer than N0 items or, when N1 is not 0, \
             more than N1 items (null items count). The default N0 = 1 removes empty branches.",
        )
        .input(tree_port("Tree", "T", "The tree to prune, of any type."))
        .input(
            Port::new("Minimum", "N0", DataType::Integer)
                .doc("Remove branches with fewer than N0 items, 0 or more; default 1.")
                .default_value(1_i64),
        )
        .input(
            Port::new("Maximum", "N1", DataType::Integer)
                .doc(
                    "Remove branches with more than N1 items, 0 or more (0 ignores the upper \
                      limit); default 0.",
                )
                .default_value(0_i64),
        )
        .output(tree_port("Tree", "T", "The pruned tree."))
        .solve(|s| {
            let count = |input: usize, name: &str| -> Result<usize, NodeError> {
                let n = *s.item::<i64>(input)?;
                usize::try_from(n)
                    .map_err(|_| NodeError(format!("{name} must be at least 0, not {n}")))
            };
            let min = count(1, "minimum N0")?;
            let max = count(2, "maximum N1")?;
            let kept = s
                .tree(0)?
                .branches()
                .iter()
                .filter(|(_, b)| b.len() >= min && (max == 0 || b.len() <= max))
                .cloned();
            s.set_tree(0, DataTree::from_branches(kept));
            Ok(())
        })
}

/// Shift Paths \[PShift\]: indices removed from the end or the front of every path.
pub fn shift_paths() -> NodeType {
    tree_node(SHIFT_PATHS, "Shift Paths", "PShift")
        .gh_guid("2d61f4e0-47c5-41d6-a41d-6afa96ee63af")
        .description(
            "Shifts the indices of every path: a negative offset removes that many indices from \
             the end ({0;0} {0;1} with −1 gives {0}), a positive one from the front ({0;0} \
             {0;1} with +1 gives {0} {1}). Branches that end up at one path merge in path \
             order; a path that loses all its indices becomes {0}.",
        )
        .input(tree_port("Data", "D", "The tree to modify, of any type."))
        .input(Port::new("Offset", "O", DataType::Integer).doc(
            "The number of indices to remove: negative from the end, positive from the front.",
        ))
        .output(tree_port("Data", "D", "The tree with shifted paths."))
        .solve(|s| {
            let offset = *s.item::<i64>(1)?;
            let mut t = s.tree(0)?.clone();
            t.shift_paths(offset);
            s.set_tree(0, t);
            Ok(())
        })
}

/// Flip Matrix \[Flip\]: rows and columns of a matrix-like tree swapped.
pub fn flip_matrix() -> NodeType {
    tree_node(FLIP_MATRIX, "Flip Matrix", "Flip")
        .gh_guid("41aa4112-9c9b-42f4-847e-503b9d90e4c7")
        .description(
            "Flips a matrix-like tree, whose branches are its rows, by swapping rows and \
             columns: item j of every branch goes, in branch order, to branch j. Shorter rows \
             give nulls. The paths must have one length and differ at one index position only; \
             other trees are an error.",
        )
        .input(tree_port("Data", "D", "The matrix to flip, of any type."))
        .output(tree_port("Data", "D", "The flipped matrix."))
        .solve(|s| {
            let mut t = s.tree(0)?.clone();
            t.flip_matrix().map_err(|e| NodeError(e.to_string()))?;
            s.set_tree(0, t);
            Ok(())
        })
}

/// The masks a new Path Mapper node starts with: every path mapped to itself.
pub const DEFAULT_SOURCE_MASK: &str = "{A;B}";
/// The target mask a new Path Mapper node starts with.
pub const DEFAULT_TARGET_MASK: &str = "{A;B}";

/// Path Mapper \[PathMapper\]: paths and item indices rewritten by lexical masks.
pub fn path_mapper() -> NodeType {
    tree_node(PATH_MAPPER, "Path Mapper", "PathMapper")
        .description(
            "Rewrites the paths (and item indices) of a tree by a source and a target mask: \
             {A;B}(i) → {B;A}(i) swaps two levels, {A;B} → {A} merges the last level, \
             {A;B}(i) → {A;B;i} grafts, {A;B}(i) → {i} flips. Target masks are integer \
             expressions of the source names and of item_count, path_count and path_index. \
             Every path must have as many indices as the source mask. Without an item index in \
             the target, items are appended to their new branch; with one, each item is \
             written at that index (gaps are nulls, later items replace earlier ones). See \
             docs/data-trees.md.",
        )
        .input(tree_port("Data", "D", "The tree to map, of any type."))
        .output(tree_port("Data", "D", "The mapped tree."))
        .setting(
            "source",
            DataType::Text,
            Some(Value::Text(DEFAULT_SOURCE_MASK.to_owned())),
            "The source mask, such as {A;B}(i): a name for each path index and, optionally, \
             for the item index; default {A;B}.",
        )
        .setting(
            "target",
            DataType::Text,
            Some(Value::Text(DEFAULT_TARGET_MASK.to_owned())),
            "The target mask, such as {B;A}(i): an integer expression for each index of the \
             new path and, optionally, for the new item index; default {A;B}.",
        )
        .prepare(|config| {
            let mask = |name: &str| match config.setting(name) {
                Some(Value::Text(t)) => Ok(t.clone()),
                Some(other) => Err(NodeError(format!(
                    "the {name} mask must be a Text, not a {}",
                    other.data_type()
                ))),
                None => Err(NodeError(format!("the node has no {name} mask"))),
            };
            let mapper = PathMapper::new(&mask("source")?, &mask("target")?)
                .map_err(|e| NodeError(e.to_string()))?;
            Ok(Arc::new(mapper) as Prepared)
        })
        .solve(|s| {
            let mapper = s
                .prepared::<PathMapper>()
                .ok_or_else(|| NodeError("internal: the masks were not prepared".to_owned()))?;
            let tree: &DataTree = s.tree(0)?;
            let mapped = mapper.apply(tree).map_err(|e| NodeError(e.to_string()))?;
            s.set_tree(0, mapped);
            Ok(())
        })
}

#[cfg(test)]
mod tests {
    use locus_runtime::{Level, NodeCall};

    use super::*;
    use crate::sets::test_support::{assert_clean, generic, messages, tree};

    fn run(node: &NodeType, input: &str) -> String {
        let r = NodeCall::new(node).input(tree(input)).run();
        assert_clean(&r);
        r.outputs[0].to_text()
    }

    fn run_with(
        node: &NodeType,
        input: DataTree,
        second: DataTree,
    ) -> locus_runtime::NodeCallResult {
        NodeCall::new(node).input(input).input(second).run()
    }

    #[test]
    fn graft_keeps_nulls_and_empty_branches() {
        assert_eq!(
            run(&graft_tree(), "{0}:[1, null, 3] {1}:[]"),
            "{0;0}:[1] {0;1}:[null] {0;2}:[3] {1;0}:[]"
        );
        let r = NodeCall::new(&graft_tree()).input(DataTree::new()).run();
        assert!(r.outputs[0].is_empty());
        assert_eq!(
            messages(&r, Level::Warning),
            ["input parameter T failed to collect data"]
        );
        let r = NodeCall::new(&graft_tree())
            .input(generic("{0}:[\"a\", true]"))
            .run();
        assert_eq!(r.outputs[0].to_text(), "{0;0}:[\"a\"] {0;1}:[true]");
    }

    #[test]
    fn flatten_to_the_default_or_a_given_path() {
        assert_eq!(
            run(&flatten_tree(), "{1}:[5] {0;0}:[1, null] {0;2}:[3]"),
            "{0}:[1, null, 3, 5]"
        );
        let r = run_with(
            &flatten_tree(),
            tree("{0;0}:[1] {0;1}:[2]"),
            DataTree::from_item("{2;7}".to_owned()),
        );
        assert_clean(&r);
        assert_eq!(r.outputs[0].to_text(), "{2;7}:[1, 2]");
        let r = run_with(
            &flatten_tree(),
            tree("{0;0}:[1]"),
            DataTree::from_item(3_i64),
        );
        assert_eq!(r.outputs[0].to_text(), "{3}:[1]");
        assert_eq!(run(&flatten_tree(), "{0;1}:[] {0;2}:[]"), "{0}:[]");
    }

    #[test]
    fn flatten_rejects_a_bad_path() {
        let r = run_with(
            &flatten_tree(),
            tree("{0;0}:[1]"),
            DataTree::from_item("{0;-1}".to_owned()),
        );
        assert_eq!(
            messages(&r, Level::Error),
            ["input P: invalid tree path `{0;-1}`: indices must be non-negative integers"]
        );
        assert!(r.outputs[0].is_empty());
    }

    #[test]
    fn simplify_all_or_front() {
        let text = "{0;0;0;1;0}:[1] {0;3;0;2;0}:[2] {0;8;0;3;0}:[3]";
        assert_eq!(run(&simplify_tree(), text), "{0;1}:[1] {3;2}:[2] {8;3}:[3]");
        let r = run_with(&simplify_tree(), tree(text), DataTree::from_item(true));
        assert_eq!(
            r.outputs[0].to_text(),
            "{0;0;1;0}:[1] {3;0;2;0}:[2] {8;0;3;0}:[3]"
        );
        assert_eq!(run(&simplify_tree(), "{0;0;0}:[1, 2]"), "{0;0;0}:[1, 2]");
    }

    #[test]
    fn trim_merges_outer_branches() {
        let text = "{0;0;0}:[1] {0;0;1}:[2] {0;1;0}:[3] {1;0;0}:[4]";
        assert_eq!(run(&trim_tree(), text), "{0;0}:[1, 2] {0;1}:[3] {1;0}:[4]");
        let r = run_with(&trim_tree(), tree(text), DataTree::from_item(2_i64));
        assert_eq!(r.outputs[0].to_text(), "{0}:[1, 2, 3] {1}:[4]");
        let r = run_with(&trim_tree(), tree(text), DataTree::from_item(-1_i64));
        assert_eq!(
            messages(&r, Level::Error),
            ["depth D must be at least 0, not -1"]
        );
    }

    #[test]
    fn shift_paths_both_ways() {
        let text = "{0;0}:[1] {0;1}:[2] {0;2}:[3]";
        let r = run_with(&shift_paths(), tree(text), DataTree::from_item(-1_i64));
        assert_clean(&r);
        assert_eq!(r.outputs[0].to_text(), "{0}:[1, 2, 3]");
        let r = run_with(&shift_paths(), tree(text), DataTree::from_item(1_i64));
        assert_eq!(r.outputs[0].to_text(), "{0}:[1] {1}:[2] {2}:[3]");
        let r = run_with(&shift_paths(), tree(text), DataTree::from_item(0_i64));
        assert_eq!(r.outputs[0].to_text(), text);
    }

    #[test]
    fn shift_paths_needs_an_offset() {
        let r = NodeCall::new(&shift_paths()).input(tree("{0;0}:[1]")).run();
        assert_eq!(
            messages(&r, Level::Warning),
            ["input parameter O failed to collect data"]
        );
    }

    #[test]
    fn flip_matrix_swaps_and_pads_with_nulls() {
        assert_eq!(
            run(&flip_matrix(), "{0;0}:[1, 2, 3] {0;1}:[4, 5]"),
            "{0;0}:[1, 4] {0;1}:[2, 5] {0;2}:[3, null]"
        );
        let r = NodeCall::new(&flip_matrix())
            .input(tree("{0;0}:[1] {0;0;1}:[2]"))
            .run();
        assert_eq!(
            messages(&r, Level::Error),
            ["flip matrix needs paths of one length: {0;0} and {0;0;1} differ"]
        );
        let r = NodeCall::new(&flip_matrix()).input(tree("{0}:[]")).run();
        assert_clean(&r);
        assert_eq!(r.outputs[0].to_text(), "");
    }

    fn mapped(source: &str, target: &str, input: &str) -> locus_runtime::NodeCallResult {
        NodeCall::new(&path_mapper())
            .setting("source", Value::Text(source.to_owned()))
            .setting("target", Value::Text(target.to_owned()))
            .input(tree(input))
            .run()
    }

    #[test]
    fn path_mapper_with_the_reference_masks() {
        let t = "{0;0}:[1, 2] {0;1}:[3, 4] {1;0}:[5, 6]";
        for (source, target, expected) in [
            (
                "{A;B}(i)",
                "{B;A}(i)",
                "{0;0}:[1, 2] {0;1}:[5, 6] {1;0}:[3, 4]",
            ),
            ("{A;B}(i)", "{A}", "{0}:[1, 2, 3, 4] {1}:[5, 6]"),
            ("{A;B}(i)", "{A}(i)", "{0}:[3, 4] {1}:[5, 6]"),
            (
                "{A;B}(i)",
                "{A;B;i}",
                "{0;0;0}:[1] {0;0;1}:[2] {0;1;0}:[3] {0;1;1}:[4] {1;0;0}:[5] {1;0;1}:[6]",
            ),
            ("{A;B}(i)", "{i}", "{0}:[1, 3, 5] {1}:[2, 4, 6]"),
            ("{A;B}", "{path_index}", "{0}:[1, 2] {1}:[3, 4] {2}:[5, 6]"),
            (
                "{A;B}(i)",
                "{A;B}(item_count-1-i)",
                "{0;0}:[2, 1] {0;1}:[4, 3] {1;0}:[6, 5]",
            ),
        ] {
            let r = mapped(source, target, t);
            assert_clean(&r);
            assert_eq!(r.outputs[0].to_text(), expected, "{source} -> {target}");
        }
    }

    #[test]
    fn path_mapper_defaults_to_the_identity_and_keeps_nulls() {
        let r = NodeCall::new(&path_mapper())
            .input(tree("{0;1}:[1, null] {2;3}:[]"))
            .run();
        assert_clean(&r);
        assert_eq!(r.outputs[0].to_text(), "{0;1}:[1, null] {2;3}:[]");
    }

    #[test]
    fn path_mapper_reports_bad_masks_and_paths() {
        let r = mapped("{A;B}", "{C}", "{0;0}:[1]");
        assert_eq!(
            messages(&r, Level::Error),
            [
                "invalid mask `{C}` at column 2: unknown name `C` (known: A, B, item_count, \
              path_count, path_index)"
            ]
        );
        let r = mapped("{A;B}", "{A}", "{0}:[1]");
        assert_eq!(
            messages(&r, Level::Error),
            ["path {0} does not match the source mask `{A;B}`"]
        );
        let r = mapped("{A}", "{A-1}", "{0}:[1]");
        assert_eq!(
            messages(&r, Level::Error),
            ["cannot map path {0}: path index -1 is negative"]
        );
    }

    #[test]
    fn every_structure_node_keeps_mixed_types_nulls_and_empty_branches() {
        let input = "{0;0}:[\"a\", null] {0;1}:[] {0;2}:[true, {1, 2, 3}]";
        let one = |node: NodeType| {
            let r = NodeCall::new(&node).input(generic(input)).run();
            assert_clean(&r);
            r.outputs[0].to_text()
        };
        assert_eq!(
            one(graft_tree()),
            "{0;0;0}:[\"a\"] {0;0;1}:[null] {0;1;0}:[] {0;2;0}:[true] {0;2;1}:[{1, 2, 3}]"
        );
        assert_eq!(one(flatten_tree()), "{0}:[\"a\", null, true, {1, 2, 3}]");
        assert_eq!(
            one(simplify_tree()),
            "{0}:[\"a\", null] {1}:[] {2}:[true, {1, 2, 3}]"
        );
        assert_eq!(one(trim_tree()), "{0}:[\"a\", null, true, {1, 2, 3}]");
        assert_eq!(
            one(flip_matrix()),
            "{0;0}:[\"a\", null, true] {0;1}:[null, null, {1, 2, 3}]"
        );
        assert_eq!(one(path_mapper()), input);
        let r = NodeCall::new(&shift_paths())
            .input(generic(input))
            .input(DataTree::from_item(1_i64))
            .run();
        assert_eq!(
            r.outputs[0].to_text(),
            "{0}:[\"a\", null] {1}:[] {2}:[true, {1, 2, 3}]"
        );
    }

    #[test]
    fn prune_removes_small_and_large_branches() {
        let t = "{0}:[] {1}:[1] {2}:[1, null] {3}:[1, 2, 3]";
        let prune = |min: i64, max: i64| {
            NodeCall::new(&prune_tree())
                .input(tree(t))
                .input(DataTree::from_item(min))
                .input(DataTree::from_item(max))
                .run()
        };
        assert_eq!(run(&prune_tree(), t), "{1}:[1] {2}:[1, null] {3}:[1, 2, 3]");
        assert_eq!(
            prune(2, 0).outputs[0].to_text(),
            "{2}:[1, null] {3}:[1, 2, 3]"
        );
        assert_eq!(
            prune(0, 2).outputs[0].to_text(),
            "{0}:[] {1}:[1] {2}:[1, null]"
        );
        assert_eq!(prune(4, 0).outputs[0].to_text(), "");
        assert_eq!(
            messages(&prune(-1, 0), Level::Error),
            ["minimum N0 must be at least 0, not -1"]
        );
        assert_eq!(
            messages(&prune(0, -1), Level::Error),
            ["maximum N1 must be at least 0, not -1"]
        );
    }
}

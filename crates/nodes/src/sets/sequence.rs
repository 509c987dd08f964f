//! Sets › Sequence: Cull Pattern. (Range and Series, also in Sets › Sequence, are in
//! [`crate::maths::sequence`].)

use locus_runtime::{DataType, NodeRegistry, NodeType, Port};

use super::list::{pattern_of, split_by_pattern};

/// Id of [`cull_pattern`].
pub const CULL_PATTERN: &str = "sets.cull_pattern";

/// Registers the sequence nodes of this module.
pub fn register(registry: &mut NodeRegistry) {
    registry.register(cull_pattern());
}

/// Cull Pattern \[Cull\]: the items of a list kept or removed by a repeating pattern.
pub fn cull_pattern() -> NodeType {
    NodeType::new(CULL_PATTERN, "Cull Pattern", "Cull", "Sets")
        .subcategory("Sequence")
        .description(
            "Removes items from a list by a pattern of booleans, repeated as often as needed: \
             item k is kept when pattern item k mod (pattern length) is true and culled when \
             it is false. A null in the pattern counts as false; null items are kept or culled \
             like any other.",
        )
        .input(
            Port::new("List", "L", DataType::Generic)
                .list()
                .doc("The list to cull, of any type."),
        )
        .input(
            Port::new("Cull Pattern", "P", DataType::Boolean)
                .list()
                .doc("The pattern of booleans (true keeps), repeated along the list."),
        )
        .output(
            Port::new("List", "L", DataType::Generic)
                .list()
                .doc("The items whose pattern value is true, in order."),
        )
        .solve(|s| {
            let Some(branch) = s.branch(0) else {
                return Ok(());
            };
            let pattern = pattern_of(s, 1)?;
            let (kept, _) = split_by_pattern(branch, &pattern);
            s.set_branch(0, kept);
            Ok(())
        })
}

#[cfg(test)]
mod tests {
    use locus_runtime::{Branch, DataTree, NodeCall, TreePath};

    use super::*;
    use crate::sets::test_support::{assert_clean, generic, tree};

    fn cull(list: DataTree, pattern: Vec<bool>) -> String {
        let r = NodeCall::new(&cull_pattern())
            .input(list)
            .input(DataTree::from_list(pattern))
            .run();
        assert_clean(&r);
        r.outputs[0].to_text()
    }

    #[test]
    fn the_pattern_repeats() {
        let l = tree("{0}:[0, 1, 2, 3, 4, 5, 6]");
        assert_eq!(cull(l.clone(), vec![true, false]), "{0}:[0, 2, 4, 6]");
        assert_eq!(cull(l.clone(), vec![false, false, true]), "{0}:[2, 5]");
        assert_eq!(cull(l.clone(), vec![true]), "{0}:[0, 1, 2, 3, 4, 5, 6]");
        assert_eq!(cull(l, vec![false]), "{0}:[]");
    }

    #[test]
    fn mixed_types_and_nulls_are_culled_like_any_item() {
        let l = generic("{0}:[\"a\", null, true, {1, 2, 3}]");
        assert_eq!(cull(l.clone(), vec![false, true]), "{0}:[null, {1, 2, 3}]");
        assert_eq!(
            cull(l, vec![true, true, false]),
            "{0}:[\"a\", null, {1, 2, 3}]"
        );
    }

    #[test]
    fn each_branch_is_culled_and_empty_lists_stay_empty() {
        let r = NodeCall::new(&cull_pattern())
            .input(tree("{0;0}:[1, 2, 3] {0;1}:[] {0;2}:[4, 5]"))
            .input(DataTree::from_list(vec![false, true]))
            .run();
        assert_eq!(r.outputs[0].to_text(), "{0;0}:[2] {0;1}:[] {0;2}:[5]");
    }

    #[test]
    fn a_null_in_the_pattern_culls() {
        let mut p = Branch::new(DataType::Boolean);
        p.push_null();
        p.push(true);
        let r = NodeCall::new(&cull_pattern())
            .input(tree("{0}:[1, 2, 3, 4]"))
            .input(DataTree::from_branches([(TreePath::zero(), p)]))
            .run();
        assert_eq!(r.outputs[0].to_text(), "{0}:[2, 4]");
    }

    #[test]
    fn numbers_cast_to_pattern_booleans() {
        let r = NodeCall::new(&cull_pattern())
            .input(tree("{0}:[1, 2, 3]"))
            .input(tree("{0}:[1, 0]"))
            .run();
        assert_clean(&r);
        assert_eq!(r.outputs[0].to_text(), "{0}:[1, 3]");
    }
}

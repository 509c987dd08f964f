//! Sets › List, splitting lists: Split List and Partition List (the other List nodes are in
//! [`super::list`]).

use locus_runtime::{Branch, DataTree, DataType, NodeError, NodeRegistry, NodeType, Port};

/// Id of [`split_list`].
pub const SPLIT_LIST: &str = "sets.split_list";
/// Id of [`partition_list`].
pub const PARTITION_LIST: &str = "sets.partition_list";

/// Registers the list splitting nodes.
pub fn register(registry: &mut NodeRegistry) {
    registry.register(split_list());
    registry.register(partition_list());
}

fn list_port(name: &str, nickname: &str, doc: &str) -> Port {
    Port::new(name, nickname, DataType::Generic).list().doc(doc)
}

/// Split List \[Split\]: a list cut in two at an index.
pub fn split_list() -> NodeType {
    NodeType::new(SPLIT_LIST, "Split List", "Split", "Sets")
        .gh_guid("9ab93e1a-ebdf-4090-9296-b000cff7b202")
        .subcategory("List")
        .description(
            "Splits a list in two at index i: List A has the items before i, List B the item \
             at i and those after it. An index at or before 0 puts every item in B, one at or \
             past the end every item in A.",
        )
        .input(list_port("List", "L", "The list to split, of any type."))
        .input(
            Port::new("Index", "i", DataType::Integer)
                .doc("The index of the first item of List B; default 0.")
                .default_value(0_i64),
        )
        .output(list_port(
            "List A",
            "A",
            "The items to the left of index i.",
        ))
        .output(list_port(
            "List B",
            "B",
            "The items from index i on, that item included.",
        ))
        .solve(|s| {
            let Some(branch) = s.branch(0) else {
                return Ok(());
            };
            let n = branch.len();
            let at = usize::try_from((*s.item::<i64>(1)?).max(0))
                .unwrap_or(n)
                .min(n);
            let mut a = Branch::new(branch.data_type());
            a.extend_range(branch, 0..at);
            let mut b = Branch::new(branch.data_type());
            b.extend_range(branch, at..n);
            s.set_branch(0, a);
            s.set_branch(1, b);
            Ok(())
        })
}

/// Partition List \[Partition\]: a list cut into chunks of given sizes.
pub fn partition_list() -> NodeType {
    NodeType::new(PARTITION_LIST, "Partition List", "Partition", "Sets")
        .gh_guid("5a93246d-2595-4c28-bc2d-90657634f92a")
        .subcategory("List")
        .description(
            "Cuts a list into consecutive chunks whose sizes are taken from S in turn, S \
             repeating as often as needed; the last chunk may be shorter. Chunk k of the list \
             at path {p} goes to branch {p;k}. Sizes must be at least 1.",
        )
        .input(list_port(
            "List",
            "L",
            "The list to partition, of any type.",
        ))
        .input(
            Port::new("Size", "S", DataType::Integer)
                .list()
                .doc("The sizes of the chunks, each 1 or more, repeated along the list."),
        )
        .output(
            Port::new("Chunks", "C", DataType::Generic)
                .tree()
                .doc("The chunks, one branch each."),
        )
        .solve(|s| {
            let Some(branch) = s.branch(0) else {
                return Ok(());
            };
            let mut sizes = Vec::new();
            for (k, size) in s.list::<i64>(1)?.iter().enumerate() {
                match size.copied().and_then(|n| usize::try_from(n).ok()) {
                    Some(n) if n >= 1 => sizes.push(n),
                    _ => {
                        return Err(NodeError(format!(
                            "size S item {k} must be at least 1, not {}",
                            size.map_or("null".to_owned(), ToString::to_string)
                        )));
                    }
                }
            }
            let path = s.path().clone();
            let n = branch.len();
            let mut chunks = Vec::new();
            let mut start = 0;
            let mut k = 0_usize;
            while start < n && !sizes.is_empty() {
                let end = start.saturating_add(sizes[k % sizes.len()]).min(n);
                let mut chunk = Branch::new(branch.data_type());
                chunk.extend_range(branch, start..end);
                chunks.push((
                    path.with_appended(u32::try_from(k).unwrap_or(u32::MAX)),
                    chunk,
                ));
                start = end;
                k += 1;
            }
            s.set_tree(0, DataTree::from_branches(chunks));
            Ok(())
        })
}

#[cfg(test)]
mod tests {
    use locus_runtime::{Level, NodeCall};

    use super::*;
    use crate::sets::test_support::{assert_clean, generic, messages, tree};

    fn split(list: &str, at: i64) -> (String, String) {
        let r = NodeCall::new(&split_list())
            .input(generic(list))
            .input(DataTree::from_item(at))
            .run();
        assert_clean(&r);
        (r.outputs[0].to_text(), r.outputs[1].to_text())
    }

    #[test]
    fn split_list_at_an_index_and_past_the_ends() {
        let l = "{0}:[0, \"a\", null, 3]";
        assert_eq!(
            split(l, 2),
            ("{0;0}:[0, \"a\"]".to_owned(), "{0;0}:[null, 3]".to_owned())
        );
        assert_eq!(
            split(l, 0),
            (
                "{0;0}:[]".to_owned(),
                "{0;0}:[0, \"a\", null, 3]".to_owned()
            )
        );
        assert_eq!(split(l, -3).0, "{0;0}:[]");
        assert_eq!(split(l, 9).1, "{0;0}:[]");
        assert_eq!(split(l, i64::MAX).0, "{0;0}:[0, \"a\", null, 3]");
    }

    fn partition(list: &str, sizes: Vec<i64>) -> locus_runtime::NodeCallResult {
        NodeCall::new(&partition_list())
            .input(tree(list))
            .input(DataTree::from_list(sizes))
            .run()
    }

    #[test]
    fn partition_list_with_repeating_sizes() {
        let r = partition("{0}:[0, 1, 2, 3, 4, 5, 6]", vec![2, 3]);
        assert_clean(&r);
        assert_eq!(
            r.outputs[0].to_text(),
            "{0;0}:[0, 1] {0;1}:[2, 3, 4] {0;2}:[5, 6]"
        );
        let r = partition("{0}:[0, null, 2]", vec![5]);
        assert_eq!(r.outputs[0].to_text(), "{0;0}:[0, null, 2]");
    }

    #[test]
    fn partition_list_per_branch_and_bad_sizes() {
        let r = NodeCall::new(&partition_list())
            .input(tree("{1}:[1, 2, 3] {2}:[]"))
            .input(DataTree::from_item(2_i64))
            .run();
        assert_eq!(r.outputs[0].to_text(), "{1;0}:[1, 2] {1;1}:[3]");
        let r = partition("{0}:[1, 2]", vec![1, 0]);
        assert_eq!(
            messages(&r, Level::Error),
            ["size S item 1 must be at least 1, not 0"]
        );
    }
}

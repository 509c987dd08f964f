//! Sets › List, matching list lengths: Longest List and Shortest List (the other List nodes
//! are in [`super::list`] and [`super::list_split`]).
//!
//! Grasshopper offers several modes on these nodes (repeat first or last, wrap, flip,
//! interpolate; trim start or end); locus has the default modes: Longest List repeats the last
//! item of the shorter list, Shortest List trims the end of the longer one.

use locus_runtime::{Branch, DataType, NodeRegistry, NodeType, Port};

/// Id of [`longest_list`].
pub const LONGEST_LIST: &str = "sets.longest_list";
/// Id of [`shortest_list`].
pub const SHORTEST_LIST: &str = "sets.shortest_list";

/// Registers the list matching nodes.
pub fn register(registry: &mut NodeRegistry) {
    registry.register(longest_list());
    registry.register(shortest_list());
}

fn matching_node(id: &str, name: &str, nickname: &str, description: &str) -> NodeType {
    let port = |name: &str, nickname: &str, doc: &str| {
        Port::new(name, nickname, DataType::Generic).list().doc(doc)
    };
    NodeType::new(id, name, nickname, "Sets")
        .subcategory("List")
        .description(description)
        .input(port("List (A)", "A", "The first list, of any type."))
        .input(port("List (B)", "B", "The second list, of any type."))
        .output(port("List (A)", "A", "List A, adjusted."))
        .output(port("List (B)", "B", "List B, adjusted."))
}

/// Longest List \[Long\]: the shorter of two lists grown to the length of the longer.
pub fn longest_list() -> NodeType {
    matching_node(
        LONGEST_LIST,
        "Longest List",
        "Long",
        "Grows the shorter of two lists to the length of the longer by repeating its last \
         item (a null last item repeats as null), so the two can be paired item by item. An \
         empty list gives two empty lists.",
    )
    .gh_guid("8440fd1b-b6e0-4bdb-aa93-4ec295c213e9")
    .solve(|s| {
        let (Some(a), Some(b)) = (s.branch(0), s.branch(1)) else {
            return Ok(());
        };
        let n = a.len().max(b.len());
        s.set_branch(0, grown(a, n));
        s.set_branch(1, grown(b, n));
        Ok(())
    })
}

/// `branch` grown to `n` items by repeating its last item.
fn grown(branch: &Branch, n: usize) -> Branch {
    let len = branch.len();
    if len == 0 || len >= n {
        return branch.clone();
    }
    branch.gather((0..n).map(|i| Some(i.min(len - 1))))
}

/// Shortest List \[Short\]: the longer of two lists cut to the length of the shorter.
pub fn shortest_list() -> NodeType {
    matching_node(
        SHORTEST_LIST,
        "Shortest List",
        "Short",
        "Shrinks the longer of two lists to the length of the shorter by removing items from \
         its end, so the two can be paired item by item. An empty list gives two empty \
         lists.",
    )
    .gh_guid("5a13ec19-e4e9-43da-bf65-f93025fa87ca")
    .solve(|s| {
        let (Some(a), Some(b)) = (s.branch(0), s.branch(1)) else {
            return Ok(());
        };
        let n = a.len().min(b.len());
        let cut = |branch: &Branch| {
            let mut out = Branch::new(branch.data_type());
            out.extend_range(branch, 0..n);
            out
        };
        s.set_branch(0, cut(a));
        s.set_branch(1, cut(b));
        Ok(())
    })
}

#[cfg(test)]
mod tests {
    use locus_runtime::NodeCall;

    use super::*;
    use crate::sets::test_support::{assert_clean, generic, tree};

    fn pair(node: &NodeType, a: &str, b: &str) -> (String, String) {
        let r = NodeCall::new(node).input(generic(a)).input(tree(b)).run();
        assert_clean(&r);
        (r.outputs[0].to_text(), r.outputs[1].to_text())
    }

    #[test]
    fn longest_list_repeats_the_last_item() {
        assert_eq!(
            pair(&longest_list(), "{0}:[\"a\", null]", "{0}:[1, 2, 3, 4]"),
            (
                "{0}:[\"a\", null, null, null]".to_owned(),
                "{0}:[1, 2, 3, 4]".to_owned()
            )
        );
        assert_eq!(
            pair(&longest_list(), "{0}:[1, 2, 3]", "{0}:[9]"),
            ("{0}:[1, 2, 3]".to_owned(), "{0}:[9, 9, 9]".to_owned())
        );
    }

    #[test]
    fn shortest_list_trims_the_end() {
        assert_eq!(
            pair(&shortest_list(), "{0}:[\"a\", true, 3]", "{0}:[1, null]"),
            ("{0}:[\"a\", true]".to_owned(), "{0}:[1, null]".to_owned())
        );
    }

    #[test]
    fn an_empty_list_gives_empty_lists() {
        for node in [longest_list(), shortest_list()] {
            let r = NodeCall::new(&node)
                .input(tree("{0}:[]"))
                .input(tree("{0}:[1, 2]"))
                .run();
            assert_eq!(r.outputs[0].to_text(), "{0}:[]");
            assert_eq!(r.outputs[1].to_text(), "{0}:[]");
        }
    }
}

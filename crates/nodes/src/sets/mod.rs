//! Sets: Grasshopper's Sets tab — lists and trees.
//!
//! - List ([`list`], [`list_split`], [`list_match`]): List Item, List Length, Reverse List,
//!   Shift List, Sort List, Dispatch, Split List, Partition List, Longest List, Shortest List.
//! - Sequence ([`sequence`]): Cull Pattern, Cull Index, Cull Nth, Repeat Data, Duplicate Data
//!   (Range and Series are in [`crate::maths::sequence`]).
//! - Tree ([`tree`], [`streams`]): Graft, Flatten, Simplify, Trim, Prune, Shift Paths, Flip
//!   Matrix, Path Mapper; Merge, Entwine, Explode Tree, Tree Branch, Tree Item, Tree Statistics.
//! - Editing ([`list_edit`], [`tree_edit`]): Sub List, Insert Items, Replace Items,
//!   Pick'n'Choose, Weave, Sift Pattern, Cross Reference, Null Item; Stream Filter, Stream Gate,
//!   Clean Tree, Split Tree, Match Tree.
//! - Random ([`random`]): Random, Jitter, Random Reduce, Fibonacci.
//! - Text ([`text`], [`text_chars`]): Concatenate, Text Split, Text Join, Text Length, Replace
//!   Text, Text Case, Match Text, Format; Characters, Text Fragment, Text Trim, Char Sequence.
//! - Sets ([`set_ops`], [`set_members`]): Create Set, Set Union, Set Intersection, Set
//!   Difference, Set Difference (S), Set Majority, Disjoint, SubSet; Member Index, Replace
//!   Members, Find similar member, Delete Consecutive, Key/Value Search.
//! - Gaps and restructuring ([`list_nulls`], [`tree_restructure`]): Replace Nulls, Combine
//!   Data; Relative Item, Unflatten Tree, Replace Paths.
//!
//! List nodes take generic data and keep it typed: items move between branches with
//! [`Branch::gather`](locus_runtime::Branch::gather) and typed range copies, never one boxed
//! value at a time (List Item and Tree Item, whose output is one item, copy that item as a
//! [`Value`]). Null items are items: they are counted, moved, culled and dispatched like any
//! other, and stay null. The tree nodes call the runtime's tree operations
//! (`DataTree::graft`, `flatten_to`, `simplify`, `trim`, `shift_paths`, `flip_matrix`,
//! `explode`, [`PathMapper`](locus_runtime::PathMapper)); their rules are in
//! `docs/data-trees.md`.
//!
//! Paths are given to ports as text, `{0;1}` (the braces may be left out, so an integer `3`
//! is the path `{3}`).

pub mod list;
pub mod list_edit;
pub mod list_match;
pub mod list_nulls;
pub mod list_split;
pub mod random;
pub mod sequence;
pub mod set_members;
pub mod set_ops;
pub mod streams;
pub mod text;
pub mod text_chars;
pub mod tree;
pub mod tree_edit;
pub mod tree_restructure;

use locus_runtime::{NodeError, NodeRegistry, TreePath};

/// Registers every Sets node type.
pub fn register(registry: &mut NodeRegistry) {
    list::register(registry);
    list_edit::register(registry);
    list_split::register(registry);
    list_match::register(registry);
    sequence::register(registry);
    tree::register(registry);
    streams::register(registry);
    random::register(registry);
    text::register(registry);
    tree_edit::register(registry);
    set_ops::register(registry);
    set_members::register(registry);
    list_nulls::register(registry);
    tree_restructure::register(registry);
    text_chars::register(registry);
}

/// Reads a path written `{0;1}` (or `0;1`), naming the port in the error.
pub(crate) fn parse_path(text: &str, port: &str) -> Result<TreePath, NodeError> {
    text.parse::<TreePath>()
        .map_err(|e| NodeError(format!("input {port}: {e}")))
}

/// The item of `branch` at the index `index` asks for: with `wrap`, any index wraps around
/// the list (−1 is the last item); without, an index outside `0..len` gives `Err` with the
/// warning text. `len` must not be 0.
pub(crate) fn pick_index(index: i64, len: usize, wrap: bool) -> Result<usize, String> {
    let n = i64::try_from(len).unwrap_or(i64::MAX);
    if wrap {
        // rem_euclid of a positive modulus is in 0..n.
        return Ok(usize::try_from(index.rem_euclid(n)).unwrap_or(0));
    }
    match usize::try_from(index) {
        Ok(i) if i < len => Ok(i),
        _ => Err(format!(
            "index {index} is out of range for a list of {len} items (0 to {})",
            len - 1
        )),
    }
}

#[cfg(test)]
pub(crate) mod test_support {
    //! Helpers for the Sets node tests.

    use locus_runtime::{DataTree, DataType, Level, NodeCallResult};

    /// A tree of numbers written `{0;1}:[1, null, 3] {0;2}:[]`.
    pub(crate) fn tree(text: &str) -> DataTree {
        DataTree::from_text(text).unwrap_or_else(|e| panic!("{text}: {e}"))
    }

    /// A tree of items of any type, each typed by its spelling (`"a"`, `true`, `{1, 2, 3}`).
    pub(crate) fn generic(text: &str) -> DataTree {
        DataTree::parse_text(text, DataType::Generic).unwrap_or_else(|e| panic!("{text}: {e}"))
    }

    /// The texts of the messages of one level.
    pub(crate) fn messages(result: &NodeCallResult, level: Level) -> Vec<String> {
        result
            .messages
            .iter()
            .filter(|m| m.level == level)
            .map(|m| m.text.clone())
            .collect()
    }

    /// Asserts that the call gave no warnings or errors.
    pub(crate) fn assert_clean(result: &NodeCallResult) {
        let bad: Vec<String> = result
            .messages
            .iter()
            .filter(|m| m.level >= Level::Warning)
            .map(ToString::to_string)
            .collect();
        assert!(bad.is_empty(), "unexpected messages: {bad:?}");
    }
}

//! Sets › Sequence: Cull Pattern, Cull Index, Cull Nth, Repeat Data and Duplicate Data.
//! (Range and Series, also in Sets › Sequence, are in [`crate::maths::sequence`].)
//!
//! All of them build their result from the input branch with typed range copies
//! ([`Branch::gather`], [`Branch::extend_range`]); null items are kept or dropped like any
//! other item.

use locus_runtime::{Branch, Column, DataType, NodeError, NodeRegistry, NodeType, Port};

use super::list::{pattern_of, split_by_pattern};
use crate::maths::sequence::MAX_SEQUENCE_LENGTH;

/// Id of [`cull_pattern`].
pub const CULL_PATTERN: &str = "sets.cull_pattern";
/// Id of [`cull_index`].
pub const CULL_INDEX: &str = "sets.cull_index";
/// Id of [`cull_nth`].
pub const CULL_NTH: &str = "sets.cull_nth";
/// Id of [`repeat_data`].
pub const REPEAT_DATA: &str = "sets.repeat_data";
/// Id of [`duplicate_data`].
pub const DUPLICATE_DATA: &str = "sets.duplicate_data";

/// Registers the sequence nodes of this module.
pub fn register(registry: &mut NodeRegistry) {
    for t in [
        cull_pattern(),
        cull_index(),
        cull_nth(),
        repeat_data(),
        duplicate_data(),
    ] {
        registry.register(t);
    }
}

fn sequence_node(id: &str, name: &str, nickname: &str) -> NodeType {
    NodeType::new(id, name, nickname, "Sets").subcategory("Sequence")
}

fn generic_list(name: &str, nickname: &str, doc: &str) -> Port {
    Port::new(name, nickname, DataType::Generic).list().doc(doc)
}

/// Cull Pattern \[Cull\]: the items of a list kept or removed by a repeating pattern.
pub fn cull_pattern() -> NodeType {
    sequence_node(CULL_PATTERN, "Cull Pattern", "Cull")
        .gh_guid("008e9a6f-478a-4813-8c8a-546273bc3a6b")
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

/// Cull Index \[Cull i\]: the items at given indices removed from a list.
pub fn cull_index() -> NodeType {
    sequence_node(CULL_INDEX, "Cull Index", "Cull i")
        .gh_guid("501aecbb-c191-4d13-83d6-7ee32445ac50")
        .description(
            "Removes the items at the indices I from a list and keeps the rest in order. With \
             Wrap, indices wrap around the list (−1 is the last item); without, indices outside \
             the list remove nothing. An index given twice removes its item once; null indices \
             are ignored.",
        )
        .input(generic_list("List", "L", "The list to cull, of any type."))
        .input(
            Port::new("Indices", "I", DataType::Integer)
                .list()
                .optional()
                .doc("The indices of the items to remove, from 0; none removes nothing."),
        )
        .input(
            Port::new("Wrap", "W", DataType::Boolean)
                .doc("Whether indices wrap around the list bounds; default false.")
                .default_value(false),
        )
        .output(generic_list("List", "L", "The items not culled, in order."))
        .solve(|s| {
            let Some(branch) = s.branch(0) else {
                return Ok(());
            };
            let wrap = *s.item::<bool>(2)?;
            let n = branch.len();
            let mut cull = vec![false; n];
            if n > 0 {
                for &index in s.list::<i64>(1)?.present() {
                    let target = if wrap {
                        usize::try_from(index.rem_euclid(n as i64)).ok()
                    } else {
                        usize::try_from(index).ok().filter(|&i| i < n)
                    };
                    if let Some(i) = target {
                        cull[i] = true;
                    }
                }
            }
            s.set_branch(0, branch.gather((0..n).filter(|&i| !cull[i]).map(Some)));
            Ok(())
        })
}

/// Cull Nth \[CullN\]: every Nth item removed from a list.
pub fn cull_nth() -> NodeType {
    sequence_node(CULL_NTH, "Cull Nth", "CullN")
        .description(
            "Removes every Nth item from a list: the items at indices N − 1, 2N − 1, … go, so \
             N = 2 keeps the items at even indices and N = 1 removes every item. N must be at \
             least 1.",
        )
        .input(generic_list("List", "L", "The list to cull, of any type."))
        .input(
            Port::new("Cull frequency", "N", DataType::Integer)
                .doc("The cull frequency N, 1 or more: every Nth item is removed."),
        )
        .output(generic_list("List", "L", "The items not culled, in order."))
        .solve(|s| {
            let Some(branch) = s.branch(0) else {
                return Ok(());
            };
            let n = *s.item::<i64>(1)?;
            let Some(n) = usize::try_from(n).ok().filter(|&n| n >= 1) else {
                return Err(NodeError(format!(
                    "cull frequency N must be at least 1, not {n}"
                )));
            };
            let len = branch.len();
            s.set_branch(
                0,
                branch.gather((0..len).filter(|i| (i + 1) % n != 0).map(Some)),
            );
            Ok(())
        })
}

/// `value` as a result length, 0 to [`MAX_SEQUENCE_LENGTH`], naming it `what`.
fn result_length(value: i64, what: &str) -> Result<usize, NodeError> {
    match usize::try_from(value) {
        Ok(n) if n <= MAX_SEQUENCE_LENGTH => Ok(n),
        Ok(_) => Err(NodeError(format!(
            "{what} must be at most {MAX_SEQUENCE_LENGTH}, not {value}"
        ))),
        Err(_) => Err(NodeError(format!("{what} must be at least 0, not {value}"))),
    }
}

/// Repeat Data \[Repeat\]: a list repeated until it has a given length.
pub fn repeat_data() -> NodeType {
    sequence_node(REPEAT_DATA, "Repeat Data", "Repeat")
        .gh_guid("c40dc145-9e36-4a69-ac1a-6d825c654993")
        .description(
            "Repeats a pattern of items until the result has L items: item k of the result is \
             item k mod (pattern length) of D, so the last repetition may be cut short and an L \
             shorter than the pattern truncates it.",
        )
        .input(generic_list(
            "Data",
            "D",
            "The pattern to repeat, of any type.",
        ))
        .input(Port::new("Length", "L", DataType::Integer).doc(&format!(
            "The length of the result, 0 to {MAX_SEQUENCE_LENGTH}."
        )))
        .output(generic_list("Data", "D", "The repeated data, L items."))
        .solve(|s| {
            let Some(pattern) = s.branch(0) else {
                return Ok(());
            };
            let length = result_length(*s.item::<i64>(1)?, "length L")?;
            let n = pattern.len();
            let mut out = Branch::from_column(Column::with_capacity(pattern.data_type(), length));
            let mut done = 0;
            while n > 0 && done < length {
                let take = n.min(length - done);
                out.extend_range(pattern, 0..take);
                done += take;
            }
            s.set_branch(0, out);
            Ok(())
        })
}

/// Duplicate Data \[Dup\]: a list duplicated a number of times.
pub fn duplicate_data() -> NodeType {
    sequence_node(DUPLICATE_DATA, "Duplicate Data", "Dup")
        .gh_guid("dd8134c0-109b-4012-92be-51d843edfff7")
        .description(
            "Duplicates the items of a list N times. With Order the whole list is repeated \
             ([a, b] twice is [a, b, a, b]); without, each item is repeated in place ([a, a, b, \
             b]).",
        )
        .input(generic_list(
            "Data",
            "D",
            "The data to duplicate, of any type.",
        ))
        .input(
            Port::new("Number", "N", DataType::Integer)
                .doc("The number of copies, 0 or more; default 2.")
                .default_value(2_i64),
        )
        .input(
            Port::new("Order", "O", DataType::Boolean)
                .doc(
                    "Retain the list order (repeat the whole list) rather than repeating each \
                      item in place; default true.",
                )
                .default_value(true),
        )
        .output(generic_list("Data", "D", "The duplicated data."))
        .solve(|s| {
            let Some(data) = s.branch(0) else {
                return Ok(());
            };
            let copies = *s.item::<i64>(1)?;
            let order = *s.item::<bool>(2)?;
            let n = data.len();
            let total = usize::try_from(copies)
                .ok()
                .and_then(|c| c.checked_mul(n))
                .unwrap_or(usize::MAX);
            if copies < 0 {
                return Err(NodeError(format!(
                    "number N must be at least 0, not {copies}"
                )));
            }
            if total > MAX_SEQUENCE_LENGTH {
                return Err(NodeError(format!(
                    "{copies} copies of {n} items would be more than {MAX_SEQUENCE_LENGTH} items"
                )));
            }
            let copies = total.checked_div(n).unwrap_or(0);
            let mut out = Branch::from_column(Column::with_capacity(data.data_type(), total));
            if order {
                for _ in 0..copies {
                    out.extend_range(data, 0..n);
                }
            } else {
                for i in 0..n {
                    for _ in 0..copies {
                        out.extend_range(data, i..i + 1);
                    }
                }
            }
            s.set_branch(0, out);
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

    #[test]
    fn cull_index_with_and_without_wrap() {
        let run = |indices: Vec<i64>, wrap: bool| {
            let r = NodeCall::new(&cull_index())
                .input(generic("{0}:[0, \"a\", null, 3]"))
                .input(DataTree::from_list(indices))
                .input(DataTree::from_item(wrap))
                .run();
            assert_clean(&r);
            r.outputs[0].to_text()
        };
        assert_eq!(run(vec![1, 1, 9, -1], false), "{0;0}:[0, null, 3]");
        assert_eq!(run(vec![-1, 5], true), "{0;0}:[0, null]");
        assert_eq!(run(vec![], true), "{0;0}:[0, \"a\", null, 3]");
    }

    #[test]
    fn cull_nth_removes_every_nth_item() {
        let run = |n: i64| {
            NodeCall::new(&cull_nth())
                .input(tree("{0}:[0, 1, 2, 3, 4, 5, 6]"))
                .input(DataTree::from_item(n))
                .run()
        };
        assert_eq!(run(2).outputs[0].to_text(), "{0;0}:[0, 2, 4, 6]");
        assert_eq!(run(3).outputs[0].to_text(), "{0;0}:[0, 1, 3, 4, 6]");
        assert_eq!(run(1).outputs[0].to_text(), "{0;0}:[]");
        assert_eq!(run(100).outputs[0].to_text(), "{0;0}:[0, 1, 2, 3, 4, 5, 6]");
        let r = run(0);
        assert_eq!(
            crate::sets::test_support::messages(&r, locus_runtime::Level::Error),
            ["cull frequency N must be at least 1, not 0"]
        );
    }

    #[test]
    fn repeat_data_to_a_length() {
        let run = |list: &str, length: i64| {
            NodeCall::new(&repeat_data())
                .input(generic(list))
                .input(DataTree::from_item(length))
                .run()
        };
        assert_eq!(
            run("{0}:[1, \"b\", null]", 7).outputs[0].to_text(),
            "{0;0}:[1, \"b\", null, 1, \"b\", null, 1]"
        );
        assert_eq!(run("{0}:[1, 2, 3]", 2).outputs[0].to_text(), "{0;0}:[1, 2]");
        assert_eq!(run("{0}:[1, 2, 3]", 0).outputs[0].to_text(), "{0;0}:[]");
        assert_eq!(run("{0}:[]", 4).outputs[0].to_text(), "{0;0}:[]");
        let r = run("{0}:[1]", -1);
        assert_eq!(
            crate::sets::test_support::messages(&r, locus_runtime::Level::Error),
            ["length L must be at least 0, not -1"]
        );
        let r = run("{0}:[1]", i64::MAX);
        assert_eq!(
            crate::sets::test_support::messages(&r, locus_runtime::Level::Error).len(),
            1
        );
    }

    #[test]
    fn duplicate_data_in_order_or_in_place() {
        let run = |n: i64, order: bool| {
            NodeCall::new(&duplicate_data())
                .input(generic("{0}:[\"a\", null, 3]"))
                .input(DataTree::from_item(n))
                .input(DataTree::from_item(order))
                .run()
        };
        assert_eq!(
            run(2, true).outputs[0].to_text(),
            "{0;0}:[\"a\", null, 3, \"a\", null, 3]"
        );
        assert_eq!(
            run(2, false).outputs[0].to_text(),
            "{0;0}:[\"a\", \"a\", null, null, 3, 3]"
        );
        assert_eq!(run(0, true).outputs[0].to_text(), "{0;0}:[]");
        let r = run(-2, true);
        assert_eq!(
            crate::sets::test_support::messages(&r, locus_runtime::Level::Error),
            ["number N must be at least 0, not -2"]
        );
        let r = run(i64::MAX, true);
        assert_eq!(
            crate::sets::test_support::messages(&r, locus_runtime::Level::Error),
            ["9223372036854775807 copies of 3 items would be more than 10000000 items"]
        );
    }
}

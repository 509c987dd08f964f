//! Sets › List: List Item, List Length, Reverse List, Shift List, Sort List and Dispatch.
//!
//! Every node here works on lists of any type (generic data) and keeps the items typed:
//! reordering, shifting and dispatching copy typed runs of the branch
//! ([`Branch::gather`], [`Branch::extend_range`]). Null items are kept wherever their item is
//! kept.

use std::cmp::Ordering;

use locus_runtime::{Branch, Column, DataType, NodeError, NodeRegistry, NodeType, Port, Value};

use super::pick_index;

/// Id of [`list_item`].
pub const LIST_ITEM: &str = "sets.list_item";
/// Id of [`list_length`].
pub const LIST_LENGTH: &str = "sets.list_length";
/// Id of [`reverse_list`].
pub const REVERSE_LIST: &str = "sets.reverse_list";
/// Id of [`shift_list`].
pub const SHIFT_LIST: &str = "sets.shift_list";
/// Id of [`sort_list`].
pub const SORT_LIST: &str = "sets.sort_list";
/// Id of [`dispatch`].
pub const DISPATCH: &str = "sets.dispatch";

/// Registers the list nodes.
pub fn register(registry: &mut NodeRegistry) {
    for t in [
        list_item(),
        list_length(),
        reverse_list(),
        shift_list(),
        sort_list(),
        dispatch(),
    ] {
        registry.register(t);
    }
}

fn list_node(id: &str, name: &str, nickname: &str) -> NodeType {
    NodeType::new(id, name, nickname, "Sets").subcategory("List")
}

fn list_input(doc: &str) -> Port {
    Port::new("List", "L", DataType::Generic).list().doc(doc)
}

fn list_output(doc: &str) -> Port {
    Port::new("List", "L", DataType::Generic).list().doc(doc)
}

/// The branch of list input `input`, or an empty generic branch when it has none.
fn branch_or_empty<'a>(s: &locus_runtime::Solve<'a>, input: usize) -> std::borrow::Cow<'a, Branch> {
    match s.branch(input) {
        Some(b) => std::borrow::Cow::Borrowed(b),
        None => std::borrow::Cow::Owned(Branch::new(DataType::Generic)),
    }
}

/// List Item \[Item\]: the item at an index of a list, and at offsets from it.
pub fn list_item() -> NodeType {
    list_node(LIST_ITEM, "List Item", "Item")
        .gh_guid("59daf374-bc21-4a5e-8282-5504fb7ae9ae")
        .description(
            "Retrieves the item at index i of a list. With Wrap, indices wrap around the list \
             (i = length is the first item again, −1 the last); without, an index outside the \
             list gives a null and a warning naming it. A null item stays null. The outputs \
             are variable, as when the component is zoomed in Grasshopper: an output named \
             `i` gives the item at i, one named `+k` or `-k` the item at i + k or i − k \
             (Grasshopper's `+1`, `+2`, …); an output with another name gives the item at i \
             plus its position among the outputs.",
        )
        .input(list_input("The list to pick from, of any type."))
        .input(
            Port::new("Index", "i", DataType::Integer)
                .doc("The index of the item, from 0; default 0.")
                .default_value(0_i64),
        )
        .input(
            Port::new("Wrap", "W", DataType::Boolean)
                .doc("Whether indices wrap around the list bounds; default true.")
                .default_value(true),
        )
        .variable_outputs(
            Port::new("Item", "i", DataType::Generic)
                .doc("The item at index i plus this output's offset (`i`, `+1`, `-1`, …)."),
            &["i"],
        )
        .solve(|s| {
            let branch = branch_or_empty(s, 0);
            let index = *s.item::<i64>(1)?;
            let wrap = *s.item::<bool>(2)?;
            for output in 0..s.output_count() {
                let name = s.output_port(output).map_or("i", |p| p.nickname.as_str());
                let offset = item_offset(name, output);
                if branch.is_empty() {
                    // Only reached for a list the runtime did not skip; nothing to pick.
                    s.set_value(output, None);
                    continue;
                }
                let Some(at) = index.checked_add(offset) else {
                    s.warning(format!("index {index} + {offset} does not fit an integer"));
                    s.set_value(output, None);
                    continue;
                };
                match pick_index(at, branch.len(), wrap) {
                    Ok(i) => s.set_value(output, branch.value(i)),
                    Err(why) => {
                        s.warning(why);
                        s.set_value(output, None);
                    }
                }
            }
            Ok(())
        })
}

/// The offset from i of a List Item output: `i` 0, `+k` k, `-k` −k, any other name its
/// position among the outputs.
fn item_offset(name: &str, position: usize) -> i64 {
    let name = name.trim();
    if name == "i" {
        return 0;
    }
    if (name.starts_with('+') || name.starts_with('-'))
        && let Ok(k) = name.parse::<i64>()
    {
        return k;
    }
    i64::try_from(position).unwrap_or(i64::MAX)
}

/// List Length \[Lng\]: the number of items of a list.
pub fn list_length() -> NodeType {
    list_node(LIST_LENGTH, "List Length", "Lng")
        .gh_guid("1817fd29-20ae-4503-b542-f0fb651e67d7")
        .description("Counts the items of a list, null items included; an empty list has length 0.")
        .input(list_input("The list to measure, of any type.").optional())
        .output(
            Port::new("Length", "L", DataType::Integer)
                .doc("The number of items in L, nulls included."),
        )
        .solve(|s| {
            match s.branch(0) {
                Some(b) => s.set(0, i64::try_from(b.len()).unwrap_or(i64::MAX)),
                None => s.warning("input parameter L failed to collect data"),
            }
            Ok(())
        })
}

/// Reverse List \[Rev\]: the items of a list in reverse order.
pub fn reverse_list() -> NodeType {
    list_node(REVERSE_LIST, "Reverse List", "Rev")
        .gh_guid("6ec97ea8-c559-47a2-8d0f-ce80c794d1f4")
        .description("Reverses the order of the items of a list; null items stay in place.")
        .input(list_input("The list to reverse, of any type."))
        .output(list_output("The items of L, last first."))
        .solve(|s| {
            let mut b = branch_or_empty(s, 0).into_owned();
            b.reverse();
            s.set_branch(0, b);
            Ok(())
        })
}

/// Shift List \[Shift\]: the items of a list moved by an offset.
pub fn shift_list() -> NodeType {
    list_node(SHIFT_LIST, "Shift List", "Shift")
        .gh_guid("4fdfe351-6c07-47ce-9fb9-be027fb62186")
        .description(
            "Offsets the items of a list: item k of the result is item k + S of L. With Wrap, \
             the items shifted off one end come back at the other, so the list keeps its \
             length ([a, b, c, d] shifted by 1 is [b, c, d, a], by −1 [d, a, b, c]); without, \
             they are dropped and the list gets shorter ([b, c, d] and [a, b, c]).",
        )
        .input(list_input("The list to shift, of any type."))
        .input(
            Port::new("Shift", "S", DataType::Integer)
                .doc("The offset, in items; positive moves items towards the start; default 1.")
                .default_value(1_i64),
        )
        .input(
            Port::new("Wrap", "W", DataType::Boolean)
                .doc("Whether items shifted off one end reappear at the other; default true.")
                .default_value(true),
        )
        .output(list_output("The shifted list."))
        .solve(|s| {
            let branch = branch_or_empty(s, 0);
            let shift = *s.item::<i64>(1)?;
            let wrap = *s.item::<bool>(2)?;
            s.set_branch(0, shifted(&branch, shift, wrap));
            Ok(())
        })
}

/// `branch` shifted by `shift` items (see [`shift_list`]).
fn shifted(branch: &Branch, shift: i64, wrap: bool) -> Branch {
    let len = branch.len();
    let mut out = Branch::from_column(Column::with_capacity(branch.data_type(), len));
    if len == 0 {
        return out;
    }
    let n = i64::try_from(len).unwrap_or(i64::MAX);
    if wrap {
        let k = usize::try_from(shift.rem_euclid(n)).unwrap_or(0);
        out.extend_range(branch, k..len);
        out.extend_range(branch, 0..k);
    } else if shift >= 0 {
        let k = usize::try_from(shift.min(n)).unwrap_or(len);
        out.extend_range(branch, k..len);
    } else {
        let k = usize::try_from(shift.unsigned_abs().min(len as u64)).unwrap_or(len);
        out.extend_range(branch, 0..len - k);
    }
    out
}

/// Sort List \[Sort\]: a list of keys sorted, and a list of values in the same order.
pub fn sort_list() -> NodeType {
    list_node(SORT_LIST, "Sort List", "Sort")
        .gh_guid("6f93d366-919f-4dda-a35e-ba03dd62799b")
        .gh_guid("cacb2c64-61b5-46db-825d-c61d5d09cc08")
        .description(
            "Sorts a list of keys in ascending order and puts the values A in the same order \
             as their keys. Keys are numbers (integers and booleans count as numbers) or texts \
             (compared character by character, by Unicode code point); the sort is stable, so \
             equal keys keep their order. NaN keys come after all numbers and null keys last. \
             Keys that mix texts with numbers, or of another type, are an error.",
        )
        .input(
            Port::new("Keys", "K", DataType::Generic)
                .list()
                .doc("The keys to sort: numbers or texts."),
        )
        .input(
            Port::new("Values A", "A", DataType::Generic)
                .list()
                .optional()
                .doc("Values to sort along with the keys, one per key, of any type; optional."),
        )
        .output(list_output_named(
            "Keys",
            "K",
            "The keys in ascending order.",
        ))
        .output(list_output_named(
            "Values A",
            "A",
            "The values A in the order of their keys.",
        ))
        .solve(|s| {
            let keys = branch_or_empty(s, 0);
            let order = sort_order(&keys)?;
            s.set_branch(0, keys.gather(order.iter().map(|&i| Some(i))));
            if let Some(values) = s.branch(1) {
                if values.len() != keys.len() {
                    return Err(NodeError(format!(
                        "values A has {} items but keys K has {}: give one value per key",
                        values.len(),
                        keys.len()
                    )));
                }
                s.set_branch(1, values.gather(order.iter().map(|&i| Some(i))));
            }
            Ok(())
        })
}

fn list_output_named(name: &str, nickname: &str, doc: &str) -> Port {
    Port::new(name, nickname, DataType::Generic).list().doc(doc)
}

/// A sort key: a number, a text, or a null (which sorts last).
#[derive(Clone, Copy, Debug)]
enum Key<'a> {
    Number(f64),
    Text(&'a str),
    Null,
}

/// The stable ascending order of the keys of `branch`, as indices.
fn sort_order(branch: &Branch) -> Result<Vec<usize>, NodeError> {
    let keys = sort_keys(branch)?;
    let mut order: Vec<usize> = (0..keys.len()).collect();
    order.sort_by(|&a, &b| compare_keys(keys[a], keys[b]));
    Ok(order)
}

fn sort_keys(branch: &Branch) -> Result<Vec<Key<'_>>, NodeError> {
    let null = |i: usize| branch.is_null(i);
    let keys: Vec<Key<'_>> = match branch.column() {
        Column::Number(v) => (0..v.len())
            .map(|i| {
                if null(i) {
                    Key::Null
                } else {
                    Key::Number(v[i])
                }
            })
            .collect(),
        Column::Integer(v) => (0..v.len())
            .map(|i| {
                if null(i) {
                    Key::Null
                } else {
                    Key::Number(v[i] as f64)
                }
            })
            .collect(),
        Column::Boolean(v) => (0..v.len())
            .map(|i| {
                if null(i) {
                    Key::Null
                } else {
                    Key::Number(f64::from(u8::from(v[i])))
                }
            })
            .collect(),
        Column::Text(v) => (0..v.len())
            .map(|i| if null(i) { Key::Null } else { Key::Text(&v[i]) })
            .collect(),
        Column::Generic(v) => {
            let mut keys = Vec::with_capacity(v.len());
            for (i, value) in v.iter().enumerate() {
                keys.push(match value {
                    _ if null(i) => Key::Null,
                    Value::Number(x) => Key::Number(*x),
                    Value::Integer(x) => Key::Number(*x as f64),
                    Value::Boolean(b) => Key::Number(f64::from(u8::from(*b))),
                    Value::Text(t) => Key::Text(t),
                    other => return Err(unsortable(i, other.data_type())),
                });
            }
            keys
        }
        other => {
            return match (0..other.len()).find(|&i| !null(i)) {
                Some(i) => Err(unsortable(i, other.data_type())),
                None => Ok(vec![Key::Null; other.len()]),
            };
        }
    };
    let number = keys.iter().position(|k| matches!(k, Key::Number(_)));
    let text = keys.iter().position(|k| matches!(k, Key::Text(_)));
    if let (Some(n), Some(t)) = (number, text) {
        return Err(NodeError(format!(
            "keys K mix numbers (item {n}) and texts (item {t}); sort one kind at a time"
        )));
    }
    Ok(keys)
}

fn unsortable(index: usize, data_type: DataType) -> NodeError {
    NodeError(format!(
        "keys K must be numbers or texts; item {index} is a {data_type}"
    ))
}

fn compare_keys(a: Key<'_>, b: Key<'_>) -> Ordering {
    match (a, b) {
        (Key::Number(x), Key::Number(y)) => match (x.is_nan(), y.is_nan()) {
            (false, false) => x.partial_cmp(&y).unwrap_or(Ordering::Equal),
            (true, true) => Ordering::Equal,
            (true, false) => Ordering::Greater,
            (false, true) => Ordering::Less,
        },
        (Key::Text(x), Key::Text(y)) => x.cmp(y),
        (Key::Null, Key::Null) => Ordering::Equal,
        (Key::Null, _) => Ordering::Greater,
        (_, Key::Null) => Ordering::Less,
        // Mixed kinds are rejected before sorting.
        _ => Ordering::Equal,
    }
}

/// Dispatch \[Dispatch\]: the items of a list split into two lists by a repeating pattern.
pub fn dispatch() -> NodeType {
    list_node(DISPATCH, "Dispatch", "Dispatch")
        .gh_guid("d8332545-21b2-4716-96e3-8559a9876e17")
        .description(
            "Sends each item of a list to List A or List B by a pattern of booleans, repeated \
             as often as needed: item k goes to A when pattern item k mod (pattern length) is \
             true, else to B. A null in the pattern counts as false; null items are dispatched \
             like any other.",
        )
        .input(list_input("The list to dispatch, of any type."))
        .input(
            Port::new("Dispatch pattern", "P", DataType::Boolean)
                .list()
                .doc("The pattern of booleans, repeated along the list."),
        )
        .output(list_output_named(
            "List A",
            "A",
            "The items whose pattern value is true.",
        ))
        .output(list_output_named(
            "List B",
            "B",
            "The items whose pattern value is false.",
        ))
        .solve(|s| {
            let branch = branch_or_empty(s, 0);
            let pattern = pattern_of(s, 1)?;
            let (a, b) = split_by_pattern(&branch, &pattern);
            s.set_branch(0, a);
            s.set_branch(1, b);
            Ok(())
        })
}

/// The boolean pattern of list input `input`, nulls as false.
pub(crate) fn pattern_of(
    s: &locus_runtime::Solve<'_>,
    input: usize,
) -> Result<Vec<bool>, NodeError> {
    let list = s.list::<bool>(input)?;
    Ok(list.iter().map(|b| b.copied().unwrap_or(false)).collect())
}

/// The items of `branch` whose repeated pattern value is true, and those whose value is false.
/// An empty pattern sends every item to the second list.
pub(crate) fn split_by_pattern(branch: &Branch, pattern: &[bool]) -> (Branch, Branch) {
    let keep = |i: usize| !pattern.is_empty() && pattern[i % pattern.len()];
    let n = branch.len();
    let a = branch.gather((0..n).filter(|&i| keep(i)).map(Some));
    let b = branch.gather((0..n).filter(|&i| !keep(i)).map(Some));
    (a, b)
}

#[cfg(test)]
mod tests {
    use locus_runtime::{DataTree, Level, NodeCall, TreePath};

    use super::*;
    use crate::sets::test_support::{assert_clean, generic, messages, tree};

    fn item(list: &str, index: i64, wrap: bool) -> locus_runtime::NodeCallResult {
        NodeCall::new(&list_item())
            .input(generic(list))
            .input(DataTree::from_item(index))
            .input(DataTree::from_item(wrap))
            .run()
    }

    #[test]
    fn list_item_picks_wraps_and_warns() {
        let r = item("{0}:[10, 20, 30]", 1, true);
        assert_clean(&r);
        assert_eq!(r.outputs[0].to_text(), "{0}:[20]");
        assert_eq!(
            item("{0}:[10, 20, 30]", 4, true).outputs[0].to_text(),
            "{0}:[20]"
        );
        assert_eq!(
            item("{0}:[10, 20, 30]", -1, true).outputs[0].to_text(),
            "{0}:[30]"
        );
        let r = item("{0}:[10, 20, 30]", 3, false);
        assert_eq!(r.outputs[0].to_text(), "{0}:[null]");
        assert_eq!(
            messages(&r, Level::Warning),
            ["index 3 is out of range for a list of 3 items (0 to 2)"]
        );
        let r = item("{0}:[10, 20, 30]", -1, false);
        assert_eq!(r.outputs[0].to_text(), "{0}:[null]");
        assert_eq!(messages(&r, Level::Warning).len(), 1);
    }

    #[test]
    fn list_item_on_mixed_types_nulls_and_several_indices() {
        let r = NodeCall::new(&list_item())
            .input(generic("{0}:[\"a\", true, {1, 2, 3}, null]"))
            .input(DataTree::from_list(vec![0_i64, 1, 2, 3, 5]))
            .run();
        assert_clean(&r);
        assert_eq!(
            r.outputs[0].to_text(),
            "{0}:[\"a\", true, {1, 2, 3}, null, true]"
        );
    }

    #[test]
    fn list_item_outputs_at_offsets_as_grasshopper_zoomed() {
        let r = NodeCall::new(&list_item())
            .output_names(&["-1", "i", "+1", "+2", "next"])
            .input(generic("{0}:[10, 20, 30]"))
            .input(DataTree::from_item(1_i64))
            .input(DataTree::from_item(false))
            .run();
        let texts: Vec<String> = r.outputs.iter().map(|o| o.to_text()).collect();
        assert_eq!(
            texts,
            [
                "{0}:[10]",
                "{0}:[20]",
                "{0}:[30]",
                "{0}:[null]",
                "{0}:[null]"
            ]
        );
        // +2 and the fifth output (offset 4) fall outside without Wrap: one warning each.
        assert_eq!(messages(&r, Level::Warning).len(), 2);
        let r = NodeCall::new(&list_item())
            .output_names(&["i", "+1", "+2", "+3"])
            .input(generic("{0}:[10, 20, 30]"))
            .input(DataTree::from_item(i64::MAX))
            .input(DataTree::from_item(true))
            .run();
        assert_eq!(r.outputs[0].to_text(), "{0}:[20]");
        assert_eq!(r.outputs[1].to_text(), "{0}:[null]");
        assert_eq!(messages(&r, Level::Warning).len(), 3);
    }

    #[test]
    fn list_item_on_an_empty_list_is_null() {
        let r = item("{0}:[]", 0, true);
        assert_eq!(r.outputs[0].to_text(), "{0}:[null]");
    }

    #[test]
    fn list_item_keeps_branches() {
        let r = NodeCall::new(&list_item())
            .input(tree("{0;0}:[1, 2] {0;1}:[3, 4, 5]"))
            .input(DataTree::from_item(-1_i64))
            .run();
        assert_eq!(r.outputs[0].to_text(), "{0;0}:[2] {0;1}:[5]");
    }

    #[test]
    fn list_length_counts_nulls_and_empty_lists() {
        let r = NodeCall::new(&list_length())
            .input(generic("{0}:[1, null, \"x\"] {1}:[]"))
            .run();
        assert_clean(&r);
        assert_eq!(r.outputs[0].to_text(), "{0}:[3] {1}:[0]");
        let r = NodeCall::new(&list_length()).run();
        assert_eq!(
            messages(&r, Level::Warning),
            ["input parameter L failed to collect data"]
        );
    }

    #[test]
    fn reverse_list_keeps_nulls_and_types() {
        let r = NodeCall::new(&reverse_list())
            .input(tree("{0}:[1, null, 3] {1}:[]"))
            .run();
        assert_eq!(r.outputs[0].to_text(), "{0}:[3, null, 1] {1}:[]");
        let b = r.outputs[0].branch(&TreePath::zero()).unwrap();
        assert_eq!(b.data_type(), DataType::Number);
        let r = NodeCall::new(&reverse_list())
            .input(generic("{0}:[\"a\", 2]"))
            .run();
        assert_eq!(r.outputs[0].to_text(), "{0}:[2, \"a\"]");
    }

    fn shift(list: &str, by: i64, wrap: bool) -> String {
        let r = NodeCall::new(&shift_list())
            .input(tree(list))
            .input(DataTree::from_item(by))
            .input(DataTree::from_item(wrap))
            .run();
        assert_clean(&r);
        r.outputs[0].to_text()
    }

    #[test]
    fn shift_list_wraps_or_shortens() {
        let l = "{0}:[1, 2, 3, 4]";
        assert_eq!(shift(l, 1, true), "{0;0}:[2, 3, 4, 1]");
        assert_eq!(shift(l, -1, true), "{0;0}:[4, 1, 2, 3]");
        assert_eq!(shift(l, 6, true), "{0;0}:[3, 4, 1, 2]");
        assert_eq!(shift(l, 0, true), "{0;0}:[1, 2, 3, 4]");
        assert_eq!(shift(l, 1, false), "{0;0}:[2, 3, 4]");
        assert_eq!(shift(l, -1, false), "{0;0}:[1, 2, 3]");
        assert_eq!(shift(l, 9, false), "{0;0}:[]");
        assert_eq!(shift(l, i64::MIN, false), "{0;0}:[]");
        assert_eq!(shift(l, i64::MIN, true), "{0;0}:[1, 2, 3, 4]");
        assert_eq!(shift("{0}:[1, null, 3]", 1, true), "{0;0}:[null, 3, 1]");
    }

    #[test]
    fn shift_list_of_an_empty_list_is_empty() {
        assert_eq!(shift("{0}:[]", 1, true), "{0;0}:[]");
    }

    fn sort(keys: DataTree, values: Option<DataTree>) -> locus_runtime::NodeCallResult {
        let node = sort_list();
        let call = NodeCall::new(&node).input(keys);
        match values {
            Some(v) => call.input(v).run(),
            None => call.run(),
        }
    }

    #[test]
    fn sort_list_sorts_numbers_with_values_stably() {
        let r = sort(
            tree("{0}:[3, 1, 2, 1, NaN, null, -5]"),
            Some(generic(
                "{0}:[\"c\", \"a1\", \"b\", \"a2\", \"nan\", \"null\", \"neg\"]",
            )),
        );
        assert_clean(&r);
        assert_eq!(r.outputs[0].to_text(), "{0}:[-5, 1, 1, 2, 3, NaN, null]");
        assert_eq!(
            r.outputs[1].to_text(),
            "{0}:[\"neg\", \"a1\", \"a2\", \"b\", \"c\", \"nan\", \"null\"]"
        );
    }

    #[test]
    fn sort_list_sorts_texts_and_mixed_numbers() {
        let r = sort(generic("{0}:[\"pear\", \"Apple\", \"apple\"]"), None);
        assert_clean(&r);
        assert_eq!(
            r.outputs[0].to_text(),
            "{0}:[\"Apple\", \"apple\", \"pear\"]"
        );
        let mut keys = Branch::new(DataType::Generic);
        keys.push_value(Value::Integer(3));
        keys.push_value(Value::Number(2.5));
        keys.push_value(Value::Boolean(true));
        let r = sort(
            DataTree::from_branches([(TreePath::zero(), keys)]),
            Some(tree("{0}:[0, 1, 2]")),
        );
        assert_eq!(r.outputs[1].to_text(), "{0}:[2, 1, 0]");
    }

    #[test]
    fn sort_list_rejects_unsortable_keys_and_mismatched_values() {
        let r = sort(generic("{0}:[1, \"a\"]"), None);
        assert_eq!(
            messages(&r, Level::Error),
            ["keys K mix numbers (item 0) and texts (item 1); sort one kind at a time"]
        );
        let r = sort(generic("{0}:[{1, 2, 3}]"), None);
        assert_eq!(
            messages(&r, Level::Error),
            ["keys K must be numbers or texts; item 0 is a Point"]
        );
        let r = sort(tree("{0}:[2, 1]"), Some(tree("{0}:[1]")));
        assert_eq!(
            messages(&r, Level::Error),
            ["values A has 1 items but keys K has 2: give one value per key"]
        );
        assert_eq!(r.outputs[0].to_text(), "{0}:[1, 2]");
        assert_eq!(r.outputs[1].item_count(), 0);
    }

    #[test]
    fn sort_list_of_an_empty_list_is_empty() {
        let r = sort(tree("{0}:[]"), None);
        assert_eq!(r.outputs[0].to_text(), "{0}:[]");
    }

    #[test]
    fn dispatch_repeats_the_pattern() {
        let pattern = DataTree::from_list(vec![true, false, false]);
        let r = NodeCall::new(&dispatch())
            .input(generic("{0}:[0, \"a\", 2, 3, null, 5, 6]"))
            .input(pattern)
            .run();
        assert_clean(&r);
        assert_eq!(r.outputs[0].to_text(), "{0}:[0, 3, 6]");
        assert_eq!(r.outputs[1].to_text(), "{0}:[\"a\", 2, null, 5]");
    }

    #[test]
    fn dispatch_treats_null_pattern_items_as_false_and_keeps_types() {
        let mut p = Branch::new(DataType::Boolean);
        p.push(true);
        p.push_null();
        let r = NodeCall::new(&dispatch())
            .input(tree("{0}:[1, 2, 3, 4]"))
            .input(DataTree::from_branches([(TreePath::zero(), p)]))
            .run();
        assert_eq!(r.outputs[0].to_text(), "{0}:[1, 3]");
        assert_eq!(r.outputs[1].to_text(), "{0}:[2, 4]");
        let a = r.outputs[0].branch(&TreePath::zero()).unwrap();
        assert_eq!(a.data_type(), DataType::Number);
        let r = NodeCall::new(&dispatch())
            .input(tree("{0}:[]"))
            .input(DataTree::from_item(true))
            .run();
        assert_eq!(r.outputs[0].to_text(), "{0}:[]");
    }
}

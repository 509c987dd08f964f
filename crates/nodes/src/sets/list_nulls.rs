//! Sets › List, filling gaps: Replace Nulls and Combine Data.
//!
//! Replace Nulls fills the nulls (and invalid items, as Null Item defines them) of a list from
//! a list of replacements; Combine Data takes, item by item, the first non-null item of
//! several inputs. Combine Data has a variable number of inputs (`inputs: ["0", "1", "2"]`).

use locus_runtime::{Branch, DataType, NodeError, NodeRegistry, NodeType, Port};

use super::list_edit::invalid_reason;
use super::set_ops::list_of;

/// Id of [`replace_nulls`].
pub const REPLACE_NULLS: &str = "sets.replace_nulls";
/// Id of [`combine_data`].
pub const COMBINE_DATA: &str = "sets.combine_data";

/// Registers the gap-filling list nodes.
pub fn register(registry: &mut NodeRegistry) {
    for t in [replace_nulls(), combine_data()] {
        registry.register(t);
    }
}

fn list_node(id: &str, name: &str, nickname: &str) -> NodeType {
    NodeType::new(id, name, nickname, "Sets").subcategory("List")
}

/// Replace Nulls \[NullRep\]: nulls and invalid items replaced from a list.
pub fn replace_nulls() -> NodeType {
    list_node(REPLACE_NULLS, "Replace Nulls", "NullRep")
        .gh_guid("f3230ecb-3631-4d6f-86f2-ef4b2ed37f45")
        .description(
            "Replaces null and invalid items (NaN or infinite numbers, points, vectors and \
             domains that are not finite, invalid planes, lines, circles, arcs and B-reps, as \
             Null Item tells them) with items of R: the first gap gets R's first item, the \
             second its second, and so on, the last item of R repeating when R runs out. \
             Gaps without any replacement are an error.",
        )
        .input(
            Port::new("Items", "I", DataType::Generic)
                .list()
                .doc("The items to test for null, of any type."),
        )
        .input(
            Port::new("Replacements", "R", DataType::Generic)
                .list()
                .optional()
                .doc("The items to replace the gaps with; optional when there is no gap."),
        )
        .output(
            Port::new("Items", "I", DataType::Generic)
                .list()
                .doc("The list without gaps."),
        )
        .output(Port::new("Count", "N", DataType::Integer).doc("The number of items replaced."))
        .solve(|s| {
            let (items, pool) = (list_of(s, 0), list_of(s, 1));
            let mut out = Branch::new(items.data_type());
            let mut replaced = 0_usize;
            for i in 0..items.len() {
                let gap = items.is_null(i)
                    || items.value(i).is_some_and(|v| invalid_reason(&v).is_some());
                if !gap {
                    out.extend_range(&items, i..i + 1);
                    continue;
                }
                if pool.is_empty() {
                    return Err(NodeError(format!(
                        "item {i} is null or invalid and R has no replacements"
                    )));
                }
                let k = replaced.min(pool.len() - 1);
                out.extend_range(&pool, k..k + 1);
                replaced += 1;
            }
            s.set_branch(0, out.narrowed());
            s.set(1, i64::try_from(replaced).unwrap_or(i64::MAX));
            Ok(())
        })
}

/// Combine Data \[Combine\]: the first non-null item of several inputs.
pub fn combine_data() -> NodeType {
    list_node(COMBINE_DATA, "Combine Data", "Combine")
        .gh_guid("e7c80ff6-0299-4303-be36-3080977c14a1")
        .description(
            "Combines non-null items out of several inputs: item by item (longest list), the \
             first input whose item is not null gives the result, and Index names that input. \
             When every input's item is null the result is null and Index is −1. The graph may \
             name more inputs (2, 3, …).",
        )
        .variable_inputs(
            Port::new("Input", "0", DataType::Generic)
                .optional()
                .doc("Data to combine, of any type; optional."),
            &["0", "1"],
        )
        .output(
            Port::new("Result", "R", DataType::Generic)
                .doc("The first non-null item, with as few nulls as possible."),
        )
        .output(
            Port::new("Index", "I", DataType::Integer)
                .doc("The index of the input copied into the result, −1 for none."),
        )
        .solve(|s| {
            for k in 0..s.input_count() {
                if let Some(v) = s.value(k) {
                    s.set_value(0, Some(v));
                    s.set(1, i64::try_from(k).unwrap_or(i64::MAX));
                    return Ok(());
                }
            }
            s.set_value(0, None);
            s.set(1, -1_i64);
            Ok(())
        })
}

#[cfg(test)]
mod tests {
    use locus_runtime::{DataTree, Level, NodeCall, Value};

    use super::*;
    use crate::sets::test_support::{assert_clean, generic, messages, tree};
    use crate::test_support::{all, items, values};

    #[test]
    fn replace_nulls_fills_gaps_in_order_and_repeats_the_last() {
        let r = NodeCall::new(&replace_nulls())
            .input(tree("{0}:[1, null, 3, null, NaN]"))
            .input(tree("{0}:[10, 20]"))
            .run();
        assert_clean(&r);
        assert_eq!(all::<f64>(&r.outputs[0]), [1.0, 10.0, 3.0, 20.0, 20.0]);
        assert_eq!(all::<i64>(&r.outputs[1]), [3]);
        // Nothing to replace: the list passes, with or without R.
        let r = NodeCall::new(&replace_nulls())
            .input(tree("{0}:[1, 2]"))
            .run();
        assert_eq!(all::<f64>(&r.outputs[0]), [1.0, 2.0]);
        assert_eq!(all::<i64>(&r.outputs[1]), [0]);
    }

    #[test]
    fn replace_nulls_without_replacements_is_an_error() {
        let r = NodeCall::new(&replace_nulls())
            .input(tree("{0}:[1, null]"))
            .run();
        let e = messages(&r, Level::Error);
        assert!(e.len() == 1 && e[0].contains("item 1"), "{e:?}");
    }

    #[test]
    fn replace_nulls_may_mix_types() {
        let r = NodeCall::new(&replace_nulls())
            .input(tree("{0}:[1, null]"))
            .input(generic(r#"{0}:["gap"]"#))
            .run();
        assert_eq!(
            values(&r.outputs[0]),
            [Some(Value::Number(1.0)), Some(Value::Text("gap".into()))]
        );
    }

    #[test]
    fn combine_data_takes_the_first_non_null_item() {
        let r = NodeCall::new(&combine_data())
            .input(tree("{0}:[null, 2, null, null]"))
            .input(tree("{0}:[10, 20, null, 40]"))
            .run();
        assert_eq!(
            items::<f64>(&r.outputs[0]),
            [Some(10.0), Some(2.0), None, Some(40.0)]
        );
        assert_eq!(all::<i64>(&r.outputs[1]), [1, 0, -1, 1]);
        // A third input, named by the graph.
        let node = combine_data();
        let r = NodeCall::new(&node)
            .input_names(&["0", "1", "2"])
            .input(tree("{0}:[null]"))
            .input(tree("{0}:[null]"))
            .input(DataTree::from_item(7.0))
            .run();
        assert_eq!(all::<f64>(&r.outputs[0]), [7.0]);
        assert_eq!(all::<i64>(&r.outputs[1]), [2]);
    }
}

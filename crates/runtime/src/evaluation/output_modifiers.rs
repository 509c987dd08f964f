//! Output modifiers: Grasshopper's flatten, graft, simplify, reverse, invert and
//! reparameterize set on a node's *output*, applied once to the tree the node produced, before
//! it is stored. Every wire and named output reading the output then sees the modified tree,
//! and it is cached with the node's other results (a node that does not run again is not
//! modified again).
//!
//! The order is the one of input modifiers (a decision where Grasshopper is silent, reference
//! §1.4): structure first (flatten, graft or simplify, which exclude each other), then
//! reverse, then the per-item changes (invert on Boolean outputs, reparameterize on Curve and
//! Surface outputs). Outputs are already of their port's type, so nothing is cast.

use std::borrow::Cow;

use crate::evaluation::collect::{map_items, reparameterize, restructure};
use crate::evaluation::iterate::{NodeLimit, NodeOutput};
use crate::{DataTree, DataType, Level, Message, Modifier, PlanNode};

/// Applies the output modifiers of `node` to the trees of `out`. A graft that would make more
/// than `max_items` items and branches empties that output with an error (the item budget).
pub(crate) fn apply(node: &PlanNode, out: &mut NodeOutput, max_items: usize) {
    for (k, tree) in out.outputs.iter_mut().enumerate() {
        let modifiers = node.output_modifiers(k);
        if modifiers.is_empty() || tree.is_empty() {
            continue;
        }
        let Some(port) = node.node_type.outputs.get(k) else {
            continue;
        };
        let what = format!("output {}", port.nickname);
        if let Err(detail) = modify(tree, modifiers, port.data_type, max_items, &what) {
            *tree = DataTree::new();
            out.messages.push(Message {
                node: node.id.clone(),
                level: Level::Error,
                path: None,
                index: None,
                text: detail.clone(),
            });
            out.limit.get_or_insert(NodeLimit::Items(detail));
            continue;
        }
        if modifiers.contains(&Modifier::Reparameterize) {
            reparameterize(&node.id, &what, tree, &mut out.messages);
        }
    }
}

/// The structural modifiers and reverse (shared with inputs), then invert on Boolean outputs.
///
/// # Errors
/// The item-budget error when a graft would make more than `max_items` items and branches.
fn modify(
    tree: &mut DataTree,
    modifiers: &[Modifier],
    data_type: DataType,
    max_items: usize,
    what: &str,
) -> Result<(), String> {
    let mut owned = Cow::Owned(std::mem::take(tree));
    let structured = restructure(&mut owned, modifiers, what, max_items);
    *tree = owned.into_owned();
    structured?;
    if modifiers.contains(&Modifier::Invert) && data_type == DataType::Boolean {
        map_items::<bool>(tree, |b| !b);
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Branch, TreePath, Value};

    fn numbers(branches: &[(&[u32], &[f64])]) -> DataTree {
        DataTree::from_branches(branches.iter().map(|(path, items)| {
            let mut b = Branch::new(DataType::Number);
            for &x in *items {
                b.push_option(Some(Value::Number(x)));
            }
            (TreePath::new(path.to_vec()), b)
        }))
    }

    #[test]
    fn structure_comes_before_reverse_whatever_the_order_given() {
        // {0;0}:[1,2] {0;1}:[3] flattened then reversed: {0}:[3,2,1]; reversing each branch
        // first would give [2,1,3].
        let mut t = numbers(&[(&[0, 0], &[1.0, 2.0]), (&[0, 1], &[3.0])]);
        modify(
            &mut t,
            &[Modifier::Reverse, Modifier::Flatten],
            DataType::Number,
            usize::MAX,
            "output R",
        )
        .unwrap();
        assert_eq!(t, numbers(&[(&[0], &[3.0, 2.0, 1.0])]));
    }

    #[test]
    fn graft_and_simplify_change_paths() {
        let mut t = numbers(&[(&[2], &[5.0, 6.0])]);
        modify(
            &mut t,
            &[Modifier::Graft],
            DataType::Number,
            usize::MAX,
            "o",
        )
        .unwrap();
        assert_eq!(t, numbers(&[(&[2, 0], &[5.0]), (&[2, 1], &[6.0])]));
        modify(
            &mut t,
            &[Modifier::Simplify],
            DataType::Number,
            usize::MAX,
            "o",
        )
        .unwrap();
        assert_eq!(t, numbers(&[(&[0], &[5.0]), (&[1], &[6.0])]));
    }

    #[test]
    fn a_graft_above_the_budget_is_an_error_before_grafting() {
        let mut t = numbers(&[(&[0], &[1.0, 2.0, 3.0])]);
        let e = modify(&mut t, &[Modifier::Graft], DataType::Number, 5, "output R").unwrap_err();
        assert!(e.contains("grafting output R would make 3 branches"), "{e}");
        assert_eq!(t.branch_count(), 1);
    }

    #[test]
    fn invert_negates_booleans_and_keeps_nulls() {
        let mut b = Branch::new(DataType::Boolean);
        b.push_option(Some(Value::Boolean(true)));
        b.push_option(None);
        b.push_option(Some(Value::Boolean(false)));
        let mut t = DataTree::from_branches([(TreePath::from([0]), b)]);
        modify(
            &mut t,
            &[Modifier::Invert],
            DataType::Boolean,
            usize::MAX,
            "o",
        )
        .unwrap();
        let values: Vec<Option<Value>> = t.values().collect();
        assert_eq!(
            values,
            [
                Some(Value::Boolean(false)),
                None,
                Some(Value::Boolean(true))
            ]
        );
    }
}

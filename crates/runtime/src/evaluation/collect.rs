//! Collecting a node's input: modifiers and casting to the port's type.
//!
//! Order of application (a decision where Grasshopper is silent, reference §1.4): structure
//! first (flatten, graft or simplify, which exclude each other), then reverse, then the
//! cast to the port's type, then the per-item modifiers (invert, degrees, reparameterize), which
//! need typed items. Data that needs no change is borrowed, not copied.

use std::borrow::Cow;

use crate::{
    Branch, DataTree, DataType, GraftMode, Level, Message, Modifier, NodeId, PlanInput,
    SimplifyMode, Value, cast_tree,
};

/// The input tree a node sees: `raw` (wired, set or given data) with the port's modifiers
/// applied and every item cast to the port's type. Failed casts become nulls with an error
/// message naming the port, path and item index.
///
/// # Errors
/// The item-budget error when a graft would make more than `max_items` items and branches
/// (checked before grafting).
pub(crate) fn prepare_input<'a>(
    node: &NodeId,
    input: &PlanInput,
    raw: Option<Cow<'a, DataTree>>,
    messages: &mut Vec<Message>,
    max_items: usize,
) -> Result<Cow<'a, DataTree>, String> {
    let Some(mut tree) = raw else {
        return Ok(Cow::Owned(DataTree::new()));
    };
    let what = format!("input {}", input.port.nickname);
    restructure(&mut tree, &input.modifiers, &what, max_items)?;
    let target = input.port.data_type;
    let needs_cast = target != DataType::Generic
        && tree
            .branches()
            .iter()
            .any(|(_, b)| !b.is_empty() && b.data_type() != target);
    if needs_cast {
        let (cast, failures) = cast_tree(&tree, target);
        for (path, index, error) in failures {
            messages.push(Message {
                node: node.clone(),
                level: Level::Error,
                path: Some(path),
                index: Some(index),
                text: format!("input {}: {error}", input.port.nickname),
            });
        }
        tree = Cow::Owned(cast);
    }
    let per_item = |m| input.modifiers.contains(&m);
    if per_item(Modifier::Invert) && target == DataType::Boolean {
        map_items::<bool>(tree.to_mut(), |b| !b);
    }
    if per_item(Modifier::Degrees) && target == DataType::Number {
        map_items::<f64>(tree.to_mut(), f64::to_radians);
    }
    if per_item(Modifier::Reparameterize) {
        reparameterize(node, &what, tree.to_mut(), messages);
    }
    Ok(tree)
}

/// The structural modifiers among `modifiers` (flatten, graft or simplify, then reverse) applied
/// to `tree`, which is copied only when one of them is there; `what` names the port in the
/// error (`input A`, `output R`).
///
/// # Errors
/// The item-budget error when a graft would make more than `max_items` items and branches
/// (checked before grafting, and the tree is left as it was).
pub(crate) fn restructure(
    tree: &mut Cow<'_, DataTree>,
    modifiers: &[Modifier],
    what: &str,
    max_items: usize,
) -> Result<(), String> {
    for modifier in [
        Modifier::Flatten,
        Modifier::Graft,
        Modifier::Simplify,
        Modifier::Reverse,
    ] {
        if !modifiers.contains(&modifier) {
            continue;
        }
        if modifier == Modifier::Graft {
            let entries = tree.item_count().saturating_mul(2);
            if entries > max_items {
                return Err(format!(
                    "grafting {what} would make {} branches ({entries} items and branches), \
                     above the limit of {max_items} items per output",
                    tree.item_count()
                ));
            }
        }
        let t = tree.to_mut();
        match modifier {
            Modifier::Flatten => t.flatten(),
            Modifier::Graft => t.graft(GraftMode::ALL),
            Modifier::Simplify => t.simplify(SimplifyMode::All),
            _ => t.reverse_items(),
        }
    }
    Ok(())
}

/// Replaces every item of type `T` by `f(item)`, keeping nulls.
pub(crate) fn map_items<T: crate::Item + Copy>(tree: &mut DataTree, f: impl Fn(T) -> T) {
    let branches = std::mem::take(tree).into_branches();
    let mapped = branches.into_iter().map(|(path, branch)| {
        let (mut column, nulls) = branch.into_parts();
        if let Some(items) = T::vec_mut(&mut column) {
            for x in items.iter_mut() {
                *x = f(*x);
            }
        }
        (path, Branch::from_parts(column, nulls))
    });
    *tree = DataTree::from_branches(mapped);
}

/// Reparameterizes curves and surfaces to the domain 0 to 1 (in each direction); `what`
/// names the port in messages (`input C`).
pub(crate) fn reparameterize(
    node: &NodeId,
    what: &str,
    tree: &mut DataTree,
    messages: &mut Vec<Message>,
) {
    let branches = std::mem::take(tree).into_branches();
    let mut out = Vec::with_capacity(branches.len());
    for (path, branch) in branches {
        let mut b = Branch::new(branch.data_type());
        for (index, item) in branch.values().enumerate() {
            let result = match item {
                Some(Value::Curve(c)) => c
                    .reparameterized(locus_kernel::Interval::UNIT)
                    .map(|c| Some(Value::Curve(crate::Shared::new(c)))),
                Some(Value::Surface(s)) => s
                    .reparameterized(locus_kernel::Interval::UNIT, locus_kernel::Interval::UNIT)
                    .map(|s| Some(Value::Surface(crate::Shared::new(s)))),
                other => Ok(other),
            };
            match result {
                Ok(v) => b.push_option(v),
                Err(e) => {
                    messages.push(Message {
                        node: node.clone(),
                        level: Level::Error,
                        path: Some(path.clone()),
                        index: Some(index),
                        text: format!("{what}: cannot reparameterize: {e}"),
                    });
                    b.push_null();
                }
            }
        }
        out.push((path, b));
    }
    *tree = DataTree::from_branches(out);
}

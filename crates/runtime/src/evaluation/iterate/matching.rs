//! Pairing the inputs' branches: the principal input, the target paths with the collision
//! offset, and the number of iterations in each pairing.

use super::*;

/// The complexity of an input for choosing the principal one (reference §2.4).
fn complexity(port: &Port, tree: &DataTree) -> i64 {
    let only_zero = tree.branch_count() == 1 && tree.branches()[0].0 == TreePath::zero();
    if tree.branch_count() == 0 || only_zero {
        return -2;
    }
    let longest = tree.paths().map(TreePath::len).max().unwrap_or(0) as i64;
    match port.access {
        Access::Item => longest,
        Access::List => longest - 1,
        Access::Tree => -1,
    }
}

fn principal_input(run: &NodeRun<'_>, data: &[&DataTree]) -> Option<usize> {
    if let Some(p) = run.principal.filter(|&p| p < run.inputs.len()) {
        return Some(p);
    }
    if run.inputs.len() == 1 {
        return Some(0);
    }
    let mut best: Option<(usize, i64)> = None;
    for (i, port) in run.inputs.iter().enumerate() {
        let c = complexity(port, data[i]);
        if best.is_none_or(|(_, b)| c > b) {
            best = Some((i, c));
        }
    }
    best.map(|(i, _)| i)
}

pub(super) fn branch_iterations<'a>(
    run: &NodeRun<'_>,
    data: &[&'a DataTree],
) -> Result<Iterations<'a>, String> {
    let ports = run.inputs;
    let max_items = run.budget.max_items;
    let has_item = ports.iter().any(|p| p.access == Access::Item);
    // Under cross reference, list inputs step their branch inside the odometer (reference
    // §2.2): every branch of such an input meets every item combination, and only the other
    // inputs' branches are paired branch by branch.
    let stepping =
        |i: usize| has_item && run.matching == Matching::Cross && ports[i].access == Access::List;
    let n_branches = ports
        .iter()
        .zip(data)
        .enumerate()
        .filter(|(i, (p, _))| p.access != Access::Tree && !stepping(*i))
        .map(|(_, (_, t))| t.branch_count().max(1))
        .max()
        .unwrap_or(1);
    // Every branch pairing makes at least one branch in each output: count them before
    // allocating anything per pairing.
    if n_branches > max_items {
        return Err(format!(
            "{n_branches} branch pairings would give {n_branches} branches in each output, above \
             the limit of {max_items} items per output"
        ));
    }
    let principal = principal_input(run, data).filter(|&p| ports[p].access != Access::Tree);
    // The stepping list inputs with their branches, in input order.
    let steps: Vec<(usize, &'a [(TreePath, Branch)])> = (0..ports.len())
        .filter(|&i| stepping(i) && data[i].branch_count() > 0)
        .map(|i| (i, data[i].branches()))
        .collect();
    let step_product = steps
        .iter()
        .try_fold(1usize, |n, (_, b)| n.checked_mul(b.len()));
    let mut total = n_branches;
    let mut out = Iterations::with_capacity(n_branches);
    for j in 0..n_branches {
        let target = match principal.map(|p| data[p].branches()) {
            Some(branches) if !branches.is_empty() => {
                if j < branches.len() {
                    branches[j].0.clone()
                } else {
                    let last = &branches[branches.len() - 1].0;
                    last.with_last_offset((j + 1 - branches.len()) as u32)
                }
            }
            _ => TreePath::new(vec![j as u32]),
        };
        let branches: PerInput<Option<&Branch>> = data
            .iter()
            .zip(ports)
            .map(|(t, p)| {
                if p.access == Access::Tree || t.branch_count() == 0 {
                    None
                } else {
                    Some(&t.branches()[j.min(t.branch_count() - 1)].1)
                }
            })
            .collect();
        let lengths: PerInput<usize> = branches.iter().map(|b| b.map_or(0, Branch::len)).collect();
        let mut item_lengths = ports
            .iter()
            .zip(&lengths)
            .filter(|(p, _)| p.access == Access::Item)
            .map(|(_, &l)| l);
        // Item inputs that are all optional and empty here do not stop a node whose other
        // inputs have data from solving once (Delaunay Mesh's points without a Plane), as
        // Grasshopper counts a list input as one item.
        let items_absent = has_item
            && ports
                .iter()
                .zip(&lengths)
                .filter(|(p, _)| p.access == Access::Item)
                .all(|(p, &l)| p.optional && l == 0)
            && ports
                .iter()
                .zip(data)
                .any(|(p, t)| p.access != Access::Item && t.branch_count() > 0);
        let count = if !has_item {
            Some(1)
        } else if items_absent {
            match run.matching {
                Matching::Cross => step_product,
                Matching::Longest | Matching::Shortest => Some(1),
            }
        } else {
            match run.matching {
                Matching::Longest => Some(item_lengths.max().unwrap_or(0)),
                Matching::Shortest => Some(item_lengths.min().unwrap_or(0)),
                Matching::Cross => item_lengths
                    .try_fold(1usize, usize::checked_mul)
                    .zip(step_product)
                    .and_then(|(a, b)| a.checked_mul(b)),
            }
        };
        let within = count
            .and_then(|c| total.checked_add(c))
            .filter(|&t| t <= max_items);
        let Some(new_total) = within else {
            return Err(too_many(
                run, &steps, &target, &lengths, count, total, max_items,
            ));
        };
        total = new_total;
        out.push(BranchIteration {
            target,
            branches,
            lengths,
            count: count.unwrap_or(0),
            steps: steps.clone(),
        });
    }
    Ok(out)
}

/// The error for iterations above the budget, naming the matching mode and the counts.
#[allow(clippy::too_many_arguments)]
fn too_many(
    run: &NodeRun<'_>,
    steps: &[(usize, &[(TreePath, Branch)])],
    target: &TreePath,
    lengths: &[usize],
    count: Option<usize>,
    before: usize,
    max_items: usize,
) -> String {
    let items: Vec<String> = run
        .inputs
        .iter()
        .zip(lengths)
        .filter(|(p, _)| p.access == Access::Item)
        .map(|(p, l)| format!("{l} ({})", p.nickname))
        .collect();
    let lists: Vec<String> = steps
        .iter()
        .map(|(i, b)| format!(" × {} branches ({})", b.len(), run.inputs[*i].nickname))
        .collect();
    let mode = match run.matching {
        Matching::Longest => "longest list",
        Matching::Shortest => "shortest list",
        Matching::Cross => "cross reference",
    };
    let count = count.map_or_else(|| "more than 2^64".to_owned(), |c| c.to_string());
    format!(
        "{mode} of {} items{} at {target} gives {count} iterations (after {before} items and \
         branches before it), above the limit of {max_items} items per output",
        items.join(" × "),
        lists.concat()
    )
}

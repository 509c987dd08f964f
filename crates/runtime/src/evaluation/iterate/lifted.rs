//! Lifted item functions and typed fast paths, run as loops over typed columns.

use super::*;
use crate::evaluation::spread;

/// Runs a node declared with `lift1`/`lift2`/`lift3` (or their `_with` forms) as loops over
/// typed columns, when its ports and data fit the loop (see `lift`); `None` to take the
/// general path.
pub(super) fn run_lifted(
    run: &NodeRun<'_>,
    data: &[&DataTree],
    parallel: bool,
) -> Option<NodeOutput> {
    let node_type = run.node_type;
    node_type
        .lift
        .iter()
        .chain(&node_type.fast_paths)
        .find_map(|lift| run_lift(run, lift, data, parallel))
}

/// Runs one lifted loop (the node's own or a fast path) when the ports and the data fit it.
fn run_lift(
    run: &NodeRun<'_>,
    lift: &crate::evaluation::lift::Lift,
    data: &[&DataTree],
    parallel: bool,
) -> Option<NodeOutput> {
    let outputs = &run.node_type.outputs;
    // A port takes the loop's type when it has that type or is generic (a fast path).
    let takes =
        |port: crate::DataType, t: crate::DataType| port == t || port == crate::DataType::Generic;
    let fits = run.inputs.len() == lift.inputs.len()
        && run
            .inputs
            .iter()
            .zip(&lift.inputs)
            .all(|(p, &t)| p.access == Access::Item && takes(p.data_type, t))
        && outputs.len() == lift.outputs.len()
        && outputs
            .iter()
            .zip(&lift.outputs)
            .all(|(p, &t)| p.access == Access::Item && takes(p.data_type, t))
        && run.matching != Matching::Cross
        && !run.inputs.is_empty();
    if !fits {
        return None;
    }
    // Above the item budget: the general path reports it.
    let iterations = branch_iterations(run, data).ok()?;
    // Every branch must hold its port's type (casting made it so; a generic column would not).
    // An optional input takes part only with a full branch without nulls in every pairing,
    // where it reads as a required one does.
    let typed = iterations.iter().all(|bi| {
        bi.branches
            .iter()
            .zip(&lift.inputs)
            .zip(run.inputs)
            .all(|((b, &t), port)| {
                if port.optional {
                    b.is_some_and(|b| !b.is_empty() && !b.has_nulls() && b.data_type() == t)
                } else {
                    b.is_none_or(|b| b.is_empty() || b.data_type() == t)
                }
            })
    });
    if !typed {
        return None;
    }
    let wanted = run.wanted;
    let empty = || -> crate::evaluation::lift::LiftOutput {
        (
            lift.outputs.iter().map(|&t| Branch::new(t)).collect(),
            Vec::new(),
        )
    };
    let one = |bi: &BranchIteration<'_>| {
        let branches: Option<PerInput<&Branch>> = bi
            .branches
            .iter()
            .map(|b| b.filter(|b| !b.is_empty()))
            .collect();
        match branches {
            // A required input with an empty branch: the output branch is empty (gap logic).
            None => empty(),
            Some(_) if bi.count == 0 => empty(),
            Some(b) => (lift.run)(&b, bi.count, parallel, wanted),
        }
    };
    // Many branch pairings: the first run on this thread and are timed, and the rest is spread
    // over threads only when that pays (as within one branch, see `spread`).
    let results: smallvec::SmallVec<[crate::evaluation::lift::LiftOutput; 1]> = if parallel
        && iterations.len() > 1
    {
        let mut results = Vec::with_capacity(iterations.len());
        let probe = spread::probe(iterations.len(), usize::MAX, |start, end| {
            results.extend(iterations[start..end].iter().map(one));
        });
        // Decided per item, not per branch pairing: pairings of many quick items are
        // memory-bound however long each takes.
        let weight =
            |bis: &[BranchIteration<'_>]| -> usize { bis.iter().map(|bi| bi.count.max(1)).sum() };
        let rest = &iterations[probe.done..];
        let by_item = spread::Probe {
            done: weight(&iterations[..probe.done]),
            elapsed: probe.elapsed,
        };
        let items_left = weight(rest);
        if let Some(chunk) = by_item.spread_chunk(items_left, usize::MAX) {
            let per_pairing = (items_left / rest.len().max(1)).max(1);
            results.par_extend(
                rest.par_iter()
                    .with_min_len((chunk / per_pairing).max(1))
                    .map(one),
            );
        } else {
            results.extend(rest.iter().map(one));
        }
        results.into()
    } else {
        iterations.iter().map(one).collect()
    };
    // A fast path that left an item to the solve function: run the node the general way.
    if results.iter().any(|(_, messages)| {
        messages
            .iter()
            .any(|(_, _, text)| text == crate::evaluation::lift::FALL_BACK)
    }) {
        return None;
    }
    let mut messages = Vec::new();
    let mut pieces: PerInput<Vec<(TreePath, Branch)>> = outputs
        .iter()
        .map(|_| Vec::with_capacity(iterations.len()))
        .collect();
    for (bi, (branches, reported)) in iterations.iter().zip(results) {
        messages.extend(reported.into_iter().map(|(k, level, text)| Message {
            node: run.node_id.clone(),
            level,
            path: Some(bi.target.clone()),
            index: Some(k),
            text,
        }));
        for (o, branch) in branches.into_iter().enumerate() {
            pieces[o].push((bi.target.clone(), branch));
        }
    }
    Some(NodeOutput {
        outputs: pieces
            .into_iter()
            .enumerate()
            .map(|(o, p)| {
                if wanted.get(o).copied().unwrap_or(true) {
                    DataTree::from_branches(p)
                } else {
                    DataTree::new()
                }
            })
            .collect(),
        messages,
        limit: None,
    })
}

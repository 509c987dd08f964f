//! Running one node over its input trees with Grasshopper's matching rules.
//!
//! This is a re-statement of Grasshopper's `GH_StructureIterator` (reference §2.2–2.4):
//!
//! 1. Nodes whose inputs are all tree access (or that have no inputs) solve once.
//! 2. Otherwise branches of the item- and list-access inputs are paired **by position** in
//!    path order, longest-list style: an input with fewer branches reuses its last branch.
//! 3. Within a branch, item-access inputs are matched item by item with the node's
//!    [`Matching`]: longest list (shorter lists repeat their last item), shortest list, or cross
//!    reference (every combination, the first input varying fastest). List-access inputs see
//!    the whole branch; under cross reference a list input's branch is one more wheel of the
//!    odometer (each of its branches meets every item combination), and only the other
//!    inputs' branches are paired.
//! 4. Outputs go to the path of the *principal* input (marked, else the only input, else the
//!    most complex one, ties to the first). When the principal input runs out of branches its
//!    last path is reused with its last index offset by 1, 2, … (the collision offset).
//!    Item outputs get one item per iteration; list outputs get a branch per iteration, with
//!    the iteration index appended to the path when any input has item access.
//! 5. Gap logic: an iteration whose required item is null (or whose solve fails) leaves a null
//!    in item outputs; one where a required item input has an empty branch leaves only the
//!    (empty) branch. List outputs get an empty branch.
//!
//! Iterations are independent, so large branches are split into chunks solved in parallel
//! with rayon; chunks are stitched back in order, which makes the result identical for any
//! number of threads.

use rayon::prelude::*;

use crate::evaluation::solve::{Cursor, OutputSink};
use crate::limits::{Budget, CHECK_EVERY};
use crate::{
    Access, Branch, DataTree, Level, Matching, Message, NodeId, NodeType, Port, Prepared, Solve,
    TreePath, Value,
};

mod lifted;
mod matching;

use super::spread;

use lifted::run_lifted;
use matching::branch_iterations;

/// The most iterations in one parallel task (fewer when items are slow, see `spread`).
const CHUNK_ITERATIONS: usize = 8192;

/// Everything about a node that running it needs, besides its input data.
#[derive(Debug)]
pub(crate) struct NodeRun<'a> {
    pub(crate) node_id: &'a NodeId,
    pub(crate) node_type: &'a NodeType,
    pub(crate) inputs: &'a [Port],
    pub(crate) settings: &'a [(String, Value)],
    pub(crate) matching: Matching,
    pub(crate) principal: Option<usize>,
    pub(crate) prepared: Option<&'a Prepared>,
    /// For each output, whether anything reads it (a wire, a named output, a host): the others
    /// are left empty.
    pub(crate) wanted: &'a [bool],
    /// The item budget, deadline and cancellation.
    pub(crate) budget: &'a Budget,
}

/// Why a node stopped before its end: its outputs are empty.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) enum NodeLimit {
    /// The deadline passed or the evaluation was cancelled.
    Watch,
    /// The outputs would exceed the item budget (the detail names the counts).
    Items(String),
}

/// The outputs and messages of one node.
#[derive(Debug, Default)]
pub(crate) struct NodeOutput {
    pub(crate) outputs: Vec<DataTree>,
    pub(crate) messages: Vec<Message>,
    /// Set when a limit stopped the node.
    pub(crate) limit: Option<NodeLimit>,
}

type RawMessage = (Level, Option<TreePath>, Option<usize>, String);

/// Inline room for the inputs of most nodes: pairing branches allocates nothing for them.
type PerInput<T> = smallvec::SmallVec<[T; 4]>;

/// The branch pairings of a node: most nodes have one, held inline.
type Iterations<'a> = smallvec::SmallVec<[BranchIteration<'a>; 1]>;

/// One pairing of branches: the `j`-th branch iteration.
struct BranchIteration<'a> {
    target: TreePath,
    branches: PerInput<Option<&'a Branch>>,
    lengths: PerInput<usize>,
    count: usize,
    /// Under cross reference, the list inputs that step their branch inside the odometer,
    /// with all their branches (reference §2.2).
    steps: Vec<(usize, &'a [(TreePath, Branch)])>,
}

/// A contiguous range of iterations within one branch iteration.
struct Task {
    branch_iteration: usize,
    start: usize,
    end: usize,
}

/// What one task produced.
struct Segment {
    pieces: Vec<Vec<(TreePath, Branch)>>,
    messages: Vec<RawMessage>,
    limit: Option<NodeLimit>,
}

/// Runs a node on its collected input trees (one per input port, already modified and cast).
pub(crate) fn run_node(run: &NodeRun<'_>, data: &[&DataTree], parallel: bool) -> NodeOutput {
    let parallel = parallel && rayon::current_num_threads() > 1;
    if let Some(out) = run_lifted(run, data, parallel) {
        return out;
    }
    let outputs = &run.node_type.outputs;
    let segments = if NodeType::solves_once(run.inputs) {
        vec![solve_once(run, data)]
    } else {
        let iterations = match branch_iterations(run, data) {
            Ok(iterations) => iterations,
            Err(detail) => return limited(run, NodeLimit::Items(detail)),
        };
        let has_item = run.inputs.iter().any(|p| p.access == Access::Item);
        let run_one = |task: &Task| {
            run_task(
                run,
                data,
                &iterations[task.branch_iteration],
                task,
                has_item,
            )
        };
        let units: usize = iterations.iter().map(|bi| bi.count.max(1)).sum();
        if parallel && units > 1 {
            // The first iterations run on this thread and are timed; the rest is spread over
            // threads in tasks sized by that time, or run here when threads would not pay.
            let mut segments = Vec::new();
            let probe = spread::probe(units, CHUNK_ITERATIONS, |start, end| {
                segments.extend(
                    tasks_in(&iterations, start, end, usize::MAX)
                        .iter()
                        .map(run_one),
                );
            });
            match probe.spread_chunk(units - probe.done, CHUNK_ITERATIONS) {
                Some(chunk) => {
                    let tasks = tasks_in(&iterations, probe.done, units, chunk);
                    segments.par_extend(tasks.par_iter().map(run_one));
                }
                None => {
                    let tasks = tasks_in(&iterations, probe.done, units, usize::MAX);
                    segments.extend(tasks.iter().map(run_one));
                }
            }
            segments
        } else {
            // On one thread each branch pairing is one task, so its output branch is built
            // in place and never stitched.
            tasks_in(&iterations, 0, units, usize::MAX)
                .iter()
                .map(run_one)
                .collect()
        }
    };
    let out = stitch(run.node_id, outputs, segments);
    within_budget(run, out)
}

/// The tasks of the work units `start..end`, at most `chunk` iterations each. Branch
/// pairing `j` is `max(count, 1)` units from the sum of the units before it: an empty pairing
/// is one unit (a task of no iterations, which gives its empty output branch), and a task
/// never spans two pairings.
fn tasks_in(
    iterations: &[BranchIteration<'_>],
    start: usize,
    end: usize,
    chunk: usize,
) -> Vec<Task> {
    let mut tasks = Vec::new();
    let mut offset = 0;
    for (j, bi) in iterations.iter().enumerate() {
        let width = bi.count.max(1);
        let (from, to) = (start.max(offset), end.min(offset + width));
        if from < to {
            if bi.count == 0 {
                tasks.push(Task {
                    branch_iteration: j,
                    start: 0,
                    end: 0,
                });
            } else {
                let mut s = from - offset;
                while s < to - offset {
                    let e = s.saturating_add(chunk).min(to - offset);
                    tasks.push(Task {
                        branch_iteration: j,
                        start: s,
                        end: e,
                    });
                    s = e;
                }
            }
        }
        offset += width;
        if offset >= end {
            break;
        }
    }
    tasks
}

/// A node's output with empty trees and the error of the limit that stopped it.
pub(crate) fn limited(run: &NodeRun<'_>, limit: NodeLimit) -> NodeOutput {
    let mut messages = Vec::new();
    if let NodeLimit::Items(detail) = &limit {
        messages.push(Message {
            node: run.node_id.clone(),
            level: Level::Error,
            path: None,
            index: None,
            text: detail.clone(),
        });
    }
    NodeOutput {
        outputs: run
            .node_type
            .outputs
            .iter()
            .map(|_| DataTree::new())
            .collect(),
        messages,
        limit: Some(limit),
    }
}

/// The output itself, or the item-budget error when one of its trees holds more entries
/// (items plus branches) than one output may.
fn within_budget(run: &NodeRun<'_>, mut out: NodeOutput) -> NodeOutput {
    if let Some(limit) = out.limit.take() {
        // A task stopped: no output, the messages so far and the limit's own.
        let mut stopped = limited(run, limit);
        out.messages.append(&mut stopped.messages);
        stopped.messages = out.messages;
        return stopped;
    }
    let max = run.budget.max_items;
    let over = out
        .outputs
        .iter()
        .zip(&run.node_type.outputs)
        .find_map(|(tree, port)| {
            let entries = tree.item_count().saturating_add(tree.branch_count());
            (entries > max).then_some((entries, port))
        });
    match over {
        None => out,
        Some((entries, port)) => limited(
            run,
            NodeLimit::Items(format!(
                "output {} would hold {entries} items and branches, above the limit of {max} \
                 items per output",
                port.nickname
            )),
        ),
    }
}

/// Joins the segments' pieces into one tree per output. A generic output's branches whose
/// items all have one type get a typed column, so that downstream nodes read typed slices.
fn stitch(node_id: &NodeId, outputs: &[Port], segments: Vec<Segment>) -> NodeOutput {
    let n_outputs = outputs.len();
    let mut pieces: Vec<Vec<(TreePath, Branch)>> = (0..n_outputs).map(|_| Vec::new()).collect();
    let mut messages = Vec::new();
    let mut limit = None;
    for segment in segments {
        if limit.is_none() {
            limit = segment.limit;
        }
        for (o, p) in segment.pieces.into_iter().enumerate() {
            if pieces[o].is_empty() {
                pieces[o] = p;
            } else {
                pieces[o].extend(p);
            }
        }
        messages.extend(
            segment
                .messages
                .into_iter()
                .map(|(level, path, index, text)| Message {
                    node: node_id.clone(),
                    level,
                    path,
                    index,
                    text,
                }),
        );
    }
    NodeOutput {
        outputs: pieces
            .into_iter()
            .zip(outputs)
            .map(|(p, port)| {
                let tree = DataTree::from_branches(p);
                if port.data_type == crate::DataType::Generic {
                    tree.narrowed()
                } else {
                    tree
                }
            })
            .collect(),
        messages,
        limit,
    }
}

fn new_sinks(outputs: &[Port], wanted: &[bool]) -> Vec<OutputSink> {
    outputs
        .iter()
        .enumerate()
        .map(|(o, p)| OutputSink {
            skip: !wanted.get(o).copied().unwrap_or(true),
            access: p.access,
            data_type: p.data_type,
            pieces: Vec::new(),
            set: false,
            listed: 0,
        })
        .collect()
}

fn solve_once(run: &NodeRun<'_>, data: &[&DataTree]) -> Segment {
    let path = TreePath::zero();
    let mut sinks = new_sinks(&run.node_type.outputs, run.wanted);
    for sink in &mut sinks {
        if sink.access == Access::Item && !sink.skip {
            sink.pieces
                .push((path.clone(), Branch::new(sink.data_type)));
        }
    }
    let cursors: Vec<Cursor<'_>> = data.iter().map(|t| Cursor::Tree(t)).collect();
    let mut messages = Vec::new();
    let result = {
        let mut solve = Solve {
            ports: run.inputs,
            output_ports: &run.node_type.outputs,
            cursors: &cursors,
            sinks: &mut sinks,
            messages: &mut messages,
            settings: run.settings,
            prepared: run.prepared,
            path: &path,
            index: None,
            append_index: false,
        };
        (run.node_type.solve)(&mut solve)
    };
    if let Err(e) = result {
        messages.push((Level::Error, None, None, e.0));
    }
    Segment {
        pieces: sinks.into_iter().map(|s| s.pieces).collect(),
        messages,
        limit: None,
    }
}

fn run_task(
    run: &NodeRun<'_>,
    data: &[&DataTree],
    bi: &BranchIteration<'_>,
    task: &Task,
    has_item: bool,
) -> Segment {
    let ports = run.inputs;
    let mut sinks = new_sinks(&run.node_type.outputs, run.wanted);
    for sink in &mut sinks {
        if sink.access == Access::Item && !sink.skip {
            let column = crate::Column::with_capacity(sink.data_type, task.end - task.start);
            sink.pieces
                .push((bi.target.clone(), Branch::from_column(column)));
        }
    }
    let mut cursors: Vec<Cursor<'_>> = ports
        .iter()
        .zip(data)
        .zip(&bi.branches)
        .map(|((p, t), b)| match p.access {
            Access::Item => Cursor::Item(*b, None),
            Access::List => Cursor::List(*b),
            Access::Tree => Cursor::Tree(t),
        })
        .collect();
    let mut messages: Vec<RawMessage> = Vec::new();
    // The odometer's wheels in input order, the first turning fastest: item inputs step
    // their item, stepping list inputs (cross reference) their branch.
    let wheels: Vec<usize> = (0..ports.len())
        .filter(|&i| ports[i].access == Access::Item || bi.steps.iter().any(|&(s, _)| s == i))
        .collect();
    let max_items = run.budget.max_items;
    let mut limit = None;
    for k in task.start..task.end {
        if (k - task.start) % CHECK_EVERY == CHECK_EVERY - 1 && run.budget.watch.check().is_some() {
            limit = Some(NodeLimit::Watch);
            break;
        }
        let mut skip = false;
        let mut empty_gap = false;
        // Cross reference: decompose k over the item inputs, the first varying fastest.
        let mut rest = k;
        for &i in &wheels {
            if let Some(&(_, branches)) = bi.steps.iter().find(|&&(s, _)| s == i) {
                let b = &branches[rest % branches.len()].1;
                rest /= branches.len();
                cursors[i] = Cursor::List(Some(b));
                if !ports[i].optional {
                    skip |= b.is_empty();
                }
                continue;
            }
            let len = bi.lengths[i];
            let index = if len == 0 {
                None
            } else {
                Some(match run.matching {
                    Matching::Longest => k.min(len - 1),
                    Matching::Shortest => k,
                    Matching::Cross => {
                        let idx = rest % len;
                        rest /= len;
                        idx
                    }
                })
            };
            let branch = bi.branches[i];
            cursors[i] = Cursor::Item(branch, index);
            if !ports[i].optional {
                match (branch, index) {
                    (Some(b), Some(idx)) => skip |= b.is_null(idx),
                    _ => {
                        skip = true;
                        empty_gap = true;
                    }
                }
            }
        }
        for (i, port) in ports.iter().enumerate() {
            if port.access == Access::List
                && !port.optional
                && !bi.steps.iter().any(|&(s, _)| s == i)
            {
                skip |= bi.branches[i].is_none_or(Branch::is_empty);
            }
        }
        let index = has_item.then_some(k);
        if !skip {
            let result = {
                let mut solve = Solve {
                    ports,
                    output_ports: &run.node_type.outputs,
                    cursors: &cursors,
                    sinks: &mut sinks,
                    messages: &mut messages,
                    settings: run.settings,
                    prepared: run.prepared,
                    path: &bi.target,
                    index,
                    append_index: has_item,
                };
                (run.node_type.solve)(&mut solve)
            };
            if let Err(e) = result {
                messages.push((Level::Error, Some(bi.target.clone()), index, e.0));
            }
        }
        for sink in &mut sinks {
            if !sink.set && !sink.skip {
                match sink.access {
                    Access::Item => {
                        if !empty_gap && let Some((_, b)) = sink.pieces.last_mut() {
                            b.push_null();
                        }
                    }
                    Access::List => {
                        let path = if has_item {
                            bi.target.with_appended(k as u32)
                        } else {
                            bi.target.clone()
                        };
                        sink.pieces.push((path, Branch::new(sink.data_type)));
                    }
                    Access::Tree => {}
                }
            }
            sink.set = false;
        }
        if let Some(sink) = sinks.iter().find(|s| s.listed > max_items) {
            limit = Some(NodeLimit::Items(format!(
                "list outputs would hold more than {} items and branches (at {} iteration {k}), \
                 above the limit of {max_items} items per output",
                sink.listed, bi.target
            )));
            break;
        }
    }
    Segment {
        pieces: sinks.into_iter().map(|s| s.pieces).collect(),
        messages,
        limit,
    }
}

#[cfg(test)]
mod tests;

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
//!    the whole branch.
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
use crate::{
    Access, Branch, DataTree, Level, Matching, Message, NodeId, NodeType, Port, Prepared, Solve,
    TreePath, Value,
};

mod lifted;
mod matching;

use lifted::run_lifted;
use matching::branch_iterations;

/// Iterations per parallel chunk.
const CHUNK_ITERATIONS: usize = 8192;

/// The fewest iterations for which a node's iterations are spread over threads.
const PARALLEL_THRESHOLD: usize = 2 * CHUNK_ITERATIONS;

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
}

/// The outputs and messages of one node.
#[derive(Debug, Default)]
pub(crate) struct NodeOutput {
    pub(crate) outputs: Vec<DataTree>,
    pub(crate) messages: Vec<Message>,
}

type RawMessage = (Level, Option<TreePath>, Option<usize>, String);

/// One pairing of branches: the `j`-th branch iteration.
struct BranchIteration<'a> {
    target: TreePath,
    branches: Vec<Option<&'a Branch>>,
    lengths: Vec<usize>,
    count: usize,
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
}

/// Runs a node on its collected input trees (one per input port, already modified and cast).
pub(crate) fn run_node(run: &NodeRun<'_>, data: &[&DataTree], parallel: bool) -> NodeOutput {
    if let Some(out) = run_lifted(run, data, parallel) {
        return out;
    }
    let outputs = &run.node_type.outputs;
    let segments = if NodeType::solves_once(run.inputs) {
        vec![solve_once(run, data)]
    } else {
        let iterations = branch_iterations(run, data);
        let has_item = run.inputs.iter().any(|p| p.access == Access::Item);
        let mut tasks = Vec::new();
        let total: usize = iterations.iter().map(|bi| bi.count).sum();
        let parallel = parallel && total >= PARALLEL_THRESHOLD;
        // Chunks are only for spreading work over threads: on one thread each branch pairing
        // is one task, so its output branch is built in place and never stitched.
        let chunk = if parallel {
            CHUNK_ITERATIONS
        } else {
            usize::MAX
        };
        for (j, bi) in iterations.iter().enumerate() {
            if bi.count == 0 {
                tasks.push(Task {
                    branch_iteration: j,
                    start: 0,
                    end: 0,
                });
            }
            let mut start = 0;
            while start < bi.count {
                let end = start.saturating_add(chunk).min(bi.count);
                tasks.push(Task {
                    branch_iteration: j,
                    start,
                    end,
                });
                start = end;
            }
        }
        let run_one = |task: &Task| {
            run_task(
                run,
                data,
                &iterations[task.branch_iteration],
                task,
                has_item,
            )
        };
        if parallel {
            tasks.par_iter().map(run_one).collect()
        } else {
            tasks.iter().map(run_one).collect()
        }
    };
    stitch(run.node_id, outputs, segments)
}

/// Joins the segments' pieces into one tree per output. A generic output's branches whose
/// items all have one type get a typed column, so that downstream nodes read typed slices.
fn stitch(node_id: &NodeId, outputs: &[Port], segments: Vec<Segment>) -> NodeOutput {
    let n_outputs = outputs.len();
    let mut pieces: Vec<Vec<(TreePath, Branch)>> = (0..n_outputs).map(|_| Vec::new()).collect();
    let mut messages = Vec::new();
    for segment in segments {
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
    }
}

fn new_sinks(outputs: &[Port]) -> Vec<OutputSink> {
    outputs
        .iter()
        .map(|p| OutputSink {
            access: p.access,
            data_type: p.data_type,
            pieces: Vec::new(),
            set: false,
        })
        .collect()
}

fn solve_once(run: &NodeRun<'_>, data: &[&DataTree]) -> Segment {
    let path = TreePath::zero();
    let mut sinks = new_sinks(&run.node_type.outputs);
    for sink in &mut sinks {
        if sink.access == Access::Item {
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
    let mut sinks = new_sinks(&run.node_type.outputs);
    for sink in &mut sinks {
        if sink.access == Access::Item {
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
    let item_inputs: Vec<usize> = (0..ports.len())
        .filter(|&i| ports[i].access == Access::Item)
        .collect();
    for k in task.start..task.end {
        let mut skip = false;
        let mut empty_gap = false;
        // Cross reference: decompose k over the item inputs, the first varying fastest.
        let mut rest = k;
        for &i in &item_inputs {
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
            if port.access == Access::List && !port.optional {
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
            if !sink.set {
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
    }
    Segment {
        pieces: sinks.into_iter().map(|s| s.pieces).collect(),
        messages,
    }
}

#[cfg(test)]
mod tests;

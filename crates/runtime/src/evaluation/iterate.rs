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

/// Runs a node declared with `lift1`/`lift2`/`lift3` as loops over typed columns, when its
/// ports and data fit the loop (see `lift`); `None` to take the general path.
fn run_lifted(run: &NodeRun<'_>, data: &[&DataTree], parallel: bool) -> Option<NodeOutput> {
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
            .all(|(p, &t)| p.access == Access::Item && !p.optional && takes(p.data_type, t))
        && outputs.len() == 1
        && outputs[0].access == Access::Item
        && takes(outputs[0].data_type, lift.output)
        && run.matching != Matching::Cross
        && !run.inputs.is_empty();
    if !fits {
        return None;
    }
    let iterations = branch_iterations(run, data);
    // Every branch must hold its port's type (casting made it so; a generic column would not).
    let typed = iterations.iter().all(|bi| {
        bi.branches
            .iter()
            .zip(&lift.inputs)
            .all(|(b, &t)| b.is_none_or(|b| b.is_empty() || b.data_type() == t))
    });
    if !typed {
        return None;
    }
    let total: usize = iterations.iter().map(|bi| bi.count).sum();
    let parallel = parallel && total >= PARALLEL_THRESHOLD;
    let one = |bi: &BranchIteration<'_>| {
        let branches: Option<Vec<&Branch>> = bi
            .branches
            .iter()
            .map(|b| b.filter(|b| !b.is_empty()))
            .collect();
        match branches {
            // A required input with an empty branch: the output branch is empty (gap logic).
            None => (Branch::new(lift.output), Vec::new()),
            Some(_) if bi.count == 0 => (Branch::new(lift.output), Vec::new()),
            Some(b) => (lift.run)(&b, bi.count, parallel && bi.count >= PARALLEL_THRESHOLD),
        }
    };
    // Many branch pairings: the first runs on this thread and is timed, and the rest is spread
    // over threads only when items are slow enough for that to pay (as within one branch).
    let results: Vec<(Branch, Vec<(usize, String)>)> = if parallel && iterations.len() > 1 {
        let started = std::time::Instant::now();
        let first = one(&iterations[0]);
        let spread =
            crate::evaluation::lift::worth_spreading(started.elapsed(), iterations[0].count.max(1));
        let rest = &iterations[1..];
        let mut results = Vec::with_capacity(iterations.len());
        results.push(first);
        if spread {
            results.par_extend(rest.par_iter().map(one));
        } else {
            results.extend(rest.iter().map(one));
        }
        results
    } else {
        iterations.iter().map(one).collect()
    };
    // A fast path that left an item to the solve function: run the node the general way.
    if results.iter().any(|(_, errors)| {
        errors
            .iter()
            .any(|(_, text)| text == crate::evaluation::lift::FALL_BACK)
    }) {
        return None;
    }
    let mut messages = Vec::new();
    let mut pieces = Vec::with_capacity(iterations.len());
    for (bi, (branch, errors)) in iterations.iter().zip(results) {
        messages.extend(errors.into_iter().map(|(k, text)| Message {
            node: run.node_id.clone(),
            level: Level::Error,
            path: Some(bi.target.clone()),
            index: Some(k),
            text,
        }));
        pieces.push((bi.target.clone(), branch));
    }
    Some(NodeOutput {
        outputs: vec![DataTree::from_branches(pieces)],
        messages,
    })
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

fn branch_iterations<'a>(run: &NodeRun<'_>, data: &[&'a DataTree]) -> Vec<BranchIteration<'a>> {
    let ports = run.inputs;
    let n_branches = ports
        .iter()
        .zip(data)
        .filter(|(p, _)| p.access != Access::Tree)
        .map(|(_, t)| t.branch_count().max(1))
        .max()
        .unwrap_or(1);
    let principal = principal_input(run, data).filter(|&p| ports[p].access != Access::Tree);
    let has_item = ports.iter().any(|p| p.access == Access::Item);
    (0..n_branches)
        .map(|j| {
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
            let branches: Vec<Option<&Branch>> = data
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
            let lengths: Vec<usize> = branches.iter().map(|b| b.map_or(0, Branch::len)).collect();
            let item_lengths = ports
                .iter()
                .zip(&lengths)
                .filter(|(p, _)| p.access == Access::Item)
                .map(|(_, &l)| l);
            let count = if !has_item {
                1
            } else {
                match run.matching {
                    Matching::Longest => item_lengths.max().unwrap_or(0),
                    Matching::Shortest => item_lengths.min().unwrap_or(0),
                    Matching::Cross => item_lengths.product(),
                }
            };
            BranchIteration {
                target,
                branches,
                lengths,
                count,
            }
        })
        .collect()
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
mod tests {
    //! The worked examples E1–E14 of the Grasshopper semantics reference, §2.5.

    use super::*;
    use crate::DataType;

    /// Parses a number tree written `{0;1}:[1, null, 3] {0;2}:[]`.
    fn tree(text: &str) -> DataTree {
        let mut t = DataTree::new();
        let mut rest = text.trim();
        while !rest.is_empty() {
            let close = rest.find('}').unwrap();
            let path: TreePath = rest[..=close].parse().unwrap();
            let after = rest[close + 1..].trim_start().strip_prefix(':').unwrap();
            let end = after.find(']').unwrap();
            let items = &after.trim_start()[1..after.trim_start().find(']').unwrap()];
            let mut b = Branch::new(DataType::Number);
            for item in items.split(',').map(str::trim).filter(|s| !s.is_empty()) {
                if item == "null" {
                    b.push_null();
                } else {
                    b.push(item.parse::<f64>().unwrap());
                }
            }
            t.insert(path, b);
            rest = after[end + 1..].trim_start();
        }
        t
    }

    fn show(t: &DataTree) -> String {
        let mut parts = Vec::new();
        for (p, b) in t.branches() {
            let items: Vec<String> = b
                .values()
                .map(|v| match v {
                    Some(Value::Number(x)) => format!("{x}"),
                    Some(other) => format!("{other:?}"),
                    None => "null".to_owned(),
                })
                .collect();
            parts.push(format!("{p}:[{}]", items.join(",")));
        }
        parts.join(" ")
    }

    fn addition() -> NodeType {
        NodeType::new("test.add", "Addition", "A+B", "Maths")
            .input(Port::new("A", "A", DataType::Number))
            .input(Port::new("B", "B", DataType::Number))
            .output(Port::new("Result", "R", DataType::Number))
            .solve(|s| {
                let a = *s.item::<f64>(0)?;
                let b = *s.item::<f64>(1)?;
                s.set(0, a + b);
                Ok(())
            })
    }

    fn run(
        node: &NodeType,
        matching: Matching,
        principal: Option<usize>,
        inputs: &[&str],
    ) -> String {
        let trees: Vec<DataTree> = inputs.iter().map(|s| tree(s)).collect();
        let refs: Vec<&DataTree> = trees.iter().collect();
        let id = NodeId::from("n");
        let r = NodeRun {
            node_id: &id,
            node_type: node,
            inputs: &node.inputs,
            settings: &[],
            matching,
            principal,
            prepared: None,
        };
        let serial = run_node(&r, &refs, false);
        let parallel = run_node(&r, &refs, true);
        assert_eq!(serial.outputs, parallel.outputs);
        show(&serial.outputs[0])
    }

    #[test]
    fn e1_longest_list_repeats_the_last_item() {
        let out = run(
            &addition(),
            Matching::Longest,
            None,
            &["{0}:[1,2,3]", "{0}:[10,20]"],
        );
        assert_eq!(out, "{0}:[11,22,23]");
    }

    #[test]
    fn e2_shortest_list_drops_extra_items() {
        let out = run(
            &addition(),
            Matching::Shortest,
            None,
            &["{0}:[1,2,3]", "{0}:[10,20]"],
        );
        assert_eq!(out, "{0}:[11,22]");
    }

    #[test]
    fn e3_cross_reference_first_input_fastest() {
        let out = run(
            &addition(),
            Matching::Cross,
            None,
            &["{0}:[1,2]", "{0}:[10,20,30]"],
        );
        assert_eq!(out, "{0}:[11,12,21,22,31,32]");
    }

    #[test]
    fn e4_list_reused_for_every_branch() {
        let out = run(
            &addition(),
            Matching::Longest,
            None,
            &["{0}:[1,2]", "{0;0}:[10,20,30] {0;1}:[40]"],
        );
        assert_eq!(out, "{0;0}:[11,22,32] {0;1}:[41,42]");
    }

    #[test]
    fn e5_collision_offset_when_principal_runs_out() {
        let out = run(
            &addition(),
            Matching::Longest,
            None,
            &["{0;0}:[1] {0;1}:[2]", "{0;0}:[10] {0;1}:[20] {0;2}:[30]"],
        );
        assert_eq!(out, "{0;0}:[11] {0;1}:[22] {0;2}:[32]");
    }

    #[test]
    fn e6_branches_paired_by_position() {
        let out = run(
            &addition(),
            Matching::Longest,
            None,
            &["{1}:[1] {5}:[2]", "{0}:[10] {1}:[20] {2}:[30]"],
        );
        assert_eq!(out, "{1}:[11] {5}:[22] {6}:[32]");
    }

    fn divide_like() -> NodeType {
        NodeType::new("test.divide", "Divide", "Div", "Curve")
            .input(Port::new("Curve", "C", DataType::Number))
            .input(Port::new("Count", "N", DataType::Number))
            .output(Port::new("Points", "P", DataType::Number).list())
            .solve(|s| {
                let c = *s.item::<f64>(0)?;
                let n = *s.item::<f64>(1)? as usize;
                s.set_list(0, (0..=n).map(|i| c + i as f64).collect());
                Ok(())
            })
    }

    #[test]
    fn e7_list_output_per_item_gets_an_index() {
        let out = run(
            &divide_like(),
            Matching::Longest,
            None,
            &["{0}:[0,10,20]", "{0}:[2]"],
        );
        assert_eq!(out, "{0;0}:[0,1,2] {0;1}:[10,11,12] {0;2}:[20,21,22]");
    }

    #[test]
    fn e8_appended_index_is_per_branch() {
        let out = run(
            &divide_like(),
            Matching::Longest,
            None,
            &["{0;0}:[0,10] {0;1}:[20]", "{0}:[1]"],
        );
        assert_eq!(out, "{0;0;0}:[0,1] {0;0;1}:[10,11] {0;1;0}:[20,21]");
    }

    fn sum_list() -> NodeType {
        NodeType::new("test.sum", "Sum", "Sum", "Maths")
            .input(Port::new("Values", "V", DataType::Number).list())
            .output(Port::new("Sum", "S", DataType::Number))
            .solve(|s| {
                let total = s.list::<f64>(0)?.present().sum::<f64>();
                s.set(0, total);
                Ok(())
            })
    }

    fn reverse_list() -> NodeType {
        NodeType::new("test.reverse", "Reverse", "Rev", "Sets")
            .input(Port::new("List", "L", DataType::Number).list())
            .output(Port::new("List", "L", DataType::Number).list())
            .solve(|s| {
                let mut v: Vec<f64> = s.list::<f64>(0)?.present().copied().collect();
                v.reverse();
                s.set_list(0, v);
                Ok(())
            })
    }

    #[test]
    fn e9_list_input_item_output_one_call_per_branch() {
        let out = run(
            &sum_list(),
            Matching::Longest,
            None,
            &["{0;0}:[1,2,3] {0;1}:[4,5]"],
        );
        assert_eq!(out, "{0;0}:[6] {0;1}:[9]");
    }

    #[test]
    fn e10_list_outputs_keep_the_path_without_item_inputs() {
        let out = run(
            &reverse_list(),
            Matching::Longest,
            None,
            &["{0;0}:[1,2,3] {0;1}:[4,5]"],
        );
        assert_eq!(out, "{0;0}:[3,2,1] {0;1}:[5,4]");
    }

    #[test]
    fn e11_null_in_null_out() {
        let out = run(
            &addition(),
            Matching::Longest,
            None,
            &["{0}:[1,null,3]", "{0}:[10]"],
        );
        assert_eq!(out, "{0}:[11,null,13]");
    }

    #[test]
    fn e12_empty_branch_in_empty_branch_out() {
        let out = run(
            &addition(),
            Matching::Longest,
            None,
            &["{0}:[1] {1}:[]", "{0}:[10] {1}:[20]"],
        );
        assert_eq!(out, "{0}:[11] {1}:[]");
    }

    #[test]
    fn e13_item_and_tree_take_the_tree_structure() {
        let out = run(
            &addition(),
            Matching::Longest,
            None,
            &["{0}:[100]", "{0;0}:[1,2] {0;1}:[3]"],
        );
        assert_eq!(out, "{0;0}:[101,102] {0;1}:[103]");
    }

    #[test]
    fn e14_grafted_input_gives_a_table_of_pairs() {
        let out = run(
            &addition(),
            Matching::Longest,
            None,
            &["{0;0}:[1] {0;1}:[2]", "{0}:[10,20,30]"],
        );
        assert_eq!(out, "{0;0}:[11,21,31] {0;1}:[12,22,32]");
    }

    #[test]
    fn marked_principal_decides_the_paths() {
        let out = run(
            &addition(),
            Matching::Longest,
            Some(0),
            &["{0}:[100]", "{0;0}:[1,2] {0;1}:[3]"],
        );
        assert_eq!(out, "{0}:[101,102] {1}:[103]");
    }

    #[test]
    fn failing_iterations_leave_nulls_and_messages() {
        let node = NodeType::new("test.div", "Division", "A/B", "Maths")
            .input(Port::new("A", "A", DataType::Number))
            .input(Port::new("B", "B", DataType::Number))
            .output(Port::new("Result", "R", DataType::Number))
            .solve(|s| {
                let a = *s.item::<f64>(0)?;
                let b = *s.item::<f64>(1)?;
                if b == 0.0 {
                    return Err("division by zero".into());
                }
                s.set(0, a / b);
                Ok(())
            });
        let trees = [tree("{0}:[1,2,3]"), tree("{0}:[1,0,3]")];
        let refs: Vec<&DataTree> = trees.iter().collect();
        let id = NodeId::from("div");
        let r = NodeRun {
            node_id: &id,
            node_type: &node,
            inputs: &node.inputs,
            settings: &[],
            matching: Matching::Longest,
            principal: None,
            prepared: None,
        };
        let out = run_node(&r, &refs, false);
        assert_eq!(show(&out.outputs[0]), "{0}:[1,null,1]");
        assert_eq!(out.messages.len(), 1);
        assert_eq!(
            out.messages[0].to_string(),
            "error: node \"div\" at {0}[1]: division by zero"
        );
    }

    #[test]
    fn large_branches_give_identical_results_in_parallel() {
        let n = 100_000;
        let a: Vec<f64> = (0..n).map(|i| i as f64).collect();
        let trees = [DataTree::from_list(a), DataTree::from_item(0.5)];
        let refs: Vec<&DataTree> = trees.iter().collect();
        let node = addition();
        let id = NodeId::from("n");
        let r = NodeRun {
            node_id: &id,
            node_type: &node,
            inputs: &node.inputs,
            settings: &[],
            matching: Matching::Longest,
            principal: None,
            prepared: None,
        };
        let serial = run_node(&r, &refs, false);
        let parallel = run_node(&r, &refs, true);
        assert_eq!(serial.outputs, parallel.outputs);
        let out = serial.outputs[0].branch(&TreePath::zero()).unwrap();
        assert_eq!(out.len(), n);
        assert_eq!(out.get::<f64>(n - 1), Some(&(n as f64 - 0.5)));
    }
}

//! Running a script node: every iteration of the node in one request to a worker.
//!
//! The node's ports are tree access at the runtime's level, so the runtime calls it once per
//! evaluation with whole trees; the node then iterates as a node with the script's own
//! per-input access and type hints would be iterated, by running the runtime's iteration
//! itself ([`NodeCall`]) twice over the same trees:
//!
//! 1. *Record*: a node with the script's ports whose solve function only records what each
//!    iteration sees (an item, or which branch or tree). The runtime casts every input to its
//!    hint on the way, with its usual errors for items that do not cast.
//! 2. One [`Request`] carries every iteration to a worker; each outcome comes back in order.
//! 3. *Replay*: the same node, whose solve function writes the `k`-th outcome in the `k`-th
//!    iteration. The runtime's iteration is deterministic, so the `k`-th iteration is the same
//!    in both runs, and the outputs get the paths, gap logic and messages any node gets.
//!
//! The replay's outputs and messages (with their paths and item indices) become the node's.

use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{Arc, Mutex, PoisonError};

use locus_runtime::{
    Access, Branch, DataTree, DataType, NodeCall, NodeError, NodeType, Port, Solve, Value,
};

use super::protocol::{InputData, Outcome, OutputData, Request, ScriptInput, SharedData};
use super::spec::ScriptSpec;
use super::worker::WorkerPool;

/// The file name a script has in its tracebacks.
const SCRIPT_FILE_NAME: &str = "<script>";

/// The name of GhPython's output that carries what the script printed.
pub const PRINTED_OUTPUT: &str = "out";

/// What the record pass saw.
#[derive(Debug, Default)]
struct Recording {
    iterations: Vec<Vec<InputData>>,
    shared: Vec<SharedData>,
    /// (input, address of the branch or tree, index in `shared`): each list or tree is sent
    /// once however many iterations see it.
    seen: Vec<(usize, usize, usize)>,
}

impl Recording {
    fn shared_index(
        &mut self,
        input: usize,
        address: usize,
        make: impl FnOnce() -> SharedData,
    ) -> usize {
        if let Some(&(_, _, k)) = self
            .seen
            .iter()
            .rev()
            .find(|(i, a, _)| *i == input && *a == address)
        {
            return k;
        }
        self.shared.push(make());
        let k = self.shared.len() - 1;
        self.seen.push((input, address, k));
        k
    }
}

/// The script's inputs as ports, with their access and hinted types.
fn script_ports(spec: &ScriptSpec) -> Vec<Port> {
    spec.inputs
        .iter()
        .map(|i| {
            let mut p = Port::new(&i.name, &i.name, i.data_type).optional();
            p.access = i.access;
            p
        })
        .collect()
}

/// Runs the inner node `node_type` on the outer node's input trees.
fn call(node_type: &NodeType, trees: &[DataTree]) -> locus_runtime::NodeCallResult {
    let mut call = NodeCall::new(node_type);
    for t in trees {
        call = call.input(t.clone());
    }
    call.run()
}

/// The record pass.
fn record(spec: &ScriptSpec, ports: &[Port], trees: &[DataTree]) -> Recording {
    let recording = Arc::new(Mutex::new(Recording::default()));
    let sink = recording.clone();
    let accesses: Vec<Access> = spec.inputs.iter().map(|i| i.access).collect();
    let mut recorder =
        NodeType::new("script.record", "Record", "Record", "Script").solve(move |s| {
            let mut r = sink.lock().unwrap_or_else(PoisonError::into_inner);
            let mut iteration = Vec::with_capacity(accesses.len());
            for (k, access) in accesses.iter().enumerate() {
                iteration.push(match access {
                    Access::Item => InputData::Item(s.value(k)),
                    Access::List => {
                        let branch = s.branch(k);
                        let address = branch.map_or(0, |b| std::ptr::from_ref(b) as usize);
                        InputData::Shared(r.shared_index(k, address, || {
                            SharedData::List(
                                branch.map(|b| b.values().collect()).unwrap_or_default(),
                            )
                        }))
                    }
                    Access::Tree => {
                        let tree = s.tree(k)?;
                        let address = std::ptr::from_ref(tree) as usize;
                        InputData::Shared(
                            r.shared_index(k, address, || SharedData::Tree(tree.clone())),
                        )
                    }
                });
            }
            r.iterations.push(iteration);
            Ok(())
        });
    recorder.inputs = ports.to_vec();
    let _ = call(&recorder, trees);
    let mut r = recording.lock().unwrap_or_else(PoisonError::into_inner);
    std::mem::take(&mut *r)
}

/// Runs the script over the outer node's input trees and writes its outputs and messages.
pub(crate) fn run(
    s: &mut Solve<'_>,
    spec: &ScriptSpec,
    pool: &WorkerPool,
) -> Result<(), NodeError> {
    if spec.code.trim().is_empty() {
        return Ok(());
    }
    let trees: Vec<DataTree> = (0..s.input_count())
        .map(|k| s.tree(k).cloned())
        .collect::<Result<_, _>>()?;
    let outputs: Vec<String> = (0..)
        .map_while(|k| s.output_port(k).map(|p| p.nickname.clone()))
        .collect();
    let ports = script_ports(spec);
    let recording = record(spec, &ports, &trees);
    let script_outputs: Vec<String> = outputs
        .iter()
        .filter(|n| n.as_str() != PRINTED_OUTPUT)
        .cloned()
        .collect();
    let request = Request {
        node: SCRIPT_FILE_NAME.to_owned(),
        code: spec.code.clone(),
        ghpython: spec.ghpython,
        time_limit: spec.time_limit.as_secs_f64(),
        inputs: spec
            .inputs
            .iter()
            .map(|i| ScriptInput {
                name: i.name.clone(),
                access: i.access,
                hint: i.hint.clone(),
            })
            .collect(),
        outputs: script_outputs,
        shared: recording.shared,
        iterations: recording.iterations,
    };
    let n = request.iterations.len();
    if n == 0 {
        return Ok(());
    }
    let bytes = request
        .encode()
        .map_err(|e| NodeError(format!("an input cannot be sent to Python: {e}")))?;
    let outcomes = pool.run(&bytes, n, spec.time_limit).map_err(NodeError)?;
    let replayed = replay(&ports, &outputs, outcomes, &trees);
    for (k, tree) in replayed.outputs.into_iter().enumerate() {
        s.set_tree(k, tree);
    }
    for m in replayed.messages {
        s.message_at(m.level, m.path, m.index, m.text);
    }
    Ok(())
}

/// The access an output gets in the replay: a tree if any call gave it a tree, else a list if
/// any gave it a list, else an item.
fn output_access(outcomes: &[Result<Outcome, String>], k: usize) -> Access {
    let kinds = outcomes
        .iter()
        .filter_map(|o| o.as_ref().ok())
        .filter_map(|o| o.outputs.get(k));
    let mut access = Access::Item;
    for data in kinds {
        match data {
            OutputData::Tree(_) => return Access::Tree,
            OutputData::List(_) => access = Access::List,
            OutputData::Item(_) | OutputData::Unset => {}
        }
    }
    access
}

/// The replay pass.
fn replay(
    ports: &[Port],
    outputs: &[String],
    outcomes: Vec<Result<Outcome, String>>,
    trees: &[DataTree],
) -> locus_runtime::NodeCallResult {
    // Which outcome output feeds which node output (the printed text has none).
    let mut sources = Vec::with_capacity(outputs.len());
    let mut next = 0;
    for name in outputs {
        if name == PRINTED_OUTPUT {
            sources.push(None);
        } else {
            sources.push(Some(next));
            next += 1;
        }
    }
    let mut replayer = NodeType::new("script.replay", "Replay", "Replay", "Script");
    replayer.inputs = ports.to_vec();
    for (name, source) in outputs.iter().zip(&sources) {
        let mut port = Port::new(name, name, DataType::Generic);
        if let Some(k) = source {
            port.access = output_access(&outcomes, *k);
        } else {
            port.data_type = DataType::Text;
        }
        replayer = replayer.output(port);
    }
    let accesses: Vec<Access> = replayer.outputs.iter().map(|p| p.access).collect();
    let counter = AtomicUsize::new(0);
    let outcomes = Arc::new(outcomes);
    let replayer = replayer.solve(move |s| {
        let i = counter.fetch_add(1, Ordering::Relaxed);
        let outcome = match outcomes.get(i) {
            Some(Ok(o)) => o,
            Some(Err(why)) => return Err(NodeError(why.clone())),
            None => {
                return Err(NodeError(
                    "internal: an iteration that was not recorded".to_owned(),
                ));
            }
        };
        let printed = outcome.printed.trim_end();
        for (k, source) in sources.iter().enumerate() {
            let data = match source {
                Some(j) => outcome
                    .outputs
                    .get(*j)
                    .cloned()
                    .unwrap_or(OutputData::Unset),
                None if printed.is_empty() => OutputData::Unset,
                None => OutputData::Item(Some(Value::Text(printed.to_owned()))),
            };
            write_output(s, k, accesses[k], data);
        }
        if !printed.is_empty() {
            s.remark(printed.to_owned());
        }
        for (level, text) in &outcome.messages {
            s.message_at(*level, Some(s.path().clone()), s.index(), text.clone());
        }
        match &outcome.error {
            Some(e) => Err(NodeError(e.clone())),
            None => Ok(()),
        }
    });
    call(&replayer, trees)
}

/// Writes what one call gave one output, as an output of the given access.
fn write_output(s: &mut Solve<'_>, k: usize, access: Access, data: OutputData) {
    match (access, data) {
        (Access::Item, OutputData::Item(v)) => s.set_value(k, v),
        (Access::Item, _) => s.set_value(k, None),
        (Access::List, OutputData::List(items)) => s.set_list_values(k, items),
        (Access::List, OutputData::Item(v)) => s.set_list_values(k, vec![v]),
        (Access::List, _) => s.set_list_values(k, Vec::new()),
        (Access::Tree, OutputData::Tree(tree)) => s.set_tree(k, tree),
        (Access::Tree, other) => {
            // Items and lists of calls that gave no tree go to the iteration's own path.
            let mut path = s.path().clone();
            if let Some(i) = s.index() {
                path = path.with_appended(u32::try_from(i).unwrap_or(u32::MAX));
            }
            let mut branch = Branch::new(DataType::Generic);
            match other {
                OutputData::Item(v) => branch.push_option(v),
                OutputData::List(items) => items.into_iter().for_each(|v| branch.push_option(v)),
                OutputData::Unset | OutputData::Tree(_) => {}
            }
            let mut tree = DataTree::new();
            tree.insert(path, branch.narrowed());
            s.set_tree(k, tree);
        }
    }
}

//! Evaluating a checked graph: input collection, scheduling, caching and parallelism.
//!
//! An [`Evaluator`] owns one [`Plan`] and the latest outputs of every node. Evaluation runs the
//! *dirty* nodes in topological order; setting a named input marks its node and everything
//! downstream of it dirty, so the next evaluation recomputes only those (Grasshopper's expiry).
//! Independent nodes of the same depth run in parallel, and large nodes split their iterations
//! over threads (see `iterate`); every result is assembled in a fixed order, so outputs and
//! messages are identical for any number of threads.

use std::panic::{AssertUnwindSafe, catch_unwind};
use std::sync::Arc;

use rayon::prelude::*;

use crate::evaluation::iterate::{NodeLimit, NodeOutput, NodeRun, run_node};
use crate::evaluation::progress::{Progress, ProgressHook, Tracker};
use crate::evaluation::{collect, output_modifiers};
use crate::limits::{Budget, Watch, thread_cap};
use crate::{DataTree, Level, LimitHit, Limits, Message, NodeError, NodeId, Plan, Prepared};

/// Why a host request could not be carried out.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[non_exhaustive]
pub enum EvalError {
    /// No named input has this name.
    #[error("unknown input \"{name}\" (the graph's inputs are: {known})")]
    UnknownInput {
        /// The name asked for.
        name: String,
        /// The graph's input names, comma-separated.
        known: String,
    },
    /// No node has this id.
    #[error("unknown node \"{id}\"")]
    UnknownNode {
        /// The id asked for.
        id: String,
    },
    /// A value given as literal text could not be read against the input's type.
    #[error("bad value for input \"{name}\": {message}")]
    BadValue {
        /// The input's name.
        name: String,
        /// What is wrong with the text.
        message: String,
    },
    /// A thread pool could not be built, or zero threads were asked for.
    #[error("cannot start {threads} threads: {reason}")]
    ThreadPool {
        /// The number of threads asked for.
        threads: usize,
        /// What went wrong.
        reason: String,
    },
}

/// How many threads evaluation may use.
#[derive(Clone, Debug, Default)]
enum Threads {
    /// Rayon's global pool (one thread per core).
    #[default]
    Global,
    /// Everything on the calling thread.
    Serial,
    /// A pool of its own.
    Pool(Arc<rayon::ThreadPool>),
}

/// The order of one evaluation: the dirty nodes grouped by depth.
#[derive(Clone, Debug, Default)]
struct Schedule {
    /// Depth `d`'s nodes are `by_depth[starts[d]..starts[d + 1]]`.
    starts: Vec<usize>,
    /// Scratch for the counting sort.
    next: Vec<usize>,
    by_depth: Vec<usize>,
}

/// The state of one node between evaluations.
#[derive(Clone, Debug, Default)]
struct NodeState {
    messages: Vec<Message>,
    dirty: bool,
    prepared: Option<Result<Prepared, NodeError>>,
    /// For each output, whether the last run left it empty because nothing read it; it is
    /// computed when a host first asks for it (see `late`).
    skipped: Vec<bool>,
    /// Skipped outputs computed on request.
    late: Vec<std::sync::OnceLock<DataTree>>,
}

/// A graph ready to evaluate, with its named inputs and the latest results.
///
/// ```
/// use locus_runtime::{DataTree, Evaluator, Plan};
/// # fn plan() -> Plan { Plan { nodes: vec![], order: vec![], inputs: vec![], outputs: vec![] } }
/// let mut evaluator = Evaluator::new(plan());
/// evaluator.evaluate();
/// assert_eq!(evaluator.messages().count(), 0);
/// ```
#[derive(Debug)]
pub struct Evaluator {
    plan: Plan,
    states: Vec<NodeState>,
    overrides: Vec<Option<DataTree>>,
    /// For each node, the nodes its outputs feed.
    downstream: Vec<Vec<usize>>,
    /// For each node, its depth: 0 for nodes without wired inputs, else 1 + the deepest source.
    depth: Vec<usize>,
    threads: Threads,
    last_run: Vec<usize>,
    /// Every node's ports, wires and outputs as flat tables (`layout.rs`).
    layout: Layout,
    /// Every node's latest outputs, node after node (`Layout::outputs`).
    outputs: Vec<Arc<DataTree>>,
    /// The empty tree that released outputs share (no allocation per output).
    empty: Arc<DataTree>,
    /// The last evaluation's order, kept for its allocations.
    schedule: Schedule,
    limits: Limits,
    /// The first limit the last evaluation hit.
    limit_hit: Option<LimitHit>,
    /// The nodes the last evaluation did not run because it stopped early.
    not_run: Vec<usize>,
    /// For each node, the entries (items plus branches) its outputs hold, and their sum.
    held: Vec<usize>,
    held_total: usize,
    /// The observer told of each evaluation's progress, if any.
    progress: Option<ProgressHook>,
}

impl Evaluator {
    /// An evaluator for a checked plan; nothing runs until [`evaluate`](Self::evaluate).
    pub fn new(plan: Plan) -> Self {
        let n = plan.nodes.len();
        let mut downstream = vec![Vec::new(); n];
        for (i, node) in plan.nodes.iter().enumerate() {
            for input in &node.inputs {
                for &(source, _) in &input.sources {
                    if source < n && !downstream[source].contains(&i) {
                        downstream[source].push(i);
                    }
                }
            }
        }
        let mut depth = vec![0; n];
        for &i in &plan.order {
            let d = plan.nodes[i]
                .inputs
                .iter()
                .flat_map(|input| input.sources.iter())
                .map(|&(source, _)| depth[source] + 1)
                .max()
                .unwrap_or(0);
            depth[i] = d;
        }
        let states = plan
            .nodes
            .iter()
            .map(|_| NodeState {
                messages: Vec::new(),
                dirty: true,
                prepared: None,
                skipped: Vec::new(),
                late: Vec::new(),
            })
            .collect();
        let overrides = vec![None; plan.inputs.len()];
        let layout = Layout::new(&plan);
        let empty = Arc::new(DataTree::new());
        let outputs = vec![Arc::clone(&empty); layout.wanted.len()];
        Self {
            layout,
            outputs,
            empty,
            schedule: Schedule::default(),
            plan,
            states,
            overrides,
            downstream,
            depth,
            threads: Threads::Global,
            last_run: Vec::new(),
            limits: Limits::default(),
            limit_hit: None,
            not_run: Vec::new(),
            held: vec![0; n],
            held_total: 0,
            progress: None,
        }
    }

    /// Tells `observer` of the progress of the next evaluations (nodes started and finished),
    /// or no one for `None`.
    pub fn set_progress(&mut self, observer: Option<Arc<dyn Progress>>) {
        self.progress = observer.map(ProgressHook);
    }

    /// Sets the limits of the next evaluations (time, cancellation, item budget).
    pub fn set_limits(&mut self, limits: Limits) {
        self.limits = limits;
    }

    /// The limits of the evaluations.
    pub fn limits(&self) -> &Limits {
        &self.limits
    }

    /// The first limit the last evaluation hit, if any: a timeout or cancellation (the
    /// evaluation stopped; [`not_run`](Self::not_run) lists the nodes it did not run), or a
    /// node above the item budget (that node got no outputs and an error message).
    pub fn limit_hit(&self) -> Option<&LimitHit> {
        self.limit_hit.as_ref()
    }

    /// The ids of the nodes the last evaluation did not run because a time limit or a
    /// cancellation stopped it (their outputs are empty; the next evaluation runs them).
    pub fn not_run(&self) -> Vec<&NodeId> {
        self.not_run
            .iter()
            .map(|&i| &self.plan.nodes[i].id)
            .collect()
    }

    /// Limits evaluation to `threads` threads (1 runs everything on the calling thread).
    /// Counts above [`MAX_THREADS_PER_CORE`](crate::MAX_THREADS_PER_CORE) × the cores are
    /// capped to that; the count used is returned (a host warns when it is less than asked).
    ///
    /// # Errors
    /// [`EvalError::ThreadPool`] when `threads` is 0 or the pool cannot be created.
    pub fn set_threads(&mut self, threads: usize) -> Result<usize, EvalError> {
        let threads = threads.min(thread_cap());
        self.threads = match threads {
            0 => {
                return Err(EvalError::ThreadPool {
                    threads,
                    reason: "at least one thread is needed".to_owned(),
                });
            }
            1 => Threads::Serial,
            n => Threads::Pool(Arc::new(
                rayon::ThreadPoolBuilder::new()
                    .num_threads(n)
                    .build()
                    .map_err(|e| EvalError::ThreadPool {
                        threads: n,
                        reason: e.to_string(),
                    })?,
            )),
        };
        Ok(threads)
    }

    /// The plan being evaluated.
    pub fn plan(&self) -> &Plan {
        &self.plan
    }

    /// The names of the graph's inputs.
    pub fn input_names(&self) -> impl Iterator<Item = &str> {
        self.plan.inputs.iter().map(|(name, _, _)| name.as_str())
    }

    /// The names of the graph's outputs.
    pub fn output_names(&self) -> impl Iterator<Item = &str> {
        self.plan.outputs.iter().map(|(name, _, _)| name.as_str())
    }

    /// Gives a named input a value (replacing the value in the graph) and marks everything
    /// downstream of it for re-evaluation.
    ///
    /// # Errors
    /// [`EvalError::UnknownInput`] when the graph has no input of that name.
    pub fn set_input(&mut self, name: &str, tree: DataTree) -> Result<(), EvalError> {
        let Some(k) = self.plan.inputs.iter().position(|(n, _, _)| n == name) else {
            return Err(self.unknown_input(name));
        };
        if self.overrides[k].as_ref() == Some(&tree) {
            return Ok(());
        }
        self.overrides[k] = Some(tree);
        let node = self.plan.inputs[k].1;
        self.mark_dirty(node);
        Ok(())
    }

    /// The error for an input name the graph does not have.
    pub(crate) fn unknown_input(&self, name: &str) -> EvalError {
        let known: Vec<&str> = self.input_names().collect();
        EvalError::UnknownInput {
            name: name.to_owned(),
            known: if known.is_empty() {
                "none".to_owned()
            } else {
                known.join(", ")
            },
        }
    }

    /// Removes a value given with [`set_input`](Self::set_input), going back to the graph's.
    pub fn clear_input(&mut self, name: &str) {
        if let Some(k) = self.plan.inputs.iter().position(|(n, _, _)| n == name)
            && self.overrides[k].take().is_some()
        {
            self.mark_dirty(self.plan.inputs[k].1);
        }
    }

    /// Marks node `node` (by id) and everything downstream of it for re-evaluation, as
    /// Grasshopper's "expire solution" does: for hosts whose data changed behind the graph's back.
    ///
    /// # Errors
    /// [`EvalError::UnknownNode`] when the graph has no node of that id.
    pub fn expire(&mut self, node: &str) -> Result<(), EvalError> {
        let Some(i) = self.plan.nodes.iter().position(|n| n.id.0 == node) else {
            return Err(EvalError::UnknownNode {
                id: node.to_owned(),
            });
        };
        self.mark_dirty(i);
        Ok(())
    }

    /// Marks every node for re-evaluation (a full recompute on the next
    /// [`evaluate`](Self::evaluate)).
    pub fn expire_all(&mut self) {
        for state in &mut self.states {
            state.dirty = true;
        }
    }

    /// Marks a node and everything downstream of it for re-evaluation.
    fn mark_dirty(&mut self, node: usize) {
        let mut stack = vec![node];
        while let Some(i) = stack.pop() {
            if i == node || !self.states[i].dirty {
                self.states[i].dirty = true;
                stack.extend(self.downstream[i].iter().copied());
            }
        }
    }

    /// Runs every node whose inputs changed since the last evaluation (all nodes the first
    /// time), in topological order.
    pub fn evaluate(&mut self) {
        let threads = self.threads.clone();
        match threads {
            Threads::Serial => self.evaluate_dirty(false),
            Threads::Global => self.evaluate_dirty(true),
            Threads::Pool(pool) => pool.install(|| self.evaluate_dirty(true)),
        }
    }

    fn evaluate_dirty(&mut self, parallel: bool) {
        // The dirty nodes grouped by depth (nodes of one depth never feed each other), in plan
        // order within a depth: a counting sort into one array, so that the cost per node does
        // not depend on the graph's size (no vector per depth).
        // The arrays are kept from one evaluation to the next: allocating and freeing arrays as
        // long as the graph on every evaluation made the allocator consolidate its free lists
        // and the kernel clear fresh pages, a cost per node that grew with the graph.
        let mut schedule = std::mem::take(&mut self.schedule);
        let Schedule {
            starts,
            next,
            by_depth,
        } = &mut schedule;
        starts.clear();
        for &i in &self.plan.order {
            if self.states[i].dirty {
                let d = self.depth[i];
                if starts.len() <= d + 1 {
                    starts.resize(d + 2, 0);
                }
                starts[d + 1] += 1;
            }
        }
        for d in 1..starts.len() {
            starts[d] += starts[d - 1];
        }
        let total = starts.last().copied().unwrap_or(0);
        by_depth.clear();
        by_depth.resize(total, 0);
        next.clear();
        next.extend_from_slice(starts);
        for &i in &self.plan.order {
            if self.states[i].dirty {
                let slot = &mut next[self.depth[i]];
                by_depth[*slot] = i;
                *slot += 1;
            }
        }
        self.run_schedule(&schedule, parallel);
        self.schedule = schedule;
    }

    /// Runs the nodes of `schedule`, wave after wave.
    fn run_schedule(&mut self, schedule: &Schedule, parallel: bool) {
        let Schedule {
            starts, by_depth, ..
        } = schedule;
        let total = by_depth.len();
        let budget = Budget {
            max_items: self.limits.max_items_per_output,
            watch: Watch::start(&self.limits),
        };
        self.limit_hit = None;
        self.not_run.clear();
        self.last_run.clear();
        let hook = self.progress.clone();
        let tracker = Tracker::start(hook.as_ref(), total);
        let mut results: Vec<(usize, NodeOutput)> = Vec::new();
        for w in 0..starts.len().saturating_sub(1) {
            let wave = &by_depth[starts[w]..starts[w + 1]];
            if wave.is_empty() {
                continue;
            }
            if let Some(hit) = budget.watch.check() {
                self.stop(hit, &by_depth[starts[w]..]);
                return;
            }
            for &i in wave {
                self.ensure_prepared(i);
                // The old outputs are replaced below; dropping them first lets their memory be
                // reused for the new ones (no node reads its own outputs).
                self.release(i);
            }
            let run = |i: usize| {
                let id = self.plan.nodes[i].id.0.as_str();
                (i, tracker.node(id, || self.run(i, parallel, &budget)))
            };
            if parallel && wave.len() > 1 {
                results.par_extend(wave.par_iter().map(|&i| run(i)));
            } else {
                results.extend(wave.iter().map(|&i| run(i)));
            }
            self.last_run.extend_from_slice(wave);
            let mut stopped = None;
            for (i, mut out) in results.drain(..) {
                match out.limit.take() {
                    Some(NodeLimit::Watch) => {
                        let hit = budget.watch.check().unwrap_or(LimitHit::Cancelled);
                        out.messages
                            .push(self.node_message(i, format!("stopped: {hit}")));
                        stopped = Some(hit);
                    }
                    Some(NodeLimit::Items(detail)) => self.hit(LimitHit::Items {
                        node: self.plan.nodes[i].id.clone(),
                        detail,
                    }),
                    None => {}
                }
                self.store(i, out);
            }
            if let Some(hit) = stopped {
                self.stop(hit, &by_depth[starts[w + 1]..]);
                return;
            }
        }
    }

    /// Records the first limit hit of an evaluation.
    fn hit(&mut self, hit: LimitHit) {
        if self.limit_hit.is_none() {
            self.limit_hit = Some(hit);
        }
    }

    /// Stops the evaluation: the nodes of the remaining waves are not run (empty outputs, still
    /// dirty for the next evaluation).
    fn stop(&mut self, hit: LimitHit, rest: &[usize]) {
        self.hit(hit);
        for &i in rest {
            self.release(i);
            self.states[i].messages.clear();
            self.not_run.push(i);
        }
    }

    /// Empties a node's outputs.
    fn release(&mut self, i: usize) {
        for tree in &mut self.outputs[self.layout.outputs(i)] {
            *tree = Arc::clone(&self.empty);
        }
        self.states[i].skipped.clear();
        self.states[i].late.clear();
        self.held_total -= self.held[i];
        self.held[i] = 0;
    }

    /// Keeps a node's new outputs, unless they take the graph above its total item budget.
    fn store(&mut self, i: usize, mut out: NodeOutput) {
        let entries = out
            .outputs
            .iter()
            .map(|t| t.item_count().saturating_add(t.branch_count()))
            .fold(0usize, usize::saturating_add);
        let max = self.limits.max_items_total;
        if self.held_total.saturating_add(entries) > max {
            let detail = format!(
                "its outputs would hold {entries} items and branches, taking the graph to {} \
                 (above the limit of {max} items in all outputs)",
                self.held_total.saturating_add(entries)
            );
            for tree in &mut out.outputs {
                *tree = DataTree::new();
            }
            out.messages.push(self.node_message(i, detail.clone()));
            self.hit(LimitHit::Items {
                node: self.plan.nodes[i].id.clone(),
                detail,
            });
        } else {
            self.held[i] = entries;
            self.held_total += entries;
        }
        let wanted = self.layout.wanted(i);
        let state = &mut self.states[i];
        // Both stay empty (no allocation) when every output is wanted.
        state.skipped.clear();
        state.late.clear();
        if wanted.iter().any(|w| !w) {
            state.skipped.extend(wanted.iter().map(|w| !w));
            state
                .late
                .extend(wanted.iter().map(|_| std::sync::OnceLock::new()));
        }
        for (slot, tree) in self.outputs[self.layout.outputs(i)]
            .iter_mut()
            .zip(out.outputs)
        {
            *slot = Arc::new(tree);
        }
        state.messages = out.messages;
        state.dirty = false;
    }

    /// An error message of node `i` about the whole node.
    fn node_message(&self, i: usize, text: String) -> Message {
        Message {
            node: self.plan.nodes[i].id.clone(),
            level: Level::Error,
            path: None,
            index: None,
            text,
        }
    }

    fn ensure_prepared(&mut self, i: usize) {
        if self.states[i].prepared.is_some() {
            return;
        }
        let node = &self.plan.nodes[i];
        let Some(prepare) = &node.node_type.prepare else {
            return;
        };
        let config = crate::NodeConfig {
            settings: &node.settings,
            inputs: self.layout.ports(i),
        };
        let result = catch_unwind(AssertUnwindSafe(|| prepare(&config))).unwrap_or_else(|_| {
            Err(NodeError(
                "internal error: the node's prepare step panicked".to_owned(),
            ))
        });
        self.states[i].prepared = Some(result);
    }

    /// Runs one node on the current outputs of its sources.
    fn run(&self, i: usize, parallel: bool, budget: &Budget) -> NodeOutput {
        self.run_wanting(i, parallel, budget, self.layout.wanted(i))
    }

    /// Runs one node, computing the outputs marked in `wanted` (the others stay empty).
    fn run_wanting(
        &self,
        i: usize,
        parallel: bool,
        budget: &Budget,
        wanted: &[bool],
    ) -> NodeOutput {
        let node = &self.plan.nodes[i];
        let n_outputs = node.node_type.outputs.len();
        let empty = || NodeOutput {
            outputs: (0..n_outputs).map(|_| DataTree::new()).collect(),
            messages: Vec::new(),
            limit: None,
        };
        if node.disabled {
            return empty();
        }
        let message = |level, text: String| Message {
            node: node.id.clone(),
            level,
            path: None,
            index: None,
            text,
        };
        let prepared = match &self.states[i].prepared {
            Some(Ok(p)) => Some(p),
            Some(Err(e)) => {
                let mut out = empty();
                out.messages.push(message(Level::Error, e.0.clone()));
                return out;
            }
            None => None,
        };
        // Collect every input: wires, graph inputs, values, defaults; then modifiers and casts.
        let mut messages = Vec::new();
        let mut data: smallvec::SmallVec<[std::borrow::Cow<'_, DataTree>; 4]> =
            smallvec::SmallVec::with_capacity(node.inputs.len());
        let mut missing = Vec::new();
        for (k, input) in node.inputs.iter().enumerate() {
            let raw = self.raw_input(i, k);
            let collected =
                match collect::prepare_input(&node.id, input, raw, &mut messages, budget.max_items)
                {
                    Ok(tree) => tree,
                    Err(detail) => {
                        let mut out = empty();
                        out.messages = messages;
                        out.messages.push(message(Level::Error, detail.clone()));
                        out.limit = Some(NodeLimit::Items(detail));
                        return out;
                    }
                };
            if !input.port.optional && collected.item_count() == 0 && collected.branch_count() == 0
            {
                missing.push(input.port.nickname.clone());
            }
            data.push(collected);
        }
        if !missing.is_empty() {
            let mut out = empty();
            out.messages = messages;
            for name in missing {
                out.messages.push(message(
                    Level::Warning,
                    format!("input parameter {name} failed to collect data"),
                ));
            }
            return out;
        }
        let run = NodeRun {
            node_id: &node.id,
            node_type: &node.node_type,
            inputs: self.layout.ports(i),
            settings: &node.settings,
            matching: node.matching,
            principal: node.principal_input(),
            prepared,
            wanted,
            budget,
        };
        let refs: smallvec::SmallVec<[&DataTree; 4]> = data.iter().map(|d| &**d).collect();
        match catch_unwind(AssertUnwindSafe(|| run_node(&run, &refs, parallel))) {
            Ok(mut out) => {
                messages.append(&mut out.messages);
                out.messages = messages;
                // Most nodes have no output modifiers: one length test on the hot path.
                if !node.output_modifiers.is_empty() {
                    output_modifiers::apply(node, &mut out, budget.max_items);
                }
                out
            }
            Err(payload) => {
                let what = payload
                    .downcast_ref::<&str>()
                    .map(|s| (*s).to_owned())
                    .or_else(|| payload.downcast_ref::<String>().cloned())
                    .unwrap_or_default();
                let mut out = empty();
                out.messages = messages;
                out.messages.push(message(
                    Level::Error,
                    format!("internal error: the node panicked ({what}); please report it"),
                ));
                out
            }
        }
    }

    /// The data arriving at input `k` of node `i` before modifiers and casts: the merged
    /// outputs of the wired sources in wire order, else the graph input's value, else the
    /// node's value or the port's default. `None` when there is none.
    fn raw_input(&self, i: usize, k: usize) -> Option<std::borrow::Cow<'_, DataTree>> {
        use std::borrow::Cow;
        let input = &self.plan.nodes[i].inputs[k];
        if let Some(slot) = self.layout.input_slot(i, k)
            && let Some(tree) = &self.overrides[slot]
        {
            return Some(Cow::Borrowed(tree));
        }
        let stored = |node: usize, output: usize| -> &DataTree {
            self.layout
                .output_index(node, output)
                .map_or(&self.empty, |j| &self.outputs[j])
        };
        match self.layout.sources(i, k) {
            [] => input.value.as_ref().map(Cow::Borrowed),
            &[(node, output)] => Some(Cow::Borrowed(stored(node, output))),
            sources => {
                let mut merged = DataTree::new();
                for &(node, output) in sources {
                    merged.merge(stored(node, output));
                }
                Some(Cow::Owned(merged))
            }
        }
    }

    /// The data of a named output after the last evaluation.
    pub fn output(&self, name: &str) -> Option<&DataTree> {
        let &(_, node, port) = self.plan.outputs.iter().find(|(n, _, _)| n == name)?;
        Some(self.tree(node, port))
    }

    /// Every named output with its data, in the graph's order.
    pub fn outputs(&self) -> impl Iterator<Item = (&str, &DataTree)> {
        self.plan
            .outputs
            .iter()
            .map(|(name, node, port)| (name.as_str(), self.tree(*node, *port)))
    }

    /// Every output of every node with its data, as `(node id, output nickname, tree)`, in the
    /// graph's node order: what Grasshopper's canvas preview draws. An output that no wire and
    /// no named output reads is computed on this request (its node runs again) unless
    /// [`keep_all_outputs`](Self::keep_all_outputs) was called before the evaluation.
    pub fn node_outputs(&self) -> impl Iterator<Item = (&str, &str, &DataTree)> {
        self.plan
            .nodes
            .iter()
            .enumerate()
            .flat_map(move |(i, node)| {
                node.node_type
                    .outputs
                    .iter()
                    .enumerate()
                    .map(move |(k, port)| {
                        (node.id.0.as_str(), port.nickname.as_str(), self.tree(i, k))
                    })
            })
    }

    /// The data of output `port` (nickname or name) of node `node`.
    pub fn node_output(&self, node: &str, port: &str) -> Option<&DataTree> {
        let i = self.plan.nodes.iter().position(|n| n.id.0 == node)?;
        let k = self.plan.nodes[i].node_type.output_index(port)?;
        Some(self.tree(i, k))
    }

    /// The data of output `output` of the node at index `node` of the plan.
    ///
    /// # Panics
    /// When the indices are out of range.
    pub fn node_output_at(&self, node: usize, output: usize) -> &DataTree {
        self.tree(node, output)
    }

    /// Every runtime message of the last evaluation (kept for nodes that did not re-run), in
    /// the graph's node order.
    pub fn messages(&self) -> impl Iterator<Item = &Message> {
        self.states.iter().flat_map(|s| s.messages.iter())
    }

    /// The runtime messages of one node (by id) from its last run; none for an unknown id.
    pub fn node_messages(&self, node: &str) -> impl Iterator<Item = &Message> {
        let i = self.plan.nodes.iter().position(|n| n.id.0 == node);
        i.into_iter().flat_map(|i| self.states[i].messages.iter())
    }

    /// The worst message level of a node, if it has messages.
    pub fn node_level(&self, node: &str) -> Option<Level> {
        let i = self.plan.nodes.iter().position(|n| n.id.0 == node)?;
        self.states[i].messages.iter().map(|m| m.level).max()
    }

    /// The ids of the nodes that ran in the last evaluation, in the order they were scheduled.
    pub fn last_run(&self) -> Vec<&NodeId> {
        self.last_run
            .iter()
            .map(|&i| &self.plan.nodes[i].id)
            .collect()
    }
}

mod late;
mod layout;

use layout::Layout;

#[cfg(test)]
mod tests;

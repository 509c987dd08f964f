//! The node runtime of locus: data trees, typed ports, Grasshopper matching and evaluation.
//!
//! The runtime names no concrete node: node types are registered by the node library (or by a
//! host) in a [`NodeRegistry`] value.
//!
//! # Hosting a graph
//!
//! A host builds a registry, loads a graph ([`Evaluator::from_text`], [`Evaluator::from_file`],
//! or [`Document::parse`] → [`Document::check`] → [`Checked::into_evaluator`] to see the
//! warnings), sets named inputs as data trees ([`Evaluator::set_input`]) or as literal text read
//! against the input's type ([`Evaluator::set_input_text`], as `locus run --set` does),
//! evaluates, and reads named outputs ([`Evaluator::output`]) and per-node messages
//! ([`Evaluator::node_messages`]). After an input changes, the next evaluation runs only the
//! nodes downstream of it ([`Evaluator::last_run`] says which). Evaluators, plans and registries
//! are `Send + Sync`, so a host can hold many graphs and evaluate them on several threads.
//! Every run is bounded by [`Limits`] ([`Evaluator::set_limits`]: a timeout, a [`CancelToken`],
//! item budgets counted before anything is allocated); [`Evaluator::limit_hit`] and
//! [`Evaluator::not_run`] say what stopped and what did not run (`docs/limits.md`).
//!
//! ```
//! use locus_runtime::{DataTree, DataType, EvalError, Evaluator, NodeRegistry, NodeType, Port};
//!
//! // The node types the graphs use: here one, declared on the spot.
//! let mut registry = NodeRegistry::new();
//! registry.register(
//!     NodeType::new("maths.addition", "Addition", "A+B", "Maths")
//!         .input(Port::new("A", "A", DataType::Number))
//!         .input(Port::new("B", "B", DataType::Number).default_value(0.0))
//!         .output(Port::new("Result", "R", DataType::Number))
//!         .solve(|s| {
//!             let sum = *s.item::<f64>(0)? + *s.item::<f64>(1)?;
//!             if !sum.is_finite() {
//!                 return Err("the sum is not finite".into());
//!             }
//!             s.set(0, sum);
//!             Ok(())
//!         }),
//! );
//! let text = r#"(
//!     format: 1,
//!     nodes: [
//!         (id: "first", type: "maths.addition", values: {"B": 10}),
//!         (id: "second", type: "maths.addition", values: {"B": 100}),
//!         (id: "other", type: "maths.addition", values: {"A": 1, "B": 2}),
//!     ],
//!     wires: [("first.R", "second.A")],
//!     inputs: {"x": "first.A"},
//!     outputs: {"sum": "second.R", "other": "other.R"},
//! )"#;
//! let mut graph = Evaluator::from_text(text, &registry).expect("a valid graph");
//!
//! // Set a named input as a data tree and evaluate.
//! graph.set_input("x", DataTree::from_list(vec![1.0, 2.0]))?;
//! graph.evaluate();
//! assert_eq!(graph.output("sum"), Some(&DataTree::from_list(vec![111.0, 112.0])));
//! assert_eq!(graph.output("other"), Some(&DataTree::from_item(3.0)));
//!
//! // Change it (here as literal text) and evaluate again: only the nodes downstream run.
//! graph.set_input_text("x", "[5, inf]")?;
//! graph.evaluate();
//! let ran: Vec<&str> = graph.last_run().iter().map(|id| id.0.as_str()).collect();
//! assert_eq!(ran, ["first", "second"]);
//! // A failing iteration leaves a null and a message naming its path and index; the rest runs.
//! let sum = graph.output("sum").expect("a named output");
//! assert_eq!(sum.to_text(), "{0}:[115, null]");
//! let messages: Vec<String> = graph.node_messages("first").map(|m| m.to_string()).collect();
//! assert_eq!(messages, ["error: node \"first\" at {0}[1]: the sum is not finite"]);
//!
//! // Bad requests name the input.
//! assert_eq!(
//!     graph.set_input_text("y", "1").unwrap_err().to_string(),
//!     "unknown input \"y\" (the graph's inputs are: x)"
//! );
//! assert!(matches!(graph.set_input_text("x", "(1, 2, 3)"), Err(EvalError::BadValue { .. })));
//!
//! // Many graphs at once, from a file too, evaluated on their own threads.
//! let path = std::env::temp_dir().join(format!("locus-host-example-{}.ron", std::process::id()));
//! std::fs::write(&path, text).expect("a writable temporary directory");
//! let mut graphs = vec![graph, Evaluator::from_file(&path, &registry)?];
//! std::fs::remove_file(&path).ok();
//! for (k, g) in graphs.iter_mut().enumerate() {
//!     g.set_input("x", DataTree::from_item(k as f64))?;
//! }
//! std::thread::scope(|scope| {
//!     for g in &mut graphs {
//!         scope.spawn(move || g.evaluate());
//!     }
//! });
//! assert_eq!(graphs[1].output("sum"), Some(&DataTree::from_item(111.0)));
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! # Declaring item functions
//!
//! A node whose inputs are all items and which has one output is best declared as a plain
//! function of typed items with [`NodeType::lift1`], [`NodeType::lift2`] or [`NodeType::lift3`]
//! (`.lift2(|a: &f64, b: &f64| Ok(a + b))`) instead of a general [`NodeType::solve`] function:
//! the runtime then runs it as one loop over the typed columns of each branch pairing (split
//! over threads for large branches), with exactly the results of the general iteration
//! (matching, nulls, errors with path and index). Anything the loop does not cover (optional
//! inputs, cross reference, a generic column) goes through the general iteration.
//!
//! A node that must keep a general solve function (generic ports that take several kinds of
//! operand, warnings) can still add typed loops with [`NodeType::fast_path2`]: they run when the
//! data on its ports is of the loop's concrete types, and hand the node back to the solve
//! function as soon as one item needs it, so results never differ.
//!
//! # Performance
//!
//! `cargo bench -p locus-runtime --bench evaluation` (criterion) measures evaluation against
//! hand-written loops over the same arithmetic, in the same run; `--bench graph_file` reading and
//! checking, `--bench tree_ops` tree operations (see `docs/data-trees.md`). Figures from the
//! shared 2-core development machine (a VM, load average 1.2–1.5 from other work during the
//! run), so the ratios to the baseline measured in the same run are what counts:
//!
//! | case | time (median) | ratio |
//! | --- | --- | --- |
//! | hand loop: move 1M points by one vector | 2.24 ms | 1 |
//! | graph: Move 1M points (lifted), one thread | 2.57 ms | 1.15× |
//! | graph: Move 1M points (general solve), one thread | 21.6 ms | 9.6× |
//! | hand loop: add two lists of 1M numbers | 0.971 ms | 1 |
//! | graph: Addition (lifted), one thread | 0.969 ms | 1.00× |
//! | graph: Addition (general solve), one thread | 19.4 ms | 20× |
//! | hand loop: rotate 1M points (a sine and cosine each) | 16.5 ms | 1 |
//! | graph: rotate 1M points (lifted), one thread | 17.2 ms | 1.04× |
//! | graph: rotate 1M points (lifted), two threads | 11.2 ms | 1.53× faster than one thread |
//! | graph: Move 1M points (lifted), two threads | 2.42 ms | stays on one thread (below) |
//! | graph: Addition (lifted), two threads | 1.03 ms | stays on one thread (below) |
//! | evaluate a 1,000-node chain of Additions, one thread | 0.415 ms | |
//! | evaluate a 1,000-node chain of Additions, two threads | 0.494 ms | |
//! | read the 1,000-node graph file (`graph_file`) | 2.3 ms | |
//! | check it | 2.2 ms | |
//!
//! - Lifted item functions cost at most 1.3× the hand-written loop on one thread (target met;
//!   1.0–1.15× in this run, 0.9–1.2× over the session's runs). The general solve function
//!   costs a dynamic call and a `Solve` context per item, about 20 ns: use it for list and tree
//!   access, and `lift*` for item functions.
//! - The 1,000-node chain evaluates in well under the 2 ms target (3.3 ms before the evaluator
//!   grouped nodes by depth in one pass instead of one scan of the dirty nodes per depth).
//! - Two threads: every loop (lifted, several outputs, the general path) first runs a probe
//!   on the calling thread, over growing ranges of 1, 2, 4, … items until 0.1 ms have passed
//!   (`evaluation/spread.rs`). It spreads the rest over the threads, in tasks of about 50 µs,
//!   only when an item takes at least 8 ns and the rest at least 0.2 ms
//!   (`PARALLEL_ITEM_NANOS`), so a hundred slow items (closest points) are spread too. Below
//!   8 ns, a loop is bound by memory traffic (Move and Addition move 48 and 24 MB for 1M
//!   items) and a second thread made it about 2× slower here, so Move and Addition stay on one thread. The rotation is spread: 1.53× faster on two
//!   threads in this run, 1.4–1.74× over the session's runs depending on what else the machine
//!   was doing; the benchmark also prints the process CPU time, 1.10–1.37× that of one thread
//!   (the 1.74× run was the quietest, at 1.10×). The 1.7× target is therefore reached only when
//!   the second core is free; under a load average of 7 two threads were no faster at all.
//! - Cost per node against the graph's size (issue 16, part 3; `chain length` in the same
//!   bench, which prints the wall and CPU time per node): chains of 1,000, 10,000 and 100,000
//!   Additions cost 1.00 : 1.21 : 1.69 in CPU time per node before (0.56, 0.68, 0.95 µs) and
//!   1.00 : 1.04 : 1.34 after (0.50, 0.51, 0.67 µs), at a load average of 10 (see
//!   `docs/performance.md`, "Graph size"). What grew was memory traffic, not work: the
//!   instructions per node were the same at every size (callgrind). The evaluator no longer
//!   allocates a vector per depth and arrays as long as the graph on each evaluation, and reads
//!   each node's ports, wires and outputs from flat tables in node order (`evaluator/layout.rs`).
//! - Reading and checking the 1,000-node graph were quoted at 9.2 and 8.7 ms under a load
//!   average of 8–11; in this session they took 2.3 and 2.2 ms (the reader and checker are
//!   unchanged apart from inline tree paths).

mod call;
mod catalogue;
mod checking;
mod compare;
mod dot;
mod evaluation;
mod file;
mod graph;
mod host;
mod json;
mod limits;
mod message;
mod node;
mod plan;
mod registry;
mod trees;
mod value;

pub use crate::call::{NodeCall, NodeCallResult};
pub use crate::checking::cast::{CastError, can_cast, cast_branch, cast_tree, cast_value};
pub use crate::checking::cast_rules::number_to_integer;
pub use crate::checking::check::{Checked, check, check_text};
pub use crate::checking::diagnostic::{
    Diagnostic, DiagnosticKind, Location, PortDirection, Severity,
};
pub use crate::checking::subgraph::{MAX_SUBGRAPH_DEPTH, MAX_SUBGRAPH_NODES};
pub use crate::compare::{COMPARE_TOLERANCE, compare_expected, compare_trees, values_agree};
pub use crate::dot::to_dot;
pub use crate::evaluation::evaluator::{EvalError, Evaluator};
pub use crate::evaluation::lift::{ItemReport, Outputs};
pub use crate::evaluation::progress::Progress;
pub use crate::evaluation::solve::{ListView, Solve};
pub use crate::file::bless::BlessOutput;
pub use crate::file::canonical::CommentInside;
pub use crate::file::expected::{
    BREP_SUMMARY_TOLERANCE, BrepSummary, ExpectedItem, ExpectedTree, expectation_literal,
};
pub use crate::file::format::{Document, write_graph};
pub use crate::file::literal::{LiteralError, UNIT_AXIS_TOLERANCE, parse_literal};
pub use crate::file::value_text::{format_number, format_value, parse_number};
pub use crate::graph::{
    ExpectedMessage, FORMAT_VERSION, Graph, GraphInput, GraphNode, GraphOutput, Literal, Modifier,
    NodeId, PortRef, SUBGRAPH_TYPE, SubGraph, Wire, text_matches,
};
pub use crate::host::{LoadError, load_file};
pub use crate::json::{MessageJson, TreeJson, ValueJson};
pub use crate::limits::{
    CancelToken, DEFAULT_MAX_ITEMS_PER_OUTPUT, DEFAULT_MAX_ITEMS_TOTAL, LimitHit, Limits,
    MAX_GRAPH_FILE_BYTES, MAX_TEXT_BYTES, MAX_THREADS_PER_CORE, read_graph_file,
};
pub use crate::message::{Level, Message};
pub use crate::node::{
    Access, Matching, NodeConfig, NodeError, NodeType, Port, PrepareFn, Prepared, Setting, SolveFn,
    ValueConstraint, VariableInputs, VariableOutputs,
};
pub use crate::plan::{Plan, PlanInput, PlanNode};
pub use crate::registry::NodeRegistry;
pub use crate::trees::path::{PathParseError, TreePath};
pub use crate::trees::path_mapper::{MAX_ITEM_PADDING, PathMapError, PathMapper};
pub use crate::trees::path_mask::MAX_MASK_TOKENS;
pub use crate::trees::simplify::SimplifyMode;
pub use crate::trees::tree::{Branch, DataTree};
pub use crate::trees::tree_ops::{GraftMode, TreeError};
pub use crate::trees::tree_text::{TreeText, TreeTextError};
pub use crate::value::{Column, DataType, Item, Shared, Value};

//! Checking a graph before running it: every problem at once, or a runnable [`Plan`].
//!
//! Checking resolves node types in the registry, port names on the node types, wires between
//! outputs and inputs (with [`can_cast`]), values, settings and modifiers against port types,
//! named inputs and outputs, and expected values; finds cycles; and orders the nodes
//! topologically, breaking ties by file order (Kahn's algorithm with a min-heap), so that
//! evaluation order never depends on hashing or on petgraph's traversal order.

use std::cmp::Reverse;
use std::collections::{BinaryHeap, HashMap, HashSet, VecDeque};
use std::ops::Range;
use std::sync::Arc;

use petgraph::graph::{DiGraph, NodeIndex};

use crate::checking::before_run::check_before_run;
use crate::checking::diagnostic::{Diagnostic, DiagnosticKind, Location, PortDirection, Severity};
use crate::checking::subgraph::{Nesting, check_nested};
use crate::file::expected::ExpectedTree;
use crate::file::format::{Document, SourceMap};
use crate::file::literal::{LiteralError, tree_from_node, value_from_node};
use crate::file::syntax::{self, Node};
use crate::{
    DataTree, DataType, Graph, Literal, Modifier, NodeRegistry, NodeType, Plan, PlanInput,
    PlanNode, Port, PortRef, Value, can_cast,
};

mod nodes;
mod order;
mod wires;

/// A graph that passed checking: the plan to run and the warnings found on the way.
#[derive(Clone, Debug)]
pub struct Checked {
    /// The resolved graph, ready to evaluate.
    pub plan: Plan,
    /// Problems that do not stop the graph from running.
    pub warnings: Vec<Diagnostic>,
}

/// Checks a graph without source positions.
///
/// # Errors
/// Every diagnostic (errors and warnings, in file order) when there is at least one error.
pub fn check(graph: &Graph, registry: &NodeRegistry) -> Result<Checked, Vec<Diagnostic>> {
    check_nested(graph, None, registry, &mut Nesting::default())
}

/// Reads and checks a graph file.
///
/// # Errors
/// The reading errors when the text is not a graph; else every diagnostic (errors and
/// warnings, in file order) when checking finds at least one error.
pub fn check_text(text: &str, registry: &NodeRegistry) -> Result<Checked, Vec<Diagnostic>> {
    Document::parse(text)?.check(registry)
}

impl Document {
    /// Checks the graph, locating every diagnostic in the source.
    ///
    /// # Errors
    /// Every diagnostic (errors and warnings, in file order) when there is at least one error.
    pub fn check(&self, registry: &NodeRegistry) -> Result<Checked, Vec<Diagnostic>> {
        check_nested(self.graph(), Some(self), registry, &mut Nesting::default())
    }
}

/// What checking learned about one node.
struct Resolved<'r> {
    node_type: &'r NodeType,
    inputs: Vec<Port>,
    /// The node's outputs: the type's, or the ones it names when they are variable.
    outputs: Vec<Port>,
}

pub(crate) struct Checker<'a> {
    graph: &'a Graph,
    doc: Option<&'a Document>,
    registry: &'a NodeRegistry,
    diagnostics: Vec<Diagnostic>,
    /// The index of the first node with each id.
    index: HashMap<&'a str, usize>,
    /// Per node: its type and input ports, when the type is known.
    resolved: Vec<Option<Resolved<'a>>>,
    /// Per node and input: the parsed value.
    values: Vec<Vec<Option<DataTree>>>,
    /// Per node and input: whether a value was given (even one that failed to parse).
    values_given: Vec<Vec<bool>>,
    /// Per node and input: whether a wire ends there (even one with a bad source or cast).
    wire_ends: Vec<Vec<bool>>,
    /// Per node and input: the sources, in wire order.
    sources: Vec<Vec<Vec<(usize, usize)>>>,
    /// Per node and input: the modifiers.
    modifiers: Vec<Vec<Vec<Modifier>>>,
    /// Per node and output: the modifiers.
    output_modifiers: Vec<Vec<Vec<Modifier>>>,
    /// Per node: the settings given, by setting index.
    settings: Vec<Vec<Option<Value>>>,
    /// Per node and input: the named input that sets it, if any.
    named_targets: Vec<Vec<Option<usize>>>,
    /// Wires between resolved ports, as (from node, to node).
    edges: Vec<(usize, usize)>,
    /// The sub-graph nodes, by index: the node type standing for the sub-graph, or `None`
    /// when the sub-graph has errors (reported already, so the node is left unresolved).
    subgraphs: HashMap<usize, Option<&'a NodeType>>,
}

impl<'a> Checker<'a> {
    pub(crate) fn new(
        graph: &'a Graph,
        doc: Option<&'a Document>,
        registry: &'a NodeRegistry,
    ) -> Self {
        Self {
            graph,
            doc,
            registry,
            diagnostics: Vec::new(),
            index: HashMap::new(),
            resolved: Vec::new(),
            values: Vec::new(),
            values_given: Vec::new(),
            wire_ends: Vec::new(),
            sources: Vec::new(),
            modifiers: Vec::new(),
            output_modifiers: Vec::new(),
            settings: Vec::new(),
            named_targets: Vec::new(),
            edges: Vec::new(),
            subgraphs: HashMap::new(),
        }
    }

    /// The checker with the node types of the graph's sub-graph nodes (`checking/subgraph.rs`).
    pub(crate) fn with_subgraphs(
        mut self,
        subgraphs: HashMap<usize, Option<&'a NodeType>>,
    ) -> Self {
        self.subgraphs = subgraphs;
        self
    }

    fn map(&self) -> Option<&'a SourceMap> {
        self.doc.map(|d| &d.map)
    }

    fn location(&self, offset: Option<usize>) -> Option<Location> {
        Some(self.doc?.location(offset?))
    }

    fn push(&mut self, severity: Severity, kind: DiagnosticKind, offset: Option<usize>) {
        let location = self.location(offset);
        self.diagnostics.push(Diagnostic {
            severity,
            kind,
            location,
            file: None,
        });
    }

    fn error(&mut self, kind: DiagnosticKind, offset: Option<usize>) {
        self.push(Severity::Error, kind, offset);
    }

    fn warning(&mut self, kind: DiagnosticKind, offset: Option<usize>) {
        self.push(Severity::Warning, kind, offset);
    }

    /// The offset of node `i`'s id in the file.
    fn node_offset(&self, i: usize) -> Option<usize> {
        self.map()?.nodes.get(i).map(|n| n.id.start)
    }

    pub(crate) fn run(mut self) -> Result<Checked, Vec<Diagnostic>> {
        self.nodes();
        for i in 0..self.graph.nodes.len() {
            self.node_values(i);
            self.node_settings(i);
            self.node_modifiers(i);
        }
        self.wires();
        self.named_inputs();
        let outputs = self.named_outputs();
        self.required_inputs();
        self.expected(&outputs);
        self.expected_messages();
        self.cycles();
        let mut diagnostics = std::mem::take(&mut self.diagnostics);
        diagnostics.sort_by_key(|d| d.location.map_or(usize::MAX, |l| l.offset));
        // A sub-graph node whose body did not check has no type: its errors are the
        // including check's (`checking/subgraph.rs`), and there is no plan to make without it.
        if diagnostics.iter().any(Diagnostic::is_error) || self.resolved.iter().any(Option::is_none)
        {
            return Err(diagnostics);
        }
        let (graph, doc) = (self.graph, self.doc);
        let plan = self.plan(outputs);
        // What can be known before running: prepare steps and literal values' constraints.
        let before_run = check_before_run(&plan, graph, doc);
        if !before_run.is_empty() {
            diagnostics.extend(before_run);
            diagnostics.sort_by_key(|d| d.location.map_or(usize::MAX, |l| l.offset));
            return Err(diagnostics);
        }
        Ok(Checked {
            plan,
            warnings: diagnostics,
        })
    }
}

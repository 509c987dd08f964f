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
use crate::file::expected::ExpectedTree;
use crate::file::format::{Document, SourceMap};
use crate::file::literal::{LiteralError, tree_from_node, value_from_node};
use crate::file::syntax::{self, Node};
use crate::{
    DataTree, DataType, Graph, Literal, Modifier, NodeRegistry, NodeType, Plan, PlanInput,
    PlanNode, Port, PortRef, Value, can_cast,
};

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
    Checker::new(graph, None, registry).run()
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
        Checker::new(self.graph(), Some(self), registry).run()
    }
}

/// What checking learned about one node.
struct Resolved<'r> {
    node_type: &'r NodeType,
    inputs: Vec<Port>,
}

struct Checker<'a> {
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
    /// Per node: the settings given, by setting index.
    settings: Vec<Vec<Option<Value>>>,
    /// Per node and input: the named input that sets it, if any.
    named_targets: Vec<Vec<Option<usize>>>,
    /// Wires between resolved ports, as (from node, to node).
    edges: Vec<(usize, usize)>,
}

impl<'a> Checker<'a> {
    fn new(graph: &'a Graph, doc: Option<&'a Document>, registry: &'a NodeRegistry) -> Self {
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
            settings: Vec::new(),
            named_targets: Vec::new(),
            edges: Vec::new(),
        }
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

    fn run(mut self) -> Result<Checked, Vec<Diagnostic>> {
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
        if diagnostics.iter().any(Diagnostic::is_error) {
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

    /// Ids, types and variable input names.
    fn nodes(&mut self) {
        let graph = self.graph;
        for (i, node) in graph.nodes.iter().enumerate() {
            let id = node.id.0.as_str();
            let at = self.node_offset(i);
            if id.is_empty() || id.contains(['.', '"']) || id.contains(char::is_whitespace) {
                self.error(
                    DiagnosticKind::InvalidNodeId {
                        node: id.to_owned(),
                    },
                    at,
                );
            }
            match self.index.get(id) {
                Some(&first) => {
                    let first_line = self.location(self.node_offset(first)).map(|l| l.line);
                    self.error(
                        DiagnosticKind::DuplicateNodeId {
                            node: id.to_owned(),
                            first_line,
                        },
                        at,
                    );
                }
                None => {
                    self.index.insert(id, i);
                }
            }
            let resolved = match self.registry.get(&node.node_type) {
                Some(node_type) => Some(self.resolve_inputs(i, node_type)),
                None => {
                    let suggestions = suggestions(self.registry, &node.node_type);
                    let at = self
                        .map()
                        .and_then(|m| m.nodes.get(i))
                        .map(|n| n.node_type.start);
                    self.error(
                        DiagnosticKind::UnknownNodeType {
                            node: id.to_owned(),
                            node_type: node.node_type.clone(),
                            suggestions,
                        },
                        at,
                    );
                    None
                }
            };
            let n_inputs = resolved.as_ref().map_or(0, |r| r.inputs.len());
            let n_settings = resolved.as_ref().map_or(0, |r| r.node_type.settings.len());
            self.resolved.push(resolved);
            self.values.push(vec![None; n_inputs]);
            self.values_given.push(vec![false; n_inputs]);
            self.wire_ends.push(vec![false; n_inputs]);
            self.sources.push(vec![Vec::new(); n_inputs]);
            self.modifiers.push(vec![Vec::new(); n_inputs]);
            self.settings.push(vec![None; n_settings]);
            self.named_targets.push(vec![None; n_inputs]);
        }
    }

    fn resolve_inputs(&mut self, i: usize, node_type: &'a NodeType) -> Resolved<'a> {
        let node = &self.graph.nodes[i];
        let Some(names) = &node.input_names else {
            return Resolved {
                node_type,
                inputs: node_type.resolve_inputs(None),
            };
        };
        let spans = self.map().and_then(|m| m.nodes.get(i));
        let name_at = |k: usize| spans.and_then(|s| s.input_names.get(k)).map(|r| r.start);
        if node_type.variable_inputs.is_none() {
            self.error(
                DiagnosticKind::BadInputNames {
                    node: node.id.0.clone(),
                    message: format!(
                        "node type \"{}\" has fixed inputs, so `inputs` cannot be given",
                        node_type.id
                    ),
                },
                name_at(0).or(self.node_offset(i)),
            );
            return Resolved {
                node_type,
                inputs: node_type.resolve_inputs(None),
            };
        }
        let mut kept: Vec<String> = Vec::with_capacity(names.len());
        for (k, name) in names.iter().enumerate() {
            let message = if name.trim().is_empty() {
                Some("empty input name".to_owned())
            } else if names[..k].contains(name) {
                Some(format!("duplicate input name \"{name}\""))
            } else {
                None
            };
            if let Some(message) = message {
                self.error(
                    DiagnosticKind::BadInputNames {
                        node: node.id.0.clone(),
                        message,
                    },
                    name_at(k),
                );
            } else {
                kept.push(name.clone());
            }
        }
        // Bad names are left out so that they cause no further errors.
        Resolved {
            node_type,
            inputs: node_type.resolve_inputs(Some(&kept)),
        }
    }

    /// The input of resolved node `i` named `port`, reporting an unknown port at `at`.
    fn find_input(&mut self, i: usize, port: &str, at: Option<usize>) -> Option<usize> {
        let r = self.resolved[i].as_ref()?;
        if let Some(k) = r.inputs.iter().position(|p| p.is_named(port)) {
            return Some(k);
        }
        let kind = DiagnosticKind::UnknownPort {
            node: self.graph.nodes[i].id.0.clone(),
            node_type: r.node_type.id.clone(),
            port: port.to_owned(),
            direction: PortDirection::Input,
            valid: r.inputs.iter().map(|p| p.nickname.clone()).collect(),
        };
        self.error(kind, at);
        None
    }

    /// Parses a literal written at `span` of the source (or without source, its own text),
    /// returning the error message and its offset in the file.
    fn parse_literal<T>(
        &self,
        literal: &Literal,
        span: Option<&Range<usize>>,
        read: impl Fn(&Node) -> Result<T, LiteralError>,
    ) -> Result<T, (String, Option<usize>)> {
        let (text, base) = match (self.doc, span) {
            (Some(doc), Some(span)) => match doc.source().get(span.clone()) {
                Some(text) => (text, Some(span.start)),
                None => (literal.0.as_str(), None),
            },
            _ => (literal.0.as_str(), None),
        };
        let node = syntax::parse(text).map_err(|e| (e.message, base.map(|b| b + e.offset)))?;
        read(&node).map_err(|e| (e.message, base.map(|b| b + e.span.start)))
    }

    fn node_values(&mut self, i: usize) {
        let graph = self.graph;
        let node = &graph.nodes[i];
        if self.resolved[i].is_none() {
            return;
        }
        let spans = self.map().and_then(|m| m.nodes.get(i));
        for (j, (port, literal)) in node.values.iter().enumerate() {
            let span = spans.and_then(|s| s.values.get(j));
            let Some(k) = self.find_input(i, port, span.map(|s| s[0].start)) else {
                continue;
            };
            let Some(input) = self.resolved[i].as_ref().map(|r| r.inputs[k].clone()) else {
                continue;
            };
            if self.values_given[i][k] {
                self.error(
                    DiagnosticKind::Malformed {
                        message: format!(
                            "input \"{}\" of node \"{}\" has two values",
                            input.nickname, node.id
                        ),
                    },
                    span.map(|s| s[0].start),
                );
                continue;
            }
            self.values_given[i][k] = true;
            let data_type = input.data_type;
            match self.parse_literal(literal, span.map(|s| &s[1]), |n| {
                tree_from_node(n, data_type)
            }) {
                Ok(tree) => self.values[i][k] = Some(tree),
                Err((message, at)) => self.error(
                    DiagnosticKind::BadValue {
                        node: node.id.0.clone(),
                        port: input.nickname.clone(),
                        message,
                    },
                    at.or(span.map(|s| s[1].start)),
                ),
            }
        }
    }

    fn node_settings(&mut self, i: usize) {
        let graph = self.graph;
        let node = &graph.nodes[i];
        let Some(node_type) = self.resolved[i].as_ref().map(|r| r.node_type) else {
            return;
        };
        let spans = self.map().and_then(|m| m.nodes.get(i));
        for (j, (name, literal)) in node.settings.iter().enumerate() {
            let span = spans.and_then(|s| s.settings.get(j));
            let name_at = span.map(|s| s[0].start);
            let Some(k) = node_type.settings.iter().position(|s| s.name == *name) else {
                self.error(
                    DiagnosticKind::UnknownSetting {
                        node: node.id.0.clone(),
                        setting: name.clone(),
                        valid: node_type.settings.iter().map(|s| s.name.clone()).collect(),
                    },
                    name_at,
                );
                continue;
            };
            if self.settings[i][k].is_some() {
                self.error(
                    DiagnosticKind::Malformed {
                        message: format!(
                            "setting \"{name}\" of node \"{}\" is given twice",
                            node.id
                        ),
                    },
                    name_at,
                );
                continue;
            }
            let data_type = node_type.settings[k].data_type;
            match self.parse_literal(literal, span.map(|s| &s[1]), |n| {
                value_from_node(n, data_type)
            }) {
                Ok(value) => self.settings[i][k] = Some(value),
                Err((message, at)) => self.error(
                    DiagnosticKind::BadSetting {
                        node: node.id.0.clone(),
                        setting: name.clone(),
                        message,
                    },
                    at.or(span.map(|s| s[1].start)),
                ),
            }
        }
    }

    fn node_modifiers(&mut self, i: usize) {
        let graph = self.graph;
        let node = &graph.nodes[i];
        if self.resolved[i].is_none() {
            return;
        }
        let spans = self.map().and_then(|m| m.nodes.get(i));
        for (j, (port, list)) in node.modifiers.iter().enumerate() {
            let span = spans.and_then(|s| s.modifiers.get(j));
            let port_at = span.map(|s| s.0.start);
            let Some(k) = self.find_input(i, port, port_at) else {
                continue;
            };
            let Some(input) = self.resolved[i].as_ref().map(|r| r.inputs[k].clone()) else {
                continue;
            };
            if !self.modifiers[i][k].is_empty() {
                self.error(
                    DiagnosticKind::Malformed {
                        message: format!(
                            "modifiers of input \"{}\" of node \"{}\" are given twice",
                            input.nickname, node.id
                        ),
                    },
                    port_at,
                );
                continue;
            }
            let mut accepted: Vec<Modifier> = Vec::new();
            for (m_index, &modifier) in list.iter().enumerate() {
                let at = span
                    .and_then(|s| s.1.get(m_index))
                    .map(|r| r.start)
                    .or(port_at);
                if !modifier_applies(modifier, input.data_type) {
                    self.error(
                        DiagnosticKind::ModifierNotApplicable {
                            node: node.id.0.clone(),
                            port: input.nickname.clone(),
                            modifier,
                            data_type: input.data_type,
                        },
                        at,
                    );
                    continue;
                }
                let structural = [Modifier::Flatten, Modifier::Graft, Modifier::Simplify];
                if let Some(&first) = accepted
                    .iter()
                    .find(|m| structural.contains(m) && structural.contains(&modifier))
                {
                    self.error(
                        DiagnosticKind::ConflictingModifiers {
                            node: node.id.0.clone(),
                            port: input.nickname.clone(),
                            first,
                            second: modifier,
                        },
                        at,
                    );
                    continue;
                }
                if !accepted.contains(&modifier) {
                    accepted.push(modifier);
                }
            }
            accepted.sort_by_key(|m| Modifier::ALL.iter().position(|a| a == m));
            self.modifiers[i][k] = accepted;
        }
        let principal: Vec<String> = self.modifiers[i]
            .iter()
            .enumerate()
            .filter(|(_, m)| m.contains(&Modifier::Principal))
            .filter_map(|(k, _)| {
                self.resolved[i]
                    .as_ref()
                    .map(|r| r.inputs[k].nickname.clone())
            })
            .collect();
        if principal.len() > 1 {
            let at = self.node_offset(i);
            self.error(
                DiagnosticKind::SeveralPrincipalInputs {
                    node: node.id.0.clone(),
                    ports: principal,
                },
                at,
            );
        }
    }

    /// Resolves `port_ref` to (node, port index) in the given direction, reporting problems at
    /// `at` with `context` naming where the reference is used.
    fn resolve_port(
        &mut self,
        port_ref: &PortRef,
        direction: PortDirection,
        context: &str,
        at: Option<usize>,
    ) -> Option<(usize, usize)> {
        let Some(&i) = self.index.get(port_ref.node.0.as_str()) else {
            self.error(
                DiagnosticKind::UnknownNode {
                    context: context.to_owned(),
                    node: port_ref.node.0.clone(),
                },
                at,
            );
            return None;
        };
        let r = self.resolved[i].as_ref()?;
        let input = r.inputs.iter().position(|p| p.is_named(&port_ref.port));
        let output = r.node_type.output_index(&port_ref.port);
        let (wanted, other, valid) = match direction {
            PortDirection::Input => (input, output, &r.inputs),
            PortDirection::Output => (output, input, &r.node_type.outputs),
        };
        if let Some(k) = wanted {
            return Some((i, k));
        }
        let kind = if other.is_some() {
            let found = match direction {
                PortDirection::Input => PortDirection::Output,
                PortDirection::Output => PortDirection::Input,
            };
            DiagnosticKind::WrongDirection {
                context: context.to_owned(),
                node: port_ref.node.0.clone(),
                port: port_ref.port.clone(),
                found,
            }
        } else {
            DiagnosticKind::UnknownPort {
                node: port_ref.node.0.clone(),
                node_type: r.node_type.id.clone(),
                port: port_ref.port.clone(),
                direction,
                valid: valid.iter().map(|p| p.nickname.clone()).collect(),
            }
        };
        self.error(kind, at);
        None
    }

    fn wires(&mut self) {
        let graph = self.graph;
        let mut seen: HashSet<(usize, usize, usize, usize)> = HashSet::new();
        for (w, wire) in graph.wires.iter().enumerate() {
            let spans = self.map().and_then(|m| m.wires.get(w));
            let from_at = spans.map(|s| s[0].start);
            let to_at = spans.map(|s| s[1].start);
            let name = format!("wire \"{}\" → \"{}\"", wire.from, wire.to);
            let from = self.resolve_port(
                &wire.from,
                PortDirection::Output,
                &format!("the start of {name}"),
                from_at,
            );
            let to = self.resolve_port(
                &wire.to,
                PortDirection::Input,
                &format!("the end of {name}"),
                to_at,
            );
            if let Some((b, inp)) = to {
                self.wire_ends[b][inp] = true;
            }
            let (Some((a, out)), Some((b, inp))) = (from, to) else {
                continue;
            };
            let (Some(ra), Some(rb)) = (&self.resolved[a], &self.resolved[b]) else {
                continue;
            };
            let from_type = ra.node_type.outputs[out].data_type;
            let to_type = rb.inputs[inp].data_type;
            if !can_cast(from_type, to_type) {
                self.error(
                    DiagnosticKind::IncompatibleWire {
                        from: wire.from.to_string(),
                        to: wire.to.to_string(),
                        from_type,
                        to_type,
                    },
                    from_at,
                );
                continue;
            }
            if !seen.insert((a, out, b, inp)) {
                self.warning(
                    DiagnosticKind::DuplicateWire {
                        from: wire.from.to_string(),
                        to: wire.to.to_string(),
                    },
                    from_at,
                );
                continue;
            }
            self.sources[b][inp].push((a, out));
            self.edges.push((a, b));
        }
    }

    fn named_inputs(&mut self) {
        let graph = self.graph;
        for (n, input) in graph.inputs.iter().enumerate() {
            let spans = self.map().and_then(|m| m.inputs.get(n));
            if graph.inputs[..n].iter().any(|o| o.name == input.name) {
                self.error(
                    DiagnosticKind::DuplicateName {
                        direction: PortDirection::Input,
                        name: input.name.clone(),
                    },
                    spans.map(|s| s[0].start),
                );
                continue;
            }
            let context = format!("named input \"{}\"", input.name);
            let at = spans.map(|s| s[1].start);
            if let Some((i, k)) =
                self.resolve_port(&input.target, PortDirection::Input, &context, at)
            {
                self.named_targets[i][k] = Some(n);
            }
        }
    }

    fn named_outputs(&mut self) -> Vec<Option<(usize, usize)>> {
        let graph = self.graph;
        let mut resolved = Vec::with_capacity(graph.outputs.len());
        for (n, output) in graph.outputs.iter().enumerate() {
            let spans = self.map().and_then(|m| m.outputs.get(n));
            if graph.outputs[..n].iter().any(|o| o.name == output.name) {
                self.error(
                    DiagnosticKind::DuplicateName {
                        direction: PortDirection::Output,
                        name: output.name.clone(),
                    },
                    spans.map(|s| s[0].start),
                );
                resolved.push(None);
                continue;
            }
            let context = format!("named output \"{}\"", output.name);
            let at = spans.map(|s| s[1].start);
            resolved.push(self.resolve_port(&output.source, PortDirection::Output, &context, at));
        }
        resolved
    }

    fn required_inputs(&mut self) {
        let graph = self.graph;
        for i in 0..graph.nodes.len() {
            let Some(r) = &self.resolved[i] else {
                continue;
            };
            let node = &graph.nodes[i];
            let spans = self.map().and_then(|m| m.nodes.get(i));
            let mut found = Vec::new();
            for (k, port) in r.inputs.iter().enumerate() {
                let wired = self.wire_ends[i][k];
                let has_value = self.values_given[i][k];
                if wired && has_value {
                    let at = node
                        .values
                        .iter()
                        .position(|(p, _)| port.is_named(p))
                        .and_then(|j| spans.and_then(|s| s.values.get(j)))
                        .map(|s| s[0].start);
                    found.push((Severity::Warning, port.nickname.clone(), at, None));
                } else if !wired && !has_value && port.default.is_none() && !port.optional {
                    found.push((
                        Severity::Error,
                        port.nickname.clone(),
                        None,
                        self.named_targets[i][k],
                    ));
                }
            }
            for (severity, port, at, named) in found {
                let node_id = node.id.0.clone();
                match (severity, named) {
                    (Severity::Warning, _) => {
                        self.warning(
                            DiagnosticKind::ValueIgnored {
                                node: node_id,
                                port,
                            },
                            at,
                        );
                    }
                    (Severity::Error, Some(n)) => {
                        let at = self.map().and_then(|m| m.inputs.get(n)).map(|s| s[0].start);
                        self.warning(
                            DiagnosticKind::UnsetGraphInput {
                                name: graph.inputs[n].name.clone(),
                                node: node_id,
                                port,
                            },
                            at,
                        );
                    }
                    (Severity::Error, None) => {
                        let at = self.node_offset(i);
                        self.error(
                            DiagnosticKind::MissingInput {
                                node: node_id,
                                port,
                            },
                            at,
                        );
                    }
                }
            }
        }
    }

    fn expected(&mut self, outputs: &[Option<(usize, usize)>]) {
        let graph = self.graph;
        for (e, (name, literal)) in graph.expected.iter().enumerate() {
            let spans = self.map().and_then(|m| m.expected.get(e));
            let name_at = spans.map(|s| s[0].start);
            let Some(o) = graph.outputs.iter().position(|o| o.name == *name) else {
                self.error(
                    DiagnosticKind::UnknownExpectedOutput {
                        name: name.clone(),
                        valid: graph.outputs.iter().map(|o| o.name.clone()).collect(),
                    },
                    name_at,
                );
                continue;
            };
            if graph.expected[..e].iter().any(|(n, _)| n == name) {
                self.error(
                    DiagnosticKind::Malformed {
                        message: format!("output \"{name}\" has two expected values"),
                    },
                    name_at,
                );
                continue;
            }
            let Some((i, k)) = outputs.get(o).copied().flatten() else {
                continue;
            };
            let Some(r) = &self.resolved[i] else {
                continue;
            };
            let data_type = r.node_type.outputs[k].data_type;
            // Expected values are literals whose B-rep items may be summaries.
            if let Err((message, at)) = self.parse_literal(literal, spans.map(|s| &s[1]), |n| {
                ExpectedTree::from_node(n, data_type)
            }) {
                self.error(
                    DiagnosticKind::BadExpected {
                        name: name.clone(),
                        message,
                    },
                    at.or(spans.map(|s| s[1].start)),
                );
            }
        }
    }

    /// Expected messages must name nodes of the graph.
    fn expected_messages(&mut self) {
        for (e, m) in self.graph.expected_messages.iter().enumerate() {
            if !self.index.contains_key(m.node.0.as_str()) {
                let at = self.map().and_then(|map| map.expected_messages.get(e));
                self.error(
                    DiagnosticKind::Malformed {
                        message: format!("expected message for unknown node \"{}\"", m.node),
                    },
                    at.map(|s| s.start),
                );
            }
        }
    }

    fn cycles(&mut self) {
        let n = self.graph.nodes.len();
        let mut g: DiGraph<(), ()> = DiGraph::with_capacity(n, self.edges.len());
        for _ in 0..n {
            g.add_node(());
        }
        let mut successors = vec![Vec::new(); n];
        for &(a, b) in &self.edges {
            g.add_edge(NodeIndex::new(a), NodeIndex::new(b), ());
            successors[a].push(b);
        }
        for s in &mut successors {
            s.sort_unstable();
            s.dedup();
        }
        let mut components: Vec<Vec<usize>> = petgraph::algo::tarjan_scc(&g)
            .into_iter()
            .map(|c| {
                let mut c: Vec<usize> = c.into_iter().map(NodeIndex::index).collect();
                c.sort_unstable();
                c
            })
            .filter(|c| c.len() > 1 || successors[c[0]].contains(&c[0]))
            .collect();
        components.sort();
        for component in components {
            let path = shortest_cycle(component[0], &component, &successors);
            let nodes = path
                .iter()
                .map(|&i| self.graph.nodes[i].id.0.clone())
                .collect();
            let at = self.node_offset(component[0]);
            self.error(DiagnosticKind::Cycle { nodes }, at);
        }
    }

    fn plan(self, outputs: Vec<Option<(usize, usize)>>) -> Plan {
        let graph = self.graph;
        let mut shared: HashMap<&str, Arc<NodeType>> = HashMap::new();
        let mut nodes = Vec::with_capacity(graph.nodes.len());
        let mut values = self.values;
        let mut sources = self.sources;
        let mut modifiers = self.modifiers;
        for (i, (node, resolved)) in graph.nodes.iter().zip(self.resolved).enumerate() {
            // Checking passed, so every node type is known.
            let Some(r) = resolved else { continue };
            let node_type = shared
                .entry(r.node_type.id.as_str())
                .or_insert_with(|| Arc::new(r.node_type.clone()))
                .clone();
            let inputs = r
                .inputs
                .into_iter()
                .enumerate()
                .map(|(k, port)| {
                    let value = values[i][k]
                        .take()
                        .or_else(|| port.default.clone().map(DataTree::from_value));
                    PlanInput {
                        port,
                        sources: std::mem::take(&mut sources[i][k]),
                        value,
                        modifiers: std::mem::take(&mut modifiers[i][k]),
                    }
                })
                .collect();
            let settings = node_type
                .settings
                .iter()
                .zip(&self.settings[i])
                .filter_map(|(s, given)| {
                    given
                        .clone()
                        .or_else(|| s.default.clone())
                        .map(|v| (s.name.clone(), v))
                })
                .collect();
            nodes.push(PlanNode {
                id: node.id.clone(),
                node_type,
                inputs,
                settings,
                matching: node.matching,
                disabled: node.disabled,
            });
        }
        let order = topological_order(nodes.len(), &self.edges);
        let inputs = graph
            .inputs
            .iter()
            .enumerate()
            .filter_map(|(n, input)| {
                self.named_targets
                    .iter()
                    .enumerate()
                    .find_map(|(i, targets)| {
                        let k = targets.iter().position(|t| *t == Some(n))?;
                        Some((input.name.clone(), i, k))
                    })
            })
            .collect();
        let outputs = graph
            .outputs
            .iter()
            .zip(outputs)
            .filter_map(|(o, r)| r.map(|(i, k)| (o.name.clone(), i, k)))
            .collect();
        Plan {
            nodes,
            order,
            inputs,
            outputs,
        }
    }
}

/// Registered type ids close to `id`: those the registry suggests by edit distance, then
/// those that start with `id` (`vector.dot` → `vector.dot_product`) or whose name after the
/// category is `id` (`dot_product` → `vector.dot_product`); at most three.
fn suggestions(registry: &NodeRegistry, id: &str) -> Vec<String> {
    let mut out: Vec<String> = registry
        .suggestions(id)
        .into_iter()
        .map(str::to_owned)
        .collect();
    if !id.is_empty() {
        for t in registry.iter() {
            let name = t.id.rsplit('.').next().unwrap_or(&t.id);
            if (t.id.starts_with(id) || name == id) && !out.contains(&t.id) {
                out.push(t.id.clone());
            }
        }
    }
    out.truncate(3);
    out
}

/// Whether a modifier applies to an input of type `data_type`.
fn modifier_applies(modifier: Modifier, data_type: DataType) -> bool {
    match modifier {
        Modifier::Invert => data_type == DataType::Boolean,
        Modifier::Degrees => data_type == DataType::Number,
        // Named rather than matched so that this reads the same before and after the curve
        // and surface types join `DataType`.
        Modifier::Reparameterize => matches!(data_type.name(), "Curve" | "Surface"),
        Modifier::Flatten
        | Modifier::Graft
        | Modifier::Simplify
        | Modifier::Reverse
        | Modifier::Principal => true,
    }
}

/// The shortest cycle through `start` within `component` (breadth-first, successors in index
/// order), as node indices with `start` first and last.
fn shortest_cycle(start: usize, component: &[usize], successors: &[Vec<usize>]) -> Vec<usize> {
    let mut parent: HashMap<usize, usize> = HashMap::new();
    let mut queue = VecDeque::from([start]);
    while let Some(a) = queue.pop_front() {
        for &b in &successors[a] {
            if component.binary_search(&b).is_err() {
                continue;
            }
            if b == start {
                let mut path = vec![start, a];
                let mut c = a;
                while let Some(&p) = parent.get(&c) {
                    path.push(p);
                    c = p;
                }
                path.reverse();
                return path;
            }
            if b != start && !parent.contains_key(&b) {
                parent.insert(b, a);
                queue.push_back(b);
            }
        }
    }
    // Unreachable for a strongly connected component; fall back to listing it.
    let mut path = component.to_vec();
    path.push(start);
    path
}

/// Kahn's algorithm with a min-heap: among the nodes whose sources are all placed, the one
/// earliest in the file goes first. Nodes on cycles (which checking rejects) are left out.
pub(crate) fn topological_order(n: usize, edges: &[(usize, usize)]) -> Vec<usize> {
    let mut successors = vec![Vec::new(); n];
    let mut in_degree = vec![0usize; n];
    for &(a, b) in edges {
        successors[a].push(b);
        in_degree[b] += 1;
    }
    let mut ready: BinaryHeap<Reverse<usize>> =
        (0..n).filter(|&i| in_degree[i] == 0).map(Reverse).collect();
    let mut order = Vec::with_capacity(n);
    while let Some(Reverse(i)) = ready.pop() {
        order.push(i);
        for &b in &successors[i] {
            in_degree[b] -= 1;
            if in_degree[b] == 0 {
                ready.push(Reverse(b));
            }
        }
    }
    order
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn topological_order_breaks_ties_by_file_order() {
        // 3 → 1, 2 → 0; free nodes 4. Ready at start: 2, 3, 4 → take 2, then 0 becomes
        // ready and is earlier than 3.
        let order = topological_order(5, &[(3, 1), (2, 0)]);
        assert_eq!(order, [2, 0, 3, 1, 4]);
    }

    #[test]
    fn shortest_cycle_names_each_node_once() {
        let successors = vec![vec![1], vec![2], vec![0, 1]];
        assert_eq!(shortest_cycle(0, &[0, 1, 2], &successors), [0, 1, 2, 0]);
        let self_loop = vec![vec![0]];
        assert_eq!(shortest_cycle(0, &[0], &self_loop), [0, 0]);
    }
}

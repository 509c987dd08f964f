//! Checking each node: its type, input names, values, settings and modifiers.

use super::*;

impl<'a> Checker<'a> {
    /// Ids, types and variable input names.
    pub(super) fn nodes(&mut self) {
        let graph = self.graph;
        for (i, node) in graph.nodes.iter().enumerate() {
            let id = node.id.0.as_str();
            let at = self.node_offset(i);
            if id.is_empty() || id.contains(['.', '"', '/']) || id.contains(char::is_whitespace) {
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
            let found = match self.subgraphs.get(&i) {
                Some(sub) => Ok(*sub),
                None => self.registry.get(&node.node_type).ok_or(()).map(Some),
            };
            let resolved = match found {
                Ok(Some(node_type)) => Some(self.resolve_ports(i, node_type)),
                Ok(None) => None,
                Err(()) => {
                    let suggestions = self
                        .registry
                        .suggestions(&node.node_type)
                        .into_iter()
                        .map(str::to_owned)
                        .collect();
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
            let n_outputs = resolved.as_ref().map_or(0, |r| r.outputs.len());
            let n_settings = resolved.as_ref().map_or(0, |r| r.node_type.settings.len());
            self.resolved.push(resolved);
            self.values.push(vec![None; n_inputs]);
            self.values_given.push(vec![false; n_inputs]);
            self.wire_ends.push(vec![false; n_inputs]);
            self.sources.push(vec![Vec::new(); n_inputs]);
            self.modifiers.push(vec![Vec::new(); n_inputs]);
            self.output_modifiers.push(vec![Vec::new(); n_outputs]);
            self.settings.push(vec![None; n_settings]);
            self.named_targets.push(vec![None; n_inputs]);
        }
    }

    /// The ports of node `i`: its inputs and outputs, with the names it gives variable ones.
    fn resolve_ports(&mut self, i: usize, node_type: &'a NodeType) -> Resolved<'a> {
        let inputs = self.resolve_inputs(i, node_type);
        let outputs = self.resolve_outputs(i, node_type);
        Resolved {
            node_type,
            inputs,
            outputs,
        }
    }

    fn resolve_outputs(&mut self, i: usize, node_type: &'a NodeType) -> Vec<Port> {
        let node = &self.graph.nodes[i];
        let Some(names) = &node.output_names else {
            return node_type.resolve_outputs(None);
        };
        let spans = self.map().and_then(|m| m.nodes.get(i));
        let name_at = |k: usize| spans.and_then(|s| s.output_names.get(k)).map(|r| r.start);
        let Some(variable) = &node_type.variable_outputs else {
            self.error(
                DiagnosticKind::BadInputNames {
                    node: node.id.0.clone(),
                    message: format!(
                        "node type \"{}\" has fixed outputs, so `outputs` cannot be given",
                        node_type.id
                    ),
                },
                name_at(0).or(self.node_offset(i)),
            );
            return node_type.resolve_outputs(None);
        };
        let mut kept: Vec<String> = Vec::with_capacity(names.len());
        for (k, name) in names.iter().enumerate() {
            let message = if name.trim().is_empty() {
                Some("empty output name".to_owned())
            } else if names[..k].contains(name) || variable.fixed.iter().any(|p| p.is_named(name)) {
                Some(format!("duplicate output name \"{name}\""))
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
        node_type.resolve_outputs(Some(&kept))
    }

    fn resolve_inputs(&mut self, i: usize, node_type: &'a NodeType) -> Vec<Port> {
        let node = &self.graph.nodes[i];
        let Some(names) = &node.input_names else {
            return node_type.resolve_inputs(None);
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
            return node_type.resolve_inputs(None);
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
        node_type.resolve_inputs(Some(&kept))
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

    /// The output of resolved node `i` named `port`, reporting an unknown port at `at`.
    fn find_output(&mut self, i: usize, port: &str, at: Option<usize>) -> Option<usize> {
        let r = self.resolved[i].as_ref()?;
        if let Some(k) = r.outputs.iter().position(|p| p.is_named(port)) {
            return Some(k);
        }
        let kind = DiagnosticKind::UnknownPort {
            node: self.graph.nodes[i].id.0.clone(),
            node_type: r.node_type.id.clone(),
            port: port.to_owned(),
            direction: PortDirection::Output,
            valid: r.outputs.iter().map(|p| p.nickname.clone()).collect(),
        };
        self.error(kind, at);
        None
    }

    /// Parses a literal written at `span` of the source (or without source, its own text),
    /// returning the error message and its offset in the file.
    pub(super) fn parse_literal<T>(
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

    pub(super) fn node_values(&mut self, i: usize) {
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

    pub(super) fn node_settings(&mut self, i: usize) {
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

    pub(super) fn node_modifiers(&mut self, i: usize) {
        if self.resolved[i].is_none() {
            return;
        }
        self.port_modifiers(i, PortDirection::Input);
        self.port_modifiers(i, PortDirection::Output);
        let node = &self.graph.nodes[i];
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

    /// The modifiers of node `i`'s inputs (`modifiers`) or outputs (`output_modifiers`).
    fn port_modifiers(&mut self, i: usize, direction: PortDirection) {
        let graph = self.graph;
        let node = &graph.nodes[i];
        let spans = self.map().and_then(|m| m.nodes.get(i));
        let (given, given_spans) = match direction {
            PortDirection::Input => (&node.modifiers, spans.map(|s| &s.modifiers)),
            PortDirection::Output => (&node.output_modifiers, spans.map(|s| &s.output_modifiers)),
        };
        for (j, (port, list)) in given.iter().enumerate() {
            let span = given_spans.and_then(|s| s.get(j));
            let port_at = span.map(|s| s.0.start);
            let found = match direction {
                PortDirection::Input => self.find_input(i, port, port_at),
                PortDirection::Output => self.find_output(i, port, port_at),
            };
            let Some(k) = found else {
                continue;
            };
            let Some(r) = self.resolved[i].as_ref() else {
                continue;
            };
            let (port, already) = match direction {
                PortDirection::Input => (r.inputs[k].clone(), &self.modifiers[i][k]),
                PortDirection::Output => (r.outputs[k].clone(), &self.output_modifiers[i][k]),
            };
            if !already.is_empty() {
                self.error(
                    DiagnosticKind::Malformed {
                        message: format!(
                            "modifiers of {} \"{}\" of node \"{}\" are given twice",
                            direction.name(),
                            port.nickname,
                            node.id
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
                let applies = modifier_applies(modifier, port.data_type)
                    && (direction == PortDirection::Input || modifier.applies_to_outputs());
                if !applies {
                    self.error(
                        DiagnosticKind::ModifierNotApplicable {
                            node: node.id.0.clone(),
                            port: port.nickname.clone(),
                            direction,
                            modifier,
                            data_type: port.data_type,
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
                            port: port.nickname.clone(),
                            direction,
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
            match direction {
                PortDirection::Input => self.modifiers[i][k] = accepted,
                PortDirection::Output => self.output_modifiers[i][k] = accepted,
            }
        }
    }
}

/// Whether a modifier applies to a port of type `data_type`.
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

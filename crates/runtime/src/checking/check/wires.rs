//! Checking the connections: wires, named inputs and outputs, required inputs and expected
//! values.

use super::*;

impl<'a> Checker<'a> {
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
        let output = r.outputs.iter().position(|p| p.is_named(&port_ref.port));
        let (wanted, other, valid) = match direction {
            PortDirection::Input => (input, output, &r.inputs),
            PortDirection::Output => (output, input, &r.outputs),
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

    pub(super) fn wires(&mut self) {
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
            let from_type = ra.outputs[out].data_type;
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

    pub(super) fn named_inputs(&mut self) {
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

    pub(super) fn named_outputs(&mut self) -> Vec<Option<(usize, usize)>> {
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

    pub(super) fn required_inputs(&mut self) {
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

    pub(super) fn expected(&mut self, outputs: &[Option<(usize, usize)>]) {
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
            let data_type = r.outputs[k].data_type;
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
    pub(super) fn expected_messages(&mut self) {
        for (e, m) in self.graph.expected_messages.iter().enumerate() {
            // A nested id (`c/d`) is checked once the sub-graph is in place
            // (`checking/subgraph.rs`).
            let outer = m.node.0.split('/').next().unwrap_or_default();
            let nested = m.node.0.contains('/')
                && self
                    .index
                    .get(outer)
                    .is_some_and(|i| self.subgraphs.contains_key(i));
            if !nested && !self.index.contains_key(m.node.0.as_str()) {
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
}

//! Wiring the mapped nodes: resolving sources through pass-throughs and clusters, the casts
//! a wire needs, and the `RH_IN:`/`RH_OUT:` groups that name inputs and outputs.

use super::*;

impl Mapper<'_> {
    /// The data type of a port of a node already in the graph.
    pub(super) fn port_type(&self, port: &PortRef, input: bool) -> Option<DataType> {
        let node = &self.graph.nodes[*self.node_pos.get(&port.node)?];
        let t = self.registry.get(&node.node_type)?;
        if input {
            t.resolve_inputs(node.input_names.as_deref())
                .iter()
                .find(|p| p.is_named(&port.port))
                .map(|p| p.data_type)
        } else {
            t.outputs
                .iter()
                .find(|p| p.is_named(&port.port))
                .map(|p| p.data_type)
        }
    }

    /// Resolves an output GUID to node ports, following pass-throughs.
    pub(super) fn resolve(
        &self,
        guid: &str,
        seen: &mut Vec<String>,
        out: &mut Vec<Result<PortRef, String>>,
    ) {
        if seen.iter().any(|s| s == guid) || seen.len() > 256 {
            out.push(Err("a loop of pass-through parameters".to_owned()));
            return;
        }
        match self.sources.get(guid) {
            Some(Source::Port(p)) => out.push(Ok(p.clone())),
            Some(Source::Missing(why)) => out.push(Err(why.clone())),
            Some(Source::Through(next)) => {
                seen.push(guid.to_owned());
                for n in next {
                    self.resolve(n, seen, out);
                }
                seen.pop();
            }
            None => out.push(Err(format!("no data from an unknown object {guid}"))),
        }
    }

    pub(super) fn wire(&mut self) {
        let pending = std::mem::take(&mut self.pending);
        for input in pending {
            let mut resolved = Vec::new();
            for s in &input.sources {
                self.resolve(s, &mut Vec::new(), &mut resolved);
            }
            let mut missing = false;
            let mut wired = false;
            for r in resolved {
                match r {
                    Ok(from) => {
                        let (a, b) = (
                            self.port_type(&from, false),
                            self.port_type(
                                &PortRef {
                                    node: input.node.clone(),
                                    port: input.port.clone(),
                                },
                                true,
                            ),
                        );
                        if let (Some(a), Some(b)) = (a, b)
                            && !locus_runtime::can_cast(a, b)
                        {
                            missing = true;
                            self.diag(
                                Level::Warning,
                                "no-cast",
                                format!(
                                    "node \"{}\" input {}: the wire from {from} carries {} data, which does not cast to {}; left out",
                                    input.node,
                                    input.port,
                                    a.name(),
                                    b.name()
                                ),
                                Some(input.object.clone()),
                                Some(input.node.clone()),
                                Some(input.port.clone()),
                            );
                            continue;
                        }
                        wired = true;
                        self.graph.wires.push(Wire {
                            from,
                            to: PortRef {
                                node: input.node.clone(),
                                port: input.port.clone(),
                            },
                        });
                    }
                    Err(why) => {
                        missing = true;
                        self.diag(
                            Level::Warning,
                            "no-data",
                            format!("node \"{}\" input {}: {why}", input.node, input.port),
                            Some(input.object.clone()),
                            Some(input.node.clone()),
                            Some(input.port.clone()),
                        );
                    }
                }
            }
            if missing
                && !wired
                && let Some(&k) = self.node_pos.get(&input.node)
            {
                let node = &mut self.graph.nodes[k];
                // Nothing reaches the input: it is empty (no branches), so the node runs on no
                // data, as in Grasshopper, instead of the graph failing to check.
                node.values.retain(|(p, _)| *p != input.port);
                node.values
                    .push((input.port.clone(), Literal("{}".to_owned())));
            }
        }
        let panels = std::mem::take(&mut self.panels);
        for (name, sources) in panels {
            let mut resolved = Vec::new();
            for s in &sources {
                self.resolve(s, &mut Vec::new(), &mut resolved);
            }
            let ports: Vec<PortRef> = resolved.into_iter().filter_map(Result::ok).collect();
            let many = ports.len() > 1;
            for (k, p) in ports.into_iter().enumerate() {
                let n = if many {
                    format!("{name} {}", k + 1)
                } else {
                    name.clone()
                };
                self.outputs.push((n, p));
            }
        }
    }

    /// `RH_IN:name` / `RH_OUT:name` groups.
    pub(super) fn groups(&mut self, doc: &GhDocument) {
        for g in doc.objects.iter().filter(|o| o.type_guid == GROUP) {
            let (is_in, name) = if let Some(n) = g.nickname.strip_prefix("RH_IN:") {
                (true, n)
            } else if let Some(n) = g.nickname.strip_prefix("RH_OUT:") {
                (false, n)
            } else {
                continue;
            };
            // The old convention puts a type code first: `RH_IN:102:name`.
            let name = match name.split_once(':') {
                Some((code, rest))
                    if !rest.is_empty()
                        && code.len() == 3
                        && code.bytes().all(|b| b.is_ascii_digit()) =>
                {
                    rest
                }
                _ => name,
            };
            // Compute knows the grouped object by the group's whole nickname, and only by the
            // first object of the group.
            let mut first = true;
            for id in g.container.items_named("ID") {
                let Some(target) = id.value.as_str() else {
                    continue;
                };
                let object = doc.objects.iter().find(|o| o.instance == target);
                let several = object.is_some_and(|o| o.outputs.len() > 1);
                let compute = (first && (!several || !is_in))
                    .then(|| (g.index, g.nickname.clone(), object.map_or(0.0, canvas_y)));
                let each_output = first && several && !is_in;
                first = false;
                let record = |this: &mut Self, port: &PortRef| {
                    if let Some((index, name, y)) = compute.clone() {
                        let list = if is_in {
                            &mut this.compute_inputs
                        } else {
                            &mut this.compute_outputs
                        };
                        list.push((index, name, port.clone(), y));
                    }
                };
                let Some(node) = self.nodes_by_object.get(target).cloned() else {
                    // A group may name a component's port (as `locus export-ghx` writes them).
                    if is_in && let Some(port) = self.input_ports.get(target).cloned() {
                        self.inputs.retain(|(_, p)| *p != port);
                        self.inputs.push((name.to_owned(), port.clone()));
                        record(self, &port);
                    } else if !is_in
                        && let Some(Source::Port(port)) = self.sources.get(target).cloned()
                    {
                        self.outputs.push((name.to_owned(), port.clone()));
                        record(self, &port);
                    }
                    continue;
                };
                let Some(graph_node) = self.node_pos.get(&node).map(|&k| &self.graph.nodes[k])
                else {
                    continue;
                };
                let Some(t) = self.registry.get(&graph_node.node_type) else {
                    continue;
                };
                if is_in {
                    if let Some(port) = t.inputs.first() {
                        // The group names the input: replace a name the widget gave it.
                        self.inputs.retain(|(_, p)| p.node != node);
                        let port = PortRef {
                            node,
                            port: port.nickname.clone(),
                        };
                        self.inputs.push((name.to_owned(), port.clone()));
                        record(self, &port);
                    }
                } else if each_output {
                    // Compute names each output of a component that is the first object of an
                    // `RH_OUT` group "<group nickname> (<output nickname>)".
                    let ports = t.resolve_outputs(graph_node.output_names.as_deref());
                    let gh_outputs = object.map_or(&[][..], |o| o.outputs.as_slice());
                    for (k, (port, gh)) in ports.iter().zip(gh_outputs).enumerate() {
                        let port = PortRef {
                            node: node.clone(),
                            port: port.nickname.clone(),
                        };
                        let suffix = if gh.nickname.is_empty() {
                            k.to_string()
                        } else {
                            gh.nickname.clone()
                        };
                        self.outputs
                            .push((format!("{name} ({suffix})"), port.clone()));
                        if let Some((index, group, y)) = &compute {
                            self.compute_outputs.push((
                                *index,
                                format!("{group} ({suffix})"),
                                port,
                                *y,
                            ));
                        }
                    }
                } else if let Some(port) = t.outputs.first() {
                    let port = PortRef {
                        node,
                        port: port.nickname.clone(),
                    };
                    self.outputs.push((name.to_owned(), port.clone()));
                    record(self, &port);
                }
            }
        }
    }
}

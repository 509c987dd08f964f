//! One component or floating parameter as a node: its ports matched by index, and each
//! input's wires, persistent data, modifiers and foreign data.

use super::*;

/// The Expression node, which also carries the expressions of inputs.
const EXPRESSION_NODE: &str = "maths.expression";

impl Mapper<'_> {
    /// Maps a component or floating parameter onto a node of `node_type`.
    pub(super) fn component(
        &mut self,
        o: &GhObject,
        r: ObjectRef,
        node_type: &NodeType,
        prefix: &str,
    ) -> Option<NodeId> {
        let variable = node_type.variable_inputs.is_some();
        if !variable && o.inputs.len() > node_type.inputs.len() {
            self.unsupported(
                o,
                r,
                "component",
                format!(
                    "it has {} inputs, the node {} has {}",
                    o.inputs.len(),
                    node_type.id,
                    node_type.inputs.len()
                ),
            );
            return None;
        }
        let variable_outputs = node_type.variable_outputs.as_ref();
        if variable_outputs.is_none() && o.outputs.len() > node_type.outputs.len() {
            self.unsupported(
                o,
                r,
                "component",
                format!(
                    "it has {} outputs, the node {} has {}",
                    o.outputs.len(),
                    node_type.id,
                    node_type.outputs.len()
                ),
            );
            return None;
        }
        let base = slug(if o.nickname.is_empty() {
            &o.name
        } else {
            &o.nickname
        });
        let id = self.unique_id(prefix, &base);
        let mut node = GraphNode {
            id: id.clone(),
            node_type: node_type.id.clone(),
            disabled: o.disabled,
            ..GraphNode::default()
        };
        let input_ports: Vec<(String, DataType)> = if variable {
            let names: Vec<String> = o
                .inputs
                .iter()
                .enumerate()
                .map(|(k, p)| {
                    if p.nickname.trim().is_empty() {
                        format!("x{k}")
                    } else {
                        p.nickname.clone()
                    }
                })
                .collect();
            let t = node_type
                .variable_inputs
                .as_ref()
                .map(|v| v.template.data_type)
                .unwrap_or(DataType::Generic);
            node.input_names = Some(names.clone());
            names.into_iter().map(|n| (n, t)).collect()
        } else {
            for (k, p) in o.inputs.iter().enumerate() {
                let port = &node_type.inputs[k];
                if !o.floating && !port.is_named(&p.nickname) && !port.is_named(&p.name) {
                    self.diag(
                        Level::Warning,
                        "port-name",
                        format!(
                            "{r}: input {k} is \"{}\" ({}) in the file but \"{}\" ({}) in {}; mapped by index",
                            p.name, p.nickname, port.name, port.nickname, node_type.id
                        ),
                        Some(r.clone()),
                        Some(id.clone()),
                        Some(port.nickname.clone()),
                    );
                }
            }
            node_type
                .inputs
                .iter()
                .map(|p| (p.nickname.clone(), p.data_type))
                .collect()
        };
        if let Some(variable) = variable_outputs {
            // Outputs named like a fixed output (a script's `out`) are that output; the others
            // are the node's named outputs, in order.
            let mut names = Vec::new();
            for (k, p) in o.outputs.iter().enumerate() {
                let fixed = variable
                    .fixed
                    .iter()
                    .find(|f| f.is_named(&p.nickname) || f.is_named(&p.name));
                let (port, data_type) = match fixed {
                    Some(f) => (f.nickname.clone(), f.data_type),
                    None => {
                        let name = [&p.nickname, &p.name]
                            .into_iter()
                            .find(|n| !n.trim().is_empty())
                            .cloned()
                            .unwrap_or_else(|| format!("o{k}"));
                        names.push(name.clone());
                        (name, variable.template.data_type)
                    }
                };
                let mods = self.modifiers(&r, &id, p, &port, data_type, false);
                if !mods.is_empty() {
                    node.output_modifiers.push((port.clone(), mods));
                }
                self.sources.insert(
                    p.instance.clone(),
                    Source::Port(PortRef {
                        node: id.clone(),
                        port,
                    }),
                );
            }
            node.output_names = Some(names);
        }
        let fixed_outputs = if variable_outputs.is_some() {
            &[][..]
        } else {
            &o.outputs[..]
        };
        for (k, p) in fixed_outputs.iter().enumerate() {
            let port = &node_type.outputs[k];
            if !o.floating && !port.is_named(&p.nickname) && !port.is_named(&p.name) {
                self.diag(
                    Level::Warning,
                    "port-name",
                    format!(
                        "{r}: output {k} is \"{}\" ({}) in the file but \"{}\" ({}) in {}; mapped by index",
                        p.name, p.nickname, port.name, port.nickname, node_type.id
                    ),
                    Some(r.clone()),
                    Some(id.clone()),
                    Some(port.nickname.clone()),
                );
            }
            self.sources.insert(
                p.instance.clone(),
                Source::Port(PortRef {
                    node: id.clone(),
                    port: port.nickname.clone(),
                }),
            );
            if !o.floating {
                // A floating parameter's modifiers are read once, as its input's.
                let mods = self.modifiers(&r, &id, p, &port.nickname, port.data_type, false);
                if !mods.is_empty() {
                    node.output_modifiers.push((port.nickname.clone(), mods));
                }
            }
        }
        let resolved = node_type.resolve_inputs(node.input_names.as_deref());
        for (k, p) in o.inputs.iter().enumerate() {
            let (port, data_type) = input_ports[k].clone();
            self.input_ports.insert(
                p.instance.clone(),
                PortRef {
                    node: id.clone(),
                    port: port.clone(),
                },
            );
            if self.input_expression(&mut node, &r, p, &port, data_type, prefix) {
                continue;
            }
            self.input_data(&mut node, &r, p, &port, data_type);
            let required = resolved
                .get(k)
                .is_some_and(|q| q.default.is_none() && !q.optional);
            let empty = p.sources.is_empty()
                && !node.values.iter().any(|(q, _)| *q == port)
                && (required || p.persistent.as_ref().is_some_and(|t| t.branches.is_empty()));
            if empty {
                // Nothing reaches the input and nothing was typed in: it is empty, so the node
                // runs on no data (Grasshopper's "failed to collect data"), instead of the
                // graph failing to check.
                node.values.push((port.clone(), Literal("{}".to_owned())));
            }
        }
        if node_type.id == EXPRESSION_NODE
            && let Some(formula) = o.container.str("Expression")
        {
            node.settings
                .push(("expression".to_owned(), Literal(literal::text(formula))));
            // A formula the node's own prepare step cannot read (Grasshopper syntax locus does
            // not have, such as `•` or `[d1]`) disables the node, so that the rest of the
            // definition still checks and runs; downstream nodes get no data from it.
            if let Err(e) = formula_reads(node_type, formula, &resolved) {
                node.disabled = true;
                self.diag(
                    Level::Warning,
                    "unsupported-expression",
                    format!(
                        "{r}: the formula \"{formula}\" does not read in locus ({e}); the node is disabled"
                    ),
                    Some(r.clone()),
                    None,
                    None,
                );
            }
        }
        if node_type.id == "curve.point_on_curve"
            && let Some(x) = o.container.item("parameter").and_then(|i| i.value.as_f64())
        {
            // The position is stored in the object, set with its slider on the canvas.
            node.settings
                .push(("parameter".to_owned(), Literal(literal::number(x))));
        }
        if node_type.id == script::PYTHON {
            let (settings, warnings) = script::settings(o, &resolved);
            node.settings.extend(settings);
            for w in warnings {
                self.diag(
                    Level::Warning,
                    "script-type-hint",
                    format!("{r}: {w}"),
                    Some(r.clone()),
                    Some(id.clone()),
                    None,
                );
            }
        }
        if node_type.id == "display.gradient" {
            match gradient::settings(&o.container) {
                Some(Ok(settings)) => node.settings.extend(settings),
                Some(Err(e)) => {
                    node.disabled = true;
                    self.diag(
                        Level::Warning,
                        "unsupported-gradient",
                        format!("{r}: the gradient does not read ({e}); the node is disabled"),
                        Some(r.clone()),
                        None,
                        None,
                    );
                }
                None => {}
            }
        }
        let mut note = format!("{} \"{}\"", o.type_name, o.nickname);
        if o.disabled {
            note.push_str(", disabled");
        }
        self.notes.push((id.clone(), note));
        self.nodes_by_object.insert(o.instance.clone(), id.clone());
        self.node_pos.insert(id.clone(), self.graph.nodes.len());
        self.graph.nodes.push(node);
        self.report.objects.push((r, Outcome::Mapped(id.clone())));
        Some(id)
    }

    /// An input with an expression (Grasshopper applies it to every item the input collects,
    /// as `x`): an Expression node takes the input's wires and typed-in data as its `x`, and
    /// its result feeds the input, which keeps its modifiers (they apply to the results,
    /// which keep the paths). Returns false, leaving the input to [`Self::input_data`], when
    /// the input has no expression or locus cannot read the formula (then with a warning).
    fn input_expression(
        &mut self,
        node: &mut GraphNode,
        r: &ObjectRef,
        p: &GhParam,
        port: &str,
        data_type: DataType,
        prefix: &str,
    ) -> bool {
        let Some(formula) = p.expression.as_deref() else {
            return false;
        };
        let id = node.id.clone();
        let names = vec!["x".to_owned()];
        let readable = match self.registry.get(EXPRESSION_NODE) {
            None => Err("the library has no Expression node".to_owned()),
            Some(expression) => {
                let resolved = expression.resolve_inputs(Some(&names));
                formula_reads(expression, formula, &resolved)
                    .map_err(|e| format!("it does not read in locus ({e})"))
            }
        };
        if let Err(why) = readable {
            self.diag(
                Level::Warning,
                "unsupported-input-expression",
                format!("{r}: the expression \"{formula}\" on input {port} is not applied: {why}"),
                Some(r.clone()),
                Some(id),
                Some(port.to_owned()),
            );
            return false;
        }
        let expression_id = self.unique_id(prefix, &format!("{}_{}_expression", id.0, slug(port)));
        let mut inner = GraphNode {
            id: expression_id.clone(),
            node_type: EXPRESSION_NODE.to_owned(),
            disabled: node.disabled,
            input_names: Some(names),
            ..GraphNode::default()
        };
        inner
            .settings
            .push(("expression".to_owned(), Literal(literal::text(formula))));
        // The wires and typed-in data, read as for the input itself; then the input's own
        // modifiers go back to the input.
        let stripped = GhParam {
            expression: None,
            ..p.clone()
        };
        self.input_data(&mut inner, r, &stripped, "x", data_type);
        node.modifiers.extend(
            inner
                .modifiers
                .drain(..)
                .map(|(_, mods)| (port.to_owned(), mods)),
        );
        self.graph.wires.push(Wire {
            from: PortRef {
                node: expression_id.clone(),
                port: "R".to_owned(),
            },
            to: PortRef {
                node: id.clone(),
                port: port.to_owned(),
            },
        });
        self.notes.push((
            expression_id.clone(),
            format!(
                "the expression \"{formula}\" on input {port} of \"{}\"",
                id.0
            ),
        ));
        self.node_pos
            .insert(expression_id.clone(), self.graph.nodes.len());
        self.graph.nodes.push(inner);
        true
    }

    /// Wires, persistent data, modifiers and foreign data of one input.
    pub(super) fn input_data(
        &mut self,
        node: &mut GraphNode,
        r: &ObjectRef,
        p: &GhParam,
        port: &str,
        data_type: DataType,
    ) {
        let id = node.id.clone();
        if !p.sources.is_empty() {
            self.pending.push(PendingInput {
                node: id.clone(),
                port: port.to_owned(),
                sources: p.sources.clone(),
                object: r.clone(),
            });
        } else if let Some(tree) = &p.persistent
            && !tree.branches.is_empty()
            && tree
                .branches
                .iter()
                .flat_map(|(_, items)| items)
                .any(|i| !matches!(i, GhItem::Other(_) | GhItem::Geometry(Err(_))))
        {
            let value = literal::tree(tree, data_type);
            match locus_runtime::parse_literal(&value.0, data_type) {
                Ok(_) => node.values.push((port.to_owned(), value)),
                Err(e) => self.diag(
                    Level::Warning,
                    "bad-value",
                    format!(
                        "{r}: the data typed into input {port} ({}) does not read as {}: {e}; left out",
                        value.0,
                        data_type.name()
                    ),
                    Some(r.clone()),
                    Some(id.clone()),
                    Some(port.to_owned()),
                ),
            }
        }
        let mods = self.modifiers(r, &id, p, port, data_type, true);
        if !mods.is_empty() {
            node.modifiers.push((port.to_owned(), mods));
        }
        for kind in &p.foreign_data {
            if kind == "ON_Data" {
                let mut reasons: Vec<&str> = p
                    .persistent
                    .iter()
                    .flat_map(|t| &t.branches)
                    .flat_map(|(_, items)| items)
                    .filter_map(|i| match i {
                        GhItem::Geometry(Err(e)) => Some(e.as_str()),
                        _ => None,
                    })
                    .collect();
                reasons.dedup();
                self.diag(
                    Level::Error,
                    "unsupported-internalised",
                    format!(
                        "{r} (instance {}): input {port} holds internalised Rhino geometry (ON_Data) that locus cannot read ({}); those items are null",
                        r.instance,
                        reasons.join("; ")
                    ),
                    Some(r.clone()),
                    Some(id.clone()),
                    Some(port.to_owned()),
                );
            } else if p.sources.is_empty() {
                let name = if r.nickname.is_empty() {
                    id.0.clone()
                } else {
                    r.nickname.clone()
                };
                self.diag(
                    Level::Warning,
                    "referenced-geometry",
                    format!(
                        "{r} (instance {}): input {port} references geometry in the Rhino document ({kind}); it is the named input \"{name}\", to be set",
                        r.instance
                    ),
                    Some(r.clone()),
                    Some(id.clone()),
                    Some(port.to_owned()),
                );
                self.inputs.push((
                    name,
                    PortRef {
                        node: id.clone(),
                        port: port.to_owned(),
                    },
                ));
            }
        }
        // Internalised geometry that nothing feeds is a named input, with the geometry as its
        // value, so that a run can set another curve or shape in its place.
        let internalised = p
            .persistent
            .iter()
            .flat_map(|t| &t.branches)
            .flat_map(|(_, items)| items)
            .any(|i| matches!(i, GhItem::Geometry(Ok(_))));
        if internalised && p.sources.is_empty() && p.foreign_data.is_empty() {
            let name = if r.nickname.is_empty() {
                id.0.clone()
            } else {
                r.nickname.clone()
            };
            self.inputs.push((
                name,
                PortRef {
                    node: id.clone(),
                    port: port.to_owned(),
                },
            ));
        }
    }

    /// The modifiers set on a parameter that locus can apply to a port of `data_type` (an
    /// input, or an output when `input` is false): Grasshopper's mapping wins over simplify,
    /// as locus applies one structural modifier per port.
    pub(super) fn modifiers(
        &mut self,
        r: &ObjectRef,
        id: &NodeId,
        p: &GhParam,
        port: &str,
        data_type: DataType,
        input: bool,
    ) -> Vec<Modifier> {
        let mut mods: Vec<Modifier> = p
            .modifiers
            .iter()
            .filter_map(|m| {
                let m = match m {
                    GhModifier::Flatten => Modifier::Flatten,
                    GhModifier::Graft => Modifier::Graft,
                    GhModifier::Simplify => Modifier::Simplify,
                    GhModifier::Reverse => Modifier::Reverse,
                    GhModifier::Invert => Modifier::Invert,
                    GhModifier::Degrees => Modifier::Degrees,
                    GhModifier::Reparameterize => Modifier::Reparameterize,
                };
                let fits = match m {
                    Modifier::Invert => data_type == DataType::Boolean,
                    Modifier::Degrees => input && data_type == DataType::Number,
                    Modifier::Reparameterize => {
                        matches!(data_type, DataType::Curve | DataType::Surface)
                    }
                    _ => true,
                };
                fits.then_some(m)
            })
            .collect();
        mods.dedup();
        if mods.contains(&Modifier::Simplify)
            && (mods.contains(&Modifier::Flatten) || mods.contains(&Modifier::Graft))
        {
            mods.retain(|m| *m != Modifier::Simplify);
            let which = if input { "input" } else { "output" };
            self.diag(
                Level::Warning,
                "modifiers",
                format!(
                    "{r}: {which} {port} has simplify with flatten or graft; simplify is left out"
                ),
                Some(r.clone()),
                Some(id.clone()),
                Some(port.to_owned()),
            );
        }
        mods
    }
}

/// Whether the Expression node type `expression` reads `formula` with the variables `inputs`:
/// its own prepare step, run as the graph check will run it.
fn formula_reads(
    expression: &NodeType,
    formula: &str,
    inputs: &[locus_runtime::Port],
) -> Result<(), String> {
    let Some(prepare) = &expression.prepare else {
        return Ok(());
    };
    let settings = [(
        "expression".to_owned(),
        locus_runtime::Value::Text(formula.to_owned()),
    )];
    prepare(&locus_runtime::NodeConfig {
        settings: &settings,
        inputs,
    })
    .map(|_| ())
    .map_err(|e| e.to_string())
}

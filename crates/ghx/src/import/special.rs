//! Objects the importer treats specially (see [`crate::known`]): pass-through parameters,
//! widgets (sliders, panels, toggles, buttons, value lists, knobs, MD sliders) and clusters.

use super::*;

impl Mapper<'_> {
    pub(super) fn pass_through(&mut self, o: &GhObject, r: ObjectRef, prefix: &str) {
        let Some(p) = o.inputs.first() else {
            self.report.objects.push((r, Outcome::Ignored));
            return;
        };
        let has_data = p
            .persistent
            .as_ref()
            .is_some_and(|t| !t.branches.is_empty());
        if p.sources.is_empty() && has_data || !p.modifiers.is_empty() {
            // Data typed in, or modifiers to apply: a generic parameter node keeps them.
            if let Some(t) = self.registry.get("params.geometry").cloned()
                && t.inputs
                    .first()
                    .is_some_and(|i| i.data_type == DataType::Generic)
            {
                self.component(o, r, &t, prefix);
                return;
            }
        }
        self.sources
            .insert(p.instance.clone(), Source::Through(p.sources.clone()));
        self.report.objects.push((r, Outcome::PassThrough));
    }

    pub(super) fn widget(&mut self, o: &GhObject, r: ObjectRef, kind: Special, prefix: &str) {
        let c = &o.container;
        let fed = o.inputs.first().is_some_and(|p| !p.sources.is_empty());
        let name = if o.nickname.trim().is_empty() {
            o.type_name.clone()
        } else {
            o.nickname.clone()
        };
        if kind == Special::Panel && fed {
            let sources = o.inputs[0].sources.clone();
            self.sources.insert(
                o.outputs[0].instance.clone(),
                Source::Through(sources.clone()),
            );
            self.panels.push((name, sources));
            self.report.objects.push((r, Outcome::PassThrough));
            return;
        }
        let (node_type, items, note): (&str, Vec<GhItem>, String) = match kind {
            Special::Slider => {
                let s = c.chunk("Slider");
                let get = |n: &str| s.and_then(|s| s.f64(n));
                let value = get("Value").unwrap_or(0.0);
                let kind = match s.and_then(|s| s.i64("Interval")) {
                    Some(1) => "integer",
                    Some(2) => "even",
                    Some(3) => "odd",
                    _ => "float",
                };
                let note = format!(
                    "Number Slider \"{}\": {kind}, {} to {}, {} digits",
                    o.nickname,
                    literal::number(get("Min").unwrap_or(0.0)),
                    literal::number(get("Max").unwrap_or(1.0)),
                    get("Digits").unwrap_or(0.0)
                );
                ("params.number", vec![GhItem::Number(value)], note)
            }
            Special::Knob => {
                let d = c.chunk("DialData");
                let get = |n: &str| d.and_then(|d| d.f64(n));
                let note = format!(
                    "Control Knob \"{}\": {} to {}, {} decimals",
                    o.nickname,
                    literal::number(get("Minimum").unwrap_or(0.0)),
                    literal::number(get("Maximum").unwrap_or(1.0)),
                    get("Decimals").unwrap_or(0.0)
                );
                let value = get("Value").unwrap_or(0.0);
                ("params.number", vec![GhItem::Number(value)], note)
            }
            Special::MdSlider => {
                // The slider keeps its position as fractions of its x, y and z domains; in
                // its two-dimensional mode (SliderMode 0) the point lies in the XY plane.
                let at = |fraction: Option<f64>, domain: &str| {
                    let [a, b] = match c.item(domain).map(|i| &i.value) {
                        Some(crate::archive::Value::Interval(d)) => *d,
                        _ => [0.0, 1.0],
                    };
                    a + fraction.unwrap_or(0.0) * (b - a)
                };
                let fractions = match c.item("slider_value").map(|i| &i.value) {
                    Some(crate::archive::Value::Point3(p)) => *p,
                    _ => [0.0; 3],
                };
                let planar = c.i64("SliderMode").unwrap_or(0) == 0;
                let point = [
                    at(Some(fractions[0]), "x_domain"),
                    at(Some(fractions[1]), "y_domain"),
                    if planar {
                        0.0
                    } else {
                        at(Some(fractions[2]), "z_domain")
                    },
                ];
                let note = format!(
                    "MD Slider \"{}\": ({}, {}, {})",
                    o.nickname,
                    literal::number(point[0]),
                    literal::number(point[1]),
                    literal::number(point[2])
                );
                ("params.point", vec![GhItem::Point(point)], note)
            }
            Special::Panel => {
                let text = c.str("UserText").unwrap_or_default();
                let multiline = c
                    .chunk("PanelProperties")
                    .and_then(|p| p.bool("Multiline"))
                    .unwrap_or(true);
                let items = if text.is_empty() {
                    Vec::new()
                } else if multiline {
                    vec![GhItem::Text(text.to_owned())]
                } else {
                    text.lines().map(|l| GhItem::Text(l.to_owned())).collect()
                };
                ("params.text", items, format!("Panel \"{}\"", o.nickname))
            }
            Special::Toggle => (
                "params.boolean",
                vec![GhItem::Boolean(c.bool("ToggleValue").unwrap_or(false))],
                format!("Boolean Toggle \"{}\"", o.nickname),
            ),
            Special::Button => (
                "params.boolean",
                vec![GhItem::Boolean(false)],
                format!("Button \"{}\" (not pressed)", o.nickname),
            ),
            _ => {
                let mut values = Vec::new();
                let mut numeric = true;
                for item in c.chunks_named("ListItem") {
                    if item.bool("Selected") == Some(true) {
                        let e = item.str("Expression").unwrap_or_default().trim();
                        match crate::xml::parse_float(e) {
                            Ok(x) => values.push(GhItem::Number(x)),
                            Err(_) => {
                                numeric = false;
                                values.push(GhItem::Text(e.trim_matches('"').to_owned()));
                            }
                        }
                    }
                }
                let node_type = if numeric {
                    "params.number"
                } else {
                    "params.text"
                };
                (node_type, values, format!("Value List \"{}\"", o.nickname))
            }
        };
        let Some(t) = self.registry.get(node_type).cloned() else {
            self.unsupported(o, r, "component", format!("no {node_type} in the registry"));
            return;
        };
        let mut widget = o.clone();
        if let Some(p) = widget.inputs.first_mut() {
            p.persistent = (!items.is_empty()).then(|| GhTree {
                branches: vec![(vec![0], items)],
            });
        }
        if let Some(id) = self.component(&widget, r, &t, prefix) {
            if let Some(n) = self.notes.iter_mut().find(|(n, _)| *n == id) {
                n.1 = note;
            }
            if !fed {
                let port = t.inputs[0].nickname.clone();
                self.inputs.push((name, PortRef { node: id, port }));
            }
        }
    }

    /// Context Bake and Context Print (Hops outputs): a Data parameter node that takes the
    /// component's input (wires, modifiers) and is a named output. Rhino.Compute names the
    /// output after the nickname of the component's input parameter
    /// (`GrasshopperDefinition.cs`: `AddOutput(param, param.NickName)`), so does the graph.
    pub(super) fn hops_put(&mut self, o: &GhObject, r: ObjectRef, cluster: &str, prefix: &str) {
        let Some(p) = o.inputs.first() else {
            self.unsupported(o, r, "hops", "the component has no input".to_owned());
            return;
        };
        let name = [&p.nickname, &p.name, &o.nickname, &o.name]
            .into_iter()
            .find(|n| !n.trim().is_empty())
            .cloned()
            .unwrap_or_else(|| "output".to_owned());
        let id = self.unique_id(prefix, &slug(&name));
        let mut node = GraphNode {
            id: id.clone(),
            node_type: "params.data".to_owned(),
            disabled: o.disabled,
            ..GraphNode::default()
        };
        if p.sources.is_empty() {
            self.diag(
                Level::Warning,
                "no-data",
                format!(
                    "{r}: nothing is wired into its input {}; the output \"{name}\" is empty",
                    p.nickname
                ),
                Some(r.clone()),
                Some(id.clone()),
                None,
            );
        } else {
            self.pending.push(PendingInput {
                node: id.clone(),
                port: "Data".to_owned(),
                sources: p.sources.clone(),
                object: r.clone(),
            });
        }
        let mods = self.modifiers(&r, &id, p, "Data", DataType::Generic, true);
        if !mods.is_empty() {
            node.modifiers.push(("Data".to_owned(), mods));
        }
        self.notes.push((
            id.clone(),
            format!("{} \"{}\" (Hops output)", o.type_name, o.nickname),
        ));
        self.nodes_by_object.insert(o.instance.clone(), id.clone());
        self.node_pos.insert(id.clone(), self.graph.nodes.len());
        self.graph.nodes.push(node);
        let port = PortRef {
            node: id.clone(),
            port: "Data".to_owned(),
        };
        if cluster.is_empty() {
            self.compute_outputs
                .push((o.index, name.clone(), port.clone(), canvas_y(o)));
        }
        self.outputs.push((name, port));
        self.report.objects.push((r, Outcome::Mapped(id)));
    }

    /// A cluster becomes a sub-graph node whose inline graph is the cluster's document: its
    /// Cluster Input and Output objects (in document order) become Data parameters that are
    /// the graph's named inputs and outputs, so that the cluster's k-th input feeds the k-th
    /// Cluster Input and its k-th output reads the k-th Cluster Output.
    pub(super) fn cluster(&mut self, o: &GhObject, r: ObjectRef, cluster: &str, depth: usize) {
        if o.outputs.is_empty() {
            // Nothing downstream can depend on a cluster without outputs (such clusters open
            // a web page or draw in the canvas): whatever is inside, there is no data to run.
            self.diag(
                Level::Remark,
                "dropped-cluster",
                format!("{r} is a cluster without outputs, so no data depends on it: dropped"),
                Some(r.clone()),
                None,
                None,
            );
            self.report.objects.push((r, Outcome::Dropped));
            return;
        }
        let Some(bytes) = o
            .container
            .item("ClusterDocument")
            .and_then(|i| match &i.value {
                crate::archive::Value::Bytes(b) => Some(b.clone()),
                _ => None,
            })
        else {
            self.unsupported(o, r, "cluster", "the cluster has no document".to_owned());
            return;
        };
        let inner = match read_cluster(&bytes, self.limits, depth + 1) {
            Ok(d) => d,
            Err(e) => {
                self.unsupported(o, r, "cluster", format!("its document does not read: {e}"));
                return;
            }
        };
        self.map_cluster(o, r, cluster, depth, &inner);
    }

    /// Maps a cluster whose document is `inner` (see [`Mapper::cluster`]).
    pub(super) fn map_cluster(
        &mut self,
        o: &GhObject,
        r: ObjectRef,
        cluster: &str,
        depth: usize,
        inner: &GhDocument,
    ) {
        let prefix = if cluster.is_empty() || self.in_cluster {
            String::new()
        } else {
            format!("{cluster}/")
        };
        let base = slug(if o.nickname.is_empty() {
            &o.name
        } else {
            &o.nickname
        });
        let id = self.unique_id(&prefix, &base);
        // The cluster's ports are the Cluster Input and Output objects inside: the one its
        // `ParamMap` names for each port, or else the objects in document order.
        let boundary_in = boundary_objects(o, &o.inputs, inner, CLUSTER_INPUT);
        let boundary_out = boundary_objects(o, &o.outputs, inner, CLUSTER_OUTPUT);
        if boundary_in.len() != o.inputs.len() || boundary_out.len() != o.outputs.len() {
            self.unsupported(
                o,
                r,
                "cluster",
                format!(
                    "its ports ({} in, {} out) do not match its document ({} in, {} out)",
                    o.inputs.len(),
                    o.outputs.len(),
                    boundary_in.len(),
                    boundary_out.len()
                ),
            );
            return;
        }
        // The inner document, mapped on its own; its objects are named in the report under
        // the cluster's path.
        let path = if cluster.is_empty() {
            id.0.clone()
        } else {
            format!("{cluster}/{id}")
        };
        let mut inner_map = Mapper::new(
            self.registry,
            self.limits,
            Graph {
                format: locus_runtime::FORMAT_VERSION,
                name: o.name.clone(),
                ..Graph::default()
            },
            inner.libraries.clone(),
        );
        inner_map.in_cluster = true;
        let (mut seen_in, mut seen_out) = (HashSet::new(), HashSet::new());
        let mut in_names = Vec::new();
        let mut out_names = Vec::new();
        for (k, boundary) in boundary_in.iter().chain(&boundary_out).enumerate() {
            let input = k < boundary_in.len();
            let base = slug(if boundary.nickname.is_empty() {
                &boundary.name
            } else {
                &boundary.nickname
            });
            let base = if base.is_empty() {
                if input { "input" } else { "output" }.to_owned()
            } else {
                base
            };
            let node = inner_map.unique_id("", &base);
            let data = PortRef {
                node: node.clone(),
                port: "Data".to_owned(),
            };
            inner_map
                .node_pos
                .insert(node.clone(), inner_map.graph.nodes.len());
            inner_map
                .nodes_by_object
                .insert(boundary.instance.clone(), node.clone());
            // The boundary object's own modifiers (a Cluster Output that grafts).
            let mut modifiers = Vec::new();
            if let Some(p) = boundary.inputs.first() {
                let mods = inner_map.modifiers(
                    &object_ref(boundary, &path),
                    &node,
                    p,
                    "Data",
                    DataType::Generic,
                    true,
                );
                if !mods.is_empty() {
                    modifiers.push(("Data".to_owned(), mods));
                }
            }
            inner_map.graph.nodes.push(GraphNode {
                id: node.clone(),
                node_type: "params.data".to_owned(),
                modifiers,
                ..GraphNode::default()
            });
            inner_map.notes.push((
                node.clone(),
                format!(
                    "Cluster {} \"{}\" {}",
                    if input { "Input" } else { "Output" },
                    boundary.nickname,
                    boundary.instance
                ),
            ));
            if input {
                let name = unique_name(&mut seen_in, base);
                if let Some(p) = boundary.outputs.first() {
                    inner_map
                        .sources
                        .insert(p.instance.clone(), Source::Port(data.clone()));
                }
                inner_map.inputs.push((name.clone(), data));
                in_names.push(name);
            } else {
                let name = unique_name(&mut seen_out, base);
                if let Some(p) = boundary.inputs.first() {
                    inner_map.pending.push(PendingInput {
                        node,
                        port: "Data".to_owned(),
                        sources: p.sources.clone(),
                        object: object_ref(boundary, &path),
                    });
                }
                inner_map.outputs.push((name.clone(), data));
                out_names.push(name);
            }
        }
        let rest = GhDocument {
            objects: inner
                .objects
                .iter()
                .filter(|x| x.type_guid != CLUSTER_INPUT && x.type_guid != CLUSTER_OUTPUT)
                .cloned()
                .collect(),
            libraries: inner.libraries.clone(),
            ..GhDocument::default()
        };
        inner_map.objects(&rest, &path, depth + 1);
        inner_map.wire();
        let mut mapped = inner_map.finish();
        // The runtime has no output modifiers on sub-graph nodes: a cluster output's apply to
        // the data its Cluster Output gives, as the output modifiers of that Data parameter.
        for (outer, name) in o.outputs.iter().zip(&out_names) {
            let mods = self.modifiers(&r, &id, outer, name, DataType::Generic, false);
            let source = mapped
                .graph
                .outputs
                .iter()
                .find(|x| &x.name == name)
                .map(|x| x.source.node.clone());
            if let (false, Some(source)) = (mods.is_empty(), source)
                && let Some(n) = mapped.graph.nodes.iter_mut().find(|n| n.id == source)
            {
                n.output_modifiers.push(("Data".to_owned(), mods));
            }
        }
        self.notes.extend(
            mapped
                .notes
                .iter()
                .map(|(inner, note)| (NodeId(format!("{id}/{inner}")), note.clone())),
        );
        self.report.objects.extend(mapped.report.objects);
        self.report.diagnostics.extend(mapped.report.diagnostics);
        // The sub-graph node, wired as any component: outer input k feeds named input k, and
        // outer output k is named output k.
        self.report
            .objects
            .push((r.clone(), Outcome::Mapped(id.clone())));
        self.notes.push((id.clone(), format!("{r}")));
        self.nodes_by_object.insert(o.instance.clone(), id.clone());
        self.node_pos.insert(id.clone(), self.graph.nodes.len());
        let mut node = GraphNode {
            id: id.clone(),
            node_type: SUBGRAPH_TYPE.to_owned(),
            subgraph: Some(SubGraph::Inline(Box::new(mapped.graph))),
            ..GraphNode::default()
        };
        // Each outer input as any component's: its wires, or the data typed into it, and its
        // modifiers.
        for (outer, name) in o.inputs.iter().zip(&in_names) {
            let port = PortRef {
                node: id.clone(),
                port: name.clone(),
            };
            self.input_ports.insert(outer.instance.clone(), port);
            self.input_data(&mut node, &r, outer, name, DataType::Generic);
        }
        self.graph.nodes.push(node);
        for (outer, name) in o.outputs.iter().zip(&out_names) {
            let port = PortRef {
                node: id.clone(),
                port: name.clone(),
            };
            self.sources
                .insert(outer.instance.clone(), Source::Port(port));
        }
    }
}

/// The Cluster Input or Output objects (`kind`) of a cluster's document, one per port of
/// `ports`: a cluster's `ParamMap` maps each port's instance GUID to its boundary object's.
/// Without a map that names every port, the objects of that kind in document order.
fn boundary_objects<'a>(
    cluster: &GhObject,
    ports: &[GhParam],
    inner: &'a GhDocument,
    kind: &str,
) -> Vec<&'a GhObject> {
    let in_order = || -> Vec<&'a GhObject> {
        inner
            .objects
            .iter()
            .filter(|x| x.type_guid == kind)
            .collect()
    };
    let Some(map) = cluster.container.chunk("ParamMap") else {
        return in_order();
    };
    let guid = |i: &crate::archive::Item| match &i.value {
        crate::archive::Value::Guid(g) => Some(g.to_ascii_lowercase()),
        _ => None,
    };
    let values: HashMap<Option<i32>, String> = map
        .items_named("Value")
        .filter_map(|i| Some((i.index, guid(i)?)))
        .collect();
    let pairs: HashMap<String, &String> = map
        .items_named("Key")
        .filter_map(|k| Some((guid(k)?, values.get(&k.index)?)))
        .collect();
    let mapped: Option<Vec<&'a GhObject>> = ports
        .iter()
        .map(|p| {
            let target = pairs.get(&p.instance.to_ascii_lowercase())?;
            inner
                .objects
                .iter()
                .find(|x| x.type_guid == kind && x.instance.eq_ignore_ascii_case(target))
        })
        .collect();
    match mapped {
        Some(objects) if !objects.is_empty() => objects,
        _ => in_order(),
    }
}

#[cfg(test)]
mod tests {
    use locus_runtime::{Evaluator, Value, check};

    use crate::Chunk;

    use super::*;

    fn param(instance: &str, nickname: &str, sources: &[&str]) -> GhParam {
        GhParam {
            instance: instance.to_owned(),
            name: nickname.to_owned(),
            nickname: nickname.to_owned(),
            sources: sources.iter().map(|s| (*s).to_owned()).collect(),
            ..GhParam::default()
        }
    }

    /// A Timer is ignored with a remark; a Data Recorder and a File Path parameter map onto
    /// their nodes, and the definition runs whole.
    #[test]
    fn timers_are_ignored_and_recorders_and_file_paths_map() {
        let mut registry = NodeRegistry::new();
        locus_nodes::register(&mut registry);
        let guid = |id: &str| registry.get(id).expect(id).gh_guids[0].clone();
        let doc = GhDocument {
            objects: vec![
                GhObject {
                    type_guid: "5a2b0735-ba98-4b7d-a7d3-c1dfc04475ad".to_owned(),
                    type_name: "Timer".to_owned(),
                    instance: "timer".to_owned(),
                    nickname: "Timer".to_owned(),
                    ..GhObject::default()
                },
                GhObject {
                    type_guid: guid("params.file_path"),
                    type_name: "File Path".to_owned(),
                    instance: "path".to_owned(),
                    nickname: "Path".to_owned(),
                    inputs: vec![param("path-in", "Path", &[])],
                    outputs: vec![param("path", "Path", &[])],
                    ..GhObject::default()
                },
                GhObject {
                    type_guid: guid("params.data_recorder"),
                    type_name: "Data Recorder".to_owned(),
                    instance: "rec".to_owned(),
                    nickname: "Rec".to_owned(),
                    inputs: vec![param("rec-in", "Rec", &["path"])],
                    outputs: vec![param("rec", "Rec", &[])],
                    ..GhObject::default()
                },
            ],
            ..GhDocument::default()
        };
        let import = import_document(&doc, &registry, &Limits::default());
        let outcomes: Vec<&Outcome> = import.report.objects.iter().map(|(_, o)| o).collect();
        assert!(
            matches!(
                outcomes[..],
                [Outcome::Ignored, Outcome::Mapped(_), Outcome::Mapped(_)]
            ),
            "{outcomes:?}"
        );
        assert!(import.report.runs_whole());
        let timer = &import.report.diagnostics[0];
        assert_eq!(
            (timer.severity, timer.code),
            (Level::Remark, "ignored-timer")
        );
        assert!(timer.message.contains("Timer"), "{}", timer.message);
        let types: Vec<&str> = import
            .graph
            .nodes
            .iter()
            .map(|n| n.node_type.as_str())
            .collect();
        assert_eq!(types, ["params.file_path", "params.data_recorder"]);
        assert_eq!(import.graph.wires.len(), 1);
    }

    /// Hops outputs as Rhino.Compute names them: a Context Bake and a Context Print are
    /// outputs named after their input's nickname, and a component with several outputs that
    /// is the first object of an `RH_OUT` group gives one output per output, "<group> (X)".
    #[test]
    fn context_bake_print_and_multi_output_groups_are_named_outputs() {
        let mut registry = NodeRegistry::new();
        locus_nodes::register(&mut registry);
        let guid = |id: &str| registry.get(id).expect(id).gh_guids[0].clone();
        let mut point = param("point-in", "Pt", &[]);
        point.persistent = Some(GhTree {
            branches: vec![(vec![0], vec![GhItem::Point([1.0, 2.0, 3.0])])],
        });
        let mut text = param("text-in", "Txt", &[]);
        text.persistent = Some(GhTree {
            branches: vec![(vec![0], vec![GhItem::Text("done".to_owned())])],
        });
        let group = crate::Chunk {
            items: vec![crate::archive::Item {
                name: "ID".to_owned(),
                index: Some(0),
                value: crate::archive::Value::Guid("decon".to_owned()),
            }],
            ..crate::Chunk::default()
        };
        let doc = GhDocument {
            objects: vec![
                GhObject {
                    index: 0,
                    type_guid: guid("params.point"),
                    type_name: "Point".to_owned(),
                    instance: "point".to_owned(),
                    nickname: "Pt".to_owned(),
                    inputs: vec![point],
                    outputs: vec![param("point", "Pt", &[])],
                    ..GhObject::default()
                },
                GhObject {
                    index: 1,
                    type_guid: guid("vector.deconstruct_point"),
                    type_name: "Deconstruct".to_owned(),
                    instance: "decon".to_owned(),
                    nickname: "pDecon".to_owned(),
                    inputs: vec![param("decon-p", "P", &["point"])],
                    outputs: vec![
                        param("decon-x", "X", &[]),
                        param("decon-y", "Y", &[]),
                        param("decon-z", "Z", &[]),
                    ],
                    ..GhObject::default()
                },
                GhObject {
                    index: 2,
                    type_guid: "ae2531b4-bab2-4bb1-b5bf-f2143d10c132".to_owned(),
                    type_name: "Context Bake".to_owned(),
                    instance: "bake".to_owned(),
                    nickname: "Context Bake".to_owned(),
                    inputs: vec![param("bake-in", "where", &["point"])],
                    ..GhObject::default()
                },
                GhObject {
                    index: 3,
                    type_guid: guid("params.text"),
                    type_name: "Text".to_owned(),
                    instance: "text".to_owned(),
                    nickname: "Txt".to_owned(),
                    inputs: vec![text],
                    outputs: vec![param("text", "Txt", &[])],
                    ..GhObject::default()
                },
                GhObject {
                    index: 4,
                    type_guid: "73215ec5-0eb5-4f85-9e07-b09c4590ce2b".to_owned(),
                    type_name: "Context Print".to_owned(),
                    instance: "print".to_owned(),
                    nickname: "Context Print".to_owned(),
                    inputs: vec![param("print-in", "Tx", &["text"])],
                    ..GhObject::default()
                },
                GhObject {
                    index: 5,
                    type_guid: crate::known::GROUP.to_owned(),
                    type_name: "Group".to_owned(),
                    instance: "group".to_owned(),
                    nickname: "RH_OUT:coords".to_owned(),
                    container: group,
                    ..GhObject::default()
                },
            ],
            ..GhDocument::default()
        };
        let import = import_document(&doc, &registry, &Limits::default());
        assert!(
            import.report.runs_whole(),
            "{:#?}",
            import.report.diagnostics
        );
        let compute: Vec<(&str, &str)> = import
            .compute_outputs
            .iter()
            .map(|n| (n.name.as_str(), n.graph.as_str()))
            .collect();
        assert_eq!(
            compute,
            [
                ("where", "where"),
                ("Tx", "Tx"),
                ("RH_OUT:coords (X)", "coords (X)"),
                ("RH_OUT:coords (Y)", "coords (Y)"),
                ("RH_OUT:coords (Z)", "coords (Z)"),
            ]
        );
        let checked = check(&import.graph, &registry)
            .unwrap_or_else(|d| panic!("{d:#?}\n{}", import.graph.to_ron()));
        let mut e = Evaluator::new(checked.plan);
        e.evaluate();
        let first = |name: &str| e.output(name).and_then(|t| t.values().next().flatten());
        assert_eq!(
            first("where"),
            Some(Value::Point(locus_kernel::Point3::new(1.0, 2.0, 3.0)))
        );
        assert_eq!(first("Tx"), Some(Value::Text("done".to_owned())));
        assert_eq!(first("coords (Y)"), Some(Value::Number(2.0)));
        assert_eq!(first("coords (Z)"), Some(Value::Number(3.0)));
    }

    /// A cluster "twice" whose document adds its input to itself: x → Addition(A = x, B = x)
    /// → y.
    #[test]
    fn a_cluster_becomes_a_sub_graph_node_that_runs() {
        let mut registry = NodeRegistry::new();
        locus_nodes::register(&mut registry);
        let addition = registry.get("maths.addition").expect("addition").gh_guids[0].clone();
        let inner = GhDocument {
            objects: vec![
                GhObject {
                    type_guid: CLUSTER_INPUT.to_owned(),
                    instance: "cluster-input".to_owned(),
                    nickname: "x".to_owned(),
                    outputs: vec![param("cluster-input-out", "x", &[])],
                    ..GhObject::default()
                },
                GhObject {
                    type_guid: addition,
                    type_name: "Addition".to_owned(),
                    instance: "add".to_owned(),
                    nickname: "add".to_owned(),
                    inputs: vec![
                        param("add-a", "A", &["cluster-input-out"]),
                        param("add-b", "B", &["cluster-input-out"]),
                    ],
                    outputs: vec![param("add-r", "R", &[])],
                    ..GhObject::default()
                },
                GhObject {
                    type_guid: CLUSTER_OUTPUT.to_owned(),
                    instance: "cluster-output".to_owned(),
                    nickname: "y".to_owned(),
                    inputs: vec![param("cluster-output-in", "y", &["add-r"])],
                    ..GhObject::default()
                },
            ],
            ..GhDocument::default()
        };
        let cluster = GhObject {
            type_name: "Cluster".to_owned(),
            instance: "cluster".to_owned(),
            nickname: "twice".to_owned(),
            inputs: vec![param("cluster-in", "x", &[])],
            outputs: vec![param("cluster-out", "y", &[])],
            ..GhObject::default()
        };
        let limits = Limits::default();
        let mut m = Mapper::new(&registry, &limits, Graph::default(), Vec::new());
        m.map_cluster(&cluster, object_ref(&cluster, ""), "", 0, &inner);
        m.wire();
        let mut graph = m.finish().graph;
        let node = &graph.nodes[0];
        assert_eq!(
            (node.id.0.as_str(), node.node_type.as_str()),
            ("twice", "graph")
        );
        let Some(SubGraph::Inline(body)) = &node.subgraph else {
            panic!("an inline sub-graph: {node:?}");
        };
        assert_eq!(body.inputs[0].name, "x");
        assert_eq!(body.outputs[0].name, "y");
        let text = graph.to_ron();
        assert!(text.contains("graph: ("), "{text}");
        // It checks and runs once given an input.
        graph.nodes[0]
            .values
            .push(("x".to_owned(), Literal("[1, 2]".to_owned())));
        graph.format = locus_runtime::FORMAT_VERSION;
        graph.outputs.push(GraphOutput {
            name: "y".to_owned(),
            source: PortRef {
                node: NodeId("twice".to_owned()),
                port: "y".to_owned(),
            },
        });
        let checked = check(&graph, &registry).unwrap_or_else(|d| panic!("{d:#?}\n{text}"));
        let mut e = Evaluator::new(checked.plan);
        e.evaluate();
        let y: Vec<Option<Value>> = e
            .output("y")
            .map(|t| t.values().collect())
            .unwrap_or_default();
        assert_eq!(
            y,
            [Some(Value::Number(2.0)), Some(Value::Number(4.0))],
            "{:?}",
            e.messages().collect::<Vec<_>>()
        );
    }

    /// A cluster's `ParamMap` says which Cluster Input feeds from which port, whatever the
    /// document order: here the first port feeds "b", the second "a", and the document
    /// computes a − b.
    #[test]
    fn a_clusters_param_map_pairs_ports_with_boundary_objects() {
        let mut registry = NodeRegistry::new();
        locus_nodes::register(&mut registry);
        let subtraction = registry.get("maths.subtraction").expect("sub").gh_guids[0].clone();
        let boundary = |instance: &str, nickname: &str| GhObject {
            type_guid: CLUSTER_INPUT.to_owned(),
            instance: instance.to_owned(),
            nickname: nickname.to_owned(),
            outputs: vec![param(instance, nickname, &[])],
            ..GhObject::default()
        };
        let inner = GhDocument {
            objects: vec![
                boundary("in-a", "a"),
                boundary("in-b", "b"),
                GhObject {
                    type_guid: subtraction,
                    instance: "sub".to_owned(),
                    nickname: "sub".to_owned(),
                    inputs: vec![
                        param("sub-a", "A", &["in-a"]),
                        param("sub-b", "B", &["in-b"]),
                    ],
                    outputs: vec![param("sub-r", "R", &[])],
                    ..GhObject::default()
                },
                GhObject {
                    type_guid: CLUSTER_OUTPUT.to_owned(),
                    instance: "out".to_owned(),
                    nickname: "d".to_owned(),
                    inputs: vec![param("out", "d", &["sub-r"])],
                    ..GhObject::default()
                },
            ],
            ..GhDocument::default()
        };
        let guid = |name: &str, index: i32, g: &str| crate::archive::Item {
            name: name.to_owned(),
            index: Some(index),
            value: crate::archive::Value::Guid(g.to_owned()),
        };
        let map = Chunk {
            name: "ParamMap".to_owned(),
            items: vec![
                guid("Key", 0, "port-1"),
                guid("Value", 0, "in-b"),
                guid("Key", 1, "port-2"),
                guid("Value", 1, "in-a"),
                guid("Key", 2, "port-out"),
                guid("Value", 2, "out"),
            ],
            ..Chunk::default()
        };
        let mut first = param("port-1", "b", &[]);
        first.persistent = Some(GhTree {
            branches: vec![(vec![0], vec![GhItem::Number(10.0)])],
        });
        let mut second = param("port-2", "a", &[]);
        second.persistent = Some(GhTree {
            branches: vec![(vec![0], vec![GhItem::Number(3.0)])],
        });
        let cluster = GhObject {
            instance: "cluster".to_owned(),
            nickname: "diff".to_owned(),
            inputs: vec![first, second],
            outputs: vec![param("port-out", "d", &[])],
            container: Chunk {
                name: "Container".to_owned(),
                chunks: vec![map],
                ..Chunk::default()
            },
            ..GhObject::default()
        };
        let ins = boundary_objects(&cluster, &cluster.inputs, &inner, CLUSTER_INPUT);
        let names: Vec<&str> = ins.iter().map(|o| o.nickname.as_str()).collect();
        assert_eq!(names, ["b", "a"]);
        // Without the map, document order.
        let mut bare = cluster.clone();
        bare.container = Chunk::default();
        let ins = boundary_objects(&bare, &bare.inputs, &inner, CLUSTER_INPUT);
        let names: Vec<&str> = ins.iter().map(|o| o.nickname.as_str()).collect();
        assert_eq!(names, ["a", "b"]);
        // And the mapped cluster runs as a − b = 3 − 10.
        let limits = Limits::default();
        let mut m = Mapper::new(&registry, &limits, Graph::default(), Vec::new());
        m.map_cluster(&cluster, object_ref(&cluster, ""), "", 0, &inner);
        m.wire();
        let mut graph = m.finish().graph;
        graph.format = locus_runtime::FORMAT_VERSION;
        graph.outputs.push(GraphOutput {
            name: "d".to_owned(),
            source: PortRef {
                node: NodeId("diff".to_owned()),
                port: "d".to_owned(),
            },
        });
        let checked =
            check(&graph, &registry).unwrap_or_else(|d| panic!("{d:#?}\n{}", graph.to_ron()));
        let mut e = Evaluator::new(checked.plan);
        e.evaluate();
        let d: Vec<Option<Value>> = e
            .output("d")
            .map(|t| t.values().collect())
            .unwrap_or_default();
        assert_eq!(d, [Some(Value::Number(-7.0))], "{}", graph.to_ron());
    }

    /// The runxel tutorials' cluster holds a real Cluster Input, which its `ParamMap` names.
    #[test]
    fn a_real_clusters_boundary_is_found_through_its_param_map() {
        let path = concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/tests/data/runxel__attractor_1_point.ghx"
        );
        let bytes = std::fs::read(path).expect("the tutorial");
        let limits = Limits::default();
        let root = crate::archive::read_archive(&bytes, &limits).expect("reads");
        let doc = crate::document::read_document(&root).expect("a document");
        let cluster = doc
            .objects
            .iter()
            .find(|o| o.type_guid == "f31d8d7a-7536-4ac8-9c96-fde6ecda4d0a")
            .expect("a cluster");
        let Some(crate::archive::Value::Bytes(b)) =
            cluster.container.item("ClusterDocument").map(|i| &i.value)
        else {
            panic!("a cluster document");
        };
        let inner = read_cluster(b, &limits, 1).expect("the cluster's document");
        let ins = boundary_objects(cluster, &cluster.inputs, &inner, CLUSTER_INPUT);
        assert_eq!(cluster.inputs.len(), 1);
        let names: Vec<(&str, &str)> = ins
            .iter()
            .map(|o| (o.nickname.as_str(), o.instance.as_str()))
            .collect();
        assert_eq!(names, [("open", "43447478-aa64-4bd1-b4f9-d5c133160376")]);
    }
}

//! Mapping a Grasshopper definition onto a locus [`Graph`] through the registry, by type GUID.
//!
//! Components and parameters become nodes of the type that declares their GUID; ports are
//! matched by index and their names checked. Widgets become parameter nodes with their
//! values, pass-through parameters are joined across, display-only objects are dropped, and
//! everything else (scripts, plugins, Hops calls, components without a node) is reported while
//! the rest of the definition is still mapped. Clusters become sub-graph nodes with an inline
//! graph (their Cluster Input and Output objects its named inputs and outputs, in order).

use std::collections::{HashMap, HashSet};

use locus_runtime::{
    DataType, Graph, GraphInput, GraphNode, GraphOutput, Level, Literal, Modifier, NodeId,
    NodeRegistry, NodeType, PortRef, SUBGRAPH_TYPE, SubGraph, Wire,
};

use crate::document::{GhDocument, GhItem, GhModifier, GhObject, GhParam, GhTree, read_cluster};
use crate::known::{GROUP, Special, special};
use crate::limits::Limits;
use crate::literal;
use crate::report::{ComputeName, ImportDiagnostic, ObjectRef, Outcome, Report};

mod component;
mod gradient;
mod script;
mod special;
mod wiring;

pub(crate) use script::TYPE_HINTS;

use crate::known::{CLUSTER_INPUT, CLUSTER_OUTPUT};

/// A definition mapped onto a graph.
#[derive(Clone, Debug, Default)]
pub struct Import {
    /// The graph (check it with the same registry before running).
    pub graph: Graph,
    /// What became of every object, and the diagnostics.
    pub report: Report,
    /// A comment per node: the Grasshopper object it comes from (for the RON writer).
    pub notes: Vec<(NodeId, String)>,
    /// The names Rhino.Compute gives the graph's inputs, in object order (see [`ComputeName`]).
    pub compute_inputs: Vec<ComputeName>,
    /// The names Rhino.Compute gives the graph's outputs, in object order.
    pub compute_outputs: Vec<ComputeName>,
}

/// Where the data of a Grasshopper output (or floating parameter) comes from in the graph.
#[derive(Clone, Debug)]
enum Source {
    /// An output port of a node.
    Port(PortRef),
    /// A pass-through parameter: the data of its own sources.
    Through(Vec<String>),
    /// An object that does not run: the message for its receivers.
    Missing(String),
}

struct Mapper<'a> {
    registry: &'a NodeRegistry,
    limits: &'a Limits,
    graph: Graph,
    report: Report,
    notes: Vec<(NodeId, String)>,
    ids: HashSet<String>,
    /// Output instance GUID → where its data is.
    sources: HashMap<String, Source>,
    /// Object instance GUID → node (for groups).
    nodes_by_object: HashMap<String, NodeId>,
    /// Node id → index in `graph.nodes`.
    node_pos: HashMap<NodeId, usize>,
    /// Input parameter instance GUID → input port (for groups that name a port).
    input_ports: HashMap<String, PortRef>,
    /// Inputs to wire once every object is known.
    pending: Vec<PendingInput>,
    /// Named inputs and outputs, in the order found.
    inputs: Vec<(String, PortRef)>,
    outputs: Vec<(String, PortRef)>,
    /// Fed panels: their name and sources, for named outputs.
    panels: Vec<(String, Vec<String>)>,
    libraries: Vec<crate::document::Library>,
    /// Rhino.Compute's names: (object index, name, port, canvas y) of inputs and outputs.
    compute_inputs: Vec<(usize, String, PortRef, f64)>,
    compute_outputs: Vec<(usize, String, PortRef, f64)>,
    /// Whether this maps a cluster's document into an inline sub-graph: its node ids are
    /// then its own (the sub-graph node's id scopes them), and `cluster` only names objects
    /// in the report.
    in_cluster: bool,
}

struct PendingInput {
    node: NodeId,
    port: String,
    sources: Vec<String>,
    object: ObjectRef,
}

/// Maps a definition onto a graph.
pub fn import_document(doc: &GhDocument, registry: &NodeRegistry, limits: &Limits) -> Import {
    let graph = Graph {
        format: locus_runtime::FORMAT_VERSION,
        name: doc
            .name
            .trim_end_matches(".ghx")
            .trim_end_matches(".gh")
            .to_owned(),
        description: doc.description.clone(),
        ..Graph::default()
    };
    let mut m = Mapper::new(registry, limits, graph, doc.libraries.clone());
    m.objects(doc, "", 0);
    m.groups(doc);
    m.wire();
    m.finish()
}

fn object_ref(o: &GhObject, cluster: &str) -> ObjectRef {
    ObjectRef {
        type_name: o.type_name.clone(),
        name: o.name.clone(),
        nickname: o.nickname.clone(),
        instance: o.instance.clone(),
        type_guid: o.type_guid.clone(),
        cluster: cluster.to_owned(),
    }
}

/// A node id from a nickname: lower case, runs of anything but letters, digits, `-` and `_`
/// as one `_`.
fn slug(text: &str) -> String {
    let mut out = String::new();
    for c in text.chars() {
        if c.is_alphanumeric() || c == '-' {
            out.extend(c.to_lowercase());
        } else if !out.ends_with('_') {
            out.push('_');
        }
    }
    out.trim_matches('_').to_owned()
}

fn is_script(o: &GhObject) -> bool {
    let c = &o.container;
    ["CodeInput", "ScriptSource", "AdditionalSource"]
        .iter()
        .any(|n| c.item(n).is_some())
        || c.chunk("Script").is_some()
}

impl Mapper<'_> {
    fn diag(
        &mut self,
        severity: Level,
        code: &'static str,
        message: String,
        object: Option<ObjectRef>,
        node: Option<NodeId>,
        port: Option<String>,
    ) {
        self.report.diagnostics.push(ImportDiagnostic {
            severity,
            code,
            message,
            object,
            node,
            port,
        });
    }

    fn unique_id(&mut self, prefix: &str, base: &str) -> NodeId {
        let base = if base.is_empty() { "node" } else { base };
        let mut id = format!("{prefix}{base}");
        let mut k = 2;
        while self.ids.contains(&id) {
            id = format!("{prefix}{base}_{k}");
            k += 1;
        }
        self.ids.insert(id.clone());
        NodeId(id)
    }

    fn objects(&mut self, doc: &GhDocument, cluster: &str, depth: usize) {
        for o in &doc.objects {
            self.object(o, cluster, depth);
        }
    }

    fn mark_missing(&mut self, o: &GhObject, why: &str) {
        for p in &o.outputs {
            self.sources
                .insert(p.instance.clone(), Source::Missing(why.to_owned()));
        }
    }

    fn unsupported(&mut self, o: &GhObject, r: ObjectRef, kind: &'static str, reason: String) {
        let code = match kind {
            "script" => "unsupported-script",
            "plugin" => "unsupported-plugin",
            "cluster" => "unsupported-cluster",
            "hops" => "unsupported-hops",
            _ => "unsupported-component",
        };
        self.diag(
            Level::Error,
            code,
            format!(
                "{r} (name \"{}\", instance {}, type {}) cannot run: {reason}",
                o.name, o.instance, o.type_guid
            ),
            Some(r.clone()),
            None,
            None,
        );
        self.mark_missing(o, &format!("no data from {r}"));
        self.report.objects.push((r, Outcome::Unsupported(kind)));
    }

    fn object(&mut self, o: &GhObject, cluster: &str, depth: usize) {
        let r = object_ref(o, cluster);
        let prefix = if cluster.is_empty() || self.in_cluster {
            String::new()
        } else {
            format!("{cluster}/")
        };
        if let Some(node_type) = self.registry.by_gh_guid(&o.type_guid) {
            let node_type = node_type.clone();
            self.component(o, r, &node_type, &prefix);
            return;
        }
        match special(&o.type_guid) {
            Some(Special::Furniture) => {
                self.report.objects.push((r, Outcome::Ignored));
            }
            Some(Special::Timer) => {
                self.diag(
                    Level::Remark,
                    "ignored-timer",
                    format!(
                        "{r} triggers new solutions on a clock; a headless run solves once: \
                         ignored"
                    ),
                    Some(r.clone()),
                    None,
                    None,
                );
                self.report.objects.push((r, Outcome::Ignored));
            }
            Some(Special::Display) => {
                self.diag(
                    Level::Remark,
                    "dropped-display",
                    format!("{r} only shows data in Grasshopper's viewport or canvas: dropped"),
                    Some(r.clone()),
                    None,
                    None,
                );
                self.mark_missing(o, &format!("no data from {r} (display only, dropped)"));
                self.report.objects.push((r, Outcome::Dropped));
            }
            Some(Special::PassThrough) => self.pass_through(o, r, &prefix),
            Some(
                s @ (Special::Slider
                | Special::Knob
                | Special::MdSlider
                | Special::Panel
                | Special::Toggle
                | Special::Button
                | Special::ValueList),
            ) => self.widget(o, r, s, &prefix),
            Some(Special::HopsGet(node_type)) => match self.registry.get(node_type).cloned() {
                Some(t) => {
                    let name = if o.nickname.is_empty() {
                        o.name.clone()
                    } else {
                        o.nickname.clone()
                    };
                    if let Some(id) = self.component(o, r, &t, &prefix) {
                        let port = PortRef {
                            node: id,
                            port: t.inputs[0].nickname.clone(),
                        };
                        // Compute finds a Hops Get parameter by its nickname.
                        if cluster.is_empty() {
                            self.compute_inputs.push((
                                o.index,
                                o.nickname.clone(),
                                port.clone(),
                                canvas_y(o),
                            ));
                        }
                        self.inputs.push((name, port));
                    }
                }
                None => self.unsupported(
                    o,
                    r,
                    "hops",
                    format!("the node type {node_type} is not in the registry"),
                ),
            },
            Some(Special::HopsPut) => self.hops_put(o, r, cluster, &prefix),
            Some(Special::HopsCall) => self.unsupported(
                o,
                r,
                "hops",
                "Hops calls a remote definition, which a headless run does not do".to_owned(),
            ),
            Some(Special::Cluster) => self.cluster(o, r, cluster, depth),
            None => {
                if is_script(o) {
                    self.unsupported(
                        o,
                        r,
                        "script",
                        "script components (GhPython, C#, VB) do not run in locus".to_owned(),
                    );
                } else if let Some(lib) = &o.library {
                    let plugin = self
                        .libraries
                        .iter()
                        .find(|l| l.id.eq_ignore_ascii_case(lib))
                        .map(|l| {
                            if l.author.is_empty() {
                                format!("plugin {} {}", l.name, l.version)
                            } else {
                                format!("plugin {} {} by {}", l.name, l.version, l.author)
                            }
                        })
                        .unwrap_or_else(|| format!("plugin library {lib}"));
                    self.unsupported(o, r, "plugin", format!("it comes from the {plugin}"));
                } else if o.type_guid == CLUSTER_INPUT || o.type_guid == CLUSTER_OUTPUT {
                    // Boundary of a flattened cluster: handled as a pass-through.
                    self.pass_through(o, r, &prefix);
                } else {
                    self.unsupported(
                        o,
                        r,
                        "component",
                        "no locus node declares this Grasshopper type".to_owned(),
                    );
                }
            }
        }
    }

    fn finish(mut self) -> Import {
        // Values in port order, whichever step set them.
        for node in &mut self.graph.nodes {
            if let Some(t) = self.registry.get(&node.node_type) {
                let ports = t.resolve_inputs(node.input_names.as_deref());
                node.values.sort_by_key(|(name, _)| {
                    ports
                        .iter()
                        .position(|p| p.is_named(name))
                        .unwrap_or(usize::MAX)
                });
            }
        }
        let mut seen = HashSet::new();
        for (name, target) in std::mem::take(&mut self.inputs) {
            let name = unique_name(&mut seen, name);
            self.graph.inputs.push(GraphInput { name, target });
        }
        if self.outputs.is_empty() {
            // No marked outputs: the outputs of the nodes nothing reads.
            let read: HashSet<&NodeId> = self.graph.wires.iter().map(|w| &w.from.node).collect();
            for n in &self.graph.nodes {
                if read.contains(&n.id) || n.node_type.starts_with("params.") {
                    continue;
                }
                if let Some(t) = self.registry.get(&n.node_type) {
                    for p in &t.outputs {
                        self.outputs.push((
                            format!("{}.{}", n.id, p.nickname),
                            PortRef {
                                node: n.id.clone(),
                                port: p.nickname.clone(),
                            },
                        ));
                    }
                }
            }
        }
        let mut seen = HashSet::new();
        for (name, source) in std::mem::take(&mut self.outputs) {
            let name = unique_name(&mut seen, name);
            self.graph.outputs.push(GraphOutput { name, source });
        }
        let compute_inputs = std::mem::take(&mut self.compute_inputs);
        let compute_outputs = std::mem::take(&mut self.compute_outputs);
        let names = |mut list: Vec<(usize, String, PortRef, f64)>, input: bool| {
            list.sort_by_key(|(index, ..)| *index);
            list.into_iter()
                .filter_map(|(_, name, port, canvas_y)| {
                    let graph = if input {
                        let i = self.graph.inputs.iter().find(|i| i.target == port)?;
                        i.name.clone()
                    } else {
                        let o = self.graph.outputs.iter().find(|o| o.source == port)?;
                        o.name.clone()
                    };
                    Some(ComputeName {
                        name,
                        graph,
                        canvas_y,
                    })
                })
                .collect::<Vec<_>>()
        };
        let compute_inputs = names(compute_inputs, true);
        let compute_outputs = names(compute_outputs, false);
        Import {
            graph: self.graph,
            report: self.report,
            notes: self.notes,
            compute_inputs,
            compute_outputs,
        }
    }
}

impl<'a> Mapper<'a> {
    fn new(
        registry: &'a NodeRegistry,
        limits: &'a Limits,
        graph: Graph,
        libraries: Vec<crate::document::Library>,
    ) -> Self {
        Self {
            registry,
            limits,
            graph,
            report: Report::default(),
            notes: Vec::new(),
            ids: HashSet::new(),
            sources: HashMap::new(),
            nodes_by_object: HashMap::new(),
            input_ports: HashMap::new(),
            node_pos: HashMap::new(),
            pending: Vec::new(),
            inputs: Vec::new(),
            outputs: Vec::new(),
            panels: Vec::new(),
            libraries,
            compute_inputs: Vec::new(),
            compute_outputs: Vec::new(),
            in_cluster: false,
        }
    }
}

/// The y position of an object on the canvas (its `Attributes/Pivot`), 0 when absent.
fn canvas_y(o: &GhObject) -> f64 {
    o.container
        .chunk("Attributes")
        .and_then(|a| a.item("Pivot"))
        .and_then(|p| match p.value {
            crate::archive::Value::DrawingPointF([_, y]) => Some(f64::from(y)),
            crate::archive::Value::DrawingPoint([_, y]) => Some(f64::from(y)),
            _ => None,
        })
        .unwrap_or(0.0)
}

fn unique_name(seen: &mut HashSet<String>, name: String) -> String {
    let mut candidate = name.clone();
    let mut k = 2;
    while !seen.insert(candidate.clone()) {
        candidate = format!("{name} ({k})");
        k += 1;
    }
    candidate
}

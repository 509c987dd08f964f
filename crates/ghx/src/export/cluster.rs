//! Sub-graph nodes as Grasshopper clusters.
//!
//! A sub-graph node is written as a cluster object: its inline graph is written as an archive
//! of its own (the chunk `Document`, holding what a file's `Definition` holds), in binary,
//! raw-deflate-compressed and in base64, as the item `ClusterDocument`. Inside, the graph's
//! named inputs and outputs are Cluster Input and Output objects: a Data parameter node that
//! only carries a named input (or output) is that object itself, any other named input or
//! output gets a boundary object of its own, wired to the port it names. The cluster's ports
//! are its graph's named inputs and outputs, in order, and its `ParamMap` pairs each port with
//! its boundary object, as Grasshopper does.

use base64::Engine;
use locus_runtime::{Port, PortRef, SUBGRAPH_TYPE, SubGraph};

use super::*;
use crate::known::{CLUSTER, CLUSTER_INPUT, CLUSTER_OUTPUT};

/// What a cluster object holds beyond a component's ports.
pub(super) struct ClusterParts {
    /// The cluster's document: base64 of its compressed binary archive.
    pub(super) document: String,
    /// (the cluster port's instance GUID, its boundary object's instance GUID), inputs first.
    pub(super) map: Vec<(String, String)>,
    /// The sub-graph node with, on each input it does not set, the value or default of the
    /// inner port that input sets: inside a cluster that port is wired to its Cluster Input,
    /// so the value moves to the cluster's port, where Grasshopper uses it when nothing is
    /// wired.
    pub(super) node: GraphNode,
}

/// One Cluster Input or Output object of a cluster's document.
pub(super) struct Boundary {
    /// The named input or output it stands for.
    pub(super) name: String,
    /// Whether it is a Cluster Input.
    pub(super) input: bool,
    /// Its instance GUID.
    pub(super) instance: String,
    /// The port the named input sets, or the named output reads.
    pub(super) port: PortRef,
    /// The Data parameter node that is this object, if any.
    node: Option<String>,
}

impl Boundary {
    /// The object type written for it.
    pub(super) fn gh_type(&self) -> (&'static str, &'static str) {
        if self.input {
            (CLUSTER_INPUT, "Cluster Input")
        } else {
            (CLUSTER_OUTPUT, "Cluster Output")
        }
    }
}

/// The boundary objects of a graph written as a cluster's document: its named inputs, then its
/// named outputs, in order.
#[derive(Default)]
pub(super) struct Boundaries {
    all: Vec<Boundary>,
}

impl Boundaries {
    /// Those that are no node of the graph, written as objects of their own.
    pub(super) fn extra(&self) -> impl Iterator<Item = &Boundary> {
        self.all.iter().filter(|b| b.node.is_none())
    }

    /// The boundary that node `id` is.
    pub(super) fn of_node(&self, id: &str) -> Option<&Boundary> {
        self.all.iter().find(|b| b.node.as_deref() == Some(id))
    }
}

/// The instance GUID of a boundary object that is no node of the graph.
fn extra_guid(input: bool, name: &str) -> String {
    guid_of(&format!(
        "cluster {}\u{0}{name}",
        if input { "input" } else { "output" }
    ))
}

/// The boundary objects of `graph`'s named inputs and outputs.
pub(super) fn boundaries(graph: &Graph) -> Boundaries {
    let data_node = |id: &str| {
        graph
            .nodes
            .iter()
            .find(|n| n.id.0 == id && n.node_type == "params.data" && n.subgraph.is_none())
    };
    let targeted = |id: &str| {
        graph
            .inputs
            .iter()
            .filter(|i| i.target.node.0 == id)
            .count()
    };
    let read = |id: &str| {
        graph
            .outputs
            .iter()
            .filter(|o| o.source.node.0 == id)
            .count()
    };
    let wired_into = |id: &str| graph.wires.iter().any(|w| w.to.node.0 == id);
    let wired_from = |id: &str| graph.wires.iter().any(|w| w.from.node.0 == id);
    let mut all = Vec::new();
    for i in &graph.inputs {
        let id = i.target.node.0.as_str();
        // A Data parameter that only carries this input is the Cluster Input itself.
        let own = data_node(id).is_some_and(|n| {
            n.values.is_empty() && !wired_into(id) && targeted(id) == 1 && read(id) == 0
        });
        all.push(Boundary {
            name: i.name.clone(),
            input: true,
            instance: if own {
                object_guid(id)
            } else {
                extra_guid(true, &i.name)
            },
            port: i.target.clone(),
            node: own.then(|| id.to_owned()),
        });
    }
    for o in &graph.outputs {
        let id = o.source.node.0.as_str();
        let own =
            data_node(id).is_some_and(|_| !wired_from(id) && read(id) == 1 && targeted(id) == 0);
        all.push(Boundary {
            name: o.name.clone(),
            input: false,
            instance: if own {
                object_guid(id)
            } else {
                extra_guid(false, &o.name)
            },
            port: o.source.clone(),
            node: own.then(|| id.to_owned()),
        });
    }
    Boundaries { all }
}

/// A sub-graph node's cluster: the node type standing for it (its graph's named inputs and
/// outputs as Generic ports) and its document. `depth` is how many clusters the node is in.
pub(super) fn cluster(
    n: &GraphNode,
    registry: &NodeRegistry,
    depth: usize,
    warnings: &mut Vec<ExportWarning>,
) -> Result<(NodeType, ClusterParts), ExportError> {
    let fail = |reason: String| ExportError::Node {
        node: n.id.0.clone(),
        reason,
    };
    let inner = match &n.subgraph {
        Some(SubGraph::Inline(inner)) => inner,
        Some(SubGraph::Path(path)) => {
            return Err(fail(format!(
                "its sub-graph is the file \"{path}\"; read it into the node (`graph:`) before \
                 writing it as a cluster (`locus export-ghx` does)"
            )));
        }
        None => return Err(fail("a sub-graph node without a graph".to_owned())),
    };
    let limit = crate::Limits::default().max_cluster_depth;
    if depth + 1 > limit {
        return Err(fail(format!(
            "sub-graphs nest more than {limit} levels deep, more than a Grasshopper file read \
             back by locus may hold"
        )));
    }
    let mut inner_warnings = Vec::new();
    let text = write_archive(
        inner,
        registry,
        Mode::Cluster,
        depth + 1,
        &mut inner_warnings,
    )
    .map_err(|e| fail(format!("in its sub-graph: {e}")))?;
    warnings.extend(
        inner_warnings
            .into_iter()
            .map(|w| ExportWarning(format!("sub-graph \"{}\": {w}", n.id))),
    );
    let root = crate::xml::read_xml(text.as_bytes(), &crate::Limits::default())
        .map_err(|e| fail(format!("its cluster document does not read back: {e}")))?;
    let mut document = root
        .chunk("Definition")
        .cloned()
        .ok_or_else(|| fail("its cluster document has no definition".to_owned()))?;
    document.name = "Document".to_owned();
    let bytes = crate::binary::write_compressed(&document);
    let name = if inner.name.is_empty() {
        n.id.0.as_str()
    } else {
        inner.name.as_str()
    };
    let mut node_type = NodeType::new(SUBGRAPH_TYPE, name, name, "Sub-graph").gh_guid(CLUSTER);
    for i in &inner.inputs {
        node_type = node_type.input(Port::new(&i.name, &i.name, DataType::Generic));
    }
    for o in &inner.outputs {
        node_type = node_type.output(Port::new(&o.name, &o.name, DataType::Generic));
    }
    let b = boundaries(inner);
    let instance = |input: bool, name: &str| {
        b.all
            .iter()
            .find(|x| x.input == input && x.name == name)
            .map(|x| x.instance.clone())
            .unwrap_or_default()
    };
    let map = inner
        .inputs
        .iter()
        .map(|i| (input_guid(&n.id.0, &i.name), instance(true, &i.name)))
        .chain(
            inner
                .outputs
                .iter()
                .map(|o| (output_guid(&n.id.0, &o.name), instance(false, &o.name))),
        )
        .collect();
    let mut node = n.clone();
    for i in &inner.inputs {
        if node.values.iter().any(|(k, _)| k == &i.name) {
            continue;
        }
        if let Some(value) = inner_value(inner, &i.target, registry) {
            node.values.push((i.name.clone(), value));
        }
    }
    Ok((
        node_type,
        ClusterParts {
            document: base64::engine::general_purpose::STANDARD.encode(bytes),
            map,
            node,
        },
    ))
}

/// The value a port of a graph has when nothing is wired into it: the node's value for it, or
/// the port's default; for a sub-graph node's input, the value of the inner port it sets.
fn inner_value(
    graph: &Graph,
    port: &PortRef,
    registry: &NodeRegistry,
) -> Option<locus_runtime::Literal> {
    inner_value_at(graph, port, registry, 0)
}

fn inner_value_at(
    graph: &Graph,
    port: &PortRef,
    registry: &NodeRegistry,
    depth: usize,
) -> Option<locus_runtime::Literal> {
    let node = graph.nodes.iter().find(|n| n.id == port.node)?;
    if let Some(SubGraph::Inline(inner)) = &node.subgraph {
        if let Some((_, v)) = node.values.iter().find(|(k, _)| k == &port.port) {
            return Some(v.clone());
        }
        let input = inner.inputs.iter().find(|i| i.name == port.port)?;
        if depth >= crate::Limits::default().max_cluster_depth {
            return None;
        }
        return inner_value_at(inner, &input.target, registry, depth + 1);
    }
    let node_type = registry.get(&node.node_type)?;
    let inputs = node_type.resolve_inputs(node.input_names.as_deref());
    let p = inputs.iter().find(|p| p.is_named(&port.port))?;
    node.values
        .iter()
        .find(|(k, _)| p.is_named(k))
        .map(|(_, v)| v.clone())
        .or_else(|| {
            p.default
                .as_ref()
                .and_then(|v| locus_runtime::Literal::from_value(v).ok())
        })
}

/// A cluster's `ParamMap`: each port's instance GUID and its boundary object's.
pub(super) fn write_param_map(o: &mut Out, map: &[(String, String)]) {
    o.chunk_start("ParamMap", None);
    items_and_chunks(
        o,
        |o| {
            o.item("Count", None, 3, &map.len().to_string());
            for (k, (port, boundary)) in map.iter().enumerate() {
                o.item("Key", Some(k), 9, port);
                o.item("Value", Some(k), 9, boundary);
            }
            1 + 2 * map.len()
        },
        |_| 0,
    );
    o.end("chunk");
}

/// A boundary object that is no node of the graph: a Cluster Input (no sources) or a Cluster
/// Output reading `sources`.
pub(super) fn write_boundary(
    o: &mut Out,
    index: usize,
    b: &Boundary,
    sources: &[String],
    pos: (f32, f32),
) {
    let (guid, name) = b.gh_type();
    o.chunk_start("Object", Some(index));
    items_and_chunks(
        o,
        |o| {
            o.item("GUID", None, 9, guid);
            o.item("Name", None, 10, name);
            2
        },
        |o| {
            o.chunk_start("Container", None);
            items_and_chunks(
                o,
                |o| {
                    o.item("InstanceGuid", None, 9, &b.instance);
                    o.item("Name", None, 10, name);
                    o.item("NickName", None, 10, &b.name);
                    for (k, s) in sources.iter().enumerate() {
                        o.item("Source", Some(k), 9, s);
                    }
                    o.item("SourceCount", None, 3, &sources.len().to_string());
                    4 + sources.len()
                },
                |o| {
                    attributes(o, pos);
                    1
                },
            );
            o.end("chunk");
            1
        },
    );
    o.end("chunk");
}

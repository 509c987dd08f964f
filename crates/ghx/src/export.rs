//! Writing a locus graph as a `.ghx` file (the XML form of a GH_IO archive), with quick-xml.
//!
//! Every node becomes an object of the first Grasshopper type GUID its node type declares;
//! `params.*` nodes become floating parameters, other nodes components with `param_input` /
//! `param_output` chunks (or `ParameterData` for variable inputs). Values become persistent
//! data, wires `Source` items, named inputs and outputs `RH_IN:` / `RH_OUT:` groups. Objects
//! are placed on a layered layout: one column per wire depth, one row per node in a column.
//! Sub-graph nodes become clusters (`cluster.rs`), whose documents are written by the same
//! writer.

use std::collections::HashMap;

mod cluster;
mod gradient;
mod object;
mod script;

use locus_runtime::{
    DataType, Graph, GraphNode, Modifier, NodeRegistry, NodeType, Value, parse_literal,
};
use quick_xml::Writer;
use quick_xml::events::{BytesDecl, BytesEnd, BytesStart, BytesText, Event};

/// What an export could not carry over (the file is still written).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ExportWarning(pub String);

impl std::fmt::Display for ExportWarning {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

/// Why a graph cannot be exported at all.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum ExportError {
    /// A node whose type is unknown or has no Grasshopper GUID.
    #[error("node \"{node}\": {reason}")]
    Node {
        /// The node id.
        node: String,
        /// Why.
        reason: String,
    },
}

/// A deterministic GUID from a text (FNV-1a, 128 bits), so that exports are reproducible.
fn guid_of(text: &str) -> String {
    let mut h: u128 = 0x6c62_272e_07bb_0142_62b8_2175_6295_c58d;
    for b in text.bytes() {
        h ^= u128::from(b);
        h = h.wrapping_mul(0x0000_0000_0100_0000_0000_0000_0000_013b);
    }
    let x = format!("{h:032x}");
    format!(
        "{}-{}-{}-{}-{}",
        &x[0..8],
        &x[8..12],
        &x[12..16],
        &x[16..20],
        &x[20..32]
    )
}

/// The nil GUID, as Grasshopper writes an absent reference.
const NIL_GUID: &str = "00000000-0000-0000-0000-000000000000";

struct Out {
    w: Writer<Vec<u8>>,
}

impl Out {
    fn start(&mut self, name: &str, attrs: &[(&str, &str)]) {
        let mut e = BytesStart::new(name);
        for (k, v) in attrs {
            e.push_attribute((*k, *v));
        }
        let _ = self.w.write_event(Event::Start(e));
    }

    fn end(&mut self, name: &str) {
        let _ = self.w.write_event(Event::End(BytesEnd::new(name)));
    }

    fn text_element(&mut self, name: &str, text: &str) {
        self.start(name, &[]);
        let _ = self.w.write_event(Event::Text(xml_text(text)));
        self.end(name);
    }

    fn item_start(&mut self, name: &str, index: Option<usize>, code: u32) {
        let type_name = crate::archive::Value::type_name(code).unwrap_or("gh_string");
        let code = code.to_string();
        let index = index.map(|i| i.to_string());
        let mut attrs = vec![("name", name)];
        if let Some(i) = &index {
            attrs.push(("index", i));
        }
        attrs.push(("type_name", type_name));
        attrs.push(("type_code", &code));
        self.start("item", &attrs);
    }

    fn item(&mut self, name: &str, index: Option<usize>, code: u32, text: &str) {
        self.item_start(name, index, code);
        let _ = self.w.write_event(Event::Text(xml_text(text)));
        self.end("item");
    }

    /// A byte array item (type code 20): its base64 text in a `stream` element, with the
    /// length of the bytes.
    fn bytes_item(&mut self, name: &str, base64: &str) {
        self.item_start(name, None, 20);
        let length = (base64.len() / 4 * 3
            - base64.bytes().rev().take_while(|&b| b == b'=').count())
        .to_string();
        self.start("stream", &[("length", &length)]);
        let _ = self.w.write_event(Event::Text(xml_text(base64)));
        self.end("stream");
        self.end("item");
    }

    fn item_parts(&mut self, name: &str, code: u32, parts: &[(&str, String)]) {
        self.item_start(name, None, code);
        for (k, v) in parts {
            self.text_element(k, v);
        }
        self.end("item");
    }

    fn chunk_start(&mut self, name: &str, index: Option<usize>) {
        let index = index.map(|i| i.to_string());
        match &index {
            Some(i) => self.start("chunk", &[("name", name), ("index", i)]),
            None => self.start("chunk", &[("name", name)]),
        }
    }
}

fn num(x: f64) -> String {
    // .NET reads "R" round-trip numbers; Rust's shortest form is one of them.
    if x.is_nan() {
        "NaN".to_owned()
    } else if x.is_infinite() {
        if x > 0.0 { "Infinity" } else { "-Infinity" }.to_owned()
    } else {
        format!("{x}")
    }
}

/// A section of items, then one of chunks, written by closures (GH_IO writes the counts).
fn items_and_chunks(
    out: &mut Out,
    items: impl FnOnce(&mut Out) -> usize,
    chunks: impl FnOnce(&mut Out) -> usize,
) {
    // Counts are attributes before the content; write into sub-writers to know them first.
    let mut inner = Out {
        w: Writer::new_with_indent(Vec::new(), b' ', 2),
    };
    let n = items(&mut inner);
    let items_xml = inner.w.into_inner();
    let mut inner = Out {
        w: Writer::new_with_indent(Vec::new(), b' ', 2),
    };
    let m = chunks(&mut inner);
    let chunks_xml = inner.w.into_inner();
    let n = n.to_string();
    out.start("items", &[("count", &n)]);
    out.w.get_mut().extend_from_slice(&items_xml);
    out.end("items");
    if m > 0 {
        let m = m.to_string();
        out.start("chunks", &[("count", &m)]);
        out.w.get_mut().extend_from_slice(&chunks_xml);
        out.end("chunks");
    }
}

struct Layout {
    position: HashMap<String, (f32, f32)>,
    /// The x of the rightmost column.
    width: f32,
}

fn layout(graph: &Graph) -> Layout {
    let mut depth: HashMap<&str, usize> =
        graph.nodes.iter().map(|n| (n.id.0.as_str(), 0)).collect();
    // Longest path from a source, by relaxation (graphs are acyclic; bounded passes).
    for _ in 0..graph.nodes.len().min(10_000) {
        let mut changed = false;
        for w in &graph.wires {
            let d = depth.get(w.from.node.0.as_str()).copied().unwrap_or(0) + 1;
            if let Some(t) = depth.get_mut(w.to.node.0.as_str())
                && *t < d
            {
                *t = d;
                changed = true;
            }
        }
        if !changed {
            break;
        }
    }
    let mut rows: HashMap<usize, usize> = HashMap::new();
    let mut position = HashMap::new();
    for n in &graph.nodes {
        let d = depth.get(n.id.0.as_str()).copied().unwrap_or(0);
        let row = rows.entry(d).or_insert(0);
        position.insert(n.id.0.clone(), (d as f32 * 220.0, *row as f32 * 90.0));
        *row += 1;
    }
    let width = rows.keys().max().map_or(0.0, |&d| d as f32 * 220.0);
    Layout { position, width }
}

struct Ports<'a> {
    node: &'a GraphNode,
    node_type: &'a NodeType,
    inputs: Vec<locus_runtime::Port>,
    outputs: Vec<locus_runtime::Port>,
    /// The object type written in place of the node type's (GUID, name): a Data parameter
    /// that is a cluster's boundary is a Cluster Input or Output object.
    gh_type: Option<(&'static str, &'static str)>,
    /// The nickname written in place of the node id (a boundary object's is its name).
    nickname: Option<String>,
    /// A sub-graph node's cluster document and port map.
    cluster: Option<cluster::ClusterParts>,
    /// The parameter types of its inputs and outputs, for `ParameterData`.
    param_ids: (Vec<String>, Vec<String>),
}

/// What an archive is written for: a file, or a cluster's document (whose named inputs and
/// outputs are Cluster Input and Output objects instead of `RH_IN` / `RH_OUT` groups).
#[derive(Clone, Copy, PartialEq, Eq)]
enum Mode {
    File,
    Cluster,
}

fn input_guid(node: &str, port: &str) -> String {
    guid_of(&format!("{node}\u{0}in\u{0}{port}"))
}

fn output_guid(node: &str, port: &str) -> String {
    guid_of(&format!("{node}\u{0}out\u{0}{port}"))
}

fn object_guid(node: &str) -> String {
    guid_of(&format!("{node}\u{0}object"))
}

/// Writes a graph as `.ghx` text; what cannot be carried over is returned as warnings.
/// Sub-graph nodes become clusters; their graphs must be inline (a `path:` sub-graph is read
/// into its node first, as `locus export-ghx` does).
pub fn export_ghx(
    graph: &Graph,
    registry: &NodeRegistry,
) -> Result<(String, Vec<ExportWarning>), ExportError> {
    let mut warnings = Vec::new();
    let text = write_archive(graph, registry, Mode::File, 0, &mut warnings)?;
    Ok((text, warnings))
}

/// Writes a graph's archive as XML text: a file's, or at `depth` > 0 a cluster's.
fn write_archive(
    graph: &Graph,
    registry: &NodeRegistry,
    mode: Mode,
    depth: usize,
    warnings: &mut Vec<ExportWarning>,
) -> Result<String, ExportError> {
    // Sub-graph nodes first: their clusters' documents, and the node types standing for them.
    let mut cluster_types: Vec<Option<NodeType>> = Vec::with_capacity(graph.nodes.len());
    let mut cluster_parts: Vec<Option<cluster::ClusterParts>> = Vec::new();
    for n in &graph.nodes {
        if n.subgraph.is_some() || n.node_type == locus_runtime::SUBGRAPH_TYPE {
            let (t, parts) = cluster::cluster(n, registry, depth, warnings)?;
            cluster_types.push(Some(t));
            cluster_parts.push(Some(parts));
        } else {
            cluster_types.push(None);
            cluster_parts.push(None);
        }
    }
    let boundaries = match mode {
        Mode::File => cluster::Boundaries::default(),
        Mode::Cluster => cluster::boundaries(graph),
    };
    let cluster_nodes: Vec<Option<GraphNode>> = cluster_parts
        .iter_mut()
        .map(|p| p.as_mut().map(|p| std::mem::take(&mut p.node)))
        .collect();
    let mut nodes = Vec::new();
    for (((n, standing), parts), cluster_node) in graph
        .nodes
        .iter()
        .zip(&cluster_types)
        .zip(cluster_parts)
        .zip(&cluster_nodes)
    {
        let n = cluster_node.as_ref().unwrap_or(n);
        let t = match standing {
            Some(t) => t,
            None => registry
                .get(&n.node_type)
                .ok_or_else(|| ExportError::Node {
                    node: n.id.0.clone(),
                    reason: format!("unknown node type {}", n.node_type),
                })?,
        };
        if t.gh_guids.is_empty() {
            return Err(ExportError::Node {
                node: n.id.0.clone(),
                reason: format!("the node type {} has no Grasshopper counterpart", t.id),
            });
        }
        if n.matching != locus_runtime::Matching::Longest {
            warnings.push(ExportWarning(format!(
                "node \"{}\": Grasshopper components always match by longest list; the matching is not written",
                n.id
            )));
        }
        let inputs = t.resolve_inputs(n.input_names.as_deref());
        let outputs = t.resolve_outputs(n.output_names.as_deref());
        if t.id == script::PYTHON {
            warnings.extend(script::warnings(n));
        }
        let boundary = boundaries.of_node(&n.id.0);
        let param_ids = object::param_type_ids(registry, t, &inputs, &outputs);
        nodes.push(Ports {
            param_ids,
            node: n,
            node_type: t,
            inputs,
            outputs,
            gh_type: boundary.map(|b| b.gh_type()),
            nickname: boundary.map(|b| b.name.clone()),
            cluster: parts,
        });
    }
    let port_nick = |p: &Ports<'_>, name: &str, input: bool| -> String {
        let list = if input { &p.inputs } else { &p.outputs };
        list.iter()
            .find(|q| q.is_named(name))
            .map(|q| q.nickname.clone())
            .unwrap_or_else(|| name.to_owned())
    };
    let by_id: HashMap<&str, &Ports<'_>> =
        nodes.iter().map(|p| (p.node.id.0.as_str(), p)).collect();
    // The GUID that a wire from an output names: a floating parameter's object, or a
    // component's output.
    let source_guid = |from: &locus_runtime::PortRef| -> Option<String> {
        let p = by_id.get(from.node.0.as_str())?;
        Some(if is_param(p.node_type) {
            object_guid(&p.node.id.0)
        } else {
            output_guid(&p.node.id.0, &port_nick(p, &from.port, false))
        })
    };
    // Sources per input, in wire order.
    let mut sources: HashMap<(String, String), Vec<String>> = HashMap::new();
    for w in &graph.wires {
        let (Some(to), Some(guid)) = (by_id.get(w.to.node.0.as_str()), source_guid(&w.from)) else {
            continue;
        };
        let to_port = port_nick(to, &w.to.port, true);
        sources
            .entry((w.to.node.0.clone(), to_port))
            .or_default()
            .push(guid);
    }
    // A cluster's boundary objects that are not nodes of its graph: a Cluster Input is a
    // source of the port its input sets, a Cluster Output reads the port its output names.
    let mut extra_boundaries = Vec::new();
    for b in boundaries.extra() {
        let Some(p) = by_id.get(b.port.node.0.as_str()) else {
            continue;
        };
        if b.input {
            let port = port_nick(p, &b.port.port, true);
            sources
                .entry((b.port.node.0.clone(), port))
                .or_default()
                .push(b.instance.clone());
            extra_boundaries.push((b, Vec::new()));
        } else {
            extra_boundaries.push((b, source_guid(&b.port).into_iter().collect()));
        }
    }
    let layout = layout(graph);
    let mut out = Out {
        w: Writer::new_with_indent(Vec::new(), b' ', 2),
    };
    let _ = out.w.write_event(Event::Decl(BytesDecl::new(
        "1.0",
        Some("utf-8"),
        Some("yes"),
    )));
    out.start("Archive", &[("name", "Root")]);
    let _ = out.w.write_event(Event::Comment(BytesText::new(
        "Grasshopper archive written by locus export-ghx",
    )));
    items_and_chunks(
        &mut out,
        |o| {
            o.item_parts(
                "ArchiveVersion",
                80,
                &[
                    ("Major", "0".into()),
                    ("Minor", "2".into()),
                    ("Revision", "2".into()),
                ],
            );
            1
        },
        |o| {
            o.chunk_start("Definition", None);
            items_and_chunks(
                o,
                |o| {
                    o.item_parts(
                        "plugin_version",
                        80,
                        &[
                            ("Major", "1".into()),
                            ("Minor", "0".into()),
                            ("Revision", "7".into()),
                        ],
                    );
                    1
                },
                |o| {
                    o.chunk_start("DocumentHeader", None);
                    items_and_chunks(
                        o,
                        |o| {
                            o.item("DocumentID", None, 9, &guid_of(&graph.name));
                            1
                        },
                        |_| 0,
                    );
                    o.end("chunk");
                    o.chunk_start("DefinitionProperties", None);
                    items_and_chunks(
                        o,
                        |o| {
                            o.item("Description", None, 10, &graph.description);
                            o.item("Name", None, 10, &graph.name);
                            2
                        },
                        |_| 0,
                    );
                    o.end("chunk");
                    o.chunk_start("GHALibraries", None);
                    items_and_chunks(
                        o,
                        |o| {
                            o.item("Count", None, 3, "0");
                            1
                        },
                        |_| 0,
                    );
                    o.end("chunk");
                    o.chunk_start("DefinitionObjects", None);
                    let groups = match mode {
                        Mode::File => groups(graph, &by_id, &port_nick),
                        Mode::Cluster => Vec::new(),
                    };
                    let total = nodes.len() + extra_boundaries.len() + groups.len();
                    items_and_chunks(
                        o,
                        |o| {
                            o.item("ObjectCount", None, 3, &total.to_string());
                            1
                        },
                        |o| {
                            for (k, p) in nodes.iter().enumerate() {
                                let pos = layout
                                    .position
                                    .get(&p.node.id.0)
                                    .copied()
                                    .unwrap_or_default();
                                object::write_object(o, k, p, &sources, pos, warnings);
                            }
                            let mut k = nodes.len();
                            for (row, (b, srcs)) in extra_boundaries.iter().enumerate() {
                                let x = if b.input {
                                    -220.0
                                } else {
                                    layout.width + 220.0
                                };
                                cluster::write_boundary(o, k, b, srcs, (x, row as f32 * 90.0));
                                k += 1;
                            }
                            for (nick, ids) in &groups {
                                write_group(o, k, nick, ids);
                                k += 1;
                            }
                            total
                        },
                    );
                    o.end("chunk");
                    4
                },
            );
            o.end("chunk");
            1
        },
    );
    out.end("Archive");
    Ok(String::from_utf8(out.w.into_inner()).unwrap_or_default())
}

fn is_param(t: &NodeType) -> bool {
    // Point On Curve is a parameter in Grasshopper (its curves come in on its own wires).
    (t.id.starts_with("params.") || t.id == POINT_ON_CURVE)
        && t.inputs.len() == 1
        && t.outputs.len() == 1
}

/// The Point On Curve node, written as the parameter-shaped object it is in Grasshopper, with
/// its position in the item `parameter`.
const POINT_ON_CURVE: &str = "curve.point_on_curve";

/// `RH_IN:` and `RH_OUT:` groups: their nickname and the GUIDs they hold (a floating
/// parameter's object, or a component's port).
fn groups(
    graph: &Graph,
    by_id: &HashMap<&str, &Ports<'_>>,
    port_nick: &dyn Fn(&Ports<'_>, &str, bool) -> String,
) -> Vec<(String, Vec<String>)> {
    let mut groups = Vec::new();
    for i in &graph.inputs {
        if let Some(p) = by_id.get(i.target.node.0.as_str()) {
            let port = port_nick(p, &i.target.port, true);
            let id = if is_param(p.node_type) {
                object_guid(&p.node.id.0)
            } else {
                input_guid(&p.node.id.0, &port)
            };
            groups.push((format!("RH_IN:{}", i.name), vec![id]));
        }
    }
    for o in &graph.outputs {
        if let Some(p) = by_id.get(o.source.node.0.as_str()) {
            let port = port_nick(p, &o.source.port, false);
            let id = if is_param(p.node_type) {
                object_guid(&p.node.id.0)
            } else {
                output_guid(&p.node.id.0, &port)
            };
            groups.push((format!("RH_OUT:{}", o.name), vec![id]));
        }
    }
    groups
}

fn write_group(o: &mut Out, index: usize, nick: &str, ids: &[String]) {
    o.chunk_start("Object", Some(index));
    items_and_chunks(
        o,
        |o| {
            o.item("GUID", None, 9, crate::known::GROUP);
            o.item("Name", None, 10, "Group");
            2
        },
        |o| {
            o.chunk_start("Container", None);
            items_and_chunks(
                o,
                |o| {
                    for (k, id) in ids.iter().enumerate() {
                        o.item("ID", Some(k), 9, id);
                    }
                    o.item("ID_Count", None, 3, &ids.len().to_string());
                    o.item(
                        "InstanceGuid",
                        None,
                        9,
                        &guid_of(&format!("group\u{0}{nick}")),
                    );
                    o.item("Name", None, 10, "Group");
                    o.item("NickName", None, 10, nick);
                    ids.len() + 4
                },
                |_| 0,
            );
            o.end("chunk");
            1
        },
    );
    o.end("chunk");
}

fn attributes(o: &mut Out, (x, y): (f32, f32)) {
    o.chunk_start("Attributes", None);
    items_and_chunks(
        o,
        |o| {
            o.item_parts(
                "Bounds",
                35,
                &[
                    ("X", num(f64::from(x))),
                    ("Y", num(f64::from(y))),
                    ("W", "120".into()),
                    ("H", "60".into()),
                ],
            );
            o.item_parts(
                "Pivot",
                31,
                &[("X", num(f64::from(x))), ("Y", num(f64::from(y)))],
            );
            2
        },
        |_| 0,
    );
    o.end("chunk");
}

/// Text content escaped for XML, with carriage returns as character references: a reader
/// normalises a literal `\r\n` to `\n` (XML 1.0 §2.11), which would change a script's code.
fn xml_text(text: &str) -> BytesText<'static> {
    let escaped = quick_xml::escape::escape(text).replace('\r', "&#xD;");
    BytesText::from_escaped(escaped)
}

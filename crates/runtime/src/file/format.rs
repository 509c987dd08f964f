//! Graph files: reading a [`Graph`] from RON text and writing it back in canonical layout.
//!
//! The layout is documented in `docs/graph-format.md`. Reading keeps the position of every
//! id, port name and value (a [`Document`]) so that checking can point into the file.
//! Writing is canonical: fixed field order, defaults left out, one node per line when it fits
//! in 100 columns and one field per line otherwise, one wire, named input, named output and
//! expected value per line. Reading a canonical file and writing it again gives the same bytes.

use std::ops::Range;
use std::path::{Path, PathBuf};
use std::sync::Arc;

use crate::checking::diagnostic::{Diagnostic, DiagnosticKind, Location};
use crate::file::syntax::{self, Field, Kind, LineIndex, Node};
pub(crate) use crate::file::write::expected_messages_node;
use crate::file::write::expected_node;
pub use crate::file::write::write_graph;
use crate::{
    ExpectedMessage, FORMAT_VERSION, Graph, GraphInput, GraphNode, GraphOutput, Level, Literal,
    Matching, Modifier, NodeId, PortRef, SUBGRAPH_TYPE, SubGraph, Wire,
};

const GRAPH_FIELDS: &[&str] = &[
    "format",
    "name",
    "description",
    "nodes",
    "wires",
    "inputs",
    "outputs",
    "expected",
    "expected_messages",
];

const EXPECTED_MESSAGE_FIELDS: &[&str] = &["node", "level", "text"];

const NODE_FIELDS: &[&str] = &[
    "id",
    "type",
    "inputs",
    "outputs",
    "values",
    "settings",
    "modifiers",
    "output_modifiers",
    "matching",
    "disabled",
    "path",
    "graph",
];

/// A graph read from text, with the text and the position of everything in it.
#[derive(Clone, Debug)]
pub struct Document {
    graph: Graph,
    /// The whole text read (shared with the documents of inline sub-graphs).
    source: Arc<str>,
    lines: Arc<LineIndex>,
    pub(crate) map: SourceMap,
    /// The file the text was read from, which sub-graph paths are relative to.
    origin: Option<PathBuf>,
}

/// Byte spans of the parts of a graph file, parallel to the vectors of [`Graph`].
#[derive(Clone, Debug, Default)]
pub(crate) struct SourceMap {
    /// Per node.
    pub nodes: Vec<NodeSpans>,
    /// Per wire: the source and target strings.
    pub wires: Vec<[Range<usize>; 2]>,
    /// Per named input: the name and the target.
    pub inputs: Vec<[Range<usize>; 2]>,
    /// Per named output: the name and the source.
    pub outputs: Vec<[Range<usize>; 2]>,
    /// Per expected value: the output name and the value.
    pub expected: Vec<[Range<usize>; 2]>,
    /// The whole `expected: {…}` field, when present.
    pub expected_field: Option<Range<usize>>,
    /// The `{…}` value of the `expected` field, when present.
    pub expected_value: Option<Range<usize>>,
    /// Per expected message: the node id string.
    pub expected_messages: Vec<Range<usize>>,
    /// The `[…]` value of the `expected_messages` field, when present.
    pub expected_messages_value: Option<Range<usize>>,
    /// The offset of the `)` that closes the graph.
    pub graph_end: usize,
}

/// Byte spans of the parts of one node.
#[derive(Clone, Debug, Default)]
pub(crate) struct NodeSpans {
    /// The id string (the whole node when the id is missing).
    pub id: Range<usize>,
    /// The type string.
    pub node_type: Range<usize>,
    /// The variable input names.
    pub input_names: Vec<Range<usize>>,
    /// The variable output names.
    pub output_names: Vec<Range<usize>>,
    /// Per value: the port name and the value.
    pub values: Vec<[Range<usize>; 2]>,
    /// Per setting: the name and the value.
    pub settings: Vec<[Range<usize>; 2]>,
    /// Per modified port: the port name and each modifier.
    pub modifiers: Vec<(Range<usize>, Vec<Range<usize>>)>,
    /// Per modified output: the port name and each modifier.
    pub output_modifiers: Vec<(Range<usize>, Vec<Range<usize>>)>,
    /// The `path` or `graph` value of a sub-graph node.
    pub body: Option<Range<usize>>,
    /// The spans of an inline sub-graph.
    pub subgraph: Option<Box<SourceMap>>,
}

impl Document {
    /// Reads a graph file.
    ///
    /// # Errors
    /// Every problem found: a RON syntax error (only the first, with its position), an
    /// unsupported format version, or all the places where the RON is not a graph (unknown or
    /// missing fields, values of the wrong kind).
    pub fn parse(text: &str) -> Result<Self, Vec<Diagnostic>> {
        let mut reader = Reader {
            text,
            lines: LineIndex::new(text),
            errors: Vec::new(),
        };
        let root = match syntax::parse(text) {
            Ok(root) => root,
            Err(e) => {
                let d = reader.diagnostic(
                    DiagnosticKind::Syntax { message: e.message },
                    e.offset..e.offset,
                );
                return Err(vec![d]);
            }
        };
        let mut map = SourceMap::default();
        let graph = reader.graph(&root, &mut map);
        match graph {
            Some(graph) if reader.errors.is_empty() => Ok(Self {
                graph,
                source: Arc::from(text),
                lines: Arc::new(reader.lines),
                map,
                origin: None,
            }),
            _ => Err(reader.errors),
        }
    }

    /// The document with the file it was read from, which the `path` of its sub-graph nodes
    /// are relative to (a document without one cannot use `path`).
    #[must_use]
    pub fn with_origin(mut self, path: impl Into<PathBuf>) -> Self {
        self.origin = Some(path.into());
        self
    }

    /// The file the document was read from, when known.
    pub fn origin(&self) -> Option<&Path> {
        self.origin.as_deref()
    }

    /// The document of the inline sub-graph of node `i`, sharing this one's text (so that its
    /// diagnostics point into the same file).
    pub(crate) fn inline_subgraph(&self, i: usize) -> Option<Self> {
        let Some(SubGraph::Inline(graph)) = &self.graph.nodes.get(i)?.subgraph else {
            return None;
        };
        let map = self.map.nodes.get(i)?.subgraph.as_deref()?.clone();
        Some(Self {
            graph: (**graph).clone(),
            source: Arc::clone(&self.source),
            lines: Arc::clone(&self.lines),
            map,
            origin: self.origin.clone(),
        })
    }

    /// The graph.
    pub fn graph(&self) -> &Graph {
        &self.graph
    }

    /// The graph, consuming the document.
    pub fn into_graph(self) -> Graph {
        self.graph
    }

    /// The text the graph was read from.
    pub fn source(&self) -> &str {
        &self.source
    }

    /// The location of a byte offset in the source.
    pub(crate) fn location(&self, offset: usize) -> Location {
        location(&self.lines, &self.source, offset)
    }

    /// The source text with the `expected` section replaced by `expected` (added before the
    /// end of the graph when absent, removed when `expected` is empty), keeping everything
    /// else byte for byte, comments included. `locus test --bless` writes files this way.
    pub fn with_expected(&self, expected: &[(String, Literal)]) -> String {
        let mut section = String::new();
        if !expected.is_empty() {
            section.push_str("expected: ");
            syntax::write_broken(&expected_node(expected), 4, &mut section);
        }
        let src = &self.source;
        match &self.map.expected_field {
            Some(span) => {
                let mut end = span.end;
                if section.is_empty() {
                    // Remove the field with its comma and the rest of its line.
                    let rest = &src[end..];
                    let trimmed = rest.trim_start_matches([' ', '\t']);
                    end += rest.len() - trimmed.len();
                    if trimmed.starts_with(',') {
                        end += 1;
                    }
                    let start = src[..span.start].trim_end_matches([' ', '\t']).len();
                    let rest = &src[end..];
                    let line_end = rest.find('\n').map_or(rest.len(), |i| i + 1);
                    if rest[..line_end].trim().is_empty() {
                        end += line_end;
                    }
                    return format!("{}{}", &src[..start], &src[end..]);
                }
                format!("{}{}{}", &src[..span.start], section, &src[end..])
            }
            None if section.is_empty() => src.to_string(),
            None => {
                let end = self.map.graph_end.min(src.len());
                let before = src[..end].trim_end();
                let comma = if before.ends_with(',') || before.ends_with('(') {
                    ""
                } else {
                    ","
                };
                format!("{before}{comma}\n    {section},\n{}", &src[end..])
            }
        }
    }
}

impl Graph {
    /// Reads a graph from RON text (see [`Document::parse`] to keep positions for checking).
    ///
    /// # Errors
    /// See [`Document::parse`].
    pub fn from_ron(text: &str) -> Result<Self, Vec<Diagnostic>> {
        Document::parse(text).map(Document::into_graph)
    }

    /// The graph as canonical RON text, ending with a newline.
    ///
    /// Literal values that are not valid RON are written as they are (the file then fails to
    /// load, pointing at them). The format version written is always [`FORMAT_VERSION`].
    pub fn to_ron(&self) -> String {
        write_graph(self)
    }
}

/// The 1-based line and column of a byte offset.
fn location(lines: &LineIndex, text: &str, offset: usize) -> Location {
    let (line, column) = lines.line_column(text, offset);
    Location {
        line,
        column,
        offset,
    }
}

struct Reader<'a> {
    text: &'a str,
    lines: LineIndex,
    errors: Vec<Diagnostic>,
}

impl Reader<'_> {
    fn diagnostic(&self, kind: DiagnosticKind, span: Range<usize>) -> Diagnostic {
        let mut d = Diagnostic::error(kind);
        d.location = Some(location(&self.lines, self.text, span.start));
        d
    }

    fn malformed(&mut self, span: Range<usize>, message: String) {
        let d = self.diagnostic(DiagnosticKind::Malformed { message }, span);
        self.errors.push(d);
    }

    fn expect_kind(&mut self, node: &Node, what: &str, context: &str) {
        self.malformed(
            node.span.clone(),
            format!("expected {what} for {context}, found {}", node.describe()),
        );
    }

    /// The fields of a struct, after reporting unknown and duplicate ones.
    fn fields<'n>(
        &mut self,
        node: &'n Node,
        names: &[&str],
        struct_name: &str,
        context: &str,
    ) -> Option<&'n [Field]> {
        let fields = match &node.kind {
            Kind::Struct(None, fields) => fields.as_slice(),
            Kind::Struct(Some(n), fields) if n == struct_name => fields.as_slice(),
            Kind::Tuple(None, v) if v.is_empty() => &[],
            _ => {
                self.expect_kind(node, "a struct `(field: value, …)`", context);
                return None;
            }
        };
        for (i, f) in fields.iter().enumerate() {
            if !names.contains(&f.name.as_str()) {
                self.malformed(
                    f.name_span.clone(),
                    format!(
                        "unknown field `{}` in {context} (fields: {})",
                        f.name,
                        names.join(", ")
                    ),
                );
            } else if fields[..i].iter().any(|g| g.name == f.name) {
                self.malformed(
                    f.name_span.clone(),
                    format!("duplicate field `{}` in {context}", f.name),
                );
            }
        }
        Some(fields)
    }

    fn string(&mut self, node: &Node, context: &str) -> Option<String> {
        match &node.kind {
            Kind::Str(s) => Some(s.clone()),
            _ => {
                self.expect_kind(node, "a string in quotes", context);
                None
            }
        }
    }

    fn graph(&mut self, root: &Node, map: &mut SourceMap) -> Option<Graph> {
        map.graph_end = root.span.end.saturating_sub(1);
        let fields = self.fields(root, GRAPH_FIELDS, "Graph", "the graph")?;
        let field = |name: &str| fields.iter().find(|f| f.name == name);
        // The version decides how the rest is read, so a wrong one stops here.
        let Some(format) = field("format") else {
            self.malformed(
                root.span.start..root.span.start,
                format!("missing field `format` in the graph (this build writes format {FORMAT_VERSION})"),
            );
            return None;
        };
        let version = match &format.value.kind {
            Kind::Number(n) => n.parse::<u32>().ok(),
            _ => None,
        };
        if version != Some(FORMAT_VERSION) {
            let d = self.diagnostic(
                DiagnosticKind::UnsupportedVersion {
                    found: format.value.describe(),
                },
                format.value.span.clone(),
            );
            self.errors = vec![d];
            return None;
        }
        let mut graph = Graph {
            format: FORMAT_VERSION,
            ..Graph::default()
        };
        for f in fields {
            let v = &f.value;
            match f.name.as_str() {
                "name" => graph.name = self.string(v, "`name`").unwrap_or_default(),
                "description" => {
                    graph.description = self.string(v, "`description`").unwrap_or_default();
                }
                "nodes" => {
                    for item in self.list(v, "`nodes`") {
                        let (node, spans) = self.node(item);
                        graph.nodes.push(node);
                        map.nodes.push(spans);
                    }
                }
                "wires" => {
                    for item in self.list(v, "`wires`") {
                        if let Some((wire, spans)) = self.wire(item) {
                            graph.wires.push(wire);
                            map.wires.push(spans);
                        }
                    }
                }
                "inputs" => {
                    for (key, value) in self.map(v, "named `inputs`") {
                        let name = self.string(key, "a named input").unwrap_or_default();
                        let context = format!("named input \"{name}\"");
                        if let Some(target) = self.port_ref(value, &context) {
                            graph.inputs.push(GraphInput { name, target });
                            map.inputs.push([key.span.clone(), value.span.clone()]);
                        }
                    }
                }
                "outputs" => {
                    for (key, value) in self.map(v, "named `outputs`") {
                        let name = self.string(key, "a named output").unwrap_or_default();
                        let context = format!("named output \"{name}\"");
                        if let Some(source) = self.port_ref(value, &context) {
                            graph.outputs.push(GraphOutput { name, source });
                            map.outputs.push([key.span.clone(), value.span.clone()]);
                        }
                    }
                }
                "expected" => {
                    map.expected_field = Some(f.name_span.start..v.span.end);
                    map.expected_value = Some(v.span.clone());
                    for (key, value) in self.map(v, "`expected`") {
                        let name = self.string(key, "an expected output").unwrap_or_default();
                        graph.expected.push((name, Literal(value.to_compact())));
                        map.expected.push([key.span.clone(), value.span.clone()]);
                    }
                }
                "expected_messages" => {
                    map.expected_messages_value = Some(v.span.clone());
                    for item in self.list(v, "`expected_messages`") {
                        if let Some((message, span)) = self.expected_message(item) {
                            graph.expected_messages.push(message);
                            map.expected_messages.push(span);
                        }
                    }
                }
                _ => {}
            }
        }
        Some(graph)
    }

    fn list<'n>(&mut self, node: &'n Node, context: &str) -> &'n [Node] {
        match &node.kind {
            Kind::List(items) => items,
            _ => {
                self.expect_kind(node, "a list `[…]`", context);
                &[]
            }
        }
    }

    fn map<'n>(&mut self, node: &'n Node, context: &str) -> &'n [(Node, Node)] {
        match &node.kind {
            Kind::Map(entries) => entries,
            _ => {
                self.expect_kind(node, "a map `{…}`", context);
                &[]
            }
        }
    }

    fn node(&mut self, item: &Node) -> (GraphNode, NodeSpans) {
        let mut node = GraphNode::default();
        let mut spans = NodeSpans {
            id: item.span.clone(),
            node_type: item.span.clone(),
            ..NodeSpans::default()
        };
        let Some(fields) = self.fields(item, NODE_FIELDS, "Node", "a node") else {
            return (node, spans);
        };
        let id = fields.iter().find(|f| f.name == "id");
        let context = match id.map(|f| &f.value.kind) {
            Some(Kind::Str(id)) => format!("node \"{id}\""),
            _ => "a node".to_owned(),
        };
        for missing in ["id", "type"] {
            if !fields.iter().any(|f| f.name == missing) {
                self.malformed(
                    item.span.start..item.span.start,
                    format!("missing field `{missing}` in {context}"),
                );
            }
        }
        for f in fields {
            let v = &f.value;
            match f.name.as_str() {
                "id" => {
                    node.id = NodeId(self.string(v, "`id`").unwrap_or_default());
                    spans.id = v.span.clone();
                }
                "type" => {
                    node.node_type = self.string(v, "`type`").unwrap_or_default();
                    spans.node_type = v.span.clone();
                }
                "inputs" => {
                    let mut names = Vec::new();
                    for name in self.list(v, &format!("`inputs` of {context}")) {
                        if let Some(s) = self.string(name, "an input name") {
                            names.push(s);
                            spans.input_names.push(name.span.clone());
                        }
                    }
                    node.input_names = Some(names);
                }
                "outputs" => {
                    let mut names = Vec::new();
                    for name in self.list(v, &format!("`outputs` of {context}")) {
                        if let Some(s) = self.string(name, "an output name") {
                            names.push(s);
                            spans.output_names.push(name.span.clone());
                        }
                    }
                    node.output_names = Some(names);
                }
                "values" | "settings" => {
                    let what = if f.name == "values" {
                        "an input name"
                    } else {
                        "a setting name"
                    };
                    let mut entries = Vec::new();
                    let mut entry_spans = Vec::new();
                    for (key, value) in self.map(v, &format!("`{}` of {context}", f.name)) {
                        if let Some(name) = self.string(key, what) {
                            entries.push((name, Literal(value.to_compact())));
                            entry_spans.push([key.span.clone(), value.span.clone()]);
                        }
                    }
                    if f.name == "values" {
                        node.values = entries;
                        spans.values = entry_spans;
                    } else {
                        node.settings = entries;
                        spans.settings = entry_spans;
                    }
                }
                "modifiers" | "output_modifiers" => {
                    let inputs = f.name == "modifiers";
                    let (what, list, list_spans) = if inputs {
                        ("an input name", &mut node.modifiers, &mut spans.modifiers)
                    } else {
                        (
                            "an output name",
                            &mut node.output_modifiers,
                            &mut spans.output_modifiers,
                        )
                    };
                    for (key, value) in self.map(v, &format!("`{}` of {context}", f.name)) {
                        let Some(port) = self.string(key, what) else {
                            continue;
                        };
                        let (modifiers, modifier_spans) = self.modifiers(value);
                        list.push((port, modifiers));
                        list_spans.push((key.span.clone(), modifier_spans));
                    }
                }
                "matching" => {
                    node.matching = match &v.kind {
                        Kind::Ident(m) if m == "longest" => Matching::Longest,
                        Kind::Ident(m) if m == "shortest" => Matching::Shortest,
                        Kind::Ident(m) if m == "cross" => Matching::Cross,
                        _ => {
                            self.expect_kind(v, "longest, shortest or cross", "`matching`");
                            Matching::Longest
                        }
                    }
                }
                "disabled" => match v.kind {
                    Kind::Bool(b) => node.disabled = b,
                    _ => self.expect_kind(v, "true or false", "`disabled`"),
                },
                "path" => {
                    let path = self.string(v, &format!("`path` of {context}"));
                    node.subgraph = path.map(SubGraph::Path);
                    spans.body = Some(v.span.clone());
                }
                "graph" => {
                    let mut map = SourceMap::default();
                    if let Some(graph) = self.graph(v, &mut map) {
                        node.subgraph = Some(SubGraph::Inline(Box::new(graph)));
                        spans.subgraph = Some(Box::new(map));
                    }
                    spans.body = Some(v.span.clone());
                }
                _ => {}
            }
        }
        self.subgraph_fields(&node, fields, &context, item.span.start);
        (node, spans)
    }

    /// A sub-graph node has one of `path` and `graph`, and other nodes neither.
    fn subgraph_fields(&mut self, node: &GraphNode, fields: &[Field], context: &str, at: usize) {
        let body: Vec<&Field> = fields
            .iter()
            .filter(|f| f.name == "path" || f.name == "graph")
            .collect();
        let is_subgraph = node.node_type == SUBGRAPH_TYPE;
        match body.as_slice() {
            [] if is_subgraph => self.malformed(
                at..at,
                format!("{context} of type \"{SUBGRAPH_TYPE}\" needs `path` or `graph`"),
            ),
            [_, second, ..] if is_subgraph => self.malformed(
                second.name_span.clone(),
                format!("{context} has both `path` and `graph`; give one"),
            ),
            [first, ..] if !is_subgraph => self.malformed(
                first.name_span.clone(),
                format!(
                    "`{}` is only for sub-graph nodes (type \"{SUBGRAPH_TYPE}\"), not {context}",
                    first.name
                ),
            ),
            _ => {}
        }
    }

    /// One entry of `expected_messages`: `(node: "d", level: error, text: "by zero")`.
    fn expected_message(&mut self, item: &Node) -> Option<(ExpectedMessage, Range<usize>)> {
        let context = "an expected message";
        let fields = self.fields(item, EXPECTED_MESSAGE_FIELDS, "Message", context)?;
        let mut ok = true;
        for missing in EXPECTED_MESSAGE_FIELDS {
            if !fields.iter().any(|f| f.name == *missing) {
                self.malformed(
                    item.span.start..item.span.start,
                    format!("missing field `{missing}` in {context}"),
                );
                ok = false;
            }
        }
        let mut message = ExpectedMessage {
            node: NodeId::default(),
            level: Level::Error,
            text: String::new(),
        };
        let mut node_span = item.span.clone();
        for f in fields {
            let v = &f.value;
            match f.name.as_str() {
                "node" => match self.string(v, "`node` of an expected message") {
                    Some(id) => {
                        message.node = NodeId(id);
                        node_span = v.span.clone();
                    }
                    None => ok = false,
                },
                "level" => match &v.kind {
                    Kind::Ident(l) if l == "error" => message.level = Level::Error,
                    Kind::Ident(l) if l == "warning" => message.level = Level::Warning,
                    Kind::Ident(l) if l == "remark" => message.level = Level::Remark,
                    _ => {
                        self.expect_kind(v, "error, warning or remark", "`level`");
                        ok = false;
                    }
                },
                "text" => match self.string(v, "`text` of an expected message") {
                    Some(t) => message.text = t,
                    None => ok = false,
                },
                _ => {}
            }
        }
        ok.then_some((message, node_span))
    }

    fn modifiers(&mut self, value: &Node) -> (Vec<Modifier>, Vec<Range<usize>>) {
        let mut list = Vec::new();
        let mut spans = Vec::new();
        for m in self.list(value, "modifiers") {
            let parsed = match &m.kind {
                Kind::Ident(name) => Modifier::from_name(name),
                _ => None,
            };
            match parsed {
                Some(modifier) if list.contains(&modifier) => self.malformed(
                    m.span.clone(),
                    format!("duplicate modifier {}", modifier.name()),
                ),
                Some(modifier) => {
                    list.push(modifier);
                    spans.push(m.span.clone());
                }
                None => {
                    let names: Vec<&str> = Modifier::ALL.iter().map(|m| m.name()).collect();
                    self.malformed(
                        m.span.clone(),
                        format!(
                            "unknown modifier {} (modifiers: {})",
                            m.describe(),
                            names.join(", ")
                        ),
                    );
                }
            }
        }
        (list, spans)
    }

    fn wire(&mut self, item: &Node) -> Option<(Wire, [Range<usize>; 2])> {
        match &item.kind {
            Kind::Tuple(None, ends) if ends.len() == 2 => {
                let from = self.port_ref(&ends[0], "a wire");
                let to = self.port_ref(&ends[1], "a wire");
                Some((
                    Wire {
                        from: from?,
                        to: to?,
                    },
                    [ends[0].span.clone(), ends[1].span.clone()],
                ))
            }
            _ => {
                self.expect_kind(item, "a wire (\"node.port\", \"node.port\")", "`wires`");
                None
            }
        }
    }

    fn port_ref(&mut self, node: &Node, context: &str) -> Option<PortRef> {
        let text = self.string(node, context)?;
        match text.split_once('.') {
            Some((n, p)) if !n.is_empty() && !p.is_empty() => Some(PortRef {
                node: NodeId(n.to_owned()),
                port: p.to_owned(),
            }),
            _ => {
                let d = self.diagnostic(
                    DiagnosticKind::BadPortRef {
                        context: context.to_owned(),
                        text,
                    },
                    node.span.clone(),
                );
                self.errors.push(d);
                None
            }
        }
    }
}

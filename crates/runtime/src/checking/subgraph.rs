//! Sub-graphs: nodes of type [`SUBGRAPH_TYPE`] that run another graph, read from a file
//! (`path:`) or written inline (`graph: (…)`).
//!
//! Checking a graph first checks the graph of each of its sub-graph nodes (recursively, up to
//! [`MAX_SUBGRAPH_DEPTH`] levels and [`MAX_SUBGRAPH_NODES`] nodes in all), reporting the
//! sub-graph's diagnostics with nested ids (`c/inner`) and, for a file, that file's name. The
//! named inputs and outputs of a sub-graph become the ports of a node type that stands for it,
//! so that the including graph is checked like any other. The plan is then *spliced*: the
//! sub-graph node is replaced by the sub-graph's own plan nodes, with nested ids, the wires
//! into its inputs going to the inner ports its named inputs set, and the wires from its
//! outputs coming from the inner outputs its named outputs read. A sub-graph's inputs thus
//! receive whole trees, as a Grasshopper cluster's do, and the evaluator sees one flat plan:
//! evaluation is incremental through the nesting (changing an outer input runs only the inner
//! nodes that depend on it), the run limits apply to every inner node, and inner nodes'
//! messages carry their nested ids.

use std::collections::HashMap;
use std::path::PathBuf;

use crate::checking::check::{Checked, Checker};
use crate::checking::diagnostic::{Diagnostic, DiagnosticKind, Location};
use crate::file::format::Document;
use crate::{
    Graph, MAX_GRAPH_FILE_BYTES, NodeRegistry, NodeType, Plan, PlanNode, SUBGRAPH_TYPE, SubGraph,
    read_graph_file,
};

/// How deeply sub-graphs may nest: a graph with a sub-graph with a sub-graph is two levels
/// deep. Deeper nesting is an error (it is almost always a mistake, and it bounds recursion).
pub const MAX_SUBGRAPH_DEPTH: usize = 32;

/// How many nodes the sub-graphs of one graph may have in all, counted as they are expanded
/// (a file included twice counts twice), so that files including each other several times
/// cannot make an exponentially large graph.
pub const MAX_SUBGRAPH_NODES: usize = 1_000_000;

/// What checking knows about the nesting it is in.
#[derive(Default)]
pub(crate) struct Nesting {
    /// How many sub-graph levels are being checked.
    depth: usize,
    /// The files of the graphs being checked, outermost first: (canonical path, path shown).
    files: Vec<(PathBuf, String)>,
    /// The sub-graph nodes expanded so far.
    nodes: usize,
}

/// A sub-graph that checked: its plan and the node type that stands for it outside.
struct Inner {
    plan: Plan,
    node_type: NodeType,
}

/// A sub-graph's graph and document, and the file it came from (`None` when inline).
struct Body {
    graph: Graph,
    doc: Option<Document>,
    file: Option<BodyFile>,
}

/// The file of a sub-graph read from `path:`.
struct BodyFile {
    /// The canonical path, to find files that include themselves.
    canonical: PathBuf,
    /// The path joined to the including file's directory, to name the files of a cycle.
    shown: String,
    /// The path as written, relative to the including file's directory.
    written: String,
}

/// Checks a graph whose nodes may be sub-graphs (see the module docs).
pub(crate) fn check_nested(
    graph: &Graph,
    doc: Option<&Document>,
    registry: &NodeRegistry,
    nesting: &mut Nesting,
) -> Result<Checked, Vec<Diagnostic>> {
    if nesting.files.is_empty()
        && let Some(origin) = doc.and_then(Document::origin)
        && let Ok(canonical) = origin.canonicalize()
    {
        nesting
            .files
            .push((canonical, origin.display().to_string()));
    }
    let mut diagnostics = Vec::new();
    let mut inners: HashMap<usize, Option<Inner>> = HashMap::new();
    let at = |i: usize| -> Option<Location> {
        let doc = doc?;
        let spans = doc.map.nodes.get(i)?;
        Some(doc.location(spans.body.as_ref().map_or(spans.id.start, |b| b.start)))
    };
    for (i, node) in graph.nodes.iter().enumerate() {
        if node.node_type != SUBGRAPH_TYPE && node.subgraph.is_none() {
            continue;
        }
        let id = node.id.0.as_str();
        let fail = |message: String| {
            let mut d = Diagnostic::error(DiagnosticKind::SubGraph {
                node: id.to_owned(),
                message,
            });
            d.location = at(i);
            d
        };
        let body = match (&node.subgraph, node.node_type == SUBGRAPH_TYPE) {
            (Some(body), true) => body,
            (Some(_), false) => {
                let message = format!(
                    "a graph body is only for nodes of type \"{SUBGRAPH_TYPE}\", not \"{}\"",
                    node.node_type
                );
                diagnostics.push(fail(message));
                continue;
            }
            (None, _) => {
                diagnostics.push(fail("needs a `path` or an inline `graph`".to_owned()));
                inners.insert(i, None);
                continue;
            }
        };
        let inner = nested_body(i, body, doc, nesting)
            .map_err(|message| vec![fail(message)])
            .and_then(|body| check_body(id, &body, registry, nesting, &fail));
        match inner {
            Ok((inner, warnings)) => {
                diagnostics.extend(warnings);
                inners.insert(i, Some(inner));
            }
            Err(errors) => {
                diagnostics.extend(errors);
                inners.insert(i, None);
            }
        }
    }
    let types = inners
        .iter()
        .map(|(&i, inner)| (i, inner.as_ref().map(|inner| &inner.node_type)))
        .collect();
    let checked = Checker::new(graph, doc, registry)
        .with_subgraphs(types)
        .run();
    let has_errors = diagnostics.iter().any(Diagnostic::is_error);
    let mut checked = match checked {
        Ok(checked) if !has_errors => checked,
        Ok(checked) => {
            diagnostics.extend(checked.warnings);
            return Err(sorted(diagnostics));
        }
        Err(errors) => {
            diagnostics.extend(errors);
            return Err(sorted(diagnostics));
        }
    };
    if inners.is_empty() {
        return Ok(checked);
    }
    let mut plans: Vec<Option<Plan>> = vec![None; checked.plan.nodes.len()];
    for (i, inner) in inners {
        plans[i] = inner.map(|inner| inner.plan);
    }
    let (plan, errors) = splice(checked.plan, plans);
    let mut errors: Vec<Diagnostic> = errors
        .into_iter()
        .map(|(i, message)| {
            let mut d = Diagnostic::error(DiagnosticKind::SubGraph {
                node: graph.nodes[i].id.0.clone(),
                message,
            });
            d.location = at(i);
            d
        })
        .collect();
    for (e, m) in graph.expected_messages.iter().enumerate() {
        if m.node.0.contains('/') && !plan.nodes.iter().any(|n| n.id == m.node) {
            let mut d = Diagnostic::error(DiagnosticKind::Malformed {
                message: format!("expected message for unknown node \"{}\"", m.node),
            });
            d.location = doc.and_then(|doc| {
                let span = doc.map.expected_messages.get(e)?;
                Some(doc.location(span.start))
            });
            errors.push(d);
        }
    }
    if !errors.is_empty() {
        diagnostics.extend(checked.warnings);
        diagnostics.extend(errors);
        return Err(sorted(diagnostics));
    }
    checked.plan = plan;
    diagnostics.extend(checked.warnings);
    checked.warnings = sorted(diagnostics);
    Ok(checked)
}

/// Diagnostics in file order: those of the checked file by position, then those of sub-graph
/// files (each file's in the order they were found).
fn sorted(mut diagnostics: Vec<Diagnostic>) -> Vec<Diagnostic> {
    diagnostics.sort_by_key(|d| {
        let offset = d.location.map_or(usize::MAX, |l| l.offset);
        (d.file.is_some(), if d.file.is_some() { 0 } else { offset })
    });
    diagnostics
}

/// The graph of sub-graph node `i`: inline, or read from its file.
fn nested_body(
    i: usize,
    body: &SubGraph,
    doc: Option<&Document>,
    nesting: &Nesting,
) -> Result<Body, String> {
    if nesting.depth >= MAX_SUBGRAPH_DEPTH {
        return Err(format!(
            "sub-graphs nest more than {MAX_SUBGRAPH_DEPTH} levels deep (MAX_SUBGRAPH_DEPTH)"
        ));
    }
    let path = match body {
        SubGraph::Inline(graph) => {
            return Ok(Body {
                graph: (**graph).clone(),
                doc: doc.and_then(|d| d.inline_subgraph(i)),
                file: None,
            });
        }
        SubGraph::Path(path) => path,
    };
    let Some(origin) = doc.and_then(Document::origin) else {
        return Err(format!(
            "`path: \"{path}\"` needs a graph read from a file, which the path is relative to; \
             this graph has no file (give its document one with `Document::with_origin`, or \
             write the sub-graph inline with `graph:`)"
        ));
    };
    let full = origin
        .parent()
        .map_or_else(|| PathBuf::from(path), |dir| dir.join(path));
    let canonical = full
        .canonicalize()
        .map_err(|e| format!("cannot read \"{path}\" ({}): {e}", full.display()))?;
    let text = read_graph_file(&full, MAX_GRAPH_FILE_BYTES)
        .map_err(|message| format!("cannot read \"{path}\": {message}"))?;
    let shown = full.display().to_string();
    let doc = Document::parse(&text).map_err(|errors| {
        let first = errors.first().map(ToString::to_string).unwrap_or_default();
        format!("\"{path}\" is not a graph: {first}")
    })?;
    Ok(Body {
        graph: doc.graph().clone(),
        doc: Some(doc.with_origin(full)),
        file: Some(BodyFile {
            canonical,
            shown,
            written: path.clone(),
        }),
    })
}

/// Checks a sub-graph's body one level deeper and makes the node type standing for it; its
/// diagnostics come back nested under `id`.
fn check_body(
    id: &str,
    body: &Body,
    registry: &NodeRegistry,
    nesting: &mut Nesting,
    fail: &impl Fn(String) -> Diagnostic,
) -> Result<(Inner, Vec<Diagnostic>), Vec<Diagnostic>> {
    if let Some(BodyFile {
        canonical, shown, ..
    }) = &body.file
        && let Some(first) = nesting.files.iter().position(|(c, _)| c == canonical)
    {
        let mut files: Vec<String> = nesting.files[first..]
            .iter()
            .map(|(_, s)| s.clone())
            .collect();
        files.push(shown.clone());
        let mut d = fail(String::new());
        d.kind = DiagnosticKind::SubGraphCycle {
            node: id.to_owned(),
            files,
        };
        return Err(vec![d]);
    }
    let count = body.graph.nodes.len();
    if nesting.nodes + count > MAX_SUBGRAPH_NODES {
        return Err(vec![fail(format!(
            "the sub-graphs have more than {MAX_SUBGRAPH_NODES} nodes in all \
             (MAX_SUBGRAPH_NODES)"
        ))]);
    }
    nesting.nodes += count;
    nesting.depth += 1;
    let pushed = body
        .file
        .as_ref()
        .map(|f| nesting.files.push((f.canonical.clone(), f.shown.clone())))
        .is_some();
    let checked = check_nested(&body.graph, body.doc.as_ref(), registry, nesting);
    if pushed {
        nesting.files.pop();
    }
    nesting.depth -= 1;
    // The file's name as the including file wrote it, for the diagnostics found in it.
    let file = body.file.as_ref().map(|f| f.written.as_str());
    let nest = |d: Diagnostic| d.nest(id, file);
    match checked {
        Ok(checked) => {
            let warnings = checked
                .warnings
                .into_iter()
                // The including graph reports an input it leaves without data itself.
                .filter(|d| !matches!(d.kind, DiagnosticKind::UnsetGraphInput { .. }))
                .map(nest)
                .collect();
            let node_type = standing_type(id, &body.graph, &checked.plan);
            Ok((
                Inner {
                    plan: checked.plan,
                    node_type,
                },
                warnings,
            ))
        }
        Err(diagnostics) => Err(diagnostics.into_iter().map(nest).collect()),
    }
}

/// The node type that stands for a checked sub-graph: its named inputs and outputs as ports,
/// with the types, access and constraints of the inner ports they set and read.
fn standing_type(id: &str, graph: &Graph, plan: &Plan) -> NodeType {
    let name = if graph.name.is_empty() {
        id
    } else {
        &graph.name
    };
    let mut node_type =
        NodeType::new(SUBGRAPH_TYPE, name, name, "Sub-graph").description(&graph.description);
    for (name, n, k) in &plan.inputs {
        let input = &plan.nodes[*n].inputs[*k];
        let mut port = input.port.clone();
        port.name.clone_from(name);
        port.nickname.clone_from(name);
        // The inner value or default is used when the including graph gives none.
        port.optional = port.optional || input.value.is_some();
        port.default = None;
        node_type = node_type.input(port);
    }
    for (name, n, k) in &plan.outputs {
        let mut port = plan.nodes[*n].node_type.outputs[*k].clone();
        port.name.clone_from(name);
        port.nickname.clone_from(name);
        node_type = node_type.output(port);
    }
    node_type
}

/// Where an output of the including plan is read from once sub-graphs are spliced in.
#[derive(Clone, Copy)]
enum Place {
    /// An ordinary node, at this index of the spliced plan.
    Node(usize),
    /// A sub-graph's nodes, starting at this index of the spliced plan.
    Sub(usize),
}

/// Replaces every sub-graph node of `outer` (those with a plan in `inner`) by its plan's nodes
/// (see the module docs). Returns the spliced plan and the problems found, as (node index in
/// `outer`, message).
fn splice(outer: Plan, mut inner: Vec<Option<Plan>>) -> (Plan, Vec<(usize, String)>) {
    let mut places = Vec::with_capacity(outer.nodes.len());
    let mut next = 0;
    for plan in &inner {
        match plan {
            Some(plan) => {
                places.push(Place::Sub(next));
                next += plan.nodes.len();
            }
            None => {
                places.push(Place::Node(next));
                next += 1;
            }
        }
    }
    let source = |inner: &[Option<Plan>], (n, k): (usize, usize)| match places[n] {
        Place::Node(at) => (at, k),
        Place::Sub(base) => {
            let (_, m, j) = inner[n].as_ref().map_or(("", 0, 0), |p| {
                let (name, m, j) = &p.outputs[k];
                (name.as_str(), *m, *j)
            });
            (base + m, j)
        }
    };
    let mut errors = Vec::new();
    let mut nodes: Vec<PlanNode> = Vec::with_capacity(next);
    for (i, node) in outer.nodes.iter().enumerate() {
        let Place::Sub(base) = places[i] else {
            let mut node = node.clone();
            for input in &mut node.inputs {
                for s in &mut input.sources {
                    *s = source(&inner, *s);
                }
            }
            nodes.push(node);
            continue;
        };
        let Some(plan) = inner[i].take() else {
            continue;
        };
        let first = nodes.len();
        for mut n in plan.nodes {
            n.id.0 = format!("{}/{}", node.id, n.id);
            n.disabled |= node.disabled;
            for input in &mut n.inputs {
                for s in &mut input.sources {
                    s.0 += base;
                }
            }
            nodes.push(n);
        }
        // The wires, values and modifiers of the sub-graph node's inputs go to the inner ports
        // its named inputs set.
        for (j, outside) in node.inputs.iter().enumerate() {
            let (_, m, k) = &plan.inputs[j];
            let sources: Vec<_> = outside.sources.iter().map(|s| source(&inner, *s)).collect();
            let target = &mut nodes[first + m].inputs[*k];
            target.sources.extend(sources);
            if outside.value.is_some() {
                target.value.clone_from(&outside.value);
            }
            if !outside.modifiers.is_empty() {
                if target.modifiers.is_empty() {
                    target.modifiers.clone_from(&outside.modifiers);
                } else {
                    errors.push((
                        i,
                        format!(
                            "input \"{}\" has modifiers both here and on the inner port it sets; \
                             keep one of them",
                            outside.port.name
                        ),
                    ));
                }
            }
        }
        if node.output_modifiers.iter().any(|m| !m.is_empty()) {
            errors.push((
                i,
                "output modifiers are not supported on sub-graph nodes (set them on the inner \
                 node, or on the inputs that read the output)"
                    .to_owned(),
            ));
        }
        // The named inputs and outputs and the order need the inner plan again.
        inner[i] = Some(Plan {
            nodes: Vec::new(),
            ..plan
        });
    }
    let mut order = Vec::with_capacity(next);
    for &i in &outer.order {
        match (places[i], &inner[i]) {
            (Place::Sub(base), Some(plan)) => order.extend(plan.order.iter().map(|n| base + n)),
            (Place::Node(at), _) => order.push(at),
            (Place::Sub(_), None) => {}
        }
    }
    let inputs = outer
        .inputs
        .iter()
        .map(|(name, n, k)| match (places[*n], &inner[*n]) {
            (Place::Sub(base), Some(plan)) => {
                let (_, m, j) = &plan.inputs[*k];
                (name.clone(), base + m, *j)
            }
            (Place::Node(at), _) | (Place::Sub(at), None) => (name.clone(), at, *k),
        })
        .collect();
    let outputs = outer
        .outputs
        .iter()
        .map(|(name, n, k)| {
            let (at, j) = source(&inner, (*n, *k));
            (name.clone(), at, j)
        })
        .collect();
    let plan = Plan {
        nodes,
        order,
        inputs,
        outputs,
    };
    (plan, errors)
}

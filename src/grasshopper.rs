//! Grasshopper files on the command line: `locus import`, `locus export-ghx`,
//! `locus check --format json`, and the hook that lets `run`, `check` and `test` read `.gh` and
//! `.ghx` files (imported on the fly).

use std::path::{Path, PathBuf};

use locus_ghx::{Import, ImportDiagnostic, Limits};
use locus_runtime::{Diagnostic, Document, Literal, NodeRegistry};
use serde_json::{Value as Json, json};

use crate::{EXIT_BAD_GRAPH, EXIT_USAGE};

/// The suffix of the file next to a Grasshopper definition that holds its expected outputs
/// for `locus test` (a RON map from output name to literal).
pub(crate) const EXPECTED_SUFFIX: &str = ".expected.ron";

/// Whether a path names a `.gh` or `.ghx` file.
pub(crate) fn is_grasshopper(path: &Path) -> bool {
    locus_ghx::is_grasshopper_path(path)
}

fn read_import(registry: &NodeRegistry, path: &Path) -> Result<Import, String> {
    let limits = Limits::default();
    let size = std::fs::metadata(path).map_err(|e| e.to_string())?.len();
    if size > limits.max_file_bytes as u64 {
        return Err(format!(
            "the file is {size} bytes, more than the limit of {}",
            limits.max_file_bytes
        ));
    }
    let bytes = std::fs::read(path).map_err(|e| e.to_string())?;
    locus_ghx::import(&bytes, registry, &limits).map_err(|e| e.to_string())
}

fn expected_path(path: &Path) -> PathBuf {
    let mut name = path.as_os_str().to_owned();
    name.push(EXPECTED_SUFFIX);
    PathBuf::from(name)
}

/// The RON text of a Grasshopper file, with the expectations of its `.expected.ron` file when
/// there is one; the import's diagnostics are printed to stderr.
pub(crate) fn load_text(registry: &NodeRegistry, path: &Path) -> Result<String, String> {
    let import = read_import(registry, path)?;
    let file = path.display();
    for d in &import.report.diagnostics {
        eprintln!("{file}: {d}");
    }
    let mut text = locus_ghx::to_ron(&import);
    let expected = expected_path(path);
    if expected.exists() {
        let map = std::fs::read_to_string(&expected)
            .map_err(|e| format!("cannot read {}: {e}", expected.display()))?;
        if let Some(end) = text.rfind(')') {
            text.insert_str(end, &format!("    expected: {},\n", map.trim()));
        }
    }
    Ok(text)
}

/// `locus test --bless` on a Grasshopper file: writes its `.expected.ron` file.
pub(crate) fn write_expected(path: &Path, expected: &[(String, Literal)]) -> Result<(), String> {
    let mut text = String::from("{\n");
    for (name, literal) in expected {
        text.push_str(&format!(
            "    {}: {},\n",
            ron_string(name),
            literal.0.replace('\n', "\n    ")
        ));
    }
    text.push_str("}\n");
    let out = expected_path(path);
    std::fs::write(&out, text).map_err(|e| format!("cannot write {}: {e}", out.display()))
}

fn ron_string(s: &str) -> String {
    let mut out = String::from("\"");
    for c in s.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            '\n' => out.push_str("\\n"),
            c => out.push(c),
        }
    }
    out.push('"');
    out
}

/// `locus import FILE [-o OUT] [--report]`.
pub(crate) fn import(
    registry: &NodeRegistry,
    path: &Path,
    output: Option<&Path>,
    report: bool,
) -> u8 {
    let import = match read_import(registry, path) {
        Ok(i) => i,
        Err(e) => {
            eprintln!("locus: cannot import {}: {e}", path.display());
            return EXIT_BAD_GRAPH;
        }
    };
    let text = locus_ghx::to_ron(&import);
    if report {
        out_str!(import.report.summary());
        let checked = Document::parse(&text).and_then(|d| d.check(registry).map(|_| ()));
        match checked {
            Ok(()) => out!("graph: checks"),
            Err(ds) => {
                out!("graph: does not check");
                for d in ds {
                    out!("  {d}");
                }
            }
        }
    }
    match output {
        Some(out) => {
            if let Err(e) = std::fs::write(out, &text) {
                eprintln!("locus: cannot write {}: {e}", out.display());
                return EXIT_USAGE;
            }
        }
        None if !report => out_str!(text),
        None => {}
    }
    0
}

fn import_json(d: &ImportDiagnostic, file: &str) -> Json {
    json!({
        "severity": d.severity.name(),
        "code": d.code,
        "message": d.message,
        "node": d.node.as_ref().map(|n| n.0.clone()),
        "port": d.port,
        "file": file,
        "line": null,
        "column": null,
        "gh_instance": d.object.as_ref().map(|o| o.instance.clone()),
        "gh_type": d.object.as_ref().map(|o| o.type_guid.clone()),
        "gh_name": d.object.as_ref().map(|o| o.name.clone()),
        "gh_nickname": d.object.as_ref().map(|o| o.nickname.clone()),
    })
}

/// A diagnostic kind's variant name in kebab case (`UnknownPort` → `unknown-port`).
fn kind_code(d: &Diagnostic) -> String {
    let debug = format!("{:?}", d.kind);
    let variant = debug
        .split(|c: char| !c.is_alphanumeric())
        .next()
        .unwrap_or_default();
    let mut code = String::new();
    for (k, c) in variant.chars().enumerate() {
        if c.is_uppercase() && k > 0 {
            code.push('-');
        }
        code.extend(c.to_lowercase());
    }
    code
}

fn check_json_entry(d: &Diagnostic, file: &str) -> Json {
    let (line, column) = match &d.location {
        Some(l) => (json!(l.line), json!(l.column)),
        None => (Json::Null, Json::Null),
    };
    json!({
        "severity": d.severity.name(),
        "code": kind_code(d),
        "message": d.message(),
        "node": d.node(),
        "port": d.port(),
        "file": file,
        "line": line,
        "column": column,
        "gh_instance": null,
        "gh_type": null,
        "gh_name": null,
        "gh_nickname": null,
    })
}

/// `locus check --format json`: every diagnostic of every file as one JSON array.
pub(crate) fn check_json(registry: &NodeRegistry, paths: &[PathBuf]) -> u8 {
    let mut all = Vec::new();
    let mut code = 0;
    for path in paths {
        let file = path.display().to_string();
        let text = if is_grasshopper(path) {
            match read_import(registry, path) {
                Ok(import) => {
                    all.extend(
                        import
                            .report
                            .diagnostics
                            .iter()
                            .map(|d| import_json(d, &file)),
                    );
                    locus_ghx::to_ron(&import)
                }
                Err(e) => {
                    all.push(json!({"severity": "error", "code": "unreadable", "message": e, "file": file}));
                    code = EXIT_BAD_GRAPH;
                    continue;
                }
            }
        } else {
            match std::fs::read_to_string(path) {
                Ok(t) => t,
                Err(e) => {
                    all.push(json!({"severity": "error", "code": "unreadable", "message": e.to_string(), "file": file}));
                    code = EXIT_BAD_GRAPH;
                    continue;
                }
            }
        };
        let diagnostics = match Document::parse(&text) {
            Ok(doc) => match doc.check(registry) {
                Ok(checked) => checked.warnings,
                Err(ds) => ds,
            },
            Err(ds) => ds,
        };
        if diagnostics.iter().any(Diagnostic::is_error) {
            code = EXIT_BAD_GRAPH;
        }
        // Positions in an imported file are in its RON form (`locus import` writes it).
        let position_file = if is_grasshopper(path) {
            format!("{file} (as imported)")
        } else {
            file.clone()
        };
        all.extend(
            diagnostics
                .iter()
                .map(|d| check_json_entry(d, &position_file)),
        );
    }
    out!(
        "{}",
        serde_json::to_string_pretty(&Json::Array(all)).unwrap_or_default()
    );
    code
}

/// Reads every `path:` sub-graph of `graph` (relative to `file`, the graph's own file) into
/// its node, at any depth, so that the graph can be written as one Grasshopper file with its
/// sub-graphs as clusters.
fn inline_subgraphs(
    graph: &mut locus_runtime::Graph,
    file: &Path,
    depth: usize,
) -> Result<(), String> {
    use locus_runtime::{MAX_GRAPH_FILE_BYTES, MAX_SUBGRAPH_DEPTH, SubGraph, read_graph_file};
    for node in &mut graph.nodes {
        let (mut inner, inner_file) = match &node.subgraph {
            None => continue,
            Some(SubGraph::Inline(g)) => ((**g).clone(), file.to_path_buf()),
            Some(SubGraph::Path(p)) => {
                if depth >= MAX_SUBGRAPH_DEPTH {
                    return Err(format!(
                        "node \"{}\": sub-graphs nest more than {MAX_SUBGRAPH_DEPTH} levels deep",
                        node.id
                    ));
                }
                let full = file
                    .parent()
                    .map_or_else(|| PathBuf::from(p), |d| d.join(p));
                let text = read_graph_file(&full, MAX_GRAPH_FILE_BYTES)
                    .map_err(|e| format!("node \"{}\": cannot read \"{p}\": {e}", node.id))?;
                let doc = Document::parse(&text).map_err(|errors| {
                    let first = errors.first().map(ToString::to_string).unwrap_or_default();
                    format!("node \"{}\": \"{p}\" is not a graph: {first}", node.id)
                })?;
                (doc.graph().clone(), full)
            }
        };
        inline_subgraphs(&mut inner, &inner_file, depth + 1)?;
        node.subgraph = Some(SubGraph::Inline(Box::new(inner)));
    }
    Ok(())
}

/// `locus export-ghx GRAPH.ron -o FILE.ghx`.
pub(crate) fn export(registry: &NodeRegistry, path: &Path, output: &Path) -> u8 {
    let text = match std::fs::read_to_string(path) {
        Ok(t) => t,
        Err(e) => {
            eprintln!("locus: cannot read {}: {e}", path.display());
            return EXIT_BAD_GRAPH;
        }
    };
    let document = match Document::parse(&text) {
        Ok(d) => d,
        Err(ds) => {
            let file = path.display().to_string();
            for d in ds {
                eprintln!("{}", d.display_in(&file));
            }
            return EXIT_BAD_GRAPH;
        }
    };
    let mut graph = document.graph().clone();
    if let Err(e) = inline_subgraphs(&mut graph, path, 0) {
        eprintln!("locus: cannot export {}: {e}", path.display());
        return EXIT_BAD_GRAPH;
    }
    match locus_ghx::export_ghx(&graph, registry) {
        Ok((ghx, warnings)) => {
            for w in warnings {
                eprintln!("locus: {}: warning: {w}", path.display());
            }
            if let Err(e) = std::fs::write(output, ghx) {
                eprintln!("locus: cannot write {}: {e}", output.display());
                return EXIT_USAGE;
            }
            0
        }
        Err(e) => {
            eprintln!("locus: cannot export {}: {e}", path.display());
            EXIT_BAD_GRAPH
        }
    }
}

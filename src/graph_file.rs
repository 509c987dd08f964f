//! `locus run`, `locus check` and `locus dot`: reading, checking and evaluating graph files.

use std::path::Path;

use locus_runtime::{
    Checked, Diagnostic, Document, Evaluator, Level, NodeRegistry, parse_literal, to_dot,
};
use serde_json::{Map, Value as Json, json};

use crate::{EXIT_BAD_GRAPH, EXIT_RUNTIME_ERROR, EXIT_USAGE, render};

/// A graph file read and checked.
pub(crate) struct Loaded {
    pub(crate) document: Document,
    pub(crate) checked: Checked,
}

/// Why a graph file could not be used.
pub(crate) enum LoadError {
    /// The file could not be read.
    Io(String),
    /// Reading or checking found errors (warnings included, in file order).
    Diagnostics(Vec<Diagnostic>),
}

impl LoadError {
    /// Prints the problem to stderr.
    pub(crate) fn report(&self, path: &Path) {
        match self {
            LoadError::Io(e) => eprintln!("locus: cannot read {}: {e}", path.display()),
            LoadError::Diagnostics(ds) => {
                let file = path.display().to_string();
                for d in ds {
                    eprintln!("{}", d.display_in(&file));
                }
                let errors = ds.iter().filter(|d| d.is_error()).count();
                eprintln!(
                    "locus: {file}: {errors} error{} found, the graph was not run",
                    if errors == 1 { "" } else { "s" }
                );
            }
        }
    }
}

/// Reads and checks a graph file.
pub(crate) fn load(registry: &NodeRegistry, path: &Path) -> Result<Loaded, LoadError> {
    let text = if crate::grasshopper::is_grasshopper(path) {
        crate::grasshopper::load_text(registry, path).map_err(LoadError::Io)?
    } else {
        std::fs::read_to_string(path).map_err(|e| LoadError::Io(e.to_string()))?
    };
    let document = Document::parse(&text).map_err(LoadError::Diagnostics)?;
    let checked = document.check(registry).map_err(LoadError::Diagnostics)?;
    Ok(Loaded { document, checked })
}

/// An evaluator for a checked graph with the thread count applied.
pub(crate) fn evaluator(checked: &Checked, threads: Option<usize>) -> Result<Evaluator, String> {
    let mut evaluator = Evaluator::new(checked.plan.clone());
    if let Some(n) = threads {
        evaluator.set_threads(n).map_err(|e| e.to_string())?;
    }
    Ok(evaluator)
}

/// `locus run`.
pub(crate) fn run(
    registry: &NodeRegistry,
    path: &Path,
    sets: &[String],
    json: bool,
    threads: Option<usize>,
) -> u8 {
    let loaded = match load(registry, path) {
        Ok(l) => l,
        Err(e) => {
            e.report(path);
            return EXIT_BAD_GRAPH;
        }
    };
    let file = path.display().to_string();
    for w in &loaded.checked.warnings {
        eprintln!("{}", w.display_in(&file));
    }
    let mut evaluator = match evaluator(&loaded.checked, threads) {
        Ok(e) => e,
        Err(e) => {
            eprintln!("locus: {e}");
            return EXIT_USAGE;
        }
    };
    let plan = &loaded.checked.plan;
    for set in sets {
        let Some((name, value)) = set.split_once('=') else {
            eprintln!("locus: --set needs NAME=VALUE, got \"{set}\"");
            return EXIT_USAGE;
        };
        let name = name.trim();
        let Some(&(_, node, port)) = plan.inputs.iter().find(|(n, _, _)| n == name) else {
            let known: Vec<&str> = plan.inputs.iter().map(|(n, _, _)| n.as_str()).collect();
            eprintln!(
                "locus: the graph has no input \"{name}\" (its inputs: {})",
                if known.is_empty() {
                    "none".to_owned()
                } else {
                    known.join(", ")
                }
            );
            return EXIT_USAGE;
        };
        let data_type = plan.nodes[node].inputs[port].port.data_type;
        match parse_literal(value, data_type) {
            Ok(tree) => {
                if let Err(e) = evaluator.set_input(name, tree) {
                    eprintln!("locus: {e}");
                    return EXIT_USAGE;
                }
            }
            Err(e) => {
                eprintln!("locus: --set {name}: {e}");
                return EXIT_USAGE;
            }
        }
    }
    evaluator.evaluate();
    if json {
        let mut outputs = Map::new();
        for (name, tree) in evaluator.outputs() {
            outputs.insert(name.to_owned(), render::tree_json(tree));
        }
        let messages: Vec<Json> = evaluator.messages().map(render::message_json).collect();
        let doc = json!({ "outputs": outputs, "messages": messages });
        out!("{}", serde_json::to_string_pretty(&doc).unwrap_or_default());
    } else {
        for (name, tree) in evaluator.outputs() {
            out!("{name}:");
            out_str!(render::tree_text(tree));
        }
        let messages: Vec<String> = evaluator.messages().map(ToString::to_string).collect();
        if !messages.is_empty() {
            out!("messages:");
            for m in messages {
                out!("  {m}");
            }
        }
    }
    if evaluator.messages().any(|m| m.level == Level::Error) {
        EXIT_RUNTIME_ERROR
    } else {
        0
    }
}

/// `locus check`.
pub(crate) fn check(registry: &NodeRegistry, paths: &[std::path::PathBuf]) -> u8 {
    let mut code = 0;
    for path in paths {
        match load(registry, path) {
            Ok(loaded) => {
                let file = path.display().to_string();
                for w in &loaded.checked.warnings {
                    out!("{}", w.display_in(&file));
                }
                let graph = loaded.document.graph();
                out!(
                    "{file}: ok ({} nodes, {} wires, {} warning{})",
                    graph.nodes.len(),
                    graph.wires.len(),
                    loaded.checked.warnings.len(),
                    if loaded.checked.warnings.len() == 1 {
                        ""
                    } else {
                        "s"
                    }
                );
            }
            Err(e) => {
                e.report(path);
                code = EXIT_BAD_GRAPH;
            }
        }
    }
    code
}

/// `locus dot`.
pub(crate) fn dot(registry: &NodeRegistry, path: &Path) -> u8 {
    let text = match std::fs::read_to_string(path) {
        Ok(t) => t,
        Err(e) => {
            LoadError::Io(e.to_string()).report(path);
            return EXIT_BAD_GRAPH;
        }
    };
    match Document::parse(&text) {
        Ok(doc) => {
            out_str!(to_dot(doc.graph(), Some(registry)));
            0
        }
        Err(ds) => {
            LoadError::Diagnostics(ds).report(path);
            EXIT_BAD_GRAPH
        }
    }
}

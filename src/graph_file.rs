//! `locus run`, `locus check` and `locus dot`: reading, checking and evaluating graph files.

use std::path::Path;

use std::time::Duration;

use locus_runtime::{
    Checked, DEFAULT_MAX_ITEMS_PER_OUTPUT, DEFAULT_MAX_ITEMS_TOTAL, Diagnostic, Document,
    Evaluator, Level, Limits, MAX_GRAPH_FILE_BYTES, NodeRegistry, read_graph_file, to_dot,
};

use crate::{EXIT_BAD_GRAPH, EXIT_LIMIT, EXIT_RUNTIME_ERROR, EXIT_USAGE, render};

/// The default of `--max-output-bytes`: 64 MiB.
pub(crate) const DEFAULT_MAX_OUTPUT_BYTES: u64 = 64 << 20;

/// The run limits of `locus run` (see `docs/limits.md`).
#[derive(Debug, Clone, clap::Args)]
pub(crate) struct RunLimits {
    /// Stop the evaluation after this many seconds (exit code 5; the nodes not run are named).
    #[arg(long, value_name = "SECONDS")]
    timeout: Option<f64>,
    /// The most items and branches one output tree may hold (default 10,000,000); all outputs
    /// together may hold 5 times as many.
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u64).range(1..))]
    max_items: Option<u64>,
    /// Print only this named output (repeatable; default: every output).
    #[arg(long = "output", value_name = "NAME")]
    outputs: Vec<String>,
    /// Stop printing outputs after this many bytes, with a notice (default 64 MiB; 0: no
    /// limit).
    #[arg(long, value_name = "N", default_value_t = DEFAULT_MAX_OUTPUT_BYTES)]
    max_output_bytes: u64,
    /// Show no progress bar (one is drawn on stderr, when it is a terminal, for runs longer
    /// than a second).
    #[arg(long, short = 'q')]
    quiet: bool,
    /// Draw or export the geometry of every node's outputs (named NODE.OUTPUT), as
    /// Grasshopper's canvas preview shows it, instead of the named outputs only (locus render,
    /// locus view and --export).
    #[arg(long)]
    preview: bool,
}

impl RunLimits {
    /// Whether `--preview` asks for every node's geometry.
    pub(crate) fn previews_every_node(&self) -> bool {
        self.preview
    }

    /// The runtime limits these options ask for.
    fn limits(&self) -> Result<Limits, String> {
        let mut limits = Limits::default();
        if let Some(t) = self.timeout {
            if !(t.is_finite() && t > 0.0) {
                return Err(format!(
                    "--timeout needs a positive number of seconds, got {t}"
                ));
            }
            limits.timeout = Some(Duration::try_from_secs_f64(t).map_err(|e| e.to_string())?);
        }
        if let Some(n) = self.max_items {
            let n = usize::try_from(n).unwrap_or(usize::MAX);
            limits.max_items_per_output = n;
            limits.max_items_total =
                n.saturating_mul(DEFAULT_MAX_ITEMS_TOTAL / DEFAULT_MAX_ITEMS_PER_OUTPUT);
        }
        Ok(limits)
    }
}

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
        for line in self.lines(path) {
            eprintln!("{}", render::for_stream(&line, &std::io::stderr()));
        }
    }
}

/// Reads and checks a graph file.
pub(crate) fn load(registry: &NodeRegistry, path: &Path) -> Result<Loaded, LoadError> {
    let text = if crate::grasshopper::is_grasshopper(path) {
        crate::grasshopper::load_text(registry, path).map_err(LoadError::Io)?
    } else {
        read_graph_file(path, MAX_GRAPH_FILE_BYTES).map_err(LoadError::Io)?
    };
    let document = Document::parse(&text)
        .map_err(LoadError::Diagnostics)?
        .with_origin(path);
    let checked = document.check(registry).map_err(LoadError::Diagnostics)?;
    Ok(Loaded { document, checked })
}

/// An evaluator for a checked graph with the thread count applied.
pub(crate) fn evaluator(checked: &Checked, threads: Option<usize>) -> Result<Evaluator, String> {
    let mut evaluator = Evaluator::new(checked.plan.clone());
    if let Some(n) = threads {
        let used = evaluator.set_threads(n).map_err(|e| e.to_string())?;
        if used < n {
            eprintln!(
                "locus: warning: --threads {n} is more than {} per core; using {used}",
                locus_runtime::MAX_THREADS_PER_CORE
            );
        }
    }
    Ok(evaluator)
}

/// Why a graph could not be made ready to run: the exit code, and the lines that say why (each
/// as it would be printed, without the terminal's escaping).
pub(crate) struct Refusal {
    pub(crate) code: u8,
    pub(crate) lines: Vec<String>,
}

impl Refusal {
    fn new(code: u8, line: String) -> Self {
        Refusal {
            code,
            lines: vec![line],
        }
    }

    /// Prints the lines to stderr and gives the exit code.
    pub(crate) fn report(self) -> u8 {
        for line in &self.lines {
            eprintln!("{}", render::for_stream(line, &std::io::stderr()));
        }
        self.code
    }
}

impl LoadError {
    /// The lines that say what is wrong, as [`LoadError::report`] prints them.
    fn lines(&self, path: &Path) -> Vec<String> {
        match self {
            LoadError::Io(e) => vec![format!("locus: cannot read {}: {e}", path.display())],
            LoadError::Diagnostics(ds) => {
                let file = path.display().to_string();
                let mut lines: Vec<String> =
                    ds.iter().map(|d| d.display_in(&file).to_string()).collect();
                let errors = ds.iter().filter(|d| d.is_error()).count();
                lines.push(format!(
                    "locus: {file}: {errors} error{} found, the graph was not run",
                    if errors == 1 { "" } else { "s" }
                ));
                lines
            }
        }
    }
}

/// Reads, checks and prepares a graph file for `locus run`, `locus view` and `locus render`:
/// thread count, limits, `--output` names checked and `--set` values given. Problems are
/// printed to stderr; the error is the exit code.
pub(crate) fn prepared(
    registry: &NodeRegistry,
    path: &Path,
    sets: &[String],
    threads: Option<usize>,
    run_limits: &RunLimits,
) -> Result<Evaluator, u8> {
    prepare(registry, path, sets, threads, run_limits).map_err(Refusal::report)
}

/// As [`prepared`], with the problems given back instead of printed (the checker's warnings
/// are printed to stderr either way).
pub(crate) fn prepare(
    registry: &NodeRegistry,
    path: &Path,
    sets: &[String],
    threads: Option<usize>,
    run_limits: &RunLimits,
) -> Result<Evaluator, Refusal> {
    let loaded = load(registry, path).map_err(|e| Refusal {
        code: EXIT_BAD_GRAPH,
        lines: e.lines(path),
    })?;
    let file = path.display().to_string();
    for w in &loaded.checked.warnings {
        let text = w.display_in(&file).to_string();
        eprintln!("{}", render::for_stream(&text, &std::io::stderr()));
    }
    let usage = |e: String| Refusal::new(EXIT_USAGE, format!("locus: {e}"));
    let mut evaluator = evaluator(&loaded.checked, threads).map_err(usage)?;
    crate::progress::attach(&mut evaluator, run_limits.quiet);
    evaluator.set_limits(run_limits.limits().map_err(usage)?);
    if run_limits.preview {
        // Every output is drawn: keep them all rather than run nodes again for them.
        evaluator.keep_all_outputs();
    }
    let known: Vec<&str> = evaluator.output_names().collect();
    if let Some(bad) = run_limits
        .outputs
        .iter()
        .find(|o| !known.contains(&o.as_str()))
    {
        return Err(usage(format!(
            "--output: unknown output \"{bad}\" (the graph's outputs are: {})",
            if known.is_empty() {
                "none".to_owned()
            } else {
                known.join(", ")
            }
        )));
    }
    for set in sets {
        let Some((name, value)) = set.split_once('=') else {
            return Err(usage(format!("--set needs NAME=VALUE, got \"{set}\"")));
        };
        evaluator
            .set_input_text(name.trim(), value)
            .map_err(|e| usage(format!("--set: {e}")))?;
    }
    Ok(evaluator)
}

impl RunLimits {
    /// Whether `--output` lets this output through (all do when none is named).
    pub(crate) fn selects(&self, name: &str) -> bool {
        self.outputs.is_empty() || self.outputs.iter().any(|o| o == name)
    }
}

/// `locus run`.
pub(crate) fn run(
    registry: &NodeRegistry,
    path: &Path,
    sets: &[String],
    json: bool,
    threads: Option<usize>,
    run_limits: &RunLimits,
    exports: &[std::path::PathBuf],
) -> u8 {
    let mut evaluator = match prepared(registry, path, sets, threads, run_limits) {
        Ok(e) => e,
        Err(code) => return code,
    };
    evaluator.evaluate();
    let mut limit_hit = false;
    if let Some(hit) = evaluator.limit_hit() {
        limit_hit = true;
        let not_run = evaluator.not_run();
        match not_run.first() {
            None => eprintln!("locus: limit: {hit}"),
            Some(first) => eprintln!(
                "locus: limit: {hit}; {} node{} not run (the first: \"{first}\")",
                not_run.len(),
                if not_run.len() == 1 { " was" } else { "s were" }
            ),
        }
    }
    let selected: Vec<(&str, &locus_runtime::DataTree)> = evaluator
        .outputs()
        .filter(|(name, _)| run_limits.selects(name))
        .collect();
    let max_bytes = match run_limits.max_output_bytes {
        0 => u64::MAX,
        n => n,
    };
    let messages: Vec<&locus_runtime::Message> = evaluator.messages().collect();
    let stdout = std::io::stdout();
    let safe = std::io::IsTerminal::is_terminal(&stdout);
    let mut out = std::io::BufWriter::new(stdout.lock());
    let written = if json {
        crate::stream::write_json(&mut out, &selected, &messages, max_bytes)
    } else {
        crate::stream::write_text(&mut out, &selected, max_bytes, safe).and_then(|truncated| {
            use std::io::Write as _;
            if truncated {
                writeln!(
                    out,
                    "(output truncated: more than {max_bytes} bytes; see --max-output-bytes)"
                )?;
            }
            if !messages.is_empty() {
                writeln!(out, "messages:")?;
                for m in &messages {
                    let m = m.to_string();
                    let m = if safe {
                        render::terminal_safe(&m)
                    } else {
                        m.as_str().into()
                    };
                    writeln!(out, "  {m}")?;
                }
            }
            Ok(truncated)
        })
    };
    // A closed stdout (`locus run g.ron | head`) ends the program quietly, as `out!` does.
    let truncated = match written.and_then(|t| {
        use std::io::Write as _;
        out.flush().map(|()| t)
    }) {
        Ok(t) => t,
        Err(_) => std::process::exit(0),
    };
    drop(out);
    if truncated {
        eprintln!(
            "locus: limit: the output was truncated at {max_bytes} bytes (--max-output-bytes)"
        );
    }
    if let Err(e) = crate::export::write_files(&evaluator, run_limits, exports) {
        eprintln!("locus: {e}");
        return crate::EXIT_EXPORT_FAILED;
    }
    if limit_hit || truncated {
        EXIT_LIMIT
    } else if evaluator.messages().any(|m| m.level == Level::Error) {
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
                    let text = w.display_in(&file).to_string();
                    out!("{}", render::for_stream(&text, &std::io::stdout()));
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
    let text = match read_graph_file(path, MAX_GRAPH_FILE_BYTES) {
        Ok(t) => t,
        Err(e) => {
            LoadError::Io(e).report(path);
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

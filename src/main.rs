//! The `locus` command: run, check and test node graphs from the command line.
//!
//! Exit codes (also in `docs/cli.md`): 0 success; 1 a node reported an error while running;
//! 2 the command line is wrong (unknown option, bad `--set` value, unknown input or node);
//! 3 a graph could not be read or failed checking; 4 `locus test` found failing graphs; 5 a run
//! limit was hit (time, items, output size).

/// Prints a line to stdout; a closed stdout (`locus nodes | head`) ends the program quietly.
macro_rules! out {
    ($($arg:tt)*) => {{
        use std::io::Write as _;
        if writeln!(std::io::stdout(), $($arg)*).is_err() {
            std::process::exit(0);
        }
    }};
}

/// Prints to stdout without a newline; see `out!`.
macro_rules! out_str {
    ($text:expr) => {{
        use std::io::Write as _;
        if write!(std::io::stdout(), "{}", $text).is_err() {
            std::process::exit(0);
        }
    }};
}

mod catalog;
mod export;
mod fmt;
mod graph_file;
mod grasshopper;
mod progress;
mod render;
mod serve;
mod stream;
mod test_graphs;
mod view_serve;
mod write_file;

use std::path::PathBuf;
use std::process::ExitCode;

use clap::{Parser, Subcommand, ValueEnum};

/// Exit code: a node reported an error while running.
const EXIT_RUNTIME_ERROR: u8 = 1;
/// Exit code: the command line is wrong.
const EXIT_USAGE: u8 = 2;
/// Exit code: a graph could not be read or failed checking.
const EXIT_BAD_GRAPH: u8 = 3;
/// Exit code: at least one graph failed its test.
const EXIT_TEST_FAILED: u8 = 4;
/// Exit code: a run limit was hit (time, items, output size); see `docs/limits.md`.
const EXIT_LIMIT: u8 = 5;
/// Exit code: an export or picture file could not be written.
const EXIT_EXPORT_FAILED: u8 = 6;

/// locus: a headless node-graph engine for computational design, with Grasshopper's semantics.
#[derive(Debug, Parser)]
#[command(name = "locus", version, about, max_term_width = 100)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

/// How `locus run` prints results.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
enum Format {
    /// Trees in Grasshopper notation, one item per line.
    Text,
    /// One JSON object (see docs/json-output.md).
    Json,
}

#[derive(Debug, Subcommand)]
enum Command {
    /// Evaluate a graph and print its named outputs and every runtime message.
    Run {
        /// The graph file (.ron, or Grasshopper .gh/.ghx).
        graph: PathBuf,
        /// Give a named input a value written as in the graph file: `--set t=0.3`,
        /// `--set A='(1,2,3)'`, `--set N='[1, 2, 3]'`.
        #[arg(long = "set", value_name = "NAME=VALUE")]
        set: Vec<String>,
        /// Output format.
        #[arg(long, value_enum, default_value_t = Format::Text)]
        format: Format,
        /// Number of threads (default: one per core; 1 runs everything on one thread; more than
        /// 4 per core are capped with a warning).
        #[arg(long, value_name = "N", value_parser = clap::value_parser!(u32).range(1..))]
        threads: Option<u32>,
        #[command(flatten)]
        limits: graph_file::RunLimits,
        /// Also write the outputs' geometry to a file: .glb, .gltf, .obj, .stl, .svg (plan
        /// view) or .png (repeatable; `--output` chooses the outputs).
        #[arg(long, value_name = "FILE")]
        export: Vec<PathBuf>,
    },
    /// Evaluate a graph and draw its outputs' geometry into a picture (.png) or drawing (.svg).
    Render {
        /// The graph file (.ron).
        graph: PathBuf,
        /// The picture file to write (.png, or .svg for a drawing from the same view).
        #[arg(short = 'o', long = "to", value_name = "FILE")]
        file: PathBuf,
        /// The view: top, front, right or iso.
        #[arg(long, default_value = "iso")]
        view: String,
        /// The picture's size in pixels, WIDTHxHEIGHT.
        #[arg(long, default_value = "800x600")]
        size: String,
        /// Give a named input a value, as with `locus run`.
        #[arg(long = "set", value_name = "NAME=VALUE")]
        set: Vec<String>,
        /// Number of threads.
        #[arg(long, value_name = "N", value_parser = clap::value_parser!(u32).range(1..))]
        threads: Option<u32>,
        #[command(flatten)]
        limits: graph_file::RunLimits,
    },
    /// Evaluate a graph and write one self-contained HTML page that shows its outputs in an
    /// orbit view, with toggles per output and branch, click-to-inspect and the messages; or,
    /// with --serve, serve the page on 127.0.0.1 and evaluate again whenever the file changes.
    View {
        /// The graph file (.ron, or Grasshopper .gh/.ghx).
        graph: PathBuf,
        /// The page to write (default: the graph's name with .html).
        #[arg(
            short = 'o',
            long = "to",
            value_name = "FILE",
            conflicts_with = "serve"
        )]
        file: Option<PathBuf>,
        /// Serve the page on 127.0.0.1 instead of writing it; the page reloads, keeping its
        /// camera, each time the graph file changes. Prints the page's address on stdout.
        #[arg(long)]
        serve: bool,
        /// The port for --serve (0: any free port).
        #[arg(long, value_name = "PORT", default_value_t = 8417, requires = "serve")]
        port: u16,
        /// Give a named input a value, as with `locus run`.
        #[arg(long = "set", value_name = "NAME=VALUE")]
        set: Vec<String>,
        /// Number of threads.
        #[arg(long, value_name = "N", value_parser = clap::value_parser!(u32).range(1..))]
        threads: Option<u32>,
        #[command(flatten)]
        limits: graph_file::RunLimits,
    },
    /// Check a graph and print every problem with file:line:column, node and port.
    Check {
        /// The graph files (.ron, or Grasshopper .gh/.ghx).
        #[arg(required = true)]
        graphs: Vec<PathBuf>,
        /// Output format (json: one array of diagnostics, see docs/grasshopper-files.md).
        #[arg(long, value_enum, default_value_t = Format::Text)]
        format: Format,
    },
    /// Import a Grasshopper definition (.gh or .ghx) as a RON graph.
    Import {
        /// The Grasshopper file.
        file: PathBuf,
        /// Write the graph here instead of printing it.
        #[arg(short, long, value_name = "FILE.ron")]
        output: Option<PathBuf>,
        /// Print a summary: objects read, mapped, dropped and unsupported, and whether the
        /// whole definition can run.
        #[arg(long)]
        report: bool,
    },
    /// Write a RON graph as a Grasshopper .ghx file.
    ExportGhx {
        /// The graph file (.ron).
        graph: PathBuf,
        /// The .ghx file to write.
        #[arg(short, long, value_name = "FILE.ghx")]
        output: PathBuf,
    },
    /// Run graphs that carry expected outputs and report pass or fail per graph.
    Test {
        /// Graph files or folders (searched for .ron files); default `graphs/`.
        paths: Vec<PathBuf>,
        /// Write the current outputs into the graphs as their new expectations (refused for a
        /// graph whose run reports an error it does not declare, unless --allow-errors).
        #[arg(long)]
        bless: bool,
        /// With --bless: declare the errors the run reports as expected messages.
        #[arg(long, requires = "bless")]
        allow_errors: bool,
        /// Number of threads.
        #[arg(long, value_name = "N", value_parser = clap::value_parser!(u32).range(1..))]
        threads: Option<u32>,
    },
    /// Rewrite graph files in canonical layout (the comments before the graph are kept).
    Fmt {
        /// Graph files or folders (searched for .ron files); default `graphs/`.
        paths: Vec<PathBuf>,
        /// Change nothing; exit with 4 if a file is not in canonical layout.
        #[arg(long)]
        check: bool,
    },
    /// List the node catalogue, optionally one category.
    Nodes {
        /// A category such as `Vector` (case-insensitive).
        category: Option<String>,
    },
    /// Show a node type's ports, types, access, defaults and documentation.
    Describe {
        /// The node type's id (`vector.dot_product`), name or nickname.
        node: String,
    },
    /// Print a graph in Graphviz DOT.
    Dot {
        /// The graph file.
        graph: PathBuf,
    },
    /// Serve graphs over HTTP: Rhino.Compute's Grasshopper endpoints and /v1/run
    /// (docs/server.md).
    Serve(serve::ServeArgs),
}

fn main() -> ExitCode {
    // A panic is a bug in locus: say so in plain words, without a backtrace.
    std::panic::set_hook(Box::new(|info| {
        let location = info
            .location()
            .map(|l| format!(" at {}:{}", l.file(), l.line()))
            .unwrap_or_default();
        eprintln!("locus: internal error{location}; please report it");
    }));
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(e) => {
            let _ = e.print();
            return if e.use_stderr() {
                ExitCode::from(EXIT_USAGE)
            } else {
                ExitCode::SUCCESS
            };
        }
    };
    let registry = catalog::registry();
    let code = match cli.command {
        Command::Run {
            graph,
            set,
            format,
            threads,
            limits,
            export,
        } => graph_file::run(
            &registry,
            &graph,
            &set,
            format == Format::Json,
            threads.map(|n| n as usize),
            &limits,
            &export,
        ),
        Command::Render {
            graph,
            file,
            view,
            size,
            set,
            threads,
            limits,
        } => export::render(
            &registry,
            &export::RenderArgs {
                graph: &graph,
                sets: &set,
                output: &file,
                view: &view,
                size: &size,
                threads: threads.map(|n| n as usize),
                limits: &limits,
            },
        ),
        Command::View {
            graph,
            serve: true,
            port,
            set,
            threads,
            limits,
            ..
        } => view_serve::serve(
            &registry,
            &graph,
            &set,
            threads.map(|n| n as usize),
            &limits,
            port,
        ),
        Command::View {
            graph,
            file,
            set,
            threads,
            limits,
            ..
        } => export::view(
            &registry,
            &graph,
            &set,
            file.as_deref(),
            threads.map(|n| n as usize),
            &limits,
        ),
        Command::Check { graphs, format } => match format {
            Format::Json => grasshopper::check_json(&registry, &graphs),
            Format::Text => graph_file::check(&registry, &graphs),
        },
        Command::Import {
            file,
            output,
            report,
        } => grasshopper::import(&registry, &file, output.as_deref(), report),
        Command::ExportGhx { graph, output } => grasshopper::export(&registry, &graph, &output),
        Command::Test {
            paths,
            bless,
            allow_errors,
            threads,
        } => test_graphs::test(
            &registry,
            &paths,
            bless,
            allow_errors,
            threads.map(|n| n as usize),
        ),
        Command::Fmt { paths, check } => fmt::fmt(&paths, check),
        Command::Nodes { category } => catalog::list(&registry, category.as_deref()),
        Command::Describe { node } => catalog::describe(&registry, &node),
        Command::Dot { graph } => graph_file::dot(&registry, &graph),
        Command::Serve(args) => serve::serve(registry, args),
    };
    ExitCode::from(code)
}

//! `locus serve`: the command line of the HTTP server (the server itself is `locus-server`).

use std::net::SocketAddr;
use std::path::PathBuf;

use locus_runtime::NodeRegistry;
use locus_server::{Config, config};

use crate::EXIT_USAGE;

/// Options of `locus serve`; the defaults are documented in docs/server.md.
#[derive(Debug, clap::Args)]
pub(crate) struct ServeArgs {
    /// The address to listen on (port 0 picks a free port, printed on stdout).
    #[arg(long, default_value = config::DEFAULT_BIND)]
    bind: SocketAddr,
    /// Solves that run at the same time (default: one per core).
    #[arg(long, value_name = "N")]
    workers: Option<usize>,
    /// A folder whose files requests may name in `pointer`.
    #[arg(long, value_name = "DIR")]
    definitions: Option<PathBuf>,
    /// Require `Authorization: Bearer TOKEN` on every request but /healthcheck
    /// (also read from LOCUS_SERVE_TOKEN).
    #[arg(
        long,
        value_name = "TOKEN",
        env = "LOCUS_SERVE_TOKEN",
        hide_env_values = true
    )]
    token: Option<String>,
    /// Largest request body in bytes.
    #[arg(long, value_name = "BYTES", default_value_t = config::DEFAULT_MAX_BODY_BYTES)]
    max_body: usize,
    /// Wall-clock deadline of one request in milliseconds, waiting included.
    #[arg(long, value_name = "MS", default_value_t = config::DEFAULT_DEADLINE.as_millis() as u64)]
    deadline_ms: u64,
    /// Largest number of input items one request may send.
    #[arg(long, value_name = "N", default_value_t = config::DEFAULT_MAX_INPUT_ITEMS)]
    max_items: usize,
    /// Largest number of output items one answer may hold.
    #[arg(long, value_name = "N", default_value_t = config::DEFAULT_MAX_OUTPUT_ITEMS)]
    max_output_items: usize,
    /// Solves that may wait for a worker before requests are refused with 503.
    #[arg(long, value_name = "N", default_value_t = config::DEFAULT_QUEUE)]
    queue: usize,
}

/// Runs the server until SIGTERM or ctrl-c.
pub(crate) fn serve(registry: NodeRegistry, args: ServeArgs) -> u8 {
    if args.workers == Some(0) {
        eprintln!("locus: --workers must be at least 1");
        return EXIT_USAGE;
    }
    if let Some(dir) = &args.definitions
        && !dir.is_dir()
    {
        eprintln!("locus: --definitions {} is not a folder", dir.display());
        return EXIT_USAGE;
    }
    let defaults = Config::default();
    let config = Config {
        bind: args.bind,
        workers: args.workers.unwrap_or(defaults.workers),
        definitions: args.definitions,
        token: args.token.filter(|t| !t.is_empty()),
        limits: locus_server::Limits {
            max_body_bytes: args.max_body,
            deadline: std::time::Duration::from_millis(args.deadline_ms),
            max_input_items: args.max_items,
            max_output_items: args.max_output_items,
            queue: args.queue,
        },
        ..defaults
    };
    if !config.bind.ip().is_loopback() && config.token.is_none() {
        eprintln!(
            "locus: warning: serving on {} without --token: anyone who can reach it may run graphs",
            config.bind
        );
    }
    locus_server::init_logging();
    match locus_server::serve(config, registry) {
        Ok(()) => 0,
        Err(e) => {
            eprintln!("locus: cannot serve on {}: {e}", args.bind);
            EXIT_USAGE
        }
    }
}

//! The server's configuration: where it listens, how many solves run at once, and the limits
//! every request gets. Every limit has a documented default (`docs/server.md`).

use std::net::SocketAddr;
use std::path::PathBuf;
use std::time::Duration;

/// The default address: loopback only, Rhino.Compute's usual port.
pub const DEFAULT_BIND: &str = "127.0.0.1:6500";
/// The default body size limit: 50 MiB, as newer Rhino.Compute versions.
pub const DEFAULT_MAX_BODY_BYTES: usize = 50 * 1024 * 1024;
/// The default wall-clock deadline of one request, queueing included.
pub const DEFAULT_DEADLINE: Duration = Duration::from_secs(30);
/// The default largest number of input items one request may send (all trees together).
pub const DEFAULT_MAX_INPUT_ITEMS: usize = 1_000_000;
/// The default largest number of output items one answer may carry (all outputs together).
pub const DEFAULT_MAX_OUTPUT_ITEMS: usize = 5_000_000;
/// The default number of requests that may wait for a worker, beyond those being solved.
pub const DEFAULT_QUEUE: usize = 64;
/// The default number of distinct definitions kept parsed and checked.
pub const DEFAULT_CACHE_ENTRIES: usize = 256;
/// The default number of idle evaluators kept per definition (for incremental re-evaluation).
pub const DEFAULT_EVALUATORS_PER_DEFINITION: usize = 4;

/// Per-request limits.
#[derive(Clone, Debug)]
pub struct Limits {
    /// The largest request body, in bytes (413 beyond).
    pub max_body_bytes: usize,
    /// The wall-clock deadline of one request, from its arrival to its answer (504 beyond).
    pub deadline: Duration,
    /// The largest number of input items a request may send (413 beyond).
    pub max_input_items: usize,
    /// The largest number of output items an answer may hold (500 beyond, naming the output).
    pub max_output_items: usize,
    /// Solves waiting for a worker beyond which requests are refused (503 beyond).
    pub queue: usize,
}

impl Default for Limits {
    fn default() -> Self {
        Self {
            max_body_bytes: DEFAULT_MAX_BODY_BYTES,
            deadline: DEFAULT_DEADLINE,
            max_input_items: DEFAULT_MAX_INPUT_ITEMS,
            max_output_items: DEFAULT_MAX_OUTPUT_ITEMS,
            queue: DEFAULT_QUEUE,
        }
    }
}

/// How the server is set up.
#[derive(Clone, Debug)]
pub struct Config {
    /// The address to listen on.
    pub bind: SocketAddr,
    /// Solves that run at the same time (each on a thread of its own).
    pub workers: usize,
    /// The folder `pointer` may name files in; `None` serves no files.
    pub definitions: Option<PathBuf>,
    /// A bearer token every request except `/healthcheck` must carry; `None` for no auth.
    pub token: Option<String>,
    /// Per-request limits.
    pub limits: Limits,
    /// Distinct definitions kept parsed and checked.
    pub cache_entries: usize,
    /// Idle evaluators kept per definition.
    pub evaluators_per_definition: usize,
}

impl Default for Config {
    fn default() -> Self {
        Self {
            bind: DEFAULT_BIND
                .parse()
                .unwrap_or_else(|_| unreachable!("the default address is valid")),
            workers: std::thread::available_parallelism().map_or(1, usize::from),
            definitions: None,
            token: None,
            limits: Limits::default(),
            cache_entries: DEFAULT_CACHE_ENTRIES,
            evaluators_per_definition: DEFAULT_EVALUATORS_PER_DEFINITION,
        }
    }
}

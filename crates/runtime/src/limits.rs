//! Run limits: what bounds the time, memory and input size of one evaluation, so that a hostile
//! graph or request ends in a clear error instead of a hang or an exhausted machine. Every
//! default is documented in `docs/limits.md`.

use std::io::Read;
use std::path::Path;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Condvar, Mutex, PoisonError};
use std::time::{Duration, Instant};

use crate::NodeId;

/// The largest graph file read by default ([`read_graph_file`]): 64 MiB.
pub const MAX_GRAPH_FILE_BYTES: u64 = 64 << 20;

/// The longest text value a graph may hold (a literal string, a formula, a Path Mapper mask)
/// and the longest literal text [`Evaluator::set_input_text`](crate::Evaluator::set_input_text)
/// reads: 1 MiB.
pub const MAX_TEXT_BYTES: usize = 1 << 20;

/// The default number of entries (items plus branches) one output tree may hold: 10 million.
pub const DEFAULT_MAX_ITEMS_PER_OUTPUT: usize = 10_000_000;

/// The default number of entries (items plus branches) all the outputs of a graph may hold
/// together: 50 million.
pub const DEFAULT_MAX_ITEMS_TOTAL: usize = 50_000_000;

/// Thread counts above this many times the cores are capped to it.
pub const MAX_THREADS_PER_CORE: usize = 4;

/// How often (in iterations) a running node looks at the deadline and the cancellation token.
pub(crate) const CHECK_EVERY: usize = 16;

/// A flag a host sets to stop a running evaluation (from another thread, a signal handler, a
/// request timeout). Clones share the flag.
#[derive(Clone, Debug, Default)]
pub struct CancelToken(Arc<AtomicBool>);

impl CancelToken {
    /// A token not cancelled.
    pub fn new() -> Self {
        Self::default()
    }

    /// Asks every evaluation holding this token to stop; it does within a few milliseconds
    /// (between nodes, and every [`CHECK_EVERY`] iterations inside a node).
    pub fn cancel(&self) {
        self.0.store(true, Ordering::Relaxed);
    }

    /// Whether [`cancel`](Self::cancel) was called.
    pub fn is_cancelled(&self) -> bool {
        self.0.load(Ordering::Relaxed)
    }
}

/// The limits of one evaluator's runs, set with
/// [`Evaluator::set_limits`](crate::Evaluator::set_limits).
#[derive(Clone, Debug)]
pub struct Limits {
    /// The wall-clock time one [`evaluate`](crate::Evaluator::evaluate) may take (default: none).
    pub timeout: Option<Duration>,
    /// A token that stops the evaluation when cancelled (default: none).
    pub cancel: Option<CancelToken>,
    /// The most entries (items plus branches) one output tree may hold. A node whose
    /// iterations would exceed it is an error before anything is allocated.
    pub max_items_per_output: usize,
    /// The most entries (items plus branches) all the nodes' outputs may hold together.
    pub max_items_total: usize,
}

impl Default for Limits {
    fn default() -> Self {
        Self {
            timeout: None,
            cancel: None,
            max_items_per_output: DEFAULT_MAX_ITEMS_PER_OUTPUT,
            max_items_total: DEFAULT_MAX_ITEMS_TOTAL,
        }
    }
}

/// Why an evaluation stopped early or left a node without data.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[non_exhaustive]
pub enum LimitHit {
    /// The wall-clock time limit was reached.
    #[error("the time limit of {} s was reached", .limit.as_secs_f64())]
    Timeout {
        /// The limit.
        limit: Duration,
    },
    /// The cancellation token was cancelled.
    #[error("the evaluation was cancelled")]
    Cancelled,
    /// A node would have produced more items than one output may hold, or than all outputs
    /// may hold together; the node got no outputs.
    #[error("node \"{node}\": {detail}")]
    Items {
        /// The node.
        node: NodeId,
        /// The counts and the limit.
        detail: String,
    },
}

/// The deadline and cancellation of one evaluation. With a timeout, a timer thread raises a
/// flag at the deadline, so that running nodes look at two atomic flags (about a nanosecond)
/// instead of the clock; the thread ends when the watch is dropped.
#[derive(Debug, Default)]
pub(crate) struct Watch {
    timed_out: Arc<AtomicBool>,
    timeout: Option<Duration>,
    cancel: Option<CancelToken>,
    _timer: Option<Timer>,
}

/// The thread that raises the timeout flag.
#[derive(Debug)]
struct Timer {
    done: Arc<(Mutex<bool>, Condvar)>,
    thread: Option<std::thread::JoinHandle<()>>,
}

impl Drop for Timer {
    fn drop(&mut self) {
        let (lock, condvar) = &*self.done;
        *lock.lock().unwrap_or_else(PoisonError::into_inner) = true;
        condvar.notify_all();
        if let Some(thread) = self.thread.take() {
            let _ = thread.join();
        }
    }
}

impl Watch {
    /// The watch for an evaluation starting now.
    pub(crate) fn start(limits: &Limits) -> Self {
        let timed_out = Arc::new(AtomicBool::new(false));
        let timer = limits.timeout.map(|timeout| {
            let done = Arc::new((Mutex::new(false), Condvar::new()));
            let (flag, pair) = (Arc::clone(&timed_out), Arc::clone(&done));
            let started = Instant::now();
            let thread = std::thread::Builder::new()
                .name("locus-deadline".to_owned())
                .spawn(move || {
                    let (lock, condvar) = &*pair;
                    let mut finished = lock.lock().unwrap_or_else(PoisonError::into_inner);
                    while !*finished {
                        let Some(left) = timeout.checked_sub(started.elapsed()) else {
                            flag.store(true, Ordering::Relaxed);
                            return;
                        };
                        finished = condvar
                            .wait_timeout(finished, left)
                            .unwrap_or_else(PoisonError::into_inner)
                            .0;
                    }
                });
            match thread {
                Ok(thread) => Timer {
                    done,
                    thread: Some(thread),
                },
                // No thread for the timer: time out at once rather than run unbounded.
                Err(_) => {
                    timed_out.store(true, Ordering::Relaxed);
                    Timer { done, thread: None }
                }
            }
        });
        Self {
            timed_out,
            timeout: limits.timeout,
            cancel: limits.cancel.clone(),
            _timer: timer,
        }
    }

    /// Whether the evaluation must stop now, and why.
    pub(crate) fn check(&self) -> Option<LimitHit> {
        if self.cancel.as_ref().is_some_and(CancelToken::is_cancelled) {
            return Some(LimitHit::Cancelled);
        }
        if self.timed_out.load(Ordering::Relaxed) {
            return Some(LimitHit::Timeout {
                limit: self.timeout.unwrap_or_default(),
            });
        }
        None
    }
}

/// What a running node needs to know of the limits.
#[derive(Debug)]
pub(crate) struct Budget {
    /// The most entries one output may hold.
    pub(crate) max_items: usize,
    /// The deadline and cancellation.
    pub(crate) watch: Watch,
}

impl Default for Budget {
    fn default() -> Self {
        Self {
            max_items: DEFAULT_MAX_ITEMS_PER_OUTPUT,
            watch: Watch::default(),
        }
    }
}

/// Reads a graph file of at most `max_bytes` bytes as UTF-8 text. Only regular files are read
/// (a FIFO, a device such as `/dev/zero` or a directory is refused without reading), and the
/// read stops after `max_bytes + 1` bytes even if the file grows meanwhile.
///
/// # Errors
/// A message saying what is wrong: not found, not a regular file, too large, not UTF-8.
pub fn read_graph_file(path: &Path, max_bytes: u64) -> Result<String, String> {
    let meta = std::fs::metadata(path).map_err(|e| e.to_string())?;
    if !meta.is_file() {
        let what = if meta.is_dir() {
            "a directory"
        } else {
            "not a regular file (a device, FIFO or socket)"
        };
        return Err(format!("{what}; only regular files are read"));
    }
    if meta.len() > max_bytes {
        return Err(too_large(meta.len(), max_bytes));
    }
    let file = std::fs::File::open(path).map_err(|e| e.to_string())?;
    let mut bytes = Vec::with_capacity(usize::try_from(meta.len()).unwrap_or(0));
    file.take(max_bytes.saturating_add(1))
        .read_to_end(&mut bytes)
        .map_err(|e| e.to_string())?;
    if bytes.len() as u64 > max_bytes {
        return Err(too_large(bytes.len() as u64, max_bytes));
    }
    String::from_utf8(bytes).map_err(|e| format!("not UTF-8 text ({e})"))
}

fn too_large(size: u64, max: u64) -> String {
    format!("the file is too large ({size} bytes; the limit is {max} bytes)")
}

/// The thread count to use for `asked` threads on this machine: at most
/// [`MAX_THREADS_PER_CORE`] × the cores.
pub(crate) fn thread_cap() -> usize {
    let cores = std::thread::available_parallelism().map_or(1, std::num::NonZero::get);
    cores.saturating_mul(MAX_THREADS_PER_CORE)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn refuses_devices_directories_and_large_files() {
        let zero = read_graph_file(Path::new("/dev/zero"), MAX_GRAPH_FILE_BYTES);
        assert!(zero.unwrap_err().starts_with("not a regular file"));
        let dir = read_graph_file(&std::env::temp_dir(), MAX_GRAPH_FILE_BYTES);
        assert!(dir.unwrap_err().starts_with("a directory"));
        let path = std::env::temp_dir().join(format!("locus-limits-{}.ron", std::process::id()));
        std::fs::write(&path, "x".repeat(100)).unwrap();
        assert_eq!(
            read_graph_file(&path, 99).unwrap_err(),
            "the file is too large (100 bytes; the limit is 99 bytes)"
        );
        assert_eq!(read_graph_file(&path, 100).unwrap().len(), 100);
        std::fs::remove_file(&path).ok();
    }

    #[test]
    fn a_cancelled_token_stops_the_watch() {
        let token = CancelToken::new();
        let limits = Limits {
            cancel: Some(token.clone()),
            ..Limits::default()
        };
        let watch = Watch::start(&limits);
        assert_eq!(watch.check(), None);
        token.cancel();
        assert_eq!(watch.check(), Some(LimitHit::Cancelled));
        let limits = Limits {
            timeout: Some(Duration::from_millis(20)),
            ..Limits::default()
        };
        let watch = Watch::start(&limits);
        assert_eq!(watch.check(), None);
        std::thread::sleep(Duration::from_millis(200));
        assert_eq!(
            watch.check(),
            Some(LimitHit::Timeout {
                limit: Duration::from_millis(20)
            })
        );
    }
}

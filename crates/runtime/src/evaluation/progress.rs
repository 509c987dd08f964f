//! Progress of an evaluation, for hosts that show it (the `locus` command draws a progress bar
//! on a terminal): an observer the evaluator tells when an evaluation starts, when each node
//! starts and finishes, and when the evaluation ends.
//!
//! The runtime draws nothing itself. Calls come from the threads that run the nodes (nodes of
//! one wave run in parallel), so an observer is `Send + Sync` and must be cheap: it is called
//! twice per node.

use std::fmt;
use std::sync::Arc;
use std::sync::atomic::{AtomicUsize, Ordering};

/// Told about the progress of each evaluation. Every method has an empty default.
pub trait Progress: Send + Sync {
    /// An evaluation starts that will run `total` nodes (those whose inputs changed).
    fn started(&self, total: usize) {
        let _ = total;
    }

    /// Node `node` starts running.
    fn node_started(&self, node: &str) {
        let _ = node;
    }

    /// Node `node` has finished; `done` of `total` nodes have finished so far.
    fn node_finished(&self, node: &str, done: usize, total: usize) {
        let _ = (node, done, total);
    }

    /// The evaluation has ended (all nodes run, or stopped by a limit).
    fn finished(&self) {}
}

/// The observer an evaluator holds.
#[derive(Clone)]
pub(crate) struct ProgressHook(pub(crate) Arc<dyn Progress>);

impl fmt::Debug for ProgressHook {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("ProgressHook")
    }
}

/// The count of one evaluation, shared by the threads that run its nodes.
pub(crate) struct Tracker<'a> {
    hook: Option<&'a dyn Progress>,
    done: AtomicUsize,
    total: usize,
}

impl<'a> Tracker<'a> {
    /// Starts counting an evaluation of `total` nodes.
    pub(crate) fn start(hook: Option<&'a ProgressHook>, total: usize) -> Self {
        let hook = hook.map(|h| &*h.0);
        if let Some(h) = hook {
            h.started(total);
        }
        Self {
            hook,
            done: AtomicUsize::new(0),
            total,
        }
    }

    /// Runs `f` as node `node`, telling the observer before and after.
    pub(crate) fn node<T>(&self, node: &str, f: impl FnOnce() -> T) -> T {
        let Some(h) = self.hook else {
            return f();
        };
        h.node_started(node);
        let res = f();
        let done = self.done.fetch_add(1, Ordering::Relaxed) + 1;
        h.node_finished(node, done, self.total);
        res
    }
}

impl Drop for Tracker<'_> {
    fn drop(&mut self) {
        if let Some(h) = self.hook {
            h.finished();
        }
    }
}

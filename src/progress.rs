//! The progress bar of `locus run`, `render` and `view`: nodes done of the nodes to run and the
//! node running now, drawn on stderr with indicatif, only when stderr is a terminal, only once a
//! run has taken longer than [`SHOW_AFTER`], and never with `--quiet`. It is the runtime's
//! [`Progress`] observer; the runtime itself draws nothing.

use std::io::IsTerminal;
use std::sync::{Arc, Mutex};
use std::time::Duration;

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use locus_runtime::{Evaluator, Progress};

/// How long a run goes before its progress bar appears: one second.
pub(crate) const SHOW_AFTER: Duration = Duration::from_secs(1);

/// How often a visible bar is redrawn while a long node runs (its elapsed time moves on).
const TICK: Duration = Duration::from_millis(100);

/// Gives the evaluator a terminal progress bar unless `quiet` or stderr is not a terminal.
pub(crate) fn attach(evaluator: &mut Evaluator, quiet: bool) {
    if !quiet && std::io::stderr().is_terminal() {
        evaluator.set_progress(Some(Arc::new(TerminalProgress::default())));
    }
}

/// A progress bar per evaluation, hidden until [`SHOW_AFTER`] has passed, and whether that
/// evaluation has ended (under one lock with the watcher that shows the bar, so that a bar
/// cleared at the end is never shown after it).
#[derive(Default)]
struct TerminalProgress {
    bar: Mutex<Option<(ProgressBar, Arc<Mutex<bool>>)>>,
}

impl TerminalProgress {
    fn with_bar(&self, f: impl FnOnce(&ProgressBar)) {
        if let Some((bar, _)) = self.bar.lock().unwrap_or_else(|e| e.into_inner()).as_ref() {
            f(bar);
        }
    }
}

impl Progress for TerminalProgress {
    fn started(&self, total: usize) {
        let bar = ProgressBar::with_draw_target(Some(total as u64), ProgressDrawTarget::hidden());
        let style = ProgressStyle::with_template(
            "{spinner} [{elapsed_precise}] {bar:30} {pos}/{len} nodes · {wide_msg}",
        )
        .unwrap_or_else(|_| ProgressStyle::default_bar());
        bar.set_style(style);
        // A watcher shows the bar once the run has lasted SHOW_AFTER, even while one long node
        // runs and nothing else happens; a run that ends first never draws anything.
        let ended = Arc::new(Mutex::new(false));
        let (watched, watched_ended) = (bar.clone(), ended.clone());
        std::thread::spawn(move || {
            std::thread::sleep(SHOW_AFTER);
            let ended = watched_ended.lock().unwrap_or_else(|e| e.into_inner());
            if !*ended {
                watched.set_draw_target(ProgressDrawTarget::stderr());
                watched.enable_steady_tick(TICK);
            }
        });
        *self.bar.lock().unwrap_or_else(|e| e.into_inner()) = Some((bar, ended));
    }

    fn node_started(&self, node: &str) {
        self.with_bar(|bar| bar.set_message(node.to_owned()));
    }

    fn node_finished(&self, _node: &str, done: usize, _total: usize) {
        self.with_bar(|bar| bar.set_position(done as u64));
    }

    fn finished(&self) {
        if let Some((bar, ended)) = self.bar.lock().unwrap_or_else(|e| e.into_inner()).take() {
            *ended.lock().unwrap_or_else(|e| e.into_inner()) = true;
            bar.finish_and_clear();
        }
    }
}

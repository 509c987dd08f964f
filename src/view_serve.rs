//! `locus view --serve`: the viewer page of a graph served on 127.0.0.1, evaluated again each
//! time the graph file changes (the page reloads itself and keeps its camera).
//!
//! The file is watched by polling its modification time and length every [`WATCH_INTERVAL`]:
//! it works the same on every file system (network mounts and editors that save by renaming
//! included) and needs no platform watcher. A change is evaluated once the file has stayed the
//! same for one interval, so a save in progress is not read half written. While the file is
//! missing (between an editor's delete and rename) the last page stays. A graph that cannot be
//! read or checked gives a page with an empty scene and the problems as its messages; the page
//! stays live, so fixing the file brings the geometry back.

use std::net::{Ipv4Addr, SocketAddr};
use std::path::Path;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::{Duration, SystemTime};

use locus_export::Scene;
use locus_runtime::NodeRegistry;
use locus_server::LivePage;
use serde_json::Value as Json;

use crate::graph_file::{RunLimits, prepare};

/// How often the graph file is looked at: 250 ms.
pub(crate) const WATCH_INTERVAL: Duration = Duration::from_millis(250);

/// What the watcher compares: the file's modification time and length (`None` while missing).
type Stamp = Option<(Option<SystemTime>, u64)>;

fn stamp(path: &Path) -> Stamp {
    std::fs::metadata(path)
        .ok()
        .map(|m| (m.modified().ok(), m.len()))
}

/// What the page is built from.
struct Source<'a> {
    registry: &'a NodeRegistry,
    graph: &'a Path,
    sets: &'a [String],
    threads: Option<usize>,
    limits: &'a RunLimits,
    title: String,
}

impl Source<'_> {
    /// Evaluates the graph and builds its live page, numbered `generation`. Also says on
    /// stderr what happened.
    fn page(&self, generation: u64) -> String {
        let (scene, messages) = match prepare(
            self.registry,
            self.graph,
            self.sets,
            self.threads,
            self.limits,
        ) {
            Ok(mut evaluator) => {
                evaluator.evaluate();
                let scene = crate::export::scene(&evaluator, self.limits);
                let messages: Vec<Json> = evaluator
                    .messages()
                    .map(crate::render::message_json)
                    .collect();
                eprintln!(
                    "locus: {}: evaluated (generation {generation}, {} message{})",
                    self.graph.display(),
                    messages.len(),
                    if messages.len() == 1 { "" } else { "s" }
                );
                (scene, messages)
            }
            Err(refusal) => {
                let file = self.graph.display().to_string();
                let messages = refusal
                    .lines
                    .iter()
                    .map(|line| serde_json::json!({ "level": "error", "node": file, "text": line }))
                    .collect();
                refusal.report();
                (Scene::new(), messages)
            }
        };
        let messages = Json::Array(messages);
        locus_export::to_live_html(&scene, &messages, &self.title, generation).unwrap_or_else(
            |e| {
                eprintln!("locus: {e}");
                let problem = serde_json::json!([{ "level": "error", "node": self.title, "text": e.to_string() }]);
                locus_export::to_live_html(&Scene::new(), &problem, &self.title, generation)
                    .unwrap_or_default()
            },
        )
    }
}

/// Watches the graph file until `stop`, publishing a new page after each change. `shown` is
/// the file's stamp from before the page served now was read.
fn watch(source: &Source<'_>, live: &LivePage, stop: &AtomicBool, mut shown: Stamp) {
    let mut last_seen = shown;
    while !stop.load(Ordering::Acquire) {
        std::thread::sleep(WATCH_INTERVAL);
        let now = stamp(source.graph);
        let settled = now == last_seen;
        last_seen = now;
        if settled && now.is_some() && now != shown {
            shown = now;
            live.publish(|generation| source.page(generation));
        }
    }
}

/// `locus view GRAPH --serve`: serves the page on 127.0.0.1:`port` (0: any free port, printed
/// on stdout as `http://127.0.0.1:PORT/`) until ctrl-c or SIGTERM.
pub(crate) fn serve(
    registry: &NodeRegistry,
    graph: &Path,
    sets: &[String],
    threads: Option<usize>,
    limits: &RunLimits,
    port: u16,
) -> u8 {
    let source = Source {
        registry,
        graph,
        sets,
        threads,
        limits,
        title: graph
            .file_stem()
            .map(|s| s.to_string_lossy().into_owned())
            .unwrap_or_default(),
    };
    // Stamped before the first reading, so that a change made while it is evaluated is seen.
    let first = stamp(graph);
    let live = Arc::new(LivePage::new(|generation| source.page(generation)));
    let stop = AtomicBool::new(false);
    let served = std::thread::scope(|scope| {
        scope.spawn(|| watch(&source, &live, &stop, first));
        let served = locus_server::serve_live_page(
            SocketAddr::from((Ipv4Addr::LOCALHOST, port)),
            Arc::clone(&live),
            |addr| {
                use std::io::Write as _;
                println!("http://{addr}/");
                let _ = std::io::stdout().flush();
                eprintln!(
                    "locus: serving {} on http://{addr}/ (ctrl-c stops)",
                    graph.display()
                );
            },
        );
        stop.store(true, Ordering::Release);
        served
    });
    match served {
        Ok(()) => 0,
        Err(e) => {
            eprintln!("locus: cannot serve on 127.0.0.1:{port}: {e}");
            crate::EXIT_USAGE
        }
    }
}

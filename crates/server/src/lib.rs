//! `locus serve`: an HTTP solver service for locus graphs, wire-compatible with Rhino.Compute's
//! Grasshopper endpoints (`/grasshopper`, `/solve`, `/io`), with locus's own `/v1/run`.
//!
//! Built on axum and tokio. Solves run on a bounded pool of blocking threads with a queue
//! ([`pool`]); definitions are read and checked once and cached by content hash, with idle
//! evaluators kept per definition for incremental re-evaluation ([`cache`]); every request has
//! limits ([`Limits`]). `docs/server.md` documents the endpoints, the schema mapping, the
//! limits and deployment. [`live`] is the small page server of `locus view --serve`.
//!
//! ```no_run
//! let mut registry = locus_runtime::NodeRegistry::new();
//! // locus_nodes::register(&mut registry);
//! let server = locus_server::Server::start(locus_server::Config::default(), registry).unwrap();
//! println!("listening on {}", server.addr());
//! server.stop();
//! ```

pub mod archive;
pub mod cache;
pub mod compute;
pub mod compute_items;
pub mod config;
pub mod definition;
pub mod error;
pub mod http;
pub mod live;
pub mod native;
pub mod openapi;
pub mod pool;
pub mod state;

use std::net::SocketAddr;

pub use config::{Config, Limits};
pub use live::{LivePage, serve_live_page};
use locus_runtime::NodeRegistry;
pub use state::State;
use tokio::sync::oneshot;

/// Serves until SIGTERM or ctrl-c, then finishes the requests in flight and returns.
/// Prints `listening on http://ADDR` on stdout once the socket is bound.
///
/// # Errors
/// When the address cannot be bound or the runtime cannot start.
pub fn serve(config: Config, registry: NodeRegistry) -> std::io::Result<()> {
    let runtime = tokio::runtime::Builder::new_multi_thread()
        .enable_all()
        .build()?;
    runtime.block_on(async move {
        let listener = tokio::net::TcpListener::bind(config.bind).await?;
        let addr = listener.local_addr()?;
        tracing::info!(%addr, workers = config.workers, "locus serve started");
        println!("listening on http://{addr}");
        let app = http::router(State::new(config, registry));
        axum::serve(listener, app)
            .with_graceful_shutdown(shutdown_signal())
            .await?;
        tracing::info!("locus serve stopped");
        Ok(())
    })
}

/// Resolves on ctrl-c or (on Unix) SIGTERM.
pub(crate) async fn shutdown_signal() {
    let ctrl_c = async {
        let _ = tokio::signal::ctrl_c().await;
    };
    #[cfg(unix)]
    let term = async {
        match tokio::signal::unix::signal(tokio::signal::unix::SignalKind::terminate()) {
            Ok(mut s) => {
                s.recv().await;
            }
            Err(_) => std::future::pending::<()>().await,
        }
    };
    #[cfg(not(unix))]
    let term = std::future::pending::<()>();
    tokio::select! {
        () = ctrl_c => {},
        () = term => {},
    }
    tracing::info!("shutting down: finishing requests in flight");
}

/// Installs the request log (tracing to stderr; `RUST_LOG` filters, default `info`).
pub fn init_logging() {
    let filter = tracing_subscriber::EnvFilter::try_from_default_env()
        .unwrap_or_else(|_| tracing_subscriber::EnvFilter::new("info"));
    let _ = tracing_subscriber::fmt()
        .with_env_filter(filter)
        .with_writer(std::io::stderr)
        .with_ansi(std::io::IsTerminal::is_terminal(&std::io::stderr()))
        .try_init();
}

/// A server running on a thread of its own (for tests and embedding hosts).
#[derive(Debug)]
pub struct Server {
    addr: SocketAddr,
    stop: Option<oneshot::Sender<()>>,
    thread: Option<std::thread::JoinHandle<std::io::Result<()>>>,
}

impl Server {
    /// Binds `config.bind` (port 0 picks a free port) and serves on a new thread.
    ///
    /// # Errors
    /// When the address cannot be bound.
    pub fn start(config: Config, registry: NodeRegistry) -> std::io::Result<Self> {
        let listener = std::net::TcpListener::bind(config.bind)?;
        listener.set_nonblocking(true)?;
        let addr = listener.local_addr()?;
        let (stop, stopped) = oneshot::channel::<()>();
        let thread = std::thread::spawn(move || {
            let runtime = tokio::runtime::Builder::new_multi_thread()
                .worker_threads(2)
                .enable_all()
                .build()?;
            runtime.block_on(async move {
                let listener = tokio::net::TcpListener::from_std(listener)?;
                let app = http::router(State::new(config, registry));
                axum::serve(listener, app)
                    .with_graceful_shutdown(async {
                        let _ = stopped.await;
                    })
                    .await
            })
        });
        Ok(Self {
            addr,
            stop: Some(stop),
            thread: Some(thread),
        })
    }

    /// The address the server listens on.
    pub fn addr(&self) -> SocketAddr {
        self.addr
    }

    /// Stops accepting, finishes requests in flight and waits for the thread.
    pub fn stop(mut self) {
        self.shutdown();
    }

    fn shutdown(&mut self) {
        if let Some(stop) = self.stop.take() {
            let _ = stop.send(());
        }
        if let Some(thread) = self.thread.take() {
            let _ = thread.join();
        }
    }
}

impl Drop for Server {
    fn drop(&mut self) {
        self.shutdown();
    }
}

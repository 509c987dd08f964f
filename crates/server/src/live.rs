//! A page that changes while it is served: `locus view --serve` shows the viewer page of a graph
//! on loopback and publishes a new page each time the graph file changes.
//!
//! Two routes: `GET /` answers the newest page (`text/html`, never cached), `GET /generation`
//! the number of the evaluation it shows (`text/plain`). A page asks for `generation` twice a
//! second and reloads when the number is no longer its own (`crates/export/viewer`). Pages are
//! built by the caller, outside any lock; a request always gets a whole page.

use std::net::SocketAddr;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::{Arc, RwLock};

use axum::Router;
use axum::extract::State as AxumState;
use axum::http::{HeaderValue, StatusCode, header};
use axum::response::{IntoResponse, Response};
use axum::routing::get;

/// The newest page and its generation (1 for the first page, one more for each published).
#[derive(Debug)]
pub struct LivePage {
    page: RwLock<Arc<str>>,
    generation: AtomicU64,
}

impl LivePage {
    /// A live page whose first page, generation 1, `build` makes.
    pub fn new(build: impl FnOnce(u64) -> String) -> Self {
        LivePage {
            page: RwLock::new(build(1).into()),
            generation: AtomicU64::new(1),
        }
    }

    /// The generation of the page served now.
    pub fn generation(&self) -> u64 {
        self.generation.load(Ordering::Acquire)
    }

    /// The page served now.
    pub fn page(&self) -> Arc<str> {
        // A writer that panicked left a whole page behind (it only ever stores whole pages).
        self.page
            .read()
            .unwrap_or_else(std::sync::PoisonError::into_inner)
            .clone()
    }

    /// Builds the next page with its generation number (before anything is replaced, so
    /// readers keep the old page meanwhile), then serves it. Returns the new generation. Meant
    /// for one publisher at a time.
    pub fn publish(&self, build: impl FnOnce(u64) -> String) -> u64 {
        let next = self.generation() + 1;
        let page: Arc<str> = build(next).into();
        *self
            .page
            .write()
            .unwrap_or_else(std::sync::PoisonError::into_inner) = page;
        self.generation.store(next, Ordering::Release);
        next
    }
}

/// The routes of a live page.
pub fn router(live: Arc<LivePage>) -> Router {
    Router::new()
        .route("/", get(page))
        .route("/generation", get(generation))
        .with_state(live)
}

fn no_store(mut response: Response) -> Response {
    response
        .headers_mut()
        .insert(header::CACHE_CONTROL, HeaderValue::from_static("no-store"));
    response
}

async fn page(AxumState(live): AxumState<Arc<LivePage>>) -> Response {
    let page = live.page();
    no_store(
        (
            StatusCode::OK,
            [(header::CONTENT_TYPE, "text/html; charset=utf-8")],
            page.to_string(),
        )
            .into_response(),
    )
}

async fn generation(AxumState(live): AxumState<Arc<LivePage>>) -> Response {
    no_store(
        (
            StatusCode::OK,
            [(header::CONTENT_TYPE, "text/plain; charset=utf-8")],
            live.generation().to_string(),
        )
            .into_response(),
    )
}

/// Serves `live` on `bind` until SIGTERM or ctrl-c. `bound` is told the address once the
/// socket is bound (port 0 picks a free one).
///
/// # Errors
/// When the address cannot be bound or the runtime cannot start.
pub fn serve_live_page(
    bind: SocketAddr,
    live: Arc<LivePage>,
    bound: impl FnOnce(SocketAddr),
) -> std::io::Result<()> {
    let runtime = tokio::runtime::Builder::new_current_thread()
        .enable_all()
        .build()?;
    runtime.block_on(async move {
        let listener = tokio::net::TcpListener::bind(bind).await?;
        bound(listener.local_addr()?);
        axum::serve(listener, router(live))
            .with_graceful_shutdown(crate::shutdown_signal())
            .await
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn publishing_numbers_the_pages() {
        let live = LivePage::new(|g| format!("page {g}"));
        assert_eq!((live.generation(), &*live.page()), (1, "page 1"));
        assert_eq!(live.publish(|g| format!("page {g}")), 2);
        assert_eq!((live.generation(), &*live.page()), (2, "page 2"));
    }

    #[test]
    fn a_page_is_kept_while_the_next_is_built() {
        let live = LivePage::new(|_| "old".to_owned());
        live.publish(|_| {
            assert_eq!(&*live.page(), "old");
            assert_eq!(live.generation(), 1);
            "new".to_owned()
        });
        assert_eq!(&*live.page(), "new");
    }
}

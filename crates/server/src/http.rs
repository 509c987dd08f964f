//! Routes, the bearer-token check, body reading with the size limit, and JSON answers.

use std::sync::Arc;

use axum::Router;
use axum::body::{Body, Bytes};
use axum::extract::{Request, State as Axum};
use axum::http::{StatusCode, header};
use axum::middleware::{self, Next};
use axum::response::{IntoResponse, Response};
use axum::routing::{get, post};
use serde_json::{Value as Json, json};
use tokio::time::Instant;
use tower_http::trace::{DefaultMakeSpan, DefaultOnResponse, TraceLayer};
use tracing::Level;

use crate::error::ApiError;
use crate::state::State;
use crate::{compute, native, openapi};

/// The application: every route with its middleware.
pub fn router(state: Arc<State>) -> Router {
    Router::new()
        .route("/healthcheck", get(|| async { "Healthy" }))
        .route("/version", get(version))
        .route(
            "/openapi.json",
            get(|| async { axum::Json(openapi::document()) }),
        )
        .route("/grasshopper", post(grasshopper))
        .route("/solve", post(grasshopper))
        .route("/io", post(io))
        .route("/v1/run", post(run))
        .fallback(not_found)
        .method_not_allowed_fallback(method_not_allowed)
        .layer(middleware::from_fn_with_state(state.clone(), authorize))
        .layer(
            TraceLayer::new_for_http()
                .make_span_with(DefaultMakeSpan::new().level(Level::INFO))
                .on_response(DefaultOnResponse::new().level(Level::INFO)),
        )
        .with_state(state)
}

async fn version() -> axum::Json<Json> {
    axum::Json(json!({
        "rhino": null,
        "compute": env!("CARGO_PKG_VERSION"),
        "git_sha": option_env!("LOCUS_GIT_SHA"),
        "locus": env!("CARGO_PKG_VERSION"),
    }))
}

async fn not_found(request: Request) -> ApiError {
    ApiError::new(
        StatusCode::NOT_FOUND,
        "not_found",
        format!("no endpoint {}", request.uri().path()),
    )
}

async fn method_not_allowed(request: Request) -> ApiError {
    ApiError::new(
        StatusCode::METHOD_NOT_ALLOWED,
        "method_not_allowed",
        format!(
            "{} is not allowed on {}",
            request.method(),
            request.uri().path()
        ),
    )
}

/// Refuses requests without the configured token (`Authorization: Bearer T`, or Compute's
/// `RhinoComputeKey: T`), except the health check.
async fn authorize(Axum(state): Axum<Arc<State>>, request: Request, next: Next) -> Response {
    if let Some(token) = &state.config.token
        && request.uri().path() != "/healthcheck"
    {
        let headers = request.headers();
        let bearer = headers
            .get(header::AUTHORIZATION)
            .and_then(|v| v.to_str().ok())
            .and_then(|v| v.strip_prefix("Bearer "));
        let key = headers.get("RhinoComputeKey").and_then(|v| v.to_str().ok());
        let ok = [bearer, key]
            .into_iter()
            .flatten()
            .any(|given| constant_time_eq(given.trim().as_bytes(), token.as_bytes()));
        if !ok {
            return ApiError::new(
                StatusCode::UNAUTHORIZED,
                "unauthorized",
                "this server needs a token: send \"Authorization: Bearer TOKEN\"",
            )
            .into_response();
        }
    }
    next.run(request).await
}

fn constant_time_eq(a: &[u8], b: &[u8]) -> bool {
    a.len() == b.len() && a.iter().zip(b).fold(0u8, |acc, (x, y)| acc | (x ^ y)) == 0
}

/// Reads the body up to the size limit.
async fn read_body(state: &State, body: Body) -> Result<Bytes, ApiError> {
    let max = state.config.limits.max_body_bytes;
    axum::body::to_bytes(body, max).await.map_err(|e| {
        let too_large = std::error::Error::source(&e)
            .is_some_and(|s| s.is::<http_body_util::LengthLimitError>())
            || e.to_string().contains("length limit");
        if too_large {
            ApiError::too_large(format!("the body is larger than {max} bytes (the limit)"))
        } else {
            ApiError::bad_request(format!("cannot read the body: {e}"))
        }
    })
}

/// Reads the body and runs `job` on it on a worker, within the request's deadline.
async fn on_worker(
    state: Arc<State>,
    request: Request,
    job: fn(&State, &[u8]) -> Result<Json, ApiError>,
) -> Result<axum::Json<Json>, ApiError> {
    let start = Instant::now();
    let deadline = state.config.limits.deadline;
    if let Some(len) = request
        .headers()
        .get(header::CONTENT_LENGTH)
        .and_then(|v| v.to_str().ok())
        .and_then(|v| v.parse::<u64>().ok())
        && len > state.config.limits.max_body_bytes as u64
    {
        return Err(ApiError::too_large(format!(
            "the body is larger than {} bytes (the limit)",
            state.config.limits.max_body_bytes
        )));
    }
    let body = tokio::time::timeout_at(start + deadline, read_body(&state, request.into_body()))
        .await
        .map_err(|_| {
            ApiError::new(
                StatusCode::REQUEST_TIMEOUT,
                "deadline",
                "the body did not arrive before the request's deadline",
            )
        })??;
    let shared = state.clone();
    state
        .pool
        .run(start, deadline, move || job(&shared, &body))
        .await
        .map(axum::Json)
}

async fn grasshopper(Axum(state): Axum<Arc<State>>, request: Request) -> Response {
    on_worker(state, request, compute::solve)
        .await
        .into_response()
}

async fn io(Axum(state): Axum<Arc<State>>, request: Request) -> Response {
    on_worker(state, request, compute::io).await.into_response()
}

async fn run(Axum(state): Axum<Arc<State>>, request: Request) -> Response {
    on_worker(state, request, native::run).await.into_response()
}

//! What every request shares: the registry, the configuration, the definitions cache and the
//! worker pool; and finding the definition a request names (`algo` or `pointer`).

use std::path::{Component, Path};
use std::sync::Arc;

use base64::Engine as _;
use locus_runtime::NodeRegistry;

use crate::cache::{Cache, Entry};
use crate::config::Config;
use crate::definition::{self, DefinitionError};
use crate::error::ApiError;
use crate::pool::Pool;

/// The server's shared state.
#[derive(Debug)]
pub struct State {
    /// The node types definitions may use.
    pub registry: NodeRegistry,
    /// The configuration.
    pub config: Config,
    /// Definitions by pointer.
    pub cache: Cache,
    /// The solve workers.
    pub pool: Pool,
}

impl State {
    /// The state for a configuration.
    pub fn new(config: Config, registry: NodeRegistry) -> Arc<Self> {
        Arc::new(Self {
            registry,
            cache: Cache::new(config.cache_entries, config.evaluators_per_definition),
            pool: Pool::new(config.workers, config.limits.queue),
            config,
        })
    }

    /// The definition a request names: `algo` (base64 of the file) wins over `pointer` (a
    /// cached definition's key or a file under `--definitions`).
    ///
    /// # Errors
    /// 400 for bad base64, definitions that do not check and pointers that are not allowed;
    /// 500 for a pointer that is neither cached nor a file (as Rhino.Compute answers).
    pub fn resolve(
        &self,
        algo: Option<&str>,
        pointer: Option<&str>,
    ) -> Result<Arc<Entry>, ApiError> {
        if let Some(algo) = algo.filter(|a| !a.trim().is_empty()) {
            let algo = algo.trim();
            let key = definition::pointer_of_algo(algo);
            if let Some(entry) = self.cache.get(&key) {
                return Ok(entry);
            }
            let bytes = base64::engine::general_purpose::STANDARD
                .decode(algo)
                .map_err(|e| ApiError::bad_request(format!("\"algo\" is not base64: {e}")))?;
            return self.load(&bytes, key);
        }
        let Some(pointer) = pointer.filter(|p| !p.trim().is_empty()) else {
            return Err(ApiError::bad_request(
                "the request names no definition: send \"algo\" (base64 of the file) or \"pointer\"",
            ));
        };
        if let Some(entry) = self.cache.get(pointer) {
            return Ok(entry);
        }
        if pointer.starts_with("md5_") {
            return Err(ApiError::new(
                axum::http::StatusCode::INTERNAL_SERVER_ERROR,
                "unknown_pointer",
                format!("unknown pointer \"{pointer}\": send the definition again in \"algo\""),
            ));
        }
        let bytes = self.read_definition_file(pointer)?;
        let key = definition::pointer_of_bytes(&bytes);
        if let Some(entry) = self.cache.get(&key) {
            return Ok(entry);
        }
        self.load(&bytes, key)
    }

    fn load(&self, bytes: &[u8], key: String) -> Result<Arc<Entry>, ApiError> {
        match definition::load(bytes, key, &self.registry) {
            Ok(d) => Ok(self.cache.insert(d)),
            Err(e @ (DefinitionError::Unsupported(_) | DefinitionError::Invalid(_))) => {
                Err(ApiError::new(
                    axum::http::StatusCode::BAD_REQUEST,
                    "bad_definition",
                    e.to_string(),
                ))
            }
        }
    }

    /// Reads a file named by a pointer, refusing anything outside `--definitions`.
    fn read_definition_file(&self, pointer: &str) -> Result<Vec<u8>, ApiError> {
        let refuse = |why: &str| {
            ApiError::new(
                axum::http::StatusCode::BAD_REQUEST,
                "bad_pointer",
                format!("pointer \"{pointer}\" is refused: {why}"),
            )
        };
        let Some(root) = &self.config.definitions else {
            return Err(ApiError::new(
                axum::http::StatusCode::INTERNAL_SERVER_ERROR,
                "unknown_pointer",
                format!(
                    "unknown pointer \"{pointer}\" (this server serves no definitions folder): \
                     send the definition in \"algo\""
                ),
            ));
        };
        if pointer.contains("://") {
            return Err(refuse("definitions are not fetched from URLs"));
        }
        let relative = Path::new(pointer);
        if relative
            .components()
            .any(|c| !matches!(c, Component::Normal(_) | Component::CurDir))
        {
            return Err(refuse(
                "it must be a relative path inside the definitions folder",
            ));
        }
        let root = root.canonicalize().map_err(|e| {
            ApiError::internal(format!("the definitions folder is not usable: {e}"))
        })?;
        let path = root.join(relative);
        let Ok(path) = path.canonicalize() else {
            return Err(ApiError::new(
                axum::http::StatusCode::NOT_FOUND,
                "not_found",
                format!("no definition \"{pointer}\" in the definitions folder"),
            ));
        };
        // A symbolic link may still lead outside the folder.
        if !path.starts_with(&root) {
            return Err(refuse("it leads outside the definitions folder"));
        }
        let meta = std::fs::metadata(&path).map_err(|e| ApiError::internal(e.to_string()))?;
        if !meta.is_file() {
            return Err(refuse("it is not a file"));
        }
        if meta.len() > self.config.limits.max_body_bytes as u64 {
            return Err(ApiError::too_large(format!(
                "definition \"{pointer}\" is larger than {} bytes",
                self.config.limits.max_body_bytes
            )));
        }
        std::fs::read(&path)
            .map_err(|e| ApiError::internal(format!("cannot read \"{pointer}\": {e}")))
    }
}

//! Locating the shared reference data (`shared/oracle/...`) from the kernel's integration tests.
//!
//! The data lives outside the repository: at `/work/shared` on the development machine, and in a
//! `shared/` directory cloned beside the repository in CI. Both are found by walking up from the
//! kernel's manifest directory and taking the first ancestor that has `shared/oracle` in it.

use std::path::{Path, PathBuf};

/// The `shared` directory that holds `oracle/`.
///
/// # Panics
/// With a message naming where it looked when no ancestor of `CARGO_MANIFEST_DIR` has a
/// `shared/oracle` directory: the test cannot run without its reference data.
pub fn shared_dir() -> PathBuf {
    let manifest_dir = Path::new(env!("CARGO_MANIFEST_DIR"));
    manifest_dir
        .ancestors()
        .map(|dir| dir.join("shared"))
        .find(|shared| shared.join("oracle").is_dir())
        .unwrap_or_else(|| {
            panic!(
                "no `shared/oracle` directory in {} or any directory above it; the reference \
                 data must be checked out as `shared/` beside the repository",
                manifest_dir.display()
            )
        })
}

/// The parsed JSON of `shared/oracle/<file_name>`.
///
/// # Panics
/// When the file is missing or is not valid JSON, with the path in the message.
pub fn read_oracle(file_name: &str) -> serde_json::Value {
    let path = shared_dir().join("oracle").join(file_name);
    let text = std::fs::read_to_string(&path)
        .unwrap_or_else(|err| panic!("cannot read {}: {err}", path.display()));
    serde_json::from_str(&text)
        .unwrap_or_else(|err| panic!("{} is not valid JSON: {err}", path.display()))
}

//! Test support: where the reference data that the tests replay lives, and reading it.
//!
//! The oracle files (values computed by openNURBS and OpenCASCADE, see
//! `tests/data/oracle/README.md`) are checked into the repository under `tests/data/oracle/`, so
//! that a fresh clone passes `cargo test --workspace` with nothing beside it. They are a copy of
//! the team's shared reference data (`shared/oracle/` beside the repository); the test
//! `the_checked_in_oracle_is_the_shared_one` below fails when the two differ, so a change to the
//! shared data is noticed and copied in.
//!
//! Every test that reads oracle data goes through [`oracle_dir`] or [`load_oracle`]: the kernel's
//! oracle replays, the node library's curve and B-rep tests.

use std::path::{Path, PathBuf};

use serde_json::Value;

/// The repository's root folder (two levels above this crate).
pub fn repository_root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .ancestors()
        .nth(2)
        .expect("crates/test-data sits two levels below the repository root")
        .to_path_buf()
}

/// The checked-in oracle folder, `tests/data/oracle/` of the repository.
pub fn oracle_dir() -> PathBuf {
    repository_root().join("tests").join("data").join("oracle")
}

/// The folder of reference values this repository generates itself with the scripts in
/// `tools/oracle/` (`tests/data/generated/`, see its README): checked in as generated, not
/// compared with the shared oracle.
pub fn generated_dir() -> PathBuf {
    repository_root()
        .join("tests")
        .join("data")
        .join("generated")
}

/// Reads one oracle file (`opennurbs-cases.json`, `occt-cases.json`, `ops-cases.json`) as JSON.
///
/// # Panics
///
/// When the file is missing or is not JSON: the tests that call this cannot run without it.
pub fn load_oracle(file: &str) -> Value {
    let path = oracle_dir().join(file);
    let text = std::fs::read_to_string(&path)
        .unwrap_or_else(|e| panic!("cannot read {}: {e}", path.display()));
    serde_json::from_str(&text).unwrap_or_else(|e| panic!("cannot parse {}: {e}", path.display()))
}

/// The shared reference data's oracle folder (`shared/oracle/` beside the repository or one of
/// its ancestors), when it exists: the development layout has it, a fresh clone does not.
pub fn shared_oracle_dir() -> Option<PathBuf> {
    let root = repository_root();
    root.ancestors()
        .skip(1)
        .map(|d| d.join("shared").join("oracle"))
        .find(|d| d.join("README.md").is_file())
}

/// The differences between two folders' files (names and bytes; sub-folders are not expected),
/// as readable lines; empty when they hold the same files with the same contents.
pub fn folder_differences(ours: &Path, theirs: &Path) -> Vec<String> {
    let names = |dir: &Path| -> Result<Vec<String>, String> {
        let mut names = Vec::new();
        for entry in std::fs::read_dir(dir).map_err(|e| format!("{}: {e}", dir.display()))? {
            let entry = entry.map_err(|e| format!("{}: {e}", dir.display()))?;
            names.push(entry.file_name().to_string_lossy().into_owned());
        }
        names.sort();
        Ok(names)
    };
    let (a, b) = match (names(ours), names(theirs)) {
        (Ok(a), Ok(b)) => (a, b),
        (Err(e), _) | (_, Err(e)) => return vec![format!("cannot list {e}")],
    };
    let mut out = Vec::new();
    for name in a.iter().filter(|n| !b.contains(n)) {
        out.push(format!("{name}: only in {}", ours.display()));
    }
    for name in b.iter().filter(|n| !a.contains(n)) {
        out.push(format!("{name}: only in {}", theirs.display()));
    }
    for name in a.iter().filter(|n| b.contains(n)) {
        match (
            std::fs::read(ours.join(name)),
            std::fs::read(theirs.join(name)),
        ) {
            (Ok(x), Ok(y)) if x == y => {}
            (Ok(_), Ok(_)) => out.push(format!("{name}: contents differ")),
            (Err(e), _) | (_, Err(e)) => out.push(format!("{name}: cannot read: {e}")),
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_checked_in_oracle_is_the_shared_one() {
        let Some(shared) = shared_oracle_dir() else {
            // A fresh clone: nothing to compare with, and nothing needed.
            return;
        };
        let differences = folder_differences(&oracle_dir(), &shared);
        assert!(
            differences.is_empty(),
            "tests/data/oracle/ differs from {}; copy it in again:\n  {}",
            shared.display(),
            differences.join("\n  ")
        );
    }

    #[test]
    fn every_oracle_file_reads() {
        for file in ["opennurbs-cases.json", "occt-cases.json", "ops-cases.json"] {
            assert!(load_oracle(file).is_object(), "{file}");
        }
        assert!(oracle_dir().join("README.md").is_file());
    }

    #[test]
    fn differences_are_found() {
        let base = std::env::temp_dir().join(format!("locus-test-data-{}", std::process::id()));
        let (a, b) = (base.join("a"), base.join("b"));
        std::fs::create_dir_all(&a).unwrap();
        std::fs::create_dir_all(&b).unwrap();
        std::fs::write(a.join("x"), "1").unwrap();
        std::fs::write(b.join("x"), "1").unwrap();
        assert!(folder_differences(&a, &b).is_empty());
        std::fs::write(b.join("x"), "2").unwrap();
        std::fs::write(b.join("y"), "").unwrap();
        let d = folder_differences(&a, &b);
        std::fs::remove_dir_all(&base).unwrap();
        assert_eq!(d.len(), 2, "{d:?}");
        assert!(d[0].starts_with("y: only in"), "{d:?}");
        assert_eq!(d[1], "x: contents differ");
    }
}

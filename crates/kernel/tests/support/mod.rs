//! Helpers shared by the integration tests: locating and reading the reference cases.

#![allow(dead_code)]

use std::path::PathBuf;

use serde_json::Value;

/// The `shared/oracle` directory, found by walking up from this crate's manifest directory
/// (locally the worktree sits below the directory holding `shared/`; in CI the repository is
/// cloned with `shared/` beside it).
pub fn oracle_dir() -> PathBuf {
    let start = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let mut dir = Some(start.as_path());
    while let Some(d) = dir {
        let candidate = d.join("shared").join("oracle");
        if candidate.is_dir() {
            return candidate;
        }
        dir = d.parent();
    }
    panic!(
        "no shared/oracle directory above {}; the reference cases are required",
        start.display()
    );
}

/// Parses one of the oracle's JSON files by name, such as `"opennurbs-cases.json"`.
pub fn load_oracle(name: &str) -> Value {
    let path = oracle_dir().join(name);
    let text = std::fs::read_to_string(&path)
        .unwrap_or_else(|e| panic!("cannot read {}: {e}", path.display()));
    serde_json::from_str(&text).unwrap_or_else(|e| panic!("cannot parse {}: {e}", path.display()))
}

/// A JSON number as `f64`.
pub fn num(v: &Value) -> f64 {
    v.as_f64()
        .unwrap_or_else(|| panic!("expected a number, got {v}"))
}

/// A JSON array of three numbers as `[f64; 3]`.
pub fn triple(v: &Value) -> [f64; 3] {
    let a = v
        .as_array()
        .unwrap_or_else(|| panic!("expected an array, got {v}"));
    assert_eq!(a.len(), 3, "expected three numbers, got {v}");
    [num(&a[0]), num(&a[1]), num(&a[2])]
}

/// A JSON array of numbers as a vector.
pub fn numbers(v: &Value) -> Vec<f64> {
    v.as_array()
        .unwrap_or_else(|| panic!("expected an array, got {v}"))
        .iter()
        .map(num)
        .collect()
}

/// Whether `actual` is within `rel` of `expected`, relative to `max(1, |expected|)`.
pub fn close(actual: f64, expected: f64, rel: f64) -> bool {
    (actual - expected).abs() <= rel * expected.abs().max(1.0)
}

/// Whether two 3-D values are within `rel` of each other, relative to `max(1, |expected|)`.
pub fn close3(actual: [f64; 3], expected: [f64; 3], rel: f64) -> bool {
    let d = (0..3)
        .map(|k| (actual[k] - expected[k]).powi(2))
        .sum::<f64>()
        .sqrt();
    let n = expected.iter().map(|x| x * x).sum::<f64>().sqrt();
    d <= rel * n.max(1.0)
}

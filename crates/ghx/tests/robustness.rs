//! Mutated and truncated `.ghx` and `.gh` files never panic and stay within a time bound:
//! every outcome is a graph or a clear error.

use std::io::{Read, Write};
use std::time::{Duration, Instant};

use flate2::Compression;
use flate2::read::DeflateDecoder;
use flate2::write::DeflateEncoder;
use locus_ghx::{Limits, import};
use locus_runtime::NodeRegistry;
use proptest::prelude::*;

fn registry() -> &'static NodeRegistry {
    static R: std::sync::OnceLock<NodeRegistry> = std::sync::OnceLock::new();
    R.get_or_init(|| {
        let mut r = NodeRegistry::new();
        locus_nodes::register(&mut r);
        r
    })
}

fn data(name: &str) -> Vec<u8> {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data")
        .join(name);
    std::fs::read(path).unwrap()
}

fn ghx() -> &'static [u8] {
    static D: std::sync::OnceLock<Vec<u8>> = std::sync::OnceLock::new();
    D.get_or_init(|| data("mcneel-compute__simple_circle_one.ghx"))
}

/// The decompressed binary archive of a `.gh` file.
fn gh_raw() -> &'static [u8] {
    static D: std::sync::OnceLock<Vec<u8>> = std::sync::OnceLock::new();
    D.get_or_init(|| {
        let bytes = data("mcneel-compute__hops_definitions_SimpleDelaunayMesh.gh");
        let mut out = Vec::new();
        DeflateDecoder::new(&bytes[..])
            .read_to_end(&mut out)
            .unwrap();
        out
    })
}

fn deflate(raw: &[u8]) -> Vec<u8> {
    let mut e = DeflateEncoder::new(Vec::new(), Compression::fast());
    e.write_all(raw).unwrap();
    e.finish().unwrap()
}

/// Imports and checks that it returns (either way) quickly.
fn survives(bytes: &[u8]) {
    let start = Instant::now();
    let outcome = import(bytes, registry(), &Limits::default());
    if let Ok(i) = &outcome {
        let _ = locus_ghx::to_ron(i);
    }
    assert!(
        start.elapsed() < Duration::from_secs(5),
        "took {:?}",
        start.elapsed()
    );
}

#[derive(Clone, Debug)]
enum Mutation {
    Truncate(usize),
    Flip(usize, u8),
    Insert(usize, Vec<u8>),
    Delete(usize, usize),
}

fn mutation() -> impl Strategy<Value = Mutation> {
    prop_oneof![
        any::<usize>().prop_map(Mutation::Truncate),
        (any::<usize>(), 1u8..=255).prop_map(|(i, x)| Mutation::Flip(i, x)),
        (
            any::<usize>(),
            proptest::collection::vec(any::<u8>(), 1..16)
        )
            .prop_map(|(i, v)| Mutation::Insert(i, v)),
        (any::<usize>(), 1usize..64).prop_map(|(i, n)| Mutation::Delete(i, n)),
    ]
}

fn apply(bytes: &[u8], ms: &[Mutation]) -> Vec<u8> {
    let mut b = bytes.to_vec();
    for m in ms {
        if b.is_empty() {
            break;
        }
        match m {
            Mutation::Truncate(i) => b.truncate(i % b.len()),
            Mutation::Flip(i, x) => {
                let k = i % b.len();
                b[k] ^= x;
            }
            Mutation::Insert(i, v) => {
                let k = i % b.len();
                b.splice(k..k, v.iter().copied());
            }
            Mutation::Delete(i, n) => {
                let k = i % b.len();
                let end = (k + n).min(b.len());
                b.drain(k..end);
            }
        }
    }
    b
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 200, ..ProptestConfig::default() })]

    #[test]
    fn mutated_ghx_never_panics(ms in proptest::collection::vec(mutation(), 1..4)) {
        survives(&apply(ghx(), &ms));
    }

    #[test]
    fn mutated_binary_archives_never_panic(ms in proptest::collection::vec(mutation(), 1..4)) {
        // Mutate the archive inside the compression, so that the reader sees the damage.
        survives(&deflate(&apply(gh_raw(), &ms)));
    }

    #[test]
    fn mutated_compressed_gh_never_panics(ms in proptest::collection::vec(mutation(), 1..3)) {
        survives(&apply(&deflate(gh_raw()), &ms));
    }
}

#[test]
fn every_truncation_of_a_binary_archive_is_an_error() {
    let raw = gh_raw();
    for cut in (0..raw.len()).step_by(97) {
        let err = import(&deflate(&raw[..cut]), registry(), &Limits::default());
        assert!(err.is_err(), "a cut at {cut} read");
    }
}

#[test]
fn hostile_xml_is_an_error() {
    // Deep nesting and a huge entity-free document stay bounded.
    let deep = format!(
        "<Archive name=\"Root\">{}",
        "<chunks><chunk name=\"c\">".repeat(100_000)
    );
    let err = import(deep.as_bytes(), registry(), &Limits::default()).unwrap_err();
    assert!(err.to_string().starts_with("line "), "{err}");
    let dtd = "<!DOCTYPE a [<!ENTITY x \"xxxxxxxx\">]><Archive name=\"Root\">&x;</Archive>";
    assert!(import(dtd.as_bytes(), registry(), &Limits::default()).is_err());
    let small = Limits {
        max_file_bytes: 100,
        ..Limits::default()
    };
    let err = import(ghx(), registry(), &small).unwrap_err();
    assert!(
        err.to_string().contains("more than the limit of 100"),
        "{err}"
    );
}

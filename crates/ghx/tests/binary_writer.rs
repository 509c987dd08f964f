//! The binary archive writer against real files: every `.gh` file of the corpus, and every
//! cluster document inside any file, written back from what was read is the very same bytes
//! that Grasshopper wrote (before compression); every `.ghx` file's archive written in binary
//! reads back unchanged.

use locus_ghx::{Chunk, Form, Limits, Value, detect, inflate, read_archive, write_binary};

fn files() -> Vec<std::path::PathBuf> {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data");
    let mut files: Vec<_> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| locus_ghx::is_grasshopper_path(p))
        .collect();
    files.sort();
    files
}

/// Every `ClusterDocument`'s bytes in a chunk tree.
fn cluster_documents(chunk: &Chunk, out: &mut Vec<Vec<u8>>) {
    for item in &chunk.items {
        if item.name == "ClusterDocument"
            && let Value::Bytes(b) = &item.value
        {
            out.push(b.clone());
        }
    }
    for c in &chunk.chunks {
        cluster_documents(c, out);
    }
}

#[test]
fn real_archives_write_back_byte_for_byte() {
    let limits = Limits::default();
    let (mut gh, mut clusters, mut ghx) = (0, 0, 0);
    for f in files() {
        let bytes = std::fs::read(&f).unwrap();
        let root = read_archive(&bytes, &limits).unwrap();
        match detect(&bytes) {
            Form::Binary => {
                let data = inflate(&bytes, &limits, "file").unwrap();
                assert!(write_binary(&root) == data, "{}", f.display());
                gh += 1;
            }
            Form::Xml => {
                let again = locus_ghx::read_binary(&write_binary(&root), &limits).unwrap();
                assert!(again == root, "{}", f.display());
                ghx += 1;
            }
        }
        let mut documents = Vec::new();
        cluster_documents(&root, &mut documents);
        for d in documents {
            let data = inflate(&d, &limits, "cluster").unwrap();
            let inner = locus_ghx::read_binary(&data, &limits).unwrap();
            assert!(write_binary(&inner) == data, "{}: a cluster", f.display());
            clusters += 1;
        }
    }
    assert!(
        gh >= 5 && ghx >= 20 && clusters >= 18,
        "{gh} {ghx} {clusters}"
    );
}

//! Every real definition in `tests/data` reads into the chunk model.

use locus_ghx::{Limits, read_archive};

fn data_files() -> Vec<std::path::PathBuf> {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data");
    let mut files: Vec<_> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| matches!(p.extension().and_then(|e| e.to_str()), Some("gh" | "ghx")))
        .collect();
    files.sort();
    files
}

#[test]
fn every_file_reads() {
    let files = data_files();
    assert_eq!(files.len(), 28);
    for f in files {
        let bytes = std::fs::read(&f).unwrap();
        let root = read_archive(&bytes, &Limits::default())
            .unwrap_or_else(|e| panic!("{}: {e}", f.display()));
        let def = root.chunk("Definition").expect("a Definition chunk");
        let objects = def.chunk("DefinitionObjects").expect("objects");
        let count = objects.i64("ObjectCount").unwrap();
        assert_eq!(
            objects.chunks_named("Object").count() as i64,
            count,
            "{}",
            f.display()
        );
    }
}

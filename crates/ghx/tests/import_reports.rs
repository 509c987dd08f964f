//! The import report of every real definition in `tests/data`, as a checked-in snapshot
//! (`UPDATE_EXPECT=1 cargo test -p locus-ghx --test import_reports` rewrites them), and the
//! check of each imported graph against the node library.

use std::fmt::Write as _;

use locus_ghx::{Limits, import};
use locus_runtime::{Document, NodeRegistry};

fn registry() -> NodeRegistry {
    let mut r = NodeRegistry::new();
    locus_nodes::register(&mut r);
    r
}

fn data_files() -> Vec<std::path::PathBuf> {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data");
    let mut files: Vec<_> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| locus_ghx::is_grasshopper_path(p))
        .collect();
    files.sort();
    files
}

#[test]
fn import_report_of_every_file() {
    let registry = registry();
    for f in data_files() {
        let bytes = std::fs::read(&f).unwrap();
        let import = import(&bytes, &registry, &Limits::default())
            .unwrap_or_else(|e| panic!("{}: {e}", f.display()));
        let mut text = import.report.summary();
        let ron = locus_ghx::to_ron(&import);
        // The written graph reads back and checks with the node library.
        let doc = Document::parse(&ron).unwrap_or_else(|e| panic!("{}: {e:?}\n{ron}", f.display()));
        match doc.check(&registry) {
            Ok(checked) => {
                let _ = writeln!(text, "check: ok, {} warnings", checked.warnings.len());
                for w in &checked.warnings {
                    let _ = writeln!(text, "  {w}");
                }
            }
            Err(ds) => {
                let _ = writeln!(text, "check: failed");
                for d in ds {
                    let _ = writeln!(text, "  {d}");
                }
            }
        }
        let name = f.file_name().unwrap().to_str().unwrap();
        expect_test::expect_file![format!("snapshots/{name}.report")].assert_eq(&text);
    }
}

//! `locus fmt`: rewrite graph files in canonical layout, or check that they are.

use std::path::PathBuf;

use locus_runtime::Document;

use crate::test_graphs::graph_files;
use crate::write_file::write_atomically;
use crate::{EXIT_BAD_GRAPH, EXIT_TEST_FAILED};

/// `locus fmt [--check] PATH…`: exit 0 when every file is (now) canonical; with `--check`,
/// files are left alone and exit code 4 says some are not; 3 when a file does not read or
/// cannot be put in canonical form without losing a comment.
pub(crate) fn fmt(paths: &[PathBuf], check: bool) -> u8 {
    let files = match graph_files(paths) {
        Ok(f) => f,
        Err(e) => {
            eprintln!("locus: {e}");
            return EXIT_BAD_GRAPH;
        }
    };
    let (mut unformatted, mut bad) = (0, 0);
    for file in &files {
        let shown = file.display();
        let text = match std::fs::read_to_string(file) {
            Ok(t) => t,
            Err(e) => {
                eprintln!("locus: cannot read {shown}: {e}");
                bad += 1;
                continue;
            }
        };
        let document = match Document::parse(&text) {
            Ok(d) => d,
            Err(ds) => {
                for d in &ds {
                    eprintln!("{}", d.display_in(&shown.to_string()));
                }
                bad += 1;
                continue;
            }
        };
        let canonical = match document.canonical() {
            Ok(c) => c,
            Err(e) => {
                eprintln!("{shown}:{e}; left unchanged");
                bad += 1;
                continue;
            }
        };
        if canonical == text {
            continue;
        }
        unformatted += 1;
        if check {
            out!("would reformat {shown}");
        } else if let Err(e) = write_atomically(file, &canonical) {
            eprintln!("locus: {e}");
            bad += 1;
        } else {
            out!("formatted {shown}");
        }
    }
    if bad > 0 {
        EXIT_BAD_GRAPH
    } else if check && unformatted > 0 {
        EXIT_TEST_FAILED
    } else {
        0
    }
}

//! `locus test`: run graphs against their expected outputs, or bless new expectations.

use std::path::{Path, PathBuf};

use locus_runtime::{COMPARE_TOLERANCE, Literal, NodeRegistry, compare_trees};

use crate::graph_file::{evaluator, load};
use crate::{EXIT_BAD_GRAPH, EXIT_TEST_FAILED};

/// The graph files under `paths` (folders searched recursively), sorted.
pub(crate) fn graph_files(paths: &[PathBuf]) -> Result<Vec<PathBuf>, String> {
    let defaults = [PathBuf::from("graphs")];
    let paths = if paths.is_empty() {
        &defaults[..]
    } else {
        paths
    };
    let mut files = Vec::new();
    for path in paths {
        collect(path, &mut files)?;
    }
    files.sort();
    files.dedup();
    Ok(files)
}

fn collect(path: &Path, files: &mut Vec<PathBuf>) -> Result<(), String> {
    if path.is_dir() {
        let entries =
            std::fs::read_dir(path).map_err(|e| format!("cannot read {}: {e}", path.display()))?;
        for entry in entries {
            let entry = entry.map_err(|e| format!("cannot read {}: {e}", path.display()))?;
            let p = entry.path();
            if p.is_dir()
                || p.extension().is_some_and(|e| e == "ron")
                    && !p
                        .to_string_lossy()
                        .ends_with(crate::grasshopper::EXPECTED_SUFFIX)
                || crate::grasshopper::is_grasshopper(&p)
            {
                collect(&p, files)?;
            }
        }
        Ok(())
    } else if path.exists() {
        files.push(path.to_owned());
        Ok(())
    } else {
        Err(format!("{} does not exist", path.display()))
    }
}

/// The outcome of testing one graph.
pub(crate) enum Outcome {
    /// Every expected output matched.
    Pass,
    /// The graph has no expectations.
    Skip,
    /// Differences, or a reason the graph could not run.
    Fail(Vec<String>),
}

/// Tests one graph file: its expected outputs against a fresh evaluation.
pub(crate) fn test_graph(registry: &NodeRegistry, path: &Path, threads: Option<usize>) -> Outcome {
    let loaded = match load(registry, path) {
        Ok(l) => l,
        Err(e) => {
            e.report(path);
            return Outcome::Fail(vec!["the graph does not load or check".to_owned()]);
        }
    };
    let expected = &loaded.document.graph().expected;
    if expected.is_empty() {
        return Outcome::Skip;
    }
    let mut ev = match evaluator(&loaded.checked, threads) {
        Ok(e) => e,
        Err(e) => return Outcome::Fail(vec![e]),
    };
    ev.evaluate();
    let plan = &loaded.checked.plan;
    let mut problems = Vec::new();
    for (name, literal) in expected {
        let Some(&(_, node, output)) = plan.outputs.iter().find(|(n, _, _)| n == name) else {
            problems.push(format!("{name}: no such output"));
            continue;
        };
        let data_type = plan.nodes[node].node_type.outputs[output].data_type;
        let want = match literal.parse(data_type) {
            Ok(t) => t,
            Err(e) => {
                problems.push(format!("{name}: the expected value does not read: {e}"));
                continue;
            }
        };
        let got = ev.output(name).cloned().unwrap_or_default();
        for line in compare_trees(&got, &want, COMPARE_TOLERANCE, 10) {
            problems.push(format!("{name} {line}"));
        }
    }
    if problems.is_empty() {
        Outcome::Pass
    } else {
        Outcome::Fail(problems)
    }
}

fn bless(registry: &NodeRegistry, path: &Path, threads: Option<usize>) -> Result<(), String> {
    let loaded = load(registry, path).map_err(|e| {
        e.report(path);
        "the graph does not load or check".to_owned()
    })?;
    let mut ev = evaluator(&loaded.checked, threads)?;
    ev.evaluate();
    let mut expected = Vec::new();
    for (name, tree) in ev.outputs() {
        let literal = Literal::from_tree(tree).map_err(|e| format!("output {name}: {e}"))?;
        expected.push((name.to_owned(), literal));
    }
    if crate::grasshopper::is_grasshopper(path) {
        return crate::grasshopper::write_expected(path, &expected);
    }
    let text = loaded.document.with_expected(&expected);
    std::fs::write(path, text).map_err(|e| format!("cannot write {}: {e}", path.display()))
}

/// `locus test`.
pub(crate) fn test(
    registry: &NodeRegistry,
    paths: &[PathBuf],
    do_bless: bool,
    threads: Option<usize>,
) -> u8 {
    let files = match graph_files(paths) {
        Ok(f) => f,
        Err(e) => {
            eprintln!("locus: {e}");
            return EXIT_BAD_GRAPH;
        }
    };
    let (mut passed, mut failed, mut skipped) = (0, 0, 0);
    for file in &files {
        if do_bless {
            match bless(registry, file, threads) {
                Ok(()) => {
                    out!("blessed {}", file.display());
                    passed += 1;
                }
                Err(e) => {
                    out!("FAILED  {}: {e}", file.display());
                    failed += 1;
                }
            }
            continue;
        }
        match test_graph(registry, file, threads) {
            Outcome::Pass => {
                out!("ok      {}", file.display());
                passed += 1;
            }
            Outcome::Skip => {
                out!("skipped {} (no expected outputs)", file.display());
                skipped += 1;
            }
            Outcome::Fail(problems) => {
                out!("FAILED  {}", file.display());
                for p in problems {
                    out!("    {p}");
                }
                failed += 1;
            }
        }
    }
    out!("graphs: {passed} passed, {failed} failed, {skipped} skipped");
    if failed > 0 { EXIT_TEST_FAILED } else { 0 }
}

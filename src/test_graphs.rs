//! `locus test`: run graphs against their expected outputs, or bless new expectations.

use std::path::{Path, PathBuf};

use locus_runtime::{
    BlessOutput, COMPARE_TOLERANCE, DataType, ExpectedMessage, ExpectedTree, Graph, Level, Literal,
    Message, NodeRegistry, compare_expected,
};

use crate::graph_file::{evaluator, load};
use crate::write_file::write_atomically;
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
    /// Every expected output and message matched.
    Pass,
    /// The graph has no expectations.
    Skip,
    /// Differences, or a reason the graph could not run.
    Fail(Vec<String>),
}

/// The runtime errors that no expected message of the graph declares, and the expected
/// messages that no runtime message matched.
fn message_problems(graph: &Graph, messages: &[Message]) -> (Vec<Message>, Vec<String>) {
    let undeclared = messages
        .iter()
        .filter(|m| m.level == Level::Error)
        .filter(|m| !graph.expected_messages.iter().any(|e| e.matches(m)))
        .cloned()
        .collect();
    let missing = graph
        .expected_messages
        .iter()
        .filter(|e| !messages.iter().any(|m| e.matches(m)))
        .map(|e| {
            format!(
                "expected {} on node \"{}\" matching \"{}\" was not reported",
                e.level, e.node, e.text
            )
        })
        .collect();
    (undeclared, missing)
}

/// Tests one graph file: its expected outputs and messages against a fresh evaluation.
///
/// A graph fails when an output differs from its expected value, when a named output has no
/// expected value, when its run reports an error that `expected_messages` does not declare, or
/// when a declared message is not reported.
pub(crate) fn test_graph(registry: &NodeRegistry, path: &Path, threads: Option<usize>) -> Outcome {
    let loaded = match load(registry, path) {
        Ok(l) => l,
        Err(e) => {
            e.report(path);
            return Outcome::Fail(vec!["the graph does not load or check".to_owned()]);
        }
    };
    let graph = loaded.document.graph();
    if graph.expected.is_empty() && graph.expected_messages.is_empty() {
        return Outcome::Skip;
    }
    let mut ev = match evaluator(&loaded.checked, threads) {
        Ok(e) => e,
        Err(e) => return Outcome::Fail(vec![e]),
    };
    ev.evaluate();
    let plan = &loaded.checked.plan;
    let mut problems = Vec::new();
    for (name, node, output) in &plan.outputs {
        let data_type = plan.nodes[*node].node_type.outputs[*output].data_type;
        let Some((_, literal)) = graph.expected.iter().find(|(n, _)| n == name) else {
            problems.push(format!(
                "{name}: no expected value (the output is unchecked)"
            ));
            continue;
        };
        let want = match ExpectedTree::parse(literal, data_type) {
            Ok(t) => t,
            Err(e) => {
                problems.push(format!("{name}: the expected value does not read: {e}"));
                continue;
            }
        };
        let got = ev.output(name).cloned().unwrap_or_default();
        for line in compare_expected(&got, &want, COMPARE_TOLERANCE, 10) {
            problems.push(format!("{name} {line}"));
        }
    }
    let messages: Vec<Message> = ev.messages().cloned().collect();
    let (undeclared, missing) = message_problems(graph, &messages);
    for m in undeclared {
        problems.push(format!("{m} (not declared in expected_messages)"));
    }
    problems.extend(missing);
    if problems.is_empty() {
        Outcome::Pass
    } else {
        Outcome::Fail(problems)
    }
}

/// What blessing did to a file.
enum Blessed {
    Written,
    Unchanged,
}

fn bless(
    registry: &NodeRegistry,
    path: &Path,
    threads: Option<usize>,
    allow_errors: bool,
) -> Result<Blessed, String> {
    let loaded = load(registry, path).map_err(|e| {
        e.report(path);
        "the graph does not load or check".to_owned()
    })?;
    let mut ev = evaluator(&loaded.checked, threads)?;
    ev.evaluate();
    let graph = loaded.document.graph();
    let messages: Vec<Message> = ev.messages().cloned().collect();
    let (undeclared, _) = message_problems(graph, &messages);
    if !undeclared.is_empty() && !allow_errors {
        let list: Vec<String> = undeclared.iter().map(ToString::to_string).collect();
        return Err(format!(
            "not blessed: the run reports {} error{} not declared in expected_messages ({}); \
             pass --allow-errors to bless them as expected",
            list.len(),
            if list.len() == 1 { "" } else { "s" },
            list.join("; ")
        ));
    }
    if crate::grasshopper::is_grasshopper(path) {
        // Grasshopper files keep their expectations in a RON file beside them.
        let mut expected = Vec::new();
        for (name, tree) in ev.outputs() {
            let literal = Literal::from_tree(tree).map_err(|e| format!("output {name}: {e}"))?;
            expected.push((name.to_owned(), literal));
        }
        crate::grasshopper::write_expected(path, &expected)?;
        return Ok(Blessed::Written);
    }
    let mut new_messages: Vec<ExpectedMessage> = Vec::new();
    for m in &undeclared {
        let e = ExpectedMessage {
            node: m.node.clone(),
            level: m.level,
            text: m.text.clone(),
        };
        if !new_messages.contains(&e) {
            new_messages.push(e);
        }
    }
    let plan = &loaded.checked.plan;
    let outputs: Vec<BlessOutput> = ev
        .outputs()
        .map(|(name, tree)| {
            let data_type = plan
                .outputs
                .iter()
                .find(|(n, _, _)| n == name)
                .map_or(DataType::Generic, |&(_, node, output)| {
                    plan.nodes[node].node_type.outputs[output].data_type
                });
            BlessOutput {
                name,
                data_type,
                tree,
            }
        })
        .collect();
    let text = loaded
        .document
        .bless(&outputs, &new_messages)
        .map_err(|e| e.to_string())?;
    if text == loaded.document.source() {
        return Ok(Blessed::Unchanged);
    }
    write_atomically(path, &text)?;
    Ok(Blessed::Written)
}

/// `locus test`.
pub(crate) fn test(
    registry: &NodeRegistry,
    paths: &[PathBuf],
    do_bless: bool,
    allow_errors: bool,
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
            match bless(registry, file, threads, allow_errors) {
                Ok(Blessed::Written) => {
                    out!("blessed {}", file.display());
                    passed += 1;
                }
                Ok(Blessed::Unchanged) => {
                    out!("ok      {} (unchanged)", file.display());
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

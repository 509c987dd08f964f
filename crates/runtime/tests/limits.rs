//! Run limits: hostile graphs end in bounded time and memory with the documented error
//! (`docs/limits.md`).

use std::time::{Duration, Instant};

use locus_runtime::{
    CancelToken, DataTree, DataType, Document, Evaluator, LimitHit, Limits, NodeRegistry, NodeType,
    Port,
};

fn registry() -> NodeRegistry {
    let mut r = NodeRegistry::new();
    r.register(
        NodeType::new("test.addition", "Addition", "A+B", "Test")
            .input(Port::new("A", "A", DataType::Number))
            .input(Port::new("B", "B", DataType::Number).default_value(0.0))
            .output(Port::new("Result", "R", DataType::Number))
            .lift2(|a: &f64, b: &f64| Ok(a + b)),
    );
    // A list of N numbers 0, 1, …, N−1.
    r.register(
        NodeType::new("test.series", "Series", "S", "Test")
            .input(Port::new("Count", "N", DataType::Integer))
            .output(Port::new("Series", "S", DataType::Number).list())
            .solve(|s| {
                let n = usize::try_from(*s.item::<i64>(0)?).map_err(|_| "negative count")?;
                s.set_list(0, (0..n).map(|i| i as f64).collect::<Vec<f64>>());
                Ok(())
            }),
    );
    // Adds its inputs after sleeping a millisecond: a slow node for the deadline.
    r.register(
        NodeType::new("test.slow", "Slow", "Slow", "Test")
            .input(Port::new("A", "A", DataType::Number))
            .output(Port::new("Result", "R", DataType::Number))
            .solve(|s| {
                std::thread::sleep(Duration::from_millis(1));
                let a = *s.item::<f64>(0)?;
                s.set(0, a);
                Ok(())
            }),
    );
    r
}

fn evaluator(text: &str) -> Evaluator {
    let doc = Document::parse(text).expect("reads");
    doc.check(&registry()).expect("checks").into_evaluator()
}

/// A chain of `n` additions, each adding 1 to the one before.
fn chain(n: usize) -> String {
    let mut text = String::from("(format: 1, nodes: [\n");
    for i in 0..n {
        let a = if i == 0 { "\"A\": 0, " } else { "" };
        text.push_str(&format!(
            "(id: \"n{i}\", type: \"test.addition\", values: {{{a}\"B\": 1}}),\n"
        ));
    }
    text.push_str("], wires: [\n");
    for i in 1..n {
        text.push_str(&format!("(\"n{}.R\", \"n{i}.A\"),\n", i - 1));
    }
    text.push_str(&format!("], outputs: {{\"last\": \"n{}.R\"}})\n", n - 1));
    text
}

fn messages(e: &Evaluator) -> Vec<String> {
    e.messages().map(ToString::to_string).collect()
}

#[test]
fn a_200000_node_chain_checks_and_runs() {
    let n = 200_000;
    let mut e = evaluator(&chain(n));
    e.evaluate();
    assert_eq!(e.output("last"), Some(&DataTree::from_item(n as f64)));
    assert_eq!(e.limit_hit(), None);
}

#[test]
fn cross_reference_of_10k_by_10k_is_refused_before_allocating() {
    let list = |k: usize| {
        let items: Vec<String> = (0..k).map(|i| i.to_string()).collect();
        format!("[{}]", items.join(", "))
    };
    let text = format!(
        r#"(format: 1, nodes: [
            (id: "x", type: "test.addition", matching: cross, values: {{"A": {a}, "B": {b}}}),
            (id: "after", type: "test.addition", values: {{"B": 1}}),
        ], wires: [("x.R", "after.A")], outputs: {{"r": "after.R"}})"#,
        a = list(10_000),
        b = list(10_000)
    );
    let mut e = evaluator(&text);
    let started = Instant::now();
    e.evaluate();
    assert!(started.elapsed() < Duration::from_secs(5));
    let detail = "cross reference of 10000 (A) × 10000 (B) items at {0} gives 100000000 \
                  iterations (after 1 items and branches before it), above the limit of \
                  10000000 items per output";
    assert_eq!(
        e.limit_hit(),
        Some(&LimitHit::Items {
            node: "x".into(),
            detail: detail.to_owned()
        })
    );
    assert_eq!(messages(&e)[0], format!("error: node \"x\": {detail}"));
    // Downstream sees no data.
    assert_eq!(e.output("r").map(DataTree::item_count), Some(0));
}

#[test]
fn ten_million_items_in_one_output_are_refused() {
    let text = r#"(format: 1, nodes: [(id: "s", type: "test.series", values: {"N": 10000000})],
        outputs: {"s": "s.S"})"#;
    let mut e = evaluator(text);
    e.evaluate();
    assert!(
        matches!(e.limit_hit(), Some(LimitHit::Items { .. })),
        "{:?}",
        e.limit_hit()
    );
    assert_eq!(e.output("s").map(DataTree::item_count), Some(0));
    let m = messages(&e);
    assert!(
        m[0].contains("above the limit of 10000000 items per output"),
        "{m:?}"
    );
}

#[test]
fn grafting_into_millions_of_branches_is_refused_before_grafting() {
    let text = r#"(format: 1, nodes: [
            (id: "s", type: "test.series", values: {"N": 6000000}),
            (id: "g", type: "test.addition", modifiers: {"A": [graft]}),
        ], wires: [("s.S", "g.A")], outputs: {"g": "g.R"})"#;
    let mut e = evaluator(text);
    e.evaluate();
    assert_eq!(
        messages(&e),
        [
            "error: node \"g\": grafting input A would make 6000000 branches (12000000 items and \
          branches), above the limit of 10000000 items per output"
        ]
    );
}

#[test]
fn the_total_budget_covers_all_outputs() {
    let text = r#"(format: 1, nodes: [
            (id: "a", type: "test.series", values: {"N": 600}),
            (id: "b", type: "test.series", values: {"N": 600}),
        ], outputs: {"a": "a.S", "b": "b.S"})"#;
    let mut e = evaluator(text);
    e.set_limits(Limits {
        max_items_total: 1000,
        ..Limits::default()
    });
    e.evaluate();
    assert_eq!(e.output("a").map(DataTree::item_count), Some(600));
    assert_eq!(e.output("b").map(DataTree::item_count), Some(0));
    assert!(matches!(e.limit_hit(), Some(LimitHit::Items { node, .. }) if node.0 == "b"));
}

#[test]
fn a_deadline_stops_a_running_node_and_reports_the_rest_as_not_run() {
    let text = r#"(format: 1, nodes: [
            (id: "s", type: "test.series", values: {"N": 100000}),
            (id: "slow", type: "test.slow"),
            (id: "after", type: "test.addition", values: {"B": 1}),
        ], wires: [("s.S", "slow.A"), ("slow.R", "after.A")], outputs: {"r": "after.R"})"#;
    let mut e = evaluator(text);
    e.set_threads(1).unwrap();
    e.set_limits(Limits {
        timeout: Some(Duration::from_millis(100)),
        ..Limits::default()
    });
    let started = Instant::now();
    e.evaluate();
    // 100,000 iterations of 1 ms would take 100 s; it stops near the deadline.
    assert!(
        started.elapsed() < Duration::from_secs(2),
        "{:?}",
        started.elapsed()
    );
    assert_eq!(
        e.limit_hit(),
        Some(&LimitHit::Timeout {
            limit: Duration::from_millis(100)
        })
    );
    assert_eq!(
        messages(&e),
        ["error: node \"slow\": stopped: the time limit of 0.1 s was reached"]
    );
    let not_run: Vec<&str> = e.not_run().iter().map(|id| id.0.as_str()).collect();
    assert_eq!(not_run, ["after"]);
    // Without the limit the next evaluation runs what was left (here on a shorter list).
    e.set_limits(Limits::default());
    e.set_input_text("x", "1").unwrap_err();
}

#[test]
fn a_cancelled_token_stops_the_evaluation_between_nodes() {
    let token = CancelToken::new();
    let mut e = evaluator(&chain(10));
    e.set_limits(Limits {
        cancel: Some(token.clone()),
        ..Limits::default()
    });
    token.cancel();
    e.evaluate();
    assert_eq!(e.limit_hit(), Some(&LimitHit::Cancelled));
    assert_eq!(e.not_run().len(), 10);
    assert!(e.last_run().is_empty());
}

#[test]
fn zero_threads_is_an_error_and_too_many_are_capped() {
    let mut e = evaluator(&chain(2));
    assert!(e.set_threads(0).is_err());
    let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
    assert_eq!(e.set_threads(100_000).unwrap(), 4 * cores);
    assert_eq!(e.set_threads(1).unwrap(), 1);
}

#[test]
fn long_texts_and_non_regular_files_are_refused() {
    let long = "x".repeat(locus_runtime::MAX_TEXT_BYTES + 1);
    let text = format!("(format: 1, nodes: [], outputs: {{}}, title: \"{long}\")");
    let err = Document::parse(&text).unwrap_err();
    assert!(
        err[0].to_string().contains("the string is too long"),
        "{}",
        err[0]
    );
    let mut e = evaluator(&chain(1).replace("outputs:", "inputs: {\"x\": \"n0.B\"}, outputs:"));
    let err = e.set_input_text("x", &long).unwrap_err();
    assert!(err.to_string().contains("the text is too long"), "{err}");
    let started = Instant::now();
    let err = Evaluator::from_file("/dev/zero", &registry()).unwrap_err();
    assert!(err.to_string().contains("not a regular file"), "{err}");
    assert!(started.elapsed() < Duration::from_secs(1));
}

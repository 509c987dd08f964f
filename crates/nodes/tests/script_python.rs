//! The Python script node, end to end: without Python (the node says Python is not available
//! and nothing else breaks) and with it (items, lists and trees in and out, type hints, what a
//! script prints, exceptions with their line, the time limit, and scripts that crash or hang
//! their Python process without touching the engine).
//!
//! The tests with Python need an interpreter with the `locus` package installed, named by
//! `$LOCUS_PYTHON` (`.ci/steps/50-python.sh` sets it to the virtualenv it installs the wheel
//! into, with `LOCUS_REQUIRE_PYTHON=1`). Without it they say so on standard error and pass, so
//! that `cargo test --workspace` runs on a machine without Python; with
//! `LOCUS_REQUIRE_PYTHON=1` a missing interpreter fails them.

use std::time::{Duration, Instant};

use locus_kernel::Point3;
use locus_nodes::script::{PYTHON_ENV, PythonConfig, python};
use locus_runtime::{
    Branch, DataTree, DataType, Document, Evaluator, Level, Message, NodeCall, NodeCallResult,
    NodeRegistry, TreePath, Value,
};

fn text(s: &str) -> Value {
    Value::Text(s.to_owned())
}

fn errors(r: &NodeCallResult) -> Vec<&Message> {
    r.messages
        .iter()
        .filter(|m| m.level == Level::Error)
        .collect()
}

/// The interpreter with the locus package, or `None` (the test then passes after saying why,
/// unless `LOCUS_REQUIRE_PYTHON=1`).
fn interpreter() -> Option<PythonConfig> {
    match std::env::var_os(PYTHON_ENV).filter(|p| !p.is_empty()) {
        Some(p) => Some(PythonConfig::Interpreter(p)),
        None => {
            assert!(
                std::env::var("LOCUS_REQUIRE_PYTHON").as_deref() != Ok("1"),
                "LOCUS_REQUIRE_PYTHON=1 but {PYTHON_ENV} is not set"
            );
            eprintln!(
                "skipped: set {PYTHON_ENV} to a Python with the locus package to run this test"
            );
            None
        }
    }
}

fn numbers(xs: &[f64]) -> DataTree {
    DataTree::from_list(xs.to_vec())
}

#[test]
fn without_python_the_node_says_python_is_not_available() {
    let node = python(PythonConfig::Interpreter(
        "/nonexistent/locus-test-python".into(),
    ));
    let r = NodeCall::new(&node)
        .input(numbers(&[1.0, 2.0]))
        .setting("code", text("a = x * 2"))
        .run();
    let errs = errors(&r);
    assert_eq!(errs.len(), 1, "{:?}", r.messages);
    assert!(
        errs[0]
            .text
            .starts_with("Python is not available: cannot start /nonexistent/locus-test-python"),
        "{}",
        errs[0].text
    );
    assert!(errs[0].text.contains("LOCUS_PYTHON"), "{}", errs[0].text);
    assert!(r.outputs.iter().all(DataTree::is_empty));
}

#[test]
fn a_python_without_the_locus_package_is_not_available_either() {
    // Any program that is not a worker: it exits at once without a hello.
    let node = python(PythonConfig::Interpreter("false".into()));
    let r = NodeCall::new(&node)
        .input(numbers(&[1.0]))
        .setting("code", text("a = x"))
        .run();
    let errs = errors(&r);
    assert_eq!(errs.len(), 1, "{:?}", r.messages);
    assert!(
        errs[0]
            .text
            .starts_with("Python is not available: false (locus._script_worker) ended"),
        "{}",
        errs[0].text
    );
}

#[test]
fn disabled_scripts_say_why_and_empty_scripts_do_nothing() {
    let node = python(PythonConfig::Disabled(
        "this server does not run scripts".into(),
    ));
    let r = NodeCall::new(&node)
        .input(numbers(&[1.0]))
        .setting("code", text("a = x"))
        .run();
    assert_eq!(
        errors(&r)[0].text,
        "Python scripts are disabled: this server does not run scripts"
    );
    // An empty script never needs Python.
    let r = NodeCall::new(&node).input(numbers(&[1.0])).run();
    assert!(r.messages.is_empty(), "{:?}", r.messages);
}

#[test]
fn bad_settings_are_check_errors_with_the_position() {
    let mut registry = NodeRegistry::new();
    locus_nodes::register(&mut registry);
    let text = r#"(
    format: 1,
    nodes: [
        (id: "s", type: "script.python", inputs: ["pts"], settings: {"code": "a = 1", "access": "pts: lists"}),
    ],
)"#;
    let ds = Document::parse(text).unwrap().check(&registry).unwrap_err();
    let msg = ds
        .iter()
        .map(|d| d.to_string())
        .collect::<Vec<_>>()
        .join("\n");
    assert!(msg.contains("access must be item, list or tree"), "{msg}");
    assert!(msg.contains("4:"), "{msg}");
}

#[test]
fn items_lists_and_trees_go_in_and_come_out() {
    let Some(config) = interpreter() else { return };
    let node = python(config);
    // x item access (three iterations), ys list access (the whole branch each time), t tree.
    let mut t = DataTree::new();
    t.insert(
        TreePath::new(vec![0, 1]),
        Branch::from_items(vec![10i64, 20]),
    );
    let r = NodeCall::new(&node)
        .input_names(&["x", "ys", "t"])
        .input(numbers(&[1.0, 2.0, 3.0]))
        .input(numbers(&[0.5, 0.25]))
        .input(t)
        .setting(
            "code",
            text("a = [x * len(ys), sum(ys), list(t)[0], t['{0;1}'][1]]\nprint('x is', x)"),
        )
        .setting("access", text("ys: list; t: tree"))
        .run();
    assert!(errors(&r).is_empty(), "{:?}", r.messages);
    // `a` is a list each time: a branch per iteration, the iteration index appended.
    let a = &r.outputs[1];
    assert_eq!(a.branch_count(), 3, "{a:?}");
    let first = a.branch(&TreePath::new(vec![0, 0])).expect("{0;0}");
    let values: Vec<Option<Value>> = first.values().collect();
    assert_eq!(
        values,
        [
            Some(Value::Number(2.0)),
            Some(Value::Number(0.75)),
            Some(Value::Text("{0;1}".to_owned())),
            Some(Value::Integer(20)),
        ]
    );
    // What it printed: the out output and a remark per call, on its item.
    let out: Vec<Option<Value>> = r.outputs[0].values().collect();
    assert_eq!(
        out,
        [
            Some(text("x is 1.0")),
            Some(text("x is 2.0")),
            Some(text("x is 3.0"))
        ]
    );
    let remarks: Vec<(&str, Option<usize>)> = r
        .messages
        .iter()
        .filter(|m| m.level == Level::Remark)
        .map(|m| (m.text.as_str(), m.index))
        .collect();
    assert_eq!(
        remarks,
        [
            ("x is 1.0", Some(0)),
            ("x is 2.0", Some(1)),
            ("x is 3.0", Some(2))
        ]
    );
}

#[test]
fn type_hints_cast_inputs_and_geometry_comes_back() {
    let Some(config) = interpreter() else { return };
    let node = python(config);
    let r = NodeCall::new(&node)
        .input_names(&["p", "n"])
        .input(DataTree::from_list(vec![
            Value::Text("1,2,3".to_owned()),
            Value::Point(Point3::new(4.0, 5.0, 6.0)),
        ]))
        .input(DataTree::from_item(Value::Text("2.6".to_owned())))
        .setting(
            "code",
            text("import locus\na = locus.Point3(p.x * n, p.y, type(n).__name__ == 'int')"),
        )
        .setting("hints", text("p: Point3d, n: int"))
        .run();
    assert!(errors(&r).is_empty(), "{:?}", r.messages);
    let a: Vec<Option<Value>> = r.outputs[1].values().collect();
    // "2.6" cast to an Integer is 3, as Grasshopper rounds; the text "1,2,3" cast to a point.
    assert_eq!(
        a,
        [
            Some(Value::Point(Point3::new(3.0, 2.0, 1.0))),
            Some(Value::Point(Point3::new(12.0, 5.0, 1.0))),
        ]
    );
}

#[test]
fn an_exception_is_an_error_on_its_item_with_the_script_line() {
    let Some(config) = interpreter() else { return };
    let node = python(config);
    let r = NodeCall::new(&node)
        .input(numbers(&[1.0, 0.0, 4.0]))
        .setting("code", text("y = 1\n\na = 2 / x\n"))
        .run();
    let errs = errors(&r);
    assert_eq!(errs.len(), 1, "{:?}", r.messages);
    assert_eq!(
        errs[0].text,
        "line 3: ZeroDivisionError: float division by zero"
    );
    assert_eq!(errs[0].index, Some(1));
    assert_eq!(errs[0].path, Some(TreePath::zero()));
    // The other items ran; the failed one is a null.
    let a: Vec<Option<Value>> = r.outputs[1].values().collect();
    assert_eq!(
        a,
        [Some(Value::Number(2.0)), None, Some(Value::Number(0.5))]
    );
    // A syntax error names its line too, on every item.
    let r = NodeCall::new(&node)
        .input(numbers(&[1.0]))
        .setting("code", text("a = 1\nif x\n"))
        .run();
    assert!(
        errors(&r)[0].text.starts_with("line 2: SyntaxError"),
        "{:?}",
        r.messages
    );
}

#[test]
fn a_script_past_its_time_limit_is_stopped_and_the_next_evaluation_runs() {
    let Some(config) = interpreter() else { return };
    let node = python(config);
    // A Python loop: the worker interrupts it at the limit and goes on with the next item.
    let started = Instant::now();
    let r = NodeCall::new(&node)
        .input(numbers(&[1.0, 2.0]))
        .setting("code", text("while x == 1:\n    pass\na = x"))
        .setting("timeout", Value::Number(0.5))
        .run();
    let errs = errors(&r);
    assert_eq!(errs.len(), 1, "{:?}", r.messages);
    assert!(
        errs[0]
            .text
            .contains("ran longer than its time limit of 0.5 s"),
        "{}",
        errs[0].text
    );
    assert_eq!(errs[0].index, Some(0));
    assert_eq!(r.outputs[1].values().nth(1), Some(Some(Value::Number(2.0))));
    // A script that turns the worker's alarm off is stopped by the engine (the process is
    // killed) at the limit plus the grace; the items after it are not run.
    let r = NodeCall::new(&node)
        .input(numbers(&[1.0, 2.0]))
        .setting(
            "code",
            text(
                "import signal\nsignal.signal(signal.SIGALRM, signal.SIG_IGN)\n\
                 while x == 1:\n    pass\na = x",
            ),
        )
        .setting("timeout", Value::Number(0.5))
        .run();
    let errs = errors(&r);
    assert_eq!(errs.len(), 2, "{:?}", r.messages);
    assert!(
        errs[0]
            .text
            .contains("did not finish within its time limit of 0.5 s"),
        "{}",
        errs[0].text
    );
    assert!(errs[1].text.contains("not run"), "{}", errs[1].text);
    assert!(started.elapsed() < Duration::from_secs(30));
    // The node runs again with a new worker.
    let r = NodeCall::new(&node)
        .input(numbers(&[5.0]))
        .setting("code", text("a = x + 1"))
        .run();
    assert!(errors(&r).is_empty(), "{:?}", r.messages);
    assert_eq!(r.outputs[1].values().next(), Some(Some(Value::Number(6.0))));
}

#[test]
fn a_script_that_ends_or_crashes_its_python_is_an_error_not_a_crash() {
    let Some(config) = interpreter() else { return };
    let node = python(config);
    for (code, expected) in [
        (
            "import os\nif x == 2:\n    os._exit(3)\na = x",
            "ended with exit code 3",
        ),
        (
            // A segmentation fault inside a C extension (ctypes reading address 0).
            "import ctypes\nif x == 2:\n    ctypes.string_at(0)\na = x",
            "was ended",
        ),
    ] {
        let r = NodeCall::new(&node)
            .input(numbers(&[1.0, 2.0, 3.0]))
            .setting("code", text(code))
            .run();
        let errs = errors(&r);
        assert_eq!(errs.len(), 2, "{:?}", r.messages);
        assert!(errs[0].text.contains(expected), "{}", errs[0].text);
        assert!(
            errs[0].text.contains("while the script ran"),
            "{}",
            errs[0].text
        );
        assert_eq!(errs[0].index, Some(1));
        assert!(errs[1].text.starts_with("not run"), "{}", errs[1].text);
        assert_eq!(r.outputs[1].values().next(), Some(Some(Value::Number(1.0))));
    }
    // And the engine goes on.
    let r = NodeCall::new(&node)
        .input(numbers(&[2.0]))
        .setting("code", text("a = x * 10"))
        .run();
    assert_eq!(
        r.outputs[1].values().next(),
        Some(Some(Value::Number(20.0)))
    );
}

#[test]
fn a_graph_of_script_nodes_runs_through_the_registry() {
    let Some(PythonConfig::Interpreter(python)) = interpreter() else {
        return;
    };
    // The registry's node reads $LOCUS_PYTHON itself.
    assert_eq!(std::env::var_os(PYTHON_ENV), Some(python));
    let mut registry = NodeRegistry::new();
    locus_nodes::register(&mut registry);
    let text = r#"(
    format: 1,
    nodes: [
        (id: "n", type: "params.number", values: {"Num": [1, 2, 3]}),
        (id: "square", type: "script.python", inputs: ["x"], settings: {"code": "a = x * x"}),
        (id: "total", type: "script.python", inputs: ["xs"], settings: {"code": "a = sum(xs)", "access": "xs: list"}),
    ],
    wires: [("n.Num", "square.x"), ("square.a", "total.xs")],
    outputs: {"total": "total.a"},
)"#;
    let checked = Document::parse(text).unwrap().check(&registry).unwrap();
    let mut evaluator = Evaluator::new(checked.plan);
    evaluator.evaluate();
    assert!(
        evaluator.messages().next().is_none(),
        "{:?}",
        evaluator.messages().collect::<Vec<_>>()
    );
    let total = evaluator.output("total").unwrap();
    assert_eq!(
        total.values().collect::<Vec<_>>(),
        [Some(Value::Number(14.0))]
    );
    assert_eq!(total.data_type(), DataType::Number);
}

use super::*;
use crate::{DataType, Matching, NodeType, PlanInput, PlanNode, Port, Value};

fn number_source() -> Arc<NodeType> {
    Arc::new(
        NodeType::new("test.number", "Number", "Num", "Params")
            .input(Port::new("Number", "N", DataType::Number).list())
            .output(Port::new("Number", "N", DataType::Number).list())
            .solve(|s| {
                let v: Vec<f64> = s.list::<f64>(0)?.present().copied().collect();
                s.set_list(0, v);
                Ok(())
            }),
    )
}

fn addition() -> Arc<NodeType> {
    Arc::new(
        NodeType::new("test.add", "Addition", "A+B", "Maths")
            .input(Port::new("A", "A", DataType::Number))
            .input(Port::new("B", "B", DataType::Number))
            .output(Port::new("Result", "R", DataType::Number))
            .solve(|s| {
                let a = *s.item::<f64>(0)?;
                let b = *s.item::<f64>(1)?;
                s.set(0, a + b);
                Ok(())
            }),
    )
}

fn input(port: &Port, sources: Vec<(usize, usize)>, value: Option<DataTree>) -> PlanInput {
    PlanInput {
        port: port.clone(),
        sources,
        value,
        modifiers: vec![],
    }
}

fn node(id: &str, t: &Arc<NodeType>, inputs: Vec<PlanInput>) -> PlanNode {
    PlanNode {
        id: NodeId::from(id),
        node_type: t.clone(),
        inputs,
        settings: vec![],
        matching: Matching::Longest,
        disabled: false,
    }
}

/// a (number) ─┐
///             ├─ sum1 (a + b) ── sum2 (sum1 + c)
/// b (number) ─┘
/// c (number) ─────────────────────┘
fn plan() -> Plan {
    let num = number_source();
    let add = addition();
    let n = &num.inputs[0];
    let nodes = vec![
        node(
            "a",
            &num,
            vec![input(n, vec![], Some(DataTree::from_list(vec![1.0, 2.0])))],
        ),
        node(
            "b",
            &num,
            vec![input(n, vec![], Some(DataTree::from_item(10.0)))],
        ),
        node(
            "c",
            &num,
            vec![input(n, vec![], Some(DataTree::from_item(100.0)))],
        ),
        node(
            "sum1",
            &add,
            vec![
                input(&add.inputs[0], vec![(0, 0)], None),
                input(&add.inputs[1], vec![(1, 0)], None),
            ],
        ),
        node(
            "sum2",
            &add,
            vec![
                input(&add.inputs[0], vec![(3, 0)], None),
                input(&add.inputs[1], vec![(2, 0)], None),
            ],
        ),
    ];
    Plan {
        nodes,
        order: vec![0, 1, 2, 3, 4],
        inputs: vec![("a".into(), 0, 0), ("c".into(), 2, 0)],
        outputs: vec![("sum".into(), 4, 0)],
    }
}

fn numbers(t: &DataTree) -> Vec<f64> {
    t.values()
        .map(|v| v.and_then(|v| v.get::<f64>()).unwrap_or(f64::NAN))
        .collect()
}

#[test]
fn evaluates_in_topological_order() {
    let mut e = Evaluator::new(plan());
    e.evaluate();
    assert_eq!(numbers(e.output("sum").unwrap()), [111.0, 112.0]);
    assert_eq!(e.last_run().len(), 5);
}

#[test]
fn the_progress_observer_sees_every_node_run() {
    #[derive(Default)]
    struct Log(std::sync::Mutex<Vec<String>>);
    impl Progress for Log {
        fn started(&self, total: usize) {
            self.0.lock().unwrap().push(format!("start {total}"));
        }
        fn node_finished(&self, node: &str, done: usize, total: usize) {
            self.0
                .lock()
                .unwrap()
                .push(format!("{node} {done}/{total}"));
        }
        fn finished(&self) {
            self.0.lock().unwrap().push("end".into());
        }
    }
    let log = Arc::new(Log::default());
    let mut e = Evaluator::new(plan());
    e.set_threads(1).unwrap();
    e.set_progress(Some(log.clone()));
    e.evaluate();
    // Waves by depth: a, b, c, then sum1, then sum2; after c changes, c and sum2 run.
    e.set_input("c", DataTree::from_item(1000.0)).unwrap();
    e.evaluate();
    let expected = [
        "start 5", "a 1/5", "b 2/5", "c 3/5", "sum1 4/5", "sum2 5/5", "end", "start 2", "c 1/2",
        "sum2 2/2", "end",
    ];
    assert_eq!(*log.0.lock().unwrap(), expected);
}

#[test]
fn only_downstream_nodes_run_after_an_input_change() {
    let mut e = Evaluator::new(plan());
    e.evaluate();
    e.set_input("c", DataTree::from_item(1000.0)).unwrap();
    e.evaluate();
    let ran: Vec<String> = e.last_run().iter().map(|id| id.0.clone()).collect();
    assert_eq!(ran, ["c", "sum2"]);
    assert_eq!(numbers(e.output("sum").unwrap()), [1011.0, 1012.0]);
    e.set_input("a", DataTree::from_item(5.0)).unwrap();
    e.evaluate();
    let ran: Vec<String> = e.last_run().iter().map(|id| id.0.clone()).collect();
    assert_eq!(ran, ["a", "sum1", "sum2"]);
    e.evaluate();
    assert!(e.last_run().is_empty());
}

#[test]
fn unknown_input_names_the_known_ones() {
    let mut e = Evaluator::new(plan());
    let err = e.set_input("z", DataTree::new()).unwrap_err();
    assert_eq!(
        err.to_string(),
        "unknown input \"z\" (the graph's inputs are: a, c)"
    );
}

#[test]
fn disabled_nodes_output_nothing_and_downstream_warns() {
    let mut p = plan();
    p.nodes[1].disabled = true;
    let mut e = Evaluator::new(p);
    e.evaluate();
    assert!(e.output("sum").unwrap().is_empty());
    let texts: Vec<String> = e.messages().map(ToString::to_string).collect();
    assert_eq!(
        texts,
        [
            "warning: node \"sum1\": input parameter B failed to collect data",
            "warning: node \"sum2\": input parameter A failed to collect data"
        ]
    );
}

#[test]
fn several_wires_into_one_input_merge_in_wire_order() {
    let mut p = plan();
    p.nodes[3].inputs[0].sources = vec![(2, 0), (0, 0)];
    let mut e = Evaluator::new(p);
    e.evaluate();
    assert_eq!(
        numbers(e.node_output("sum1", "R").unwrap()),
        [110.0, 11.0, 12.0]
    );
}

#[test]
fn thread_count_does_not_change_results() {
    let mut results = Vec::new();
    for threads in [1, 2, 4] {
        let mut e = Evaluator::new(plan());
        e.set_threads(threads).unwrap();
        e.set_input(
            "a",
            DataTree::from_list((0..50_000).map(f64::from).collect()),
        )
        .unwrap();
        e.evaluate();
        results.push(e.output("sum").unwrap().clone());
    }
    assert_eq!(results[0], results[1]);
    assert_eq!(results[0], results[2]);
}

#[test]
fn a_panicking_node_becomes_an_error_message() {
    let mut p = plan();
    let bad = Arc::new(
        NodeType::new("test.bad", "Bad", "Bad", "Test")
            .input(Port::new("A", "A", DataType::Number))
            .output(Port::new("R", "R", DataType::Number))
            .solve(|_| panic!("boom")),
    );
    p.nodes[4] = node(
        "sum2",
        &bad,
        vec![input(&bad.inputs[0], vec![(3, 0)], None)],
    );
    let mut e = Evaluator::new(p);
    let hook = std::panic::take_hook();
    std::panic::set_hook(Box::new(|_| {}));
    e.evaluate();
    std::panic::set_hook(hook);
    assert_eq!(e.node_level("sum2"), Some(Level::Error));
    assert_eq!(numbers(e.node_output("sum1", "R").unwrap()), [11.0, 12.0]);
}

#[test]
fn failed_casts_become_nulls_with_messages() {
    let mut p = plan();
    p.nodes[1].inputs[0].value = Some(DataTree::from_list(vec![
        Value::Text("abc".into()),
        Value::Text("10".into()),
    ]));
    let mut e = Evaluator::new(p);
    e.evaluate();
    let texts: Vec<String> = e.messages().map(ToString::to_string).collect();
    assert_eq!(
        texts,
        ["error: node \"b\" at {0}[0]: input N: invalid cast: Text \"abc\" → Number"]
    );
    assert_eq!(numbers(e.node_output("sum1", "R").unwrap())[1], 12.0);
}

#[test]
fn graft_and_degrees_modifiers_apply_before_solving() {
    let mut p = plan();
    p.nodes[3].inputs[0].modifiers = vec![crate::Modifier::Graft];
    p.nodes[4].inputs[1].modifiers = vec![crate::Modifier::Degrees];
    p.nodes[2].inputs[0].value = Some(DataTree::from_item(180.0));
    let mut e = Evaluator::new(p);
    e.evaluate();
    let out = e.output("sum").unwrap();
    let paths: Vec<String> = out.paths().map(ToString::to_string).collect();
    assert_eq!(paths, ["{0;0}", "{0;1}"]);
    let v = numbers(out);
    assert!((v[0] - (11.0 + std::f64::consts::PI)).abs() < 1e-12);
}

#[test]
fn the_flat_layout_matches_the_plan() {
    let plan = plan();
    let layout = layout::Layout::new(&plan);
    for (i, node) in plan.nodes.iter().enumerate() {
        let names: Vec<&str> = layout.ports(i).iter().map(|p| p.name.as_str()).collect();
        let expected: Vec<&str> = node.inputs.iter().map(|p| p.port.name.as_str()).collect();
        assert_eq!(names, expected, "ports of {}", node.id.0);
        for (k, input) in node.inputs.iter().enumerate() {
            assert_eq!(layout.sources(i, k), input.sources.as_slice());
        }
        assert_eq!(
            layout.sources(i, node.inputs.len()),
            &[] as &[(usize, usize)]
        );
        assert_eq!(layout.outputs(i).len(), node.node_type.outputs.len());
    }
    // Graph inputs "a" (node 0) and "c" (node 2); no other input is set from outside.
    assert_eq!(layout.input_slot(0, 0), Some(0));
    assert_eq!(layout.input_slot(2, 0), Some(1));
    assert_eq!(layout.input_slot(1, 0), None);
    assert_eq!(layout.input_slot(0, 1), None);
    // Every output is wired or named except none: a, b, c feed the sums, sum2 is named.
    let wanted: Vec<bool> = (0..5).flat_map(|i| layout.wanted(i).to_vec()).collect();
    assert_eq!(wanted, [true; 5]);
    assert_eq!(layout.output_index(4, 0), Some(4));
    assert_eq!(layout.output_index(4, 1), None);
}

#[test]
#[should_panic(expected = "has no output 1")]
fn an_output_index_out_of_range_panics() {
    let mut e = Evaluator::new(plan());
    e.evaluate();
    // Node 3 has one output: index 1 must not read node 4's.
    e.node_output_at(3, 1);
}

#[test]
fn waves_run_in_depth_order_and_reruns_reuse_the_schedule() {
    let mut e = Evaluator::new(plan());
    e.evaluate();
    let ids = |e: &Evaluator| -> Vec<String> { e.last_run().iter().map(|n| n.0.clone()).collect() };
    assert_eq!(ids(&e), ["a", "b", "c", "sum1", "sum2"]);
    e.set_input("c", DataTree::from_item(1.0)).unwrap();
    e.evaluate();
    assert_eq!(ids(&e), ["c", "sum2"]);
    assert_eq!(numbers(e.output("sum").unwrap()), [12.0, 13.0]);
    e.expire_all();
    e.evaluate();
    assert_eq!(ids(&e), ["a", "b", "c", "sum1", "sum2"]);
    assert_eq!(numbers(e.output("sum").unwrap()), [12.0, 13.0]);
}

//! Output modifiers at run time: applied to the tree a node produced before any wire or named
//! output reads it, once per run of the node (a node that does not run again keeps its modified
//! tree and is not modified again), on outputs computed on request too, on the named outputs
//! of nodes with variable outputs, and within the item budget.

use locus_runtime::{
    DataTree, DataType, Document, Evaluator, Level, Limits, NodeRegistry, NodeType, Port,
};

fn registry() -> NodeRegistry {
    let mut r = NodeRegistry::new();
    // No item input, so its lists land on {0}: S = 0, 1, …, N − 1 and E = the even ones.
    r.register(
        NodeType::new("t.count", "Count", "Count", "Test")
            .input(Port::new("Number", "N", DataType::Integer).tree())
            .output(Port::new("Series", "S", DataType::Number).list())
            .output(Port::new("Even", "E", DataType::Number).list())
            .solve(|s| {
                let n = s
                    .tree(0)?
                    .values()
                    .flatten()
                    .find_map(|v| v.get::<i64>())
                    .unwrap_or(0);
                let all: Vec<f64> = (0..n).map(|i| i as f64).collect();
                let even: Vec<f64> = all.iter().copied().filter(|x| x % 2.0 == 0.0).collect();
                s.set_list(0, all);
                s.set_list(1, even);
                Ok(())
            }),
    );
    r.register(
        NodeType::new("t.add", "Addition", "A+B", "Test")
            .input(Port::new("A", "A", DataType::Number))
            .input(Port::new("B", "B", DataType::Number).default_value(0.0))
            .output(Port::new("Result", "R", DataType::Number))
            .output(Port::new("Positive", "P", DataType::Boolean))
            .solve(|s| {
                let r = *s.item::<f64>(0)? + *s.item::<f64>(1)?;
                s.set(0, r);
                s.set(1, r > 0.0);
                Ok(())
            }),
    );
    // Variable outputs: output k holds the input list times k + 1.
    r.register(
        NodeType::new("t.scale", "Scale", "Scale", "Test")
            .input(Port::new("List", "L", DataType::Number).list())
            .variable_outputs(Port::new("Out", "o", DataType::Number).list(), &["o"])
            .solve(|s| {
                let list: Vec<f64> = s.list::<f64>(0)?.present().copied().collect();
                let outputs = (0..).take_while(|&k| s.output_port(k).is_some()).count();
                for k in 0..outputs {
                    let factor = (k + 1) as f64;
                    s.set_list(k, list.iter().map(|x| x * factor).collect::<Vec<f64>>());
                }
                Ok(())
            }),
    );
    r
}

fn evaluator(text: &str) -> Evaluator {
    let document = Document::parse(text).expect("the graph reads");
    let checked = document.check(&registry()).expect("the graph checks");
    let mut e = Evaluator::new(checked.plan);
    e.evaluate();
    e
}

/// The tree as `{path}:[items]` text, branch after branch.
fn show(tree: &DataTree) -> String {
    tree.branches()
        .iter()
        .map(|(path, branch)| {
            let items: Vec<String> = branch
                .values()
                .map(|v| v.map_or("null".to_owned(), |v| locus_runtime::format_value(&v)))
                .collect();
            format!("{path}:[{}]", items.join(","))
        })
        .collect::<Vec<_>>()
        .join(" ")
}

const GRAPH: &str = r#"(format: 1, nodes: [
  (id: "count", type: "t.count", values: {"N": 3}, output_modifiers: {"S": [graft], "E": [reverse]}),
  (id: "b", type: "t.add", values: {"A": 10.0}),
  (id: "add", type: "t.add", output_modifiers: {"R": [flatten, reverse], "P": [invert]}),
  (id: "regraft", type: "t.add", modifiers: {"A": [graft]}),
], wires: [("count.S", "add.A"), ("b.R", "add.B"), ("add.R", "regraft.A")],
   inputs: {"b": "b.A"},
   outputs: {"grafted": "count.S", "sum": "add.R", "positive": "add.P", "regrafted": "regraft.R"})"#;

#[test]
fn wires_and_named_outputs_read_the_modified_tree() {
    let e = evaluator(GRAPH);
    // count.S is {0}:[0,1,2] before its graft; add (+10) follows the grafted paths, then its
    // flatten and reverse give one list; regraft grafts that list again at its input.
    assert_eq!(
        show(e.output("grafted").unwrap()),
        "{0;0}:[0] {0;1}:[1] {0;2}:[2]"
    );
    assert_eq!(show(e.output("sum").unwrap()), "{0}:[12,11,10]");
    assert_eq!(
        show(e.output("positive").unwrap()),
        "{0;0}:[False] {0;1}:[False] {0;2}:[False]"
    );
    assert_eq!(
        show(e.output("regrafted").unwrap()),
        "{0;0}:[12] {0;1}:[11] {0;2}:[10]"
    );
    assert_eq!(
        e.messages().count(),
        0,
        "{:?}",
        e.messages().collect::<Vec<_>>()
    );
}

#[test]
fn an_output_computed_on_request_is_modified_too() {
    let e = evaluator(GRAPH);
    // Nothing reads count.E, so it is computed when first asked for: 0, 2 reversed.
    assert_eq!(show(e.node_output("count", "E").unwrap()), "{0}:[2,0]");
}

#[test]
fn a_node_that_does_not_run_again_is_not_modified_again() {
    let mut e = evaluator(GRAPH);
    e.set_input("b", DataTree::from_item(-20.0)).unwrap();
    e.evaluate();
    let ran: Vec<&str> = e.last_run().iter().map(|id| id.0.as_str()).collect();
    assert!(!ran.contains(&"count"), "{ran:?}");
    // count keeps its tree grafted once (a second graft would give {0;0;0}: …).
    assert_eq!(
        show(e.output("grafted").unwrap()),
        "{0;0}:[0] {0;1}:[1] {0;2}:[2]"
    );
    assert_eq!(show(e.output("sum").unwrap()), "{0}:[-18,-19,-20]");
    assert_eq!(
        show(e.output("positive").unwrap()),
        "{0;0}:[True] {0;1}:[True] {0;2}:[True]"
    );
}

#[test]
fn named_variable_outputs_take_modifiers() {
    let e = evaluator(
        r#"(format: 1, nodes: [
  (id: "count", type: "t.count", values: {"N": 3}),
  (id: "scale", type: "t.scale", outputs: ["x1", "x2"], output_modifiers: {"x2": [graft, reverse]}),
], wires: [("count.S", "scale.L")], outputs: {"x1": "scale.x1", "x2": "scale.x2"})"#,
    );
    assert_eq!(show(e.output("x1").unwrap()), "{0}:[0,1,2]");
    // Grafted first, so reversing each one-item branch changes nothing.
    assert_eq!(
        show(e.output("x2").unwrap()),
        "{0;0}:[0] {0;1}:[2] {0;2}:[4]"
    );
}

#[test]
fn a_graft_beyond_the_item_budget_empties_the_output_with_an_error() {
    let document = Document::parse(
        r#"(format: 1, nodes: [
  (id: "count", type: "t.count", values: {"N": 40}, output_modifiers: {"S": [graft]}),
], outputs: {"s": "count.S", "e": "count.E"})"#,
    )
    .unwrap();
    let checked = document.check(&registry()).unwrap();
    let mut e = Evaluator::new(checked.plan);
    e.set_limits(Limits {
        max_items_per_output: 50,
        ..Limits::default()
    });
    e.evaluate();
    // 40 items grafted are 40 items in 40 branches: 80 entries, above 50.
    assert!(e.output("s").unwrap().is_empty());
    let errors: Vec<String> = e
        .node_messages("count")
        .filter(|m| m.level == Level::Error)
        .map(|m| m.text.clone())
        .collect();
    assert_eq!(
        errors,
        [
            "grafting output S would make 40 branches (80 items and branches), above the limit of \
          50 items per output"
        ]
    );
}

//! A generic output whose branch holds items of one type is stored as a typed column (nulls
//! kept), so that typed nodes downstream read contiguous slices; mixed branches stay generic.

use locus_runtime::{DataType, Document, Evaluator, NodeRegistry, NodeType, Port, Value};

/// `test.pick`: a generic item output that is the number, a null for negative numbers and
/// text for 99; `test.list`: the same as a list output.
fn registry() -> NodeRegistry {
    fn pick(x: f64) -> Option<Value> {
        if x < 0.0 {
            None
        } else if x == 99.0 {
            Some(Value::Text("ninety-nine".into()))
        } else {
            Some(Value::Number(x))
        }
    }
    let mut r = NodeRegistry::new();
    r.register(
        NodeType::new("test.pick", "Pick", "Pick", "Test")
            .input(Port::new("Number", "N", DataType::Number))
            .output(Port::new("Result", "R", DataType::Generic))
            .solve(|s| {
                let x = *s.item::<f64>(0)?;
                s.set_value(0, pick(x));
                Ok(())
            }),
    );
    r.register(
        NodeType::new("test.list", "List", "List", "Test")
            .input(Port::new("Numbers", "N", DataType::Number).list())
            .output(Port::new("Result", "R", DataType::Generic).list())
            .solve(|s| {
                let values = s
                    .branch(0)
                    .map(|b| {
                        b.values()
                            .map(|v| v.and_then(|v| pick(v.get::<f64>()?)))
                            .collect()
                    })
                    .unwrap_or_default();
                s.set_list_values(0, values);
                Ok(())
            }),
    );
    r.register(
        NodeType::new("test.sum", "Sum", "Sum", "Test")
            .input(Port::new("Numbers", "N", DataType::Number).list())
            .output(Port::new("Sum", "S", DataType::Number))
            .solve(|s| {
                // Reads the typed slice directly: it is there only if the column is typed.
                let branch = s.branch(0).ok_or("no branch")?;
                let items = branch.slice::<f64>().ok_or("not a number column")?;
                let sum: f64 = (0..items.len())
                    .filter(|&i| !branch.is_null(i))
                    .map(|i| items[i])
                    .sum();
                s.set(0, sum);
                Ok(())
            }),
    );
    r
}

fn run(numbers: &str) -> Evaluator {
    let text = format!(
        r#"(
    format: 1,
    nodes: [
        (id: "p", type: "test.pick", values: {{"N": {numbers}}}),
        (id: "l", type: "test.list", values: {{"N": {numbers}}}),
        (id: "s", type: "test.sum"),
    ],
    wires: [("p.R", "s.N")],
    outputs: {{"item": "p.R", "list": "l.R", "sum": "s.S"}},
)"#
    );
    let checked = Document::parse(&text).unwrap().check(&registry()).unwrap();
    let mut e = Evaluator::new(checked.plan);
    e.evaluate();
    e
}

#[test]
fn one_type_branches_become_typed_columns_with_their_nulls() {
    let e = run("[1, -1, 2.5]");
    for name in ["item", "list"] {
        let tree = e.output(name).unwrap();
        let branch = &tree.branches()[0].1;
        assert_eq!(branch.data_type(), DataType::Number, "{name}");
        assert_eq!(branch.null_mask(), [false, true, false], "{name}");
        assert_eq!(
            branch.values().collect::<Vec<_>>(),
            [Some(Value::Number(1.0)), None, Some(Value::Number(2.5))],
            "{name}"
        );
    }
    // The typed node downstream reads the number column.
    assert_eq!(
        e.output("sum").unwrap().values().collect::<Vec<_>>(),
        [Some(Value::Number(3.5))]
    );
    assert_eq!(e.messages().count(), 0);
}

#[test]
fn mixed_and_all_null_branches_stay_generic() {
    let e = run("[1, 99]");
    for name in ["item", "list"] {
        let branch = &e.output(name).unwrap().branches()[0].1;
        assert_eq!(branch.data_type(), DataType::Generic, "{name}");
        assert_eq!(
            branch.values().collect::<Vec<_>>(),
            [
                Some(Value::Number(1.0)),
                Some(Value::Text("ninety-nine".into()))
            ]
        );
    }
    let e = run("[-1, -2]");
    for name in ["item", "list"] {
        let branch = &e.output(name).unwrap().branches()[0].1;
        assert_eq!(branch.data_type(), DataType::Generic, "{name}");
        assert_eq!(branch.values().collect::<Vec<_>>(), [None, None]);
    }
}

//! The example graphs `graphs/maths_*.ron`, rebuilt node by node with `NodeCall`, so that their
//! expected outputs are checked even before the graph reader runs them.

use locus_kernel::{Interval, Point3};
use locus_nodes::maths::{comparison, domain, script, sequence};
use locus_nodes::params::primitive;
use locus_runtime::{Branch, DataTree, DataType, NodeCall, TreePath, Value};

fn branch_values(tree: &DataTree, path: &[u32]) -> Vec<Value> {
    let branch = tree
        .branch(&TreePath::new(path.to_vec()))
        .unwrap_or_else(|| panic!("no branch {path:?} in\n{tree}"));
    branch.values().map(|v| v.expect("no nulls")).collect()
}

/// The tree with its generic number items in a Number column: what the runtime's cast does on
/// the way into a Number port (wired in a graph, the evaluator does this itself).
fn as_number_tree(tree: &DataTree) -> DataTree {
    DataTree::from_branches(tree.branches().iter().map(|(path, branch)| {
        let mut typed = Branch::new(DataType::Number);
        for v in branch.values() {
            match v {
                Some(Value::Number(x)) => typed.push(x),
                _ => typed.push_null(),
            }
        }
        (path.clone(), typed)
    }))
}

fn numbers(values: &[f64]) -> Vec<Value> {
    values.iter().map(|&x| Value::Number(x)).collect()
}

fn booleans(values: &[bool]) -> Vec<Value> {
    values.iter().map(|&b| Value::Boolean(b)).collect()
}

#[test]
fn maths_range_remap() {
    let dom = NodeCall::new(&domain::construct_domain())
        .input(DataTree::from_item(0.0))
        .input(DataTree::from_item(10.0))
        .run();
    let steps = NodeCall::new(&primitive::integer())
        .input(DataTree::from_item(4_i64))
        .run();
    let range = NodeCall::new(&sequence::range())
        .input(dom.outputs[0].clone())
        .input(steps.outputs[0].clone())
        .run();
    let remap = NodeCall::new(&domain::remap_numbers())
        .input(range.outputs[0].clone())
        .input(dom.outputs[0].clone())
        .input(DataTree::from_item(Interval::UNIT))
        .run();
    let half = NodeCall::new(&comparison::larger_than())
        .input(remap.outputs[0].clone())
        .input(DataTree::from_item(0.5))
        .run();
    assert_eq!(
        branch_values(&range.outputs[0], &[0, 0]),
        numbers(&[0.0, 2.5, 5.0, 7.5, 10.0])
    );
    assert_eq!(
        branch_values(&remap.outputs[0], &[0, 0]),
        numbers(&[0.0, 0.25, 0.5, 0.75, 1.0])
    );
    assert_eq!(
        branch_values(&half.outputs[1], &[0, 0]),
        booleans(&[false, false, true, true, true])
    );
}

#[test]
fn maths_expression_points() {
    let t = NodeCall::new(&sequence::series())
        .input(DataTree::from_item(0.0))
        .input(DataTree::from_item(0.25))
        .input(DataTree::from_item(5_i64))
        .run();
    let d = NodeCall::new(&script::expression())
        .input_names(&["A", "B", "t"])
        .setting("expression", Value::Text("A + t*(B-A)".to_owned()))
        .input(DataTree::from_item(Point3::new(0.0, 0.0, 0.0)))
        .input(DataTree::from_item(Point3::new(30.0, 40.0, 0.0)))
        .input(t.outputs[0].clone())
        .run();
    let length = NodeCall::new(&script::evaluate())
        .input_names(&["F", "p"])
        .input(DataTree::from_item("abs(p)".to_owned()))
        .input(d.outputs[0].clone())
        .run();
    let far = NodeCall::new(&comparison::larger_than())
        .input(as_number_tree(&length.outputs[0]))
        .input(DataTree::from_item(20.0))
        .run();
    let points: Vec<Value> = [
        (0.0, 0.0),
        (7.5, 10.0),
        (15.0, 20.0),
        (22.5, 30.0),
        (30.0, 40.0),
    ]
    .iter()
    .map(|&(x, y)| Value::Point(Point3::new(x, y, 0.0)))
    .collect();
    assert_eq!(branch_values(&d.outputs[0], &[0, 0]), points);
    assert_eq!(
        branch_values(&length.outputs[0], &[0, 0]),
        numbers(&[0.0, 12.5, 25.0, 37.5, 50.0])
    );
    assert_eq!(
        branch_values(&far.outputs[0], &[0, 0]),
        booleans(&[false, false, true, true, true])
    );
    for r in [&t, &d, &length, &far] {
        assert!(r.messages.is_empty(), "{:?}", r.messages);
    }
}

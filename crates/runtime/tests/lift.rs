//! Lifted item functions (`lift1`/`lift2`/`lift3`) give exactly what the same function gives as a
//! general solve function: same items, nulls, paths and messages, for every matching mode,
//! with nulls, empty and missing branches, failing items, and on one or two threads.

use locus_runtime::{
    Branch, DataTree, DataType, Evaluator, Matching, NodeCall, NodeError, NodeRegistry, NodeType,
    Port, TreePath,
};
use proptest::prelude::*;

fn add(a: &f64, b: &f64) -> Result<f64, NodeError> {
    if a + b > 8.0 {
        return Err(NodeError(format!("sum {} is too large", a + b)));
    }
    Ok(a + b)
}

/// `add`, made slow enough per item (some microseconds) for the runtime to spread it over
/// threads.
fn slow_add(a: &f64, b: &f64) -> Result<f64, NodeError> {
    let mut x = *a;
    for _ in 0..20 {
        x = std::hint::black_box(x.sin());
    }
    std::hint::black_box(x);
    add(a, b)
}

fn ports(id: &str, optional_b: bool) -> NodeType {
    let b = Port::new("B", "B", DataType::Number);
    NodeType::new(id, "Addition", "A+B", "Test")
        .input(Port::new("A", "A", DataType::Number))
        .input(if optional_b { b.optional() } else { b })
        .output(Port::new("Result", "R", DataType::Number))
}

fn lifted(optional_b: bool) -> NodeType {
    ports("test.lifted", optional_b).lift2(add)
}

fn general(optional_b: bool) -> NodeType {
    ports("test.general", optional_b).solve(|s| {
        let r = add(s.item::<f64>(0)?, s.item::<f64>(1)?)?;
        s.set(0, r);
        Ok(())
    })
}

/// A number tree from branches of optional items.
fn tree(branches: &[(Vec<u32>, Vec<Option<u8>>)]) -> DataTree {
    let mut t = DataTree::new();
    for (path, items) in branches {
        let mut b = Branch::new(DataType::Number);
        for item in items {
            match item {
                Some(x) => b.push(f64::from(*x)),
                None => b.push_null(),
            }
        }
        t.insert(TreePath::new(path.clone()), b);
    }
    t
}

fn branches() -> impl Strategy<Value = Vec<(Vec<u32>, Vec<Option<u8>>)>> {
    prop::collection::vec(
        (
            prop::collection::vec(0u32..3, 1..3),
            prop::collection::vec(prop::option::weighted(0.85, 0u8..6), 0..6),
        ),
        0..4,
    )
}

fn matching() -> impl Strategy<Value = Matching> {
    prop_oneof![
        Just(Matching::Longest),
        Just(Matching::Shortest),
        Just(Matching::Cross)
    ]
}

proptest! {
    #[test]
    fn lifted_and_general_agree(
        a in branches(),
        b in branches(),
        m in matching(),
        optional_b: bool,
    ) {
        let (ta, tb) = (tree(&a), tree(&b));
        let run = |node: &NodeType| {
            let r = NodeCall::new(node).input(ta.clone()).input(tb.clone()).matching(m).run();
            let messages: Vec<String> = r
                .messages
                .iter()
                .map(|m| format!("{:?} {:?} {:?} {}", m.level, m.path, m.index, m.text))
                .collect();
            (r.outputs, messages)
        };
        prop_assert_eq!(run(&lifted(optional_b)), run(&general(optional_b)));
    }
}

#[test]
fn calling_solve_after_lift_replaces_the_item_function() {
    let node = lifted(false).solve(|s| {
        s.set(0, 1.0);
        Ok(())
    });
    let r = NodeCall::new(&node)
        .input(DataTree::from_list(vec![1.0, 2.0]))
        .input(DataTree::from_item(1.0))
        .run();
    assert_eq!(r.outputs[0], DataTree::from_list(vec![1.0, 1.0]));
}

#[test]
fn one_and_lift3_lift_too() {
    let neg = NodeType::new("t.neg", "Negative", "Neg", "Test")
        .input(Port::new("x", "x", DataType::Integer))
        .output(Port::new("y", "y", DataType::Integer))
        .lift1(|x: &i64| x.checked_neg().ok_or_else(|| NodeError::from("overflow")));
    let r = NodeCall::new(&neg)
        .input(DataTree::from_list(vec![1i64, i64::MIN, -3]))
        .run();
    assert_eq!(r.outputs[0].to_text(), "{0}:[-1, null, 3]");
    assert_eq!(
        r.messages[0].to_string(),
        "error: node \"t.neg\" at {0}[1]: overflow"
    );
    let mul_add = NodeType::new("t.fma", "Fma", "Fma", "Test")
        .input(Port::new("a", "a", DataType::Number))
        .input(Port::new("b", "b", DataType::Number))
        .input(Port::new("c", "c", DataType::Number))
        .output(Port::new("r", "r", DataType::Number))
        .lift3(|a: &f64, b: &f64, c: &f64| Ok(a * b + c));
    let r = NodeCall::new(&mul_add)
        .input(DataTree::from_list(vec![1.0, 2.0, 3.0]))
        .input(DataTree::from_item(10.0))
        .input(DataTree::from_list(vec![0.5, 0.25]))
        .run();
    assert_eq!(r.outputs[0], DataTree::from_list(vec![10.5, 20.25, 30.25]));
}

/// Large branches split over two threads give the same items, nulls and messages as one
/// thread, in the same order (with and without null items, with failing items).
#[test]
fn large_lifted_branches_agree_on_one_and_two_threads() {
    let mut registry = NodeRegistry::new();
    registry.register(lifted(false));
    registry.register(general(false));
    registry.register(ports("test.slow", false).lift2(slow_add));
    let n = 100_000usize;
    for with_nulls in [true, false] {
        let mut a = Branch::new(DataType::Number);
        for i in 0..n {
            if with_nulls && i % 9_999 == 0 {
                a.push_null();
            } else {
                a.push((i % 10) as f64);
            }
        }
        let mut ta = DataTree::new();
        ta.insert(TreePath::zero(), a.clone());
        ta.insert(TreePath::from([1]), a);
        let results: Vec<_> = [
            ("test.lifted", 1),
            ("test.lifted", 2),
            ("test.general", 1),
            ("test.slow", 2),
        ]
        .into_iter()
        .map(|(node_type, threads)| {
            let text = format!(
                r#"(format: 1, nodes: [(id: "n", type: "{node_type}", values: {{"B": 0.5}})],
                       inputs: {{"a": "n.A"}}, outputs: {{"r": "n.R"}})"#
            );
            let mut e = Evaluator::from_text(&text, &registry).unwrap();
            e.set_threads(threads).unwrap();
            e.set_input("a", ta.clone()).unwrap();
            e.evaluate();
            let messages: Vec<String> = e.messages().map(ToString::to_string).collect();
            (e.output("r").unwrap().clone(), messages)
        })
        .collect();
        let failing = (0..n)
            .filter(|i| !(with_nulls && i % 9_999 == 0) && i % 10 >= 8)
            .count();
        assert_eq!(results[0].1.len(), 2 * failing);
        assert_eq!(results[0].0.item_count(), 2 * n);
        assert_eq!(results[0], results[1]);
        assert_eq!(results[0], results[2]);
        assert_eq!(results[0], results[3]);
    }
}

/// An item function with two outputs that warns above 6 and fails above 8, for
/// `lift2_with_plain` against `lift2_with`.
fn sum_and_order(
    a: &f64,
    b: &f64,
    report: &mut locus_runtime::ItemReport,
) -> Result<(f64, bool), NodeError> {
    if a + b > 6.0 {
        report.warning(format!("sum {} is large", a + b));
    }
    add(a, b).map(|s| (s, a > b))
}

fn two_outputs(id: &str, optional_b: bool) -> NodeType {
    ports(id, optional_b).output(Port::new("Larger", "L", DataType::Boolean))
}

proptest! {
    #[test]
    fn the_plain_loop_agrees_with_the_reporting_loop(
        a in branches(),
        b in branches(),
        m in matching(),
        optional_b: bool,
    ) {
        let (ta, tb) = (tree(&a), tree(&b));
        let plain = two_outputs("test.plain", optional_b).lift2_with_plain(
            |a: &f64, b: &f64| a + b <= 6.0,
            |a: &f64, b: &f64| (a + b, a > b),
            sum_and_order,
        );
        let reporting = two_outputs("test.reporting", optional_b).lift2_with(sum_and_order);
        let run = |node: &NodeType| {
            let r = NodeCall::new(node).input(ta.clone()).input(tb.clone()).matching(m).run();
            let messages: Vec<String> = r
                .messages
                .iter()
                .map(|m| format!("{:?} {:?} {:?} {}", m.level, m.path, m.index, m.text))
                .collect();
            (r.outputs, messages)
        };
        prop_assert_eq!(run(&plain), run(&reporting));
    }
}

proptest! {
    #[test]
    fn the_plain_loop_of_three_inputs_agrees_with_the_reporting_loop(
        a in branches(),
        b in branches(),
        c in branches(),
        m in matching(),
    ) {
        let three = |id: &str| {
            NodeType::new(id, "Sum3", "S3", "Test")
                .input(Port::new("A", "A", DataType::Number))
                .input(Port::new("B", "B", DataType::Number))
                .input(Port::new("C", "C", DataType::Number))
                .output(Port::new("Sum", "S", DataType::Number))
                .output(Port::new("Larger", "L", DataType::Boolean))
        };
        let f = |a: &f64, b: &f64, c: &f64, r: &mut locus_runtime::ItemReport| {
            sum_and_order(&(a + c), b, r)
        };
        let plain = three("test.sum3").lift3_with_plain(
            |a: &f64, b: &f64, c: &f64| a + c + b <= 6.0,
            |a: &f64, b: &f64, c: &f64| (a + c + b, a + c > *b),
            f,
        );
        let reporting = three("test.sum3").lift3_with(f);
        let (ta, tb, tc) = (tree(&a), tree(&b), tree(&c));
        let run = |node: &NodeType| {
            let r = NodeCall::new(node)
                .input(ta.clone())
                .input(tb.clone())
                .input(tc.clone())
                .matching(m)
                .run();
            let messages: Vec<String> = r.messages.iter().map(|m| m.to_string()).collect();
            (r.outputs, messages)
        };
        prop_assert_eq!(run(&plain), run(&reporting));
    }
}

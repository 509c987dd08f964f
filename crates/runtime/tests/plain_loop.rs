//! The loop without reports of `lift2_with_plain`, `lift3_with_plain` and
//! `fast_path2_with_plain` (and `lift1_with_plain`) gives exactly what the reporting loop gives (the items of both
//! outputs, nulls, and messages with path and index) on long branches, several chunks of the
//! loop long, with items that are not clean in random places (one here and there, or most of
//! them), with the second input a full branch, one item or a shorter branch, on one and two
//! threads, and with either output or both read; and for nodes of one output and of three,
//! with any set of the three read (the pass writes one output, all of them, or some of
//! several in different ways).

use locus_runtime::{
    Branch, DataTree, DataType, Evaluator, ItemReport, NodeError, NodeRegistry, NodeType, Port,
    TreePath,
};
use proptest::prelude::*;

/// Two outputs: the sum and whether `a > b`. Warns above 6, fails (both outputs null) above 8,
/// and fails output 1 only for a NaN input (output 0 is then -1).
fn sum_and_order(a: &f64, b: &f64, report: &mut ItemReport) -> Result<(f64, bool), NodeError> {
    let s = a + b;
    if s.is_nan() {
        report.error(1, "an input is NaN");
        // Not the NaN, which would compare unequal to itself in the test.
        return Ok((-1.0, false));
    }
    if s > 6.0 {
        report.warning(format!("sum {s} is large"));
    }
    if s > 8.0 {
        return Err(NodeError(format!("sum {s} is too large")));
    }
    Ok((s, a > b))
}

/// Where `sum_and_order` reports nothing.
fn clean(a: &f64, b: &f64) -> bool {
    a + b <= 6.0
}

/// `sum_and_order` where it is clean (and something else, never a panic, elsewhere).
fn plain(a: &f64, b: &f64) -> (f64, bool) {
    (a + b, a > b)
}

fn node(id: &str, generic: bool) -> NodeType {
    let t = |t| if generic { DataType::Generic } else { t };
    NodeType::new(id, "Sum", "S", "Test")
        .input(Port::new("A", "A", t(DataType::Number)))
        .input(Port::new("B", "B", t(DataType::Number)))
        .output(Port::new("Sum", "R", t(DataType::Number)))
        .output(Port::new("Larger", "L", t(DataType::Boolean)))
}

/// The node types compared, all with the same results: the reporting loop, the plain loops of
/// two and three inputs (the third input is a zero added to `a`), and a fast path with the
/// plain loop on generic ports (which leaves the items whose `a` is exactly 5 to the general
/// solve function, so that some branches fall back to it).
fn registry() -> NodeRegistry {
    let mut r = NodeRegistry::new();
    r.register(node("t.reporting", false).lift2_with(sum_and_order));
    r.register(node("t.plain2", false).lift2_with_plain(clean, plain, sum_and_order));
    r.register(
        node("t.plain3", false)
            .input(Port::new("C", "C", DataType::Number).default_value(0.0))
            .lift3_with_plain(
                |a: &f64, b: &f64, c: &f64| clean(&(a + c), b),
                |a: &f64, b: &f64, c: &f64| plain(&(a + c), b),
                |a: &f64, b: &f64, c: &f64, r: &mut ItemReport| sum_and_order(&(a + c), b, r),
            ),
    );
    r.register(
        node("t.fast", true)
            .solve(|s| {
                // `sum_and_order` as a general solve function.
                let (a, b) = (*s.item::<f64>(0)?, *s.item::<f64>(1)?);
                let sum = a + b;
                if sum.is_nan() {
                    s.error("an input is NaN");
                    s.set(0, -1.0);
                    return Ok(());
                }
                if sum > 6.0 {
                    s.warning(format!("sum {sum} is large"));
                }
                if sum > 8.0 {
                    return Err(NodeError(format!("sum {sum} is too large")));
                }
                s.set(0, sum);
                s.set(1, a > b);
                Ok(())
            })
            .fast_path2_with_plain(clean, plain, |a: &f64, b: &f64, r| {
                (*a != 5.0).then(|| sum_and_order(a, b, r))
            }),
    );
    r
}

/// A branch of `n` numbers: clean ones (0 to 2.5) but at `dirty` positions (taken modulo
/// `n`), and a fraction `dense` of all items, which are large or NaN.
fn numbers(n: usize, dirty: &[usize], dense: f64, seed: u64) -> Branch {
    let mut b = Branch::new(DataType::Number);
    let mut x = seed | 1;
    let mut next = || {
        // xorshift: reproducible from the seed proptest chose.
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        x
    };
    let bad = [7.0, 9.0, f64::NAN, 5.0];
    for k in 0..n {
        let r = next();
        let value = if dirty.iter().any(|&d| d % n == k) || (r % 1000) as f64 / 1000.0 < dense {
            bad[(r >> 20) as usize % bad.len()]
        } else {
            (r >> 30) as f64 % 6.0 / 2.0
        };
        b.push(value);
    }
    b
}

fn run(
    registry: &NodeRegistry,
    node_type: &str,
    a: &DataTree,
    b: &DataTree,
    threads: usize,
    read: &str,
) -> (Vec<DataTree>, Vec<String>) {
    let outputs = match read {
        "R" => r#""r": "n.R""#,
        "L" => r#""l": "n.L""#,
        _ => r#""r": "n.R", "l": "n.L""#,
    };
    let text = format!(
        r#"(format: 1, nodes: [(id: "n", type: "{node_type}")],
               inputs: {{"a": "n.A", "b": "n.B"}}, outputs: {{{outputs}}})"#
    );
    let mut e = Evaluator::from_text(&text, registry).unwrap();
    e.set_threads(threads).unwrap();
    e.set_input("a", a.clone()).unwrap();
    e.set_input("b", b.clone()).unwrap();
    e.evaluate();
    let outputs = e.outputs().map(|(_, tree)| tree.clone()).collect();
    let messages = e.messages().map(ToString::to_string).collect();
    (outputs, messages)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]
    #[test]
    fn the_plain_loops_agree_with_the_reporting_loop_on_long_branches(
        n in 1usize..5_000,
        dirty in prop::collection::vec(any::<usize>(), 0..6),
        dense in prop_oneof![4 => Just(0.0), 1 => Just(0.002), 1 => Just(0.6), 1 => Just(1.0)],
        seed: u64,
        b_kind in 0usize..3,
        b_len in 1usize..3_000,
        two_branches: bool,
        threads in 1usize..3,
        read in prop_oneof![Just("R"), Just("L"), Just("RL")],
    ) {
        let a_branch = numbers(n, &dirty, dense, seed);
        let b_branch = match b_kind {
            0 => numbers(n, &[], 0.0, seed ^ 0x9e37),
            1 => numbers(1, &[], 0.0, seed ^ 0x9e37),
            _ => numbers(b_len, &dirty, dense / 2.0, seed ^ 0x7f4a),
        };
        let tree = |branch: Branch| {
            let mut t = DataTree::new();
            if two_branches {
                t.insert(TreePath::from([1]), branch.clone());
            }
            t.insert(TreePath::zero(), branch);
            t
        };
        let (a, b) = (tree(a_branch), tree(b_branch));
        let registry = registry();
        let expected = run(&registry, "t.reporting", &a, &b, 1, read);
        for node_type in ["t.plain2", "t.plain3", "t.fast"] {
            prop_assert_eq!(
                &run(&registry, node_type, &a, &b, threads, read),
                &expected,
                "{}", node_type
            );
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(32))]
    #[test]
    fn the_plain_loop_of_one_input_agrees_with_the_reporting_loop(
        n in 1usize..5_000,
        dirty in prop::collection::vec(any::<usize>(), 0..6),
        dense in prop_oneof![4 => Just(0.0), 1 => Just(0.002), 1 => Just(0.6), 1 => Just(1.0)],
        seed: u64,
        threads in 1usize..3,
        read in prop_oneof![Just("R"), Just("L"), Just("RL")],
    ) {
        let one = |id: &str| {
            NodeType::new(id, "Sum", "S", "Test")
                .input(Port::new("A", "A", DataType::Number))
                .output(Port::new("Sum", "R", DataType::Number))
                .output(Port::new("Larger", "L", DataType::Boolean))
        };
        let f = |a: &f64, r: &mut ItemReport| sum_and_order(a, &1.0, r);
        let mut registry = NodeRegistry::new();
        registry.register(one("t.reporting").lift1_with(f));
        registry.register(one("t.plain1").lift1_with_plain(
            |a: &f64| clean(a, &1.0),
            |a: &f64| plain(a, &1.0),
            f,
        ));
        let mut a = DataTree::new();
        a.insert(TreePath::zero(), numbers(n, &dirty, dense, seed));
        let outputs = match read {
            "R" => r#""r": "n.R""#,
            "L" => r#""l": "n.L""#,
            _ => r#""r": "n.R", "l": "n.L""#,
        };
        let run = |node_type: &str| {
            let text = format!(
                r#"(format: 1, nodes: [(id: "n", type: "{node_type}")],
                       inputs: {{"a": "n.A"}}, outputs: {{{outputs}}})"#
            );
            let mut e = Evaluator::from_text(&text, &registry).unwrap();
            e.set_threads(threads).unwrap();
            e.set_input("a", a.clone()).unwrap();
            e.evaluate();
            let trees: Vec<DataTree> = e.outputs().map(|(_, tree)| tree.clone()).collect();
            let messages: Vec<String> = e.messages().map(ToString::to_string).collect();
            (trees, messages)
        };
        prop_assert_eq!(run("t.plain1"), run("t.reporting"));
    }
}

/// `sum_and_order` with a third output, the product (-2 where it is NaN).
fn sum_order_product(
    a: &f64,
    b: &f64,
    report: &mut ItemReport,
) -> Result<(f64, bool, f64), NodeError> {
    sum_and_order(a, b, report).map(|(s, l)| (s, l, product(a, b)))
}

/// `a * b`, or -2 where that is NaN (which would compare unequal to itself in the test).
fn product(a: &f64, b: &f64) -> f64 {
    let p = a * b;
    if p.is_nan() { -2.0 } else { p }
}

/// One output, the sum: as `sum_and_order`, but a NaN input fails the item.
fn sum_only(a: &f64, b: &f64, report: &mut ItemReport) -> Result<(f64,), NodeError> {
    if (a + b).is_nan() {
        return Err(NodeError("an input is NaN".into()));
    }
    sum_and_order(a, b, report).map(|(s, _)| (s,))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(32))]
    #[test]
    fn the_plain_loop_agrees_with_the_reporting_loop_for_one_and_three_outputs(
        n in 1usize..5_000,
        dirty in prop::collection::vec(any::<usize>(), 0..6),
        dense in prop_oneof![4 => Just(0.0), 1 => Just(0.002), 1 => Just(0.6), 1 => Just(1.0)],
        seed: u64,
        single_b: bool,
        threads in 1usize..3,
        // Which of the three outputs are read (bits), every set but the empty one.
        read in 1u32..8,
    ) {
        let three = |id: &str| {
            node(id, false).output(Port::new("Product", "P", DataType::Number))
        };
        let one = |id: &str| {
            NodeType::new(id, "Sum", "S", "Test")
                .input(Port::new("A", "A", DataType::Number))
                .input(Port::new("B", "B", DataType::Number))
                .output(Port::new("Sum", "R", DataType::Number))
        };
        let mut registry = NodeRegistry::new();
        registry.register(three("t.reporting3").lift2_with(sum_order_product));
        registry.register(three("t.plain3").lift2_with_plain(
            clean,
            |a: &f64, b: &f64| (a + b, a > b, product(a, b)),
            sum_order_product,
        ));
        registry.register(one("t.reporting1").lift2_with(sum_only));
        registry.register(one("t.plain1").lift2_with_plain(
            clean,
            |a: &f64, b: &f64| (a + b,),
            sum_only,
        ));
        let tree = |branch: Branch| {
            let mut t = DataTree::new();
            t.insert(TreePath::zero(), branch);
            t
        };
        let a = tree(numbers(n, &dirty, dense, seed));
        let b = tree(numbers(if single_b { 1 } else { n }, &[], 0.0, seed ^ 0x9e37));
        let run = |node_type: &str, read: u32| {
            let outputs: Vec<String> = ["R", "L", "P"]
                .iter()
                .enumerate()
                .filter(|&(k, _)| read & (1 << k) != 0)
                .map(|(_, o)| format!(r#""{}": "n.{o}""#, o.to_lowercase()))
                .collect();
            let text = format!(
                r#"(format: 1, nodes: [(id: "n", type: "{node_type}")],
                       inputs: {{"a": "n.A", "b": "n.B"}}, outputs: {{{}}})"#,
                outputs.join(", ")
            );
            let mut e = Evaluator::from_text(&text, &registry).unwrap();
            e.set_threads(threads).unwrap();
            e.set_input("a", a.clone()).unwrap();
            e.set_input("b", b.clone()).unwrap();
            e.evaluate();
            let trees: Vec<DataTree> = e.outputs().map(|(_, tree)| tree.clone()).collect();
            let messages: Vec<String> = e.messages().map(ToString::to_string).collect();
            (trees, messages)
        };
        prop_assert_eq!(run("t.plain3", read), run("t.reporting3", read));
        prop_assert_eq!(run("t.plain1", 1), run("t.reporting1", 1));
    }
}

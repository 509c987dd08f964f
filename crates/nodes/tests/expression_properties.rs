//! Property tests of the expression language: no input makes the parser or evaluator panic,
//! and formulas agree with the operator nodes they mirror.

use locus_kernel::{Point3, Vector3};
use locus_nodes::expression::{Operand, Program};
use locus_nodes::maths::{operators, script};
use locus_runtime::{DataTree, Level, NodeCall, NodeType, Value};
use proptest::prelude::*;

/// Pieces of formulas, valid and not, including every operator, keyword and function kind.
const TOKENS: &[&str] = &[
    "x", "y", "z", "X", "1", "0", "2.5", ".5", "1e3", "1e400", "+", "-", "*", "/", "%", "^", "&",
    "<", "<=", ">", ">=", "=", "==", "!=", "<>", "(", ")", "(", ")", ",", ".", ".x", ".y", "and",
    "or", "xor", "not", "true", "false", "if", "if(", "sqrt", "sqrt(", "min(", "max", "round(",
    "log(", "atan2(", "abs(", "frac", "pi", "e", "π", "−", "×", "≤", "\"t\"", "\"", "#", "foo",
    "foo(", "!", "\\",
];

fn number() -> impl Strategy<Value = f64> {
    prop_oneof![
        4 => -1e3..1e3_f64,
        1 => Just(0.0),
        1 => Just(f64::NAN),
        1 => Just(f64::INFINITY),
        1 => Just(-0.0),
        1 => any::<f64>(),
    ]
}

fn finite() -> impl Strategy<Value = f64> {
    -1e6..1e6_f64
}

/// Any value an expression variable may hold.
fn operand() -> impl Strategy<Value = Operand> {
    prop_oneof![
        number().prop_map(Operand::Number),
        any::<bool>().prop_map(Operand::Boolean),
        "[a-z0-9 .]{0,4}".prop_map(|s| Operand::Text(s.as_str().into())),
        (finite(), finite(), finite()).prop_map(|(x, y, z)| Operand::Point(Point3::new(x, y, z))),
        (finite(), finite(), finite()).prop_map(|(x, y, z)| Operand::Vector(Vector3::new(x, y, z))),
    ]
}

/// Values the operator nodes and formulas treat alike (text is read as a number by the nodes
/// but stays text in formulas, so it is left out).
fn arithmetic_value() -> impl Strategy<Value = Value> {
    prop_oneof![
        number().prop_map(Value::Number),
        (-1000_i64..1000).prop_map(Value::Integer),
        any::<bool>().prop_map(Value::Boolean),
        (finite(), finite(), finite()).prop_map(|(x, y, z)| Value::Point(Point3::new(x, y, z))),
        (finite(), finite(), finite()).prop_map(|(x, y, z)| Value::Vector(Vector3::new(x, y, z))),
    ]
}

fn evaluate_everything(source: &str, values: &[Operand]) {
    if let Ok(program) = Program::compile(source, &["x", "y", "z"]) {
        let r = program.evaluate(|i| Ok(values[i].clone()));
        if let Ok(evaluation) = r {
            // Invalid numbers never leave as infinity.
            if let Operand::Number(x) = evaluation.value {
                assert!(!x.is_infinite());
            }
        }
    }
}

/// Equality that treats NaN as equal to NaN and ignores the sign of zero.
fn same_number(a: f64, b: f64) -> bool {
    (a.is_nan() && b.is_nan()) || a == b
}

fn same(a: &Option<Value>, b: &Option<Value>) -> bool {
    match (a, b) {
        (Some(Value::Number(x)), Some(Value::Number(y))) => same_number(*x, *y),
        (Some(Value::Point(p)), Some(Value::Point(q))) => {
            same_number(p.x, q.x) && same_number(p.y, q.y) && same_number(p.z, q.z)
        }
        (Some(Value::Vector(p)), Some(Value::Vector(q))) => {
            same_number(p.x, q.x) && same_number(p.y, q.y) && same_number(p.z, q.z)
        }
        _ => a == b,
    }
}

fn count(messages: &[locus_runtime::Message], level: Level) -> usize {
    messages.iter().filter(|m| m.level == level).count()
}

fn assert_node_matches_formula(node: &NodeType, formula: &str, a: &Value, b: &Value) {
    let by_node = NodeCall::new(node)
        .input(DataTree::from_value(a.clone()))
        .input(DataTree::from_value(b.clone()))
        .run();
    let by_formula = NodeCall::new(&script::expression())
        .setting("expression", Value::Text(formula.to_owned()))
        .input(DataTree::from_value(a.clone()))
        .input(DataTree::from_value(b.clone()))
        .run();
    let x: Vec<Option<Value>> = by_node.outputs[0].values().collect();
    let y: Vec<Option<Value>> = by_formula.outputs[0].values().collect();
    assert_eq!(x.len(), y.len());
    for (p, q) in x.iter().zip(&y) {
        assert!(
            same(p, q),
            "{} gave {p:?}, {formula} gave {q:?} for {a:?}, {b:?}",
            node.name
        );
    }
    for level in [Level::Warning, Level::Error] {
        assert_eq!(
            count(&by_node.messages, level),
            count(&by_formula.messages, level),
            "{level} messages differ for {a:?}, {b:?}: {:?} vs {:?}",
            by_node.messages,
            by_formula.messages
        );
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(512))]

    #[test]
    fn random_token_streams_never_panic(
        tokens in prop::collection::vec(prop::sample::select(TOKENS), 0..40),
        spaced in any::<bool>(),
        values in prop::collection::vec(operand(), 3),
    ) {
        let source = tokens.join(if spaced { " " } else { "" });
        evaluate_everything(&source, &values);
    }

    #[test]
    fn random_text_never_panics(
        source in "\\PC{0,60}",
        values in prop::collection::vec(operand(), 3),
    ) {
        evaluate_everything(&source, &values);
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(128))]

    #[test]
    fn x_plus_y_equals_addition(a in arithmetic_value(), b in arithmetic_value()) {
        assert_node_matches_formula(&operators::addition(), "x + y", &a, &b);
    }

    #[test]
    fn x_minus_y_equals_subtraction(a in arithmetic_value(), b in arithmetic_value()) {
        assert_node_matches_formula(&operators::subtraction(), "x - y", &a, &b);
    }

    #[test]
    fn x_times_y_equals_multiplication(a in arithmetic_value(), b in arithmetic_value()) {
        assert_node_matches_formula(&operators::multiplication(), "x * y", &a, &b);
    }

    #[test]
    fn x_over_y_equals_division(a in arithmetic_value(), b in arithmetic_value()) {
        assert_node_matches_formula(&operators::division(), "x / y", &a, &b);
    }
}

#[test]
fn the_comparison_catches_a_difference() {
    // Guard against a vacuous property: a formula that is not the node's operation differs.
    let result = std::panic::catch_unwind(|| {
        assert_node_matches_formula(
            &operators::addition(),
            "x - y",
            &Value::Number(1.0),
            &Value::Number(2.0),
        );
    });
    assert!(result.is_err());
}

#[test]
fn the_language_doc_lists_every_function() {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../docs/expression.md");
    let doc = std::fs::read_to_string(&path).expect("docs/expression.md is readable");
    for (name, _) in locus_nodes::expression::FUNCTIONS {
        assert!(
            doc.contains(&format!("`{name}(")),
            "docs/expression.md does not describe {name}"
        );
    }
    assert!(doc.contains("`if(c, a, b)`"));
    assert!(doc.contains(&format!(
        "at most {} levels",
        locus_nodes::expression::MAX_NESTING
    )));
}

//! Maths › Operators: arithmetic on numbers, vectors and points.
//!
//! Addition, Subtraction, Multiplication, Division and Negative take generic data, like
//! Grasshopper's: numbers, integers, booleans (as 0 and 1), text that reads as a number,
//! points and vectors, combined by the rules of [`crate::expression::Operand`] (so an Addition
//! node and the formula `A + B` always agree). Absolute, Power and Modulus take numbers.

use locus_kernel::{Point3, Vector3};
use locus_runtime::{DataType, NodeError, NodeRegistry, NodeType, Port, Solve};

use super::{set_number, set_operand};
use crate::expression::{BinaryOp, Operand, UnaryOp, binary_warning};

/// Id of [`addition`].
pub const ADDITION: &str = "maths.addition";
/// Id of [`subtraction`].
pub const SUBTRACTION: &str = "maths.subtraction";
/// Id of [`multiplication`].
pub const MULTIPLICATION: &str = "maths.multiplication";
/// Id of [`division`].
pub const DIVISION: &str = "maths.division";
/// Id of [`negative`].
pub const NEGATIVE: &str = "maths.negative";
/// Id of [`absolute`].
pub const ABSOLUTE: &str = "maths.absolute";
/// Id of [`power`].
pub const POWER: &str = "maths.power";
/// Id of [`modulus`].
pub const MODULUS: &str = "maths.modulus";

/// Registers the operator nodes.
pub fn register(registry: &mut NodeRegistry) {
    for t in [
        addition(),
        subtraction(),
        multiplication(),
        division(),
        negative(),
        absolute(),
        power(),
        modulus(),
    ] {
        registry.register(t);
    }
}

const OPERAND_TYPES: &str = "a number, vector or point (integers, booleans as 0/1 and text \
    that reads as a number are accepted)";

fn operator(id: &str, name: &str, nickname: &str) -> NodeType {
    NodeType::new(id, name, nickname, "Maths").subcategory("Operators")
}

/// Addition \[A+B\]: `A + B (+ C …)`.
pub fn addition() -> NodeType {
    operator(ADDITION, "Addition", "A+B")
        .gh_guid("a0d62394-a118-422d-abb3-6af115c75b25")
        .description(
            "Adds items: numbers, vectors, and points. A point plus a vector is the moved \
             point; a point plus a point adds the coordinates. Further inputs (C, D, …) may be \
             added and are summed in order.",
        )
        .variable_inputs(
            Port::new("Item", "A", DataType::Generic)
                .doc(&format!("An item to add: {OPERAND_TYPES}.")),
            &["A", "B"],
        )
        .output(
            Port::new("Result", "R", DataType::Generic)
                .doc("The sum; NaN with a warning when it is not a finite number."),
        )
        .solve(|s| fold(s, BinaryOp::Add))
        .fast_path2(|a: &f64, b: &f64| finite(*a + *b))
}

/// Subtraction \[A-B\]: `A − B`.
pub fn subtraction() -> NodeType {
    operator(SUBTRACTION, "Subtraction", "A-B")
        .gh_guid("2c56ab33-c7cc-4129-886c-d5856b714010")
        .gh_guid("9c007a04-d0d9-48e4-9da3-9ba142bc4d46")
        .description(
            "Subtracts B from A. A point minus a point is the vector from B to A; a point \
             minus a vector is the moved point.",
        )
        .input(Port::new("A", "A", DataType::Generic).doc(&format!(
            "The item to subtract from (minuend): {OPERAND_TYPES}."
        )))
        .input(Port::new("B", "B", DataType::Generic).doc(&format!(
            "The item to subtract (subtrahend): {OPERAND_TYPES}."
        )))
        .output(
            Port::new("Result", "R", DataType::Generic)
                .doc("A − B; NaN with a warning when it is not a finite number."),
        )
        .solve(|s| fold(s, BinaryOp::Subtract))
        .fast_path2(|a: &f64, b: &f64| finite(*a - *b))
}

/// Multiplication \[A×B\]: `A × B (× C …)`.
pub fn multiplication() -> NodeType {
    operator(MULTIPLICATION, "Multiplication", "A×B")
        .gh_guid("b8963bb1-aa57-476e-a20e-ed6cf635a49c")
        .gh_guid("ce46b74e-00c9-43c4-805a-193b69ea4a11")
        .description(
            "Multiplies items. A vector (or point) times a number scales it; a vector times a \
             vector is their dot product (a number). Further inputs (C, D, …) may be added and \
             are multiplied in order.",
        )
        .variable_inputs(
            Port::new("Item", "A", DataType::Generic)
                .doc(&format!("An item to multiply: {OPERAND_TYPES}.")),
            &["A", "B"],
        )
        .output(
            Port::new("Result", "R", DataType::Generic)
                .doc("The product; NaN with a warning when it is not a finite number."),
        )
        .solve(|s| fold(s, BinaryOp::Multiply))
        .fast_path2(|a: &f64, b: &f64| finite(*a * *b))
}

/// Division \[A/B\]: `A ÷ B`.
pub fn division() -> NodeType {
    operator(DIVISION, "Division", "A/B")
        .gh_guid("9c85271f-89fa-4e9f-9f4a-d75802120ccc")
        .description(
            "Divides A by B. A vector or point divided by a number is scaled by its inverse. \
             Division by zero gives NaN with a warning (the item is kept, so lists stay \
             aligned).",
        )
        .input(
            Port::new("A", "A", DataType::Generic)
                .doc(&format!("The item to divide (dividend): {OPERAND_TYPES}.")),
        )
        .input(Port::new("B", "B", DataType::Generic).doc("The number to divide by (divisor)."))
        .output(
            Port::new("Result", "R", DataType::Generic)
                .doc("A ÷ B; NaN with a warning when B is zero or the result is not finite."),
        )
        .solve(|s| fold(s, BinaryOp::Divide))
        .fast_path2(|a: &f64, b: &f64| finite_result(*a, *b, *a / *b))
}

/// Negative \[Neg\]: `−x`.
pub fn negative() -> NodeType {
    operator(NEGATIVE, "Negative", "Neg")
        .gh_guid("a3371040-e552-4bc8-b0ff-10a840258e88")
        .description("Negates a number, or every coordinate of a vector or point.")
        .input(
            Port::new("Value", "x", DataType::Generic)
                .doc(&format!("The item to negate: {OPERAND_TYPES}.")),
        )
        .output(Port::new("Result", "y", DataType::Generic).doc("−x."))
        .solve(|s| {
            let x = operand(s, 0)?;
            let r = UnaryOp::Negate.apply(&x)?;
            let why = (!x.is_finite()).then(|| format!("input x is {x}"));
            set_operand(s, 0, r, why);
            Ok(())
        })
}

/// Absolute \[Abs\]: `|x|`.
pub fn absolute() -> NodeType {
    operator(ABSOLUTE, "Absolute", "Abs")
        .gh_guid("28124995-cf99-4298-b6f4-c75a8e379f18")
        .description("Computes the absolute value of a number.")
        .input(Port::new("Value", "x", DataType::Number).doc("The number."))
        .output(Port::new("Result", "y", DataType::Number).doc("|x|, never negative."))
        .solve(|s| {
            let x = *s.item::<f64>(0)?;
            set_number(s, 0, x.abs(), || format!("input x is {x}"));
            Ok(())
        })
}

/// Power \[Pow\]: `A ^ B`.
pub fn power() -> NodeType {
    operator(POWER, "Power", "Pow")
        .gh_guid("78fed580-851b-46fe-af2f-6519a9d378e0")
        .description(
            "Raises A to the power B. A negative A with a fractional B has no real result and \
             gives NaN with a warning.",
        )
        .input(Port::new("A", "A", DataType::Number).doc("The number to raise (the base)."))
        .input(Port::new("B", "B", DataType::Number).doc("The exponent."))
        .output(Port::new("Result", "R", DataType::Number).doc("A raised to the power B."))
        .solve(|s| numbers(s, BinaryOp::Power))
}

/// Modulus \[Mod\]: the remainder of `A ÷ B`.
pub fn modulus() -> NodeType {
    operator(MODULUS, "Modulus", "Mod")
        .gh_guid("431bc610-8ae1-4090-b217-1a9d9c519fe2")
        .description(
            "Divides A by B and returns the remainder of the truncated division: it has the \
             sign of A (−7 mod 3 is −1), as in .NET, which Grasshopper is built on. B = 0 \
             gives NaN with a warning.",
        )
        .input(Port::new("A", "A", DataType::Number).doc("The number to divide (dividend)."))
        .input(Port::new("B", "B", DataType::Number).doc("The number to divide by (divisor)."))
        .output(Port::new("Result", "R", DataType::Number).doc("The remainder of A ÷ B."))
        .solve(|s| numbers(s, BinaryOp::Modulus))
}

/// Input `i` as an operand, text read as a number.
fn operand(s: &Solve<'_>, i: usize) -> Result<Operand, NodeError> {
    // Typed columns first: reading them copies no `Value`.
    if let Some(x) = s.item_opt::<f64>(i) {
        return Ok(Operand::Number(*x));
    }
    if let Some(p) = s.item_opt::<Point3>(i) {
        return Ok(Operand::Point(*p));
    }
    if let Some(v) = s.item_opt::<Vector3>(i) {
        return Ok(Operand::Vector(*v));
    }
    // Required inputs with a null item are skipped by the runtime, so a value is present.
    let name = s.input_port(i).map_or("?", |p| p.nickname.as_str());
    let value = s
        .value(i)
        .ok_or_else(|| NodeError(format!("input {name} has no item")))?;
    Ok(Operand::from_value_numeric(&value)?)
}

/// Combines every input with `op`, left to right, and writes the result to output 0.
/// The fast path of an operator on two numbers: its result when both numbers and the result
/// are finite; otherwise `None`, and the node runs [`fold`], which warns.
fn finite_result(a: f64, b: f64, r: f64) -> Option<f64> {
    (a.is_finite() && b.is_finite() && r.is_finite()).then_some(r)
}

/// [`finite_result`] of a sum, difference or product `r`, which is finite only when both
/// operands are (an infinite or NaN operand gives an infinite or NaN result: ∞ ± x, ∞ − ∞,
/// ∞ × 0, NaN anything), so one check does for three: the fast loop stays one compare per item.
#[inline(always)]
fn finite(r: f64) -> Option<f64> {
    Some(r).filter(|r| r.is_finite())
}

fn fold(s: &mut Solve<'_>, op: BinaryOp) -> Result<(), NodeError> {
    let mut acc = operand(s, 0)?;
    let mut why = (!acc.is_finite()).then(|| input_warning(s, 0, &acc));
    for i in 1..s.input_count() {
        let x = operand(s, i)?;
        if why.is_none() && !x.is_finite() {
            why = Some(input_warning(s, i, &x));
        }
        let r = op.apply(&acc, &x)?;
        if why.is_none() && !r.is_finite() {
            why = Some(binary_warning(op, &acc, &x));
        }
        acc = r;
    }
    set_operand(s, 0, acc, why);
    Ok(())
}

fn input_warning(s: &Solve<'_>, i: usize, x: &Operand) -> String {
    let name = s.input_port(i).map_or("?", |p| p.nickname.as_str());
    format!("input {name} is {x}")
}

/// Applies a numeric operator to the number inputs A and B.
fn numbers(s: &mut Solve<'_>, op: BinaryOp) -> Result<(), NodeError> {
    let a = *s.item::<f64>(0)?;
    let b = *s.item::<f64>(1)?;
    let (x, y) = (Operand::Number(a), Operand::Number(b));
    let r = op.apply(&x, &y)?;
    let why = if a.is_finite() && b.is_finite() {
        (!r.is_finite()).then(|| binary_warning(op, &x, &y))
    } else {
        Some(format!("the inputs are {a} and {b}"))
    };
    set_operand(s, 0, r, why);
    Ok(())
}

#[cfg(test)]
mod tests {
    use locus_runtime::{DataTree, Level, NodeCall, Value};

    use super::*;
    use crate::maths::test_support::{messages, numbers, values};

    /// The same numbers as a generic column, which the fast path does not take.
    fn generic(items: &[Option<f64>]) -> DataTree {
        let mut b = locus_runtime::Branch::new(locus_runtime::DataType::Generic);
        for x in items {
            b.push_option(x.map(Value::Number));
        }
        DataTree::from_branches([(locus_runtime::TreePath::new(vec![0]), b)])
    }

    /// The same numbers as a typed number column, which the fast path takes.
    fn typed(items: &[Option<f64>]) -> DataTree {
        let mut b = locus_runtime::Branch::new(locus_runtime::DataType::Number);
        for x in items {
            match x {
                Some(x) => b.push(*x),
                None => b.push_null(),
            }
        }
        DataTree::from_branches([(locus_runtime::TreePath::new(vec![0]), b)])
    }

    #[test]
    fn the_number_fast_path_gives_what_the_general_path_gives() {
        let a = [
            Some(1.5),
            Some(-2.0),
            None,
            Some(0.0),
            Some(1e300),
            Some(7.0),
        ];
        let cases: [&[Option<f64>]; 4] = [
            &[Some(2.0), Some(0.5), Some(3.0)],
            &[Some(4.0)],
            &[Some(0.0), Some(1e300), None, Some(-3.0)],
            &[Some(f64::NAN), Some(1.0)],
        ];
        for node in [addition(), subtraction(), multiplication(), division()] {
            for b in cases {
                let fast = run2(&node, typed(&a), typed(b));
                let general = run2(&node, generic(&a), generic(b));
                // As text, so that NaN items compare equal.
                assert_eq!(
                    format!("{fast:?}"),
                    format!("{general:?}"),
                    "{} with {b:?}",
                    node.id
                );
            }
        }
        // Large lists take the loop (and the general path where an item warns).
        let many: Vec<Option<f64>> = (0..50_000).map(|k| Some(f64::from(k) - 100.0)).collect();
        let fast = run2(&division(), typed(&many), typed(&[Some(0.0), Some(2.0)]));
        let general = run2(
            &division(),
            generic(&many),
            generic(&[Some(0.0), Some(2.0)]),
        );
        assert_eq!(format!("{fast:?}"), format!("{general:?}"));
        let fast = run2(&addition(), typed(&many), typed(&[Some(0.25)]));
        let general = run2(&addition(), generic(&many), generic(&[Some(0.25)]));
        assert_eq!(fast, general);
        assert!(fast.messages.is_empty());
    }

    fn run2(node: &NodeType, a: DataTree, b: DataTree) -> locus_runtime::NodeCallResult {
        NodeCall::new(node).input(a).input(b).run()
    }

    #[test]
    fn addition_of_numbers_follows_longest_list() {
        let r = run2(
            &addition(),
            DataTree::from_list(vec![1.0, 2.0, 3.0]),
            DataTree::from_list(vec![10.0, 20.0]),
        );
        assert_eq!(numbers(&r.outputs[0]), [11.0, 22.0, 23.0]);
        assert!(r.messages.is_empty());
    }

    #[test]
    fn addition_with_more_inputs() {
        let r = NodeCall::new(&addition())
            .input_names(&["A", "B", "C"])
            .input(DataTree::from_item(1.0))
            .input(DataTree::from_item(2.0))
            .input(DataTree::from_item(4.0))
            .run();
        assert_eq!(numbers(&r.outputs[0]), [7.0]);
    }

    #[test]
    fn addition_of_points_and_vectors() {
        let r = run2(
            &addition(),
            DataTree::from_item(Point3::new(1.0, 2.0, 3.0)),
            DataTree::from_item(Vector3::new(0.0, 0.0, 10.0)),
        );
        assert_eq!(
            values(&r.outputs[0]),
            [Some(Value::Point(Point3::new(1.0, 2.0, 13.0)))]
        );
        let r = run2(
            &addition(),
            DataTree::from_item(Vector3::new(1.0, 0.0, 0.0)),
            DataTree::from_item(Vector3::new(0.0, 1.0, 0.0)),
        );
        assert_eq!(
            values(&r.outputs[0]),
            [Some(Value::Vector(Vector3::new(1.0, 1.0, 0.0)))]
        );
    }

    #[test]
    fn addition_reads_text_and_integers_as_numbers() {
        let r = run2(
            &addition(),
            DataTree::from_item("2.5".to_owned()),
            DataTree::from_item(2_i64),
        );
        assert_eq!(numbers(&r.outputs[0]), [4.5]);
    }

    #[test]
    fn bad_operands_are_errors_on_the_item() {
        let r = run2(
            &addition(),
            DataTree::from_list(vec!["abc".to_owned(), "1".to_owned()]),
            DataTree::from_item(1.0),
        );
        assert_eq!(values(&r.outputs[0]), [None, Some(Value::Number(2.0))]);
        assert_eq!(
            messages(&r, Level::Error),
            ["cannot read \"abc\" as a number"]
        );
        let r = run2(
            &addition(),
            DataTree::from_item(Point3::ORIGIN),
            DataTree::from_item(true),
        );
        assert_eq!(
            messages(&r, Level::Error),
            ["cannot compute Point + Boolean"]
        );
        let r = run2(
            &addition(),
            DataTree::from_item(locus_kernel::Interval::UNIT),
            DataTree::from_item(1.0),
        );
        assert_eq!(messages(&r, Level::Error), ["a Domain cannot be used here"]);
    }

    #[test]
    fn subtraction_of_points_is_a_vector() {
        let r = run2(
            &subtraction(),
            DataTree::from_item(Point3::new(4.0, 6.0, 0.0)),
            DataTree::from_item(Point3::new(1.0, 2.0, 0.0)),
        );
        assert_eq!(
            values(&r.outputs[0]),
            [Some(Value::Vector(Vector3::new(3.0, 4.0, 0.0)))]
        );
        let r = run2(
            &subtraction(),
            DataTree::from_item(10.0),
            DataTree::from_list(vec![1.0, 2.0]),
        );
        assert_eq!(numbers(&r.outputs[0]), [9.0, 8.0]);
    }

    #[test]
    fn multiplication_scales_vectors_and_dots_them() {
        let r = run2(
            &multiplication(),
            DataTree::from_item(Vector3::new(1.0, 2.0, 3.0)),
            DataTree::from_item(2.0),
        );
        assert_eq!(
            values(&r.outputs[0]),
            [Some(Value::Vector(Vector3::new(2.0, 4.0, 6.0)))]
        );
        let r = run2(
            &multiplication(),
            DataTree::from_item(Vector3::new(1.0, 2.0, 3.0)),
            DataTree::from_item(Vector3::new(4.0, 5.0, 6.0)),
        );
        assert_eq!(numbers(&r.outputs[0]), [32.0]);
    }

    #[test]
    fn division_by_zero_is_nan_with_a_warning_and_keeps_the_item() {
        let r = run2(
            &division(),
            DataTree::from_list(vec![1.0, 6.0]),
            DataTree::from_list(vec![0.0, 3.0]),
        );
        let out = numbers(&r.outputs[0]);
        assert!(out[0].is_nan());
        assert_eq!(out[1], 2.0);
        assert_eq!(
            messages(&r, Level::Warning),
            ["invalid numeric result, kept as NaN: division by zero"]
        );
        let r = run2(
            &division(),
            DataTree::from_item(Vector3::new(2.0, 4.0, 0.0)),
            DataTree::from_item(2.0),
        );
        assert_eq!(
            values(&r.outputs[0]),
            [Some(Value::Vector(Vector3::new(1.0, 2.0, 0.0)))]
        );
        let r = run2(
            &division(),
            DataTree::from_item(2.0),
            DataTree::from_item(Vector3::X),
        );
        assert_eq!(
            messages(&r, Level::Error),
            ["cannot compute Number / Vector"]
        );
    }

    #[test]
    fn negative_of_numbers_and_vectors() {
        let r = NodeCall::new(&negative())
            .input(DataTree::from_list(vec![
                Value::Number(2.0),
                Value::Vector(Vector3::X),
            ]))
            .run();
        assert_eq!(
            values(&r.outputs[0]),
            [
                Some(Value::Number(-2.0)),
                Some(Value::Vector(Vector3::new(-1.0, -0.0, -0.0)))
            ]
        );
        let r = NodeCall::new(&negative())
            .input(DataTree::from_item("x".to_owned()))
            .run();
        assert_eq!(values(&r.outputs[0]), [None]);
        assert_eq!(messages(&r, Level::Error).len(), 1);
    }

    #[test]
    fn absolute_and_nan_input() {
        let r = NodeCall::new(&absolute())
            .input(DataTree::from_list(vec![-3.0, 2.0, f64::NAN]))
            .run();
        let out = numbers(&r.outputs[0]);
        assert_eq!(out[..2], [3.0, 2.0]);
        assert!(out[2].is_nan());
        assert_eq!(
            messages(&r, Level::Warning),
            ["invalid numeric result, kept as NaN: input x is NaN"]
        );
    }

    #[test]
    fn power_and_its_invalid_results() {
        let r = run2(
            &power(),
            DataTree::from_list(vec![2.0, -8.0, 10.0]),
            DataTree::from_list(vec![10.0, 0.5, 400.0]),
        );
        let out = numbers(&r.outputs[0]);
        assert_eq!(out[0], 1024.0);
        assert!(out[1].is_nan() && out[2].is_nan());
        assert_eq!(
            messages(&r, Level::Warning),
            [
                "invalid numeric result, kept as NaN: -8 ^ 0.5 is NaN",
                "invalid numeric result, kept as NaN: 10 ^ 400 is Infinity"
            ]
        );
    }

    #[test]
    fn modulus_keeps_the_sign_of_a() {
        let r = run2(
            &modulus(),
            DataTree::from_list(vec![7.0, -7.0, 5.5, 1.0]),
            DataTree::from_list(vec![3.0, 3.0, 2.0, 0.0]),
        );
        let out = numbers(&r.outputs[0]);
        assert_eq!(out[..3], [1.0, -1.0, 1.5]);
        assert!(out[3].is_nan());
        assert_eq!(
            messages(&r, Level::Warning),
            ["invalid numeric result, kept as NaN: modulus by zero"]
        );
    }

    #[test]
    fn missing_input_runs_nothing() {
        let r = NodeCall::new(&subtraction())
            .input(DataTree::from_item(1.0))
            .run();
        assert!(r.outputs[0].is_empty());
        assert_eq!(
            messages(&r, Level::Warning),
            ["input parameter B failed to collect data"]
        );
    }
}

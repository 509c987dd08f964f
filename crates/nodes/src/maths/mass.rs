//! Maths › Operators on whole lists and on integers: Mass Addition, Mass Multiplication and
//! Integer Division.
//!
//! Mass Addition and Mass Multiplication fold a list with the operators of
//! [`crate::expression::Operand`], so `Mass Addition` of a list and a chain of Addition nodes
//! always agree: numbers, integers, booleans (as 0 and 1), text that reads as a number, points
//! and vectors. A list of plain numbers (a typed number column without nulls) is folded in one
//! loop without converting any item.

use locus_runtime::{Branch, DataType, NodeError, NodeRegistry, NodeType, Port, Solve};

use super::invalid_number_warning;
use crate::expression::{BinaryOp, Operand};

/// Id of [`mass_addition`].
pub const MASS_ADDITION: &str = "maths.mass_addition";
/// Id of [`mass_multiplication`].
pub const MASS_MULTIPLICATION: &str = "maths.mass_multiplication";
/// Id of [`integer_division`].
pub const INTEGER_DIVISION: &str = "maths.integer_division";

/// Registers the list operators and Integer Division.
pub fn register(registry: &mut NodeRegistry) {
    for t in [mass_addition(), mass_multiplication(), integer_division()] {
        registry.register(t);
    }
}

fn operator(id: &str, name: &str, nickname: &str) -> NodeType {
    NodeType::new(id, name, nickname, "Maths").subcategory("Operators")
}

/// Mass Addition \[MA\]: the sum of all items of a list, and the running sums.
pub fn mass_addition() -> NodeType {
    mass(
        operator(MASS_ADDITION, "Mass Addition", "MA")
            .gh_guid("5b850221-b527-4bd6-8c62-e94168cd6efa"),
        BinaryOp::Add,
        "Adds all items of a list: numbers, vectors or points, by the rules of the Addition \
         node (a point plus a vector is the moved point). Null items are skipped. Partial \
         Results lists the running sums, one per item that was added. An empty list (or one \
         of nulls only) gives a null result, an empty Partial Results list and a warning.",
        "The sum of all items of I; NaN with a warning when it is not finite.",
        "The running sums: item k is the sum of the first k + 1 items added.",
    )
}

/// Mass Multiplication \[MM\]: the product of all items of a list, and the running products.
pub fn mass_multiplication() -> NodeType {
    mass(
        operator(MASS_MULTIPLICATION, "Mass Multiplication", "MM")
            .gh_guid("e44c1bd7-72cc-4697-80c9-02787baf7bb4"),
        BinaryOp::Multiply,
        "Multiplies all items of a list, by the rules of the Multiplication node (a vector \
         times a number scales it; two vectors give their dot product). Null items are \
         skipped. Partial Results lists the running products, one per item that was \
         multiplied. An empty list (or one of nulls only) gives a null result, an empty \
         Partial Results list and a warning.",
        "The product of all items of I; NaN with a warning when it is not finite.",
        "The running products: item k is the product of the first k + 1 items multiplied.",
    )
}

fn mass(t: NodeType, op: BinaryOp, description: &str, result: &str, partial: &str) -> NodeType {
    t.description(description)
        .input(
            Port::new("Input", "I", DataType::Generic)
                .list()
                .doc("The items to combine: numbers, vectors or points (integers, booleans as 0/1 and text that reads as a number are accepted)."),
        )
        .output(Port::new("Result", "R", DataType::Generic).doc(result))
        .output(
            Port::new("Partial Results", "Pr", DataType::Generic)
                .list()
                .doc(partial),
        )
        .solve(move |s| fold_list(s, op))
}

/// Folds the list of input 0 with `op` into output 0 (the result) and 1 (the partial results).
fn fold_list(s: &mut Solve<'_>, op: BinaryOp) -> Result<(), NodeError> {
    let Some(branch) = s.branch(0) else {
        s.warning("input I failed to collect data");
        return Ok(());
    };
    if let Some(numbers) = branch.slice::<f64>().filter(|_| !branch.has_nulls()) {
        return fold_numbers(s, numbers, op);
    }
    let mut acc: Option<Operand> = None;
    let mut partial = Vec::with_capacity(branch.len());
    let mut invalid: Option<String> = None;
    for (k, value) in branch.values().enumerate() {
        let Some(value) = value else { continue };
        let x = Operand::from_value_numeric(&value)
            .map_err(|e| NodeError(format!("item {k} of input I: {e}")))?;
        let next = match acc {
            None => x,
            Some(a) => op
                .apply(&a, &x)
                .map_err(|e| NodeError(format!("item {k} of input I: {e}")))?,
        };
        if invalid.is_none() && !next.is_finite() {
            invalid = Some(format!("the {} up to item {k} is {next}", op_noun(op)));
        }
        partial.push(Some(next.clone().with_invalid_as_nan().into_value()));
        acc = Some(next);
    }
    let Some(acc) = acc else {
        s.warning("the list has no items to combine");
        s.set_value(0, None);
        s.set_list_values(1, Vec::new());
        return Ok(());
    };
    if let Some(why) = invalid {
        s.warning(invalid_number_warning(&why));
    }
    s.set_value(0, Some(acc.with_invalid_as_nan().into_value()));
    s.set_list_values(1, partial);
    Ok(())
}

/// The loop for a list of numbers without nulls.
fn fold_numbers(s: &mut Solve<'_>, numbers: &[f64], op: BinaryOp) -> Result<(), NodeError> {
    if numbers.is_empty() {
        s.warning("the list has no items to combine");
        s.set_value(0, None);
        s.set_list_values(1, Vec::new());
        return Ok(());
    }
    let mut partial = Vec::with_capacity(numbers.len());
    let mut acc = numbers[0];
    partial.push(acc);
    for &x in &numbers[1..] {
        acc = match op {
            BinaryOp::Multiply => acc * x,
            _ => acc + x,
        };
        partial.push(acc);
    }
    if let Some(k) = partial.iter().position(|x| !x.is_finite()) {
        s.warning(invalid_number_warning(&format!(
            "the {} up to item {k} is {}",
            op_noun(op),
            partial[k]
        )));
        for x in &mut partial {
            if !x.is_finite() {
                *x = f64::NAN;
            }
        }
    }
    s.set(0, *partial.last().unwrap_or(&f64::NAN));
    s.set_branch(1, Branch::from_items(partial));
    Ok(())
}

fn op_noun(op: BinaryOp) -> &'static str {
    match op {
        BinaryOp::Multiply => "product",
        _ => "sum",
    }
}

/// Integer Division \[A\\B\]: the whole part of `A ÷ B`.
pub fn integer_division() -> NodeType {
    operator(INTEGER_DIVISION, "Integer Division", "A\\B")
        .gh_guid("54db2568-3441-4ae2-bcef-92c4cc608e11")
        .description(
            "Divides the integer A by the integer B and drops the remainder, rounding towards \
             zero (7 \\ 2 is 3, −7 \\ 2 is −3), as C# integer division does. Division by zero, \
             and the one quotient that does not fit (the smallest integer divided by −1), are \
             errors.",
        )
        .input(Port::new("A", "A", DataType::Integer).doc("The integer to divide (dividend)."))
        .input(Port::new("B", "B", DataType::Integer).doc("The integer to divide by (divisor)."))
        .output(Port::new("Result", "R", DataType::Integer).doc("A \\ B, rounded towards zero."))
        .lift2(|a: &i64, b: &i64| {
            if *b == 0 {
                return Err(NodeError(format!("{a} \\ 0: division by zero")));
            }
            a.checked_div(*b)
                .ok_or_else(|| NodeError(format!("{a} \\ {b} does not fit in an integer")))
        })
}

#[cfg(test)]
mod tests {
    use locus_kernel::{Point3, Vector3};
    use locus_runtime::{DataTree, Level, NodeCall, TreePath, Value};

    use super::*;
    use crate::maths::test_support::{assert_clean, is_null, messages, numbers, only, values};

    fn generic(items: Vec<Option<Value>>) -> DataTree {
        let mut b = Branch::new(DataType::Generic);
        for v in items {
            b.push_option(v);
        }
        DataTree::from_branches([(TreePath::new(vec![0]), b)])
    }

    #[test]
    fn mass_addition_sums_numbers_with_running_sums() {
        let r = NodeCall::new(&mass_addition())
            .input(DataTree::from_list(vec![1.0, 2.0, 3.5]))
            .run();
        assert_clean(&r);
        assert_eq!(only::<f64>(&r, 0), 6.5);
        assert_eq!(numbers(&r.outputs[1]), [1.0, 3.0, 6.5]);
    }

    #[test]
    fn mass_addition_of_mixed_items_skips_nulls_and_moves_points() {
        let r = NodeCall::new(&mass_addition())
            .input(generic(vec![
                Some(Value::Point(Point3::new(1.0, 0.0, 0.0))),
                None,
                Some(Value::Vector(Vector3::new(0.0, 2.0, 0.0))),
                Some(Value::Vector(Vector3::new(0.0, 0.0, 3.0))),
            ]))
            .run();
        assert_clean(&r);
        assert_eq!(only::<Point3>(&r, 0), Point3::new(1.0, 2.0, 3.0));
        assert_eq!(values(&r.outputs[1]).len(), 3);
        // Text that reads as a number and integers count.
        let r = NodeCall::new(&mass_addition())
            .input(generic(vec![
                Some(Value::Text("2.5".into())),
                Some(Value::Integer(3)),
                Some(Value::Boolean(true)),
            ]))
            .run();
        assert_eq!(only::<f64>(&r, 0), 6.5);
    }

    #[test]
    fn mass_multiplication_multiplies() {
        let r = NodeCall::new(&mass_multiplication())
            .input(DataTree::from_list(vec![2.0, -3.0, 0.5]))
            .run();
        assert_eq!(only::<f64>(&r, 0), -3.0);
        assert_eq!(numbers(&r.outputs[1]), [2.0, -6.0, -3.0]);
        let r = NodeCall::new(&mass_multiplication())
            .input(generic(vec![
                Some(Value::Vector(Vector3::new(1.0, 2.0, 3.0))),
                Some(Value::Number(2.0)),
            ]))
            .run();
        assert_eq!(only::<Vector3>(&r, 0), Vector3::new(2.0, 4.0, 6.0));
    }

    #[test]
    fn bad_lists_give_messages_not_panics() {
        // An empty list is a gap: the runtime does not call the node, and there is no result.
        let r = NodeCall::new(&mass_addition())
            .input(DataTree::from_branches([(
                TreePath::new(vec![0]),
                Branch::new(DataType::Number),
            )]))
            .run();
        assert!(r.messages.is_empty());
        assert!(values(&r.outputs[0]).iter().all(Option::is_none));
        // A list of nulls only: a null and a warning.
        let r = NodeCall::new(&mass_addition())
            .input(generic(vec![None, None]))
            .run();
        assert!(is_null(&r, 0));
        assert_eq!(
            messages(&r, Level::Warning),
            ["the list has no items to combine"]
        );
        // Overflow: NaN and one warning.
        let r = NodeCall::new(&mass_addition())
            .input(DataTree::from_list(vec![f64::MAX, f64::MAX, 1.0]))
            .run();
        assert!(only::<f64>(&r, 0).is_nan());
        assert_eq!(
            messages(&r, Level::Warning),
            ["invalid numeric result, kept as NaN: the sum up to item 1 is inf"]
        );
        // A text that is not a number, a curve: errors naming the item.
        let r = NodeCall::new(&mass_addition())
            .input(generic(vec![
                Some(Value::Number(1.0)),
                Some(Value::Text("abc".into())),
            ]))
            .run();
        let errors = messages(&r, Level::Error);
        assert_eq!(errors.len(), 1);
        assert!(errors[0].contains("item 1 of input I"), "{errors:?}");
        // A domain is no operand.
        let r = NodeCall::new(&mass_multiplication())
            .input(generic(vec![
                Some(Value::Number(2.0)),
                Some(Value::Domain(locus_kernel::Interval::UNIT)),
            ]))
            .run();
        assert_eq!(messages(&r, Level::Error).len(), 1);
    }

    #[test]
    fn integer_division_truncates_towards_zero() {
        let r = NodeCall::new(&integer_division())
            .input(DataTree::from_list(vec![7_i64, -7, 6, 0]))
            .input(DataTree::from_item(2_i64))
            .run();
        assert_clean(&r);
        let out: Vec<i64> = crate::test_support::all(&r.outputs[0]);
        assert_eq!(out, [3, -3, 3, 0]);
    }

    #[test]
    fn integer_division_by_zero_and_overflow_are_errors() {
        let r = NodeCall::new(&integer_division())
            .input(DataTree::from_list(vec![1_i64, i64::MIN]))
            .input(DataTree::from_list(vec![0_i64, -1]))
            .run();
        let errors = messages(&r, Level::Error);
        assert_eq!(errors.len(), 2, "{errors:?}");
        assert!(errors[0].contains("division by zero"));
        assert!(errors[1].contains("does not fit"));
        assert!(values(&r.outputs[0]).iter().all(Option::is_none));
    }
}

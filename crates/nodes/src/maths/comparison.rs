//! Maths › Operators: comparing two numbers.
//!
//! Comparisons are exact (Grasshopper has a separate Similarity component for comparing with a
//! tolerance). A NaN input makes every comparison false (and Inequality true), with a warning.

use locus_runtime::{DataType, ItemReport, NodeRegistry, NodeType, Port};

/// Id of [`larger_than`].
pub const LARGER_THAN: &str = "maths.larger_than";
/// Id of [`smaller_than`].
pub const SMALLER_THAN: &str = "maths.smaller_than";
/// Id of [`equality`].
pub const EQUALITY: &str = "maths.equality";

/// Registers the comparison nodes.
pub fn register(registry: &mut NodeRegistry) {
    for t in [larger_than(), smaller_than(), equality()] {
        registry.register(t);
    }
}

fn comparison(id: &str, name: &str, nickname: &str, description: &str) -> NodeType {
    NodeType::new(id, name, nickname, "Maths")
        .subcategory("Operators")
        .description(description)
        .input(Port::new("First Number", "A", DataType::Number).doc("The number to test."))
        .input(Port::new("Second Number", "B", DataType::Number).doc("The number to test against."))
}

/// Larger Than \[Larger\]: `A > B` and `A >= B`.
pub fn larger_than() -> NodeType {
    comparison(
        LARGER_THAN,
        "Larger Than",
        "Larger",
        "Tests whether A is larger than B, and whether it is larger than or equal to B.",
    )
    .gh_guid("30d58600-1aab-42db-80a3-f1ea6c4269a0")
    .output(Port::new("Larger than", ">", DataType::Boolean).doc("True if A > B."))
    .output(Port::new("… or Equal to", ">=", DataType::Boolean).doc("True if A ≥ B."))
    .lift2_with_plain(
        neither_nan,
        |&a: &f64, &b: &f64| (a > b, a >= b),
        |a: &f64, b: &f64, report| Ok(compare(*a, *b, report, |a, b| (a > b, a >= b))),
    )
}

/// Smaller Than \[Smaller\]: `A < B` and `A <= B`.
pub fn smaller_than() -> NodeType {
    comparison(
        SMALLER_THAN,
        "Smaller Than",
        "Smaller",
        "Tests whether A is smaller than B, and whether it is smaller than or equal to B.",
    )
    .gh_guid("ae840986-cade-4e5a-96b0-570f007d4fc0")
    .output(Port::new("Smaller than", "<", DataType::Boolean).doc("True if A < B."))
    .output(Port::new("… or Equal to", "<=", DataType::Boolean).doc("True if A ≤ B."))
    .lift2_with_plain(
        neither_nan,
        |&a: &f64, &b: &f64| (a < b, a <= b),
        |a: &f64, b: &f64, report| Ok(compare(*a, *b, report, |a, b| (a < b, a <= b))),
    )
}

/// Equality \[Equals\]: `A = B` and `A ≠ B`.
pub fn equality() -> NodeType {
    comparison(
        EQUALITY,
        "Equality",
        "Equals",
        "Tests whether two numbers are exactly equal, and whether they differ.",
    )
    .gh_guid("5db0fb89-4f22-4f09-a777-fa5e55aed7ec")
    .output(Port::new("Equality", "=", DataType::Boolean).doc("True if A = B exactly."))
    .output(Port::new("Inequality", "≠", DataType::Boolean).doc("True if A ≠ B."))
    .lift2_with_plain(
        neither_nan,
        |&a: &f64, &b: &f64| (a == b, a != b),
        |a: &f64, b: &f64, report| Ok(compare(*a, *b, report, |a, b| (a == b, a != b))),
    )
}

/// Whether neither input is NaN: then a comparison reports nothing, and its items take the
/// lifted loop's plain pass.
#[inline(always)]
fn neither_nan(a: &f64, b: &f64) -> bool {
    !a.is_nan() & !b.is_nan()
}

/// The two results of a comparison, with a warning when an input is NaN.
#[inline(always)]
fn compare(
    a: f64,
    b: f64,
    report: &mut ItemReport,
    f: impl Fn(f64, f64) -> (bool, bool),
) -> (bool, bool) {
    if a.is_nan() || b.is_nan() {
        report.warning("an input is NaN, which compares false with everything");
    }
    f(a, b)
}

#[cfg(test)]
mod tests {
    use locus_runtime::{DataTree, Level, NodeCall};

    use super::*;
    use crate::maths::test_support::{booleans, messages};

    fn run(node: &NodeType, a: Vec<f64>, b: Vec<f64>) -> locus_runtime::NodeCallResult {
        NodeCall::new(node)
            .input(DataTree::from_list(a))
            .input(DataTree::from_list(b))
            .run()
    }

    #[test]
    fn larger_than() {
        let r = run(&super::larger_than(), vec![1.0, 2.0, 3.0], vec![2.0]);
        assert_eq!(booleans(&r.outputs[0]), [false, false, true]);
        assert_eq!(booleans(&r.outputs[1]), [false, true, true]);
    }

    #[test]
    fn smaller_than() {
        let r = run(&super::smaller_than(), vec![1.0, 2.0, 3.0], vec![2.0]);
        assert_eq!(booleans(&r.outputs[0]), [true, false, false]);
        assert_eq!(booleans(&r.outputs[1]), [true, true, false]);
    }

    #[test]
    fn equality_is_exact() {
        let r = run(&super::equality(), vec![0.1 + 0.2, 2.0], vec![0.3, 2.0]);
        assert_eq!(booleans(&r.outputs[0]), [false, true]);
        assert_eq!(booleans(&r.outputs[1]), [true, false]);
    }

    #[test]
    fn nan_compares_false_with_a_warning() {
        let r = run(&super::larger_than(), vec![f64::NAN], vec![0.0]);
        assert_eq!(booleans(&r.outputs[0]), [false]);
        assert_eq!(booleans(&r.outputs[1]), [false]);
        assert_eq!(messages(&r, Level::Warning).len(), 1);
        let r = run(&super::equality(), vec![f64::NAN], vec![f64::NAN]);
        assert_eq!(booleans(&r.outputs[0]), [false]);
        assert_eq!(booleans(&r.outputs[1]), [true]);
    }

    #[test]
    fn outputs_are_found_by_symbol_or_name() {
        let t = super::equality();
        assert_eq!(t.output_index("≠"), Some(1));
        assert_eq!(t.output_index("inequality"), Some(1));
    }
}

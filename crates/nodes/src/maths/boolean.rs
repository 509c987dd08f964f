//! Maths › Operators: logic gates on booleans.
//!
//! Inputs are booleans; numbers are cast on the way in (0 is false, anything else true). The
//! gates are lifted item functions (`lift1`/`lift2`): one loop over the boolean columns.

use locus_runtime::{DataType, NodeRegistry, NodeType, Port};

/// Id of [`gate_and`].
pub const GATE_AND: &str = "maths.gate_and";
/// Id of [`gate_or`].
pub const GATE_OR: &str = "maths.gate_or";
/// Id of [`gate_xor`].
pub const GATE_XOR: &str = "maths.gate_xor";
/// Id of [`gate_nand`].
pub const GATE_NAND: &str = "maths.gate_nand";
/// Id of [`gate_nor`].
pub const GATE_NOR: &str = "maths.gate_nor";
/// Id of [`gate_xnor`].
pub const GATE_XNOR: &str = "maths.gate_xnor";
/// Id of [`gate_not`].
pub const GATE_NOT: &str = "maths.gate_not";

/// Registers the gate nodes.
pub fn register(registry: &mut NodeRegistry) {
    for t in [
        gate_and(),
        gate_or(),
        gate_xor(),
        gate_nand(),
        gate_nor(),
        gate_xnor(),
        gate_not(),
    ] {
        registry.register(t);
    }
}

fn gate(
    id: &str,
    name: &str,
    nickname: &str,
    description: &str,
    f: fn(bool, bool) -> bool,
) -> NodeType {
    NodeType::new(id, name, nickname, "Maths")
        .subcategory("Operators")
        .description(description)
        .input(Port::new("A", "A", DataType::Boolean).doc("The first (left-hand) boolean."))
        .input(Port::new("B", "B", DataType::Boolean).doc("The second (right-hand) boolean."))
        .output(Port::new("Result", "R", DataType::Boolean).doc("The result of the gate."))
        .lift2(move |a: &bool, b: &bool| Ok(f(*a, *b)))
}

/// Gate And \[And\]: true when both A and B are true.
pub fn gate_and() -> NodeType {
    gate(
        GATE_AND,
        "Gate And",
        "And",
        "Boolean conjunction (AND gate): true when A and B are both true.",
        |a, b| a && b,
    )
}

/// Gate Or \[Or\]: true when A or B (or both) is true.
pub fn gate_or() -> NodeType {
    gate(
        GATE_OR,
        "Gate Or",
        "Or",
        "Boolean disjunction (OR gate): true when A or B (or both) is true.",
        |a, b| a || b,
    )
    .gh_guid("5cad70f9-5a53-4c5c-a782-54a479b4abe3")
}

/// Gate Xor \[Xor\]: true when exactly one of A and B is true.
pub fn gate_xor() -> NodeType {
    gate(
        GATE_XOR,
        "Gate Xor",
        "Xor",
        "Boolean exclusive disjunction (XOR gate): true when exactly one of A and B is true.",
        |a, b| a != b,
    )
}

/// Gate Nand \[Nand\]: false only when both A and B are true.
pub fn gate_nand() -> NodeType {
    gate(
        GATE_NAND,
        "Gate Nand",
        "Nand",
        "Boolean alternative denial (NAND gate): false only when A and B are both true.",
        |a, b| !(a && b),
    )
}

/// Gate Nor \[Nor\]: true only when both A and B are false.
pub fn gate_nor() -> NodeType {
    gate(
        GATE_NOR,
        "Gate Nor",
        "Nor",
        "Boolean joint denial (NOR gate): true only when A and B are both false.",
        |a, b| !(a || b),
    )
}

/// Gate Xnor \[Xnor\]: true when A and B are equal.
pub fn gate_xnor() -> NodeType {
    gate(
        GATE_XNOR,
        "Gate Xnor",
        "Xnor",
        "Boolean biconditional (XNOR gate): true when A and B are equal.",
        |a, b| a == b,
    )
}

/// Gate Not \[Not\]: the inverse of A.
pub fn gate_not() -> NodeType {
    NodeType::new(GATE_NOT, "Gate Not", "Not", "Maths")
        .gh_guid("cb2c7d3c-41b4-4c6d-a6bd-9235bd2851bb")
        .subcategory("Operators")
        .description("Boolean negation (NOT gate): true when A is false.")
        .input(Port::new("A", "A", DataType::Boolean).doc("The boolean to invert."))
        .output(Port::new("Result", "R", DataType::Boolean).doc("The inverse of A."))
        .lift1(|a: &bool| Ok(!a))
}

#[cfg(test)]
mod tests {
    use locus_runtime::{DataTree, NodeCall};

    use super::*;
    use crate::maths::test_support::booleans;

    /// Runs a two-input gate on the four combinations (F,F), (T,F), (F,T), (T,T).
    fn truth_table(node: &NodeType) -> Vec<bool> {
        let r = NodeCall::new(node)
            .input(DataTree::from_list(vec![false, true, false, true]))
            .input(DataTree::from_list(vec![false, false, true, true]))
            .run();
        assert!(r.messages.is_empty());
        booleans(&r.outputs[0])
    }

    #[test]
    fn truth_tables() {
        assert_eq!(truth_table(&gate_and()), [false, false, false, true]);
        assert_eq!(truth_table(&gate_or()), [false, true, true, true]);
        assert_eq!(truth_table(&gate_xor()), [false, true, true, false]);
        assert_eq!(truth_table(&gate_nand()), [true, true, true, false]);
        assert_eq!(truth_table(&gate_nor()), [true, false, false, false]);
        assert_eq!(truth_table(&gate_xnor()), [true, false, false, true]);
    }

    #[test]
    fn not_inverts() {
        let r = NodeCall::new(&gate_not())
            .input(DataTree::from_list(vec![true, false]))
            .run();
        assert_eq!(booleans(&r.outputs[0]), [false, true]);
    }

    #[test]
    fn a_null_input_gives_a_null_result() {
        let mut b = locus_runtime::Branch::new(DataType::Boolean);
        b.push(true);
        b.push_null();
        let a = DataTree::from_branches([(locus_runtime::TreePath::zero(), b)]);
        let r = NodeCall::new(&gate_and())
            .input(a)
            .input(DataTree::from_item(true))
            .run();
        let out: Vec<_> = r.outputs[0].values().collect();
        assert_eq!(out, [Some(locus_runtime::Value::Boolean(true)), None]);
        assert!(r.messages.is_empty());
    }
}

//! The formula language of the Expression and Evaluate nodes.
//!
//! A formula is parsed once into a [`Program`] and then evaluated for every item. It computes
//! with numbers, booleans, texts, points and vectors ([`Operand`]); `A + t*(B-A)` with points
//! `A`, `B` and a number `t` gives a point. The full language (grammar, precedence, functions
//! and type rules) is described in `docs/expression.md` at the root of the repository.
//!
//! ```
//! use locus_nodes::expression::{Operand, Program};
//! use locus_kernel::Point3;
//! let program = Program::compile("A + t*(B-A)", &["A", "B", "t"]).unwrap();
//! let vars = [
//!     Operand::Point(Point3::new(0.0, 0.0, 0.0)),
//!     Operand::Point(Point3::new(2.0, 4.0, 6.0)),
//!     Operand::Number(0.5),
//! ];
//! let r = program.evaluate(|i| Ok(vars[i].clone())).unwrap();
//! assert_eq!(r.value, Operand::Point(Point3::new(1.0, 2.0, 3.0)));
//!
//! let e = Program::compile("(x + 1", &["x"]).unwrap_err();
//! assert_eq!(e.to_string(), "expected \")\" at column 7");
//! ```

mod eval;
mod functions;
mod lexer;
mod operand;
mod parser;

use std::fmt;

use locus_runtime::DataType;

pub(crate) use self::eval::binary_warning;
pub use self::eval::{EvalFailure, Evaluation, Program};
pub use self::functions::{FUNCTIONS, Function};
pub use self::operand::{BinaryOp, Operand, UnaryOp};
pub use self::parser::MAX_NESTING;

/// Why a formula could not be parsed: what is wrong and where.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ParseError {
    /// What is wrong, such as `expected ")"`.
    pub message: String,
    /// The 1-based character column of the fault (one past the end for a formula that ends
    /// too early).
    pub column: usize,
}

impl ParseError {
    pub(crate) fn new(message: impl Into<String>, column: usize) -> Self {
        Self {
            message: message.into(),
            column,
        }
    }
}

impl fmt::Display for ParseError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} at column {}", self.message, self.column)
    }
}

impl std::error::Error for ParseError {}

impl From<EvalError> for locus_runtime::NodeError {
    fn from(e: EvalError) -> Self {
        Self(e.to_string())
    }
}

impl From<EvalFailure> for locus_runtime::NodeError {
    fn from(e: EvalFailure) -> Self {
        Self(e.to_string())
    }
}

impl From<ParseError> for locus_runtime::NodeError {
    fn from(e: ParseError) -> Self {
        Self(e.to_string())
    }
}

/// Why evaluating a formula (or applying an operator node) failed.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum EvalError {
    /// A binary operator met operands it does not apply to.
    #[error("cannot compute {left} {op} {right}")]
    Binary {
        /// The operator symbol.
        op: &'static str,
        /// The kind of the left operand.
        left: &'static str,
        /// The kind of the right operand.
        right: &'static str,
    },
    /// A prefix operator met an operand it does not apply to.
    #[error("cannot compute {op}{operand}")]
    Unary {
        /// The operator symbol.
        op: &'static str,
        /// The kind of the operand.
        operand: &'static str,
    },
    /// A function got an argument that is not a number.
    #[error("{function} needs a Number, not a {got}")]
    Argument {
        /// The function's name.
        function: &'static str,
        /// The kind of the argument.
        got: &'static str,
    },
    /// A function of vectors got an argument that is not a vector or point.
    #[error("{function} needs a Vector or a Point, not a {got}")]
    VectorArgument {
        /// The function's name.
        function: &'static str,
        /// The kind of the argument.
        got: &'static str,
    },
    /// The unit vector of a zero vector.
    #[error("a zero vector has no direction, so no unit vector")]
    ZeroVector,
    /// `round(x, n)` with `n` not a whole number from 0 to 15.
    #[error("round needs 0 to 15 digits, not {0}")]
    Digits(f64),
    /// A condition or logical operand that is not a boolean or a number.
    #[error("expected a Boolean, not a {0}")]
    NotBoolean(&'static str),
    /// `.x`, `.y` or `.z` on something that is not a point or vector.
    #[error(".x, .y and .z need a Point or a Vector, not a {0}")]
    Member(&'static str),
    /// A value of a type expressions do not compute with.
    #[error("a {0} cannot be used here")]
    Unsupported(DataType),
    /// A text that should have been a number.
    #[error("cannot read \"{0}\" as a number")]
    NotANumber(String),
    /// A variable the formula uses has no data at all.
    #[error("input {0} has no data")]
    NoData(String),
    /// A variable's item is null; the node leaves a null and reports nothing.
    #[error("input {0} is null")]
    Null(String),
    /// A bug: an inconsistent program.
    #[error("internal error: {0}")]
    Internal(&'static str),
}

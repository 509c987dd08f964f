//! The kernel's error type.

use thiserror::Error;

/// The result of a fallible kernel operation.
pub type Result<T, E = Error> = std::result::Result<T, E>;

/// Why a kernel operation could not produce a result.
///
/// Messages are lower-case without a trailing full stop so that callers can prefix them with
/// the node, port and item that caused them.
#[derive(Clone, Debug, Error, PartialEq)]
#[non_exhaustive]
pub enum Error {
    /// An input coordinate, parameter or factor was NaN or infinite.
    #[error("{what} is not finite")]
    NotFinite {
        /// What was not finite, such as `"point"` or `"parameter"`.
        what: &'static str,
    },
    /// A vector that must have a direction has (near) zero length.
    #[error("{what} has zero length")]
    ZeroLength {
        /// Which vector, such as `"normal"` or `"axis"`.
        what: &'static str,
    },
    /// Three or more points that must span a plane lie on one line.
    #[error("points are collinear")]
    Collinear,
    /// A matrix that must be inverted is singular.
    #[error("transform is singular and has no inverse")]
    SingularTransform,
    /// Too few points or control points for the requested construction.
    #[error("{what} needs at least {needed} points, got {got}")]
    TooFewPoints {
        /// The construction.
        what: &'static str,
        /// How many are needed.
        needed: usize,
        /// How many were given.
        got: usize,
    },
    /// A degree outside the supported range.
    #[error("invalid degree {degree}: {reason}")]
    InvalidDegree {
        /// The degree given.
        degree: usize,
        /// Why it is invalid.
        reason: String,
    },
    /// A knot vector that is not valid for the curve or surface.
    #[error("invalid knot vector: {reason}")]
    InvalidKnots {
        /// Why it is invalid.
        reason: String,
    },
    /// A control-point weight that is zero, negative or not finite.
    #[error("weight {index} is {weight}, weights must be positive")]
    InvalidWeight {
        /// The index of the control point.
        index: usize,
        /// The weight given.
        weight: f64,
    },
    /// A parameter or interval outside what the operation accepts.
    #[error("{0}")]
    InvalidInput(String),
    /// The geometry is degenerate where the operation needs it not to be, such as a surface
    /// whose partial derivatives are zero or parallel at the requested parameters.
    #[error("{what} is degenerate")]
    Degenerate {
        /// What is degenerate, such as `"surface frame"`.
        what: &'static str,
    },
    /// An iterative method did not reach its tolerance.
    #[error("{what} did not converge")]
    NoConvergence {
        /// The computation.
        what: &'static str,
    },
    /// A transform collapsed a frame or a box so that the result has no well-defined axes, as
    /// when a plane is projected onto a plane perpendicular to it.
    #[error("{what} is degenerate after the transform")]
    DegenerateTransformResult {
        /// What was transformed, such as `"plane"`.
        what: &'static str,
    },
}

//! The node library of locus.

pub mod expression;
pub mod maths;

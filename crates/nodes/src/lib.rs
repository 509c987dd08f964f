//! The node library of locus.

pub mod expression;

//! The node runtime of locus: data trees, typed ports, Grasshopper matching and evaluation.
//!
//! The runtime names no concrete node: node types are registered by the node library (or by a
//! host) in a `NodeRegistry` value.

mod path;
mod tree;
mod value;

pub use crate::path::{PathParseError, TreePath};
pub use crate::tree::{Branch, DataTree};
pub use crate::value::{Column, DataType, Item, Shared, Value};

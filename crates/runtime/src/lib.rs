//! The node runtime of locus: data trees, typed ports, Grasshopper matching and evaluation.
//!
//! The runtime names no concrete node: node types are registered by the node library (or by a
//! host) in a `NodeRegistry` value.

mod call;
mod cast;
mod collect;
mod evaluator;
mod graph;
mod iterate;
mod message;
mod node;
mod path;
mod plan;
mod registry;
mod solve;
mod tree;
mod value;

pub use crate::call::{NodeCall, NodeCallResult};
pub use crate::cast::can_cast;
pub use crate::evaluator::{EvalError, Evaluator};
pub use crate::graph::{
    FORMAT_VERSION, Graph, GraphInput, GraphNode, GraphOutput, Literal, Modifier, NodeId, PortRef,
    Wire,
};
pub use crate::message::{Level, Message};
pub use crate::node::{
    Access, Matching, NodeConfig, NodeError, NodeType, Port, PrepareFn, Prepared, Setting, SolveFn,
    VariableInputs,
};
pub use crate::path::{PathParseError, TreePath};
pub use crate::plan::{Plan, PlanInput, PlanNode};
pub use crate::registry::NodeRegistry;
pub use crate::solve::{ListView, Solve};
pub use crate::tree::{Branch, DataTree};
pub use crate::value::{Column, DataType, Item, Shared, Value};

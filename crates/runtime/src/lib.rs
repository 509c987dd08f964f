//! The node runtime of locus: data trees, typed ports, Grasshopper matching and evaluation.
//!
//! The runtime names no concrete node: node types are registered by the node library (or by a
//! host) in a `NodeRegistry` value.

mod call;
mod cast;
mod cast_geometry;
mod cast_rules;
mod catalogue;
mod check;
mod collect;
mod compare;
mod diagnostic;
mod dot;
mod evaluator;
mod format;
mod graph;
mod iterate;
mod literal;
mod literal_geometry;
mod message;
mod node;
mod path;
mod path_mapper;
mod path_mask;
mod plan;
mod registry;
mod simplify;
mod solve;
mod syntax;
mod tree;
mod tree_ops;
mod tree_text;
mod value;
mod value_text;

pub use crate::call::{NodeCall, NodeCallResult};
pub use crate::cast::{CastError, can_cast, cast_branch, cast_tree, cast_value};
pub use crate::cast_rules::number_to_integer;
pub use crate::check::{Checked, check, check_text};
pub use crate::compare::{COMPARE_TOLERANCE, compare_trees, values_agree};
pub use crate::diagnostic::{Diagnostic, DiagnosticKind, Location, PortDirection, Severity};
pub use crate::dot::to_dot;
pub use crate::evaluator::{EvalError, Evaluator};
pub use crate::format::{Document, write_graph};
pub use crate::graph::{
    FORMAT_VERSION, Graph, GraphInput, GraphNode, GraphOutput, Literal, Modifier, NodeId, PortRef,
    Wire,
};
pub use crate::literal::{LiteralError, UNIT_AXIS_TOLERANCE, parse_literal};
pub use crate::message::{Level, Message};
pub use crate::node::{
    Access, Matching, NodeConfig, NodeError, NodeType, Port, PrepareFn, Prepared, Setting, SolveFn,
    VariableInputs,
};
pub use crate::path::{PathParseError, TreePath};
pub use crate::path_mapper::{MAX_ITEM_PADDING, PathMapError, PathMapper};
pub use crate::path_mask::MAX_MASK_TOKENS;
pub use crate::plan::{Plan, PlanInput, PlanNode};
pub use crate::registry::NodeRegistry;
pub use crate::simplify::SimplifyMode;
pub use crate::solve::{ListView, Solve};
pub use crate::tree::{Branch, DataTree};
pub use crate::tree_ops::{GraftMode, TreeError};
pub use crate::tree_text::{TreeText, TreeTextError};
pub use crate::value::{Column, DataType, Item, Shared, Value};
pub use crate::value_text::{format_number, format_value, parse_number};

//! Checking a graph into a plan: the checker, its diagnostics, and the casting table.

pub(crate) mod before_run;
pub(crate) mod cast;
pub(crate) mod cast_geometry;
pub(crate) mod cast_mesh;
pub(crate) mod cast_rules;
pub(crate) mod check;
pub(crate) mod diagnostic;
pub(crate) mod subgraph;

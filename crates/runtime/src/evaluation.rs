//! Evaluating a plan: collecting an input's data, Grasshopper's iteration, lifted item loops, the
//! `Solve` context, and the evaluator that schedules, caches and re-evaluates.

pub(crate) mod collect;
pub(crate) mod evaluator;
pub(crate) mod iterate;
pub(crate) mod lift;
pub(crate) mod output_modifiers;
pub(crate) mod progress;
pub(crate) mod solve;
pub(crate) mod spread;

//! The elements every other module builds on: points and vectors, planes, intervals, axis-aligned
//! and oriented boxes, and the named tolerances.

pub(crate) mod best_candidate;
pub(crate) mod bounding_box;
pub(crate) mod interval;
pub(crate) mod oriented_box;
pub(crate) mod oriented_box_boundary;
pub(crate) mod plane;
pub(crate) mod plane_fit;
pub(crate) mod point;
pub(crate) mod small_linear;
pub mod tolerance;
pub(crate) mod vector;

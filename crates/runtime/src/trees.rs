//! Data trees: paths, trees of typed branches, tree operations, simplification, the Path Mapper
//! and its masks, and the text form of trees.

pub(crate) mod path;
pub(crate) mod path_mapper;
pub(crate) mod path_mask;
pub(crate) mod simplify;
pub(crate) mod tree;
pub(crate) mod tree_ops;
pub(crate) mod tree_text;

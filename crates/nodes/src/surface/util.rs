//! Surface › util (to be filled in).

use locus_runtime::NodeRegistry;

/// Registers the node types of this file.
pub fn register(_registry: &mut NodeRegistry) {}

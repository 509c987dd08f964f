//! Sets: Grasshopper's Sets tab — lists and trees (to be filled in).

use locus_runtime::NodeRegistry;

/// Registers every Sets node type.
pub fn register(_registry: &mut NodeRegistry) {}

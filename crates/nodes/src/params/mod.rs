//! Params: containers that hold values of one type and cast what flows into them
//! (Grasshopper's Params tab).

pub mod geometry;

use locus_runtime::NodeRegistry;

/// Registers every Params node type.
pub fn register(registry: &mut NodeRegistry) {
    geometry::register(registry);
}

//! Params: containers that hold values and cast what flows into them to their type
//! (Grasshopper's Params tab).

pub mod curve;

use locus_runtime::NodeRegistry;

/// Registers every Params node type.
pub fn register(registry: &mut NodeRegistry) {
    curve::register(registry);
}

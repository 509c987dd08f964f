//! Grasshopper's Display category: colours ([`colour`]).

pub mod colour;

use locus_runtime::NodeRegistry;

/// Registers every Display node.
pub fn register(registry: &mut NodeRegistry) {
    colour::register(registry);
}

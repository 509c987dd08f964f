//! Grasshopper's Display category: colours ([`colour`]) and the colour gradient ([`gradient`]).

pub mod colour;
pub mod gradient;

use locus_runtime::NodeRegistry;

/// Registers every Display node.
pub fn register(registry: &mut NodeRegistry) {
    colour::register(registry);
    gradient::register(registry);
}

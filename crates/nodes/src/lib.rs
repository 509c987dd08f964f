//! The node library of locus.

pub mod params;
pub mod transform;
pub mod vector;

use locus_runtime::NodeRegistry;

/// Registers every node type of the library.
pub fn register(registry: &mut NodeRegistry) {
    params::register(registry);
    vector::register(registry);
    transform::register(registry);
}

//! The node library of locus.

pub mod curve;
pub mod params;

use locus_runtime::NodeRegistry;

/// Registers every node type of the library.
pub fn register(registry: &mut NodeRegistry) {
    curve::register(registry);
    params::register(registry);
}

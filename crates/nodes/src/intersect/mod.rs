//! Grasshopper's Intersect category: lines, planes and curves against lines and planes
//! ([`mathematical`]), meshes against rays and planes ([`mesh`]), sections and contours of
//! B-reps and meshes ([`section`]), curves against curves and themselves ([`physical`]), and
//! surfaces and B-reps against lines and curves ([`surface_curve`]).

pub mod mathematical;
pub mod mesh;
pub mod physical;
pub mod section;
pub mod shape;
pub mod surface_curve;

use locus_runtime::NodeRegistry;

/// The distance within which inputs meet: 0.001 model units, Rhino's default absolute
/// tolerance (a new model's), which Grasshopper's intersection components use as the
/// document's tolerance. Points are polished to full precision whatever the tolerance.
pub const INTERSECTION_TOLERANCE: f64 = 0.001;

/// Registers every Intersect node.
pub fn register(registry: &mut NodeRegistry) {
    mathematical::register(registry);
    mesh::register(registry);
    physical::register(registry);
    section::register(registry);
    shape::register(registry);
    surface_curve::register(registry);
}

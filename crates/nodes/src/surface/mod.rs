//! Surface: Grasshopper's Surface tab — primitives (Sphere, Cylinder, Cone, Plane Surface),
//! freeform surfaces, analysis (evaluation, closest points, curvature), utilities (Divide
//! Surface, Isocurve), boxes and B-reps.

pub mod analysis;
pub mod boundary;
pub mod bounding_box;
pub mod box_corners;
pub mod box_nodes;
pub mod brep;
pub mod brep_analysis;
pub mod extrusion;
pub mod freeform;
pub mod lofting;
pub mod primitive;
pub mod sweeping;
pub mod util;
pub mod wireframe;

use locus_runtime::NodeRegistry;

/// Registers every Surface node type.
pub fn register(registry: &mut NodeRegistry) {
    primitive::register(registry);
    freeform::register(registry);
    extrusion::register(registry);
    lofting::register(registry);
    sweeping::register(registry);
    boundary::register(registry);
    analysis::register(registry);
    util::register(registry);
    box_nodes::register(registry);
    bounding_box::register(registry);
    brep::register(registry);
    brep_analysis::register(registry);
    box_corners::register(registry);
    wireframe::register(registry);
}

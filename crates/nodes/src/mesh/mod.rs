//! Grasshopper's Mesh category: turning B-reps into meshes and mesh primitives
//! ([`primitive`], with meshing [`settings`]), meshes from and to their parts ([`construct`]),
//! grids of quads on planes, boxes and surfaces ([`grid`]), measuring meshes ([`analysis`],
//! [`faces`], [`edges`]), colouring them ([`colours`]), editing them ([`util`]) and triangulating points in a plane
//! ([`triangulation`]: Delaunay meshes and edges, Voronoi cells, convex hulls).
//!
//! Meshes are the kernel's [`locus_kernel::Mesh`]: triangles and quads with optional vertex
//! normals and colours. B-reps, surfaces and boxes wired into a Mesh port are meshed with the
//! kernel's default [`locus_kernel::MeshingParameters`], as Grasshopper meshes them.

pub mod analysis;
pub mod colours;
pub mod construct;
pub mod edges;
pub mod faces;
pub mod grid;
pub mod primitive;
pub mod settings;
pub mod triangulation;
pub mod util;

use locus_runtime::{NodeError, NodeRegistry, NodeType, Shared, Solve};

use locus_kernel::Mesh;

/// Registers every Mesh node.
pub fn register(registry: &mut NodeRegistry) {
    primitive::register(registry);
    construct::register(registry);
    grid::register(registry);
    analysis::register(registry);
    faces::register(registry);
    util::register(registry);
    settings::register(registry);
    edges::register(registry);
    colours::register(registry);
    triangulation::register(registry);
}

/// A node of the Mesh category.
pub(crate) fn mesh_node(id: &str, name: &str, nickname: &str, subcategory: &str) -> NodeType {
    NodeType::new(id, name, nickname, "Mesh").subcategory(subcategory)
}

/// The mesh on item input `input`.
pub(crate) fn mesh_item(s: &Solve<'_>, input: usize) -> Result<Shared<Mesh>, NodeError> {
    Ok(s.item::<Shared<Mesh>>(input)?.clone())
}

//! Params: containers that hold values and cast what flows in (Grasshopper's Params tab).
//!
//! A parameter node is how a graph declares a named value: it has one input and one output,
//! both called by the parameter's name and nickname (`Number`/`Num`). The input takes the
//! values given in the graph or wired in, with list access, so the tree's paths, empty
//! branches and nulls pass through unchanged; every item is cast to the parameter's type on
//! the way in (a failed cast is an error naming the item, which becomes null).

pub mod brep;
pub mod curve;
pub mod dam;
pub mod geometry;
pub mod mesh;

pub mod graph_mapper;
pub mod primitive;
pub mod shapes;
pub mod surface;

use locus_runtime::NodeRegistry;

/// Registers every Params node type.
pub fn register(registry: &mut NodeRegistry) {
    primitive::register(registry);
    geometry::register(registry);
    curve::register(registry);
    surface::register(registry);
    brep::register(registry);
    mesh::register(registry);

    shapes::register(registry);
    dam::register(registry);
    graph_mapper::register(registry);
}

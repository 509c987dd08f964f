//! Every box and B-rep node of the Surface category and the Box, Brep, Geometry and Transform
//! parameters are registered under their ids, in the category and subcategory they belong to.

use locus_nodes::intersect::shape;
use locus_nodes::params::brep as params;
use locus_nodes::surface::{bounding_box, box_nodes, brep, brep_analysis};
use locus_runtime::NodeRegistry;

#[test]
fn box_and_brep_ids_are_registered() {
    let mut registry = NodeRegistry::new();
    locus_nodes::register(&mut registry);
    let ids = [
        (box_nodes::BOX_2PT, "Surface", "Primitive"),
        (box_nodes::CENTER_BOX, "Surface", "Primitive"),
        (box_nodes::DOMAIN_BOX, "Surface", "Primitive"),
        (box_nodes::BOX_RECTANGLE, "Surface", "Primitive"),
        (bounding_box::BOUNDING_BOX, "Surface", "Primitive"),
        (box_nodes::BOX_PROPERTIES, "Surface", "Analysis"),
        (box_nodes::DECONSTRUCT_BOX, "Surface", "Analysis"),
        (brep::DECONSTRUCT_BREP, "Surface", "Analysis"),
        (brep::BREP_EDGES, "Surface", "Analysis"),
        (brep::BREP_JOIN, "Surface", "Util"),
        (brep::SINGULAR_POINTS, "Surface", "Analysis"),
        (brep_analysis::AREA, "Surface", "Analysis"),
        (brep_analysis::VOLUME, "Surface", "Analysis"),
        (shape::SOLID_UNION, "Intersect", "Shape"),
        (shape::SOLID_DIFFERENCE, "Intersect", "Shape"),
        (shape::SPLIT_BREP, "Intersect", "Shape"),
        (shape::POINT_IN_BREP, "Surface", "Analysis"),
        (params::BOX, "Params", "Geometry"),
        (params::BREP, "Params", "Geometry"),
        (params::GEOMETRY, "Params", "Geometry"),
        (params::TRANSFORM, "Params", "Primitive"),
    ];
    for (id, category, subcategory) in ids {
        let t = registry
            .get(id)
            .unwrap_or_else(|| panic!("{id} is not registered"));
        assert_eq!(
            (t.category.as_str(), t.subcategory.as_str()),
            (category, subcategory),
            "{id}"
        );
    }
    // Grasshopper's nicknames.
    for (id, nickname) in [
        (box_nodes::BOX_2PT, "Box"),
        (bounding_box::BOUNDING_BOX, "BBox"),
        (box_nodes::BOX_RECTANGLE, "BoxRec"),
        (box_nodes::BOX_PROPERTIES, "BoxProp"),
        (box_nodes::DECONSTRUCT_BOX, "DeBox"),
        (brep::DECONSTRUCT_BREP, "DeBrep"),
        (brep::BREP_EDGES, "Edges"),
        (brep::BREP_JOIN, "Join"),
        (brep::SINGULAR_POINTS, "Sing"),
        (params::GEOMETRY, "Geo"),
        (shape::SOLID_UNION, "SUnion"),
        (shape::SOLID_DIFFERENCE, "SDiff"),
        (shape::SPLIT_BREP, "Split"),
        (shape::POINT_IN_BREP, "BrepInc"),
    ] {
        assert_eq!(
            registry.get(id).map(|t| t.nickname.as_str()),
            Some(nickname)
        );
    }
}

//! Every surface node of the Primitive, Freeform, Analysis and Util subcategories and the
//! Surface parameter are registered under their ids, in their category and subcategory.

use locus_nodes::params;
use locus_nodes::surface::{analysis, freeform, primitive, sweeping, util, wireframe};
use locus_runtime::NodeRegistry;

#[test]
fn surface_ids_are_registered() {
    let mut registry = NodeRegistry::new();
    locus_nodes::register(&mut registry);
    let ids = [
        (primitive::SPHERE, "Primitive"),
        (primitive::SPHERE_FIT, "Primitive"),
        (primitive::CYLINDER, "Primitive"),
        (primitive::CONE, "Primitive"),
        (primitive::PLANE_SURFACE, "Primitive"),
        (freeform::SURFACE_FROM_POINTS, "Freeform"),
        (sweeping::PIPE, "Freeform"),
        (sweeping::SWEEP1, "Freeform"),
        (freeform::FOUR_POINT_SURFACE, "Freeform"),
        (freeform::EDGE_SURFACE, "Freeform"),
        (wireframe::BREP_WIREFRAME, "Analysis"),
        (analysis::EVALUATE_SURFACE, "Analysis"),
        (analysis::SURFACE_CLOSEST_POINT, "Analysis"),
        (analysis::PRINCIPAL_CURVATURE, "Analysis"),
        (analysis::SURFACE_CURVATURE, "Analysis"),
        (util::DIVIDE_SURFACE, "Util"),
        (util::ISO_CURVE, "Util"),
        (util::FLIP_SURFACE, "Util"),
    ];
    for (id, subcategory) in ids {
        let t = registry
            .get(id)
            .unwrap_or_else(|| panic!("{id} is not registered"));
        assert_eq!(
            (t.category.as_str(), t.subcategory.as_str()),
            ("Surface", subcategory),
            "{id}"
        );
    }
    let param = registry
        .get(params::surface::SURFACE)
        .expect("the Surface parameter is registered");
    assert_eq!(
        (param.category.as_str(), param.subcategory.as_str()),
        ("Params", "Geometry")
    );
}

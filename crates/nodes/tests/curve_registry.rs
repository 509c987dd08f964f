//! Every Curve node and the Curve parameter are registered under their ids, and the Curve
//! category holds no node that is not listed here.

use locus_nodes::curve::{
    analysis, dash, deconstruct_arc, derivatives, division, edit, extend, frames, point_on_curve,
    primitive, primitive_more, primitive_rect, regions, spline, util,
};
use locus_nodes::params;
use locus_runtime::NodeRegistry;

#[test]
fn curve_ids_are_registered() {
    let mut registry = NodeRegistry::new();
    locus_nodes::register(&mut registry);
    let ids = [
        primitive::LINE,
        primitive::CIRCLE,
        primitive::ARC,
        primitive::ELLIPSE,
        spline::POLYLINE,
        spline::BEZIER_SPAN,
        spline::NURBS_CURVE,
        spline::NURBS_CURVE_PWK,
        spline::INTERPOLATE,
        spline::KNOT_VECTOR,
        analysis::CONTROL_POINTS,
        analysis::EVALUATE_CURVE,
        analysis::CURVATURE,
        analysis::CURVE_DOMAIN,
        analysis::END_POINTS,
        analysis::LENGTH,
        analysis::EVALUATE_LENGTH,
        analysis::CURVE_CLOSEST_POINT,
        analysis::CURVE_CONTINUITY,
        derivatives::DERIVATIVES,
        deconstruct_arc::DECONSTRUCT_ARC,
        point_on_curve::POINT_ON_CURVE,
        division::DIVIDE_CURVE,
        division::DIVIDE_LENGTH,
        division::SHATTER,
        division::DIVIDE_DISTANCE,
        dash::DASH_PATTERN,
        util::FLIP_CURVE,
        util::SPLIT_CURVE,
        util::FILLET,
        util::FILLET_DISTANCE,
        util::SEAM,
        util::FIT_CURVE,
        primitive_more::LINE_SDL,
        primitive_more::CIRCLE_CNR,
        primitive_more::CIRCLE_3PT,
        primitive_more::CIRCLE_FIT,
        primitive_more::ARC_3PT,
        primitive_more::ARC_SED,
        primitive_more::POLYGON,
        primitive_more::RECTANGLE,
        primitive_more::CURVE_MIDDLE,
        primitive_rect::RECTANGLE_2PT,
        primitive_rect::RECTANGLE_3PT,
        edit::JOIN_CURVES,
        edit::EXPLODE,
        edit::OFFSET_CURVE,
        frames::CURVE_FRAME,
        frames::PERP_FRAME,
        frames::CURVE_FRAMES,
        frames::PERP_FRAMES,
        regions::POLYGON_CENTER,
        regions::POINT_IN_CURVE,
        extend::EXTEND_CURVE,
        extend::TWEEN_CURVE,
        extend::DISCONTINUITY,
    ];
    for id in ids {
        let t = registry
            .get(id)
            .unwrap_or_else(|| panic!("{id} is not registered"));
        assert_eq!(t.category, "Curve", "{id}");
    }
    let in_category = registry.iter().filter(|t| t.category == "Curve").count();
    assert_eq!(in_category, ids.len());
    let curve_param = registry
        .get(params::curve::CURVE)
        .expect("the Curve parameter is registered");
    assert_eq!(
        (
            curve_param.category.as_str(),
            curve_param.subcategory.as_str()
        ),
        ("Params", "Geometry")
    );
}

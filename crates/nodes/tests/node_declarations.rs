//! Checks every node type of the library for the declarations users and graph files rely on:
//! well-formed unique ids, documentation on the node and every port, distinct port names and
//! defaults of the port's type.

use std::collections::HashSet;

use locus_runtime::{DataType, NodeRegistry, NodeType};

fn registry() -> NodeRegistry {
    let mut registry = NodeRegistry::new();
    locus_nodes::register(&mut registry);
    registry
}

/// Whether `id` is `category.snake_name`: `^[a-z]+\.[a-z_0-9]+$`.
fn is_well_formed(id: &str) -> bool {
    let Some((category, name)) = id.split_once('.') else {
        return false;
    };
    !category.is_empty()
        && category.chars().all(|c| c.is_ascii_lowercase())
        && !name.is_empty()
        && name
            .chars()
            .all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == '_')
}

fn problems(t: &NodeType) -> Vec<String> {
    let mut out = Vec::new();
    if !is_well_formed(&t.id) {
        out.push("the id is not category.snake_name".to_owned());
    }
    if t.id.split('.').next() != Some(t.category.to_lowercase().as_str()) {
        out.push(format!(
            "the id does not start with the category {}",
            t.category
        ));
    }
    if t.name.is_empty() || t.nickname.is_empty() || t.subcategory.is_empty() {
        out.push("the name, nickname or subcategory is empty".to_owned());
    }
    if !t.description.ends_with('.') || t.description.len() < 20 {
        out.push("the description is missing or not a sentence".to_owned());
    }
    let template = t.variable_inputs.as_ref().map(|v| &v.template);
    for (side, ports) in [("input", &t.inputs), ("output", &t.outputs)] {
        let mut nicknames = HashSet::new();
        for p in ports.iter().chain(template.filter(|_| side == "input")) {
            if p.description.is_empty() {
                out.push(format!("{side} {} has no doc", p.nickname));
            }
            if p.nickname.is_empty() || p.name.is_empty() {
                out.push(format!("an {side} has no name or nickname"));
            }
            if let Some(d) = &p.default
                && p.data_type != DataType::Generic
                && d.data_type() != p.data_type
            {
                out.push(format!(
                    "{side} {} of type {} has a default of type {}",
                    p.nickname,
                    p.data_type,
                    d.data_type()
                ));
            }
        }
        for p in ports {
            if !nicknames.insert(p.nickname.as_str()) {
                out.push(format!("two {side}s are called {}", p.nickname));
            }
        }
    }
    for s in &t.settings {
        if s.description.is_empty() {
            out.push(format!("setting {} has no doc", s.name));
        }
    }
    out
}

#[test]
fn every_node_is_declared_completely() {
    let registry = registry();
    let mut report = Vec::new();
    for t in registry.iter() {
        for p in problems(t) {
            report.push(format!("{}: {p}", t.id));
        }
    }
    assert!(report.is_empty(), "{}", report.join("\n"));
}

#[test]
fn the_checks_catch_a_bad_declaration() {
    let bad = NodeType::new("Maths.Bad-Id", "Bad", "", "Maths")
        .input(locus_runtime::Port::new("A", "A", DataType::Number).default_value(true))
        .input(locus_runtime::Port::new("B", "A", DataType::Number));
    let p = problems(&bad);
    assert!(p.iter().any(|m| m.contains("not category.snake_name")));
    assert!(p.iter().any(|m| m.contains("has no doc")));
    assert!(p.iter().any(|m| m.contains("default of type Boolean")));
    assert!(p.iter().any(|m| m.contains("two inputs are called A")));
    assert!(p.iter().any(|m| m.contains("description")));
}

#[test]
fn vector_transform_and_geometry_params_ids_are_registered() {
    use locus_nodes::params::geometry;
    use locus_nodes::transform::{affine, array, euclidean, util};
    use locus_nodes::vector::{
        grid, plane, plane_edit, point, point_sets, populate, products, pull, vectors,
    };
    let registry = registry();
    let ids = [
        geometry::POINT,
        geometry::VECTOR,
        geometry::PLANE,
        point::CONSTRUCT_POINT,
        point::DECONSTRUCT_POINT,
        point::DISTANCE,
        point::POINT_BETWEEN,
        pull::PULL_POINT,
        vectors::VECTOR_XYZ,
        vectors::DECONSTRUCT_VECTOR,
        vectors::UNIT_X,
        vectors::UNIT_Y,
        vectors::UNIT_Z,
        vectors::VECTOR_2PT,
        vectors::UNIT_VECTOR,
        vectors::AMPLITUDE,
        vectors::VECTOR_LENGTH,
        vectors::REVERSE,
        vectors::ROTATE,
        products::DOT_PRODUCT,
        products::CROSS_PRODUCT,
        products::ANGLE,
        plane::CONSTRUCT_PLANE,
        plane::PLANE_3PT,
        plane::PLANE_NORMAL,
        plane::XY_PLANE,
        plane::YZ_PLANE,
        plane::XZ_PLANE,
        plane::DECONSTRUCT_PLANE,
        plane::PLANE_COEFFICIENTS,
        plane::PLANE_CLOSEST_POINT,
        grid::SQUARE,
        grid::RECTANGULAR,
        grid::HEXAGONAL,
        euclidean::MOVE,
        euclidean::ROTATE,
        euclidean::ROTATE_AXIS,
        euclidean::ROTATE_3D,
        euclidean::MIRROR,
        euclidean::ORIENT,
        affine::SCALE,
        affine::SCALE_NU,
        affine::SHEAR,
        affine::PROJECT,
        affine::ORIENT_DIRECTION,
        util::TRANSFORM,
        util::COMPOUND,
        util::INVERSE_TRANSFORM,
        util::DECONSTRUCT_TRANSFORM,
        util::CONSTRUCT_TRANSFORM,
        array::LINEAR_ARRAY,
        array::RECTANGULAR_ARRAY,
        array::POLAR_ARRAY,
        array::BOX_ARRAY,
        plane_edit::FLIP_PLANE,
        plane_edit::PLANE_ORIGIN,
        plane_edit::ALIGN_PLANE,
        plane_edit::ROTATE_PLANE,
        point_sets::POINT_POLAR,
        point_sets::CLOSEST_POINT,
        point_sets::CULL_DUPLICATES,
        populate::POPULATE_2D,
        populate::POPULATE_3D,
        populate::POPULATE_GEOMETRY,
    ];
    for id in ids {
        assert!(registry.get(id).is_some(), "{id} is not registered");
    }
    let vector_and_transform = registry
        .iter()
        .filter(|t| t.category == "Vector" || t.category == "Transform")
        .count();
    let geometry_params = registry
        .iter()
        .filter(|t| t.category == "Params" && t.subcategory == "Geometry")
        // The Curve, Surface, Brep, Box and Geometry parameters belong to the curve and
        // surface nodes and are checked with them.
        .filter(|t| {
            ![
                "params.curve",
                "params.surface",
                "params.brep",
                "params.box",
                "params.geometry",
                // The curve-shaped parameters, checked with the Params shapes.
                "params.line",
                "params.circle",
                "params.arc",
                "params.rectangle",
                "params.mesh",
            ]
            .contains(&t.id.as_str())
        })
        .count();
    assert_eq!(vector_and_transform + geometry_params, ids.len());
}

#[test]
fn maths_and_params_ids_are_registered() {
    use locus_nodes::{maths, params};
    let registry = registry();
    for id in [
        maths::operators::ADDITION,
        maths::operators::SUBTRACTION,
        maths::operators::MULTIPLICATION,
        maths::operators::DIVISION,
        maths::operators::NEGATIVE,
        maths::operators::ABSOLUTE,
        maths::operators::POWER,
        maths::operators::MODULUS,
        maths::comparison::LARGER_THAN,
        maths::comparison::SMALLER_THAN,
        maths::comparison::EQUALITY,
        maths::boolean::GATE_AND,
        maths::boolean::GATE_OR,
        maths::boolean::GATE_XOR,
        maths::boolean::GATE_NAND,
        maths::boolean::GATE_NOR,
        maths::boolean::GATE_XNOR,
        maths::boolean::GATE_NOT,
        maths::domain::CONSTRUCT_DOMAIN,
        maths::domain::DECONSTRUCT_DOMAIN,
        maths::domain::REMAP_NUMBERS,
        maths::sequence::RANGE,
        maths::sequence::SERIES,
        maths::script::EXPRESSION,
        maths::script::EVALUATE,
        maths::functions::SQUARE,
        maths::functions::SQUARE_ROOT,
        maths::functions::CUBE,
        maths::functions::CUBE_ROOT,
        maths::functions::POWER_OF_2,
        maths::functions::POWER_OF_10,
        maths::functions::POWER_OF_E,
        maths::functions::LOGARITHM,
        maths::functions::NATURAL_LOGARITHM,
        maths::functions::LOG_N,
        maths::functions::SINE,
        maths::functions::COSINE,
        maths::functions::TANGENT,
        maths::functions::ARC_SINE,
        maths::functions::ARC_COSINE,
        maths::functions::ARC_TANGENT,
        maths::functions::SECANT,
        maths::functions::COSECANT,
        maths::functions::COTANGENT,
        maths::functions::SINC,
        maths::functions::GOLDEN_RATIO,
        maths::functions::EPSILON,
        maths::functions::EXTREMES,
        params::primitive::NUMBER,
        params::primitive::INTEGER,
        params::primitive::BOOLEAN,
        params::primitive::TEXT,
        params::primitive::DOMAIN,
    ] {
        assert!(registry.get(id).is_some(), "{id} is not registered");
    }
}

#[test]
fn sets_ids_are_registered() {
    use locus_nodes::maths::sequence;
    use locus_nodes::sets::{
        list, list_edit, list_match, list_nulls, list_split, random, sequence as cull, set_members,
        set_ops, streams, text, text_chars, tree, tree_edit, tree_restructure,
    };
    let registry = registry();
    let ids = [
        list::LIST_ITEM,
        list::LIST_LENGTH,
        list::REVERSE_LIST,
        list::SHIFT_LIST,
        list::SORT_LIST,
        list::DISPATCH,
        list_split::SPLIT_LIST,
        list_split::PARTITION_LIST,
        list_match::LONGEST_LIST,
        list_match::SHORTEST_LIST,
        cull::CULL_PATTERN,
        cull::CULL_INDEX,
        cull::CULL_NTH,
        cull::REPEAT_DATA,
        cull::DUPLICATE_DATA,
        sequence::RANGE,
        sequence::SERIES,
        tree::GRAFT_TREE,
        tree::FLATTEN_TREE,
        tree::SIMPLIFY_TREE,
        tree::TRIM_TREE,
        tree::PRUNE_TREE,
        tree::SHIFT_PATHS,
        tree::FLIP_MATRIX,
        tree::PATH_MAPPER,
        streams::MERGE,
        streams::ENTWINE,
        streams::EXPLODE_TREE,
        streams::TREE_BRANCH,
        streams::TREE_ITEM,
        streams::TREE_STATISTICS,
        list_edit::SUB_LIST,
        list_edit::INSERT_ITEMS,
        list_edit::REPLACE_ITEMS,
        list_edit::PICK_N_CHOOSE,
        list_edit::WEAVE,
        list_edit::SIFT_PATTERN,
        list_edit::CROSS_REFERENCE,
        list_edit::NULL_ITEM,
        tree_edit::STREAM_FILTER,
        tree_edit::STREAM_GATE,
        tree_edit::CLEAN_TREE,
        tree_edit::SPLIT_TREE,
        tree_edit::MATCH_TREE,
        random::RANDOM,
        random::JITTER,
        random::RANDOM_REDUCE,
        random::FIBONACCI,
        text::CONCATENATE,
        text::TEXT_SPLIT,
        text::TEXT_JOIN,
        text::TEXT_LENGTH,
        text::REPLACE_TEXT,
        text::TEXT_CASE,
        text::MATCH_TEXT,
        text::FORMAT,
        text_chars::CHARACTERS,
        text_chars::TEXT_FRAGMENT,
        text_chars::TEXT_TRIM,
        text_chars::CHAR_SEQUENCE,
        set_ops::CREATE_SET,
        set_ops::SET_UNION,
        set_ops::SET_INTERSECTION,
        set_ops::SET_DIFFERENCE,
        set_ops::SYMMETRIC_DIFFERENCE,
        set_ops::SET_MAJORITY,
        set_ops::DISJOINT,
        set_ops::SUBSET,
        set_members::MEMBER_INDEX,
        set_members::REPLACE_MEMBERS,
        set_members::FIND_SIMILAR_MEMBER,
        set_members::DELETE_CONSECUTIVE,
        set_members::KEY_VALUE_SEARCH,
        list_nulls::REPLACE_NULLS,
        list_nulls::COMBINE_DATA,
        tree_restructure::RELATIVE_ITEM,
        tree_restructure::UNFLATTEN_TREE,
        tree_restructure::REPLACE_PATHS,
    ];
    for id in ids {
        assert!(registry.get(id).is_some(), "{id} is not registered");
    }
    let sets = registry.iter().filter(|t| t.category == "Sets").count();
    assert_eq!(sets, ids.len());
}

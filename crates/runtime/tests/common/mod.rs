//! A small node registry for tests: enough node types to write graphs with every port type,
//! list access, variable inputs, settings and defaults. Solve functions do nothing: checking
//! never calls them.

#![allow(dead_code, reason = "each test binary uses part of this module")]

use locus_kernel::Vector3;
use locus_runtime::{DataType, NodeRegistry, NodeType, Port};

/// The test registry.
pub fn registry() -> NodeRegistry {
    let mut r = NodeRegistry::new();
    let param = |id: &str, name: &str, nick: &str, t: DataType| {
        NodeType::new(id, name, nick, "Params")
            .input(Port::new(name, nick, t).optional())
            .output(Port::new(name, nick, t))
    };
    r.register(param("params.point", "Point", "Pt", DataType::Point));
    r.register(param("params.number", "Number", "N", DataType::Number));
    r.register(param("params.integer", "Integer", "I", DataType::Integer));
    r.register(param("params.boolean", "Boolean", "B", DataType::Boolean));
    r.register(param("params.text", "Text", "T", DataType::Text));
    r.register(param("params.vector", "Vector", "V", DataType::Vector));
    r.register(param("params.plane", "Plane", "Pl", DataType::Plane));
    r.register(param("params.domain", "Domain", "D", DataType::Domain));
    r.register(param(
        "params.transform",
        "Transform",
        "X",
        DataType::Transform,
    ));
    r.register(param("params.generic", "Data", "D", DataType::Generic));
    r.register(param("params.box", "Box", "Box", DataType::Box));
    r.register(param("params.line", "Line", "L", DataType::Line));
    r.register(param("params.circle", "Circle", "C", DataType::Circle));
    r.register(param("params.arc", "Arc", "A", DataType::Arc));
    r.register(param("params.curve", "Curve", "Crv", DataType::Curve));
    r.register(param("params.surface", "Surface", "Srf", DataType::Surface));
    r.register(param("params.brep", "Brep", "B", DataType::Brep));
    r.register(
        NodeType::new("vector.dot_product", "Dot Product", "DProd", "Vector")
            .input(Port::new("Vector A", "A", DataType::Vector))
            .input(Port::new("Vector B", "B", DataType::Vector))
            .output(Port::new("Dot product", "D", DataType::Number)),
    );
    r.register(
        NodeType::new("vector.two_pt", "Vector 2Pt", "Vec2Pt", "Vector")
            .input(Port::new("Point A", "A", DataType::Point))
            .input(Port::new("Point B", "B", DataType::Point))
            .input(Port::new("Unitize", "U", DataType::Boolean).default_value(false))
            .output(Port::new("Vector", "V", DataType::Vector))
            .output(Port::new("Length", "L", DataType::Number)),
    );
    r.register(
        NodeType::new("vector.rotate", "Rotate", "VRot", "Vector")
            .input(Port::new("Vector", "V", DataType::Vector))
            .input(Port::new("Axis", "X", DataType::Vector).default_value(Vector3::Z))
            .input(Port::new("Angle", "A", DataType::Number))
            .output(Port::new("Vector", "V", DataType::Vector)),
    );
    r.register(
        NodeType::new("math.addition", "Addition", "A+B", "Maths")
            .input(Port::new("A", "A", DataType::Number))
            .input(Port::new("B", "B", DataType::Number).default_value(0.0))
            .output(Port::new("Result", "R", DataType::Number)),
    );
    r.register(
        NodeType::new("math.expression", "Expression", "Expression", "Maths")
            .variable_inputs(Port::new("Variable", "x", DataType::Generic), &["x", "y"])
            .setting("expression", DataType::Text, None, "The formula.")
            .setting(
                "precision",
                DataType::Integer,
                Some(locus_runtime::Value::Integer(6)),
                "Digits.",
            )
            .output(Port::new("Result", "R", DataType::Generic)),
    );
    r.register(
        NodeType::new("logic.not", "Gate Not", "Not", "Maths")
            .input(Port::new("A", "A", DataType::Boolean))
            .output(Port::new("Result", "R", DataType::Boolean)),
    );
    r.register(
        NodeType::new("sets.list_item", "List Item", "Item", "Sets")
            .input(Port::new("List", "L", DataType::Generic).list())
            .input(Port::new("Index", "i", DataType::Integer).default_value(0i64))
            .input(Port::new("Wrap", "W", DataType::Boolean).default_value(true))
            .output(Port::new("Item", "i", DataType::Generic)),
    );
    r.register(
        NodeType::new("transform.compound", "Compound", "Comp", "Transform")
            .input(Port::new("Transforms", "T", DataType::Transform).list())
            .output(Port::new("Transform", "X", DataType::Transform)),
    );
    r.register(
        NodeType::new("plane.construct", "Construct Plane", "Pl", "Vector")
            .input(Port::new("Origin", "O", DataType::Point))
            .input(Port::new("X-Axis", "X", DataType::Vector))
            .input(Port::new("Y-Axis", "Y", DataType::Vector))
            .output(Port::new("Plane", "Pl", DataType::Plane)),
    );
    r
}

//! GhPython Script components onto `script.python` nodes: the script (`CodeInput`), each
//! input's access (`ScriptParamAccess`) and type hint (`TypeHintID`), and the `ghpython`
//! setting, so that the script sees Rhino types as in Grasshopper.

use locus_runtime::{Literal, Port};

use crate::document::GhObject;
use crate::literal;

/// The node type GhPython components map onto (declared by the node library with the
/// component's GUID).
pub(super) const PYTHON: &str = "script.python";

/// GhPython's type hints by `TypeHintID`, as the script node's `hints` setting names them.
/// Grasshopper's own hints and GhPython's versions of `float`, `str` and `ghdoc Object` have
/// different ids for the same hint; the first id of each name is the one written back.
pub(crate) const TYPE_HINTS: &[(&str, &str)] = &[
    ("87f87f55-5b71-41f4-8aea-21d494016f81", "ghdoc Object"),
    ("1c282eeb-dd16-439f-94e4-7d92b542fe8b", "ghdoc Object"),
    ("5325b8e1-51d7-4d36-837a-d98394626c35", "ghdoc Object"),
    ("c37956f4-d39c-49c7-af71-1e87f8031b26", "GeometryBase"),
    ("39fbc626-7a01-46ab-a18e-ec1c0c41685b", "float"),
    ("9d51e32e-c038-4352-9554-f4137ca91b9a", "float"),
    ("19ff81a2-dc4f-4035-8de9-26224c561321", "float"),
    ("37261734-eec7-4f50-b6a8-b8d1f3c4396b", "str"),
    ("3aceb454-6dbd-4c5b-9b6b-e71f8c1cdf88", "str"),
    ("9e93878a-f9c5-4f0a-8a70-584bf09f24bb", "str"),
    ("d60527f5-b5af-4ef6-8970-5f96fe412559", "bool"),
    ("48d01794-d3d8-4aef-990e-127168822244", "int"),
    ("24b1d1a3-ab79-498c-9e44-c5b14607c4d3", "Color"),
    ("e1937b56-b1da-4c12-8bd8-e34ee81746ef", "Point3d"),
    ("15a50725-e3d3-4075-9f7c-142ba5f40747", "Vector3d"),
    ("3897522d-58e9-4d60-b38c-978ddacfedd8", "Plane"),
    ("589748aa-e558-4dd9-976f-78e3ab91fc77", "Interval"),
    ("f29cb021-de79-4e63-9f04-fc8e0df5f8b6", "Box"),
    ("c4b38e4c-21ff-415f-a0d1-406d282428dd", "Transform"),
    ("f802a8cd-e699-4a94-97ea-83b5406271de", "Line"),
    ("3c5409a1-3293-4181-a6fa-c24c37fc0c32", "Circle"),
    ("9c80ec18-b48c-41b0-bc6e-cd93d9c916aa", "Arc"),
    ("66fa617b-e3e8-4480-9f1e-2c0688c1d21b", "Polyline"),
    ("83da014b-a550-4bf5-89ff-16e54225bd5d", "Rectangle3d"),
    ("9ba89ec2-5315-435f-a621-b66c5fa2f301", "Curve"),
    ("794a1f9d-21d5-4379-b987-9e8bbf433912", "Mesh"),
    ("f4070a37-c822-410f-9057-100d2e22a22d", "Surface"),
    ("2ceb0405-fdfe-403d-a4d6-8786da45fb9d", "Brep"),
];

/// Hints that mean "no hint": items arrive as they are.
const NO_HINT: &[&str] = &[
    "35915213-5534-4277-81b8-1bdc9e7383d2",
    "6a184b65-baa3-42d1-a548-3915b401de53",
    "00000000-0000-0000-0000-000000000000",
];

/// The settings of the node a GhPython component becomes, and warnings for type hints locus
/// does not have (their inputs take items as they come). `inputs` are the node's resolved
/// input ports, in the component's order.
pub(super) fn settings(o: &GhObject, inputs: &[Port]) -> (Vec<(String, Literal)>, Vec<String>) {
    let mut settings = Vec::new();
    let mut warnings = Vec::new();
    let code = o.container.str("CodeInput").unwrap_or_default();
    settings.push(("code".to_owned(), Literal(literal::text(code))));
    let mut access = Vec::new();
    let mut hints = Vec::new();
    for (p, port) in o.inputs.iter().zip(inputs) {
        let name = &port.nickname;
        match p.script_access {
            Some(1) => access.push(format!("{name}: list")),
            Some(2) => access.push(format!("{name}: tree")),
            _ => {}
        }
        let Some(hint) = &p.type_hint else { continue };
        if NO_HINT.contains(&hint.as_str()) {
            continue;
        }
        match TYPE_HINTS.iter().find(|(id, _)| id == hint) {
            Some((_, hint_name)) => hints.push(format!("{name}: {hint_name}")),
            None => warnings.push(format!(
                "input {name}: type hint {hint} is not one locus has; its items arrive as they are"
            )),
        }
    }
    if !access.is_empty() {
        settings.push(("access".to_owned(), Literal(literal::text(&access.join(", ")))));
    }
    if !hints.is_empty() {
        settings.push(("hints".to_owned(), Literal(literal::text(&hints.join(", ")))));
    }
    settings.push(("ghpython".to_owned(), Literal("true".to_owned())));
    (settings, warnings)
}

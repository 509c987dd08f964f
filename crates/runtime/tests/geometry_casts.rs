//! B-reps wired into Surface and Box ports, through the checker and the evaluator: a one-face
//! B-rep arrives as its surface, a six-face one as a null with an error on the node, and every
//! B-rep on a Box port as its tight world bounding box.

use locus_kernel::{Interval, NurbsSurface, OrientedBox, Plane, Point3};
use locus_runtime::{DataType, Document, Evaluator, NodeRegistry, NodeType, Port, Value};

/// Parameters that pass their (cast) input through.
fn registry() -> NodeRegistry {
    let mut r = NodeRegistry::new();
    for (id, name, nick, t) in [
        ("params.brep", "Brep", "B", DataType::Brep),
        ("params.surface", "Surface", "Srf", DataType::Surface),
        ("params.box", "Box", "Box", DataType::Box),
    ] {
        r.register(
            NodeType::new(id, name, nick, "Params")
                .input(Port::new(name, nick, t).list().optional())
                .output(Port::new(name, nick, t).list())
                .solve(|s| {
                    if let Some(branch) = s.branch(0) {
                        let branch = branch.clone();
                        s.set_branch(0, branch);
                    }
                    Ok(())
                }),
        );
    }
    r
}

const BILINEAR: &str = "(degree: (1, 1), points: [[(0, 0, 0), (0, 1, 0)], [(2, 0, 0), \
                        (2, 1, 1)]], knots_u: [0, 1], knots_v: [0, 1])";

fn graph() -> String {
    format!(
        r#"(
    format: 1,
    nodes: [
        (id: "b", type: "params.brep", values: {{"B": [(plane: XY, x: (0, 1), y: (0, 2), z: (0, 3)), {BILINEAR}]}}),
        (id: "s", type: "params.surface"),
        (id: "x", type: "params.box"),
    ],
    wires: [("b.B", "s.Srf"), ("b.B", "x.Box")],
    outputs: {{"surfaces": "s.Srf", "boxes": "x.Box"}},
)"#
    )
}

fn world(x: (f64, f64), y: (f64, f64), z: (f64, f64)) -> Option<Value> {
    Some(Value::Box(OrientedBox::new(
        Plane::WORLD_XY,
        Interval::new(x.0, x.1),
        Interval::new(y.0, y.1),
        Interval::new(z.0, z.1),
    )))
}

#[test]
fn breps_flow_into_surface_and_box_ports() {
    let registry = registry();
    let doc = Document::parse(&graph()).unwrap();
    let checked = doc
        .check(&registry)
        .expect("Brep → Surface and Brep → Box wires check");
    assert!(checked.warnings.is_empty());
    let mut e = Evaluator::new(checked.plan);
    e.evaluate();

    let bilinear = NurbsSurface::non_rational(
        1,
        1,
        vec![
            vec![Point3::new(0.0, 0.0, 0.0), Point3::new(0.0, 1.0, 0.0)],
            vec![Point3::new(2.0, 0.0, 0.0), Point3::new(2.0, 1.0, 1.0)],
        ],
        vec![0.0, 1.0],
        vec![0.0, 1.0],
    )
    .unwrap();
    let surfaces: Vec<Option<Value>> = e.output("surfaces").unwrap().values().collect();
    assert_eq!(
        surfaces,
        [
            None,
            Some(Value::Surface(locus_runtime::Shared::new(bilinear.clone())))
        ]
    );
    let boxes: Vec<Option<Value>> = e.output("boxes").unwrap().values().collect();
    assert_eq!(
        boxes,
        [
            world((0.0, 1.0), (0.0, 2.0), (0.0, 3.0)),
            world((0.0, 2.0), (0.0, 1.0), (0.0, 1.0)),
        ]
    );
    let messages: Vec<String> = e.messages().map(ToString::to_string).collect();
    assert_eq!(
        messages,
        ["error: node \"s\" at {0}[0]: input Srf: invalid cast: Brep with 6 faces → Surface"]
    );
}

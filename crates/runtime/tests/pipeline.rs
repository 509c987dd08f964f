//! From text to results: read, check, evaluate, set a named input from a literal, and compare
//! outputs with the expected trees stored in the file (what `locus run --set` and `locus test`
//! do).

use locus_kernel::{Point3, Vector3};
use locus_runtime::{
    DataType, Document, Evaluator, Literal, NodeRegistry, NodeType, Port, parse_literal,
};

fn registry() -> NodeRegistry {
    let mut r = NodeRegistry::new();
    r.register(
        NodeType::new("params.point", "Point", "Pt", "Params")
            .input(Port::new("Point", "Pt", DataType::Point).optional())
            .output(Port::new("Point", "Pt", DataType::Point))
            .solve(|s| {
                let p: Point3 = *s.item(0)?;
                s.set(0, p);
                Ok(())
            }),
    );
    r.register(
        NodeType::new("vector.two_pt", "Vector 2Pt", "Vec2Pt", "Vector")
            .input(Port::new("Point A", "A", DataType::Point))
            .input(Port::new("Point B", "B", DataType::Point))
            .output(Port::new("Vector", "V", DataType::Vector))
            .output(Port::new("Length", "L", DataType::Number))
            .solve(|s| {
                let a: Point3 = *s.item(0)?;
                let b: Point3 = *s.item(1)?;
                let v = b - a;
                s.set(0, v);
                s.set(1, v.length());
                Ok(())
            }),
    );
    r.register(
        NodeType::new("vector.dot_product", "Dot Product", "DProd", "Vector")
            .input(Port::new("Vector A", "A", DataType::Vector))
            .input(Port::new("Vector B", "B", DataType::Vector).default_value(Vector3::Z))
            .output(Port::new("Dot product", "D", DataType::Number))
            .solve(|s| {
                let a: Vector3 = *s.item(0)?;
                let b: Vector3 = *s.item(1)?;
                s.set(0, a.dot(b));
                Ok(())
            }),
    );
    r
}

const GRAPH: &str = r#"(
    format: 1,
    name: "pipeline",
    nodes: [
        (id: "a", type: "params.point", values: {"Pt": (0, 0, 0)}),
        (id: "b", type: "params.point", values: {"Pt": [(3, 4, 0), (0, 0, 2)]}),
        (id: "v", type: "vector.two_pt"),
        (id: "d", type: "vector.dot_product"),
    ],
    wires: [
        ("a.Pt", "v.A"),
        ("b.Pt", "v.B"),
        ("v.V", "d.A"),
    ],
    inputs: {
        "B": "b.Pt",
    },
    outputs: {
        "length": "v.L",
        "up": "d.D",
    },
    expected: {
        "length": [5.0, 2.0],
        "up": [0.0, 2.0],
    },
)
"#;

#[test]
fn a_graph_file_runs_and_meets_its_expectations() {
    let registry = registry();
    let doc = Document::parse(GRAPH).unwrap();
    let checked = doc.check(&registry).unwrap();
    let mut evaluator = Evaluator::new(checked.plan.clone());
    evaluator.evaluate();
    for (name, literal) in &doc.graph().expected {
        let (_, node, output) = checked
            .plan
            .outputs
            .iter()
            .find(|(n, _, _)| n == name)
            .unwrap();
        let data_type = checked.plan.nodes[*node].node_type.outputs[*output].data_type;
        let expected = literal.parse(data_type).unwrap();
        assert_eq!(evaluator.output(name), Some(&expected), "{name}");
    }

    // `--set B='[(0, 0, 7)]'`, then `--bless` writes the new outputs back.
    let b = parse_literal("[(0, 0, 7)]", DataType::Point).unwrap();
    evaluator.set_input("B", b).unwrap();
    evaluator.evaluate();
    let blessed: Vec<(String, Literal)> = ["length", "up"]
        .into_iter()
        .map(|n| {
            let tree = evaluator.output(n).unwrap();
            (n.to_owned(), Literal::from_tree(tree).unwrap())
        })
        .collect();
    assert_eq!(
        blessed,
        [
            ("length".to_owned(), Literal("7.0".to_owned())),
            ("up".to_owned(), Literal("7.0".to_owned())),
        ]
    );
    let rewritten = doc.with_expected(&blessed);
    assert!(
        rewritten
            .contains("    expected: {\n        \"length\": 7.0,\n        \"up\": 7.0,\n    },\n)")
    );
    assert_eq!(
        Document::parse(&rewritten).unwrap().graph().expected,
        blessed
    );
}

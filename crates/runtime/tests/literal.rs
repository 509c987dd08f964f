//! Literal values: reading every type, shape inference on generic ports, errors, and
//! write → read round trips.

use locus_kernel::{Interval, Plane, Point3, Transform, Vector3};
use locus_runtime::{Branch, DataTree, DataType, Literal, TreePath, Value, parse_literal};
use proptest::prelude::*;

fn read(text: &str, t: DataType) -> DataTree {
    parse_literal(text, t).unwrap_or_else(|e| panic!("{text}: {e}"))
}

fn fails(text: &str, t: DataType) -> String {
    match parse_literal(text, t) {
        Ok(tree) => panic!("{text} read as {tree:?}"),
        Err(e) => e.message,
    }
}

fn write(tree: &DataTree) -> String {
    Literal::from_tree(tree).unwrap().0
}

#[test]
fn items_of_every_type() {
    assert_eq!(read("0.5", DataType::Number), DataTree::from_item(0.5));
    assert_eq!(read("-3", DataType::Number), DataTree::from_item(-3.0));
    assert_eq!(
        read("1_000.5e-3", DataType::Number),
        DataTree::from_item(1.0005)
    );
    assert_eq!(read("3", DataType::Integer), DataTree::from_item(3i64));
    assert_eq!(read("true", DataType::Boolean), DataTree::from_item(true));
    assert_eq!(
        read(r#""a\"b""#, DataType::Text),
        DataTree::from_item("a\"b".to_owned())
    );
    assert_eq!(
        read("(1, 2, 3)", DataType::Point),
        DataTree::from_item(Point3::new(1.0, 2.0, 3.0))
    );
    assert_eq!(
        read("Vector(1, 2, 3)", DataType::Vector),
        DataTree::from_item(Vector3::new(1.0, 2.0, 3.0))
    );
    assert_eq!(
        read("(0, 1)", DataType::Domain),
        DataTree::from_item(Interval::new(0.0, 1.0))
    );
    assert_eq!(
        read("YZ", DataType::Plane),
        DataTree::from_item(Plane::WORLD_YZ)
    );
    assert_eq!(
        read("((1, 2, 3), (0, 2, 0), (1, 1, 0))", DataType::Plane),
        DataTree::from_item(Plane {
            origin: Point3::new(1.0, 2.0, 3.0),
            x_axis: Vector3::Y,
            y_axis: Vector3::X,
            z_axis: -Vector3::Z,
        })
    );
    let rows = [
        [1.0, 0.0, 0.0, 10.0],
        [0.0, 1.0, 0.0, 20.0],
        [0.0, 0.0, 1.0, 30.0],
        [0.0, 0.0, 0.0, 1.0],
    ];
    assert_eq!(
        read(
            "((1, 0, 0, 10), (0, 1, 0, 20), (0, 0, 1, 30), (0, 0, 0, 1))",
            DataType::Transform
        ),
        DataTree::from_item(Transform::from_rows(rows))
    );
}

#[test]
fn tags_of_another_type_cast_as_a_wire_would() {
    assert_eq!(
        read("Vector(1, 2, 3)", DataType::Point),
        DataTree::from_item(Point3::new(1.0, 2.0, 3.0))
    );
    assert_eq!(
        read("Number(2.6)", DataType::Integer),
        DataTree::from_item(3i64)
    );
    assert_eq!(
        read("Integer(2)", DataType::Text),
        DataTree::from_item("2".to_owned())
    );
}

#[test]
fn lists_trees_and_nulls() {
    assert_eq!(
        read("[1, 2, 3]", DataType::Number),
        DataTree::from_list(vec![1.0, 2.0, 3.0])
    );
    let mut expected = DataTree::new();
    let mut b = Branch::new(DataType::Integer);
    b.push(1i64);
    b.push_null();
    expected.insert(TreePath::from([0, 1]), b);
    expected.insert(TreePath::from([0, 2]), Branch::new(DataType::Integer));
    assert_eq!(
        read(r#"{"{0;2}": [], "{0;1}": [1, null]}"#, DataType::Integer),
        expected
    );
    assert_eq!(write(&expected), r#"{"{0;1}": [1, null], "{0;2}": []}"#);
    assert_eq!(read("{}", DataType::Number), DataTree::new());
    let mut empty = DataTree::new();
    empty.insert(TreePath::zero(), Branch::new(DataType::Point));
    assert_eq!(read("[]", DataType::Point), empty);
    assert_eq!(write(&empty), "[]");
    let mut one_null = DataTree::new();
    let mut b = Branch::new(DataType::Point);
    b.push_null();
    one_null.insert(TreePath::zero(), b);
    assert_eq!(read("null", DataType::Point), one_null);
    assert_eq!(write(&one_null), "[null]");
}

#[test]
fn generic_items_take_their_type_from_the_shape() {
    let tree = read(
        r#"[1, 2.5, true, "x", (1, 2, 3), Vector(0, 0, 1), (0, 1), XY,
            ((0, 0, 0), (1, 0, 0), (0, 1, 0)),
            ((1, 0, 0, 0), (0, 1, 0, 0), (0, 0, 1, 0), (0, 0, 0, 1)), Text("t"), null]"#,
        DataType::Generic,
    );
    let values: Vec<Option<Value>> = tree.values().collect();
    assert_eq!(
        values,
        [
            Some(Value::Integer(1)),
            Some(Value::Number(2.5)),
            Some(Value::Boolean(true)),
            Some(Value::Text("x".into())),
            Some(Value::Point(Point3::new(1.0, 2.0, 3.0))),
            Some(Value::Vector(Vector3::Z)),
            Some(Value::Domain(Interval::UNIT)),
            Some(Value::Plane(Plane::WORLD_XY)),
            Some(Value::Plane(Plane::WORLD_XY)),
            Some(Value::Transform(Transform::IDENTITY)),
            Some(Value::Text("t".into())),
            None,
        ]
    );
    assert_eq!(
        write(&tree),
        "[1, 2.5, true, \"x\", (1.0, 2.0, 3.0), Vector(0.0, 0.0, 1.0), (0.0, 1.0), XY, XY, \
         ((1.0, 0.0, 0.0, 0.0), (0.0, 1.0, 0.0, 0.0), (0.0, 0.0, 1.0, 0.0), (0.0, 0.0, 0.0, \
         1.0)), \"t\", null]"
    );
    assert_eq!(read(&write(&tree), DataType::Generic), tree);
}

#[test]
fn errors_say_what_was_expected() {
    let cases = [
        (
            r#""abc""#,
            DataType::Point,
            r#"expected a point (x, y, z), found "abc""#,
        ),
        (
            "(1, 2)",
            DataType::Vector,
            "expected a vector (x, y, z), found a tuple of 2 items",
        ),
        (
            "(1, true, 3)",
            DataType::Point,
            "expected a number in a point (x, y, z), found true",
        ),
        ("2.5", DataType::Integer, "expected an integer, found 2.5"),
        (
            "99999999999999999999",
            DataType::Integer,
            "integer 99999999999999999999 is out of range",
        ),
        (
            "1",
            DataType::Boolean,
            "expected a boolean (true or false), found 1",
        ),
        (
            "abc",
            DataType::Text,
            "expected a text in quotes, found abc",
        ),
        (
            "ZY",
            DataType::Plane,
            "expected a plane ((origin), (x axis), (y axis)) or XY, YZ, XZ, ZX, found ZY",
        ),
        (
            "((0, 0, 0), (1, 0, 0), (2, 0, 0))",
            DataType::Plane,
            "invalid plane: points are collinear",
        ),
        (
            "((1, 0, 0, 0))",
            DataType::Transform,
            "expected a transform of four rows ((a, b, c, d), …), found a tuple of 1 item",
        ),
        (
            "Boolean(true)",
            DataType::Point,
            "invalid cast: Boolean → Point",
        ),
        ("Hue(1, 2, 3)", DataType::Point, "unknown value type `Hue`"),
        (
            "(1, 2, 3, 4, 5)",
            DataType::Generic,
            "cannot tell the type of a tuple of 5 items: write a point (x, y, z), a domain (start, end), a Domain2 of two pairs, a line of two triples, a plane of three triples or a transform of four rows, or tag it as in Vector(1, 2, 3)",
        ),
        (
            r#"{"{0}": 1}"#,
            DataType::Number,
            "expected the list of items of branch {0}, found 1",
        ),
        (
            r#"{"{0}": [], "{0}": []}"#,
            DataType::Number,
            "duplicate path {0}",
        ),
        (
            "{0: [1]}",
            DataType::Number,
            "expected a tree path in quotes such as \"{0;1}\", found 0",
        ),
        (
            "[1, 2",
            DataType::Number,
            "expected `,` or `]`, found end of file",
        ),
        (
            "[1, [2]]",
            DataType::Number,
            "expected a number, found a list of 1 item",
        ),
    ];
    for (text, t, message) in cases {
        assert_eq!(fails(text, t), message, "{text}");
    }
}

#[test]
fn errors_point_at_the_faulty_item() {
    let e = parse_literal("[(1, 2, 3), (4, x, 6)]", DataType::Point).unwrap_err();
    assert_eq!(e.span, 16..17);
}

#[test]
fn settings_read_one_item() {
    let lit = Literal("\"x + 1\"".to_owned());
    assert_eq!(
        lit.parse_value(DataType::Text),
        Ok(Value::Text("x + 1".to_owned()))
    );
    assert!(
        Literal("null".to_owned())
            .parse_value(DataType::Text)
            .is_err()
    );
    assert_eq!(
        Literal::from_value(&Value::Vector(Vector3::X)).unwrap().0,
        "(1.0, 0.0, 0.0)"
    );
    assert_eq!(Literal::canonical("( 1,2 ,3 ,)").unwrap().0, "(1, 2, 3)");
}

fn finite() -> impl Strategy<Value = f64> {
    prop_oneof![
        -1e6..1e6f64,
        any::<f64>().prop_filter("finite", |x| x.is_finite()),
    ]
}

fn number() -> impl Strategy<Value = f64> {
    prop_oneof![
        8 => finite(),
        1 => Just(f64::INFINITY),
        1 => Just(f64::NEG_INFINITY),
        1 => Just(-0.0),
    ]
}

fn triple() -> impl Strategy<Value = [f64; 3]> {
    [number(), number(), number()]
}

fn value_of(t: DataType) -> BoxedStrategy<Value> {
    match t {
        DataType::Number => number().prop_map(Value::Number).boxed(),
        DataType::Integer => any::<i64>().prop_map(Value::Integer).boxed(),
        DataType::Boolean => any::<bool>().prop_map(Value::Boolean).boxed(),
        DataType::Text => any::<String>().prop_map(Value::Text).boxed(),
        DataType::Point => triple()
            .prop_map(|[x, y, z]| Value::Point(Point3::new(x, y, z)))
            .boxed(),
        DataType::Vector => triple()
            .prop_map(|[x, y, z]| Value::Vector(Vector3::new(x, y, z)))
            .boxed(),
        DataType::Domain => (number(), number())
            .prop_map(|(a, b)| Value::Domain(Interval::new(a, b)))
            .boxed(),
        DataType::Plane => (
            [finite(), finite(), finite()],
            [-1.0..1.0f64, -1.0..1.0, -1.0..1.0],
            [-1.0..1.0f64, -1.0..1.0, -1.0..1.0],
        )
            .prop_filter_map("degenerate frame", |(o, x, y)| {
                Plane::from_frame(
                    Point3::new(o[0], o[1], o[2]),
                    Vector3::new(x[0], x[1], x[2]),
                    Vector3::new(y[0], y[1], y[2]),
                )
                .ok()
                .map(Value::Plane)
            })
            .boxed(),
        DataType::Transform => proptest::array::uniform4(proptest::array::uniform4(number()))
            .prop_map(|rows| Value::Transform(Transform::from_rows(rows)))
            .boxed(),
        _ => prop_oneof![
            value_of(DataType::Number),
            value_of(DataType::Integer),
            value_of(DataType::Text),
            value_of(DataType::Point),
            value_of(DataType::Vector),
            value_of(DataType::Plane),
        ]
        .boxed(),
    }
}

/// The types that have a literal form (geometry types get theirs later).
const LITERAL_TYPES: [DataType; 10] = [
    DataType::Number,
    DataType::Integer,
    DataType::Boolean,
    DataType::Text,
    DataType::Point,
    DataType::Vector,
    DataType::Plane,
    DataType::Domain,
    DataType::Transform,
    DataType::Generic,
];

fn tree_of(t: DataType) -> impl Strategy<Value = DataTree> {
    let item = proptest::option::weighted(0.9, value_of(t));
    let branch = proptest::collection::vec(item, 0..5);
    let path = proptest::collection::vec(0u32..4, 1..3);
    proptest::collection::vec((path, branch), 0..4).prop_map(move |branches| {
        let mut tree = DataTree::new();
        for (path, items) in branches {
            let mut b = Branch::new(t);
            for v in items {
                b.push_option(v);
            }
            tree.insert(TreePath::new(path), b);
        }
        tree
    })
}

proptest! {
    #[test]
    fn written_trees_read_back_equal(
        (t, tree) in proptest::sample::select(LITERAL_TYPES.to_vec())
            .prop_flat_map(|t| (Just(t), tree_of(t)))
    ) {
        let text = write(&tree);
        let back = parse_literal(&text, t);
        prop_assert_eq!(back, Ok(tree), "{}", text);
    }
}

#[test]
fn meshes_and_colours_read_and_write_back() {
    let text = "(vertices: [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)], faces: [(0, 1, 2, 3)])";
    let tree = parse_literal(text, DataType::Mesh).unwrap();
    let Some(Value::Mesh(m)) = tree.values().next().flatten() else {
        panic!("not a mesh")
    };
    assert_eq!(m.area(), 1.0);
    // Written back and read again, the mesh is the same.
    let again = parse_literal(&write(&tree), DataType::Mesh).unwrap();
    assert_eq!(again, tree);
    for (text, t, message) in [
        (
            "(vertices: [(0, 0, 0)], faces: [(0, 1, 2)])",
            DataType::Mesh,
            "names vertex",
        ),
        (
            "(vertices: [(0, 0, 0)], faces: [(0, 0)])",
            DataType::Mesh,
            "three or four",
        ),
        (
            "(vertices: [(0, 0, 0)])",
            DataType::Mesh,
            "needs the field `faces`",
        ),
        ("(r: 256, g: 0, b: 0)", DataType::Colour, "0 to 255"),
        ("\"#GG0000\"", DataType::Colour, "#RRGGBB"),
    ] {
        let e = parse_literal(text, t).unwrap_err();
        assert!(e.message.contains(message), "{text}: {}", e.message);
    }
    for (text, expected) in [
        (
            "(r: 255, g: 128, b: 0)",
            locus_kernel::Color::rgb(255, 128, 0),
        ),
        ("(1, 2, 3, 4)", locus_kernel::Color::rgba(1, 2, 3, 4)),
        ("\"#80FF0000\"", locus_kernel::Color::rgba(255, 0, 0, 128)),
    ] {
        let tree = parse_literal(text, DataType::Colour).unwrap();
        let v = tree.values().next().flatten();
        assert_eq!(v, Some(Value::Colour(expected)), "{text}");
        assert_eq!(
            parse_literal(&write(&tree), DataType::Colour).unwrap(),
            tree
        );
    }
}

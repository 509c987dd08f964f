//! Literal forms of the geometry types: each reads to the kernel value it describes, writes back
//! to the same text (and the same value), is inferred on generic ports, and a bad literal gives
//! the kernel's reason at the field at fault, located in the graph file.

mod common;

use locus_kernel::{
    Arc, Brep, Circle, Curve, Interval, Line, NurbsCurve, NurbsSurface, OrientedBox, Plane, Point3,
    Polyline, Vector3,
};
use locus_runtime::{
    DataTree, DataType, Document, Literal, Shared, Value, check_text, parse_literal,
};

fn read(text: &str, t: DataType) -> Value {
    let tree = parse_literal(text, t).unwrap_or_else(|e| panic!("{text}: {e}"));
    assert_eq!(tree.item_count(), 1, "{text}");
    tree.values().next().flatten().unwrap()
}

fn fails(text: &str, t: DataType) -> (String, String) {
    match parse_literal(text, t) {
        Ok(tree) => panic!("{text} read as {tree:?}"),
        // The message and the text at the reported place.
        Err(e) => (e.message, text[e.span.start..].chars().take(12).collect()),
    }
}

fn write(value: &Value) -> String {
    Literal::from_value(value).unwrap().0
}

/// The value reads from `text`, and writes back to exactly `text` (and reads back equal).
fn round_trip(text: &str, t: DataType, expected: &Value) {
    let value = read(text, t);
    assert_eq!(&value, expected, "{text}");
    assert_eq!(write(&value), text);
    let tree = DataTree::from_value(value.clone());
    assert_eq!(Literal::from_tree(&tree).unwrap().0, text);
    assert_eq!(read(&write(&value), t), value);
}

fn p(x: f64, y: f64, z: f64) -> Point3 {
    Point3::new(x, y, z)
}

#[test]
fn lines() {
    let l = Line::new(p(0.0, 0.0, 0.0), p(1.0, 2.0, 3.0));
    round_trip(
        "((0.0, 0.0, 0.0), (1.0, 2.0, 3.0))",
        DataType::Line,
        &Value::Line(l),
    );
    assert_eq!(
        read("((0, 0, 0), (1, 2, 3))", DataType::Line),
        Value::Line(l)
    );
    assert_eq!(
        read("((0, 0, 0), (1, 2, 3))", DataType::Generic),
        Value::Line(l)
    );
    assert_eq!(
        fails("((0, 0, 0), (1, 2))", DataType::Line).0,
        "expected a point (x, y, z), found a tuple of 2 items"
    );
}

#[test]
fn boxes() {
    let b = OrientedBox::new(
        Plane::WORLD_XY,
        Interval::new(0.0, 1.0),
        Interval::new(-2.0, 2.0),
        Interval::new(0.0, 3.5),
    );
    let text = "(plane: XY, x: (0.0, 1.0), y: (-2.0, 2.0), z: (0.0, 3.5))";
    round_trip(text, DataType::Box, &Value::Box(b));
    assert_eq!(read(text, DataType::Generic), Value::Box(b));
    assert_eq!(read(&format!("Box{text}"), DataType::Box), Value::Box(b));
    let (m, at) = fails("(plane: XY, x: (0, 1), y: (0, 1))", DataType::Box);
    assert_eq!(m, "a box needs the field `z`");
    assert_eq!(at, "(plane: XY, ");
    let (m, at) = fails(
        "(plane: XY, x: (0, 1), y: (0, 1), z: (0, 1), w: 2)",
        DataType::Box,
    );
    assert_eq!(
        m,
        "unknown field `w` of a box (its fields are: plane, x, y, z)"
    );
    assert_eq!(at, "w: 2)");
    assert_eq!(
        fails(
            "(plane: XY, x: (0, 1), x: (0, 1), y: (0, 1), z: (0, 1))",
            DataType::Box
        )
        .0,
        "field `x` of a box is given twice"
    );
}

#[test]
fn planes_by_name_and_by_axes() {
    let xz = Plane {
        origin: Point3::ORIGIN,
        x_axis: Vector3::X,
        y_axis: Vector3::Z,
        z_axis: -Vector3::Y,
    };
    for (text, plane) in [
        ("XY", Plane::WORLD_XY),
        ("YZ", Plane::WORLD_YZ),
        ("XZ", xz),
        ("ZX", Plane::WORLD_ZX),
    ] {
        round_trip(text, DataType::Plane, &Value::Plane(plane));
    }
    let moved = Plane {
        origin: p(1.0, 2.0, 3.0),
        ..Plane::WORLD_XY
    };
    round_trip(
        "((1.0, 2.0, 3.0), (1.0, 0.0, 0.0), (0.0, 1.0, 0.0))",
        DataType::Plane,
        &Value::Plane(moved),
    );
    assert_eq!(
        fails("((0, 0, 0), (1, 0, 0), (2, 0, 0))", DataType::Plane).0,
        "invalid plane: points are collinear"
            .replace("points are collinear", &fails_reason_collinear()),
    );
}

/// The kernel's reason for a plane whose axes are parallel.
fn fails_reason_collinear() -> String {
    Plane::from_frame(Point3::ORIGIN, Vector3::X, Vector3::new(2.0, 0.0, 0.0))
        .unwrap_err()
        .to_string()
}

#[test]
fn circles_and_arcs() {
    let c = Circle::new(Plane::WORLD_XY, 2.0).unwrap();
    round_trip(
        "(plane: XY, radius: 2.0)",
        DataType::Circle,
        &Value::Circle(c),
    );
    assert_eq!(
        read("(plane: XY, radius: 2)", DataType::Generic),
        Value::Circle(c)
    );
    let (m, at) = fails("(plane: XY, radius: 0)", DataType::Circle);
    assert_eq!(m, "invalid circle: circle radius 0 is not positive");
    assert_eq!(at, "0)");
    let a = Arc::new(c, Interval::new(0.0, 1.5)).unwrap();
    round_trip(
        "(plane: XY, radius: 2.0, angle: (0.0, 1.5))",
        DataType::Arc,
        &Value::Arc(a),
    );
    assert_eq!(
        read("(plane: XY, radius: 2, angle: (0, 1.5))", DataType::Generic),
        Value::Arc(a)
    );
    let (m, at) = fails("(plane: XY, radius: 2, angle: (1, 0))", DataType::Arc);
    assert_eq!(
        m,
        "invalid arc: arc angle 1 to 0 must increase by at most 2π"
    );
    assert_eq!(at, "(1, 0))");
}

fn curve(c: impl Into<Curve>) -> Value {
    Value::Curve(Shared::new(c.into()))
}

#[test]
fn nurbs_curves() {
    let pts = vec![
        p(0.0, 0.0, 0.0),
        p(1.0, 1.0, 0.0),
        p(2.0, 0.0, 0.0),
        p(3.0, 1.0, 0.0),
    ];
    let knots = vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0];
    let c = NurbsCurve::new_non_rational(3, pts.clone(), knots.clone()).unwrap();
    let text = "(degree: 3, points: [(0.0, 0.0, 0.0), (1.0, 1.0, 0.0), (2.0, 0.0, 0.0), \
                (3.0, 1.0, 0.0)], knots: [0.0, 0.0, 0.0, 1.0, 1.0, 1.0])";
    round_trip(text, DataType::Curve, &curve(c.clone()));
    assert_eq!(read(text, DataType::Generic), curve(c.clone()));
    // Rational: the weights are written.
    let w = NurbsCurve::new(3, pts.clone(), vec![1.0, 2.0, 2.0, 1.0], knots).unwrap();
    let text = "(degree: 3, points: [(0.0, 0.0, 0.0), (1.0, 1.0, 0.0), (2.0, 0.0, 0.0), \
                (3.0, 1.0, 0.0)], weights: [1.0, 2.0, 2.0, 1.0], knots: [0.0, 0.0, 0.0, 1.0, 1.0, 1.0])";
    round_trip(text, DataType::Curve, &curve(w));
    // Without knots: Rhino's NurbsCurve.Create, open or periodic.
    let points = "[(0, 0, 0), (1, 1, 0), (2, 0, 0), (3, 1, 0)]";
    assert_eq!(
        read(&format!("(degree: 3, points: {points})"), DataType::Curve),
        curve(NurbsCurve::create(&pts, 3, false).unwrap())
    );
    let periodic = read(
        &format!("(degree: 3, points: {points}, periodic: true)"),
        DataType::Curve,
    );
    assert_eq!(periodic, curve(NurbsCurve::create(&pts, 3, true).unwrap()));
    let Value::Curve(pc) = &periodic else {
        unreachable!()
    };
    assert!(pc.is_periodic());
    // …and its exact form reads back to the same periodic curve.
    assert_eq!(read(&write(&periodic), DataType::Curve), periodic);
}

#[test]
fn bad_nurbs_curves_name_the_kernels_reason_at_the_field() {
    let points = "[(0, 0, 0), (1, 1, 0), (2, 0, 0), (3, 1, 0)]";
    let (m, at) = fails(
        &format!("(degree: 3, points: {points}, knots: [0, 0, 1, 1])"),
        DataType::Curve,
    );
    assert_eq!(
        m,
        "invalid curve: ".to_owned()
            + &NurbsCurve::new_non_rational(3, vec![Point3::ORIGIN; 4], vec![0.0, 0.0, 1.0, 1.0])
                .unwrap_err()
                .to_string()
    );
    assert!(m.contains("knot"), "{m}");
    assert_eq!(at, "[0, 0, 1, 1]");
    let (m, at) = fails(
        &format!("(degree: 3, points: {points}, weights: [1, 0, 1, 1], knots: [0, 0, 0, 1, 1, 1])"),
        DataType::Curve,
    );
    assert_eq!(m, "invalid curve: weight 1 is 0, weights must be positive");
    assert_eq!(at, "[1, 0, 1, 1]");
    let (m, _) = fails(
        &format!("(degree: 3, points: {points}, weights: [1, 1], knots: [0, 0, 0, 1, 1, 1])"),
        DataType::Curve,
    );
    assert_eq!(m, "invalid curve: 2 weights for 4 control points");
    let (m, at) = fails(
        &format!("(degree: 0, points: {points}, knots: [0, 1, 2])"),
        DataType::Curve,
    );
    assert!(m.starts_with("invalid curve: invalid degree 0"), "{m}");
    assert_eq!(at, "0, points: [");
    let (m, _) = fails(
        &format!("(degree: 3, points: {points}, weights: [1, 1, 1, 1])"),
        DataType::Curve,
    );
    assert!(m.starts_with("weights need knots"), "{m}");
    let (m, _) = fails(
        &format!("(degree: 3, points: {points}, knots: [0, 0, 0, 1, 1, 1], periodic: true)"),
        DataType::Curve,
    );
    assert!(
        m.starts_with("periodic is for curves given without knots"),
        "{m}"
    );
    let (m, _) = fails("(degree: 2, points: [(0, 0, 0)])", DataType::Curve);
    assert!(m.starts_with("invalid curve: "), "{m}");
    assert_eq!(
        fails("(points: [])", DataType::Curve).0,
        "a curve needs exactly one of the fields degree (a NURBS curve), line, polyline, circle or arc"
    );
    assert_eq!(
        fails("(line: ((0, 0, 0), (1, 0, 0)), knots: [])", DataType::Curve).0,
        "a curve given by `line` takes no field `knots` (only line, domain)"
    );
}

#[test]
fn lines_polylines_circles_and_arcs_as_curves() {
    let l = Line::new(p(0.0, 0.0, 0.0), p(3.0, 4.0, 0.0));
    round_trip(
        "(line: ((0.0, 0.0, 0.0), (3.0, 4.0, 0.0)))",
        DataType::Curve,
        &curve(l),
    );
    // A domain other than the default is written.
    let r = Curve::from(l).reparameterized(Interval::UNIT).unwrap();
    round_trip(
        "(line: ((0.0, 0.0, 0.0), (3.0, 4.0, 0.0)), domain: (0.0, 1.0))",
        DataType::Curve,
        &Value::Curve(Shared::new(r)),
    );
    let pl = Polyline::new(vec![p(0.0, 0.0, 0.0), p(1.0, 0.0, 0.0), p(1.0, 1.0, 0.0)]).unwrap();
    round_trip(
        "(polyline: [(0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (1.0, 1.0, 0.0)])",
        DataType::Curve,
        &curve(pl),
    );
    let c = Circle::new(Plane::WORLD_XY, 1.0).unwrap();
    round_trip(
        "(circle: (plane: XY, radius: 1.0))",
        DataType::Curve,
        &curve(c),
    );
    let a = Arc::new(c, Interval::new(0.0, 1.0)).unwrap();
    round_trip(
        "(arc: (plane: XY, radius: 1.0, angle: (0.0, 1.0)))",
        DataType::Curve,
        &curve(a),
    );
    // A line, circle or arc literal tagged with its type is cast to a curve, as a wire would.
    assert_eq!(
        read("Line((0, 0, 0), (3, 4, 0))", DataType::Curve),
        curve(l)
    );
    assert_eq!(
        read("Circle(plane: XY, radius: 1)", DataType::Curve),
        curve(c)
    );
    let (m, at) = fails("(polyline: [(0, 0, 0)])", DataType::Curve);
    assert_eq!(
        m,
        "invalid polyline: a polyline needs at least 2 points, got 1"
    );
    assert_eq!(at, "[(0, 0, 0)])");
    let (m, at) = fails(
        "(line: ((0, 0, 0), (1, 0, 0)), domain: (1, 1))",
        DataType::Curve,
    );
    assert_eq!(m, "invalid curve domain: domain 1 to 1 is not increasing");
    assert_eq!(at, "(1, 1))");
}

fn bilinear() -> NurbsSurface {
    NurbsSurface::non_rational(
        1,
        1,
        vec![
            vec![p(0.0, 0.0, 0.0), p(0.0, 1.0, 0.0)],
            vec![p(1.0, 0.0, 0.0), p(1.0, 1.0, 1.0)],
        ],
        vec![0.0, 1.0],
        vec![0.0, 1.0],
    )
    .unwrap()
}

const BILINEAR: &str = "(degree: (1, 1), points: [[(0.0, 0.0, 0.0), (0.0, 1.0, 0.0)], \
                        [(1.0, 0.0, 0.0), (1.0, 1.0, 1.0)]], knots_u: [0.0, 1.0], knots_v: [0.0, 1.0])";

#[test]
fn surfaces() {
    let s = bilinear();
    round_trip(
        BILINEAR,
        DataType::Surface,
        &Value::Surface(Shared::new(s.clone())),
    );
    assert_eq!(
        read(BILINEAR, DataType::Generic),
        Value::Surface(Shared::new(s))
    );
    let rational = NurbsSurface::new(
        1,
        1,
        vec![
            vec![p(0.0, 0.0, 0.0), p(0.0, 1.0, 0.0)],
            vec![p(1.0, 0.0, 0.0), p(1.0, 1.0, 1.0)],
        ],
        vec![vec![1.0, 2.0], vec![1.0, 1.0]],
        vec![0.0, 1.0],
        vec![0.0, 1.0],
    )
    .unwrap();
    round_trip(
        "(degree: (1, 1), points: [[(0.0, 0.0, 0.0), (0.0, 1.0, 0.0)], [(1.0, 0.0, 0.0), \
         (1.0, 1.0, 1.0)]], weights: [[1.0, 2.0], [1.0, 1.0]], knots_u: [0.0, 1.0], knots_v: [0.0, 1.0])",
        DataType::Surface,
        &Value::Surface(Shared::new(rational)),
    );
    let (m, at) = fails(
        &BILINEAR.replace("knots_v: [0.0, 1.0]", "knots_v: [0.0]"),
        DataType::Surface,
    );
    assert_eq!(
        m,
        "invalid surface: invalid knot vector: v needs 2 knots for 2 control points of degree 1, got 1"
    );
    assert_eq!(at, "[0.0])");
    let (m, at) = fails(
        &BILINEAR.replace("knots_u: [0.0, 1.0]", "knots_u: [1.0, 0.0]"),
        DataType::Surface,
    );
    assert!(
        m.starts_with("invalid surface: invalid knot vector: u"),
        "{m}"
    );
    assert_eq!(at, "[1.0, 0.0], ");
    let (m, _) = fails(
        &BILINEAR.replace("[(1.0, 0.0, 0.0), (1.0, 1.0, 1.0)]", "[(1.0, 0.0, 0.0)]"),
        DataType::Surface,
    );
    assert_eq!(
        m,
        "invalid surface: control point grid rows have different lengths"
    );
    let (m, at) = fails(
        &BILINEAR.replace("], knots_u", "], weights: [[1, 1]], knots_u"),
        DataType::Surface,
    );
    assert_eq!(
        m,
        "invalid surface: weights grid must be 2 by 2 like the control points"
    );
    assert_eq!(at, "[[1, 1]], kn");
    assert_eq!(
        fails(
            "(degree: 3, points: [[]], knots_u: [], knots_v: [])",
            DataType::Surface
        )
        .0,
        "expected the degrees (u, v) of the surface, found 3"
    );
}

#[test]
fn breps_from_boxes_and_surfaces() {
    let b = OrientedBox::new(
        Plane::WORLD_XY,
        Interval::UNIT,
        Interval::UNIT,
        Interval::UNIT,
    );
    let text = "(plane: XY, x: (0, 1), y: (0, 1), z: (0, 1))";
    let brep = Value::Brep(Shared::new(Brep::from_box(&b).unwrap()));
    assert_eq!(read(text, DataType::Brep), brep);
    assert_eq!(read(&format!("Box{text}"), DataType::Brep), brep);
    assert_eq!(
        read(BILINEAR, DataType::Brep),
        Value::Brep(Shared::new(Brep::from_surface(bilinear()).unwrap()))
    );
    assert_eq!(
        fails("(plane: XY, radius: 1)", DataType::Brep).0,
        "expected a box or a surface literal for a B-rep, found a struct"
    );
    let e = Literal::from_value(&brep).unwrap_err();
    assert_eq!(
        e.message,
        "B-reps have no literal form: write the box or surface it is made from"
    );
    // A tag that cannot be cast to the port's type.
    assert_eq!(
        fails("Circle(plane: XY, radius: 1)", DataType::Point).0,
        "invalid cast: Circle → Point"
    );
}

#[test]
fn tagged_breps_cast_to_surfaces_and_boxes_as_wires_do() {
    // A one-face B-rep on a Surface port is its face's surface.
    assert_eq!(
        read(&format!("Brep{BILINEAR}"), DataType::Surface),
        Value::Surface(Shared::new(bilinear()))
    );
    // A six-face one is an error naming the face count.
    let cube = "Brep(plane: XY, x: (0, 1), y: (0, 2), z: (0, 3))";
    assert_eq!(
        fails(cube, DataType::Surface).0,
        "invalid cast: Brep with 6 faces → Surface"
    );
    // On a Box port a B-rep or a surface becomes its world bounding box.
    let world = |x: (f64, f64), y: (f64, f64), z: (f64, f64)| {
        Value::Box(OrientedBox::new(
            Plane::WORLD_XY,
            Interval::new(x.0, x.1),
            Interval::new(y.0, y.1),
            Interval::new(z.0, z.1),
        ))
    };
    assert_eq!(
        read(cube, DataType::Box),
        world((0.0, 1.0), (0.0, 2.0), (0.0, 3.0))
    );
    assert_eq!(
        read(&format!("Surface{BILINEAR}"), DataType::Box),
        world((0.0, 1.0), (0.0, 1.0), (0.0, 1.0))
    );
}

#[test]
fn generic_trees_of_geometry_round_trip() {
    let c = Circle::new(Plane::WORLD_XY, 1.0).unwrap();
    let items = vec![
        Value::Line(Line::new(p(0.0, 0.0, 0.0), p(1.0, 0.0, 0.0))),
        Value::Circle(c),
        Value::Arc(Arc::new(c, Interval::UNIT).unwrap()),
        Value::Box(OrientedBox::new(
            Plane::WORLD_YZ,
            Interval::UNIT,
            Interval::UNIT,
            Interval::UNIT,
        )),
        curve(Line::new(p(0.0, 0.0, 0.0), p(0.0, 0.0, 2.0))),
        Value::Surface(Shared::new(bilinear())),
    ];
    let tree = DataTree::from_list(items);
    let text = Literal::from_tree(&tree).unwrap().0;
    assert_eq!(parse_literal(&text, DataType::Generic).unwrap(), tree);
}

#[test]
fn bad_geometry_values_in_graph_files_are_located_and_named() {
    let text = r#"(format: 1, nodes: [
  (id: "c", type: "params.curve", values: {"Crv": (degree: 3, points: [(0, 0, 0), (1, 1, 0), (2, 0, 0), (3, 1, 0)], knots: [0, 1])}),
  (id: "o", type: "params.circle", values: {"C": (plane: XY, radius: -1)}),
  (id: "s", type: "params.surface", values: {"Srf": (degree: (1, 1), points: [[(0, 0, 0)]], knots_u: [0, 1], knots_v: [0, 1])}),
])"#;
    let errors: Vec<String> = match check_text(text, &common::registry()) {
        Ok(_) => panic!("checking passed"),
        Err(d) => d
            .iter()
            .map(|d| d.display_in("g.ron").to_string())
            .collect(),
    };
    assert_eq!(
        errors,
        [
            "g.ron:2:124: error: bad value for input \"Crv\" of node \"c\": invalid curve: \
             invalid knot vector: 2 knots for 4 control points of degree 3, expected 6"
                .to_owned(),
            "g.ron:3:70: error: bad value for input \"C\" of node \"o\": invalid circle: circle \
             radius -1 is not positive"
                .to_owned(),
            "g.ron:4:78: error: bad value for input \"Srf\" of node \"s\": invalid surface: a \
             nurbs surface in u needs at least 2 points, got 1"
                .to_owned(),
        ]
    );
}

#[test]
fn graph_files_with_geometry_values_round_trip_byte_for_byte() {
    let text = r#"(
    format: 1,
    nodes: [
        (
            id: "b",
            type: "params.brep",
            values: {"B": Box(plane: XY, x: (0, 1), y: (0, 2), z: (0, 3))},
        ),
        (
            id: "l",
            type: "params.line",
            values: {"L": [((0, 0, 0), (1, 0, 0)), ((0, 0, 0), (0, 1, 0))]},
        ),
        (
            id: "c",
            type: "params.curve",
            values: {
                "Crv": (
                    degree: 3,
                    points: [(0, 0, 0), (1, 1, 0), (2, 0, 0), (3, 1, 0), (4, 0, 0), (5, 1, 0)],
                    weights: [1, 1, 2, 2, 1, 1],
                    knots: [0, 0, 0, 1, 2, 3, 3, 3],
                ),
            },
        ),
        (id: "a", type: "params.arc", values: {"A": (plane: XZ, radius: 2, angle: (0, 1))}),
    ],
)
"#;
    let doc = Document::parse(text).unwrap();
    assert_eq!(doc.graph().to_ron(), text);
    let checked = doc.check(&common::registry()).unwrap();
    assert!(checked.warnings.is_empty());
}

proptest::proptest! {
    /// Truncated and spliced geometry literals never panic: they read or give an error.
    #[test]
    fn broken_geometry_literals_never_panic(cut in 0usize..400, splice in 0usize..400, t in 0usize..16) {
        let samples = [
            BILINEAR,
            "(degree: 3, points: [(0, 0, 0), (1, 1, 0), (2, 0, 0), (3, 1, 0)], periodic: true)",
            "(arc: (plane: XY, radius: 2, angle: (0, 1)), domain: (0, 5))",
            "Box(plane: ((0, 0, 0), (1, 0, 0), (0, 1, 0)), x: (0, 1), y: (0, 1), z: (0, 1))",
            "[((0, 0, 0), (1, 0, 0)), (plane: XZ, radius: 1), (polyline: [(0, 0, 0), (1, 1, 1)])]",
        ];
        let types = DataType::ALL;
        let ty = types[t % types.len()];
        for s in samples {
            let a = &s[..cut.min(s.len())];
            let b = &s[splice.min(s.len())..];
            let _ = parse_literal(a, ty);
            let _ = parse_literal(&format!("{a}{b}"), ty);
            let _ = parse_literal(s, ty);
        }
    }
}

#[test]
fn huge_degrees_and_empty_lists_are_errors_not_panics() {
    let points = "[(0, 0, 0), (1, 1, 0), (2, 0, 0), (3, 1, 0)]";
    for degree in ["18446744073709551615", "4294967296", "0"] {
        for rest in ["", ", periodic: true", ", knots: [0, 0, 0, 1, 1, 1]"] {
            let text = format!("(degree: {degree}, points: {points}{rest})");
            assert!(parse_literal(&text, DataType::Curve).is_err(), "{text}");
        }
        let text = BILINEAR.replace("degree: (1, 1)", &format!("degree: ({degree}, 1)"));
        assert!(parse_literal(&text, DataType::Surface).is_err(), "{text}");
    }
    for text in [
        "(degree: 3, points: [])",
        "(degree: 3, points: [], knots: [])",
        "(degree: 2, points: [(0, 0, 0), (1, 0, 0)], periodic: true)",
        "(polyline: [])",
    ] {
        assert!(parse_literal(text, DataType::Curve).is_err(), "{text}");
    }
    assert!(
        parse_literal(
            "(degree: (1, 1), points: [], knots_u: [], knots_v: [])",
            DataType::Surface
        )
        .is_err()
    );
}

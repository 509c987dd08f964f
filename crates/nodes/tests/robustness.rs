//! Bad input never panics: every node type of the library, fed awkward trees on every input.
//!
//! Each input gets trees built from a pool of awkward items of its own type (NaN, infinities,
//! zero-length vectors, empty domains, singular transforms, degenerate boxes, circles of radius
//! zero, curves whose points coincide, empty B-reps, …) and of other types (so that casts are
//! exercised), in awkward shapes (no branch, an empty branch, a null, several branches). A call
//! passes when it returns: an error or warning on the node is the right answer to bad input; a
//! panic inside a solve function (which the runtime turns into an "internal error" message), a
//! panic in the runtime, or a call that does not finish within [`TIME_LIMIT`] fails the test,
//! naming the node and the inputs.
//!
//! Counts in the pools stay small (at most 1000) so that a correct node never builds huge
//! outputs; the limits on generated items are tested beside the nodes that have them.

use std::panic::{AssertUnwindSafe, catch_unwind};
use std::sync::Arc;
use std::sync::mpsc;
use std::time::Duration;

use locus_kernel::{
    Arc as ArcCurve, Brep, Circle, Color, Curve, Interval, Line, Mesh, MeshFace, MeshingParameters,
    NurbsCurve, OrientedBox, Plane, Point3, Polyline, Sphere, Transform, UvInterval, Vector3,
};
use locus_runtime::{
    Branch, DataTree, DataType, NodeCall, NodeRegistry, NodeType, Shared, TreePath, Value,
};

/// How long one call may take.
const TIME_LIMIT: Duration = Duration::from_secs(20);

/// How many random input combinations each node type gets, besides the systematic ones.
const RANDOM_CASES: usize = 24;

fn registry() -> NodeRegistry {
    let mut r = NodeRegistry::new();
    locus_nodes::register(&mut r);
    r
}

fn p(x: f64, y: f64, z: f64) -> Point3 {
    Point3::new(x, y, z)
}

fn v(x: f64, y: f64, z: f64) -> Vector3 {
    Vector3::new(x, y, z)
}

/// A plane whose fields are written directly, so that it may be degenerate.
fn raw_plane(origin: Point3) -> Plane {
    Plane {
        origin,
        ..Plane::WORLD_XY
    }
}

fn curve(c: impl Into<Curve>) -> Value {
    Value::Curve(Shared::new(c.into()))
}

/// Awkward items of one type. Every pool starts with an ordinary item.
fn pool(t: DataType) -> Vec<Value> {
    let nan = f64::NAN;
    let inf = f64::INFINITY;
    match t {
        DataType::Number => [
            1.0, 0.0, -0.0, -2.5, 0.5, nan, inf, -inf, 1e-300, 1e300, 3.0,
        ]
        .map(Value::Number)
        .to_vec(),
        DataType::Integer => [2, 0, 1, -1, -1000, 1000, 3, i64::MIN, i64::MAX]
            .map(Value::Integer)
            .to_vec(),
        DataType::Boolean => vec![Value::Boolean(true), Value::Boolean(false)],
        DataType::Text => ["x + y", "", "abc", "{0;1}", "1e400", "(", "{-1}", "0.5"]
            .map(|s| Value::Text(s.to_owned()))
            .to_vec(),
        DataType::Point => vec![
            Value::Point(p(1.0, 2.0, 3.0)),
            Value::Point(Point3::ORIGIN),
            Value::Point(p(nan, 0.0, 0.0)),
            Value::Point(p(inf, 1.0, 0.0)),
            Value::Point(p(1e300, -1e300, 0.0)),
        ],
        DataType::Vector => vec![
            Value::Vector(v(1.0, 0.0, 0.0)),
            Value::Vector(Vector3::ZERO),
            Value::Vector(v(nan, 1.0, 0.0)),
            Value::Vector(v(0.0, 0.0, -inf)),
            Value::Vector(v(1e-300, 0.0, 0.0)),
        ],
        DataType::Plane => vec![
            Value::Plane(Plane::WORLD_XY),
            Value::Plane(raw_plane(p(nan, 0.0, 0.0))),
            Value::Plane(Plane {
                x_axis: Vector3::ZERO,
                y_axis: Vector3::ZERO,
                z_axis: Vector3::ZERO,
                origin: Point3::ORIGIN,
            }),
        ],
        DataType::Domain => vec![
            Value::Domain(Interval::new(0.0, 1.0)),
            Value::Domain(Interval::new(0.0, 0.0)),
            Value::Domain(Interval::new(1.0, -1.0)),
            Value::Domain(Interval::new(nan, 1.0)),
            Value::Domain(Interval::new(-inf, inf)),
        ],
        DataType::Domain2 => vec![
            Value::Domain2(UvInterval::new(
                Interval::new(0.0, 0.5),
                Interval::new(0.2, 1.0),
            )),
            Value::Domain2(UvInterval::new(
                Interval::new(0.0, 0.0),
                Interval::new(0.0, 1.0),
            )),
            Value::Domain2(UvInterval::new(
                Interval::new(1.0, -1.0),
                Interval::new(3.0, 2.0),
            )),
            Value::Domain2(UvInterval::new(Interval::new(nan, 1.0), Interval::UNIT)),
            Value::Domain2(UvInterval::new(Interval::UNIT, Interval::new(-inf, inf))),
        ],
        DataType::Transform => vec![
            Value::Transform(Transform::IDENTITY),
            Value::Transform(Transform::from_rows([[0.0; 4]; 4])),
            Value::Transform(Transform::from_rows([[nan; 4]; 4])),
        ],
        DataType::Box => vec![
            Value::Box(OrientedBox::new(
                Plane::WORLD_XY,
                Interval::new(0.0, 1.0),
                Interval::new(0.0, 2.0),
                Interval::new(0.0, 3.0),
            )),
            Value::Box(OrientedBox::new(
                Plane::WORLD_XY,
                Interval::new(0.0, 0.0),
                Interval::new(0.0, 0.0),
                Interval::new(0.0, 0.0),
            )),
            Value::Box(OrientedBox::new(
                raw_plane(p(nan, 0.0, 0.0)),
                Interval::new(0.0, 1.0),
                Interval::new(nan, 1.0),
                Interval::new(0.0, 1.0),
            )),
        ],
        DataType::Line => vec![
            Value::Line(Line::new(Point3::ORIGIN, p(3.0, 4.0, 0.0))),
            Value::Line(Line::new(p(1.0, 1.0, 1.0), p(1.0, 1.0, 1.0))),
            Value::Line(Line::new(p(nan, 0.0, 0.0), p(1.0, 0.0, 0.0))),
        ],
        DataType::Circle => vec![
            Value::Circle(Circle {
                plane: Plane::WORLD_XY,
                radius: 2.0,
            }),
            Value::Circle(Circle {
                plane: Plane::WORLD_XY,
                radius: 0.0,
            }),
            Value::Circle(Circle {
                plane: Plane::WORLD_XY,
                radius: nan,
            }),
        ],
        DataType::Arc => vec![
            Value::Arc(ArcCurve {
                circle: Circle {
                    plane: Plane::WORLD_XY,
                    radius: 1.0,
                },
                angle: Interval::new(0.0, 1.0),
            }),
            Value::Arc(ArcCurve {
                circle: Circle {
                    plane: Plane::WORLD_XY,
                    radius: 1.0,
                },
                angle: Interval::new(0.0, 0.0),
            }),
        ],
        DataType::Curve => {
            let mut out = vec![
                curve(
                    NurbsCurve::create(
                        &[
                            p(0.0, 0.0, 0.0),
                            p(1.0, 2.0, 0.0),
                            p(3.0, 2.0, 1.0),
                            p(4.0, 0.0, 0.0),
                        ],
                        3,
                        false,
                    )
                    .expect("a cubic"),
                ),
                curve(Line::new(Point3::ORIGIN, p(0.0, 0.0, 5.0))),
                curve(Circle {
                    plane: Plane::WORLD_XY,
                    radius: 1.0,
                }),
            ];
            if let Ok(c) = NurbsCurve::create(&[p(1.0, 1.0, 1.0); 4], 3, false) {
                out.push(curve(c));
            }
            if let Ok(c) = Polyline::new(vec![p(0.0, 0.0, 0.0), p(0.0, 0.0, 0.0), p(1.0, 0.0, 0.0)])
            {
                out.push(curve(c));
            }
            out
        }
        DataType::Surface => {
            let sphere = Sphere::new(Point3::ORIGIN, 2.0).expect("a sphere");
            vec![Value::Surface(Shared::new(
                sphere.to_nurbs().expect("its NURBS form"),
            ))]
        }
        DataType::Brep => {
            let b = OrientedBox::new(
                Plane::WORLD_XY,
                Interval::new(0.0, 1.0),
                Interval::new(0.0, 1.0),
                Interval::new(0.0, 1.0),
            );
            vec![
                Value::Brep(Shared::new(Brep::from_box(&b).expect("a box brep"))),
                Value::Brep(Shared::new(Brep::default())),
                Value::Brep(Shared::new(
                    Brep::from_sphere(&Sphere::new(Point3::ORIGIN, 1.0).expect("a sphere"))
                        .expect("a sphere brep"),
                )),
            ]
        }
        DataType::Mesh => {
            let b = OrientedBox::new(
                Plane::WORLD_XY,
                Interval::new(0.0, 1.0),
                Interval::new(0.0, 1.0),
                Interval::new(0.0, 1.0),
            );
            let brep = Brep::from_box(&b).expect("a box brep");
            vec![
                Value::Mesh(Shared::new(
                    Mesh::from_brep(&brep, &MeshingParameters::default()).expect("a mesh"),
                )),
                Value::Mesh(Shared::new(Mesh::default())),
                // One triangle of zero area.
                Value::Mesh(Shared::new(
                    Mesh::new(
                        vec![Point3::ORIGIN, Point3::ORIGIN, p(1.0, 0.0, 0.0)],
                        vec![MeshFace::triangle(0, 1, 2)],
                    )
                    .expect("a degenerate mesh"),
                )),
            ]
        }
        DataType::Colour => vec![
            Value::Colour(Color::rgb(255, 0, 0)),
            Value::Colour(Color::rgba(0, 0, 0, 0)),
        ],
        DataType::Generic => [
            DataType::Number,
            DataType::Text,
            DataType::Point,
            DataType::Curve,
            DataType::Brep,
            DataType::Boolean,
        ]
        .into_iter()
        .flat_map(|t| pool(t).into_iter().take(2))
        .collect(),
    }
}

/// A small deterministic random source (xorshift), so that failures reproduce.
struct Rng(u64);

impl Rng {
    fn for_node(id: &str) -> Self {
        Self(
            id.bytes().fold(0x9E37_79B9_7F4A_7C15, |h, b| {
                (h ^ u64::from(b)).wrapping_mul(0x100_0000_01B3)
            }) | 1,
        )
    }

    fn next(&mut self) -> u64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        self.0
    }

    fn below(&mut self, n: usize) -> usize {
        (self.next() % n as u64) as usize
    }
}

fn branch_of(items: &[Option<Value>]) -> Branch {
    let mut b = Branch::new(DataType::Generic);
    for item in items {
        b.push_option(item.clone());
    }
    b
}

fn tree(branches: Vec<(TreePath, Vec<Option<Value>>)>) -> DataTree {
    let mut t = DataTree::new();
    for (path, items) in branches {
        t.insert(path, branch_of(&items));
    }
    t
}

/// A random input tree for a port of type `t`: mostly its own type, sometimes another one.
fn random_tree(rng: &mut Rng, t: DataType) -> DataTree {
    let own = pool(t);
    let other = pool(
        [
            DataType::Number,
            DataType::Text,
            DataType::Point,
            DataType::Curve,
            DataType::Integer,
            DataType::Domain,
        ][rng.below(6)],
    );
    let item = |rng: &mut Rng| -> Option<Value> {
        match rng.below(12) {
            0 => None,
            1 => Some(other[rng.below(other.len())].clone()),
            _ => Some(own[rng.below(own.len())].clone()),
        }
    };
    match rng.below(8) {
        0 => DataTree::new(),
        1 => tree(vec![(TreePath::new(vec![0]), vec![])]),
        2 => tree(vec![(TreePath::new(vec![0]), vec![None])]),
        3 | 4 => {
            let n = 1 + rng.below(4);
            tree(vec![(
                TreePath::new(vec![0]),
                (0..n).map(|_| item(rng)).collect(),
            )])
        }
        5 => tree(vec![
            (TreePath::new(vec![0, 0]), vec![item(rng), item(rng)]),
            (TreePath::new(vec![0, 2]), vec![]),
            (TreePath::new(vec![1]), vec![item(rng)]),
        ]),
        _ => tree(vec![(TreePath::new(vec![0]), vec![item(rng)])]),
    }
}

/// The types of the inputs a node has when a graph does not name its inputs.
fn input_types(t: &NodeType) -> Vec<DataType> {
    match &t.variable_inputs {
        Some(var) => var
            .default_names
            .iter()
            .map(|_| var.template.data_type)
            .collect(),
        None => t.inputs.iter().map(|p| p.data_type).collect(),
    }
}

/// Runs one call on its own thread; `Err` names what went wrong.
fn run(node_type: &Arc<NodeType>, inputs: Vec<Option<DataTree>>) -> Result<(), String> {
    let (send, receive) = mpsc::channel();
    let t = Arc::clone(node_type);
    std::thread::spawn(move || {
        let outcome = catch_unwind(AssertUnwindSafe(|| {
            let mut call = NodeCall::new(&t);
            for input in inputs {
                call = match input {
                    Some(tree) => call.input(tree),
                    None => call.skip_input(),
                };
            }
            call.run()
        }));
        // The receiver may have given up waiting.
        let _ = send.send(outcome.map_err(|_| ()));
    });
    match receive.recv_timeout(TIME_LIMIT) {
        Ok(Ok(result)) => match result
            .messages
            .iter()
            .find(|m| m.text.contains("internal error"))
        {
            Some(m) => Err(m.to_string()),
            None => Ok(()),
        },
        Ok(Err(())) => Err("the runtime panicked".to_owned()),
        Err(_) => Err(format!("did not finish within {TIME_LIMIT:?}")),
    }
}

fn describe(inputs: &[Option<DataTree>]) -> String {
    inputs
        .iter()
        .map(|i| match i {
            Some(t) => format!("{t:?}"),
            None => "unset".to_owned(),
        })
        .collect::<Vec<_>>()
        .join(" | ")
}

#[test]
fn no_node_panics_or_hangs_on_awkward_input() {
    let registry = registry();
    // Panics are expected to be caught and reported; keep their default output quiet.
    std::panic::set_hook(Box::new(|_| {}));
    let mut failures = Vec::new();
    for node_type in registry.iter() {
        let node_type = Arc::new(node_type.clone());
        let types = input_types(&node_type);
        let mut cases: Vec<Vec<Option<DataTree>>> = Vec::new();
        // Every input unset; every input an empty tree; every input one null.
        cases.push(types.iter().map(|_| None).collect());
        cases.push(types.iter().map(|_| Some(DataTree::new())).collect());
        cases.push(
            types
                .iter()
                .map(|_| Some(tree(vec![(TreePath::new(vec![0]), vec![None])])))
                .collect(),
        );
        // Each awkward item of each input's own type, the other inputs at their defaults.
        for (i, t) in types.iter().enumerate() {
            for item in pool(*t) {
                let mut case: Vec<Option<DataTree>> = types.iter().map(|_| None).collect();
                case[i] = Some(DataTree::from_value(item));
                cases.push(case);
            }
        }
        let mut rng = Rng::for_node(&node_type.id);
        for _ in 0..RANDOM_CASES {
            cases.push(
                types
                    .iter()
                    .map(|t| Some(random_tree(&mut rng, *t)))
                    .collect(),
            );
        }
        for case in cases {
            if let Err(why) = run(&node_type, case.clone()) {
                failures.push(format!(
                    "{}: {why}\n    inputs: {}",
                    node_type.id,
                    describe(&case)
                ));
                break;
            }
        }
    }
    let _ = std::panic::take_hook();
    assert!(
        failures.is_empty(),
        "{} node types failed on awkward input:\n{}",
        failures.len(),
        failures.join("\n")
    );
}

//! Literal forms of the geometry value types: boxes, lines, circles, arcs, curves, surfaces,
//! and B-reps given as a box or a surface.
//!
//! The forms are RON structs whose field names say what each part is (see
//! `docs/graph-format.md`, "Literal values"):
//!
//! | type | literal |
//! | --- | --- |
//! | Line | `((x, y, z), (x, y, z))`: start, end |
//! | Box | `(plane: XY, x: (0, 1), y: (0, 1), z: (0, 1))` |
//! | Circle | `(plane: XY, radius: 2)` |
//! | Arc | `(plane: XY, radius: 2, angle: (0, 1.5707963267948966))` (radians) |
//! | Curve | `(degree: 3, points: [...], weights: [...], knots: [...])`, `(degree: 3, points: [...], periodic: true)`, or `(line: …)`, `(polyline: [...])`, `(circle: …)`, `(arc: …)` with an optional `domain: (t0, t1)` |
//! | Surface | `(degree: (3, 3), points: [[...], ...], weights: [[...], ...], knots_u: [...], knots_v: [...])` |
//! | Brep | a Box or Surface literal, made into a B-rep |
//!
//! Every form is read through the kernel's validating constructors, so a knot vector of the
//! wrong length or a zero radius is reported with the kernel's reason, at the field at fault.

use locus_kernel::{
    Arc, Brep, Circle, Curve, Error as KernelError, Interval, Line, NurbsCurve, NurbsSurface,
    OrientedBox, Point3, Polyline,
};

use crate::file::literal::{
    error, mismatch, number, number_node, numbers, numbers_node, plane, plane_node,
};
use crate::file::syntax::{Field, Kind, Node};
use crate::{DataType, LiteralError, Shared, Value};

/// The fields of a struct literal, looked up by name; every field must be used.
struct Fields<'a> {
    node: &'a Node,
    what: &'static str,
    fields: &'a [Field],
    allowed: &'static [&'static str],
}

impl<'a> Fields<'a> {
    /// The fields of `node`, which must be an untagged struct with only `allowed` fields, each
    /// at most once.
    fn of(
        node: &'a Node,
        data_type: DataType,
        what: &'static str,
        allowed: &'static [&'static str],
    ) -> Result<Self, LiteralError> {
        let Kind::Struct(None, fields) = &node.kind else {
            return mismatch(node, data_type);
        };
        for (i, f) in fields.iter().enumerate() {
            if !allowed.contains(&f.name.as_str()) {
                return Err(LiteralError {
                    message: format!(
                        "unknown field `{}` of {what} (its fields are: {})",
                        f.name,
                        allowed.join(", ")
                    ),
                    span: f.name_span.clone(),
                });
            }
            if fields[..i].iter().any(|g| g.name == f.name) {
                return Err(LiteralError {
                    message: format!("field `{}` of {what} is given twice", f.name),
                    span: f.name_span.clone(),
                });
            }
        }
        Ok(Self {
            node,
            what,
            fields,
            allowed,
        })
    }

    fn get(&self, name: &str) -> Option<&'a Node> {
        debug_assert!(self.allowed.contains(&name));
        self.fields
            .iter()
            .find(|f| f.name == name)
            .map(|f| &f.value)
    }

    fn need(&self, name: &str) -> Result<&'a Node, LiteralError> {
        self.get(name).map_or_else(
            || error(self.node, format!("{} needs the field `{name}`", self.what)),
            Ok,
        )
    }
}

/// A kernel error as a literal error at `node`.
fn invalid<T>(node: &Node, what: &str, e: &KernelError) -> Result<T, LiteralError> {
    error(node, format!("invalid {what}: {e}"))
}

fn list<'a>(node: &'a Node, what: &str) -> Result<&'a [Node], LiteralError> {
    match &node.kind {
        Kind::List(items) => Ok(items),
        _ => error(
            node,
            format!("expected a list of {what}, found {}", node.describe()),
        ),
    }
}

fn point(node: &Node, data_type: DataType) -> Result<Point3, LiteralError> {
    if !matches!(&node.kind, Kind::Tuple(None, v) if v.len() == 3) {
        return error(
            node,
            format!("expected a point (x, y, z), found {}", node.describe()),
        );
    }
    let [x, y, z] = numbers::<3>(node, data_type)?;
    Ok(Point3::new(x, y, z))
}

fn points(node: &Node, data_type: DataType) -> Result<Vec<Point3>, LiteralError> {
    list(node, "points (x, y, z)")?
        .iter()
        .map(|p| point(p, data_type))
        .collect()
}

fn reals(node: &Node, what: &str, data_type: DataType) -> Result<Vec<f64>, LiteralError> {
    list(node, what)?
        .iter()
        .map(|x| number(x, data_type))
        .collect()
}

fn count(node: &Node, what: &str) -> Result<usize, LiteralError> {
    match &node.kind {
        Kind::Number(n) => n.replace('_', "").parse::<usize>().or_else(|_| {
            error(
                node,
                format!("expected a whole {what} of at least 0, found {n}"),
            )
        }),
        _ => error(
            node,
            format!("expected a whole {what}, found {}", node.describe()),
        ),
    }
}

fn domain(node: &Node, data_type: DataType) -> Result<Interval, LiteralError> {
    let [t0, t1] = numbers::<2>(node, data_type)?;
    Ok(Interval::new(t0, t1))
}

/// Reads a line `((x, y, z), (x, y, z))`.
pub(crate) fn line(node: &Node) -> Result<Line, LiteralError> {
    match &node.kind {
        Kind::Tuple(None, items) if items.len() == 2 => Ok(Line::new(
            point(&items[0], DataType::Line)?,
            point(&items[1], DataType::Line)?,
        )),
        _ => mismatch(node, DataType::Line),
    }
}

/// Reads a box `(plane: P, x: (a, b), y: (a, b), z: (a, b))`.
pub(crate) fn oriented_box(node: &Node) -> Result<OrientedBox, LiteralError> {
    let t = DataType::Box;
    let f = Fields::of(node, t, "a box", &["plane", "x", "y", "z"])?;
    Ok(OrientedBox::new(
        plane(f.need("plane")?)?,
        domain(f.need("x")?, t)?,
        domain(f.need("y")?, t)?,
        domain(f.need("z")?, t)?,
    ))
}

/// Reads a circle `(plane: P, radius: r)`.
pub(crate) fn circle(node: &Node) -> Result<Circle, LiteralError> {
    let f = Fields::of(node, DataType::Circle, "a circle", &["plane", "radius"])?;
    let radius = f.need("radius")?;
    Circle::new(plane(f.need("plane")?)?, number(radius, DataType::Circle)?)
        .or_else(|e| invalid(radius, "circle", &e))
}

/// Reads an arc `(plane: P, radius: r, angle: (a0, a1))`.
pub(crate) fn arc(node: &Node) -> Result<Arc, LiteralError> {
    let t = DataType::Arc;
    let f = Fields::of(node, t, "an arc", &["plane", "radius", "angle"])?;
    let (radius, angle) = (f.need("radius")?, f.need("angle")?);
    let circle = Circle::new(plane(f.need("plane")?)?, number(radius, t)?)
        .or_else(|e| invalid(radius, "arc", &e))?;
    Arc::new(circle, domain(angle, t)?).or_else(|e| invalid(angle, "arc", &e))
}

const CURVE_FIELDS: &[&str] = &[
    "degree", "points", "weights", "knots", "periodic", "line", "polyline", "circle", "arc",
    "domain",
];

/// Reads a curve: a NURBS form, or a line, polyline, circle or arc with an optional domain.
pub(crate) fn curve(node: &Node) -> Result<Curve, LiteralError> {
    let t = DataType::Curve;
    let f = Fields::of(node, t, "a curve", CURVE_FIELDS)?;
    let shapes = ["degree", "line", "polyline", "circle", "arc"];
    let given: Vec<&str> = shapes
        .iter()
        .copied()
        .filter(|s| f.get(s).is_some())
        .collect();
    let [shape] = given.as_slice() else {
        return error(
            node,
            format!(
                "a curve needs exactly one of the fields degree (a NURBS curve), line, polyline, \
                 circle or arc{}",
                if given.is_empty() {
                    String::new()
                } else {
                    format!(", found {}", given.join(", "))
                }
            ),
        );
    };
    let only = |allowed: &[&str]| -> Result<(), LiteralError> {
        for field in f.fields {
            if !allowed.contains(&field.name.as_str()) {
                return Err(LiteralError {
                    message: format!(
                        "a curve given by `{shape}` takes no field `{}` (only {})",
                        field.name,
                        allowed.join(", ")
                    ),
                    span: field.name_span.clone(),
                });
            }
        }
        Ok(())
    };
    let simple = match *shape {
        "degree" => {
            only(&["degree", "points", "weights", "knots", "periodic"])?;
            return nurbs_curve(&f).map(Curve::Nurbs);
        }
        "line" => {
            only(&["line", "domain"])?;
            Curve::from(line(f.need("line")?)?)
        }
        "polyline" => {
            only(&["polyline", "domain"])?;
            let at = f.need("polyline")?;
            Curve::from(Polyline::new(points(at, t)?).or_else(|e| invalid(at, "polyline", &e))?)
        }
        "circle" => {
            only(&["circle", "domain"])?;
            Curve::from(circle(f.need("circle")?)?)
        }
        _ => {
            only(&["arc", "domain"])?;
            Curve::from(arc(f.need("arc")?)?)
        }
    };
    match f.get("domain") {
        None => Ok(simple),
        Some(at) => simple
            .reparameterized(domain(at, t)?)
            .or_else(|e| invalid(at, "curve domain", &e)),
    }
}

fn nurbs_curve(f: &Fields<'_>) -> Result<NurbsCurve, LiteralError> {
    let t = DataType::Curve;
    let degree_at = f.need("degree")?;
    let degree = count(degree_at, "degree")?;
    let points_at = f.need("points")?;
    let pts = points(points_at, t)?;
    let periodic = match f.get("periodic") {
        None => None,
        Some(n) => match n.kind {
            Kind::Bool(b) => Some((b, n)),
            _ => return error(n, format!("expected true or false, found {}", n.describe())),
        },
    };
    let Some(knots_at) = f.get("knots") else {
        if let Some(w) = f.get("weights") {
            return error(
                w,
                "weights need knots: give the knots too, or leave the weights out for uniform \
                 knots"
                    .to_owned(),
            );
        }
        let periodic = periodic.is_some_and(|(b, _)| b);
        return NurbsCurve::create(&pts, degree, periodic)
            .or_else(|e| invalid(f.node, "curve", &e));
    };
    if let Some((_, n)) = periodic {
        return error(
            n,
            "periodic is for curves given without knots (uniform knots); with knots, a curve is \
             periodic when its knots and points say so"
                .to_owned(),
        );
    }
    let knots = reals(knots_at, "knots", t)?;
    let weights_at = f.get("weights");
    let weights = match weights_at {
        Some(w) => reals(w, "weights", t)?,
        None => vec![1.0; pts.len()],
    };
    if weights.len() != pts.len() {
        let at = weights_at.unwrap_or(points_at);
        return error(
            at,
            format!(
                "invalid curve: {} weights for {} control points",
                weights.len(),
                pts.len()
            ),
        );
    }
    NurbsCurve::new(degree, pts, weights, knots).or_else(|e| {
        let at = match e {
            KernelError::InvalidKnots { .. } => knots_at,
            KernelError::InvalidWeight { .. } => weights_at.unwrap_or(points_at),
            KernelError::InvalidDegree { .. } => degree_at,
            _ => points_at,
        };
        invalid(at, "curve", &e)
    })
}

/// Reads a surface `(degree: (du, dv), points: [[...]], weights: [[...]], knots_u, knots_v)`.
pub(crate) fn surface(node: &Node) -> Result<NurbsSurface, LiteralError> {
    let t = DataType::Surface;
    let f = Fields::of(
        node,
        t,
        "a surface",
        &["degree", "points", "weights", "knots_u", "knots_v"],
    )?;
    let degree_at = f.need("degree")?;
    let [du, dv] = match &degree_at.kind {
        Kind::Tuple(None, items) if items.len() == 2 => {
            [count(&items[0], "degree")?, count(&items[1], "degree")?]
        }
        _ => {
            return error(
                degree_at,
                format!(
                    "expected the degrees (u, v) of the surface, found {}",
                    degree_at.describe()
                ),
            );
        }
    };
    let points_at = f.need("points")?;
    let grid: Vec<Vec<Point3>> = list(points_at, "rows of control points")?
        .iter()
        .map(|row| points(row, t))
        .collect::<Result<_, _>>()?;
    let weights_at = f.get("weights");
    let weights: Vec<Vec<f64>> = match weights_at {
        Some(w) => list(w, "rows of weights")?
            .iter()
            .map(|row| reals(row, "weights", t))
            .collect::<Result<_, _>>()?,
        None => grid.iter().map(|row| vec![1.0; row.len()]).collect(),
    };
    let (ku_at, kv_at) = (f.need("knots_u")?, f.need("knots_v")?);
    let knots_u = reals(ku_at, "knots", t)?;
    let knots_v = reals(kv_at, "knots", t)?;
    NurbsSurface::new(du, dv, grid, weights, knots_u, knots_v).or_else(|e| {
        let at = match &e {
            KernelError::InvalidKnots { reason }
                if reason.starts_with("v ") || reason.starts_with("the v ") =>
            {
                kv_at
            }
            KernelError::InvalidKnots { .. } => ku_at,
            KernelError::InvalidWeight { .. } => weights_at.unwrap_or(points_at),
            KernelError::InvalidInput(text) if text.contains("weights") => {
                weights_at.unwrap_or(points_at)
            }
            KernelError::InvalidDegree { .. } => degree_at,
            _ => points_at,
        };
        invalid(at, "surface", &e)
    })
}

/// Reads a B-rep: a box or a surface literal, made into a B-rep.
pub(crate) fn brep(node: &Node) -> Result<Brep, LiteralError> {
    match struct_type(node) {
        Some(DataType::Box) => {
            Brep::from_box(&oriented_box(node)?).or_else(|e| invalid(node, "B-rep", &e))
        }
        Some(DataType::Surface) => {
            Brep::from_surface(surface(node)?).or_else(|e| invalid(node, "B-rep", &e))
        }
        _ => mismatch(node, DataType::Brep),
    }
}

/// The geometry type of an untagged struct literal, told by its field names.
pub(crate) fn struct_type(node: &Node) -> Option<DataType> {
    let Kind::Struct(None, fields) = &node.kind else {
        return None;
    };
    let has = |name: &str| fields.iter().any(|f| f.name == name);
    let degree_pair = fields.iter().any(|f| {
        f.name == "degree" && matches!(&f.value.kind, Kind::Tuple(None, v) if v.len() == 2)
    });
    Some(if has("knots_u") || has("knots_v") || degree_pair {
        DataType::Surface
    } else if ["degree", "line", "polyline", "circle", "arc"]
        .iter()
        .any(|f| has(f))
    {
        DataType::Curve
    } else if has("angle") {
        DataType::Arc
    } else if has("radius") {
        DataType::Circle
    } else if has("x") || has("y") || has("z") {
        DataType::Box
    } else {
        return None;
    })
}

/// Reads a geometry item of `data_type`, or `None` if the type is not a geometry form here.
pub(crate) fn parse_geometry(
    node: &Node,
    data_type: DataType,
) -> Option<Result<Value, LiteralError>> {
    Some(match data_type {
        DataType::Line => line(node).map(Value::Line),
        DataType::Box => oriented_box(node).map(Value::Box),
        DataType::Circle => circle(node).map(Value::Circle),
        DataType::Arc => arc(node).map(Value::Arc),
        DataType::Curve => curve(node).map(|c| Value::Curve(Shared::new(c))),
        DataType::Surface => surface(node).map(|s| Value::Surface(Shared::new(s))),
        DataType::Brep => brep(node).map(|b| Value::Brep(Shared::new(b))),
        _ => return None,
    })
}

fn field(name: &str, value: Node) -> Field {
    Field {
        name: name.to_owned(),
        name_span: 0..0,
        value,
    }
}

fn fields_node(fields: Vec<Field>) -> Node {
    Node::new(Kind::Struct(None, fields))
}

fn point_node(p: Point3) -> Node {
    numbers_node(p.to_array())
}

fn points_node(points: &[Point3]) -> Node {
    Node::new(Kind::List(points.iter().map(|&p| point_node(p)).collect()))
}

fn reals_node(values: &[f64]) -> Node {
    Node::new(Kind::List(values.iter().map(|&x| number_node(x)).collect()))
}

fn line_node(l: &Line) -> Node {
    Node::new(Kind::Tuple(
        None,
        vec![point_node(l.from), point_node(l.to)],
    ))
}

fn circle_node(c: &Circle) -> Node {
    fields_node(vec![
        field("plane", plane_node(&c.plane)),
        field("radius", number_node(c.radius)),
    ])
}

fn arc_node(a: &Arc) -> Node {
    fields_node(vec![
        field("plane", plane_node(&a.circle.plane)),
        field("radius", number_node(a.circle.radius)),
        field("angle", numbers_node([a.angle.t0, a.angle.t1])),
    ])
}

fn curve_node(c: &Curve) -> Node {
    let (name, shape, default) = match c {
        Curve::Nurbs(n) => {
            let mut fields = vec![
                field("degree", Node::new(Kind::Number(n.degree().to_string()))),
                field("points", points_node(n.points())),
            ];
            if n.is_rational() {
                fields.push(field("weights", reals_node(n.weights())));
            }
            fields.push(field("knots", reals_node(n.knots())));
            return fields_node(fields);
        }
        Curve::Line { line, .. } => ("line", line_node(line), Curve::from(*line).domain()),
        Curve::Polyline { polyline, .. } => (
            "polyline",
            points_node(polyline.points()),
            Curve::from(polyline.clone()).domain(),
        ),
        Curve::Circle { circle, .. } => {
            ("circle", circle_node(circle), Curve::from(*circle).domain())
        }
        Curve::Arc { arc, .. } => ("arc", arc_node(arc), Curve::from(*arc).domain()),
    };
    let mut fields = vec![field(name, shape)];
    let d = c.domain();
    if d != default {
        fields.push(field("domain", numbers_node([d.t0, d.t1])));
    }
    fields_node(fields)
}

fn surface_node(s: &NurbsSurface) -> Node {
    let (nu, nv) = (s.count_u(), s.count_v());
    let rows = |n: usize| (0..n).map(move |i| i * nv..(i + 1) * nv);
    let degree = Node::new(Kind::Tuple(
        None,
        [s.degree_u(), s.degree_v()]
            .map(|d| Node::new(Kind::Number(d.to_string())))
            .to_vec(),
    ));
    let mut fields = vec![
        field("degree", degree),
        field(
            "points",
            Node::new(Kind::List(
                rows(nu).map(|r| points_node(&s.points()[r])).collect(),
            )),
        ),
    ];
    if s.weights().iter().any(|&w| w != 1.0) {
        fields.push(field(
            "weights",
            Node::new(Kind::List(
                rows(nu).map(|r| reals_node(&s.weights()[r])).collect(),
            )),
        ));
    }
    fields.push(field("knots_u", reals_node(s.knots_u())));
    fields.push(field("knots_v", reals_node(s.knots_v())));
    fields_node(fields)
}

/// The literal syntax of a geometry item, or `None` for a type that is not written here.
pub(crate) fn geometry_node(value: &Value) -> Option<Result<Node, LiteralError>> {
    Some(Ok(match value {
        Value::Line(l) => line_node(l),
        Value::Box(b) => fields_node(vec![
            field("plane", plane_node(&b.plane)),
            field("x", numbers_node([b.x.t0, b.x.t1])),
            field("y", numbers_node([b.y.t0, b.y.t1])),
            field("z", numbers_node([b.z.t0, b.z.t1])),
        ]),
        Value::Circle(c) => circle_node(c),
        Value::Arc(a) => arc_node(a),
        Value::Curve(c) => curve_node(c),
        Value::Surface(s) => surface_node(s),
        Value::Brep(_) => {
            return Some(Err(LiteralError {
                message: "B-reps have no literal form: write the box or surface it is made from"
                    .to_owned(),
                span: 0..0,
            }));
        }
        _ => return None,
    }))
}

//! Literal values: data trees written as RON in graph files, on the command line (`--set`)
//! and as expected outputs.
//!
//! A literal is read against the type of the port it is given to. Its shape says how the tree
//! is built:
//!
//! - one item, such as `0.5`, is a tree with that item on branch `{0}`;
//! - a list `[a, b, c]` is one branch `{0}` (an empty list `[]` is one empty branch);
//! - a map from paths to lists, `{"{0;1}": [a, b], "{0;2}": []}`, is a whole tree (`{}` has
//!   no branches);
//! - `null` is a null item.
//!
//! Items are written per type:
//!
//! | type | literal |
//! | --- | --- |
//! | Number | `0.5`, `-3`, `1e-7`, `inf`, `NaN` |
//! | Integer | `3`, `-12` (no decimal point) |
//! | Boolean | `true`, `false` |
//! | Text | `"abc"` with RON escapes (`\"`, `\\`, `\n`, `\u{e9}`) |
//! | Point, Vector | `(1, 2, 3)` |
//! | Domain | `(0, 1)`, start then end |
//! | Domain2 | `((u0, u1), (v0, v1))`: the u domain, then the v domain |
//! | Plane | `((ox, oy, oz), (xx, xy, xz), (yx, yy, yz))`: origin, x axis, y axis; or `XY`, `YZ`, `XZ`, `ZX` |
//! | Transform | `((a, b, c, d), (e, f, g, h), (i, j, k, l), (m, n, o, p))`: four rows |
//! | Line, Box, Circle, Arc, Curve, Surface, Brep | see `literal_geometry.rs` |
//!
//! Any item may carry a type's name as a tag, `Vector(1, 2, 3)`, `Integer(3)`, `Text("a")`,
//! `Box(plane: XY, …)`. A tag of another type than the port's reads the item as that type and
//! casts it to the port's type as a wire would (`Box(…)` on a Brep port). On a `Generic` port
//! the type is taken from the tag, or else from the shape: an integer without decimal point is
//! an Integer, other numbers are Numbers, `(x, y, z)` is a Point, `(a, b)` a Domain, two pairs a
//! Domain2, two triples a Line, three triples a Plane, four quadruples a Transform, and a struct by its field names.
//! The writer tags vectors in generic trees so that they read back as vectors.
//!
//! The axes of a plane are taken as written when they are orthonormal to within
//! [`UNIT_AXIS_TOLERANCE`] (so that written planes read back exactly); otherwise the y axis is
//! made perpendicular to the x axis and both are normalized (Gram–Schmidt).
//!
//! New value types add their literal form in [`parse_item`] and [`item_node`] (geometry in
//! `literal_geometry`), typically as a struct with named fields.

use std::fmt;
use std::ops::Range;

use locus_kernel::{Interval, Plane, Point3, Transform, UvInterval, Vector3};

use crate::file::syntax::{self, Kind, Node};
use crate::{Branch, DataTree, DataType, Literal, TreePath, Value};

/// How far from unit length and from perpendicular the written axes of a plane may be for the
/// plane to be taken exactly as written (1e-12, a few thousand ulps of 1).
pub const UNIT_AXIS_TOLERANCE: f64 = 1e-12;

/// Grasshopper's world XZ plane (the XZ Plane component, Rhino's Front view): x axis X, y axis
/// Z, normal X × Z = −Y. Rhino's `WorldZX` (x axis Z, y axis X, normal Y) is written `ZX`.
const WORLD_XZ: Plane = Plane {
    origin: Point3::ORIGIN,
    x_axis: Vector3::X,
    y_axis: Vector3::Z,
    z_axis: Vector3::new(0.0, -1.0, 0.0),
};

/// Why a literal could not be read or written.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct LiteralError {
    /// What was expected and found, such as `expected a point (x, y, z), found "abc"`.
    pub message: String,
    /// The byte range of the fault in the literal text.
    pub span: Range<usize>,
}

impl fmt::Display for LiteralError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.message)
    }
}

impl std::error::Error for LiteralError {}

impl Literal {
    /// Reads the literal as a data tree of type `data_type`.
    ///
    /// # Errors
    /// A [`LiteralError`] naming what was expected when the text is not valid RON or does not
    /// describe a tree of that type.
    pub fn parse(&self, data_type: DataType) -> Result<DataTree, LiteralError> {
        parse_literal(&self.0, data_type)
    }

    /// Reads the literal as one item of type `data_type` (for node settings).
    ///
    /// # Errors
    /// A [`LiteralError`] when the text is not one item of that type.
    pub fn parse_value(&self, data_type: DataType) -> Result<Value, LiteralError> {
        let node = parse_syntax(&self.0)?;
        value_from_node(&node, data_type)
    }

    /// The canonical literal of a data tree.
    ///
    /// # Errors
    /// A [`LiteralError`] when the tree holds a value type that has no literal form yet.
    pub fn from_tree(tree: &DataTree) -> Result<Self, LiteralError> {
        Ok(Self(tree_node(tree)?.to_compact()))
    }

    /// The canonical literal of one value.
    ///
    /// # Errors
    /// A [`LiteralError`] when the value's type has no literal form yet.
    pub fn from_value(value: &Value) -> Result<Self, LiteralError> {
        Ok(Self(item_node(value, false)?.to_compact()))
    }

    /// The same literal in canonical layout (`(1,2,3)` becomes `(1, 2, 3)`).
    ///
    /// # Errors
    /// A [`LiteralError`] when the text is not valid RON.
    pub fn canonical(text: &str) -> Result<Self, LiteralError> {
        Ok(Self(parse_syntax(text)?.to_compact()))
    }
}

impl fmt::Display for Literal {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

/// Reads `text` as a data tree of type `data_type`.
///
/// # Errors
/// See [`Literal::parse`].
pub fn parse_literal(text: &str, data_type: DataType) -> Result<DataTree, LiteralError> {
    let node = parse_syntax(text)?;
    tree_from_node(&node, data_type)
}

fn parse_syntax(text: &str) -> Result<Node, LiteralError> {
    syntax::parse(text).map_err(|e| LiteralError {
        message: e.message,
        span: e.offset..e.offset,
    })
}

pub(crate) fn error<T>(node: &Node, message: String) -> Result<T, LiteralError> {
    Err(LiteralError {
        message,
        span: node.span.clone(),
    })
}

pub(crate) fn mismatch<T>(node: &Node, data_type: DataType) -> Result<T, LiteralError> {
    error(
        node,
        format!(
            "expected {}, found {}",
            expectation(data_type),
            node.describe()
        ),
    )
}

/// What a literal of a type looks like, for messages.
fn expectation(data_type: DataType) -> &'static str {
    match data_type {
        DataType::Number => "a number",
        DataType::Integer => "an integer",
        DataType::Boolean => "a boolean (true or false)",
        DataType::Text => "a text in quotes",
        DataType::Point => "a point (x, y, z)",
        DataType::Vector => "a vector (x, y, z)",
        DataType::Plane => "a plane ((origin), (x axis), (y axis)) or XY, YZ, XZ, ZX",
        DataType::Domain => "a domain (start, end)",
        DataType::Domain2 => "a two-dimensional domain ((u0, u1), (v0, v1))",
        DataType::Transform => "a transform of four rows ((a, b, c, d), …)",
        DataType::Box => "a box (plane: …, x: (x0, x1), y: (y0, y1), z: (z0, z1))",
        DataType::Line => "a line ((start), (end))",
        DataType::Circle => "a circle (plane: …, radius: r)",
        DataType::Arc => "an arc (plane: …, radius: r, angle: (a0, a1))",
        DataType::Curve => {
            "a curve (degree: d, points: […], knots: […]) or (line: …), (polyline: […]), \
             (circle: …), (arc: …)"
        }
        DataType::Surface => {
            "a surface (degree: (du, dv), points: [[…], …], knots_u: […], knots_v: […])"
        }
        DataType::Brep => "a box or a surface literal for a B-rep",
        DataType::Mesh => "a mesh (vertices: [(x, y, z), …], faces: [(a, b, c), …])",
        DataType::Colour => "a colour (r: 255, g: 0, b: 0), (r, g, b) or \"#RRGGBB\"",
        DataType::Generic => "a value",
    }
}

/// Builds a data tree from a parsed literal.
pub(crate) fn tree_from_node(node: &Node, data_type: DataType) -> Result<DataTree, LiteralError> {
    match &node.kind {
        Kind::Map(entries) => {
            let mut tree = DataTree::new();
            for (key, value) in entries {
                let Kind::Str(path_text) = &key.kind else {
                    return error(
                        key,
                        format!(
                            "expected a tree path in quotes such as \"{{0;1}}\", found {}",
                            key.describe()
                        ),
                    );
                };
                let path: TreePath = match path_text.parse() {
                    Ok(p) => p,
                    Err(e) => return error(key, e.to_string()),
                };
                if tree.contains_path(&path) {
                    return error(key, format!("duplicate path {path}"));
                }
                let Kind::List(items) = &value.kind else {
                    return error(
                        value,
                        format!(
                            "expected the list of items of branch {path}, found {}",
                            value.describe()
                        ),
                    );
                };
                tree.insert(path, branch_from_items(items, data_type)?);
            }
            Ok(tree)
        }
        Kind::List(items) => {
            let mut tree = DataTree::new();
            tree.insert(TreePath::zero(), branch_from_items(items, data_type)?);
            Ok(tree)
        }
        _ => {
            let mut tree = DataTree::new();
            tree.insert(
                TreePath::zero(),
                branch_from_items(std::slice::from_ref(node), data_type)?,
            );
            Ok(tree)
        }
    }
}

fn branch_from_items(items: &[Node], data_type: DataType) -> Result<Branch, LiteralError> {
    let mut branch = Branch::new(data_type);
    for item in items {
        branch.push_option(parse_item(item, data_type)?);
    }
    Ok(branch)
}

/// Reads one item that must not be null, for settings.
pub(crate) fn value_from_node(node: &Node, data_type: DataType) -> Result<Value, LiteralError> {
    match parse_item(node, data_type)? {
        Some(v) => Ok(v),
        None => mismatch(node, data_type),
    }
}

/// Reads one item of `data_type`: `None` for `null`.
pub(crate) fn parse_item(node: &Node, data_type: DataType) -> Result<Option<Value>, LiteralError> {
    if matches!(&node.kind, Kind::Ident(i) if i == "null") {
        return Ok(None);
    }
    // A tagged item, such as `Vector(1, 2, 3)`: the tag must name the port's type (or give the
    // type of a generic item).
    // A tag of another type reads the item as that type and casts it to the port's type, as
    // a wire would: `Box(…)` on a B-rep port, `Circle(…)` on a curve port.
    let tag = match &node.kind {
        Kind::Tuple(Some(tag), _) | Kind::Struct(Some(tag), _) => Some(tag),
        _ => None,
    };
    if let Some(tag) = tag {
        let Some(t) = DataType::from_name(tag).filter(|t| *t != DataType::Generic) else {
            return error(node, format!("unknown value type `{tag}`"));
        };
        let value = match &node.kind {
            // `Number(1)`, `Text("a")`, `Plane(XY)`: the tag wraps the item itself.
            Kind::Tuple(_, items)
                if items.len() == 1
                    && (!matches!(items[0].kind, Kind::Number(_))
                        || matches!(t, DataType::Number | DataType::Integer)) =>
            {
                parse_item(&items[0], t)?
            }
            Kind::Tuple(_, items) => parse_item(
                &Node {
                    kind: Kind::Tuple(None, items.clone()),
                    span: node.span.clone(),
                },
                t,
            )?,
            Kind::Struct(_, fields) => parse_item(
                &Node {
                    kind: Kind::Struct(None, fields.clone()),
                    span: node.span.clone(),
                },
                t,
            )?,
            _ => None,
        };
        return match value {
            Some(v) if t != data_type && data_type != DataType::Generic => {
                match crate::cast_value(&v, data_type) {
                    Ok(cast) => Ok(Some(cast)),
                    Err(e) => error(node, e.to_string()),
                }
            }
            v => Ok(v),
        };
    }
    let value = match data_type {
        DataType::Number => Value::Number(number(node, data_type)?),
        DataType::Integer => Value::Integer(integer(node)?),
        DataType::Boolean => match node.kind {
            Kind::Bool(b) => Value::Boolean(b),
            _ => return mismatch(node, data_type),
        },
        DataType::Text => match &node.kind {
            Kind::Str(s) => Value::Text(s.clone()),
            _ => return mismatch(node, data_type),
        },
        DataType::Point => Value::Point({
            let [x, y, z] = triple(node, data_type)?;
            Point3::new(x, y, z)
        }),
        DataType::Vector => {
            let [x, y, z] = triple(node, data_type)?;
            Value::Vector(Vector3::new(x, y, z))
        }
        DataType::Domain => {
            let [t0, t1] = numbers(node, data_type)?;
            Value::Domain(Interval::new(t0, t1))
        }
        DataType::Domain2 => {
            let [[u0, u1], [v0, v1]] =
                tuple_of::<2, _>(node, data_type, |pair| numbers::<2>(pair, data_type))?;
            Value::Domain2(UvInterval::new(
                Interval::new(u0, u1),
                Interval::new(v0, v1),
            ))
        }
        DataType::Plane => Value::Plane(plane(node)?),
        DataType::Transform => {
            let rows = tuple_of::<4, _>(node, DataType::Transform, |row| {
                numbers::<4>(row, DataType::Transform)
            })?;
            Value::Transform(Transform::from_rows(rows))
        }
        DataType::Generic => return infer_item(node),
        other => match crate::file::literal_geometry::parse_geometry(node, other) {
            Some(value) => value?,
            None => {
                return error(
                    node,
                    format!("values of type {other} have no literal form yet"),
                );
            }
        },
    };
    Ok(Some(value))
}

/// Reads an item of a generic port, taking the type from the literal's shape.
fn infer_item(node: &Node) -> Result<Option<Value>, LiteralError> {
    let data_type = match &node.kind {
        Kind::Number(n) if is_integer_lexeme(n) => DataType::Integer,
        Kind::Number(_) => DataType::Number,
        Kind::Bool(_) => DataType::Boolean,
        Kind::Str(_) => DataType::Text,
        Kind::Ident(i) if plane_by_name(i).is_some() => DataType::Plane,
        Kind::Struct(None, _) => match crate::file::literal_geometry::struct_type(node) {
            Some(t) => t,
            None => {
                return error(
                    node,
                    format!(
                        "cannot tell the type of {}: tag it as in Circle(plane: XY, radius: 1)",
                        node.describe()
                    ),
                );
            }
        },
        Kind::Tuple(None, items) => {
            let all = |k: fn(&Node) -> bool| items.iter().all(k);
            let is_number = |n: &Node| matches!(n.kind, Kind::Number(_));
            let is_tuple_of = |len: usize| move |n: &Node| matches!(&n.kind, Kind::Tuple(None, v) if v.len() == len && v.iter().all(is_number));
            match items.len() {
                2 if all(is_number) => DataType::Domain,
                2 if items.iter().all(is_tuple_of(2)) => DataType::Domain2,
                2 if items.iter().all(is_tuple_of(3)) => DataType::Line,
                3 if all(is_number) => DataType::Point,
                3 if items.iter().all(is_tuple_of(3)) => DataType::Plane,
                4 if items.iter().all(is_tuple_of(4)) => DataType::Transform,
                _ => {
                    return error(
                        node,
                        format!(
                            "cannot tell the type of {}: write a point (x, y, z), a domain \
                             (start, end), a Domain2 of two pairs, a line of two triples, a plane of three triples or a \
                             transform of four rows, or tag it as in Vector(1, 2, 3)",
                            node.describe()
                        ),
                    );
                }
            }
        }
        _ => return mismatch(node, DataType::Generic),
    };
    parse_item(node, data_type)
}

fn is_integer_lexeme(n: &str) -> bool {
    !n.contains(['.', 'e', 'E', 'i', 'N'])
}

pub(crate) fn number(node: &Node, data_type: DataType) -> Result<f64, LiteralError> {
    match &node.kind {
        Kind::Number(n) => n
            .replace('_', "")
            .parse::<f64>()
            .or_else(|_| error(node, format!("invalid number {n}"))),
        _ => mismatch(node, data_type),
    }
}

fn integer(node: &Node) -> Result<i64, LiteralError> {
    match &node.kind {
        Kind::Number(n) if is_integer_lexeme(n) => n
            .replace('_', "")
            .parse::<i64>()
            .or_else(|_| error(node, format!("integer {n} is out of range"))),
        _ => mismatch(node, DataType::Integer),
    }
}

/// Reads an untagged tuple of exactly `N` elements, each with `element`.
fn tuple_of<const N: usize, T: Copy + Default>(
    node: &Node,
    data_type: DataType,
    mut element: impl FnMut(&Node) -> Result<T, LiteralError>,
) -> Result<[T; N], LiteralError> {
    match &node.kind {
        Kind::Tuple(None, items) if items.len() == N => {
            let mut out = [T::default(); N];
            for (slot, item) in out.iter_mut().zip(items) {
                *slot = element(item)?;
            }
            Ok(out)
        }
        _ => mismatch(node, data_type),
    }
}

/// Reads `(a, b, …)` of `N` numbers; a non-number names the enclosing type.
pub(crate) fn numbers<const N: usize>(
    node: &Node,
    data_type: DataType,
) -> Result<[f64; N], LiteralError> {
    tuple_of::<N, f64>(node, data_type, |item| match &item.kind {
        Kind::Number(_) => number(item, data_type),
        _ => error(
            item,
            format!(
                "expected a number in {}, found {}",
                expectation(data_type),
                item.describe()
            ),
        ),
    })
}

fn triple(node: &Node, data_type: DataType) -> Result<[f64; 3], LiteralError> {
    numbers::<3>(node, data_type)
}

fn plane_by_name(name: &str) -> Option<Plane> {
    match name {
        "XY" => Some(Plane::WORLD_XY),
        "YZ" => Some(Plane::WORLD_YZ),
        "XZ" => Some(WORLD_XZ),
        "ZX" => Some(Plane::WORLD_ZX),
        _ => None,
    }
}

pub(crate) fn plane(node: &Node) -> Result<Plane, LiteralError> {
    if let Kind::Ident(name) = &node.kind {
        return match plane_by_name(name) {
            Some(p) => Ok(p),
            None => mismatch(node, DataType::Plane),
        };
    }
    let [o, x, y] = tuple_of::<3, [f64; 3]>(node, DataType::Plane, |item| {
        numbers::<3>(item, DataType::Plane)
    })?;
    let origin = Point3::new(o[0], o[1], o[2]);
    let x = Vector3::new(x[0], x[1], x[2]);
    let y = Vector3::new(y[0], y[1], y[2]);
    let orthonormal = (x.length_squared() - 1.0).abs() <= UNIT_AXIS_TOLERANCE
        && (y.length_squared() - 1.0).abs() <= UNIT_AXIS_TOLERANCE
        && x.dot(y).abs() <= UNIT_AXIS_TOLERANCE;
    if orthonormal && origin.is_finite() {
        return Ok(Plane {
            origin,
            x_axis: x,
            y_axis: y,
            z_axis: x.cross(y),
        });
    }
    Plane::from_frame(origin, x, y).or_else(|e| error(node, format!("invalid plane: {e}")))
}

/// The literal syntax of a tree (see the module docs for the shapes).
pub(crate) fn tree_node(tree: &DataTree) -> Result<Node, LiteralError> {
    let branches = tree.branches();
    if let [(path, branch)] = branches
        && *path == TreePath::zero()
    {
        if branch.len() == 1 && !branch.is_null(0) {
            return branch_items(branch).map(|mut v| v.swap_remove(0));
        }
        return Ok(Node::new(Kind::List(branch_items(branch)?)));
    }
    let mut entries = Vec::with_capacity(branches.len());
    for (path, branch) in branches {
        entries.push((
            Node::new(Kind::Str(path.to_string())),
            Node::new(Kind::List(branch_items(branch)?)),
        ));
    }
    Ok(Node::new(Kind::Map(entries)))
}

fn branch_items(branch: &Branch) -> Result<Vec<Node>, LiteralError> {
    let generic = branch.data_type() == DataType::Generic;
    branch
        .values()
        .map(|v| match v {
            Some(v) => item_node(&v, generic),
            None => Ok(Node::new(Kind::Ident("null".to_owned()))),
        })
        .collect()
}

pub(crate) fn number_node(x: f64) -> Node {
    // `{:?}` is the shortest text that reads back to the same `f64`, and always has a
    // decimal point or exponent (or is `inf` or `NaN`), so it reads back as a Number.
    Node::new(Kind::Number(format!("{x:?}")))
}

pub(crate) fn numbers_node<const N: usize>(values: [f64; N]) -> Node {
    Node::new(Kind::Tuple(None, values.map(number_node).to_vec()))
}

/// The literal syntax of one item; `in_generic` tags the types whose shape is ambiguous.
pub(crate) fn item_node(value: &Value, in_generic: bool) -> Result<Node, LiteralError> {
    let node = match value {
        Value::Number(x) => number_node(*x),
        Value::Integer(i) => Node::new(Kind::Number(i.to_string())),
        Value::Boolean(b) => Node::new(Kind::Bool(*b)),
        Value::Text(s) => Node::new(Kind::Str(s.clone())),
        Value::Point(p) => numbers_node(p.to_array()),
        Value::Vector(v) => {
            let tag = in_generic.then(|| "Vector".to_owned());
            Node::new(Kind::Tuple(tag, v.to_array().map(number_node).to_vec()))
        }
        Value::Domain(d) => numbers_node([d.t0, d.t1]),
        Value::Domain2(d) => Node::new(Kind::Tuple(
            None,
            vec![
                numbers_node([d.u.t0, d.u.t1]),
                numbers_node([d.v.t0, d.v.t1]),
            ],
        )),
        Value::Plane(p) => plane_node(p),
        Value::Transform(t) => Node::new(Kind::Tuple(None, t.to_rows().map(numbers_node).to_vec())),
        other => match crate::file::literal_geometry::geometry_node(other) {
            Some(node) => node?,
            None => {
                return Err(LiteralError {
                    message: format!(
                        "values of type {} have no literal form yet",
                        other.data_type()
                    ),
                    span: 0..0,
                });
            }
        },
    };
    Ok(node)
}

pub(crate) fn plane_node(p: &Plane) -> Node {
    for (name, named) in [
        ("XY", Plane::WORLD_XY),
        ("YZ", Plane::WORLD_YZ),
        ("XZ", WORLD_XZ),
        ("ZX", Plane::WORLD_ZX),
    ] {
        if *p == named {
            return Node::new(Kind::Ident(name.to_owned()));
        }
    }
    Node::new(Kind::Tuple(
        None,
        vec![
            numbers_node(p.origin.to_array()),
            numbers_node(p.x_axis.to_array()),
            numbers_node(p.y_axis.to_array()),
        ],
    ))
}

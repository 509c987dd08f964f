//! Type casting between value types, modelled on Grasshopper's conversions.
//!
//! There are two views of one table. [`can_cast`] answers, per pair of types, whether a wire
//! between them can work at all; it is what the checker uses before running. The value-level
//! casts ([`cast_value`], [`cast_branch`], [`cast_tree`]) convert items and report the ones
//! that fail (text that is not a number, NaN to an integer) as [`CastError`]s, leaving nulls.
//! A test keeps the two views in agreement. The whole table, with the rules chosen where
//! Grasshopper is vague, is written out in `docs/casting.md`.
//!
//! The value-level table is the `cast_table!` invocation below: one line per pair, naming a
//! typed function `fn(&A) -> Option<B>`. The same line generates the per-value dispatch and
//! the branch-level loop over a typed column, so the two cannot disagree. The conversions
//! themselves live in `cast_rules.rs` (numbers, text, points) and `cast_geometry.rs`
//! (bounding boxes and other geometry).

use std::borrow::Cow;
use std::fmt;

use locus_kernel::{
    Arc as ArcCurve, Brep, Circle, Color, Curve, Interval, Line, Mesh, NurbsSurface, OrientedBox,
    Plane, Point3, UvInterval, Vector3,
};

use crate::checking::cast_geometry::{
    arc_to_box, brep_to_box, brep_to_surface, circle_plane, circle_to_box, curve_to_arc,
    curve_to_box, curve_to_circle, curve_to_line, line_to_box, point_to_box, surface_to_box,
};
use crate::checking::cast_mesh;
use crate::checking::cast_rules::{
    number_to_boolean, number_to_domain, number_to_integer, parse_xyz, point_to_plane,
    text_to_boolean, text_to_domain, text_to_integer,
};
use crate::file::value_text::{
    format_boolean, format_domain, format_number, format_plane, format_point, format_transform,
    format_value, format_vector, parse_number, write_quoted,
};
use crate::{Branch, DataTree, DataType, Item, Shared, TreePath, Value};

/// Whether items of type `from` can in general be cast to `to`, for checking wires before
/// running. Individual items may still fail (text that is not a number) and are then reported
/// per item at run time.
pub fn can_cast(from: DataType, to: DataType) -> bool {
    use DataType::*;
    if from == to || from == Generic || to == Generic {
        return true;
    }
    matches!(
        (from, to),
        (Number, Integer)
            | (Integer, Number)
            | (Number | Integer | Boolean, Text)
            | (Text, Number | Integer | Boolean | Point | Vector | Domain)
            | (Boolean, Integer | Number)
            | (Integer | Number, Boolean)
            | (Number | Integer, Domain)
            | (Number | Integer | Domain | Surface | Brep, Domain2)
            | (Domain2, Text)
            | (Point, Vector)
            | (Vector, Point)
            | (Point, Plane)
            | (Plane, Point)
            | (Domain, Number)
            | (Point | Vector | Plane | Domain | Transform, Text)
            | (Point | Line | Circle | Arc | Curve | Surface | Brep, Box)
            | (Line | Circle | Arc, Curve)
            | (Curve, Line | Circle | Arc)
            | (Line | Circle | Arc | Curve, Number)
            | (Curve, Domain)
            | (Circle | Arc | Box, Plane)
            | (Line, Vector)
            | (Box | Line | Circle | Arc | Curve | Surface | Brep, Text)
            | (Box | Surface, Brep)
            | (Brep, Surface)
            | (Box | Surface | Brep, Mesh)
            | (Mesh, Box | Text)
            | (Colour, Text)
            | (Text | Integer, Colour)
    )
}

/// The longest value text (in characters) quoted in a [`CastError`] message.
const MAX_SHOWN_VALUE_CHARS: usize = 40;

/// An item that could not be cast: `invalid cast: Text "abc" → Number`.
///
/// The offending value is shown when the pair of types can be cast in general (so the value is
/// what went wrong) and its text is short; otherwise the message names the types only, as in
/// `invalid cast: Point → Number`. A B-rep cast to a surface is shown by what decides the cast,
/// its face count: `invalid cast: Brep with 6 faces → Surface`.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub struct CastError {
    /// The type of the item.
    pub from: DataType,
    /// The type it was cast to.
    pub to: DataType,
    /// The item as shown in the message (text in double quotes), if shown.
    pub value: Option<String>,
}

impl CastError {
    /// An error naming the two types only.
    pub fn new(from: DataType, to: DataType) -> Self {
        Self {
            from,
            to,
            value: None,
        }
    }

    /// An error for `value`, which is shown in the message if the pair of types can be cast
    /// in general and the value's text is short.
    pub fn for_value(value: &Value, to: DataType) -> Self {
        let from = value.data_type();
        let shown = can_cast(from, to).then(|| show_value(value, to)).flatten();
        Self {
            from,
            to,
            value: shown,
        }
    }
}

fn show_value(value: &Value, to: DataType) -> Option<String> {
    let text = match value {
        Value::Brep(b) if to == DataType::Surface => {
            let n = b.faces().len();
            format!("with {n} face{}", if n == 1 { "" } else { "s" })
        }
        // What fails a B-rep's other casts (no geometry, a number that is not finite) is not
        // in its text.
        Value::Brep(_) => return None,
        Value::Text(t) => {
            let mut s = String::with_capacity(t.len() + 2);
            write_quoted(&mut s, t);
            s
        }
        other => format_value(other),
    };
    (text.chars().count() <= MAX_SHOWN_VALUE_CHARS).then_some(text)
}

impl fmt::Display for CastError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match &self.value {
            Some(v) => write!(f, "invalid cast: {} {v} → {}", self.from, self.to),
            None => write!(f, "invalid cast: {} → {}", self.from, self.to),
        }
    }
}

/// Casts one value to type `to`.
///
/// A value already of type `to`, or any value cast to `Generic`, is returned as it is.
///
/// # Errors
/// [`CastError`] when the types have no cast (`Point → Number`) or this value cannot be
/// converted (`Text "abc" → Number`, `Number NaN → Integer`).
pub fn cast_value(value: &Value, to: DataType) -> Result<Value, CastError> {
    if to == DataType::Generic || value.data_type() == to {
        return Ok(value.clone());
    }
    match cast_by_table(value, to) {
        Some(Some(v)) => Ok(v),
        _ => Err(CastError::for_value(value, to)),
    }
}

/// Casts every item of a branch to type `to`, returning the cast branch and, per item that
/// failed, its index and error. Failed items become nulls; null items stay null without an
/// error, and the branch keeps its length.
///
/// A branch already of type `to`, and any branch cast to `Generic`, is borrowed as it is:
/// no per-item work. Otherwise the typed column is converted in one loop.
pub fn cast_branch(branch: &Branch, to: DataType) -> (Cow<'_, Branch>, Vec<(usize, CastError)>) {
    let from = branch.data_type();
    if to == DataType::Generic || from == to {
        return (Cow::Borrowed(branch), Vec::new());
    }
    if from != DataType::Generic
        && let Some((cast, errors)) = cast_column(branch, to)
    {
        return (Cow::Owned(cast), errors);
    }
    let (cast, errors) = cast_each(branch, to);
    (Cow::Owned(cast), errors)
}

/// Casts every branch of a tree to type `to` (see [`cast_branch`]), returning the cast tree and
/// the failures with their paths and item indices. Paths and branch lengths are unchanged.
pub fn cast_tree(tree: &DataTree, to: DataType) -> (DataTree, Vec<(TreePath, usize, CastError)>) {
    let mut failures = Vec::new();
    let branches: Vec<(TreePath, Branch)> = tree
        .branches()
        .iter()
        .map(|(path, branch)| {
            let (cast, errors) = cast_branch(branch, to);
            failures.extend(errors.into_iter().map(|(i, e)| (path.clone(), i, e)));
            (path.clone(), cast.into_owned())
        })
        .collect();
    (DataTree::from_branches(branches), failures)
}

/// Casts item by item through [`cast_value`]: for generic columns and pairs without a cast.
fn cast_each(branch: &Branch, to: DataType) -> (Branch, Vec<(usize, CastError)>) {
    let mut out = Branch::new(to);
    let mut errors = Vec::new();
    for i in 0..branch.len() {
        match branch.value(i) {
            None => out.push_null(),
            Some(v) => match cast_value(&v, to) {
                Ok(c) => out.push_value(c),
                Err(e) => {
                    errors.push((i, e));
                    out.push_null();
                }
            },
        }
    }
    (out, errors)
}

/// Converts a typed column with `f`, one tight loop, nulls carried over.
fn map_branch<A, B, F>(branch: &Branch, to: DataType, f: F) -> (Branch, Vec<(usize, CastError)>)
where
    A: Item,
    B: Item,
    F: Fn(&A) -> Option<B>,
{
    let Some(items) = branch.slice::<A>() else {
        return cast_each(branch, to);
    };
    let mask = branch.null_mask();
    let mut failed: Vec<usize> = Vec::new();
    // Collecting from a mapped slice iterator writes the output without capacity checks.
    let out: Vec<B> = if mask.is_empty() {
        items
            .iter()
            .enumerate()
            .map(|(i, a)| {
                f(a).unwrap_or_else(|| {
                    failed.push(i);
                    B::placeholder()
                })
            })
            .collect()
    } else {
        items
            .iter()
            .zip(mask)
            .enumerate()
            .map(|(i, (a, &null))| {
                if null {
                    return B::placeholder();
                }
                f(a).unwrap_or_else(|| {
                    failed.push(i);
                    B::placeholder()
                })
            })
            .collect()
    };
    if failed.is_empty() {
        return (
            Branch::from_parts(B::into_column(out), mask.to_vec()),
            Vec::new(),
        );
    }
    let mut nulls = if mask.is_empty() {
        vec![false; items.len()]
    } else {
        mask.to_vec()
    };
    let errors = failed
        .into_iter()
        .map(|i| {
            nulls[i] = true;
            (i, CastError::for_value(&items[i].clone().into_value(), to))
        })
        .collect();
    (Branch::from_parts(B::into_column(out), nulls), errors)
}

/// Declares the value-level casting table: each line `From(A) => To(B) = function;` names a
/// function `fn(&A) -> Option<B>` that returns `None` for an item that cannot be cast.
macro_rules! cast_table {
    ($( $from:ident($a:ty) => $to:ident($b:ty) = $f:expr; )*) => {
        /// The cast of one value by the table: `None` if the pair is not in the table,
        /// `Some(None)` if this value failed.
        fn cast_by_table(value: &Value, to: DataType) -> Option<Option<Value>> {
            match (value, to) {
                $( (Value::$from(x), DataType::$to) => Some(($f)(x).map(Value::$to)), )*
                _ => None,
            }
        }

        /// The cast of a typed column by the table, or `None` if the pair is not in it.
        fn cast_column(branch: &Branch, to: DataType) -> Option<(Branch, Vec<(usize, CastError)>)> {
            match (branch.data_type(), to) {
                $( (DataType::$from, DataType::$to) => Some(map_branch::<$a, $b, _>(branch, to, $f)), )*
                _ => None,
            }
        }
    };
}

cast_table! {
    Number(f64) => Integer(i64) = |x: &f64| number_to_integer(*x);
    Number(f64) => Boolean(bool) = number_to_boolean;
    Number(f64) => Domain(Interval) = number_to_domain;
    Number(f64) => Text(String) = |x: &f64| Some(format_number(*x));
    Integer(i64) => Number(f64) = |i: &i64| Some(*i as f64);
    Integer(i64) => Boolean(bool) = |i: &i64| Some(*i != 0);
    Integer(i64) => Domain(Interval) = |i: &i64| Some(Interval::new(0.0, *i as f64));
    Integer(i64) => Text(String) = |i: &i64| Some(i.to_string());
    Boolean(bool) => Integer(i64) = |b: &bool| Some(i64::from(*b));
    Boolean(bool) => Number(f64) = |b: &bool| Some(if *b { 1.0 } else { 0.0 });
    Boolean(bool) => Text(String) = |b: &bool| Some(format_boolean(*b).to_owned());
    Text(String) => Number(f64) = |t: &String| parse_number(t);
    Text(String) => Integer(i64) = |t: &String| text_to_integer(t);
    Text(String) => Boolean(bool) = |t: &String| text_to_boolean(t);
    Text(String) => Point(Point3) = |t: &String| parse_xyz(t).map(|[x, y, z]| Point3::new(x, y, z));
    Text(String) => Vector(Vector3) = |t: &String| parse_xyz(t).map(|[x, y, z]| Vector3::new(x, y, z));
    Text(String) => Domain(Interval) = |t: &String| text_to_domain(t);
    Point(Point3) => Vector(Vector3) = |p: &Point3| Some(p.to_vector());
    Point(Point3) => Plane(Plane) = point_to_plane;
    Point(Point3) => Text(String) = |p: &Point3| Some(format_point(*p));
    Vector(Vector3) => Point(Point3) = |v: &Vector3| Some(Point3::from_vector(*v));
    Vector(Vector3) => Text(String) = |v: &Vector3| Some(format_vector(*v));
    Plane(Plane) => Point(Point3) = |p: &Plane| Some(p.origin);
    Plane(Plane) => Text(String) = |p: &Plane| Some(format_plane(p));
    Domain(Interval) => Number(f64) = |d: &Interval| Some(d.length());
    Domain(Interval) => Text(String) = |d: &Interval| Some(format_domain(*d));
    Number(f64) => Domain2(UvInterval) =
        |x: &f64| number_to_domain(x).map(|d| UvInterval::new(d, d));
    Integer(i64) => Domain2(UvInterval) = |i: &i64| {
        let d = Interval::new(0.0, *i as f64);
        Some(UvInterval::new(d, d))
    };
    Domain(Interval) => Domain2(UvInterval) = |d: &Interval| Some(UvInterval::new(*d, *d));
    Surface(Shared<NurbsSurface>) => Domain2(UvInterval) =
        |s: &Shared<NurbsSurface>| Some(UvInterval::new(s.domain_u(), s.domain_v()));
    Brep(Shared<Brep>) => Domain2(UvInterval) = |b: &Shared<Brep>| {
        brep_to_surface(b).map(|s| UvInterval::new(s.domain_u(), s.domain_v()))
    };
    Domain2(UvInterval) => Text(String) =
        |d: &UvInterval| Some(format_value(&Value::Domain2(*d)));
    Transform(locus_kernel::Transform) => Text(String) =
        |t: &locus_kernel::Transform| Some(format_transform(t));
    Point(Point3) => Box(OrientedBox) = point_to_box;
    Line(Line) => Box(OrientedBox) = line_to_box;
    Circle(Circle) => Box(OrientedBox) = circle_to_box;
    Arc(ArcCurve) => Box(OrientedBox) = arc_to_box;
    Curve(Shared<Curve>) => Box(OrientedBox) = curve_to_box;
    Surface(Shared<NurbsSurface>) => Box(OrientedBox) = surface_to_box;
    Brep(Shared<Brep>) => Box(OrientedBox) = brep_to_box;
    Brep(Shared<Brep>) => Surface(Shared<NurbsSurface>) = brep_to_surface;
    Line(Line) => Curve(Shared<Curve>) = |l: &Line| Some(Shared::new(Curve::from(*l)));
    Circle(Circle) => Curve(Shared<Curve>) = |c: &Circle| Some(Shared::new(Curve::from(*c)));
    Arc(ArcCurve) => Curve(Shared<Curve>) = |a: &ArcCurve| Some(Shared::new(Curve::from(*a)));
    Curve(Shared<Curve>) => Line(Line) = curve_to_line;
    Curve(Shared<Curve>) => Circle(Circle) = curve_to_circle;
    Curve(Shared<Curve>) => Arc(ArcCurve) = curve_to_arc;
    Line(Line) => Number(f64) = |l: &Line| Some(l.length());
    Circle(Circle) => Number(f64) = |c: &Circle| Some(c.circumference());
    Arc(ArcCurve) => Number(f64) = |a: &ArcCurve| Some(a.length());
    Curve(Shared<Curve>) => Number(f64) = |c: &Shared<Curve>| Some(c.length());
    Curve(Shared<Curve>) => Domain(Interval) = |c: &Shared<Curve>| Some(c.domain());
    Circle(Circle) => Plane(Plane) = circle_plane;
    Arc(ArcCurve) => Plane(Plane) = |a: &ArcCurve| circle_plane(&a.circle);
    Box(OrientedBox) => Plane(Plane) = |b: &OrientedBox| Some(b.plane);
    Line(Line) => Vector(Vector3) = |l: &Line| Some(l.direction());
    Box(OrientedBox) => Text(String) = |b: &OrientedBox| Some(format_value(&Value::Box(*b)));
    Line(Line) => Text(String) = |l: &Line| Some(format_value(&Value::Line(*l)));
    Circle(Circle) => Text(String) = |c: &Circle| Some(format_value(&Value::Circle(*c)));
    Arc(ArcCurve) => Text(String) = |a: &ArcCurve| Some(format_value(&Value::Arc(*a)));
    Curve(Shared<Curve>) => Text(String) =
        |c: &Shared<Curve>| Some(format_value(&Value::Curve(c.clone())));
    Box(OrientedBox) => Brep(Shared<Brep>) = |b: &OrientedBox| Brep::from_box(b).ok().map(Shared::new);
    Surface(Shared<NurbsSurface>) => Brep(Shared<Brep>) =
        |s: &Shared<NurbsSurface>| Brep::from_surface((**s).clone()).ok().map(Shared::new);
    Brep(Shared<Brep>) => Text(String) = |b: &Shared<Brep>| Some(format_value(&Value::Brep(b.clone())));
    Surface(Shared<NurbsSurface>) => Text(String) =
        |s: &Shared<NurbsSurface>| Some(format_value(&Value::Surface(s.clone())));
    Box(OrientedBox) => Mesh(Shared<Mesh>) = cast_mesh::box_to_mesh;
    Surface(Shared<NurbsSurface>) => Mesh(Shared<Mesh>) = cast_mesh::surface_to_mesh;
    Brep(Shared<Brep>) => Mesh(Shared<Mesh>) = cast_mesh::brep_to_mesh;
    Mesh(Shared<Mesh>) => Box(OrientedBox) = cast_mesh::mesh_to_box;
    Mesh(Shared<Mesh>) => Text(String) = |m: &Shared<Mesh>| Some(format_value(&Value::Mesh(m.clone())));
    Colour(Color) => Text(String) = |c: &Color| Some(format_value(&Value::Colour(*c)));
    Text(String) => Colour(Color) = |t: &String| cast_mesh::text_to_colour(t);
    Integer(i64) => Colour(Color) = cast_mesh::integer_to_colour;
}

#[cfg(test)]
mod tests {
    use super::*;
    use locus_kernel::Transform;

    fn line() -> Line {
        Line::new(Point3::ORIGIN, Point3::new(3.0, 4.0, 0.0))
    }

    fn circle() -> Circle {
        Circle::new(Plane::WORLD_XY, 2.0).unwrap()
    }

    fn arc() -> ArcCurve {
        ArcCurve::new(circle(), Interval::new(0.0, 1.0)).unwrap()
    }

    fn unit_box() -> OrientedBox {
        OrientedBox::new(
            Plane::WORLD_XY,
            Interval::UNIT,
            Interval::UNIT,
            Interval::UNIT,
        )
    }

    /// A surface over `[0, 2] × [0, 1]` bulging up to z = 1 in the middle, from a control
    /// row at z = 2 (so its control points' box is twice as tall as the surface).
    fn bump() -> NurbsSurface {
        let row = |x: f64, z: f64| vec![Point3::new(x, 0.0, z), Point3::new(x, 1.0, z)];
        NurbsSurface::new(
            2,
            1,
            vec![row(0.0, 0.0), row(1.0, 2.0), row(2.0, 0.0)],
            vec![vec![1.0; 2]; 3],
            vec![0.0, 0.0, 1.0, 1.0],
            vec![0.0, 1.0],
        )
        .unwrap()
    }

    /// The corners of a world box, `[min, max]`, after checking it is on World XY.
    fn world_corners(v: Value) -> [[f64; 3]; 2] {
        let Value::Box(b) = v else {
            panic!("not a box: {v:?}");
        };
        assert_eq!(b.plane, Plane::WORLD_XY);
        [[b.x.t0, b.y.t0, b.z.t0], [b.x.t1, b.y.t1, b.z.t1]]
    }

    fn assert_corners(got: [[f64; 3]; 2], want: [[f64; 3]; 2]) {
        for (g, w) in got.iter().flatten().zip(want.iter().flatten()) {
            assert!((g - w).abs() < 1e-9, "{got:?} ≠ {want:?}");
        }
    }

    fn text(s: &str) -> Value {
        Value::Text(s.to_owned())
    }

    fn ok(v: Value, to: DataType) -> Value {
        cast_value(&v, to).unwrap_or_else(|e| panic!("{v:?} → {to}: {e}"))
    }

    fn err(v: Value, to: DataType) -> String {
        match cast_value(&v, to) {
            Ok(c) => panic!("{v:?} cast to {c:?}"),
            Err(e) => e.to_string(),
        }
    }

    /// Values of each type, including ones that cast to every type reachable from it.
    fn samples(t: DataType) -> Vec<Value> {
        match t {
            DataType::Number => vec![Value::Number(1.5), Value::Number(f64::NAN)],
            DataType::Integer => vec![Value::Integer(-3), Value::Integer(0)],
            DataType::Boolean => vec![Value::Boolean(true), Value::Boolean(false)],
            DataType::Text => ["1", "true", "1,2,3", "0 To 1", "abc", "", "#FF8000"]
                .into_iter()
                .map(text)
                .collect(),
            DataType::Point => vec![Value::Point(Point3::new(1.0, 2.0, 3.0))],
            DataType::Vector => vec![Value::Vector(Vector3::new(1.0, 2.0, 3.0))],
            DataType::Plane => vec![Value::Plane(Plane::WORLD_YZ)],
            DataType::Domain => vec![Value::Domain(Interval::new(1.0, 4.0))],
            DataType::Domain2 => vec![Value::Domain2(UvInterval::new(
                Interval::new(1.0, 4.0),
                Interval::new(0.0, -2.0),
            ))],
            DataType::Transform => vec![Value::Transform(Transform::IDENTITY)],
            DataType::Box => vec![Value::Box(OrientedBox::new(
                Plane::WORLD_XY,
                Interval::UNIT,
                Interval::UNIT,
                Interval::new(0.0, 2.0),
            ))],
            DataType::Line => vec![Value::Line(line())],
            DataType::Circle => vec![Value::Circle(circle())],
            DataType::Arc => vec![Value::Arc(arc())],
            DataType::Curve => vec![
                Value::Curve(Shared::new(Curve::from(line()))),
                Value::Curve(Shared::new(Curve::from(circle()))),
                Value::Curve(Shared::new(Curve::from(arc()))),
            ],
            DataType::Surface => vec![Value::Surface(Shared::new(
                NurbsSurface::from_plane(&Plane::WORLD_XY, Interval::UNIT, Interval::UNIT).unwrap(),
            ))],
            DataType::Brep => vec![
                Value::Brep(Shared::new(Brep::default())),
                Value::Brep(Shared::new(Brep::from_surface(bump()).unwrap())),
                Value::Brep(Shared::new(Brep::from_box(&unit_box()).unwrap())),
            ],
            DataType::Mesh => vec![Value::Mesh(Shared::new(
                Mesh::from_brep(
                    &Brep::from_box(&unit_box()).unwrap(),
                    &locus_kernel::MeshingParameters::default(),
                )
                .unwrap(),
            ))],
            DataType::Colour => vec![Value::Colour(Color::rgb(255, 128, 0))],
            DataType::Generic => Vec::new(),
        }
    }

    #[test]
    fn can_cast_agrees_with_the_value_table() {
        for &from in DataType::ALL {
            if from == DataType::Generic {
                continue;
            }
            let values = samples(from);
            assert!(!values.is_empty(), "no samples for {from}");
            for &to in DataType::ALL {
                let castable = values.iter().any(|v| cast_value(v, to).is_ok());
                assert_eq!(can_cast(from, to), castable, "{from} → {to}");
                // The branch-level cast agrees with the value-level one, item by item.
                let mut branch = Branch::new(from);
                for v in &values {
                    branch.push_value(v.clone());
                }
                let (cast, errors) = cast_branch(&branch, to);
                assert_eq!(cast.len(), values.len());
                for (i, v) in values.iter().enumerate() {
                    match cast_value(v, to) {
                        // Compared as Debug text so that NaN equals NaN.
                        Ok(c) => assert_eq!(
                            format!("{:?}", cast.value(i)),
                            format!("{:?}", Some(c)),
                            "{from} → {to} [{i}]"
                        ),
                        Err(e) => {
                            assert_eq!(cast.value(i), None);
                            assert!(errors.contains(&(i, e)), "{from} → {to} [{i}]");
                        }
                    }
                }
            }
        }
    }

    #[test]
    fn one_face_breps_cast_to_their_surface() {
        let sphere = locus_kernel::Sphere::new(Point3::new(1.0, 0.0, 0.0), 2.0).unwrap();
        let brep = Value::Brep(Shared::new(Brep::from_sphere(&sphere).unwrap()));
        assert_eq!(
            ok(brep, DataType::Surface),
            Value::Surface(Shared::new(sphere.to_nurbs().unwrap()))
        );
        // Surface → B-rep → Surface gives the same surface back.
        let srf = Value::Surface(Shared::new(bump()));
        assert_eq!(ok(ok(srf.clone(), DataType::Brep), DataType::Surface), srf);
    }

    #[test]
    fn breps_with_several_faces_or_none_name_the_count() {
        let six = Value::Brep(Shared::new(Brep::from_box(&unit_box()).unwrap()));
        assert_eq!(
            err(six, DataType::Surface),
            "invalid cast: Brep with 6 faces → Surface"
        );
        assert_eq!(
            err(Value::Brep(Shared::new(Brep::default())), DataType::Surface),
            "invalid cast: Brep with 0 faces → Surface"
        );
    }

    #[test]
    fn brep_branches_cast_to_surfaces_item_by_item() {
        let one = Shared::new(Brep::from_surface(bump()).unwrap());
        let six = Shared::new(Brep::from_box(&unit_box()).unwrap());
        let branch = Branch::from_parts(
            <Shared<Brep> as Item>::into_column(vec![one.clone(), six, one]),
            vec![false, false, true],
        );
        let (cast, errors) = cast_branch(&branch, DataType::Surface);
        assert_eq!(cast.data_type(), DataType::Surface);
        assert_eq!(
            cast.values().collect::<Vec<_>>(),
            [Some(Value::Surface(Shared::new(bump()))), None, None]
        );
        assert_eq!(errors.len(), 1, "{errors:?}");
        assert_eq!(errors[0].0, 1);
        assert_eq!(
            errors[0].1.to_string(),
            "invalid cast: Brep with 6 faces → Surface"
        );
    }

    #[test]
    fn geometry_boxes_are_tight() {
        // The surface peaks at z = 1; its control points reach z = 2.
        let srf = Value::Surface(Shared::new(bump()));
        assert_corners(
            world_corners(ok(srf, DataType::Box)),
            [[0.0, 0.0, 0.0], [2.0, 1.0, 1.0]],
        );
        let brep = Value::Brep(Shared::new(Brep::from_surface(bump()).unwrap()));
        assert_corners(
            world_corners(ok(brep, DataType::Box)),
            [[0.0, 0.0, 0.0], [2.0, 1.0, 1.0]],
        );
        // A sphere's box touches it (its rational control net is the same box here), and a
        // box turned 45° about z has the box of its corners.
        let sphere = locus_kernel::Sphere::new(Point3::new(1.0, 2.0, 3.0), 0.5).unwrap();
        let ball = Value::Brep(Shared::new(Brep::from_sphere(&sphere).unwrap()));
        assert_corners(
            world_corners(ok(ball, DataType::Box)),
            [[0.5, 1.5, 2.5], [1.5, 2.5, 3.5]],
        );
        let turned = OrientedBox::new(
            Plane::from_frame(
                Point3::ORIGIN,
                Vector3::new(1.0, 1.0, 0.0),
                Vector3::new(-1.0, 1.0, 0.0),
            )
            .unwrap(),
            Interval::new(-1.0, 1.0),
            Interval::new(-1.0, 1.0),
            Interval::new(0.0, 2.0),
        );
        let turned = Value::Brep(Shared::new(Brep::from_box(&turned).unwrap()));
        let r = std::f64::consts::SQRT_2;
        assert_corners(
            world_corners(ok(turned, DataType::Box)),
            [[-r, -r, 0.0], [r, r, 2.0]],
        );
    }

    #[test]
    fn empty_breps_have_no_box() {
        assert_eq!(
            err(Value::Brep(Shared::new(Brep::default())), DataType::Box),
            "invalid cast: Brep → Box"
        );
    }

    #[test]
    fn long_values_are_left_out_of_messages() {
        let long = "x".repeat(100);
        assert_eq!(
            err(text(&long), DataType::Number),
            "invalid cast: Text → Number"
        );
    }

    #[test]
    fn pairs_without_a_cast_name_the_types() {
        assert_eq!(
            err(Value::Point(Point3::ORIGIN), DataType::Number),
            "invalid cast: Point → Number"
        );
        assert_eq!(
            err(text("x"), DataType::Plane),
            "invalid cast: Text → Plane"
        );
        assert_eq!(
            err(Value::Transform(Transform::IDENTITY), DataType::Point),
            "invalid cast: Transform → Point"
        );
    }

    #[test]
    fn same_type_and_generic_branches_are_borrowed() {
        let b = Branch::from_items(vec![1.0, 2.0]);
        let (cast, errors) = cast_branch(&b, DataType::Number);
        assert!(matches!(cast, Cow::Borrowed(_)) && errors.is_empty());
        let (cast, errors) = cast_branch(&b, DataType::Generic);
        assert!(matches!(cast, Cow::Borrowed(_)) && errors.is_empty());
    }

    #[test]
    fn failed_items_become_nulls_and_nulls_stay_null() {
        let mut b = Branch::new(DataType::Text);
        b.push("1".to_owned());
        b.push_null();
        b.push("x".to_owned());
        b.push(" 2 ".to_owned());
        let (cast, errors) = cast_branch(&b, DataType::Number);
        assert_eq!(cast.data_type(), DataType::Number);
        assert_eq!(
            cast.values().collect::<Vec<_>>(),
            [
                Some(Value::Number(1.0)),
                None,
                None,
                Some(Value::Number(2.0))
            ]
        );
        assert_eq!(errors.len(), 1);
        assert_eq!(errors[0].0, 2);
        assert_eq!(errors[0].1.to_string(), "invalid cast: Text \"x\" → Number");
    }

    #[test]
    fn generic_branches_cast_per_item() {
        let mut b = Branch::new(DataType::Generic);
        b.push_value(Value::Number(2.5));
        b.push_value(Value::Integer(3));
        b.push_value(text("4"));
        b.push_value(Value::Point(Point3::ORIGIN));
        let (cast, errors) = cast_branch(&b, DataType::Integer);
        assert_eq!(cast.data_type(), DataType::Integer);
        assert_eq!(cast.slice::<i64>(), Some(&[2, 3, 4, 0][..]));
        assert!(cast.is_null(3));
        assert_eq!(errors.len(), 1);
        assert_eq!(errors[0].1.to_string(), "invalid cast: Point → Integer");
    }

    #[test]
    fn trees_cast_branch_by_branch() {
        let mut tree = DataTree::new();
        tree.insert(
            TreePath::from([0, 1]),
            Branch::from_items(vec![1.5, f64::NAN]),
        );
        tree.insert(TreePath::from([2]), Branch::from_items(vec![2.5]));
        let (cast, failures) = cast_tree(&tree, DataType::Integer);
        assert_eq!(cast.item_count(), 3);
        assert_eq!(
            cast.branch(&TreePath::from([2]))
                .and_then(|b| b.slice::<i64>()),
            Some(&[2][..])
        );
        assert_eq!(failures.len(), 1);
        assert_eq!(failures[0].0, TreePath::from([0, 1]));
        assert_eq!(failures[0].1, 1);
    }
}

//! Params: Data and Relay (any data), and the Line, Circle, Arc and Rectangle parameters
//! (Params › Geometry).
//!
//! Like every parameter they have one list input and one list output of the same name and
//! nickname and pass their data through with its paths, empty branches and nulls. The
//! Rectangle parameter holds curves that are rectangles: closed four-sided planar polylines
//! with right angles (the runtime has no rectangle value, so a rectangle is that polyline).

use locus_kernel::{Curve, Point3};
use locus_runtime::{Branch, DataType, NodeRegistry, NodeType, Port, Solve, Value, cast_branch};

/// Id of [`data`].
pub const DATA: &str = "params.data";
/// Id of [`relay`].
pub const RELAY: &str = "params.relay";
/// Id of [`line`].
pub const LINE: &str = "params.line";
/// Id of [`circle`].
pub const CIRCLE: &str = "params.circle";
/// Id of [`arc`].
pub const ARC: &str = "params.arc";
/// Id of [`rectangle`].
pub const RECTANGLE: &str = "params.rectangle";

/// How far from a right angle (as the cosine of the angle between neighbouring sides, and
/// relative to the side lengths for planarity) a polyline may be and still be a rectangle.
pub const RECTANGLE_TOLERANCE: f64 = 1e-9;

/// Registers the Data, Relay, Line, Circle, Arc and Rectangle parameters.
pub fn register(registry: &mut NodeRegistry) {
    for t in [data(), relay(), line(), circle(), arc(), rectangle()] {
        registry.register(t);
    }
}

const PASS_THROUGH: &str = "A parameter passes its data through unchanged (paths, empty \
    branches and nulls included) after casting every item to its type; a graph uses it to \
    declare a named input.";

fn parameter(
    t: NodeType,
    name: &str,
    nickname: &str,
    data_type: DataType,
    accepts: &str,
) -> NodeType {
    t.input(Port::new(name, nickname, data_type).list().doc(&format!(
        "The values, given in the graph or wired in: {accepts}. No default; a parameter \
         without data warns that it failed to collect data."
    )))
    .output(
        Port::new(name, nickname, data_type)
            .list()
            .doc("The same values, cast."),
    )
}

/// Passes the branch of input 0 to output 0, cast to `to` (the runtime casts wired data; this
/// covers a branch given to the node directly). Failed casts are errors naming the item.
fn pass(s: &mut Solve<'_>, to: DataType) -> Option<Branch> {
    let branch = s.branch(0)?;
    let (cast, errors) = cast_branch(branch, to);
    let cast = cast.into_owned();
    for (i, e) in errors {
        s.error(format!("{e} (item {i})"));
    }
    Some(cast)
}

/// Data \[Data\]: a collection of data of any type.
pub fn data() -> NodeType {
    parameter(
        NodeType::new(DATA, "Data", "Data", "Params")
            .subcategory("Primitive")
            .gh_guid("8ec86459-bf01-4409-baee-174d0d2b13d0")
            .description(&format!(
                "Contains a collection of generic data: items of any type keep their own \
                 type. {PASS_THROUGH}"
            )),
        "Data",
        "Data",
        DataType::Generic,
        "any values",
    )
    .solve(|s| {
        if let Some(b) = pass(s, DataType::Generic) {
            s.set_branch(0, b);
        }
        Ok(())
    })
}

/// Relay: a wire's data passed on unchanged (Grasshopper's wire relay dot).
pub fn relay() -> NodeType {
    parameter(
        NodeType::new(RELAY, "Relay", "Relay", "Params")
            .subcategory("Util")
            .gh_guid("b6236720-8d88-4289-93c3-ac4c99f9b97b")
            .description(&format!(
                "Passes the data of a wire on unchanged, items of any type keeping their own \
                 type: Grasshopper's relay, a dot on a wire that organises the canvas. \
                 {PASS_THROUGH}"
            )),
        "Data",
        "Data",
        DataType::Generic,
        "any values",
    )
    .solve(|s| {
        if let Some(b) = pass(s, DataType::Generic) {
            s.set_branch(0, b);
        }
        Ok(())
    })
}

fn geometry_parameter(
    id: &str,
    name: &str,
    nickname: &str,
    data_type: DataType,
    description: &str,
    accepts: &str,
) -> NodeType {
    parameter(
        NodeType::new(id, name, nickname, "Params")
            .subcategory("Geometry")
            .description(&format!(
                "{description} {PASS_THROUGH} Items that do not cast are errors and become \
                 null."
            )),
        name,
        nickname,
        data_type,
        accepts,
    )
    .solve(move |s| {
        if let Some(b) = pass(s, data_type) {
            s.set_branch(0, b);
        }
        Ok(())
    })
}

/// Line \[Line\]: a collection of line segments.
pub fn line() -> NodeType {
    geometry_parameter(
        LINE,
        "Line",
        "Line",
        DataType::Line,
        "Contains a collection of line segments.",
        "lines, or curves that are straight lines",
    )
    .gh_guid("8529dbdf-9b6f-42e9-8e1f-c7a2bde56a70")
}

/// Circle \[Circle\]: a collection of circles.
pub fn circle() -> NodeType {
    geometry_parameter(
        CIRCLE,
        "Circle",
        "Circle",
        DataType::Circle,
        "Contains a collection of circles.",
        "circles, or curves that are circles",
    )
    .gh_guid("d1028c72-ff86-4057-9eb0-36c687a4d98c")
}

/// Arc \[Arc\]: a collection of circular arcs.
pub fn arc() -> NodeType {
    geometry_parameter(
        ARC,
        "Arc",
        "Arc",
        DataType::Arc,
        "Contains a collection of circular arcs (its Grasshopper GUID is not in the project's \
         table, so files cannot name it yet).",
        "arcs, or curves that are arcs",
    )
}

/// Why the curve is not a rectangle, if it is not one.
pub fn not_a_rectangle(curve: &Curve) -> Option<&'static str> {
    let Curve::Polyline { polyline, .. } = curve else {
        return Some("it is not a polyline");
    };
    let pts: &[Point3] = polyline.points();
    if pts.len() != 5 || pts[0] != pts[4] {
        return Some("it is not a closed polyline of four segments");
    }
    let sides: Vec<_> = (0..4).map(|k| pts[k + 1] - pts[k]).collect();
    let scale = sides.iter().map(|v| v.length()).fold(0.0, f64::max);
    if !(scale.is_finite() && scale > 0.0) || sides.iter().any(|v| v.length() == 0.0) {
        return Some("it has a side of zero or non-finite length");
    }
    for k in 0..4 {
        let (a, b) = (sides[k], sides[(k + 1) % 4]);
        if a.dot(b).abs() > RECTANGLE_TOLERANCE * a.length() * b.length() {
            return Some("its corners are not right angles");
        }
    }
    // Opposite sides are parallel and of equal length when all four corners are right
    // angles and the polyline closes in one plane.
    let normal = sides[0].cross(sides[1]);
    if sides[2].dot(normal).abs() > RECTANGLE_TOLERANCE * scale * normal.length()
        || sides[3].dot(normal).abs() > RECTANGLE_TOLERANCE * scale * normal.length()
    {
        return Some("it is not planar");
    }
    None
}

/// Rectangle \[Rec\]: a collection of rectangles.
pub fn rectangle() -> NodeType {
    parameter(
        NodeType::new(RECTANGLE, "Rectangle", "Rec", "Params")
            .subcategory("Geometry")
            .gh_guid("abf9c670-5462-4cd8-acb3-f1ab0256dbf3")
            .description(&format!(
                "Contains a collection of rectangles: closed planar polylines of four sides \
                 with right angles (within RECTANGLE_TOLERANCE = 1e-9, relative). {PASS_THROUGH} \
                 A curve that is not a rectangle is an error saying why and becomes null."
            )),
        "Rectangle",
        "Rec",
        DataType::Curve,
        "rectangles (curves), such as the Rectangle component makes",
    )
    .solve(|s| {
        let Some(b) = pass(s, DataType::Curve) else {
            return Ok(());
        };
        let mut out = Vec::with_capacity(b.len());
        for (i, v) in b.values().enumerate() {
            match v {
                Some(Value::Curve(c)) => match not_a_rectangle(&c) {
                    None => out.push(Some(Value::Curve(c))),
                    Some(why) => {
                        s.error(format!("item {i} is not a rectangle: {why}"));
                        out.push(None);
                    }
                },
                _ => out.push(None),
            }
        }
        s.set_list_values(0, out);
        Ok(())
    })
}

#[cfg(test)]
mod tests {
    use locus_kernel::{Arc as ArcCurve, Circle, Interval, Line, Plane, Polyline};
    use locus_runtime::{DataTree, Level, NodeCall, Shared};

    use super::*;
    use crate::sets::test_support::{generic, messages};

    fn curve(c: impl Into<Curve>) -> Value {
        Value::Curve(Shared::new(c.into()))
    }

    fn one(v: Value) -> DataTree {
        DataTree::from_value(v)
    }

    #[test]
    fn data_and_relay_pass_anything_through() {
        let t = generic("{0;1}:[1, \"a\", null] {2}:[]");
        for node in [data(), relay()] {
            let r = NodeCall::new(&node).input(t.clone()).run();
            assert!(r.messages.is_empty());
            assert_eq!(r.outputs[0], t);
        }
    }

    #[test]
    fn line_circle_and_arc_params_cast_curves() {
        let l = Line::new(Point3::ORIGIN, Point3::new(1.0, 0.0, 0.0));
        let r = NodeCall::new(&line()).input(one(curve(l))).run();
        assert!(r.messages.is_empty(), "{:?}", r.messages);
        assert_eq!(r.outputs[0], DataTree::from_item(l));
        let c = Circle {
            plane: Plane::WORLD_XY,
            radius: 2.0,
        };
        let r = NodeCall::new(&circle()).input(one(curve(c))).run();
        assert_eq!(r.outputs[0], DataTree::from_item(c));
        let a = ArcCurve {
            circle: c,
            angle: Interval::new(0.0, 1.0),
        };
        let r = NodeCall::new(&arc()).input(one(Value::Arc(a))).run();
        assert_eq!(r.outputs[0], DataTree::from_item(a));
        // A circle is not a line: an error and a null.
        let r = NodeCall::new(&line()).input(one(curve(c))).run();
        assert_eq!(messages(&r, Level::Error).len(), 1);
        assert_eq!(r.outputs[0].values().collect::<Vec<_>>(), [None]);
    }

    #[test]
    fn rectangle_param_keeps_rectangles_and_rejects_other_curves() {
        let p = |x: f64, y: f64| Point3::new(x, y, 0.0);
        let rect = Polyline::new(vec![
            p(0.0, 0.0),
            p(2.0, 0.0),
            p(2.0, 1.0),
            p(0.0, 1.0),
            p(0.0, 0.0),
        ])
        .unwrap();
        let r = NodeCall::new(&rectangle()).input(one(curve(rect))).run();
        assert!(r.messages.is_empty(), "{:?}", r.messages);
        let skew = Polyline::new(vec![
            p(0.0, 0.0),
            p(2.0, 0.0),
            p(3.0, 1.0),
            p(0.0, 1.0),
            p(0.0, 0.0),
        ])
        .unwrap();
        let open = Polyline::new(vec![p(0.0, 0.0), p(2.0, 0.0), p(2.0, 1.0), p(0.0, 1.0)]).unwrap();
        for bad in [
            curve(skew),
            curve(open),
            curve(Line::new(p(0.0, 0.0), p(1.0, 0.0))),
        ] {
            let r = NodeCall::new(&rectangle()).input(one(bad)).run();
            let e = messages(&r, Level::Error);
            assert_eq!(e.len(), 1);
            assert!(e[0].contains("is not a rectangle"), "{e:?}");
        }
    }
}

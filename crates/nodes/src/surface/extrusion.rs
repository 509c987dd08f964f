//! Surface › Freeform: Extrude and Extrude Point, curves and surfaces swept along a vector or
//! to a point, as B-reps.
//!
//! A curve is split at its kinks into one face per piece, joined (an extruded rectangle has
//! four side faces). A closed planar curve is capped, so that it becomes a closed solid, as
//! Grasshopper's Extrude does with closed planar profiles (an extruded rectangle is a box);
//! extruded to a point it is capped at its base. A surface or B-rep is extruded with its naked
//! edges and comes out closed. Planarity and joining use [`MODEL_TOLERANCE`].

use locus_kernel::{Brep, Point3, Vector3};
use locus_runtime::{DataType, NodeError, NodeType, Port, Shared, Value};

use super::brep::surface_node;
use crate::curve::curve_from_value;

/// Id of [`extrude`].
pub const EXTRUDE: &str = "surface.extrude";
/// Id of [`extrude_point`].
pub const EXTRUDE_POINT: &str = "surface.extrude_point";

/// The tolerance for planarity, closure and joining: 0.001 model units, Rhino's default
/// absolute tolerance, which Grasshopper's components use.
pub const MODEL_TOLERANCE: f64 = 0.001;

/// Registers Extrude and Extrude Point.
pub fn register(registry: &mut locus_runtime::NodeRegistry) {
    registry.register(extrude());
    registry.register(extrude_point());
}

fn base_port() -> Port {
    Port::new("Base", "B", DataType::Generic)
        .doc("Profile curve (line, arc, circle, polyline or NURBS curve), surface or open B-rep.")
}

/// What an extrusion starts from.
enum Profile {
    Curve(Shared<locus_kernel::Curve>),
    Brep(Brep),
}

fn profile(value: Option<Value>) -> Result<Profile, NodeError> {
    let value = value.ok_or_else(|| NodeError::from("input B has no item"))?;
    if let Some(c) = curve_from_value(&value) {
        if !c.is_valid() {
            return Err("input B: the curve is not valid (not finite or degenerate)".into());
        }
        return Ok(Profile::Curve(c));
    }
    let brep = match &value {
        Value::Surface(s) => Brep::from_surface((**s).clone())?,
        Value::Brep(b) => (**b).clone(),
        Value::Box(b) => Brep::from_box(b)?,
        other => {
            return Err(NodeError(format!(
                "input B: a {} cannot be extruded; give a curve, surface or brep",
                other.data_type().name().to_lowercase()
            )));
        }
    };
    let finite = brep.vertices().iter().all(|v| v.point.is_finite())
        && brep.faces().iter().all(|f| f.surface.is_finite());
    if !finite {
        return Err("input B: the geometry has a coordinate that is not finite".into());
    }
    Ok(Profile::Brep(brep))
}

/// Extrude \[Extr\]: a curve or surface swept along a vector.
pub fn extrude() -> NodeType {
    surface_node(EXTRUDE, "Extrude", "Extr", "Freeform")
        .gh_guid("962034e9-cc27-4394-afc4-5c16e3447cf9")
        .description(
            "Extrudes a curve or surface along a vector into a B-rep. A curve gives one face \
             per kink-free piece (u along the curve, v along the vector from 0 to its length), \
             joined; a closed planar curve extruded out of its plane is capped at both ends \
             and becomes a closed solid (a rectangle gives a box). A surface or open B-rep is \
             joined with its moved copy and the sweep of its naked edges into a closed solid. \
             A zero vector and closed B-reps are errors.",
        )
        .input(base_port())
        .input(
            Port::new("Direction", "D", DataType::Vector)
                .default_value(Vector3::Z)
                .doc("Extrusion direction and distance. Default the unit z vector."),
        )
        .output(Port::new("Extrusion", "E", DataType::Brep).doc("The extrusion, a B-rep."))
        .solve(|s| {
            let base = profile(s.value(0))?;
            let d = *s.item::<Vector3>(1)?;
            if !d.is_finite() {
                return Err("input D: the direction is not finite".into());
            }
            if d.length() == 0.0 {
                return Err("input D: the direction is zero".into());
            }
            let brep = match base {
                Profile::Curve(c) => Brep::from_curve_extrusion(&c, d, MODEL_TOLERANCE)?,
                Profile::Brep(b) => b.extruded(d, MODEL_TOLERANCE)?,
            };
            s.set(0, Shared::new(brep));
            Ok(())
        })
}

/// Extrude Point \[Extr\]: a curve or surface extruded to a point.
pub fn extrude_point() -> NodeType {
    surface_node(EXTRUDE_POINT, "Extrude Point", "Extr", "Freeform")
        .gh_guid("be6636b2-2f1a-4d42-897b-fdef429b6f17")
        .description(
            "Extrudes a curve or surface to a point into a B-rep of straight lines from the \
             profile to the point (a cone on a circle, a pyramid on a polygon). A curve gives \
             one face per kink-free piece (u along the curve, v from the curve at 0 to the tip \
             at 1), joined; a closed planar curve with the tip off its plane is capped at its \
             base and becomes a closed solid. A surface or open B-rep is joined with the lines \
             from its naked edges to the tip.",
        )
        .input(base_port())
        .input(
            Port::new("Point", "P", DataType::Point).doc("The tip of the extrusion. No default."),
        )
        .output(Port::new("Extrusion", "E", DataType::Brep).doc("The extrusion, a B-rep."))
        .solve(|s| {
            let base = profile(s.value(0))?;
            let apex = *s.item::<Point3>(1)?;
            if !apex.is_finite() {
                return Err("input P: the point is not finite".into());
            }
            let brep = match base {
                Profile::Curve(c) => Brep::from_point_extrusion(&c, apex, MODEL_TOLERANCE)?,
                Profile::Brep(b) => b.extruded_to_point(apex, MODEL_TOLERANCE)?,
            };
            s.set(0, Shared::new(brep));
            Ok(())
        })
}

#[cfg(test)]
mod tests {
    use locus_kernel::{Circle, Curve, Plane, Polyline};
    use locus_runtime::{DataTree, Level, NodeCall, NodeCallResult};

    use super::*;

    fn square() -> Value {
        let pts = vec![
            Point3::ORIGIN,
            Point3::new(1.0, 0.0, 0.0),
            Point3::new(1.0, 1.0, 0.0),
            Point3::new(0.0, 1.0, 0.0),
            Point3::ORIGIN,
        ];
        Value::Curve(Shared::new(Curve::from(Polyline::new(pts).unwrap())))
    }

    fn run(node: NodeType, base: Value, second: Value) -> NodeCallResult {
        NodeCall::new(&node)
            .input(DataTree::from_item(base))
            .input(DataTree::from_item(second))
            .run()
    }

    fn brep(r: &NodeCallResult) -> Shared<Brep> {
        match r.outputs[0].values().next().flatten() {
            Some(Value::Brep(b)) => b,
            other => panic!("no brep: {other:?} {:?}", r.messages),
        }
    }

    fn error(r: &NodeCallResult) -> String {
        r.messages
            .iter()
            .find(|m| m.level == Level::Error)
            .map(|m| m.text.clone())
            .unwrap_or_default()
    }

    #[test]
    fn extruded_square_is_a_closed_box_of_volume_two() {
        let r = run(
            extrude(),
            square(),
            Value::Vector(Vector3::new(0.0, 0.0, 2.0)),
        );
        let b = brep(&r);
        assert!(b.is_solid());
        assert_eq!(b.faces().len(), 6);
        assert!((b.volume().unwrap() - 2.0).abs() < 1e-12);
    }

    #[test]
    fn extruded_surface_and_circle() {
        let disc = Circle::new(Plane::WORLD_XY, 1.0).unwrap();
        let r = run(
            extrude(),
            Value::Circle(disc),
            Value::Vector(Vector3::new(0.0, 0.0, 1.0)),
        );
        let b = brep(&r);
        assert!(b.is_solid());
        assert!((b.volume().unwrap() - std::f64::consts::PI).abs() < 1e-9);
        // A line extruded is one open face.
        let line = Value::Line(locus_kernel::Line::new(
            Point3::ORIGIN,
            Point3::new(10.0, 0.0, 0.0),
        ));
        let b = brep(&run(
            extrude(),
            line,
            Value::Vector(Vector3::new(0.0, 3.0, 0.0)),
        ));
        assert!(!b.is_solid());
        assert!((b.area().unwrap() - 30.0).abs() < 1e-12);
    }

    #[test]
    fn extrude_point_makes_a_pyramid() {
        let r = run(
            extrude_point(),
            square(),
            Value::Point(Point3::new(0.0, 0.0, 3.0)),
        );
        let b = brep(&r);
        assert!(b.is_solid());
        assert!((b.volume().unwrap() - 1.0).abs() < 1e-12);
    }

    #[test]
    fn bad_input_is_an_error() {
        let r = run(extrude(), square(), Value::Vector(Vector3::ZERO));
        assert!(error(&r).contains("zero"), "{:?}", r.messages);
        let r = run(extrude(), Value::Number(1.0), Value::Vector(Vector3::Z));
        assert!(error(&r).contains("cannot be extruded"));
        let r = run(
            extrude_point(),
            square(),
            Value::Point(Point3::new(f64::NAN, 0.0, 0.0)),
        );
        assert!(error(&r).contains("not finite"));
        let boxed = locus_kernel::OrientedBox::new(
            Plane::WORLD_XY,
            locus_kernel::Interval::UNIT,
            locus_kernel::Interval::UNIT,
            locus_kernel::Interval::UNIT,
        );
        let r = run(extrude(), Value::Box(boxed), Value::Vector(Vector3::Z));
        assert!(error(&r).contains("closed"));
    }
}

//! Vector › Point › Pull Point: a point pulled onto points, curves, surfaces, planes and boxes.
//!
//! Each piece of geometry pulls the point to its own closest point: a point to itself, a line,
//! circle, arc or curve to the curve's closest point (the kernel's global search, ends and
//! kinks included), a surface to the surface's closest point, a plane to the foot of the
//! perpendicular and a box to the nearest point of its six faces (a point inside the box moves
//! out to the nearest face).
//!
//! With *Closest* true (the default) the result is the pull to the nearest piece of geometry;
//! on a tie the first in the list wins. With *Closest* false every piece pulls at once: the
//! point moves by the sum of the pull vectors. Grasshopper documents the input only as "only
//! use the closest pulled point"; the summed pull is our reading of what using every pulled
//! point means for a single output point.

use locus_kernel::{Curve, Point3, Vector3};
use locus_runtime::{DataType, NodeError, NodeRegistry, NodeType, Port, Value};

use super::finite_point;

/// Id of [`pull_point`].
pub const PULL_POINT: &str = "vector.pull_point";

/// Registers Pull Point.
pub fn register(registry: &mut NodeRegistry) {
    registry.register(pull_point());
}

/// The point of `geometry` closest to `p`, or why there is none.
fn pull_onto(geometry: &Value, p: Point3) -> Result<Point3, NodeError> {
    Ok(match geometry {
        Value::Point(q) => *q,
        Value::Line(line) => line.closest_point(p),
        Value::Circle(circle) => circle.closest_point(p),
        Value::Arc(arc) => Curve::from(*arc).closest_point(p)?.point,
        Value::Curve(curve) => curve.closest_point(p)?.point,
        Value::Surface(surface) => surface.closest_point(p)?.point,
        Value::Plane(plane) => plane.closest_point(p),
        Value::Box(b) => b.closest_point_on_boundary(p),
        other => {
            return Err(NodeError(format!(
                "cannot pull a point onto a {}",
                other.data_type().name().to_lowercase()
            )));
        }
    })
}

/// Pull Point \[Pull\]: a point pulled onto a list of geometry.
pub fn pull_point() -> NodeType {
    NodeType::new(PULL_POINT, "Pull Point", "Pull", "Vector")
        .gh_guid("902289da-28dc-454b-98d4-b8f8aa234516")
        .subcategory("Point")
        .description(
            "Pulls a point onto geometry: points, lines, circles, arcs, curves, surfaces, \
             planes and boxes (onto a box's faces, even from inside). With Closest (the \
             default) the point goes to the closest point of the nearest piece of geometry; \
             otherwise every piece pulls at once and the point moves by the sum of the pull \
             vectors. Items that are not geometry are reported as errors and skipped.",
        )
        .input(Port::new("Point", "P", DataType::Point).doc("The point to pull."))
        .input(
            Port::new("Geometry", "G", DataType::Generic)
                .doc(
                    "The geometry that pulls: a list of points, curves, surfaces, planes or boxes.",
                )
                .list(),
        )
        .input(
            Port::new("Closest", "C", DataType::Boolean)
                .doc(
                    "Whether only the nearest geometry pulls (true), or all pull at once and \
                     their pull vectors add up (false). Default true.",
                )
                .default_value(true),
        )
        .output(
            Port::new("Closest Point", "P", DataType::Point)
                .doc("The pulled point: on the nearest geometry when Closest is true."),
        )
        .output(
            Port::new("Distance", "D", DataType::Number)
                .doc("The distance from P to the pulled point, in model units."),
        )
        .solve(|s| {
            let p = finite_point(*s.item::<Point3>(0)?, "point P")?;
            let closest_only = *s.item::<bool>(2)?;
            let Some(branch) = s.branch(1) else {
                return Err("input G has no geometry".into());
            };
            let mut nearest: Option<(f64, Point3)> = None;
            let mut sum = Vector3::ZERO;
            let mut pulled_any = false;
            let mut skipped = Vec::new();
            for (index, value) in branch.values().enumerate() {
                let Some(value) = value else { continue };
                match pull_onto(&value, p) {
                    Ok(q) => {
                        pulled_any = true;
                        let d = q.distance(p);
                        if nearest.is_none_or(|(best, _)| d < best) {
                            nearest = Some((d, q));
                        }
                        sum += q - p;
                    }
                    Err(e) => skipped.push(format!("geometry item {index}: {e}")),
                }
            }
            for message in skipped {
                s.error(message);
            }
            if !pulled_any {
                return Err("no geometry to pull onto".into());
            }
            let pulled = if closest_only {
                nearest.map_or(p, |(_, q)| q)
            } else {
                p + sum
            };
            let pulled = finite_point(pulled, "the pulled point")?;
            s.set(0, pulled);
            s.set(1, pulled.distance(p));
            Ok(())
        })
}

#[cfg(test)]
mod tests {
    use locus_kernel::{
        Arc, Circle, Interval, Line, NurbsSurface, OrientedBox, Plane, Sphere, Transform,
    };
    use locus_runtime::{Branch, DataTree, Level, NodeCall, Shared};

    use super::*;
    use crate::vector::test_support::{assert_clean, assert_error, is_null, messages, only};

    fn geometry(values: Vec<Value>) -> DataTree {
        let mut b = Branch::new(DataType::Generic);
        for v in values {
            b.push_value(v);
        }
        let mut t = DataTree::new();
        t.insert(locus_runtime::TreePath::zero(), b);
        t
    }

    fn pull(p: Point3, g: Vec<Value>, closest: bool) -> locus_runtime::NodeCallResult {
        NodeCall::new(&pull_point())
            .input(DataTree::from_item(p))
            .input(geometry(g))
            .input(DataTree::from_item(closest))
            .run()
    }

    fn line() -> Value {
        Value::Line(Line::new(Point3::ORIGIN, Point3::new(10.0, 0.0, 0.0)))
    }

    #[test]
    fn pull_onto_a_line_and_a_point() {
        let r = pull(Point3::new(3.0, 4.0, 0.0), vec![line()], true);
        assert_clean(&r);
        assert_eq!(only::<Point3>(&r, 0), Point3::new(3.0, 0.0, 0.0));
        assert_eq!(only::<f64>(&r, 1), 4.0);
        // Past the end of the segment the end point is closest.
        let r = pull(Point3::new(13.0, 4.0, 0.0), vec![line()], true);
        assert_eq!(only::<Point3>(&r, 0), Point3::new(10.0, 0.0, 0.0));
        assert_eq!(only::<f64>(&r, 1), 5.0);
        // The nearest of several wins.
        let q = Value::Point(Point3::new(3.0, 5.0, 0.0));
        let r = pull(Point3::new(3.0, 4.0, 0.0), vec![line(), q], true);
        assert_eq!(only::<Point3>(&r, 0), Point3::new(3.0, 5.0, 0.0));
        assert_eq!(only::<f64>(&r, 1), 1.0);
    }

    #[test]
    fn pull_onto_circles_arcs_and_curves() {
        let circle = Circle::new(Plane::WORLD_XY, 2.0).unwrap();
        let p = Point3::new(0.0, 5.0, 1.0);
        let r = pull(p, vec![Value::Circle(circle)], true);
        assert!(only::<Point3>(&r, 0).abs_diff_eq(Point3::new(0.0, 2.0, 0.0), 1e-14));
        assert!((only::<f64>(&r, 1) - 10f64.sqrt()).abs() < 1e-14);
        // The quarter arc from angle 0 to π/2 does not reach (−5, 0): its start is nearest.
        let arc = Arc::new(circle, Interval::new(0.0, std::f64::consts::FRAC_PI_2)).unwrap();
        let r = pull(Point3::new(-5.0, -0.1, 0.0), vec![Value::Arc(arc)], true);
        assert!(only::<Point3>(&r, 0).abs_diff_eq(Point3::new(0.0, 2.0, 0.0), 1e-12));
        // A NURBS curve (the circle's NURBS form) gives the same pull as the exact circle.
        let nurbs = Value::Curve(Shared::new(Curve::Nurbs(circle.to_nurbs())));
        let r = pull(p, vec![nurbs], true);
        assert!(only::<Point3>(&r, 0).abs_diff_eq(Point3::new(0.0, 2.0, 0.0), 1e-9));
    }

    #[test]
    fn pull_onto_a_surface_as_in_the_face_direction_tutorial() {
        // The book's face-direction tutorial pulls a point onto a surface; here a sphere of
        // radius 2 pulls (0, 0, 5) to its north pole, 3 units away.
        let sphere = Sphere::new(Point3::ORIGIN, 2.0).unwrap();
        let surface: NurbsSurface = sphere.to_nurbs().unwrap();
        let r = pull(
            Point3::new(0.0, 0.0, 5.0),
            vec![Value::Surface(Shared::new(surface))],
            true,
        );
        assert_clean(&r);
        assert!(only::<Point3>(&r, 0).abs_diff_eq(Point3::new(0.0, 0.0, 2.0), 1e-9));
        assert!((only::<f64>(&r, 1) - 3.0).abs() < 1e-9);
    }

    #[test]
    fn pull_onto_planes_and_boxes() {
        let plane = Plane::WORLD_XY.translated(Vector3::new(0.0, 0.0, 1.0));
        let r = pull(Point3::new(2.0, 3.0, 4.0), vec![Value::Plane(plane)], true);
        assert_eq!(only::<Point3>(&r, 0), Point3::new(2.0, 3.0, 1.0));
        let b = OrientedBox::new(
            Plane::WORLD_XY,
            Interval::new(0.0, 4.0),
            Interval::new(0.0, 4.0),
            Interval::new(0.0, 4.0),
        );
        // From inside, the point moves out to the nearest face.
        let r = pull(Point3::new(2.0, 3.5, 2.0), vec![Value::Box(b)], true);
        assert_eq!(only::<Point3>(&r, 0), Point3::new(2.0, 4.0, 2.0));
        assert_eq!(only::<f64>(&r, 1), 0.5);
    }

    #[test]
    fn pull_by_all_adds_the_pull_vectors() {
        // Two parallel lines at y = 0 and y = 10 pull (3, 4) by <0, −4> and <0, 6>.
        let other = Value::Line(Line::new(
            Point3::new(0.0, 10.0, 0.0),
            Point3::new(10.0, 10.0, 0.0),
        ));
        let r = pull(Point3::new(3.0, 4.0, 0.0), vec![line(), other], false);
        assert_clean(&r);
        assert_eq!(only::<Point3>(&r, 0), Point3::new(3.0, 6.0, 0.0));
        assert_eq!(only::<f64>(&r, 1), 2.0);
    }

    #[test]
    fn pull_skips_what_is_not_geometry() {
        let r = pull(
            Point3::new(3.0, 4.0, 0.0),
            vec![Value::Number(2.0), line(), Value::Vector(Vector3::X)],
            true,
        );
        let errors = messages(&r, Level::Error);
        assert_eq!(errors.len(), 2, "{errors:?}");
        assert!(errors[0].contains("item 0") && errors[0].contains("number"));
        assert!(errors[1].contains("item 2") && errors[1].contains("vector"));
        assert_eq!(only::<Point3>(&r, 0), Point3::new(3.0, 0.0, 0.0));
        // Nothing to pull onto at all is an error and a null.
        let r = pull(Point3::ORIGIN, vec![Value::Text("x".into())], true);
        assert_eq!(messages(&r, Level::Error).len(), 2);
        assert!(is_null(&r, 0) && is_null(&r, 1));
    }

    #[test]
    fn pull_a_nan_point_is_an_error() {
        let r = pull(Point3::new(f64::NAN, 0.0, 0.0), vec![line()], true);
        assert_error(&r, "point P");
        assert!(is_null(&r, 0));
    }

    #[test]
    fn pull_onto_transformed_geometry() {
        // A rotated line still pulls to its closest point.
        let rot = Transform::rotation_z(std::f64::consts::FRAC_PI_2);
        let l = Line::new(Point3::ORIGIN, Point3::new(10.0, 0.0, 0.0)).transformed(&rot);
        let r = pull(Point3::new(4.0, 3.0, 0.0), vec![Value::Line(l)], true);
        assert!(only::<Point3>(&r, 0).abs_diff_eq(Point3::new(0.0, 3.0, 0.0), 1e-14));
    }
}

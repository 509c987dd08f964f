//! Curve › Analysis: Deconstruct Arc, the base plane, radius and angle domain of an arc or a
//! circle.

use locus_kernel::{Curve, Interval, tolerance::DOCUMENT_TOLERANCE};
use locus_runtime::{DataType, NodeRegistry, NodeType, Port};

use super::curve_input;

/// Id of [`deconstruct_arc`].
pub const DECONSTRUCT_ARC: &str = "curve.deconstruct_arc";

/// Registers the Deconstruct Arc node.
pub fn register(registry: &mut NodeRegistry) {
    registry.register(deconstruct_arc());
}

/// Deconstruct Arc \[DArc\]: the base plane, radius and angle domain of an arc or circle.
pub fn deconstruct_arc() -> NodeType {
    NodeType::new(DECONSTRUCT_ARC, "Deconstruct Arc", "DArc", "Curve")
        .subcategory("Analysis")
        .gh_guid("23862862-049a-40be-b558-2418aacbd916")
        .description(&format!(
            "Takes an arc or a circle apart: its base plane (origin at the centre, x axis \
             towards the angle 0), its radius and its angle domain in radians (0 to 2π for a \
             circle). A NURBS curve that traces an arc or circle within the document \
             tolerance ({DOCUMENT_TOLERANCE}) counts as one, with its plane's x axis through \
             the curve's start; any other curve is an error."
        ))
        .input(Port::new("Arc", "A", DataType::Curve).doc("Arc or circle to deconstruct."))
        .output(
            Port::new("Base Plane", "B", DataType::Plane).doc("Base plane of the arc or circle."),
        )
        .output(Port::new("Radius", "R", DataType::Number).doc("Radius of the arc or circle."))
        .output(
            Port::new("Angle", "A", DataType::Domain).doc("Angle domain of the arc, in radians."),
        )
        .solve(|s| {
            let curve = curve_input(s, 0)?;
            let (plane, radius, angle) = match curve.as_ref() {
                Curve::Circle { circle, .. } => (
                    circle.plane,
                    circle.radius,
                    Interval::new(0.0, std::f64::consts::TAU),
                ),
                Curve::Arc { arc, .. } => (arc.circle.plane, arc.circle.radius, arc.angle),
                other => {
                    let arc = other.try_arc(DOCUMENT_TOLERANCE).ok_or_else(|| {
                        format!("the curve is not an arc or a circle (within {DOCUMENT_TOLERANCE})")
                    })?;
                    (arc.circle.plane, arc.circle.radius, arc.angle)
                }
            };
            s.set(0, plane);
            s.set(1, radius);
            s.set(2, angle);
            Ok(())
        })
}

#[cfg(test)]
mod tests {
    use std::f64::consts::{FRAC_PI_2, TAU};

    use locus_kernel::{Arc, Circle, Line, Plane, Point3};
    use locus_runtime::{DataTree, NodeCall};

    use super::*;
    use crate::curve::test_support::*;

    fn run(tree: DataTree) -> locus_runtime::NodeCallResult {
        NodeCall::new(&deconstruct_arc()).input(tree).run()
    }

    #[test]
    fn circles_and_arcs_come_apart() {
        let plane = Plane::WORLD_XY;
        let circle = Circle::new(plane, 3.0).unwrap();
        let r = run(DataTree::from_item(circle));
        assert_clean(&r);
        assert_eq!(only::<Plane>(&r, 0), plane);
        assert_eq!(only::<f64>(&r, 1), 3.0);
        assert_eq!(only::<Interval>(&r, 2), Interval::new(0.0, TAU));
        let arc = Arc::new(circle, Interval::new(0.5, FRAC_PI_2)).unwrap();
        let r = run(curve_tree(arc));
        assert_clean(&r);
        assert_eq!(only::<Interval>(&r, 2), Interval::new(0.5, FRAC_PI_2));
    }

    #[test]
    fn a_nurbs_arc_counts_and_a_line_does_not() {
        let circle = Circle::new(Plane::WORLD_XY, 2.0).unwrap();
        let arc = Arc::new(circle, Interval::new(0.0, FRAC_PI_2)).unwrap();
        let nurbs = Curve::Nurbs(Curve::from(arc).to_nurbs());
        let r = run(curve_tree(nurbs));
        assert_clean(&r);
        assert!((only::<f64>(&r, 1) - 2.0).abs() < 1e-12);
        let angle = only::<Interval>(&r, 2);
        assert!((angle.length() - FRAC_PI_2).abs() < 1e-12, "{angle:?}");
        assert!(only::<Plane>(&r, 0).origin.distance(Point3::ORIGIN) < 1e-12);
        let line = Line::new(Point3::ORIGIN, Point3::new(1.0, 0.0, 0.0));
        assert_error(&run(curve_tree(line)), "not an arc or a circle");
    }
}

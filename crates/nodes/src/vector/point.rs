//! Vector › Point: points from coordinates and back, the distance between two points, and the
//! point between two points at a parameter.

use locus_kernel::Point3;
use locus_runtime::{DataType, NodeRegistry, NodeType, Port};

use super::{finite_number, finite_point, warn_unless_finite};

/// Id of [`construct_point`].
pub const CONSTRUCT_POINT: &str = "vector.construct_point";
/// Id of [`deconstruct_point`].
pub const DECONSTRUCT_POINT: &str = "vector.deconstruct_point";
/// Id of [`distance`].
pub const DISTANCE: &str = "vector.distance";
/// Id of [`point_between`].
pub const POINT_BETWEEN: &str = "vector.point_between";

/// Registers the Point nodes (Pull Point is in [`super::pull`]).
pub fn register(registry: &mut NodeRegistry) {
    for t in [
        construct_point(),
        deconstruct_point(),
        distance(),
        point_between(),
    ] {
        registry.register(t);
    }
}

fn point_node(id: &str, name: &str, nickname: &str) -> NodeType {
    NodeType::new(id, name, nickname, "Vector").subcategory("Point")
}

/// Construct Point \[Pt\]: a point from its x, y and z coordinates.
pub fn construct_point() -> NodeType {
    point_node(CONSTRUCT_POINT, "Construct Point", "Pt")
        .gh_guid("3581f42a-9592-4549-bd6b-1c0fc39d067b")
        .description(
            "Makes a point from its {x, y, z} coordinates in the world coordinate system. A \
             NaN or infinite coordinate is an error.",
        )
        .input(
            Port::new("X coordinate", "X", DataType::Number)
                .doc("The x coordinate, in model units. Default 0.")
                .default_value(0.0),
        )
        .input(
            Port::new("Y coordinate", "Y", DataType::Number)
                .doc("The y coordinate, in model units. Default 0.")
                .default_value(0.0),
        )
        .input(
            Port::new("Z coordinate", "Z", DataType::Number)
                .doc("The z coordinate, in model units. Default 0.")
                .default_value(0.0),
        )
        .output(Port::new("Point", "Pt", DataType::Point).doc("The point (X, Y, Z)."))
        .lift3(|x: &f64, y: &f64, z: &f64| {
            let x = finite_number(*x, "coordinate X")?;
            let y = finite_number(*y, "coordinate Y")?;
            let z = finite_number(*z, "coordinate Z")?;
            Ok(Point3::new(x, y, z))
        })
}

/// Deconstruct \[pDecon\]: the coordinates of a point.
pub fn deconstruct_point() -> NodeType {
    point_node(DECONSTRUCT_POINT, "Deconstruct", "pDecon")
        .gh_guid("9abae6b7-fa1d-448c-9209-4a8155345841")
        .description(
            "Splits a point into its x, y and z coordinates in the world system. A NaN or \
             infinite coordinate is passed on with a warning.",
        )
        .input(Port::new("Point", "P", DataType::Point).doc("The point to deconstruct."))
        .output(
            Port::new("X component", "X", DataType::Number)
                .doc("The x coordinate, in model units."),
        )
        .output(
            Port::new("Y component", "Y", DataType::Number)
                .doc("The y coordinate, in model units."),
        )
        .output(
            Port::new("Z component", "Z", DataType::Number)
                .doc("The z coordinate, in model units."),
        )
        .lift1_with_plain(
            // The sum of the coordinates is finite only when they all are (or overflows, a
            // case the reporting loop then takes): one check, nothing to report.
            |p: &Point3| (p.x + p.y + p.z).is_finite(),
            |p: &Point3| (p.x, p.y, p.z),
            |p: &Point3, report| {
                warn_unless_finite(report, p.is_finite(), "point P");
                Ok((p.x, p.y, p.z))
            },
        )
}

/// Distance \[Dist\]: the Euclidean distance between two points.
pub fn distance() -> NodeType {
    point_node(DISTANCE, "Distance", "Dist")
        .gh_guid("93b8e93d-f932-402c-b435-84be04d87666")
        .description(
            "Computes the Euclidean distance between two points, \
             √((xB − xA)² + (yB − yA)² + (zB − zA)²).",
        )
        .input(Port::new("Point A", "A", DataType::Point).doc("The first point."))
        .input(Port::new("Point B", "B", DataType::Point).doc("The second point."))
        .output(
            Port::new("Distance", "D", DataType::Number)
                .doc("The distance from A to B, in model units; never negative."),
        )
        .lift2_with_plain(
            // Finite points give a finite distance, or one that overflows (a case the
            // reporting function then takes, with the same result); a NaN or infinite
            // coordinate gives a NaN or infinite one. One check, nothing to report.
            |a: &Point3, b: &Point3| a.distance(*b).is_finite(),
            |a: &Point3, b: &Point3| (a.distance(*b),),
            |a: &Point3, b: &Point3, _| {
                let a = finite_point(*a, "point A")?;
                let b = finite_point(*b, "point B")?;
                Ok((a.distance(b),))
            },
        )
}

/// Point Between: the point at parameter `t` on the way from A to B, `A + t (B − A)`.
///
/// Grasshopper has no component of this name (users write the formula in an Expression or
/// evaluate a line); it is the book's vector equation of a line through two points.
pub fn point_between() -> NodeType {
    point_node(POINT_BETWEEN, "Point Between", "PtBtw")
        .description(
            "Finds the point at parameter t between two points: M = A + t (B − A), the \
             vector equation of the line through A and B. t = 0 gives A, t = 1 gives B and \
             t = 0.5 the midpoint; values outside 0 to 1 extrapolate beyond the points. Not \
             a Grasshopper component: Grasshopper users write this formula in an Expression.",
        )
        .input(Port::new("Point A", "A", DataType::Point).doc("The start point (t = 0)."))
        .input(Port::new("Point B", "B", DataType::Point).doc("The end point (t = 1)."))
        .input(
            Port::new("Parameter", "t", DataType::Number)
                .doc("The parameter along A to B, unitless: 0 at A, 1 at B. Default 0.5.")
                .default_value(0.5),
        )
        .output(Port::new("Point", "P", DataType::Point).doc("The point A + t (B − A)."))
        .lift3(|a: &Point3, b: &Point3, t: &f64| {
            let a = finite_point(*a, "point A")?;
            let b = finite_point(*b, "point B")?;
            let t = finite_number(*t, "parameter t")?;
            finite_point(a + (b - a) * t, "the point")
        })
}

#[cfg(test)]
mod tests {
    use locus_runtime::{DataTree, Level, NodeCall};

    use super::*;
    use crate::vector::test_support::{assert_clean, assert_error, is_null, items, messages, only};

    #[test]
    fn construct_point_with_defaults() {
        let r = NodeCall::new(&construct_point())
            .input(DataTree::from_item(2.0))
            .skip_input()
            .input(DataTree::from_item(1.0))
            .run();
        assert_clean(&r);
        assert_eq!(only::<Point3>(&r, 0), Point3::new(2.0, 0.0, 1.0));
    }

    #[test]
    fn construct_point_matches_lists_longest() {
        let r = NodeCall::new(&construct_point())
            .input(DataTree::from_list(vec![1.0, 2.0, 3.0]))
            .input(DataTree::from_item(5.0))
            .run();
        assert_eq!(
            items::<Point3>(&r.outputs[0]),
            vec![
                Some(Point3::new(1.0, 5.0, 0.0)),
                Some(Point3::new(2.0, 5.0, 0.0)),
                Some(Point3::new(3.0, 5.0, 0.0)),
            ]
        );
    }

    #[test]
    fn construct_point_rejects_nan() {
        let r = NodeCall::new(&construct_point())
            .input(DataTree::from_item(f64::NAN))
            .run();
        assert_error(&r, "coordinate X is not a finite number");
        assert!(is_null(&r, 0));
        let r = NodeCall::new(&construct_point())
            .skip_input()
            .skip_input()
            .input(DataTree::from_item(f64::INFINITY))
            .run();
        assert_error(&r, "coordinate Z");
    }

    #[test]
    fn deconstruct_point_round_trips() {
        let p = Point3::new(2.0, 3.0, 1.0);
        let r = NodeCall::new(&deconstruct_point())
            .input(DataTree::from_item(p))
            .run();
        assert_clean(&r);
        assert_eq!(only::<f64>(&r, 0), 2.0);
        assert_eq!(only::<f64>(&r, 1), 3.0);
        assert_eq!(only::<f64>(&r, 2), 1.0);
    }

    #[test]
    fn deconstruct_point_passes_nan_on_with_a_warning() {
        let r = NodeCall::new(&deconstruct_point())
            .input(DataTree::from_item(Point3::new(1.0, f64::NAN, 3.0)))
            .run();
        assert_eq!(
            messages(&r, Level::Warning),
            vec!["point P has a coordinate that is not finite; its numbers are not finite either"]
        );
        assert_eq!(only::<f64>(&r, 0), 1.0);
        assert!(only::<f64>(&r, 1).is_nan());
    }

    #[test]
    fn deconstruct_point_of_nothing_is_empty() {
        let r = NodeCall::new(&deconstruct_point()).run();
        assert!(r.outputs[0].values().next().is_none());
    }

    #[test]
    fn distance_of_the_book_vector_length() {
        // The book's vector a = <4, 3, 0> has length 5: the distance from the origin to (4, 3, 0).
        let r = NodeCall::new(&distance())
            .input(DataTree::from_item(Point3::ORIGIN))
            .input(DataTree::from_item(Point3::new(4.0, 3.0, 0.0)))
            .run();
        assert_clean(&r);
        assert_eq!(only::<f64>(&r, 0), 5.0);
        // Symmetric.
        let r = NodeCall::new(&distance())
            .input(DataTree::from_item(Point3::new(1.0, 2.0, 3.0)))
            .input(DataTree::from_item(Point3::new(-1.0, 0.0, 4.0)))
            .run();
        assert_eq!(only::<f64>(&r, 0), 3.0);
    }

    #[test]
    fn distance_rejects_nan() {
        let r = NodeCall::new(&distance())
            .input(DataTree::from_item(Point3::new(f64::NAN, 0.0, 0.0)))
            .input(DataTree::from_item(Point3::ORIGIN))
            .run();
        assert_error(&r, "point A");
        assert!(is_null(&r, 0));
    }

    #[test]
    fn distance_over_a_list_reports_each_failing_item() {
        // Distance is a lifted item function: a failing item is a null with an error that
        // names its path and index, a null item stays null without one, and the shorter input
        // repeats its last item (longest list).
        let mut a = locus_runtime::Branch::new(DataType::Point);
        a.push(Point3::new(3.0, 4.0, 0.0));
        a.push(Point3::new(f64::NAN, 0.0, 0.0));
        a.push_null();
        a.push(Point3::new(0.0, 0.0, 2.0));
        let path = locus_runtime::TreePath::zero();
        let r = NodeCall::new(&distance())
            .input(DataTree::from_branches([(path.clone(), a)]))
            .input(DataTree::from_item(Point3::ORIGIN))
            .run();
        assert_eq!(
            items::<f64>(&r.outputs[0]),
            [Some(5.0), None, None, Some(2.0)]
        );
        let errors: Vec<_> = r
            .messages
            .iter()
            .filter(|m| m.level == Level::Error)
            .collect();
        assert_eq!(errors.len(), 1, "{:?}", r.messages);
        assert_eq!(
            (errors[0].path.as_ref(), errors[0].index),
            (Some(&path), Some(1))
        );
        assert_eq!(
            errors[0].text,
            "point A has a coordinate that is not finite"
        );
        assert_eq!(r.messages.len(), 1);
    }

    #[test]
    fn point_between_follows_the_book() {
        // The book's midpoint M = Q + 0.5 (P − Q).
        let q = Point3::new(1.0, 2.0, 3.0);
        let p = Point3::new(5.0, 6.0, -1.0);
        let r = NodeCall::new(&point_between())
            .input(DataTree::from_item(q))
            .input(DataTree::from_item(p))
            .run();
        assert_clean(&r);
        assert_eq!(only::<Point3>(&r, 0), Point3::new(3.0, 4.0, 1.0));
        let r = NodeCall::new(&point_between())
            .input(DataTree::from_item(q))
            .input(DataTree::from_item(p))
            .input(DataTree::from_list(vec![0.0, 1.0, 0.25, 2.0]))
            .run();
        assert_eq!(
            items::<Point3>(&r.outputs[0]),
            vec![
                Some(q),
                Some(p),
                Some(Point3::new(2.0, 3.0, 2.0)),
                Some(Point3::new(9.0, 10.0, -5.0)),
            ]
        );
    }

    #[test]
    fn point_between_rejects_nan_and_overflow() {
        let r = NodeCall::new(&point_between())
            .input(DataTree::from_item(Point3::ORIGIN))
            .input(DataTree::from_item(Point3::new(1.0, 0.0, 0.0)))
            .input(DataTree::from_item(f64::NAN))
            .run();
        assert_error(&r, "parameter t");
        let r = NodeCall::new(&point_between())
            .input(DataTree::from_item(Point3::ORIGIN))
            .input(DataTree::from_item(Point3::new(1e300, 0.0, 0.0)))
            .input(DataTree::from_item(1e300))
            .run();
        assert_error(&r, "not finite");
        assert!(is_null(&r, 0));
    }
}

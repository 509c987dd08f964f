//! Surface › Primitive and Analysis: boxes. Box 2Pt, Center Box, Domain Box and Box Rectangle
//! build them;
//! Box Properties and Deconstruct Box take them apart. Bounding Box is in
//! [`super::bounding_box`].
//!
//! A box is Grasshopper's (and Rhino's) `Box`: a plane and three intervals in its coordinates
//! ([`OrientedBox`]). It need not be solid: a box with a size of zero is *degenerate* (a
//! rectangle, a segment or a point). The nodes that build boxes output degenerate boxes as they
//! are, with a warning; Box Properties reports the degeneracy as a number.

use locus_kernel::{Curve, Interval, OrientedBox, Plane, Point3, tolerance};
use locus_runtime::{DataType, NodeError, NodeRegistry, NodeType, Port, Shared, Solve};

use crate::params::shapes::not_a_rectangle;

use super::brep::surface_node;

/// Id of [`box_2pt`].
pub const BOX_2PT: &str = "surface.box_2pt";
/// Id of [`center_box`].
pub const CENTER_BOX: &str = "surface.center_box";
/// Id of [`domain_box`].
pub const DOMAIN_BOX: &str = "surface.domain_box";
/// Id of [`box_rectangle`].
pub const BOX_RECTANGLE: &str = "surface.box_rectangle";
/// Id of [`box_properties`].
pub const BOX_PROPERTIES: &str = "surface.box_properties";
/// Id of [`deconstruct_box`].
pub const DECONSTRUCT_BOX: &str = "surface.deconstruct_box";

/// The degeneracy Box Properties reports for an invalid box (a non-orthonormal plane, a NaN
/// or a decreasing interval), after Grasshopper's 0 = box, 1 = rectangle, 2 = line,
/// 3 = point, 4 = invalid.
pub const INVALID_DEGENERACY: i64 = 4;

/// Registers the box nodes.
pub fn register(registry: &mut NodeRegistry) {
    for t in [
        box_2pt(),
        center_box(),
        domain_box(),
        box_rectangle(),
        box_properties(),
        deconstruct_box(),
    ] {
        registry.register(t);
    }
}

/// How many sizes of the box are zero, by Rhino's rule: a size counts as zero when it is at
/// most √ε ([`tolerance::SQRT_EPSILON`]) times the largest size. `None` for an invalid box.
pub fn degeneracy(b: &OrientedBox) -> Option<usize> {
    let largest = b.sizes().into_iter().fold(0.0, f64::max);
    b.degeneracy(tolerance::SQRT_EPSILON * largest)
}

/// Writes a new box to output 0, warning when it is flat, a segment or a point.
fn finish_box(s: &mut Solve<'_>, b: OrientedBox) -> Result<(), NodeError> {
    if !b.is_finite() {
        return Err("the box is not finite".into());
    }
    match degeneracy(&b) {
        Some(1) => s.warning("the box is flat: one of its sizes is zero"),
        Some(2) => s.warning("the box is a segment: two of its sizes are zero"),
        Some(3) => s.warning("the box is a point: all its sizes are zero"),
        _ => {}
    }
    s.set(0, b);
    Ok(())
}

/// Checks that the plane on input `input` (named `name`) can carry a box.
pub(crate) fn box_plane(s: &Solve<'_>, input: usize, name: &str) -> Result<Plane, NodeError> {
    let plane = *s.item::<Plane>(input)?;
    if !plane.is_finite() {
        return Err(format!("plane {name} is not finite").into());
    }
    if !plane.is_valid() {
        return Err(format!("plane {name} does not have orthonormal axes").into());
    }
    Ok(plane)
}

/// Box 2Pt \[Box\]: the box on a plane between two corner points.
pub fn box_2pt() -> NodeType {
    surface_node(BOX_2PT, "Box 2Pt", "Box", "Primitive")
        .gh_guid("2a43ef96-8f87-4892-8b94-237a47e8d3cf")
        .description(
            "Creates a box aligned with a plane from two opposite corners: along each axis of \
             the plane it runs from the smaller to the larger coordinate of the two points. \
             Points with the same coordinate along an axis give a flat box (a warning); NaN \
             or infinite points are an error.",
        )
        .input(
            Port::new("Point A", "A", DataType::Point)
                .doc("The first corner. Default (0, 0, 0).")
                .default_value(Point3::ORIGIN),
        )
        .input(
            Port::new("Point B", "B", DataType::Point)
                .doc("The opposite corner. Default (1, 1, 1).")
                .default_value(Point3::new(1.0, 1.0, 1.0)),
        )
        .input(
            Port::new("Plane", "P", DataType::Plane)
                .doc("The plane the box is aligned with. Default World XY.")
                .default_value(Plane::WORLD_XY),
        )
        .output(Port::new("Box", "B", DataType::Box).doc("The box, on plane P."))
        .solve(|s| {
            let a = *s.item::<Point3>(0)?;
            let b = *s.item::<Point3>(1)?;
            if !a.is_finite() || !b.is_finite() {
                return Err("point A or B has a coordinate that is not finite".into());
            }
            let plane = box_plane(s, 2, "P")?;
            let bx = OrientedBox::from_two_points(&plane, a, b)?;
            finish_box(s, bx)
        })
}

/// Center Box \[Box\]: the box centred on a plane's origin with given half-sizes.
pub fn center_box() -> NodeType {
    surface_node(CENTER_BOX, "Center Box", "Box", "Primitive")
        .gh_guid("28061aae-04fb-4cb5-ac45-16f3b66bc0a4")
        .description(
            "Creates a box centred on the origin of a plane, reaching X, Y and Z units along \
             the plane's axes in both directions, so that its sizes are 2X, 2Y and 2Z. \
             Negative sizes count as positive; a size of zero gives a flat box (a warning).",
        )
        .input(
            Port::new("Base", "B", DataType::Plane)
                .doc("The plane at the centre of the box. Default World XY.")
                .default_value(Plane::WORLD_XY),
        )
        .input(
            Port::new("X", "X", DataType::Number)
                .doc("Half the size along the plane's x axis, in model units. Default 1.")
                .default_value(1.0),
        )
        .input(
            Port::new("Y", "Y", DataType::Number)
                .doc("Half the size along the plane's y axis, in model units. Default 1.")
                .default_value(1.0),
        )
        .input(
            Port::new("Z", "Z", DataType::Number)
                .doc("Half the size along the plane's normal, in model units. Default 1.")
                .default_value(1.0),
        )
        .output(Port::new("Box", "B", DataType::Box).doc("The box, on the base plane."))
        .solve(|s| {
            let plane = box_plane(s, 0, "B")?;
            let (x, y, z) = (*s.item::<f64>(1)?, *s.item::<f64>(2)?, *s.item::<f64>(3)?);
            if !(x.is_finite() && y.is_finite() && z.is_finite()) {
                return Err(format!("the sizes X, Y, Z ({x}, {y}, {z}) must be finite").into());
            }
            finish_box(s, OrientedBox::centered(&plane, x, y, z)?)
        })
}

/// Domain Box \[Box\]: the box on a plane spanning three domains.
pub fn domain_box() -> NodeType {
    surface_node(DOMAIN_BOX, "Domain Box", "Box", "Primitive")
        .gh_guid("79aa7f47-397c-4d3f-9761-aaf421bb7f5f")
        .description(
            "Creates a box from a base plane and a domain along each of its axes, in plane \
             coordinates: the box holds the points base.point_at(x, y, z) with x in X, y in Y \
             and z in Z. Domains are kept as given (Deconstruct Box returns them); a \
             decreasing domain still spans the same extent, though Box Properties reports such \
             a box as invalid (degeneracy 4).",
        )
        .input(
            Port::new("Base", "B", DataType::Plane)
                .doc("The plane whose coordinates the domains are in. Default World XY.")
                .default_value(Plane::WORLD_XY),
        )
        .input(
            Port::new("X", "X", DataType::Domain)
                .doc("The extent along the plane's x axis, in model units. Default 0 To 1.")
                .default_value(Interval::UNIT),
        )
        .input(
            Port::new("Y", "Y", DataType::Domain)
                .doc("The extent along the plane's y axis, in model units. Default 0 To 1.")
                .default_value(Interval::UNIT),
        )
        .input(
            Port::new("Z", "Z", DataType::Domain)
                .doc("The extent along the plane's normal, in model units. Default 0 To 1.")
                .default_value(Interval::UNIT),
        )
        .output(Port::new("Box", "B", DataType::Box).doc("The box, on the base plane."))
        .solve(|s| {
            let plane = box_plane(s, 0, "B")?;
            let (x, y, z) = (
                *s.item::<Interval>(1)?,
                *s.item::<Interval>(2)?,
                *s.item::<Interval>(3)?,
            );
            if !(x.is_finite() && y.is_finite() && z.is_finite()) {
                return Err("the domains X, Y and Z must have finite ends".into());
            }
            finish_box(s, OrientedBox::new(plane, x, y, z))
        })
}

/// Box Rectangle \[BoxRec\]: the box standing on a rectangle.
pub fn box_rectangle() -> NodeType {
    surface_node(BOX_RECTANGLE, "Box Rectangle", "BoxRec", "Primitive")
        .gh_guid("d0a56c9e-2483-45e7-ab98-a450b97f1bc0")
        .description(
            "Creates the box whose base is a rectangle, H units high along the rectangle's \
             normal (the side that sees its corners run anticlockwise); a negative height \
             puts the box below the rectangle. The box's plane has its origin at the \
             rectangle's first corner and its x axis along the first side (locus's \
             rectangles are polylines, which do not keep the plane they were made on; \
             Grasshopper's keep it, so Deconstruct Box may give another plane and domains for \
             the same box). A height of zero gives a flat box (a warning); a curve that is \
             not a rectangle is an error.",
        )
        .input(
            Port::new("Rectangle", "R", DataType::Curve)
                .doc("The base: a closed planar polyline of four right-angled sides."),
        )
        .input(
            Port::new("Height", "H", DataType::Number)
                .doc("The height along the rectangle's normal, in model units. Default 1.")
                .default_value(1.0),
        )
        .output(Port::new("Box", "B", DataType::Box).doc("The box on the rectangle."))
        .solve(|s| {
            let rectangle = s.item::<Shared<Curve>>(0)?;
            if let Some(why) = not_a_rectangle(rectangle) {
                return Err(format!("R is not a rectangle: {why}").into());
            }
            let Curve::Polyline { polyline, .. } = rectangle.as_ref() else {
                return Err("R is not a rectangle".into());
            };
            let height = *s.item::<f64>(1)?;
            if !height.is_finite() {
                return Err(format!("height H is {height}, not a finite number").into());
            }
            let p = polyline.points();
            let (a, b) = (p[1] - p[0], p[3] - p[0]);
            let plane = Plane::from_frame(p[0], a, b)?;
            let z = Interval::new(height.min(0.0), height.max(0.0));
            finish_box(
                s,
                OrientedBox::new(
                    plane,
                    Interval::new(0.0, a.length()),
                    Interval::new(0.0, b.length()),
                    z,
                ),
            )
        })
}

/// Box Properties \[BoxProp\]: centre, diagonal, area, volume and degeneracy of a box.
pub fn box_properties() -> NodeType {
    surface_node(BOX_PROPERTIES, "Box Properties", "BoxProp", "Analysis")
        .gh_guid("af9cdb9d-9617-4827-bb3c-9efd88c76a70")
        .description(
            "Measures a box: its centre, the diagonal from its first corner to the opposite \
             one, its surface area and volume, and how degenerate it is. Sizes are the \
             absolute lengths of the box's domains. Degeneracy counts the sizes that are zero \
             (at most √ε times the largest size, Rhino's rule): 0 = box, 1 = rectangle, \
             2 = line, 3 = point, 4 = invalid (a plane without orthonormal axes, or a \
             decreasing domain).",
        )
        .input(Port::new("Box", "B", DataType::Box).doc("The box to measure."))
        .output(Port::new("Center", "C", DataType::Point).doc("The centre of the box."))
        .output(Port::new("Diagonal", "D", DataType::Vector).doc(
            "The diagonal, from the corner at the start of all three domains to the \
                 corner at their ends, in model units.",
        ))
        .output(
            Port::new("Area", "A", DataType::Number)
                .doc("The area of the six sides, in square model units."),
        )
        .output(Port::new("Volume", "V", DataType::Number).doc("The volume, in cubic model units."))
        .output(Port::new("Degeneracy", "d", DataType::Integer).doc(
            "0 = box, 1 = rectangle, 2 = line, 3 = point (the number of zero sizes), \
                 4 = invalid.",
        ))
        .solve(|s| {
            let b = *s.item::<OrientedBox>(0)?;
            if !b.is_finite() {
                return Err("the box is not finite".into());
            }
            s.set(0, b.center());
            s.set(1, b.diagonal());
            s.set(2, b.area());
            s.set(3, b.volume());
            let d = degeneracy(&b).map_or(INVALID_DEGENERACY, |d| d as i64);
            if d == INVALID_DEGENERACY {
                s.warning(
                    "the box is not valid (its plane is not orthonormal or a domain decreases)",
                );
            }
            s.set(4, d);
            Ok(())
        })
}

/// Deconstruct Box \[DeBox\]: the plane and three domains of a box.
pub fn deconstruct_box() -> NodeType {
    surface_node(DECONSTRUCT_BOX, "Deconstruct Box", "DeBox", "Analysis")
        .gh_guid("db7d83b1-2898-4ef9-9be5-4e94b4e2048d")
        .description(
            "Takes a box apart into its plane and its three domains in that plane's \
             coordinates, so that Domain Box on the outputs gives the box back. The plane is \
             the box's own (for Center Box its origin is the centre, for Box 2Pt and Bounding \
             Box it is the plane they were given); use Box Properties for the centre.",
        )
        .input(Port::new("Box", "B", DataType::Box).doc("The box to take apart."))
        .output(Port::new("Plane", "P", DataType::Plane).doc("The plane of the box."))
        .output(
            Port::new("X", "X", DataType::Domain)
                .doc("The extent along the plane's x axis, in plane coordinates."),
        )
        .output(
            Port::new("Y", "Y", DataType::Domain)
                .doc("The extent along the plane's y axis, in plane coordinates."),
        )
        .output(
            Port::new("Z", "Z", DataType::Domain)
                .doc("The extent along the plane's normal, in plane coordinates."),
        )
        .solve(|s| {
            let b = *s.item::<OrientedBox>(0)?;
            if !b.is_finite() {
                return Err("the box is not finite".into());
            }
            s.set(0, b.plane);
            s.set(1, b.x);
            s.set(2, b.y);
            s.set(3, b.z);
            Ok(())
        })
}

#[cfg(test)]
mod tests {
    use locus_kernel::Vector3;
    use locus_runtime::{DataTree, Level, NodeCall};

    use super::*;
    use crate::vector::test_support::{assert_clean, assert_error, is_null, messages, only};

    fn close(a: Point3, b: Point3) -> bool {
        a.distance(b) < 1e-12
    }

    fn tilted() -> Plane {
        Plane::from_normal(Point3::new(1.0, 2.0, 3.0), Vector3::new(1.0, -1.0, 2.0)).unwrap()
    }

    #[test]
    fn box_2pt_spans_the_points() {
        let r = NodeCall::new(&box_2pt())
            .input(DataTree::from_item(Point3::new(2.0, 3.0, 4.0)))
            .input(DataTree::from_item(Point3::new(0.0, -1.0, 1.0)))
            .run();
        assert_clean(&r);
        let b = only::<OrientedBox>(&r, 0);
        assert_eq!(b.plane, Plane::WORLD_XY);
        assert_eq!(
            (b.x, b.y, b.z),
            (
                Interval::new(0.0, 2.0),
                Interval::new(-1.0, 3.0),
                Interval::new(1.0, 4.0)
            )
        );
        // On a tilted plane the corners are still corners.
        let plane = tilted();
        let (a, c) = (
            plane.point_at(-1.0, 2.0, 0.5),
            plane.point_at(3.0, -2.0, 1.5),
        );
        let r = NodeCall::new(&box_2pt())
            .input(DataTree::from_item(a))
            .input(DataTree::from_item(c))
            .input(DataTree::from_item(plane))
            .run();
        let b = only::<OrientedBox>(&r, 0);
        assert!(b.corners().iter().any(|&p| close(p, a)));
        assert!(b.corners().iter().any(|&p| close(p, c)));
        assert!((b.volume() - 16.0).abs() < 1e-12);
    }

    #[test]
    fn box_2pt_bad_input() {
        // Coincident points: a point box, with a warning.
        let r = NodeCall::new(&box_2pt())
            .input(DataTree::from_item(Point3::ORIGIN))
            .input(DataTree::from_item(Point3::ORIGIN))
            .run();
        assert_eq!(messages(&r, Level::Warning).len(), 1);
        assert_eq!(only::<OrientedBox>(&r, 0).volume(), 0.0);
        let r = NodeCall::new(&box_2pt())
            .input(DataTree::from_item(Point3::new(f64::NAN, 0.0, 0.0)))
            .run();
        assert_error(&r, "not finite");
        assert!(is_null(&r, 0));
        let mut bad = Plane::WORLD_XY;
        bad.x_axis = Vector3::new(2.0, 0.0, 0.0);
        let r = NodeCall::new(&box_2pt())
            .skip_input()
            .skip_input()
            .input(DataTree::from_item(bad))
            .run();
        assert_error(&r, "orthonormal");
    }

    fn rectangle(points: &[Point3]) -> DataTree {
        let polyline = locus_kernel::Polyline::new(points.to_vec()).unwrap();
        DataTree::from_item(Shared::new(Curve::from(polyline)))
    }

    #[test]
    fn box_rectangle_stands_on_its_rectangle() {
        let plane = tilted();
        let corners: Vec<Point3> = [(0.0, 0.0), (3.0, 0.0), (3.0, 2.0), (0.0, 2.0), (0.0, 0.0)]
            .iter()
            .map(|&(x, y)| plane.point_at(x, y, 0.0))
            .collect();
        let r = NodeCall::new(&box_rectangle())
            .input(rectangle(&corners))
            .input(DataTree::from_item(4.0))
            .run();
        assert_clean(&r);
        let b = only::<OrientedBox>(&r, 0);
        assert!((b.volume() - 24.0).abs() < 1e-12);
        for (x, y, z) in [(0.0, 0.0, 0.0), (3.0, 2.0, 0.0), (3.0, 2.0, 4.0)] {
            let want = plane.point_at(x, y, z);
            assert!(b.corners().iter().any(|&p| close(p, want)), "{want:?}");
        }
        // A negative height hangs the box below; zero gives a flat box with a warning.
        let r = NodeCall::new(&box_rectangle())
            .input(rectangle(&corners))
            .input(DataTree::from_item(-1.0))
            .run();
        let b = only::<OrientedBox>(&r, 0);
        assert_eq!(b.z, Interval::new(-1.0, 0.0));
        assert!(
            b.corners()
                .iter()
                .any(|&p| close(p, plane.point_at(3.0, 2.0, -1.0)))
        );
        let r = NodeCall::new(&box_rectangle())
            .input(rectangle(&corners))
            .input(DataTree::from_item(0.0))
            .run();
        assert_eq!(messages(&r, Level::Warning).len(), 1);
    }

    #[test]
    fn box_rectangle_bad_input() {
        let skew = [
            Point3::ORIGIN,
            Point3::new(2.0, 0.0, 0.0),
            Point3::new(3.0, 1.0, 0.0),
            Point3::new(1.0, 1.0, 0.0),
            Point3::ORIGIN,
        ];
        let r = NodeCall::new(&box_rectangle())
            .input(rectangle(&skew))
            .run();
        assert_error(&r, "not a rectangle");
        assert!(is_null(&r, 0));
        let square = [
            Point3::ORIGIN,
            Point3::new(1.0, 0.0, 0.0),
            Point3::new(1.0, 1.0, 0.0),
            Point3::new(0.0, 1.0, 0.0),
            Point3::ORIGIN,
        ];
        let r = NodeCall::new(&box_rectangle())
            .input(rectangle(&square))
            .input(DataTree::from_item(f64::INFINITY))
            .run();
        assert_error(&r, "height H");
    }

    #[test]
    fn center_box_and_domain_box() {
        let r = NodeCall::new(&center_box())
            .input(DataTree::from_item(tilted()))
            .input(DataTree::from_item(1.0))
            .input(DataTree::from_item(-2.0))
            .input(DataTree::from_item(0.5))
            .run();
        assert_clean(&r);
        let b = only::<OrientedBox>(&r, 0);
        assert_eq!(b.center(), tilted().origin);
        assert_eq!(b.y, Interval::new(-2.0, 2.0));
        assert_eq!(b.volume(), 8.0);
        // Defaults: the 2 × 2 × 2 cube about the origin.
        let r = NodeCall::new(&center_box()).run();
        assert_eq!(only::<OrientedBox>(&r, 0).volume(), 8.0);
        let r = NodeCall::new(&center_box())
            .skip_input()
            .input(DataTree::from_item(f64::INFINITY))
            .run();
        assert_error(&r, "finite");
        let r = NodeCall::new(&center_box())
            .skip_input()
            .skip_input()
            .skip_input()
            .input(DataTree::from_item(0.0))
            .run();
        assert!(messages(&r, Level::Warning)[0].contains("flat"));

        let r = NodeCall::new(&domain_box())
            .skip_input()
            .input(DataTree::from_item(Interval::new(1.0, 3.0)))
            .run();
        assert_clean(&r);
        let b = only::<OrientedBox>(&r, 0);
        assert_eq!(
            (b.x, b.y, b.z),
            (Interval::new(1.0, 3.0), Interval::UNIT, Interval::UNIT)
        );
        let r = NodeCall::new(&domain_box())
            .skip_input()
            .input(DataTree::from_item(Interval::new(0.0, f64::NAN)))
            .run();
        assert_error(&r, "finite");
    }

    #[test]
    fn box_properties_by_hand() {
        let b = OrientedBox::new(
            Plane::WORLD_XY,
            Interval::new(0.0, 2.0),
            Interval::new(0.0, 3.0),
            Interval::new(0.0, 4.0),
        );
        let r = NodeCall::new(&box_properties())
            .input(DataTree::from_item(b))
            .run();
        assert_clean(&r);
        assert_eq!(only::<Point3>(&r, 0), Point3::new(1.0, 1.5, 2.0));
        assert_eq!(only::<Vector3>(&r, 1), Vector3::new(2.0, 3.0, 4.0));
        assert_eq!(only::<f64>(&r, 2), 52.0);
        assert_eq!(only::<f64>(&r, 3), 24.0);
        assert_eq!(only::<i64>(&r, 4), 0);
        // Degenerate boxes: a rectangle, a segment, a point.
        for (sizes, d) in [([2.0, 3.0, 0.0], 1), ([2.0, 0.0, 0.0], 2), ([0.0; 3], 3)] {
            let b = OrientedBox::new(
                Plane::WORLD_XY,
                Interval::new(0.0, sizes[0]),
                Interval::new(0.0, sizes[1]),
                Interval::new(0.0, sizes[2]),
            );
            let r = NodeCall::new(&box_properties())
                .input(DataTree::from_item(b))
                .run();
            assert_eq!(only::<i64>(&r, 4), d, "{sizes:?}");
            assert_eq!(only::<f64>(&r, 3), 0.0);
        }
        // A decreasing domain is invalid but still measured.
        let b = OrientedBox::new(
            Plane::WORLD_XY,
            Interval::new(2.0, 0.0),
            Interval::UNIT,
            Interval::UNIT,
        );
        let r = NodeCall::new(&box_properties())
            .input(DataTree::from_item(b))
            .run();
        assert_eq!(only::<i64>(&r, 4), INVALID_DEGENERACY);
        assert_eq!(only::<f64>(&r, 3), 2.0);
        assert_eq!(messages(&r, Level::Warning).len(), 1);
        let nan = OrientedBox::new(
            Plane::WORLD_XY,
            Interval::new(0.0, f64::NAN),
            Interval::UNIT,
            Interval::UNIT,
        );
        let r = NodeCall::new(&box_properties())
            .input(DataTree::from_item(nan))
            .run();
        assert_error(&r, "not finite");
        assert!(is_null(&r, 0));
    }

    #[test]
    fn deconstruct_box_round_trips_through_domain_box() {
        let b = OrientedBox::new(
            tilted(),
            Interval::new(-1.0, 2.0),
            Interval::new(0.5, 1.0),
            Interval::new(3.0, 4.0),
        );
        let r = NodeCall::new(&deconstruct_box())
            .input(DataTree::from_item(b))
            .run();
        assert_clean(&r);
        let (p, x, y, z) = (
            only::<Plane>(&r, 0),
            only::<Interval>(&r, 1),
            only::<Interval>(&r, 2),
            only::<Interval>(&r, 3),
        );
        let back = NodeCall::new(&domain_box())
            .input(DataTree::from_item(p))
            .input(DataTree::from_item(x))
            .input(DataTree::from_item(y))
            .input(DataTree::from_item(z))
            .run();
        assert_eq!(only::<OrientedBox>(&back, 0), b);
    }
}

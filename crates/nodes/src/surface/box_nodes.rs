//! Surface › Primitive and Analysis: boxes. Box 2Pt, Center Box, Domain Box and Bounding Box
//! build them; Box Properties and Deconstruct Box take them apart.
//!
//! A box is Grasshopper's (and Rhino's) `Box`: a plane and three intervals in its coordinates
//! ([`OrientedBox`]). It need not be solid: a box with a size of zero is *degenerate* (a
//! rectangle, a segment or a point). The nodes that build boxes output degenerate boxes as they
//! are, with a warning; Box Properties reports the degeneracy as a number.
//!
//! **Bounding Box** is the variant of Grasshopper's component with a Union input (GUID
//! `87df35c8…`: Content, Union, Plane): without Union every object gets its own box, with it
//! the list gets one box around everything (the right-click "Union Box" of the other variant).
//! Boxes are tight: a B-rep's or surface's box touches the geometry (Rhino's accurate
//! `GetBoundingBox(true)`), not the loose box of the control points. With a plane, the
//! geometry is measured in the plane's coordinates; output B is that box on the plane, and
//! output Bp (Grasshopper's second "Box" output, renamed here because two outputs may not
//! share a nickname) is the same box in plane coordinates, on World XY.

use locus_kernel::{BoundingBox, Interval, OrientedBox, Plane, Point3, Transform, tolerance};
use locus_runtime::{DataType, NodeError, NodeRegistry, NodeType, Port, Solve, Value, cast_value};

use crate::curve::curve_from_value;

/// Id of [`box_2pt`].
pub const BOX_2PT: &str = "surface.box_2pt";
/// Id of [`center_box`].
pub const CENTER_BOX: &str = "surface.center_box";
/// Id of [`domain_box`].
pub const DOMAIN_BOX: &str = "surface.domain_box";
/// Id of [`bounding_box`].
pub const BOUNDING_BOX: &str = "surface.bounding_box";
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
        bounding_box(),
        box_properties(),
        deconstruct_box(),
    ] {
        registry.register(t);
    }
}

fn surface_node(id: &str, name: &str, nickname: &str, subcategory: &str) -> NodeType {
    NodeType::new(id, name, nickname, "Surface").subcategory(subcategory)
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
fn box_plane(s: &Solve<'_>, input: usize, name: &str) -> Result<Plane, NodeError> {
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

/// The world bounding box of a geometry value after `xform` (when given): tight for every
/// kind (exact for points, boxes, lines, polylines, circles and arcs; to rounding for NURBS
/// curves, surfaces and B-reps).
///
/// # Errors
/// When the value is not geometry with a size (a number, text, vector, plane, domain or
/// transform), when the transform fails on it, or when the result is not finite.
pub fn bounds_of(value: &Value, xform: Option<&Transform>) -> Result<BoundingBox, NodeError> {
    let map = |p: Point3| xform.map_or(p, |x| x.transform_point(p));
    let bbox = match value {
        Value::Point(p) => BoundingBox::new(map(*p), map(*p)),
        Value::Box(b) => {
            let mut bbox = BoundingBox::EMPTY;
            for c in b.corners() {
                bbox.include_point(map(c));
            }
            bbox
        }
        Value::Line(_) | Value::Circle(_) | Value::Arc(_) | Value::Curve(_) => {
            let curve = curve_from_value(value).ok_or("not a curve")?;
            if !curve_is_finite(&curve) {
                return Err("the curve has a coordinate that is not finite".into());
            }
            let curve = match xform {
                Some(x) => curve.transformed(x)?,
                None => (*curve).clone(),
            };
            // Lines, polylines, circles and arcs have exact boxes of their own.
            match cast_value(
                &Value::Curve(locus_runtime::Shared::new(curve.clone())),
                DataType::Box,
            ) {
                Ok(Value::Box(b)) if !matches!(curve, locus_kernel::Curve::Nurbs(_)) => {
                    b.bounding_box()
                }
                _ => curve.to_nurbs().bounding_box(),
            }
        }
        Value::Surface(surface) if !surface.is_finite() => {
            return Err("the surface has a coordinate that is not finite".into());
        }
        Value::Surface(surface) => match xform {
            Some(x) => surface.transformed(x)?.bounding_box(),
            None => surface.bounding_box(),
        },
        Value::Brep(brep) => {
            if brep.faces().is_empty() && brep.edges().is_empty() && brep.vertices().is_empty() {
                return Err("the brep is empty".into());
            }
            let finite = brep.vertices().iter().all(|v| v.point.is_finite())
                && brep.faces().iter().all(|f| f.surface.is_finite())
                && brep.edges().iter().all(|e| e.curve.is_finite());
            if !finite {
                return Err("the brep has a coordinate that is not finite".into());
            }
            match xform {
                Some(x) => brep.transformed(x)?.bounding_box(),
                None => brep.bounding_box(),
            }
        }
        other => {
            return Err(NodeError(format!(
                "a {} has no bounding box: it is not geometry",
                other.data_type().name().to_lowercase()
            )));
        }
    };
    if bbox.is_empty() || !bbox.is_finite() {
        return Err("the geometry has a coordinate that is not finite".into());
    }
    Ok(bbox)
}

/// Whether every number of a curve is finite (a zero-length line is finite, though not a
/// valid curve).
fn curve_is_finite(curve: &locus_kernel::Curve) -> bool {
    use locus_kernel::Curve;
    match curve {
        Curve::Line { line, .. } => line.is_finite(),
        Curve::Polyline { polyline, .. } => polyline.points().iter().all(|p| p.is_finite()),
        Curve::Circle { circle, .. } => circle.plane.is_finite() && circle.radius.is_finite(),
        Curve::Arc { arc, .. } => {
            arc.circle.plane.is_finite() && arc.circle.radius.is_finite() && arc.angle.is_finite()
        }
        Curve::Nurbs(c) => c.is_finite(),
    }
}

/// The world-aligned box of a geometry value, as Grasshopper's Box parameter casts non-box
/// geometry; a box stays as it is.
///
/// # Errors
/// As [`bounds_of`].
pub fn box_from_value(value: &Value) -> Result<OrientedBox, NodeError> {
    match value {
        Value::Box(b) => Ok(*b),
        other => Ok(OrientedBox::from_bounding_box(&bounds_of(other, None)?)),
    }
}

/// Bounding Box \[BBox\]: the boxes around geometry, per object or for the whole list.
pub fn bounding_box() -> NodeType {
    surface_node(BOUNDING_BOX, "Bounding Box", "BBox", "Primitive")
        .description(
            "Solves the bounding boxes of geometry: the smallest boxes aligned with a plane that \
             contain it. Without Union every object gets its own box (one per list item); with \
             Union the whole list gets one box. Boxes are tight, not the boxes of control \
             points. Output B is the box on plane P in world coordinates; output Bp is the \
             same box in the plane's coordinates, on World XY (the two agree for World XY). \
             Items that are not geometry (numbers, text, vectors, planes) are an error and \
             get a null box; null items get null boxes.",
        )
        .input(
            Port::new("Content", "C", DataType::Generic)
                .doc(
                    "The geometry to contain: points, boxes, lines, circles, arcs, curves, \
                     surfaces or B-reps (a list).",
                )
                .list(),
        )
        .input(
            Port::new("Union", "U", DataType::Boolean)
                .doc(
                    "Whether to give one box around the whole list (true) or one box per \
                     object (false). Default false.",
                )
                .default_value(false),
        )
        .input(
            Port::new("Plane", "P", DataType::Plane)
                .doc("The plane the boxes are aligned with. Default World XY.")
                .default_value(Plane::WORLD_XY),
        )
        .output(
            Port::new("Box", "B", DataType::Box)
                .doc("The aligned bounding boxes in world coordinates, on plane P.")
                .list(),
        )
        .output(
            Port::new("Plane Box", "Bp", DataType::Box)
                .doc(
                    "The same boxes in the coordinates of plane P, on World XY (Grasshopper's \
                     second Box output).",
                )
                .list(),
        )
        .solve(|s| {
            let union = *s.item::<bool>(1)?;
            let plane = box_plane(s, 2, "P")?;
            let to_plane = Transform::plane_to_plane(&plane, &Plane::WORLD_XY);
            let xform = (plane != Plane::WORLD_XY).then_some(&to_plane);
            let mut local: Vec<Option<BoundingBox>> = Vec::new();
            if let Some(branch) = s.branch(0) {
                for (i, value) in branch.values().enumerate() {
                    match value.map(|v| bounds_of(&v, xform)) {
                        None => local.push(None),
                        Some(Ok(b)) => local.push(Some(b)),
                        Some(Err(e)) => {
                            s.error(format!("content item {i}: {e}"));
                            local.push(None);
                        }
                    }
                }
            }
            if union {
                let all = local
                    .iter()
                    .flatten()
                    .fold(BoundingBox::EMPTY, |acc, b| acc.union(b));
                local = if all.is_empty() {
                    Vec::new()
                } else {
                    vec![Some(all)]
                };
            }
            let on_plane = |b: &BoundingBox| {
                OrientedBox::new(plane, b.x_interval(), b.y_interval(), b.z_interval())
            };
            let world: Vec<Option<Value>> = local
                .iter()
                .map(|b| b.as_ref().map(|b| Value::Box(on_plane(b))))
                .collect();
            let plane_boxes: Vec<Option<Value>> = local
                .iter()
                .map(|b| {
                    b.as_ref()
                        .map(|b| Value::Box(OrientedBox::from_bounding_box(b)))
                })
                .collect();
            s.set_list_values(0, world);
            s.set_list_values(1, plane_boxes);
            Ok(())
        })
}

/// Box Properties \[BoxProp\]: centre, diagonal, area, volume and degeneracy of a box.
pub fn box_properties() -> NodeType {
    surface_node(BOX_PROPERTIES, "Box Properties", "BoxProp", "Analysis")
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
    use std::f64::consts::FRAC_1_SQRT_2;

    use locus_kernel::{Brep, Circle, Curve, Line, NurbsCurve, Sphere, Vector3};
    use locus_runtime::{Branch, DataTree, Level, NodeCall, Shared, TreePath};

    use super::*;
    use crate::vector::test_support::{assert_clean, assert_error, is_null, items, messages, only};

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

    fn bbox_call(content: Vec<Value>, union: bool, plane: Plane) -> locus_runtime::NodeCallResult {
        let mut branch = Branch::new(DataType::Generic);
        for v in content {
            branch.push_value(v);
        }
        let mut tree = DataTree::new();
        tree.insert(TreePath::zero(), branch);
        NodeCall::new(&bounding_box())
            .input(tree)
            .input(DataTree::from_item(union))
            .input(DataTree::from_item(plane))
            .run()
    }

    fn boxes(r: &locus_runtime::NodeCallResult, output: usize) -> Vec<OrientedBox> {
        items::<OrientedBox>(&r.outputs[output])
            .into_iter()
            .map(|b| b.expect("a box"))
            .collect()
    }

    fn assert_bounds(b: &OrientedBox, min: [f64; 3], max: [f64; 3]) {
        let got = [b.x.t0, b.y.t0, b.z.t0, b.x.t1, b.y.t1, b.z.t1];
        let want = [min[0], min[1], min[2], max[0], max[1], max[2]];
        for (g, w) in got.iter().zip(want) {
            assert!((g - w).abs() < 1e-12, "{got:?} vs {want:?}");
        }
    }

    #[test]
    fn bounding_boxes_per_object_and_united() {
        let sphere =
            Brep::from_sphere(&Sphere::new(Point3::new(5.0, 0.0, 0.0), 2.0).unwrap()).unwrap();
        let content = vec![
            Value::Point(Point3::new(1.0, 2.0, 3.0)),
            Value::Line(Line::new(Point3::ORIGIN, Point3::new(-1.0, 1.0, 0.0))),
            Value::Brep(Shared::new(sphere)),
        ];
        let r = bbox_call(content.clone(), false, Plane::WORLD_XY);
        assert_clean(&r);
        let per = boxes(&r, 0);
        assert_eq!(per.len(), 3);
        assert_bounds(&per[0], [1.0, 2.0, 3.0], [1.0, 2.0, 3.0]);
        assert_bounds(&per[1], [-1.0, 0.0, 0.0], [0.0, 1.0, 0.0]);
        // The sphere's box is tight, not the box of its control points.
        assert_bounds(&per[2], [3.0, -2.0, -2.0], [7.0, 2.0, 2.0]);
        assert_eq!(boxes(&r, 1), per);
        let r = bbox_call(content, true, Plane::WORLD_XY);
        let all = boxes(&r, 0);
        assert_eq!(all.len(), 1);
        assert_bounds(&all[0], [-1.0, -2.0, -2.0], [7.0, 2.0, 3.0]);
    }

    #[test]
    fn bounding_box_in_a_plane() {
        // A unit square rotated 45° about z, boxed in the plane rotated with it, is the
        // square itself; in World XY it is √2 wide.
        let plane = Plane::from_frame(
            Point3::ORIGIN,
            Vector3::new(1.0, 1.0, 0.0),
            Vector3::new(-1.0, 1.0, 0.0),
        )
        .unwrap();
        let corners = [
            plane.point_at(0.0, 0.0, 0.0),
            plane.point_at(1.0, 0.0, 0.0),
            plane.point_at(1.0, 1.0, 0.0),
            plane.point_at(0.0, 1.0, 0.0),
        ];
        let content: Vec<Value> = corners.iter().map(|&p| Value::Point(p)).collect();
        let r = bbox_call(content.clone(), true, plane);
        assert_clean(&r);
        let b = boxes(&r, 0)[0];
        assert_eq!(b.plane, plane);
        assert_bounds(&b, [0.0, 0.0, 0.0], [1.0, 1.0, 0.0]);
        assert_bounds(&boxes(&r, 1)[0], [0.0, 0.0, 0.0], [1.0, 1.0, 0.0]);
        assert_eq!(boxes(&r, 1)[0].plane, Plane::WORLD_XY);
        let world = boxes(&bbox_call(content, true, Plane::WORLD_XY), 0)[0];
        let s = 2.0 * FRAC_1_SQRT_2;
        assert_bounds(&world, [-FRAC_1_SQRT_2, 0.0, 0.0], [FRAC_1_SQRT_2, s, 0.0]);
        // A circle about a tilted axis in its own plane is a square of side 2r.
        let circle = Circle::new(tilted(), 1.5).unwrap();
        let r = bbox_call(vec![Value::Circle(circle)], false, tilted());
        let b = boxes(&r, 0)[0];
        assert!((b.x.length() - 3.0).abs() < 1e-12 && b.z.length().abs() < 1e-12);
    }

    #[test]
    fn bounding_boxes_of_nurbs_curves_are_tight() {
        let parabola = NurbsCurve::new_non_rational(
            2,
            vec![
                Point3::ORIGIN,
                Point3::new(1.0, 2.0, 0.0),
                Point3::new(2.0, 0.0, 0.0),
            ],
            vec![0.0, 0.0, 1.0, 1.0],
        )
        .unwrap();
        let v = Value::Curve(Shared::new(Curve::from(parabola)));
        let b = boxes(&bbox_call(vec![v], false, Plane::WORLD_XY), 0)[0];
        assert_bounds(&b, [0.0, 0.0, 0.0], [2.0, 1.0, 0.0]);
    }

    #[test]
    fn bounding_box_bad_content() {
        let mut branch = Branch::new(DataType::Generic);
        branch.push_value(Value::Number(1.0));
        branch.push_null();
        branch.push_value(Value::Point(Point3::new(f64::NAN, 0.0, 0.0)));
        branch.push_value(Value::Point(Point3::ORIGIN));
        let mut tree = DataTree::new();
        tree.insert(TreePath::zero(), branch);
        let r = NodeCall::new(&bounding_box()).input(tree.clone()).run();
        let errors = messages(&r, Level::Error);
        assert_eq!(errors.len(), 2, "{errors:?}");
        assert!(errors[0].contains("item 0") && errors[0].contains("number"));
        assert!(errors[1].contains("item 2"));
        let out = items::<OrientedBox>(&r.outputs[0]);
        assert_eq!(out.len(), 4);
        assert!(out[0].is_none() && out[1].is_none() && out[2].is_none() && out[3].is_some());
        // United, the good items still give a box.
        let r = NodeCall::new(&bounding_box())
            .input(tree)
            .input(DataTree::from_item(true))
            .run();
        assert_eq!(boxes(&r, 0).len(), 1);
        // An empty list gives no box.
        let r = NodeCall::new(&bounding_box())
            .input(DataTree::from_list(Vec::<Point3>::new()))
            .input(DataTree::from_item(true))
            .run();
        assert_eq!(r.outputs[0].item_count(), 0);
    }
}

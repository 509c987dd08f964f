//! Transform › Affine: transformations that keep lines straight and parallels parallel but may
//! change lengths and angles: Scale, Scale NU, Shear, Project and Orient Direction.

use locus_kernel::tolerance::ZERO_TOLERANCE;
use locus_kernel::{Plane, Point3, Transform, Vector3};
use locus_runtime::{DataType, NodeRegistry, NodeType, Port};

use super::{finish, geometry_input, geometry_output, transform_node, transform_output};

/// Id of [`scale`].
pub const SCALE: &str = "transform.scale";
/// Id of [`scale_nu`].
pub const SCALE_NU: &str = "transform.scale_nu";
/// Id of [`shear`].
pub const SHEAR: &str = "transform.shear";
/// Id of [`project`].
pub const PROJECT: &str = "transform.project";
/// Id of [`orient_direction`].
pub const ORIENT_DIRECTION: &str = "transform.orient_direction";

/// Registers the Affine nodes.
pub fn register(registry: &mut NodeRegistry) {
    for t in [scale(), scale_nu(), shear(), project(), orient_direction()] {
        registry.register(t);
    }
}

fn affine(id: &str, name: &str, nickname: &str) -> NodeType {
    transform_node(id, name, nickname, "Affine")
}

/// Scale \[Scale\]: a uniform scale about a centre.
pub fn scale() -> NodeType {
    affine(SCALE, "Scale", "Scale")
        .gh_guid("4d2a06bd-4b0f-4c65-9ee0-4220e4c01703")
        .description(
            "Scales geometry uniformly about a centre point: P goes to C + F (P − C). A \
             negative factor also turns the geometry through the centre; a zero factor \
             collapses it onto the centre (planes and boxes then have no axes, which is an \
             error for them).",
        )
        .input(geometry_input("scale"))
        .input(
            Port::new("Center", "C", DataType::Point)
                .doc("The centre of scaling, which stays fixed. Default (0, 0, 0).")
                .default_value(Point3::ORIGIN),
        )
        .input(
            Port::new("Factor", "F", DataType::Number)
                .doc("The scale factor, unitless (1 keeps the size). Default 0.5.")
                .default_value(0.5),
        )
        .output(geometry_output("scaled"))
        .output(transform_output())
        .solve(|s| {
            let center = *s.item::<Point3>(1)?;
            let factor = *s.item::<f64>(2)?;
            if !center.is_finite() {
                return Err("center C has a coordinate that is not finite".into());
            }
            finish(s, Transform::scale(center, factor))
        })
}

/// Scale NU \[Scale NU\]: a non-uniform scale along the axes of a plane.
pub fn scale_nu() -> NodeType {
    affine(SCALE_NU, "Scale NU", "Scale NU")
        .gh_guid("290f418a-65ee-406a-a9d0-35699815b512")
        .description(
            "Scales geometry by different factors along the x, y and z axes of a plane, about \
             its origin: a point at plane coordinates (u, v, w) goes to (X·u, Y·v, Z·w). \
             Circles become NURBS curves (ellipses) unless the factors in their plane are \
             equal; boxes aligned with the plane stay boxes.",
        )
        .input(geometry_input("scale"))
        .input(
            Port::new("Plane", "P", DataType::Plane)
                .doc("The plane whose origin is fixed and whose axes are scaled. Default World XY.")
                .default_value(Plane::WORLD_XY),
        )
        .input(
            Port::new("Scale X", "X", DataType::Number)
                .doc("The factor along the plane's x axis, unitless. Default 1.")
                .default_value(1.0),
        )
        .input(
            Port::new("Scale Y", "Y", DataType::Number)
                .doc("The factor along the plane's y axis, unitless. Default 1.")
                .default_value(1.0),
        )
        .input(
            Port::new("Scale Z", "Z", DataType::Number)
                .doc("The factor along the plane's z axis (normal), unitless. Default 1.")
                .default_value(1.0),
        )
        .output(geometry_output("scaled"))
        .output(transform_output())
        .solve(|s| {
            let plane = *s.item::<Plane>(1)?;
            let x = *s.item::<f64>(2)?;
            let y = *s.item::<f64>(3)?;
            let z = *s.item::<f64>(4)?;
            finish(s, Transform::scale_non_uniform(&plane, x, y, z))
        })
}

/// Shear \[Shear\]: the shear of a base plane that moves a grip point to a target point.
pub fn shear() -> NodeType {
    affine(SHEAR, "Shear", "Shear")
        .description(
            "Shears geometry parallel to a base plane: points on the plane stay, and every \
             other point moves by the shearing vector from the grip Gr to the target T, \
             scaled by its height above the plane relative to the grip's, so that the grip \
             goes exactly to the target. In plane coordinates the plane's x and y axes are \
             kept and its z axis goes to z + (T − Gr)/h, with h the grip's height. A grip on \
             the base plane cannot be moved off it and is an error.",
        )
        .input(geometry_input("shear"))
        .input(
            Port::new("Base", "P", DataType::Plane)
                .doc("The base plane, which stays fixed. Default the world XY plane.")
                .default_value(Plane::WORLD_XY),
        )
        .input(Port::new("Grip", "Gr", DataType::Point).doc(
            "The reference point, off the base plane, that is moved to the target. \
                 (Grasshopper's nickname is G, as the geometry's; locus needs distinct names, \
                 so it is Gr here, and `Grip` works too.)",
        ))
        .input(Port::new("Target", "T", DataType::Point).doc("Where the grip point goes."))
        .output(geometry_output("sheared"))
        .output(transform_output())
        .solve(|s| {
            let plane = *s.item::<Plane>(1)?;
            let grip = *s.item::<Point3>(2)?;
            let target = *s.item::<Point3>(3)?;
            if !grip.is_finite() || !target.is_finite() {
                return Err("the grip or target point has a coordinate that is not finite".into());
            }
            let height = plane.signed_distance_to(grip);
            let scale = 1.0 + (grip - plane.origin).length();
            if height.abs() <= ZERO_TOLERANCE * scale {
                return Err("the grip point lies on the base plane, so no shear moves it".into());
            }
            let z = plane.z_axis + (target - grip) / height;
            finish(s, Transform::shear(&plane, plane.x_axis, plane.y_axis, z))
        })
}

/// Project \[Proj\]: the orthogonal projection onto a plane.
pub fn project() -> NodeType {
    affine(PROJECT, "Project", "Proj")
        .gh_guid("23285717-156c-468f-a691-b242488c06a6")
        .description(
            "Projects geometry onto a plane along its normal: every point goes to its closest \
             point of the plane (the book: projecting onto world XY sets z to 0). The matrix \
             is singular, so it has no inverse. Planes perpendicular to the projection plane \
             collapse to a line and are an error.",
        )
        .input(geometry_input("project"))
        .input(
            Port::new("Plane", "P", DataType::Plane)
                .doc("The plane to project onto. Default the world XY plane.")
                .default_value(Plane::WORLD_XY),
        )
        .output(geometry_output("projected"))
        .output(transform_output())
        .solve(|s| {
            let plane = *s.item::<Plane>(1)?;
            finish(s, Transform::planar_projection(&plane))
        })
}

/// Orient Direction \[Orient\]: moves, turns and scales geometry so that a point and a
/// direction at it land on another point and direction.
pub fn orient_direction() -> NodeType {
    affine(ORIENT_DIRECTION, "Orient Direction", "Orient")
        .gh_guid("1602b2cc-007c-4b79-8926-0067c6184e44")
        .description(
            "Orients geometry using directional constraints only: it moves point A onto point \
             B, turns direction A onto direction B about B (the smallest rotation, about the \
             axis A × B; a half turn for opposite directions), and scales uniformly about B by \
             |B| / |A|, the ratio of the directions' lengths (they are not unitized, so unit \
             vectors keep the size). A direction of zero length or a coordinate that is not \
             finite is an error.",
        )
        .input(geometry_input("orient"))
        .input(Port::new("Point A", "pA", DataType::Point).doc("The reference point."))
        .input(
            Port::new("Direction A", "dA", DataType::Vector)
                .doc("The reference direction at point A; its length is the scale's reference."),
        )
        .input(Port::new("Point B", "pB", DataType::Point).doc("The target point."))
        .input(
            Port::new("Direction B", "dB", DataType::Vector)
                .doc("The target direction at point B; its length over A's is the scale factor."),
        )
        .output(geometry_output("oriented"))
        .output(transform_output())
        .solve(|s| {
            let point_a = *s.item::<Point3>(1)?;
            let direction_a = *s.item::<Vector3>(2)?;
            let point_b = *s.item::<Point3>(3)?;
            let direction_b = *s.item::<Vector3>(4)?;
            let xform = orient_direction_transform(point_a, direction_a, point_b, direction_b)?;
            finish(s, xform)
        })
}

/// The transform of [`orient_direction`]: translate A to B, turn direction A onto direction B
/// about B, scale about B by |dB| / |dA|.
fn orient_direction_transform(
    point_a: Point3,
    direction_a: Vector3,
    point_b: Point3,
    direction_b: Vector3,
) -> Result<Transform, locus_runtime::NodeError> {
    for (p, name) in [(point_a, "pA"), (point_b, "pB")] {
        if !p.is_finite() {
            return Err(
                format!("input {name}: the point has a coordinate that is not finite").into(),
            );
        }
    }
    let mut lengths = [0.0; 2];
    for (k, (v, name)) in [(direction_a, "dA"), (direction_b, "dB")]
        .into_iter()
        .enumerate()
    {
        let length = v.length();
        if !length.is_finite() {
            return Err(
                format!("input {name}: the direction has a coordinate that is not finite").into(),
            );
        }
        if length <= ZERO_TOLERANCE {
            return Err(format!("input {name}: the direction has zero length").into());
        }
        lengths[k] = length;
    }
    let rotation = Transform::rotation_between(direction_a, direction_b, point_b)?;
    let scale = Transform::scale(point_b, lengths[1] / lengths[0]);
    Ok(scale * rotation * Transform::translation(point_b - point_a))
}

#[cfg(test)]
mod tests {
    use locus_kernel::{Circle, Curve, Interval, OrientedBox, Vector3};
    use locus_runtime::{DataTree, Level, NodeCall, Value};

    use super::*;
    use crate::vector::test_support::{
        assert_clean, assert_error, is_null, messages, only, only_value,
    };

    fn rows_exact(t: &Transform, rows: [[f64; 4]; 4]) {
        assert_eq!(t.to_rows(), rows);
    }

    #[test]
    fn scale_by_a_quarter_as_in_the_book() {
        // The book scales a box by 0.25 about the origin: diag(0.25, 0.25, 0.25, 1).
        let b = OrientedBox::new(
            Plane::WORLD_XY,
            Interval::new(0.0, 4.0),
            Interval::new(0.0, 8.0),
            Interval::new(0.0, 12.0),
        );
        let r = NodeCall::new(&scale())
            .input(DataTree::from_item(b))
            .skip_input()
            .input(DataTree::from_item(0.25))
            .run();
        assert_clean(&r);
        rows_exact(
            &only::<Transform>(&r, 1),
            [
                [0.25, 0.0, 0.0, 0.0],
                [0.0, 0.25, 0.0, 0.0],
                [0.0, 0.0, 0.25, 0.0],
                [0.0, 0.0, 0.0, 1.0],
            ],
        );
        let Value::Box(out) = only_value(&r, 0) else {
            panic!("expected a box");
        };
        assert!((out.volume() - 4.0 * 8.0 * 12.0 / 64.0).abs() < 1e-12);
    }

    #[test]
    fn scale_about_a_centre_and_by_default() {
        let r = NodeCall::new(&scale())
            .input(DataTree::from_item(Point3::new(4.0, 4.0, 4.0)))
            .input(DataTree::from_item(Point3::new(2.0, 2.0, 2.0)))
            .run();
        assert_clean(&r);
        assert_eq!(only_value(&r, 0), Value::Point(Point3::new(3.0, 3.0, 3.0)));
    }

    #[test]
    fn scale_bad_input() {
        let r = NodeCall::new(&scale())
            .input(DataTree::from_item(Point3::ORIGIN))
            .skip_input()
            .input(DataTree::from_item(f64::NAN))
            .run();
        assert_error(&r, "not finite");
        assert!(is_null(&r, 0) && is_null(&r, 1));
        // A zero factor is a valid (singular) transform: points collapse, planes fail.
        let r = NodeCall::new(&scale())
            .input(DataTree::from_list(vec![
                Value::Point(Point3::new(1.0, 2.0, 3.0)),
                Value::Plane(Plane::WORLD_XY),
            ]))
            .skip_input()
            .input(DataTree::from_item(0.0))
            .run();
        let out: Vec<Option<Value>> = r.outputs[0].values().collect();
        assert_eq!(out[0], Some(Value::Point(Point3::ORIGIN)));
        assert_eq!(out[1], None);
        assert_eq!(messages(&r, Level::Error).len(), 1);
    }

    #[test]
    fn scale_nu_turns_circles_into_ellipses() {
        let c = Circle::new(Plane::WORLD_XY, 1.0).unwrap();
        let r = NodeCall::new(&scale_nu())
            .input(DataTree::from_item(c))
            .skip_input()
            .input(DataTree::from_item(3.0))
            .run();
        assert_clean(&r);
        rows_exact(
            &only::<Transform>(&r, 1),
            [
                [3.0, 0.0, 0.0, 0.0],
                [0.0, 1.0, 0.0, 0.0],
                [0.0, 0.0, 1.0, 0.0],
                [0.0, 0.0, 0.0, 1.0],
            ],
        );
        let Value::Curve(curve) = only_value(&r, 0) else {
            panic!("expected a curve");
        };
        assert!(matches!(*curve, Curve::Nurbs(_)));
        let d = curve.domain();
        assert!(
            curve
                .point_at(d.t0)
                .abs_diff_eq(Point3::new(3.0, 0.0, 0.0), 1e-14)
        );
        // Equal factors in the circle's plane keep it a circle.
        let r = NodeCall::new(&scale_nu())
            .input(DataTree::from_item(c))
            .skip_input()
            .input(DataTree::from_item(2.0))
            .input(DataTree::from_item(2.0))
            .input(DataTree::from_item(7.0))
            .run();
        assert!(matches!(only_value(&r, 0), Value::Circle(c) if c.radius == 2.0));
    }

    #[test]
    fn scale_nu_bad_input() {
        let r = NodeCall::new(&scale_nu())
            .input(DataTree::from_item(Point3::ORIGIN))
            .skip_input()
            .skip_input()
            .input(DataTree::from_item(f64::INFINITY))
            .run();
        assert_error(&r, "not finite");
        assert!(is_null(&r, 0) && is_null(&r, 1));
        // A zero factor flattens a box into a flat box, and a circle in that plane into a
        // degenerate curve, but a plane whose y axis collapses is an error.
        let r = NodeCall::new(&scale_nu())
            .input(DataTree::from_item(Plane::WORLD_XY))
            .skip_input()
            .skip_input()
            .input(DataTree::from_item(0.0))
            .run();
        assert_error(&r, "degenerate");
    }

    #[test]
    fn scale_nu_in_a_tilted_plane_fixes_its_origin() {
        let plane =
            Plane::from_normal(Point3::new(1.0, 2.0, 3.0), Vector3::new(1.0, 1.0, 1.0)).unwrap();
        let r = NodeCall::new(&scale_nu())
            .input(DataTree::from_item(plane.point_at(1.0, 1.0, 1.0)))
            .input(DataTree::from_item(plane))
            .input(DataTree::from_item(2.0))
            .input(DataTree::from_item(3.0))
            .input(DataTree::from_item(4.0))
            .run();
        let Value::Point(p) = only_value(&r, 0) else {
            panic!("expected a point");
        };
        assert!(p.abs_diff_eq(plane.point_at(2.0, 3.0, 4.0), 1e-14));
        assert!(
            only::<Transform>(&r, 1)
                .transform_point(plane.origin)
                .abs_diff_eq(plane.origin, 1e-14)
        );
    }

    #[test]
    fn shear_in_x_keeping_z_as_in_the_book() {
        // Grip (0, 0, 1) to (1, 0, 1) over world XY: x' = x + z, the book's shear in x and y
        // keeping the z coordinate fixed (with one factor zero).
        let r = NodeCall::new(&shear())
            .input(DataTree::from_item(Point3::new(2.0, 3.0, 4.0)))
            .skip_input()
            .input(DataTree::from_item(Point3::new(0.0, 0.0, 1.0)))
            .input(DataTree::from_item(Point3::new(1.0, 0.0, 1.0)))
            .run();
        assert_clean(&r);
        rows_exact(
            &only::<Transform>(&r, 1),
            [
                [1.0, 0.0, 1.0, 0.0],
                [0.0, 1.0, 0.0, 0.0],
                [0.0, 0.0, 1.0, 0.0],
                [0.0, 0.0, 0.0, 1.0],
            ],
        );
        assert_eq!(only_value(&r, 0), Value::Point(Point3::new(6.0, 3.0, 4.0)));
    }

    #[test]
    fn shear_moves_the_grip_to_the_target() {
        let plane =
            Plane::from_normal(Point3::new(1.0, -1.0, 2.0), Vector3::new(0.0, 1.0, 1.0)).unwrap();
        let grip = plane.point_at(2.0, 1.0, 3.0);
        let target = grip + Vector3::new(1.5, -2.0, 0.5);
        let on_plane = plane.point_at(-4.0, 7.0, 0.0);
        let r = NodeCall::new(&shear())
            .input(DataTree::from_list(vec![
                Value::Point(grip),
                Value::Point(on_plane),
            ]))
            .input(DataTree::from_item(plane))
            .input(DataTree::from_item(grip))
            .input(DataTree::from_item(target))
            .run();
        assert_clean(&r);
        let out: Vec<Option<Value>> = r.outputs[0].values().collect();
        let Some(Value::Point(g)) = out[0] else {
            panic!("expected a point");
        };
        assert!(g.abs_diff_eq(target, 1e-14));
        let Some(Value::Point(q)) = out[1] else {
            panic!("expected a point");
        };
        assert!(q.abs_diff_eq(on_plane, 1e-14));
    }

    #[test]
    fn shear_bad_input() {
        // A grip on the base plane.
        let r = NodeCall::new(&shear())
            .input(DataTree::from_item(Point3::ORIGIN))
            .skip_input()
            .input(DataTree::from_item(Point3::new(1.0, 1.0, 0.0)))
            .input(DataTree::from_item(Point3::new(1.0, 1.0, 1.0)))
            .run();
        assert_error(&r, "lies on the base plane");
        assert!(is_null(&r, 0) && is_null(&r, 1));
        let r = NodeCall::new(&shear())
            .input(DataTree::from_item(Point3::ORIGIN))
            .skip_input()
            .input(DataTree::from_item(Point3::new(0.0, 0.0, 1.0)))
            .input(DataTree::from_item(Point3::new(f64::NAN, 1.0, 1.0)))
            .run();
        assert_error(&r, "not finite");
        // A sheared box is not a box: it becomes a B-rep, as in Grasshopper.
        let b = OrientedBox::new(
            Plane::WORLD_XY,
            Interval::UNIT,
            Interval::UNIT,
            Interval::UNIT,
        );
        let r = NodeCall::new(&shear())
            .input(DataTree::from_item(b))
            .skip_input()
            .input(DataTree::from_item(Point3::new(0.0, 0.0, 1.0)))
            .input(DataTree::from_item(Point3::new(1.0, 0.0, 1.0)))
            .run();
        assert!(r.messages.is_empty(), "{:?}", r.messages);
        let sheared = r.outputs[0].values().next().flatten();
        assert!(
            matches!(sheared, Some(locus_runtime::Value::Brep(_))),
            "{sheared:?}"
        );
        assert!(!is_null(&r, 1));
    }

    #[test]
    fn project_onto_world_xy_as_in_the_book() {
        // The book: the projection onto the world xy-plane zeroes the third row.
        let r = NodeCall::new(&project())
            .input(DataTree::from_item(Point3::new(2.0, 3.0, 4.0)))
            .run();
        assert_clean(&r);
        let x = only::<Transform>(&r, 1);
        rows_exact(
            &x,
            [
                [1.0, 0.0, 0.0, 0.0],
                [0.0, 1.0, 0.0, 0.0],
                [0.0, 0.0, 0.0, 0.0],
                [0.0, 0.0, 0.0, 1.0],
            ],
        );
        assert!(x.inverse().is_err());
        assert_eq!(only_value(&r, 0), Value::Point(Point3::new(2.0, 3.0, 0.0)));
    }

    #[test]
    fn project_a_curve_and_a_perpendicular_plane() {
        // The book: projecting a curve projects its control points.
        let c = Circle::new(Plane::WORLD_YZ.translated(Vector3::new(0.0, 0.0, 5.0)), 1.0).unwrap();
        let r = NodeCall::new(&project())
            .input(DataTree::from_item(c))
            .input(DataTree::from_item(Plane::WORLD_XY))
            .run();
        assert_clean(&r);
        let Value::Curve(curve) = only_value(&r, 0) else {
            panic!("expected a curve");
        };
        let Curve::Nurbs(n) = &*curve else {
            panic!("expected a NURBS curve");
        };
        assert!(n.points().iter().all(|p| p.z == 0.0 && p.x == 0.0));
        // A plane perpendicular to the projection plane collapses.
        let r = NodeCall::new(&project())
            .input(DataTree::from_item(Plane::WORLD_YZ))
            .run();
        assert_error(&r, "degenerate");
        assert!(is_null(&r, 0));
    }

    #[test]
    fn orient_direction_moves_turns_and_scales() {
        // A = (1, 0, 0) with direction +X, B = (0, 0, 5) with direction 2·(+Y): the point
        // (2, 0, 0), one unit along A's direction from A, goes two units along +Y from B.
        let r = NodeCall::new(&orient_direction())
            .input(DataTree::from_list(vec![
                Value::Point(Point3::new(2.0, 0.0, 0.0)),
                Value::Point(Point3::new(1.0, 1.0, 0.0)),
            ]))
            .input(DataTree::from_item(Point3::new(1.0, 0.0, 0.0)))
            .input(DataTree::from_item(Vector3::new(1.0, 0.0, 0.0)))
            .input(DataTree::from_item(Point3::new(0.0, 0.0, 5.0)))
            .input(DataTree::from_item(Vector3::new(0.0, 2.0, 0.0)))
            .run();
        assert_clean(&r);
        let out: Vec<Option<Value>> = r.outputs[0].values().collect();
        let want = [Point3::new(0.0, 2.0, 5.0), Point3::new(-2.0, 0.0, 5.0)];
        for (got, want) in out.iter().zip(want) {
            match got {
                Some(Value::Point(p)) => assert!(p.distance(want) < 1e-12, "{p:?} {want:?}"),
                other => panic!("no point: {other:?}"),
            }
        }
        // Opposite directions of equal length: a half turn about B.
        let r = NodeCall::new(&orient_direction())
            .input(DataTree::from_item(Point3::new(1.0, 0.0, 0.0)))
            .input(DataTree::from_item(Point3::ORIGIN))
            .input(DataTree::from_item(Vector3::new(0.0, 0.0, 3.0)))
            .input(DataTree::from_item(Point3::ORIGIN))
            .input(DataTree::from_item(Vector3::new(0.0, 0.0, -3.0)))
            .run();
        match only_value(&r, 0) {
            Value::Point(p) => {
                assert!((p.distance(Point3::ORIGIN) - 1.0).abs() < 1e-12);
                assert!(p.z.abs() < 1e-12);
            }
            other => panic!("no point: {other:?}"),
        }
    }

    #[test]
    fn orient_direction_bad_input() {
        let run = |da: Vector3, pb: Point3| {
            NodeCall::new(&orient_direction())
                .input(DataTree::from_item(Point3::ORIGIN))
                .input(DataTree::from_item(Point3::ORIGIN))
                .input(DataTree::from_item(da))
                .input(DataTree::from_item(pb))
                .input(DataTree::from_item(Vector3::new(0.0, 1.0, 0.0)))
                .run()
        };
        let r = run(Vector3::ZERO, Point3::ORIGIN);
        assert_error(&r, "input dA: the direction has zero length");
        assert!(is_null(&r, 0) && is_null(&r, 1));
        let r = run(Vector3::new(f64::NAN, 0.0, 1.0), Point3::ORIGIN);
        assert_error(
            &r,
            "input dA: the direction has a coordinate that is not finite",
        );
        let r = run(Vector3::X, Point3::new(0.0, f64::INFINITY, 0.0));
        assert_error(
            &r,
            "input pB: the point has a coordinate that is not finite",
        );
    }
}

//! Transform › Euclidean: rigid motions and mirrors, which keep lengths and angles: Move,
//! Rotate, Rotate Axis, Rotate 3D, Mirror and Orient.

use std::f64::consts::FRAC_PI_2;

use locus_kernel::{Line, Plane, Point3, Transform, Vector3};
use locus_runtime::{DataType, NodeError, NodeRegistry, NodeType, Port};

use super::{
    finish, geometry_input, geometry_output, transform_node, transform_output, transform_point,
};

/// Id of [`move_geometry`].
pub const MOVE: &str = "transform.move";
/// Id of [`rotate`].
pub const ROTATE: &str = "transform.rotate";
/// Id of [`rotate_axis`].
pub const ROTATE_AXIS: &str = "transform.rotate_axis";
/// Id of [`rotate_3d`].
pub const ROTATE_3D: &str = "transform.rotate_3d";
/// Id of [`mirror`].
pub const MIRROR: &str = "transform.mirror";
/// Id of [`orient`].
pub const ORIENT: &str = "transform.orient";

/// Registers the Euclidean nodes.
pub fn register(registry: &mut NodeRegistry) {
    for t in [
        move_geometry(),
        rotate(),
        rotate_axis(),
        rotate_3d(),
        mirror(),
        orient(),
    ] {
        registry.register(t);
    }
}

fn euclidean(id: &str, name: &str, nickname: &str) -> NodeType {
    transform_node(id, name, nickname, "Euclidean")
}

fn angle_input() -> Port {
    Port::new("Angle", "A", DataType::Number)
        .doc(
            "The rotation angle, in radians, counter-clockwise seen from the tip of the axis \
             (right-hand rule). Default ½π (a quarter turn).",
        )
        .default_value(FRAC_PI_2)
}

/// Move \[Move\]: a translation by a vector.
pub fn move_geometry() -> NodeType {
    euclidean(MOVE, "Move", "Move")
        .gh_guid("e9eb1dcf-92f6-4d4d-84ae-96222d60f56b")
        .description(
            "Translates geometry by a motion vector: every point P goes to P + T. The matrix \
             is the identity with T in its last column. Vectors, having no position, are not \
             changed.",
        )
        .input(geometry_input("move"))
        .input(
            Port::new("Motion", "T", DataType::Vector)
                .doc("The translation vector, in model units. Default <0, 0, 10>.")
                .default_value(Vector3::new(0.0, 0.0, 10.0)),
        )
        .output(geometry_output("moved"))
        .output(transform_output())
        .solve(|s| {
            let t = *s.item::<Vector3>(1)?;
            finish(s, Transform::translation(t))
        })
        .fast_path2_with_plain(
            // A finite motion and moved point: nothing to report.
            |&p: &Point3, &t: &Vector3| {
                let x = Transform::translation(t);
                x.is_finite() & x.transform_point(p).is_finite()
            },
            |&p: &Point3, &t: &Vector3| {
                let x = Transform::translation(t);
                (x.transform_point(p), x)
            },
            |p: &Point3, t: &Vector3, report| {
                Some(transform_point(*p, Transform::translation(*t), report))
            },
        )
}

/// Rotate \[Rotate\]: a rotation in a plane, about its normal through its origin.
pub fn rotate() -> NodeType {
    euclidean(ROTATE, "Rotate", "Rotate")
        .gh_guid("b7798b74-037e-4f0c-8ac7-dc1043d093e0")
        .description(
            "Rotates geometry in a plane: about the plane's normal through its origin, by an \
             angle in radians, counter-clockwise as seen from above the plane. A NaN angle is \
             an error.",
        )
        .input(geometry_input("rotate"))
        .input(angle_input())
        .input(
            Port::new("Plane", "P", DataType::Plane)
                .doc(
                    "The plane of rotation: the centre is its origin and the axis its normal. \
                     Default the world XY plane.",
                )
                .default_value(Plane::WORLD_XY),
        )
        .output(geometry_output("rotated"))
        .output(transform_output())
        .solve(|s| {
            let angle = *s.item::<f64>(1)?;
            let plane = *s.item::<Plane>(2)?;
            finish(s, Transform::rotation(angle, plane.normal(), plane.origin)?)
        })
        .fast_path3_with(|p: &Point3, angle: &f64, plane: &Plane, report| {
            Some(
                Transform::rotation(*angle, plane.normal(), plane.origin)
                    .map_err(NodeError::from)
                    .and_then(|xform| transform_point(*p, xform, report)),
            )
        })
}

/// Rotate Axis \[RotAx\]: a rotation about a line.
pub fn rotate_axis() -> NodeType {
    euclidean(ROTATE_AXIS, "Rotate Axis", "RotAx")
        .description(
            "Rotates geometry about an axis line by an angle in radians, counter-clockwise \
             seen from the line's end looking back to its start. A zero-length line has no \
             direction and is an error.",
        )
        .input(geometry_input("rotate"))
        .input(angle_input())
        .input(
            Port::new("Axis", "X", DataType::Line)
                .doc(
                    "The rotation axis, from its start towards its end. Default the world z \
                     axis, (0, 0, 0) to (0, 0, 1).",
                )
                .default_value(Line::new(Point3::ORIGIN, Point3::new(0.0, 0.0, 1.0))),
        )
        .output(geometry_output("rotated"))
        .output(transform_output())
        .solve(|s| {
            let angle = *s.item::<f64>(1)?;
            let axis = *s.item::<Line>(2)?;
            finish(s, Transform::rotation(angle, axis.direction(), axis.from)?)
        })
}

/// Rotate 3D \[Rot3D\]: a rotation about an axis vector through a centre point.
pub fn rotate_3d() -> NodeType {
    euclidean(ROTATE_3D, "Rotate 3D", "Rot3D")
        .gh_guid("3dfb9a77-6e05-4016-9f20-94f78607d672")
        .description(
            "Rotates geometry about an axis through a centre point, by an angle in radians, \
             counter-clockwise seen from the tip of the axis. A zero-length axis is an error.",
        )
        .input(geometry_input("rotate"))
        .input(angle_input())
        .input(
            Port::new("Center", "C", DataType::Point)
                .doc("A point on the rotation axis. Default (0, 0, 0).")
                .default_value(Point3::ORIGIN),
        )
        .input(
            Port::new("Axis", "X", DataType::Vector)
                .doc("The direction of the rotation axis. Default <0, 0, 1>.")
                .default_value(Vector3::Z),
        )
        .output(geometry_output("rotated"))
        .output(transform_output())
        .solve(|s| {
            let angle = *s.item::<f64>(1)?;
            let center = *s.item::<Point3>(2)?;
            let axis = *s.item::<Vector3>(3)?;
            finish(s, Transform::rotation(angle, axis, center)?)
        })
}

/// Mirror \[Mirror\]: a reflection across a plane.
pub fn mirror() -> NodeType {
    euclidean(MIRROR, "Mirror", "Mirror")
        .gh_guid("f12daa2f-4fd5-48c1-8ac3-5dea476912ca")
        .description(
            "Mirrors geometry across a plane: every point P goes to P − 2 d n, with d its \
             signed distance from the plane and n the plane's unit normal. Mirroring reverses \
             orientation (the book: face directions flip); mirrored planes are kept \
             right-handed by reversing their normal.",
        )
        .input(geometry_input("mirror"))
        .input(
            Port::new("Plane", "P", DataType::Plane)
                .doc("The mirror plane. Default the world YZ plane (x goes to −x).")
                .default_value(Plane::WORLD_YZ),
        )
        .output(geometry_output("mirrored"))
        .output(transform_output())
        .solve(|s| {
            let plane = *s.item::<Plane>(1)?;
            finish(s, Transform::mirror(&plane))
        })
}

/// Orient \[Orient\]: the motion that takes one plane onto another.
pub fn orient() -> NodeType {
    euclidean(ORIENT, "Orient", "Orient")
        .gh_guid("378d0690-9da0-4dd1-ab16-1d15246e7c22")
        .description(
            "Moves geometry from a source plane to a target plane: the source origin goes to \
             the target origin and the source axes onto the target axes, so every point keeps \
             its plane coordinates (Rhino's plane-to-plane transform).",
        )
        .input(geometry_input("orient"))
        .input(
            Port::new("Source", "A", DataType::Plane)
                .doc("The plane to move from. Default the world XY plane.")
                .default_value(Plane::WORLD_XY),
        )
        .input(Port::new("Target", "B", DataType::Plane).doc("The plane to move onto."))
        .output(geometry_output("oriented"))
        .output(transform_output())
        .solve(|s| {
            let from = *s.item::<Plane>(1)?;
            let to = *s.item::<Plane>(2)?;
            finish(s, Transform::plane_to_plane(&from, &to))
        })
}

#[cfg(test)]
mod tests {
    use std::f64::consts::{FRAC_PI_4, PI};

    use locus_kernel::{Circle, Curve, Interval, OrientedBox};
    use locus_runtime::{DataTree, NodeCall, Value};

    use super::*;
    use crate::vector::test_support::{assert_clean, assert_error, is_null, only, only_value};

    fn rows_close(t: &Transform, rows: [[f64; 4]; 4], tolerance: f64) {
        let actual = t.to_rows();
        for i in 0..4 {
            for j in 0..4 {
                assert!(
                    (actual[i][j] - rows[i][j]).abs() <= tolerance,
                    "entry ({i}, {j}): {} vs {}",
                    actual[i][j],
                    rows[i][j]
                );
            }
        }
    }

    #[test]
    fn move_a_point_as_in_the_book() {
        // The book: P(2, 3, 1) moved by <2, 2, 2> is (4, 5, 3), with the translation matrix.
        let r = NodeCall::new(&move_geometry())
            .input(DataTree::from_item(Point3::new(2.0, 3.0, 1.0)))
            .input(DataTree::from_item(Vector3::new(2.0, 2.0, 2.0)))
            .run();
        assert_clean(&r);
        assert_eq!(only_value(&r, 0), Value::Point(Point3::new(4.0, 5.0, 3.0)));
        rows_close(
            &only::<Transform>(&r, 1),
            [
                [1.0, 0.0, 0.0, 2.0],
                [0.0, 1.0, 0.0, 2.0],
                [0.0, 0.0, 1.0, 2.0],
                [0.0, 0.0, 0.0, 1.0],
            ],
            0.0,
        );
    }

    #[test]
    fn move_the_book_box_by_4_5_3() {
        // The book moves a box by <4, 5, 3>: each of its eight corners moves.
        let b = OrientedBox::new(
            Plane::WORLD_XY,
            Interval::new(0.0, 1.0),
            Interval::new(0.0, 2.0),
            Interval::new(0.0, 3.0),
        );
        let r = NodeCall::new(&move_geometry())
            .input(DataTree::from_item(b))
            .input(DataTree::from_item(Vector3::new(4.0, 5.0, 3.0)))
            .run();
        assert_clean(&r);
        let Value::Box(moved) = only_value(&r, 0) else {
            panic!("expected a box");
        };
        for (before, after) in b.corners().iter().zip(moved.corners()) {
            assert!(after.abs_diff_eq(*before + Vector3::new(4.0, 5.0, 3.0), 1e-15));
        }
    }

    #[test]
    fn move_without_geometry_gives_only_the_transform() {
        let r = NodeCall::new(&move_geometry()).run();
        assert_clean(&r);
        assert!(is_null(&r, 0));
        assert_eq!(
            only::<Transform>(&r, 1),
            Transform::translation(Vector3::new(0.0, 0.0, 10.0))
        );
    }

    #[test]
    fn move_bad_input() {
        let r = NodeCall::new(&move_geometry())
            .input(DataTree::from_item(Point3::ORIGIN))
            .input(DataTree::from_item(Vector3::new(f64::NAN, 0.0, 0.0)))
            .run();
        assert_error(&r, "not finite");
        assert!(is_null(&r, 0) && is_null(&r, 1));
        // Text is not geometry: an error for the geometry, but the transform is written.
        let r = NodeCall::new(&move_geometry())
            .input(DataTree::from_item(String::from("box")))
            .run();
        assert_error(&r, "cannot transform a text");
        assert!(is_null(&r, 0));
        assert!(only::<Transform>(&r, 1).is_translation(0.0));
    }

    #[test]
    fn rotate_30_degrees_as_in_the_book() {
        // The book's 30° rotation about z: [[0.87, −0.5, 0, 0], [0.5, 0.87, 0, 0], …].
        let angle = 30f64.to_radians();
        let r = NodeCall::new(&rotate())
            .input(DataTree::from_item(Point3::new(1.0, 0.0, 0.0)))
            .input(DataTree::from_item(angle))
            .run();
        assert_clean(&r);
        let (s, c) = angle.sin_cos();
        rows_close(
            &only::<Transform>(&r, 1),
            [
                [c, -s, 0.0, 0.0],
                [s, c, 0.0, 0.0],
                [0.0, 0.0, 1.0, 0.0],
                [0.0, 0.0, 0.0, 1.0],
            ],
            1e-15,
        );
        assert!((c - 0.87).abs() < 0.005 && (s - 0.5).abs() < 1e-15);
        let Value::Point(p) = only_value(&r, 0) else {
            panic!("expected a point");
        };
        assert!(p.abs_diff_eq(Point3::new(c, s, 0.0), 1e-15));
    }

    #[test]
    fn rotate_in_a_plane_fixes_its_origin() {
        let plane = Plane::from_normal(Point3::new(1.0, 2.0, 3.0), Vector3::X).unwrap();
        let r = NodeCall::new(&rotate())
            .input(DataTree::from_list(vec![
                Value::Point(plane.origin),
                Value::Point(plane.point_at(1.0, 0.0, 0.0)),
            ]))
            .skip_input()
            .input(DataTree::from_item(plane))
            .run();
        assert_clean(&r);
        let out: Vec<Option<Value>> = r.outputs[0].values().collect();
        let Some(Value::Point(o)) = out[0] else {
            panic!("expected a point");
        };
        assert!(o.abs_diff_eq(plane.origin, 1e-15));
        let Some(Value::Point(q)) = out[1] else {
            panic!("expected a point");
        };
        // A quarter turn takes the plane's x axis to its y axis.
        assert!(q.abs_diff_eq(plane.point_at(0.0, 1.0, 0.0), 1e-15));
    }

    #[test]
    fn rotate_about_a_point_cast_to_a_plane() {
        // A point given for the plane is cast to the XY plane through it.
        let r = NodeCall::new(&rotate())
            .input(DataTree::from_item(Point3::new(2.0, 1.0, 7.0)))
            .input(DataTree::from_item(PI))
            .input(DataTree::from_item(Point3::new(1.0, 1.0, 0.0)))
            .run();
        assert_clean(&r);
        let Value::Point(p) = only_value(&r, 0) else {
            panic!("expected a point");
        };
        assert!(p.abs_diff_eq(Point3::new(0.0, 1.0, 7.0), 1e-15));
    }

    #[test]
    fn rotate_nan_angle_is_an_error() {
        let r = NodeCall::new(&rotate())
            .input(DataTree::from_item(Point3::ORIGIN))
            .input(DataTree::from_item(f64::NAN))
            .run();
        assert_error(&r, "angle is not finite");
        assert!(is_null(&r, 0) && is_null(&r, 1));
    }

    #[test]
    fn rotate_axis_about_a_line() {
        // About the vertical line through (1, 0, 0), a half turn takes the origin to (2, 0, 0).
        let axis = Line::new(Point3::new(1.0, 0.0, 0.0), Point3::new(1.0, 0.0, 5.0));
        let r = NodeCall::new(&rotate_axis())
            .input(DataTree::from_item(Point3::ORIGIN))
            .input(DataTree::from_item(PI))
            .input(DataTree::from_item(axis))
            .run();
        assert_clean(&r);
        let Value::Point(p) = only_value(&r, 0) else {
            panic!("expected a point");
        };
        assert!(p.abs_diff_eq(Point3::new(2.0, 0.0, 0.0), 1e-15));
        // A degenerate axis.
        let r = NodeCall::new(&rotate_axis())
            .input(DataTree::from_item(Point3::ORIGIN))
            .skip_input()
            .input(DataTree::from_item(Line::new(
                Point3::ORIGIN,
                Point3::ORIGIN,
            )))
            .run();
        assert_error(&r, "axis has zero length");
        assert!(is_null(&r, 1));
    }

    #[test]
    fn rotate_3d_matches_the_kernel_rotation() {
        let center = Point3::new(3.0, 4.0, 5.0);
        let axis = Vector3::new(1.0, 1.0, 0.0);
        let r = NodeCall::new(&rotate_3d())
            .input(DataTree::from_item(Vector3::new(0.0, 0.0, 2.0)))
            .input(DataTree::from_item(FRAC_PI_4))
            .input(DataTree::from_item(center))
            .input(DataTree::from_item(axis))
            .run();
        assert_clean(&r);
        let x = only::<Transform>(&r, 1);
        assert_eq!(x, Transform::rotation(FRAC_PI_4, axis, center).unwrap());
        assert!(x.transform_point(center).abs_diff_eq(center, 1e-14));
        // Vectors rotate without the translation and keep their length.
        let Value::Vector(v) = only_value(&r, 0) else {
            panic!("expected a vector");
        };
        assert!((v.length() - 2.0).abs() < 1e-15);
        assert!(v.dot(axis).abs() < 1e-15);
        let r = NodeCall::new(&rotate_3d())
            .skip_input()
            .skip_input()
            .skip_input()
            .input(DataTree::from_item(Vector3::ZERO))
            .run();
        assert_error(&r, "axis has zero length");
    }

    #[test]
    fn mirror_across_world_xy_as_in_the_book() {
        // The book's mirror across the world xy-plane: diag(1, 1, −1, 1).
        let r = NodeCall::new(&mirror())
            .input(DataTree::from_item(Point3::new(1.0, 2.0, 3.0)))
            .input(DataTree::from_item(Plane::WORLD_XY))
            .run();
        assert_clean(&r);
        rows_close(
            &only::<Transform>(&r, 1),
            [
                [1.0, 0.0, 0.0, 0.0],
                [0.0, 1.0, 0.0, 0.0],
                [0.0, 0.0, -1.0, 0.0],
                [0.0, 0.0, 0.0, 1.0],
            ],
            0.0,
        );
        assert_eq!(only_value(&r, 0), Value::Point(Point3::new(1.0, 2.0, -3.0)));
        // The default plane is World YZ; a mirrored circle is still a circle.
        let c = Circle::new(Plane::WORLD_XY.translated(Vector3::new(5.0, 0.0, 0.0)), 2.0).unwrap();
        let r = NodeCall::new(&mirror()).input(DataTree::from_item(c)).run();
        let Value::Circle(m) = only_value(&r, 0) else {
            panic!("expected a circle");
        };
        assert!(m.center().abs_diff_eq(Point3::new(-5.0, 0.0, 0.0), 1e-15));
        assert_eq!(m.radius, 2.0);
        assert!(m.plane.is_valid());
    }

    #[test]
    fn mirror_and_orient_with_a_nan_plane() {
        let nan = Plane::WORLD_XY.translated(Vector3::new(0.0, f64::NAN, 0.0));
        let r = NodeCall::new(&mirror())
            .input(DataTree::from_item(Point3::ORIGIN))
            .input(DataTree::from_item(nan))
            .run();
        assert_error(&r, "not finite");
        assert!(is_null(&r, 0) && is_null(&r, 1));
        let r = NodeCall::new(&orient())
            .input(DataTree::from_item(Point3::ORIGIN))
            .skip_input()
            .input(DataTree::from_item(nan))
            .run();
        assert_error(&r, "not finite");
        assert!(is_null(&r, 0) && is_null(&r, 1));
    }

    #[test]
    fn orient_keeps_plane_coordinates() {
        let from = Plane::WORLD_XY;
        let to = Plane::from_points(
            Point3::new(1.0, 1.0, 1.0),
            Point3::new(1.0, 2.0, 1.0),
            Point3::new(0.0, 1.0, 1.0),
        )
        .unwrap();
        let r = NodeCall::new(&orient())
            .input(DataTree::from_item(Point3::new(2.0, 3.0, 4.0)))
            .input(DataTree::from_item(from))
            .input(DataTree::from_item(to))
            .run();
        assert_clean(&r);
        let Value::Point(p) = only_value(&r, 0) else {
            panic!("expected a point");
        };
        assert!(p.abs_diff_eq(to.point_at(2.0, 3.0, 4.0), 1e-14));
        // A plane goes onto the target plane.
        let r = NodeCall::new(&orient())
            .input(DataTree::from_item(from))
            .input(DataTree::from_item(from))
            .input(DataTree::from_item(to))
            .run();
        let Value::Plane(q) = only_value(&r, 0) else {
            panic!("expected a plane");
        };
        assert!(q.abs_diff_eq(&to, 1e-15));
        // Without a target the node has nothing to do.
        let r = NodeCall::new(&orient())
            .input(DataTree::from_item(Point3::ORIGIN))
            .run();
        assert!(r.outputs[1].values().all(|v| v.is_none()));
    }

    #[test]
    fn rotate_a_curve_keeps_its_kind() {
        let line = Curve::from(Line::new(Point3::ORIGIN, Point3::new(2.0, 0.0, 0.0)));
        let r = NodeCall::new(&rotate())
            .input(DataTree::from_item(locus_runtime::Shared::new(line)))
            .run();
        let Value::Curve(c) = only_value(&r, 0) else {
            panic!("expected a curve");
        };
        assert!(matches!(*c, Curve::Line { .. }));
        assert!(c.end_point().abs_diff_eq(Point3::new(0.0, 2.0, 0.0), 1e-15));
    }
}

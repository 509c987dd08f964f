//! Vector › Plane, changing planes: Flip Plane, Plane Origin, Align Plane and Rotate Plane.
//!
//! Every result is orthonormal and right-handed (`z = x × y`). A plane that is not valid (an
//! axis of zero length or not finite) is an error for the item.

use locus_kernel::{Plane, Point3, Vector3};
use locus_runtime::{DataType, NodeError, NodeRegistry, NodeType, Port};

use super::{finite_number, finite_point, finite_vector};

/// Id of [`flip_plane`].
pub const FLIP_PLANE: &str = "vector.flip_plane";
/// Id of [`plane_origin`].
pub const PLANE_ORIGIN: &str = "vector.plane_origin";
/// Id of [`align_plane`].
pub const ALIGN_PLANE: &str = "vector.align_plane";
/// Id of [`rotate_plane`].
pub const ROTATE_PLANE: &str = "vector.rotate_plane";

/// How long, relative to the direction's length, the part of Align Plane's direction in the
/// plane must be for it to give the x axis a direction: 1e-12 (below that the direction is
/// along the normal).
pub const ALIGN_TOLERANCE: f64 = 1e-12;

/// Registers the plane editing nodes.
pub fn register(registry: &mut NodeRegistry) {
    for t in [flip_plane(), plane_origin(), align_plane(), rotate_plane()] {
        registry.register(t);
    }
}

fn plane_node(id: &str, name: &str, nickname: &str) -> NodeType {
    NodeType::new(id, name, nickname, "Vector").subcategory("Plane")
}

fn valid(plane: &Plane, what: &str) -> Result<Plane, NodeError> {
    if plane.is_valid() {
        Ok(*plane)
    } else {
        Err(NodeError(format!("{what} is not a valid plane")))
    }
}

/// `plane` with x axis `x` and y axis `y` (unit and perpendicular), normal `x × y`.
fn with_axes(plane: &Plane, x: Vector3, y: Vector3) -> Plane {
    Plane {
        origin: plane.origin,
        x_axis: x,
        y_axis: y,
        z_axis: x.cross(y),
    }
}

/// `plane` turned about its normal by `angle` radians, counter-clockwise seen from above.
pub fn rotated_about_normal(plane: &Plane, angle: f64) -> Plane {
    let (sin, cos) = angle.sin_cos();
    let x = plane.x_axis * cos + plane.y_axis * sin;
    let y = plane.y_axis * cos - plane.x_axis * sin;
    with_axes(plane, x, y)
}

fn boolean(name: &str, nickname: &str, doc: &str) -> Port {
    Port::new(name, nickname, DataType::Boolean)
        .doc(doc)
        .default_value(false)
}

/// Flip Plane \[PFlip\]: reverse or swap a plane's axes.
pub fn flip_plane() -> NodeType {
    plane_node(FLIP_PLANE, "Flip Plane", "PFlip")
        .gh_guid("c73e1ed0-82a2-40b0-b4df-8f10e445d60b")
        .description(
            "Flips or swaps the axes of a plane: Reverse X negates the x axis, Reverse Y the y \
             axis, then Swap axes exchanges them; the normal is always x × y, so reversing one \
             axis or swapping them reverses it.",
        )
        .input(Port::new("Plane", "P", DataType::Plane).doc("The plane to flip."))
        .input(boolean(
            "Reverse X",
            "X",
            "Whether to reverse the x axis; default false.",
        ))
        .input(boolean(
            "Reverse Y",
            "Y",
            "Whether to reverse the y axis; default false.",
        ))
        .input(boolean(
            "Swap axes",
            "S",
            "Whether to swap the x and y axes (after reversing); default false.",
        ))
        .output(Port::new("Plane", "P", DataType::Plane).doc("The flipped plane."))
        .solve(|s| {
            let plane = valid(s.item::<Plane>(0)?, "plane P")?;
            let (rx, ry, swap) = (
                *s.item::<bool>(1)?,
                *s.item::<bool>(2)?,
                *s.item::<bool>(3)?,
            );
            let mut x = if rx { -plane.x_axis } else { plane.x_axis };
            let mut y = if ry { -plane.y_axis } else { plane.y_axis };
            if swap {
                std::mem::swap(&mut x, &mut y);
            }
            s.set(0, with_axes(&plane, x, y));
            Ok(())
        })
}

/// Plane Origin \[Pl Origin\]: a plane moved to a new origin.
pub fn plane_origin() -> NodeType {
    plane_node(PLANE_ORIGIN, "Plane Origin", "Pl Origin")
        .gh_guid("75eec078-a905-47a1-b0d2-0934182b1e3d")
        .description("Changes the origin of a plane: the same axes through the new origin point.")
        .input(Port::new("Base", "B", DataType::Plane).doc("The plane whose axes are kept."))
        .input(Port::new("Origin", "O", DataType::Point).doc("The new origin."))
        .output(Port::new("Plane", "Pl", DataType::Plane).doc("The plane through the new origin."))
        .lift2(|base: &Plane, origin: &Point3| {
            let base = valid(base, "base B")?;
            Ok(Plane {
                origin: finite_point(*origin, "origin O")?,
                ..base
            })
        })
}

/// Align Plane \[Align\]: the smallest turn of a plane about its normal that points its x axis
/// along a direction.
pub fn align_plane() -> NodeType {
    plane_node(ALIGN_PLANE, "Align Plane", "Align")
        .gh_guid("e76040ec-3b91-41e1-8e00-c74c23b89391")
        .description(
            "Turns a plane about its normal so that its x axis points along the direction D \
             projected into the plane; the normal and origin stay. The angle A is the turn, \
             counter-clockwise seen from above, in −π to π. A direction along the normal (or \
             of zero length) has no projection and is an error.",
        )
        .input(Port::new("Plane", "P", DataType::Plane).doc("The plane to align."))
        .input(Port::new("Direction", "D", DataType::Vector).doc("The guide direction."))
        .output(Port::new("Plane", "P", DataType::Plane).doc("The aligned plane."))
        .output(
            Port::new("Angle", "A", DataType::Number)
                .doc("The rotation angle, in radians, counter-clockwise about the normal."),
        )
        .lift2_with(|plane: &Plane, d: &Vector3, _report| {
            let plane = valid(plane, "plane P")?;
            let d = finite_vector(*d, "direction D")?;
            let (u, v) = (d.dot(plane.x_axis), d.dot(plane.y_axis));
            if u.hypot(v) <= ALIGN_TOLERANCE * d.length() || d.length() == 0.0 {
                return Err(
                    "direction D is along the plane's normal (or zero) and has no \
                            direction in the plane"
                        .into(),
                );
            }
            let angle = v.atan2(u);
            Ok((rotated_about_normal(&plane, angle), angle))
        })
}

/// Rotate Plane \[PRot\]: a plane turned about its normal.
pub fn rotate_plane() -> NodeType {
    plane_node(ROTATE_PLANE, "Rotate Plane", "PRot")
        .gh_guid("f6f14b09-6497-4564-8403-09e4eb5a6b82")
        .description(
            "Rotates a plane about its own normal (z axis) through its origin, by an angle in \
             radians, counter-clockwise seen from above.",
        )
        .input(Port::new("Plane", "P", DataType::Plane).doc("The plane to rotate."))
        .input(
            Port::new("Angle", "A", DataType::Number)
                .doc("The rotation angle, in radians; default 0.")
                .default_value(0.0),
        )
        .output(Port::new("Plane", "P", DataType::Plane).doc("The rotated plane."))
        .lift2(|plane: &Plane, angle: &f64| {
            let plane = valid(plane, "plane P")?;
            let angle = finite_number(*angle, "angle A")?;
            Ok(rotated_about_normal(&plane, angle))
        })
}

#[cfg(test)]
mod tests {
    use std::f64::consts::{FRAC_PI_2, FRAC_PI_4};

    use locus_runtime::{DataTree, NodeCall};

    use super::*;
    use crate::test_support::{assert_error, only};

    fn near(a: Vector3, b: Vector3) -> bool {
        (a - b).length() < 1e-12
    }

    fn plane_at(o: Point3) -> DataTree {
        DataTree::from_item(Plane {
            origin: o,
            ..Plane::WORLD_XY
        })
    }

    #[test]
    fn flip_plane_reverses_then_swaps() {
        let run = |x: bool, y: bool, swap: bool| {
            let r = NodeCall::new(&flip_plane())
                .input(plane_at(Point3::new(1.0, 2.0, 3.0)))
                .input(DataTree::from_item(x))
                .input(DataTree::from_item(y))
                .input(DataTree::from_item(swap))
                .run();
            only::<Plane>(&r, 0)
        };
        let p = run(false, false, false);
        assert_eq!(
            p,
            Plane {
                origin: Point3::new(1.0, 2.0, 3.0),
                ..Plane::WORLD_XY
            }
        );
        let p = run(true, false, false);
        assert_eq!(
            (p.x_axis, p.y_axis, p.z_axis),
            (-Vector3::X, Vector3::Y, -Vector3::Z)
        );
        let p = run(false, false, true);
        assert_eq!(
            (p.x_axis, p.y_axis, p.z_axis),
            (Vector3::Y, Vector3::X, -Vector3::Z)
        );
        let p = run(true, true, true);
        assert_eq!(
            (p.x_axis, p.y_axis, p.z_axis),
            (-Vector3::Y, -Vector3::X, -Vector3::Z)
        );
    }

    #[test]
    fn plane_origin_keeps_the_axes() {
        let r = NodeCall::new(&plane_origin())
            .input(DataTree::from_item(Plane::WORLD_YZ))
            .input(DataTree::from_item(Point3::new(4.0, 5.0, 6.0)))
            .run();
        let p = only::<Plane>(&r, 0);
        assert_eq!(p.origin, Point3::new(4.0, 5.0, 6.0));
        assert_eq!(p.z_axis, Plane::WORLD_YZ.z_axis);
        let r = NodeCall::new(&plane_origin())
            .input(DataTree::from_item(Plane::WORLD_YZ))
            .input(DataTree::from_item(Point3::new(f64::NAN, 5.0, 6.0)))
            .run();
        assert_error(&r, "origin O has a coordinate that is not finite");
    }

    #[test]
    fn align_plane_turns_x_towards_the_projected_direction() {
        let r = NodeCall::new(&align_plane())
            .input(plane_at(Point3::ORIGIN))
            .input(DataTree::from_item(Vector3::new(1.0, 1.0, 5.0)))
            .run();
        let p = only::<Plane>(&r, 0);
        let h = std::f64::consts::FRAC_1_SQRT_2;
        assert!(near(p.x_axis, Vector3::new(h, h, 0.0)));
        assert!(near(p.y_axis, Vector3::new(-h, h, 0.0)));
        assert!(near(p.z_axis, Vector3::Z));
        assert!((only::<f64>(&r, 1) - FRAC_PI_4).abs() < 1e-15);
        let r = NodeCall::new(&align_plane())
            .input(plane_at(Point3::ORIGIN))
            .input(DataTree::from_item(Vector3::new(0.0, -2.0, 0.0)))
            .run();
        assert!((only::<f64>(&r, 1) + FRAC_PI_2).abs() < 1e-15);
        let r = NodeCall::new(&align_plane())
            .input(plane_at(Point3::ORIGIN))
            .input(DataTree::from_item(Vector3::new(0.0, 0.0, 2.0)))
            .run();
        assert_error(&r, "along the plane's normal");
    }

    #[test]
    fn rotate_plane_turns_about_the_normal() {
        let r = NodeCall::new(&rotate_plane())
            .input(plane_at(Point3::new(1.0, 0.0, 0.0)))
            .input(DataTree::from_item(FRAC_PI_2))
            .run();
        let p = only::<Plane>(&r, 0);
        assert_eq!(p.origin, Point3::new(1.0, 0.0, 0.0));
        assert!(near(p.x_axis, Vector3::Y));
        assert!(near(p.y_axis, -Vector3::X));
        assert!(near(p.z_axis, Vector3::Z));
        let bad = Plane {
            x_axis: Vector3::ZERO,
            ..Plane::WORLD_XY
        };
        let r = NodeCall::new(&rotate_plane())
            .input(DataTree::from_item(bad))
            .run();
        assert_error(&r, "plane P is not a valid plane");
    }
}

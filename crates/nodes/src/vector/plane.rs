//! Vector › Plane: planes from points and axes, the world planes, a plane's parts and equation,
//! and the closest point of a plane.
//!
//! Planes are orthonormal and right-handed (`z = x × y`), as in Rhino. The world planes follow
//! Grasshopper: *XY Plane* has axes X, Y and normal +Z; *YZ Plane* has axes Y, Z and normal +X;
//! *XZ Plane* has axes X, Z and therefore normal X × Z = −Y (Rhino's Front construction plane).

use locus_kernel::{Plane, Point3, Vector3};
use locus_runtime::{DataType, NodeRegistry, NodeType, Port};

use super::{finite_point, finite_vector, warn_unless_finite};

/// Id of [`construct_plane`].
pub const CONSTRUCT_PLANE: &str = "vector.construct_plane";
/// Id of [`plane_3pt`].
pub const PLANE_3PT: &str = "vector.plane_3pt";
/// Id of [`plane_normal`].
pub const PLANE_NORMAL: &str = "vector.plane_normal";
/// Id of [`xy_plane`].
pub const XY_PLANE: &str = "vector.xy_plane";
/// Id of [`yz_plane`].
pub const YZ_PLANE: &str = "vector.yz_plane";
/// Id of [`xz_plane`].
pub const XZ_PLANE: &str = "vector.xz_plane";
/// Id of [`deconstruct_plane`].
pub const DECONSTRUCT_PLANE: &str = "vector.deconstruct_plane";
/// Id of [`plane_coefficients`].
pub const PLANE_COEFFICIENTS: &str = "vector.plane_coefficients";
/// Id of [`plane_closest_point`].
pub const PLANE_CLOSEST_POINT: &str = "vector.plane_closest_point";

/// Grasshopper's world XZ plane: origin (0,0,0), x axis X, y axis Z, normal −Y.
pub const WORLD_XZ: Plane = Plane {
    origin: Point3::ORIGIN,
    x_axis: Vector3::X,
    y_axis: Vector3::Z,
    z_axis: Vector3::new(0.0, -1.0, 0.0),
};

/// Registers the Plane nodes.
pub fn register(registry: &mut NodeRegistry) {
    for t in [
        construct_plane(),
        plane_3pt(),
        plane_normal(),
        xy_plane(),
        yz_plane(),
        xz_plane(),
        deconstruct_plane(),
        plane_coefficients(),
        plane_closest_point(),
    ] {
        registry.register(t);
    }
}

fn plane_node(id: &str, name: &str, nickname: &str) -> NodeType {
    NodeType::new(id, name, nickname, "Vector").subcategory("Plane")
}

/// Construct Plane \[Pl\]: a plane from an origin and two axis directions.
pub fn construct_plane() -> NodeType {
    plane_node(CONSTRUCT_PLANE, "Construct Plane", "Pl")
        .gh_guid("bc3e379e-7206-4e7b-b63a-ff61f4b38a3e")
        .description(
            "Makes a plane from an origin and {x, y} axis directions. The x axis is the unit \
             X direction; the y axis is the part of the Y direction perpendicular to it, made \
             one unit long; the normal is x × y. A zero-length axis, or a Y parallel to X, is \
             an error.",
        )
        .input(
            Port::new("Origin", "O", DataType::Point)
                .doc("The origin of the plane. Default (0, 0, 0).")
                .default_value(Point3::ORIGIN),
        )
        .input(
            Port::new("X-Axis", "X", DataType::Vector)
                .doc("The direction of the x axis; its length does not matter. Default <1, 0, 0>.")
                .default_value(Vector3::X),
        )
        .input(
            Port::new("Y-Axis", "Y", DataType::Vector)
                .doc(
                    "A direction in the plane, not parallel to X, towards the positive y side. \
                     Default <0, 1, 0>.",
                )
                .default_value(Vector3::Y),
        )
        .output(Port::new("Plane", "Pl", DataType::Plane).doc("The plane."))
        .lift3(|o: &Point3, x: &Vector3, y: &Vector3| Ok(Plane::from_frame(*o, *x, *y)?))
}

/// Plane 3Pt \[Pl 3Pt\]: the plane through three points.
pub fn plane_3pt() -> NodeType {
    plane_node(PLANE_3PT, "Plane 3Pt", "Pl 3Pt")
        .description(
            "Makes the plane through three points: the origin at A, the x axis towards B and \
             C on the positive y side; the normal is (B − A) × (C − A), unitized. Collinear or \
             coincident points do not define a plane and are an error.",
        )
        .input(Port::new("Point A", "A", DataType::Point).doc("The origin of the plane."))
        .input(Port::new("Point B", "B", DataType::Point).doc("A point on the x axis."))
        .input(
            Port::new("Point C", "C", DataType::Point)
                .doc("A point on the positive y side of the plane."),
        )
        .output(Port::new("Plane", "Pl", DataType::Plane).doc("The plane through A, B and C."))
        .lift3(|a: &Point3, b: &Point3, c: &Point3| Ok(Plane::from_points(*a, *b, *c)?))
}

/// Plane Normal \[Pl\]: the plane through a point with a given normal.
pub fn plane_normal() -> NodeType {
    plane_node(PLANE_NORMAL, "Plane Normal", "Pl")
        .gh_guid("cfb6b17f-ca82-4f5d-b604-d4f69f569de3")
        .description(
            "Makes the plane through an origin with the given normal (z axis). The x axis is \
             chosen as Rhino chooses it, perpendicular to the normal; a normal along +Z gives \
             the world XY plane. A zero-length normal is an error.",
        )
        .input(
            Port::new("Origin", "O", DataType::Point)
                .doc("The origin of the plane. Default (0, 0, 0).")
                .default_value(Point3::ORIGIN),
        )
        .input(
            Port::new("Z-Axis", "Z", DataType::Vector)
                .doc("The normal of the plane; its length does not matter. Default <0, 0, 1>.")
                .default_value(Vector3::Z),
        )
        .output(Port::new("Plane", "P", DataType::Plane).doc("The plane."))
        .lift2(|o: &Point3, z: &Vector3| Ok(Plane::from_normal(*o, *z)?))
}

fn world_plane(id: &str, name: &str, nickname: &str, plane: Plane, axes: &str) -> NodeType {
    plane_node(id, name, nickname)
        .description(&format!(
            "Makes a plane parallel to the world {name}: {axes}, through the given origin."
        ))
        .input(
            Port::new("Origin", "O", DataType::Point)
                .doc("The origin of the plane. Default (0, 0, 0).")
                .default_value(Point3::ORIGIN),
        )
        .output(Port::new("Plane", "P", DataType::Plane).doc(&format!("The {name}.")))
        .lift1(move |o: &Point3| {
            let o = finite_point(*o, "origin O")?;
            Ok(Plane { origin: o, ..plane })
        })
}

/// XY Plane \[XY\]: the world XY plane through a point.
pub fn xy_plane() -> NodeType {
    world_plane(
        XY_PLANE,
        "XY Plane",
        "XY",
        Plane::WORLD_XY,
        "x axis <1, 0, 0>, y axis <0, 1, 0>, normal <0, 0, 1>",
    )
    .gh_guid("17b7152b-d30d-4d50-b9ef-c9fe25576fc2")
}

/// YZ Plane \[YZ\]: the world YZ plane through a point.
pub fn yz_plane() -> NodeType {
    world_plane(
        YZ_PLANE,
        "YZ Plane",
        "YZ",
        Plane::WORLD_YZ,
        "x axis <0, 1, 0>, y axis <0, 0, 1>, normal <1, 0, 0>",
    )
    .gh_guid("fad344bc-09b1-4855-a2e6-437ef5715fe3")
}

/// XZ Plane \[XZ\]: the world XZ plane through a point (normal −Y, see [`WORLD_XZ`]).
pub fn xz_plane() -> NodeType {
    world_plane(
        XZ_PLANE,
        "XZ Plane",
        "XZ",
        WORLD_XZ,
        "x axis <1, 0, 0>, y axis <0, 0, 1>, normal <0, −1, 0> (x × y, as Rhino's Front \
         construction plane)",
    )
    .gh_guid("8cc3a196-f6a0-49ea-9ed9-0cb343a3ae64")
}

/// Deconstruct Plane \[DePlane\]: the origin and axes of a plane.
pub fn deconstruct_plane() -> NodeType {
    plane_node(DECONSTRUCT_PLANE, "Deconstruct Plane", "DePlane")
        .gh_guid("3cd2949b-4ea8-4ffb-a70c-5c380f9f46ea")
        .description(
            "Splits a plane into its origin and its three unit axes. A plane with a NaN or \
             infinite coordinate is passed on with a warning.",
        )
        .input(Port::new("Plane", "P", DataType::Plane).doc("The plane to deconstruct."))
        .output(Port::new("Origin", "O", DataType::Point).doc("The origin of the plane."))
        .output(Port::new("X-Axis", "X", DataType::Vector).doc("The unit x axis."))
        .output(Port::new("Y-Axis", "Y", DataType::Vector).doc("The unit y axis."))
        .output(Port::new("Z-Axis", "Z", DataType::Vector).doc("The unit normal, x × y."))
        .lift1_with(|p: &Plane, report| {
            warn_unless_finite(report, p.is_finite(), "plane P");
            Ok((p.origin, p.x_axis, p.y_axis, p.z_axis))
        })
}

/// Plane Coefficients \[PlEq\]: the coefficients of the plane's equation.
pub fn plane_coefficients() -> NodeType {
    plane_node(PLANE_COEFFICIENTS, "Plane Coefficients", "PlEq")
        .description(
            "Gives the coefficients of the plane's equation A·x + B·y + C·z + D = 0, the \
             book's a(x − x0) + b(y − y0) + c(z − z0) = 0 with (A, B, C) the unit normal: \
             D = −normal · origin, so A·x + B·y + C·z + D is the signed distance of a point \
             (x, y, z) from the plane.",
        )
        .input(Port::new("Plane", "P", DataType::Plane).doc("The plane."))
        .output(
            Port::new("Coefficient A", "A", DataType::Number)
                .doc("The x component of the unit normal."),
        )
        .output(
            Port::new("Coefficient B", "B", DataType::Number)
                .doc("The y component of the unit normal."),
        )
        .output(
            Port::new("Coefficient C", "C", DataType::Number)
                .doc("The z component of the unit normal."),
        )
        .output(Port::new("Coefficient D", "D", DataType::Number).doc(
            "The constant term, −normal · origin: minus the signed distance of the \
                 world origin from the plane, in model units.",
        ))
        .lift1_with(|p: &Plane, report| {
            warn_unless_finite(report, p.is_finite(), "plane P");
            let [a, b, c, d] = p.equation();
            Ok((a, b, c, d))
        })
}

/// Plane Closest Point \[Plane CP\]: the foot of the perpendicular from a point to a plane.
pub fn plane_closest_point() -> NodeType {
    plane_node(PLANE_CLOSEST_POINT, "Plane Closest Point", "Plane CP")
        .description(
            "Projects a point onto a plane along its normal: the closest point of the plane, \
             its plane coordinates {u, v} and the distance to it.",
        )
        .input(Port::new("Sample", "S", DataType::Point).doc("The point to project."))
        .input(
            Port::new("Plane", "P", DataType::Plane)
                .doc("The plane to project onto. Default the world XY plane.")
                .default_value(Plane::WORLD_XY),
        )
        .output(
            Port::new("Point", "P", DataType::Point).doc("The point of the plane closest to S."),
        )
        .output(Port::new("UV Point", "uvP", DataType::Point).doc(
            "The plane coordinates of the closest point as the point (u, v, 0): u along \
                 the x axis and v along the y axis from the origin, in model units.",
        ))
        .output(
            Port::new("Distance", "D", DataType::Number)
                .doc("The distance from S to the plane, in model units; never negative."),
        )
        .solve(|s| {
            let sample = finite_point(*s.item::<Point3>(0)?, "sample S")?;
            let plane = *s.item::<Plane>(1)?;
            finite_point(plane.origin, "the plane's origin")?;
            finite_vector(plane.z_axis, "the plane's normal")?;
            let (u, v) = plane.closest_parameter(sample);
            s.set(0, plane.closest_point(sample));
            s.set(1, Point3::new(u, v, 0.0));
            s.set(2, plane.distance_to(sample));
            Ok(())
        })
}

#[cfg(test)]
mod tests {
    use locus_runtime::{DataTree, Level, NodeCall};

    use super::*;
    use crate::vector::test_support::{assert_clean, assert_error, is_null, messages, only};

    fn v(x: f64, y: f64, z: f64) -> Vector3 {
        Vector3::new(x, y, z)
    }

    #[test]
    fn construct_plane_orthogonalizes_y() {
        let r = NodeCall::new(&construct_plane())
            .input(DataTree::from_item(Point3::new(1.0, 2.0, 3.0)))
            .input(DataTree::from_item(v(2.0, 0.0, 0.0)))
            .input(DataTree::from_item(v(1.0, 1.0, 0.0)))
            .run();
        assert_clean(&r);
        let p = only::<Plane>(&r, 0);
        assert_eq!(p.origin, Point3::new(1.0, 2.0, 3.0));
        assert_eq!(
            (p.x_axis, p.y_axis, p.z_axis),
            (Vector3::X, Vector3::Y, Vector3::Z)
        );
        assert!(p.is_valid());
    }

    #[test]
    fn construct_plane_with_parallel_axes_is_an_error() {
        let r = NodeCall::new(&construct_plane())
            .skip_input()
            .input(DataTree::from_item(v(1.0, 1.0, 0.0)))
            .input(DataTree::from_item(v(-2.0, -2.0, 0.0)))
            .run();
        assert_error(&r, "collinear");
        assert!(is_null(&r, 0));
        let r = NodeCall::new(&construct_plane())
            .skip_input()
            .input(DataTree::from_item(Vector3::ZERO))
            .run();
        assert_error(&r, "zero length");
    }

    #[test]
    fn plane_3pt_follows_the_book_normal() {
        // The book: n = (B − A) × (C − A).
        let a = Point3::new(1.0, 0.0, 0.0);
        let b = Point3::new(3.0, 1.0, 0.0);
        let c = Point3::new(1.0, 2.0, 2.0);
        let r = NodeCall::new(&plane_3pt())
            .input(DataTree::from_item(a))
            .input(DataTree::from_item(b))
            .input(DataTree::from_item(c))
            .run();
        assert_clean(&r);
        let p = only::<Plane>(&r, 0);
        let n = (b - a).cross(c - a).unitize().unwrap();
        assert_eq!(p.origin, a);
        assert!(p.z_axis.abs_diff_eq(n, 1e-15));
        assert!(p.x_axis.abs_diff_eq((b - a).unitize().unwrap(), 1e-15));
        // C lies in the plane, on the positive y side.
        assert!(p.distance_to(c) < 1e-15);
        assert!(p.local_coordinates(c)[1] > 0.0);
    }

    #[test]
    fn plane_3pt_collinear_and_nan() {
        let r = NodeCall::new(&plane_3pt())
            .input(DataTree::from_item(Point3::ORIGIN))
            .input(DataTree::from_item(Point3::new(1.0, 1.0, 1.0)))
            .input(DataTree::from_item(Point3::new(3.0, 3.0, 3.0)))
            .run();
        assert_error(&r, "points are collinear");
        assert!(is_null(&r, 0));
        // Coincident points are collinear too.
        let r = NodeCall::new(&plane_3pt())
            .input(DataTree::from_item(Point3::ORIGIN))
            .input(DataTree::from_item(Point3::ORIGIN))
            .input(DataTree::from_item(Point3::new(0.0, 1.0, 0.0)))
            .run();
        assert_error(&r, "collinear");
        let r = NodeCall::new(&plane_3pt())
            .input(DataTree::from_item(Point3::new(f64::NAN, 0.0, 0.0)))
            .input(DataTree::from_item(Point3::ORIGIN))
            .input(DataTree::from_item(Point3::new(0.0, 1.0, 0.0)))
            .run();
        assert_error(&r, "not finite");
    }

    #[test]
    fn plane_normal_defaults_to_world_xy() {
        let r = NodeCall::new(&plane_normal()).run();
        assert_clean(&r);
        assert_eq!(only::<Plane>(&r, 0), Plane::WORLD_XY);
        let r = NodeCall::new(&plane_normal())
            .input(DataTree::from_item(Point3::new(0.0, 0.0, 5.0)))
            .input(DataTree::from_item(v(0.0, 0.0, -3.0)))
            .run();
        let p = only::<Plane>(&r, 0);
        assert_eq!(p.z_axis, -Vector3::Z);
        assert!(p.is_valid());
        let r = NodeCall::new(&plane_normal())
            .skip_input()
            .input(DataTree::from_item(Vector3::ZERO))
            .run();
        assert_error(&r, "normal has zero length");
    }

    #[test]
    fn world_planes() {
        let o = Point3::new(1.0, 2.0, 3.0);
        for (node, x, y, z) in [
            (xy_plane(), Vector3::X, Vector3::Y, Vector3::Z),
            (yz_plane(), Vector3::Y, Vector3::Z, Vector3::X),
            (xz_plane(), Vector3::X, Vector3::Z, -Vector3::Y),
        ] {
            let r = NodeCall::new(&node).input(DataTree::from_item(o)).run();
            assert_clean(&r);
            let p = only::<Plane>(&r, 0);
            assert_eq!((p.origin, p.x_axis, p.y_axis, p.z_axis), (o, x, y, z));
            assert!(p.is_valid(), "{} is not right-handed", node.name);
            let r = NodeCall::new(&node).run();
            assert_eq!(only::<Plane>(&r, 0).origin, Point3::ORIGIN);
            let r = NodeCall::new(&node)
                .input(DataTree::from_item(Point3::new(0.0, f64::NAN, 0.0)))
                .run();
            assert_error(&r, "origin O");
        }
    }

    #[test]
    fn deconstruct_plane_gives_origin_and_axes() {
        let plane = Plane::from_normal(Point3::new(1.0, 2.0, 3.0), v(1.0, 1.0, 1.0)).unwrap();
        let r = NodeCall::new(&deconstruct_plane())
            .input(DataTree::from_item(plane))
            .run();
        assert_clean(&r);
        assert_eq!(only::<Point3>(&r, 0), plane.origin);
        assert_eq!(only::<Vector3>(&r, 1), plane.x_axis);
        assert_eq!(only::<Vector3>(&r, 2), plane.y_axis);
        assert_eq!(only::<Vector3>(&r, 3), plane.z_axis);
    }

    #[test]
    fn taking_apart_a_nan_plane_warns() {
        let nan = Plane::WORLD_XY.translated(v(f64::NAN, 0.0, 0.0));
        for node in [deconstruct_plane(), plane_coefficients()] {
            let r = NodeCall::new(&node).input(DataTree::from_item(nan)).run();
            assert_eq!(messages(&r, Level::Warning).len(), 1, "{}", node.name);
            assert!(messages(&r, Level::Error).is_empty());
        }
    }

    #[test]
    fn plane_coefficients_give_the_signed_distance() {
        // The plane z = 2: 0x + 0y + 1z − 2 = 0.
        let plane = Plane::WORLD_XY.translated(v(5.0, -1.0, 2.0));
        let r = NodeCall::new(&plane_coefficients())
            .input(DataTree::from_item(plane))
            .run();
        assert_clean(&r);
        let abcd: Vec<f64> = (0..4).map(|k| only::<f64>(&r, k)).collect();
        assert_eq!(abcd, vec![0.0, 0.0, 1.0, -2.0]);
        // A tilted plane: the equation is zero on the plane and the signed distance off it.
        let plane = Plane::from_points(
            Point3::new(1.0, 0.0, 0.0),
            Point3::new(0.0, 1.0, 0.0),
            Point3::new(0.0, 0.0, 1.0),
        )
        .unwrap();
        let r = NodeCall::new(&plane_coefficients())
            .input(DataTree::from_item(plane))
            .run();
        let [a, b, c, d] = [0, 1, 2, 3].map(|k| only::<f64>(&r, k));
        let k = 1.0 / 3f64.sqrt();
        assert!((a - k).abs() < 1e-15 && (b - k).abs() < 1e-15 && (c - k).abs() < 1e-15);
        assert!((d + k).abs() < 1e-15);
        let value = |p: Point3| a * p.x + b * p.y + c * p.z + d;
        assert!(value(Point3::new(0.5, 0.5, 0.0)).abs() < 1e-15);
        assert!((value(Point3::ORIGIN) + k).abs() < 1e-15);
    }

    #[test]
    fn plane_closest_point_projects() {
        let plane = Plane::WORLD_YZ.translated(v(2.0, 0.0, 0.0));
        let r = NodeCall::new(&plane_closest_point())
            .input(DataTree::from_item(Point3::new(7.0, 3.0, 4.0)))
            .input(DataTree::from_item(plane))
            .run();
        assert_clean(&r);
        assert_eq!(only::<Point3>(&r, 0), Point3::new(2.0, 3.0, 4.0));
        assert_eq!(only::<Point3>(&r, 1), Point3::new(3.0, 4.0, 0.0));
        assert_eq!(only::<f64>(&r, 2), 5.0);
        // Below the plane the distance is still positive; default plane is World XY.
        let r = NodeCall::new(&plane_closest_point())
            .input(DataTree::from_item(Point3::new(1.0, 2.0, -3.0)))
            .run();
        assert_eq!(only::<Point3>(&r, 0), Point3::new(1.0, 2.0, 0.0));
        assert_eq!(only::<f64>(&r, 2), 3.0);
    }

    #[test]
    fn plane_closest_point_rejects_nan() {
        let r = NodeCall::new(&plane_closest_point())
            .input(DataTree::from_item(Point3::new(f64::NAN, 2.0, -3.0)))
            .run();
        assert_error(&r, "sample S");
        assert!(is_null(&r, 0) && is_null(&r, 1) && is_null(&r, 2));
    }
}

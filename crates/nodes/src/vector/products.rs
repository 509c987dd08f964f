//! Vector › Vector: the dot and cross products of two vectors and the angle between them.

use std::f64::consts::TAU;

use locus_kernel::{Plane, Vector3};
use locus_runtime::{DataType, NodeRegistry, NodeType, Port};

use super::vectors::vector_node;
use super::{finite_vector, unit};

/// Id of [`dot_product`].
pub const DOT_PRODUCT: &str = "vector.dot_product";
/// Id of [`cross_product`].
pub const CROSS_PRODUCT: &str = "vector.cross_product";
/// Id of [`angle`].
pub const ANGLE: &str = "vector.angle";

/// Registers the product and angle nodes.
pub fn register(registry: &mut NodeRegistry) {
    for t in [dot_product(), cross_product(), angle()] {
        registry.register(t);
    }
}

/// Dot Product \[DProd\]: `A · B`.
pub fn dot_product() -> NodeType {
    vector_node(DOT_PRODUCT, "Dot Product", "DProd")
        .description(
            "Computes the dot product A · B = ax·bx + ay·by + az·bz = |A| |B| cos θ: positive \
             when the vectors point the same general way, negative when they point apart, \
             zero when they are perpendicular. With Unitize, the vectors are made one unit \
             long first, so the result is cos θ, between −1 and 1; unitizing a zero-length \
             vector is an error.",
        )
        .input(Port::new("Vector A", "A", DataType::Vector).doc("The first vector."))
        .input(Port::new("Vector B", "B", DataType::Vector).doc("The second vector."))
        .input(
            Port::new("Unitize", "U", DataType::Boolean)
                .doc("Whether to unitize A and B before multiplying. Default false.")
                .default_value(false),
        )
        .output(
            Port::new("Dot product", "D", DataType::Number)
                .doc("A · B, in square model units (unitless when unitized)."),
        )
        .lift3(|a: &Vector3, b: &Vector3, unitize: &bool| {
            let a = finite_vector(*a, "vector A")?;
            let b = finite_vector(*b, "vector B")?;
            Ok(if *unitize {
                unit(a, "vector A")?.dot(unit(b, "vector B")?)
            } else {
                a.dot(b)
            })
        })
}

/// Cross Product \[XProd\]: `A × B`.
pub fn cross_product() -> NodeType {
    vector_node(CROSS_PRODUCT, "Cross Product", "XProd")
        .description(
            "Computes the cross product A × B, the vector perpendicular to both by the \
             right-hand rule, whose length |A| |B| sin θ is the area of the parallelogram they \
             span. The order matters: B × A = −(A × B). With Unitize the result is made one \
             unit long; parallel vectors then have no cross direction, which is an error (the \
             length, 0, is still given).",
        )
        .input(Port::new("Vector A", "A", DataType::Vector).doc("The first vector."))
        .input(Port::new("Vector B", "B", DataType::Vector).doc("The second vector."))
        .input(
            Port::new("Unitize", "U", DataType::Boolean)
                .doc("Whether to unitize the result. Default false.")
                .default_value(false),
        )
        .output(
            Port::new("Vector", "V", DataType::Vector)
                .doc("A × B, or its unit vector when U is true."),
        )
        .output(
            Port::new("Length", "L", DataType::Number)
                .doc("The length of A × B before unitizing, in square model units."),
        )
        .solve(|s| {
            let a = finite_vector(*s.item::<Vector3>(0)?, "vector A")?;
            let b = finite_vector(*s.item::<Vector3>(1)?, "vector B")?;
            let c = a.cross(b);
            s.set(1, c.length());
            s.set(
                0,
                if *s.item::<bool>(2)? {
                    unit(c, "the cross product (the vectors are parallel or zero)")?
                } else {
                    c
                },
            );
            Ok(())
        })
}

/// Angle \[Angle\]: the angle between two vectors, optionally measured in a plane.
pub fn angle() -> NodeType {
    vector_node(ANGLE, "Angle", "Angle")
        .gh_guid("b464fccb-50e7-41bd-9789-8438db9bea9f")
        .description(
            "Computes the angle between two vectors in radians. Without a plane it is the \
             smaller angle, from 0 to π. With a plane, both vectors are projected onto it and \
             the angle is measured counter-clockwise from A to B about the plane's normal, \
             from 0 to 2π. The reflex angle is 2π minus the angle. Zero-length vectors (or, \
             with a plane, vectors perpendicular to it) have no direction and are an error.",
        )
        .input(Port::new("Vector A", "A", DataType::Vector).doc("The first vector."))
        .input(Port::new("Vector B", "B", DataType::Vector).doc("The second vector."))
        .input(
            Port::new("Plane", "P", DataType::Plane)
                .doc(
                    "The plane to measure in (optional). When given, the angle runs \
                     counter-clockwise about its normal. Default none.",
                )
                .optional(),
        )
        .output(
            Port::new("Angle", "A", DataType::Number)
                .doc("The angle from A to B, in radians: 0 to π, or 0 to 2π with a plane."),
        )
        .output(
            Port::new("Reflex", "R", DataType::Number)
                .doc("The reflex angle, 2π minus the angle, in radians."),
        )
        .solve(|s| {
            let a = *s.item::<Vector3>(0)?;
            let b = *s.item::<Vector3>(1)?;
            let angle = match s.item_opt::<Plane>(2) {
                Some(plane) => a.angle_in_plane(b, plane.normal())?,
                None => a.angle_to(b)?,
            };
            s.set(0, angle);
            s.set(1, TAU - angle);
            Ok(())
        })
}

#[cfg(test)]
mod tests {
    use std::f64::consts::{FRAC_PI_2, FRAC_PI_4, PI};

    use locus_kernel::Point3;
    use locus_runtime::{DataTree, NodeCall};

    use super::*;
    use crate::vector::test_support::{assert_clean, assert_error, is_null, only};

    fn v(x: f64, y: f64, z: f64) -> Vector3 {
        Vector3::new(x, y, z)
    }

    fn dot(a: Vector3, b: Vector3, unitize: bool) -> locus_runtime::NodeCallResult {
        NodeCall::new(&dot_product())
            .input(DataTree::from_item(a))
            .input(DataTree::from_item(b))
            .input(DataTree::from_item(unitize))
            .run()
    }

    #[test]
    fn dot_products_of_the_book() {
        let r = dot(v(1.0, 2.0, 3.0), v(5.0, 6.0, 7.0), false);
        assert_clean(&r);
        assert_eq!(only::<f64>(&r, 0), 38.0);
        assert_eq!(
            only::<f64>(&dot(Vector3::X, v(0.6, 0.8, 0.0), false), 0),
            0.6
        );
        let a = v(0.0, 3.0, 4.0);
        assert_eq!(only::<f64>(&dot(a, a, false), 0), 25.0);
        assert_eq!(only::<f64>(&dot(Vector3::X, Vector3::Y, false), 0), 0.0);
        // The projection length of a = <5, 2, 0> onto b = <9, 0, 0> is a · unit(b); the
        // book's own sum (5·1) + (2·0) + (0·0) gives 5 (its printed "2" is a misprint).
        let b = v(9.0, 0.0, 0.0);
        let unit_b = only::<Vector3>(
            &NodeCall::new(&super::super::vectors::unit_vector())
                .input(DataTree::from_item(b))
                .run(),
            0,
        );
        assert_eq!(only::<f64>(&dot(v(5.0, 2.0, 0.0), unit_b, false), 0), 5.0);
    }

    #[test]
    fn dot_product_unitized_is_the_cosine() {
        let r = dot(v(3.0, 0.0, 0.0), v(2.0, 2.0, 0.0), true);
        assert_clean(&r);
        assert!((only::<f64>(&r, 0) - FRAC_PI_4.cos()).abs() < 1e-15);
        // Opposite directions give −1.
        let r = dot(v(0.0, 0.0, 2.0), v(0.0, 0.0, -7.0), true);
        assert_eq!(only::<f64>(&r, 0), -1.0);
    }

    #[test]
    fn dot_product_bad_input() {
        // A zero vector is fine without unitizing ...
        let r = dot(Vector3::ZERO, Vector3::X, false);
        assert_eq!(only::<f64>(&r, 0), 0.0);
        // ... and an error with it.
        let r = dot(Vector3::ZERO, Vector3::X, true);
        assert_error(&r, "vector A has zero length");
        assert!(is_null(&r, 0));
        let r = dot(Vector3::X, v(f64::NAN, 0.0, 0.0), false);
        assert_error(&r, "vector B");
    }

    fn cross(a: Vector3, b: Vector3, unitize: bool) -> locus_runtime::NodeCallResult {
        NodeCall::new(&cross_product())
            .input(DataTree::from_item(a))
            .input(DataTree::from_item(b))
            .input(DataTree::from_item(unitize))
            .run()
    }

    #[test]
    fn cross_products_of_the_book() {
        let r = cross(v(3.0, 1.0, 0.0), v(1.0, 2.0, 0.0), false);
        assert_clean(&r);
        assert_eq!(only::<Vector3>(&r, 0), v(0.0, 0.0, 5.0));
        assert_eq!(only::<f64>(&r, 1), 5.0);
        assert_eq!(
            only::<Vector3>(&cross(Vector3::X, Vector3::Y, false), 0),
            Vector3::Z
        );
        assert_eq!(
            only::<Vector3>(&cross(Vector3::Y, Vector3::X, false), 0),
            -Vector3::Z
        );
        // Unitized, the length output still reports |A × B|.
        let r = cross(v(3.0, 1.0, 0.0), v(1.0, 2.0, 0.0), true);
        assert_eq!(only::<Vector3>(&r, 0), Vector3::Z);
        assert_eq!(only::<f64>(&r, 1), 5.0);
    }

    #[test]
    fn cross_product_of_parallel_vectors() {
        let r = cross(v(1.0, 2.0, 3.0), v(2.0, 4.0, 6.0), false);
        assert_clean(&r);
        assert_eq!(only::<Vector3>(&r, 0), Vector3::ZERO);
        let r = cross(v(1.0, 2.0, 3.0), v(2.0, 4.0, 6.0), true);
        assert_error(&r, "parallel");
        assert!(is_null(&r, 0));
        assert_eq!(only::<f64>(&r, 1), 0.0);
        let r = cross(v(f64::INFINITY, 2.0, 3.0), Vector3::X, false);
        assert_error(&r, "vector A");
    }

    fn angle_of(a: Vector3, b: Vector3, plane: Option<Plane>) -> locus_runtime::NodeCallResult {
        let node = angle();
        let call = NodeCall::new(&node)
            .input(DataTree::from_item(a))
            .input(DataTree::from_item(b));
        match plane {
            Some(p) => call.input(DataTree::from_item(p)).run(),
            None => call.run(),
        }
    }

    #[test]
    fn angle_without_plane() {
        let r = angle_of(Vector3::X, Vector3::Y, None);
        assert_clean(&r);
        assert_eq!(only::<f64>(&r, 0), FRAC_PI_2);
        assert_eq!(only::<f64>(&r, 1), 1.5 * PI);
        // Order does not matter, and lengths do not either.
        let r = angle_of(v(0.0, -3.0, 0.0), v(2.0, 0.0, 0.0), None);
        assert_eq!(only::<f64>(&r, 0), FRAC_PI_2);
        // The book: unit vectors <1,0,0> and <0.6,0.8,0> have cos θ = 0.6.
        let r = angle_of(Vector3::X, v(0.6, 0.8, 0.0), None);
        assert!((only::<f64>(&r, 0) - 0.6f64.acos()).abs() < 1e-15);
    }

    #[test]
    fn angle_in_a_plane_runs_counter_clockwise() {
        let xy = Plane::WORLD_XY;
        let r = angle_of(Vector3::X, -Vector3::Y, Some(xy));
        assert_clean(&r);
        assert!((only::<f64>(&r, 0) - 1.5 * PI).abs() < 1e-15);
        assert!((only::<f64>(&r, 1) - FRAC_PI_2).abs() < 1e-15);
        // Seen from below (the flipped plane), the same turn is a quarter turn.
        let r = angle_of(Vector3::X, -Vector3::Y, Some(xy.flipped()));
        assert!((only::<f64>(&r, 0) - FRAC_PI_2).abs() < 1e-15);
        // Components along the normal are ignored.
        let r = angle_of(v(1.0, 0.0, 5.0), v(0.0, 1.0, -3.0), Some(xy));
        assert!((only::<f64>(&r, 0) - FRAC_PI_2).abs() < 1e-15);
        // A plane elsewhere measures the same: only its normal matters.
        let moved = Plane::from_normal(Point3::new(4.0, 5.0, 6.0), Vector3::Z).unwrap();
        let r = angle_of(Vector3::X, Vector3::Y, Some(moved));
        assert!((only::<f64>(&r, 0) - FRAC_PI_2).abs() < 1e-15);
    }

    #[test]
    fn angle_bad_input() {
        let r = angle_of(Vector3::ZERO, Vector3::X, None);
        assert_error(&r, "zero length");
        assert!(is_null(&r, 0) && is_null(&r, 1));
        // A vector along the plane's normal has no direction in the plane.
        let r = angle_of(Vector3::Z, Vector3::X, Some(Plane::WORLD_XY));
        assert_error(&r, "zero length");
        let r = angle_of(v(f64::NAN, 0.0, 0.0), Vector3::X, None);
        assert_error(&r, "not finite");
    }
}

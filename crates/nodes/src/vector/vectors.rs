//! Vector › Vector: vectors from components, points and axes; lengths, unit vectors,
//! amplitudes, reversal and rotation. Dot and cross products and angles are in
//! [`super::products`].

use std::f64::consts::FRAC_PI_2;

use locus_kernel::{Point3, Vector3};
use locus_runtime::{DataType, ItemReport, NodeError, NodeRegistry, NodeType, Port};

use super::{finite_number, finite_point, finite_vector, unit, warn_unless_finite};

/// Id of [`vector_xyz`].
pub const VECTOR_XYZ: &str = "vector.vector_xyz";
/// Id of [`deconstruct_vector`].
pub const DECONSTRUCT_VECTOR: &str = "vector.deconstruct_vector";
/// Id of [`unit_x`].
pub const UNIT_X: &str = "vector.unit_x";
/// Id of [`unit_y`].
pub const UNIT_Y: &str = "vector.unit_y";
/// Id of [`unit_z`].
pub const UNIT_Z: &str = "vector.unit_z";
/// Id of [`vector_2pt`].
pub const VECTOR_2PT: &str = "vector.vector_2pt";
/// Id of [`unit_vector`].
pub const UNIT_VECTOR: &str = "vector.unit_vector";
/// Id of [`amplitude`].
pub const AMPLITUDE: &str = "vector.amplitude";
/// Id of [`vector_length`].
pub const VECTOR_LENGTH: &str = "vector.vector_length";
/// Id of [`reverse`].
pub const REVERSE: &str = "vector.reverse";
/// Id of [`rotate`].
pub const ROTATE: &str = "vector.rotate";

/// Registers the vector nodes of this file.
pub fn register(registry: &mut NodeRegistry) {
    for t in [
        vector_xyz(),
        deconstruct_vector(),
        unit_x(),
        unit_y(),
        unit_z(),
        vector_2pt(),
        unit_vector(),
        amplitude(),
        vector_length(),
        reverse(),
        rotate(),
    ] {
        registry.register(t);
    }
}

pub(super) fn vector_node(id: &str, name: &str, nickname: &str) -> NodeType {
    NodeType::new(id, name, nickname, "Vector").subcategory("Vector")
}

/// Vector XYZ \[Vec\]: a vector from its components, and its length.
pub fn vector_xyz() -> NodeType {
    vector_node(VECTOR_XYZ, "Vector XYZ", "Vec")
        .gh_guid("56b92eab-d121-43f7-94d3-6cd8f0ddead8")
        .description(
            "Makes a vector from its {x, y, z} components and gives its length \
             √(x² + y² + z²). A NaN or infinite component is an error.",
        )
        .input(
            Port::new("X component", "X", DataType::Number)
                .doc("The x component, in model units. Default 0.")
                .default_value(0.0),
        )
        .input(
            Port::new("Y component", "Y", DataType::Number)
                .doc("The y component, in model units. Default 0.")
                .default_value(0.0),
        )
        .input(
            Port::new("Z component", "Z", DataType::Number)
                .doc("The z component, in model units. Default 0.")
                .default_value(0.0),
        )
        .output(Port::new("Vector", "V", DataType::Vector).doc("The vector <X, Y, Z>."))
        .output(
            Port::new("Length", "L", DataType::Number)
                .doc("The length of the vector, in model units."),
        )
        .lift3_with(|x: &f64, y: &f64, z: &f64, _| {
            let x = finite_number(*x, "component X")?;
            let y = finite_number(*y, "component Y")?;
            let z = finite_number(*z, "component Z")?;
            let v = Vector3::new(x, y, z);
            Ok((v, v.length()))
        })
}

/// Deconstruct Vector \[DeVec\]: the components of a vector.
pub fn deconstruct_vector() -> NodeType {
    vector_node(DECONSTRUCT_VECTOR, "Deconstruct Vector", "DeVec")
        .gh_guid("a50fcd4a-cf42-4c3f-8616-022761e6cc93")
        .description(
            "Splits a vector into its x, y and z components. A NaN or infinite component is \
             passed on with a warning.",
        )
        .input(Port::new("Vector", "V", DataType::Vector).doc("The vector to deconstruct."))
        .output(Port::new("X component", "X", DataType::Number).doc("The x component."))
        .output(Port::new("Y component", "Y", DataType::Number).doc("The y component."))
        .output(Port::new("Z component", "Z", DataType::Number).doc("The z component."))
        .lift1_with_plain(
            // The sum of the coordinates is finite only when they all are (or overflows, a
            // case the reporting loop then takes): one check, nothing to report.
            |v: &Vector3| (v.x + v.y + v.z).is_finite(),
            |v: &Vector3| (v.x, v.y, v.z),
            |v: &Vector3, report| {
                warn_unless_finite(report, v.is_finite(), "vector V");
                Ok((v.x, v.y, v.z))
            },
        )
}

fn unit_axis(id: &str, name: &str, nickname: &str, axis: Vector3, letter: &str) -> NodeType {
    vector_node(id, name, nickname)
        .description(&format!(
            "Makes a vector along the world {letter} axis: the unit {letter} vector times the \
             factor (a negative factor points the other way)."
        ))
        .input(
            Port::new("Factor", "F", DataType::Number)
                .doc("The length and sense of the vector, in model units. Default 1.")
                .default_value(1.0),
        )
        .output(
            Port::new("Unit vector", "V", DataType::Vector)
                .doc(&format!("The {letter} axis scaled by the factor.")),
        )
        .lift1(move |f: &f64| Ok(axis * finite_number(*f, "factor F")?))
}

/// Unit X \[X\]: the world x axis times a factor.
pub fn unit_x() -> NodeType {
    unit_axis(UNIT_X, "Unit X", "X", Vector3::X, "x")
        .gh_guid("79f9fbb3-8f1d-4d9a-88a9-f7961b1012cd")
}

/// Unit Y \[Y\]: the world y axis times a factor.
pub fn unit_y() -> NodeType {
    unit_axis(UNIT_Y, "Unit Y", "Y", Vector3::Y, "y")
        .gh_guid("d3d195ea-2d59-4ffa-90b1-8b7ff3369f69")
}

/// Unit Z \[Z\]: the world z axis times a factor.
pub fn unit_z() -> NodeType {
    unit_axis(UNIT_Z, "Unit Z", "Z", Vector3::Z, "z")
        .gh_guid("9103c240-a6a9-4223-9b42-dbd19bf38e2b")
}

/// Vector 2Pt \[Vec2Pt\]: the vector from point A to point B.
pub fn vector_2pt() -> NodeType {
    vector_node(VECTOR_2PT, "Vector 2Pt", "Vec2Pt")
        .gh_guid("934ede4a-924a-4973-bb05-0dc4b36fae75")
        .description(
            "Makes the vector from point A to point B, B − A, optionally of unit length. \
             Unitizing the vector between two coincident points is an error (it has no \
             direction); the length is still given.",
        )
        .input(Port::new("Point A", "A", DataType::Point).doc("The base point (the tail)."))
        .input(Port::new("Point B", "B", DataType::Point).doc("The tip point (the head)."))
        .input(
            Port::new("Unitize", "U", DataType::Boolean)
                .doc("Whether to make the vector one unit long. Default false.")
                .default_value(false),
        )
        .output(
            Port::new("Vector", "V", DataType::Vector)
                .doc("B − A, or its unit vector when U is true."),
        )
        .output(
            Port::new("Length", "L", DataType::Number)
                .doc("The distance from A to B (the length before unitizing), in model units."),
        )
        .lift3_with_plain(
            // Not unitized and a finite difference (so finite points: an infinite or NaN
            // coordinate makes the difference's infinite or NaN), nothing to report. One check:
            // the sum of the coordinates is finite exactly when they all are, or overflows (a
            // case the reporting loop then takes).
            |&a: &Point3, &b: &Point3, unitize: &bool| {
                let v = b - a;
                !*unitize & (v.x + v.y + v.z).is_finite()
            },
            |&a: &Point3, &b: &Point3, _: &bool| {
                let v = b - a;
                (v, v.length())
            },
            vector_2pt_item,
        )
}

/// One item of Vector 2Pt, with its checks and reports.
fn vector_2pt_item(
    a: &Point3,
    b: &Point3,
    unitize: &bool,
    report: &mut ItemReport,
) -> Result<(Vector3, f64), NodeError> {
    let a = finite_point(*a, "point A")?;
    let b = finite_point(*b, "point B")?;
    let v = b - a;
    let vector = if *unitize {
        // The length is still given when the vector has no direction.
        unit(v, "the vector from A to B").unwrap_or_else(|e| {
            report.error(0, e.0);
            Vector3::ZERO
        })
    } else {
        v
    };
    Ok((vector, v.length()))
}

/// Unit Vector \[Unit\]: a vector scaled to length one.
pub fn unit_vector() -> NodeType {
    vector_node(UNIT_VECTOR, "Unit Vector", "Unit")
        .gh_guid("d2da1306-259a-4994-85a4-672d8a4c7805")
        .description(
            "Scales a vector to length one, keeping its direction: v / |v|. A zero-length \
             vector has no direction and is an error.",
        )
        .input(Port::new("Vector", "V", DataType::Vector).doc("The vector to unitize."))
        .output(
            Port::new("Unit vector", "V", DataType::Vector)
                .doc("The vector of length one in the direction of V."),
        )
        .lift1(|v: &Vector3| unit(*v, "vector V"))
}

/// Amplitude \[Amp\]: a vector with its length set.
pub fn amplitude() -> NodeType {
    vector_node(AMPLITUDE, "Amplitude", "Amp")
        .gh_guid("6ec39468-dae7-4ffa-a766-f2ab22a2c62e")
        .description(
            "Sets the length of a vector, keeping its direction: A · v / |v|. A negative \
             amplitude reverses the vector. A zero-length vector has no direction and is an \
             error.",
        )
        .input(Port::new("Vector", "V", DataType::Vector).doc("The vector to resize."))
        .input(
            Port::new("Amplitude", "A", DataType::Number)
                .doc("The new length, in model units. Default 1.")
                .default_value(1.0),
        )
        .output(
            Port::new("Vector", "V", DataType::Vector)
                .doc("The vector of length |A| along V (against V when A < 0)."),
        )
        .lift2(|v: &Vector3, a: &f64| {
            let a = finite_number(*a, "amplitude A")?;
            Ok(unit(*v, "vector V")? * a)
        })
}

/// Vector Length \[VLen\]: the length of a vector.
pub fn vector_length() -> NodeType {
    vector_node(VECTOR_LENGTH, "Vector Length", "VLen")
        .gh_guid("675e31bf-1775-48d7-bb8d-76b77786dd53")
        .description("Computes the length (magnitude) of a vector, √(x² + y² + z²).")
        .input(Port::new("Vector", "V", DataType::Vector).doc("The vector."))
        .output(
            Port::new("Length", "L", DataType::Number)
                .doc("The length of the vector, in model units; never negative."),
        )
        .lift1(|v: &Vector3| Ok(finite_vector(*v, "vector V")?.length()))
}

/// Reverse \[Rev\]: the vector pointing the other way.
pub fn reverse() -> NodeType {
    vector_node(REVERSE, "Reverse", "Rev")
        .gh_guid("d5788074-d75d-4021-b1a3-0bf992928584")
        .description("Reverses a vector: −v, the same length in the opposite direction.")
        .input(Port::new("Vector", "V", DataType::Vector).doc("The vector to reverse."))
        .output(Port::new("Vector", "V", DataType::Vector).doc("The reversed vector, −V."))
        .lift1(|v: &Vector3| Ok(-finite_vector(*v, "vector V")?))
}

/// Rotate \[VRot\]: a vector rotated about an axis.
pub fn rotate() -> NodeType {
    vector_node(ROTATE, "Rotate", "VRot")
        .gh_guid("b6d7ba20-cf74-4191-a756-2216a36e30a7")
        .description(
            "Rotates a vector about an axis through the origin by an angle in radians, \
             counter-clockwise seen from the tip of the axis (right-hand rule). A zero-length \
             axis is an error.",
        )
        .input(Port::new("Vector", "V", DataType::Vector).doc("The vector to rotate."))
        .input(
            Port::new("Axis", "X", DataType::Vector)
                .doc("The rotation axis; only its direction matters. Default the world z axis.")
                .default_value(Vector3::Z),
        )
        .input(
            Port::new("Angle", "A", DataType::Number)
                .doc("The rotation angle, in radians. Default ½π (a quarter turn).")
                .default_value(FRAC_PI_2),
        )
        .output(Port::new("Vector", "V", DataType::Vector).doc("The rotated vector."))
        .lift3(|v: &Vector3, axis: &Vector3, angle: &f64| {
            let v = finite_vector(*v, "vector V")?;
            let angle = finite_number(*angle, "angle A")?;
            Ok(v.rotated(angle, *axis)?)
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
    fn vector_xyz_gives_the_book_length() {
        let r = NodeCall::new(&vector_xyz())
            .input(DataTree::from_item(4.0))
            .input(DataTree::from_item(3.0))
            .run();
        assert_clean(&r);
        assert_eq!(only::<Vector3>(&r, 0), v(4.0, 3.0, 0.0));
        assert_eq!(only::<f64>(&r, 1), 5.0);
    }

    #[test]
    fn vector_xyz_rejects_nan() {
        let r = NodeCall::new(&vector_xyz())
            .skip_input()
            .input(DataTree::from_item(f64::NAN))
            .run();
        assert_error(&r, "component Y");
        assert!(is_null(&r, 0) && is_null(&r, 1));
    }

    #[test]
    fn deconstruct_vector_round_trips() {
        let r = NodeCall::new(&deconstruct_vector())
            .input(DataTree::from_item(v(-1.0, 2.5, 7.0)))
            .run();
        assert_clean(&r);
        assert_eq!(
            [only::<f64>(&r, 0), only::<f64>(&r, 1), only::<f64>(&r, 2)],
            [-1.0, 2.5, 7.0]
        );
    }

    #[test]
    fn deconstruct_vector_passes_infinity_on_with_a_warning() {
        let r = NodeCall::new(&deconstruct_vector())
            .input(DataTree::from_item(v(f64::INFINITY, 2.0, 0.0)))
            .run();
        assert_eq!(messages(&r, Level::Warning).len(), 1);
        assert_eq!(only::<f64>(&r, 0), f64::INFINITY);
        assert_eq!(only::<f64>(&r, 1), 2.0);
    }

    #[test]
    fn unit_axes_scale_by_the_factor() {
        let r = NodeCall::new(&unit_x()).run();
        assert_eq!(only::<Vector3>(&r, 0), Vector3::X);
        let r = NodeCall::new(&unit_y())
            .input(DataTree::from_item(-2.0))
            .run();
        assert_eq!(only::<Vector3>(&r, 0), v(0.0, -2.0, 0.0));
        let r = NodeCall::new(&unit_z())
            .input(DataTree::from_item(10.0))
            .run();
        assert_eq!(only::<Vector3>(&r, 0), v(0.0, 0.0, 10.0));
        let r = NodeCall::new(&unit_z())
            .input(DataTree::from_item(f64::INFINITY))
            .run();
        assert_error(&r, "factor F");
    }

    #[test]
    fn vector_2pt_is_b_minus_a() {
        // The book: a vector from the tip of b to the tip of a is a − b.
        let a = Point3::new(1.0, 2.0, 0.0);
        let b = Point3::new(4.0, 1.0, 4.0);
        let r = NodeCall::new(&vector_2pt())
            .input(DataTree::from_item(b))
            .input(DataTree::from_item(a))
            .run();
        assert_clean(&r);
        assert_eq!(only::<Vector3>(&r, 0), v(-3.0, 1.0, -4.0));
        assert_eq!(only::<f64>(&r, 1), 26f64.sqrt());
    }

    #[test]
    fn vector_2pt_unitized_keeps_the_length_output() {
        let r = NodeCall::new(&vector_2pt())
            .input(DataTree::from_item(Point3::new(1.0, 1.0, 1.0)))
            .input(DataTree::from_item(Point3::new(5.0, 4.0, 1.0)))
            .input(DataTree::from_item(true))
            .run();
        assert_clean(&r);
        assert!(only::<Vector3>(&r, 0).abs_diff_eq(v(0.8, 0.6, 0.0), 1e-15));
        assert_eq!(only::<f64>(&r, 1), 5.0);
    }

    #[test]
    fn vector_2pt_of_coincident_points() {
        let p = Point3::new(1.0, 2.0, 3.0);
        // Without unitizing, the zero vector is a valid answer.
        let r = NodeCall::new(&vector_2pt())
            .input(DataTree::from_item(p))
            .input(DataTree::from_item(p))
            .run();
        assert_clean(&r);
        assert_eq!(only::<Vector3>(&r, 0), Vector3::ZERO);
        // Unitized, it is an error, but the length is still reported.
        let r = NodeCall::new(&vector_2pt())
            .input(DataTree::from_item(p))
            .input(DataTree::from_item(p))
            .input(DataTree::from_item(true))
            .run();
        assert_error(&r, "zero length");
        assert!(is_null(&r, 0));
        assert_eq!(only::<f64>(&r, 1), 0.0);
        let r = NodeCall::new(&vector_2pt())
            .input(DataTree::from_item(Point3::new(f64::NAN, 0.0, 0.0)))
            .input(DataTree::from_item(p))
            .run();
        assert_error(&r, "point A");
        assert!(is_null(&r, 0) && is_null(&r, 1));
    }

    #[test]
    fn unit_vector_of_the_book() {
        // The book: the unit vector of <4, 3, 0> is <0.8, 0.6, 0>.
        let r = NodeCall::new(&unit_vector())
            .input(DataTree::from_item(v(4.0, 3.0, 0.0)))
            .run();
        assert_clean(&r);
        let u = only::<Vector3>(&r, 0);
        assert!(u.abs_diff_eq(v(0.8, 0.6, 0.0), 1e-15));
        assert!((u.length() - 1.0).abs() < 1e-15);
    }

    #[test]
    fn unit_vector_rejects_zero_and_nan() {
        let r = NodeCall::new(&unit_vector())
            .input(DataTree::from_item(Vector3::ZERO))
            .run();
        assert_error(&r, "zero length");
        assert!(is_null(&r, 0));
        let r = NodeCall::new(&unit_vector())
            .input(DataTree::from_item(v(f64::NAN, 1.0, 0.0)))
            .run();
        assert_error(&r, "not finite");
    }

    #[test]
    fn amplitude_sets_the_length() {
        let r = NodeCall::new(&amplitude())
            .input(DataTree::from_item(v(4.0, 3.0, 0.0)))
            .input(DataTree::from_item(10.0))
            .run();
        assert_clean(&r);
        assert!(only::<Vector3>(&r, 0).abs_diff_eq(v(8.0, 6.0, 0.0), 1e-14));
        // Default amplitude 1 is the unit vector; a negative amplitude reverses.
        let r = NodeCall::new(&amplitude())
            .input(DataTree::from_item(v(0.0, 0.0, 3.0)))
            .run();
        assert_eq!(only::<Vector3>(&r, 0), Vector3::Z);
        let r = NodeCall::new(&amplitude())
            .input(DataTree::from_item(v(0.0, 0.0, 3.0)))
            .input(DataTree::from_item(-2.0))
            .run();
        assert_eq!(only::<Vector3>(&r, 0), v(0.0, 0.0, -2.0));
    }

    #[test]
    fn amplitude_of_zero_vector_is_an_error() {
        let r = NodeCall::new(&amplitude())
            .input(DataTree::from_item(Vector3::ZERO))
            .input(DataTree::from_item(5.0))
            .run();
        assert_error(&r, "zero length");
        let r = NodeCall::new(&amplitude())
            .input(DataTree::from_item(Vector3::X))
            .input(DataTree::from_item(f64::NAN))
            .run();
        assert_error(&r, "amplitude A");
    }

    #[test]
    fn vector_length_and_reverse() {
        let r = NodeCall::new(&vector_length())
            .input(DataTree::from_item(v(0.0, 3.0, 4.0)))
            .run();
        assert_eq!(only::<f64>(&r, 0), 5.0);
        let r = NodeCall::new(&vector_length())
            .input(DataTree::from_item(v(0.0, f64::INFINITY, 4.0)))
            .run();
        assert_error(&r, "vector V");
        let r = NodeCall::new(&reverse())
            .input(DataTree::from_item(v(1.0, -2.0, 0.0)))
            .run();
        assert_eq!(only::<Vector3>(&r, 0), v(-1.0, 2.0, -0.0));
        let r = NodeCall::new(&reverse())
            .input(DataTree::from_item(v(f64::NAN, 0.0, 0.0)))
            .run();
        assert_error(&r, "vector V");
        assert!(is_null(&r, 0));
    }

    #[test]
    fn rotate_a_quarter_turn_about_z() {
        let r = NodeCall::new(&rotate())
            .input(DataTree::from_item(v(1.0, 0.0, 5.0)))
            .run();
        assert_clean(&r);
        assert_eq!(only::<Vector3>(&r, 0), v(0.0, 1.0, 5.0));
        // About x by π: y goes to −y.
        let r = NodeCall::new(&rotate())
            .input(DataTree::from_item(Vector3::Y))
            .input(DataTree::from_item(Vector3::X))
            .input(DataTree::from_item(std::f64::consts::PI))
            .run();
        assert!(only::<Vector3>(&r, 0).abs_diff_eq(-Vector3::Y, 1e-15));
    }

    #[test]
    fn rotate_about_a_zero_axis_is_an_error() {
        let r = NodeCall::new(&rotate())
            .input(DataTree::from_item(Vector3::X))
            .input(DataTree::from_item(Vector3::ZERO))
            .run();
        assert_error(&r, "zero length");
        assert!(is_null(&r, 0));
    }
}

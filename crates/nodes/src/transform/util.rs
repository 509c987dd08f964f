//! Transform › Util: applying, combining, inverting, taking apart and building transformation
//! matrices.
//!
//! *Compound* follows Grasshopper: the transforms are applied in list order, the first one
//! first, so the list `[M1, M2, M3, M4]` gives the book's master matrix `M4·M3·M2·M1`.
//! *Deconstruct Transform* and *Construct Transform* give and take the sixteen entries row by
//! row, as the book prints matrices: `[m00, m01, m02, m03, m10, …, m33]`, with the translation
//! in entries 3, 7 and 11. (Grasshopper keeps matrices apart from transforms, with *Transform
//! Matrix* and *Construct Matrix*; locus has no matrix type, so these two nodes stand in.)

use locus_kernel::Transform;
use locus_runtime::{DataType, NodeRegistry, NodeType, Port};

use super::apply::transform_value;
use super::transform_node;

/// Id of [`transform`].
pub const TRANSFORM: &str = "transform.transform";
/// Id of [`compound`].
pub const COMPOUND: &str = "transform.compound";
/// Id of [`inverse_transform`].
pub const INVERSE_TRANSFORM: &str = "transform.inverse_transform";
/// Id of [`deconstruct_transform`].
pub const DECONSTRUCT_TRANSFORM: &str = "transform.deconstruct_transform";
/// Id of [`construct_transform`].
pub const CONSTRUCT_TRANSFORM: &str = "transform.construct_transform";

/// Registers the Util nodes.
pub fn register(registry: &mut NodeRegistry) {
    for t in [
        transform(),
        compound(),
        inverse_transform(),
        deconstruct_transform(),
        construct_transform(),
    ] {
        registry.register(t);
    }
}

fn util(id: &str, name: &str, nickname: &str) -> NodeType {
    transform_node(id, name, nickname, "Util")
}

/// Transform \[Transform\]: applies a transformation to geometry.
pub fn transform() -> NodeType {
    util(TRANSFORM, "Transform", "Transform")
        .gh_guid("610e689b-5adc-47b3-af8f-e3a32b7ea341")
        .description(
            "Applies a transformation matrix to geometry: points, vectors (without the \
             translation), planes, lines, circles, arcs, curves, surfaces and boxes. Circles \
             and arcs under a transform that is not a similarity become NURBS curves; a box \
             that would no longer be a box is an error.",
        )
        .input(Port::new("Geometry", "G", DataType::Generic).doc("The geometry to transform."))
        .input(Port::new("Transform", "T", DataType::Transform).doc("The transformation."))
        .output(Port::new("Geometry", "G", DataType::Generic).doc("The transformed geometry."))
        .solve(|s| {
            let xform = *s.item::<Transform>(1)?;
            let value = s
                .value(0)
                .ok_or_else(|| locus_runtime::NodeError::from("input G has no item"))?;
            s.set_value(0, Some(transform_value(&value, &xform)?));
            Ok(())
        })
}

/// Compound \[Comp\]: one transformation that does a list of them in order.
pub fn compound() -> NodeType {
    util(COMPOUND, "Compound", "Comp")
        .gh_guid("ca80054a-cde0-4f69-a132-10502b24866d")
        .description(
            "Combines a list of transformations into one that applies them in list order, \
             the first first: [M1, M2, M3] gives M3·M2·M1. Null items are skipped with a \
             warning.",
        )
        .input(
            Port::new("Transforms", "T", DataType::Transform)
                .doc("The transformations, in the order they are to be applied.")
                .list(),
        )
        .output(
            Port::new("Compound", "X", DataType::Transform)
                .doc("The combined transformation, the last matrix times … times the first."),
        )
        .solve(|s| {
            let list = s.list::<Transform>(0)?;
            let mut out = Transform::IDENTITY;
            let mut skipped = Vec::new();
            for (index, t) in list.iter().enumerate() {
                match t {
                    Some(t) => out = *t * out,
                    None => skipped.push(index),
                }
            }
            if !skipped.is_empty() {
                s.warning(format!("null transforms skipped at items {skipped:?}"));
            }
            if !out.is_finite() {
                return Err("the compound transform has an entry that is not finite".into());
            }
            s.set(0, out);
            Ok(())
        })
}

/// Inverse Transform \[Inverse\]: the transformation that undoes another.
pub fn inverse_transform() -> NodeType {
    util(INVERSE_TRANSFORM, "Inverse Transform", "Inverse")
        .description(
            "Inverts a transformation: the result undoes it, so that the two compounded are \
             the identity. Singular transformations (projections, zero scales) have no \
             inverse and are an error.",
        )
        .input(Port::new("Transform", "T", DataType::Transform).doc("The transformation."))
        .output(Port::new("Transform", "T", DataType::Transform).doc("Its inverse."))
        .lift1(|t: &Transform| Ok(t.inverse()?))
}

/// Deconstruct Transform \[DeXform\]: the sixteen entries of a matrix, row by row.
pub fn deconstruct_transform() -> NodeType {
    util(DECONSTRUCT_TRANSFORM, "Deconstruct Transform", "DeXform")
        .description(
            "Lists the sixteen entries of a 4×4 transformation matrix row by row, as the book \
             prints matrices: m00, m01, m02, m03 (the translation along x is m03), m10, …, \
             m33. The bottom row of an affine transform is 0, 0, 0, 1.",
        )
        .input(Port::new("Transform", "T", DataType::Transform).doc("The transformation."))
        .output(
            Port::new("Values", "V", DataType::Number)
                .doc("The 16 entries, row-major: the entry of row i, column j is item 4i + j.")
                .list(),
        )
        .solve(|s| {
            let t = *s.item::<Transform>(0)?;
            if !t.is_finite() {
                s.warning("the transform has an entry that is not finite");
            }
            let values: Vec<f64> = t.to_rows().into_iter().flatten().collect();
            s.set_list(0, values);
            Ok(())
        })
}

/// Construct Transform \[Xform\]: a transformation from its sixteen entries, row by row.
pub fn construct_transform() -> NodeType {
    util(CONSTRUCT_TRANSFORM, "Construct Transform", "Xform")
        .description(
            "Builds a 4×4 transformation matrix from its sixteen entries given row by row \
             (item 4i + j is the entry of row i, column j), as the book writes matrices. The \
             list must hold exactly 16 finite numbers. A bottom row other than 0, 0, 0, 1 \
             makes a perspective transform, under which points are divided by w.",
        )
        .input(
            Port::new("Values", "V", DataType::Number)
                .doc("The 16 entries, row-major.")
                .list(),
        )
        .output(Port::new("Transform", "T", DataType::Transform).doc("The transformation."))
        .solve(|s| {
            let list = s.list::<f64>(0)?;
            if list.len() != 16 {
                return Err(format!("a 4×4 matrix needs 16 values, got {}", list.len()).into());
            }
            let mut rows = [[0.0; 4]; 4];
            for (k, x) in list.iter().enumerate() {
                let x = *x.ok_or_else(|| format!("value {k} is null"))?;
                if !x.is_finite() {
                    return Err(format!("value {k} is not a finite number ({x})").into());
                }
                rows[k / 4][k % 4] = x;
            }
            s.set(0, Transform::from_rows(rows));
            Ok(())
        })
}

#[cfg(test)]
mod tests {
    use std::f64::consts::FRAC_PI_2;

    use locus_kernel::{Plane, Point3, Vector3};
    use locus_runtime::{DataTree, NodeCall, Value};

    use super::*;
    use crate::vector::test_support::{
        assert_clean, assert_error, is_null, items, only, only_value,
    };

    #[test]
    fn transform_applies_the_matrix() {
        let t = Transform::translation(Vector3::new(1.0, 2.0, 3.0));
        let r = NodeCall::new(&transform())
            .input(DataTree::from_list(vec![
                Value::Point(Point3::ORIGIN),
                Value::Vector(Vector3::X),
                Value::Plane(Plane::WORLD_XY),
            ]))
            .input(DataTree::from_item(t))
            .run();
        assert_clean(&r);
        let out: Vec<Option<Value>> = r.outputs[0].values().collect();
        assert_eq!(
            out,
            vec![
                Some(Value::Point(Point3::new(1.0, 2.0, 3.0))),
                Some(Value::Vector(Vector3::X)),
                Some(Value::Plane(
                    Plane::WORLD_XY.translated(Vector3::new(1.0, 2.0, 3.0))
                )),
            ]
        );
    }

    #[test]
    fn transform_bad_input() {
        let r = NodeCall::new(&transform())
            .input(DataTree::from_item(3.0))
            .input(DataTree::from_item(Transform::IDENTITY))
            .run();
        assert_error(&r, "cannot transform a number");
        assert!(is_null(&r, 0));
        let nan = Transform::scale(Point3::ORIGIN, f64::NAN);
        let r = NodeCall::new(&transform())
            .input(DataTree::from_item(Point3::ORIGIN))
            .input(DataTree::from_item(nan))
            .run();
        assert_error(&r, "not finite");
    }

    #[test]
    fn compound_applies_the_first_first() {
        // Translate by x, then rotate a quarter turn: (1, 0, 0) → (2, 0, 0) → (0, 2, 0).
        let m1 = Transform::translation(Vector3::X);
        let m2 = Transform::rotation_z(FRAC_PI_2);
        let r = NodeCall::new(&compound())
            .input(DataTree::from_list(vec![m1, m2]))
            .run();
        assert_clean(&r);
        let x = only::<Transform>(&r, 0);
        assert_eq!(x, m2 * m1);
        assert_eq!(
            x.transform_point(Point3::new(1.0, 0.0, 0.0)),
            Point3::new(0.0, 2.0, 0.0)
        );
    }

    #[test]
    fn compound_the_book_multiple_transformations() {
        // The book's tutorial: move the centre (3, 4, 5) to the origin, rotate 45° about z,
        // scale by 0.2, move back; the master matrix keeps the centre fixed.
        let centre = Point3::new(3.0, 4.0, 5.0);
        let m1 = Transform::translation(Point3::ORIGIN - centre);
        let m2 = Transform::rotation(45f64.to_radians(), Vector3::Z, Point3::ORIGIN).unwrap();
        let m3 = Transform::scale(Point3::ORIGIN, 0.2);
        let inverse = NodeCall::new(&inverse_transform())
            .input(DataTree::from_item(m1))
            .run();
        let m4 = only::<Transform>(&inverse, 0);
        let r = NodeCall::new(&compound())
            .input(DataTree::from_list(vec![m1, m2, m3, m4]))
            .run();
        let master = only::<Transform>(&r, 0);
        assert!(master.transform_point(centre).abs_diff_eq(centre, 1e-15));
        let v = NodeCall::new(&deconstruct_transform())
            .input(DataTree::from_item(master))
            .run();
        let values: Vec<f64> = items::<f64>(&v.outputs[0]).into_iter().flatten().collect();
        assert_eq!(values.len(), 16);
        // Row 0, column 3: 3 − 0.2 (3 cos 45° − 4 sin 45°) = 3.14142135623731.
        assert!((values[3] - 3.14142135623731).abs() < 1e-14);
        assert_eq!(&values[12..], &[0.0, 0.0, 0.0, 1.0]);
    }

    #[test]
    fn compound_of_a_nan_transform_is_an_error() {
        let nan = Transform::translation(Vector3::new(f64::NAN, 0.0, 0.0));
        let r = NodeCall::new(&compound())
            .input(DataTree::from_list(vec![Transform::IDENTITY, nan]))
            .run();
        assert_error(&r, "not finite");
        assert!(is_null(&r, 0));
        // An empty list has nothing to compound: no iteration runs.
        let r = NodeCall::new(&compound())
            .input(DataTree::from_list(Vec::<Transform>::new()))
            .run();
        assert!(r.outputs[0].values().all(|v| v.is_none()));
    }

    #[test]
    fn compound_skips_nulls() {
        let mut b = locus_runtime::Branch::new(DataType::Transform);
        b.push(Transform::translation(Vector3::X));
        b.push_null();
        b.push(Transform::translation(Vector3::Y));
        let mut tree = DataTree::new();
        tree.insert(locus_runtime::TreePath::zero(), b);
        let r = NodeCall::new(&compound()).input(tree).run();
        assert_eq!(
            only::<Transform>(&r, 0),
            Transform::translation(Vector3::new(1.0, 1.0, 0.0))
        );
        assert_eq!(r.messages.len(), 1);
        assert!(r.messages[0].text.contains("[1]"));
    }

    #[test]
    fn inverse_undoes_and_rejects_singular() {
        let t = Transform::rotation(0.7, Vector3::new(1.0, 2.0, 2.0), Point3::new(1.0, 0.0, 0.0))
            .unwrap()
            * Transform::scale(Point3::ORIGIN, 3.0);
        let r = NodeCall::new(&inverse_transform())
            .input(DataTree::from_item(t))
            .run();
        assert_clean(&r);
        assert!((only::<Transform>(&r, 0) * t).is_identity(1e-14));
        let r = NodeCall::new(&inverse_transform())
            .input(DataTree::from_item(Transform::planar_projection(
                &Plane::WORLD_XY,
            )))
            .run();
        assert_error(&r, "singular");
        assert!(is_null(&r, 0));
        let r = NodeCall::new(&inverse_transform())
            .input(DataTree::from_item(Transform::scale(Point3::ORIGIN, 0.0)))
            .run();
        assert_error(&r, "singular");
    }

    #[test]
    fn deconstruct_and_construct_round_trip() {
        let t = Transform::translation(Vector3::new(4.0, 5.0, 3.0));
        let r = NodeCall::new(&deconstruct_transform())
            .input(DataTree::from_item(t))
            .run();
        assert_clean(&r);
        let values: Vec<f64> = items::<f64>(&r.outputs[0]).into_iter().flatten().collect();
        // The book's translation matrix by <4, 5, 3>.
        assert_eq!(
            values,
            vec![
                1.0, 0.0, 0.0, 4.0, 0.0, 1.0, 0.0, 5.0, 0.0, 0.0, 1.0, 3.0, 0.0, 0.0, 0.0, 1.0
            ]
        );
        let back = NodeCall::new(&construct_transform())
            .input(DataTree::from_list(values))
            .run();
        assert_clean(&back);
        assert_eq!(only::<Transform>(&back, 0), t);
    }

    #[test]
    fn deconstruct_a_nan_transform_warns() {
        let t = Transform::translation(Vector3::new(f64::NAN, 0.0, 0.0));
        let r = NodeCall::new(&deconstruct_transform())
            .input(DataTree::from_item(t))
            .run();
        assert_eq!(r.messages.len(), 1);
        assert_eq!(r.messages[0].level, locus_runtime::Level::Warning);
        assert!(items::<f64>(&r.outputs[0])[3].is_some_and(f64::is_nan));
    }

    #[test]
    fn construct_transform_bad_input() {
        let r = NodeCall::new(&construct_transform())
            .input(DataTree::from_list(vec![1.0; 15]))
            .run();
        assert_error(&r, "needs 16 values, got 15");
        assert!(is_null(&r, 0));
        let mut values = vec![0.0; 16];
        values[5] = f64::NAN;
        let r = NodeCall::new(&construct_transform())
            .input(DataTree::from_list(values))
            .run();
        assert_error(&r, "value 5 is not a finite number");
    }

    #[test]
    fn construct_then_apply_a_book_matrix() {
        // The book's 30° rotation written out with 0.87 and 0.5, applied to (1, 0, 0).
        let values = vec![
            0.87, -0.5, 0.0, 0.0, 0.5, 0.87, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0,
        ];
        let t = only::<Transform>(
            &NodeCall::new(&construct_transform())
                .input(DataTree::from_list(values))
                .run(),
            0,
        );
        let r = NodeCall::new(&transform())
            .input(DataTree::from_item(Point3::new(1.0, 0.0, 0.0)))
            .input(DataTree::from_item(t))
            .run();
        assert_eq!(only_value(&r, 0), Value::Point(Point3::new(0.87, 0.5, 0.0)));
    }
}

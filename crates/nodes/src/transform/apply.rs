//! Applying a transform to whatever geometry arrives: the one place where the Transform nodes
//! dispatch on the type of a value. Adding a geometry type is one arm of [`transform_value`].
//!
//! | value | result |
//! | --- | --- |
//! | point | the transformed point (projective matrices divide by `w`) |
//! | vector | the linear part applied, without translation (as Rhino's `Vector3d.Transform`) |
//! | plane | origin moved, axes mapped and re-orthonormalized, kept right-handed ([`Plane::transformed`]) |
//! | line | both ends transformed |
//! | circle, arc | a circle or arc under a similarity (move, rotate, mirror, uniform scale); otherwise a NURBS curve, exact, as Rhino turns a non-uniformly scaled circle into a NURBS curve |
//! | curve | [`Curve::transformed`]: lines and polylines stay so under affine maps, circles and arcs under similarities, everything else becomes NURBS |
//! | surface | the control points transformed (exact for every affine and projective map) |
//! | box | a box when the image is still a box (see below), else a six-face B-rep |
//! | B-rep | every surface, curve and vertex transformed; a mirror keeps faces pointing outwards |
//! | mesh | vertices transformed, normals by the inverse transpose; a mirror reverses the faces |
//!
//! A box stays a box under every transform that maps its three edge directions to mutually
//! perpendicular directions: rigid motions, mirrors, uniform scales, non-uniform scales and
//! projections along the box's own axes. A shear, or a non-uniform scale across the box's
//! axes, makes a parallelepiped, which is not a box; as in Grasshopper, the result is then a B-rep.
//! The test compares the eight transformed corners with the corners of the box rebuilt on the
//! transformed plane, within [`BOX_TOLERANCE`] relative to the box's size.
//!
//! A transform with a NaN or infinite entry is an error for every value, and so is a result
//! with a non-finite coordinate (a point sent to infinity by a perspective matrix). Values that
//! are not geometry (numbers, text, domains, transforms) cannot be transformed and are an
//! error.

use locus_kernel::{Curve, OrientedBox, Plane, Point3, Transform};
use locus_runtime::{NodeError, Shared, Value};

/// How far, relative to the size of a box, a transformed corner may lie from the corner of the
/// rebuilt box for the image to count as a box: 1e-9 (the rebuilt corners agree to rounding,
/// about 1e-15, under transforms that keep boxes; a shear moves them by its full amount).
pub const BOX_TOLERANCE: f64 = 1e-9;

/// The value `value` mapped by `xform`.
///
/// # Errors
/// When the transform is not finite, when the value is not geometry, when the result would not
/// be finite or would collapse (a plane projected edge-on), and when a box would stop being a
/// box (see the module documentation).
pub fn transform_value(value: &Value, xform: &Transform) -> Result<Value, NodeError> {
    if !xform.is_finite() {
        return Err("the transform has an entry that is not finite".into());
    }
    let out = match value {
        Value::Point(p) => Value::Point(finite(xform.transform_point(*p), "point")?),
        Value::Vector(v) => {
            let w = xform.transform_vector(*v);
            if !w.is_finite() {
                return Err("the transformed vector is not finite".into());
            }
            Value::Vector(w)
        }
        Value::Plane(plane) => Value::Plane(transform_plane(plane, xform)?),
        Value::Line(line) => {
            let l = line.transformed(xform);
            finite(l.from, "line")?;
            finite(l.to, "line")?;
            Value::Line(l)
        }
        Value::Circle(circle) => match circle.transformed(xform) {
            Ok(c) if c.plane.is_finite() && c.radius.is_finite() => Value::Circle(c),
            _ => curve(Curve::from(*circle).transformed(xform)?),
        },
        Value::Arc(arc) => match arc.transformed(xform) {
            Ok(a) if a.circle.plane.is_finite() && a.circle.radius.is_finite() => Value::Arc(a),
            _ => curve(Curve::from(*arc).transformed(xform)?),
        },
        Value::Curve(c) => curve(c.transformed(xform)?),
        Value::Surface(s) => Value::Surface(Shared::new(s.transformed(xform)?)),
        Value::Box(b) => transform_box(b, xform)?,
        Value::Brep(b) => Value::Brep(Shared::new(b.transformed(xform)?)),
        Value::Mesh(m) => Value::Mesh(Shared::new(m.transformed(xform)?)),
        other => {
            return Err(NodeError(format!(
                "cannot transform a {}: it is not geometry",
                other.data_type().name().to_lowercase()
            )));
        }
    };
    Ok(out)
}

fn curve(c: Curve) -> Value {
    Value::Curve(Shared::new(c))
}

fn finite(p: Point3, what: &str) -> Result<Point3, NodeError> {
    if p.is_finite() {
        Ok(p)
    } else {
        Err(NodeError(format!("the transformed {what} is not finite")))
    }
}

fn transform_plane(plane: &Plane, xform: &Transform) -> Result<Plane, NodeError> {
    let out = plane.transformed(xform)?;
    if !out.is_finite() {
        return Err("the transformed plane is not finite".into());
    }
    Ok(out)
}

/// The image of a box when it is still a box.
/// A box stays a box under transforms that keep it one; otherwise it becomes a B-rep, as in
/// Grasshopper.
fn transform_box(b: &OrientedBox, xform: &Transform) -> Result<Value, NodeError> {
    let out = b.transformed(xform)?;
    let mut corners = b.corners();
    xform.transform_points(&mut corners);
    let rebuilt = out.corners();
    let size = rebuilt[0]
        .distance(rebuilt[6])
        .max(corners[0].distance(corners[6]));
    let tolerance = BOX_TOLERANCE * size.max(1.0);
    let still_a_box = corners
        .iter()
        .all(|c| rebuilt.iter().any(|r| r.distance(*c) <= tolerance));
    if still_a_box {
        Ok(Value::Box(out))
    } else {
        let brep = locus_kernel::Brep::from_box(b)?.transformed(xform)?;
        Ok(Value::Brep(Shared::new(brep)))
    }
}

#[cfg(test)]
mod tests {
    use std::f64::consts::FRAC_PI_2;

    use locus_kernel::{Arc, Circle, Interval, Line, NurbsSurface, Vector3};

    use super::*;

    fn b() -> OrientedBox {
        OrientedBox::new(
            Plane::WORLD_XY,
            Interval::new(0.0, 2.0),
            Interval::new(0.0, 3.0),
            Interval::new(0.0, 4.0),
        )
    }

    #[test]
    fn points_and_vectors() {
        let t = Transform::translation(Vector3::new(2.0, 2.0, 2.0));
        // The book: P(2, 3, 1) moved by <2, 2, 2> is (4, 5, 3).
        assert_eq!(
            transform_value(&Value::Point(Point3::new(2.0, 3.0, 1.0)), &t),
            Ok(Value::Point(Point3::new(4.0, 5.0, 3.0)))
        );
        // Vectors ignore the translation.
        assert_eq!(
            transform_value(&Value::Vector(Vector3::X), &t),
            Ok(Value::Vector(Vector3::X))
        );
    }

    #[test]
    fn circles_stay_circles_under_similarities_only() {
        let c = Circle::new(Plane::WORLD_XY, 1.0).unwrap();
        let moved = transform_value(&Value::Circle(c), &Transform::scale(Point3::ORIGIN, 3.0));
        match moved {
            Ok(Value::Circle(m)) => assert!((m.radius - 3.0).abs() < 1e-15),
            other => panic!("expected a circle, got {other:?}"),
        }
        let squash = Transform::scale_non_uniform(&Plane::WORLD_XY, 2.0, 1.0, 1.0);
        match transform_value(&Value::Circle(c), &squash) {
            Ok(Value::Curve(curve)) => {
                assert!(matches!(*curve, Curve::Nurbs(_)));
                // The ellipse passes through (2, 0) and (0, 1).
                let d = curve.domain();
                assert!(
                    curve
                        .point_at(d.t0)
                        .abs_diff_eq(Point3::new(2.0, 0.0, 0.0), 1e-14)
                );
                let cp = curve.closest_point(Point3::new(0.0, 5.0, 0.0)).unwrap();
                assert!(cp.point.abs_diff_eq(Point3::new(0.0, 1.0, 0.0), 1e-9));
            }
            other => panic!("expected a curve, got {other:?}"),
        }
        let arc = Arc::new(c, Interval::new(0.0, FRAC_PI_2)).unwrap();
        assert!(matches!(
            transform_value(&Value::Arc(arc), &Transform::rotation_z(1.0)),
            Ok(Value::Arc(_))
        ));
        assert!(matches!(
            transform_value(&Value::Arc(arc), &squash),
            Ok(Value::Curve(_))
        ));
    }

    #[test]
    fn boxes_stay_boxes_or_become_breps() {
        let rotate = Transform::rotation(0.3, Vector3::new(1.0, 2.0, 3.0), Point3::ORIGIN).unwrap();
        assert!(matches!(
            transform_value(&Value::Box(b()), &rotate),
            Ok(Value::Box(_))
        ));
        // A non-uniform scale along the box's axes keeps it a box.
        let nu = Transform::scale_non_uniform(&Plane::WORLD_XY, 2.0, 0.5, 3.0);
        match transform_value(&Value::Box(b()), &nu) {
            Ok(Value::Box(out)) => assert!((out.volume() - 24.0 * 3.0).abs() < 1e-12),
            other => panic!("expected a box, got {other:?}"),
        }
        // A shear does not: the box becomes a B-rep with the sheared corners.
        let shear = Transform::shear(
            &Plane::WORLD_XY,
            Vector3::X,
            Vector3::Y,
            Vector3::new(1.0, 0.0, 1.0),
        );
        match transform_value(&Value::Box(b()), &shear) {
            Ok(Value::Brep(brep)) => {
                assert_eq!(brep.faces().len(), 6);
                let mut corners = b().corners();
                shear.transform_points(&mut corners);
                for c in corners {
                    assert!(brep.vertices().iter().any(|v| v.point.distance(c) < 1e-12));
                }
            }
            other => panic!("expected a B-rep, got {other:?}"),
        }
        // A projection onto the box's base plane flattens it into a (flat) box.
        let flat = transform_value(
            &Value::Box(b()),
            &Transform::planar_projection(&Plane::WORLD_XY),
        );
        match flat {
            Ok(Value::Box(out)) => assert_eq!(out.volume(), 0.0),
            other => panic!("expected a flat box, got {other:?}"),
        }
    }

    #[test]
    fn bad_transforms_and_values() {
        let nan = Transform::translation(Vector3::new(f64::NAN, 0.0, 0.0));
        let err = transform_value(&Value::Point(Point3::ORIGIN), &nan).unwrap_err();
        assert!(err.0.contains("not finite"));
        let err = transform_value(&Value::Number(1.0), &Transform::IDENTITY).unwrap_err();
        assert_eq!(err.0, "cannot transform a number: it is not geometry");
        // A plane projected edge-on collapses.
        let err = transform_value(
            &Value::Plane(Plane::WORLD_YZ),
            &Transform::planar_projection(&Plane::WORLD_XY),
        )
        .unwrap_err();
        assert!(err.0.contains("degenerate"), "{err}");
    }

    #[test]
    fn lines_and_surfaces() {
        let t = Transform::rotation_z(FRAC_PI_2);
        let l = Line::new(Point3::ORIGIN, Point3::new(1.0, 0.0, 0.0));
        assert_eq!(
            transform_value(&Value::Line(l), &t),
            Ok(Value::Line(Line::new(
                Point3::ORIGIN,
                Point3::new(0.0, 1.0, 0.0)
            )))
        );
        let s = NurbsSurface::from_plane(&Plane::WORLD_XY, Interval::UNIT, Interval::UNIT).unwrap();
        match transform_value(&Value::Surface(Shared::new(s)), &t) {
            Ok(Value::Surface(out)) => {
                assert!(
                    out.point_at(1.0, 0.0)
                        .abs_diff_eq(Point3::new(0.0, 1.0, 0.0), 1e-15)
                );
            }
            other => panic!("expected a surface, got {other:?}"),
        }
    }
}

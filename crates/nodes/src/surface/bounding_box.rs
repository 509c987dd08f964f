//! Surface › Primitive › Bounding Box, and the tight world bounding boxes of geometry that
//! it and the Box parameter use.
//!
//! **Bounding Box** is the variant of Grasshopper's component with a Union input (GUID
//! `87df35c8…`: Content, Union, Plane): without Union every object gets its own box, with it
//! the list gets one box around everything (the right-click "Union Box" of the other variant).
//! Boxes are tight: a B-rep's or surface's box touches the geometry (Rhino's accurate
//! `GetBoundingBox(true)`), not the loose box of the control points. With a plane, the
//! geometry is measured in the plane's coordinates; output B is that box on the plane, and
//! output Bp (Grasshopper's second "Box" output, renamed here because two outputs may not
//! share a nickname) is the same box in plane coordinates, on World XY.

use locus_kernel::{BoundingBox, OrientedBox, Plane, Point3, Transform};
use locus_runtime::{DataType, NodeError, NodeRegistry, NodeType, Port, Value, cast_value};

use super::box_nodes::box_plane;
use super::brep::surface_node;
use crate::curve::curve_from_value;

/// Id of [`bounding_box`].
pub const BOUNDING_BOX: &str = "surface.bounding_box";

/// Registers Bounding Box.
pub fn register(registry: &mut NodeRegistry) {
    registry.register(bounding_box());
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
        .gh_guid("0bb3d234-9097-45db-9998-621639c87d3b")
        .gh_guid("87df35c8-6e1d-4e2a-821a-7c1066714409")
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
            Port::new("Plane", "P", DataType::Plane)
                .doc("The plane the boxes are aligned with. Default World XY.")
                .default_value(Plane::WORLD_XY),
        )
        .input(
            Port::new("Union", "U", DataType::Boolean)
                .doc(
                    "Whether to give one box around the whole list (true) or one box per \
                     object (false). Default false. Grasshopper has this as the \"Union Box\" \
                     menu option, not a port, so it is the third input here, after \
                     Grasshopper's two (a file's ports map by index).",
                )
                .default_value(false),
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
            let plane = box_plane(s, 1, "P")?;
            let union = *s.item::<bool>(2)?;
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

#[cfg(test)]
mod tests {
    use std::f64::consts::FRAC_1_SQRT_2;

    use locus_kernel::{Brep, Circle, Curve, Line, NurbsCurve, Sphere, Vector3};
    use locus_runtime::{Branch, DataTree, Level, NodeCall, Shared, TreePath};

    use super::*;
    use crate::vector::test_support::{assert_clean, items, messages};

    fn tilted() -> Plane {
        Plane::from_normal(Point3::new(1.0, 2.0, 3.0), Vector3::new(1.0, -1.0, 2.0)).unwrap()
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
            .input(DataTree::from_item(plane))
            .input(DataTree::from_item(union))
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
            .input(DataTree::from_item(Plane::WORLD_XY))
            .input(DataTree::from_item(true))
            .run();
        assert_eq!(boxes(&r, 0).len(), 1);
        // An empty list gives no box.
        let r = NodeCall::new(&bounding_box())
            .input(DataTree::from_list(Vec::<Point3>::new()))
            .input(DataTree::from_item(Plane::WORLD_XY))
            .input(DataTree::from_item(true))
            .run();
        assert_eq!(r.outputs[0].item_count(), 0);
    }
}

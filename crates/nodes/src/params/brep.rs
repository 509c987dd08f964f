//! Params › Geometry › Box, Brep and Geometry, and Params › Primitive › Transform: containers
//! of boxes, B-reps, any geometry and transformation matrices.
//!
//! - **Box** casts any non-box geometry to its tight world bounding box, as Grasshopper's Box
//!   parameter does ("any non-box geometry becomes its world bounding box"). Its input is
//!   generic so that B-reps, surfaces and curves can be wired in; what is not geometry is an
//!   error and becomes null.
//! - **Brep** takes B-reps, and boxes and surfaces as the same shapes (a six-face B-rep, a
//!   one-face B-rep).
//! - **Geometry** takes any geometric value (points, vectors, planes, boxes, lines, circles,
//!   arcs, curves, surfaces, B-reps) unchanged and rejects numbers, text, domains and
//!   transforms.
//! - **Transform** holds 4×4 transformation matrices.

use locus_runtime::{Branch, DataType, NodeRegistry, NodeType, Port, Solve, Value, cast_value};

use crate::surface::bounding_box::box_from_value;

/// Id of [`brep`].
pub const BREP: &str = "params.brep";
/// Id of [`box_param`].
pub const BOX: &str = "params.box";
/// Id of [`geometry`].
pub const GEOMETRY: &str = "params.geometry";
/// Id of [`transform`].
pub const TRANSFORM: &str = "params.transform";

/// Registers the Box, Brep, Geometry and Transform parameters.
pub fn register(registry: &mut NodeRegistry) {
    for t in [box_param(), brep(), geometry(), transform()] {
        registry.register(t);
    }
}

/// The shared description of a container.
fn container_description(what: &str) -> String {
    format!(
        "Contains a collection of {what}. A parameter passes its data through unchanged \
         (paths, empty branches and nulls included) after casting every item to its type; a \
         graph uses it to declare a named input."
    )
}

/// Casts every item of the input branch with `convert`; failures are errors naming the item
/// and become nulls.
fn convert_branch(
    s: &mut Solve<'_>,
    target: &str,
    convert: impl Fn(&Value) -> Result<Value, String>,
) {
    let Some(branch) = s.branch(0) else {
        return;
    };
    let mut out = Vec::with_capacity(branch.len());
    let mut errors = Vec::new();
    for (i, value) in branch.values().enumerate() {
        match value.map(|v| (convert(&v), v.data_type())) {
            None => out.push(None),
            Some((Ok(v), _)) => out.push(Some(v)),
            Some((Err(why), t)) => {
                errors.push(format!("invalid cast: {t} → {target} (item {i}): {why}"));
                out.push(None);
            }
        }
    }
    for e in errors {
        s.error(e);
    }
    s.set_list_values(0, out);
}

/// Box \[Box\]: a container of boxes; other geometry becomes its world bounding box.
pub fn box_param() -> NodeType {
    NodeType::new(BOX, "Box", "Box", "Params")
        .gh_guid("c9482db6-bea9-448d-98ff-fed6d69a8efc")
        .subcategory("Geometry")
        .description(&format!(
            "{} Boxes pass as they are; any other geometry (points, lines, circles, arcs, \
             curves, surfaces, B-reps) becomes its tight world-aligned bounding box, as in \
             Grasshopper. Items that are not geometry are errors and become null.",
            container_description("boxes")
        ))
        .input(Port::new("Box", "Box", DataType::Generic).list().doc(
            "The boxes, or geometry to box, given in the graph or wired in. No default; a \
             parameter without data warns that it failed to collect data.",
        ))
        .output(
            Port::new("Box", "Box", DataType::Box)
                .list()
                .doc("The boxes: the inputs as boxes, on World XY for non-box geometry."),
        )
        .solve(|s| {
            convert_branch(s, "Box", |v| {
                box_from_value(v).map(Value::Box).map_err(|e| e.0)
            });
            Ok(())
        })
}

/// Brep \[Brep\]: a container of B-reps; boxes and surfaces become B-reps.
pub fn brep() -> NodeType {
    NodeType::new(BREP, "Brep", "Brep", "Params")
        .gh_guid("919e146f-30ae-4aae-be34-4d72f555e7da")
        .subcategory("Geometry")
        .description(&format!(
            "{} B-reps (boundary representations: polysurfaces and solids) pass as they are; \
             boxes become six-face closed B-reps and surfaces one-face B-reps. Items that do \
             not cast are errors and become null.",
            container_description("B-reps")
        ))
        .input(Port::new("Brep", "Brep", DataType::Brep).list().doc(
            "The B-reps, given in the graph or wired in: B-reps, boxes or surfaces. No \
             default; a parameter without data warns that it failed to collect data.",
        ))
        .output(
            Port::new("Brep", "Brep", DataType::Brep)
                .list()
                .doc("The same B-reps, cast."),
        )
        .solve(|s| {
            if let Some(branch) = s.branch(0)
                && (branch.data_type() == DataType::Brep || branch.is_empty())
            {
                let branch = branch.clone();
                s.set_branch(0, branch);
                return Ok(());
            }
            // The runtime casts inputs to the port's type; this covers a branch given to the
            // node directly, without that cast.
            convert_branch(s, "Brep", |v| {
                cast_value(v, DataType::Brep).map_err(|e| e.to_string())
            });
            Ok(())
        })
}

/// Whether a value is geometry (what Grasshopper's Geometry parameter holds).
pub fn is_geometry(value: &Value) -> bool {
    matches!(
        value,
        Value::Point(_)
            | Value::Vector(_)
            | Value::Plane(_)
            | Value::Box(_)
            | Value::Line(_)
            | Value::Circle(_)
            | Value::Arc(_)
            | Value::Curve(_)
            | Value::Surface(_)
            | Value::Brep(_)
            | Value::Mesh(_)
    )
}

/// Geometry \[Geo\]: a container of any geometry.
pub fn geometry() -> NodeType {
    NodeType::new(GEOMETRY, "Geometry", "Geo", "Params")
        .gh_guid("ac2bc2cb-70fb-4dd5-9c78-7e1ea97fe278")
        .subcategory("Geometry")
        .description(&format!(
            "{} Any geometry passes unchanged, keeping its own type: points, vectors, planes, \
             boxes, lines, circles, arcs, curves, surfaces, B-reps and meshes. Numbers, \
             integers, booleans, text, domains, transforms and colours are not geometry: they are errors and \
             become null.",
            container_description("geometry of any kind")
        ))
        .input(Port::new("Geometry", "Geo", DataType::Generic).list().doc(
            "The geometry, given in the graph or wired in. No default; a parameter without \
             data warns that it failed to collect data.",
        ))
        .output(
            Port::new("Geometry", "Geo", DataType::Generic)
                .list()
                .doc("The same geometry."),
        )
        .solve(|s| {
            let Some(branch) = s.branch(0) else {
                return Ok(());
            };
            if branch.values().flatten().all(|v| is_geometry(&v)) {
                let branch: Branch = branch.clone();
                s.set_branch(0, branch);
                return Ok(());
            }
            convert_branch(s, "Geometry", |v| {
                if is_geometry(v) {
                    Ok(v.clone())
                } else {
                    Err("it is not geometry".into())
                }
            });
            Ok(())
        })
}

/// Transform \[Transform\]: a container of transformation matrices.
pub fn transform() -> NodeType {
    NodeType::new(TRANSFORM, "Transform", "Transform", "Params")
        .subcategory("Primitive")
        .description(&format!(
            "{} A transform is a 4×4 matrix acting on column vectors [x, y, z, 1], as made by \
             the Transform nodes and applied by Transform › Util › Transform.",
            container_description("transformation matrices")
        ))
        .input(Port::new("Transform", "Transform", DataType::Transform).list().doc(
            "The transforms, given in the graph (four rows of four numbers) or wired in. No \
             default; a parameter without data warns that it failed to collect data.",
        ))
        .output(
            Port::new("Transform", "Transform", DataType::Transform)
                .list()
                .doc("The same transforms."),
        )
        .solve(|s| {
            if let Some(branch) = s.branch(0) {
                let branch = branch.clone();
                s.set_branch(0, branch);
            }
            Ok(())
        })
}

#[cfg(test)]
mod tests {
    use locus_kernel::{
        Brep, Interval, Line, NurbsSurface, OrientedBox, Plane, Point3, Sphere, Transform,
    };
    use locus_runtime::{Branch, DataTree, Level, NodeCall, Shared, TreePath};

    use super::*;
    use crate::vector::test_support::{assert_clean, items, messages};

    fn generic(values: Vec<Option<Value>>) -> DataTree {
        let mut b = Branch::new(DataType::Generic);
        for v in values {
            b.push_option(v);
        }
        let mut tree = DataTree::new();
        tree.insert(TreePath::zero(), b);
        tree
    }

    #[test]
    fn box_parameter_boxes_geometry() {
        let bx = OrientedBox::centered(&Plane::WORLD_XY, 1.0, 2.0, 3.0).unwrap();
        let sphere = Brep::from_sphere(&Sphere::new(Point3::ORIGIN, 2.0).unwrap()).unwrap();
        let tree = generic(vec![
            Some(Value::Box(bx)),
            Some(Value::Point(Point3::new(1.0, 2.0, 3.0))),
            Some(Value::Brep(Shared::new(sphere))),
            None,
            Some(Value::Number(2.0)),
            Some(Value::Line(Line::new(
                Point3::new(f64::NAN, 0.0, 0.0),
                Point3::ORIGIN,
            ))),
        ]);
        let r = NodeCall::new(&box_param()).input(tree).run();
        let out = items::<OrientedBox>(&r.outputs[0]);
        assert_eq!(out.len(), 6);
        assert_eq!(out[0], Some(bx));
        let p = out[1].unwrap();
        assert_eq!(
            (p.x, p.y, p.z),
            (
                Interval::new(1.0, 1.0),
                Interval::new(2.0, 2.0),
                Interval::new(3.0, 3.0)
            )
        );
        let s = out[2].unwrap();
        assert!((s.volume() - 64.0).abs() < 1e-9, "{s:?}");
        assert_eq!(out[3], None);
        assert_eq!(out[4], None);
        assert_eq!(out[5], None);
        let errors = messages(&r, Level::Error);
        assert_eq!(errors.len(), 2, "{errors:?}");
        assert!(errors[0].contains("Number → Box (item 4)"), "{errors:?}");
        assert!(errors[1].contains("item 5"), "{errors:?}");
    }

    #[test]
    fn brep_parameter_casts_boxes_and_surfaces() {
        let bx = OrientedBox::centered(&Plane::WORLD_XY, 1.0, 1.0, 1.0).unwrap();
        let srf =
            NurbsSurface::from_plane(&Plane::WORLD_XY, Interval::UNIT, Interval::UNIT).unwrap();
        let tree = generic(vec![
            Some(Value::Box(bx)),
            Some(Value::Surface(Shared::new(srf))),
            Some(Value::Text("no".into())),
        ]);
        let r = NodeCall::new(&brep()).input(tree).run();
        let out = items::<Shared<Brep>>(&r.outputs[0]);
        assert_eq!(out[0].as_ref().unwrap().faces().len(), 6);
        assert!(out[0].as_ref().unwrap().is_solid());
        assert_eq!(out[1].as_ref().unwrap().faces().len(), 1);
        assert!(out[2].is_none());
        assert_eq!(messages(&r, Level::Error).len(), 1);
        // B-reps pass through untouched.
        let b = Shared::new(Brep::from_box(&bx).unwrap());
        let r = NodeCall::new(&brep())
            .input(DataTree::from_list(vec![b.clone()]))
            .run();
        assert_clean(&r);
        assert_eq!(r.outputs[0], DataTree::from_list(vec![b]));
    }

    #[test]
    fn geometry_parameter_keeps_geometry_and_rejects_the_rest() {
        let geometry = vec![
            Some(Value::Point(Point3::ORIGIN)),
            Some(Value::Plane(Plane::WORLD_XY)),
            None,
        ];
        let tree = generic(geometry.clone());
        let r = NodeCall::new(&geometry_param_type())
            .input(tree.clone())
            .run();
        assert_clean(&r);
        assert_eq!(r.outputs[0], tree);
        let mut mixed = geometry;
        mixed.push(Some(Value::Transform(Transform::IDENTITY)));
        let r = NodeCall::new(&geometry_param_type())
            .input(generic(mixed))
            .run();
        let out: Vec<Option<Value>> = r.outputs[0].values().collect();
        assert_eq!(out.len(), 4);
        assert!(out[0].is_some() && out[1].is_some() && out[2].is_none() && out[3].is_none());
        let errors = messages(&r, Level::Error);
        assert_eq!(errors.len(), 1);
        assert!(
            errors[0].contains("Transform → Geometry (item 3)"),
            "{errors:?}"
        );
    }

    fn geometry_param_type() -> NodeType {
        geometry()
    }

    #[test]
    fn transform_parameter_passes_matrices() {
        let t = DataTree::from_list(vec![Transform::IDENTITY, Transform::rotation_z(1.0)]);
        let r = NodeCall::new(&transform()).input(t.clone()).run();
        assert_clean(&r);
        assert_eq!(r.outputs[0], t);
        let r = NodeCall::new(&transform()).run();
        assert_eq!(messages(&r, Level::Warning).len(), 1);
    }
}

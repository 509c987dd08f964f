//! Params › Geometry › Surface: a container of surfaces.

use locus_kernel::NurbsSurface;
use locus_runtime::{DataType, NodeRegistry, NodeType, Port, Shared, Value};

/// Id of [`surface`].
pub const SURFACE: &str = "params.surface";

/// Registers the Surface parameter.
pub fn register(registry: &mut NodeRegistry) {
    registry.register(surface());
}

/// The surface a value stands for: a surface as it is, and a B-rep with exactly one face as
/// that face's underlying (untrimmed) surface, as Rhino's `BrepFace.DuplicateSurface`; `None`
/// for other values (and for B-reps with no face or several).
///
/// The runtime's cast table has no B-rep → Surface row yet, so a B-rep wired into a Surface
/// input is an invalid cast before a node sees it; this function is what such a cast (or a
/// node reading generic data) should use.
pub fn surface_from_value(value: &Value) -> Option<Shared<NurbsSurface>> {
    match value {
        Value::Surface(s) => Some(s.clone()),
        Value::Brep(b) => match b.faces() {
            [face] => Some(Shared::new(face.surface.clone())),
            _ => None,
        },
        _ => None,
    }
}

/// Surface \[Srf\]: a collection of surfaces.
pub fn surface() -> NodeType {
    NodeType::new(SURFACE, "Surface", "Srf", "Params")
        .subcategory("Geometry")
        .description(
            "Contains a collection of surfaces. A parameter passes its data through unchanged \
             (paths, empty branches and nulls included) after casting every item to its type; \
             a graph uses it to declare a named input. NURBS surfaces pass as they are. Items \
             that do not cast are errors and become null; B-reps are not cast to surfaces \
             (take a B-rep's faces with Deconstruct Brep). The reparameterize modifier on its input gives every surface the domain 0 to 1 in u \
             and v.",
        )
        .input(Port::new("Surface", "Srf", DataType::Surface).list().doc(
            "The surfaces, wired in. No default; a \
             parameter without data warns that it failed to collect data.",
        ))
        .output(
            Port::new("Surface", "Srf", DataType::Surface)
                .list()
                .doc("The same surfaces, cast."),
        )
        .solve(|s| {
            let Some(branch) = s.branch(0) else {
                return Ok(());
            };
            if branch.data_type() == DataType::Surface || branch.is_empty() {
                let branch = branch.clone();
                s.set_branch(0, branch);
                return Ok(());
            }
            // The runtime casts inputs to the port's type; this covers a branch given to the
            // node directly, without that cast.
            let mut out = Vec::with_capacity(branch.len());
            for (i, value) in branch.values().enumerate() {
                match value {
                    None => out.push(None),
                    Some(v) => match surface_from_value(&v) {
                        Some(srf) => out.push(Some(Value::Surface(srf))),
                        None => {
                            s.error(format!("invalid cast: {} → Surface (item {i})", v.data_type()));
                            out.push(None);
                        }
                    },
                }
            }
            s.set_list_values(0, out);
            Ok(())
        })
}

#[cfg(test)]
mod tests {
    use locus_kernel::{Brep, Interval, OrientedBox, Plane, Point3, Sphere};
    use locus_runtime::{Branch, Column, DataTree, Level, NodeCall, TreePath, Value};

    use super::*;

    fn square() -> Shared<NurbsSurface> {
        Shared::new(
            NurbsSurface::from_plane(&Plane::WORLD_XY, Interval::UNIT, Interval::UNIT).unwrap(),
        )
    }

    #[test]
    fn surfaces_pass_through() {
        let s = square();
        let r = NodeCall::new(&surface())
            .input(DataTree::from_list(vec![s.clone(), s.clone()]))
            .run();
        assert_eq!(r.outputs[0], DataTree::from_list(vec![s.clone(), s]));
        assert!(r.messages.is_empty());
    }

    #[test]
    fn surface_from_value_takes_one_face_breps_only() {
        let sphere = Sphere::new(Point3::ORIGIN, 2.0).unwrap();
        let one_face = Value::Brep(Shared::new(Brep::from_sphere(&sphere).unwrap()));
        let bx = OrientedBox::new(
            Plane::WORLD_XY,
            Interval::UNIT,
            Interval::UNIT,
            Interval::UNIT,
        );
        let six_faces = Value::Brep(Shared::new(Brep::from_box(&bx).unwrap()));
        let s = surface_from_value(&one_face).unwrap();
        assert_eq!(*s, sphere.to_nurbs().unwrap());
        assert!(surface_from_value(&six_faces).is_none());
        assert!(surface_from_value(&Value::Number(1.0)).is_none());
    }

    #[test]
    fn items_that_do_not_cast_are_errors_and_nulls_stay() {
        let items = vec![
            Value::Surface(square()),
            Value::Number(1.0),
            Value::Boolean(false),
        ];
        let branch = Branch::from_parts(Column::Generic(items), vec![false, false, true]);
        let mut tree = DataTree::new();
        tree.insert(TreePath::zero(), branch);
        let r = NodeCall::new(&surface()).input(tree).run();
        let out: Vec<Option<Value>> = r.outputs[0].values().collect();
        assert_eq!(out, vec![Some(Value::Surface(square())), None, None]);
        let errors: Vec<&str> = r
            .messages
            .iter()
            .filter(|m| m.level == Level::Error)
            .map(|m| m.text.as_str())
            .collect();
        assert_eq!(errors.len(), 1, "{errors:?}");
        assert!(errors[0].contains("Number"), "{errors:?}");
    }
}

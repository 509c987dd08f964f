//! Params › Geometry › Surface: a container of surfaces.

use locus_kernel::NurbsSurface;
use locus_runtime::{
    DataType, NodeRegistry, NodeType, Port, Shared, Value, cast_branch, cast_value,
};

/// Id of [`surface`].
pub const SURFACE: &str = "params.surface";

/// Registers the Surface parameter.
pub fn register(registry: &mut NodeRegistry) {
    registry.register(surface());
}

/// The surface a value stands for, by the runtime's cast to Surface (`docs/casting.md`): a
/// surface as it is, and a B-rep with exactly one face as that face's underlying (untrimmed)
/// surface, as Rhino's `BrepFace.DuplicateSurface`; `None` for other values (and for B-reps
/// with no face or several). For nodes reading generic data; a Surface input already holds
/// cast items.
pub fn surface_from_value(value: &Value) -> Option<Shared<NurbsSurface>> {
    match cast_value(value, DataType::Surface) {
        Ok(Value::Surface(s)) => Some(s),
        _ => None,
    }
}

/// Surface \[Srf\]: a collection of surfaces.
pub fn surface() -> NodeType {
    NodeType::new(SURFACE, "Surface", "Srf", "Params")
        .gh_guid("deaf8653-5528-4286-807c-3de8b8dad781")
        .subcategory("Geometry")
        .description(
            "Contains a collection of surfaces. A parameter passes its data through unchanged \
             (paths, empty branches and nulls included) after casting every item to its type; \
             a graph uses it to declare a named input. NURBS surfaces pass as they are; a \
             B-rep with exactly one face becomes that face's untrimmed surface. Items that do \
             not cast are errors and become null, B-reps with several faces among them (take \
             a B-rep's faces with Deconstruct Brep). The reparameterize modifier on its input \
             gives every surface the domain 0 to 1 in u and v.",
        )
        .input(Port::new("Surface", "Srf", DataType::Surface).list().doc(
            "The surfaces, wired in: surfaces, or one-face B-reps. No default; a parameter \
             without data warns that it failed to collect data.",
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
            // The runtime casts inputs to the port's type, so this is a copy; it casts a branch
            // given to the node directly, without that cast.
            let (cast, errors) = cast_branch(branch, DataType::Surface);
            let cast = cast.into_owned();
            for (i, e) in errors {
                s.error(format!("{e} (item {i})"));
            }
            s.set_branch(0, cast);
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
    fn one_face_breps_become_surfaces_and_others_are_errors() {
        let one_face = Shared::new(Brep::from_surface((*square()).clone()).unwrap());
        let bx = OrientedBox::new(
            Plane::WORLD_XY,
            Interval::UNIT,
            Interval::UNIT,
            Interval::UNIT,
        );
        let six_faces = Shared::new(Brep::from_box(&bx).unwrap());
        let r = NodeCall::new(&surface())
            .input(DataTree::from_list(vec![one_face, six_faces]))
            .run();
        let out: Vec<Option<Value>> = r.outputs[0].values().collect();
        assert_eq!(out, vec![Some(Value::Surface(square())), None]);
        let errors: Vec<&str> = r
            .messages
            .iter()
            .filter(|m| m.level == Level::Error)
            .map(|m| m.text.as_str())
            .collect();
        assert_eq!(
            errors,
            ["input Srf: invalid cast: Brep with 6 faces → Surface"]
        );
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

//! Params › Geometry › Curve: a container of curves.

use locus_runtime::{DataType, NodeRegistry, NodeType, Port, Value};

use crate::curve::curve_from_value;

/// Id of [`curve`].
pub const CURVE: &str = "params.curve";

/// Registers the Curve parameter.
pub fn register(registry: &mut NodeRegistry) {
    registry.register(curve());
}

/// Curve \[Crv\]: a collection of curves; lines, circles and arcs that flow in become curves.
pub fn curve() -> NodeType {
    NodeType::new(CURVE, "Curve", "Crv", "Params")
        .gh_guid("d5967b9f-e8ee-436b-a8ad-29fdcecf32d5")
        .subcategory("Geometry")
        .description(
            "Contains a collection of curves. A parameter passes its data through unchanged \
             (paths, empty branches and nulls included) after casting every item to its type; \
             a graph uses it to declare a named input. Curves pass as they are; lines, circles \
             and arcs become curves with their usual domains (a line 0 to its length, a circle \
             0 to 2π, an arc its angle interval). Items that do not cast are errors and become \
             null.",
        )
        .input(Port::new("Curve", "Crv", DataType::Curve).list().doc(
            "The curves, given in the graph or wired in: curves, lines, circles or \
                     arcs. No default; a parameter without data warns that it failed to \
                     collect data.",
        ))
        .output(
            Port::new("Curve", "Crv", DataType::Curve)
                .list()
                .doc("The same curves, cast."),
        )
        .solve(|s| {
            let Some(branch) = s.branch(0) else {
                return Ok(());
            };
            if branch.data_type() == DataType::Curve || branch.is_empty() {
                let branch = branch.clone();
                s.set_branch(0, branch);
                return Ok(());
            }
            // The runtime casts inputs to the port's type; this covers a branch given to the
            // node directly, without that cast.
            let mut out = Vec::with_capacity(branch.len());
            for (i, value) in branch.values().enumerate() {
                let cast = value.as_ref().map(|v| (curve_from_value(v), v.data_type()));
                match cast {
                    None => out.push(None),
                    Some((Some(c), _)) => out.push(Some(Value::Curve(c))),
                    Some((None, t)) => {
                        s.error(format!("invalid cast: {t} → Curve (item {i})"));
                        out.push(None);
                    }
                }
            }
            s.set_list_values(0, out);
            Ok(())
        })
}

#[cfg(test)]
mod tests {
    use locus_kernel::{Circle, Curve, Line, Plane, Point3};
    use locus_runtime::{Branch, Column, DataTree, Level, NodeCall, TreePath, Value};

    use super::*;

    #[test]
    fn casts_lines_circles_and_arcs_and_keeps_nulls() {
        let line = Line::new(Point3::ORIGIN, Point3::new(3.0, 4.0, 0.0));
        let circle = Circle::new(Plane::WORLD_XY, 2.0).unwrap();
        let items = vec![
            Value::Line(line),
            Value::Circle(circle),
            Value::Number(1.0),
            Value::Boolean(false),
        ];
        let branch = Branch::from_parts(Column::Generic(items), vec![false, false, false, true]);
        let mut tree = DataTree::new();
        tree.insert(TreePath::zero(), branch);
        let r = NodeCall::new(&curve()).input(tree).run();
        let out: Vec<Option<Value>> = r.outputs[0].values().collect();
        assert_eq!(out.len(), 4);
        let Some(Value::Curve(c)) = &out[0] else {
            panic!("{out:?}")
        };
        assert_eq!(**c, Curve::from(line));
        assert_eq!(c.length(), 5.0);
        let Some(Value::Curve(c)) = &out[1] else {
            panic!("{out:?}")
        };
        assert!(c.is_closed());
        assert_eq!(out[2], None);
        assert_eq!(out[3], None);
        let errors: Vec<&str> = r
            .messages
            .iter()
            .filter(|m| m.level == Level::Error)
            .map(|m| m.text.as_str())
            .collect();
        assert_eq!(errors.len(), 1, "{errors:?}");
        assert!(errors[0].contains("Number"), "{errors:?}");
    }

    #[test]
    fn curves_pass_through() {
        let c = std::sync::Arc::new(Curve::from(Line::new(
            Point3::ORIGIN,
            Point3::new(1.0, 0.0, 0.0),
        )));
        let r = NodeCall::new(&curve())
            .input(DataTree::from_list(vec![c.clone(), c.clone()]))
            .run();
        assert_eq!(r.outputs[0], DataTree::from_list(vec![c.clone(), c]));
        assert!(r.messages.is_empty());
    }
}

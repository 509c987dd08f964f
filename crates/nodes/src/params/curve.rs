//! Params › Geometry › Curve: a container of curves.

use locus_runtime::{DataType, NodeRegistry, NodeType, Port};

use crate::curve::curve_from_value;

/// Id of [`curve`].
pub const CURVE: &str = "params.curve";

/// Registers the Curve parameter.
pub fn register(registry: &mut NodeRegistry) {
    registry.register(curve());
}

/// Curve \[Crv\]: holds curves; lines, circles and arcs that flow in become curves.
pub fn curve() -> NodeType {
    NodeType::new(CURVE, "Curve", "Crv", "Params")
        .subcategory("Geometry")
        .description(
            "Contains a collection of curves. Curves pass through unchanged; lines, circles and \
             arcs are cast to curves (with their usual domains). Any other item becomes a null \
             with an error naming its type; nulls stay null.",
        )
        .input(
            Port::new("Curve", "C", DataType::Curve)
                .doc("The curves (or lines, circles, arcs) to hold.")
                .list(),
        )
        .output(
            Port::new("Curve", "C", DataType::Curve)
                .doc("The curves, in the same order and tree structure.")
                .list(),
        )
        .solve(|s| {
            let Some(branch) = s.branch(0) else {
                s.set_list_values(0, Vec::new());
                return Ok(());
            };
            let mut out = Vec::with_capacity(branch.len());
            let mut failures = Vec::new();
            for (i, value) in branch.values().enumerate() {
                match value {
                    None => out.push(None),
                    Some(v) => match curve_from_value(&v) {
                        Some(c) => out.push(Some(locus_runtime::Value::Curve(c))),
                        None => {
                            failures.push(format!(
                                "invalid cast: {} » Curve (item {i})",
                                v.data_type()
                            ));
                            out.push(None);
                        }
                    },
                }
            }
            for f in failures {
                s.error(f);
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
        assert_eq!(errors, vec!["invalid cast: Number » Curve (item 2)"]);
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

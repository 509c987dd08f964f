//! Curve › Analysis: Derivatives, the point and the derivatives of a curve at a parameter.
//!
//! Grasshopper's Derivatives has a variable number of outputs (the user zooms in to add
//! them): the point, then the first, second, … derivative. Here the point is the fixed output
//! and the derivatives are variable outputs, named by the graph (Grasshopper names them `1`,
//! `2`, …); output `k` after the point is the `k`-th derivative whatever its name.

use locus_kernel::Point3;
use locus_runtime::{DataType, NodeRegistry, NodeType, Port};

use super::analysis::parameter_on;
use super::curve_input;

/// Id of [`derivatives`].
pub const DERIVATIVES: &str = "curve.derivatives";

/// Registers the Derivatives node.
pub fn register(registry: &mut NodeRegistry) {
    registry.register(derivatives());
}

/// Derivatives \[CDiv\]: the point and the first `n` derivatives of a curve at a parameter.
pub fn derivatives() -> NodeType {
    NodeType::new(DERIVATIVES, "Derivatives", "CDiv", "Curve")
        .subcategory("Analysis")
        .gh_guid("ab14760f-87a6-462e-b481-4a2c26a9a0d7")
        .description(
            "Evaluates a curve and its derivatives with respect to its parameter at t: the \
             point, then one derivative per further output, the first (the velocity), the \
             second (the acceleration), and so on, as many as the node has outputs. The \
             derivatives are not unitized: they scale with the curve's parametrisation. At a \
             knot or a polyline corner they are the derivatives from the right (from the left \
             at the end of the domain). A parameter outside the domain evaluates the curve's \
             extension, with a warning.",
        )
        .input(Port::new("Curve", "C", DataType::Curve).doc("Curve to evaluate."))
        .input(
            Port::new("Parameter", "t", DataType::Number)
                .doc("Parameter on the curve's domain to evaluate at."),
        )
        .output(Port::new("Point", "P", DataType::Point).doc("Point on the curve at t."))
        .variable_outputs(
            Port::new("Derivative", "1", DataType::Vector)
                .doc("A derivative at t: the k-th output after the point is the k-th derivative."),
            &["1", "2"],
        )
        .solve(|s| {
            let curve = curve_input(s, 0)?;
            let t = parameter_on(s, 1, &curve)?;
            let order = s.output_count().saturating_sub(1);
            let derivatives = curve.derivatives_at(t, order);
            if derivatives.iter().any(|d| !d.is_finite()) {
                return Err(format!("the curve's derivatives at {t} are not finite").into());
            }
            s.set(0, Point3::from_vector(derivatives[0]));
            for (k, d) in derivatives.into_iter().enumerate().skip(1) {
                s.set(k, d);
            }
            Ok(())
        })
}

#[cfg(test)]
mod tests {
    use locus_kernel::{Circle, Curve, NurbsCurve, Plane, Vector3};
    use locus_runtime::{DataTree, NodeCall};

    use super::*;
    use crate::curve::test_support::*;

    fn parabola() -> Curve {
        // (t, t², 0) on [0, 1]: a quadratic Bézier curve.
        NurbsCurve::new_non_rational(
            2,
            vec![
                Point3::new(0.0, 0.0, 0.0),
                Point3::new(0.5, 0.0, 0.0),
                Point3::new(1.0, 1.0, 0.0),
            ],
            vec![0.0, 0.0, 1.0, 1.0],
        )
        .unwrap()
        .into()
    }

    fn run(curve: Curve, t: f64, names: &[&str]) -> locus_runtime::NodeCallResult {
        NodeCall::new(&derivatives())
            .input(curve_tree(curve))
            .input(DataTree::from_item(t))
            .output_names(names)
            .run()
    }

    #[test]
    fn a_parabola_has_its_derivatives_by_position() {
        let r = run(parabola(), 0.5, &["1", "2", "3"]);
        assert_clean(&r);
        assert_eq!(r.outputs.len(), 4);
        assert!(close(
            points(&r.outputs[0])[0],
            Point3::new(0.5, 0.25, 0.0),
            1e-15
        ));
        assert_eq!(vectors(&r.outputs[1])[0], Vector3::new(1.0, 1.0, 0.0));
        assert_eq!(vectors(&r.outputs[2])[0], Vector3::new(0.0, 2.0, 0.0));
        assert_eq!(vectors(&r.outputs[3])[0], Vector3::ZERO);
        // The names do not decide the order: the first output after the point is the first
        // derivative.
        let r = run(parabola(), 0.5, &["acceleration"]);
        assert_eq!(r.outputs.len(), 2);
        assert_eq!(vectors(&r.outputs[1])[0], Vector3::new(1.0, 1.0, 0.0));
    }

    #[test]
    fn a_circle_turns_its_derivatives_a_quarter_each_time() {
        let circle = Circle::new(Plane::WORLD_XY, 2.0).unwrap();
        let r = run(circle.into(), 0.0, &["1", "2"]);
        assert_clean(&r);
        let d1 = vectors(&r.outputs[1])[0];
        let d2 = vectors(&r.outputs[2])[0];
        assert!(
            (d1 - Vector3::new(0.0, 2.0, 0.0)).length() < 1e-15,
            "{d1:?}"
        );
        assert!(
            (d2 - Vector3::new(-2.0, 0.0, 0.0)).length() < 1e-15,
            "{d2:?}"
        );
    }

    #[test]
    fn the_default_outputs_are_the_first_two_derivatives() {
        let r = NodeCall::new(&derivatives())
            .input(curve_tree(parabola()))
            .input(DataTree::from_item(0.0))
            .run();
        assert_eq!(r.outputs.len(), 3);
        assert_eq!(vectors(&r.outputs[2])[0], Vector3::new(0.0, 2.0, 0.0));
    }

    #[test]
    fn bad_parameters_are_reported() {
        assert_error(&run(parabola(), f64::NAN, &["1"]), "t");
        let r = run(parabola(), 2.0, &["1"]);
        assert!(messages(&r, locus_runtime::Level::Warning)[0].contains("outside the domain"));
        assert!(close(
            points(&r.outputs[0])[0],
            Point3::new(2.0, 4.0, 0.0),
            1e-12
        ));
    }
}

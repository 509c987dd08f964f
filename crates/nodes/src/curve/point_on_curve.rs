//! Curve › Analysis: Point On Curve, the point at a fraction of a curve's domain.
//!
//! In Grasshopper, Point On Curve is a parameter-shaped object: the curves come in on its own
//! wires, it outputs points, and the position is a number stored in the object (`parameter`,
//! set with a slider on the canvas, 0.5 by default), not an input. locus keeps that number as
//! the node's setting `parameter`. Grasshopper's documentation does not say whether the number
//! is a fraction of the domain or of the length; locus reads it as a fraction of the domain
//! (normalised parameter, as the object's presets ¼, ⅓, ½ … of a curve's domain suggest) and
//! says so in the description.

use locus_kernel::{Curve, Point3};
use locus_runtime::{DataType, NodeError, NodeRegistry, NodeType, Port, Shared, Solve, Value};

use super::{curve_input, valid_curve};

/// Id of [`point_on_curve`].
pub const POINT_ON_CURVE: &str = "curve.point_on_curve";

/// The setting that holds the position along the domain.
pub const PARAMETER: &str = "parameter";

/// Registers the Point On Curve node.
pub fn register(registry: &mut NodeRegistry) {
    registry.register(point_on_curve());
}

/// Point On Curve \[CurvePoint\]: the point at a fraction of each curve's domain.
pub fn point_on_curve() -> NodeType {
    NodeType::new(POINT_ON_CURVE, "Point On Curve", "CurvePoint", "Curve")
        .subcategory("Analysis")
        .gh_guid("7f6a9d34-0470-4bb7-aadd-07496bcbe572")
        .description(
            "The point of each curve at the normalised parameter set on the node (setting \
             `parameter`, from 0 at the curve's start to 1 at its end, 0.5 by default): the \
             curve evaluated at t0 + parameter·(t1 − t0) of its domain t0 to t1. A parameter \
             outside 0 to 1, or not a number, is an error.",
        )
        .setting(
            PARAMETER,
            DataType::Number,
            Some(Value::Number(0.5)),
            "The position along the curve's domain, from 0 (start) to 1 (end); default 0.5.",
        )
        .input(Port::new("Curve", "C", DataType::Curve).doc("The curves to evaluate."))
        .output(Port::new("Point", "P", DataType::Point).doc("The point of each curve."))
        .solve(|s| {
            let curve = curve_input(s, 0)?;
            valid_curve(&curve, "C")?;
            let fraction = parameter(s)?;
            s.set(0, point_at_fraction(&curve, fraction));
            Ok(())
        })
}

fn parameter(s: &Solve<'_>) -> Result<f64, NodeError> {
    let fraction = match s.setting(PARAMETER) {
        None => 0.5,
        Some(Value::Number(x)) => *x,
        Some(Value::Integer(i)) => *i as f64,
        Some(other) => {
            return Err(format!(
                "setting {PARAMETER}: a {} is not a number",
                other.data_type()
            )
            .into());
        }
    };
    if !(0.0..=1.0).contains(&fraction) {
        return Err(format!("setting {PARAMETER}: {fraction} is not between 0 and 1").into());
    }
    Ok(fraction)
}

/// The point at `fraction` of the curve's domain (the ends exactly at 0 and 1).
fn point_at_fraction(curve: &Shared<Curve>, fraction: f64) -> Point3 {
    let d = curve.domain();
    let t = if fraction == 1.0 {
        d.t1
    } else {
        d.t0 + fraction * (d.t1 - d.t0)
    };
    curve.point_at(t)
}

#[cfg(test)]
mod tests {
    use locus_kernel::{Line, NurbsCurve};
    use locus_runtime::{DataTree, NodeCall};

    use super::*;
    use crate::test_support::{assert_clean, assert_error};

    fn run(curve: Curve, parameter: Option<f64>) -> locus_runtime::NodeCallResult {
        let node = point_on_curve();
        let mut call = NodeCall::new(&node).input(DataTree::from_item(Shared::new(curve)));
        if let Some(p) = parameter {
            call = call.setting(PARAMETER, Value::Number(p));
        }
        call.run()
    }

    fn point(r: &locus_runtime::NodeCallResult) -> Point3 {
        match r.outputs[0].values().next().flatten() {
            Some(Value::Point(p)) => p,
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn the_default_is_the_middle_of_the_domain() {
        let line = Curve::from(Line::new(
            Point3::new(0.0, 0.0, 0.0),
            Point3::new(4.0, 2.0, 0.0),
        ));
        let r = run(line, None);
        assert_clean(&r);
        assert_eq!(point(&r), Point3::new(2.0, 1.0, 0.0));
    }

    #[test]
    fn a_fraction_of_the_domain_not_of_the_length() {
        // The parabola (t, t², 0) on the domain 0 to 1, as a quadratic Bézier: a quarter of the
        // domain is (0.25, 0.0625, 0), not a quarter of the length.
        let parabola = NurbsCurve::new(
            2,
            vec![
                Point3::new(0.0, 0.0, 0.0),
                Point3::new(0.5, 0.0, 0.0),
                Point3::new(1.0, 1.0, 0.0),
            ],
            vec![1.0; 3],
            vec![0.0, 0.0, 1.0, 1.0],
        )
        .unwrap();
        let r = run(Curve::Nurbs(parabola.clone()), Some(0.25));
        assert_clean(&r);
        let p = point(&r);
        assert!(
            (p - Point3::new(0.25, 0.0625, 0.0)).length() < 1e-15,
            "{p:?}"
        );
        assert_eq!(
            point(&run(Curve::Nurbs(parabola), Some(1.0))),
            Point3::new(1.0, 1.0, 0.0)
        );
    }

    #[test]
    fn bad_parameters_and_curves_are_errors() {
        let line = || Curve::from(Line::new(Point3::ORIGIN, Point3::new(1.0, 0.0, 0.0)));
        assert_error(&run(line(), Some(1.5)), "not between 0 and 1");
        assert_error(&run(line(), Some(f64::NAN)), "not between 0 and 1");
        let degenerate = Curve::from(Line::new(
            Point3::new(f64::NAN, 0.0, 0.0),
            Point3::new(1.0, 0.0, 0.0),
        ));
        assert_error(&run(degenerate, None), "not valid");
    }
}

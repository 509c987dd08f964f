//! Curve › Util: Flip Curve and Split Curve.

use locus_kernel::Curve;
use locus_runtime::{DataType, NodeRegistry, NodeType, Port, Shared};

use super::{curve_input, finite_parameter};

/// Id of [`flip_curve`].
pub const FLIP_CURVE: &str = "curve.flip_curve";
/// Id of [`split_curve`].
pub const SPLIT_CURVE: &str = "curve.split_curve";

/// The number of places along a curve where its direction is compared with a guide's.
const DIRECTION_SAMPLES: usize = 16;

/// Registers the utility nodes.
pub fn register(registry: &mut NodeRegistry) {
    for t in [flip_curve(), split_curve()] {
        registry.register(t);
    }
}

fn util(id: &str, name: &str, nickname: &str) -> NodeType {
    NodeType::new(id, name, nickname, "Curve").subcategory("Util")
}

/// Whether `curve` runs against `guide`: at evenly spaced parameters of `curve`, the tangent
/// is compared (dot product) with the guide's tangent at the guide's closest point, and the
/// sum of the comparisons is negative.
fn runs_against(curve: &Curve, guide: &Curve) -> Result<bool, locus_kernel::Error> {
    let d = curve.domain();
    let mut agreement = 0.0;
    for i in 0..DIRECTION_SAMPLES {
        let t = d.parameter_at((i as f64 + 0.5) / DIRECTION_SAMPLES as f64);
        let Some(tangent) = curve.tangent_at(t) else {
            continue;
        };
        let cp = guide.closest_point(curve.point_at(t))?;
        if let Some(g) = guide.tangent_at(cp.t) {
            agreement += tangent.dot(g);
        }
    }
    Ok(agreement < 0.0)
}

/// Flip Curve \[Flip\]: a curve reversed, optionally only when it runs against a guide.
pub fn flip_curve() -> NodeType {
    util(FLIP_CURVE, "Flip Curve", "Flip")
        .gh_guid("22990b1f-9be6-477c-ad89-f775cd347105")
        .description(
            "Reverses the direction of a curve, as Rhino's Flip: the domain t0 to t1 becomes \
             −t1 to −t0, so the point at t moves to −t. With a guide curve the curve is reversed \
             only when it runs against the guide (its tangents, compared with the guide's at \
             the closest points of 16 evenly spaced samples, mostly point the other way).",
        )
        .input(Port::new("Curve", "C", DataType::Curve).doc("Curve to flip."))
        .input(
            Port::new("Guide", "G", DataType::Curve)
                .doc("Optional guide curve whose direction the result follows.")
                .optional(),
        )
        .output(Port::new("Curve", "C", DataType::Curve).doc("The flipped (or unchanged) curve."))
        .output(Port::new("Flag", "F", DataType::Boolean).doc("True when the curve was reversed."))
        .solve(|s| {
            let curve = curve_input(s, 0)?;
            let flip = if s.value(1).is_some() {
                let guide = curve_input(s, 1)?;
                runs_against(&curve, &guide)?
            } else {
                true
            };
            let out = if flip {
                Shared::new(curve.reversed())
            } else {
                curve
            };
            s.set(0, out);
            s.set(1, flip);
            Ok(())
        })
}

/// Split Curve \[Split\]: the two pieces of a curve on either side of a parameter.
pub fn split_curve() -> NodeType {
    util(SPLIT_CURVE, "Split Curve", "Split")
        .description(
            "Cuts a curve at one parameter into the piece before it (domain t0 to t) and the \
             piece after it (t to t1), closed curves included (their seam stays an end). \
             Grasshopper has no single-cut component (it uses Shatter); this one gives the two \
             pieces on separate outputs. Pieces keep their parameters and, where possible, the \
             kind of their curve.",
        )
        .input(Port::new("Curve", "C", DataType::Curve).doc("Curve to cut."))
        .input(
            Port::new("Parameter", "t", DataType::Number)
                .doc("Parameter to cut at, strictly inside the curve's domain."),
        )
        .output(Port::new("Curve A", "A", DataType::Curve).doc("The piece from t0 to t."))
        .output(Port::new("Curve B", "B", DataType::Curve).doc("The piece from t to t1."))
        .solve(|s| {
            let curve = curve_input(s, 0)?;
            let t = finite_parameter(*s.item::<f64>(1)?, "t")?;
            let (a, b) = curve.split_at(t)?;
            s.set(0, Shared::new(a));
            s.set(1, Shared::new(b));
            Ok(())
        })
}

#[cfg(test)]
mod tests {
    use locus_kernel::{Circle, Interval, Line, Plane, Point3};
    use locus_runtime::{DataTree, NodeCall, Value};

    use super::*;
    use crate::curve::test_support::*;

    fn line(a: (f64, f64), b: (f64, f64)) -> Curve {
        Line::new(Point3::new(a.0, a.1, 0.0), Point3::new(b.0, b.1, 0.0)).into()
    }

    #[test]
    fn flip_without_guide_reverses() {
        let r = NodeCall::new(&flip_curve())
            .input(curve_tree(line((0.0, 0.0), (4.0, 0.0))))
            .run();
        let c = curves(&r.outputs[0])[0].clone();
        assert_eq!(c.domain(), Interval::new(-4.0, 0.0));
        assert_eq!(c.start_point(), Point3::new(4.0, 0.0, 0.0));
        assert_eq!(values(&r.outputs[1]), vec![Some(Value::Boolean(true))]);
    }

    #[test]
    fn flip_follows_a_guide() {
        let guide = line((0.0, 1.0), (10.0, 1.5));
        let r = NodeCall::new(&flip_curve())
            .input(DataTree::from_list(vec![
                Shared::new(line((0.0, 0.0), (4.0, 0.0))),
                Shared::new(line((4.0, 0.0), (0.0, 0.0))),
            ]))
            .input(curve_tree(guide))
            .run();
        assert_eq!(
            values(&r.outputs[1]),
            vec![Some(Value::Boolean(false)), Some(Value::Boolean(true))]
        );
        for c in curves(&r.outputs[0]) {
            assert_eq!(c.start_point(), Point3::ORIGIN);
        }
    }

    #[test]
    fn flip_bad_input() {
        let r = NodeCall::new(&flip_curve())
            .input(curve_tree(line((0.0, 0.0), (4.0, 0.0))))
            .input(DataTree::from_item(Point3::ORIGIN))
            .run();
        assert!(single_error(&r).contains("invalid cast: Point"));
    }

    #[test]
    fn split_a_circle() {
        let r = NodeCall::new(&split_curve())
            .input(curve_tree(Circle::new(Plane::WORLD_XY, 1.0).unwrap()))
            .input(DataTree::from_list(vec![1.0, 0.0, 7.0, f64::NAN]))
            .run();
        let a = values(&r.outputs[0]);
        let b = values(&r.outputs[1]);
        let (Some(Value::Curve(a0)), Some(Value::Curve(b0))) = (&a[0], &b[0]) else {
            panic!("{a:?}")
        };
        assert!(matches!(**a0, Curve::Arc { .. }));
        assert_eq!(a0.domain(), Interval::new(0.0, 1.0));
        assert_eq!(b0.domain(), Interval::new(1.0, std::f64::consts::TAU));
        assert!((a0.length() + b0.length() - std::f64::consts::TAU).abs() < 1e-14);
        assert_eq!(a[1..], [None, None, None]);
        let errors = messages(&r, locus_runtime::Level::Error);
        assert_eq!(errors.len(), 3);
        assert!(errors[0].contains("not inside the domain"), "{errors:?}");
    }
}

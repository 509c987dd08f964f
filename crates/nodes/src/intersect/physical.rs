//! Intersect › Physical, on curves: Curve | Curve and Curve | Self.
//!
//! Curves are intersected as they are (bounded), within the intersection tolerance. Where two
//! curves (or two passes of one curve) coincide along a stretch, the ends of the stretch are
//! given as points, with a remark that names the overlap on both curves.

use locus_kernel::{Curve, CurveCurveIntersections, Point3};
use locus_runtime::{DataType, NodeRegistry, NodeType, Port, Shared, Solve};

use super::INTERSECTION_TOLERANCE;
use crate::curve::curve_input;

/// Id of [`curve_curve_node`].
pub const CURVE_CURVE: &str = "intersect.curve_curve";
/// Id of [`curve_self_node`].
pub const CURVE_SELF: &str = "intersect.curve_self";

/// Registers the Physical curve intersection nodes.
pub fn register(registry: &mut NodeRegistry) {
    registry.register(curve_curve_node());
    registry.register(curve_self_node());
}

pub(crate) fn physical(id: &str, name: &str, nickname: &str) -> NodeType {
    NodeType::new(id, name, nickname, "Intersect").subcategory("Physical")
}

/// The events of a curve | curve search as `(point, t_a, t_b)`: the points, and both ends of
/// every overlap, in order of `t_a`; a remark names the overlaps.
fn events(
    s: &mut Solve<'_>,
    a: &Curve,
    found: &CurveCurveIntersections,
) -> Vec<(Point3, f64, f64)> {
    let mut out: Vec<(Point3, f64, f64)> = found
        .points
        .iter()
        .map(|h| (h.point_a, h.t_a, h.t_b))
        .collect();
    for o in &found.overlaps {
        out.push((a.point_at(o.a.t0), o.a.t0, o.b.t0));
        out.push((a.point_at(o.a.t1), o.a.t1, o.b.t1));
    }
    out.sort_by(|x, y| x.1.total_cmp(&y.1));
    if !found.overlaps.is_empty() {
        let list: Vec<String> = found
            .overlaps
            .iter()
            .map(|o| format!("[{}, {}] with [{}, {}]", o.a.t0, o.a.t1, o.b.t0, o.b.t1))
            .collect();
        s.remark(format!(
            "the curves overlap on {}: the ends of each overlap are given as points",
            list.join(", ")
        ));
    }
    out
}

/// Curve | Curve \[CCX\]: where two curves meet.
pub fn curve_curve_node() -> NodeType {
    physical(CURVE_CURVE, "Curve | Curve", "CCX")
        .gh_guid("84627490-0fb2-4498-8138-ad134ee4cb36")
        .description(
            "Solves the intersection events of two curves: every point where they cross or \
             touch (tangencies, kinks and end points included, a closed curve's seam once), \
             within the intersection tolerance (0.001), with its parameter on both curves. \
             Where the curves coincide along a stretch, the ends of the stretch are given as \
             points, with a remark naming the overlap on both curves.",
        )
        .input(Port::new("Curve A", "A", DataType::Curve).doc("The first curve."))
        .input(Port::new("Curve B", "B", DataType::Curve).doc("The second curve."))
        .output(
            Port::new("Points", "P", DataType::Point)
                .doc("The intersection events, in order along A.")
                .list(),
        )
        .output(
            Port::new("Params A", "tA", DataType::Number)
                .doc("The parameters of the events on A.")
                .list(),
        )
        .output(
            Port::new("Params B", "tB", DataType::Number)
                .doc("The parameters of the events on B.")
                .list(),
        )
        .solve(|s| {
            let a: Shared<Curve> = curve_input(s, 0)?;
            let b: Shared<Curve> = curve_input(s, 1)?;
            let found = a.intersect_curve(&b, INTERSECTION_TOLERANCE)?;
            let events = events(s, &a, &found);
            s.set_list(0, events.iter().map(|e| e.0).collect());
            s.set_list(1, events.iter().map(|e| e.1).collect());
            s.set_list(2, events.iter().map(|e| e.2).collect());
            Ok(())
        })
}

/// Curve | Self \[CX\]: where a curve crosses itself.
pub fn curve_self_node() -> NodeType {
    physical(CURVE_SELF, "Curve | Self", "CX")
        .gh_guid("0991ac99-6a0b-47a9-b07d-dd510ca57f0f")
        .description(
            "Solves the self-intersection events of a curve: every point where it crosses or \
             touches itself, within the intersection tolerance (0.001). Each event is listed \
             twice, once for each pass of the curve through it: the point with the parameter \
             of the earlier pass, then the point with the parameter of the later one. Where \
             the curve runs back over itself, the ends of that stretch are given the same way, \
             with a remark. A closed curve's seam is not an event.",
        )
        .input(Port::new("Curve", "C", DataType::Curve).doc("The curve."))
        .output(
            Port::new("Points", "P", DataType::Point)
                .doc("The self-intersection events, two entries each (one per pass).")
                .list(),
        )
        .output(
            Port::new("Params", "t", DataType::Number)
                .doc("The parameter of each entry of P on the curve.")
                .list(),
        )
        .solve(|s| {
            let curve: Shared<Curve> = curve_input(s, 0)?;
            let found = curve.self_intersections(INTERSECTION_TOLERANCE)?;
            let events = events(s, &curve, &found);
            let mut points = Vec::with_capacity(2 * events.len());
            let mut params = Vec::with_capacity(2 * events.len());
            for (p, ta, tb) in events {
                points.push(p);
                params.push(ta);
                points.push(curve.point_at(tb));
                params.push(tb);
            }
            s.set_list(0, points);
            s.set_list(1, params);
            Ok(())
        })
}

#[cfg(test)]
mod tests {
    use locus_kernel::{Circle, Line, Plane, Polyline, Vector3};
    use locus_runtime::{DataTree, Level, NodeCall, Value};

    use super::*;
    use crate::test_support::{assert_clean, assert_error, messages, numbers, points};

    fn p(x: f64, y: f64, z: f64) -> Point3 {
        Point3::new(x, y, z)
    }

    fn curve(c: impl Into<Curve>) -> DataTree {
        DataTree::from_item(Shared::new(c.into()))
    }

    #[test]
    fn two_circles_meet_twice_with_both_parameters() {
        let a = Circle::new(Plane::WORLD_XY, 2.0).unwrap();
        let b = Circle::new(Plane::WORLD_XY.translated(Vector3::new(2.0, 0.0, 0.0)), 2.0).unwrap();
        let r = NodeCall::new(&curve_curve_node())
            .input(curve(a))
            .input(curve(b))
            .run();
        assert_clean(&r);
        let pts = points(&r.outputs[0]);
        assert_eq!(pts.len(), 2);
        // At 60° and 300° on A, 120° and 240° on B.
        let third = std::f64::consts::FRAC_PI_3;
        let (ta, tb) = (numbers(&r.outputs[1]), numbers(&r.outputs[2]));
        assert!(
            (ta[0] - third).abs() < 1e-12 && (ta[1] - 5.0 * third).abs() < 1e-12,
            "{ta:?}"
        );
        assert!((tb[0] - 2.0 * third).abs() < 1e-12 && (tb[1] - 4.0 * third).abs() < 1e-12);
        assert!(pts[0].distance(p(1.0, 3f64.sqrt(), 0.0)) < 1e-12);
    }

    #[test]
    fn overlapping_lines_give_the_ends_and_a_remark() {
        let r = NodeCall::new(&curve_curve_node())
            .input(curve(Line::new(p(0.0, 0.0, 0.0), p(4.0, 0.0, 0.0))))
            .input(curve(Line::new(p(6.0, 0.0, 0.0), p(2.0, 0.0, 0.0))))
            .run();
        assert_eq!(numbers(&r.outputs[1]), vec![2.0, 4.0]);
        assert_eq!(numbers(&r.outputs[2]), vec![4.0, 2.0]);
        assert!(messages(&r, Level::Remark)[0].contains("overlap on [2, 4] with [4, 2]"));
    }

    #[test]
    fn a_figure_eight_lists_its_crossing_twice() {
        let c = Polyline::new(vec![
            p(0.0, 0.0, 0.0),
            p(2.0, 2.0, 0.0),
            p(2.0, 0.0, 0.0),
            p(0.0, 2.0, 0.0),
        ])
        .unwrap();
        let r = NodeCall::new(&curve_self_node()).input(curve(c)).run();
        assert_clean(&r);
        assert_eq!(numbers(&r.outputs[1]), vec![0.5, 2.5]);
        let pts = points(&r.outputs[0]);
        assert!(pts.iter().all(|q| q.distance(p(1.0, 1.0, 0.0)) < 1e-15));
    }

    #[test]
    fn non_curves_are_errors() {
        let r = NodeCall::new(&curve_curve_node())
            .input(DataTree::from_item(Value::Number(3.0)))
            .input(curve(Line::new(p(0.0, 0.0, 0.0), p(1.0, 0.0, 0.0))))
            .run();
        assert_error(&r, "invalid cast: Number → Curve");
        let r = NodeCall::new(&curve_self_node())
            .input(DataTree::from_item(Value::Text("x".into())))
            .run();
        assert_error(&r, "input C");
    }
}

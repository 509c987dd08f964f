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
/// Id of [`multiple_curves_node`].
pub const MULTIPLE_CURVES: &str = "intersect.multiple_curves";

/// The most curves Multiple Curves intersects pairwise (10,000: 5·10⁷ pairs).
pub const MAX_MULTIPLE_CURVES: usize = 10_000;

/// Registers the Physical curve intersection nodes.
pub fn register(registry: &mut NodeRegistry) {
    registry.register(curve_curve_node());
    registry.register(curve_self_node());
    registry.register(multiple_curves_node());
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

/// Multiple Curves \[MCX\]: where the curves of a list meet one another.
pub fn multiple_curves_node() -> NodeType {
    physical(MULTIPLE_CURVES, "Multiple Curves", "MCX")
        .gh_guid("931e6030-ccb3-4a7b-a89a-99dcce8770cd")
        .description(
            "Solves the intersection events of every pair of curves in a list, as Curve | Curve \
             does for two (within the intersection tolerance, 0.001; the ends of a stretch where \
             two curves coincide are events, with a remark). Pairs are taken in order, (0, 1), \
             (0, 2), …, (1, 2), …, and the events of a pair in order along the first curve; a \
             curve is not intersected with itself. Null items are skipped (with a warning) and \
             keep their place in the indices.",
        )
        .input(
            Port::new("Curves", "C", DataType::Curve)
                .doc("The curves to intersect with one another.")
                .list(),
        )
        .output(
            Port::new("Points", "P", DataType::Point)
                .doc("The intersection events.")
                .list(),
        )
        .output(
            Port::new("Index A", "iA", DataType::Integer)
                .doc("The index in C of the first curve of each event.")
                .list(),
        )
        .output(
            Port::new("Index B", "iB", DataType::Integer)
                .doc("The index in C of the second curve of each event.")
                .list(),
        )
        .output(
            Port::new("Param A", "tA", DataType::Number)
                .doc("The parameter of each event on the first curve.")
                .list(),
        )
        .output(
            Port::new("Param B", "tB", DataType::Number)
                .doc("The parameter of each event on the second curve.")
                .list(),
        )
        .solve(|s| {
            let Some(branch) = s.branch(0) else {
                return Ok(());
            };
            if branch.len() > MAX_MULTIPLE_CURVES {
                return Err(format!(
                    "input C: {} curves are more than the {MAX_MULTIPLE_CURVES} intersected \
                     pairwise",
                    branch.len()
                )
                .into());
            }
            let mut curves: Vec<(usize, Shared<Curve>)> = Vec::with_capacity(branch.len());
            let mut nulls = 0;
            for (i, value) in branch.values().enumerate() {
                let Some(value) = value else {
                    nulls += 1;
                    continue;
                };
                let curve = crate::curve::curve_from_value(&value).ok_or_else(|| {
                    format!("input C: item {i}, a {}, is not a curve", value.data_type())
                })?;
                crate::curve::valid_curve(&curve, &format!("C (item {i})"))?;
                curves.push((i, curve));
            }
            if nulls > 0 {
                s.warning(format!("input C: {nulls} null item(s) skipped"));
            }
            let (mut points, mut index_a, mut index_b, mut t_a, mut t_b) =
                (Vec::new(), Vec::new(), Vec::new(), Vec::new(), Vec::new());
            for (k, (i, a)) in curves.iter().enumerate() {
                for (j, b) in &curves[k + 1..] {
                    let found = a.intersect_curve(b, INTERSECTION_TOLERANCE)?;
                    for (p, ta, tb) in events(s, a, &found) {
                        points.push(p);
                        index_a.push(*i as i64);
                        index_b.push(*j as i64);
                        t_a.push(ta);
                        t_b.push(tb);
                    }
                }
            }
            s.set_list(0, points);
            s.set_list(1, index_a);
            s.set_list(2, index_b);
            s.set_list(3, t_a);
            s.set_list(4, t_b);
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

    fn integers(tree: &DataTree) -> Vec<i64> {
        tree.values()
            .map(|v| match v {
                Some(Value::Integer(i)) => i,
                other => panic!("{other:?}"),
            })
            .collect()
    }

    #[test]
    fn multiple_curves_intersect_every_pair_once_with_input_indices() {
        // A horizontal line (0), a null (1), a vertical line (2) and a circle of radius 1
        // about the origin (3): the lines cross at the origin; each line meets the circle
        // twice; nothing is intersected with itself.
        let lines = vec![
            Some(Value::Curve(Shared::new(
                Line::new(p(-2.0, 0.0, 0.0), p(2.0, 0.0, 0.0)).into(),
            ))),
            None,
            Some(Value::Curve(Shared::new(
                Line::new(p(0.0, -2.0, 0.0), p(0.0, 2.0, 0.0)).into(),
            ))),
            Some(Value::Curve(Shared::new(
                Circle::new(Plane::WORLD_XY, 1.0).unwrap().into(),
            ))),
        ];
        let mut branch = locus_runtime::Branch::new(DataType::Curve);
        for v in lines {
            match v {
                Some(v) => branch.push_value(v),
                None => branch.push_null(),
            }
        }
        let tree = DataTree::from_branches([(locus_runtime::TreePath::zero(), branch)]);
        let r = NodeCall::new(&multiple_curves_node()).input(tree).run();
        assert_eq!(
            messages(&r, Level::Warning),
            ["input C: 1 null item(s) skipped"]
        );
        assert_eq!(integers(&r.outputs[1]), [0, 0, 0, 2, 2]);
        assert_eq!(integers(&r.outputs[2]), [2, 3, 3, 3, 3]);
        let pts = points(&r.outputs[0]);
        let want = [
            p(0.0, 0.0, 0.0),
            p(-1.0, 0.0, 0.0),
            p(1.0, 0.0, 0.0),
            p(0.0, -1.0, 0.0),
            p(0.0, 1.0, 0.0),
        ];
        for (got, want) in pts.iter().zip(want) {
            assert!(got.distance(want) < 1e-12, "{pts:?}");
        }
        // Parameters: a line's run from 0 at its start to its length (4), the circle's from
        // (1, 0, 0).
        let (ta, tb) = (numbers(&r.outputs[3]), numbers(&r.outputs[4]));
        assert!(
            (ta[0] - 2.0).abs() < 1e-12 && (tb[0] - 2.0).abs() < 1e-12,
            "{ta:?} {tb:?}"
        );
        assert!((tb[3] - 1.5 * std::f64::consts::PI).abs() < 1e-9, "{tb:?}");
    }

    #[test]
    fn multiple_curves_on_one_curve_or_none_find_nothing_and_bad_items_are_errors() {
        let one = curve(Line::new(p(0.0, 0.0, 0.0), p(1.0, 0.0, 0.0)));
        let r = NodeCall::new(&multiple_curves_node()).input(one).run();
        assert_clean(&r);
        assert!(r.outputs[0].values().next().is_none());
        let r = NodeCall::new(&multiple_curves_node())
            .input(DataTree::from_item(Value::Number(1.0)))
            .run();
        assert_error(&r, "invalid cast: Number → Curve");
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

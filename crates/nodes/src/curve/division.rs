//! Curve › Division: Divide Curve, Divide Length, Divide Distance and Shatter.

use locus_kernel::{Curve, KINK_ANGLE_TOLERANCE, MAX_DIVISIONS};
use locus_runtime::{DataType, NodeError, NodeRegistry, NodeType, Port, Shared, Solve, Value};

use super::{curve_input, finite_parameter, number_list};

/// Id of [`divide_curve`].
pub const DIVIDE_CURVE: &str = "curve.divide_curve";
/// Id of [`divide_length`].
pub const DIVIDE_LENGTH: &str = "curve.divide_length";
/// Id of [`shatter`].
pub const SHATTER: &str = "curve.shatter";
/// Id of [`divide_distance`].
pub const DIVIDE_DISTANCE: &str = "curve.divide_distance";

/// Registers the division nodes.
pub fn register(registry: &mut NodeRegistry) {
    for t in [
        divide_curve(),
        divide_length(),
        shatter(),
        divide_distance(),
    ] {
        registry.register(t);
    }
}

fn division(id: &str, name: &str, nickname: &str) -> NodeType {
    NodeType::new(id, name, nickname, "Curve").subcategory("Division")
}

/// Adds the Points, Tangents and Parameters list outputs of the divide nodes.
fn division_outputs(node: NodeType) -> NodeType {
    node.output(
        Port::new("Points", "P", DataType::Point)
            .doc("Division points.")
            .list(),
    )
    .output(
        Port::new("Tangents", "T", DataType::Vector)
            .doc("Unit tangents at the division points (null where undefined).")
            .list(),
    )
    .output(
        Port::new("Parameters", "t", DataType::Number)
            .doc("Curve parameters of the division points.")
            .list(),
    )
}

/// Writes the points, tangents and parameters at `ts` to outputs 0, 1 and 2.
fn set_division(s: &mut Solve<'_>, curve: &Curve, ts: Vec<f64>) {
    let points = ts.iter().map(|&t| curve.point_at(t)).collect();
    let tangents = ts
        .iter()
        .map(|&t| curve.tangent_at(t).map(Value::Vector))
        .collect();
    s.set_list(0, points);
    s.set_list_values(1, tangents);
    s.set_list(2, ts);
}

/// Divide Curve \[Divide\]: points dividing a curve into pieces of equal length.
pub fn divide_curve() -> NodeType {
    division_outputs(
        division(DIVIDE_CURVE, "Divide Curve", "Divide").description(
            "Divides a curve into a number of pieces of equal length: N + 1 points on an open \
         curve, N on a closed one (the seam is not repeated). With Kinks set, the curve's \
         corners (where its direction turns by more than one degree) are added to the division \
         points, in order.",
        ),
    )
    .gh_guid("2162e72e-72fc-4bf8-9459-d4d82fa8aa14")
    .input(Port::new("Curve", "C", DataType::Curve).doc("Curve to divide."))
    .input(
        Port::new("Count", "N", DataType::Integer)
            .doc("Number of segments, at least 1. Default 10.")
            .default_value(10i64),
    )
    .input(
        Port::new("Kinks", "K", DataType::Boolean)
            .doc("Also divide at the curve's kinks. Default false.")
            .default_value(false),
    )
    .solve(|s| {
        let curve = curve_input(s, 0)?;
        let count: i64 = *s.item(1)?;
        let kinks: bool = *s.item(2)?;
        if count < 1 {
            return Err(format!("count {count} is below 1 segment").into());
        }
        let count = match usize::try_from(count) {
            Ok(n) if n <= MAX_DIVISIONS => n,
            _ => return Err(format!("count {count} is more than {MAX_DIVISIONS}").into()),
        };
        let mut ts = curve.divide_by_count(count)?;
        if kinks {
            ts = with_kinks(&curve, ts)?;
        }
        set_division(s, &curve, ts);
        Ok(())
    })
}

/// The parameters `ts` (increasing) with the curve's kinks merged in, repeats left out.
fn with_kinks(curve: &Curve, ts: Vec<f64>) -> Result<Vec<f64>, NodeError> {
    let kinks = curve.kinks(KINK_ANGLE_TOLERANCE)?;
    let d = curve.domain();
    let slack = 1e-9 * d.length();
    let mut all = ts;
    all.extend(kinks);
    all.sort_by(f64::total_cmp);
    all.dedup_by(|b, a| *b - *a <= slack);
    Ok(all)
}

/// Divide Length \[DivLength\]: points at a fixed length along a curve.
pub fn divide_length() -> NodeType {
    division_outputs(
        division(DIVIDE_LENGTH, "Divide Length", "DivLength").description(
            "Divides a curve into pieces of a given length, measured along the curve from its \
             start: points at 0, L, 2L, … The end is included only when L divides the curve's \
             length exactly (and never repeated on a closed curve); the last piece is the \
             remainder.",
        ),
    )
    .gh_guid("fdc466a9-d3b8-4056-852a-09dba0f74aca")
    .input(Port::new("Curve", "C", DataType::Curve).doc("Curve to divide."))
    .input(
        Port::new("Length", "L", DataType::Number)
            .doc("Length of the pieces, in model units, positive."),
    )
    .solve(|s| {
        let curve = curve_input(s, 0)?;
        let length = finite_parameter(*s.item::<f64>(1)?, "L")?;
        let ts = curve.divide_by_length(length)?;
        set_division(s, &curve, ts);
        Ok(())
    })
}

/// Divide Distance \[DivDist\]: points a fixed straight-line distance apart along a curve.
pub fn divide_distance() -> NodeType {
    division_outputs(
        division(DIVIDE_DISTANCE, "Divide Distance", "DivDist").description(
            "Divides a curve into points a fixed distance apart in straight lines (chords), \
             from its start: each point is where the curve, going on from the previous one, \
             first gets that far from it. The division stops where the rest of the curve \
             stays closer than the distance, so the end is included only when it falls \
             exactly on a step.",
        ),
    )
    .gh_guid("1e531c08-9c80-46d6-8850-1b50d1dae69f")
    .input(Port::new("Curve", "C", DataType::Curve).doc("Curve to divide."))
    .input(
        Port::new("Distance", "D", DataType::Number)
            .doc("Straight-line distance between points, positive."),
    )
    .solve(|s| {
        let curve = curve_input(s, 0)?;
        let distance = finite_parameter(*s.item::<f64>(1)?, "D")?;
        let ts = curve.divide_equidistant(distance)?;
        set_division(s, &curve, ts);
        Ok(())
    })
}

/// Shatter \[Shatter\]: the pieces of a curve between parameters.
pub fn shatter() -> NodeType {
    division(SHATTER, "Shatter", "Shatter")
        .gh_guid("2ad2a4d4-3de1-42f6-a4b8-f71835f35710")
        .description(
            "Cuts a curve at a list of parameters into pieces, in order. Parameters are sorted; \
             those not strictly inside the domain and repeats are ignored; if all are ignored \
             the whole curve is the one piece. On an open curve k cuts give k + 1 pieces. On a \
             closed curve the seam is not a cut: k cuts give k pieces, the last one running \
             from the last cut across the seam to the first (its domain continues past the \
             end). Pieces keep their parameters, and the kind of their curve where possible \
             (pieces of lines are lines, of circles and arcs arcs, of polylines polylines when cut at
             vertices).",
        )
        .input(Port::new("Curve", "C", DataType::Curve).doc("Curve to cut."))
        .input(
            Port::new("Parameters", "t", DataType::Number)
                .doc("Parameters to cut at, on the curve's domain. Nulls are left out.")
                .list(),
        )
        .output(
            Port::new("Segments", "S", DataType::Curve)
                .doc("The pieces, in order along the curve.")
                .list(),
        )
        .solve(|s| {
            let curve = curve_input(s, 0)?;
            let ts = number_list(s, 1)?;
            let pieces = curve.split_at_parameters(&ts)?;
            s.set_list(0, pieces.into_iter().map(Shared::new).collect());
            Ok(())
        })
}

#[cfg(test)]
mod tests {
    use std::f64::consts::PI;

    use locus_kernel::{Circle, Interval, Line, NurbsCurve, Plane, Point3, Polyline, Vector3};
    use locus_runtime::{DataTree, Level, NodeCall};

    use super::*;
    use crate::curve::test_support::*;

    fn rectangle() -> Curve {
        Polyline::new(vec![
            Point3::new(0.0, 0.0, 0.0),
            Point3::new(3.0, 0.0, 0.0),
            Point3::new(3.0, 2.0, 0.0),
            Point3::new(0.0, 2.0, 0.0),
            Point3::new(0.0, 0.0, 0.0),
        ])
        .unwrap()
        .into()
    }

    #[test]
    fn divide_curve_open_and_closed() {
        let r = NodeCall::new(&divide_curve())
            .input(curve_tree(Line::new(
                Point3::ORIGIN,
                Point3::new(10.0, 0.0, 0.0),
            )))
            .input(DataTree::from_item(4i64))
            .run();
        assert_eq!(numbers(&r.outputs[2]), vec![0.0, 2.5, 5.0, 7.5, 10.0]);
        assert_eq!(points(&r.outputs[0])[1], Point3::new(2.5, 0.0, 0.0));
        assert!(vectors(&r.outputs[1]).iter().all(|t| *t == Vector3::X));
        // A closed curve: the seam is not repeated.
        let r = NodeCall::new(&divide_curve())
            .input(curve_tree(Circle::new(Plane::WORLD_XY, 1.0).unwrap()))
            .input(DataTree::from_item(4i64))
            .run();
        let t = numbers(&r.outputs[2]);
        assert_eq!(t.len(), 4);
        for (k, t) in t.iter().enumerate() {
            assert!((t - k as f64 * PI / 2.0).abs() < 1e-14);
        }
    }

    #[test]
    fn divide_curve_default_count_is_ten() {
        let r = NodeCall::new(&divide_curve())
            .input(curve_tree(rectangle()))
            .run();
        assert_eq!(points(&r.outputs[0]).len(), 10);
    }

    #[test]
    fn divide_curve_equal_arc_lengths_on_nurbs() {
        let curve: Curve = NurbsCurve::create(
            &[
                Point3::new(0.0, 0.0, 0.0),
                Point3::new(1.0, 3.0, 0.0),
                Point3::new(3.0, 4.0, 1.0),
                Point3::new(5.0, 2.0, 0.0),
                Point3::new(7.0, 5.0, 2.0),
            ],
            3,
            false,
        )
        .unwrap()
        .into();
        let r = NodeCall::new(&divide_curve())
            .input(curve_tree(curve.clone()))
            .input(DataTree::from_item(7i64))
            .run();
        let t = numbers(&r.outputs[2]);
        let piece = curve.length() / 7.0;
        for w in t.windows(2) {
            let l = curve.length_between(w[0], w[1]).unwrap();
            assert!((l - piece).abs() < 1e-9 * piece);
        }
    }

    #[test]
    fn divide_curve_with_kinks() {
        let r = NodeCall::new(&divide_curve())
            .input(curve_tree(rectangle()))
            .input(DataTree::from_item(4i64))
            .input(DataTree::from_item(true))
            .run();
        // Perimeter 10: divisions at lengths 0, 2.5, 5 and 7.5, and the corners at vertices 1, 2
        // and 3 (lengths 3, 5 and 8; the one at 5 is already a division point).
        let t = numbers(&r.outputs[2]);
        let want = [0.0, 2.5 / 3.0, 1.0, 2.0, 2.0 + 2.5 / 3.0, 3.0];
        assert_eq!(t.len(), want.len(), "{t:?}");
        for (a, b) in t.iter().zip(want) {
            assert!((a - b).abs() < 1e-12, "{t:?}");
        }
    }

    #[test]
    fn divide_curve_bad_count() {
        for bad in [0i64, -3] {
            let r = NodeCall::new(&divide_curve())
                .input(curve_tree(rectangle()))
                .input(DataTree::from_item(bad))
                .run();
            assert!(single_error(&r).contains("below 1"));
            assert!(points(&r.outputs[0]).is_empty());
        }
    }

    #[test]
    fn divide_length_steps_along_the_curve() {
        let r = NodeCall::new(&divide_length())
            .input(curve_tree(rectangle()))
            .input(DataTree::from_list(vec![2.5, 4.0, 0.0, -1.0, f64::NAN]))
            .run();
        // 2.5 divides the perimeter 10 exactly; the closed curve does not repeat its seam.
        let branches = r.outputs[0].branches();
        assert_eq!(branches.len(), 5);
        assert_eq!(branches[0].1.len(), 4);
        assert_eq!(branches[1].1.len(), 3);
        assert_eq!(
            branches[1].1.value(2),
            Some(Value::Point(Point3::new(0.0, 2.0, 0.0)))
        );
        assert_eq!(messages(&r, Level::Error).len(), 3);
    }

    #[test]
    fn divisions_past_the_limit_are_errors_not_allocations() {
        // A tiny length (and a huge count) would ask for more points than memory holds.
        let r = NodeCall::new(&divide_length())
            .input(curve_tree(rectangle()))
            .input(DataTree::from_list(vec![1e-300, f64::MIN_POSITIVE]))
            .run();
        let errors = messages(&r, Level::Error);
        assert_eq!(errors.len(), 2, "{errors:?}");
        assert!(
            errors[0].contains("more than 10000000 pieces"),
            "{errors:?}"
        );
        let r = NodeCall::new(&divide_curve())
            .input(curve_tree(rectangle()))
            .input(DataTree::from_list(vec![i64::MAX, 10_000_001]))
            .run();
        let errors = messages(&r, Level::Error);
        assert_eq!(errors.len(), 2, "{errors:?}");
        assert!(errors[1].contains("more than 10000000"), "{errors:?}");
    }

    #[test]
    fn shatter_open_and_closed() {
        let line: Curve = Line::new(Point3::ORIGIN, Point3::new(10.0, 0.0, 0.0)).into();
        let r = NodeCall::new(&shatter())
            .input(curve_tree(line))
            .input(DataTree::from_list(vec![7.0, 2.0, 12.0]))
            .run();
        let pieces = curves(&r.outputs[0]);
        let domains: Vec<Interval> = pieces.iter().map(|c| c.domain()).collect();
        assert_eq!(
            domains,
            vec![
                Interval::new(0.0, 2.0),
                Interval::new(2.0, 7.0),
                Interval::new(7.0, 10.0)
            ]
        );
        assert!(pieces.iter().all(|c| matches!(**c, Curve::Line { .. })));
        assert_eq!(pieces[1].start_point(), Point3::new(2.0, 0.0, 0.0));

        let r = NodeCall::new(&shatter())
            .input(curve_tree(rectangle()))
            .input(DataTree::from_list(vec![1.0, 3.0]))
            .run();
        let pieces = curves(&r.outputs[0]);
        assert_eq!(pieces.len(), 2);
        // From vertex 1 to vertex 3, and from vertex 3 across the seam back to vertex 1.
        assert_eq!(pieces[0].length(), 5.0);
        assert_eq!(pieces[1].length(), 5.0);
        assert_eq!(pieces[1].domain(), Interval::new(3.0, 5.0));
        assert_eq!(pieces[1].end_point(), Point3::new(3.0, 0.0, 0.0));
    }

    #[test]
    fn shatter_bad_parameters() {
        let r = NodeCall::new(&shatter())
            .input(curve_tree(rectangle()))
            .input(DataTree::from_list(vec![1.0, f64::NAN]))
            .run();
        assert!(single_error(&r).contains("not finite"));
        // Parameters only at the ends give the whole curve back.
        let r = NodeCall::new(&shatter())
            .input(curve_tree(rectangle()))
            .input(DataTree::from_list(vec![0.0, 4.0]))
            .run();
        assert_eq!(*curves(&r.outputs[0])[0], rectangle());
    }

    #[test]
    fn divide_distance_on_a_circle() {
        let circle = Circle::new(Plane::WORLD_XY, 2.0).unwrap();
        let r = NodeCall::new(&divide_distance())
            .input(curve_tree(circle))
            .input(DataTree::from_item(2.0))
            .run();
        let pts = points(&r.outputs[0]);
        assert_eq!(pts.len(), 6);
        assert!(close(pts[1], Point3::new(1.0, 3f64.sqrt(), 0.0), 1e-12));
        let r = NodeCall::new(&divide_distance())
            .input(curve_tree(circle))
            .input(DataTree::from_item(-1.0))
            .run();
        assert_error(&r, "not positive");
    }
}

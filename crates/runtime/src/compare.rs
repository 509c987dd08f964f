//! Comparing data trees with a tolerance, for regression tests (`locus test`) and hosts.

use locus_kernel::{NurbsCurve, Plane, Point3, Vector3};

use crate::file::expected::{BrepSummary, ExpectedItem, ExpectedTree};
use crate::{DataTree, Value, format_value};

/// The default relative tolerance of [`compare_trees`]: 1e-9, the agreement the kernel keeps
/// with openNURBS. Numbers `a` and `b` agree when `|a − b| ≤ tolerance · max(1, |a|, |b|)`.
pub const COMPARE_TOLERANCE: f64 = 1e-9;

/// The differences between an actual and an expected tree, as readable lines
/// (`{0;1}[2]: expected 0.5, got 0.5000001`); empty when they agree.
///
/// Paths and item counts must match exactly; numbers and the coordinates of geometry agree
/// within `tolerance` (relative, see [`COMPARE_TOLERANCE`]); integers, booleans and text exactly.
/// At most `max_lines` differences are listed, then a count of the rest.
pub fn compare_trees(
    actual: &DataTree,
    expected: &DataTree,
    tolerance: f64,
    max_lines: usize,
) -> Vec<String> {
    let expected = ExpectedTree {
        branches: expected
            .branches()
            .iter()
            .map(|(path, b)| {
                (
                    path.clone(),
                    b.values().map(|v| v.map(ExpectedItem::Value)).collect(),
                )
            })
            .collect(),
    };
    compare_expected(actual, &expected, tolerance, max_lines)
}

/// The differences between an actual tree and an expected one as `locus test` reads it
/// ([`ExpectedTree`]: values, and B-reps by their [`BrepSummary`](crate::BrepSummary)), as
/// [`compare_trees`] lists them; a B-rep's differences name the summary's fields
/// (`{0}[2]: faces: expected 6, got 5`).
pub fn compare_expected(
    actual: &DataTree,
    expected: &ExpectedTree,
    tolerance: f64,
    max_lines: usize,
) -> Vec<String> {
    let mut out = Vec::new();
    let mut more = 0usize;
    let mut push = |line: String, out: &mut Vec<String>| {
        if out.len() < max_lines {
            out.push(line);
        } else {
            more += 1;
        }
    };
    let actual_paths: Vec<String> = actual.paths().map(ToString::to_string).collect();
    let expected_paths: Vec<String> = expected
        .branches
        .iter()
        .map(|(p, _)| p.to_string())
        .collect();
    if actual_paths != expected_paths {
        push(
            format!(
                "branches differ: expected {}, got {}",
                summarize(&expected_paths),
                summarize(&actual_paths)
            ),
            &mut out,
        );
        return out;
    }
    for ((path, a), (_, e)) in actual.branches().iter().zip(&expected.branches) {
        if a.len() != e.len() {
            push(
                format!("{path}: expected {} items, got {}", e.len(), a.len()),
                &mut out,
            );
            continue;
        }
        for (i, (av, ev)) in a.values().zip(e).enumerate() {
            match (&av, ev) {
                (None, None) => {}
                (Some(Value::Brep(b)), Some(ExpectedItem::Brep(want))) => {
                    for d in BrepSummary::of(b).differences(want) {
                        push(format!("{path}[{i}]: {d}"), &mut out);
                    }
                }
                (Some(x), Some(ExpectedItem::Value(y))) if values_agree(x, y, tolerance) => {}
                (Some(x), Some(ExpectedItem::Value(y))) => {
                    let detail = first_difference(x, y, tolerance)
                        .map(|d| format!(" ({d})"))
                        .unwrap_or_default();
                    push(
                        format!(
                            "{path}[{i}]: expected {}, got {}{detail}",
                            show(Some(y)),
                            show(Some(x))
                        ),
                        &mut out,
                    );
                }
                (av, ev) => {
                    let want = match ev {
                        None => "null".to_owned(),
                        Some(ExpectedItem::Value(v)) => show(Some(v)),
                        Some(ExpectedItem::Brep(_)) => "a Brep".to_owned(),
                    };
                    push(
                        format!("{path}[{i}]: expected {want}, got {}", show(av.as_ref())),
                        &mut out,
                    );
                }
            }
        }
    }
    if more > 0 {
        out.push(format!("… and {more} more differences"));
    }
    out
}

fn summarize(paths: &[String]) -> String {
    if paths.is_empty() {
        return "no branches".to_owned();
    }
    let shown: Vec<&str> = paths.iter().take(6).map(String::as_str).collect();
    let tail = if paths.len() > 6 {
        format!(" … ({} in all)", paths.len())
    } else {
        String::new()
    };
    format!("{}{tail}", shown.join(" "))
}

fn show(v: Option<&Value>) -> String {
    match v {
        None => "null".to_owned(),
        Some(Value::Text(t)) => format!("{t:?}"),
        Some(Value::Brep(b)) => {
            let s = BrepSummary::of(b);
            format!(
                "Brep ({} faces, {} edges, {} vertices)",
                s.faces, s.edges, s.vertices
            )
        }
        Some(v) => format!("{} {}", v.data_type(), format_value(v)),
    }
}

fn near(a: f64, b: f64, tolerance: f64) -> bool {
    if a == b || (a.is_nan() && b.is_nan()) {
        return true;
    }
    (a - b).abs() <= tolerance * 1f64.max(a.abs()).max(b.abs())
}

fn all_near(a: &[f64], b: &[f64], tolerance: f64) -> bool {
    a.len() == b.len() && a.iter().zip(b).all(|(&x, &y)| near(x, y, tolerance))
}

fn point_near(a: Point3, b: Point3, tolerance: f64) -> bool {
    all_near(&a.to_array(), &b.to_array(), tolerance)
}

fn vector_near(a: Vector3, b: Vector3, tolerance: f64) -> bool {
    all_near(&a.to_array(), &b.to_array(), tolerance)
}

fn plane_near(a: &Plane, b: &Plane, tolerance: f64) -> bool {
    point_near(a.origin, b.origin, tolerance)
        && vector_near(a.x_axis, b.x_axis, tolerance)
        && vector_near(a.y_axis, b.y_axis, tolerance)
        && vector_near(a.z_axis, b.z_axis, tolerance)
}

fn nurbs_near(a: &NurbsCurve, b: &NurbsCurve, tolerance: f64) -> bool {
    a.degree() == b.degree()
        && a.points().len() == b.points().len()
        && a.points()
            .iter()
            .zip(b.points())
            .all(|(p, q)| point_near(*p, *q, tolerance))
        && all_near(a.weights(), b.weights(), tolerance)
        && all_near(a.knots(), b.knots(), tolerance)
}

/// Where two curves or surfaces that print alike first differ (`control point 3: expected …,
/// got …`); `None` for other values, whose printed forms already show the difference.
fn first_difference(actual: &Value, expected: &Value, tolerance: f64) -> Option<String> {
    fn points(what: &str, a: &[Point3], e: &[Point3], tolerance: f64) -> Option<String> {
        if a.len() != e.len() {
            return Some(format!("{} {what}s expected, got {}", e.len(), a.len()));
        }
        let i = a
            .iter()
            .zip(e)
            .position(|(p, q)| !point_near(*p, *q, tolerance))?;
        Some(format!(
            "{what} {i}: expected {}, got {}",
            format_value(&Value::Point(e[i])),
            format_value(&Value::Point(a[i]))
        ))
    }
    fn numbers(what: &str, a: &[f64], e: &[f64], tolerance: f64) -> Option<String> {
        if a.len() != e.len() {
            return Some(format!("{} {what}s expected, got {}", e.len(), a.len()));
        }
        let i = a
            .iter()
            .zip(e)
            .position(|(x, y)| !near(*x, *y, tolerance))?;
        Some(format!("{what} {i}: expected {}, got {}", e[i], a[i]))
    }
    match (actual, expected) {
        (Value::Curve(a), Value::Curve(e)) => {
            let (a, e) = (a.to_nurbs(), e.to_nurbs());
            if a.degree() != e.degree() {
                return Some(format!(
                    "degree {} expected, got {}",
                    e.degree(),
                    a.degree()
                ));
            }
            points("control point", a.points(), e.points(), tolerance)
                .or_else(|| numbers("weight", a.weights(), e.weights(), tolerance))
                .or_else(|| numbers("knot", a.knots(), e.knots(), tolerance))
        }
        (Value::Surface(a), Value::Surface(e)) => {
            if (a.degree_u(), a.degree_v()) != (e.degree_u(), e.degree_v()) {
                return Some(format!(
                    "degrees {}×{} expected, got {}×{}",
                    e.degree_u(),
                    e.degree_v(),
                    a.degree_u(),
                    a.degree_v()
                ));
            }
            points("control point", a.points(), e.points(), tolerance)
                .or_else(|| numbers("weight", a.weights(), e.weights(), tolerance))
                .or_else(|| numbers("u knot", a.knots_u(), e.knots_u(), tolerance))
                .or_else(|| numbers("v knot", a.knots_v(), e.knots_v(), tolerance))
        }
        _ => None,
    }
}

/// Whether two values agree within `tolerance` (see [`compare_trees`]). Values of different
/// types never agree, except numbers and integers of equal value.
pub fn values_agree(a: &Value, b: &Value, tolerance: f64) -> bool {
    match (a, b) {
        (Value::Number(x), Value::Number(y)) => near(*x, *y, tolerance),
        (Value::Number(x), Value::Integer(i)) | (Value::Integer(i), Value::Number(x)) => {
            near(*x, *i as f64, tolerance)
        }
        (Value::Point(p), Value::Point(q)) => point_near(*p, *q, tolerance),
        (Value::Vector(p), Value::Vector(q)) => vector_near(*p, *q, tolerance),
        (Value::Plane(p), Value::Plane(q)) => plane_near(p, q, tolerance),
        (Value::Domain(p), Value::Domain(q)) => all_near(&[p.t0, p.t1], &[q.t0, q.t1], tolerance),
        (Value::Transform(p), Value::Transform(q)) => all_near(
            p.to_rows().as_flattened(),
            q.to_rows().as_flattened(),
            tolerance,
        ),
        (Value::Box(p), Value::Box(q)) => {
            plane_near(&p.plane, &q.plane, tolerance)
                && all_near(
                    &[p.x.t0, p.x.t1, p.y.t0, p.y.t1, p.z.t0, p.z.t1],
                    &[q.x.t0, q.x.t1, q.y.t0, q.y.t1, q.z.t0, q.z.t1],
                    tolerance,
                )
        }
        (Value::Line(p), Value::Line(q)) => {
            point_near(p.from, q.from, tolerance) && point_near(p.to, q.to, tolerance)
        }
        (Value::Circle(p), Value::Circle(q)) => {
            plane_near(&p.plane, &q.plane, tolerance) && near(p.radius, q.radius, tolerance)
        }
        (Value::Arc(p), Value::Arc(q)) => {
            plane_near(&p.circle.plane, &q.circle.plane, tolerance)
                && all_near(
                    &[p.circle.radius, p.angle.t0, p.angle.t1],
                    &[q.circle.radius, q.angle.t0, q.angle.t1],
                    tolerance,
                )
        }
        (Value::Curve(p), Value::Curve(q)) => {
            let (dp, dq) = (p.domain(), q.domain());
            all_near(&[dp.t0, dp.t1], &[dq.t0, dq.t1], tolerance)
                && nurbs_near(&p.to_nurbs(), &q.to_nurbs(), tolerance)
        }
        (Value::Surface(p), Value::Surface(q)) => {
            p.count_u() == q.count_u()
                && p.count_v() == q.count_v()
                && p.degree_u() == q.degree_u()
                && p.degree_v() == q.degree_v()
                && p.points()
                    .iter()
                    .zip(q.points())
                    .all(|(a, b)| point_near(*a, *b, tolerance))
                && all_near(p.weights(), q.weights(), tolerance)
                && all_near(p.knots_u(), q.knots_u(), tolerance)
                && all_near(p.knots_v(), q.knots_v(), tolerance)
        }
        (x, y) => x == y,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_agree_within_the_relative_tolerance() {
        let a = DataTree::from_list(vec![1.0, 1e6]);
        let b = DataTree::from_list(vec![1.0 + 1e-12, 1e6 + 1e-4]);
        assert!(compare_trees(&a, &b, COMPARE_TOLERANCE, 10).is_empty());
        let c = DataTree::from_list(vec![1.0, 1e6 + 1.0]);
        assert_eq!(
            compare_trees(&a, &c, COMPARE_TOLERANCE, 10),
            ["{0}[1]: expected Number 1000001, got Number 1000000"]
        );
    }

    #[test]
    fn different_structure_is_reported_once() {
        let a = DataTree::from_list(vec![1.0]);
        let mut b = DataTree::new();
        b.insert(
            crate::TreePath::from([0, 0]),
            crate::Branch::from_items(vec![1.0]),
        );
        assert_eq!(
            compare_trees(&a, &b, COMPARE_TOLERANCE, 10),
            ["branches differ: expected {0;0}, got {0}"]
        );
    }

    #[test]
    fn curves_that_print_alike_name_their_first_difference() {
        let curve = |y: f64| {
            let points = [
                Point3::ORIGIN,
                Point3::new(1.0, y, 0.0),
                Point3::new(2.0, 0.0, 0.0),
            ];
            let c = NurbsCurve::create(&points, 2, false).expect("a curve");
            DataTree::from_item(crate::Shared::new(locus_kernel::Curve::from(c)))
        };
        let lines = compare_trees(&curve(1.0), &curve(1.5), COMPARE_TOLERANCE, 10);
        assert_eq!(lines.len(), 1);
        assert!(
            lines[0].ends_with("(control point 1: expected {1, 1.5, 0}, got {1, 1, 0})"),
            "{lines:?}"
        );
        assert!(compare_trees(&curve(1.0), &curve(1.0), COMPARE_TOLERANCE, 10).is_empty());
    }
}

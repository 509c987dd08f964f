//! Comparing data trees with a tolerance, for regression tests (`locus test`) and hosts.

use locus_kernel::{NurbsCurve, Plane, Point3, Vector3};

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
    let expected_paths: Vec<String> = expected.paths().map(ToString::to_string).collect();
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
    for ((path, a), (_, e)) in actual.branches().iter().zip(expected.branches()) {
        if a.len() != e.len() {
            push(
                format!("{path}: expected {} items, got {}", e.len(), a.len()),
                &mut out,
            );
            continue;
        }
        for (i, (av, ev)) in a.values().zip(e.values()).enumerate() {
            let same = match (&av, &ev) {
                (None, None) => true,
                (Some(x), Some(y)) => values_agree(x, y, tolerance),
                _ => false,
            };
            if !same {
                push(
                    format!(
                        "{path}[{i}]: expected {}, got {}",
                        show(ev.as_ref()),
                        show(av.as_ref())
                    ),
                    &mut out,
                );
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
}

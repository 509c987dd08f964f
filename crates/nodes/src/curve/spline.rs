//! Curve › Spline: PolyLine, Bézier Span, NURBS curves from control points (with or without
//! weights and knots), Interpolate and Knot Vector.

use locus_kernel::{Bezier, Curve, NurbsCurve, Point3, Polyline, Vector3};
use locus_runtime::{DataType, NodeRegistry, NodeType, Port, Shared};

use super::{degree_from, knot_style_from, number_list, point_list, set_curve_length_domain};
use crate::maths::sequence::MAX_SEQUENCE_LENGTH;

/// Id of [`polyline`].
pub const POLYLINE: &str = "curve.polyline";
/// Id of [`bezier_span`].
pub const BEZIER_SPAN: &str = "curve.bezier_span";
/// Id of [`nurbs_curve`].
pub const NURBS_CURVE: &str = "curve.nurbs_curve";
/// Id of [`nurbs_curve_pwk`].
pub const NURBS_CURVE_PWK: &str = "curve.nurbs_curve_pwk";
/// Id of [`interpolate`].
pub const INTERPOLATE: &str = "curve.interpolate";
/// Id of [`knot_vector`].
pub const KNOT_VECTOR: &str = "curve.knot_vector";

/// Registers the spline nodes.
pub fn register(registry: &mut NodeRegistry) {
    for t in [
        polyline(),
        bezier_span(),
        nurbs_curve(),
        nurbs_curve_pwk(),
        interpolate(),
        knot_vector(),
    ] {
        registry.register(t);
    }
}

fn spline(id: &str, name: &str, nickname: &str) -> NodeType {
    NodeType::new(id, name, nickname, "Curve").subcategory("Spline")
}

fn curve_length_domain_outputs(node: NodeType, what: &str) -> NodeType {
    node.output(Port::new("Curve", "C", DataType::Curve).doc(what))
        .output(Port::new("Length", "L", DataType::Number).doc("Length of the curve."))
        .output(Port::new("Domain", "D", DataType::Domain).doc("Domain of the curve."))
}

/// PolyLine \[PLine\]: the polyline through points.
pub fn polyline() -> NodeType {
    spline(POLYLINE, "PolyLine", "PLine")
        .gh_guid("71b5b089-500a-4ea6-81c5-2f960441a0e8")
        .description(
            "Creates the polyline through a list of vertices. When closed, the first vertex is \
             added again at the end (unless the list already ends there). The domain is 0 to the \
             number of segments: vertex i sits at parameter i.",
        )
        .input(
            Port::new("Vertices", "V", DataType::Point)
                .doc("Polyline vertices, in order; at least 2 (3 when closed). Nulls are left out.")
                .list(),
        )
        .input(
            Port::new("Closed", "C", DataType::Boolean)
                .doc("Close the polyline back to its first vertex. Default false.")
                .default_value(false),
        )
        .output(Port::new("Polyline", "Pl", DataType::Curve).doc("The polyline."))
        .solve(|s| {
            let mut points = point_list(s, 0)?;
            let closed: bool = *s.item(1)?;
            if closed {
                let open_count = match (points.first(), points.last()) {
                    (Some(a), Some(b)) if a == b => points.len() - 1,
                    _ => points.len(),
                };
                if open_count < 3 {
                    return Err(format!(
                        "a closed polyline needs at least 3 vertices, got {open_count}"
                    )
                    .into());
                }
                if open_count == points.len() {
                    points.push(points[0]);
                }
            }
            let polyline = Polyline::new(points)?;
            s.set(0, Shared::new(Curve::from(polyline)));
            Ok(())
        })
}

/// Bezier Span \[BzSpan\]: the cubic Bézier curve from two end points and their handles.
pub fn bezier_span() -> NodeType {
    curve_length_domain_outputs(
        spline(BEZIER_SPAN, "Bezier Span", "BzSpan").description(
            "Creates the cubic Bézier span with control points A, A + At, B + Bt and B, as \
             Grasshopper does: the tangent vectors are the handles at each end, at full length. \
             The span leaves A in the direction of At (with derivative 3·At) and arrives at B \
             travelling against Bt (derivative −3·Bt). Its domain is 0 to 1; points on it are \
             those of de Casteljau's construction.",
        ),
        "The Bézier span, as a degree-3 NURBS curve.",
    )
    .input(Port::new("Start point", "A", DataType::Point).doc("Start of the curve."))
    .input(
        Port::new("Start tangent", "At", DataType::Vector)
            .doc("Handle at the start: the second control point is A + At."),
    )
    .input(Port::new("End point", "B", DataType::Point).doc("End of the curve."))
    .input(
        Port::new("End tangent", "Bt", DataType::Vector)
            .doc("Handle at the end: the third control point is B + Bt."),
    )
    .solve(|s| {
        let a: Point3 = *s.item(0)?;
        let at: Vector3 = *s.item(1)?;
        let b: Point3 = *s.item(2)?;
        let bt: Vector3 = *s.item(3)?;
        let bezier = Bezier::new(vec![a, a + at, b + bt, b])?;
        let curve = Curve::from(bezier);
        if curve.length() == 0.0 {
            return Err("the span collapses to a single point".into());
        }
        set_curve_length_domain(s, 0, curve);
        Ok(())
    })
}

/// Nurbs Curve \[Nurbs\]: the curve with given control points, as Rhino builds it.
pub fn nurbs_curve() -> NodeType {
    curve_length_domain_outputs(
        spline(NURBS_CURVE, "Nurbs Curve", "Nurbs").description(
            "Creates the NURBS curve whose control points are the vertices, with uniform knots \
             of spacing 1, as Rhino's Curve command. An open curve is clamped: it starts at the \
             first vertex and ends at the last. A periodic curve is closed and smooth: the first \
             `degree` vertices are repeated at the end, the knots run uniformly past both ends, \
             and the domain is 0 to the number of vertices (a last vertex equal to the first is \
             ignored). A degree above what the vertices allow is lowered (to one less than the \
             number of vertices when open, to that number when periodic), with a remark.",
        ),
        "The NURBS curve.",
    )
    .gh_guid("dde71aef-d6ed-40a6-af98-6b0673983c82")
    .input(
        Port::new("Vertices", "V", DataType::Point)
            .doc("Control points; at least 2 (3 for a periodic curve). Nulls are left out.")
            .list(),
    )
    .input(
        Port::new("Degree", "D", DataType::Integer)
            .doc("Curve degree, from 1 to 15. Default 3.")
            .default_value(3i64),
    )
    .input(
        Port::new("Periodic", "P", DataType::Boolean)
            .doc("Make a closed, periodic curve. Default false.")
            .default_value(false),
    )
    .solve(|s| {
        let points = point_list(s, 0)?;
        let mut degree = degree_from(*s.item::<i64>(1)?)?;
        let periodic: bool = *s.item(2)?;
        let distinct = match (points.first(), points.last()) {
            (Some(a), Some(b)) if periodic && points.len() > 1 && a == b => points.len() - 1,
            _ => points.len(),
        };
        let fit = if periodic {
            distinct
        } else {
            distinct.saturating_sub(1)
        };
        if fit >= 1 && degree > fit {
            s.remark(format!(
                "degree {degree} lowered to {fit} to fit {distinct} control points"
            ));
            degree = fit;
        }
        let curve = NurbsCurve::create(&points, degree, periodic)?;
        set_curve_length_domain(s, 0, curve.into());
        Ok(())
    })
}

/// Nurbs Curve PWK \[NurbCrv\]: a NURBS curve from control points, weights and knots.
pub fn nurbs_curve_pwk() -> NodeType {
    curve_length_domain_outputs(
        spline(NURBS_CURVE_PWK, "Nurbs Curve PWK", "NurbCrv").description(
            "Creates the NURBS curve with the given control points, weights and knots. The \
             knots are in Rhino's form, as Knot Vector and Control Points give them: one knot \
             fewer than control points plus degree, so the degree is |K| − |P| + 1 (there is \
             no degree input, as in Grasshopper). Weights must be positive; without weights \
             the curve is non-rational. Knots must not decrease, and no knot may repeat more \
             than the degree.",
        ),
        "The NURBS curve.",
    )
    .input(
        Port::new("Points", "P", DataType::Point)
            .doc("Control points; at least degree + 1. Nulls are left out.")
            .list(),
    )
    .input(
        Port::new("Weights", "W", DataType::Number)
            .doc("Control point weights, one per point, positive. Optional: all 1 when empty.")
            .list()
            .optional(),
    )
    .input(
        Port::new("Knots", "K", DataType::Number)
            .doc("Knot vector in Rhino's form: |P| + degree − 1 non-decreasing values.")
            .list(),
    )
    .solve(|s| {
        let points = point_list(s, 0)?;
        let mut weights = number_list(s, 1)?;
        let knots = number_list(s, 2)?;
        let (n, k) = (points.len(), knots.len());
        if k < n {
            return Err(format!(
                "{n} control points need at least {n} knots (|P| + degree − 1), got {k}"
            )
            .into());
        }
        let degree = degree_from((k + 1 - n) as i64)?;
        if weights.is_empty() {
            weights = vec![1.0; n];
        } else if weights.len() != n {
            return Err(format!("{} weights given for {n} control points", weights.len()).into());
        }
        let curve = NurbsCurve::new(degree, points, weights, knots)?;
        set_curve_length_domain(s, 0, curve.into());
        Ok(())
    })
}

/// Interpolate \[IntCrv\]: the curve through points.
pub fn interpolate() -> NodeType {
    curve_length_domain_outputs(
        spline(INTERPOLATE, "Interpolate", "IntCrv").description(
            "Creates the NURBS curve of odd degree through the vertices, as Rhino's InterpCrv: \
             the parameters of the vertices are spaced by the knot style (uniformly, by the \
             distance between them, or by its square root) and become the knots. An open curve \
             has natural end conditions (for a cubic, no second derivative at the ends); a \
             periodic curve closes smoothly back to the first vertex. The domain starts at 0 \
             and is as long as the sum of the spacings.",
        ),
        "The interpolated curve.",
    )
    .gh_guid("2b2a4145-3dff-41d4-a8de-1ea9d29eef33")
    .input(
        Port::new("Vertices", "V", DataType::Point)
            .doc(
                "Points to pass through, in order; at least 2 (3, and at least the degree, \
                 when periodic). Consecutive points must differ. Nulls are left out.",
            )
            .list(),
    )
    .input(
        Port::new("Degree", "D", DataType::Integer)
            .doc("Curve degree: odd, from 1 to 15. Default 3.")
            .default_value(3i64),
    )
    .input(
        Port::new("Periodic", "P", DataType::Boolean)
            .doc("Make a closed, periodic curve. Default false.")
            .default_value(false),
    )
    .input(
        Port::new("KnotStyle", "K", DataType::Integer)
            .doc("Knot spacing: 0 uniform, 1 chord length, 2 square root of chord length. Default 1.")
            .default_value(1i64),
    )
    .solve(|s| {
        let points = point_list(s, 0)?;
        let degree = degree_from(*s.item::<i64>(1)?)?;
        let periodic: bool = *s.item(2)?;
        let style = knot_style_from(*s.item::<i64>(3)?)?;
        let curve = if periodic {
            NurbsCurve::interpolate_periodic(&points, degree, style)?
        } else {
            NurbsCurve::interpolate(&points, degree, style)?
        };
        set_curve_length_domain(s, 0, curve.into());
        Ok(())
    })
}

/// The knots Grasshopper's Knot Vector gives: Rhino's form, spacing 1. Clamped:
/// `0 (×d), 1, 2, …, n − d (×d)`; periodic: `0, 1, …, n + d − 2`.
pub fn uniform_knots(count: usize, degree: usize, periodic: bool) -> Vec<f64> {
    if periodic {
        return (0..count + degree - 1).map(|i| i as f64).collect();
    }
    let spans = count - degree;
    let mut knots = Vec::with_capacity(count + degree - 1);
    knots.extend(std::iter::repeat_n(0.0, degree));
    knots.extend((1..spans).map(|i| i as f64));
    knots.extend(std::iter::repeat_n(spans as f64, degree));
    knots
}

/// Knot Vector \[Knots\]: a uniform knot vector for a number of control points.
pub fn knot_vector() -> NodeType {
    spline(KNOT_VECTOR, "Knot Vector", "Knots")
        .gh_guid("846470bd-4918-4d00-9388-7e022b2cba73")
        .description(
            "Creates a uniform knot vector (spacing 1) in Rhino's form, with |N| + degree − 1 \
             knots, ready for Nurbs Curve PWK. A clamped vector repeats its first and last knots \
             `degree` times, so the curve starts and ends at its end control points; a periodic \
             vector is the plain run 0, 1, …, N + D − 2. A degree above N − 1 is lowered to \
             N − 1, with a remark.",
        )
        .input(
            Port::new("Count", "N", DataType::Integer).doc("Number of control points, at least 2."),
        )
        .input(
            Port::new("Degree", "D", DataType::Integer)
                .doc("Curve degree, from 1 to 15. Default 3.")
                .default_value(3i64),
        )
        .input(
            Port::new("Periodic", "P", DataType::Boolean)
                .doc("Make a periodic (unclamped) knot vector. Default false.")
                .default_value(false),
        )
        .output(
            Port::new("Knots", "K", DataType::Number)
                .doc("The knots, non-decreasing.")
                .list(),
        )
        .solve(|s| {
            let count: i64 = *s.item(0)?;
            let mut degree = degree_from(*s.item::<i64>(1)?)?;
            let periodic: bool = *s.item(2)?;
            if count < 2 {
                return Err(format!("count {count} is below 2 control points").into());
            }
            let count = match usize::try_from(count) {
                Ok(n) if n <= MAX_SEQUENCE_LENGTH => n,
                _ => {
                    return Err(format!("count {count} is more than {MAX_SEQUENCE_LENGTH}").into());
                }
            };
            if degree > count - 1 {
                s.remark(format!(
                    "degree {degree} lowered to {} to fit {count} control points",
                    count - 1
                ));
                degree = count - 1;
            }
            s.set_list(0, uniform_knots(count, degree, periodic));
            Ok(())
        })
}

#[cfg(test)]
mod tests {
    use locus_kernel::Interval;
    use locus_runtime::{DataTree, Level, NodeCall};

    use super::*;
    use crate::curve::test_support::*;

    fn square() -> Vec<Point3> {
        vec![
            Point3::new(0.0, 0.0, 0.0),
            Point3::new(10.0, 0.0, 0.0),
            Point3::new(10.0, 10.0, 0.0),
            Point3::new(0.0, 10.0, 0.0),
        ]
    }

    fn nurbs(c: &Curve) -> &NurbsCurve {
        match c {
            Curve::Nurbs(n) => n,
            other => panic!("not a nurbs curve: {other:?}"),
        }
    }

    #[test]
    fn polyline_open_and_closed() {
        let r = NodeCall::new(&polyline())
            .input(DataTree::from_list(square()))
            .input(DataTree::from_list(vec![false, true]))
            .run();
        let c = curves(&r.outputs[0]);
        assert_eq!(c[0].domain(), Interval::new(0.0, 3.0));
        assert!(!c[0].is_closed());
        assert_eq!(c[1].domain(), Interval::new(0.0, 4.0));
        assert!(c[1].is_closed());
        assert_eq!(c[1].length(), 40.0);
        // A list that already ends at its start is not closed twice.
        let mut closed = square();
        closed.push(closed[0]);
        let r = NodeCall::new(&polyline())
            .input(DataTree::from_list(closed))
            .input(DataTree::from_item(true))
            .run();
        assert_eq!(curves(&r.outputs[0])[0].domain(), Interval::new(0.0, 4.0));
    }

    #[test]
    fn polyline_bad_input() {
        let r = NodeCall::new(&polyline())
            .input(DataTree::from_list(vec![Point3::ORIGIN]))
            .run();
        assert!(single_error(&r).contains("at least 2"));
        let r = NodeCall::new(&polyline())
            .input(DataTree::from_list(square()[..2].to_vec()))
            .input(DataTree::from_item(true))
            .run();
        assert!(single_error(&r).contains("at least 3"));
        let r = NodeCall::new(&polyline())
            .input(DataTree::from_list(vec![
                Point3::ORIGIN,
                Point3::new(f64::NAN, 1.0, 1.0),
            ]))
            .run();
        assert!(single_error(&r).contains("not finite"));
    }

    #[test]
    fn polyline_leaves_out_nulls_with_a_warning() {
        let mut tree = DataTree::from_list(square());
        let branch = tree
            .branch_mut(&locus_runtime::TreePath::zero())
            .expect("branch");
        branch.push_null();
        let r = NodeCall::new(&polyline()).input(tree).run();
        assert_eq!(curves(&r.outputs[0])[0].domain(), Interval::new(0.0, 3.0));
        assert_eq!(messages(&r, Level::Warning).len(), 1);
    }

    #[test]
    fn bezier_span_matches_de_casteljau() {
        // The book's de Casteljau construction on A, B, C, D at t.
        let (a, at, b, bt) = (
            Point3::new(0.0, 0.0, 0.0),
            Vector3::new(1.0, 3.0, 0.0),
            Point3::new(8.0, 0.0, 2.0),
            Vector3::new(-1.0, 4.0, 0.0),
        );
        let r = NodeCall::new(&bezier_span())
            .input(DataTree::from_item(a))
            .input(DataTree::from_item(at))
            .input(DataTree::from_item(b))
            .input(DataTree::from_item(bt))
            .run();
        let c = curves(&r.outputs[0])[0].clone();
        assert_eq!(domains(&r.outputs[2]), vec![Interval::UNIT]);
        let (pa, pb, pc, pd) = (a, a + at, b + bt, b);
        for t in [0.0, 0.25, 0.4, 0.5, 0.9, 1.0] {
            let m = pa.lerp(pb, t);
            let n = pb.lerp(pc, t);
            let o = pc.lerp(pd, t);
            let p = m.lerp(n, t);
            let q = n.lerp(o, t);
            let expected = p.lerp(q, t);
            assert!(close(c.point_at(t), expected, 1e-14), "t = {t}");
        }
        let d = c.derivatives_at(0.0, 1)[1];
        assert!((d - at * 3.0).length() < 1e-13);
        let d = c.derivatives_at(1.0, 1)[1];
        assert!((d + bt * 3.0).length() < 1e-13);
        assert!((numbers(&r.outputs[1])[0] - c.length()).abs() < 1e-15);
    }

    #[test]
    fn bezier_span_bad_input() {
        let r = NodeCall::new(&bezier_span())
            .input(DataTree::from_item(Point3::ORIGIN))
            .input(DataTree::from_item(Vector3::ZERO))
            .input(DataTree::from_item(Point3::ORIGIN))
            .input(DataTree::from_item(Vector3::ZERO))
            .run();
        assert!(single_error(&r).contains("single point"));
        let r = NodeCall::new(&bezier_span())
            .input(DataTree::from_item(Point3::ORIGIN))
            .input(DataTree::from_item(Vector3::new(f64::NAN, 0.0, 0.0)))
            .input(DataTree::from_item(Point3::new(1.0, 0.0, 0.0)))
            .input(DataTree::from_item(Vector3::ZERO))
            .run();
        assert!(single_error(&r).contains("not finite"));
    }

    #[test]
    fn nurbs_curve_open_and_periodic_as_rhino() {
        // The book's figure 41: the same points, clamped and periodic.
        let r = NodeCall::new(&nurbs_curve())
            .input(DataTree::from_list(square()))
            .skip_input()
            .input(DataTree::from_list(vec![false, true]))
            .run();
        let c = curves(&r.outputs[0]);
        let open = nurbs(&c[0]);
        assert_eq!(open.knots(), &[0.0, 0.0, 0.0, 1.0, 1.0, 1.0]);
        assert_eq!(open.start_point(), square()[0]);
        let periodic = nurbs(&c[1]);
        assert_eq!(periodic.point_count(), 7);
        assert_eq!(
            periodic.knots(),
            &[-2.0, -1.0, 0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0]
        );
        assert!(periodic.is_periodic());
        assert_eq!(
            domains(&r.outputs[2]),
            vec![Interval::new(0.0, 1.0), Interval::new(0.0, 4.0)]
        );
        let lengths = numbers(&r.outputs[1]);
        assert!((lengths[0] - c[0].length()).abs() < 1e-12);
    }

    #[test]
    fn nurbs_curve_degree_is_lowered_or_rejected() {
        let r = NodeCall::new(&nurbs_curve())
            .input(DataTree::from_list(square()[..3].to_vec()))
            .input(DataTree::from_item(5i64))
            .run();
        assert_eq!(nurbs(&curves(&r.outputs[0])[0]).degree(), 2);
        assert_eq!(messages(&r, Level::Remark).len(), 1);
        for bad in [0i64, -1, 16] {
            let r = NodeCall::new(&nurbs_curve())
                .input(DataTree::from_list(square()))
                .input(DataTree::from_item(bad))
                .run();
            assert!(single_error(&r).contains("degree"), "{bad}");
        }
        let r = NodeCall::new(&nurbs_curve())
            .input(DataTree::from_list(vec![Point3::ORIGIN]))
            .run();
        assert!(single_error(&r).contains("needs at least"));
        let r = NodeCall::new(&nurbs_curve())
            .input(DataTree::from_list(square()[..2].to_vec()))
            .skip_input()
            .input(DataTree::from_item(true))
            .run();
        assert!(single_error(&r).contains("needs at least"));
    }

    fn pwk(
        points: Vec<Point3>,
        weights: Vec<f64>,
        knots: Vec<f64>,
    ) -> locus_runtime::NodeCallResult {
        let w = if weights.is_empty() {
            DataTree::new()
        } else {
            DataTree::from_list(weights)
        };
        NodeCall::new(&nurbs_curve_pwk())
            .input(DataTree::from_list(points))
            .input(w)
            .input(DataTree::from_list(knots))
            .run()
    }

    fn book_points() -> Vec<Point3> {
        vec![
            Point3::new(0.0, 0.0, 0.0),
            Point3::new(1.0, 3.0, 0.0),
            Point3::new(3.0, 4.0, 1.0),
            Point3::new(5.0, 2.0, 0.0),
            Point3::new(7.0, 5.0, 2.0),
            Point3::new(9.0, 1.0, 0.0),
            Point3::new(10.0, 4.0, 1.0),
        ]
    }

    #[test]
    fn pwk_de_boor_at_0_4() {
        // The book's de Boor example (also the first openNURBS oracle curve).
        let r = pwk(
            book_points(),
            vec![],
            vec![0.0, 0.0, 0.0, 0.25, 0.5, 0.75, 1.0, 1.0, 1.0],
        );
        let c = curves(&r.outputs[0])[0].clone();
        assert_eq!(c.degree(), 3);
        let p = c.point_at(0.4);
        let expected = Point3::new(4.189333333333334, 2.942666666666667, 0.4813333333333334);
        assert!(close(p, expected, 1e-14), "{p:?}");
        assert_eq!(domains(&r.outputs[2]), vec![Interval::UNIT]);
    }

    #[test]
    fn pwk_bad_input() {
        let knots = vec![0.0, 0.0, 0.0, 0.25, 0.5, 0.75, 1.0, 1.0, 1.0];
        let e = single_error(&pwk(book_points(), vec![], vec![0.0, 1.0]));
        assert!(e.contains("at least 7 knots"), "{e}");
        // Decreasing knots.
        let mut bad = knots.clone();
        bad.swap(3, 4);
        assert!(single_error(&pwk(book_points(), vec![], bad)).contains("knot"));
        // Zero weight.
        let mut w = vec![1.0; 7];
        w[2] = 0.0;
        assert!(single_error(&pwk(book_points(), w, knots.clone())).contains("weight"));
        // Wrong number of weights.
        assert!(single_error(&pwk(book_points(), vec![1.0; 3], knots.clone())).contains("weights"));
        // A knot repeated beyond the degree.
        let e = single_error(&pwk(
            book_points(),
            vec![],
            vec![0.0, 0.0, 0.0, 0.5, 0.5, 0.5, 0.5, 1.0, 1.0],
        ));
        assert!(e.contains("knot"), "{e}");
        // Too few points for the degree the knots imply: 2 points, 5 knots is degree 4.
        let e = single_error(&pwk(
            book_points()[..2].to_vec(),
            vec![],
            vec![0.0, 0.0, 0.0, 1.0, 1.0],
        ));
        assert!(e.contains("points"), "{e}");
        let e = single_error(&pwk(book_points(), vec![], {
            let mut k = knots.clone();
            k[4] = f64::NAN;
            k
        }));
        assert!(e.contains("knot"), "{e}");
    }

    #[test]
    fn pwk_rational_quarter_circle() {
        let w = std::f64::consts::FRAC_1_SQRT_2;
        let r = pwk(
            vec![
                Point3::new(1.0, 0.0, 0.0),
                Point3::new(1.0, 1.0, 0.0),
                Point3::new(0.0, 1.0, 0.0),
            ],
            vec![1.0, w, 1.0],
            vec![0.0, 0.0, 1.0, 1.0],
        );
        let c = curves(&r.outputs[0])[0].clone();
        for i in 0..=10 {
            let p = c.point_at(i as f64 / 10.0);
            assert!((p.to_vector().length() - 1.0).abs() < 1e-15);
        }
        assert!((numbers(&r.outputs[1])[0] - std::f64::consts::FRAC_PI_2).abs() < 1e-12);
    }

    #[test]
    fn knot_vector_feeds_pwk() {
        for periodic in [false, true] {
            let r = NodeCall::new(&knot_vector())
                .input(DataTree::from_item(7i64))
                .skip_input()
                .input(DataTree::from_item(periodic))
                .run();
            let knots = numbers(&r.outputs[0]);
            assert_eq!(knots.len(), 9);
            if periodic {
                assert_eq!(knots, (0..9).map(f64::from).collect::<Vec<_>>());
            } else {
                assert_eq!(knots, vec![0.0, 0.0, 0.0, 1.0, 2.0, 3.0, 4.0, 4.0, 4.0]);
                let made = pwk(book_points(), vec![], knots);
                let created = NurbsCurve::create(&book_points(), 3, false).unwrap();
                assert_eq!(*curves(&made.outputs[0])[0], Curve::Nurbs(created));
            }
        }
    }

    #[test]
    fn knot_vector_bad_input() {
        let r = NodeCall::new(&knot_vector())
            .input(DataTree::from_item(1i64))
            .run();
        assert!(single_error(&r).contains("below 2"));
        let r = NodeCall::new(&knot_vector())
            .input(DataTree::from_item(5i64))
            .input(DataTree::from_item(0i64))
            .run();
        assert!(single_error(&r).contains("degree"));
        let r = NodeCall::new(&knot_vector())
            .input(DataTree::from_item(3i64))
            .input(DataTree::from_item(5i64))
            .run();
        assert_eq!(numbers(&r.outputs[0]), vec![0.0, 0.0, 1.0, 1.0]);
        assert_eq!(messages(&r, Level::Remark).len(), 1);
    }

    #[test]
    fn interpolate_passes_through_the_points() {
        let pts = book_points();
        for (periodic, style) in [(false, 0i64), (false, 1), (false, 2), (true, 1)] {
            let r = NodeCall::new(&interpolate())
                .input(DataTree::from_list(pts.clone()))
                .skip_input()
                .input(DataTree::from_item(periodic))
                .input(DataTree::from_item(style))
                .run();
            assert!(r.messages.is_empty(), "{:?}", r.messages);
            let c = curves(&r.outputs[0])[0].clone();
            assert_eq!(c.is_periodic(), periodic);
            // Every point is on the curve.
            for p in &pts {
                let cp = c.closest_point(*p).unwrap();
                assert!(cp.distance < 1e-9, "{periodic} {style}: {cp:?}");
            }
        }
        // Chord spacing: the domain is the polygon's length.
        let r = NodeCall::new(&interpolate())
            .input(DataTree::from_list(square()))
            .run();
        assert_eq!(domains(&r.outputs[2]), vec![Interval::new(0.0, 30.0)]);
    }

    #[test]
    fn interpolate_bad_input() {
        let run = |pts: Vec<Point3>, d: i64, p: bool, k: i64| {
            NodeCall::new(&interpolate())
                .input(DataTree::from_list(pts))
                .input(DataTree::from_item(d))
                .input(DataTree::from_item(p))
                .input(DataTree::from_item(k))
                .run()
        };
        assert!(single_error(&run(square(), 2, false, 1)).contains("odd degree"));
        assert!(single_error(&run(square(), 0, false, 1)).contains("degree"));
        assert!(single_error(&run(square(), 3, false, 3)).contains("knot style"));
        assert!(single_error(&run(vec![Point3::ORIGIN], 3, false, 1)).contains("at least 2"));
        assert!(single_error(&run(square()[..2].to_vec(), 3, true, 1)).contains("at least 3"));
        let mut dup = square();
        dup.insert(1, dup[0]);
        assert!(single_error(&run(dup, 3, false, 1)).contains("coincide"));
        let mut nan = square();
        nan[2] = Point3::new(0.0, f64::NAN, 0.0);
        assert!(single_error(&run(nan, 3, false, 1)).contains("not finite"));
        assert_eq!(
            values(&run(vec![Point3::ORIGIN], 3, false, 1).outputs[1]),
            vec![None]
        );
    }
}

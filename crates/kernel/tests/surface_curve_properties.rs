//! Property tests of curve | surface and line | surface intersections on random height-field
//! surfaces (control points on a grid in x and y, random heights, rational or not) and random
//! curves and lines crossing their box:
//!
//! - every reported point lies on both: `C(t)` is the reported point and `S(u, v)` lies within
//!   the tolerance of it;
//! - nothing is missed: the curve is sampled densely, each sample's signed distance from the
//!   surface is measured along the normal at its closest point, and wherever it changes sign
//!   clearly between neighbouring samples whose closest points lie inside the surface (not on
//!   an edge, where the sign means nothing), a point (or an overlap) is reported between them.

use locus_kernel::{Curve, Line, NurbsCurve, NurbsSurface, Point3};
use proptest::prelude::*;

/// The intersection tolerance of the properties (the oracle's).
const TOL: f64 = 1e-7;
/// Samples per curve.
const SAMPLES: usize = 160;
/// Signed distances smaller than this are not taken as a side.
const CLEAR: f64 = 1e-6;

/// A random height field over `[0, 4]²`: degree 1 to 3 in each direction, 2 to 3 extra rows.
fn arb_surface() -> impl Strategy<Value = NurbsSurface> {
    (
        1usize..=3,
        1usize..=3,
        0usize..=2,
        0usize..=2,
        any::<bool>(),
    )
        .prop_flat_map(|(p, q, eu, ev, rational)| {
            let (nu, nv) = (p + 1 + eu, q + 1 + ev);
            (
                Just((p, q, nu, nv, rational)),
                prop::collection::vec(-1.0f64..1.0, nu * nv),
                prop::collection::vec(0.5f64..2.0, nu * nv),
            )
                .prop_map(|((p, q, nu, nv, rational), heights, weights)| {
                    let points: Vec<Vec<Point3>> = (0..nu)
                        .map(|i| {
                            (0..nv)
                                .map(|j| {
                                    Point3::new(
                                        4.0 * i as f64 / (nu - 1) as f64,
                                        4.0 * j as f64 / (nv - 1) as f64,
                                        heights[i * nv + j],
                                    )
                                })
                                .collect()
                        })
                        .collect();
                    let weights: Vec<Vec<f64>> = (0..nu)
                        .map(|i| {
                            (0..nv)
                                .map(|j| if rational { weights[i * nv + j] } else { 1.0 })
                                .collect()
                        })
                        .collect();
                    NurbsSurface::new(p, q, points, weights, clamped(p, nu), clamped(q, nv))
                        .expect("valid surface")
                })
        })
}

/// Clamped uniform knots in Rhino form for `n` control points of degree `p`.
fn clamped(p: usize, n: usize) -> Vec<f64> {
    let mut knots = vec![0.0; p];
    for k in 1..n - p {
        knots.push(k as f64);
    }
    knots.extend(std::iter::repeat_n((n - p) as f64, p));
    knots
}

/// A random cubic (or straight) curve through the box of the surfaces.
fn arb_curve() -> impl Strategy<Value = Curve> {
    (
        any::<bool>(),
        prop::collection::vec((-1.0f64..5.0, -1.0f64..5.0, -1.5f64..1.5), 4),
    )
        .prop_map(|(straight, points)| {
            let points: Vec<Point3> = points
                .into_iter()
                .map(|(x, y, z)| Point3::new(x, y, z))
                .collect();
            if straight {
                Curve::Line {
                    line: Line::new(points[0], points[3]),
                    domain: locus_kernel::Interval::UNIT,
                }
            } else {
                Curve::Nurbs(
                    NurbsCurve::new_non_rational(3, points, vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0])
                        .expect("valid curve"),
                )
            }
        })
}

/// The signed distance of `p` from the surface along the normal at its closest point, if that
/// point lies clearly inside the domain.
fn side(s: &NurbsSurface, p: Point3) -> Option<f64> {
    let c = s.closest_point(p).ok()?;
    let (du, dv) = (s.domain_u(), s.domain_v());
    let margin = 1e-3;
    let inside = c.u > du.t0 + margin
        && c.u < du.t1 - margin
        && c.v > dv.t0 + margin
        && c.v < dv.t1 - margin;
    let n = s.normal_at(c.u, c.v).ok()?;
    inside.then(|| (p - c.point).dot(n))
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 48, ..ProptestConfig::default() })]

    #[test]
    fn reported_points_lie_on_both_and_no_crossing_is_missed(
        surface in arb_surface(),
        curve in arb_curve(),
    ) {
        let found = surface.intersect_curve(&curve, TOL).expect("intersection");
        for h in &found.points {
            prop_assert!(curve.point_at(h.t).distance(h.point) <= 1e-9, "{h:?}");
            prop_assert!(surface.point_at(h.u, h.v).distance(h.point) <= TOL, "{h:?}");
        }
        let d = curve.domain();
        let samples: Vec<(f64, Option<f64>)> = (0..=SAMPLES)
            .map(|k| {
                let t = d.parameter_at(k as f64 / SAMPLES as f64);
                (t, side(&surface, curve.point_at(t)))
            })
            .collect();
        let h = d.length() / SAMPLES as f64;
        for w in samples.windows(2) {
            let ((t0, s0), (t1, s1)) = (w[0], w[1]);
            let (Some(s0), Some(s1)) = (s0, s1) else { continue };
            if s0.abs() > CLEAR && s1.abs() > CLEAR && s0.signum() != s1.signum() {
                let reported = found.points.iter().any(|p| p.t >= t0 - h && p.t <= t1 + h)
                    || found.overlaps.iter().any(|o| o.t.t0 <= t1 + h && o.t.t1 >= t0 - h);
                prop_assert!(reported, "missed a crossing in [{t0}, {t1}]: {found:?}");
            }
        }
    }

    #[test]
    fn infinite_lines_find_what_their_segments_find(
        surface in arb_surface(),
        a in (-1.0f64..5.0, -1.0f64..5.0, -1.5f64..1.5),
        b in (-1.0f64..5.0, -1.0f64..5.0, -1.5f64..1.5),
    ) {
        let line = Line::new(Point3::new(a.0, a.1, a.2), Point3::new(b.0, b.1, b.2));
        prop_assume!(line.length() > 1e-3);
        let segment = Curve::Line { line, domain: locus_kernel::Interval::UNIT };
        let on_segment = surface.intersect_curve(&segment, TOL).expect("segment");
        let infinite = surface.intersect_line(&line, TOL).expect("line");
        for h in &on_segment.points {
            prop_assert!(
                infinite.points.iter().any(|g| g.point.distance(h.point) <= 1e-6)
                    || h.t <= 1e-6 || h.t >= 1.0 - 1e-6,
                "{h:?} not in {infinite:?}"
            );
        }
        for g in &infinite.points {
            prop_assert!(line.point_at(g.t).distance(g.point) <= 1e-9, "{g:?}");
        }
    }
}

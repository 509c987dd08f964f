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
    let offset = p - c.point;
    // Only where `p − c` runs along the normal: at a crease (a knot line of a degree-1
    // surface) the closest point is on the crease and the normal of one side means nothing.
    let along = offset.dot(n).abs() >= 0.999 * offset.length();
    (inside && along).then(|| offset.dot(n))
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

/// Found by `infinite_lines_find_what_their_segments_find` in CI: a bilinear-in-v, rational
/// degree-1 surface whose infinite line missed the crossing its segment found.
#[test]
fn infinite_line_finds_crossing_on_rational_degree_one_surface() {
    let heights = [
        [0.0, 0.0],
        [0.0, 0.0],
        [0.0, -0.8746248628422133],
        [-0.7697755802347255, 0.3108520198978612],
    ];
    let weights = [
        [1.6210827907702505, 0.6747902903260776],
        [1.9706063499953468, 1.0999324262230241],
        [1.6952730940534124, 1.2116079476928427],
        [0.6324260199533985, 1.0975288838864552],
    ];
    let points: Vec<Vec<Point3>> = (0..4)
        .map(|i| {
            (0..2)
                .map(|j| Point3::new(4.0 * i as f64 / 3.0, 4.0 * j as f64, heights[i][j]))
                .collect()
        })
        .collect();
    let weights: Vec<Vec<f64>> = weights.iter().map(|w| w.to_vec()).collect();
    let surface = NurbsSurface::new(1, 1, points, weights, clamped(1, 4), clamped(1, 2))
        .expect("valid surface");
    let line = Line::new(
        Point3::new(4.292214412016207, 2.74314125583116, -1.1195507908048672),
        Point3::new(2.886119024433167, 0.34244370073653546, -0.11209789997390619),
    );
    let segment = Curve::Line {
        line,
        domain: locus_kernel::Interval::UNIT,
    };
    let on_segment = surface.intersect_curve(&segment, TOL).expect("segment");
    let infinite = surface.intersect_line(&line, TOL).expect("line");
    assert_eq!(on_segment.points.len(), 1, "{on_segment:?}");
    assert_eq!(infinite.points.len(), 1, "{infinite:?}");
    assert!(
        infinite.points[0]
            .point
            .distance(on_segment.points[0].point)
            <= 1e-6
    );
}

/// A twisted bilinear patch (the saddle `z = xy` over `[-1, 1]²`) is its own control net, yet a
/// line crosses it twice: both crossings are found.
#[test]
fn a_line_crossing_a_saddle_twice_finds_both() {
    let z = |x: f64, y: f64| Point3::new(x, y, x * y);
    let surface = NurbsSurface::new(
        1,
        1,
        vec![
            vec![z(-1.0, -1.0), z(-1.0, 1.0)],
            vec![z(1.0, -1.0), z(1.0, 1.0)],
        ],
        vec![vec![1.0; 2]; 2],
        vec![0.0, 1.0],
        vec![0.0, 1.0],
    )
    .expect("valid surface");
    let line = Line::new(Point3::new(-1.0, -1.0, 0.25), Point3::new(1.0, 1.0, 0.25));
    let segment = Curve::Line {
        line,
        domain: locus_kernel::Interval::UNIT,
    };
    for found in [
        surface.intersect_curve(&segment, TOL).expect("segment"),
        surface.intersect_line(&line, TOL).expect("line"),
    ] {
        let mut xs: Vec<f64> = found.points.iter().map(|h| h.point.x).collect();
        xs.sort_by(f64::total_cmp);
        assert_eq!(xs.len(), 2, "{found:?}");
        assert!(
            (xs[0] + 0.5).abs() <= 1e-9 && (xs[1] - 0.5).abs() <= 1e-9,
            "{xs:?}"
        );
    }
}

/// Found by `reported_points_lie_on_both_and_no_crossing_is_missed`: a line through a cubic
/// wave close to a fold.
#[test]
fn a_line_near_a_fold_of_a_cubic_wave() {
    let heights = [
        [0.0, 0.0],
        [0.0, 0.0],
        [-0.891744527385116, -0.7536626400869116],
        [0.8812679877515252, 0.23632030162340611],
        [0.016214855574235774, -0.20777908143808027],
        [0.0, 0.0],
    ];
    let points: Vec<Vec<Point3>> = (0..6)
        .map(|i| {
            (0..2)
                .map(|j| Point3::new(0.8 * i as f64, 4.0 * j as f64, heights[i][j]))
                .collect()
        })
        .collect();
    let surface = NurbsSurface::new(
        3,
        1,
        points,
        vec![vec![1.0; 2]; 6],
        clamped(3, 6),
        clamped(1, 2),
    )
    .expect("valid surface");
    let line = Line::new(
        Point3::new(3.150834389854508, -0.17967640909949842, 0.6134942123216475),
        Point3::new(-0.5856846817339676, 3.0119520992900446, -0.9445334984687298),
    );
    let curve = Curve::Line {
        line,
        domain: locus_kernel::Interval::UNIT,
    };
    let found = surface.intersect_curve(&curve, TOL).expect("intersection");
    for k in 0..=40 {
        let t = 0.17 + 0.04 * k as f64 / 40.0;
        eprintln!("DBG {t:.4} {:?}", side(&surface, line.point_at(t)));
    }
    eprintln!("DBG {found:?}");
}

/// A line grazing a shallow parabolic trough (`z = 0.001 x²`, flat to a thousandth of its size)
/// crosses it twice inside one flat patch: both crossings are found (a polish from the flat
/// estimate finds one, so the pair must be halved for being nearly tangent).
#[test]
fn a_line_grazing_a_shallow_trough_finds_both_crossings() {
    let row = |x: f64, z: f64| vec![Point3::new(x, -1.0, z), Point3::new(x, 1.0, z)];
    let surface = NurbsSurface::new(
        2,
        1,
        vec![row(-1.0, 0.001), row(0.0, -0.001), row(1.0, 0.001)],
        vec![vec![1.0; 2]; 3],
        vec![0.0, 0.0, 1.0, 1.0],
        vec![0.0, 1.0],
    )
    .expect("valid surface");
    // z = 0.0003 − 0.00005 x meets z = 0.001 x² at x = (−0.05 ± √1.2025) / 2.
    let line = Line::new(
        Point3::new(-2.0, 0.3, 0.0004),
        Point3::new(2.0, 0.3, 0.0002),
    );
    let roots = [
        (-0.05 - 1.2025f64.sqrt()) / 2.0,
        (-0.05 + 1.2025f64.sqrt()) / 2.0,
    ];
    let found = surface.intersect_line(&line, TOL).expect("line");
    let mut xs: Vec<f64> = found.points.iter().map(|h| h.point.x).collect();
    xs.sort_by(f64::total_cmp);
    assert_eq!(xs.len(), 2, "{found:?}");
    assert!(
        (xs[0] - roots[0]).abs() <= 1e-9 && (xs[1] - roots[1]).abs() <= 1e-9,
        "{xs:?} against {roots:?}"
    );
}

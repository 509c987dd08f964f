//! Replays the intersection cases of `ops-cases.json` (OpenCASCADE, cross-checked with
//! openNURBS and exact arithmetic) through the kernel:
//!
//! - `line_plane`: the parameter on the infinite line, or parallel;
//! - `plane_plane`: the line's direction (up to sign) and a point on it, or parallel; three
//!   planes: the point, or none;
//! - `curve_plane`: every point (parameter, point, crossing or touching) and every overlap;
//! - `curve_curve` where curve B is a line segment: [`Curve::intersect_line`] on B's infinite
//!   line, the points kept that lie on the segment;
//! - every `curve_curve` case through the general [`Curve::intersect_curve`]: each point with
//!   both parameters (a closed curve's seam at either end of its domain), tangential points to
//!   the tangential tolerance, every overlap with its interval on both curves; the cases with a
//!   closest approach instead of a point must find nothing.
//!
//! Tolerances are the file's (`tolerances` block): points 1e-9 × max(1, |coordinates|),
//! parameters 1e-9 × the domain's length, tangential points 1e-6. Every failing case is named
//! and all failures are reported together.

mod support;

use locus_kernel::{
    Curve, CurveCurveIntersections, CurveIntersections, Line, NurbsCurve, Plane, Point3, Vector3,
    line_plane, plane_plane, plane_plane_plane,
};
use serde_json::Value;
use support::{Failures, close, close3, load_oracle, num, numbers, triple};

/// Agreement of points and parameters at transversal events (relative to the domain's length
/// or `max(1, |coordinates|)`).
const REL: f64 = 1e-9;

/// Agreement at tangential events, where a double root is determined only to about √ε.
const TANGENTIAL: f64 = 1e-6;

fn point(v: &Value) -> Point3 {
    Point3::from_array(triple(v))
}

fn vector(v: &Value) -> Vector3 {
    Vector3::from_array(triple(v))
}

fn plane(v: &Value) -> Plane {
    Plane {
        origin: point(&v["origin"]),
        x_axis: vector(&v["x_axis"]),
        y_axis: vector(&v["y_axis"]),
        z_axis: vector(&v["normal"]),
    }
}

fn line(v: &Value) -> Line {
    Line::new(point(&v["from"]), point(&v["to"]))
}

fn curve(v: &Value) -> Curve {
    let degree = v["degree"].as_u64().expect("degree") as usize;
    let cvs = v["cvs"].as_array().expect("cvs");
    let points = cvs.iter().map(|cv| point(&cv["p"])).collect();
    let weights = cvs.iter().map(|cv| num(&cv["w"])).collect();
    let nurbs = NurbsCurve::new(degree, points, weights, numbers(&v["knots"]))
        .unwrap_or_else(|e| panic!("{}: invalid curve: {e}", v["name"]));
    Curve::Nurbs(nurbs)
}

fn cases(section: &str) -> Vec<Value> {
    load_oracle("ops-cases.json")[section]
        .as_array()
        .unwrap_or_else(|| panic!("no section {section}"))
        .clone()
}

#[test]
fn line_plane_cases() {
    let mut failures = Failures::default();
    for case in cases("line_plane") {
        let id = case["id"].as_str().unwrap();
        let (l, p) = (
            line(&case["inputs"]["line"]),
            plane(&case["inputs"]["plane"]),
        );
        let e = &case["expected"];
        let got = line_plane(&l, &p);
        if e["parallel"].as_bool().unwrap() {
            failures.check(got.is_none(), || {
                format!("{id}: {got:?}, expected parallel")
            });
            continue;
        }
        let want = num(&e["t"]);
        let rel = num(&e["suggested_relative_tolerance"]);
        match got {
            Some(t) => failures.check(close(t, want, rel), || {
                format!("{id}: t = {t}, expected {want} (to {rel})")
            }),
            None => failures.push(format!("{id}: parallel, expected t = {want}")),
        }
    }
    failures.finish("line | plane");
}

#[test]
fn plane_plane_cases() {
    let mut failures = Failures::default();
    for case in cases("plane_plane") {
        let id = case["id"].as_str().unwrap();
        let inputs = &case["inputs"];
        let e = &case["expected"];
        let (a, b) = (plane(&inputs["plane_a"]), plane(&inputs["plane_b"]));
        if !inputs["plane_c"].is_null() {
            let got = plane_plane_plane(&a, &b, &plane(&inputs["plane_c"]));
            if e["unique_point"].as_bool().unwrap() {
                let want = triple(&e["point"]);
                match got {
                    Some(p) => failures.check(close3(p.to_array(), want, REL), || {
                        format!("{id}: {p:?}, expected {want:?}")
                    }),
                    None => failures.push(format!("{id}: no point, expected {want:?}")),
                }
            } else {
                failures.check(got.is_none(), || format!("{id}: {got:?}, expected none"));
            }
            continue;
        }
        let got = plane_plane(&a, &b);
        if e["parallel"].as_bool().unwrap() {
            failures.check(got.is_none(), || {
                format!("{id}: {got:?}, expected parallel")
            });
            continue;
        }
        let Some(l) = got else {
            failures.push(format!("{id}: parallel, expected a line"));
            continue;
        };
        let tol = &e["suggested_tolerance"];
        let direction = l.unit_direction().unwrap();
        let want = vector(&e["direction"]);
        let sine = direction.cross(want).length();
        // The line is Rhino's, of length sin(angle) from a start that may lie far away: its
        // direction is known only to the rounding of its end points relative to that length.
        let rounding = 4.0 * f64::EPSILON * l.from.to_vector().length() / l.length();
        failures.check(sine <= num(&tol["direction_sine"]).max(rounding), || {
            format!("{id}: direction {direction:?}, expected ±{want:?} (sine {sine:e})")
        });
        let distance =
            Line::from_direction(l.from, direction).closest_parameter_unbounded(point(&e["point"]));
        let off = (l.from + direction * distance).distance(point(&e["point"]));
        failures.check(off <= num(&tol["point_distance"]), || {
            format!("{id}: the expected point is {off:e} from the line")
        });
        // openNURBS's own line: the same start, as the formula is openNURBS's.
        if num(&e["sin_angle"]) > 0.1 {
            let rhino = triple(&case["rhino3dm"]["from"]);
            failures.check(close3(l.from.to_array(), rhino, REL), || {
                format!("{id}: starts at {:?}, Rhino's at {rhino:?}", l.from)
            });
        }
    }
    failures.finish("plane | plane");
}

/// Checks what was found against a case's `points` (with the parameter field `t_field`) and
/// `overlaps`.
fn check_events(
    id: &str,
    c: &Curve,
    got: &CurveIntersections,
    expected: &Value,
    t_field: &str,
    failures: &mut Failures,
) {
    let length = c.domain().length();
    let want = expected["points"].as_array().unwrap();
    failures.check(got.points.len() == want.len(), || {
        format!(
            "{id}: {} points {:?}, expected {}",
            got.points.len(),
            got.points.iter().map(|h| h.t).collect::<Vec<_>>(),
            want.len()
        )
    });
    for w in want {
        let t = num(&w[t_field]);
        let tangential = w["tangential"].as_bool().unwrap_or(false);
        let rel = if tangential { TANGENTIAL } else { REL };
        let Some(hit) = got
            .points
            .iter()
            .min_by(|a, b| (a.t - t).abs().total_cmp(&(b.t - t).abs()))
        else {
            continue;
        };
        failures.check((hit.t - t).abs() <= rel * length, || {
            format!("{id}: t = {}, expected {t}", hit.t)
        });
        let p = triple(&w["point"]);
        failures.check(close3(hit.point.to_array(), p, rel), || {
            format!("{id}: point {:?}, expected {p:?}", hit.point)
        });
        // A grazing crossing (at an angle below OCCT's angular tolerance) is listed as
        // tangential and not crossing; the kernel reports whether the sign changes.
        if let Some(crossing) = w["crossing"].as_bool().filter(|_| !tangential) {
            failures.check(hit.tangential != crossing, || {
                format!(
                    "{id} t = {t}: crossing is {}, expected {crossing}",
                    !hit.tangential
                )
            });
        }
    }
    let want = expected["overlaps"].as_array().unwrap();
    failures.check(got.overlaps.len() == want.len(), || {
        format!("{id}: overlaps {:?}, expected {want:?}", got.overlaps)
    });
    for (o, w) in got.overlaps.iter().zip(want) {
        let range = w.get("t").or_else(|| w.get("a")).unwrap();
        let [t0, t1] = [num(&range[0]), num(&range[1])];
        failures.check(
            (o.t0 - t0).abs() <= REL * length && (o.t1 - t1).abs() <= REL * length,
            || format!("{id}: overlap {o:?}, expected [{t0}, {t1}]"),
        );
    }
}

#[test]
fn curve_plane_cases() {
    let mut failures = Failures::default();
    for case in cases("curve_plane") {
        let id = case["id"].as_str().unwrap();
        let inputs = &case["inputs"];
        let c = curve(&inputs["curve"]);
        let tolerance = num(&inputs["tolerance"]);
        match c.intersect_plane(&plane(&inputs["plane"]), tolerance) {
            Ok(got) => check_events(id, &c, &got, &case["expected"], "t", &mut failures),
            Err(e) => failures.push(format!("{id}: {e}")),
        }
    }
    failures.finish("curve | plane");
}

#[test]
fn curve_line_cases() {
    let mut failures = Failures::default();
    let mut replayed = 0;
    for case in cases("curve_curve") {
        let id = case["id"].as_str().unwrap();
        let inputs = &case["inputs"];
        let b = &inputs["curve_b"];
        if b["degree"].as_u64() != Some(1) || b["cvs"].as_array().unwrap().len() != 2 {
            continue;
        }
        let (b0, b1) = (point(&b["cvs"][0]["p"]), point(&b["cvs"][1]["p"]));
        let segment = Line::new(b0, b1);
        let a = curve(&inputs["curve_a"]);
        let tolerance = num(&inputs["tolerance"]);
        let Ok(mut got) = a.intersect_line(&segment, tolerance) else {
            failures.push(format!("{id}: error"));
            continue;
        };
        // The segment's own events: points whose line parameter is in [0, 1] (within the
        // tolerance), and no overlaps beyond it.
        let on_segment =
            |p: Point3| segment.point_at(segment.closest_parameter(p)).distance(p) <= tolerance;
        got.points.retain(|h| on_segment(h.point));
        got.overlaps
            .retain(|o| on_segment(a.point_at(o.t0)) || on_segment(a.point_at(o.t1)));
        if !case["expected"]["overlaps"].as_array().unwrap().is_empty() {
            // Overlap ends clipped to the segment are the general curve | curve search's.
            continue;
        }
        replayed += 1;
        check_events(id, &a, &got, &case["expected"], "t_a", &mut failures);
    }
    assert!(replayed >= 6, "only {replayed} curve | line cases");
    failures.finish("curve | line");
}

/// Whether parameter `got` matches `want` on `c` to `rel` of the domain's length, where on a
/// closed curve the two ends of the domain are the same place.
fn same_parameter(c: &Curve, got: f64, want: f64, rel: f64) -> bool {
    let d = c.domain();
    let tol = rel * d.length();
    (got - want).abs() <= tol || c.is_closed() && ((got - want).abs() - d.length()).abs() <= tol
}

fn check_curve_curve(
    id: &str,
    a: &Curve,
    b: &Curve,
    got: &CurveCurveIntersections,
    expected: &Value,
    failures: &mut Failures,
) {
    let want = expected["points"].as_array().unwrap();
    failures.check(got.points.len() == want.len(), || {
        format!(
            "{id}: {} points {:?}, expected {}",
            got.points.len(),
            got.points
                .iter()
                .map(|h| (h.t_a, h.t_b))
                .collect::<Vec<_>>(),
            want.len()
        )
    });
    for w in want {
        let (ta, tb) = (num(&w["t_a"]), num(&w["t_b"]));
        let rel = if w["tangential"].as_bool().unwrap_or(false) {
            TANGENTIAL
        } else {
            REL
        };
        let p = triple(&w["point"]);
        let Some(hit) = got.points.iter().min_by(|x, y| {
            let d = |h: &&locus_kernel::CurveCurveHit| h.point_a.distance(Point3::from_array(p));
            d(x).total_cmp(&d(y))
        }) else {
            continue;
        };
        failures.check(same_parameter(a, hit.t_a, ta, rel), || {
            format!("{id}: t_a = {}, expected {ta}", hit.t_a)
        });
        failures.check(same_parameter(b, hit.t_b, tb, rel), || {
            format!("{id}: t_b = {}, expected {tb}", hit.t_b)
        });
        failures.check(
            close3(hit.point_a.to_array(), p, rel) && close3(hit.point_b.to_array(), p, rel),
            || {
                format!(
                    "{id}: points {:?} {:?}, expected {p:?}",
                    hit.point_a, hit.point_b
                )
            },
        );
        if w["tangential"].as_bool() == Some(true) {
            failures.check(hit.tangential, || format!("{id}: not tangential at {ta}"));
        }
    }
    let want = expected["overlaps"].as_array().unwrap();
    failures.check(got.overlaps.len() == want.len(), || {
        format!("{id}: overlaps {:?}, expected {want:?}", got.overlaps)
    });
    for (o, w) in got.overlaps.iter().zip(want) {
        let [a0, a1] = [num(&w["a"][0]), num(&w["a"][1])];
        let [b0, b1] = [num(&w["b"][0]), num(&w["b"][1])];
        failures.check(
            same_parameter(a, o.a.t0, a0, REL)
                && same_parameter(a, o.a.t1, a1, REL)
                && same_parameter(b, o.b.t0, b0, REL)
                && same_parameter(b, o.b.t1, b1, REL),
            || format!("{id}: overlap {o:?}, expected a [{a0}, {a1}] b [{b0}, {b1}]"),
        );
        let (s, e) = (triple(&w["start_point"]), triple(&w["end_point"]));
        failures.check(
            close3(a.point_at(o.a.t0).to_array(), s, REL)
                && close3(a.point_at(o.a.t1).to_array(), e, REL),
            || format!("{id}: overlap ends {o:?}, expected {s:?} to {e:?}"),
        );
    }
}

#[test]
fn curve_curve_cases() {
    let mut failures = Failures::default();
    let mut replayed = 0;
    for case in cases("curve_curve") {
        let id = case["id"].as_str().unwrap();
        let inputs = &case["inputs"];
        let (a, b) = (curve(&inputs["curve_a"]), curve(&inputs["curve_b"]));
        let tolerance = num(&inputs["tolerance"]);
        match a.intersect_curve(&b, tolerance) {
            Ok(got) => {
                replayed += 1;
                check_curve_curve(id, &a, &b, &got, &case["expected"], &mut failures);
            }
            Err(e) => failures.push(format!("{id}: {e}")),
        }
    }
    assert_eq!(replayed, 23, "every curve | curve case is replayed");
    failures.finish("curve | curve");
}

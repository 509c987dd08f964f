//! Replays the `offset` cases of `ops-cases.json` (OpenCASCADE's `BRepOffsetAPI_MakeOffset`,
//! cross-checked with openNURBS and closed forms) through [`Curve::offset`], the kernel side of
//! the Offset Curve node: polygons and polylines with sharp and round corners, circles, a
//! periodic cubic and a cubic with two kinks, offset outwards and inwards (closed curves) or to
//! the left and right (open ones).
//!
//! Each case is replayed from its NURBS record, and again from its construction where it has
//! one (a polyline, or a circle as the kernel's own circle type), so that the rational form of a
//! circle is held to the same exact answer as the circle itself. The side is turned into the
//! kernel's signed distance: a positive distance moves along `T × N`, which is the right of
//! the direction of travel (`left = N × T` in the file's convention) and the outside of a curve
//! running counter-clockwise about the plane's normal.
//!
//! Checks, to the file's tolerances (`tolerances.offsets`): one curve, closed or open as
//! expected, no warnings; length and enclosed area 1e-9 relative; end points and polygon
//! vertices 1e-9 absolute; circles offset to an exact circle of radius `R ± d`. Curves that are
//! neither polylines nor arcs are offset by a fit within a tolerance ([`FIT_TOLERANCE`]); the
//! area such a fit encloses may differ from the exact one by up to that distance times the
//! length, which is added to their area tolerance (their lengths still meet 1e-9). Every
//! failing case is named and all failures are reported together.

mod support;

use locus_kernel::{Circle, Curve, OffsetCorners, Plane, Point3, Polyline};
use serde_json::Value;
use support::breps::{nurbs_curve, plane, point};
use support::{Failures, load_oracle, num, signed_area};

/// Lengths and enclosed areas (relative).
const EXACT: f64 = 1e-9;
/// End points and polygon vertices (absolute).
const POINTS: f64 = 1e-9;
/// The tolerance given to [`Curve::offset`] for the curves it must approximate.
const FIT_TOLERANCE: f64 = 1e-9;

/// The curves a case is replayed from: its NURBS record, and its construction when it has one.
fn inputs(case: &Value) -> Vec<(&'static str, Curve)> {
    let record = &case["inputs"]["curve"];
    let mut out = vec![("nurbs", Curve::Nurbs(nurbs_curve(record)))];
    let construction = &record["construction"];
    match construction["kind"].as_str() {
        Some("polyline") => {
            let points = construction["points"]
                .as_array()
                .unwrap()
                .iter()
                .map(point)
                .collect();
            out.push(("polyline", Polyline::new(points).unwrap().into()));
        }
        Some("circle") => {
            let circle =
                Circle::new(plane(&construction["plane"]), num(&construction["radius"])).unwrap();
            out.push(("circle", circle.into()));
        }
        _ => {}
    }
    out
}

/// The kernel's signed distance for the case's side.
fn signed_distance(case: &Value, curve: &Curve, cut: &Plane) -> f64 {
    let d = num(&case["inputs"]["distance"]);
    match case["inputs"]["side"].as_str().unwrap() {
        "right" => d,
        "left" => -d,
        side => {
            let counter_clockwise = signed_area(curve, cut) > 0.0;
            if (side == "outside") == counter_clockwise {
                d
            } else {
                -d
            }
        }
    }
}

/// The vertices of a polyline result (the closing vertex of a closed one once).
fn polygon_vertices(curve: &Curve) -> Option<Vec<Point3>> {
    let mut points = match curve {
        Curve::Polyline { polyline, .. } => polyline.points().to_vec(),
        Curve::Nurbs(c) if c.degree() == 1 => c.points().to_vec(),
        Curve::Line { line, .. } => vec![line.from, line.to],
        _ => return None,
    };
    if curve.is_closed() {
        points.pop();
    }
    Some(points)
}

fn check_case(id: &str, case: &Value, curve: &Curve, f: &mut Failures) {
    let inputs = &case["inputs"];
    let e = &case["expected"];
    let cut = plane(&inputs["plane"]);
    let corners = match inputs["corner"].as_str().unwrap() {
        "sharp" => OffsetCorners::Sharp,
        "round" => OffsetCorners::Round,
        other => panic!("{id}: no corner style {other}"),
    };
    let distance = signed_distance(case, curve, &cut);
    let offset = match curve.offset(distance, &cut, corners, FIT_TOLERANCE) {
        Ok(o) => o,
        Err(err) => {
            f.push(format!("{id}: offset failed: {err}"));
            return;
        }
    };
    let got = &offset.curve;
    f.check(offset.warnings.is_empty(), || {
        format!("{id}: warnings {:?}", offset.warnings)
    });
    assert_eq!(e["curves"].as_u64(), Some(1), "{id}: one curve expected");
    let closed = e["closed"].as_bool().unwrap();
    f.check(got.is_closed() == closed, || {
        format!("{id}: closed is {}, expected {closed}", got.is_closed())
    });
    let length = got.length();
    let want_length = num(&e["length"]);
    f.check((length - want_length).abs() <= EXACT * want_length, || {
        format!(
            "{id}: length {length}, expected {want_length} (relative error {:.2e})",
            (length - want_length).abs() / want_length
        )
    });
    let kind = inputs["curve"]["construction"]["kind"].as_str();
    let fitted = !matches!(kind, Some("polyline" | "circle"));
    if let Some(area) = e["enclosed_area"].as_f64() {
        let got_area = signed_area(got, &cut).abs();
        let allowed = EXACT * area + if fitted { FIT_TOLERANCE * length } else { 0.0 };
        f.check((got_area - area).abs() <= allowed, || {
            format!(
                "{id}: enclosed area {got_area}, expected {area} (error {:.2e}, allowed {allowed:.2e})",
                (got_area - area).abs()
            )
        });
    }
    for (key, got_point) in [
        ("start_point", got.start_point()),
        ("end_point", got.end_point()),
    ] {
        if !e[key].is_null() {
            let want = point(&e[key]);
            f.check(got_point.distance(want) <= POINTS, || {
                format!("{id}: {key} {got_point:?}, expected {want:?}")
            });
        }
    }
    if let Some(want) = e["polygon_vertices"].as_array() {
        match polygon_vertices(got) {
            Some(vertices) => {
                f.check(vertices.len() == want.len(), || {
                    format!("{id}: {} vertices, expected {}", vertices.len(), want.len())
                });
                for w in want.iter().map(point) {
                    f.check(vertices.iter().any(|v| v.distance(w) <= POINTS), || {
                        format!("{id}: no vertex at {w:?} among {vertices:?}")
                    });
                }
            }
            None => f.push(format!("{id}: not a polyline: {got:?}")),
        }
    }
    if kind == Some("circle") {
        let radius = num(&inputs["curve"]["construction"]["radius"]);
        let want = radius
            + if inputs["side"] == "outside" {
                1.0
            } else {
                -1.0
            } * num(&inputs["distance"]);
        match got.try_arc(1e-12) {
            Some(arc) if (arc.radius() - want).abs() <= 1e-12 * want => {}
            other => f.push(format!(
                "{id}: not an exact circle of radius {want}: {other:?}"
            )),
        }
    }
}

#[test]
fn offset_cases() {
    let mut f = Failures::default();
    let cases = load_oracle("ops-cases.json")["offset"]
        .as_array()
        .expect("an offset section")
        .clone();
    let mut replayed = 0;
    for case in &cases {
        let id = case["id"].as_str().unwrap();
        for (form, curve) in inputs(case) {
            check_case(&format!("{id} ({form})"), case, &curve, &mut f);
            replayed += 1;
        }
    }
    assert_eq!(cases.len(), 14, "every offset case is replayed");
    assert!(replayed >= cases.len());
    f.finish("offset");
}

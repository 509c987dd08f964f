//! Replays the section cases of `ops-cases.json` (OpenCASCADE, cross-checked with openNURBS and
//! closed forms) through the kernel's own B-reps (`support/breps.rs`):
//!
//! - `brep_plane`: [`Brep::intersect_plane`]: the number of curves, and per curve (by
//!   decreasing length) its length, whether it is closed, the area it encloses (closed curves)
//!   or its end points (open ones); the isolated touching points;
//! - `contour`: [`Brep::contour`]: per plane index `k` the number of curves, their lengths and
//!   closedness; planes the case does not list must have no curves.
//!
//! Tolerances are the file's (`tolerances.section_lengths`): lengths and areas of closed-form
//! sections 1e-9 relative; of sections of NURBS and swept faces, whose reference values come
//! from points on the intersection, 1e-6 (areas 1e-5, the reference's own agreement being
//! 5e-6); end points and touching points 1e-6. Sections through curved faces are curves fitted
//! within a tenth of the tolerance of the exact section (`surface_plane.rs`), so the area
//! they enclose may differ from the exact one by up to that distance times their length: that
//! bound is added to the area tolerance of such sections (their lengths, a second-order effect
//! of the fit, still meet 1e-9). Every failing case is named and all failures are reported
//! together.

mod support;

use locus_kernel::{Brep, BrepSection, Curve, Plane, Point3};
use serde_json::Value;
use support::breps::{brep, plane, point, vector};
use support::{Failures, enclosed_area, load_oracle, num, triple};

/// Lengths and areas of closed-form sections (relative).
const EXACT: f64 = 1e-9;
/// Lengths of sections of NURBS and swept faces (relative).
const TRACED: f64 = 1e-6;
/// Areas of sections of NURBS and swept faces (relative).
const TRACED_AREA: f64 = 1e-5;
/// End points and touching points.
const POINTS: f64 = 1e-6;

fn cases(section: &str) -> Vec<Value> {
    load_oracle("ops-cases.json")[section]
        .as_array()
        .unwrap_or_else(|| panic!("no section {section}"))
        .clone()
}

/// The fraction of the tolerance within which fitted section curves follow the exact ones.
const FIT: f64 = 0.1;

/// The relative tolerances (length, area) for a recipe.
fn tolerances(recipe: &Value) -> (f64, f64) {
    match recipe["kind"].as_str() {
        Some("surface" | "extrusion") => (TRACED, TRACED_AREA),
        _ => (EXACT, EXACT),
    }
}

/// Whether a recipe has curved faces (its sections through them are fitted curves).
fn curved(recipe: &Value) -> bool {
    recipe["kind"].as_str() != Some("box")
}

fn relative(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs().max(1e-300)
}

/// The curves by decreasing length, with their lengths.
fn by_length(section: &BrepSection) -> Vec<(f64, &Curve)> {
    let mut out: Vec<(f64, &Curve)> = section.curves.iter().map(|c| (c.length(), c)).collect();
    out.sort_by(|a, b| b.0.total_cmp(&a.0));
    out
}

fn check_section(
    id: &str,
    got: &BrepSection,
    expected: &Value,
    cut: &Plane,
    (rel_length, rel_area): (f64, f64),
    fit_tolerance: f64,
    f: &mut Failures,
) {
    let want = expected["curves"].as_array().unwrap();
    let curves = by_length(got);
    f.check(curves.len() == want.len(), || {
        format!(
            "{id}: {} curves of lengths {:?}, expected {}",
            curves.len(),
            curves.iter().map(|c| c.0).collect::<Vec<_>>(),
            want.len()
        )
    });
    for ((length, c), w) in curves.iter().zip(want) {
        let want_length = num(&w["length"]);
        f.check(relative(*length, want_length) <= rel_length, || {
            format!("{id}: length {length}, expected {want_length}")
        });
        let closed = w["closed"].as_bool().unwrap();
        f.check(c.is_closed() == closed, || {
            format!("{id}: curve of length {length} closed is {}", c.is_closed())
        });
        if let Some(area) = w["enclosed_area"].as_f64()
            && c.is_closed()
        {
            let got_area = enclosed_area(c, cut);
            let allowed = rel_area * area.abs() + fit_tolerance * length;
            f.check((got_area - area).abs() <= allowed, || {
                format!("{id}: enclosed area {got_area}, expected {area} (within {allowed:e})")
            });
        }
        if let Some(ends) = w["end_points"].as_array() {
            let (s, e) = (c.start_point(), c.end_point());
            let (a, b) = (point(&ends[0]), point(&ends[1]));
            let matches =
                |x: Point3, y: Point3| x.distance(y) <= POINTS * y.to_vector().length().max(1.0);
            f.check(
                (matches(s, a) && matches(e, b)) || (matches(s, b) && matches(e, a)),
                || format!("{id}: ends {s:?} {e:?}, expected {a:?} {b:?}"),
            );
        }
    }
    let want_points = expected["points"].as_array().unwrap();
    f.check(got.points.len() == want_points.len(), || {
        format!("{id}: points {:?}, expected {want_points:?}", got.points)
    });
    for (p, w) in got.points.iter().zip(want_points) {
        let w = Point3::from_array(triple(w));
        f.check(
            p.distance(w) <= POINTS * w.to_vector().length().max(1.0),
            || format!("{id}: point {p:?}, expected {w:?}"),
        );
    }
}

#[test]
fn brep_plane_cases() {
    let mut f = Failures::default();
    let mut replayed = 0;
    for case in cases("brep_plane") {
        let id = case["id"].as_str().unwrap();
        let inputs = &case["inputs"];
        let b: Brep = brep(&inputs["brep"]);
        let cut = plane(&inputs["plane"]);
        match b.intersect_plane(&cut, num(&inputs["tolerance"])) {
            Ok(got) => {
                replayed += 1;
                let tolerance = num(&inputs["tolerance"]);
                let fit = if curved(&inputs["brep"]) {
                    FIT * tolerance
                } else {
                    0.0
                };
                check_section(
                    id,
                    &got,
                    &case["expected"],
                    &cut,
                    tolerances(&inputs["brep"]),
                    fit,
                    &mut f,
                );
            }
            Err(e) => f.push(format!("{id}: {e}")),
        }
    }
    assert_eq!(replayed, 18, "every brep | plane case is replayed");
    f.finish("brep | plane");
}

#[test]
fn contour_cases() {
    let mut f = Failures::default();
    for case in cases("contour") {
        let id = case["id"].as_str().unwrap();
        let inputs = &case["inputs"];
        let b = brep(&inputs["brep"]);
        let (rel, _) = tolerances(&inputs["brep"]);
        let got = match b.contour(
            point(&inputs["point"]),
            vector(&inputs["direction"]),
            num(&inputs["distance"]),
            num(&inputs["tolerance"]),
        ) {
            Ok(got) => got,
            Err(e) => {
                f.push(format!("{id}: {e}"));
                continue;
            }
        };
        let planes = case["expected"]["planes"].as_array().unwrap();
        for w in planes {
            let k = w["k"].as_i64().unwrap();
            let Some(section) = got.iter().find(|s| s.index == k) else {
                f.push(format!("{id}: no plane k = {k}"));
                continue;
            };
            let origin = triple(&w["plane_origin"]);
            f.check(
                section.plane.origin.distance(Point3::from_array(origin)) <= 1e-12,
                || {
                    format!(
                        "{id} k = {k}: plane at {:?}, expected {origin:?}",
                        section.plane.origin
                    )
                },
            );
            let curves = by_length(&section.section);
            let count = w["curves"].as_u64().unwrap() as usize;
            f.check(curves.len() == count, || {
                format!(
                    "{id} k = {k}: {} curves {:?}, expected {count}",
                    curves.len(),
                    curves.iter().map(|c| c.0).collect::<Vec<_>>()
                )
            });
            let mut lengths: Vec<f64> = w["lengths"].as_array().unwrap().iter().map(num).collect();
            lengths.sort_by(|a, b| b.total_cmp(a));
            for ((length, c), want) in curves.iter().zip(&lengths) {
                f.check(relative(*length, *want) <= rel, || {
                    format!("{id} k = {k}: length {length}, expected {want}")
                });
                let closed = w["closed"]
                    .as_array()
                    .unwrap()
                    .iter()
                    .all(|x| x.as_bool() == Some(true));
                if closed {
                    f.check(c.is_closed(), || {
                        format!("{id} k = {k}: an open curve of length {length}")
                    });
                }
            }
        }
        for s in &got {
            if !planes.iter().any(|w| w["k"].as_i64() == Some(s.index)) {
                f.check(s.section.curves.is_empty(), || {
                    format!("{id}: plane k = {} has curves, expected none", s.index)
                });
            }
        }
    }
    f.finish("contour");
}

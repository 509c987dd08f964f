//! Replays the Brep | Brep cases of `tests/data/generated/occt-brep-brep.json` (OpenCASCADE's
//! `BRepAlgoAPI_Section`, written by `tools/oracle/brep_brep.py`) through
//! [`Brep::intersect_brep`], on the kernel's own B-reps of the same shapes
//! (`support/breps.rs`):
//!
//! - the total length of the curves, within [`LENGTH`] relative (OpenCASCADE's own edges are
//!   approximations, within their edge tolerance of about 1e-7, of the true intersection);
//! - the number of joined curves and whether each is closed: OpenCASCADE's edges connected
//!   end to end into wires;
//! - the curves' bounding box, within [`BOX`] (plus the reference's edge tolerance);
//! - every curve lying on both B-reps within the tolerance of the intersection.
//!
//! Every failing case is named and all failures are reported together.

mod support;

use locus_kernel::{Curve, Point3};
use serde_json::Value;
use support::breps::brep;
use support::{Failures, num, triple, worst_distance};

/// The tolerance the intersections are computed with.
const TOLERANCE: f64 = 1e-9;
/// Total lengths, relative. Measured: closed-form cases (spheres, boxes, a box and a sphere)
/// agree within 2e-12, traced ones (cylinders, cones, tori) within 2.5e-9.
const LENGTH: f64 = 1e-8;
/// Bounding box corners, absolute.
const BOX: f64 = 1e-6;

fn load() -> Value {
    let path = locus_test_data::generated_dir().join("occt-brep-brep.json");
    let text = std::fs::read_to_string(&path)
        .unwrap_or_else(|e| panic!("cannot read {}: {e}", path.display()));
    serde_json::from_str(&text).unwrap_or_else(|e| panic!("cannot parse {}: {e}", path.display()))
}

/// The tight box of the curves, from dense samples.
fn curves_box(curves: &[Curve]) -> ([f64; 3], [f64; 3]) {
    let mut lo = [f64::INFINITY; 3];
    let mut hi = [f64::NEG_INFINITY; 3];
    for c in curves {
        let n = c.to_nurbs();
        for w in n.span_breaks().windows(2) {
            for k in 0..=64 {
                let p: Point3 = n.point_at(w[0] + (w[1] - w[0]) * k as f64 / 64.0);
                for (i, x) in [p.x, p.y, p.z].into_iter().enumerate() {
                    lo[i] = lo[i].min(x);
                    hi[i] = hi[i].max(x);
                }
            }
        }
    }
    (lo, hi)
}

#[test]
fn brep_brep_matches_opencascade() {
    let doc = load();
    let cases = doc["cases"].as_array().expect("cases");
    assert!(cases.len() >= 8, "too few cases: {}", cases.len());
    let mut failures = Failures::default();
    for case in cases {
        let id = case["id"].as_str().expect("id");
        let (a, b) = (brep(&case["inputs"]["a"]), brep(&case["inputs"]["b"]));
        let expected = &case["expected"];
        let x = match a.intersect_brep(&b, TOLERANCE) {
            Ok(x) => x,
            Err(e) => {
                failures.push(format!("{id}: {e}"));
                continue;
            }
        };
        let length: f64 = x.curves.iter().map(Curve::length).sum();
        let want = num(&expected["length"]);
        failures.check((length - want).abs() <= LENGTH * want.max(1.0), || {
            format!("{id}: length {length}, OpenCASCADE {want}")
        });
        let mut closed: Vec<bool> = x.curves.iter().map(Curve::is_closed).collect();
        closed.sort_unstable();
        let want_closed: Vec<bool> = expected["wires_closed"]
            .as_array()
            .expect("wires_closed")
            .iter()
            .map(|v| v.as_bool().expect("bool"))
            .collect();
        failures.check(closed == want_closed, || {
            format!("{id}: curves closed {closed:?}, OpenCASCADE's wires {want_closed:?}")
        });
        if !expected["bbox"].is_null() && !x.curves.is_empty() {
            let (lo, hi) = curves_box(&x.curves);
            let slack = BOX + num(&expected["edge_tolerance"]);
            let (want_lo, want_hi) = (
                triple(&expected["bbox"]["min"]),
                triple(&expected["bbox"]["max"]),
            );
            for k in 0..3 {
                failures.check(
                    (lo[k] - want_lo[k]).abs() <= slack && (hi[k] - want_hi[k]).abs() <= slack,
                    || format!("{id}: box {lo:?}..{hi:?}, OpenCASCADE {want_lo:?}..{want_hi:?}"),
                );
            }
        }
        for (name, shape) in [("a", &a), ("b", &b)] {
            let d = worst_distance(&x.curves, shape);
            failures.check(d <= 10.0 * TOLERANCE, || {
                format!("{id}: a curve point lies {d} from B-rep {name}")
            });
        }
    }
    failures.finish("Brep | Brep oracle");
}

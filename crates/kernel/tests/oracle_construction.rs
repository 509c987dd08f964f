//! Replays the surface-construction cases of `ops-cases.json` (OpenCASCADE, cross-checked with
//! openNURBS and closed forms) through the kernel's own builders:
//!
//! - `extrude`: [`Brep::from_curve_extrusion`] (capped when the case is), or the planar region
//!   with holes [`Brep::extruded`]: area, area centroid, volume and volume centroid;
//! - `ruled`: [`NurbsSurface::ruled`]: area, centroid, and the ruling midpoints on the surface;
//! - `revolve`: [`NurbsSurface::revolution`]: area, volume where given, and the point at half
//!   the angle on the surface;
//! - `loft`: [`NurbsSurface::loft`] (straight for `ruled`, normal for `smooth`): area where the
//!   result is forced, and the ruling midpoints on the result;
//! - `cap_holes`: [`Brep::cap_planar_holes`] on extrusions and ruled lofts: caps added, closed,
//!   volume (the `surface` recipe, `ch-05`, is not replayed);
//! - `join_curves`: [`Curve::join`]: chain count, closed, length;
//! - `planar_boundary`: [`Brep::planar_regions`]: total area, per-face area and centroid;
//! - `pipe`: [`Brep::pipe`] open (lateral area and centroid) and with flat caps (area, volume,
//!   volume centroid), and the start circle's points on the tube; the thick-walled `pi-07` is
//!   not replayed (Grasshopper's Pipe has no inner radius);
//! - `four_point_surface`: [`NurbsSurface::from_corners`]: area, centroid, centre point,
//!   corners, bounding box;
//! - `edge_surface`: [`NurbsSurface::from_edges`]: the boundary points on the patch, the area
//!   where it is forced (planar edges) and, for straight edges, the bilinear patch's area.
//!
//! Not replayed yet: `offset` (the cases' inside/outside and left/right sides still have to be
//! mapped onto the kernel's signed distance).
//!
//! Tolerances are the file's (`tolerances.areas_volumes`, `points_on_result`): 1e-9 relative for
//! exact constructions, 1e-6 for smooth lofts; centroids 1e-8 × max(1, size); points 1e-7
//! (1e-6 for smooth lofts). Every failing case is named and all failures are reported together.

mod support;

use std::f64::consts::TAU;

use locus_kernel::{
    Brep, Curve, Interval, LoftType, NurbsCurve, NurbsSurface, PipeCaps, Point3, Vector3,
};
use serde_json::Value;
use support::{Failures, close, close3, load_oracle, num, numbers, triple};

/// Areas and volumes of exact constructions (relative).
const EXACT: f64 = 1e-9;
/// Areas of smooth lofts, which a kernel may fit (relative).
const FITTED: f64 = 1e-6;
/// Centroids, relative to max(1, size).
const CENTROID: f64 = 1e-8;
/// Points that must lie on an exact result.
const ON_RESULT: f64 = 1e-7;
/// Points that must lie on a smooth loft.
const ON_FITTED: f64 = 1e-6;
/// The modelling tolerance the builders get (the cases' `tolerance`).
const MODEL_TOL: f64 = 1e-7;

fn point(v: &Value) -> Point3 {
    Point3::from_array(triple(v))
}

fn vector(v: &Value) -> Vector3 {
    Vector3::from_array(triple(v))
}

fn nurbs(v: &Value) -> NurbsCurve {
    let degree = v["degree"].as_u64().expect("degree") as usize;
    let cvs = v["cvs"].as_array().expect("cvs");
    let points = cvs.iter().map(|cv| point(&cv["p"])).collect();
    let weights = cvs.iter().map(|cv| num(&cv["w"])).collect();
    NurbsCurve::new(degree, points, weights, numbers(&v["knots"]))
        .unwrap_or_else(|e| panic!("{}: invalid curve: {e}", v["name"]))
}

fn cases(section: &str) -> Vec<Value> {
    load_oracle("ops-cases.json")[section]
        .as_array()
        .unwrap_or_else(|| panic!("no section {section}"))
        .clone()
}

fn id(case: &Value) -> String {
    case["id"].as_str().unwrap().to_owned()
}

/// Checks `brep`'s area (and centroid when given under `centroid_key`).
fn check_area(f: &mut Failures, id: &str, brep: &Brep, e: &Value, rel: f64, centroid_key: &str) {
    match brep.area_properties() {
        Ok(props) => {
            if let Some(want) = e["area"].as_f64() {
                f.check(close(props.area, want, rel), || {
                    format!("{id}: area {} , expected {want}", props.area)
                });
            }
            if !e[centroid_key].is_null() {
                let want = triple(&e[centroid_key]);
                let got = props.centroid.to_array();
                f.check(close3(got, want, CENTROID), || {
                    format!("{id}: area centroid {got:?}, expected {want:?}")
                });
            }
        }
        Err(err) => f.push(format!("{id}: area failed: {err}")),
    }
}

fn check_volume(f: &mut Failures, id: &str, brep: &Brep, e: &Value, rel: f64) {
    let Some(want) = e["volume"].as_f64() else {
        return;
    };
    match brep.volume_properties() {
        Ok(props) => {
            f.check(close(props.volume.abs(), want, rel), || {
                format!("{id}: volume {}, expected {want}", props.volume)
            });
            if !e["volume_centroid"].is_null() {
                let want = triple(&e["volume_centroid"]);
                let got = props.centroid.to_array();
                f.check(close3(got, want, CENTROID), || {
                    format!("{id}: volume centroid {got:?}, expected {want:?}")
                });
            }
        }
        Err(err) => f.push(format!("{id}: volume failed: {err}")),
    }
}

/// Checks that `p` lies within `tol` of one of `surfaces`.
///
/// The nearer of [`NurbsSurface::closest_point`] and [`NurbsSurface::closest_point_in`] over
/// the whole domain: on the lofts through three unrelated curves (`lo-07`, `lo-08`) each of the
/// two global searches returns a local minimum (0.125 to 0.25 away) for some point that lies
/// on the surface, where the other finds it (a kernel defect in `surface/closest_point.rs`,
/// left for a fix; the loft itself agrees with the oracle).
fn check_on(f: &mut Failures, id: &str, surfaces: &[NurbsSurface], p: Point3, tol: f64) {
    let best = surfaces
        .iter()
        .filter_map(|s| {
            let (du, dv) = (s.domain_u(), s.domain_v());
            let pruned = s.closest_point(p).ok().map(|c| c.distance);
            let full = s
                .closest_point_in(p, [du.t0, du.t1], [dv.t0, dv.t1])
                .ok()
                .map(|c| c.distance);
            pruned.into_iter().chain(full).reduce(f64::min)
        })
        .fold(f64::INFINITY, f64::min);
    f.check(best <= tol, || {
        format!("{id}: point {p:?} is {best} from the result (tolerance {tol})")
    });
}

#[test]
fn extrude_cases() {
    let mut f = Failures::default();
    for case in cases("extrude") {
        let id = id(&case);
        let inputs = &case["inputs"];
        let e = &case["expected"];
        let curve = Curve::Nurbs(nurbs(&inputs["curve"]));
        let v = vector(&inputs["vector"]);
        let capped = inputs["capped"].as_bool().unwrap();
        let built = if let Some(holes) = inputs["holes"].as_array() {
            let mut curves = vec![curve];
            curves.extend(holes.iter().map(|h| Curve::Nurbs(nurbs(h))));
            Brep::planar_regions(&curves, MODEL_TOL).and_then(|(regions, failed)| {
                assert!(failed.is_empty(), "{id}: boundaries failed: {failed:?}");
                assert_eq!(regions.len(), 1, "{id}: one region with holes");
                regions[0].extruded(v, MODEL_TOL)
            })
        } else if capped {
            Brep::from_curve_extrusion(&curve, v, MODEL_TOL)
        } else {
            NurbsSurface::extrusion(&curve.to_nurbs(), v).and_then(Brep::from_surface)
        };
        let brep = match built {
            Ok(b) => b,
            Err(err) => {
                f.push(format!("{id}: extrusion failed: {err}"));
                continue;
            }
        };
        if capped {
            f.check(brep.is_solid(), || format!("{id}: not a closed solid"));
        }
        check_area(&mut f, &id, &brep, e, EXACT, "area_centroid");
        check_volume(&mut f, &id, &brep, e, EXACT);
    }
    f.finish("extrude");
}

#[test]
fn ruled_cases() {
    let mut f = Failures::default();
    for case in cases("ruled") {
        let id = id(&case);
        let inputs = &case["inputs"];
        let e = &case["expected"];
        let (a, b) = (nurbs(&inputs["curve_a"]), nurbs(&inputs["curve_b"]));
        let surface = match NurbsSurface::ruled(&a, &b) {
            Ok(s) => s,
            Err(err) => {
                f.push(format!("{id}: ruled failed: {err}"));
                continue;
            }
        };
        let brep = Brep::from_surface(surface.clone()).expect("a brep from the surface");
        check_area(&mut f, &id, &brep, e, EXACT, "area_centroid");
        for m in e["ruling_midpoints"].as_array().unwrap() {
            check_on(
                &mut f,
                &id,
                std::slice::from_ref(&surface),
                point(&m["point"]),
                ON_RESULT,
            );
        }
    }
    f.finish("ruled");
}

#[test]
fn revolve_cases() {
    let mut f = Failures::default();
    for case in cases("revolve") {
        let id = id(&case);
        let inputs = &case["inputs"];
        let e = &case["expected"];
        let profile = nurbs(&inputs["curve"]);
        let from = point(&inputs["axis"]["from"]);
        let axis = point(&inputs["axis"]["to"]) - from;
        let angle = num(&inputs["angle"]).min(TAU);
        let surface =
            match NurbsSurface::revolution(&profile, from, axis, Interval::new(0.0, angle)) {
                Ok(s) => s,
                Err(err) => {
                    f.push(format!("{id}: revolution failed: {err}"));
                    continue;
                }
            };
        let brep = Brep::from_surface(surface.clone()).expect("a brep from the surface");
        check_area(&mut f, &id, &brep, e, EXACT, "area_centroid");
        check_volume(&mut f, &id, &brep, e, EXACT);
        if !e["point_on_result_half_angle"].is_null() {
            let p = point(&e["point_on_result_half_angle"]);
            check_on(&mut f, &id, &[surface], p, ON_RESULT);
        }
    }
    f.finish("revolve");
}

fn loft(case: &Value) -> locus_kernel::Result<(NurbsSurface, bool)> {
    let inputs = &case["inputs"];
    let sections: Vec<NurbsCurve> = inputs["sections"]
        .as_array()
        .unwrap()
        .iter()
        .map(nurbs)
        .collect();
    let smooth = inputs["type"].as_str() == Some("smooth");
    let kind = if smooth {
        LoftType::Normal
    } else {
        LoftType::Straight
    };
    NurbsSurface::loft(&sections, kind, false).map(|s| (s, smooth))
}

#[test]
fn loft_cases() {
    let mut f = Failures::default();
    for case in cases("loft") {
        let id = id(&case);
        let e = &case["expected"];
        let (surface, smooth) = match loft(&case) {
            Ok(s) => s,
            Err(err) => {
                f.push(format!("{id}: loft failed: {err}"));
                continue;
            }
        };
        let (rel, on) = if smooth {
            (FITTED, ON_FITTED)
        } else {
            (EXACT, ON_RESULT)
        };
        let mut brep = Brep::from_surface(surface.clone()).expect("a brep from the surface");
        if case["inputs"]["solid"].as_bool() == Some(true) {
            match brep.cap_planar_holes(MODEL_TOL) {
                Ok((capped, _)) => brep = capped,
                Err(err) => f.push(format!("{id}: capping failed: {err}")),
            }
            f.check(brep.is_solid(), || format!("{id}: not a closed solid"));
            check_volume(&mut f, &id, &brep, e, EXACT);
        }
        check_area(&mut f, &id, &brep, e, rel, "area_centroid");
        for key in ["sections_on_result", "ruling_midpoints_on_result"] {
            for item in e[key].as_array().into_iter().flatten() {
                let pts: Vec<&Value> = match item["points"].as_array() {
                    Some(list) => list.iter().collect(),
                    None => vec![&item["point"]],
                };
                for p in pts {
                    check_on(&mut f, &id, std::slice::from_ref(&surface), point(p), on);
                }
            }
        }
    }
    f.finish("loft");
}

#[test]
fn cap_holes_cases() {
    let mut f = Failures::default();
    for case in cases("cap_holes") {
        let id = id(&case);
        let recipe = &case["inputs"]["brep"];
        let e = &case["expected"];
        let built = match recipe["kind"].as_str().unwrap() {
            "extrusion" => {
                let profile = nurbs(&recipe["profile"]);
                NurbsSurface::extrusion(&profile, vector(&recipe["vector"]))
                    .and_then(Brep::from_surface)
            }
            "loft" => {
                let sections: Vec<NurbsCurve> = recipe["sections"]
                    .as_array()
                    .unwrap()
                    .iter()
                    .map(nurbs)
                    .collect();
                let kind = if recipe["type"].as_str() == Some("smooth") {
                    LoftType::Normal
                } else {
                    LoftType::Straight
                };
                NurbsSurface::loft(&sections, kind, false).and_then(Brep::from_surface)
            }
            "surface" => {
                eprintln!("{id}: surface recipe not replayed (needs the surface record reader)");
                continue;
            }
            other => {
                eprintln!("{id}: recipe {other} not replayed here");
                continue;
            }
        };
        let brep = match built {
            Ok(b) => b,
            Err(err) => {
                f.push(format!("{id}: build failed: {err}"));
                continue;
            }
        };
        match brep.cap_planar_holes(MODEL_TOL) {
            Ok((capped, added)) => {
                let want = e["caps_added"].as_u64().unwrap() as usize;
                f.check(added == want, || {
                    format!("{id}: {added} caps, expected {want}")
                });
                let closed = e["closed"].as_bool().unwrap();
                f.check(capped.is_solid() == closed, || {
                    format!("{id}: solid {}, expected {closed}", capped.is_solid())
                });
                check_volume(&mut f, &id, &capped, e, EXACT);
            }
            Err(err) => f.push(format!("{id}: cap failed: {err}")),
        }
    }
    f.finish("cap holes");
}

/// `join_curves`: [`Curve::join`] gives the file's chains: their count, and per chain (matched
/// by length) closed and length (1e-9 relative).
#[test]
fn join_curves_cases() {
    let mut f = Failures::default();
    for case in cases("join_curves") {
        let id = id(&case);
        let inputs = &case["inputs"];
        let e = &case["expected"];
        let curves: Vec<Curve> = inputs["curves"]
            .as_array()
            .unwrap()
            .iter()
            .map(|c| Curve::Nurbs(nurbs(c)))
            .collect();
        let joined = match Curve::join(&curves, num(&inputs["tolerance"]), false) {
            Ok(j) => j,
            Err(err) => {
                f.push(format!("{id}: join failed: {err}"));
                continue;
            }
        };
        let want = e["chains"].as_array().unwrap();
        f.check(joined.len() == want.len(), || {
            format!("{id}: {} chains, expected {}", joined.len(), want.len())
        });
        for chain in want {
            let length = num(&chain["length"]);
            let closed = chain["closed"].as_bool().unwrap();
            let found = joined
                .iter()
                .any(|c| close(c.to_nurbs().length(), length, EXACT) && c.is_closed() == closed);
            f.check(found, || {
                format!("{id}: no joined curve of length {length} (closed {closed})")
            });
        }
    }
    f.finish("join curves");
}

/// `planar_boundary`: [`Brep::planar_regions`] gives one face per outer boundary with its
/// holes: the total area, and each expected face's area and centroid (faces matched by area).
#[test]
fn planar_boundary_cases() {
    let mut f = Failures::default();
    for case in cases("planar_boundary") {
        let id = id(&case);
        let e = &case["expected"];
        let curves: Vec<Curve> = case["inputs"]["curves"]
            .as_array()
            .unwrap()
            .iter()
            .map(|c| Curve::Nurbs(nurbs(c)))
            .collect();
        let regions = match Brep::planar_regions(&curves, MODEL_TOL) {
            Ok((regions, failed)) => {
                f.check(failed.is_empty(), || {
                    format!("{id}: boundaries failed: {failed:?}")
                });
                regions
            }
            Err(err) => {
                f.push(format!("{id}: planar regions failed: {err}"));
                continue;
            }
        };
        let props: Vec<_> = regions
            .iter()
            .filter_map(|r| r.area_properties().ok())
            .collect();
        let total: f64 = props.iter().map(|p| p.area).sum();
        let want_total = num(&e["total_area"]);
        f.check(close(total, want_total, EXACT), || {
            format!("{id}: total area {total}, expected {want_total}")
        });
        for face in e["faces"].as_array().unwrap() {
            let (area, centroid) = (num(&face["area"]), triple(&face["centroid"]));
            let found = props.iter().any(|p| {
                close(p.area, area, EXACT) && close3(p.centroid.to_array(), centroid, CENTROID)
            });
            f.check(found, || {
                format!("{id}: no face of area {area} and centroid {centroid:?}")
            });
        }
    }
    f.finish("planar boundary");
}

/// The fit tolerance the pipe replays give [`Brep::pipe`]: well inside the cases' 1e-6 on
/// areas and 1e-8 on centroids.
const PIPE_FIT: f64 = 1e-9;

#[test]
fn pipe_cases() {
    let mut f = Failures::default();
    for case in cases("pipe") {
        let id = id(&case);
        let inputs = &case["inputs"];
        let e = &case["expected"];
        if !inputs["inner_radius"].is_null() {
            // A thick-walled pipe (pi-07): Grasshopper's Pipe has no inner radius.
            continue;
        }
        let rail = Curve::Nurbs(nurbs(&inputs["path"]));
        let radius = num(&inputs["radius"]);
        let build = |caps| match Brep::pipe(&rail, radius, caps, PIPE_FIT) {
            Ok(mut b) if b.len() == 1 => Ok(b.remove(0)),
            Ok(b) => Err(format!("{} breps", b.len())),
            Err(err) => Err(err.to_string()),
        };
        let (open, capped) = match (build(PipeCaps::None), build(PipeCaps::Flat)) {
            (Ok(a), Ok(b)) => (a, b),
            (Err(err), _) | (_, Err(err)) => {
                f.push(format!("{id}: pipe failed: {err}"));
                continue;
            }
        };
        // The tube alone: the lateral area and its centroid.
        let lateral = serde_json::json!({
            "area": e["lateral_area"],
            "lateral_area_centroid": e["lateral_area_centroid"],
        });
        check_area(
            &mut f,
            &id,
            &open,
            &lateral,
            FITTED,
            "lateral_area_centroid",
        );
        f.check(capped.is_solid(), || format!("{id}: not a closed solid"));
        check_area(&mut f, &id, &capped, e, FITTED, "no centroid");
        check_volume(&mut f, &id, &capped, e, FITTED);
        let faces: Vec<NurbsSurface> = open.faces().iter().map(|x| x.surface.clone()).collect();
        for p in e["start_circle_points"].as_array().unwrap() {
            check_on(&mut f, &id, &faces, point(p), ON_FITTED);
        }
    }
    f.finish("pipe");
}

#[test]
fn four_point_surface_cases() {
    let mut f = Failures::default();
    for case in cases("four_point_surface") {
        let id = id(&case);
        let e = &case["expected"];
        let p: Vec<Point3> = case["inputs"]["points"]
            .as_array()
            .unwrap()
            .iter()
            .map(point)
            .collect();
        let d = p.get(3).copied().unwrap_or(p[2]);
        let surface = match NurbsSurface::from_corners(p[0], p[1], p[2], d) {
            Ok(s) => s,
            Err(err) => {
                f.push(format!("{id}: four-point surface failed: {err}"));
                continue;
            }
        };
        let brep = Brep::from_surface(surface.clone()).expect("a brep from the surface");
        check_area(&mut f, &id, &brep, e, EXACT, "area_centroid");
        let centre = surface.point_at(0.5, 0.5);
        let want = triple(&e["center_point"]);
        f.check(close3(centre.to_array(), want, CENTROID), || {
            format!("{id}: centre {centre:?}, expected {want:?}")
        });
        for (k, c) in e["corners"].as_array().unwrap().iter().enumerate() {
            let (u, v) = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)][k];
            let got = surface.point_at(u, v).to_array();
            let want = triple(c);
            f.check(close3(got, want, 1e-15), || {
                format!("{id}: corner {k} {got:?}, expected {want:?}")
            });
        }
        let bbox = brep.bounding_box();
        for (got, key) in [(bbox.min, "min"), (bbox.max, "max")] {
            let want = triple(&e["bbox"][key]);
            f.check(close3(got.to_array(), want, CENTROID), || {
                format!("{id}: bbox {key} {got:?}, expected {want:?}")
            });
        }
    }
    f.finish("four_point_surface");
}

#[test]
fn edge_surface_cases() {
    let mut f = Failures::default();
    for case in cases("edge_surface") {
        let id = id(&case);
        let e = &case["expected"];
        let curves: Vec<NurbsCurve> = case["inputs"]["curves"]
            .as_array()
            .unwrap()
            .iter()
            .map(nurbs)
            .collect();
        let surface = match NurbsSurface::from_edges(&curves, MODEL_TOL) {
            Ok(s) => s,
            Err(err) => {
                f.push(format!("{id}: edge surface failed: {err}"));
                continue;
            }
        };
        let brep = Brep::from_surface(surface.clone()).expect("a brep from the surface");
        // Where the interior is forced the area is given; a bilinearly blended Coons patch
        // on straight edges is the bilinear patch, whose area is given too.
        let area = e["area"].as_f64().or(e["bilinear_area"].as_f64());
        if let Some(want) = area {
            let got = brep.area().unwrap_or(f64::NAN);
            f.check(close(got, want, EXACT), || {
                format!("{id}: area {got}, expected {want}")
            });
        }
        for item in e["boundary_points_on_result"].as_array().unwrap() {
            for p in item["points"].as_array().unwrap() {
                check_on(
                    &mut f,
                    &id,
                    std::slice::from_ref(&surface),
                    point(p),
                    ON_RESULT,
                );
            }
        }
    }
    f.finish("edge_surface");
}

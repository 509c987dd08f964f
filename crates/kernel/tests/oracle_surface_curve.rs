//! Replays the surface and B-rep intersection cases of `ops-cases.json` (OpenCASCADE,
//! cross-checked with openNURBS, closed forms and independent Newton solves) through the kernel:
//!
//! - `surface_line`: [`NurbsSurface::intersect_curve`] on the segment `from → to` (parameter
//!   `t` in `[0, 1]`, as Rhino's `Line.PointAt`): every point with its `t`, `u` and `v` (a
//!   closed direction's seam at either end of its domain; `u` not compared where the case says
//!   it is arbitrary, at a pole), tangential points to the tangential tolerance, every overlap
//!   with its interval; and [`NurbsSurface::intersect_line`] on the infinite line must find
//!   the same points (the cases' lines meet their surfaces only on the segments);
//! - `brep_curve`: [`Brep::intersect_curve`] on the kernel's own B-rep of the recipe
//!   (`support/breps.rs`): every point with its curve parameter, every overlap.
//!
//! Tolerances are the file's (`tolerances.intersection_points`): points 1e-9 × max(1,
//! |coordinates|), parameters 1e-9 × the domain's length, tangential points 1e-6. Every failing
//! case is named and all failures are reported together.

mod support;

use locus_kernel::{Curve, Interval, Line, NurbsSurface};
use serde_json::Value;
use support::breps::{brep, nurbs_curve, nurbs_surface, point};
use support::{Failures, close3, load_oracle, num};

/// Agreement of points and parameters at transversal events.
const REL: f64 = 1e-9;
/// Agreement at tangential events, where a double root is determined only to about √ε.
const TANGENTIAL: f64 = 1e-6;

fn cases(section: &str) -> Vec<Value> {
    load_oracle("ops-cases.json")[section]
        .as_array()
        .unwrap_or_else(|| panic!("no section {section}"))
        .clone()
}

/// Whether parameter `got` matches `want` within `rel` of the domain's length, either end of a
/// closed direction's domain counting as the same.
fn same_parameter(got: f64, want: f64, domain: Interval, closed: bool, rel: f64) -> bool {
    let tol = rel * domain.length().abs().max(1.0);
    if (got - want).abs() <= tol {
        return true;
    }
    closed && (got - want).abs() >= domain.length().abs() - tol
}

/// Whether a surface is closed in `u` (`in_u`) or `v`: its first and last rows of control
/// points coincide.
fn closed_in(s: &NurbsSurface, in_u: bool) -> bool {
    let (nu, nv) = (s.count_u(), s.count_v());
    if in_u {
        (0..nv).all(|j| {
            s.control_point(0, j)
                .unwrap()
                .distance(s.control_point(nu - 1, j).unwrap())
                < 1e-12
        })
    } else {
        (0..nu).all(|i| {
            s.control_point(i, 0)
                .unwrap()
                .distance(s.control_point(i, nv - 1).unwrap())
                < 1e-12
        })
    }
}

#[test]
fn surface_line_cases() {
    let mut failures = Failures::default();
    let all = cases("surface_line");
    assert_eq!(all.len(), 14);
    for case in &all {
        let id = case["id"].as_str().unwrap();
        let inputs = &case["inputs"];
        let surface = nurbs_surface(&inputs["surface"]);
        let line = Line::new(point(&inputs["line"]["from"]), point(&inputs["line"]["to"]));
        let tolerance = num(&inputs["tolerance"]);
        let segment = Curve::Line {
            line,
            domain: Interval::UNIT,
        };
        let expected = &case["expected"];
        let want_points = expected["points"].as_array().unwrap();
        let want_overlaps = expected["overlaps"].as_array().unwrap();
        let (closed_u, closed_v) = (closed_in(&surface, true), closed_in(&surface, false));
        for (how, found) in [
            ("segment", surface.intersect_curve(&segment, tolerance)),
            ("infinite line", surface.intersect_line(&line, tolerance)),
        ] {
            let found = match found {
                Ok(f) => f,
                Err(e) => {
                    failures.push(format!("{id} ({how}): error {e}"));
                    continue;
                }
            };
            if found.points.len() != want_points.len()
                || found.overlaps.len() != want_overlaps.len()
            {
                failures.push(format!(
                    "{id} ({how}): {} points and {} overlaps, want {} and {}: {found:?}",
                    found.points.len(),
                    found.overlaps.len(),
                    want_points.len(),
                    want_overlaps.len()
                ));
                continue;
            }
            for (got, want) in found.points.iter().zip(want_points) {
                let tangential = want["tangential"].as_bool().unwrap_or(false);
                let rel = if tangential { TANGENTIAL } else { REL };
                let t = num(&want["t"]);
                failures.check(same_parameter(got.t, t, Interval::UNIT, false, rel), || {
                    format!("{id} ({how}): t {} want {t}", got.t)
                });
                failures.check(
                    close3(got.point.to_array(), support::triple(&want["point"]), rel),
                    || format!("{id} ({how}): point {:?} want {}", got.point, want["point"]),
                );
                failures.check(got.tangential == tangential, || {
                    format!(
                        "{id} ({how}): tangential {} want {tangential}",
                        got.tangential
                    )
                });
                let on = surface.point_at(got.u, got.v);
                failures.check(
                    close3(on.to_array(), support::triple(&want["point"]), rel),
                    || format!("{id} ({how}): S(u, v) = {on:?} want {}", want["point"]),
                );
                if !want["u_arbitrary"].as_bool().unwrap_or(false) {
                    let u = num(&want["u"]);
                    failures.check(
                        same_parameter(got.u, u, surface.domain_u(), closed_u, rel),
                        || format!("{id} ({how}): u {} want {u}", got.u),
                    );
                }
                let v = num(&want["v"]);
                failures.check(
                    same_parameter(got.v, v, surface.domain_v(), closed_v, rel),
                    || format!("{id} ({how}): v {} want {v}", got.v),
                );
            }
            for (got, want) in found.overlaps.iter().zip(want_overlaps) {
                let t = [num(&want["t"][0]), num(&want["t"][1])];
                failures.check(
                    (got.t.t0 - t[0]).abs() <= REL && (got.t.t1 - t[1]).abs() <= REL,
                    || format!("{id} ({how}): overlap {:?} want {t:?}", got.t),
                );
            }
        }
    }
    failures.finish("surface_line");
}

#[test]
fn brep_curve_cases() {
    let mut failures = Failures::default();
    let all = cases("brep_curve");
    assert_eq!(all.len(), 11);
    for case in &all {
        let id = case["id"].as_str().unwrap();
        let inputs = &case["inputs"];
        let b = brep(&inputs["brep"]);
        let curve = Curve::Nurbs(nurbs_curve(&inputs["curve"]));
        let domain = curve.domain();
        let tolerance = num(&inputs["tolerance"]);
        let expected = &case["expected"];
        let want_points = expected["points"].as_array().unwrap();
        let want_overlaps = expected["overlaps"].as_array().unwrap();
        let found = match b.intersect_curve(&curve, tolerance) {
            Ok(f) => f,
            Err(e) => {
                failures.push(format!("{id}: error {e}"));
                continue;
            }
        };
        if found.points.len() != want_points.len() || found.overlaps.len() != want_overlaps.len() {
            failures.push(format!(
                "{id}: {} points and {} overlaps, want {} and {}: {found:?}",
                found.points.len(),
                found.overlaps.len(),
                want_points.len(),
                want_overlaps.len()
            ));
            continue;
        }
        for (got, want) in found.points.iter().zip(want_points) {
            let tangential = want["tangential"].as_bool().unwrap_or(false);
            let rel = if tangential { TANGENTIAL } else { REL };
            let t = num(&want["t"]);
            failures.check(same_parameter(got.hit.t, t, domain, false, rel), || {
                format!("{id}: t {} want {t}", got.hit.t)
            });
            failures.check(
                close3(
                    got.hit.point.to_array(),
                    support::triple(&want["point"]),
                    rel,
                ),
                || format!("{id}: point {:?} want {}", got.hit.point, want["point"]),
            );
            if want.get("tangential").is_some() {
                failures.check(got.hit.tangential == tangential, || {
                    format!("{id}: tangential {} want {tangential}", got.hit.tangential)
                });
            }
            let surface = &b.faces()[got.face].surface;
            let on = surface.point_at(got.hit.u, got.hit.v);
            failures.check(
                close3(on.to_array(), support::triple(&want["point"]), rel),
                || format!("{id}: S(u, v) = {on:?} want {}", want["point"]),
            );
        }
        for (got, want) in found.overlaps.iter().zip(want_overlaps) {
            let t = [num(&want["t"][0]), num(&want["t"][1])];
            failures.check(
                same_parameter(got.t.t0, t[0], domain, false, REL)
                    && same_parameter(got.t.t1, t[1], domain, false, REL),
                || format!("{id}: overlap {:?} want {t:?}", got.t),
            );
        }
    }
    failures.finish("brep_curve");
}

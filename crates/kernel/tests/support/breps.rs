//! The B-rep recipes of `ops-cases.json` (`conventions.breps`), built with the kernel's own
//! builders: box, sphere, cylinder, cone, torus (a circle revolved a full turn), one untrimmed
//! surface, the extrusion of a curve (capped when the recipe says so), the revolution of a
//! curve about an axis, and a planar face bounded by closed curves (outer and holes).

use std::f64::consts::TAU;

use locus_kernel::{
    Brep, Circle, Cone, Curve, Cylinder, Interval, NurbsCurve, NurbsSurface, OrientedBox, Plane,
    Point3, Sphere, Vector3,
};
use serde_json::Value;

use super::{num, numbers, triple};

/// A point from a JSON triple.
pub fn point(v: &Value) -> Point3 {
    Point3::from_array(triple(v))
}

/// A vector from a JSON triple.
pub fn vector(v: &Value) -> Vector3 {
    Vector3::from_array(triple(v))
}

/// A plane record: origin, x and y axes, normal.
pub fn plane(v: &Value) -> Plane {
    Plane {
        origin: point(&v["origin"]),
        x_axis: vector(&v["x_axis"]),
        y_axis: vector(&v["y_axis"]),
        z_axis: vector(&v["normal"]),
    }
}

/// A NURBS curve record.
pub fn nurbs_curve(v: &Value) -> NurbsCurve {
    let degree = v["degree"].as_u64().expect("degree") as usize;
    let cvs = v["cvs"].as_array().expect("cvs");
    let points = cvs.iter().map(|cv| point(&cv["p"])).collect();
    let weights = cvs.iter().map(|cv| num(&cv["w"])).collect();
    NurbsCurve::new(degree, points, weights, numbers(&v["knots"]))
        .unwrap_or_else(|e| panic!("{}: invalid curve: {e}", v["name"]))
}

/// A NURBS surface record.
pub fn nurbs_surface(v: &Value) -> NurbsSurface {
    let rows = v["cvs_u_by_v"].as_array().expect("cvs_u_by_v");
    let points = rows
        .iter()
        .map(|r| {
            r.as_array()
                .unwrap()
                .iter()
                .map(|cv| point(&cv["p"]))
                .collect()
        })
        .collect();
    let weights = rows
        .iter()
        .map(|r| {
            r.as_array()
                .unwrap()
                .iter()
                .map(|cv| num(&cv["w"]))
                .collect()
        })
        .collect();
    NurbsSurface::new(
        v["degree_u"].as_u64().unwrap() as usize,
        v["degree_v"].as_u64().unwrap() as usize,
        points,
        weights,
        numbers(&v["knots_u"]),
        numbers(&v["knots_v"]),
    )
    .unwrap_or_else(|e| panic!("{}: invalid surface: {e}", v["name"]))
}

fn interval(v: &Value) -> Interval {
    Interval::new(num(&v[0]), num(&v[1]))
}

/// The B-rep of a recipe.
pub fn brep(v: &Value) -> Brep {
    let kind = v["kind"].as_str().expect("kind");
    let built = match kind {
        "box" => Brep::from_box(&OrientedBox::new(
            plane(&v["plane"]),
            interval(&v["x"]),
            interval(&v["y"]),
            interval(&v["z"]),
        )),
        "sphere" => {
            Brep::from_sphere(&Sphere::new(point(&v["center"]), num(&v["radius"])).unwrap())
        }
        "cylinder" => Brep::from_cylinder(
            &Cylinder::new(
                plane(&v["base_plane"]),
                num(&v["radius"]),
                num(&v["height"]),
            )
            .unwrap(),
            v["capped"].as_bool().unwrap(),
        ),
        "cone" => Brep::from_cone(
            &Cone::new(
                plane(&v["apex_plane"]),
                num(&v["height"]),
                num(&v["radius"]),
            )
            .unwrap(),
            v["capped"].as_bool().unwrap(),
        ),
        "torus" => {
            let p = plane(&v["plane"]);
            let centre = p.origin + p.x_axis * num(&v["major_radius"]);
            let circle_plane = Plane {
                origin: centre,
                x_axis: p.x_axis,
                y_axis: p.z_axis,
                z_axis: p.x_axis.cross(p.z_axis),
            };
            let profile = Circle::new(circle_plane, num(&v["minor_radius"]))
                .unwrap()
                .to_nurbs();
            let surface =
                NurbsSurface::revolution(&profile, p.origin, p.z_axis, Interval::new(0.0, TAU))
                    .unwrap();
            Brep::from_surface(surface)
        }
        "surface" => Brep::from_surface(nurbs_surface(&v["surface"])),
        "extrusion" => {
            let profile = Curve::Nurbs(nurbs_curve(&v["profile"]));
            assert!(v["capped"].as_bool().unwrap_or(false) == profile.is_closed());
            Brep::from_curve_extrusion(&profile, vector(&v["vector"]), 1e-7)
        }
        "revolution" => {
            let profile = nurbs_curve(&v["profile"]);
            let from = point(&v["axis"]["from"]);
            let axis = point(&v["axis"]["to"]) - from;
            let angle = num(&v["angle"]).min(TAU);
            let surface =
                NurbsSurface::revolution(&profile, from, axis, Interval::new(0.0, angle)).unwrap();
            Brep::from_surface(surface)
        }
        "planar-face" => {
            let mut loops = vec![vec![nurbs_curve(&v["outer"])]];
            for hole in v["holes"].as_array().into_iter().flatten() {
                loops.push(vec![nurbs_curve(hole)]);
            }
            Brep::from_planar_loops(&loops, 1e-7)
        }
        other => panic!("no recipe for a {other}"),
    };
    built.unwrap_or_else(|e| panic!("the {kind} recipe failed: {e}"))
}

//! A plain JSON description of geometry (points as `[x, y, z]` lists), shared by the golden
//! tests and the `archive_json` example that the rhino3dm end-to-end tests drive.

use locus_kernel::{
    Arc, Circle, Color, Curve, Interval, Line, Mesh, MeshFace, NurbsCurve, NurbsSurface, Plane,
    Point3, Polyline, Vector3,
};
use locus_opennurbs_archive::Geometry;
use serde_json::{Value, json};

fn p(p: Point3) -> Value {
    json!([p.x, p.y, p.z])
}
fn v(v: Vector3) -> Value {
    json!([v.x, v.y, v.z])
}
fn iv(i: Interval) -> Value {
    json!([i.t0, i.t1])
}
fn plane(pl: &Plane) -> Value {
    json!({"origin": p(pl.origin), "x": v(pl.x_axis), "y": v(pl.y_axis), "z": v(pl.z_axis)})
}

/// The description of a piece of geometry.
pub fn describe(g: &Geometry) -> Value {
    match g {
        Geometry::Mesh(m) => json!({
            "type": "mesh",
            "vertices": m.vertices().iter().map(|&q| p(q)).collect::<Vec<_>>(),
            "faces": m.faces().iter().map(|f| json!(f.vertices)).collect::<Vec<_>>(),
            "normals": m.normals().map(|ns| ns.iter().map(|&n| v(n)).collect::<Vec<_>>()),
            "colors": m.colors().map(|cs| cs.iter().map(|c| json!([c.r, c.g, c.b, c.a])).collect::<Vec<_>>()),
        }),
        Geometry::Curve(c) => match c {
            Curve::Nurbs(n) => json!({
                "type": "nurbs_curve",
                "degree": n.degree(),
                "points": n.points().iter().map(|&q| p(q)).collect::<Vec<_>>(),
                "weights": n.weights(),
                "knots": n.knots(),
            }),
            Curve::Line { line, domain } => json!({
                "type": "line", "from": p(line.from), "to": p(line.to), "domain": iv(*domain),
            }),
            Curve::Polyline { polyline, domain } => json!({
                "type": "polyline",
                "points": polyline.points().iter().map(|&q| p(q)).collect::<Vec<_>>(),
                "domain": iv(*domain),
            }),
            Curve::Arc { arc, domain } => json!({
                "type": "arc", "plane": plane(&arc.circle.plane), "radius": arc.circle.radius,
                "angle": iv(arc.angle), "domain": iv(*domain),
            }),
            Curve::Circle { circle, domain } => json!({
                "type": "circle", "plane": plane(&circle.plane), "radius": circle.radius,
                "domain": iv(*domain),
            }),
        },
        Geometry::Surface(s) => json!({
            "type": "nurbs_surface",
            "degree": [s.degree_u(), s.degree_v()],
            "count": [s.count_u(), s.count_v()],
            "points": s.points().iter().map(|&q| p(q)).collect::<Vec<_>>(),
            "weights": s.weights(),
            "knots_u": s.knots_u(),
            "knots_v": s.knots_v(),
        }),
    }
}

fn num(v: &Value, what: &str) -> Result<f64, String> {
    v.as_f64().ok_or_else(|| format!("{what} must be a number"))
}
fn pt(v: &Value) -> Result<Point3, String> {
    let a = v
        .as_array()
        .filter(|a| a.len() == 3)
        .ok_or("a point is [x, y, z]")?;
    Ok(Point3::new(
        num(&a[0], "x")?,
        num(&a[1], "y")?,
        num(&a[2], "z")?,
    ))
}
fn vec3(v: &Value) -> Result<Vector3, String> {
    let q = pt(v)?;
    Ok(Vector3::new(q.x, q.y, q.z))
}
fn pts(v: &Value) -> Result<Vec<Point3>, String> {
    v.as_array()
        .ok_or("points must be a list")?
        .iter()
        .map(pt)
        .collect()
}
fn nums(v: &Value) -> Result<Vec<f64>, String> {
    v.as_array()
        .ok_or("expected a list of numbers")?
        .iter()
        .map(|x| num(x, "item"))
        .collect()
}
fn interval(v: &Value) -> Result<Interval, String> {
    let a = nums(v)?;
    if a.len() != 2 {
        return Err("an interval is [t0, t1]".into());
    }
    Ok(Interval::new(a[0], a[1]))
}
fn usize_of(v: &Value) -> Result<usize, String> {
    v.as_u64()
        .map(|x| x as usize)
        .ok_or_else(|| "expected a count".into())
}
fn plane_of(v: &Value) -> Result<Plane, String> {
    Plane::from_frame(pt(&v["origin"])?, vec3(&v["x"])?, vec3(&v["y"])?).map_err(|e| e.to_string())
}

/// Builds geometry from its description.
pub fn build(d: &Value) -> Result<Geometry, String> {
    let e = |x: locus_kernel::Error| x.to_string();
    Ok(match d["type"].as_str().unwrap_or("") {
        "mesh" => {
            let faces = d["faces"]
                .as_array()
                .ok_or("faces must be a list")?
                .iter()
                .map(|f| {
                    let a: Vec<u32> = nums(f)?.iter().map(|&x| x as u32).collect();
                    match a[..] {
                        [a, b, c] => Ok(MeshFace::triangle(a, b, c)),
                        [a, b, c, d] => Ok(MeshFace {
                            vertices: [a, b, c, d],
                        }),
                        _ => Err("a face has 3 or 4 indices".to_string()),
                    }
                })
                .collect::<Result<Vec<_>, _>>()?;
            let mut m = Mesh::new(pts(&d["vertices"])?, faces).map_err(e)?;
            if !d["normals"].is_null() {
                let ns = d["normals"]
                    .as_array()
                    .ok_or("normals")?
                    .iter()
                    .map(vec3)
                    .collect::<Result<_, _>>()?;
                m = m.with_normals(ns).map_err(e)?;
            }
            if !d["colors"].is_null() {
                let cs = d["colors"]
                    .as_array()
                    .ok_or("colors")?
                    .iter()
                    .map(|c| {
                        let a = nums(c)?;
                        let a = |i: usize| a.get(i).copied().unwrap_or(255.0) as u8;
                        Ok(Color::rgba(a(0), a(1), a(2), a(3)))
                    })
                    .collect::<Result<_, String>>()?;
                m = m.with_colors(cs).map_err(e)?;
            }
            Geometry::Mesh(m)
        }
        "nurbs_curve" => {
            let points = pts(&d["points"])?;
            let weights = if d["weights"].is_null() {
                vec![1.0; points.len()]
            } else {
                nums(&d["weights"])?
            };
            Geometry::Curve(Curve::Nurbs(
                NurbsCurve::new(usize_of(&d["degree"])?, points, weights, nums(&d["knots"])?)
                    .map_err(e)?,
            ))
        }
        "line" => Geometry::Curve(Curve::Line {
            line: Line {
                from: pt(&d["from"])?,
                to: pt(&d["to"])?,
            },
            domain: interval(&d["domain"])?,
        }),
        "polyline" => Geometry::Curve(Curve::Polyline {
            polyline: Polyline::new(pts(&d["points"])?).map_err(e)?,
            domain: interval(&d["domain"])?,
        }),
        "arc" => Geometry::Curve(Curve::Arc {
            arc: Arc::new(
                Circle::new(plane_of(&d["plane"])?, num(&d["radius"], "radius")?).map_err(e)?,
                interval(&d["angle"])?,
            )
            .map_err(e)?,
            domain: interval(&d["domain"])?,
        }),
        "circle" => Geometry::Curve(Curve::Circle {
            circle: Circle::new(plane_of(&d["plane"])?, num(&d["radius"], "radius")?).map_err(e)?,
            domain: interval(&d["domain"])?,
        }),
        "nurbs_surface" => {
            let deg = nums(&d["degree"])?;
            let cnt = nums(&d["count"])?;
            if deg.len() != 2 || cnt.len() != 2 {
                return Err("degree and count are [u, v]".into());
            }
            let points = pts(&d["points"])?;
            let weights = if d["weights"].is_null() {
                vec![1.0; points.len()]
            } else {
                nums(&d["weights"])?
            };
            Geometry::Surface(
                NurbsSurface::from_flat(
                    [deg[0] as usize, deg[1] as usize],
                    [cnt[0] as usize, cnt[1] as usize],
                    points,
                    weights,
                    [nums(&d["knots_u"])?, nums(&d["knots_v"])?],
                )
                .map_err(e)?,
            )
        }
        other => return Err(format!("unknown geometry type {other:?}")),
    })
}

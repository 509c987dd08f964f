//! Surface › Analysis: Evaluate Surface, Surface Closest Point, Principal Curvature and Surface
//! Curvature.
//!
//! Surface parameters are given and returned as points `(u, v, 0)` in the surface's own
//! domain, as in Grasshopper. A `uv` outside the domain evaluates the surface's extension (the
//! polynomial of the nearest span, as Rhino's `PointAt` does) with a warning naming the domain;
//! reparameterize the surface input to give `uv` in `0` to `1`. Curvatures follow openNURBS's
//! signs: they are positive where the surface bends towards its normal `Su × Sv`, so Rhino's
//! sphere of radius `r` (outward normals) has principal curvatures `−1/r`, Gaussian curvature
//! `1/r²` and mean curvature `−1/r`.

use locus_kernel::{Interval, NurbsSurface, Point3};
use locus_runtime::{DataType, NodeError, NodeRegistry, NodeType, Port, Shared, Solve};

use crate::curve::input_name;
use crate::params::surface::surface_from_value;

/// Id of [`evaluate_surface`].
pub const EVALUATE_SURFACE: &str = "surface.evaluate_surface";
/// Id of [`surface_closest_point`].
pub const SURFACE_CLOSEST_POINT: &str = "surface.surface_closest_point";
/// Id of [`principal_curvature`].
pub const PRINCIPAL_CURVATURE: &str = "surface.principal_curvature";
/// Id of [`surface_curvature`].
pub const SURFACE_CURVATURE: &str = "surface.surface_curvature";

/// Relative slack, in units of the domain's size, within which a parameter counts as inside.
const DOMAIN_SLACK: f64 = 1e-12;

/// Registers the analysis nodes.
pub fn register(registry: &mut NodeRegistry) {
    for t in [
        evaluate_surface(),
        surface_closest_point(),
        principal_curvature(),
        surface_curvature(),
    ] {
        registry.register(t);
    }
}

fn analysis(id: &str, name: &str, nickname: &str) -> NodeType {
    NodeType::new(id, name, nickname, "Surface").subcategory("Analysis")
}

pub(crate) fn surface_port(doc: &str) -> Port {
    Port::new("Surface", "S", DataType::Surface).doc(doc)
}

pub(crate) fn uv_port(name: &str) -> Port {
    Port::new(name, "uv", DataType::Point).doc(
        "Parameters to evaluate at, as a point (u, v, 0) in the surface's domain (the z \
         coordinate is ignored). Outside the domain the surface is extended, with a warning.",
    )
}

/// The surface on item input `input` (see [`surface_from_value`] for the values that stand for
/// a surface).
///
/// # Errors
/// When the input has no item or holds a value that is not a surface.
pub(crate) fn surface_input(
    s: &Solve<'_>,
    input: usize,
) -> Result<Shared<NurbsSurface>, NodeError> {
    if let Some(srf) = s.item_opt::<Shared<NurbsSurface>>(input) {
        return Ok(srf.clone());
    }
    let Some(value) = s.value(input) else {
        return Err(format!("input {} has no surface", input_name(s, input)).into());
    };
    surface_from_value(&value).ok_or_else(|| {
        format!(
            "input {}: a {} is not a surface (a B-rep must have exactly one face)",
            input_name(s, input),
            value.data_type()
        )
        .into()
    })
}

/// Whether `t` lies in `d` up to [`DOMAIN_SLACK`].
fn within(d: Interval, t: f64) -> bool {
    let slack = DOMAIN_SLACK * d.t0.abs().max(d.t1.abs()).max(d.length().abs());
    t >= d.min() - slack && t <= d.max() + slack
}

/// Reads the `uv` point on item input `input` as `(u, v)` on `surface`: finite, with a warning
/// when it lies outside the domain (the surface is then extended, as Rhino does).
pub(crate) fn uv_on(
    s: &mut Solve<'_>,
    input: usize,
    surface: &NurbsSurface,
) -> Result<(f64, f64), NodeError> {
    let p = *s.item::<Point3>(input)?;
    if !(p.x.is_finite() && p.y.is_finite()) {
        return Err(format!(
            "input {}: the parameters ({}, {}) are not finite numbers",
            input_name(s, input),
            p.x,
            p.y
        )
        .into());
    }
    let (du, dv) = (surface.domain_u(), surface.domain_v());
    if !within(du, p.x) || !within(dv, p.y) {
        s.warning(format!(
            "parameters ({}, {}) are outside the domain {} to {} × {} to {}; the surface is \
             extended",
            p.x, p.y, du.t0, du.t1, dv.t0, dv.t1
        ));
    }
    Ok((p.x, p.y))
}

/// Evaluate Surface \[EvalSrf\]: point, normal, partial derivatives and frame at a `uv`.
pub fn evaluate_surface() -> NodeType {
    analysis(EVALUATE_SURFACE, "Evaluate Surface", "EvalSrf")
        .gh_guid("353b206e-bde5-4f02-a913-b3b8a977d4b9")
        .description(
            "Evaluates a surface at a {uv} coordinate: the point, the unit normal, the first \
             partial derivatives along u and v, and the frame (origin at the point, x axis \
             along the u direction, z axis the normal; openNURBS's FrameAt). Where the surface \
             is singular (a sphere's pole, a cone's tip) the normal and frame are the limits \
             from inside the parameter rectangle, as in Rhino, and a derivative may be zero. \
             Parameters outside the domain evaluate the surface's extension, with a warning.",
        )
        .input(surface_port("Surface to evaluate."))
        .input(uv_port("Point"))
        .output(Port::new("Point", "P", DataType::Point).doc("Point on the surface at {uv}."))
        .output(
            Port::new("Normal", "N", DataType::Vector)
                .doc("Unit normal at {uv}, (Su × Sv)/|Su × Sv| or its limit; null if none."),
        )
        .output(
            Port::new("U direction", "U", DataType::Vector)
                .doc("First partial derivative Su along u at {uv} (not unitized)."),
        )
        .output(
            Port::new("V direction", "V", DataType::Vector)
                .doc("First partial derivative Sv along v at {uv} (not unitized)."),
        )
        .output(
            Port::new("Frame", "F", DataType::Plane)
                .doc("Surface frame at {uv}: x along Su, z the normal; null if none."),
        )
        .solve(|s| {
            let surface = surface_input(s, 0)?;
            let (u, v) = uv_on(s, 1, &surface)?;
            let d = surface.derivatives_at(u, v, 1)?;
            s.set(0, d.point);
            s.set(2, d.du);
            s.set(3, d.dv);
            match (surface.normal_at(u, v), surface.frame_at(u, v)) {
                (Ok(n), Ok(f)) => {
                    s.set(1, n);
                    s.set(4, f);
                }
                (n, _) => {
                    if let Ok(n) = n {
                        s.set(1, n);
                    }
                    s.warning(format!("the surface has no normal or frame at ({u}, {v})"));
                }
            }
            Ok(())
        })
}

/// Surface Closest Point \[Srf CP\]: the closest point on a surface and its parameters.
pub fn surface_closest_point() -> NodeType {
    analysis(SURFACE_CLOSEST_POINT, "Surface Closest Point", "Srf CP")
        .gh_guid("4a9e9a8e-0943-4438-b360-129c30f2bb0f")
        .description(
            "Finds the point of a surface closest to a sample point: the global minimum over \
             the whole (untrimmed) surface, edges, corners and singular points included. Where \
             several points are equally close (the centre of a sphere) one of them is given. \
             The parameters come as a point (u, v, 0) in the surface's domain, ready for \
             Evaluate Surface.",
        )
        .input(Port::new("Point", "P", DataType::Point).doc("Sample point to project."))
        .input(surface_port("Surface to project onto."))
        .output(Port::new("Point", "P", DataType::Point).doc("Closest point on the surface."))
        .output(
            Port::new("UV Point", "uvP", DataType::Point)
                .doc("Parameters of the closest point, as (u, v, 0)."),
        )
        .output(
            Port::new("Distance", "D", DataType::Number)
                .doc("Distance from the sample point to the closest point, in model units."),
        )
        .solve(|s| {
            let p = *s.item::<Point3>(0)?;
            if !p.is_finite() {
                return Err("input P: the point is not finite".into());
            }
            let surface = surface_input(s, 1)?;
            let cp = surface.closest_point(p)?;
            s.set(0, cp.point);
            s.set(1, Point3::new(cp.u, cp.v, 0.0));
            s.set(2, cp.distance);
            Ok(())
        })
}

/// Principal Curvature \[Curvature\]: the principal curvatures and directions at a `uv`.
pub fn principal_curvature() -> NodeType {
    analysis(PRINCIPAL_CURVATURE, "Principal Curvature", "Curvature")
        .description(
            "Evaluates the principal curvatures of a surface at a {uv} coordinate: the largest \
             and smallest normal curvature over all tangent directions and the directions in \
             which they occur, with openNURBS's signs (positive where the surface bends \
             towards its normal; Rhino's sphere of radius r has −1/r for both, a cylinder 0 \
             along its axis and −1/r around it). At an umbilic (a sphere, a plane) every \
             direction is principal and K¹ is the u direction. At a singular point (a pole, a \
             tip) the curvature is undefined: the curvature outputs are null, with a warning.",
        )
        .input(surface_port("Surface to evaluate."))
        .input(uv_port("Point"))
        .output(
            Port::new("Frame", "F", DataType::Plane)
                .doc("Surface frame at {uv}: x along Su, z the normal."),
        )
        .output(
            Port::new("Maximum", "C1", DataType::Number)
                .doc("Largest principal curvature k1, in 1/model units (signed)."),
        )
        .output(
            Port::new("Minimum", "C2", DataType::Number)
                .doc("Smallest principal curvature k2 ≤ k1, in 1/model units (signed)."),
        )
        .output(
            Port::new("K¹ Direction", "K1", DataType::Vector)
                .doc("Unit tangent direction of the maximum curvature."),
        )
        .output(
            Port::new("K² Direction", "K2", DataType::Vector)
                .doc("Unit tangent direction of the minimum curvature: normal × K¹."),
        )
        .solve(|s| {
            let surface = surface_input(s, 0)?;
            let (u, v) = uv_on(s, 1, &surface)?;
            if let Ok(f) = surface.frame_at(u, v) {
                s.set(0, f);
            }
            match surface.curvature_at(u, v) {
                Ok(c) => {
                    s.set(1, c.k1);
                    s.set(2, c.k2);
                    s.set(3, c.direction1);
                    s.set(4, c.direction2);
                }
                Err(e) => s.warning(format!("no curvature at ({u}, {v}): {e}")),
            }
            Ok(())
        })
}

/// Surface Curvature \[Curvature\]: the Gaussian and mean curvature at a `uv`.
pub fn surface_curvature() -> NodeType {
    analysis(SURFACE_CURVATURE, "Surface Curvature", "Curvature")
        .description(
            "Evaluates the Gaussian and mean curvature of a surface at a {uv} coordinate. The \
             Gaussian curvature is the product of the principal curvatures: positive where the \
             surface is bowl-like, negative where it is saddle-like, zero where it is flat in \
             at least one direction (planes, cylinders, cones). The mean curvature is half \
             their sum, zero on minimal surfaces; it carries openNURBS's sign (Rhino's sphere \
             of radius r has mean curvature −1/r, a cylinder −1/(2r)). At a singular point (a \
             pole, a tip) the curvature is undefined: the curvature outputs are null, with a \
             warning.",
        )
        .input(surface_port("Surface to evaluate."))
        .input(uv_port("Point"))
        .output(
            Port::new("Frame", "F", DataType::Plane)
                .doc("Surface frame at {uv}: x along Su, z the normal."),
        )
        .output(
            Port::new("Gaussian", "G", DataType::Number)
                .doc("Gaussian curvature k1·k2, in 1/model units²."),
        )
        .output(
            Port::new("Mean", "M", DataType::Number)
                .doc("Mean curvature (k1 + k2)/2, in 1/model units (signed)."),
        )
        .solve(|s| {
            let surface = surface_input(s, 0)?;
            let (u, v) = uv_on(s, 1, &surface)?;
            if let Ok(f) = surface.frame_at(u, v) {
                s.set(0, f);
            }
            match surface.curvature_at(u, v) {
                Ok(c) => {
                    s.set(1, c.gaussian);
                    s.set(2, c.mean);
                }
                Err(e) => s.warning(format!("no curvature at ({u}, {v}): {e}")),
            }
            Ok(())
        })
}

#[cfg(test)]
mod tests {
    use std::f64::consts::{FRAC_PI_2, PI};

    use locus_kernel::{Cylinder, Plane, Sphere, Vector3};
    use locus_runtime::{DataTree, Level, NodeCall, NodeCallResult, Value};

    use super::*;

    const EPS: f64 = 1e-12;

    fn sphere(r: f64) -> Shared<NurbsSurface> {
        Shared::new(Sphere::new(Point3::ORIGIN, r).unwrap().to_nurbs().unwrap())
    }

    fn uv(u: f64, v: f64) -> DataTree {
        DataTree::from_item(Point3::new(u, v, 0.0))
    }

    fn number(r: &NodeCallResult, output: usize) -> Option<f64> {
        match r.outputs[output].values().next().flatten() {
            Some(Value::Number(x)) => Some(x),
            _ => None,
        }
    }

    fn vector(r: &NodeCallResult, output: usize) -> Option<Vector3> {
        match r.outputs[output].values().next().flatten() {
            Some(Value::Vector(x)) => Some(x),
            _ => None,
        }
    }

    fn point(r: &NodeCallResult, output: usize) -> Option<Point3> {
        match r.outputs[output].values().next().flatten() {
            Some(Value::Point(x)) => Some(x),
            _ => None,
        }
    }

    fn texts(r: &NodeCallResult, level: Level) -> Vec<String> {
        r.messages
            .iter()
            .filter(|m| m.level == level)
            .map(|m| m.text.clone())
            .collect()
    }

    #[test]
    fn evaluate_surface_on_a_sphere() {
        let r = NodeCall::new(&evaluate_surface())
            .input(DataTree::from_item(sphere(2.0)))
            .input(uv(FRAC_PI_2, 0.0))
            .run();
        assert!(r.messages.is_empty(), "{:?}", r.messages);
        assert!(
            point(&r, 0)
                .unwrap()
                .abs_diff_eq(Point3::new(0.0, 2.0, 0.0), EPS)
        );
        assert!((vector(&r, 1).unwrap() - Vector3::Y).length() < EPS);
        // Su along −x, Sv along +z at the equator.
        let su = vector(&r, 2).unwrap();
        let sv = vector(&r, 3).unwrap();
        assert!(su.x < 0.0 && su.y.abs() < EPS && sv.z > 0.0 && sv.x.abs() < EPS);
        let Some(Value::Plane(f)) = r.outputs[4].values().next().flatten() else {
            panic!("no frame")
        };
        assert!((f.z_axis - Vector3::Y).length() < EPS && (f.x_axis + Vector3::X).length() < EPS);
    }

    #[test]
    fn evaluate_surface_at_a_pole_gives_the_limit_normal() {
        let r = NodeCall::new(&evaluate_surface())
            .input(DataTree::from_item(sphere(1.0)))
            .input(uv(1.0, FRAC_PI_2))
            .run();
        assert!(r.messages.is_empty(), "{:?}", r.messages);
        assert!(
            point(&r, 0)
                .unwrap()
                .abs_diff_eq(Point3::new(0.0, 0.0, 1.0), EPS)
        );
        assert!((vector(&r, 1).unwrap() - Vector3::Z).length() < 1e-9);
        assert!(
            vector(&r, 2).unwrap().length() < 1e-12,
            "Su vanishes at the pole"
        );
    }

    #[test]
    fn evaluate_surface_at_a_cone_tip() {
        let cone = Shared::new(
            locus_kernel::Cone::new(Plane::WORLD_XY, 2.0, 1.0)
                .unwrap()
                .to_nurbs()
                .unwrap(),
        );
        let r = NodeCall::new(&evaluate_surface())
            .input(DataTree::from_item(cone))
            .input(uv(1.0, 0.0))
            .run();
        assert!(r.messages.is_empty(), "{:?}", r.messages);
        assert!(point(&r, 0).unwrap().abs_diff_eq(Point3::ORIGIN, EPS));
        // The limit normal at the apex is along the generator's normal at that u.
        let n = vector(&r, 1).unwrap();
        assert!((n.length() - 1.0).abs() < 1e-12 && n.z < 0.0, "{n:?}");
    }

    #[test]
    fn evaluate_surface_outside_the_domain_extends_with_a_warning() {
        let plane = Shared::new(
            NurbsSurface::from_plane(&Plane::WORLD_XY, Interval::UNIT, Interval::UNIT).unwrap(),
        );
        let r = NodeCall::new(&evaluate_surface())
            .input(DataTree::from_item(plane))
            .input(uv(2.0, -1.0))
            .run();
        assert_eq!(point(&r, 0), Some(Point3::new(2.0, -1.0, 0.0)));
        let w = texts(&r, Level::Warning);
        assert!(
            w.len() == 1 && w[0].contains("outside the domain 0 to 1"),
            "{w:?}"
        );
        let nan = NodeCall::new(&evaluate_surface())
            .input(DataTree::from_item(sphere(1.0)))
            .input(uv(f64::NAN, 0.0))
            .run();
        assert_eq!(point(&nan, 0), None);
        assert!(texts(&nan, Level::Error)[0].contains("input uv"));
    }

    #[test]
    fn closest_point_on_a_sphere_and_at_its_centre() {
        let r = NodeCall::new(&surface_closest_point())
            .input(DataTree::from_item(Point3::new(0.0, 3.0, 4.0)))
            .input(DataTree::from_item(sphere(2.0)))
            .run();
        assert!(r.messages.is_empty(), "{:?}", r.messages);
        assert!(
            point(&r, 0)
                .unwrap()
                .abs_diff_eq(Point3::new(0.0, 1.2, 1.6), 1e-12)
        );
        assert!((number(&r, 2).unwrap() - 3.0).abs() < 1e-12);
        let uvp = point(&r, 1).unwrap();
        assert!((uvp.x - FRAC_PI_2).abs() < 1e-9 && uvp.z == 0.0);
        // Every point of the sphere is 2 from its centre; one of them is given.
        let c = NodeCall::new(&surface_closest_point())
            .input(DataTree::from_item(Point3::ORIGIN))
            .input(DataTree::from_item(sphere(2.0)))
            .run();
        assert!((number(&c, 2).unwrap() - 2.0).abs() < 1e-12);
        let bad = NodeCall::new(&surface_closest_point())
            .input(DataTree::from_item(Point3::new(f64::NAN, 0.0, 0.0)))
            .input(DataTree::from_item(sphere(2.0)))
            .run();
        assert!(texts(&bad, Level::Error)[0].contains("input P"));
    }

    #[test]
    fn principal_curvatures_of_a_sphere_and_a_cylinder() {
        let r = NodeCall::new(&principal_curvature())
            .input(DataTree::from_item(sphere(2.0)))
            .input(uv(1.0, 0.3))
            .run();
        assert!(r.messages.is_empty(), "{:?}", r.messages);
        assert!((number(&r, 1).unwrap() + 0.5).abs() < EPS);
        assert!((number(&r, 2).unwrap() + 0.5).abs() < EPS);
        let cylinder = Shared::new(
            Cylinder::new(Plane::WORLD_XY, 1.5, 4.0)
                .unwrap()
                .to_nurbs()
                .unwrap(),
        );
        let r = NodeCall::new(&principal_curvature())
            .input(DataTree::from_item(cylinder))
            .input(uv(PI, 2.0))
            .run();
        assert!(number(&r, 1).unwrap().abs() < EPS);
        assert!((number(&r, 2).unwrap() + 1.0 / 1.5).abs() < EPS);
        assert!((vector(&r, 3).unwrap().z.abs() - 1.0).abs() < EPS);
        let k2 = vector(&r, 4).unwrap();
        assert!(k2.z.abs() < EPS && (k2.length() - 1.0).abs() < EPS);
    }

    #[test]
    fn curvature_at_a_pole_is_null_with_a_warning() {
        for node in [principal_curvature(), surface_curvature()] {
            let r = NodeCall::new(&node)
                .input(DataTree::from_item(sphere(1.0)))
                .input(uv(0.0, -FRAC_PI_2))
                .run();
            assert_eq!(number(&r, 1), None);
            assert_eq!(number(&r, 2), None);
            assert_eq!(
                r.outputs[1].item_count(),
                1,
                "a null keeps the item aligned"
            );
            let w = texts(&r, Level::Warning);
            assert!(w[0].contains("no curvature"), "{w:?}");
        }
    }

    #[test]
    fn gaussian_and_mean_curvature() {
        let r = NodeCall::new(&surface_curvature())
            .input(DataTree::from_item(sphere(4.0)))
            .input(uv(2.0, 0.7))
            .run();
        assert!((number(&r, 1).unwrap() - 1.0 / 16.0).abs() < EPS);
        assert!((number(&r, 2).unwrap() + 0.25).abs() < EPS);
        let bad = NodeCall::new(&surface_curvature())
            .input(DataTree::from_item(Value::Number(1.0)))
            .input(uv(0.0, 0.0))
            .run();
        assert!(texts(&bad, Level::Error)[0].contains("input S"));
    }
}

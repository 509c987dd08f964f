//! Surface › Util: Divide Surface, Iso Curve, Offset Surface, Isotrim and Flip.
//!
//! Grasshopper files Iso Curve under Curve › Spline; here it sits with the other nodes that
//! take a surface and a {uv} (**decision**, so that the Curve category stays as it is).

use locus_kernel::tolerance::{DOCUMENT_TOLERANCE, ZERO_TOLERANCE};
use locus_kernel::{Curve, Interval, NurbsSurface, Point3, SurfaceDirection, UvInterval, Vector3};
use locus_runtime::{
    Branch, DataTree, DataType, NodeError, NodeRegistry, NodeType, Port, Shared, Value,
    format_value,
};

use super::analysis::{surface_input, surface_port, uv_on, uv_port};

/// Id of [`divide_surface`].
pub const DIVIDE_SURFACE: &str = "surface.divide_surface";
/// Id of [`iso_curve`].
pub const ISO_CURVE: &str = "surface.iso_curve";
/// Id of [`offset_surface`].
pub const OFFSET_SURFACE: &str = "surface.offset_surface";
/// Id of [`isotrim`].
pub const ISOTRIM: &str = "surface.isotrim";
/// Id of [`flip_surface`].
pub const FLIP_SURFACE: &str = "surface.flip";

/// The largest number of points Divide Surface makes for one surface: (U + 1)·(V + 1).
pub const MAX_GRID_POINTS: u64 = 10_000_000;

/// Registers the util nodes.
pub fn register(registry: &mut NodeRegistry) {
    registry.register(divide_surface());
    registry.register(iso_curve());
    registry.register(offset_surface());
    registry.register(isotrim());
    registry.register(flip_surface());
}

/// A division count: a positive integer.
fn count(n: i64, input: &str) -> Result<usize, NodeError> {
    if n < 1 {
        return Err(format!("input {input}: the count must be at least 1, got {n}").into());
    }
    usize::try_from(n).map_err(|_| format!("input {input}: the count {n} is too large").into())
}

/// Divide Surface \[SDivide\]: a grid of points, normals and parameters on a surface.
pub fn divide_surface() -> NodeType {
    NodeType::new(DIVIDE_SURFACE, "Divide Surface", "SDivide", "Surface")
        .gh_guid("5106bafc-d5d4-4983-83e7-7be3ed07f502")
        .subcategory("Util")
        .description(
            "Divides a surface into a grid of U × V equal steps of its parameter rectangle \
             (equal in parameters, not in distance): (U + 1) × (V + 1) points, edges included, \
             with their unit normals and their parameters as points (u, v, 0). Each row of \
             constant u is one branch, its path the surface's path with the surface's index \
             and the row number appended ({0;0;0} to {0;0;U} for one surface), and runs along \
             v. At singular points (poles, tips) the normal is the limit from inside the \
             rectangle, as in Rhino; a point with no normal at all gets a null normal.",
        )
        .input(surface_port("Surface to divide."))
        .input(
            Port::new("U Count", "U", DataType::Integer)
                .default_value(10_i64)
                .doc("Number of steps along u, at least 1. Default 10."),
        )
        .input(
            Port::new("V Count", "V", DataType::Integer)
                .default_value(10_i64)
                .doc("Number of steps along v, at least 1. Default 10."),
        )
        .output(
            Port::new("Points", "P", DataType::Point)
                .tree()
                .doc("Grid points, one branch per row of constant u."),
        )
        .output(
            Port::new("Normals", "N", DataType::Vector)
                .tree()
                .doc("Unit normals at the grid points, in the same tree."),
        )
        .output(
            Port::new("Parameters", "uv", DataType::Point)
                .tree()
                .doc("Parameters of the grid points as (u, v, 0), in the same tree."),
        )
        .solve(|s| {
            let surface = surface_input(s, 0)?;
            let nu = count(*s.item::<i64>(1)?, "U")?;
            let nv = count(*s.item::<i64>(2)?, "V")?;
            let total = (nu as u64 + 1).saturating_mul(nv as u64 + 1);
            if total > MAX_GRID_POINTS {
                return Err(format!(
                    "a {nu} × {nv} division makes {total} points, more than the limit of \
                     {MAX_GRID_POINTS}"
                )
                .into());
            }
            let (du, dv) = (surface.domain_u(), surface.domain_v());
            // The ends are the domain's ends exactly, so that edges and poles are hit.
            let steps = |d: locus_kernel::Interval, n: usize| -> Vec<f64> {
                (0..=n)
                    .map(|i| match i {
                        0 => d.t0,
                        i if i == n => d.t1,
                        i => d.parameter_at(i as f64 / n as f64),
                    })
                    .collect()
            };
            let (us, vs) = (steps(du, nu), steps(dv, nv));
            let mut grid = vec![Point3::ORIGIN; us.len() * vs.len()];
            surface.points_on_grid(&us, &vs, &mut grid)?;
            let base = s.path().with_appended(s.index().unwrap_or(0) as u32);
            let (mut points, mut normals, mut params) =
                (DataTree::new(), DataTree::new(), DataTree::new());
            let mut missing = 0usize;
            for (i, &u) in us.iter().enumerate() {
                let path = base.with_appended(i as u32);
                let row = &grid[i * vs.len()..(i + 1) * vs.len()];
                let mut n = Branch::new(DataType::Vector);
                for &v in &vs {
                    match surface.normal_at(u, v) {
                        Ok(normal) => n.push::<Vector3>(normal),
                        Err(_) => {
                            missing += 1;
                            n.push_null();
                        }
                    }
                }
                let uv: Vec<Point3> = vs.iter().map(|&v| Point3::new(u, v, 0.0)).collect();
                points.insert(path.clone(), Branch::from_items(row.to_vec()));
                normals.insert(path.clone(), n);
                params.insert(path, Branch::from_items(uv));
            }
            if missing > 0 {
                s.warning(format!("{missing} grid point(s) have no normal"));
            }
            s.set_tree(0, points);
            s.set_tree(1, normals);
            s.set_tree(2, params);
            Ok(())
        })
}

/// Iso Curve \[Iso\]: the isocurves of a surface through a `uv`.
pub fn iso_curve() -> NodeType {
    NodeType::new(ISO_CURVE, "Iso Curve", "Iso", "Surface")
        .gh_guid("d1d57181-d594-41e8-8efb-041e29f8a5ca")
        .subcategory("Util")
        .description(
            "Extracts the two isocurves of a surface through a {uv} coordinate, as exact NURBS \
             curves (Rhino's IsoCurve): the U isocurve runs in the u direction at constant v, \
             over the surface's u domain; the V isocurve runs in the v direction at constant u. \
             An isocurve along a singular side (a sphere's pole) collapses to a point and is \
             still given, with a remark. Parameters outside the domain give isocurves of the \
             surface's extension, with a warning.",
        )
        .input(surface_port("Surface to extract isocurves from."))
        .input(uv_port("UV Point"))
        .output(
            Port::new("U Isocurve", "U", DataType::Curve)
                .doc("Isocurve in the u direction, at v = the uv point's v."),
        )
        .output(
            Port::new("V Isocurve", "V", DataType::Curve)
                .doc("Isocurve in the v direction, at u = the uv point's u."),
        )
        .solve(|s| {
            let surface = surface_input(s, 0)?;
            let (u, v) = uv_on(s, 1, &surface)?;
            let along_u = surface.isocurve(SurfaceDirection::U, v)?;
            let along_v = surface.isocurve(SurfaceDirection::V, u)?;
            for (name, c) in [("U", &along_u), ("V", &along_v)] {
                let first = c.points()[0];
                let tolerance = ZERO_TOLERANCE * (1.0 + first.to_vector().length());
                if c.points().iter().all(|p| p.distance(first) <= tolerance) {
                    s.remark(format!(
                        "the {name} isocurve collapses to the point {}",
                        format_value(&Value::Point(first))
                    ));
                }
            }
            s.set(0, Shared::new(Curve::from(along_u)));
            s.set(1, Shared::new(Curve::from(along_v)));
            Ok(())
        })
}

/// Offset Surface \[Offset\]: a surface moved along its normals by a distance.
pub fn offset_surface() -> NodeType {
    NodeType::new(OFFSET_SURFACE, "Offset Surface", "Offset", "Surface")
        .gh_guid("b25c5762-f90e-4839-9fc5-74b74ab42b1e")
        .subcategory("Util")
        .description(
            "Offsets a surface by a distance along its normals (against them for a negative \
             distance). The exact offset is not a NURBS surface in general, so, as in Rhino, \
             the result approximates it within the document tolerance (0.001): a bicubic \
             surface interpolating offset points on a grid of the surface's parameters, \
             refined until the offset is within the tolerance between the samples too, with \
             the surface's domain. Planes offset exactly. At singular points (poles) the normal \
             is its limit. An offset past the radius of curvature on the concave side folds \
             the surface over itself. Locus surfaces carry no trims, so Retrim changes nothing.",
        )
        .input(surface_port("Surface to offset."))
        .input(
            Port::new("Distance", "D", DataType::Number)
                .default_value(1.0)
                .doc("Offset distance along the normals, in model units. Default 1."),
        )
        .input(
            Port::new("Retrim", "T", DataType::Boolean)
                .default_value(true)
                .doc("Whether to trim the offset like the surface; untrimmed surfaces ignore it. Default true."),
        )
        .output(surface_port("The offset surface."))
        .solve(|s| {
            let surface = surface_input(s, 0)?;
            let distance = *s.item::<f64>(1)?;
            if !distance.is_finite() {
                return Err(format!("input D: the distance must be a finite number, got {distance}").into());
            }
            let offset = surface
                .offset(distance, DOCUMENT_TOLERANCE)
                .map_err(|e| NodeError(format!("input S: {e}")))?;
            s.set(0, Shared::new(offset));
            Ok(())
        })
}

/// Parameter samples per direction for comparing a surface's normals with a guide's.
const FLIP_SAMPLES: usize = 4;

/// Whether `surface` faces against `guide`: its normals at the centres of a 4 × 4 grid of
/// parameter cells, compared with the guide's normals at the closest points, point the other
/// way on balance (their dot products sum to less than zero).
fn faces_against(surface: &NurbsSurface, guide: &NurbsSurface) -> Result<bool, NodeError> {
    let (du, dv) = (surface.domain_u(), surface.domain_v());
    let mut agreement = 0.0;
    for i in 0..FLIP_SAMPLES {
        for j in 0..FLIP_SAMPLES {
            let u = du.parameter_at((i as f64 + 0.5) / FLIP_SAMPLES as f64);
            let v = dv.parameter_at((j as f64 + 0.5) / FLIP_SAMPLES as f64);
            let Ok(normal) = surface.normal_at(u, v) else {
                continue;
            };
            let cp = guide
                .closest_point(surface.point_at(u, v))
                .map_err(|e| NodeError(format!("input G: {e}")))?;
            if let Ok(g) = guide.normal_at(cp.u, cp.v) {
                agreement += normal.dot(g);
            }
        }
    }
    Ok(agreement < 0.0)
}

/// Flip \[Flip\]: a surface with its normals reversed, optionally only when it faces against a
/// guide.
pub fn flip_surface() -> NodeType {
    NodeType::new(FLIP_SURFACE, "Flip", "Flip", "Surface")
        .gh_guid("c3d1f2b8-8596-4e8d-8861-c28ba8ffb4f4")
        .subcategory("Util")
        .description(
            "Flips the normals of a surface. Locus surfaces carry no orientation flag (Rhino \
             flips a face's), so the flipped surface is the surface with u and v swapped \
             (Rhino's Transpose): the same points, the domains exchanged, the normal reversed. \
             With a guide surface the surface is flipped only when it faces against the guide: \
             its normals at the centres of a 4 × 4 grid of parameter cells, compared with the \
             guide's at the closest points, point the other way on balance.",
        )
        .input(surface_port("Surface to flip."))
        .input(
            Port::new("Guide", "G", DataType::Surface)
                .doc("Optional guide surface whose normals the result follows.")
                .optional(),
        )
        .output(surface_port("The flipped (or unchanged) surface."))
        .output(
            Port::new("Result", "R", DataType::Boolean).doc("True when the surface was flipped."),
        )
        .solve(|s| {
            let surface = surface_input(s, 0)?;
            let flip = if s.value(1).is_some() {
                let guide = surface_input(s, 1)?;
                faces_against(&surface, &guide)?
            } else {
                true
            };
            let out = if flip {
                Shared::new(surface.transposed())
            } else {
                surface
            };
            s.set(0, out);
            s.set(1, flip);
            Ok(())
        })
}

/// Isotrim \[SubSrf\]: the part of a surface over a rectangle of its parameters.
pub fn isotrim() -> NodeType {
    NodeType::new(ISOTRIM, "Isotrim", "SubSrf", "Surface")
        .gh_guid("6a9ccaab-1b03-484e-bbda-be9c81584a66")
        .subcategory("Util")
        .description(
            "The part of a surface over a two-dimensional domain of its parameters, an exact \
             NURBS surface that keeps the parameters: its domain is D, and every point has \
             the parameters it had on the whole surface. Each of D's intervals is taken in \
             increasing order (a decreasing interval cuts the same part). A part reaching \
             past the surface's domain is cut at the domain, with a warning; a part of zero \
             width, or wholly outside, is an error. With Divide Domain² on the surface this \
             cuts it into panels.",
        )
        .input(surface_port("Base surface."))
        .input(Port::new("Domain", "D", DataType::Domain2).doc(
            "The rectangle of parameters to keep, in the surface's domain (see Divide Domain²).",
        ))
        .output(surface_port("The part of the surface over D."))
        .solve(|s| {
            let surface = surface_input(s, 0)?;
            let d = *s.item::<UvInterval>(1)?;
            let mut clipped = false;
            let mut part = |name: &str, want: Interval, have: Interval| {
                if !want.is_finite() {
                    return Err(NodeError(format!(
                        "input D: the {name} interval {} to {} is not finite",
                        want.t0, want.t1
                    )));
                }
                let (lo, hi) = (want.min().max(have.min()), want.max().min(have.max()));
                if lo != want.min() || hi != want.max() {
                    clipped = true;
                }
                if lo >= hi {
                    return Err(NodeError(format!(
                        "input D: the {name} interval {} to {} leaves nothing of the \
                         surface's {name} domain {} to {}",
                        want.t0, want.t1, have.t0, have.t1
                    )));
                }
                Ok(Interval::new(lo, hi))
            };
            let u = part("u", d.u, surface.domain_u())?;
            let v = part("v", d.v, surface.domain_v())?;
            if clipped {
                s.warning(format!(
                    "input D reaches past the surface's domain; cut to {} × {}",
                    format_value(&Value::Domain(u)),
                    format_value(&Value::Domain(v))
                ));
            }
            let sub = surface
                .sub_surface(u, v)
                .map_err(|e| NodeError(format!("input S: {e}")))?;
            s.set(0, Shared::new(sub));
            Ok(())
        })
}

#[cfg(test)]
mod tests {
    use std::f64::consts::{FRAC_PI_2, TAU};

    use locus_kernel::{Plane, Sphere};
    use locus_runtime::{Level, NodeCall, TreePath, Value};

    use super::*;

    fn sphere(r: f64) -> Shared<NurbsSurface> {
        Shared::new(Sphere::new(Point3::ORIGIN, r).unwrap().to_nurbs().unwrap())
    }

    fn points(tree: &DataTree, path: &str) -> Vec<Point3> {
        let b = tree.branch(&path.parse::<TreePath>().unwrap()).expect(path);
        b.slice::<Point3>().unwrap().to_vec()
    }

    #[test]
    fn divides_a_plane_into_a_tree_of_rows() {
        let plane = Shared::new(
            NurbsSurface::from_plane(&Plane::WORLD_XY, Interval::new(0.0, 4.0), Interval::UNIT)
                .unwrap(),
        );
        let r = NodeCall::new(&divide_surface())
            .input(DataTree::from_item(plane))
            .input(DataTree::from_item(2_i64))
            .input(DataTree::from_item(1_i64))
            .run();
        assert!(r.messages.is_empty(), "{:?}", r.messages);
        assert_eq!(r.outputs[0].branch_count(), 3);
        assert_eq!(
            points(&r.outputs[0], "{0;0;1}"),
            vec![Point3::new(2.0, 0.0, 0.0), Point3::new(2.0, 1.0, 0.0)]
        );
        assert_eq!(
            points(&r.outputs[2], "{0;0;2}"),
            vec![Point3::new(4.0, 0.0, 0.0), Point3::new(4.0, 1.0, 0.0)]
        );
        let normals = r.outputs[1].branch(&"{0;0;0}".parse().unwrap()).unwrap();
        assert_eq!(
            normals.slice::<Vector3>().unwrap(),
            &[Vector3::Z, Vector3::Z]
        );
    }

    #[test]
    fn sphere_grid_reaches_the_poles_with_limit_normals() {
        let r = NodeCall::new(&divide_surface())
            .input(DataTree::from_list(vec![sphere(1.0), sphere(2.0)]))
            .input(DataTree::from_item(4_i64))
            .input(DataTree::from_item(2_i64))
            .run();
        assert!(r.messages.is_empty(), "{:?}", r.messages);
        assert_eq!(r.outputs[0].branch_count(), 10);
        let row = points(&r.outputs[0], "{0;1;3}");
        assert!(row[0].abs_diff_eq(Point3::new(0.0, 0.0, -2.0), 1e-12));
        assert!(row[2].abs_diff_eq(Point3::new(0.0, 0.0, 2.0), 1e-12));
        let n = r.outputs[1].branch(&"{0;1;3}".parse().unwrap()).unwrap();
        let n = n.slice::<Vector3>().unwrap();
        assert!((n[0] + Vector3::Z).length() < 1e-9 && (n[2] - Vector3::Z).length() < 1e-9);
        let uv = points(&r.outputs[2], "{0;0;4}");
        assert_eq!(uv[0], Point3::new(TAU, -FRAC_PI_2, 0.0));
    }

    #[test]
    fn bad_counts_are_errors() {
        for (u, v, word) in [
            (0, 3, "input U"),
            (3, -1, "input V"),
            (10_000, 10_000, "limit"),
        ] {
            let r = NodeCall::new(&divide_surface())
                .input(DataTree::from_item(sphere(1.0)))
                .input(DataTree::from_item(u as i64))
                .input(DataTree::from_item(v as i64))
                .run();
            assert!(r.outputs[0].is_empty());
            let e: Vec<&str> = r
                .messages
                .iter()
                .filter(|m| m.level == Level::Error)
                .map(|m| m.text.as_str())
                .collect();
            assert!(e.len() == 1 && e[0].contains(word), "{e:?}");
        }
    }

    #[test]
    fn isocurves_of_a_sphere() {
        let r = NodeCall::new(&iso_curve())
            .input(DataTree::from_item(sphere(2.0)))
            .input(DataTree::from_item(Point3::new(FRAC_PI_2, 0.0, 0.0)))
            .run();
        assert!(r.messages.is_empty(), "{:?}", r.messages);
        let Some(Value::Curve(u)) = r.outputs[0].values().next().flatten() else {
            panic!("no U curve")
        };
        let Some(Value::Curve(v)) = r.outputs[1].values().next().flatten() else {
            panic!("no V curve")
        };
        // The U isocurve at v = 0 is the equator, the V isocurve at u = π/2 a meridian.
        assert_eq!(u.domain(), Interval::new(0.0, TAU));
        assert!((u.length() - 2.0 * TAU).abs() < 1e-9);
        assert!(
            u.point_at(0.0)
                .abs_diff_eq(Point3::new(2.0, 0.0, 0.0), 1e-12)
        );
        assert!((v.length() - TAU).abs() < 1e-9);
        assert!(
            v.point_at(0.0)
                .abs_diff_eq(Point3::new(0.0, 2.0, 0.0), 1e-12)
        );
        // At the pole the U isocurve collapses.
        let pole = NodeCall::new(&iso_curve())
            .input(DataTree::from_item(sphere(2.0)))
            .input(DataTree::from_item(Point3::new(1.0, FRAC_PI_2, 0.0)))
            .run();
        assert!(
            pole.messages
                .iter()
                .any(|m| m.level == Level::Remark && m.text.contains("U isocurve"))
        );
        let nan = NodeCall::new(&iso_curve())
            .input(DataTree::from_item(sphere(2.0)))
            .input(DataTree::from_item(Point3::new(1.0, f64::INFINITY, 0.0)))
            .run();
        assert!(nan.outputs[0].values().all(|v| v.is_none()));
    }

    #[test]
    fn offset_surface_grows_a_sphere_and_rejects_bad_distances() {
        let r = NodeCall::new(&offset_surface())
            .input(DataTree::from_item(sphere(3.0)))
            .input(DataTree::from_list(vec![1.0, -1.0]))
            .run();
        assert!(r.messages.is_empty(), "{:?}", r.messages);
        let out: Vec<Option<Value>> = r.outputs[0].values().collect();
        for (value, radius) in out.iter().zip([4.0, 2.0]) {
            let Some(Value::Surface(o)) = value else {
                panic!("{value:?}")
            };
            let (du, dv) = (o.domain_u(), o.domain_v());
            let p = o.point_at(du.parameter_at(0.3), dv.parameter_at(0.6));
            assert!((p.distance(Point3::ORIGIN) - radius).abs() < DOCUMENT_TOLERANCE);
        }
        for bad in [f64::NAN, f64::INFINITY] {
            let r = NodeCall::new(&offset_surface())
                .input(DataTree::from_item(sphere(3.0)))
                .input(DataTree::from_item(bad))
                .run();
            let errors = crate::test_support::messages(&r, Level::Error);
            assert_eq!(errors.len(), 1, "{errors:?}");
            assert!(errors[0].contains("input D"), "{errors:?}");
        }
        let r = NodeCall::new(&offset_surface())
            .input(DataTree::from_item(Point3::ORIGIN))
            .run();
        assert_eq!(crate::test_support::messages(&r, Level::Error).len(), 1);
    }

    #[test]
    fn offset_plane_is_exact() {
        let plane = NurbsSurface::from_plane(
            &Plane::WORLD_XY,
            Interval::new(0.0, 2.0),
            Interval::new(0.0, 3.0),
        )
        .unwrap();
        let r = NodeCall::new(&offset_surface())
            .input(DataTree::from_item(Shared::new(plane)))
            .input(DataTree::from_item(-2.5))
            .run();
        let Some(Value::Surface(o)) = r.outputs[0].values().next().flatten() else {
            panic!("{:?}", r.messages)
        };
        assert!(o.point_at(1.0, 1.5).distance(Point3::new(1.0, 1.5, -2.5)) < 1e-12);
    }

    #[test]
    fn isotrim_keeps_the_parameters_and_cuts_at_the_domain() {
        let sphere = sphere(2.0);
        let (du, dv) = (sphere.domain_u(), sphere.domain_v());
        let d = UvInterval::new(
            Interval::new(du.parameter_at(0.6), du.parameter_at(0.1)),
            Interval::new(dv.parameter_at(0.2), dv.parameter_at(0.5)),
        );
        let r = NodeCall::new(&isotrim())
            .input(DataTree::from_item(sphere.clone()))
            .input(DataTree::from_item(d))
            .run();
        assert!(r.messages.is_empty(), "{:?}", r.messages);
        let Some(Value::Surface(part)) = r.outputs[0].values().next().flatten() else {
            panic!("{:?}", r.outputs[0])
        };
        assert_eq!(part.domain_u(), Interval::new(d.u.t1, d.u.t0));
        assert_eq!(part.domain_v(), d.v);
        let (pu, pv) = (du.parameter_at(0.3), dv.parameter_at(0.4));
        assert!(part.point_at(pu, pv).distance(sphere.point_at(pu, pv)) < 1e-12);
        // Past the domain: cut, with a warning.
        let past = UvInterval::new(Interval::new(du.t0 - 5.0, du.parameter_at(0.5)), dv);
        let r = NodeCall::new(&isotrim())
            .input(DataTree::from_item(sphere.clone()))
            .input(DataTree::from_item(past))
            .run();
        assert_eq!(r.messages.len(), 1);
        assert_eq!(r.messages[0].level, Level::Warning);
        assert_eq!(r.outputs[0].item_count(), 1);
        // Nothing left, or not finite: errors.
        for bad in [
            UvInterval::new(Interval::new(du.t1 + 1.0, du.t1 + 2.0), dv),
            UvInterval::new(Interval::new(0.5, 0.5), dv),
            UvInterval::new(du, Interval::new(f64::NAN, 1.0)),
        ] {
            let r = NodeCall::new(&isotrim())
                .input(DataTree::from_item(sphere.clone()))
                .input(DataTree::from_item(bad))
                .run();
            assert_eq!(r.messages.len(), 1, "{bad:?}");
            assert_eq!(r.messages[0].level, Level::Error);
            assert!(
                r.messages[0].text.starts_with("input D:"),
                "{}",
                r.messages[0].text
            );
        }
    }

    fn flip_result(r: &locus_runtime::NodeCallResult) -> (Shared<NurbsSurface>, bool) {
        let surface = match r.outputs[0].values().next().flatten() {
            Some(Value::Surface(s)) => s,
            other => panic!("no surface: {other:?} {:?}", r.messages),
        };
        let flag = match r.outputs[1].values().next().flatten() {
            Some(Value::Boolean(b)) => b,
            other => panic!("no flag: {other:?}"),
        };
        (surface, flag)
    }

    #[test]
    fn flip_reverses_the_normal_and_follows_a_guide() {
        // World XY over [0, 2] × [0, 1]: normal +Z.
        let plane = |p: Plane| {
            Shared::new(
                NurbsSurface::from_plane(&p, Interval::new(0.0, 2.0), Interval::UNIT).unwrap(),
            )
        };
        let up = plane(Plane::WORLD_XY);
        let r = NodeCall::new(&flip_surface())
            .input(DataTree::from_item(up.clone()))
            .run();
        let (flipped, flag) = flip_result(&r);
        assert!(flag);
        let n = flipped.normal_at(0.5, 1.0).unwrap();
        assert!((n.z + 1.0).abs() < 1e-12, "{n:?}");
        assert!(flipped.point_at(0.5, 1.0).distance(up.point_at(1.0, 0.5)) < 1e-12);

        // A guide below facing down: flipped; a guide facing up: kept.
        let mut down = Plane::WORLD_XY;
        down.origin = Point3::new(0.0, 0.0, -3.0);
        down.y_axis = -down.y_axis;
        down.z_axis = -down.z_axis;
        let mut above = Plane::WORLD_XY;
        above.origin = Point3::new(5.0, 5.0, 5.0);
        for (guide, want) in [(plane(down), true), (plane(above), false)] {
            let r = NodeCall::new(&flip_surface())
                .input(DataTree::from_item(up.clone()))
                .input(DataTree::from_item(guide))
                .run();
            let (out, flag) = flip_result(&r);
            assert_eq!(flag, want);
            let n = out
                .normal_at(out.domain_u().mid(), out.domain_v().mid())
                .unwrap();
            assert!((n.z - if want { -1.0 } else { 1.0 }).abs() < 1e-12, "{n:?}");
        }
    }

    #[test]
    fn flip_reports_what_is_not_a_surface() {
        let r = NodeCall::new(&flip_surface())
            .input(DataTree::from_item(Point3::new(f64::NAN, 0.0, 0.0)))
            .run();
        let errors: Vec<_> = r
            .messages
            .iter()
            .filter(|m| m.level == Level::Error)
            .collect();
        assert_eq!(errors.len(), 1, "{:?}", r.messages);
        assert!(errors[0].text.contains("input S"), "{errors:?}");
        let r = NodeCall::new(&flip_surface())
            .input(DataTree::from_item(sphere(1.0)))
            .input(DataTree::from_item(1.5))
            .run();
        let errors: Vec<_> = r
            .messages
            .iter()
            .filter(|m| m.level == Level::Error)
            .collect();
        assert_eq!(errors.len(), 1, "{:?}", r.messages);
        assert!(errors[0].text.contains("input G"), "{errors:?}");
    }
}

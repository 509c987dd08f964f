//! Surface › Primitive: Sphere, Sphere Fit, Cylinder, Cone and Plane Surface.
//!
//! Every primitive outputs a NURBS surface in the exact form Rhino builds (see
//! `locus_kernel::Sphere::to_nurbs` and friends), so that parameters, seams and singular sides
//! are where a Rhino user expects them: a sphere's `u` runs over `0` to `2π` in longitude and
//! its `v` over `−π/2` to `π/2` in latitude, with the poles as the singular sides `v = −π/2`
//! and `v = π/2`; a cone's apex is its singular side `v = 0`. As in Grasshopper, whose
//! primitives output Surface parameters, these are surfaces, not B-reps; a Brep input accepts
//! them (the runtime casts a surface to a one-face B-rep), so they flow into Deconstruct Brep,
//! Area or Singular Points unchanged.

use locus_kernel::{Cone, Cylinder, Interval, NurbsSurface, Plane, Point3, Sphere};
use locus_runtime::{DataType, NodeError, NodeRegistry, NodeType, Port, Shared};

/// Id of [`sphere`].
pub const SPHERE: &str = "surface.sphere";
/// Id of [`sphere_fit`].
pub const SPHERE_FIT: &str = "surface.sphere_fit";
/// Id of [`cylinder`].
pub const CYLINDER: &str = "surface.cylinder";
/// Id of [`cone`].
pub const CONE: &str = "surface.cone";
/// Id of [`plane_surface`].
pub const PLANE_SURFACE: &str = "surface.plane_surface";

/// Registers the primitive nodes.
pub fn register(registry: &mut NodeRegistry) {
    for t in [sphere(), sphere_fit(), cylinder(), cone(), plane_surface()] {
        registry.register(t);
    }
}

fn primitive(id: &str, name: &str, nickname: &str) -> NodeType {
    NodeType::new(id, name, nickname, "Surface").subcategory("Primitive")
}

fn base_port(doc: &str) -> Port {
    Port::new("Base", "B", DataType::Plane)
        .default_value(Plane::WORLD_XY)
        .doc(doc)
}

fn radius_port(doc: &str) -> Port {
    Port::new("Radius", "R", DataType::Number)
        .default_value(1.0)
        .constraint(crate::constraints::positive_radius)
        .doc(doc)
}

fn length_port(doc: &str) -> Port {
    Port::new("Length", "L", DataType::Number)
        .default_value(10.0)
        .doc(doc)
}

/// A radius that is a positive finite number, or an error naming input R.
fn positive_radius(r: f64) -> Result<f64, NodeError> {
    if r.is_finite() && r > 0.0 {
        Ok(r)
    } else {
        Err(format!("input R: the radius must be a positive number, got {r}").into())
    }
}

/// A length that is a finite number other than zero, or an error naming input L.
fn nonzero_length(l: f64) -> Result<f64, NodeError> {
    if l.is_finite() && l != 0.0 {
        Ok(l)
    } else {
        Err(format!("input L: the length must be a finite number other than zero, got {l}").into())
    }
}

/// A base plane with finite, valid axes, or an error naming the input.
fn valid_plane(plane: &Plane, input: &str) -> Result<Plane, NodeError> {
    if plane.is_finite() && plane.is_valid() {
        Ok(*plane)
    } else {
        Err(format!("input {input}: the plane is not valid").into())
    }
}

/// Sphere \[Sph\]: a spherical surface from a centre plane and a radius.
pub fn sphere() -> NodeType {
    primitive(SPHERE, "Sphere", "Sph")
        .gh_guid("dabc854d-f50e-408a-b001-d043c7de151d")
        .description(
            "Creates a spherical surface centred at the origin of the base plane, in Rhino's \
             exact NURBS form (degree 2 × 2, 9 × 5 control points, rational). The plane \
             orients the parameters: u is the longitude from the plane's x axis about its z \
             axis, on 0 to 2π; v is the latitude on −π/2 (the south pole, on the plane's −z \
             side) to π/2 (the north pole). The poles are singular sides of the parameter \
             rectangle and the seam is at u = 0 = 2π; normals point outwards. A radius that is \
             not positive is an error.",
        )
        .input(base_port(
            "Base plane: its origin is the centre and its axes orient the sphere. A point \
             becomes the plane parallel to World XY through it. Default World XY.",
        ))
        .input(radius_port(
            "Radius of the sphere, in model units; positive. Default 1.",
        ))
        .output(
            Port::new("Sphere", "S", DataType::Surface)
                .doc("The sphere, a NURBS surface with domain 0 to 2π × −π/2 to π/2."),
        )
        .lift2(|plane: &Plane, r: &f64| {
            let plane = valid_plane(plane, "B")?;
            let r = positive_radius(*r)?;
            let sphere = Sphere::from_plane(plane, r)?;
            Ok(Shared::new(sphere.to_nurbs()?))
        })
}

/// Sphere Fit \[SFit\]: the sphere that fits a list of points best.
pub fn sphere_fit() -> NodeType {
    primitive(SPHERE_FIT, "Sphere Fit", "SFit")
        .gh_guid("e7ffb3af-2d77-4804-a260-755308bf8285")
        .description(
            "Fits a sphere to a 3D collection of points (Rhino's Sphere.FitSphereToPoints): the \
             sphere that minimises the sum of squared distances from the points (algebraic fit \
             refined by Gauss–Newton), exact for points on a sphere. Gives its centre, its \
             radius and the sphere as a surface, oriented by the world axes as Sphere's is by \
             World XY. Fewer than four points, or points in one plane (no single sphere), are \
             an error; empty items are skipped.",
        )
        .input(
            Port::new("Points", "P", DataType::Point)
                .doc("The points to fit, at least four not in one plane.")
                .list(),
        )
        .output(Port::new("Center", "C", DataType::Point).doc("The centre of the sphere."))
        .output(Port::new("Radius", "R", DataType::Number).doc("The radius of the sphere."))
        .output(
            Port::new("Sphere", "S", DataType::Surface)
                .doc("The fitted sphere, a NURBS surface as Sphere makes it."),
        )
        .solve(|s| {
            let points: Vec<Point3> = s.list::<Point3>(0)?.present().copied().collect();
            let fit = Sphere::fit(&points).map_err(|e| format!("input P: {e}"))?;
            s.set(0, fit.sphere.center());
            s.set(1, fit.sphere.radius);
            s.set(2, Shared::new(fit.sphere.to_nurbs()?));
            Ok(())
        })
}

/// Cylinder \[Cyl\]: a cylindrical surface on a base circle, extruded along the plane's normal.
pub fn cylinder() -> NodeType {
    primitive(CYLINDER, "Cylinder", "Cyl")
        .gh_guid("0373008a-80ee-45be-887d-ab5a244afc29")
        .description(
            "Creates a cylindrical surface (without caps): the circle of the given radius in the \
             base plane, extruded along the plane's z axis by the length; a negative length \
             extrudes backwards. Rhino's exact NURBS form: degree 2 × 1, u is the circle \
             parameter on 0 to 2π starting on the plane's x axis, v the height along the axis \
             (0 to L, or L to 0 for a negative length). Normals point away from the axis. A \
             radius that is not positive or a zero length is an error.",
        )
        .input(base_port(
            "Base plane: the centre of the bottom circle and the orientation (the axis is its \
             z axis). A point becomes the plane parallel to World XY. Default World XY.",
        ))
        .input(radius_port(
            "Radius of the cylinder, in model units; positive. Default 1.",
        ))
        .input(length_port(
            "Length of the cylinder along the plane's z axis, in model units; not zero, \
             negative goes backwards. Default 10.",
        ))
        .output(
            Port::new("Cylinder", "C", DataType::Surface)
                .doc("The lateral surface of the cylinder, a NURBS surface."),
        )
        .lift3(|plane: &Plane, r: &f64, l: &f64| {
            let plane = valid_plane(plane, "B")?;
            let r = positive_radius(*r)?;
            let l = nonzero_length(*l)?;
            let cylinder = Cylinder::new(plane, r, l)?;
            Ok(Shared::new(cylinder.to_nurbs()?))
        })
}

/// Cone \[Cone\]: a conical surface on a base circle, with its tip along the plane's normal.
pub fn cone() -> NodeType {
    primitive(CONE, "Cone", "Cone")
        .gh_guid("03e331ed-c4d1-4a23-afa2-f57b87d2043c")
        .description(
            "Creates a conical surface (without a cap): the base circle of the given radius \
             lies in the base plane and the tip is at the length along the plane's z axis \
             (behind the plane for a negative length). openNURBS's exact NURBS form: degree \
             2 × 1, u is the circle parameter on 0 to 2π starting on the plane's x axis, v the \
             axial distance from the tip, so the tip is the singular side v = 0 (the domain is \
             −L to 0, or 0 to −L for a negative length). Normals point away from the axis. A radius that is not positive or a \
             zero length is an error.",
        )
        .input(base_port(
            "Base plane: the centre and plane of the base circle, its z axis pointing to the \
             tip. A point becomes the plane parallel to World XY. Default World XY.",
        ))
        .input(radius_port(
            "Radius of the base circle, in model units; positive. Default 1.",
        ))
        .input(length_port(
            "Distance from the base to the tip along the plane's z axis, in model units; not \
             zero, negative puts the tip behind the plane. Default 10.",
        ))
        .output(
            Port::new("Cone", "C", DataType::Surface)
                .doc("The lateral surface of the cone, a NURBS surface with the tip at v = 0."),
        )
        .output(Port::new("Tip", "T", DataType::Point).doc("The tip (apex) of the cone."))
        .solve(|s| {
            let plane = valid_plane(s.item::<Plane>(0)?, "B")?;
            let r = positive_radius(*s.item::<f64>(1)?)?;
            let l = nonzero_length(*s.item::<f64>(2)?)?;
            let tip: Point3 = plane.point_at(0.0, 0.0, l);
            // openNURBS's cone has its apex at the plane's origin and the base at `height`
            // along the axis: the apex plane keeps the base plane's axes, so u still starts on
            // the base plane's x axis, and the base is at −L from it.
            let apex_plane = Plane {
                origin: tip,
                ..plane
            };
            let cone = Cone::new(apex_plane, -l, r)?;
            s.set(0, Shared::new(cone.to_nurbs()?));
            s.set(1, tip);
            Ok(())
        })
}

/// Plane Surface \[PlaneSrf\]: a rectangle in a plane, from two domains.
pub fn plane_surface() -> NodeType {
    primitive(PLANE_SURFACE, "Plane Surface", "PlaneSrf")
        .gh_guid("439a55a5-2f9e-4f66-9de2-32f24fec2ef5")
        .description(
            "Creates a rectangular planar surface: the points of the plane whose x coordinate \
             lies in the X domain and y coordinate in the Y domain. As Rhino's PlaneSurface, \
             the domains are the surface's parameter domains (u along the plane's x axis, v \
             along its y axis; degree 1 × 1, 2 × 2 control points), so evaluating at (x, y) \
             gives the plane's point at (x, y). A decreasing domain is used as the same \
             interval increasing; a domain of zero length or with a non-finite end is an \
             error. A number given for a domain means 0 to that number.",
        )
        .input(
            Port::new("Plane", "P", DataType::Plane)
                .default_value(Plane::WORLD_XY)
                .doc("Plane of the surface. Default World XY."),
        )
        .input(
            Port::new("X Size", "X", DataType::Domain)
                .default_value(Interval::new(0.0, 10.0))
                .doc("Extent along the plane's x axis, a domain in model units. Default 0 to 10."),
        )
        .input(
            Port::new("Y Size", "Y", DataType::Domain)
                .default_value(Interval::new(0.0, 10.0))
                .doc("Extent along the plane's y axis, a domain in model units. Default 0 to 10."),
        )
        .output(
            Port::new("Plane", "P", DataType::Surface)
                .doc("The planar surface, with the X and Y domains as its u and v domains."),
        )
        .lift3(|plane: &Plane, x: &Interval, y: &Interval| {
            let plane = valid_plane(plane, "P")?;
            let x = extent(*x, "X")?;
            let y = extent(*y, "Y")?;
            Ok(Shared::new(NurbsSurface::from_plane(&plane, x, y)?))
        })
}

/// A finite domain of non-zero length, made increasing.
fn extent(d: Interval, input: &str) -> Result<Interval, NodeError> {
    if !d.is_finite() {
        return Err(format!(
            "input {input}: the domain {} to {} is not finite",
            d.t0, d.t1
        )
        .into());
    }
    if d.t0 == d.t1 {
        return Err(format!("input {input}: the domain {} to {} is empty", d.t0, d.t1).into());
    }
    Ok(d.increasing())
}

#[cfg(test)]
mod tests {
    use std::f64::consts::{FRAC_PI_2, PI, TAU};

    use locus_kernel::{SurfaceSide, Vector3};
    use locus_runtime::{DataTree, Level, NodeCall, NodeCallResult, Value};

    use super::*;

    const EPS: f64 = 1e-12;

    fn surface(r: &NodeCallResult, output: usize) -> Shared<NurbsSurface> {
        match r.outputs[output].values().next().flatten() {
            Some(Value::Surface(s)) => s,
            other => panic!("no surface: {other:?} {:?}", r.messages),
        }
    }

    fn errors(r: &NodeCallResult) -> Vec<String> {
        r.messages
            .iter()
            .filter(|m| m.level == Level::Error)
            .map(|m| m.text.clone())
            .collect()
    }

    #[test]
    fn sphere_defaults_to_the_unit_sphere_with_poles_at_the_v_ends() {
        let r = NodeCall::new(&sphere()).run();
        assert!(r.messages.is_empty(), "{:?}", r.messages);
        let s = surface(&r, 0);
        assert_eq!(s.domain_u(), Interval::new(0.0, TAU));
        assert_eq!(s.domain_v(), Interval::new(-FRAC_PI_2, FRAC_PI_2));
        assert_eq!(
            s.singular_point(SurfaceSide::South),
            Some(Point3::new(0.0, 0.0, -1.0))
        );
        assert_eq!(
            s.singular_point(SurfaceSide::North),
            Some(Point3::new(0.0, 0.0, 1.0))
        );
        assert!(!s.is_singular(SurfaceSide::West));
        for (u, v) in [(0.3, 0.2), (2.0, -1.0), (5.5, 1.4)] {
            assert!((s.point_at(u, v).distance(Point3::ORIGIN) - 1.0).abs() < EPS);
        }
        assert!(
            s.point_at(0.0, 0.0)
                .abs_diff_eq(Point3::new(1.0, 0.0, 0.0), EPS)
        );
        assert!(
            s.point_at(PI / 2.0, 0.0)
                .abs_diff_eq(Point3::new(0.0, 1.0, 0.0), EPS)
        );
    }

    #[test]
    fn sphere_takes_a_point_cast_to_a_plane_and_a_radius() {
        let centre = Point3::new(1.0, 2.0, 3.0);
        let plane = Plane {
            origin: centre,
            ..Plane::WORLD_XY
        };
        let r = NodeCall::new(&sphere())
            .input(DataTree::from_item(plane))
            .input(DataTree::from_list(vec![2.0, 0.5]))
            .run();
        assert_eq!(r.outputs[0].item_count(), 2);
        let s = surface(&r, 0);
        assert!((s.point_at(1.0, 0.5).distance(centre) - 2.0).abs() < EPS);
        let n = s.normal_at(1.0, 0.5).unwrap();
        assert!((n - (s.point_at(1.0, 0.5) - centre) / 2.0).length() < EPS);
    }

    #[test]
    fn bad_radii_are_errors_and_leave_nulls() {
        let r = NodeCall::new(&sphere())
            .skip_input()
            .input(DataTree::from_list(vec![0.0, -1.0, f64::NAN, 1.0]))
            .run();
        let out: Vec<Option<Value>> = r.outputs[0].values().collect();
        assert_eq!(out.len(), 4);
        assert!(out[..3].iter().all(Option::is_none));
        assert!(out[3].is_some());
        let e = errors(&r);
        assert_eq!(e.len(), 3, "{e:?}");
        assert!(e.iter().all(|t| t.contains("input R")), "{e:?}");
    }

    #[test]
    fn degenerate_planes_are_errors() {
        let flat = Plane {
            origin: Point3::ORIGIN,
            x_axis: Vector3::X,
            y_axis: Vector3::X,
            z_axis: Vector3::ZERO,
        };
        for node in [sphere(), cylinder(), cone()] {
            let r = NodeCall::new(&node).input(DataTree::from_item(flat)).run();
            assert!(r.outputs[0].values().all(|v| v.is_none()));
            assert!(errors(&r)[0].contains("input B"), "{:?}", r.messages);
        }
        let r = NodeCall::new(&plane_surface())
            .input(DataTree::from_item(flat))
            .run();
        assert!(errors(&r)[0].contains("input P"), "{:?}", r.messages);
    }

    #[test]
    fn sphere_fit_gives_back_a_sphere_and_reports_bad_points() {
        // The six points where the sphere of radius 2 about (1, -2, 3) meets its axes.
        let c = Point3::new(1.0, -2.0, 3.0);
        let points: Vec<Point3> = [
            Vector3::X,
            -Vector3::X,
            Vector3::Y,
            -Vector3::Y,
            Vector3::Z,
            -Vector3::Z,
        ]
        .iter()
        .map(|&d| c + d * 2.0)
        .collect();
        let r = NodeCall::new(&sphere_fit())
            .input(DataTree::from_list(points))
            .run();
        assert!(r.messages.is_empty(), "{:?}", r.messages);
        match r.outputs[0].values().next().flatten() {
            Some(Value::Point(p)) => assert!(p.distance(c) < EPS),
            other => panic!("no centre: {other:?}"),
        }
        match r.outputs[1].values().next().flatten() {
            Some(Value::Number(radius)) => assert!((radius - 2.0).abs() < EPS),
            other => panic!("no radius: {other:?}"),
        }
        let s = surface(&r, 2);
        for (u, v) in [(0.3, 0.2), (2.0, -1.0), (5.5, 1.4)] {
            assert!((s.point_at(u, v).distance(c) - 2.0).abs() < EPS);
        }

        // Too few points, points on one circle (one plane), a NaN point: errors naming P.
        let square = vec![
            Point3::new(1.0, 0.0, 0.0),
            Point3::new(0.0, 1.0, 0.0),
            Point3::new(-1.0, 0.0, 0.0),
            Point3::new(0.0, -1.0, 0.0),
        ];
        let mut with_nan = square.clone();
        with_nan.push(Point3::new(f64::NAN, 0.0, 1.0));
        for bad in [square[..3].to_vec(), square, with_nan] {
            let r = NodeCall::new(&sphere_fit())
                .input(DataTree::from_list(bad))
                .run();
            let errors = errors(&r);
            assert_eq!(errors.len(), 1, "{errors:?}");
            assert!(errors[0].contains("input P"), "{errors:?}");
            assert_eq!(r.outputs[2].values().next().flatten(), None);
        }
    }

    #[test]
    fn cylinder_runs_along_the_plane_normal() {
        let r = NodeCall::new(&cylinder())
            .skip_input()
            .input(DataTree::from_item(2.0))
            .input(DataTree::from_item(-3.0))
            .run();
        assert!(r.messages.is_empty(), "{:?}", r.messages);
        let s = surface(&r, 0);
        assert_eq!(s.domain_v(), Interval::new(-3.0, 0.0));
        assert!(
            s.point_at(0.0, -3.0)
                .abs_diff_eq(Point3::new(2.0, 0.0, -3.0), EPS)
        );
        let n = s.normal_at(0.0, -1.0).unwrap();
        assert!((n - Vector3::X).length() < EPS, "{n:?}");
        let bad = NodeCall::new(&cylinder())
            .skip_input()
            .skip_input()
            .input(DataTree::from_item(0.0))
            .run();
        assert!(errors(&bad)[0].contains("input L"));
    }

    #[test]
    fn cone_has_its_base_on_the_plane_and_its_tip_singular() {
        let r = NodeCall::new(&cone())
            .skip_input()
            .input(DataTree::from_item(2.0))
            .input(DataTree::from_item(4.0))
            .run();
        assert!(r.messages.is_empty(), "{:?}", r.messages);
        let s = surface(&r, 0);
        let tip = Point3::new(0.0, 0.0, 4.0);
        assert_eq!(r.outputs[1], DataTree::from_item(tip));
        assert_eq!(s.domain_v(), Interval::new(-4.0, 0.0));
        assert_eq!(s.singular_point(SurfaceSide::North), Some(tip));
        // The base circle lies in World XY, starting on the x axis.
        assert!(
            s.point_at(0.0, -4.0)
                .abs_diff_eq(Point3::new(2.0, 0.0, 0.0), EPS)
        );
        assert!(
            s.point_at(PI, -4.0)
                .abs_diff_eq(Point3::new(-2.0, 0.0, 0.0), EPS)
        );
        // Outward normals: away from the axis and up (the slope is 2 in 4).
        let n = s.normal_at(0.0, -2.0).unwrap();
        let want = Vector3::new(4.0, 0.0, 2.0) / 20f64.sqrt();
        assert!((n - want).length() < 1e-12, "{n:?}");
        // A negative length puts the tip below the plane.
        let down = NodeCall::new(&cone())
            .skip_input()
            .skip_input()
            .input(DataTree::from_item(-1.0))
            .run();
        let s = surface(&down, 0);
        assert_eq!(
            down.outputs[1],
            DataTree::from_item(Point3::new(0.0, 0.0, -1.0))
        );
        assert!(
            s.point_at(0.0, 1.0)
                .abs_diff_eq(Point3::new(1.0, 0.0, 0.0), EPS)
        );
        let bad = NodeCall::new(&cone())
            .skip_input()
            .input(DataTree::from_item(f64::INFINITY))
            .run();
        assert!(errors(&bad)[0].contains("input R"));
    }

    #[test]
    fn plane_surface_uses_the_domains_as_parameters() {
        let plane = Plane {
            origin: Point3::new(0.0, 0.0, 5.0),
            ..Plane::WORLD_YZ
        };
        let r = NodeCall::new(&plane_surface())
            .input(DataTree::from_item(plane))
            .input(DataTree::from_item(Interval::new(3.0, -1.0)))
            .input(DataTree::from_item(Interval::new(0.0, 2.0)))
            .run();
        assert!(r.messages.is_empty(), "{:?}", r.messages);
        let s = surface(&r, 0);
        assert_eq!(s.domain_u(), Interval::new(-1.0, 3.0));
        assert!(
            s.point_at(2.0, 1.0)
                .abs_diff_eq(plane.point_at(2.0, 1.0, 0.0), EPS)
        );
        let bad = NodeCall::new(&plane_surface())
            .skip_input()
            .input(DataTree::from_item(Interval::new(1.0, 1.0)))
            .input(DataTree::from_item(Interval::new(0.0, f64::NAN)))
            .run();
        let e = errors(&bad);
        assert!(e[0].contains("input X"), "{e:?}");
        let defaults = NodeCall::new(&plane_surface()).run();
        let s = surface(&defaults, 0);
        assert_eq!(s.domain_u(), Interval::new(0.0, 10.0));
    }
}

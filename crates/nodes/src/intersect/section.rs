//! Intersect, on B-reps: Brep | Plane (a section) and Contour (a series of parallel sections of
//! a B-rep or a mesh), and Brep | Brep (Physical: where two B-reps meet).
//!
//! Sections come from the kernel ([`Brep::intersect_plane`], [`Brep::contour`],
//! [`mesh_plane`], [`Brep::intersect_brep`]) within the intersection tolerance: planar faces give exact lines, curved
//! faces curves traced on the surface and fitted within a hundredth of the tolerance, all
//! joined across the B-rep's edges.

use locus_kernel::{Brep, Curve, Mesh, Plane, Point3, Vector3, contour_planes, mesh_plane};
use locus_runtime::{
    Branch, DataTree, DataType, NodeError, NodeRegistry, NodeType, Port, Shared, Solve, TreePath,
    Value, cast_value,
};

use super::INTERSECTION_TOLERANCE;
use crate::surface::brep::brep_item;

/// Id of [`brep_plane_node`].
pub const BREP_PLANE: &str = "intersect.brep_plane";
/// Id of [`contour_node`].
pub const CONTOUR: &str = "intersect.contour";

/// Id of [`brep_brep_node`].
pub const BREP_BREP: &str = "intersect.brep_brep";

/// Registers Brep | Plane, Contour and Brep | Brep.
pub fn register(registry: &mut NodeRegistry) {
    registry.register(brep_plane_node());
    registry.register(contour_node());
    registry.register(brep_brep_node());
}

fn mathematical(id: &str, name: &str, nickname: &str) -> NodeType {
    NodeType::new(id, name, nickname, "Intersect").subcategory("Mathematical")
}

/// Brep | Plane \[Sec\]: the section of a B-rep by a plane.
pub fn brep_plane_node() -> NodeType {
    mathematical(BREP_PLANE, "Brep | Plane", "Sec")
        .gh_guid("4fe828e8-fa95-4cc5-9a8c-c33856ecc783")
        .description(
            "Solves the section of a B-rep by a plane, within the intersection tolerance \
             (0.001): the section curves, joined across the B-rep's edges and closed where the \
             section goes round (a box gives a polygon of lines, a sphere a circle, a cylinder \
             an ellipse), and the points where the B-rep only touches the plane (a corner, a \
             tangent face). A face lying in the plane contributes its boundary.",
        )
        .input(
            Port::new("Brep", "B", DataType::Brep)
                .doc("The B-rep to cut. Boxes and surfaces are taken as B-reps."),
        )
        .input(
            Port::new("Plane", "P", DataType::Plane)
                .doc("The section plane. Default the world XY plane.")
                .default_value(Plane::WORLD_XY),
        )
        .output(
            Port::new("Curves", "C", DataType::Curve)
                .doc("The section curves.")
                .list(),
        )
        .output(
            Port::new("Points", "P", DataType::Point)
                .doc("The points where the B-rep touches the plane without a curve through them.")
                .list(),
        )
        .solve(|s| {
            let brep = brep_item(s, 0)?;
            let plane = *s.item::<Plane>(1)?;
            if !plane.is_valid() {
                return Err("plane P is not a valid plane".into());
            }
            let section = brep.intersect_plane(&plane, INTERSECTION_TOLERANCE)?;
            s.set_list(0, section.curves.into_iter().map(Shared::new).collect());
            s.set_list(1, section.points);
            Ok(())
        })
}

/// Brep | Brep \[BBX\]: where two B-reps meet.
pub fn brep_brep_node() -> NodeType {
    NodeType::new(BREP_BREP, "Brep | Brep", "BBX", "Intersect")
        .subcategory("Physical")
        .gh_guid("904e4b56-484a-4814-b35f-aa4baf362117")
        .description(
            "Solves where two B-reps meet, within the intersection tolerance (0.001): the \
             intersection curves, traced on both surfaces of every pair of faces, kept where \
             they lie on both faces, joined across the edges and closed where they go round \
             (two spheres give a circle, two overlapping boxes a polygon of lines), and the \
             points where the B-reps only touch. Regions where the two B-reps coincide (faces \
             lying on each other) give no curves, with a warning.",
        )
        .input(
            Port::new("Brep A", "A", DataType::Brep)
                .doc("The first B-rep. Boxes and surfaces are taken as B-reps."),
        )
        .input(
            Port::new("Brep B", "B", DataType::Brep)
                .doc("The second B-rep. Boxes and surfaces are taken as B-reps."),
        )
        .output(
            Port::new("Curves", "C", DataType::Curve)
                .doc("The intersection curves.")
                .list(),
        )
        .output(
            Port::new("Points", "P", DataType::Point)
                .doc("The points where the B-reps touch without a curve through them.")
                .list(),
        )
        .solve(|s| {
            let a = brep_item(s, 0)?;
            let b = brep_item(s, 1)?;
            let x = a.intersect_brep(&b, INTERSECTION_TOLERANCE)?;
            if x.coincident {
                s.warning(
                    "the B-reps coincide over a region (faces lying on each other): the region \
                     gives no curves or points",
                );
            }
            s.set_list(0, x.curves.into_iter().map(Shared::new).collect());
            s.set_list(1, x.points);
            Ok(())
        })
}

/// The shape of a contour: a B-rep (boxes and surfaces cast to one) or a mesh.
enum Shape {
    Brep(Shared<Brep>),
    Mesh(Shared<Mesh>),
}

fn shape_input(s: &Solve<'_>) -> Result<Shape, NodeError> {
    let value = s
        .value(0)
        .ok_or_else(|| NodeError::from("input S has no item"))?;
    if let Value::Mesh(m) = &value {
        if !m.vertices().iter().all(|p| p.is_finite()) {
            return Err("the mesh S has a vertex that is not finite".into());
        }
        return Ok(Shape::Mesh(m.clone()));
    }
    match cast_value(&value, DataType::Brep) {
        Ok(Value::Brep(brep)) => {
            let finite = brep.vertices().iter().all(|v| v.point.is_finite())
                && brep.faces().iter().all(|f| f.surface.is_finite());
            if !finite {
                return Err("the brep S has a coordinate that is not finite".into());
            }
            Ok(Shape::Brep(brep))
        }
        _ => Err(NodeError(format!(
            "shape S must be a brep, surface, box or mesh, not a {}",
            value.data_type().name().to_lowercase()
        ))),
    }
}

/// Contour \[Contour\]: parallel sections of a B-rep or a mesh.
pub fn contour_node() -> NodeType {
    mathematical(CONTOUR, "Contour", "Contour")
        .gh_guid("3b112fb6-3eba-42d2-ba75-0f903c18faab")
        .description(
            "Cuts a B-rep or a mesh with a series of parallel planes: the planes normal to the \
             direction N through P + k·D·N̂ for every whole number k, as far as the shape \
             reaches on either side of P. Each plane that cuts the shape gives one branch of \
             section curves (B-rep sections as Brep | Plane, mesh sections as Mesh | Plane \
             polylines), in increasing k; planes that miss the shape or only touch it are left \
             out.",
        )
        .input(
            Port::new("Shape", "S", DataType::Generic)
                .doc("The B-rep (or surface, box) or mesh to contour."),
        )
        .input(
            Port::new("Point", "P", DataType::Point)
                .doc("A point on one of the contour planes. Default the world origin.")
                .default_value(Point3::ORIGIN),
        )
        .input(
            Port::new("Direction", "N", DataType::Vector)
                .doc("The direction of the contour planes' normal. Default the world z axis.")
                .default_value(Vector3::Z),
        )
        .input(
            Port::new("Distance", "D", DataType::Number)
                .doc("The distance between consecutive planes, positive. Default 1.")
                .default_value(1.0),
        )
        .output(
            Port::new("Contours", "C", DataType::Curve)
                .doc("The section curves, one branch per plane that cuts the shape.")
                .tree(),
        )
        .output(
            Port::new("Planes", "P", DataType::Plane)
                .doc("The planes of the branches of C, in the same order.")
                .list(),
        )
        .solve(|s| {
            let shape = shape_input(s)?;
            let point = *s.item::<Point3>(1)?;
            let direction = *s.item::<Vector3>(2)?;
            let distance = *s.item::<f64>(3)?;
            if !point.is_finite() {
                return Err("point P is not finite".into());
            }
            if !direction.is_finite() || direction.length_squared() == 0.0 {
                return Err("direction N is zero or not finite".into());
            }
            if !(distance.is_finite() && distance > 0.0) {
                return Err(format!("distance D must be positive, got {distance}").into());
            }
            let sections: Vec<(Plane, Vec<Curve>)> = match shape {
                Shape::Brep(b) => b
                    .contour(point, direction, distance, INTERSECTION_TOLERANCE)?
                    .into_iter()
                    .map(|c| (c.plane, c.section.curves))
                    .collect(),
                Shape::Mesh(m) => contour_planes(m.bounding_box(), point, direction, distance)?
                    .into_iter()
                    .map(|(_, plane)| {
                        let curves = mesh_plane(&m, &plane, INTERSECTION_TOLERANCE)
                            .into_iter()
                            .map(Curve::from)
                            .collect();
                        (plane, curves)
                    })
                    .collect(),
            };
            let base = {
                let index = u32::try_from(s.index().unwrap_or(0)).unwrap_or(u32::MAX);
                s.path().with_appended(index)
            };
            let mut branches: Vec<(TreePath, Branch)> = Vec::new();
            let mut planes = Vec::new();
            for (plane, curves) in sections.into_iter().filter(|c| !c.1.is_empty()) {
                let j = u32::try_from(planes.len()).unwrap_or(u32::MAX);
                let mut branch = Branch::new(DataType::Curve);
                for c in curves {
                    branch.push(Shared::new(c));
                }
                branches.push((base.with_appended(j), branch));
                planes.push(plane);
            }
            s.set_tree(0, DataTree::from_branches(branches));
            s.set_list(1, planes);
            Ok(())
        })
}

#[cfg(test)]
mod tests {
    use std::f64::consts::PI;

    use locus_kernel::{Interval, MeshingParameters, OrientedBox, Sphere};
    use locus_runtime::{Level, NodeCall};

    use super::*;
    use crate::test_support::{assert_clean, assert_error, curves, messages, points};

    fn brep(b: Brep) -> DataTree {
        DataTree::from_item(Shared::new(b))
    }

    /// The box [0, 2] × [0, 3] × [0, 4].
    fn a_box() -> OrientedBox {
        OrientedBox::new(
            Plane::WORLD_XY,
            Interval::new(0.0, 2.0),
            Interval::new(0.0, 3.0),
            Interval::new(0.0, 4.0),
        )
    }

    fn sphere() -> Brep {
        Brep::from_sphere(&Sphere::new(Point3::new(1.0, -2.0, 0.5), 3.0).unwrap()).unwrap()
    }

    fn plane(origin: Point3, normal: Vector3) -> DataTree {
        DataTree::from_item(Plane::from_normal(origin, normal).unwrap())
    }

    #[test]
    fn a_box_cut_across_gives_its_rectangle() {
        let r = NodeCall::new(&brep_plane_node())
            .input(brep(Brep::from_box(&a_box()).unwrap()))
            .input(plane(Point3::new(0.0, 0.0, 1.5), Vector3::Z))
            .run();
        assert_clean(&r);
        let c = curves(&r.outputs[0]);
        assert_eq!(c.len(), 1);
        assert!(c[0].is_closed());
        // The 2 × 3 rectangle.
        assert!((c[0].length() - 10.0).abs() < 1e-12, "{}", c[0].length());
        assert!(points(&r.outputs[1]).is_empty());
    }

    #[test]
    fn a_box_given_as_a_box_is_cut_as_a_brep_and_a_corner_touch_is_a_point() {
        // The plane x + y + z = 9 touches the box only at its corner (2, 3, 4).
        let r = NodeCall::new(&brep_plane_node())
            .input(DataTree::from_item(a_box()))
            .input(plane(
                Point3::new(2.0, 3.0, 4.0),
                Vector3::new(1.0, 1.0, 1.0),
            ))
            .run();
        assert_clean(&r);
        assert!(curves(&r.outputs[0]).is_empty());
        let p = points(&r.outputs[1]);
        assert_eq!(p.len(), 1);
        assert!(p[0].distance(Point3::new(2.0, 3.0, 4.0)) < 1e-12);
    }

    #[test]
    fn a_sphere_section_is_a_circle_of_radius_root_r2_minus_d2() {
        // Centre (1, -2, 0.5), R = 3; the plane z = 2.5 is 2 above the centre: r = √5.
        let r = NodeCall::new(&brep_plane_node())
            .input(brep(sphere()))
            .input(plane(Point3::new(0.0, 0.0, 2.5), Vector3::Z))
            .run();
        assert_clean(&r);
        let c = curves(&r.outputs[0]);
        assert_eq!(c.len(), 1);
        assert!(c[0].is_closed());
        let want = 2.0 * PI * 5f64.sqrt();
        assert!(
            (c[0].length() - want).abs() < 1e-6 * want,
            "{}",
            c[0].length()
        );
        for k in 0..20 {
            let t = c[0].domain().parameter_at(k as f64 / 20.0);
            let q = c[0].point_at(t);
            assert!((q.z - 2.5).abs() < 1e-9);
            let radial = ((q.x - 1.0).powi(2) + (q.y + 2.0).powi(2)).sqrt();
            assert!((radial - 5f64.sqrt()).abs() < 1e-5, "{radial}");
        }
    }

    #[test]
    fn two_spheres_meet_in_a_circle_and_touching_ones_in_a_point() {
        // Radii 3 and 2, centres 4 apart: the circle at distance (16 + 9 − 4) / 8 from the
        // first centre, of radius √(9 − 441/64).
        let other = |x: f64| {
            brep(
                Brep::from_sphere(&Sphere::new(Point3::new(1.0 + x, -2.0, 0.5), 2.0).unwrap())
                    .unwrap(),
            )
        };
        let r = NodeCall::new(&brep_brep_node())
            .input(brep(sphere()))
            .input(other(4.0))
            .run();
        assert_clean(&r);
        let c = curves(&r.outputs[0]);
        assert_eq!(c.len(), 1);
        assert!(c[0].is_closed());
        let radius = (9.0f64 - 441.0 / 64.0).sqrt();
        let want = 2.0 * PI * radius;
        assert!((c[0].length() - want).abs() < 1e-6, "{}", c[0].length());
        assert!(points(&r.outputs[1]).is_empty());

        let r = NodeCall::new(&brep_brep_node())
            .input(brep(sphere()))
            .input(other(5.0))
            .run();
        assert_clean(&r);
        assert!(curves(&r.outputs[0]).is_empty());
        let p = points(&r.outputs[1]);
        assert_eq!(p.len(), 1);
        assert!(p[0].distance(Point3::new(4.0, -2.0, 0.5)) < 1e-3);
    }

    #[test]
    fn a_box_through_a_sphere_and_bad_input() {
        let r = NodeCall::new(&brep_brep_node())
            .input(DataTree::from_item(a_box()))
            .input(brep(
                Brep::from_sphere(&Sphere::new(Point3::new(1.0, 1.5, 4.0), 1.0).unwrap()).unwrap(),
            ))
            .run();
        assert_clean(&r);
        // The top face z = 4 cuts the sphere along its equator, a circle of radius 1 inside
        // the face.
        let c = curves(&r.outputs[0]);
        assert_eq!(c.len(), 1);
        assert!(c[0].is_closed());
        assert!((c[0].length() - 2.0 * PI).abs() < 1e-6, "{}", c[0].length());

        let r = NodeCall::new(&brep_brep_node())
            .input(brep(sphere()))
            .input(DataTree::from_item(Point3::ORIGIN))
            .run();
        assert_error(&r, "B");

        let r = NodeCall::new(&brep_brep_node())
            .input(brep(sphere()))
            .input(brep(sphere()))
            .run();
        assert!(curves(&r.outputs[0]).is_empty() && points(&r.outputs[1]).is_empty());
        let m = messages(&r, Level::Warning);
        assert!(m.iter().any(|t| t.contains("coincide")), "{m:?}");
    }

    #[test]
    fn a_plane_missing_the_brep_gives_nothing() {
        let r = NodeCall::new(&brep_plane_node())
            .input(brep(sphere()))
            .input(plane(Point3::new(0.0, 0.0, 10.0), Vector3::Z))
            .run();
        assert_clean(&r);
        assert!(curves(&r.outputs[0]).is_empty() && points(&r.outputs[1]).is_empty());
    }

    #[test]
    fn brep_plane_reports_bad_input() {
        let r = NodeCall::new(&brep_plane_node())
            .input(DataTree::from_item(Value::Number(2.0)))
            .run();
        assert_error(&r, "Number → Brep");
        let bad = Plane {
            z_axis: Vector3::ZERO,
            ..Plane::WORLD_XY
        };
        let r = NodeCall::new(&brep_plane_node())
            .input(brep(sphere()))
            .input(DataTree::from_item(bad))
            .run();
        assert_error(&r, "plane P is not a valid plane");
    }

    #[test]
    fn box_contours_are_rectangles_one_branch_per_plane() {
        // Planes z = 0, 1, 2, 3, 4 meet the box; z = 0 and z = 4 lie on its bottom and top,
        // which give their boundaries.
        let r = NodeCall::new(&contour_node())
            .input(brep(Brep::from_box(&a_box()).unwrap()))
            .run();
        assert_clean(&r);
        let branches = r.outputs[0].branches();
        assert_eq!(branches.len(), 5);
        for (k, (path, branch)) in branches.iter().enumerate() {
            assert_eq!(path.to_string(), format!("{{0;0;{k}}}"));
            assert_eq!(branch.len(), 1);
            let c = branch.get::<Shared<Curve>>(0).unwrap();
            assert!(c.is_closed());
            assert!((c.length() - 10.0).abs() < 1e-12);
            assert!((c.start_point().z - k as f64).abs() < 1e-12);
        }
        let planes = crate::test_support::all::<Plane>(&r.outputs[1]);
        assert_eq!(planes.len(), 5);
        assert!((planes[3].origin.z - 3.0).abs() < 1e-12);
    }

    #[test]
    fn sphere_contours_are_circles_of_the_right_radii() {
        // R = 3 about z = 0.5, planes z = 0.5 + 1.25 k through P = (0, 0, 0.5): k = -2 … 2,
        // radii √(9 − (1.25 k)²).
        let r = NodeCall::new(&contour_node())
            .input(brep(sphere()))
            .input(DataTree::from_item(Point3::new(0.0, 0.0, 0.5)))
            .input(DataTree::from_item(Vector3::new(0.0, 0.0, 7.0)))
            .input(DataTree::from_item(1.25))
            .run();
        assert_clean(&r);
        let branches = r.outputs[0].branches();
        assert_eq!(branches.len(), 5);
        for (j, (_, branch)) in branches.iter().enumerate() {
            let h = 1.25 * (j as f64 - 2.0);
            let radius = (9.0 - h * h).sqrt();
            let c = branch.get::<Shared<Curve>>(0).unwrap();
            let want = 2.0 * PI * radius;
            assert!(
                (c.length() - want).abs() < 1e-6 * want,
                "{j}: {}",
                c.length()
            );
        }
    }

    #[test]
    fn mesh_contours_are_polylines() {
        let b = Brep::from_box(&a_box()).unwrap();
        let mesh = Mesh::from_brep(&b, &MeshingParameters::default()).unwrap();
        let r = NodeCall::new(&contour_node())
            .input(DataTree::from_item(Shared::new(mesh)))
            .input(DataTree::from_item(Point3::new(0.0, 0.5, 0.0)))
            .input(DataTree::from_item(Vector3::Y))
            .run();
        assert_clean(&r);
        // Planes y = 0.5, 1.5, 2.5 cut the box: 2 × 4 rectangles.
        let all = curves(&r.outputs[0]);
        let lengths: Vec<f64> = all.iter().map(|c| c.length()).collect();
        assert_eq!(r.outputs[0].branches().len(), 3, "{lengths:?}");
        assert!(
            lengths.iter().all(|l| (l - 12.0).abs() < 1e-9),
            "{lengths:?}"
        );
    }

    #[test]
    fn contour_reports_bad_input() {
        let run = |shape: DataTree, n: Vector3, d: f64| {
            NodeCall::new(&contour_node())
                .input(shape)
                .input(DataTree::from_item(Point3::ORIGIN))
                .input(DataTree::from_item(n))
                .input(DataTree::from_item(d))
                .run()
        };
        let b = || brep(Brep::from_box(&a_box()).unwrap());
        assert_error(&run(b(), Vector3::ZERO, 1.0), "direction N is zero");
        assert_error(&run(b(), Vector3::Z, 0.0), "distance D must be positive");
        assert_error(&run(b(), Vector3::Z, -1.0), "distance D must be positive");
        assert_error(&run(b(), Vector3::Z, 1e-9), "more than");
        let r = run(DataTree::from_item(Point3::ORIGIN), Vector3::Z, 1.0);
        assert_error(
            &r,
            "shape S must be a brep, surface, box or mesh, not a point",
        );
        assert!(messages(&r, Level::Warning).is_empty());
    }
}

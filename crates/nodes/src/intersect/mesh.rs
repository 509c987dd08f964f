//! Intersect › Mathematical, on meshes: Mesh | Ray and Mesh | Plane.

use locus_kernel::{Curve, Mesh, Plane, Point3, Vector3, mesh_plane, mesh_ray};
use locus_runtime::{DataType, NodeRegistry, NodeType, Port, Shared};

use super::INTERSECTION_TOLERANCE;

/// Id of [`mesh_ray_node`].
pub const MESH_RAY: &str = "intersect.mesh_ray";
/// Id of [`mesh_plane_node`].
pub const MESH_PLANE: &str = "intersect.mesh_plane";

/// Registers the mesh intersection nodes.
pub fn register(registry: &mut NodeRegistry) {
    registry.register(mesh_ray_node());
    registry.register(mesh_plane_node());
}

/// Mesh | Ray \[MeshRay\]: where a ray first hits a mesh.
pub fn mesh_ray_node() -> NodeType {
    NodeType::new(MESH_RAY, "Mesh | Ray", "MeshRay", "Intersect")
        .subcategory("Mathematical")
        .gh_guid("4c02a168-9aba-4f42-8951-2719f24d391f")
        .description(
            "Intersects a mesh with a ray, a half-line from a point along a direction: the \
             first point where the ray hits a face, and whether it hits at all.",
        )
        .input(Port::new("Mesh", "M", DataType::Mesh).doc("The mesh to intersect."))
        .input(Port::new("Point", "P", DataType::Point).doc("The ray's start."))
        .input(
            Port::new("Direction", "D", DataType::Vector)
                .doc("The ray's direction. Default the world z axis.")
                .default_value(Vector3::new(0.0, 0.0, 1.0)),
        )
        .output(
            Port::new("Point", "X", DataType::Point)
                .doc("The first intersection point (null on a miss)."),
        )
        .output(Port::new("Hit", "H", DataType::Boolean).doc("Whether the ray hits the mesh."))
        .solve(|s| {
            let mesh = s.item::<Shared<Mesh>>(0)?.clone();
            let start = *s.item::<Point3>(1)?;
            let direction = *s.item::<Vector3>(2)?;
            if !start.is_finite() {
                return Err("the ray's start P is not finite".into());
            }
            if !direction.is_finite() || direction.length_squared() == 0.0 {
                return Err("the ray's direction D is zero or not finite".into());
            }
            match mesh_ray(&mesh, start, direction) {
                Some((_, point, _)) => {
                    s.set(0, point);
                    s.set(1, true);
                }
                None => s.set(1, false),
            }
            Ok(())
        })
}

/// Mesh | Plane \[Sec\]: the section polylines of a mesh.
pub fn mesh_plane_node() -> NodeType {
    NodeType::new(MESH_PLANE, "Mesh | Plane", "Sec", "Intersect")
        .subcategory("Mathematical")
        .gh_guid("3b1ae469-0e9b-461d-8c30-fa5a7de8b7a9")
        .description(
            "Intersects a mesh with a plane (a section): polylines through the crossed edges, \
             closed where the section goes round, joined across unwelded seams within the \
             intersection tolerance (0.001).",
        )
        .input(Port::new("Mesh", "M", DataType::Mesh).doc("The mesh to cut."))
        .input(
            Port::new("Plane", "P", DataType::Plane)
                .doc("The section plane. Default the world XY plane.")
                .default_value(Plane::WORLD_XY),
        )
        .output(
            Port::new("Curves", "C", DataType::Curve)
                .doc("The section polylines.")
                .list(),
        )
        .solve(|s| {
            let mesh = s.item::<Shared<Mesh>>(0)?.clone();
            let plane = *s.item::<Plane>(1)?;
            if !plane.is_valid() {
                return Err("plane P is not a valid plane".into());
            }
            let curves = mesh_plane(&mesh, &plane, INTERSECTION_TOLERANCE)
                .into_iter()
                .map(|p| Shared::new(Curve::from(p)))
                .collect();
            s.set_list(0, curves);
            Ok(())
        })
}

#[cfg(test)]
mod tests {
    use locus_kernel::{Brep, Interval, MeshingParameters, OrientedBox};
    use locus_runtime::{DataTree, NodeCall};

    use super::*;
    use crate::test_support::{assert_clean, assert_error, curves, is_null, only};

    fn cube() -> Shared<Mesh> {
        let b = OrientedBox::new(
            Plane::WORLD_XY,
            Interval::new(0.0, 2.0),
            Interval::new(0.0, 2.0),
            Interval::new(0.0, 2.0),
        );
        let brep = Brep::from_box(&b).unwrap();
        Shared::new(Mesh::from_brep(&brep, &MeshingParameters::default()).unwrap())
    }

    #[test]
    fn a_ray_from_below_hits_the_bottom() {
        let r = NodeCall::new(&mesh_ray_node())
            .input(DataTree::from_item(cube()))
            .input(DataTree::from_item(Point3::new(1.0, 1.0, -5.0)))
            .run();
        assert_clean(&r);
        assert_eq!(only::<Point3>(&r, 0), Point3::new(1.0, 1.0, 0.0));
        assert!(only::<bool>(&r, 1));
        let r = NodeCall::new(&mesh_ray_node())
            .input(DataTree::from_item(cube()))
            .input(DataTree::from_item(Point3::new(1.0, 1.0, -5.0)))
            .input(DataTree::from_item(Vector3::new(0.0, 0.0, -1.0)))
            .run();
        assert!(is_null(&r, 0) && !only::<bool>(&r, 1));
        let r = NodeCall::new(&mesh_ray_node())
            .input(DataTree::from_item(cube()))
            .input(DataTree::from_item(Point3::new(1.0, 1.0, -5.0)))
            .input(DataTree::from_item(Vector3::ZERO))
            .run();
        assert_error(&r, "direction");
    }

    #[test]
    fn a_section_of_a_cube_is_a_closed_square() {
        let r = NodeCall::new(&mesh_plane_node())
            .input(DataTree::from_item(cube()))
            .input(DataTree::from_item(
                Plane::WORLD_XY.translated(Vector3::new(0.0, 0.0, 0.5)),
            ))
            .run();
        assert_clean(&r);
        let c = curves(&r.outputs[0]);
        assert_eq!(c.len(), 1);
        assert!(c[0].is_closed());
        assert!((c[0].length() - 8.0).abs() < 1e-12);
    }
}

//! Mesh › Primitive and Mesh › Util: the meshes of quads on a grid that Grasshopper makes with
//! Mesh Plane, Mesh Box and Mesh Surface (the kernel's [`Mesh::quad_grid`]).

use locus_kernel::{Curve, Mesh, NurbsSurface, OrientedBox, Point3, Vector3};
use locus_runtime::{DataType, NodeError, NodeRegistry, NodeType, Port, Shared};

use super::mesh_node;
use crate::params::shapes::not_a_rectangle;

/// Id of [`mesh_plane`].
pub const MESH_PLANE: &str = "mesh.mesh_plane";
/// Id of [`mesh_box`].
pub const MESH_BOX: &str = "mesh.mesh_box";
/// Id of [`mesh_surface`].
pub const MESH_SURFACE: &str = "mesh.mesh_surface";

/// The most faces Mesh Plane, Mesh Box (all six sides) and Mesh Surface make: 10,000,000.
pub const MAX_GRID_FACES: i64 = 10_000_000;

/// Registers Mesh Plane, Mesh Box and Mesh Surface.
pub fn register(registry: &mut NodeRegistry) {
    registry.register(mesh_plane());
    registry.register(mesh_box());
    registry.register(mesh_surface());
}

/// A face count port with Grasshopper's default of 10.
fn count_port(name: &str, nickname: &str, doc: &str) -> Port {
    Port::new(name, nickname, DataType::Integer)
        .default_value(10i64)
        .doc(doc)
}

/// The face counts as sizes, checked: each at least 1, their product at most
/// [`MAX_GRID_FACES`].
fn counts(names: &[&str], counts: &[i64], sides: i64) -> Result<Vec<usize>, NodeError> {
    for (name, &n) in names.iter().zip(counts) {
        if n < 1 {
            return Err(format!("{name} must be at least 1, got {n}").into());
        }
    }
    let faces = counts
        .iter()
        .try_fold(sides, |acc, &n| acc.checked_mul(n))
        .filter(|&f| f <= MAX_GRID_FACES);
    if faces.is_none() {
        return Err(format!(
            "the mesh would have more than {MAX_GRID_FACES} faces ({} = {counts:?})",
            names.join(" × ")
        )
        .into());
    }
    Ok(counts.iter().map(|&n| n as usize).collect())
}

/// Mesh Plane \[MPlane\]: a rectangle as a grid of quads.
pub fn mesh_plane() -> NodeType {
    mesh_node(MESH_PLANE, "Mesh Plane", "MPlane", "Primitive")
        .gh_guid("8adbf481-7589-4a40-b490-006531ea001d")
        .description(
            "Creates a mesh of W × H quads on a rectangle, W along its first side and H along \
             its second, with normals on the side the rectangle's corners turn \
             counter-clockwise around.",
        )
        .input(
            Port::new("Boundary", "B", DataType::Curve)
                .doc("The rectangle (a closed polyline of four sides with right angles)."),
        )
        .input(count_port(
            "Width Count",
            "W",
            "The number of faces along the first side; at least 1.",
        ))
        .input(count_port(
            "Height Count",
            "H",
            "The number of faces along the second side; at least 1.",
        ))
        .output(Port::new("Mesh", "M", DataType::Mesh).doc("The mesh."))
        .output(Port::new("Area", "A", DataType::Number).doc("The area of the mesh."))
        .solve(|s| {
            let boundary = s.item::<Shared<Curve>>(0)?;
            if let Some(why) = not_a_rectangle(boundary) {
                return Err(format!("the boundary is not a rectangle: {why}").into());
            }
            let Curve::Polyline { polyline, .. } = &**boundary else {
                return Err("the boundary is not a rectangle".into());
            };
            let p = polyline.points();
            let n = counts(&["W", "H"], &[*s.item::<i64>(1)?, *s.item::<i64>(2)?], 1)?;
            let (w, h) = (p[1] - p[0], p[3] - p[0]);
            let mesh = Mesh::quad_grid(n[0], n[1], |i, j| {
                p[0] + w * (i as f64 / n[0] as f64) + h * (j as f64 / n[1] as f64)
            })?;
            let normal = w.cross(h).unitize()?;
            let count = mesh.vertices().len();
            let mesh = mesh.with_normals(vec![normal; count])?;
            s.set(0, Shared::new(mesh));
            s.set(1, w.length() * h.length());
            Ok(())
        })
}

/// The six sides of a box as (corner, first direction, second direction, first count, second
/// count), each turning counter-clockwise seen from outside: the box's axes scaled to its
/// extents, `counts` being the faces along x, y and z.
fn box_sides(b: &OrientedBox, counts: [usize; 3]) -> [(Point3, Vector3, Vector3, usize, usize); 6] {
    let [nx, ny, nz] = counts;
    let at = |a: f64, bb: f64, c: f64| {
        b.plane.origin
            + b.plane.x_axis * b.x.parameter_at(a)
            + b.plane.y_axis * b.y.parameter_at(bb)
            + b.plane.z_axis * b.z.parameter_at(c)
    };
    let o = at(0.0, 0.0, 0.0);
    let x = at(1.0, 0.0, 0.0) - o;
    let y = at(0.0, 1.0, 0.0) - o;
    let z = at(0.0, 0.0, 1.0) - o;
    [
        (o, y, x, ny, nx),     // bottom, −z
        (o + z, x, y, nx, ny), // top, +z
        (o, x, z, nx, nz),     // front, −y
        (o + y, z, x, nz, nx), // back, +y
        (o, z, y, nz, ny),     // left, −x
        (o + x, y, z, ny, nz), // right, +x
    ]
}

/// Mesh Box \[MBox\]: a box as six grids of quads.
pub fn mesh_box() -> NodeType {
    mesh_node(MESH_BOX, "Mesh Box", "MBox", "Primitive")
        .description(
            "Creates a mesh box: each of the six sides a grid of quads (X × Y on the bottom \
             and top, X × Z on the front and back, Y × Z on the left and right), facing out. \
             Each side has its own vertices and normals, so the edges stay sharp, as in \
             Rhino's Mesh.CreateFromBox; Weld Mesh joins them into a closed mesh. Its \
             Grasshopper GUID is not in the project's table, so files cannot name it yet.",
        )
        .input(Port::new("Base", "B", DataType::Box).doc("The box to mesh."))
        .input(count_port(
            "X Count",
            "X",
            "The number of faces along the box's x axis; at least 1.",
        ))
        .input(count_port(
            "Y Count",
            "Y",
            "The number of faces along the box's y axis; at least 1.",
        ))
        .input(count_port(
            "Z Count",
            "Z",
            "The number of faces along the box's z axis; at least 1.",
        ))
        .output(Port::new("Mesh", "M", DataType::Mesh).doc("The box mesh."))
        .solve(|s| {
            let b = *s.item::<OrientedBox>(0)?;
            let n = counts(
                &["X", "Y", "Z"],
                &[*s.item::<i64>(1)?, *s.item::<i64>(2)?, *s.item::<i64>(3)?],
                1,
            )?;
            // The sides hold 2 (XY + XZ + YZ) faces; check that sum, not the product.
            let faces = 2 * (n[0] * n[1] + n[0] * n[2] + n[1] * n[2]);
            if faces as i64 > MAX_GRID_FACES {
                return Err(format!(
                    "the box would have {faces} faces, more than {MAX_GRID_FACES}"
                )
                .into());
            }
            s.set(0, Shared::new(box_mesh(&b, [n[0], n[1], n[2]])?));
            Ok(())
        })
}

/// The mesh of a box: six grids, facing out.
fn box_mesh(b: &OrientedBox, counts: [usize; 3]) -> Result<Mesh, NodeError> {
    if !b.plane.origin.is_finite() || [b.x, b.y, b.z].iter().any(|i| !i.is_finite()) {
        return Err("the box is not finite".into());
    }
    if [b.x, b.y, b.z].iter().any(|i| i.length() == 0.0) {
        return Err("the box is flat (an extent of zero length)".into());
    }
    // Appending keeps normals only when both meshes have them: start from the first side.
    let mut mesh: Option<Mesh> = None;
    for (corner, u, v, nu, nv) in box_sides(b, counts) {
        let side = Mesh::quad_grid(nu, nv, |i, j| {
            corner + u * (i as f64 / nu as f64) + v * (j as f64 / nv as f64)
        })?;
        let normal = u.cross(v).unitize()?;
        let count = side.vertices().len();
        let side = side.with_normals(vec![normal; count])?;
        match &mut mesh {
            None => mesh = Some(side),
            Some(m) => m.append(&side),
        }
    }
    let mesh = mesh.unwrap_or_default();
    // A box whose extents run backwards (or a left-handed frame) turns the sides inside out.
    Ok(if mesh.volume() < 0.0 {
        mesh.flipped()
    } else {
        mesh
    })
}

/// Mesh Surface \[Mesh Surface\]: a surface as a grid of quads.
pub fn mesh_surface() -> NodeType {
    mesh_node(MESH_SURFACE, "Mesh Surface", "Mesh Surface", "Util")
        .gh_guid("58cf422f-19f7-42f7-9619-fc198c51c657")
        .description(
            "Creates a mesh of U × V quads on a surface, on a grid of equal steps of its \
             parameters, with the surface's normals at the vertices. Where a side of the \
             surface is a single point (a sphere's pole, a cone's apex) the quads there are \
             triangles. The surface is untrimmed (a B-rep wired in is taken as its face's \
             surface, as Grasshopper's cast does).",
        )
        .input(Port::new("Surface", "S", DataType::Surface).doc("The surface to mesh."))
        .input(count_port(
            "U Count",
            "U",
            "The number of faces along the surface's u direction; at least 1.",
        ))
        .input(count_port(
            "V Count",
            "V",
            "The number of faces along the surface's v direction; at least 1.",
        ))
        .output(Port::new("Mesh", "M", DataType::Mesh).doc("The surface mesh."))
        .solve(|s| {
            let surface = s.item::<Shared<NurbsSurface>>(0)?;
            let n = counts(&["U", "V"], &[*s.item::<i64>(1)?, *s.item::<i64>(2)?], 1)?;
            s.set(0, Shared::new(surface_mesh(surface, n[0], n[1])?));
            Ok(())
        })
}

/// The grid mesh of a surface with its normals (the faces' average where the surface has no
/// normal, at a pole).
fn surface_mesh(surface: &NurbsSurface, nu: usize, nv: usize) -> Result<Mesh, NodeError> {
    let (du, dv) = (surface.domain_u(), surface.domain_v());
    let uv = |i: usize, j: usize| {
        (
            du.parameter_at(i as f64 / nu as f64),
            dv.parameter_at(j as f64 / nv as f64),
        )
    };
    let mesh = Mesh::quad_grid(nu, nv, |i, j| {
        let (u, v) = uv(i, j);
        surface.point_at(u, v)
    })?;
    let fallback = mesh.clone().with_computed_normals();
    let fallback = fallback.normals().unwrap_or_default();
    let normals = (0..=nv)
        .flat_map(|j| (0..=nu).map(move |i| (i, j)))
        .enumerate()
        .map(|(k, (i, j))| {
            let (u, v) = uv(i, j);
            surface.normal_at(u, v).unwrap_or(fallback[k])
        })
        .collect();
    Ok(mesh.with_normals(normals)?)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_support::{assert_clean, assert_error, only};
    use locus_kernel::{Interval, MeshFace, Plane, Polyline};
    use locus_runtime::{DataTree, NodeCall, Value};

    fn rectangle(w: f64, h: f64) -> DataTree {
        let p = |x: f64, y: f64| Point3::new(x, y, 0.0);
        let pl = Polyline::new(vec![
            p(0.0, 0.0),
            p(w, 0.0),
            p(w, h),
            p(0.0, h),
            p(0.0, 0.0),
        ])
        .unwrap();
        DataTree::from_value(Value::Curve(Shared::new(Curve::from(pl))))
    }

    fn int(n: i64) -> DataTree {
        DataTree::from_value(Value::Integer(n))
    }

    #[test]
    fn mesh_plane_gives_quads_and_the_area() {
        let r = NodeCall::new(&mesh_plane())
            .input(rectangle(4.0, 2.0))
            .input(int(2))
            .input(int(1))
            .run();
        assert_clean(&r);
        let m = only::<Shared<Mesh>>(&r, 0);
        // 3 × 2 vertices, row by row: (0,0) (2,0) (4,0) then (0,2) (2,2) (4,2).
        assert_eq!(m.vertices()[4], Point3::new(2.0, 2.0, 0.0));
        assert_eq!(
            m.faces(),
            &[MeshFace::quad(0, 1, 4, 3), MeshFace::quad(1, 2, 5, 4)]
        );
        assert_eq!(m.normals().unwrap()[0], Vector3::Z);
        assert_eq!(only::<f64>(&r, 1), 8.0);
        assert_eq!(m.area(), 8.0);
        let r = NodeCall::new(&mesh_plane())
            .input(rectangle(4.0, 2.0))
            .input(int(0))
            .run();
        assert_error(&r, "W must be at least 1");
        let r = NodeCall::new(&mesh_plane())
            .input(rectangle(4.0, 2.0))
            .input(int(100_000))
            .input(int(100_000))
            .run();
        assert_error(&r, "more than 10000000 faces");
        let line = Curve::from(locus_kernel::Line::new(
            Point3::ORIGIN,
            Point3::new(1.0, 0.0, 0.0),
        ));
        let r = NodeCall::new(&mesh_plane())
            .input(DataTree::from_value(Value::Curve(Shared::new(line))))
            .run();
        assert_error(&r, "not a rectangle");
    }

    fn unit_box() -> OrientedBox {
        OrientedBox::new(
            Plane::WORLD_XY,
            Interval::new(0.0, 1.0),
            Interval::new(0.0, 2.0),
            Interval::new(0.0, 3.0),
        )
    }

    #[test]
    fn mesh_box_has_six_outward_grids() {
        let r = NodeCall::new(&mesh_box())
            .input(DataTree::from_value(Value::Box(unit_box())))
            .input(int(1))
            .input(int(2))
            .input(int(3))
            .run();
        assert_clean(&r);
        let m = only::<Shared<Mesh>>(&r, 0);
        // Faces: 2 (1·2 + 1·3 + 2·3) = 22; vertices 2 (2·3 + 2·4 + 3·4) = 52.
        assert_eq!(m.faces().len(), 22);
        assert_eq!(m.vertices().len(), 52);
        assert!(m.faces().iter().all(|f| !f.is_triangle()));
        // 1 × 2 × 3: area 2 (2 + 3 + 6) = 22, volume 6.
        assert!((m.area() - 22.0).abs() < 1e-12);
        assert!((m.volume() - 6.0).abs() < 1e-12);
        // Welded, it is closed.
        assert!(m.welded(std::f64::consts::PI).is_closed_and_oriented());
        // The bottom side's normal points down.
        assert_eq!(m.normals().unwrap()[0], -Vector3::Z);
        // A box with its extents backwards still faces out.
        let mut b = unit_box();
        b.x = Interval::new(1.0, 0.0);
        assert!((box_mesh(&b, [1, 1, 1]).unwrap().volume() - 6.0).abs() < 1e-12);
        b.z = Interval::new(1.0, 1.0);
        assert!(box_mesh(&b, [1, 1, 1]).is_err());
    }

    #[test]
    fn mesh_surface_follows_the_parameters() {
        // A bilinear patch over the square (0,0)–(2,2) at z = 0: the grid is the square's.
        let plane = NurbsSurface::from_plane(
            &Plane::WORLD_XY,
            Interval::new(0.0, 2.0),
            Interval::new(0.0, 2.0),
        )
        .unwrap();
        let r = NodeCall::new(&mesh_surface())
            .input(DataTree::from_value(Value::Surface(Shared::new(plane))))
            .input(int(2))
            .input(int(2))
            .run();
        assert_clean(&r);
        let m = only::<Shared<Mesh>>(&r, 0);
        assert_eq!(m.vertices().len(), 9);
        assert_eq!(m.vertices()[4], Point3::new(1.0, 1.0, 0.0));
        assert_eq!(m.faces().len(), 4);
        assert!((m.area() - 4.0).abs() < 1e-12);
        assert!(
            m.normals()
                .unwrap()
                .iter()
                .all(|n| (*n - Vector3::Z).length() < 1e-12)
        );
    }

    #[test]
    fn mesh_surface_makes_triangles_at_a_spheres_poles() {
        let sphere = locus_kernel::Sphere::new(Point3::ORIGIN, 1.0)
            .unwrap()
            .to_nurbs()
            .unwrap();
        let m = surface_mesh(&sphere, 4, 4).unwrap();
        // 16 faces; the 4 around each pole are triangles, the 8 between quads.
        assert_eq!(m.faces().len(), 16);
        assert_eq!(m.faces().iter().filter(|f| f.is_triangle()).count(), 8);
        // Every vertex is on the sphere, with the outward normal (exactly away from the poles;
        // at a pole, where the surface has no normal, the faces' average, 4 faces being coarse).
        for (p, n) in m.vertices().iter().zip(m.normals().unwrap()) {
            assert!((p.to_vector().length() - 1.0).abs() < 1e-12);
            if p.z.abs() < 0.99 {
                assert!((*n - p.to_vector()).length() < 1e-9, "{p:?} {n:?}");
            } else {
                assert!(n.dot(p.to_vector()) > 0.9, "{p:?} {n:?}");
            }
        }
        // Welded, the mesh is closed, with positive volume under the sphere's.
        let closed = m.welded(std::f64::consts::PI);
        assert!(closed.is_closed_and_oriented());
        let v = closed.volume();
        assert!(v > 0.0 && v < 4.0 / 3.0 * std::f64::consts::PI, "{v}");
    }
}

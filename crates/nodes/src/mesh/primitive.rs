//! Mesh › Primitive and Mesh › Util: Mesh Brep (a B-rep tessellated by the kernel) and Mesh
//! Sphere (a UV sphere of quads with triangle fans at the poles).

use locus_kernel::{Mesh, MeshFace, MeshingParameters, Plane, Point3};
use locus_runtime::{DataType, NodeError, NodeRegistry, NodeType, Port, Shared};

use super::mesh_node;
use super::settings::parse_settings;
use crate::surface::brep::brep_item;

/// Id of [`mesh_brep`].
pub const MESH_BREP: &str = "mesh.mesh_brep";
/// Id of [`mesh_sphere`].
pub const MESH_SPHERE: &str = "mesh.mesh_sphere";
/// Id of [`mesh_sphere_ex`].
pub const MESH_SPHERE_EX: &str = "mesh.mesh_sphere_ex";

/// The most faces Mesh Sphere makes (U × V): 10,000,000.
pub const MAX_SPHERE_FACES: i64 = 10_000_000;

/// Registers Mesh Brep and Mesh Sphere.
pub fn register(registry: &mut NodeRegistry) {
    registry.register(mesh_brep());
    registry.register(mesh_sphere());
    registry.register(mesh_sphere_ex());
}

/// Mesh Brep \[Mesh\]: a mesh approximating a B-rep.
pub fn mesh_brep() -> NodeType {
    mesh_node(MESH_BREP, "Mesh Brep", "Mesh", "Util")
        .gh_guid("60e7defa-8b21-4ee1-99aa-a9223d6134ff")
        .description(
            "Creates a mesh that approximates a B-rep, with the Settings of a settings node \
             (Settings (Custom), Settings (Speed), Settings (Quality)) or by default the \
             kernel's default meshing parameters (maximum angle between neighbouring normals \
             3.5°, no chord or edge-length limit, minimum edge length 1e-4): one mesh for all \
             faces, with vertices shared along the edges so that a closed B-rep gives a \
             closed, consistently oriented mesh with normals pointing out. Poles and apexes \
             become fans of triangles.",
        )
        .input(Port::new("Brep", "B", DataType::Brep).doc(
            "The B-rep to mesh. Boxes and surfaces are taken as B-reps (six faces, one face).",
        ))
        .input(Port::new("Settings", "S", DataType::Text).optional().doc(
            "The meshing settings (the text a settings node makes); the defaults when absent.",
        ))
        .output(Port::new("Mesh", "M", DataType::Mesh).doc("The mesh of the B-rep."))
        .solve(|s| {
            let brep = brep_item(s, 0)?;
            let parameters = match s.item_opt::<String>(1) {
                Some(text) => parse_settings(text).map_err(|e| format!("settings: {e}"))?,
                None => MeshingParameters::default(),
            };
            let mesh = Mesh::from_brep(&brep, &parameters)?;
            s.set(0, Shared::new(mesh));
            Ok(())
        })
}

/// Mesh Sphere \[MSphere\]: a UV sphere mesh.
pub fn mesh_sphere() -> NodeType {
    mesh_node(MESH_SPHERE, "Mesh Sphere", "MSphere", "Primitive")
        .gh_guid("0a391eac-5048-443c-9c1b-f592299b6dd6")
        .description(
            "Creates a mesh sphere: U faces around the base plane's Z axis and V faces from \
             the south pole to the north pole, quads between the rings of parallels and \
             triangle fans at the poles. The mesh is closed, with outward faces and normals.",
        )
        .input(
            Port::new("Base", "B", DataType::Plane)
                .default_value(Plane::WORLD_XY)
                .doc("The base plane: the sphere's centre is its origin, its poles on its Z axis."),
        )
        .input(
            Port::new("Radius", "R", DataType::Number)
                .default_value(1.0)
                .doc("The radius of the sphere; must be positive."),
        )
        .input(
            Port::new("U Count", "U", DataType::Integer)
                .default_value(10i64)
                .doc("The number of faces around the sphere; at least 3."),
        )
        .input(
            Port::new("V Count", "V", DataType::Integer)
                .default_value(10i64)
                .doc("The number of faces from pole to pole; at least 2."),
        )
        .output(Port::new("Mesh", "M", DataType::Mesh).doc("The sphere mesh."))
        .solve(|s| {
            let plane = *s.item::<Plane>(0)?;
            let radius = *s.item::<f64>(1)?;
            let u = *s.item::<i64>(2)?;
            let v = *s.item::<i64>(3)?;
            s.set(0, Shared::new(uv_sphere(&plane, radius, u, v)?));
            Ok(())
        })
}

/// A UV sphere on `plane` with `u` faces around and `v` from pole to pole.
fn uv_sphere(plane: &Plane, radius: f64, u: i64, v: i64) -> Result<Mesh, NodeError> {
    if !(radius.is_finite() && radius > 0.0) {
        return Err(format!("the radius must be positive, got {radius}").into());
    }
    if u < 3 || v < 2 {
        return Err(
            format!("U count must be at least 3 and V count at least 2, got {u} and {v}").into(),
        );
    }
    if u.saturating_mul(v) > MAX_SPHERE_FACES {
        return Err(format!("U × V must be at most {MAX_SPHERE_FACES}, got {u} × {v}").into());
    }
    if !plane.origin.is_finite() {
        return Err("the base plane is not finite".into());
    }
    let (u, v) = (u as u32, v as u32);
    let at = |theta: f64, phi: f64| -> Point3 {
        let (x, y, z) = (phi.cos() * theta.cos(), phi.cos() * theta.sin(), phi.sin());
        plane.origin + (plane.x_axis * x + plane.y_axis * y + plane.z_axis * z) * radius
    };
    let mut vertices = vec![at(0.0, -std::f64::consts::FRAC_PI_2)];
    for j in 1..v {
        let phi = -std::f64::consts::FRAC_PI_2 + std::f64::consts::PI * f64::from(j) / f64::from(v);
        for i in 0..u {
            vertices.push(at(std::f64::consts::TAU * f64::from(i) / f64::from(u), phi));
        }
    }
    vertices.push(at(0.0, std::f64::consts::FRAC_PI_2));
    let north = vertices.len() as u32 - 1;
    let ring = |j: u32, i: u32| 1 + (j - 1) * u + i % u;
    let mut faces = Vec::new();
    for i in 0..u {
        faces.push(MeshFace::triangle(0, ring(1, i + 1), ring(1, i)));
        for j in 1..v - 1 {
            faces.push(MeshFace::quad(
                ring(j, i),
                ring(j, i + 1),
                ring(j + 1, i + 1),
                ring(j + 1, i),
            ));
        }
        faces.push(MeshFace::triangle(
            north,
            ring(v - 1, i),
            ring(v - 1, i + 1),
        ));
    }
    let normals = vertices
        .iter()
        .map(|&p| (p - plane.origin).normalize_or_zero())
        .collect();
    Ok(Mesh::new(vertices, faces)?.with_normals(normals)?)
}

/// Mesh Sphere Ex \[MSphereEx\]: a quad ball, a cube's six faces divided into C × C quads and
/// pushed out onto the sphere.
pub fn mesh_sphere_ex() -> NodeType {
    mesh_node(MESH_SPHERE_EX, "Mesh Sphere Ex", "MSphereEx", "Primitive")
        .gh_guid("76f85ee4-5a88-4511-8ba7-30df07e50533")
        .description(
            "Creates a quad ball: a mesh sphere made of six square patches, topologically a \
             cube. Each face of the cube around the sphere (aligned with the base plane's axes) \
             is divided into C × C squares, and every vertex is moved along its ray from the \
             centre onto the sphere. The mesh is closed and welded (6·C² + 2 vertices), with \
             outward quads and normals.",
        )
        .input(
            Port::new("Base", "B", DataType::Plane)
                .default_value(Plane::WORLD_XY)
                .doc(
                    "The base plane: the sphere's centre is its origin, the cube's axes its axes.",
                ),
        )
        .input(
            Port::new("Radius", "R", DataType::Number)
                .default_value(1.0)
                .doc("The radius of the sphere; must be positive."),
        )
        .input(
            Port::new("Count", "C", DataType::Integer)
                .default_value(10i64)
                .doc("The number of quads along each edge of each of the six patches; at least 1."),
        )
        .output(Port::new("Mesh", "M", DataType::Mesh).doc("The quad ball."))
        .solve(|s| {
            let plane = *s.item::<Plane>(0)?;
            let radius = *s.item::<f64>(1)?;
            let count = *s.item::<i64>(2)?;
            s.set(0, Shared::new(quad_ball(&plane, radius, count)?));
            Ok(())
        })
}

/// A quad ball on `plane`: the cube `[−1, 1]³` with `count` squares along each edge of each
/// face, its vertices (welded along the cube's edges) projected onto the sphere of `radius`.
fn quad_ball(plane: &Plane, radius: f64, count: i64) -> Result<Mesh, NodeError> {
    if !(radius.is_finite() && radius > 0.0) {
        return Err(format!("the radius must be positive, got {radius}").into());
    }
    if count < 1 {
        return Err(format!("the count must be at least 1, got {count}").into());
    }
    if count.saturating_mul(count).saturating_mul(6) > MAX_SPHERE_FACES {
        return Err(format!("6 × C² must be at most {MAX_SPHERE_FACES}, got C = {count}").into());
    }
    if !plane.origin.is_finite() {
        return Err("the base plane is not finite".into());
    }
    let n = count as u32;
    // Lattice points (i, j, k) of the cube's surface, 0..=n on each axis, numbered once.
    let mut index: std::collections::HashMap<[u32; 3], u32> = std::collections::HashMap::new();
    let mut vertices = Vec::new();
    let mut normals = Vec::new();
    let mut vertex = |l: [u32; 3]| -> u32 {
        *index.entry(l).or_insert_with(|| {
            let c = |t: u32| 2.0 * f64::from(t) / f64::from(n) - 1.0;
            let d = (plane.x_axis * c(l[0]) + plane.y_axis * c(l[1]) + plane.z_axis * c(l[2]))
                .normalize_or_zero();
            vertices.push(plane.origin + d * radius);
            normals.push(d);
            (vertices.len() - 1) as u32
        })
    };
    let mut faces = Vec::with_capacity(6 * (n as usize).pow(2));
    // Face of the cube where axis `a` is at `side` (0 or n); (b, c) follow a cyclically, so that
    // b × c points along +a: the quads turn counter-clockwise seen from outside on the + side,
    // and are reversed on the − side.
    for a in 0..3 {
        let (b, c) = ((a + 1) % 3, (a + 2) % 3);
        for side in [0, n] {
            for u in 0..n {
                for v in 0..n {
                    let at = |du: u32, dv: u32| {
                        let mut l = [0; 3];
                        l[a] = side;
                        l[b] = u + du;
                        l[c] = v + dv;
                        l
                    };
                    let q = [
                        vertex(at(0, 0)),
                        vertex(at(1, 0)),
                        vertex(at(1, 1)),
                        vertex(at(0, 1)),
                    ];
                    faces.push(if side == n {
                        MeshFace::quad(q[0], q[1], q[2], q[3])
                    } else {
                        MeshFace::quad(q[0], q[3], q[2], q[1])
                    });
                }
            }
        }
    }
    Ok(Mesh::new(vertices, faces)?.with_normals(normals)?)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_support::{assert_clean, assert_error, only};
    use locus_kernel::{Brep, Interval, OrientedBox};
    use locus_runtime::{DataTree, NodeCall, Value};

    #[test]
    fn mesh_brep_meshes_a_box_closed() {
        let b = OrientedBox::new(
            Plane::WORLD_XY,
            Interval::new(0.0, 2.0),
            Interval::new(0.0, 3.0),
            Interval::new(0.0, 4.0),
        );
        let brep = Value::Brep(Shared::new(Brep::from_box(&b).unwrap()));
        let r = NodeCall::new(&mesh_brep())
            .input(DataTree::from_value(brep))
            .run();
        assert_clean(&r);
        let m = only::<Shared<Mesh>>(&r, 0);
        assert!(m.is_closed_and_oriented());
        assert!((m.volume() - 24.0).abs() < 1e-12);
        // A box wired in is meshed as its B-rep.
        let r = NodeCall::new(&mesh_brep())
            .input(DataTree::from_value(Value::Box(b)))
            .run();
        assert!((only::<Shared<Mesh>>(&r, 0).area() - 52.0).abs() < 1e-12);
        // Coarser settings give fewer faces on a sphere; bad settings are an error.
        let sphere = locus_kernel::Sphere::new(Point3::ORIGIN, 1.0).unwrap();
        let sphere = Value::Brep(Shared::new(
            Brep::from_surface(sphere.to_nurbs().unwrap()).unwrap(),
        ));
        let with = |settings: &str| {
            NodeCall::new(&mesh_brep())
                .input(DataTree::from_value(sphere.clone()))
                .input(DataTree::from_value(Value::Text(settings.into())))
                .run()
        };
        let coarse = only::<Shared<Mesh>>(&with("max_angle=0.35"), 0)
            .faces()
            .len();
        let fine = only::<Shared<Mesh>>(&with("max_angle=0.1"), 0)
            .faces()
            .len();
        assert!(coarse < fine, "{coarse} {fine}");
        assert_error(&with("max_angle=-1"), "settings: meshing maximum angle");
        // Not geometry: a cast error on the input.
        let r = NodeCall::new(&mesh_brep())
            .input(DataTree::from_value(Value::Number(1.0)))
            .run();
        assert!(!r.messages.is_empty());
    }

    #[test]
    fn mesh_sphere_is_closed_with_fans_at_the_poles() {
        let r = NodeCall::new(&mesh_sphere())
            .input(DataTree::from_value(Value::Plane(Plane::WORLD_XY)))
            .input(DataTree::from_value(Value::Number(2.0)))
            .run();
        assert_clean(&r);
        let m = only::<Shared<Mesh>>(&r, 0);
        assert!(m.is_closed_and_oriented());
        assert_eq!(m.vertices().len(), 2 + 9 * 10);
        assert_eq!(m.faces().len(), 100);
        assert!(m.volume() > 0.0 && m.volume() < 4.0 / 3.0 * std::f64::consts::PI * 8.0);
        let bad = |radius: f64, u: i64, v: i64| {
            NodeCall::new(&mesh_sphere())
                .input(DataTree::from_value(Value::Plane(Plane::WORLD_XY)))
                .input(DataTree::from_value(Value::Number(radius)))
                .input(DataTree::from_value(Value::Integer(u)))
                .input(DataTree::from_value(Value::Integer(v)))
                .run()
        };
        assert_error(&bad(0.0, 10, 10), "radius must be positive");
        assert_error(&bad(f64::NAN, 10, 10), "radius must be positive");
        assert_error(&bad(1.0, 2, 10), "at least 3");
        assert_error(&bad(1.0, i64::MAX, i64::MAX), "at most");
    }

    #[test]
    fn mesh_sphere_ex_is_a_closed_quad_ball() {
        let run = |r: f64, c: i64| {
            NodeCall::new(&mesh_sphere_ex())
                .input(DataTree::from_value(Value::Plane(Plane::WORLD_XY)))
                .input(DataTree::from_value(Value::Number(r)))
                .input(DataTree::from_value(Value::Integer(c)))
                .run()
        };
        // C = 1 is the cube inscribed in the sphere: radius √3 gives the cube [−1, 1]³.
        let r = run(3f64.sqrt(), 1);
        assert_clean(&r);
        let m = only::<Shared<Mesh>>(&r, 0);
        assert_eq!((m.vertices().len(), m.faces().len()), (8, 6));
        assert!(m.is_closed_and_oriented());
        assert!((m.volume() - 8.0).abs() < 1e-12, "{}", m.volume());
        for c in [2, 5, 12] {
            let r = run(2.0, c);
            let m = only::<Shared<Mesh>>(&r, 0);
            let c = c as usize;
            // Welded: Euler's V − E + F = 2 with F = 6c², E = 12c².
            assert_eq!(m.vertices().len(), 6 * c * c + 2);
            assert_eq!(m.faces().len(), 6 * c * c);
            assert!(m.is_closed_and_oriented());
            for p in m.vertices() {
                assert!((p.distance(Point3::ORIGIN) - 2.0).abs() < 1e-12);
            }
            // Inside the sphere, closer to it as C grows.
            let sphere = 4.0 / 3.0 * std::f64::consts::PI * 8.0;
            let low = if c >= 5 { 0.9 } else { 0.7 };
            assert!(
                m.volume() < sphere && m.volume() > low * sphere,
                "{}",
                m.volume()
            );
        }
        assert!(
            only::<Shared<Mesh>>(&run(1.0, 12), 0).volume()
                > only::<Shared<Mesh>>(&run(1.0, 4), 0).volume()
        );
        assert_error(&run(0.0, 4), "the radius must be positive");
        assert_error(&run(1.0, 0), "the count must be at least 1");
        assert_error(&run(1.0, 100_000), "6 × C² must be at most");
    }
}

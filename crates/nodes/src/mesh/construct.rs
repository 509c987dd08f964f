//! Mesh › Primitive and Mesh › Analysis: Construct Mesh and Deconstruct Mesh, a mesh from and
//! to its vertices, faces, colours and normals.
//!
//! locus has no Mesh Face value yet, so faces travel as the text Grasshopper shows for them:
//! `T{a;b;c}` for a triangle and `Q{a;b;c;d}` for a quad, zero-based vertex indices. Construct
//! Mesh also reads `{a;b;c}` and commas for semicolons.

use locus_kernel::{Color, Mesh, MeshFace, Point3};
use locus_runtime::{DataType, NodeError, NodeRegistry, NodeType, Port, Shared, Value};

use super::{mesh_item, mesh_node};

/// Id of [`construct_mesh`].
pub const CONSTRUCT_MESH: &str = "mesh.construct_mesh";
/// Id of [`deconstruct_mesh`].
pub const DECONSTRUCT_MESH: &str = "mesh.deconstruct_mesh";

/// Registers Construct Mesh and Deconstruct Mesh.
pub fn register(registry: &mut NodeRegistry) {
    registry.register(construct_mesh());
    registry.register(deconstruct_mesh());
}

/// The text of a face, as Grasshopper writes a Mesh Face: `T{0;1;2}` or `Q{0;1;2;3}`.
pub fn face_text(face: &MeshFace) -> String {
    let [a, b, c, d] = face.vertices;
    if face.is_triangle() {
        format!("T{{{a};{b};{c}}}")
    } else {
        format!("Q{{{a};{b};{c};{d}}}")
    }
}

/// The face a text names: `T{a;b;c}`, `Q{a;b;c;d}` or `{…}` with three or four indices.
///
/// # Errors
/// A message saying what is wrong with the text.
pub fn parse_face(text: &str) -> Result<MeshFace, String> {
    let t = text.trim();
    let (kind, rest) = match t.chars().next() {
        Some(k @ ('T' | 't' | 'Q' | 'q')) => (Some(k.to_ascii_uppercase()), &t[1..]),
        _ => (None, t),
    };
    let inner = rest
        .trim()
        .strip_prefix('{')
        .and_then(|r| r.strip_suffix('}'))
        .ok_or_else(|| format!("{text:?} is not a mesh face: write T{{a;b;c}} or Q{{a;b;c;d}}"))?;
    let indices = inner
        .split([';', ','])
        .map(|s| s.trim().parse::<u32>())
        .collect::<Result<Vec<u32>, _>>()
        .map_err(|_| {
            format!("{text:?} is not a mesh face: its indices must be whole numbers ≥ 0")
        })?;
    match (kind, indices.as_slice()) {
        (Some('T') | None, &[a, b, c]) => Ok(MeshFace::triangle(a, b, c)),
        (Some('Q') | None, &[a, b, c, d]) => Ok(MeshFace::quad(a, b, c, d)),
        _ => Err(format!(
            "{text:?} is not a mesh face: a triangle T has three indices, a quad Q four"
        )),
    }
}

/// Construct Mesh \[ConMesh\]: a mesh of vertices, faces and optional colours.
pub fn construct_mesh() -> NodeType {
    mesh_node(CONSTRUCT_MESH, "Construct Mesh", "ConMesh", "Primitive")
        .gh_guid("e2c0f9db-a862-4bd9-810c-ef2610e7a56f")
        .description(
            "Constructs a mesh from vertices and faces, with optional vertex colours. Faces \
             are texts in Grasshopper's Mesh Face notation, T{a;b;c} for a triangle and \
             Q{a;b;c;d} for a quad, counter-clockwise seen from the front, with zero-based \
             vertex indices (locus has no Mesh Face value yet). Vertex normals are computed \
             from the faces. A face naming a missing vertex or repeating one is an error.",
        )
        .input(
            Port::new("Vertices", "V", DataType::Point)
                .list()
                .doc("The mesh vertices."),
        )
        .input(
            Port::new("Faces", "F", DataType::Text)
                .list()
                .default_value("Q{0;1;2;3}".to_owned())
                .doc("The faces: T{a;b;c} or Q{a;b;c;d}; by default one quad of the first four vertices."),
        )
        .input(
            Port::new("Colours", "C", DataType::Colour)
                .list()
                .optional()
                .doc("The vertex colours: one per vertex, or one for every vertex."),
        )
        .output(Port::new("Mesh", "M", DataType::Mesh).doc("The mesh."))
        .solve(|s| {
            let vertices = s.list::<Point3>(0)?;
            let faces = s.list::<String>(1)?;
            let colours = s.list::<Color>(2)?;
            let mesh = construct(
                &vertices.iter().collect::<Vec<_>>(),
                &faces.iter().collect::<Vec<_>>(),
                &colours.iter().collect::<Vec<_>>(),
            )?;
            s.set(0, Shared::new(mesh));
            Ok(())
        })
}

/// The mesh of Construct Mesh's lists (`None` items are nulls).
fn construct(
    vertices: &[Option<&Point3>],
    faces: &[Option<&String>],
    colours: &[Option<&Color>],
) -> Result<Mesh, NodeError> {
    let vertices = vertices
        .iter()
        .enumerate()
        .map(|(i, p)| p.copied().ok_or_else(|| format!("vertex {i} is null")))
        .collect::<Result<Vec<_>, _>>()?;
    let faces = faces
        .iter()
        .enumerate()
        .map(|(i, f)| match f {
            Some(text) => parse_face(text).map_err(|e| format!("face {i}: {e}")),
            None => Err(format!("face {i} is null")),
        })
        .collect::<Result<Vec<_>, _>>()?;
    let n = vertices.len();
    let mut mesh = Mesh::new(vertices, faces)?.with_computed_normals();
    if !colours.is_empty() {
        let colours = colours
            .iter()
            .enumerate()
            .map(|(i, c)| c.copied().ok_or_else(|| format!("colour {i} is null")))
            .collect::<Result<Vec<_>, _>>()?;
        let per_vertex = match colours[..] {
            [one] => vec![one; n],
            _ if colours.len() == n => colours,
            _ => {
                return Err(format!(
                    "there are {} colours for {n} vertices: give one per vertex or one for all",
                    colours.len()
                )
                .into());
            }
        };
        mesh = mesh.with_colors(per_vertex)?;
    }
    Ok(mesh)
}

/// Deconstruct Mesh \[DeMesh\]: the vertices, faces, colours and normals of a mesh.
pub fn deconstruct_mesh() -> NodeType {
    mesh_node(DECONSTRUCT_MESH, "Deconstruct Mesh", "DeMesh", "Analysis")
        .gh_guid("ba2d8f57-0738-42b4-b5a5-fe4d853517eb")
        .description(
            "Deconstructs a mesh into its vertices, faces (texts T{a;b;c} and Q{a;b;c;d}, as \
             Construct Mesh reads them), vertex colours (empty when the mesh has none) and \
             vertex normals (computed from the faces when the mesh has none, as Rhino always \
             has them).",
        )
        .input(Port::new("Mesh", "M", DataType::Mesh).doc("The mesh to deconstruct."))
        .output(
            Port::new("Vertices", "V", DataType::Point)
                .list()
                .doc("The vertices."),
        )
        .output(
            Port::new("Faces", "F", DataType::Text)
                .list()
                .doc("The faces, T{a;b;c} or Q{a;b;c;d}."),
        )
        .output(
            Port::new("Colours", "C", DataType::Colour)
                .list()
                .doc("The vertex colours."),
        )
        .output(
            Port::new("Normals", "N", DataType::Vector)
                .list()
                .doc("The vertex normals."),
        )
        .solve(|s| {
            let m = mesh_item(s, 0)?;
            s.set_list(0, m.vertices().to_vec());
            s.set_list(1, m.faces().iter().map(face_text).collect::<Vec<_>>());
            s.set_list(2, m.colors().map(<[Color]>::to_vec).unwrap_or_default());
            let normals = match m.normals() {
                Some(n) => n.to_vec(),
                None => (*m)
                    .clone()
                    .with_computed_normals()
                    .normals()
                    .map(<[_]>::to_vec)
                    .unwrap_or_default(),
            };
            s.set_list_values(
                3,
                normals
                    .into_iter()
                    .map(|n| Some(Value::Vector(n)))
                    .collect(),
            );
            Ok(())
        })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_support::{all, assert_clean, assert_error, only, points, vectors};
    use locus_kernel::Vector3;
    use locus_runtime::{DataTree, NodeCall};

    fn list<T: locus_runtime::Item>(items: Vec<T>) -> DataTree {
        DataTree::from_list(items)
    }

    fn square() -> Vec<Point3> {
        let p = |x: f64, y: f64| Point3::new(x, y, 0.0);
        vec![p(0.0, 0.0), p(2.0, 0.0), p(2.0, 2.0), p(0.0, 2.0)]
    }

    #[test]
    fn faces_read_and_write_grasshoppers_notation() {
        assert_eq!(parse_face("T{0;1;2}"), Ok(MeshFace::triangle(0, 1, 2)));
        assert_eq!(parse_face(" q{3, 2 ,1;0} "), Ok(MeshFace::quad(3, 2, 1, 0)));
        assert_eq!(parse_face("{4;5;6}"), Ok(MeshFace::triangle(4, 5, 6)));
        assert!(
            parse_face("T{0;1;2;3}")
                .unwrap_err()
                .contains("three indices")
        );
        assert!(
            parse_face("Q{0;-1;2;3}")
                .unwrap_err()
                .contains("whole numbers")
        );
        assert!(parse_face("0 1 2").unwrap_err().contains("not a mesh face"));
        assert!(parse_face("").is_err());
        assert_eq!(face_text(&MeshFace::quad(0, 1, 2, 3)), "Q{0;1;2;3}");
        assert_eq!(face_text(&MeshFace::triangle(7, 8, 9)), "T{7;8;9}");
    }

    #[test]
    fn construct_mesh_makes_a_square_of_one_quad() {
        // Faces default to Q{0;1;2;3}.
        let r = NodeCall::new(&construct_mesh()).input(list(square())).run();
        assert_clean(&r);
        let m = only::<Shared<Mesh>>(&r, 0);
        assert_eq!(m.faces(), &[MeshFace::quad(0, 1, 2, 3)]);
        assert_eq!(m.area(), 4.0);
        assert_eq!(m.normals().unwrap(), &[Vector3::Z; 4]);
        // One colour colours every vertex; four colour each.
        let red = Color::rgb(255, 0, 0);
        let r = NodeCall::new(&construct_mesh())
            .input(list(square()))
            .input(list(vec!["T{0;1;2}".to_owned(), "T{0;2;3}".to_owned()]))
            .input(list(vec![red]))
            .run();
        assert_clean(&r);
        let m = only::<Shared<Mesh>>(&r, 0);
        assert_eq!(m.triangle_count(), 2);
        assert_eq!(m.colors().unwrap(), &[red; 4]);
    }

    #[test]
    fn construct_mesh_reports_bad_faces_and_colours() {
        let run = |faces: Vec<&str>, colours: Vec<Color>| {
            NodeCall::new(&construct_mesh())
                .input(list(square()))
                .input(list(faces.into_iter().map(str::to_owned).collect()))
                .input(list(colours))
                .run()
        };
        assert_error(&run(vec!["Q{0;1;2;4}"], vec![]), "names vertex 4");
        assert_error(&run(vec!["Q{0;1;1;2}"], vec![]), "repeats a vertex");
        assert_error(&run(vec!["T{0;1;2}", "pentagon"], vec![]), "face 1");
        assert_error(
            &run(vec!["T{0;1;2}"], vec![Color::WHITE; 2]),
            "2 colours for 4 vertices",
        );
    }

    #[test]
    fn deconstruct_mesh_gives_the_lists_back() {
        let m = Mesh::new(
            square(),
            vec![MeshFace::triangle(0, 1, 2), MeshFace::quad(0, 1, 2, 3)],
        )
        .unwrap();
        let r = NodeCall::new(&deconstruct_mesh())
            .input(DataTree::from_value(Value::Mesh(Shared::new(m))))
            .run();
        assert_clean(&r);
        assert_eq!(points(&r.outputs[0]), square());
        let faces: Vec<String> = all(&r.outputs[1]);
        assert_eq!(faces, ["T{0;1;2}", "Q{0;1;2;3}"]);
        assert_eq!(r.outputs[2].item_count(), 0);
        // The square is flat in XY: every computed normal is Z.
        assert_eq!(vectors(&r.outputs[3]), vec![Vector3::Z; 4]);
    }
}

//! Literal forms of meshes and colours (see `docs/graph-format.md`, "Literal values"):
//!
//! | type | literal |
//! | --- | --- |
//! | Mesh | `(vertices: [(x, y, z), …], faces: [(a, b, c), (a, b, c, d), …])`, optionally with `normals: [(x, y, z), …]` and `colours: [(r: …, g: …, b: …), …]` (one per vertex) |
//! | Colour | `(r: 255, g: 128, b: 0)` with an optional `a: 255`, `(255, 128, 0)` / `(255, 128, 0, 64)` (red, green, blue, alpha), or `"#FF8000"` / `"#40FF8000"` (`#RRGGBB`, `#AARRGGBB`) |
//!
//! Meshes are read through [`Mesh::new`], so a face naming a missing vertex or repeating a
//! vertex is reported with the kernel's reason at the field at fault.

use locus_kernel::{Color, Mesh, MeshFace, Point3, Vector3};

use crate::file::literal::{error, mismatch, number, number_node, numbers_node};
use crate::file::syntax::{Field, Kind, Node};
use crate::{DataType, LiteralError, Shared, Value};

fn fields(node: &Node, data_type: DataType) -> Result<&[Field], LiteralError> {
    match &node.kind {
        Kind::Struct(None, fields) => Ok(fields),
        _ => mismatch(node, data_type),
    }
}

fn check_fields(
    node: &Node,
    fields: &[Field],
    what: &str,
    allowed: &[&str],
) -> Result<(), LiteralError> {
    for (i, f) in fields.iter().enumerate() {
        if !allowed.contains(&f.name.as_str()) {
            return Err(LiteralError {
                message: format!(
                    "unknown field `{}` of {what} (its fields are: {})",
                    f.name,
                    allowed.join(", ")
                ),
                span: f.name_span.clone(),
            });
        }
        if fields[..i].iter().any(|g| g.name == f.name) {
            return Err(LiteralError {
                message: format!("field `{}` of {what} is given twice", f.name),
                span: f.name_span.clone(),
            });
        }
    }
    let _ = node;
    Ok(())
}

fn get<'a>(fields: &'a [Field], name: &str) -> Option<&'a Node> {
    fields.iter().find(|f| f.name == name).map(|f| &f.value)
}

fn list<'a>(node: &'a Node, what: &str) -> Result<&'a [Node], LiteralError> {
    match &node.kind {
        Kind::List(items) => Ok(items),
        _ => error(
            node,
            format!("expected a list of {what}, found {}", node.describe()),
        ),
    }
}

fn triple(node: &Node, what: &str) -> Result<[f64; 3], LiteralError> {
    match &node.kind {
        Kind::Tuple(None, v) if v.len() == 3 => Ok([
            number(&v[0], DataType::Mesh)?,
            number(&v[1], DataType::Mesh)?,
            number(&v[2], DataType::Mesh)?,
        ]),
        _ => error(
            node,
            format!("expected {what} (x, y, z), found {}", node.describe()),
        ),
    }
}

fn index(node: &Node) -> Result<u32, LiteralError> {
    match &node.kind {
        Kind::Number(n) => n.replace('_', "").parse::<u32>().or_else(|_| {
            error(
                node,
                format!("expected a vertex index (a whole number from 0), found {n}"),
            )
        }),
        _ => error(
            node,
            format!("expected a vertex index, found {}", node.describe()),
        ),
    }
}

fn face(node: &Node) -> Result<MeshFace, LiteralError> {
    match &node.kind {
        Kind::Tuple(None, v) if v.len() == 3 => Ok(MeshFace::triangle(
            index(&v[0])?,
            index(&v[1])?,
            index(&v[2])?,
        )),
        Kind::Tuple(None, v) if v.len() == 4 => Ok(MeshFace::quad(
            index(&v[0])?,
            index(&v[1])?,
            index(&v[2])?,
            index(&v[3])?,
        )),
        _ => error(
            node,
            format!(
                "expected a face of three or four vertex indices (a, b, c) or (a, b, c, d), \
                 found {}",
                node.describe()
            ),
        ),
    }
}

/// Reads a mesh literal.
pub(crate) fn mesh(node: &Node) -> Result<Mesh, LiteralError> {
    let f = fields(node, DataType::Mesh)?;
    check_fields(
        node,
        f,
        "a mesh",
        &["vertices", "faces", "normals", "colours"],
    )?;
    let need = |name: &str| {
        get(f, name).map_or_else(
            || error(node, format!("a mesh needs the field `{name}`")),
            Ok,
        )
    };
    let vertices_at = need("vertices")?;
    let vertices = list(vertices_at, "vertices (x, y, z)")?
        .iter()
        .map(|p| triple(p, "a vertex").map(|[x, y, z]| Point3::new(x, y, z)))
        .collect::<Result<Vec<_>, _>>()?;
    let faces_at = need("faces")?;
    let faces = list(faces_at, "faces")?
        .iter()
        .map(face)
        .collect::<Result<Vec<_>, _>>()?;
    let mut mesh = Mesh::new(vertices, faces).or_else(|e| {
        let at = if e.to_string().contains("vertex") && e.to_string().contains("face") {
            faces_at
        } else {
            vertices_at
        };
        error(at, format!("invalid mesh: {e}"))
    })?;
    if let Some(at) = get(f, "normals") {
        let normals = list(at, "normals (x, y, z)")?
            .iter()
            .map(|p| triple(p, "a normal").map(|[x, y, z]| Vector3::new(x, y, z)))
            .collect::<Result<Vec<_>, _>>()?;
        mesh = mesh
            .with_normals(normals)
            .or_else(|e| error(at, format!("invalid mesh: {e}")))?;
    }
    if let Some(at) = get(f, "colours") {
        let colours = list(at, "colours")?
            .iter()
            .map(colour)
            .collect::<Result<Vec<_>, _>>()?;
        mesh = mesh
            .with_colors(colours)
            .or_else(|e| error(at, format!("invalid mesh: {e}")))?;
    }
    Ok(mesh)
}

fn channel(node: &Node) -> Result<u8, LiteralError> {
    match &node.kind {
        Kind::Number(n) => n.replace('_', "").parse::<u8>().or_else(|_| {
            error(
                node,
                format!("expected a colour channel (a whole number 0 to 255), found {n}"),
            )
        }),
        _ => error(
            node,
            format!(
                "expected a colour channel 0 to 255, found {}",
                node.describe()
            ),
        ),
    }
}

/// A colour from `#RRGGBB` or `#AARRGGBB`.
pub(crate) fn parse_hex_colour(text: &str) -> Option<Color> {
    let hex = text.trim().strip_prefix('#')?;
    if !hex.chars().all(|c| c.is_ascii_hexdigit()) {
        return None;
    }
    let value = u32::from_str_radix(hex, 16).ok()?;
    match hex.len() {
        6 => Some(Color::from_argb(0xFF00_0000 | value)),
        8 => Some(Color::from_argb(value)),
        _ => None,
    }
}

/// Reads a colour literal.
pub(crate) fn colour(node: &Node) -> Result<Color, LiteralError> {
    match &node.kind {
        Kind::Struct(None, f) => {
            check_fields(node, f, "a colour", &["r", "g", "b", "a"])?;
            let need = |name: &str| {
                get(f, name).map_or_else(
                    || error(node, format!("a colour needs the field `{name}`")),
                    channel,
                )
            };
            let a = match get(f, "a") {
                Some(a) => channel(a)?,
                None => 255,
            };
            Ok(Color::rgba(need("r")?, need("g")?, need("b")?, a))
        }
        Kind::Tuple(None, v) if v.len() == 3 || v.len() == 4 => {
            let a = if v.len() == 4 { channel(&v[3])? } else { 255 };
            Ok(Color::rgba(
                channel(&v[0])?,
                channel(&v[1])?,
                channel(&v[2])?,
                a,
            ))
        }
        Kind::Str(s) => parse_hex_colour(s).map_or_else(
            || {
                error(
                    node,
                    format!("expected a colour \"#RRGGBB\" or \"#AARRGGBB\", found \"{s}\""),
                )
            },
            Ok,
        ),
        _ => mismatch(node, DataType::Colour),
    }
}

/// Whether an untagged struct literal is a mesh or a colour, told by its field names.
pub(crate) fn struct_type(fields: &[Field]) -> Option<DataType> {
    let has = |name: &str| fields.iter().any(|f| f.name == name);
    if has("vertices") || has("faces") {
        Some(DataType::Mesh)
    } else if has("r") && has("g") && has("b") {
        Some(DataType::Colour)
    } else {
        None
    }
}

/// Reads a mesh or colour item, or `None` for another type.
pub(crate) fn parse(node: &Node, data_type: DataType) -> Option<Result<Value, LiteralError>> {
    Some(match data_type {
        DataType::Mesh => mesh(node).map(|m| Value::Mesh(Shared::new(m))),
        DataType::Colour => colour(node).map(Value::Colour),
        _ => return None,
    })
}

fn field(name: &str, value: Node) -> Field {
    Field {
        name: name.to_owned(),
        name_span: 0..0,
        value,
    }
}

fn colour_node(c: Color) -> Node {
    let int = |x: u8| Node::new(Kind::Number(x.to_string()));
    let mut fields = vec![
        field("r", int(c.r)),
        field("g", int(c.g)),
        field("b", int(c.b)),
    ];
    if c.a != 255 {
        fields.push(field("a", int(c.a)));
    }
    Node::new(Kind::Struct(None, fields))
}

/// The literal syntax of a mesh or colour item, or `None` for another type.
pub(crate) fn node(value: &Value) -> Option<Node> {
    Some(match value {
        Value::Colour(c) => colour_node(*c),
        Value::Mesh(m) => {
            let triples = |items: Vec<[f64; 3]>| {
                Node::new(Kind::List(items.into_iter().map(numbers_node).collect()))
            };
            let index = |i: u32| Node::new(Kind::Number(i.to_string()));
            let faces = m
                .faces()
                .iter()
                .map(|f| {
                    Node::new(Kind::Tuple(
                        None,
                        f.corners().iter().map(|&i| index(i)).collect(),
                    ))
                })
                .collect();
            let mut fields = vec![
                field(
                    "vertices",
                    triples(m.vertices().iter().map(|p| p.to_array()).collect()),
                ),
                field("faces", Node::new(Kind::List(faces))),
            ];
            if let Some(n) = m.normals() {
                fields.push(field(
                    "normals",
                    triples(n.iter().map(|v| v.to_array()).collect()),
                ));
            }
            if let Some(c) = m.colors() {
                fields.push(field(
                    "colours",
                    Node::new(Kind::List(c.iter().map(|&c| colour_node(c)).collect())),
                ));
            }
            let _ = number_node;
            Node::new(Kind::Struct(None, fields))
        }
        _ => return None,
    })
}

//! Polygon meshes of triangles and quads, as Rhino's `Mesh`: vertices, faces of three or four
//! vertex indices, and optional per-vertex normals and colours.
//!
//! A face stores four indices; a triangle repeats its third index in the fourth place, as
//! openNURBS's `ON_MeshFace` does, so that faces are one fixed-size array and a mesh converts to
//! and from Rhino's without copying face by face.

mod closest;
mod edges;
mod grid;
pub(crate) mod index;
mod measure;
pub(crate) mod parameters;
mod polyline;
pub(crate) mod populate;
mod sampling;
mod tessellate;
mod triangulation;
mod weld;

use std::collections::HashMap;

pub use closest::MeshPoint;
pub use edges::MeshEdge;
pub use grid::GRID_COINCIDENT_DISTANCE;
pub use index::INDEX_MIN_FACES;
pub use populate::{GeometrySampler, spread_points};
pub use tessellate::FaceTriangle;
pub use triangulation::PlanarTriangulation;
pub use weld::WELD_DISTANCE;

use crate::{BoundingBox, Error, Point3, Result, Transform, Vector3};

/// A colour with 8-bit red, green, blue and alpha channels (alpha 255 is opaque), as
/// Grasshopper's `System.Drawing.Color` and openNURBS's `ON_Color` hold them.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Color {
    /// Red, 0–255.
    pub r: u8,
    /// Green, 0–255.
    pub g: u8,
    /// Blue, 0–255.
    pub b: u8,
    /// Alpha, 0 (transparent) – 255 (opaque).
    pub a: u8,
}

impl Color {
    /// Opaque black.
    pub const BLACK: Self = Self::rgb(0, 0, 0);
    /// Opaque white.
    pub const WHITE: Self = Self::rgb(255, 255, 255);

    /// An opaque colour.
    pub const fn rgb(r: u8, g: u8, b: u8) -> Self {
        Self { r, g, b, a: 255 }
    }

    /// A colour with an alpha channel.
    pub const fn rgba(r: u8, g: u8, b: u8, a: u8) -> Self {
        Self { r, g, b, a }
    }

    /// The colour as `0xAARRGGBB`, the layout of .NET's `Color.ToArgb`.
    pub const fn to_argb(self) -> u32 {
        (self.a as u32) << 24 | (self.r as u32) << 16 | (self.g as u32) << 8 | self.b as u32
    }

    /// The colour of a `0xAARRGGBB` value.
    pub const fn from_argb(argb: u32) -> Self {
        Self {
            a: (argb >> 24) as u8,
            r: (argb >> 16) as u8,
            g: (argb >> 8) as u8,
            b: argb as u8,
        }
    }
}

/// One face of a [`Mesh`]: four vertex indices, counter-clockwise seen from the side the face's
/// normal points to. A triangle has `vertices[2] == vertices[3]`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct MeshFace {
    /// The vertex indices; the fourth repeats the third for a triangle.
    pub vertices: [u32; 4],
}

impl MeshFace {
    /// A triangle `a b c`.
    pub const fn triangle(a: u32, b: u32, c: u32) -> Self {
        Self {
            vertices: [a, b, c, c],
        }
    }

    /// A quad `a b c d`.
    pub const fn quad(a: u32, b: u32, c: u32, d: u32) -> Self {
        Self {
            vertices: [a, b, c, d],
        }
    }

    /// Whether the face is a triangle.
    pub const fn is_triangle(&self) -> bool {
        self.vertices[2] == self.vertices[3]
    }

    /// The face's distinct corner indices: three for a triangle, four for a quad.
    pub fn corners(&self) -> &[u32] {
        if self.is_triangle() {
            &self.vertices[..3]
        } else {
            &self.vertices
        }
    }

    /// The face as one or two triangles (a quad is split along its `a c` diagonal, as Rhino's
    /// `ConvertQuadsToTriangles` does for planar quads).
    pub fn triangles(&self) -> impl Iterator<Item = [u32; 3]> {
        let [a, b, c, d] = self.vertices;
        let second = (!self.is_triangle()).then_some([a, c, d]);
        std::iter::once([a, b, c]).chain(second)
    }

    /// The same face with the opposite orientation.
    pub fn flipped(&self) -> Self {
        let [a, b, c, d] = self.vertices;
        if self.is_triangle() {
            Self::triangle(a, c, b)
        } else {
            Self::quad(a, d, c, b)
        }
    }
}

/// A polygon mesh of triangles and quads with optional vertex normals and vertex colours.
///
/// The constructor checks that every index names a vertex, that every coordinate is finite and
/// that normals and colours, where given, have one entry per vertex; the fields are private so
/// that these hold for every mesh.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct Mesh {
    vertices: Vec<Point3>,
    faces: Vec<MeshFace>,
    normals: Option<Vec<Vector3>>,
    colors: Option<Vec<Color>>,
    /// The spatial index of the faces, built when queries need it (`index.rs`).
    index: index::IndexCache,
}

impl Mesh {
    /// A mesh of vertices and faces.
    ///
    /// # Errors
    /// [`Error::NotFinite`] for a vertex that is not finite, [`Error::InvalidInput`] for a face
    /// index past the last vertex or a face that repeats a vertex (other than a triangle's
    /// repeated third index).
    pub fn new(vertices: Vec<Point3>, faces: Vec<MeshFace>) -> Result<Self> {
        if vertices.iter().any(|p| !p.is_finite()) {
            return Err(Error::NotFinite {
                what: "mesh vertex",
            });
        }
        let count = vertices.len();
        for (i, face) in faces.iter().enumerate() {
            if let Some(&bad) = face.vertices.iter().find(|&&v| v as usize >= count) {
                return Err(Error::InvalidInput(format!(
                    "mesh face {i} names vertex {bad}, but the mesh has {count} vertices"
                )));
            }
            let c = face.corners();
            let repeats = (0..c.len()).any(|j| c[j + 1..].contains(&c[j]));
            if repeats {
                return Err(Error::InvalidInput(format!(
                    "mesh face {i} repeats a vertex: {:?}",
                    face.vertices
                )));
            }
        }
        Ok(Self {
            vertices,
            faces,
            normals: None,
            colors: None,
            index: index::IndexCache::default(),
        })
    }

    /// The mesh with one normal per vertex.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] when the count differs from the vertex count,
    /// [`Error::NotFinite`] for a normal that is not finite.
    pub fn with_normals(mut self, normals: Vec<Vector3>) -> Result<Self> {
        if normals.len() != self.vertices.len() {
            return Err(Error::InvalidInput(format!(
                "mesh has {} vertices but {} normals",
                self.vertices.len(),
                normals.len()
            )));
        }
        if normals.iter().any(|n| !n.is_finite()) {
            return Err(Error::NotFinite {
                what: "mesh normal",
            });
        }
        self.normals = Some(normals);
        Ok(self)
    }

    /// The mesh with one colour per vertex.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] when the count differs from the vertex count.
    pub fn with_colors(mut self, colors: Vec<Color>) -> Result<Self> {
        if colors.len() != self.vertices.len() {
            return Err(Error::InvalidInput(format!(
                "mesh has {} vertices but {} colours",
                self.vertices.len(),
                colors.len()
            )));
        }
        self.colors = Some(colors);
        Ok(self)
    }

    /// The vertices.
    pub fn vertices(&self) -> &[Point3] {
        &self.vertices
    }

    /// The faces.
    pub fn faces(&self) -> &[MeshFace] {
        &self.faces
    }

    /// The vertex normals, if the mesh has them.
    pub fn normals(&self) -> Option<&[Vector3]> {
        self.normals.as_deref()
    }

    /// The vertex colours, if the mesh has them.
    pub fn colors(&self) -> Option<&[Color]> {
        self.colors.as_deref()
    }

    /// Whether the mesh has no faces.
    pub fn is_empty(&self) -> bool {
        self.faces.is_empty()
    }

    /// The number of triangles once quads are split.
    pub fn triangle_count(&self) -> usize {
        self.faces
            .iter()
            .map(|f| if f.is_triangle() { 1 } else { 2 })
            .sum()
    }

    /// The triangles of the mesh (quads split along their `a c` diagonal).
    pub fn triangles(&self) -> impl Iterator<Item = [u32; 3]> + '_ {
        self.faces.iter().flat_map(MeshFace::triangles)
    }

    /// The bounding box of the vertices (empty for a mesh without vertices).
    pub fn bounding_box(&self) -> BoundingBox {
        let mut bbox = BoundingBox::EMPTY;
        for &p in &self.vertices {
            bbox.include_point(p);
        }
        bbox
    }

    /// The corners of a triangle.
    fn corners_of(&self, [a, b, c]: [u32; 3]) -> [Point3; 3] {
        [
            self.vertices[a as usize],
            self.vertices[b as usize],
            self.vertices[c as usize],
        ]
    }

    /// The area: the sum of the triangles' areas.
    pub fn area(&self) -> f64 {
        self.triangles()
            .map(|t| {
                let [p, q, r] = self.corners_of(t);
                0.5 * (q - p).cross(r - p).length()
            })
            .sum()
    }

    /// The signed volume enclosed by the triangles (positive when the faces are oriented with
    /// normals pointing out); meaningful for a closed mesh (see [`Mesh::naked_edge_count`]).
    pub fn volume(&self) -> f64 {
        // Divergence theorem over triangles, measured from the bounding box's centre to keep
        // the products small for meshes far from the origin.
        let o = self.bounding_box().center();
        self.triangles()
            .map(|t| {
                let [p, q, r] = self.corners_of(t);
                (p - o).dot((q - o).cross(r - o)) / 6.0
            })
            .sum()
    }

    /// Each undirected edge `(low, high)` with the number of faces that use it.
    pub fn edge_valences(&self) -> HashMap<(u32, u32), usize> {
        let mut edges = HashMap::new();
        for face in &self.faces {
            let c = face.corners();
            for i in 0..c.len() {
                let (a, b) = (c[i], c[(i + 1) % c.len()]);
                *edges.entry((a.min(b), a.max(b))).or_insert(0) += 1;
            }
        }
        edges
    }

    /// The number of edges used by only one face. A closed mesh has none.
    pub fn naked_edge_count(&self) -> usize {
        self.edge_valences().values().filter(|&&n| n == 1).count()
    }

    /// Whether every edge is shared by exactly two faces, each using it once in each direction:
    /// the mesh is closed, manifold and consistently oriented.
    pub fn is_closed_and_oriented(&self) -> bool {
        let mut directed: HashMap<(u32, u32), i32> = HashMap::new();
        for face in &self.faces {
            let c = face.corners();
            for i in 0..c.len() {
                let (a, b) = (c[i], c[(i + 1) % c.len()]);
                let key = (a.min(b), a.max(b));
                *directed.entry(key).or_insert(0) += if a < b { 1 } else { -1 };
            }
        }
        !self.faces.is_empty()
            && directed.values().all(|&d| d == 0)
            && self.edge_valences().values().all(|&n| n == 2)
    }

    /// The unit normal of each face (Newell's method, so quads that are not planar get their
    /// average normal); `None` for a face of zero area.
    pub fn face_normals(&self) -> Vec<Option<Vector3>> {
        self.faces
            .iter()
            .map(|face| {
                let c = face.corners();
                let mut n = Vector3::ZERO;
                for i in 0..c.len() {
                    let p = self.vertices[c[i] as usize] - Point3::ORIGIN;
                    let q = self.vertices[c[(i + 1) % c.len()] as usize] - Point3::ORIGIN;
                    n += p.cross(q);
                }
                n.unitize().ok()
            })
            .collect()
    }

    /// The mesh with vertex normals computed as the area-weighted average of the normals of the
    /// faces around each vertex (a vertex on faces of zero area only gets the zero vector's
    /// fallback, world Z).
    pub fn with_computed_normals(mut self) -> Self {
        let mut sums = vec![Vector3::ZERO; self.vertices.len()];
        for t in self.triangles().collect::<Vec<_>>() {
            let [p, q, r] = self.corners_of(t);
            let n = (q - p).cross(r - p);
            for v in t {
                sums[v as usize] += n;
            }
        }
        let normals = sums
            .into_iter()
            .map(|n| n.unitize().unwrap_or(Vector3::Z))
            .collect();
        self.normals = Some(normals);
        self
    }

    /// The mesh with every face reversed (and normals negated).
    pub fn flipped(&self) -> Self {
        self.flipped_parts(true, true)
    }

    /// The mesh with its vertex normals negated (`vertex_normals`) and every face's vertex
    /// order reversed (`orientation`), as Rhino's `Mesh.Flip`.
    pub fn flipped_parts(&self, vertex_normals: bool, orientation: bool) -> Self {
        let mut mesh = self.clone();
        if orientation {
            for face in &mut mesh.faces {
                *face = face.flipped();
            }
        }
        if vertex_normals && let Some(normals) = &mut mesh.normals {
            for n in normals {
                *n = -*n;
            }
        }
        mesh
    }

    /// The mesh transformed: vertices as points, normals by the inverse transpose (re-unitized).
    ///
    /// # Errors
    /// [`Error::NotFinite`] when the transform makes a vertex infinite.
    pub fn transformed(&self, xform: &Transform) -> Result<Self> {
        let mut mesh = self.clone();
        xform.transform_points(&mut mesh.vertices);
        if mesh.vertices.iter().any(|p| !p.is_finite()) {
            return Err(Error::NotFinite {
                what: "mesh vertex",
            });
        }
        if let Some(normals) = &mut mesh.normals {
            let normal_map = xform.inverse().map(|inv| Transform {
                matrix: inv.matrix.transpose(),
            });
            for n in normals.iter_mut() {
                let mapped = match &normal_map {
                    Ok(m) => m.transform_vector(*n),
                    Err(_) => *n,
                };
                *n = mapped.unitize().unwrap_or(*n);
            }
        }
        if xform.determinant() < 0.0 {
            for face in &mut mesh.faces {
                *face = face.flipped();
            }
        }
        Ok(mesh)
    }

    /// The spatial index of the faces, when a query should use one (see `index.rs`: built on
    /// the second query of a large mesh).
    pub(crate) fn face_index(&self) -> Option<&index::FaceIndex> {
        self.index.get(self)
    }

    /// Appends another mesh (its vertices and faces follow this mesh's). Normals and colours
    /// are kept only when both meshes have them.
    pub fn append(&mut self, other: &Mesh) {
        self.index.clear();
        let offset = self.vertices.len() as u32;
        self.vertices.extend_from_slice(&other.vertices);
        self.faces.extend(other.faces.iter().map(|f| MeshFace {
            vertices: f.vertices.map(|v| v + offset),
        }));
        self.normals = match (self.normals.take(), &other.normals) {
            (Some(mut a), Some(b)) => {
                a.extend_from_slice(b);
                Some(a)
            }
            _ => None,
        };
        self.colors = match (self.colors.take(), &other.colors) {
            (Some(mut a), Some(b)) => {
                a.extend_from_slice(b);
                Some(a)
            }
            _ => None,
        };
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn unit_cube() -> Mesh {
        let v = |x: f64, y: f64, z: f64| Point3::new(x, y, z);
        let vertices = vec![
            v(0.0, 0.0, 0.0),
            v(1.0, 0.0, 0.0),
            v(1.0, 1.0, 0.0),
            v(0.0, 1.0, 0.0),
            v(0.0, 0.0, 1.0),
            v(1.0, 0.0, 1.0),
            v(1.0, 1.0, 1.0),
            v(0.0, 1.0, 1.0),
        ];
        let faces = vec![
            MeshFace::quad(0, 3, 2, 1),
            MeshFace::quad(4, 5, 6, 7),
            MeshFace::quad(0, 1, 5, 4),
            MeshFace::quad(1, 2, 6, 5),
            MeshFace::quad(2, 3, 7, 6),
            MeshFace::quad(3, 0, 4, 7),
        ];
        Mesh::new(vertices, faces).unwrap()
    }

    #[test]
    fn cube_measures() {
        let cube = unit_cube();
        assert_eq!(cube.triangle_count(), 12);
        assert!((cube.area() - 6.0).abs() < 1e-12);
        assert!((cube.volume() - 1.0).abs() < 1e-12);
        assert_eq!(cube.naked_edge_count(), 0);
        assert!(cube.is_closed_and_oriented());
        assert!((cube.flipped().volume() + 1.0).abs() < 1e-12);
        let normals = cube.face_normals();
        assert_eq!(normals[0], Some(-Vector3::Z));
        assert_eq!(normals[1], Some(Vector3::Z));
    }

    #[test]
    fn bad_meshes_are_errors() {
        let p = vec![
            Point3::ORIGIN,
            Point3::new(1.0, 0.0, 0.0),
            Point3::new(0.0, 1.0, 0.0),
        ];
        let e = Mesh::new(p.clone(), vec![MeshFace::triangle(0, 1, 3)]).unwrap_err();
        assert_eq!(
            e.to_string(),
            "mesh face 0 names vertex 3, but the mesh has 3 vertices"
        );
        assert!(Mesh::new(p.clone(), vec![MeshFace::quad(0, 1, 1, 2)]).is_err());
        let nan = vec![Point3::new(f64::NAN, 0.0, 0.0)];
        assert!(Mesh::new(nan, vec![]).is_err());
        let mesh = Mesh::new(p, vec![MeshFace::triangle(0, 1, 2)]).unwrap();
        assert!(mesh.clone().with_normals(vec![Vector3::Z]).is_err());
        assert!(mesh.clone().with_colors(vec![Color::WHITE; 2]).is_err());
        assert_eq!(mesh.naked_edge_count(), 3);
        assert!(!mesh.is_closed_and_oriented());
    }

    #[test]
    fn mirroring_keeps_volume_positive() {
        let cube = unit_cube().with_computed_normals();
        let mirror = Transform::mirror(&crate::Plane::WORLD_XY);
        let mirrored = cube.transformed(&mirror).unwrap();
        assert!((mirrored.volume() - 1.0).abs() < 1e-12);
        let top = mirrored
            .vertices()
            .iter()
            .position(|p| p.z == -1.0)
            .unwrap();
        assert!(mirrored.normals().unwrap()[top].z < 0.0);
    }

    #[test]
    fn append_offsets_indices() {
        let mut a = unit_cube();
        let b = unit_cube().transformed(&Transform::translation(Vector3::new(2.0, 0.0, 0.0)));
        a.append(&b.unwrap());
        assert_eq!(a.vertices().len(), 16);
        assert_eq!(a.faces()[6].vertices, [8, 11, 10, 9]);
        assert!((a.volume() - 2.0).abs() < 1e-12);
    }

    #[test]
    fn argb_round_trips() {
        let c = Color::rgba(10, 20, 30, 40);
        assert_eq!(c.to_argb(), 0x280a141e);
        assert_eq!(Color::from_argb(c.to_argb()), c);
    }
}

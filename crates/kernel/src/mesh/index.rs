//! A spatial index of a mesh's triangles, so that closest points and ray hits on a large mesh
//! cost a logarithmic search instead of a pass over every face.
//!
//! The index is an R*-tree (the `rstar` crate, georust's well-kept spatial index, instead of a
//! BVH of our own) over the mesh's triangles, quads as their two triangles split along `a c` as
//! [`MeshFace::triangles`](crate::MeshFace::triangles) splits them. Each leaf carries its three
//! corners, so a search reads no other memory.
//!
//! *When it is built.* A mesh builds its index on the second query that could use it, not the
//! first: one query on a mesh is one pass over its faces, cheaper than building a tree, while
//! many queries (Mesh Closest Point or Mesh | Ray over a list of points) pay for the tree once.
//! Meshes of fewer than [`INDEX_MIN_FACES`] faces are always searched face by face.
//! The index is shared by clones of the same `Arc<Mesh>` (a tree's items) and dropped when the
//! mesh changes.
//!
//! *Same answers.* An indexed search returns exactly what the pass over the faces returns: the
//! same per-triangle arithmetic, and ties broken the same way (the lowest face, then its first
//! triangle). A property test compares the two on random meshes.

use std::sync::atomic::{AtomicU32, Ordering};
use std::sync::{Arc, OnceLock};

use rstar::{AABB, PointDistance, RTree, RTreeObject, SelectionFunction};

use crate::{Mesh, Point3, Vector3};

/// Meshes with fewer faces than this are searched face by face, without an index.
pub const INDEX_MIN_FACES: usize = 64;

/// One triangle of a mesh face, with its corners.
#[derive(Clone, Debug)]
pub(crate) struct IndexedTriangle {
    /// The triangle's corners, in the face's order.
    pub corners: [Point3; 3],
    /// The face it belongs to.
    pub face: u32,
    /// 0 for a face's first triangle (`a b c`), 1 for a quad's second (`a c d`).
    pub half: u8,
}

impl IndexedTriangle {
    /// The key that breaks ties between triangles: lower faces first, then first halves.
    pub fn order(&self) -> (u32, u8) {
        (self.face, self.half)
    }
}

impl RTreeObject for IndexedTriangle {
    type Envelope = AABB<[f64; 3]>;

    fn envelope(&self) -> Self::Envelope {
        let [a, b, c] = self.corners;
        AABB::from_corners(
            [
                a.x.min(b.x).min(c.x),
                a.y.min(b.y).min(c.y),
                a.z.min(b.z).min(c.z),
            ],
            [
                a.x.max(b.x).max(c.x),
                a.y.max(b.y).max(c.y),
                a.z.max(b.z).max(c.z),
            ],
        )
    }
}

impl PointDistance for IndexedTriangle {
    fn distance_2(&self, point: &[f64; 3]) -> f64 {
        let p = Point3::new(point[0], point[1], point[2]);
        let [a, b, c] = self.corners;
        let (on, _) = super::closest::closest_on_triangle(p, a, b, c);
        (on - p).length_squared()
    }
}

/// The triangles of a mesh in an R*-tree.
#[derive(Debug)]
pub(crate) struct FaceIndex {
    tree: RTree<IndexedTriangle>,
}

impl FaceIndex {
    fn build(mesh: &Mesh) -> Self {
        let v = mesh.vertices();
        let triangles = mesh
            .faces()
            .iter()
            .enumerate()
            .flat_map(|(face, f)| {
                f.triangles()
                    .enumerate()
                    .map(move |(half, t)| IndexedTriangle {
                        corners: t.map(|i| v[i as usize]),
                        face: face as u32,
                        half: half as u8,
                    })
            })
            .collect();
        Self {
            tree: RTree::bulk_load(triangles),
        }
    }

    /// The triangles nearest `point`: every triangle at the smallest distance (usually one),
    /// in no particular order, with that distance.
    pub fn nearest(&self, point: Point3) -> (Vec<&IndexedTriangle>, f64) {
        let mut nearest = Vec::new();
        let mut best = f64::INFINITY;
        for (triangle, d2) in self
            .tree
            .nearest_neighbor_iter_with_distance_2([point.x, point.y, point.z])
        {
            // Distances compare as the face-by-face search compares them (after the square
            // root), so that ties are the same ties.
            let distance = d2.sqrt();
            if nearest.is_empty() {
                best = distance;
            } else if distance > best {
                break;
            }
            nearest.push(triangle);
        }
        (nearest, best)
    }

    /// The triangles whose bounding boxes the ray from `start` along `direction` (`t ≥ 0`)
    /// meets, in no particular order.
    pub fn along_ray(
        &self,
        start: Point3,
        direction: Vector3,
    ) -> impl Iterator<Item = &IndexedTriangle> {
        self.tree
            .locate_with_selection_function(RaySelection { start, direction })
    }
}

/// Selects the nodes and triangles whose boxes a ray meets.
struct RaySelection {
    start: Point3,
    direction: Vector3,
}

impl RaySelection {
    /// Whether the ray meets the box, by the slab test; the box is widened by a relative 1e-9
    /// of its size so that a rounding error cannot lose a triangle the ray grazes.
    fn meets(&self, envelope: &AABB<[f64; 3]>) -> bool {
        let (lo, hi) = (envelope.lower(), envelope.upper());
        let s = [self.start.x, self.start.y, self.start.z];
        let d = [self.direction.x, self.direction.y, self.direction.z];
        let (mut t0, mut t1) = (0.0_f64, f64::INFINITY);
        for k in 0..3 {
            let pad = 1e-9
                * (hi[k] - lo[k])
                    .abs()
                    .max(lo[k].abs())
                    .max(hi[k].abs())
                    .max(1.0);
            let (lo, hi) = (lo[k] - pad, hi[k] + pad);
            if d[k] == 0.0 {
                if s[k] < lo || s[k] > hi {
                    return false;
                }
                continue;
            }
            let (a, b) = ((lo - s[k]) / d[k], (hi - s[k]) / d[k]);
            let (a, b) = if a <= b { (a, b) } else { (b, a) };
            t0 = t0.max(a);
            t1 = t1.min(b);
            if t0 > t1 {
                return false;
            }
        }
        true
    }
}

impl SelectionFunction<IndexedTriangle> for RaySelection {
    fn should_unpack_parent(&self, envelope: &AABB<[f64; 3]>) -> bool {
        self.meets(envelope)
    }

    fn should_unpack_leaf(&self, leaf: &IndexedTriangle) -> bool {
        self.meets(&leaf.envelope())
    }
}

/// A mesh's lazily built index. Clones start empty (a clone is usually about to change), and
/// every mesh compares equal whatever its cache holds.
#[derive(Default)]
pub(crate) struct IndexCache {
    queries: AtomicU32,
    index: OnceLock<Arc<FaceIndex>>,
}

impl IndexCache {
    /// The index, if this query should use one: built on the second query of a mesh of at
    /// least [`INDEX_MIN_FACES`] faces.
    pub fn get(&self, mesh: &Mesh) -> Option<&FaceIndex> {
        if let Some(index) = self.index.get() {
            return Some(index);
        }
        if mesh.faces().len() < INDEX_MIN_FACES {
            return None;
        }
        if self.queries.fetch_add(1, Ordering::Relaxed) == 0 {
            return None;
        }
        Some(self.index.get_or_init(|| Arc::new(FaceIndex::build(mesh))))
    }

    /// Forgets the index (the mesh changed).
    pub fn clear(&mut self) {
        *self = Self::default();
    }
}

impl Clone for IndexCache {
    fn clone(&self) -> Self {
        Self::default()
    }
}

impl PartialEq for IndexCache {
    fn eq(&self, _: &Self) -> bool {
        true
    }
}

impl std::fmt::Debug for IndexCache {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("..")
    }
}

#[cfg(test)]
mod tests {
    use proptest::prelude::*;

    use super::*;
    use crate::MeshFace;
    use crate::mesh_ray;

    /// The answer of a search face by face: a fresh clone's first query never uses an index.
    fn unindexed(mesh: &Mesh, p: Point3) -> Option<crate::MeshPoint> {
        mesh.clone().closest_point(p)
    }

    /// A mesh whose index is built (it has been asked twice).
    fn indexed(mesh: Mesh) -> Mesh {
        mesh.closest_point(Point3::ORIGIN);
        mesh.closest_point(Point3::ORIGIN);
        assert!(
            mesh.face_index().is_some(),
            "a mesh of {} faces",
            mesh.faces().len()
        );
        mesh
    }

    /// A wavy grid of `n × n` quads (on a flat grid, `wave` 0, many points tie).
    fn grid(n: usize, wave: f64) -> Mesh {
        Mesh::quad_grid(n, n, |i, j| {
            let (x, y) = (i as f64, j as f64);
            Point3::new(x, y, wave * (x * 0.7).sin() * (y * 0.4).cos())
        })
        .unwrap()
    }

    #[test]
    fn small_meshes_and_first_queries_go_face_by_face() {
        let small = grid(7, 0.0);
        assert!(small.faces().len() < INDEX_MIN_FACES);
        for _ in 0..3 {
            small.closest_point(Point3::ORIGIN);
        }
        assert!(small.face_index().is_none());
        let large = grid(8, 0.0);
        large.closest_point(Point3::ORIGIN);
        assert!(
            large.index.index.get().is_none(),
            "built on the first query"
        );
        large.closest_point(Point3::ORIGIN);
        assert!(
            large.index.index.get().is_some(),
            "not built on the second query"
        );
    }

    #[test]
    fn ties_go_to_the_lowest_face_as_face_by_face() {
        // Above a vertex of a flat grid, four faces (eight triangles) are at the same distance.
        let mesh = indexed(grid(10, 0.0));
        for p in [
            Point3::new(3.0, 4.0, 1.0),
            Point3::new(5.0, 5.0, -2.0),
            Point3::new(-1.0, -1.0, 0.0),
        ] {
            let a = mesh.closest_point(p).unwrap();
            let b = unindexed(&mesh, p).unwrap();
            assert_eq!(a, b, "at {p:?}");
        }
        // A vertical ray through a shared vertex hits four faces at the same parameter.
        let start = Point3::new(3.0, 4.0, 5.0);
        let down = Vector3::new(0.0, 0.0, -1.0);
        let hit = mesh_ray(&mesh, start, down).unwrap();
        let reference = mesh_ray(&mesh.clone(), start, down).unwrap();
        assert_eq!(hit, reference);
        // The faces around vertex (3, 4) are (2..3, 3..4) = face 32, 33, 42 and 43.
        assert_eq!(hit.2, 32);
    }

    #[test]
    fn a_changed_mesh_forgets_its_index() {
        let mut mesh = indexed(grid(8, 0.0));
        let far = grid(1, 0.0)
            .transformed(&crate::Transform::translation(Vector3::new(0.0, 0.0, 50.0)))
            .unwrap();
        mesh.append(&far);
        let p = Point3::new(0.5, 0.5, 49.0);
        assert_eq!(mesh.closest_point(p).unwrap().face, 64);
        assert_eq!(mesh.closest_point(p).unwrap().face, 64);
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(64))]

        /// Indexed searches give exactly the answers of face-by-face searches, on triangle
        /// soups with quads, for points near and far.
        #[test]
        fn indexed_answers_equal_face_by_face(
            corners in proptest::collection::vec((-10.0..10.0f64, -10.0..10.0f64, -10.0..10.0f64), 260..400),
            queries in proptest::collection::vec((-15.0..15.0f64, -15.0..15.0f64, -15.0..15.0f64, -1.0..1.0f64, -1.0..1.0f64, -1.0..1.0f64), 1..40),
        ) {
            let vertices: Vec<Point3> = corners.iter().map(|&(x, y, z)| Point3::new(x, y, z)).collect();
            let n = vertices.len() as u32;
            let faces = (0..n / 4)
                .map(|k| if k % 3 == 0 {
                    MeshFace::quad(4 * k, 4 * k + 1, 4 * k + 2, 4 * k + 3)
                } else {
                    MeshFace::triangle(4 * k, 4 * k + 1, 4 * k + 2)
                })
                .collect();
            let mesh = indexed(Mesh::new(vertices, faces).unwrap());
            for (x, y, z, dx, dy, dz) in queries {
                let p = Point3::new(x, y, z);
                prop_assert_eq!(mesh.closest_point(p), unindexed(&mesh, p));
                let d = Vector3::new(dx, dy, dz);
                prop_assert_eq!(mesh_ray(&mesh, p, d), mesh_ray(&mesh.clone(), p, d));
            }
        }

        /// The same on wavy grids, where neighbouring faces share edges and vertices.
        #[test]
        fn indexed_answers_equal_face_by_face_on_grids(
            wave in 0.0..3.0f64,
            queries in proptest::collection::vec((-2.0..12.0f64, -2.0..12.0f64, -4.0..4.0f64), 1..40),
        ) {
            let mesh = indexed(grid(10, wave));
            for (x, y, z) in queries {
                let p = Point3::new(x, y, z);
                prop_assert_eq!(mesh.closest_point(p), unindexed(&mesh, p));
                let down = Vector3::new(0.0, 0.0, -1.0);
                let start = Point3::new(x, y, 10.0);
                prop_assert_eq!(mesh_ray(&mesh, start, down), mesh_ray(&mesh.clone(), start, down));
            }
        }
    }
}

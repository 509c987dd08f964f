//! Welding and unwelding a mesh's vertices (Rhino's `Mesh.Weld` and `Mesh.Unweld`).
//!
//! *Weld* merges vertices that lie at one point (within [`WELD_DISTANCE`]) when the faces that
//! use them differ in normal by at most the angle: faces at a crease sharper than the angle keep
//! their own vertices. *Unweld* does the reverse: a vertex is split into one copy per fan of
//! faces around it that are joined across edges bending by at most the angle, so edges sharper
//! than the angle get a vertex on each side. Both keep each vertex's colour and, when the mesh
//! has vertex normals, compute them again from the new faces.

use std::collections::HashMap;

use crate::geometry::tolerance::DEFAULT_TOLERANCE;
use crate::{Mesh, MeshFace, Point3, Vector3};

/// The distance under which Weld takes two vertices for one point: the kernel's
/// [`DEFAULT_TOLERANCE`].
pub const WELD_DISTANCE: f64 = DEFAULT_TOLERANCE;

/// A union-find over `0..n` (path halving; the root of a set is its smallest member, so that
/// results do not depend on the order of unions).
struct Sets(Vec<usize>);

impl Sets {
    fn new(n: usize) -> Self {
        Self((0..n).collect())
    }

    fn find(&mut self, mut i: usize) -> usize {
        while self.0[i] != i {
            self.0[i] = self.0[self.0[i]];
            i = self.0[i];
        }
        i
    }

    fn union(&mut self, a: usize, b: usize) {
        let (a, b) = (self.find(a), self.find(b));
        let (low, high) = if a < b { (a, b) } else { (b, a) };
        self.0[high] = low;
    }
}

/// The angle between two face normals; faces of zero area (no normal) join anything.
fn normal_angle(a: Option<Vector3>, b: Option<Vector3>) -> f64 {
    match (a, b) {
        (Some(a), Some(b)) => a.dot(b).clamp(-1.0, 1.0).acos(),
        _ => 0.0,
    }
}

impl Mesh {
    /// The mesh with coincident vertices merged where the normals of the faces using them
    /// differ by at most `angle` (radians; `π` or more merges every coincident pair).
    pub fn welded(&self, angle: f64) -> Self {
        let normals = self.face_normals();
        // One slot per face corner; corners at one point whose faces agree join one set.
        let corners: Vec<(usize, usize)> = self
            .faces()
            .iter()
            .enumerate()
            .flat_map(|(f, face)| (0..face.corners().len()).map(move |k| (f, k)))
            .collect();
        let vertex_of = |&(f, k): &(usize, usize)| self.faces()[f].corners()[k] as usize;
        let mut sets = Sets::new(corners.len());
        // Corners already sharing a vertex stay together.
        let mut first_corner: HashMap<usize, usize> = HashMap::new();
        for (slot, corner) in corners.iter().enumerate() {
            let v = vertex_of(corner);
            match first_corner.get(&v) {
                Some(&s) => sets.union(s, slot),
                None => {
                    first_corner.insert(v, slot);
                }
            }
        }
        // Coincident corners: sort by x and compare within the weld distance.
        let positions: Vec<Point3> = corners
            .iter()
            .map(|c| self.vertices()[vertex_of(c)])
            .collect();
        let mut order: Vec<usize> = (0..corners.len()).collect();
        order.sort_by(|&a, &b| positions[a].x.total_cmp(&positions[b].x));
        for (n, &a) in order.iter().enumerate() {
            for &b in &order[n + 1..] {
                if positions[b].x - positions[a].x > WELD_DISTANCE {
                    break;
                }
                if positions[a].distance(positions[b]) <= WELD_DISTANCE
                    && normal_angle(normals[corners[a].0], normals[corners[b].0]) <= angle
                {
                    sets.union(a, b);
                }
            }
        }
        self.rebuilt(&corners, &mut sets)
    }

    /// The mesh with vertices split along every edge whose two faces' normals differ by more
    /// than `angle` (radians; 0 splits every edge that is not flat).
    pub fn unwelded(&self, angle: f64) -> Self {
        let normals = self.face_normals();
        let corners: Vec<(usize, usize)> = self
            .faces()
            .iter()
            .enumerate()
            .flat_map(|(f, face)| (0..face.corners().len()).map(move |k| (f, k)))
            .collect();
        let mut slot_of: HashMap<(usize, u32), usize> = HashMap::new();
        for (slot, &(f, k)) in corners.iter().enumerate() {
            slot_of.insert((f, self.faces()[f].corners()[k]), slot);
        }
        // The faces on each edge, by its vertex pair.
        let mut edge_faces: HashMap<(u32, u32), Vec<usize>> = HashMap::new();
        for (f, face) in self.faces().iter().enumerate() {
            let c = face.corners();
            for k in 0..c.len() {
                let (a, b) = (c[k], c[(k + 1) % c.len()]);
                edge_faces.entry((a.min(b), a.max(b))).or_default().push(f);
            }
        }
        let mut sets = Sets::new(corners.len());
        let mut edges: Vec<_> = edge_faces.into_iter().collect();
        edges.sort_unstable();
        for ((a, b), faces) in edges {
            for (i, &f) in faces.iter().enumerate() {
                for &g in &faces[i + 1..] {
                    if normal_angle(normals[f], normals[g]) <= angle {
                        for v in [a, b] {
                            sets.union(slot_of[&(f, v)], slot_of[&(g, v)]);
                        }
                    }
                }
            }
        }
        self.rebuilt(&corners, &mut sets)
    }

    /// The mesh with one vertex per set of face corners (numbered in order of first use, at the
    /// position and with the colour of the set's first corner's vertex).
    fn rebuilt(&self, corners: &[(usize, usize)], sets: &mut Sets) -> Self {
        let mut new_index: HashMap<usize, u32> = HashMap::new();
        let mut vertices = Vec::new();
        let mut colors = Vec::new();
        let mut faces = Vec::with_capacity(self.faces().len());
        let mut slot = 0;
        for face in self.faces() {
            let c = face.corners();
            let mut ids = [0u32; 4];
            for id_slot in ids.iter_mut().take(c.len()) {
                let root = sets.find(slot);
                let next = vertices.len() as u32;
                let id = *new_index.entry(root).or_insert_with(|| {
                    let (f, k) = corners[root];
                    let source = self.faces()[f].corners()[k] as usize;
                    vertices.push(self.vertices()[source]);
                    if let Some(cs) = self.colors() {
                        colors.push(cs[source]);
                    }
                    next
                });
                *id_slot = id;
                slot += 1;
            }
            faces.push(if c.len() == 3 {
                MeshFace::triangle(ids[0], ids[1], ids[2])
            } else {
                MeshFace::quad(ids[0], ids[1], ids[2], ids[3])
            });
        }
        // Welding can make a face repeat a vertex (two of its corners at one point); such a
        // face has no area and is left out, as Rhino's Weld culls degenerate faces.
        faces.retain(|f| {
            let c = f.corners();
            (0..c.len()).all(|j| !c[j + 1..].contains(&c[j]))
        });
        let mut mesh = Self {
            vertices,
            faces,
            normals: None,
            colors: None,
            index: Default::default(),
        };
        if self.colors().is_some() {
            mesh.colors = Some(colors);
        }
        if self.normals().is_some() {
            mesh = mesh.with_computed_normals();
        }
        mesh
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Two unit squares at a right angle along the x axis, each with its own four vertices.
    fn hinge() -> Mesh {
        let p = Point3::new;
        Mesh::new(
            vec![
                p(0.0, 0.0, 0.0),
                p(1.0, 0.0, 0.0),
                p(1.0, 1.0, 0.0),
                p(0.0, 1.0, 0.0),
                p(0.0, 0.0, 0.0),
                p(0.0, 0.0, 1.0),
                p(1.0, 0.0, 1.0),
                p(1.0, 0.0, 0.0),
            ],
            vec![MeshFace::quad(0, 1, 2, 3), MeshFace::quad(4, 5, 6, 7)],
        )
        .unwrap()
    }

    #[test]
    fn weld_merges_across_a_crease_only_above_its_angle() {
        let m = hinge();
        // The faces' normals are Z and Y: 90° apart.
        let sharp = m.welded(80f64.to_radians());
        assert_eq!(sharp.vertices().len(), 8);
        let all = m.welded(std::f64::consts::PI);
        assert_eq!(all.vertices().len(), 6);
        // Vertex 4 (0,0,0) became vertex 0, vertex 7 (1,0,0) vertex 1.
        assert_eq!(all.faces()[1], MeshFace::quad(0, 4, 5, 1));
        assert_eq!(all.naked_edge_count(), 6);
    }

    #[test]
    fn unweld_splits_sharp_edges_and_keeps_flat_ones() {
        let welded = hinge().welded(std::f64::consts::PI);
        assert_eq!(welded.unwelded(100f64.to_radians()).vertices().len(), 6);
        assert_eq!(welded.unwelded(80f64.to_radians()).vertices().len(), 8);
        assert_eq!(welded.unwelded(0.0).vertices().len(), 8);
        // A flat strip of two quads keeps its shared edge at any angle.
        let strip = Mesh::quad_grid(2, 1, |i, j| Point3::new(i as f64, j as f64, 0.0)).unwrap();
        assert_eq!(strip.unwelded(0.0).vertices().len(), 6);
    }

    #[test]
    fn colours_follow_and_normals_are_computed_again() {
        let colors = (0..8).map(|i| crate::Color::rgb(i * 10, 0, 0)).collect();
        let m = hinge().with_colors(colors).unwrap().with_computed_normals();
        let w = m.welded(std::f64::consts::PI);
        let cs = w.colors().unwrap();
        assert_eq!(cs.len(), 6);
        assert_eq!(cs[0], crate::Color::rgb(0, 0, 0));
        assert_eq!(cs[4], crate::Color::rgb(50, 0, 0));
        // The shared corner (0,0,0) averages Z and Y.
        let n = w.normals().unwrap()[0];
        assert!((n - Vector3::new(0.0, 1.0, 1.0).normalize_or_zero()).length() < 1e-12);
    }
}

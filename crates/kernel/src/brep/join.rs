//! Joining B-reps along coincident edges (Rhino's `Brep.JoinBreps`, Grasshopper's Brep Join).
//!
//! All faces of the input B-reps are put together; then every pair of *naked* edges (edges
//! used by one trim) that coincide within the tolerance becomes one edge used by both trims,
//! and the vertices at their ends become one vertex. Faces that end up connected through
//! shared edges form one B-rep of the result; unconnected groups stay separate B-reps, so the
//! result has as few B-reps as the edges allow.
//!
//! Two edges coincide when their ends match (in the same or in opposite directions) and seven
//! interior points of each lie within the tolerance of the other curve. Edges must match end to
//! end: an edge that runs along only part of another is not split to fit (Rhino would split it),
//! and two closed edges (full circles) join only if they start at the same point. A naked edge
//! that coincides with several others joins all of them into one non-manifold edge.
//!
//! Faces are then oriented consistently: across every joined edge the two faces must run along
//! the edge in opposite directions relative to their outward sides, and faces that do not are
//! flipped (their `reversed` flag), starting from the first face of each group. A group that
//! encloses a volume is finally turned outwards if its volume came out negative.

use crate::brep::{Brep, BrepEdge, BrepFace, BrepLoop, BrepTrim, BrepVertex};
use crate::{Error, NurbsCurve, Point3, Result};

/// The interior points compared along two edges.
const SAMPLES: usize = 7;

impl Brep {
    /// Joins B-reps where their naked edges coincide within `tolerance` (see the module
    /// documentation), giving one B-rep per connected group of faces, in the order of each
    /// group's first face. B-reps without faces are left out.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] for a negative or NaN tolerance, [`Error::NotFinite`] for a
    /// B-rep with a non-finite vertex, edge or surface.
    pub fn join(breps: &[Brep], tolerance: f64) -> Result<Vec<Brep>> {
        if !(tolerance >= 0.0 && tolerance.is_finite()) {
            return Err(Error::InvalidInput(format!(
                "the join tolerance must be finite and not negative, got {tolerance}"
            )));
        }
        for b in breps {
            let finite = b.vertices.iter().all(|v| v.point.is_finite())
                && b.edges.iter().all(|e| e.curve.is_finite())
                && b.faces.iter().all(|f| f.surface.is_finite());
            if !finite {
                return Err(Error::NotFinite { what: "brep" });
            }
        }
        let mut all = concatenate(breps.iter().filter(|b| !b.faces.is_empty()));
        all.merge_edges(tolerance);
        let components = all.face_components();
        let mut out = Vec::with_capacity(components.len());
        for faces in components {
            let mut part = all.subset(&faces);
            part.orient_faces();
            out.push(part);
        }
        Ok(out)
    }

    /// Merges the naked edges that coincide within `tolerance` and the vertices at their ends,
    /// then drops unused edges and vertices.
    fn merge_edges(&mut self, tolerance: f64) {
        let naked: Vec<usize> = (0..self.edges.len())
            .filter(|&e| self.edges[e].trims.len() == 1)
            .collect();
        let mut vertex_sets = UnionFind::new(self.vertices.len());
        // Where each edge went: itself, or the edge it was merged into.
        let mut target: Vec<usize> = (0..self.edges.len()).collect();
        let mut flip = vec![false; self.edges.len()];
        for (k, &i) in naked.iter().enumerate() {
            if target[i] != i {
                continue;
            }
            for &j in &naked[k + 1..] {
                if target[j] != j {
                    continue;
                }
                let (a, b) = (&self.edges[i], &self.edges[j]);
                let Some(reversed) = edges_coincide(&a.curve, &b.curve, tolerance) else {
                    continue;
                };
                target[j] = i;
                flip[j] = reversed;
                let (bi, bj) = (a.vertices, b.vertices);
                if reversed {
                    vertex_sets.union(bi[0], bj[1]);
                    vertex_sets.union(bi[1], bj[0]);
                } else {
                    vertex_sets.union(bi[0], bj[0]);
                    vertex_sets.union(bi[1], bj[1]);
                }
            }
        }
        for trim in &mut self.trims {
            if let Some(e) = trim.edge
                && target[e] != e
            {
                trim.reversed ^= flip[e];
                trim.edge = Some(target[e]);
            }
        }
        let roots: Vec<usize> = (0..self.vertices.len())
            .map(|v| vertex_sets.find(v))
            .collect();
        for trim in &mut self.trims {
            trim.vertices = trim.vertices.map(|v| roots[v]);
        }
        for edge in &mut self.edges {
            edge.vertices = edge.vertices.map(|v| roots[v]);
        }
        self.compact();
    }

    /// Removes the edges no trim uses and the vertices nothing uses, renumbering the rest.
    fn compact(&mut self) {
        let mut edge_used = vec![false; self.edges.len()];
        for t in &self.trims {
            if let Some(e) = t.edge {
                edge_used[e] = true;
            }
        }
        let edge_map = renumber(&edge_used);
        let old_edges = std::mem::take(&mut self.edges);
        self.edges = old_edges
            .into_iter()
            .zip(&edge_used)
            .filter_map(|(e, &used)| used.then_some(e))
            .collect();
        for t in &mut self.trims {
            t.edge = t.edge.and_then(|e| edge_map[e]);
        }
        let mut vertex_used = vec![false; self.vertices.len()];
        for t in &self.trims {
            for &v in &t.vertices {
                vertex_used[v] = true;
            }
        }
        for e in &self.edges {
            for &v in &e.vertices {
                vertex_used[v] = true;
            }
        }
        let vertex_map = renumber(&vertex_used);
        let old_vertices = std::mem::take(&mut self.vertices);
        self.vertices = old_vertices
            .into_iter()
            .zip(&vertex_used)
            .filter_map(|(v, &used)| used.then_some(v))
            .collect();
        let remap = |v: &mut usize| *v = vertex_map[*v].unwrap_or(0);
        for t in &mut self.trims {
            t.vertices.iter_mut().for_each(remap);
        }
        for e in &mut self.edges {
            e.vertices.iter_mut().for_each(remap);
        }
        self.link();
    }

    /// The groups of faces connected through shared edges, each in face order, the groups in
    /// the order of their first faces.
    fn face_components(&self) -> Vec<Vec<usize>> {
        let mut sets = UnionFind::new(self.faces.len());
        for e in &self.edges {
            let mut faces = e.trims.iter().map(|&t| self.face_of_trim(t));
            if let Some(first) = faces.next() {
                for f in faces {
                    sets.union(first, f);
                }
            }
        }
        let mut groups: Vec<(usize, Vec<usize>)> = Vec::new();
        for f in 0..self.faces.len() {
            let root = sets.find(f);
            match groups.iter_mut().find(|(r, _)| *r == root) {
                Some((_, g)) => g.push(f),
                None => groups.push((root, vec![f])),
            }
        }
        groups.into_iter().map(|(_, g)| g).collect()
    }

    fn face_of_trim(&self, t: usize) -> usize {
        self.loops[self.trims[t].loop_index].face
    }

    /// Flips faces so that neighbours agree on which side is outside (breadth first from the
    /// first face), then turns a closed B-rep outwards.
    fn orient_faces(&mut self) {
        let n = self.faces.len();
        let mut visited = vec![false; n];
        for start in 0..n {
            if visited[start] {
                continue;
            }
            visited[start] = true;
            let mut queue = std::collections::VecDeque::from([start]);
            while let Some(f) = queue.pop_front() {
                for &l in &self.faces[f].loops.clone() {
                    for &t in &self.loops[l].trims.clone() {
                        let Some(e) = self.trims[t].edge else {
                            continue;
                        };
                        let users = self.edges[e].trims.clone();
                        // Orientation across a non-manifold edge is not defined.
                        if users.len() != 2 {
                            continue;
                        }
                        let other = if users[0] == t { users[1] } else { users[0] };
                        let g = self.face_of_trim(other);
                        if g == f || visited[g] {
                            continue;
                        }
                        let direction = |b: &Brep, trim: usize, face: usize| {
                            b.trims[trim].reversed ^ b.faces[face].reversed
                        };
                        if direction(self, t, f) == direction(self, other, g) {
                            self.faces[g].reversed = !self.faces[g].reversed;
                        }
                        visited[g] = true;
                        queue.push_back(g);
                    }
                }
            }
        }
        if self.is_solid()
            && let Ok(v) = self.volume_properties()
            && v.volume < 0.0
        {
            for f in &mut self.faces {
                f.reversed = !f.reversed;
            }
        }
    }
}

/// All the parts of several B-reps in one, indices shifted.
pub(crate) fn concatenate<'a>(breps: impl Iterator<Item = &'a Brep>) -> Brep {
    let mut out = Brep::default();
    for b in breps {
        let (nf, nl, nt, ne, nv) = (
            out.faces.len(),
            out.loops.len(),
            out.trims.len(),
            out.edges.len(),
            out.vertices.len(),
        );
        out.faces.extend(b.faces.iter().map(|f| BrepFace {
            surface: f.surface.clone(),
            loops: f.loops.iter().map(|l| l + nl).collect(),
            reversed: f.reversed,
        }));
        out.loops.extend(b.loops.iter().map(|l| BrepLoop {
            face: l.face + nf,
            kind: l.kind,
            trims: l.trims.iter().map(|t| t + nt).collect(),
        }));
        out.trims.extend(b.trims.iter().map(|t| BrepTrim {
            curve: t.curve.clone(),
            edge: t.edge.map(|e| e + ne),
            reversed: t.reversed,
            kind: t.kind,
            loop_index: t.loop_index + nl,
            vertices: t.vertices.map(|v| v + nv),
        }));
        out.edges.extend(b.edges.iter().map(|e| BrepEdge {
            curve: e.curve.clone(),
            vertices: e.vertices.map(|v| v + nv),
            trims: Vec::new(),
        }));
        out.vertices.extend(b.vertices.iter().map(|v| BrepVertex {
            point: v.point,
            edges: Vec::new(),
        }));
    }
    out.link();
    out
}

/// New indices for the kept items, `None` for the dropped ones.
fn renumber(keep: &[bool]) -> Vec<Option<usize>> {
    let mut next = 0;
    keep.iter()
        .map(|&k| {
            k.then(|| {
                next += 1;
                next - 1
            })
        })
        .collect()
}

/// Whether two edge curves coincide within `tolerance`: `Some(false)` when they run the same
/// way, `Some(true)` when opposite, `None` when they do not coincide.
fn edges_coincide(a: &NurbsCurve, b: &NurbsCurve, tolerance: f64) -> Option<bool> {
    let near = |p: Point3, q: Point3| p.distance(q) <= tolerance;
    let (a0, a1, b0, b1) = (
        a.start_point(),
        a.end_point(),
        b.start_point(),
        b.end_point(),
    );
    let same = near(a0, b0) && near(a1, b1);
    let opposite = near(a0, b1) && near(a1, b0);
    let reversed = match (same, opposite) {
        (false, false) => return None,
        (true, false) => false,
        (false, true) => true,
        // Closed (or very short) edges: compare the directions at the start.
        (true, true) => {
            let ta = a.tangent_at(a.domain().t0)?;
            let tb = b.tangent_at(b.domain().t0)?;
            ta.dot(tb) < 0.0
        }
    };
    let within = |from: &NurbsCurve, to: &NurbsCurve| {
        let d = from.domain();
        (1..=SAMPLES).all(|k| {
            let p = from.point_at(d.parameter_at(k as f64 / (SAMPLES + 1) as f64));
            to.closest_point(p).is_ok_and(|c| c.distance <= tolerance)
        })
    };
    (within(a, b) && within(b, a)).then_some(reversed)
}

/// Disjoint sets of indices.
struct UnionFind {
    parent: Vec<usize>,
}

impl UnionFind {
    fn new(n: usize) -> Self {
        Self {
            parent: (0..n).collect(),
        }
    }

    fn find(&mut self, mut x: usize) -> usize {
        while self.parent[x] != x {
            self.parent[x] = self.parent[self.parent[x]];
            x = self.parent[x];
        }
        x
    }

    /// Joins the sets of `a` and `b`; the smaller root stays the root.
    fn union(&mut self, a: usize, b: usize) {
        let (ra, rb) = (self.find(a), self.find(b));
        if ra != rb {
            let (lo, hi) = (ra.min(rb), ra.max(rb));
            self.parent[hi] = lo;
        }
    }
}

#[cfg(test)]
mod tests {
    use proptest::prelude::*;

    use super::*;
    use crate::{Cylinder, EdgeKind, Interval, OrientedBox, Plane, Sphere, Transform, Vector3};

    fn faces_of(b: &Brep) -> Vec<Brep> {
        (0..b.faces().len())
            .map(|i| b.extract_face(i).unwrap())
            .collect()
    }

    fn sample_box(plane: Plane, size: [f64; 3]) -> Brep {
        Brep::from_box(&OrientedBox::new(
            plane,
            Interval::new(0.0, size[0]),
            Interval::new(0.0, size[1]),
            Interval::new(0.0, size[2]),
        ))
        .unwrap()
    }

    #[test]
    fn the_faces_of_a_box_join_into_the_box() {
        let b = sample_box(Plane::WORLD_XY, [2.0, 3.0, 4.0]);
        let joined = Brep::join(&faces_of(&b), 1e-9).unwrap();
        assert_eq!(joined.len(), 1);
        let j = &joined[0];
        assert_eq!(
            (j.faces().len(), j.edges().len(), j.vertices().len()),
            (6, 12, 8)
        );
        assert!(j.is_solid());
        assert!((j.volume().unwrap() - 24.0).abs() < 1e-12);
        assert_eq!(j.edges_of_kind(EdgeKind::Interior).len(), 12);
    }

    #[test]
    fn flipped_faces_are_turned_outwards() {
        let b = sample_box(Plane::WORLD_XY, [1.0, 1.0, 1.0]);
        let mut faces = faces_of(&b);
        // Flip the first face and two others: the join reorients them all outwards.
        for k in [0, 2, 5] {
            faces[k].faces[0].reversed = !faces[k].faces[0].reversed;
        }
        let j = Brep::join(&faces, 1e-9).unwrap().remove(0);
        assert!((j.volume().unwrap() - 1.0).abs() < 1e-12);
        assert!(
            j.faces()
                .iter()
                .zip(b.faces())
                .all(|(a, b)| a.reversed == b.reversed)
        );
    }

    #[test]
    fn separate_pieces_stay_separate() {
        let a = sample_box(Plane::WORLD_XY, [1.0, 1.0, 1.0]);
        let far = Plane::WORLD_XY.translated(Vector3::new(5.0, 0.0, 0.0));
        let b = sample_box(far, [1.0, 1.0, 1.0]);
        let mut faces = faces_of(&a);
        faces.extend(faces_of(&b));
        faces.pop();
        let joined = Brep::join(&faces, 1e-9).unwrap();
        assert_eq!(joined.len(), 2);
        assert!(joined[0].is_solid());
        assert!(!joined[1].is_solid());
        assert_eq!(joined[1].faces().len(), 5);
        assert_eq!(joined[1].edges_of_kind(EdgeKind::Naked).len(), 4);
        // Nothing joins at a tolerance too small to bridge a gap of 1e-6.
        let gap = Transform::translation(Vector3::new(1e-6, 0.0, 0.0));
        let moved = faces_of(&a)[1].transformed(&gap).unwrap();
        let mut faces = faces_of(&a);
        faces[1] = moved;
        let joined = Brep::join(&faces, 1e-9).unwrap();
        assert_eq!(joined.len(), 2);
        let joined = Brep::join(&faces, 1e-5).unwrap();
        assert_eq!(joined.len(), 1);
        assert!(joined[0].is_solid());
    }

    #[test]
    fn cylinder_parts_join_and_a_sphere_stays_whole() {
        let cyl =
            Brep::from_cylinder(&Cylinder::new(Plane::WORLD_XY, 1.0, 2.0).unwrap(), true).unwrap();
        let j = Brep::join(&faces_of(&cyl), 1e-9).unwrap();
        assert_eq!(j.len(), 1);
        assert_eq!((j[0].edges().len(), j[0].vertices().len()), (3, 2));
        assert!(j[0].is_solid());
        let v = j[0].volume().unwrap();
        assert!((v - 2.0 * std::f64::consts::PI).abs() < 1e-9, "{v}");
        let sphere = Brep::from_sphere(&Sphere::new(Point3::ORIGIN, 1.0).unwrap()).unwrap();
        let j = Brep::join(std::slice::from_ref(&sphere), 1e-9).unwrap();
        assert_eq!(j, vec![sphere]);
    }

    #[test]
    fn three_faces_on_one_edge_make_it_non_manifold() {
        let b = sample_box(Plane::WORLD_XY, [1.0, 1.0, 1.0]);
        let faces = faces_of(&b);
        // Faces 0 (front, y = 0) and 4 (bottom, z = 0) share the edge 0-1; a copy of the
        // front face mirrored below the bottom shares it too.
        let mirror = Transform::mirror(&Plane::WORLD_XY);
        let below = faces[0].transformed(&mirror).unwrap();
        let joined = Brep::join(&[faces[0].clone(), faces[4].clone(), below], 1e-9).unwrap();
        assert_eq!(joined.len(), 1);
        assert_eq!(joined[0].edges_of_kind(EdgeKind::NonManifold).len(), 1);
    }

    #[test]
    fn bad_input() {
        let b = sample_box(Plane::WORLD_XY, [1.0, 1.0, 1.0]);
        assert!(Brep::join(std::slice::from_ref(&b), f64::NAN).is_err());
        assert!(Brep::join(std::slice::from_ref(&b), -1.0).is_err());
        assert_eq!(Brep::join(&[], 1e-9).unwrap(), Vec::<Brep>::new());
        assert_eq!(
            Brep::join(&[Brep::default()], 1e-9).unwrap(),
            Vec::<Brep>::new()
        );
        let mut nan = b.clone();
        nan.vertices[0].point.x = f64::NAN;
        assert!(matches!(
            Brep::join(&[nan], 1e-9),
            Err(Error::NotFinite { .. })
        ));
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(32))]

        /// The faces of any box, in any order, moved by any rigid motion, join back into a
        /// closed B-rep of the box's volume with the box's topology.
        #[test]
        fn exploded_boxes_join_back(
            sx in 0.1f64..10.0, sy in 0.1f64..10.0, sz in 0.1f64..10.0,
            nx in -1.0f64..1.0, ny in -1.0f64..1.0, nz in 0.1f64..1.0,
            ox in -50.0f64..50.0, oy in -50.0f64..50.0, oz in -50.0f64..50.0,
            order in Just((0..6usize).collect::<Vec<_>>()).prop_shuffle(),
            flips in proptest::collection::vec(any::<bool>(), 6),
        ) {
            let plane = Plane::from_normal(Point3::new(ox, oy, oz), Vector3::new(nx, ny, nz))
                .unwrap();
            let b = sample_box(plane, [sx, sy, sz]);
            let faces = faces_of(&b);
            let mut shuffled: Vec<Brep> = order.iter().map(|&k| faces[k].clone()).collect();
            for (f, flip) in shuffled.iter_mut().zip(&flips) {
                if *flip {
                    f.faces[0].reversed = !f.faces[0].reversed;
                }
            }
            let joined = Brep::join(&shuffled, 1e-9).unwrap();
            prop_assert_eq!(joined.len(), 1);
            let j = &joined[0];
            prop_assert!(j.is_solid());
            prop_assert_eq!((j.faces().len(), j.edges().len(), j.vertices().len()), (6, 12, 8));
            let v = j.volume().unwrap();
            prop_assert!((v - sx * sy * sz).abs() <= 1e-9 * (sx * sy * sz).max(1.0), "{}", v);
            let a = j.area().unwrap();
            prop_assert!((a - b.area().unwrap()).abs() <= 1e-9 * a);
        }

        /// Joining never loses or invents faces, whatever pieces come in.
        #[test]
        fn joining_keeps_every_face(take in proptest::collection::vec(0..6usize, 0..10)) {
            let b = sample_box(Plane::WORLD_XY, [1.0, 2.0, 3.0]);
            let faces = faces_of(&b);
            let pieces: Vec<Brep> = take.iter().map(|&k| faces[k].clone()).collect();
            let joined = Brep::join(&pieces, 1e-9).unwrap();
            let count: usize = joined.iter().map(|j| j.faces().len()).sum();
            prop_assert_eq!(count, pieces.len());
        }
    }
}

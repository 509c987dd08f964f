//! A mesh's topological edges (Rhino's `Mesh.TopologyEdges`): vertices at the same point are
//! one topological vertex (as Rhino's topology vertices), and each edge is counted with the
//! faces that use it.

use std::collections::HashMap;

use crate::{Line, Mesh};

/// One topological edge of a mesh: its line and the number of faces that use it (1 naked, 2
/// interior, more non-manifold).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MeshEdge {
    /// The edge, from the corner where the first face that uses it meets it first.
    pub line: Line,
    /// The number of faces that use the edge.
    pub valence: usize,
}

impl Mesh {
    /// The topological edges, in the order the faces first use them (faces in order, each
    /// from its first corner round). Vertices at identical coordinates are one topological
    /// vertex, so an unwelded mesh has the same edges as the welded one. A face's degenerate
    /// side (both ends at one point) is no edge.
    pub fn topology_edges(&self) -> Vec<MeshEdge> {
        let mut vertex_ids: HashMap<[u64; 3], usize> = HashMap::new();
        let topo: Vec<usize> = self
            .vertices()
            .iter()
            .map(|p| {
                // +0.0 and −0.0 are one point.
                let key = [p.x + 0.0, p.y + 0.0, p.z + 0.0].map(f64::to_bits);
                let next = vertex_ids.len();
                *vertex_ids.entry(key).or_insert(next)
            })
            .collect();
        let mut index: HashMap<(usize, usize), usize> = HashMap::new();
        let mut edges: Vec<MeshEdge> = Vec::new();
        for face in self.faces() {
            let c = face.corners();
            for i in 0..c.len() {
                let (a, b) = (c[i] as usize, c[(i + 1) % c.len()] as usize);
                let (ta, tb) = (topo[a], topo[b]);
                if ta == tb {
                    continue;
                }
                let key = (ta.min(tb), ta.max(tb));
                match index.get(&key) {
                    Some(&k) => edges[k].valence += 1,
                    None => {
                        index.insert(key, edges.len());
                        let v = self.vertices();
                        edges.push(MeshEdge {
                            line: Line::new(v[a], v[b]),
                            valence: 1,
                        });
                    }
                }
            }
        }
        edges
    }
}

#[cfg(test)]
mod tests {
    use crate::{Mesh, MeshFace, Point3};

    fn p(x: f64, y: f64) -> Point3 {
        Point3::new(x, y, 0.0)
    }

    #[test]
    fn two_unwelded_quads_share_their_middle_edge() {
        // Two unit squares side by side, each with its own four vertices.
        let vertices = vec![
            p(0.0, 0.0),
            p(1.0, 0.0),
            p(1.0, 1.0),
            p(0.0, 1.0),
            p(1.0, 0.0),
            p(2.0, 0.0),
            p(2.0, 1.0),
            p(1.0, 1.0),
        ];
        let faces = vec![MeshFace::quad(0, 1, 2, 3), MeshFace::quad(4, 5, 6, 7)];
        let mesh = Mesh::new(vertices, faces).unwrap();
        let edges = mesh.topology_edges();
        assert_eq!(edges.len(), 7);
        let valences: Vec<usize> = edges.iter().map(|e| e.valence).collect();
        assert_eq!(valences, [1, 2, 1, 1, 1, 1, 1]);
        assert_eq!(edges[1].line.from, p(1.0, 0.0));
        assert_eq!(edges[1].line.to, p(1.0, 1.0));
    }

    #[test]
    fn three_triangles_on_one_edge_make_it_non_manifold() {
        let vertices = vec![
            Point3::new(0.0, 0.0, 0.0),
            Point3::new(1.0, 0.0, 0.0),
            Point3::new(0.5, 1.0, 0.0),
            Point3::new(0.5, -1.0, 0.0),
            Point3::new(0.5, 0.0, 1.0),
        ];
        let faces = vec![
            MeshFace::triangle(0, 1, 2),
            MeshFace::triangle(1, 0, 3),
            MeshFace::triangle(0, 1, 4),
        ];
        let edges = Mesh::new(vertices, faces).unwrap().topology_edges();
        assert_eq!(edges[0].valence, 3);
        assert_eq!(edges.len(), 7);
    }
}

//! The closest point on a mesh (Rhino's `Mesh.ClosestMeshPoint`): the face it lies on and its
//! barycentric weights on that face's corners, as openNURBS's `ON_MESH_POINT` holds them.
//!
//! Every triangle is tested (quads as their two triangles), so a query costs one pass over the
//! faces, or a search of the mesh's spatial index (`index.rs`) once the mesh is queried again;
//! the closest point of a triangle is found by Voronoi regions (Ericson, *Real-Time Collision
//! Detection*, 5.1.5).

use crate::{Mesh, Point3, Vector3};

/// The closest point of a mesh to a point.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MeshPoint {
    /// The point on the mesh.
    pub point: Point3,
    /// The index of the face it lies on.
    pub face: usize,
    /// The weights of the face's four corners (`vertices[0..4]` of the face; a triangle's
    /// fourth weight is 0), which sum to 1: `point = Σ t[k] · vertex[k]`.
    pub weights: [f64; 4],
    /// The distance from the query point.
    pub distance: f64,
}

impl Mesh {
    /// The point of the mesh closest to `point`; `None` for a mesh without faces. Ties go to
    /// the lower face index. Large meshes asked more than once are searched through their
    /// spatial index (`index.rs`), with the same answers.
    pub fn closest_point(&self, point: Point3) -> Option<MeshPoint> {
        if let Some(index) = self.face_index() {
            let (nearest, _) = index.nearest(point);
            let best = nearest.into_iter().min_by_key(|t| t.order())?;
            return Some(on_triangle(
                point,
                best.corners,
                best.face as usize,
                best.half,
            ));
        }
        let v = self.vertices();
        let mut best: Option<MeshPoint> = None;
        for (face_index, face) in self.faces().iter().enumerate() {
            for (half, corners) in face.triangles().enumerate() {
                let candidate = on_triangle(
                    point,
                    corners.map(|i| v[i as usize]),
                    face_index,
                    half as u8,
                );
                if best.is_none_or(|b| candidate.distance < b.distance) {
                    best = Some(candidate);
                }
            }
        }
        best
    }
}

/// The closest point to `point` of the triangle `half` (0: `a b c`, 1: a quad's `a c d`) of face
/// `face`, whose corners are `corners`.
fn on_triangle(point: Point3, corners: [Point3; 3], face: usize, half: u8) -> MeshPoint {
    let [p, q, r] = corners;
    let (on, w) = closest_on_triangle(point, p, q, r);
    let slots = if half == 0 { [0, 1, 2] } else { [0, 2, 3] };
    let mut weights = [0.0; 4];
    for (slot, weight) in slots.into_iter().zip(w) {
        weights[slot] += weight;
    }
    MeshPoint {
        point: on,
        face,
        weights,
        distance: on.distance(point),
    }
}

/// The point of triangle `a b c` closest to `p`, and its barycentric weights.
pub(super) fn closest_on_triangle(
    p: Point3,
    a: Point3,
    b: Point3,
    c: Point3,
) -> (Point3, [f64; 3]) {
    let (ab, ac, ap) = (b - a, c - a, p - a);
    let (d1, d2) = (ab.dot(ap), ac.dot(ap));
    if d1 <= 0.0 && d2 <= 0.0 {
        return (a, [1.0, 0.0, 0.0]);
    }
    let bp = p - b;
    let (d3, d4) = (ab.dot(bp), ac.dot(bp));
    if d3 >= 0.0 && d4 <= d3 {
        return (b, [0.0, 1.0, 0.0]);
    }
    let vc = d1 * d4 - d3 * d2;
    if vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0 {
        let t = d1 / (d1 - d3);
        return (a + ab * t, [1.0 - t, t, 0.0]);
    }
    let cp = p - c;
    let (d5, d6) = (ab.dot(cp), ac.dot(cp));
    if d6 >= 0.0 && d5 <= d6 {
        return (c, [0.0, 0.0, 1.0]);
    }
    let vb = d5 * d2 - d1 * d6;
    if vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0 {
        let t = d2 / (d2 - d6);
        return (a + ac * t, [1.0 - t, 0.0, t]);
    }
    let va = d3 * d6 - d5 * d4;
    if va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0 {
        let t = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        return (b + (c - b) * t, [0.0, 1.0 - t, t]);
    }
    let sum = va + vb + vc;
    if sum == 0.0 || !sum.is_finite() {
        // A triangle of zero area whose Voronoi tests all failed: its nearest corner.
        let corners = [a, b, c];
        let k = (0..3)
            .min_by(|&i, &j| p.distance(corners[i]).total_cmp(&p.distance(corners[j])))
            .unwrap_or(0);
        let mut w = [0.0; 3];
        w[k] = 1.0;
        return (corners[k], w);
    }
    let (v, w) = (vb / sum, vc / sum);
    let on: Vector3 = ab * v + ac * w;
    (a + on, [1.0 - v - w, v, w])
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::MeshFace;

    fn unit_square() -> Mesh {
        let p = |x: f64, y: f64| Point3::new(x, y, 0.0);
        Mesh::new(
            vec![p(0.0, 0.0), p(1.0, 0.0), p(1.0, 1.0), p(0.0, 1.0)],
            vec![MeshFace::quad(0, 1, 2, 3)],
        )
        .unwrap()
    }

    #[test]
    fn a_point_above_a_quad_projects_onto_it() {
        let m = unit_square();
        let r = m.closest_point(Point3::new(0.25, 0.75, 2.0)).unwrap();
        assert_eq!(r.point, Point3::new(0.25, 0.75, 0.0));
        assert_eq!(r.face, 0);
        assert_eq!(r.distance, 2.0);
        // (0.25, 0.75) is in the second triangle a c d = (0,0) (1,1) (0,1):
        // 0.25·c + 0.5·d + 0.25·a = (0.25, 0.75).
        assert_eq!(r.weights, [0.25, 0.0, 0.25, 0.5]);
    }

    #[test]
    fn points_beside_the_mesh_go_to_an_edge_or_a_corner() {
        let m = unit_square();
        let r = m.closest_point(Point3::new(2.0, 0.5, 0.0)).unwrap();
        assert_eq!(r.point, Point3::new(1.0, 0.5, 0.0));
        assert_eq!(r.distance, 1.0);
        let r = m.closest_point(Point3::new(-3.0, -4.0, 0.0)).unwrap();
        assert_eq!(r.point, Point3::ORIGIN);
        assert_eq!(r.distance, 5.0);
        assert_eq!(r.weights, [1.0, 0.0, 0.0, 0.0]);
        assert_eq!(Mesh::default().closest_point(Point3::ORIGIN), None);
    }
}

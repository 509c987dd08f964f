//! Meshes against rays and planes (Rhino's `Intersection.MeshRay` and `MeshPlane`).
//!
//! A ray hits the triangle nearest its start (Möller and Trumbore's test on every triangle, quads
//! as their two triangles, or on the triangles whose boxes the ray meets in the mesh's spatial
//! index once the mesh is queried again). A plane cuts each triangle whose vertices lie on both sides of it
//! in one segment, between two of its edges; segments that share an edge (the same two vertex
//! indices) or, across unwelded seams, an end point within the tolerance, are chained into
//! polylines, closed where the chain comes back to its start. A vertex exactly on the plane
//! counts as above it, so that a plane through vertices still cuts each triangle once and the
//! segments of neighbouring triangles meet.

use std::collections::HashMap;

use crate::{Mesh, Plane, Point3, Polyline, Vector3};

/// The nearest point where the ray from `start` along `direction` hits the mesh, with the ray
/// parameter (`start + t·direction`, `t ≥ 0`) and the index of the face hit; `None` on a miss
/// (or a ray without direction).
pub fn mesh_ray(mesh: &Mesh, start: Point3, direction: Vector3) -> Option<(f64, Point3, usize)> {
    if !start.is_finite() || !direction.is_finite() || direction.length_squared() == 0.0 {
        return None;
    }
    if let Some(index) = mesh.face_index() {
        let best = index
            .along_ray(start, direction)
            .filter_map(|t| {
                let [p0, p1, p2] = t.corners;
                ray_triangle(start, direction, p0, p1, p2).map(|hit| (hit, t.order()))
            })
            .min_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
        return best.map(|(t, (face, _))| (t, start + direction * t, face as usize));
    }
    let v = mesh.vertices();
    let mut best: Option<(f64, usize)> = None;
    for (index, face) in mesh.faces().iter().enumerate() {
        for [a, b, c] in face.triangles() {
            let (p0, p1, p2) = (v[a as usize], v[b as usize], v[c as usize]);
            if let Some(t) = ray_triangle(start, direction, p0, p1, p2)
                && best.is_none_or(|(bt, _)| t < bt)
            {
                best = Some((t, index));
            }
        }
    }
    best.map(|(t, index)| (t, start + direction * t, index))
}

/// Möller and Trumbore's ray–triangle test: the ray parameter `t ≥ 0` of the hit, inside the
/// triangle or on its border, or `None`.
fn ray_triangle(start: Point3, d: Vector3, p0: Point3, p1: Point3, p2: Point3) -> Option<f64> {
    let (e1, e2) = (p1 - p0, p2 - p0);
    let h = d.cross(e2);
    let det = e1.dot(h);
    let scale = e1.length() * e2.length() * d.length();
    if !det.is_finite() || det.abs() <= 1e-14 * scale {
        return None;
    }
    let inv = 1.0 / det;
    let s = start - p0;
    let u = inv * s.dot(h);
    if !(0.0..=1.0).contains(&u) {
        return None;
    }
    let q = s.cross(e1);
    let w = inv * d.dot(q);
    if w < 0.0 || u + w > 1.0 {
        return None;
    }
    let t = inv * e2.dot(q);
    (t >= 0.0 && t.is_finite()).then_some(t)
}

/// The polylines where `plane` cuts the mesh (see the module documentation); chains whose ends
/// are within `tolerance` are joined.
pub fn mesh_plane(mesh: &Mesh, plane: &Plane, tolerance: f64) -> Vec<Polyline> {
    let v = mesh.vertices();
    let above: Vec<bool> = v
        .iter()
        .map(|&p| (p - plane.origin).dot(plane.z_axis) >= 0.0)
        .collect();
    let distance = |i: u32| (v[i as usize] - plane.origin).dot(plane.z_axis);
    let crossing = |a: u32, b: u32| -> Point3 {
        let (da, db) = (distance(a), distance(b));
        let s = da / (da - db);
        v[a as usize] + (v[b as usize] - v[a as usize]) * s
    };
    // Each segment runs between two crossed edges, named by their sorted vertex indices.
    let mut segments: Vec<[(u32, u32); 2]> = Vec::new();
    let mut points: HashMap<(u32, u32), Point3> = HashMap::new();
    for face in mesh.faces() {
        for tri in face.triangles() {
            let mut ends = Vec::with_capacity(2);
            for k in 0..3 {
                let (a, b) = (tri[k], tri[(k + 1) % 3]);
                if above[a as usize] != above[b as usize] {
                    let key = (a.min(b), a.max(b));
                    points.entry(key).or_insert_with(|| crossing(key.0, key.1));
                    ends.push(key);
                }
            }
            if let [x, y] = ends[..]
                && x != y
            {
                segments.push([x, y]);
            }
        }
    }
    chain(&segments, &points, tolerance)
}

/// Chains segments (pairs of edge keys) into polylines: through shared keys first, then by end
/// points within `tolerance`.
fn chain(
    segments: &[[(u32, u32); 2]],
    points: &HashMap<(u32, u32), Point3>,
    tolerance: f64,
) -> Vec<Polyline> {
    let mut by_key: HashMap<(u32, u32), Vec<usize>> = HashMap::new();
    for (i, s) in segments.iter().enumerate() {
        for k in s {
            by_key.entry(*k).or_default().push(i);
        }
    }
    let mut used = vec![false; segments.len()];
    let mut chains: Vec<Vec<Point3>> = Vec::new();
    for first in 0..segments.len() {
        if used[first] {
            continue;
        }
        used[first] = true;
        let mut keys = std::collections::VecDeque::from(segments[first].to_vec());
        // Grow at the back, then at the front.
        for front in [false, true] {
            loop {
                let end = if front { keys[0] } else { keys[keys.len() - 1] };
                let next = by_key[&end].iter().copied().find(|&i| !used[i]);
                let Some(i) = next else { break };
                used[i] = true;
                let [x, y] = segments[i];
                let other = if x == end { y } else { x };
                if front {
                    keys.push_front(other);
                } else {
                    keys.push_back(other);
                }
            }
        }
        chains.push(keys.iter().map(|k| points[k]).collect());
    }
    join_by_distance(chains, tolerance)
        .into_iter()
        .filter_map(|pts| Polyline::new(pts).ok())
        .collect()
}

/// Joins chains whose ends meet within `tolerance` (across unwelded seams), and closes chains
/// whose ends meet.
fn join_by_distance(mut chains: Vec<Vec<Point3>>, tolerance: f64) -> Vec<Vec<Point3>> {
    let mut out: Vec<Vec<Point3>> = Vec::new();
    while let Some(mut current) = chains.pop() {
        loop {
            let (start, end) = (current[0], current[current.len() - 1]);
            if current.len() > 2 && start.distance(end) <= tolerance {
                let last = current.len() - 1;
                current[last] = start;
                break;
            }
            let found = chains.iter().position(|c| {
                let (s, e) = (c[0], c[c.len() - 1]);
                [s, e].iter().any(|q| q.distance(end) <= tolerance)
                    || [s, e].iter().any(|q| q.distance(start) <= tolerance)
            });
            let Some(i) = found else { break };
            let mut other = chains.swap_remove(i);
            let (s, e) = (other[0], other[other.len() - 1]);
            if s.distance(end) <= tolerance {
                current.extend(other.drain(1..));
            } else if e.distance(end) <= tolerance {
                other.reverse();
                current.extend(other.drain(1..));
            } else if e.distance(start) <= tolerance {
                other.extend(current.drain(1..));
                current = other;
            } else {
                other.reverse();
                other.extend(current.drain(1..));
                current = other;
            }
        }
        out.push(current);
    }
    out.reverse();
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{MeshingParameters, OrientedBox};

    fn unit_box() -> Mesh {
        let b = OrientedBox::new(
            Plane::WORLD_XY,
            crate::Interval::new(0.0, 1.0),
            crate::Interval::new(0.0, 1.0),
            crate::Interval::new(0.0, 1.0),
        );
        Mesh::from_brep(
            &crate::Brep::from_box(&b).unwrap(),
            &MeshingParameters::default(),
        )
        .unwrap()
    }

    #[test]
    fn a_ray_hits_the_nearest_face() {
        let m = unit_box();
        let (t, p, _) = mesh_ray(
            &m,
            Point3::new(0.25, 0.5, -2.0),
            Vector3::new(0.0, 0.0, 1.0),
        )
        .unwrap();
        assert!((t - 2.0).abs() < 1e-12 && p.distance(Point3::new(0.25, 0.5, 0.0)) < 1e-12);
        assert!(mesh_ray(&m, Point3::new(2.0, 2.0, -2.0), Vector3::new(0.0, 0.0, 1.0)).is_none());
        assert!(mesh_ray(&m, Point3::new(0.5, 0.5, 2.0), Vector3::new(0.0, 0.0, 1.0)).is_none());
        assert!(mesh_ray(&m, Point3::new(0.5, 0.5, 2.0), Vector3::ZERO).is_none());
    }

    #[test]
    fn a_plane_through_a_box_gives_one_closed_square() {
        let m = unit_box();
        let plane = Plane::WORLD_XY.translated(Vector3::new(0.0, 0.0, 0.3));
        let cuts = mesh_plane(&m, &plane, 1e-9);
        assert_eq!(cuts.len(), 1, "{cuts:?}");
        let pts = cuts[0].points();
        assert_eq!(pts.first(), pts.last());
        assert!(pts.iter().all(|p| (p.z - 0.3).abs() < 1e-12));
        assert!((cuts[0].length() - 4.0).abs() < 1e-12);
        let missed = Plane::WORLD_XY.translated(Vector3::new(0.0, 0.0, 3.0));
        assert!(mesh_plane(&m, &missed, 1e-9).is_empty());
    }
}

//! Binary STL export: the triangles of every mesh in the scene (STL holds nothing else; curves
//! and points are left out). Coordinates are written Z-up as they are, with facet normals from
//! the triangles' winding.

use locus_kernel::Vector3;

use crate::scene::Scene;

/// The scene's triangles as binary STL.
pub fn to_stl(scene: &Scene) -> Vec<u8> {
    let count = scene.triangle_count();
    let mut out = Vec::with_capacity(84 + 50 * count);
    let mut header = [0u8; 80];
    let text = b"binary STL written by locus";
    header[..text.len()].copy_from_slice(text);
    out.extend_from_slice(&header);
    out.extend_from_slice(&(count.min(u32::MAX as usize) as u32).to_le_bytes());
    for mesh in scene.objects.iter().filter_map(|o| o.mesh.as_ref()) {
        let v = mesh.vertices();
        for [a, b, c] in mesh.triangles() {
            let (p, q, r) = (v[a as usize], v[b as usize], v[c as usize]);
            let n = (q - p).cross(r - p).unitize().unwrap_or(Vector3::ZERO);
            for x in [n.x, n.y, n.z, p.x, p.y, p.z, q.x, q.y, q.z, r.x, r.y, r.z] {
                out.extend_from_slice(&(x as f32).to_le_bytes());
            }
            out.extend_from_slice(&[0, 0]);
        }
    }
    out
}

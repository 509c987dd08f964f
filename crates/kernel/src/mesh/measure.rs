//! Mass properties of meshes: area and volume centroids (Rhino's `AreaMassProperties` and
//! `VolumeMassProperties` of a mesh), summed over the triangles.

use crate::{Mesh, Point3, Vector3};

impl Mesh {
    /// The area centroid: the triangles' centroids weighted by their areas; `None` for a mesh
    /// of zero area.
    pub fn area_centroid(&self) -> Option<Point3> {
        let v = self.vertices();
        let o = self.bounding_box().center();
        let (mut total, mut sum) = (0.0, Vector3::ZERO);
        for [a, b, c] in self.triangles() {
            let [p, q, r] = [a, b, c].map(|i| v[i as usize] - o);
            let area = 0.5 * (q - p).cross(r - p).length();
            total += area;
            sum += (p + q + r) * (area / 3.0);
        }
        (total > 0.0).then(|| o + sum / total)
    }

    /// The volume centroid of a closed mesh: the signed tetrahedra from the bounding box's
    /// centre to each triangle, their centroids weighted by their volumes; `None` for a mesh
    /// enclosing no volume.
    pub fn volume_centroid(&self) -> Option<Point3> {
        let v = self.vertices();
        let o = self.bounding_box().center();
        let (mut total, mut sum) = (0.0, Vector3::ZERO);
        for [a, b, c] in self.triangles() {
            let [p, q, r] = [a, b, c].map(|i| v[i as usize] - o);
            let volume = p.dot(q.cross(r)) / 6.0;
            total += volume;
            sum += (p + q + r) * (volume / 4.0);
        }
        (total != 0.0 && total.is_finite()).then(|| o + sum / total)
    }
}

#[cfg(test)]
mod tests {
    use crate::{Brep, Interval, Mesh, MeshingParameters, OrientedBox, Plane, Point3};

    #[test]
    fn a_box_mesh_has_its_centre_as_both_centroids() {
        let b = OrientedBox::new(
            Plane::WORLD_XY,
            Interval::new(1.0, 3.0),
            Interval::new(0.0, 4.0),
            Interval::new(-1.0, 5.0),
        );
        let mesh =
            Mesh::from_brep(&Brep::from_box(&b).unwrap(), &MeshingParameters::default()).unwrap();
        let c = Point3::new(2.0, 2.0, 2.0);
        assert!(mesh.area_centroid().unwrap().distance(c) < 1e-12);
        assert!(mesh.volume_centroid().unwrap().distance(c) < 1e-12);
        assert_eq!(Mesh::default().area_centroid(), None);
        assert_eq!(Mesh::default().volume_centroid(), None);
    }
}

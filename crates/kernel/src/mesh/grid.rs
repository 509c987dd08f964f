//! Meshes of quads on a grid of points (Rhino's `Mesh.CreateFromPlane`, `CreateFromBox` and
//! `CreateFromSurface` with a fixed count of faces): the faces Grasshopper's Mesh Plane, Mesh
//! Box and Mesh Surface make.
//!
//! A grid of `columns × rows` faces has `(columns + 1) × (rows + 1)` vertices, numbered row by
//! row; face `(i, j)` is the quad `(i, j) (i+1, j) (i+1, j+1) (i, j+1)`, counter-clockwise seen
//! from the side its normal points to. Where two neighbouring corners of a quad coincide (a
//! sphere's pole, a cone's apex), the quad becomes a triangle; a quad with two such sides (it
//! has no area) is left out, so that a grid never holds a degenerate face.

use crate::geometry::tolerance::DEFAULT_TOLERANCE;
use crate::{Error, Mesh, MeshFace, Point3, Result};

use super::parameters::MAX_MESH_VERTICES;

/// The distance under which two corners of a grid quad count as one point (the quad becomes a
/// triangle): the kernel's [`DEFAULT_TOLERANCE`].
pub const GRID_COINCIDENT_DISTANCE: f64 = DEFAULT_TOLERANCE;

impl Mesh {
    /// A mesh of `columns × rows` quads on the grid of points `point(i, j)` for
    /// `i in 0..=columns`, `j in 0..=rows`.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] for a zero count or more than [`MAX_MESH_VERTICES`] vertices,
    /// [`Error::NotFinite`] for a point that is not finite.
    pub fn quad_grid(
        columns: usize,
        rows: usize,
        mut point: impl FnMut(usize, usize) -> Point3,
    ) -> Result<Self> {
        if columns == 0 || rows == 0 {
            return Err(Error::InvalidInput(format!(
                "a mesh grid needs at least one face each way, got {columns} × {rows}"
            )));
        }
        let count = (columns + 1)
            .checked_mul(rows + 1)
            .filter(|&n| n <= MAX_MESH_VERTICES);
        let Some(count) = count else {
            return Err(Error::InvalidInput(format!(
                "a mesh grid of {columns} × {rows} faces has more than {MAX_MESH_VERTICES} vertices"
            )));
        };
        let mut vertices = Vec::with_capacity(count);
        for j in 0..=rows {
            for i in 0..=columns {
                vertices.push(point(i, j));
            }
        }
        let index = |i: usize, j: usize| (j * (columns + 1) + i) as u32;
        let mut faces = Vec::with_capacity(columns * rows);
        for j in 0..rows {
            for i in 0..columns {
                let quad = [
                    index(i, j),
                    index(i + 1, j),
                    index(i + 1, j + 1),
                    index(i, j + 1),
                ];
                if let Some(face) = grid_face(&vertices, quad) {
                    faces.push(face);
                }
            }
        }
        Self::new(vertices, faces)
    }
}

/// The face of a grid quad: the quad, a triangle where one side has collapsed to a point, or
/// nothing when more than one side has.
fn grid_face(vertices: &[Point3], quad: [u32; 4]) -> Option<MeshFace> {
    let at = |k: usize| vertices[quad[k] as usize];
    let collapsed: Vec<usize> = (0..4)
        .filter(|&k| at(k).distance(at((k + 1) % 4)) <= GRID_COINCIDENT_DISTANCE)
        .collect();
    match collapsed[..] {
        [] => Some(MeshFace::quad(quad[0], quad[1], quad[2], quad[3])),
        [k] => {
            // Side k → k+1 is a point: drop corner k+1.
            let keep: Vec<u32> = (0..4)
                .filter(|&c| c != (k + 1) % 4)
                .map(|c| quad[c])
                .collect();
            Some(MeshFace::triangle(keep[0], keep[1], keep[2]))
        }
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_two_by_one_grid_has_six_vertices_and_two_quads() {
        let m = Mesh::quad_grid(2, 1, |i, j| Point3::new(i as f64, j as f64, 0.0)).unwrap();
        assert_eq!(m.vertices().len(), 6);
        // Vertices row by row: 0 1 2 on y = 0, 3 4 5 on y = 1.
        assert_eq!(
            m.faces(),
            &[MeshFace::quad(0, 1, 4, 3), MeshFace::quad(1, 2, 5, 4)]
        );
        assert_eq!(m.area(), 2.0);
        assert_eq!(m.face_normals()[0], Some(crate::Vector3::Z));
    }

    #[test]
    fn a_collapsed_side_makes_a_triangle_and_two_make_nothing() {
        // A fan: every point of row 1 is the apex (0, 0, 1).
        let m = Mesh::quad_grid(2, 1, |i, j| {
            if j == 1 {
                Point3::new(0.0, 0.0, 1.0)
            } else {
                Point3::new(i as f64, 0.0, 0.0)
            }
        })
        .unwrap();
        // Quad 0 1 4 3 with 4 = 3 drops corner 3 (the side 2 → 3 of the quad, 4 → 3).
        assert_eq!(
            m.faces(),
            &[MeshFace::triangle(0, 1, 4), MeshFace::triangle(1, 2, 5)]
        );
        // All four corners in one point: no face.
        let m = Mesh::quad_grid(1, 1, |_, _| Point3::ORIGIN).unwrap();
        assert!(m.faces().is_empty());
    }

    #[test]
    fn bad_grids_are_refused() {
        assert!(Mesh::quad_grid(0, 3, |_, _| Point3::ORIGIN).is_err());
        assert!(Mesh::quad_grid(1 << 20, 1 << 20, |_, _| Point3::ORIGIN).is_err());
        assert!(Mesh::quad_grid(1, 1, |_, _| Point3::new(f64::NAN, 0.0, 0.0)).is_err());
    }
}

//! 4×4 transformation matrices: the transformations of chapter 2 of the book, built the way
//! Rhino builds them (openNURBS `ON_Xform`), so that our matrices equal Rhino's entry for entry.
//!
//! A [`Transform`] acts on column vectors `[x, y, z, 1]` (points) and `[x, y, z, 0]`
//! (vectors, which therefore ignore translation). Composition follows the book: `a * b` applies
//! `b` first, so the master matrix of a sequence `M1, M2, M3, M4` is `M4 * M3 * M2 * M1`.
//!
//! | constructor | Rhino |
//! | --- | --- |
//! | [`Transform::translation`] | `Transform.Translation(v)` |
//! | [`Transform::rotation`] | `Transform.Rotation(angle, axis, center)` |
//! | [`Transform::rotation_sin_cos`] | `Transform.Rotation(sin, cos, axis, center)` |
//! | [`Transform::rotation_between`] | `Transform.Rotation(startDir, endDir, center)` |
//! | [`Transform::scale`] | `Transform.Scale(anchor, factor)` |
//! | [`Transform::scale_non_uniform`] | `Transform.Scale(plane, x, y, z)` |
//! | [`Transform::shear`] | `Transform.Shear(plane, x, y, z)` |
//! | [`Transform::mirror`], [`Transform::mirror_about`] | `Transform.Mirror(plane)`, `Mirror(point, normal)` |
//! | [`Transform::planar_projection`] | `Transform.PlanarProjection(plane)` |
//! | [`Transform::plane_to_plane`] | `Transform.PlaneToPlane(from, to)` (Grasshopper's *Orient*) |
//! | [`Transform::change_basis`] | `Transform.ChangeBasis(from, to)` |

mod apply;
mod constructors;
mod inverse;

use std::ops::Mul;

use glam::{DMat3, DMat4, DVec3, DVec4};

use crate::{BoundingBox, OrientedBox, Plane, Point3, Result, Vector3};

/// A 4×4 transformation matrix acting on column vectors `[x, y, z, 1]`, as in Rhino.
///
/// Composition follows the book: `a * b` applies `b` first, then `a`, so `M4 * M3 * M2 * M1`
/// applies `M1` first. Storage is glam's column-major [`DMat4`]; [`Transform::to_rows`] gives
/// the row-major array that Rhino prints, and [`Transform::from_rows`] reads one.
///
/// Constructors that can only fail on non-finite input (such as [`Transform::translation`])
/// return the matrix directly, and a NaN or infinite input shows as a non-finite matrix
/// ([`Transform::is_finite`]); constructors with geometric failure modes (a zero axis, a zero
/// normal) return a [`Result`] and also report non-finite input.
///
/// # Examples
/// The book's multiple-transformations tutorial: move the centre to the origin, rotate 45°
/// about z, scale by 0.2, move back, as one master matrix.
/// ```
/// use locus_kernel::{Point3, Transform, Vector3};
/// # fn main() -> locus_kernel::Result<()> {
/// let centre = Point3::new(3.0, 4.0, 5.0);
/// let m1 = Transform::translation(Point3::ORIGIN - centre);
/// let m2 = Transform::rotation(45f64.to_radians(), Vector3::Z, Point3::ORIGIN)?;
/// let m3 = Transform::scale(Point3::ORIGIN, 0.2);
/// let m4 = m1.inverse()?;
/// let master = m4 * m3 * m2 * m1;
/// assert!(master.transform_point(centre).abs_diff_eq(centre, 1e-15));
/// let rows = master.to_rows();
/// assert!((rows[0][3] - 3.14142135623731).abs() < 1e-14);
/// # Ok(())
/// # }
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Transform {
    /// The matrix.
    pub matrix: DMat4,
}

impl Default for Transform {
    fn default() -> Self {
        Self::IDENTITY
    }
}

impl Transform {
    /// The identity transform.
    pub const IDENTITY: Self = Self {
        matrix: DMat4::IDENTITY,
    };

    /// A transform whose every entry is NaN: what the infallible constructors return for a
    /// non-finite angle.
    const NAN: Self = Self { matrix: DMat4::NAN };

    /// The transform with the given glam matrix.
    #[inline]
    pub const fn from_matrix(matrix: DMat4) -> Self {
        Self { matrix }
    }

    /// A transform from a row-major 4×4 array (`rows[i][j]` is row `i`, column `j`).
    pub fn from_rows(rows: [[f64; 4]; 4]) -> Self {
        Self {
            matrix: DMat4::from_cols_array_2d(&rows).transpose(),
        }
    }

    /// The matrix as a row-major 4×4 array (`rows[i][j]` is row `i`, column `j`), as Rhino
    /// prints it.
    pub fn to_rows(&self) -> [[f64; 4]; 4] {
        self.matrix.transpose().to_cols_array_2d()
    }

    /// The translation by `v`: `[[1,0,0,x],[0,1,0,y],[0,0,1,z],[0,0,0,1]]`.
    #[inline]
    pub fn translation(v: Vector3) -> Self {
        Self {
            matrix: DMat4::from_translation(v.to_dvec3()),
        }
    }

    /// The affine transform with linear part `linear` (a 3×3 matrix) and translation `t`.
    fn from_linear_translation(linear: DMat3, t: DVec3) -> Self {
        Self {
            matrix: DMat4::from_mat3_translation(linear, t),
        }
    }

    /// The composition `self ∘ other`: `other` is applied first, then `self` (the same as
    /// `self * other`).
    #[inline]
    pub fn then_after(&self, other: &Self) -> Self {
        Self {
            matrix: self.matrix * other.matrix,
        }
    }

    /// The composition that applies `self` first, then `next` (the same as `next * self`).
    #[inline]
    pub fn then(&self, next: &Self) -> Self {
        next.then_after(self)
    }

    /// Applies the transform to a point.
    ///
    /// For projective matrices the result is divided by the homogeneous coordinate `w`; as
    /// Rhino, a point mapped to `w = 0` (to infinity) is returned undivided.
    #[inline]
    pub fn transform_point(&self, p: Point3) -> Point3 {
        let h = self.matrix * DVec4::new(p.x, p.y, p.z, 1.0);
        if h.w == 1.0 || h.w == 0.0 {
            Point3::new(h.x, h.y, h.z)
        } else {
            Point3::new(h.x / h.w, h.y / h.w, h.z / h.w)
        }
    }

    /// Applies the transform to a vector: the linear part only, no translation (as Rhino's
    /// `Vector3d.Transform`). Note that normals of surfaces transform differently (by the
    /// inverse transpose) under non-similarity transforms.
    #[inline]
    pub fn transform_vector(&self, v: Vector3) -> Vector3 {
        Vector3::from_dvec3(self.matrix.transform_vector3(v.to_dvec3()))
    }

    /// Applies the transform to every point of a slice, in place, without allocating.
    ///
    /// Affine transforms take a path without the homogeneous coordinate; the results are the
    /// same, bit for bit, as [`transform_point`](Self::transform_point)'s.
    pub fn transform_points(&self, points: &mut [Point3]) {
        if self.is_affine() {
            let m = &self.matrix;
            let (c0, c1, c2, c3) = (
                m.x_axis.truncate(),
                m.y_axis.truncate(),
                m.z_axis.truncate(),
                m.w_axis.truncate(),
            );
            for p in points {
                // The same order of operations as DMat4 * DVec4 with w = 1.
                *p = Point3::from_dvec3(c0 * p.x + c1 * p.y + c2 * p.z + c3);
            }
        } else {
            for p in points {
                *p = self.transform_point(*p);
            }
        }
    }

    /// Applies the transform to every vector of a slice, in place, without allocating.
    pub fn transform_vectors(&self, vectors: &mut [Vector3]) {
        for v in vectors {
            *v = self.transform_vector(*v);
        }
    }

    /// Applies the transform to a plane; see [`Plane::transformed`] for how the result is kept
    /// orthonormal.
    ///
    /// # Errors
    /// As [`Plane::transformed`].
    #[inline]
    pub fn transform_plane(&self, plane: &Plane) -> Result<Plane> {
        plane.transformed(self)
    }

    /// The bounding box of the transformed box: see [`BoundingBox::transformed`].
    #[inline]
    pub fn transform_bounding_box(&self, bbox: &BoundingBox) -> BoundingBox {
        bbox.transformed(self)
    }

    /// Applies the transform to an oriented box: see [`OrientedBox::transformed`].
    ///
    /// # Errors
    /// As [`OrientedBox::transformed`].
    #[inline]
    pub fn transform_oriented_box(&self, oriented_box: &OrientedBox) -> Result<OrientedBox> {
        oriented_box.transformed(self)
    }

    /// Whether every entry is finite.
    #[inline]
    pub fn is_finite(&self) -> bool {
        self.matrix.is_finite()
    }

    /// Whether the bottom row is exactly `[0, 0, 0, 1]`: the transform maps points to points
    /// without a perspective division (every transform built here except user matrices).
    #[inline]
    pub fn is_affine(&self) -> bool {
        let m = &self.matrix;
        m.x_axis.w == 0.0 && m.y_axis.w == 0.0 && m.z_axis.w == 0.0 && m.w_axis.w == 1.0
    }

    /// Whether every entry is within `tolerance` of the identity's (false when an entry is
    /// NaN), as Rhino's `IsIdentity(tolerance)`.
    pub fn is_identity(&self, tolerance: f64) -> bool {
        self.matrix
            .to_cols_array()
            .iter()
            .zip(DMat4::IDENTITY.to_cols_array())
            .all(|(a, b)| (a - b).abs() <= tolerance)
    }

    /// Whether the transform is a pure translation: affine, with a linear part within
    /// `tolerance` of the identity.
    pub fn is_translation(&self, tolerance: f64) -> bool {
        self.is_affine()
            && self.is_finite()
            && DMat3::from_mat4(self.matrix).abs_diff_eq(DMat3::IDENTITY, tolerance)
    }

    /// Whether the transform is a similarity: affine, with a linear part that is a rotation or
    /// a mirror times a non-zero uniform scale, so that it preserves angles and maps circles
    /// to circles.
    ///
    /// The columns of the linear part must have lengths that agree to within `tolerance`
    /// relative to the largest, and must be perpendicular to within `tolerance` (the cosine of
    /// the angle between any two). Rhino's `IsSimilarity` makes the same test with fixed
    /// tolerances of 1e-4 and 1e-3.
    pub fn is_similarity(&self, tolerance: f64) -> bool {
        if !self.is_affine() || !self.is_finite() {
            return false;
        }
        let m = &self.matrix;
        let cols = [
            m.x_axis.truncate(),
            m.y_axis.truncate(),
            m.z_axis.truncate(),
        ];
        let lengths = cols.map(DVec3::length);
        let largest = lengths[0].max(lengths[1]).max(lengths[2]);
        if largest.is_nan() || largest <= 0.0 || lengths.contains(&0.0) {
            return false;
        }
        let same_length = lengths
            .iter()
            .all(|&l| (l - largest).abs() <= tolerance * largest);
        let perpendicular = (0..3).all(|i| {
            let j = (i + 1) % 3;
            (cols[i].dot(cols[j]) / (lengths[i] * lengths[j])).abs() <= tolerance
        });
        same_length && perpendicular
    }
}

impl Mul for Transform {
    type Output = Self;
    /// `a * b` applies `b` first, then `a`.
    #[inline]
    fn mul(self, rhs: Self) -> Self {
        self.then_after(&rhs)
    }
}

impl Mul<Point3> for Transform {
    type Output = Point3;
    /// Applies the transform to a point ([`Transform::transform_point`]).
    #[inline]
    fn mul(self, rhs: Point3) -> Point3 {
        self.transform_point(rhs)
    }
}

impl Mul<Vector3> for Transform {
    type Output = Vector3;
    /// Applies the linear part to a vector ([`Transform::transform_vector`]).
    #[inline]
    fn mul(self, rhs: Vector3) -> Vector3 {
        self.transform_vector(rhs)
    }
}
#[cfg(test)]
mod tests {
    use std::f64::consts::FRAC_PI_2;

    use super::*;

    #[test]
    fn rows_round_trip() {
        let rows = [
            [1.0, 2.0, 3.0, 4.0],
            [5.0, 6.0, 7.0, 8.0],
            [9.0, 10.0, 11.0, 12.0],
            [13.0, 14.0, 15.0, 16.0],
        ];
        let t = Transform::from_rows(rows);
        assert_eq!(t.to_rows(), rows);
        // Row 0, column 3 is the x translation.
        assert_eq!(t.matrix.w_axis.x, 4.0);
    }

    #[test]
    fn composition_order_follows_the_book() {
        let m1 = Transform::translation(Vector3::new(1.0, 0.0, 0.0));
        let m2 = Transform::rotation_z(FRAC_PI_2);
        let p = Point3::new(1.0, 0.0, 0.0);
        // Translate first, then rotate: (1,0,0) -> (2,0,0) -> (0,2,0).
        assert_eq!((m2 * m1).transform_point(p), Point3::new(0.0, 2.0, 0.0));
        assert_eq!(m1.then(&m2), m2 * m1);
        assert_eq!(m2.then_after(&m1), m2 * m1);
        assert_eq!(m2 * m1 * p, Point3::new(0.0, 2.0, 0.0));
        assert_eq!(m2 * m1 * Vector3::X, Vector3::Y);
    }

    #[test]
    fn predicates() {
        let t = Transform::translation(Vector3::new(1.0, 2.0, 3.0));
        assert!(t.is_translation(0.0) && t.is_affine() && t.is_similarity(0.0));
        assert!(!t.is_identity(1.0));
        assert!(Transform::IDENTITY.is_identity(0.0));
        assert!(!Transform::rotation_z(0.1).is_translation(1e-3));
        assert!(Transform::mirror(&Plane::WORLD_YZ).is_similarity(0.0));
        assert!(!Transform::planar_projection(&Plane::WORLD_XY).is_similarity(1e-3));
        assert_eq!(Transform::IDENTITY.determinant(), 1.0);
        let mut pts = [Point3::ORIGIN, Point3::new(1.0, 1.0, 1.0)];
        t.transform_points(&mut pts);
        // The affine path gives what transform_point gives, bit for bit.
        let r = Transform::rotation_z(0.3) * Transform::scale(Point3::new(0.1, 0.2, 0.3), 1.7) * t;
        let mut many: Vec<Point3> = (0..50)
            .map(|i| Point3::new(f64::from(i).sin() * 7.0, f64::from(i) * 0.37, -f64::from(i)))
            .collect();
        let expected: Vec<Point3> = many.iter().map(|&p| r.transform_point(p)).collect();
        r.transform_points(&mut many);
        assert_eq!(many, expected);
        assert_eq!(
            pts,
            [Point3::new(1.0, 2.0, 3.0), Point3::new(2.0, 3.0, 4.0)]
        );
        let mut vs = [Vector3::X];
        t.transform_vectors(&mut vs);
        assert_eq!(vs, [Vector3::X]);
    }
}

//! Inverting transforms, with a scale-free singularity test.

use glam::{DMat3, DMat4, DVec3, DVec4};

use crate::geometry::tolerance::SINGULAR_TOLERANCE;
use crate::{Error, Result, Transform};

impl Transform {
    /// The inverse transform, such that `self * inverse` is the identity to rounding.
    ///
    /// A transform is singular when the volume spanned by its rows scaled to unit length, or
    /// by its columns if that is larger, is at most [`SINGULAR_TOLERANCE`] (1e-12); for affine
    /// transforms only the 3×3 linear part is measured, so translations never count, and
    /// rotations, mirrors, uniform scales of any size and non-uniform scales along the world
    /// axes are invertible. The measure follows what floating point can represent rather than
    /// the geometry alone: a scale by 1e-13 along the world z axis is the exact matrix
    /// `diag(1, 1, 1e-13)` and inverts exactly, while the same scale along an oblique axis
    /// leaves the factor only in the last digits of every entry, so its inverse would be wrong
    /// from the third digit, and it is reported as singular.
    ///
    /// The inverse is computed on that row- or column-normalized matrix and scaled back, so
    /// that tiny or huge scale factors invert without overflow; affine transforms invert as
    /// `[L⁻¹ | −L⁻¹ t]` and keep an exact `[0, 0, 0, 1]` bottom row. Rhino's `TryGetInverse`
    /// fails only for exactly singular matrices, and so "inverts" projections whose rounding
    /// left a determinant of 1e-17; we report those.
    ///
    /// # Errors
    /// [`Error::SingularTransform`] when the matrix has no inverse (a projection, a zero scale,
    /// rows that are dependent to within the tolerance) or its inverse is not representable
    /// in `f64`; [`Error::NotFinite`] when an entry is NaN or infinite.
    pub fn inverse(&self) -> Result<Self> {
        if !self.is_finite() {
            return Err(Error::NotFinite { what: "transform" });
        }
        let matrix = if self.is_affine() {
            let linear = DMat3::from_mat4(self.matrix);
            let linear_inverse = inverse3(linear).ok_or(Error::SingularTransform)?;
            let t = self.matrix.w_axis.truncate();
            DMat4::from_mat3_translation(linear_inverse, -(linear_inverse * t))
        } else {
            inverse4(self.matrix).ok_or(Error::SingularTransform)?
        };
        if !matrix.is_finite() {
            return Err(Error::SingularTransform);
        }
        Ok(Self { matrix })
    }

    /// The determinant of the 4×4 matrix.
    #[inline]
    pub fn determinant(&self) -> f64 {
        self.matrix.determinant()
    }

    /// The determinant of the 3×3 linear part: negative for transforms that reverse
    /// orientation (mirrors), the volume ratio for affine transforms.
    #[inline]
    pub fn linear_determinant(&self) -> f64 {
        DMat3::from_mat4(self.matrix).determinant()
    }
}

/// `v / |v|` and `|v|`, computed without overflow or underflow, or `None` for the zero vector.
fn unit_and_length3(v: DVec3) -> Option<(DVec3, f64)> {
    let largest = v.abs().max_element();
    if largest.is_nan() || largest <= 0.0 {
        return None;
    }
    let length = largest * (v / largest).length();
    Some((v / length, length))
}

/// As [`unit_and_length3`] for 4-vectors.
fn unit_and_length4(v: DVec4) -> Option<(DVec4, f64)> {
    let largest = v.abs().max_element();
    if largest.is_nan() || largest <= 0.0 {
        return None;
    }
    let length = largest * (v / largest).length();
    Some((v / length, length))
}

/// The inverse of a 3×3 matrix by the scheme of [`Transform::inverse`], or `None` when it is
/// singular to within [`SINGULAR_TOLERANCE`].
fn inverse3(m: DMat3) -> Option<DMat3> {
    // Column scaling: m = B·D with unit columns in B, so m⁻¹ = D⁻¹·B⁻¹.
    let cols = [m.x_axis, m.y_axis, m.z_axis].map(unit_and_length3);
    // Row scaling: m = D·B with unit rows in B, so m⁻¹ = B⁻¹·D⁻¹.
    let t = m.transpose();
    let rows = [t.x_axis, t.y_axis, t.z_axis].map(unit_and_length3);
    let [Some(c0), Some(c1), Some(c2)] = cols else {
        return None;
    };
    let [Some(r0), Some(r1), Some(r2)] = rows else {
        return None;
    };
    let by_cols = DMat3::from_cols(c0.0, c1.0, c2.0);
    let by_rows = DMat3::from_cols(r0.0, r1.0, r2.0).transpose();
    let det_cols = by_cols.determinant();
    let det_rows = by_rows.determinant();
    if det_cols.abs() >= det_rows.abs() {
        if det_cols.is_nan() || det_cols.abs() <= SINGULAR_TOLERANCE {
            return None;
        }
        // Scale row i of B⁻¹ by 1 / |column i|.
        let inv = by_cols.inverse().transpose();
        Some(DMat3::from_cols(inv.x_axis / c0.1, inv.y_axis / c1.1, inv.z_axis / c2.1).transpose())
    } else {
        if det_rows.is_nan() || det_rows.abs() <= SINGULAR_TOLERANCE {
            return None;
        }
        // Scale column j of B⁻¹ by 1 / |row j|.
        let inv = by_rows.inverse();
        Some(DMat3::from_cols(
            inv.x_axis / r0.1,
            inv.y_axis / r1.1,
            inv.z_axis / r2.1,
        ))
    }
}

/// The inverse of a 4×4 matrix by the scheme of [`Transform::inverse`], or `None` when it is
/// singular to within [`SINGULAR_TOLERANCE`].
fn inverse4(m: DMat4) -> Option<DMat4> {
    let cols = [m.x_axis, m.y_axis, m.z_axis, m.w_axis].map(unit_and_length4);
    let t = m.transpose();
    let rows = [t.x_axis, t.y_axis, t.z_axis, t.w_axis].map(unit_and_length4);
    let [Some(c0), Some(c1), Some(c2), Some(c3)] = cols else {
        return None;
    };
    let [Some(r0), Some(r1), Some(r2), Some(r3)] = rows else {
        return None;
    };
    let by_cols = DMat4::from_cols(c0.0, c1.0, c2.0, c3.0);
    let by_rows = DMat4::from_cols(r0.0, r1.0, r2.0, r3.0).transpose();
    let det_cols = by_cols.determinant();
    let det_rows = by_rows.determinant();
    if det_cols.abs() >= det_rows.abs() {
        if det_cols.is_nan() || det_cols.abs() <= SINGULAR_TOLERANCE {
            return None;
        }
        let inv = by_cols.inverse().transpose();
        Some(
            DMat4::from_cols(
                inv.x_axis / c0.1,
                inv.y_axis / c1.1,
                inv.z_axis / c2.1,
                inv.w_axis / c3.1,
            )
            .transpose(),
        )
    } else {
        if det_rows.is_nan() || det_rows.abs() <= SINGULAR_TOLERANCE {
            return None;
        }
        let inv = by_rows.inverse();
        Some(DMat4::from_cols(
            inv.x_axis / r0.1,
            inv.y_axis / r1.1,
            inv.z_axis / r2.1,
            inv.w_axis / r3.1,
        ))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Plane, Point3, Vector3};

    #[test]
    fn inverse_of_affine_transforms() {
        let t = Transform::rotation(
            0.4,
            Vector3::new(1.0, -1.0, 2.0),
            Point3::new(3.0, 1.0, 0.0),
        )
        .unwrap()
            * Transform::scale_non_uniform(&Plane::WORLD_YZ, 0.5, 3.0, 20.0)
            * Transform::translation(Vector3::new(10.0, -20.0, 5.0));
        let inv = t.inverse().unwrap();
        assert!(inv.is_affine());
        let p = Point3::new(0.3, -7.0, 2.0);
        let back = inv.transform_point(t.transform_point(p));
        assert!(back.abs_diff_eq(p, 1e-12), "{back:?}");
        assert!((inv * t).is_identity(1e-12));
        // Tiny and huge scales invert without overflow, even non-uniform ones along the axes.
        for f in [1e-200, 1e200] {
            let s = Transform::scale(Point3::ORIGIN, f).inverse().unwrap();
            assert_eq!(s.to_rows()[0][0], 1.0 / f);
            let flat = Transform::scale_non_uniform(&Plane::WORLD_XY, 1.0, f, 1.0);
            assert_eq!(flat.inverse().unwrap().to_rows()[1][1], 1.0 / f);
        }
        // A shear followed by a tiny scale: dependent columns, but rows that scale apart.
        let crushed_y = Transform::shear(
            &Plane::WORLD_XY,
            Vector3::X,
            Vector3::new(1.0, 1e-13, 0.0),
            Vector3::Z,
        );
        let inv = crushed_y.inverse().unwrap();
        assert!((crushed_y * inv).is_identity(1e-15));
    }

    #[test]
    fn large_translations_are_invertible() {
        // Regression: a determinant threshold relative to the largest entry to the fourth power
        // called every translation by 1000 or more singular.
        for d in [1e3, 1e9, 1e15] {
            let t = Transform::translation(Vector3::new(d, -d, 0.5 * d));
            let inv = t.inverse().unwrap();
            assert_eq!(inv, Transform::translation(Vector3::new(-d, d, -0.5 * d)));
        }
    }

    #[test]
    fn singular_transforms_have_no_inverse() {
        let plane =
            Plane::from_normal(Point3::new(1.0, 2.0, 3.0), Vector3::new(1.0, 1.0, 1.0)).unwrap();
        assert_eq!(
            Transform::planar_projection(&plane).inverse(),
            Err(Error::SingularTransform)
        );
        assert_eq!(
            Transform::scale(Point3::ORIGIN, 0.0).inverse(),
            Err(Error::SingularTransform)
        );
        // A scale by 1e-13 along an oblique axis keeps that factor only in the last digits of
        // the entries, so its inverse would be wrong in the third digit: it counts as singular.
        let oblique = Transform::scale_non_uniform(&plane, 1.0, 1.0, 1e-13);
        assert_eq!(oblique.inverse(), Err(Error::SingularTransform));
        // A scale by 1e-9 along the same axis still inverts.
        let mild = Transform::scale_non_uniform(&plane, 1.0, 1.0, 1e-9);
        assert!((mild * mild.inverse().unwrap()).is_identity(1e-6));
        // A strong but well-conditioned shear is fine.
        let sheared = Transform::shear(
            &Plane::WORLD_XY,
            Vector3::X,
            Vector3::new(1e3, 1.0, 0.0),
            Vector3::Z,
        );
        assert!((sheared * sheared.inverse().unwrap()).is_identity(1e-12));
        let mut nan = Transform::IDENTITY;
        nan.matrix.x_axis.y = f64::NAN;
        assert_eq!(nan.inverse(), Err(Error::NotFinite { what: "transform" }));
    }

    #[test]
    fn projective_points_and_inverse() {
        let p = Transform::from_rows([
            [1.0, 0.0, 0.0, 0.0],
            [0.0, 1.0, 0.0, 0.0],
            [0.0, 0.0, 1.0, 0.0],
            [0.0, 0.0, 0.5, 1.0],
        ]);
        assert!(!p.is_affine());
        assert_eq!(
            p.transform_point(Point3::new(2.0, 4.0, 2.0)),
            Point3::new(1.0, 2.0, 1.0)
        );
        // A point sent to infinity comes back undivided, as in Rhino.
        assert_eq!(
            p.transform_point(Point3::new(2.0, 4.0, -2.0)),
            Point3::new(2.0, 4.0, -2.0)
        );
        let inv = p.inverse().unwrap();
        assert!((p * inv).is_identity(1e-15));
    }
}

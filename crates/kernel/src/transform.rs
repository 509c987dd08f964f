//! 4×4 transformation matrices.

use glam::{DMat4, DVec4};

use crate::{Error, Point3, Result, Vector3};

/// A 4×4 transformation matrix acting on column vectors `[x, y, z, 1]`, as in Rhino.
///
/// Composition follows the book: `a * b` applies `b` first, then `a`, so `M4 * M3 * M2 * M1`
/// applies `M1` first. Storage is glam's column-major [`DMat4`]; [`Transform::to_rows`] gives
/// the row-major array that Rhino prints.
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

    /// A transform from a row-major 4×4 array (`rows[i][j]` is row `i`, column `j`).
    pub fn from_rows(rows: [[f64; 4]; 4]) -> Self {
        Self {
            matrix: DMat4::from_cols_array_2d(&rows).transpose(),
        }
    }

    /// The matrix as a row-major 4×4 array.
    pub fn to_rows(&self) -> [[f64; 4]; 4] {
        self.matrix.transpose().to_cols_array_2d()
    }

    /// The translation by `v`.
    pub fn translation(v: Vector3) -> Self {
        Self {
            matrix: DMat4::from_translation(v.to_dvec3()),
        }
    }

    /// The composition `self ∘ other`: `other` is applied first.
    #[inline]
    pub fn then_after(&self, other: &Self) -> Self {
        Self {
            matrix: self.matrix * other.matrix,
        }
    }

    /// Applies the transform to a point (with translation and, for projective matrices, the
    /// division by the homogeneous coordinate).
    #[inline]
    pub fn transform_point(&self, p: Point3) -> Point3 {
        let h = self.matrix * DVec4::new(p.x, p.y, p.z, 1.0);
        if h.w == 1.0 {
            Point3::new(h.x, h.y, h.z)
        } else {
            Point3::new(h.x / h.w, h.y / h.w, h.z / h.w)
        }
    }

    /// Applies the transform to a vector: the linear part only, no translation.
    #[inline]
    pub fn transform_vector(&self, v: Vector3) -> Vector3 {
        Vector3::from_dvec3(self.matrix.transform_vector3(v.to_dvec3()))
    }

    /// The inverse transform.
    ///
    /// # Errors
    /// [`Error::SingularTransform`] when the matrix has no inverse (a projection, a zero scale).
    pub fn inverse(&self) -> Result<Self> {
        let det = self.matrix.determinant();
        let scale = self
            .matrix
            .to_cols_array()
            .iter()
            .fold(0.0f64, |m, x| m.max(x.abs()));
        if !det.is_finite() || det.abs() <= 1e-12 * scale.powi(4).max(f64::MIN_POSITIVE) {
            return Err(Error::SingularTransform);
        }
        Ok(Self {
            matrix: self.matrix.inverse(),
        })
    }

    /// Whether every entry is finite.
    pub fn is_finite(&self) -> bool {
        self.matrix.is_finite()
    }
}

impl std::ops::Mul for Transform {
    type Output = Self;
    /// `a * b` applies `b` first, then `a`.
    fn mul(self, rhs: Self) -> Self {
        self.then_after(&rhs)
    }
}

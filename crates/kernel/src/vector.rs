//! Free vectors: directions and displacements, with no position.

use std::ops::{Add, AddAssign, Div, Mul, MulAssign, Neg, Sub, SubAssign};

use glam::DVec3;

use crate::tolerance::ZERO_TOLERANCE;

/// A free vector in 3-D space: a direction with a length, and no position.
///
/// Vectors and [`Point3`](crate::Point3) are distinct types because they transform differently
/// (a translation moves a point but not a vector) and because some operations make no geometric
/// sense for one of them: `Point3 + Point3` is not defined, `Point3 - Point3` is a `Vector3`.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Vector3 {
    /// The x component.
    pub x: f64,
    /// The y component.
    pub y: f64,
    /// The z component.
    pub z: f64,
}

impl Vector3 {
    /// The zero vector.
    pub const ZERO: Self = Self::new(0.0, 0.0, 0.0);
    /// The unit vector along the world x axis.
    pub const X: Self = Self::new(1.0, 0.0, 0.0);
    /// The unit vector along the world y axis.
    pub const Y: Self = Self::new(0.0, 1.0, 0.0);
    /// The unit vector along the world z axis.
    pub const Z: Self = Self::new(0.0, 0.0, 1.0);

    /// Creates a vector from its components.
    #[inline]
    pub const fn new(x: f64, y: f64, z: f64) -> Self {
        Self { x, y, z }
    }

    /// The vector as a glam vector.
    #[inline]
    pub const fn to_dvec3(self) -> DVec3 {
        DVec3::new(self.x, self.y, self.z)
    }

    /// The vector with the components of a glam vector.
    #[inline]
    pub const fn from_dvec3(v: DVec3) -> Self {
        Self::new(v.x, v.y, v.z)
    }

    /// The components as an array `[x, y, z]`.
    #[inline]
    pub const fn to_array(self) -> [f64; 3] {
        [self.x, self.y, self.z]
    }

    /// The Euclidean length `√(x² + y² + z²)`.
    #[inline]
    pub fn length(self) -> f64 {
        self.to_dvec3().length()
    }

    /// The squared length, cheaper than [`length`](Self::length).
    #[inline]
    pub fn length_squared(self) -> f64 {
        self.dot(self)
    }

    /// The dot product `a·b = |a||b|cos θ`.
    #[inline]
    pub fn dot(self, other: Self) -> f64 {
        self.x * other.x + self.y * other.y + self.z * other.z
    }

    /// The cross product `a×b`, perpendicular to both, with length `|a||b|sin θ`.
    #[inline]
    pub fn cross(self, other: Self) -> Self {
        Self::from_dvec3(self.to_dvec3().cross(other.to_dvec3()))
    }

    /// The unit vector in the same direction, or `None` when the length is zero
    /// (below [`ZERO_TOLERANCE`]) or not finite.
    #[inline]
    pub fn try_normalize(self) -> Option<Self> {
        let len = self.length();
        if len.is_finite() && len > ZERO_TOLERANCE {
            Some(self / len)
        } else {
            None
        }
    }

    /// Whether the length is within `tolerance` of one.
    #[inline]
    pub fn is_normalized(self, tolerance: f64) -> bool {
        (self.length() - 1.0).abs() <= tolerance
    }

    /// Whether every component is finite (neither NaN nor infinite).
    #[inline]
    pub fn is_finite(self) -> bool {
        self.x.is_finite() && self.y.is_finite() && self.z.is_finite()
    }

    /// Whether any component is NaN.
    #[inline]
    pub fn is_nan(self) -> bool {
        self.x.is_nan() || self.y.is_nan() || self.z.is_nan()
    }

    /// Whether the length is at most `tolerance`.
    #[inline]
    pub fn is_zero(self, tolerance: f64) -> bool {
        self.length() <= tolerance
    }
}

impl Add for Vector3 {
    type Output = Self;
    #[inline]
    fn add(self, rhs: Self) -> Self {
        Self::new(self.x + rhs.x, self.y + rhs.y, self.z + rhs.z)
    }
}

impl AddAssign for Vector3 {
    #[inline]
    fn add_assign(&mut self, rhs: Self) {
        *self = *self + rhs;
    }
}

impl Sub for Vector3 {
    type Output = Self;
    #[inline]
    fn sub(self, rhs: Self) -> Self {
        Self::new(self.x - rhs.x, self.y - rhs.y, self.z - rhs.z)
    }
}

impl SubAssign for Vector3 {
    #[inline]
    fn sub_assign(&mut self, rhs: Self) {
        *self = *self - rhs;
    }
}

impl Neg for Vector3 {
    type Output = Self;
    #[inline]
    fn neg(self) -> Self {
        Self::new(-self.x, -self.y, -self.z)
    }
}

impl Mul<f64> for Vector3 {
    type Output = Self;
    #[inline]
    fn mul(self, rhs: f64) -> Self {
        Self::new(self.x * rhs, self.y * rhs, self.z * rhs)
    }
}

impl Mul<Vector3> for f64 {
    type Output = Vector3;
    #[inline]
    fn mul(self, rhs: Vector3) -> Vector3 {
        rhs * self
    }
}

impl MulAssign<f64> for Vector3 {
    #[inline]
    fn mul_assign(&mut self, rhs: f64) {
        *self = *self * rhs;
    }
}

impl Div<f64> for Vector3 {
    type Output = Self;
    #[inline]
    fn div(self, rhs: f64) -> Self {
        Self::new(self.x / rhs, self.y / rhs, self.z / rhs)
    }
}

impl From<DVec3> for Vector3 {
    #[inline]
    fn from(v: DVec3) -> Self {
        Self::from_dvec3(v)
    }
}

impl From<Vector3> for DVec3 {
    #[inline]
    fn from(v: Vector3) -> Self {
        v.to_dvec3()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn book_vector_length_is_five() {
        assert_eq!(Vector3::new(4.0, 3.0, 0.0).length(), 5.0);
    }

    #[test]
    fn book_dot_product_is_38() {
        assert_eq!(
            Vector3::new(1.0, 2.0, 3.0).dot(Vector3::new(5.0, 6.0, 7.0)),
            38.0
        );
    }

    #[test]
    fn book_cross_product() {
        let c = Vector3::new(3.0, 1.0, 0.0).cross(Vector3::new(1.0, 2.0, 0.0));
        assert_eq!(c, Vector3::new(0.0, 0.0, 5.0));
    }

    #[test]
    fn zero_vector_does_not_normalize() {
        assert_eq!(Vector3::ZERO.try_normalize(), None);
        assert_eq!(Vector3::new(f64::NAN, 0.0, 1.0).try_normalize(), None);
    }
}

//! Points: locations in space.
//!
//! # Why points and vectors are distinct types
//!
//! The book insists: "Do not confuse vectors and points. [...] the North direction is a vector,
//! while the North Pole is a location." The kernel makes the distinction in the type system
//! with two structs, [`Point3`] and [`Vector3`], instead of using glam's `DVec3` for both.
//!
//! - **They transform differently.** A translation moves a point and leaves a vector alone;
//!   a projective transform divides a point by its homogeneous weight. With one type for both,
//!   every caller of a transform must remember which it holds;
//!   [`Transform::transform_point`](crate::Transform::transform_point) and
//!   [`Transform::transform_vector`](crate::Transform::transform_vector) take different types,
//!   so the compiler remembers.
//! - **The affine algebra is enforced.** `Point3 - Point3` is the `Vector3` between them,
//!   `Point3 ± Vector3` is a `Point3`, vectors add and scale freely. `Point3 + Point3` and
//!   `f64 * Point3` do not compile, because their result depends on where the origin is; the
//!   coordinate-free combinations are [`Point3::lerp`] (the book's `M = Q + t (P − Q)`) and
//!   [`Point3::midpoint`].
//! - **Grasshopper's ports are typed the same way.** Rhino and Grasshopper separate `Point3d`
//!   from `Vector3d`, so values crossing the runtime keep the meaning the user gave them.
//!
//! **Architecture Invariant:** kernel APIs take and return `Point3` for locations and `Vector3`
//! for directions and displacements, never a bare `DVec3`. Both are plain `Copy` structs of
//! three `f64` with the same layout, and convert to and from glam's `DVec3` for free
//! (`to_dvec3`, `from_dvec3`, `From`), so numeric kernels may drop to glam internally. The
//! explicit conversions [`Point3::to_vector`] and [`Point3::from_vector`] exist for the few
//! places where a position vector is meant.

use std::ops::{Add, AddAssign, Sub, SubAssign};

use glam::DVec3;

use crate::Vector3;

/// A location in 3-D space.
///
/// `Point3 - Point3` is the [`Vector3`] from the second point to the first;
/// `Point3 ± Vector3` is a point. Adding two points is not defined (see [`Vector3`]);
/// use [`Point3::lerp`] or [`Point3::midpoint`] for combinations of points.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Point3 {
    /// The x coordinate.
    pub x: f64,
    /// The y coordinate.
    pub y: f64,
    /// The z coordinate.
    pub z: f64,
}

impl Point3 {
    /// The world origin (0, 0, 0).
    pub const ORIGIN: Self = Self::new(0.0, 0.0, 0.0);

    /// Creates a point from its coordinates.
    #[inline]
    pub const fn new(x: f64, y: f64, z: f64) -> Self {
        Self { x, y, z }
    }

    /// The point as a glam vector (its position vector).
    #[inline]
    pub const fn to_dvec3(self) -> DVec3 {
        DVec3::new(self.x, self.y, self.z)
    }

    /// The point at the position vector `v`.
    #[inline]
    pub const fn from_dvec3(v: DVec3) -> Self {
        Self::new(v.x, v.y, v.z)
    }

    /// The coordinates as an array `[x, y, z]`.
    #[inline]
    pub const fn to_array(self) -> [f64; 3] {
        [self.x, self.y, self.z]
    }

    /// The point with the coordinates of an array `[x, y, z]`.
    #[inline]
    pub const fn from_array(a: [f64; 3]) -> Self {
        Self::new(a[0], a[1], a[2])
    }

    /// The position vector: the vector from the origin to this point.
    #[inline]
    pub const fn to_vector(self) -> Vector3 {
        Vector3::new(self.x, self.y, self.z)
    }

    /// The point whose position vector is `v`.
    #[inline]
    pub const fn from_vector(v: Vector3) -> Self {
        Self::new(v.x, v.y, v.z)
    }

    /// The distance to another point.
    #[inline]
    pub fn distance(self, other: Self) -> f64 {
        (self - other).length()
    }

    /// The squared distance to another point.
    #[inline]
    pub fn distance_squared(self, other: Self) -> f64 {
        (self - other).length_squared()
    }

    /// The point at `t` on the way from `self` to `other`: `self + t (other − self)`.
    ///
    /// `t = 0` gives `self`, `t = 1` gives `other`. The book writes the same point as
    /// `M = Q + t (P − Q)` with `Q = self` and `P = other`.
    #[inline]
    pub fn lerp(self, other: Self, t: f64) -> Self {
        self + (other - self) * t
    }

    /// The point halfway between two points.
    #[inline]
    pub fn midpoint(self, other: Self) -> Self {
        Self::new(
            0.5 * (self.x + other.x),
            0.5 * (self.y + other.y),
            0.5 * (self.z + other.z),
        )
    }

    /// Whether every coordinate is finite (neither NaN nor infinite).
    #[inline]
    pub fn is_finite(self) -> bool {
        self.x.is_finite() && self.y.is_finite() && self.z.is_finite()
    }

    /// Whether any coordinate is NaN.
    #[inline]
    pub fn is_nan(self) -> bool {
        self.x.is_nan() || self.y.is_nan() || self.z.is_nan()
    }

    /// Whether every coordinate differs from `other`'s by at most `max_abs_diff`.
    #[inline]
    pub fn abs_diff_eq(self, other: Self, max_abs_diff: f64) -> bool {
        (self.x - other.x).abs() <= max_abs_diff
            && (self.y - other.y).abs() <= max_abs_diff
            && (self.z - other.z).abs() <= max_abs_diff
    }
}

impl Sub for Point3 {
    type Output = Vector3;
    #[inline]
    fn sub(self, rhs: Self) -> Vector3 {
        Vector3::new(self.x - rhs.x, self.y - rhs.y, self.z - rhs.z)
    }
}

impl Add<Vector3> for Point3 {
    type Output = Self;
    #[inline]
    fn add(self, rhs: Vector3) -> Self {
        Self::new(self.x + rhs.x, self.y + rhs.y, self.z + rhs.z)
    }
}

impl AddAssign<Vector3> for Point3 {
    #[inline]
    fn add_assign(&mut self, rhs: Vector3) {
        *self = *self + rhs;
    }
}

impl Sub<Vector3> for Point3 {
    type Output = Self;
    #[inline]
    fn sub(self, rhs: Vector3) -> Self {
        Self::new(self.x - rhs.x, self.y - rhs.y, self.z - rhs.z)
    }
}

impl SubAssign<Vector3> for Point3 {
    #[inline]
    fn sub_assign(&mut self, rhs: Vector3) {
        *self = *self - rhs;
    }
}

impl From<DVec3> for Point3 {
    #[inline]
    fn from(v: DVec3) -> Self {
        Self::from_dvec3(v)
    }
}

impl From<Point3> for DVec3 {
    #[inline]
    fn from(p: Point3) -> Self {
        p.to_dvec3()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn book_point_moved_by_vector() {
        let p = Point3::new(2.0, 3.0, 1.0) + Vector3::new(2.0, 2.0, 2.0);
        assert_eq!(p, Point3::new(4.0, 5.0, 3.0));
    }

    #[test]
    fn book_tip_point_and_distance() {
        let a = Point3::new(1.0, 2.0, 3.0);
        let b = a + Vector3::new(5.0, 6.0, 7.0);
        assert_eq!(b, Point3::new(6.0, 8.0, 10.0));
        assert_eq!(b - a, Vector3::new(5.0, 6.0, 7.0));
        assert_eq!(a.distance(Point3::new(4.0, 6.0, 3.0)), 5.0);
        assert_eq!(a.distance_squared(Point3::new(4.0, 6.0, 3.0)), 25.0);
    }

    #[test]
    fn lerp_ends_and_middle() {
        let q = Point3::new(0.0, 0.0, 0.0);
        let p = Point3::new(2.0, 4.0, 6.0);
        assert_eq!(q.lerp(p, 0.0), q);
        assert_eq!(q.lerp(p, 1.0), p);
        assert_eq!(q.lerp(p, 0.5), Point3::new(1.0, 2.0, 3.0));
    }
}

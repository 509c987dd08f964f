//! Free vectors: directions and displacements, with no position.
//!
//! This module holds [`Vector3`] and the operations of chapter 1 of the book on it: length,
//! unit vector, scalar multiple, sum and difference, dot and cross products, the angle between
//! two vectors and the signed angle in a plane, the projection length of one vector onto
//! another, and the parallel and perpendicular tests ([`Parallelism`]).
//!
//! Why vectors and points are distinct types is explained in the [`point`](crate::Point3)
//! module.

use std::f64::consts::{PI, TAU};
use std::ops::{Add, AddAssign, Div, Mul, MulAssign, Neg, Sub, SubAssign};

use glam::DVec3;

use crate::geometry::tolerance::ZERO_TOLERANCE;
use crate::{Error, Result};

/// A free vector in 3-D space: a direction with a length, and no position.
///
/// Vectors and [`Point3`](crate::Point3) are distinct types because they transform differently
/// (a translation moves a point but not a vector) and because some operations make no geometric
/// sense for one of them: `Point3 + Point3` is not defined, `Point3 - Point3` is a `Vector3`.
///
/// A vector is *zero* for the kernel when its length is at most
/// [`ZERO_TOLERANCE`]; operations that need a direction ([`unitize`](Self::unitize),
/// [`angle_to`](Self::angle_to), ...) report such vectors as [`Error::ZeroLength`].
///
/// # Examples
/// ```
/// use locus_kernel::{Parallelism, Vector3};
/// let a = Vector3::new(3.0, 1.0, 0.0);
/// let b = Vector3::new(1.0, 2.0, 0.0);
/// assert_eq!(a.cross(b), Vector3::new(0.0, 0.0, 5.0));
/// let quarter = Vector3::X.signed_angle_to(Vector3::Y, Vector3::Z).unwrap();
/// assert!((quarter - std::f64::consts::FRAC_PI_2).abs() < 1e-15);
/// assert_eq!(a.parallelism(a * -2.0, 1e-12), Parallelism::Antiparallel);
/// assert!(Vector3::ZERO.unitize().is_err());
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Vector3 {
    /// The x component.
    pub x: f64,
    /// The y component.
    pub y: f64,
    /// The z component.
    pub z: f64,
}

/// How the directions of two vectors relate, as Rhino's `Vector3d.IsParallelTo` reports it.
///
/// Rhino returns `+1`, `-1` or `0`; [`Parallelism::to_sign`] gives the same numbers.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Parallelism {
    /// The vectors point the same way, within the angle tolerance (Rhino's `+1`).
    Parallel,
    /// The vectors point opposite ways, within the angle tolerance (Rhino's `-1`).
    Antiparallel,
    /// Neither, or at least one of the vectors has zero length (Rhino's `0`).
    NotParallel,
}

impl Parallelism {
    /// Rhino's integer for this relation: `+1` parallel, `-1` antiparallel, `0` neither.
    #[inline]
    pub const fn to_sign(self) -> i32 {
        match self {
            Self::Parallel => 1,
            Self::Antiparallel => -1,
            Self::NotParallel => 0,
        }
    }
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

    /// The vector with the components of an array `[x, y, z]`.
    #[inline]
    pub const fn from_array(a: [f64; 3]) -> Self {
        Self::new(a[0], a[1], a[2])
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

    /// The cross product `a×b`, perpendicular to both, with length `|a||b|sin θ`, oriented by
    /// the right-hand rule.
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

    /// The unit vector in the same direction (the book's *unit vector*, Rhino's `Unitize`).
    ///
    /// # Errors
    /// [`Error::NotFinite`] for a NaN or infinite component, [`Error::ZeroLength`] when the
    /// length is at most [`ZERO_TOLERANCE`].
    #[inline]
    pub fn unitize(self) -> Result<Self> {
        if !self.is_finite() {
            return Err(Error::NotFinite { what: "vector" });
        }
        self.try_normalize()
            .ok_or(Error::ZeroLength { what: "vector" })
    }

    /// The unit vector in the same direction, or the zero vector when there is none.
    #[inline]
    pub fn normalize_or_zero(self) -> Self {
        self.try_normalize().unwrap_or(Self::ZERO)
    }

    /// The vector with the same direction and the given length (Grasshopper's *Amplitude*).
    ///
    /// # Errors
    /// As [`unitize`](Self::unitize), and [`Error::NotFinite`] for a non-finite length.
    #[inline]
    pub fn with_length(self, length: f64) -> Result<Self> {
        if !length.is_finite() {
            return Err(Error::NotFinite { what: "length" });
        }
        Ok(self.unitize()? * length)
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

    /// Whether every component differs from `other`'s by at most `max_abs_diff`.
    #[inline]
    pub fn abs_diff_eq(self, other: Self, max_abs_diff: f64) -> bool {
        (self.x - other.x).abs() <= max_abs_diff
            && (self.y - other.y).abs() <= max_abs_diff
            && (self.z - other.z).abs() <= max_abs_diff
    }

    /// The unit vector of `self` for an operation that needs a direction, with the error that
    /// names the operand.
    fn direction(self, what: &'static str) -> Result<Self> {
        if !self.is_finite() {
            return Err(Error::NotFinite { what });
        }
        self.try_normalize().ok_or(Error::ZeroLength { what })
    }

    /// The angle between two vectors, from 0 to π radians.
    ///
    /// Computed as `atan2(|â×b̂|, â·b̂)` on the unit vectors, which stays accurate near 0 and π
    /// where `acos(â·b̂)` (the book's formula, and Rhino's `VectorAngle`) loses about half its
    /// digits; the two agree to about 1e-8 rad there and to rounding elsewhere.
    ///
    /// # Errors
    /// [`Error::ZeroLength`] if either vector has zero length, [`Error::NotFinite`] for NaN or
    /// infinite components.
    pub fn angle_to(self, other: Self) -> Result<f64> {
        let a = self.direction("vector")?;
        let b = other.direction("vector")?;
        Ok(a.cross(b).length().atan2(a.dot(b)))
    }

    /// The signed angle from `self` to `other` seen from the tip of `normal`, in (−π, π]
    /// radians: positive when the turn from `self` to `other` is counter-clockwise about
    /// `normal`.
    ///
    /// Both vectors are first projected onto the plane perpendicular to `normal`, as Rhino's
    /// `VectorAngle(a, b, plane)` does. [`angle_in_plane`](Self::angle_in_plane) gives the same
    /// angle in Rhino's range 0 to 2π.
    ///
    /// # Errors
    /// [`Error::ZeroLength`] if `normal` has zero length or either vector is parallel to it (its
    /// projection vanishes), [`Error::NotFinite`] for NaN or infinite components.
    pub fn signed_angle_to(self, other: Self, normal: Self) -> Result<f64> {
        let n = normal.direction("normal")?;
        if !self.is_finite() || !other.is_finite() {
            return Err(Error::NotFinite { what: "vector" });
        }
        let a = (self - n * self.dot(n)).direction("projected vector")?;
        let b = (other - n * other.dot(n)).direction("projected vector")?;
        let angle = a.cross(b).dot(n).atan2(a.dot(b));
        // atan2 returns −π for a negative zero sine; the half turn is reported as +π.
        Ok(if angle == -PI { PI } else { angle })
    }

    /// The angle from `self` to `other` measured counter-clockwise about `normal`, from 0 to
    /// 2π radians, as Rhino's `Vector3d.VectorAngle(a, b, plane)` returns it (Grasshopper's
    /// *Angle* with a plane, whose *Reflex* output is `2π` minus the angle).
    ///
    /// # Errors
    /// As [`signed_angle_to`](Self::signed_angle_to).
    pub fn angle_in_plane(self, other: Self, normal: Self) -> Result<f64> {
        let angle = self.signed_angle_to(other, normal)?;
        Ok(if angle < 0.0 { angle + TAU } else { angle })
    }

    /// The length of the projection of `self` onto the direction of `onto`: `a · unit(b)`,
    /// `|a| cos θ`. Negative when the vectors point away from each other.
    ///
    /// # Errors
    /// [`Error::ZeroLength`] if `onto` has zero length, [`Error::NotFinite`] for NaN or infinite
    /// components.
    pub fn projection_length_onto(self, onto: Self) -> Result<f64> {
        if !self.is_finite() {
            return Err(Error::NotFinite { what: "vector" });
        }
        Ok(self.dot(onto.direction("direction")?))
    }

    /// The vector projection of `self` onto the direction of `onto`: the component of `self`
    /// along `onto`.
    ///
    /// # Errors
    /// As [`projection_length_onto`](Self::projection_length_onto).
    pub fn projected_onto(self, onto: Self) -> Result<Self> {
        let u = onto.direction("direction")?;
        if !self.is_finite() {
            return Err(Error::NotFinite { what: "vector" });
        }
        Ok(u * self.dot(u))
    }

    /// How the directions of `self` and `other` relate, within `angle_tolerance` radians.
    ///
    /// The vectors are [`Parallelism::Parallel`] when the angle between them is at most
    /// `angle_tolerance` and [`Parallelism::Antiparallel`] when it is at least
    /// `π − angle_tolerance`. Zero-length or non-finite vectors are never parallel to anything
    /// (Rhino returns 0 for them too). The angle is computed as in
    /// [`angle_to`](Self::angle_to), so tolerances as small as 1e-15 rad are meaningful;
    /// Rhino compares cosines, which cannot tell angles below about 1e-8 rad from zero.
    pub fn parallelism(self, other: Self, angle_tolerance: f64) -> Parallelism {
        match self.angle_to(other) {
            Ok(angle) if angle <= angle_tolerance => Parallelism::Parallel,
            Ok(angle) if PI - angle <= angle_tolerance => Parallelism::Antiparallel,
            _ => Parallelism::NotParallel,
        }
    }

    /// Whether the vectors are parallel or antiparallel within `angle_tolerance` radians (see
    /// [`parallelism`](Self::parallelism)).
    #[inline]
    pub fn is_parallel_to(self, other: Self, angle_tolerance: f64) -> bool {
        self.parallelism(other, angle_tolerance) != Parallelism::NotParallel
    }

    /// Whether the angle between the vectors is within `angle_tolerance` radians of a right
    /// angle. Zero-length or non-finite vectors are not perpendicular to anything (as in Rhino).
    #[inline]
    pub fn is_perpendicular_to(self, other: Self, angle_tolerance: f64) -> bool {
        self.angle_to(other)
            .is_ok_and(|angle| (angle - 0.5 * PI).abs() <= angle_tolerance)
    }

    /// A unit vector perpendicular to `self`, chosen as Rhino chooses it (see
    /// [`perpendicular_to`](crate::perpendicular_to)), or `None` for a zero-length or
    /// non-finite vector.
    #[inline]
    pub fn perpendicular(self) -> Option<Self> {
        if !self.is_finite() {
            return None;
        }
        crate::perpendicular_to(self.try_normalize()?).try_normalize()
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
    fn book_unit_vector() {
        let b = Vector3::new(4.0, 3.0, 0.0).unitize().unwrap();
        assert!(b.abs_diff_eq(Vector3::new(0.8, 0.6, 0.0), 1e-16));
        assert_eq!(
            Vector3::ZERO.unitize(),
            Err(Error::ZeroLength { what: "vector" })
        );
        assert_eq!(
            Vector3::new(f64::INFINITY, 0.0, 0.0).unitize(),
            Err(Error::NotFinite { what: "vector" })
        );
    }

    #[test]
    fn angle_between_vectors_covers_zero_to_pi() {
        let x = Vector3::X;
        assert_eq!(x.angle_to(x * 3.0).unwrap(), 0.0);
        assert_eq!(x.angle_to(-x).unwrap(), PI);
        assert!((x.angle_to(Vector3::new(1.0, 1.0, 0.0)).unwrap() - PI / 4.0).abs() < 1e-15);
        assert!((x.angle_to(Vector3::new(-1.0, 0.0, 1.0)).unwrap() - 0.75 * PI).abs() < 1e-15);
        // Tiny angles keep their digits (acos would return 0 here).
        let tiny = x.angle_to(Vector3::new(1.0, 1e-12, 0.0)).unwrap();
        assert!((tiny - 1e-12).abs() < 1e-27);
        assert!(x.angle_to(Vector3::ZERO).is_err());
        assert!(x.angle_to(Vector3::new(f64::NAN, 0.0, 0.0)).is_err());
    }

    #[test]
    fn signed_angle_follows_the_normal() {
        let n = Vector3::Z;
        let a = Vector3::X;
        let b = Vector3::new(0.0, 2.0, 5.0); // projects onto +y
        assert!((a.signed_angle_to(b, n).unwrap() - PI / 2.0).abs() < 1e-15);
        assert!((b.signed_angle_to(a, n).unwrap() + PI / 2.0).abs() < 1e-15);
        assert!((b.angle_in_plane(a, n).unwrap() - 1.5 * PI).abs() < 1e-15);
        assert!((a.signed_angle_to(b, -n).unwrap() + PI / 2.0).abs() < 1e-15);
        assert_eq!(a.signed_angle_to(-a, n).unwrap(), PI);
        assert_eq!(a.signed_angle_to(a, n).unwrap(), 0.0);
        assert_eq!(a.angle_in_plane(a, n).unwrap(), 0.0);
        assert!(a.signed_angle_to(Vector3::Z, n).is_err());
        assert!(a.signed_angle_to(b, Vector3::ZERO).is_err());
    }

    #[test]
    fn projection_length() {
        let a = Vector3::new(5.0, 2.0, 0.0);
        assert_eq!(
            a.projection_length_onto(Vector3::new(9.0, 0.0, 0.0)),
            Ok(5.0)
        );
        assert_eq!(
            a.projection_length_onto(Vector3::new(-9.0, 0.0, 0.0)),
            Ok(-5.0)
        );
        assert_eq!(
            a.projected_onto(Vector3::new(0.0, 7.0, 0.0)),
            Ok(Vector3::new(0.0, 2.0, 0.0))
        );
        assert!(a.projection_length_onto(Vector3::ZERO).is_err());
    }

    #[test]
    fn parallel_and_perpendicular_with_tolerance() {
        let a = Vector3::new(1.0, 2.0, 3.0);
        assert_eq!(a.parallelism(a * 2.5, 1e-12), Parallelism::Parallel);
        assert_eq!(a.parallelism(a * -0.1, 1e-12), Parallelism::Antiparallel);
        assert_eq!(a.parallelism(a * -0.1, 1e-12).to_sign(), -1);
        let off = a + Vector3::new(0.0, 0.0, 1e-6);
        assert_eq!(a.parallelism(off, 1e-9), Parallelism::NotParallel);
        assert_eq!(a.parallelism(off, 1e-6), Parallelism::Parallel);
        assert_eq!(a.parallelism(Vector3::ZERO, 1.0), Parallelism::NotParallel);
        assert!(Vector3::X.is_perpendicular_to(Vector3::new(0.0, 3.0, -4.0), 1e-15));
        assert!(!Vector3::X.is_perpendicular_to(Vector3::new(1e-6, 3.0, -4.0), 1e-9));
        assert!(!Vector3::X.is_perpendicular_to(Vector3::ZERO, 1.0));
    }

    #[test]
    fn perpendicular_is_unit_and_orthogonal() {
        for v in [
            Vector3::X,
            Vector3::new(1.0, -2.0, 0.5),
            Vector3::new(0.0, 0.0, -3.0),
        ] {
            let p = v.perpendicular().unwrap();
            assert!(p.is_normalized(1e-15));
            assert!(p.dot(v).abs() < 1e-15);
        }
        assert_eq!(Vector3::ZERO.perpendicular(), None);
    }

    #[test]
    fn rotated_vector_and_amplitude() {
        let v = Vector3::X.rotated(PI / 2.0, Vector3::Z).unwrap();
        assert_eq!(v, Vector3::Y);
        let w = Vector3::new(3.0, 0.0, 4.0).with_length(10.0).unwrap();
        assert!(w.abs_diff_eq(Vector3::new(6.0, 0.0, 8.0), 1e-14));
        assert!(Vector3::X.rotated(1.0, Vector3::ZERO).is_err());
    }

    #[test]
    fn zero_vector_does_not_normalize() {
        assert_eq!(Vector3::ZERO.try_normalize(), None);
        assert_eq!(Vector3::new(f64::NAN, 0.0, 1.0).try_normalize(), None);
    }
}

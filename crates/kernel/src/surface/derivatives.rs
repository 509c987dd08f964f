//! The point and partial derivatives of a surface at one parameter pair.

use crate::{Point3, Vector3};

/// A surface point with its partial derivatives up to order 2 at a parameter pair `(u, v)`.
///
/// Derivatives that were not requested are zero.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct SurfaceDerivatives {
    /// The point `S(u, v)`.
    pub point: Point3,
    /// The first partial derivative `∂S/∂u`.
    pub du: Vector3,
    /// The first partial derivative `∂S/∂v`.
    pub dv: Vector3,
    /// The second partial derivative `∂²S/∂u²`.
    pub duu: Vector3,
    /// The mixed second partial derivative `∂²S/∂u∂v`.
    pub duv: Vector3,
    /// The second partial derivative `∂²S/∂v²`.
    pub dvv: Vector3,
}

impl SurfaceDerivatives {
    /// Whether the point and every derivative are finite.
    pub fn is_finite(&self) -> bool {
        self.point.is_finite()
            && self.du.is_finite()
            && self.dv.is_finite()
            && self.duu.is_finite()
            && self.duv.is_finite()
            && self.dvv.is_finite()
    }

    /// The cross product `Su × Sv`, whose direction is the surface normal where it is not zero.
    #[inline]
    pub fn normal_cross(&self) -> Vector3 {
        self.du.cross(self.dv)
    }

    /// The coefficients `(E, F, G) = (Su·Su, Su·Sv, Sv·Sv)` of the first fundamental form.
    #[inline]
    pub fn first_fundamental_form(&self) -> [f64; 3] {
        [
            self.du.dot(self.du),
            self.du.dot(self.dv),
            self.dv.dot(self.dv),
        ]
    }

    /// The coefficients `(L, M, N) = (Suu·n, Suv·n, Svv·n)` of the second fundamental form for
    /// the unit normal `n`.
    #[inline]
    pub fn second_fundamental_form(&self, normal: Vector3) -> [f64; 3] {
        [
            self.duu.dot(normal),
            self.duv.dot(normal),
            self.dvv.dot(normal),
        ]
    }
}

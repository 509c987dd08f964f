//! Planes: an origin with an orthonormal frame.

use crate::{Error, Point3, Result, Vector3};

/// A plane in 3-D space given by an origin and three orthonormal axes, right-handed
/// (`z_axis = x_axis × y_axis`), as in Rhino.
///
/// A plane doubles as a local coordinate system: the plane coordinates `(u, v, w)` of a point
/// `P` are its components along `x_axis`, `y_axis` and `z_axis` measured from the origin.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Plane {
    /// The origin of the plane.
    pub origin: Point3,
    /// The unit x axis, in the plane.
    pub x_axis: Vector3,
    /// The unit y axis, in the plane.
    pub y_axis: Vector3,
    /// The unit normal, `x_axis × y_axis`.
    pub z_axis: Vector3,
}

impl Default for Plane {
    fn default() -> Self {
        Self::WORLD_XY
    }
}

impl Plane {
    /// The world XY plane: origin (0,0,0), axes X, Y, normal Z.
    pub const WORLD_XY: Self = Self {
        origin: Point3::ORIGIN,
        x_axis: Vector3::X,
        y_axis: Vector3::Y,
        z_axis: Vector3::Z,
    };
    /// The world YZ plane: axes Y, Z, normal X.
    pub const WORLD_YZ: Self = Self {
        origin: Point3::ORIGIN,
        x_axis: Vector3::Y,
        y_axis: Vector3::Z,
        z_axis: Vector3::X,
    };
    /// The world ZX plane: axes Z, X, normal Y (Rhino's `WorldZX`).
    pub const WORLD_ZX: Self = Self {
        origin: Point3::ORIGIN,
        x_axis: Vector3::Z,
        y_axis: Vector3::X,
        z_axis: Vector3::Y,
    };

    /// A plane from an origin and two directions: `x_dir` gives the x axis, and the y axis is
    /// the part of `y_dir` perpendicular to it (Gram–Schmidt).
    ///
    /// # Errors
    /// [`Error::ZeroLength`] if `x_dir` has zero length, [`Error::Collinear`] if `y_dir` is
    /// parallel to it, [`Error::NotFinite`] for NaN or infinite input.
    pub fn from_frame(origin: Point3, x_dir: Vector3, y_dir: Vector3) -> Result<Self> {
        if !origin.is_finite() || !x_dir.is_finite() || !y_dir.is_finite() {
            return Err(Error::NotFinite { what: "plane" });
        }
        let x_axis = x_dir
            .try_normalize()
            .ok_or(Error::ZeroLength { what: "x axis" })?;
        let y_axis = (y_dir - x_axis * y_dir.dot(x_axis))
            .try_normalize()
            .ok_or(Error::Collinear)?;
        let z_axis = x_axis.cross(y_axis);
        Ok(Self {
            origin,
            x_axis,
            y_axis,
            z_axis,
        })
    }

    /// The plane through `origin` with normal `normal`, with Rhino's choice of x axis
    /// (`ON_Plane::CreateFromNormal`, which uses `ON_3dVector::PerpendicularTo`).
    ///
    /// # Errors
    /// [`Error::ZeroLength`] if the normal has zero length, [`Error::NotFinite`] for NaN input.
    pub fn from_normal(origin: Point3, normal: Vector3) -> Result<Self> {
        if !origin.is_finite() || !normal.is_finite() {
            return Err(Error::NotFinite { what: "plane" });
        }
        let z_axis = normal
            .try_normalize()
            .ok_or(Error::ZeroLength { what: "normal" })?;
        let x_axis = perpendicular_to(z_axis)
            .try_normalize()
            .ok_or(Error::ZeroLength { what: "normal" })?;
        let y_axis = z_axis.cross(x_axis);
        Ok(Self {
            origin,
            x_axis,
            y_axis,
            z_axis,
        })
    }

    /// The plane through three points: origin `a`, x axis towards `b`, and `c` on the positive
    /// y side (Rhino's Plane 3Pt).
    ///
    /// # Errors
    /// [`Error::Collinear`] when the three points lie on one line (or two coincide).
    pub fn from_points(a: Point3, b: Point3, c: Point3) -> Result<Self> {
        if !a.is_finite() || !b.is_finite() || !c.is_finite() {
            return Err(Error::NotFinite { what: "point" });
        }
        let x_dir = b - a;
        if x_dir.try_normalize().is_none() {
            return Err(Error::Collinear);
        }
        Self::from_frame(a, x_dir, c - a)
    }

    /// The normal of the plane (its z axis).
    #[inline]
    pub fn normal(&self) -> Vector3 {
        self.z_axis
    }

    /// The point at plane coordinates `(u, v)` (and `w` along the normal).
    #[inline]
    pub fn point_at(&self, u: f64, v: f64, w: f64) -> Point3 {
        self.origin + self.x_axis * u + self.y_axis * v + self.z_axis * w
    }

    /// The plane coordinates `(u, v, w)` of a point.
    #[inline]
    pub fn local_coordinates(&self, p: Point3) -> [f64; 3] {
        let d = p - self.origin;
        [d.dot(self.x_axis), d.dot(self.y_axis), d.dot(self.z_axis)]
    }

    /// The coefficients `[a, b, c, d]` of the plane's equation `a x + b y + c z + d = 0`,
    /// with `(a, b, c)` the unit normal.
    #[inline]
    pub fn equation(&self) -> [f64; 4] {
        let n = self.z_axis;
        [n.x, n.y, n.z, -n.dot(self.origin.to_vector())]
    }

    /// The signed distance from the plane to a point, positive on the side the normal points to.
    #[inline]
    pub fn signed_distance_to(&self, p: Point3) -> f64 {
        (p - self.origin).dot(self.z_axis)
    }

    /// The point of the plane closest to `p` (the foot of the perpendicular).
    #[inline]
    pub fn closest_point(&self, p: Point3) -> Point3 {
        p - self.z_axis * self.signed_distance_to(p)
    }

    /// Maps a point given in the coordinates of `self` to world coordinates, then expresses it
    /// in the coordinates of `target`: the point keeps its plane coordinates.
    #[inline]
    pub fn remap_to(&self, p: Point3, target: &Self) -> Point3 {
        let [u, v, w] = self.local_coordinates(p);
        target.point_at(u, v, w)
    }

    /// The same plane with the normal reversed (x and y swapped, as Rhino's `Flip`).
    #[inline]
    pub fn flipped(&self) -> Self {
        Self {
            origin: self.origin,
            x_axis: self.y_axis,
            y_axis: self.x_axis,
            z_axis: -self.z_axis,
        }
    }

    /// Whether origin and axes are finite.
    #[inline]
    pub fn is_finite(&self) -> bool {
        self.origin.is_finite()
            && self.x_axis.is_finite()
            && self.y_axis.is_finite()
            && self.z_axis.is_finite()
    }
}

/// A vector perpendicular to `v`, chosen as openNURBS's `ON_3dVector::PerpendicularTo` does.
///
/// The two largest components of `v` are swapped and one negated, which gives a stable,
/// non-zero perpendicular for every non-zero `v`.
pub fn perpendicular_to(v: Vector3) -> Vector3 {
    let ax = v.x.abs();
    let ay = v.y.abs();
    let az = v.z.abs();
    if ax <= az && ay <= az {
        // z is the largest component: rotate in the x/z or y/z plane.
        if ax > ay {
            Vector3::new(-v.z, 0.0, v.x)
        } else {
            Vector3::new(0.0, v.z, -v.y)
        }
    } else if ax <= ay {
        // y is the largest.
        if ax > az {
            Vector3::new(-v.y, v.x, 0.0)
        } else {
            Vector3::new(0.0, v.z, -v.y)
        }
    } else if ay > az {
        Vector3::new(-v.y, v.x, 0.0)
    } else {
        Vector3::new(-v.z, 0.0, v.x)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn three_collinear_points_are_an_error() {
        let a = Point3::new(0.0, 0.0, 0.0);
        let b = Point3::new(1.0, 1.0, 1.0);
        let c = Point3::new(2.0, 2.0, 2.0);
        assert_eq!(Plane::from_points(a, b, c), Err(Error::Collinear));
    }

    #[test]
    fn from_normal_gives_orthonormal_frame() {
        for n in [
            Vector3::Z,
            Vector3::X,
            Vector3::new(1.0, 2.0, 3.0),
            Vector3::new(0.0, -3.0, 0.1),
        ] {
            let p = Plane::from_normal(Point3::ORIGIN, n).unwrap();
            assert!((p.x_axis.length() - 1.0).abs() < 1e-15);
            assert!(p.x_axis.dot(p.y_axis).abs() < 1e-15);
            assert!((p.x_axis.cross(p.y_axis) - p.z_axis).length() < 1e-15);
        }
    }

    #[test]
    fn equation_and_distance() {
        let p = Plane::from_normal(Point3::new(0.0, 0.0, 2.0), Vector3::Z).unwrap();
        assert_eq!(p.equation(), [0.0, 0.0, 1.0, -2.0]);
        assert_eq!(p.signed_distance_to(Point3::new(5.0, 1.0, 5.0)), 3.0);
    }
}

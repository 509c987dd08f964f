//! Planes: an origin with an orthonormal frame.

use crate::geometry::tolerance::ZERO_TOLERANCE;
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
    /// the part of `y_dir` perpendicular to it (Gram–Schmidt), as Rhino's
    /// `ON_Plane::CreateFromFrame`.
    ///
    /// # Errors
    /// [`Error::ZeroLength`] if `x_dir` or `y_dir` has zero length, [`Error::Collinear`] if
    /// `y_dir` is parallel to `x_dir` (the sine of the angle between them is at most
    /// [`ZERO_TOLERANCE`], a scale-free test), [`Error::NotFinite`] for NaN or infinite input.
    pub fn from_frame(origin: Point3, x_dir: Vector3, y_dir: Vector3) -> Result<Self> {
        if !origin.is_finite() || !x_dir.is_finite() || !y_dir.is_finite() {
            return Err(Error::NotFinite { what: "plane" });
        }
        let x_axis = x_dir
            .try_normalize()
            .ok_or(Error::ZeroLength { what: "x axis" })?;
        let y_unit = y_dir
            .try_normalize()
            .ok_or(Error::ZeroLength { what: "y axis" })?;
        // Orthogonalize the unit y direction, so that the length of the remainder is the sine
        // of the angle between the two directions whatever their lengths.
        let y_perp = y_unit - x_axis * y_unit.dot(x_axis);
        let sine = y_perp.length();
        if sine <= ZERO_TOLERANCE {
            return Err(Error::Collinear);
        }
        let y_axis = y_perp / sine;
        let z_axis = x_axis.cross(y_axis);
        Ok(Self {
            origin,
            x_axis,
            y_axis,
            z_axis,
        })
    }

    /// The plane through `origin` with normal `normal`, with Rhino's choice of x axis
    /// (`ON_Plane::CreateFromNormal`): the x axis is [`perpendicular_to`] the unit normal, and
    /// `y = z × x`. A normal along +Z gives the world XY plane.
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
        // z and x are orthonormal, so the cross product is a unit vector up to rounding;
        // Rhino normalizes it again, and so do we to give the same digits.
        let y_axis = z_axis
            .cross(x_axis)
            .try_normalize()
            .ok_or(Error::ZeroLength { what: "normal" })?;
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
    /// [`Error::Collinear`] when the three points lie on one line or two of them coincide (the
    /// test is scale-free: the sine of the angle at `a` between `b` and `c` is at most
    /// [`ZERO_TOLERANCE`]), [`Error::NotFinite`] for NaN or infinite coordinates.
    pub fn from_points(a: Point3, b: Point3, c: Point3) -> Result<Self> {
        if !a.is_finite() || !b.is_finite() || !c.is_finite() {
            return Err(Error::NotFinite { what: "point" });
        }
        match Self::from_frame(a, b - a, c - a) {
            Err(Error::ZeroLength { .. }) => Err(Error::Collinear),
            res => res,
        }
    }

    /// The plane of the equation `a x + b y + c z + d = 0`, given as `[a, b, c, d]`, as Rhino's
    /// `ON_Plane::CreateFromEquation`: the origin is the point of the plane closest to the world
    /// origin and the axes are those of [`from_normal`](Self::from_normal) with normal
    /// `(a, b, c)`.
    ///
    /// # Errors
    /// [`Error::ZeroLength`] if `(a, b, c)` has zero length, [`Error::NotFinite`] for NaN or
    /// infinite coefficients.
    pub fn from_equation(equation: [f64; 4]) -> Result<Self> {
        if equation.iter().any(|e| !e.is_finite()) {
            return Err(Error::NotFinite {
                what: "plane equation",
            });
        }
        let [a, b, c, d] = equation;
        let n = Vector3::new(a, b, c);
        let len = n.length();
        if len <= ZERO_TOLERANCE {
            return Err(Error::ZeroLength { what: "normal" });
        }
        let unit = n / len;
        Self::from_normal(Point3::from_vector(unit * (-d / len)), n)
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

    /// The value of the plane's equation at `p`: the signed distance, since the normal is a
    /// unit vector.
    #[inline]
    pub fn value_at(&self, p: Point3) -> f64 {
        let [a, b, c, d] = self.equation();
        a * p.x + b * p.y + c * p.z + d
    }

    /// The signed distance from the plane to a point, positive on the side the normal points to.
    #[inline]
    pub fn signed_distance_to(&self, p: Point3) -> f64 {
        (p - self.origin).dot(self.z_axis)
    }

    /// The (unsigned) distance from the plane to a point.
    #[inline]
    pub fn distance_to(&self, p: Point3) -> f64 {
        self.signed_distance_to(p).abs()
    }

    /// The point of the plane closest to `p` (the foot of the perpendicular).
    #[inline]
    pub fn closest_point(&self, p: Point3) -> Point3 {
        p - self.z_axis * self.signed_distance_to(p)
    }

    /// The plane coordinates `(u, v)` of the point of the plane closest to `p`, so that
    /// `point_at(u, v, 0)` is [`closest_point`](Self::closest_point) (Rhino's
    /// `ClosestParameter`).
    #[inline]
    pub fn closest_parameter(&self, p: Point3) -> (f64, f64) {
        let d = p - self.origin;
        (d.dot(self.x_axis), d.dot(self.y_axis))
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

    /// The plane moved by `v`, with the same axes.
    #[inline]
    pub fn translated(&self, v: Vector3) -> Self {
        Self {
            origin: self.origin + v,
            ..*self
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

    /// Whether the plane is finite and its axes are orthonormal and right-handed, each to
    /// within [`ZERO_TOLERANCE`] (lengths, dot products, and `x × y − z`).
    pub fn is_valid(&self) -> bool {
        let tol = ZERO_TOLERANCE;
        self.is_finite()
            && self.x_axis.is_normalized(tol)
            && self.y_axis.is_normalized(tol)
            && self.z_axis.is_normalized(tol)
            && self.x_axis.dot(self.y_axis).abs() <= tol
            && self.y_axis.dot(self.z_axis).abs() <= tol
            && self.z_axis.dot(self.x_axis).abs() <= tol
            && (self.x_axis.cross(self.y_axis) - self.z_axis).length() <= tol
    }

    /// Whether origin and axes differ from `other`'s by at most `max_abs_diff` in every
    /// coordinate.
    pub fn abs_diff_eq(&self, other: &Self, max_abs_diff: f64) -> bool {
        self.origin.abs_diff_eq(other.origin, max_abs_diff)
            && self.x_axis.abs_diff_eq(other.x_axis, max_abs_diff)
            && self.y_axis.abs_diff_eq(other.y_axis, max_abs_diff)
            && self.z_axis.abs_diff_eq(other.z_axis, max_abs_diff)
    }
}

/// A vector perpendicular to `v`, chosen as openNURBS's `ON_3dVector::PerpendicularTo` chooses
/// it; Rhino builds the x axis of a plane from its normal with it.
///
/// The component of largest magnitude `v[i]` and the next largest `v[j]` are rotated a quarter
/// turn in their coordinate plane, `p[i] = −v[j]`, `p[j] = v[i]`, and the third component is
/// zero. Ties between magnitudes are broken exactly as openNURBS breaks them (the comments on
/// the branches give the orderings). For `v = Z` this gives `X`, so [`Plane::from_normal`] with
/// normal Z is the world XY plane.
///
/// The result is not normalized; its length is `√(v[i]² + v[j]²)`, at least `|v|·√(2/3)`, and
/// zero only for the zero vector.
pub fn perpendicular_to(v: Vector3) -> Vector3 {
    let ax = v.x.abs();
    let ay = v.y.abs();
    let az = v.z.abs();
    if ay > ax {
        if az > ay {
            // |z| > |y| > |x|: turn in the y/z plane.
            Vector3::new(0.0, v.z, -v.y)
        } else if az >= ax {
            // |y| ≥ |z| ≥ |x|: turn in the y/z plane, the other way.
            Vector3::new(0.0, -v.z, v.y)
        } else {
            // |y| > |x| > |z|: turn in the x/y plane.
            Vector3::new(v.y, -v.x, 0.0)
        }
    } else if az > ax {
        // |z| > |x| ≥ |y|: turn in the z/x plane.
        Vector3::new(v.z, 0.0, -v.x)
    } else if az > ay {
        // |x| ≥ |z| > |y|: turn in the z/x plane, the other way.
        Vector3::new(-v.z, 0.0, v.x)
    } else {
        // |x| ≥ |y| ≥ |z|: turn in the x/y plane.
        Vector3::new(-v.y, v.x, 0.0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Transform;

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
    fn perpendicular_to_matches_opennurbs_choices() {
        // One case per branch of ON_3dVector::PerpendicularTo, with the expected vector worked
        // out by hand from its rule (largest component i, next j: p[i] = -v[j], p[j] = v[i]).
        let cases = [
            (Vector3::new(1.0, 2.0, 3.0), Vector3::new(0.0, 3.0, -2.0)), // |z|>|y|>|x|
            (Vector3::new(1.0, 3.0, 2.0), Vector3::new(0.0, -2.0, 3.0)), // |y|>=|z|>=|x|
            (Vector3::new(2.0, 3.0, 1.0), Vector3::new(3.0, -2.0, 0.0)), // |y|>|x|>|z|
            (Vector3::new(2.0, 1.0, 3.0), Vector3::new(3.0, 0.0, -2.0)), // |z|>|x|>=|y|
            (Vector3::new(3.0, 1.0, 2.0), Vector3::new(-2.0, 0.0, 3.0)), // |x|>=|z|>|y|
            (Vector3::new(3.0, 2.0, 1.0), Vector3::new(-2.0, 3.0, 0.0)), // |x|>=|y|>=|z|
            (Vector3::Z, Vector3::X),
            (-Vector3::Z, -Vector3::X),
            (Vector3::X, Vector3::new(0.0, 1.0, 0.0)),
            (Vector3::Y, Vector3::new(0.0, 0.0, 1.0)),
            (Vector3::new(1.0, 1.0, 1.0), Vector3::new(-1.0, 1.0, 0.0)),
        ];
        for (v, expected) in cases {
            let p = perpendicular_to(v);
            assert_eq!(p, expected, "perpendicular to {v:?}");
            assert_eq!(p.dot(v), 0.0);
        }
    }

    #[test]
    fn from_normal_follows_rhino() {
        assert_eq!(
            Plane::from_normal(Point3::ORIGIN, Vector3::Z).unwrap(),
            Plane::WORLD_XY
        );
        let p = Plane::from_normal(Point3::ORIGIN, Vector3::X).unwrap();
        assert_eq!((p.x_axis, p.y_axis), (Vector3::Y, Vector3::Z));
        let p = Plane::from_normal(Point3::ORIGIN, Vector3::Y).unwrap();
        assert_eq!((p.x_axis, p.y_axis), (Vector3::Z, Vector3::X));
        let p = Plane::from_normal(Point3::ORIGIN, -Vector3::Z).unwrap();
        assert_eq!((p.x_axis, p.y_axis), (-Vector3::X, Vector3::Y));
        assert!(Plane::from_normal(Point3::ORIGIN, Vector3::ZERO).is_err());
        assert!(Plane::from_normal(Point3::new(f64::NAN, 0.0, 0.0), Vector3::Z).is_err());
    }

    #[test]
    fn three_points_make_the_book_normal() {
        let a = Point3::new(1.0, 0.0, 0.0);
        let b = Point3::new(0.0, 2.0, 0.0);
        let c = Point3::new(0.0, 0.0, 3.0);
        let p = Plane::from_points(a, b, c).unwrap();
        let n = ((b - a).cross(c - a)).unitize().unwrap();
        assert!(p.z_axis.abs_diff_eq(n, 1e-15));
        assert!(p.is_valid());
        assert_eq!(p.origin, a);
        assert!(p.value_at(b).abs() < 1e-15 && p.value_at(c).abs() < 1e-15);
        // Coincident points, and nearly collinear points far from the origin.
        assert_eq!(Plane::from_points(a, a, c), Err(Error::Collinear));
        assert_eq!(Plane::from_points(a, b, a), Err(Error::Collinear));
        let far = Point3::new(1e6, 0.0, 0.0);
        let nearly = Point3::new(2e6, 1e-6, 0.0);
        assert_eq!(
            Plane::from_points(Point3::ORIGIN, far, nearly),
            Err(Error::Collinear)
        );
    }

    #[test]
    fn plane_from_equation_round_trips() {
        let p = Plane::from_equation([0.0, 0.0, 2.0, -6.0]).unwrap();
        assert_eq!(p.origin, Point3::new(0.0, 0.0, 3.0));
        assert_eq!(p.z_axis, Vector3::Z);
        let q = Plane::from_points(
            Point3::new(1.0, 2.0, 3.0),
            Point3::new(-1.0, 0.5, 2.0),
            Point3::new(0.0, 4.0, -1.0),
        )
        .unwrap();
        let r = Plane::from_equation(q.equation()).unwrap();
        assert!(r.z_axis.abs_diff_eq(q.z_axis, 1e-15));
        assert!(r.distance_to(q.origin) < 1e-14);
        assert!(Plane::from_equation([0.0, 0.0, 0.0, 1.0]).is_err());
    }

    #[test]
    fn closest_point_and_remap() {
        let p = Plane::from_frame(
            Point3::new(1.0, 1.0, 1.0),
            Vector3::new(1.0, 1.0, 0.0),
            Vector3::new(-1.0, 1.0, 0.0),
        )
        .unwrap();
        let q = Point3::new(3.0, 1.0, 5.0);
        let c = p.closest_point(q);
        assert!(c.abs_diff_eq(Point3::new(3.0, 1.0, 1.0), 1e-15));
        assert_eq!(p.signed_distance_to(q), 4.0);
        assert_eq!(p.flipped().signed_distance_to(q), -4.0);
        let (u, v) = p.closest_parameter(q);
        assert!(p.point_at(u, v, 0.0).abs_diff_eq(c, 1e-15));
        let moved = p.remap_to(q, &Plane::WORLD_XY);
        let [a, b, w] = p.local_coordinates(q);
        assert_eq!(moved, Point3::new(a, b, w));
        assert!(Plane::WORLD_XY.remap_to(moved, &p).abs_diff_eq(q, 1e-15));
    }

    #[test]
    fn transformed_plane_stays_right_handed() {
        let p =
            Plane::from_normal(Point3::new(1.0, 2.0, 3.0), Vector3::new(1.0, 1.0, 1.0)).unwrap();
        assert_eq!(p.transformed(&Transform::IDENTITY), Ok(p));
        let mirror = Transform::mirror(&Plane::WORLD_XY);
        let m = p.transformed(&mirror).unwrap();
        assert!(m.is_valid());
        assert!(
            m.x_axis
                .abs_diff_eq(mirror.transform_vector(p.x_axis), 1e-15)
        );
        assert!(
            m.y_axis
                .abs_diff_eq(mirror.transform_vector(p.y_axis), 1e-15)
        );
        // The normal is x' × y', not the mirror image of the normal.
        assert!(
            m.z_axis
                .abs_diff_eq(-mirror.transform_vector(p.z_axis), 1e-15)
        );
        let shear = Transform::shear(
            &Plane::WORLD_XY,
            Vector3::X,
            Vector3::new(1.0, 1.0, 0.0),
            Vector3::Z,
        );
        assert!(p.transformed(&shear).unwrap().is_valid());
        let flatten = Transform::planar_projection(&Plane::WORLD_ZX);
        assert_eq!(
            Plane::WORLD_XY.transformed(&flatten),
            Err(Error::DegenerateTransformResult { what: "plane" })
        );
    }

    #[test]
    fn equation_and_distance() {
        let p = Plane::from_normal(Point3::new(0.0, 0.0, 2.0), Vector3::Z).unwrap();
        assert_eq!(p.equation(), [0.0, 0.0, 1.0, -2.0]);
        assert_eq!(p.signed_distance_to(Point3::new(5.0, 1.0, 5.0)), 3.0);
    }
}

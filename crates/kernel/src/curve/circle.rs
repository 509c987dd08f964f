//! Circles.

use std::f64::consts::{FRAC_PI_2, PI, TAU};

use crate::{Error, Interval, NurbsCurve, Plane, Point3, Result, Transform, Vector3};

/// The weight of the corner control points of Rhino's NURBS circle, `1/√2` (as openNURBS
/// computes it, which is one unit in the last place below `std::f64::consts::FRAC_1_SQRT_2`).
pub(crate) fn corner_weight() -> f64 {
    1.0 / 2.0f64.sqrt()
}

/// A circle: a plane (centre and orientation) and a radius, as Rhino's `Circle`.
///
/// The circle is parameterized by the angle `θ ∈ [0, 2π]` from the plane's x axis towards its
/// y axis: `C(θ) = origin + r (cos θ · x + sin θ · y)`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Circle {
    /// The plane of the circle; its origin is the centre.
    pub plane: Plane,
    /// The radius, positive.
    pub radius: f64,
}

impl Circle {
    /// The circle in `plane` about its origin with radius `radius`.
    ///
    /// # Errors
    /// [`Error::NotFinite`] for a non-finite plane or radius; [`Error::InvalidInput`] for a
    /// radius that is not positive.
    pub fn new(plane: Plane, radius: f64) -> Result<Self> {
        if !plane.is_finite() || !radius.is_finite() {
            return Err(Error::NotFinite { what: "circle" });
        }
        if radius <= 0.0 {
            return Err(Error::InvalidInput(format!(
                "circle radius {radius} is not positive"
            )));
        }
        Ok(Self { plane, radius })
    }

    /// The circle about `center` in the plane with normal `normal` (x axis chosen as Rhino does).
    ///
    /// # Errors
    /// As [`Circle::new`] and [`Plane::from_normal`].
    pub fn from_center_normal(center: Point3, normal: Vector3, radius: f64) -> Result<Self> {
        Self::new(Plane::from_normal(center, normal)?, radius)
    }

    /// The circle through three points, with its plane's x axis towards the first point
    /// (Rhino's Circle 3Pt).
    ///
    /// # Errors
    /// [`Error::Collinear`] when the points lie on one line or two coincide;
    /// [`Error::NotFinite`] for NaN input.
    pub fn from_three_points(a: Point3, b: Point3, c: Point3) -> Result<Self> {
        let (center, normal) = circumcenter(a, b, c)?;
        let x = a - center;
        let y = normal.cross(x);
        let plane = Plane::from_frame(center, x, y)?;
        Self::new(plane, x.length())
    }

    /// The centre.
    #[inline]
    pub fn center(&self) -> Point3 {
        self.plane.origin
    }

    /// The unit normal (the plane's z axis).
    #[inline]
    pub fn normal(&self) -> Vector3 {
        self.plane.z_axis
    }

    /// The circumference `2πr`.
    #[inline]
    pub fn circumference(&self) -> f64 {
        TAU * self.radius
    }

    /// The domain `[0, 2π]`.
    #[inline]
    pub fn domain(&self) -> Interval {
        Interval::new(0.0, TAU)
    }

    /// The point at angle `angle`.
    #[inline]
    pub fn point_at(&self, angle: f64) -> Point3 {
        let (s, c) = angle.sin_cos();
        self.plane.origin
            + self.plane.x_axis * (self.radius * c)
            + self.plane.y_axis * (self.radius * s)
    }

    /// The point and first and second derivatives with respect to the angle.
    pub fn point_and_derivatives_at(&self, angle: f64) -> (Point3, Vector3, Vector3) {
        let (s, c) = angle.sin_cos();
        let r = self.radius;
        let (x, y) = (self.plane.x_axis, self.plane.y_axis);
        let radial = x * (r * c) + y * (r * s);
        let d1 = x * (-r * s) + y * (r * c);
        (self.plane.origin + radial, d1, -radial)
    }

    /// The unit tangent at `angle` (counter-clockwise about the normal).
    pub fn tangent_at(&self, angle: f64) -> Vector3 {
        let (s, c) = angle.sin_cos();
        self.plane.x_axis * -s + self.plane.y_axis * c
    }

    /// The curvature vector at `angle`: towards the centre, of length `1/r`.
    pub fn curvature_at(&self, angle: f64) -> Vector3 {
        (self.center() - self.point_at(angle)) / (self.radius * self.radius)
    }

    /// The angle in `[0, 2π)` of the point of the circle closest to `p`; 0 when `p` is on the
    /// axis (where every point is equally close).
    pub fn closest_parameter(&self, p: Point3) -> f64 {
        let [u, v, _] = self.plane.local_coordinates(p);
        if u == 0.0 && v == 0.0 {
            return 0.0;
        }
        let a = v.atan2(u);
        if a < 0.0 { a + TAU } else { a }
    }

    /// The point of the circle closest to `p`.
    pub fn closest_point(&self, p: Point3) -> Point3 {
        self.point_at(self.closest_parameter(p))
    }

    /// The circle mapped by `transform`, when the image is a circle (similarities: rotation,
    /// translation, uniform scale, mirror).
    ///
    /// # Errors
    /// [`Error::InvalidInput`] when the transform distorts the circle (non-uniform scale,
    /// shear, projection); use the NURBS form for those.
    pub fn transformed(&self, transform: &Transform) -> Result<Self> {
        let o = transform.transform_point(self.plane.origin);
        let x = transform.transform_vector(self.plane.x_axis * self.radius);
        let y = transform.transform_vector(self.plane.y_axis * self.radius);
        let (lx, ly) = (x.length(), y.length());
        let tol = 1e-12 * lx.max(ly).max(1.0);
        if (lx - ly).abs() > tol || x.dot(y).abs() > tol * lx.max(1.0) {
            return Err(Error::InvalidInput(
                "the transform does not map the circle to a circle".into(),
            ));
        }
        Self::new(Plane::from_frame(o, x, y)?, lx)
    }

    /// The same circle traversed clockwise: the plane is flipped about its x axis, so the start
    /// point stays and the angle runs the other way.
    pub fn reversed(&self) -> Self {
        let mut plane = self.plane;
        plane.y_axis = -plane.y_axis;
        plane.z_axis = -plane.z_axis;
        Self {
            plane,
            radius: self.radius,
        }
    }

    /// Rhino's NURBS circle: degree 2, 9 control points on the square around the circle
    /// (corners with weight `1/√2`), knots `0, 0, π/2, π/2, π, π, 3π/2, 3π/2, 2π, 2π`.
    ///
    /// The NURBS form passes through the same points at the knots but is not parameterized by
    /// the angle in between.
    pub fn to_nurbs(&self) -> NurbsCurve {
        let r = self.radius;
        let pl = &self.plane;
        let at = |u: f64, v: f64| pl.origin + pl.x_axis * u + pl.y_axis * v;
        let points = vec![
            at(r, 0.0),
            at(r, r),
            at(0.0, r),
            at(-r, r),
            at(-r, 0.0),
            at(-r, -r),
            at(0.0, -r),
            at(r, -r),
            at(r, 0.0),
        ];
        let w = corner_weight();
        let weights = vec![1.0, w, 1.0, w, 1.0, w, 1.0, w, 1.0];
        let knots = vec![
            0.0,
            0.0,
            FRAC_PI_2,
            FRAC_PI_2,
            PI,
            PI,
            3.0 * FRAC_PI_2,
            3.0 * FRAC_PI_2,
            TAU,
            TAU,
        ];
        NurbsCurve::from_parts_unchecked(2, points, weights, knots)
    }
}

/// The centre and unit normal of the circle through three points.
pub(crate) fn circumcenter(a: Point3, b: Point3, c: Point3) -> Result<(Point3, Vector3)> {
    if !a.is_finite() || !b.is_finite() || !c.is_finite() {
        return Err(Error::NotFinite { what: "point" });
    }
    let ab = b - a;
    let ac = c - a;
    let n = ab.cross(ac);
    let n2 = n.length_squared();
    let scale = ab.length_squared().max(ac.length_squared());
    if n2 <= 1e-24 * scale * scale || scale == 0.0 {
        return Err(Error::Collinear);
    }
    // Standard formula: centre = a + ((|ac|² (n × ab)) + (|ab|² (ac × n))) / (2|n|²).
    let offset =
        (n.cross(ab) * ac.length_squared() + ac.cross(n) * ab.length_squared()) / (2.0 * n2);
    let normal = n.try_normalize().ok_or(Error::Collinear)?;
    Ok((a + offset, normal))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rhino_nurbs_circle() {
        let plane = Plane {
            origin: Point3::new(1.0, 2.0, 3.0),
            ..Plane::WORLD_XY
        };
        let c = Circle::new(plane, 10.0).unwrap();
        let n = c.to_nurbs();
        assert_eq!(n.degree(), 2);
        assert_eq!(n.point_count(), 9);
        assert_eq!(n.points()[1], Point3::new(11.0, 12.0, 3.0));
        assert_eq!(n.weights()[1], 0.7071067811865475);
        assert_eq!(n.domain(), Interval::new(0.0, TAU));
        for i in 0..=40 {
            let t = TAU * i as f64 / 40.0;
            let p = n.point_at(t);
            assert!((p.distance(c.center()) - 10.0).abs() < 1e-12);
        }
        // At the knots the two parameterizations agree.
        for k in [0.0, FRAC_PI_2, PI, 3.0 * FRAC_PI_2, TAU] {
            assert!(n.point_at(k).distance(c.point_at(k)) < 1e-12);
        }
    }

    #[test]
    fn evaluation_closest_point_and_three_points() {
        let c = Circle::new(Plane::WORLD_XY, 2.0).unwrap();
        let (p, d1, d2) = c.point_and_derivatives_at(FRAC_PI_2);
        assert!(p.distance(Point3::new(0.0, 2.0, 0.0)) < 1e-15);
        assert!((d1 - Vector3::new(-2.0, 0.0, 0.0)).length() < 1e-15);
        assert!((d2 - Vector3::new(0.0, -2.0, 0.0)).length() < 1e-15);
        assert!((c.curvature_at(1.0).length() - 0.5).abs() < 1e-15);
        let t = c.closest_parameter(Point3::new(-1.0, -1.0, 5.0));
        assert!((t - 1.25 * PI).abs() < 1e-15);
        assert_eq!(c.closest_parameter(Point3::new(0.0, 0.0, 3.0)), 0.0);
        let three = Circle::from_three_points(
            Point3::new(1.0, 0.0, 0.0),
            Point3::new(0.0, 1.0, 0.0),
            Point3::new(-1.0, 0.0, 0.0),
        )
        .unwrap();
        assert!(three.center().distance(Point3::ORIGIN) < 1e-15);
        assert!((three.radius - 1.0).abs() < 1e-15);
        assert!((three.normal() - Vector3::Z).length() < 1e-15);
        assert!(matches!(
            Circle::from_three_points(
                Point3::ORIGIN,
                Point3::new(1.0, 1.0, 1.0),
                Point3::new(2.0, 2.0, 2.0)
            ),
            Err(Error::Collinear)
        ));
        assert!(Circle::new(Plane::WORLD_XY, 0.0).is_err());
        assert!(Circle::new(Plane::WORLD_XY, f64::NAN).is_err());
    }

    #[test]
    fn transform_and_reverse() {
        let c = Circle::new(Plane::WORLD_XY, 2.0).unwrap();
        let moved = c
            .transformed(&Transform::translation(Vector3::new(1.0, 0.0, 0.0)))
            .unwrap();
        assert_eq!(moved.center(), Point3::new(1.0, 0.0, 0.0));
        let r = c.reversed();
        assert!(r.point_at(0.0).distance(c.point_at(0.0)) < 1e-15);
        assert!(r.point_at(1.0).distance(c.point_at(-1.0)) < 1e-15);
        let squash = Transform::from_rows([
            [1.0, 0.0, 0.0, 0.0],
            [0.0, 2.0, 0.0, 0.0],
            [0.0, 0.0, 1.0, 0.0],
            [0.0, 0.0, 0.0, 1.0],
        ]);
        assert!(c.transformed(&squash).is_err());
    }
}

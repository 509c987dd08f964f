//! Ellipses, as Rhino's `Ellipse`: a plane and two radii, along its x and y axes.
//!
//! The NURBS form is Rhino's: the nine-point rational quadratic circle with its control points
//! scaled by the radii along the plane's axes (an affine map keeps a rational curve exact),
//! weights `1, 1/√2, 1, …` and knots at the quarter angles, domain `[0, 2π]`.

use std::f64::consts::{FRAC_PI_2, PI, TAU};

use crate::curve::circle::corner_weight;
use crate::{Error, NurbsCurve, Plane, Point3, Result};

/// An ellipse about the origin of a plane: `E(θ) = origin + r₁ cos θ · x + r₂ sin θ · y`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ellipse {
    /// The plane of the ellipse; its origin is the centre.
    pub plane: Plane,
    /// The radius along the plane's x axis, positive.
    pub radius1: f64,
    /// The radius along the plane's y axis, positive.
    pub radius2: f64,
}

impl Ellipse {
    /// The ellipse in `plane` with radius `radius1` along its x axis and `radius2` along its y
    /// axis.
    ///
    /// # Errors
    /// [`Error::NotFinite`] for a non-finite plane or radius; [`Error::InvalidInput`] for a
    /// radius that is not positive.
    pub fn new(plane: Plane, radius1: f64, radius2: f64) -> Result<Self> {
        if !plane.is_finite() || !radius1.is_finite() || !radius2.is_finite() {
            return Err(Error::NotFinite { what: "ellipse" });
        }
        for (name, r) in [("first", radius1), ("second", radius2)] {
            if r <= 0.0 {
                return Err(Error::InvalidInput(format!(
                    "ellipse {name} radius {r} is not positive"
                )));
            }
        }
        Ok(Self {
            plane,
            radius1,
            radius2,
        })
    }

    /// The point at angle `theta` (radians from the x axis towards the y axis).
    pub fn point_at(&self, theta: f64) -> Point3 {
        let pl = &self.plane;
        pl.origin
            + pl.x_axis * (self.radius1 * theta.cos())
            + pl.y_axis * (self.radius2 * theta.sin())
    }

    /// The two foci, on the major axis at `√(a² − b²)` either side of the centre: first the one
    /// on the positive side of the major axis (the x axis when `radius1 ≥ radius2`, else the
    /// y axis), as openNURBS's `ON_Ellipse::GetFoci`. A circle's foci are both its centre.
    pub fn foci(&self) -> (Point3, Point3) {
        let (a, b, axis) = if self.radius1 >= self.radius2 {
            (self.radius1, self.radius2, self.plane.x_axis)
        } else {
            (self.radius2, self.radius1, self.plane.y_axis)
        };
        let c = ((a - b) * (a + b)).max(0.0).sqrt();
        (self.plane.origin + axis * c, self.plane.origin - axis * c)
    }

    /// The exact rational NURBS form, degree 2 with nine control points and domain `[0, 2π]`.
    /// Its parameter is not the angle `θ` of [`Ellipse::point_at`] except at the quarter
    /// points, as for Rhino's circles.
    pub fn to_nurbs(&self) -> NurbsCurve {
        let (a, b) = (self.radius1, self.radius2);
        let pl = &self.plane;
        let at = |u: f64, v: f64| pl.origin + pl.x_axis * (a * u) + pl.y_axis * (b * v);
        let points = vec![
            at(1.0, 0.0),
            at(1.0, 1.0),
            at(0.0, 1.0),
            at(-1.0, 1.0),
            at(-1.0, 0.0),
            at(-1.0, -1.0),
            at(0.0, -1.0),
            at(1.0, -1.0),
            at(1.0, 0.0),
        ];
        let w = corner_weight();
        let weights = vec![1.0, w, 1.0, w, 1.0, w, 1.0, w, 1.0];
        let q = FRAC_PI_2;
        let knots = vec![0.0, 0.0, q, q, PI, PI, 3.0 * q, 3.0 * q, TAU, TAU];
        NurbsCurve::from_parts_unchecked(2, points, weights, knots)
    }
}

#[cfg(test)]
mod tests {
    use proptest::prelude::*;

    use super::*;
    use crate::Vector3;

    #[test]
    fn foci_lie_on_the_major_axis() {
        let e = Ellipse::new(Plane::WORLD_XY, 5.0, 3.0).unwrap();
        assert_eq!(
            e.foci(),
            (Point3::new(4.0, 0.0, 0.0), Point3::new(-4.0, 0.0, 0.0))
        );
        let e = Ellipse::new(Plane::WORLD_XY, 3.0, 5.0).unwrap();
        assert_eq!(
            e.foci(),
            (Point3::new(0.0, 4.0, 0.0), Point3::new(0.0, -4.0, 0.0))
        );
        let e = Ellipse::new(Plane::WORLD_XY, 2.0, 2.0).unwrap();
        assert_eq!(e.foci(), (Point3::ORIGIN, Point3::ORIGIN));
    }

    #[test]
    fn bad_radii_are_errors() {
        assert!(Ellipse::new(Plane::WORLD_XY, 0.0, 1.0).is_err());
        assert!(Ellipse::new(Plane::WORLD_XY, 1.0, -1.0).is_err());
        assert!(Ellipse::new(Plane::WORLD_XY, f64::NAN, 1.0).is_err());
    }

    #[test]
    fn nurbs_form_passes_through_the_vertices() {
        let e = Ellipse::new(Plane::WORLD_XY, 5.0, 3.0).unwrap();
        let c = e.to_nurbs();
        assert_eq!(c.domain().t0, 0.0);
        assert_eq!(c.domain().t1, TAU);
        for (t, p) in [
            (0.0, (5.0, 0.0)),
            (FRAC_PI_2, (0.0, 3.0)),
            (PI, (-5.0, 0.0)),
            (3.0 * FRAC_PI_2, (0.0, -3.0)),
        ] {
            let q = c.point_at(t);
            assert!(q.distance(Point3::new(p.0, p.1, 0.0)) < 1e-14, "{t}: {q:?}");
        }
    }

    proptest! {
        /// Every point of the NURBS form satisfies the ellipse's equation, so the sum of its
        /// distances to the foci is twice the major radius.
        #[test]
        fn nurbs_points_lie_on_the_ellipse(
            a in 0.01f64..100.0,
            b in 0.01f64..100.0,
            t in 0.0f64..TAU,
            ox in -10.0f64..10.0,
            tilt in 0.0f64..3.0,
        ) {
            let normal = Vector3::new(tilt.sin(), 0.0, tilt.cos());
            let plane = Plane::from_normal(Point3::new(ox, 1.0, -2.0), normal).unwrap();
            let e = Ellipse::new(plane, a, b).unwrap();
            let p = e.to_nurbs().point_at(t);
            let d = p - plane.origin;
            let (u, v) = (d.dot(plane.x_axis) / a, d.dot(plane.y_axis) / b);
            prop_assert!((u * u + v * v - 1.0).abs() < 1e-12);
            prop_assert!(d.dot(plane.z_axis).abs() < 1e-9 * (1.0 + a + b));
            let (f1, f2) = e.foci();
            let sum = p.distance(f1) + p.distance(f2);
            prop_assert!((sum - 2.0 * a.max(b)).abs() < 1e-9 * a.max(b));
        }
    }
}

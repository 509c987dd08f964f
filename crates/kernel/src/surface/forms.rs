//! Analytic surfaces (sphere, cylinder, cone) and the exact NURBS forms Rhino builds for them
//! and for planar rectangles.
//!
//! All round forms use Rhino's circle: degree 2, nine control points at the corners and edge
//! midpoints of the circumscribed square, corner weights `1/√2` (computed as `1.0 / √2.0`,
//! as openNURBS does), and knots `0, 0, π/2, π/2, π, π, 3π/2, 3π/2, 2π, 2π`. The circle
//! parameter is therefore not the angle, but `u = 0, π/2, π, 3π/2` do land on the axes.

use std::f64::consts::{FRAC_PI_2, PI, TAU};
use std::sync::OnceLock;

use crate::{Error, Interval, NurbsSurface, Plane, Point3, Result};

/// Rhino's unit circle control points `(x, y)` and the corner flag (weight `1/√2`).
const CIRCLE: [(f64, f64, bool); 9] = [
    (1.0, 0.0, false),
    (1.0, 1.0, true),
    (0.0, 1.0, false),
    (-1.0, 1.0, true),
    (-1.0, 0.0, false),
    (-1.0, -1.0, true),
    (0.0, -1.0, false),
    (1.0, -1.0, true),
    (1.0, 0.0, false),
];

/// The knots of Rhino's circle.
fn circle_knots() -> Vec<f64> {
    vec![
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
    ]
}

/// The corner weight of Rhino's circle, `1.0 / √2.0` (one ulp below `FRAC_1_SQRT_2`, as in
/// openNURBS).
#[inline]
fn corner_weight() -> f64 {
    1.0 / 2f64.sqrt()
}

fn check_radius(radius: f64) -> Result<()> {
    if !radius.is_finite() {
        return Err(Error::NotFinite { what: "radius" });
    }
    if radius <= 0.0 {
        return Err(Error::InvalidInput(format!(
            "radius must be positive, got {radius}"
        )));
    }
    Ok(())
}

fn check_plane(plane: &Plane) -> Result<()> {
    if !plane.is_finite() {
        return Err(Error::NotFinite { what: "plane" });
    }
    Ok(())
}

impl NurbsSurface {
    /// The planar rectangle `plane.point_at(x, y)` for `x` in `x_extent` and `y` in
    /// `y_extent`, as Rhino's `PlaneSurface(plane, x, y).ToNurbsSurface()`: degree 1 × 1, two by
    /// two control points, and the extents as domains.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] unless both extents are finite and increasing,
    /// [`Error::NotFinite`] for a non-finite plane.
    pub fn from_plane(plane: &Plane, x_extent: Interval, y_extent: Interval) -> Result<Self> {
        check_plane(plane)?;
        for (name, d) in [("x", x_extent), ("y", y_extent)] {
            if !d.is_finite() || !d.is_increasing() {
                return Err(Error::InvalidInput(format!(
                    "plane surface {name} extent {} to {} must be finite and increasing",
                    d.t0, d.t1
                )));
            }
        }
        let points = vec![
            plane.point_at(x_extent.t0, y_extent.t0, 0.0),
            plane.point_at(x_extent.t0, y_extent.t1, 0.0),
            plane.point_at(x_extent.t1, y_extent.t0, 0.0),
            plane.point_at(x_extent.t1, y_extent.t1, 0.0),
        ];
        Self::from_flat(
            [1, 1],
            [2, 2],
            points,
            vec![1.0; 4],
            [
                vec![x_extent.t0, x_extent.t1],
                vec![y_extent.t0, y_extent.t1],
            ],
        )
    }
}

/// The weights and knots of Rhino's sphere (see [`Sphere::to_nurbs`]), computed once.
fn sphere_pattern() -> &'static ([f64; 45], [f64; 10], [f64; 6]) {
    static PATTERN: OnceLock<([f64; 45], [f64; 10], [f64; 6])> = OnceLock::new();
    PATTERN.get_or_init(|| {
        let s = corner_weight();
        let mut weights = [0.0; 45];
        for (i, &(_, _, corner_u)) in CIRCLE.iter().enumerate() {
            for (j, &(_, _, corner_v)) in MERIDIAN.iter().enumerate() {
                weights[i * 5 + j] = match (corner_u, corner_v) {
                    (true, true) => 0.5,
                    (false, false) => 1.0,
                    _ => s,
                };
            }
        }
        let mut knots_u = [0.0; 10];
        knots_u.copy_from_slice(&circle_knots());
        let knots_v = [-FRAC_PI_2, -FRAC_PI_2, 0.0, 0.0, FRAC_PI_2, FRAC_PI_2];
        (weights, knots_u, knots_v)
    })
}

/// The meridian of Rhino's sphere: `(ρ, z)` on the unit half circle from the south to the north
/// pole and the corner flag (weight `1/√2`).
const MERIDIAN: [(f64, f64, bool); 5] = [
    (0.0, -1.0, false),
    (1.0, -1.0, true),
    (1.0, 0.0, false),
    (1.0, 1.0, true),
    (0.0, 1.0, false),
];

/// A sphere: the points at distance `radius` from the origin of `plane`. The plane orients the
/// NURBS form: longitude `u` starts on its x axis and turns about its z axis, latitude `v` runs
/// from the south pole (`−z`) to the north pole.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sphere {
    /// The equatorial plane; its origin is the centre.
    pub plane: Plane,
    /// The radius, positive.
    pub radius: f64,
}

impl Sphere {
    /// A sphere with the given centre and radius, oriented by the world axes (Rhino's
    /// `Sphere(Point3d, double)`).
    ///
    /// # Errors
    /// [`Error::InvalidInput`] for a radius that is not positive, [`Error::NotFinite`] for NaN.
    pub fn new(center: Point3, radius: f64) -> Result<Self> {
        let plane = Plane {
            origin: center,
            ..Plane::WORLD_XY
        };
        Self::from_plane(plane, radius)
    }

    /// A sphere centred at the origin of `plane`, oriented by it.
    ///
    /// # Errors
    /// As [`Sphere::new`].
    pub fn from_plane(plane: Plane, radius: f64) -> Result<Self> {
        check_plane(&plane)?;
        check_radius(radius)?;
        Ok(Self { plane, radius })
    }

    /// The centre.
    #[inline]
    pub fn center(&self) -> Point3 {
        self.plane.origin
    }

    /// The surface area `4πr²`.
    #[inline]
    pub fn area(&self) -> f64 {
        4.0 * PI * self.radius * self.radius
    }

    /// The enclosed volume `4πr³/3`.
    #[inline]
    pub fn volume(&self) -> f64 {
        4.0 / 3.0 * PI * self.radius.powi(3)
    }

    /// The exact NURBS form as Rhino builds it (`Sphere.ToNurbsSurface()`): degree 2 × 2 with
    /// 9 × 5 control points; `u` is Rhino's circle in longitude on `[0, 2π]`, `v` a rational
    /// half circle in latitude on `[−π/2, π/2]` from the south to the north pole. The sides
    /// `v = −π/2` and `v = π/2` are singular, the sides `u = 0` and `u = 2π` meet at a seam,
    /// and the normals point outwards.
    ///
    /// # Errors
    /// [`Error::NotFinite`] if the control points overflow (a radius near `f64::MAX`).
    pub fn to_nurbs(&self) -> Result<NurbsSurface> {
        let Plane {
            origin,
            x_axis,
            y_axis,
            z_axis,
        } = self.plane;
        let r = self.radius;
        let mut points = Vec::with_capacity(45);
        for &(cx, cy, _) in &CIRCLE {
            for &(rho, z, _) in &MERIDIAN {
                points.push(
                    origin + x_axis * (r * rho * cx) + y_axis * (r * rho * cy) + z_axis * (r * z),
                );
            }
        }
        if points.iter().any(|p| !p.is_finite()) {
            return Err(Error::NotFinite {
                what: "control point",
            });
        }
        // Degrees, counts, knots and weights are Rhino's sphere, valid by construction: only
        // the control points (which overflow for radii near `f64::MAX`) need checking, and the
        // weights and knots are the same for every sphere.
        let (weights, knots_u, knots_v) = sphere_pattern();
        Ok(NurbsSurface {
            degree_u: 2,
            degree_v: 2,
            count_u: 9,
            count_v: 5,
            points,
            weights: weights.to_vec(),
            knots_u: knots_u.to_vec(),
            knots_v: knots_v.to_vec(),
            rational: true,
        })
    }
}

/// A finite right circular cylinder: the circle of `radius` about the z axis of `plane`, swept
/// along that axis over `height` (Rhino's `ON_Cylinder` with `height[0]`, `height[1]`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Cylinder {
    /// The plane of the base circle; its z axis is the cylinder's axis.
    pub plane: Plane,
    /// The radius, positive.
    pub radius: f64,
    /// The axial extent, measured along the z axis from the plane's origin; increasing.
    pub height: Interval,
}

impl Cylinder {
    /// The cylinder on the circle in `plane` with the given radius, extruded by `height` along
    /// the plane's normal (Rhino's `Cylinder(circle, height)`: a negative height extrudes
    /// backwards, giving the extent `height` to 0).
    ///
    /// # Errors
    /// [`Error::InvalidInput`] for a non-positive radius or a zero height,
    /// [`Error::NotFinite`] for NaN input.
    pub fn new(plane: Plane, radius: f64, height: f64) -> Result<Self> {
        if !height.is_finite() {
            return Err(Error::NotFinite { what: "height" });
        }
        let extent = if height > 0.0 {
            Interval::new(0.0, height)
        } else {
            Interval::new(height, 0.0)
        };
        Self::with_extent(plane, radius, extent)
    }

    /// The cylinder on the circle in `plane` over the axial extent `height` (increasing).
    ///
    /// # Errors
    /// [`Error::InvalidInput`] for a non-positive radius or an extent that is not increasing,
    /// [`Error::NotFinite`] for NaN input.
    pub fn with_extent(plane: Plane, radius: f64, height: Interval) -> Result<Self> {
        check_plane(&plane)?;
        check_radius(radius)?;
        if !height.is_finite() {
            return Err(Error::NotFinite { what: "height" });
        }
        if !height.is_increasing() {
            return Err(Error::InvalidInput(format!(
                "cylinder height {} to {} must be increasing",
                height.t0, height.t1
            )));
        }
        Ok(Self {
            plane,
            radius,
            height,
        })
    }

    /// The plane of the circle at axial position `h`, parallel to the base plane.
    pub fn circle_plane_at(&self, h: f64) -> Plane {
        Plane {
            origin: self.plane.origin + self.plane.z_axis * h,
            ..self.plane
        }
    }

    /// The lateral area `2πr·h`.
    #[inline]
    pub fn lateral_area(&self) -> f64 {
        TAU * self.radius * self.height.length()
    }

    /// The enclosed volume `πr²·h`.
    #[inline]
    pub fn volume(&self) -> f64 {
        PI * self.radius * self.radius * self.height.length()
    }

    /// The exact NURBS form of the lateral surface as Rhino builds it
    /// (`Cylinder.ToNurbsSurface()`): degree 2 × 1 with 9 × 2 control points; `u` is Rhino's
    /// circle on `[0, 2π]`, `v` the axial position over the height extent. Normals point
    /// outwards; the sides `u = 0` and `u = 2π` meet at a seam.
    ///
    /// # Errors
    /// [`Error::NotFinite`] if the control points overflow.
    pub fn to_nurbs(&self) -> Result<NurbsSurface> {
        let s = corner_weight();
        let Plane {
            origin,
            x_axis,
            y_axis,
            z_axis,
        } = self.plane;
        let r = self.radius;
        let mut points = Vec::with_capacity(18);
        let mut weights = Vec::with_capacity(18);
        for &(cx, cy, corner) in &CIRCLE {
            let on_circle = origin + x_axis * (r * cx) + y_axis * (r * cy);
            for h in [self.height.t0, self.height.t1] {
                points.push(on_circle + z_axis * h);
                weights.push(if corner { s } else { 1.0 });
            }
        }
        NurbsSurface::from_flat(
            [2, 1],
            [9, 2],
            points,
            weights,
            [circle_knots(), vec![self.height.t0, self.height.t1]],
        )
    }
}

/// A finite right circular cone with its apex at the origin of `plane` and its base circle of
/// `radius` in the plane parallel to it at `height` along the z axis (Rhino's `ON_Cone`; a
/// negative height puts the base behind the apex).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Cone {
    /// The plane at the apex; its z axis is the cone's axis.
    pub plane: Plane,
    /// The signed distance from the apex to the base along the axis, not zero.
    pub height: f64,
    /// The radius of the base circle, positive.
    pub radius: f64,
}

impl Cone {
    /// A cone from its apex plane, height and base radius (Rhino's `Cone(plane, height,
    /// radius)`).
    ///
    /// # Errors
    /// [`Error::InvalidInput`] for a zero height or a non-positive radius,
    /// [`Error::NotFinite`] for NaN input.
    pub fn new(plane: Plane, height: f64, radius: f64) -> Result<Self> {
        check_plane(&plane)?;
        check_radius(radius)?;
        if !height.is_finite() {
            return Err(Error::NotFinite { what: "height" });
        }
        if height == 0.0 {
            return Err(Error::InvalidInput("cone height must not be zero".into()));
        }
        Ok(Self {
            plane,
            height,
            radius,
        })
    }

    /// The apex.
    #[inline]
    pub fn apex(&self) -> Point3 {
        self.plane.origin
    }

    /// The plane of the base circle, parallel to the apex plane.
    pub fn base_plane(&self) -> Plane {
        Plane {
            origin: self.plane.origin + self.plane.z_axis * self.height,
            ..self.plane
        }
    }

    /// The lateral area `πr·√(r² + h²)`.
    #[inline]
    pub fn lateral_area(&self) -> f64 {
        PI * self.radius * self.radius.hypot(self.height)
    }

    /// The enclosed volume `πr²|h|/3`.
    #[inline]
    pub fn volume(&self) -> f64 {
        PI * self.radius * self.radius * self.height.abs() / 3.0
    }

    /// The exact NURBS form of the lateral surface as openNURBS's `ON_Cone::GetNurbForm`
    /// builds it: degree 2 × 1 with 9 × 2 control points; `u` is Rhino's circle on `[0, 2π]`
    /// in the base plane, `v` runs over `[0, height]` (or `[height, 0]` for a negative height)
    /// with `v = 0` at the apex, whose row repeats the apex with the circle's weights. The apex
    /// side is singular; for a positive height the normals point away from the axis.
    ///
    /// # Errors
    /// [`Error::NotFinite`] if the control points overflow.
    pub fn to_nurbs(&self) -> Result<NurbsSurface> {
        let s = corner_weight();
        let base = self.base_plane();
        let apex = self.apex();
        let r = self.radius;
        let mut points = Vec::with_capacity(18);
        let mut weights = Vec::with_capacity(18);
        for &(cx, cy, corner) in &CIRCLE {
            let w = if corner { s } else { 1.0 };
            let on_circle = base.origin + base.x_axis * (r * cx) + base.y_axis * (r * cy);
            if self.height > 0.0 {
                points.extend([apex, on_circle]);
            } else {
                points.extend([on_circle, apex]);
            }
            weights.extend([w, w]);
        }
        let knots_v = if self.height > 0.0 {
            vec![0.0, self.height]
        } else {
            vec![self.height, 0.0]
        };
        NurbsSurface::from_flat([2, 1], [9, 2], points, weights, [circle_knots(), knots_v])
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Vector3;

    fn tilted() -> Plane {
        Plane::from_normal(Point3::new(1.0, 2.0, -1.0), Vector3::new(0.3, -1.0, 2.0)).unwrap()
    }

    fn for_grid(s: &NurbsSurface, mut f: impl FnMut(f64, f64)) {
        for i in 0..=12 {
            for j in 0..=12 {
                f(
                    s.domain_u().parameter_at(i as f64 / 12.0),
                    s.domain_v().parameter_at(j as f64 / 12.0),
                );
            }
        }
    }

    #[test]
    fn the_sphere_built_without_checks_passes_them() {
        let s = Sphere::from_plane(tilted(), 1.5)
            .unwrap()
            .to_nurbs()
            .unwrap();
        let checked = NurbsSurface::from_flat(
            [2, 2],
            [9, 5],
            s.points.clone(),
            s.weights.clone(),
            [s.knots_u.clone(), s.knots_v.clone()],
        )
        .unwrap();
        assert_eq!(checked, s);
        assert_eq!(s.weights[1], 1.0 / 2f64.sqrt());
        assert_eq!(s.weights[6], 0.5);
    }

    #[test]
    fn plane_surface_is_the_rectangle() {
        let plane = tilted();
        let s = NurbsSurface::from_plane(&plane, Interval::new(-1.0, 3.0), Interval::new(2.0, 5.0))
            .unwrap();
        assert_eq!(s.domain_u(), Interval::new(-1.0, 3.0));
        assert_eq!(s.domain_v(), Interval::new(2.0, 5.0));
        for_grid(&s, |u, v| {
            assert!(s.point_at(u, v).distance(plane.point_at(u, v, 0.0)) < 1e-14);
            assert!((s.normal_at(u, v).unwrap() - plane.z_axis).length() < 1e-15);
        });
        assert!(NurbsSurface::from_plane(&plane, Interval::new(1.0, 0.0), Interval::UNIT).is_err());
        assert!(NurbsSurface::from_plane(&plane, Interval::new(1.0, 1.0), Interval::UNIT).is_err());
    }

    #[test]
    fn round_forms_lie_on_their_analytic_surfaces() {
        let plane = tilted();
        let sphere = Sphere::from_plane(plane, 2.5).unwrap();
        let s = sphere.to_nurbs().unwrap();
        assert_eq!(s.domain_u(), Interval::new(0.0, TAU));
        assert_eq!(s.domain_v(), Interval::new(-FRAC_PI_2, FRAC_PI_2));
        for_grid(&s, |u, v| {
            assert!((s.point_at(u, v).distance(plane.origin) - 2.5).abs() < 1e-14);
        });
        // The knots land on the axes: u = π/2 on the y axis, v = π/2 at the north pole.
        assert!(
            s.point_at(FRAC_PI_2, 0.0)
                .distance(plane.point_at(0.0, 2.5, 0.0))
                < 1e-14
        );
        assert!(
            s.point_at(1.0, FRAC_PI_2)
                .distance(plane.point_at(0.0, 0.0, 2.5))
                < 1e-14
        );

        let cylinder = Cylinder::new(plane, 1.5, -4.0).unwrap();
        assert_eq!(cylinder.height, Interval::new(-4.0, 0.0));
        let c = cylinder.to_nurbs().unwrap();
        for_grid(&c, |u, v| {
            let [x, y, z] = plane.local_coordinates(c.point_at(u, v));
            assert!((x.hypot(y) - 1.5).abs() < 1e-14 && (z - v).abs() < 1e-14);
        });

        let cone = Cone::new(plane, 3.0, 1.5).unwrap();
        let k = cone.to_nurbs().unwrap();
        for_grid(&k, |u, v| {
            let [x, y, z] = plane.local_coordinates(k.point_at(u, v));
            assert!((x.hypot(y) - 1.5 * z / 3.0).abs() < 1e-14 && (z - v).abs() < 1e-14);
        });
        assert!((cone.lateral_area() - PI * 1.5 * 1.5f64.hypot(3.0)).abs() < 1e-14);
        assert!((cone.volume() - PI * 2.25).abs() < 1e-14);
        assert!((sphere.area() - 25.0 * PI).abs() < 1e-12);
        assert!((sphere.volume() - 4.0 / 3.0 * PI * 2.5f64.powi(3)).abs() < 1e-12);
        assert!((cylinder.volume() - PI * 2.25 * 4.0).abs() < 1e-12);
        assert!((cylinder.lateral_area() - TAU * 1.5 * 4.0).abs() < 1e-12);
    }

    #[test]
    fn bad_dimensions_are_errors() {
        let plane = tilted();
        assert!(Sphere::new(Point3::ORIGIN, 0.0).is_err());
        assert!(Sphere::new(Point3::ORIGIN, -1.0).is_err());
        assert!(matches!(
            Sphere::new(Point3::ORIGIN, f64::NAN),
            Err(Error::NotFinite { .. })
        ));
        assert!(Sphere::new(Point3::new(f64::NAN, 0.0, 0.0), 1.0).is_err());
        assert!(Cylinder::new(plane, 1.0, 0.0).is_err());
        assert!(Cylinder::new(plane, 1.0, f64::INFINITY).is_err());
        assert!(Cylinder::with_extent(plane, 1.0, Interval::new(2.0, 1.0)).is_err());
        assert!(Cone::new(plane, 0.0, 1.0).is_err());
        assert!(Cone::new(plane, 1.0, -1.0).is_err());
        // Overflowing control points are reported, not returned.
        let huge = Sphere::new(Point3::new(f64::MAX, 0.0, 0.0), f64::MAX).unwrap();
        assert!(huge.to_nurbs().is_err());
    }
}

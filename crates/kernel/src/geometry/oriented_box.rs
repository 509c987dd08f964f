//! Oriented boxes: Rhino's and Grasshopper's `Box`, a plane with three intervals.

use crate::{BoundingBox, Error, Interval, Plane, Point3, Result, Vector3};

/// A box aligned with a plane: the points `plane.point_at(u, v, w)` with `u` in `x`, `v` in `y`
/// and `w` in `z` (Rhino's and Grasshopper's `Box`).
///
/// The box is *valid* when its plane is valid and the three intervals are finite and
/// increasing or singletons (a flat box is valid and [`degenerate`](Self::degeneracy)).
/// Measures use the absolute lengths of the intervals, so a box with a decreasing interval
/// still has a positive volume; [`made_increasing`](Self::made_increasing) normalizes one.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct OrientedBox {
    /// The plane whose axes the box follows; its origin need not be inside the box.
    pub plane: Plane,
    /// The extent along the plane's x axis, in plane coordinates.
    pub x: Interval,
    /// The extent along the plane's y axis, in plane coordinates.
    pub y: Interval,
    /// The extent along the plane's z axis (the normal), in plane coordinates.
    pub z: Interval,
}

impl OrientedBox {
    /// The box on `plane` with extents `x`, `y` and `z` in plane coordinates.
    #[inline]
    pub const fn new(plane: Plane, x: Interval, y: Interval, z: Interval) -> Self {
        Self { plane, x, y, z }
    }

    /// The axis-aligned box as a box on the world XY plane.
    pub fn from_bounding_box(bbox: &BoundingBox) -> Self {
        Self::new(
            Plane::WORLD_XY,
            bbox.x_interval(),
            bbox.y_interval(),
            bbox.z_interval(),
        )
    }

    /// The box on `plane` with opposite corners `a` and `b` (Grasshopper's *Box 2Pt*): the
    /// intervals run from the smaller to the larger plane coordinate of the two points.
    ///
    /// # Errors
    /// [`Error::NotFinite`] for NaN or infinite points, [`Error::InvalidInput`] for an invalid
    /// plane.
    pub fn from_two_points(plane: &Plane, a: Point3, b: Point3) -> Result<Self> {
        Self::from_points_in_plane(plane, &[a, b])
    }

    /// The smallest box on `plane` containing every point (Grasshopper's *Bounding Box* with a
    /// plane input): the intervals are the ranges of the points' plane coordinates.
    ///
    /// # Errors
    /// [`Error::TooFewPoints`] for an empty slice, [`Error::NotFinite`] for a NaN or infinite
    /// point, [`Error::InvalidInput`] for an invalid plane.
    pub fn from_points_in_plane(plane: &Plane, points: &[Point3]) -> Result<Self> {
        check_plane(plane)?;
        if points.is_empty() {
            return Err(Error::TooFewPoints {
                what: "box",
                needed: 1,
                got: 0,
            });
        }
        let mut local = BoundingBox::EMPTY;
        for &p in points {
            if !p.is_finite() {
                return Err(Error::NotFinite { what: "point" });
            }
            local.include_point(Point3::from_array(plane.local_coordinates(p)));
        }
        Ok(Self::new(
            *plane,
            local.x_interval(),
            local.y_interval(),
            local.z_interval(),
        ))
    }

    /// The box centred on the origin of `plane` reaching `x`, `y` and `z` along each axis in
    /// both directions: the intervals are `−|x|..|x|` and so on (Grasshopper's *Center Box*,
    /// whose sizes are half-sizes).
    ///
    /// # Errors
    /// [`Error::NotFinite`] for a NaN or infinite size, [`Error::InvalidInput`] for an invalid
    /// plane.
    pub fn centered(plane: &Plane, x: f64, y: f64, z: f64) -> Result<Self> {
        check_plane(plane)?;
        if !(x.is_finite() && y.is_finite() && z.is_finite()) {
            return Err(Error::NotFinite { what: "box size" });
        }
        let half = |s: f64| Interval::new(-s.abs(), s.abs());
        Ok(Self::new(*plane, half(x), half(y), half(z)))
    }

    /// The point at plane coordinates `(u, v, w)` of the box's plane.
    #[inline]
    pub fn point_at(&self, u: f64, v: f64, w: f64) -> Point3 {
        self.plane.point_at(u, v, w)
    }

    /// The centre of the box.
    #[inline]
    pub fn center(&self) -> Point3 {
        self.point_at(self.x.mid(), self.y.mid(), self.z.mid())
    }

    /// The eight corners in the order of RhinoCommon's `Box.GetCorners` (Grasshopper's *Box
    /// Corners* A to H): the face at `z.t0` counter-clockwise about the plane's normal from
    /// `(x.t0, y.t0)`, then the face at `z.t1` the same way:
    ///
    /// `0 (x0,y0,z0), 1 (x1,y0,z0), 2 (x1,y1,z0), 3 (x0,y1,z0),`
    /// `4 (x0,y0,z1), 5 (x1,y0,z1), 6 (x1,y1,z1), 7 (x0,y1,z1)`.
    pub fn corners(&self) -> [Point3; 8] {
        let (x0, x1) = (self.x.t0, self.x.t1);
        let (y0, y1) = (self.y.t0, self.y.t1);
        let (z0, z1) = (self.z.t0, self.z.t1);
        [
            self.point_at(x0, y0, z0),
            self.point_at(x1, y0, z0),
            self.point_at(x1, y1, z0),
            self.point_at(x0, y1, z0),
            self.point_at(x0, y0, z1),
            self.point_at(x1, y0, z1),
            self.point_at(x1, y1, z1),
            self.point_at(x0, y1, z1),
        ]
    }

    /// The sizes along the plane's axes (absolute interval lengths).
    #[inline]
    pub fn sizes(&self) -> [f64; 3] {
        [
            self.x.length().abs(),
            self.y.length().abs(),
            self.z.length().abs(),
        ]
    }

    /// The vector from corner 0 to corner 6, along the box: `x.len·X + y.len·Y + z.len·Z` with
    /// the plane's axes and signed interval lengths.
    #[inline]
    pub fn diagonal(&self) -> Vector3 {
        self.plane.x_axis * self.x.length()
            + self.plane.y_axis * self.y.length()
            + self.plane.z_axis * self.z.length()
    }

    /// The surface area `2 (ab + bc + ca)` of the sizes.
    pub fn area(&self) -> f64 {
        let [a, b, c] = self.sizes();
        2.0 * (a * b + b * c + c * a)
    }

    /// The volume, the product of the sizes.
    pub fn volume(&self) -> f64 {
        let [a, b, c] = self.sizes();
        a * b * c
    }

    /// How many of the three sizes are at most `tolerance`: 0 for a solid box, 1 for a
    /// rectangle, 2 for a segment, 3 for a point (Rhino's `Box.IsDegenerate`, Grasshopper's
    /// *Box Properties* degeneracy), or `None` for a box that is not
    /// [`is_valid`](Self::is_valid).
    ///
    /// Rhino, given an invalid tolerance, uses `√ε` times the largest size, with `√ε` =
    /// [`SQRT_EPSILON`](crate::geometry::tolerance::SQRT_EPSILON); pass that for the same answer.
    pub fn degeneracy(&self, tolerance: f64) -> Option<usize> {
        if !self.is_valid() {
            return None;
        }
        Some(self.sizes().iter().filter(|&&s| s <= tolerance).count())
    }

    /// The same box with increasing intervals (Rhino's `MakeValid`); the corners are the same
    /// points in another order.
    pub fn made_increasing(&self) -> Self {
        Self::new(
            self.plane,
            self.x.increasing(),
            self.y.increasing(),
            self.z.increasing(),
        )
    }

    /// Whether the point lies in the box, to within `tolerance` in plane coordinates.
    pub fn contains_point(&self, p: Point3, tolerance: f64) -> bool {
        let [u, v, w] = self.plane.local_coordinates(p);
        let inside = |i: Interval, t: f64| t >= i.min() - tolerance && t <= i.max() + tolerance;
        inside(self.x, u) && inside(self.y, v) && inside(self.z, w)
    }

    /// The point of the box closest to `p` (`p` itself when inside).
    pub fn closest_point(&self, p: Point3) -> Point3 {
        let [u, v, w] = self.plane.local_coordinates(p);
        self.point_at(self.x.clamp(u), self.y.clamp(v), self.z.clamp(w))
    }

    /// The axis-aligned bounding box of the eight corners.
    pub fn bounding_box(&self) -> BoundingBox {
        let mut res = BoundingBox::EMPTY;
        for corner in self.corners() {
            res.include_point(corner);
        }
        res
    }

    /// Whether the plane and the intervals are finite.
    pub fn is_finite(&self) -> bool {
        self.plane.is_finite() && self.x.is_finite() && self.y.is_finite() && self.z.is_finite()
    }

    /// Whether the plane is valid ([`Plane::is_valid`]) and the intervals are finite and not
    /// decreasing.
    pub fn is_valid(&self) -> bool {
        self.is_finite()
            && self.plane.is_valid()
            && !self.x.is_decreasing()
            && !self.y.is_decreasing()
            && !self.z.is_decreasing()
    }
}

/// Checks that a plane can carry a box.
fn check_plane(plane: &Plane) -> Result<()> {
    if !plane.is_finite() {
        return Err(Error::NotFinite { what: "plane" });
    }
    if !plane.is_valid() {
        return Err(Error::InvalidInput(
            "plane axes are not orthonormal".to_owned(),
        ));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use std::f64::consts::FRAC_PI_2;

    use super::*;
    use crate::Transform;

    fn tilted_plane() -> Plane {
        Plane::from_normal(Point3::new(1.0, 2.0, 3.0), Vector3::new(1.0, -1.0, 2.0)).unwrap()
    }

    #[test]
    fn measures_of_a_box() {
        let b = OrientedBox::new(
            tilted_plane(),
            Interval::new(0.0, 2.0),
            Interval::new(-1.0, 2.0),
            Interval::new(1.0, 5.0),
        );
        assert!(b.is_valid());
        assert_eq!(b.sizes(), [2.0, 3.0, 4.0]);
        assert_eq!(b.volume(), 24.0);
        assert_eq!(b.area(), 2.0 * (6.0 + 12.0 + 8.0));
        assert!((b.diagonal().length() - 29f64.sqrt()).abs() < 1e-14);
        let c = b.corners();
        assert!((c[6] - c[0]).abs_diff_eq(b.diagonal(), 1e-14));
        assert!(b.center().abs_diff_eq(c[0].midpoint(c[6]), 1e-14));
        assert!(b.center().abs_diff_eq(b.point_at(1.0, 0.5, 3.0), 1e-14));
        assert_eq!(b.degeneracy(0.0), Some(0));
        assert_eq!(b.degeneracy(2.5), Some(1));
    }

    #[test]
    fn corners_in_rhinocommon_order() {
        let b = OrientedBox::new(
            Plane::WORLD_XY,
            Interval::new(0.0, 1.0),
            Interval::new(0.0, 2.0),
            Interval::new(0.0, 3.0),
        );
        let expected = BoundingBox::new(Point3::ORIGIN, Point3::new(1.0, 2.0, 3.0)).corners();
        assert_eq!(b.corners(), expected);
        assert_eq!(b.bounding_box().corners(), expected);
    }

    #[test]
    fn two_point_box_and_centred_box() {
        let plane = tilted_plane();
        let a = plane.point_at(3.0, -1.0, 2.0);
        let b = plane.point_at(-1.0, 4.0, 2.0);
        let bx = OrientedBox::from_two_points(&plane, a, b).unwrap();
        assert!((bx.x.t0 + 1.0).abs() < 1e-14 && (bx.x.t1 - 3.0).abs() < 1e-14);
        assert!((bx.y.t0 + 1.0).abs() < 1e-14 && (bx.y.t1 - 4.0).abs() < 1e-14);
        assert!(bx.z.length().abs() < 1e-14);
        assert_eq!(bx.degeneracy(1e-12), Some(1));
        assert!(bx.contains_point(a, 1e-12) && bx.contains_point(b, 1e-12));
        let centred = OrientedBox::centered(&plane, 1.0, -2.0, 0.5).unwrap();
        assert_eq!(centred.y, Interval::new(-2.0, 2.0));
        assert_eq!(centred.center(), plane.origin);
        assert_eq!(centred.volume(), 8.0);
        assert!(OrientedBox::centered(&plane, f64::NAN, 1.0, 1.0).is_err());
        assert!(OrientedBox::from_points_in_plane(&plane, &[]).is_err());
        let mut bad = plane;
        bad.x_axis = Vector3::new(2.0, 0.0, 0.0);
        assert!(OrientedBox::from_two_points(&bad, a, b).is_err());
    }

    #[test]
    fn closest_point_and_containment() {
        let b = OrientedBox::centered(&tilted_plane(), 1.0, 1.0, 1.0).unwrap();
        let outside = b.point_at(3.0, 0.5, -4.0);
        assert!(!b.contains_point(outside, 1e-9));
        assert!(
            b.closest_point(outside)
                .abs_diff_eq(b.point_at(1.0, 0.5, -1.0), 1e-14)
        );
        let inside = b.point_at(0.2, -0.3, 0.9);
        assert!(b.closest_point(inside).abs_diff_eq(inside, 1e-14));
    }

    #[test]
    fn transformed_box_is_exact_for_similarities() {
        let b = OrientedBox::new(
            tilted_plane(),
            Interval::new(0.0, 2.0),
            Interval::new(-1.0, 2.0),
            Interval::new(1.0, 5.0),
        );
        let xforms = [
            Transform::rotation(
                0.7,
                Vector3::new(1.0, 2.0, 3.0),
                Point3::new(1.0, -1.0, 2.0),
            )
            .unwrap(),
            Transform::scale(Point3::new(4.0, 0.0, 1.0), 0.25),
            Transform::mirror(&Plane::WORLD_YZ),
            Transform::translation(Vector3::new(3.0, 2.0, 1.0)),
        ];
        for xform in xforms {
            let t = b.transformed(&xform).unwrap();
            assert!(t.is_valid());
            let mut expected = b.corners();
            xform.transform_points(&mut expected);
            // Same solid: every transformed corner is a corner of the new box.
            for p in expected {
                assert!(
                    t.corners().iter().any(|q| q.abs_diff_eq(p, 1e-13)),
                    "{p:?} is not a corner of {t:?}"
                );
            }
            let s = xform.linear_determinant().abs().cbrt();
            assert!((t.volume() - b.volume() * s * s * s).abs() < 1e-12);
        }
        let rotated = b.transformed(&Transform::rotation_z(FRAC_PI_2)).unwrap();
        assert!((rotated.volume() - 24.0).abs() < 1e-12);
    }

    #[test]
    fn transformed_box_encloses_sheared_box() {
        let b = OrientedBox::centered(&Plane::WORLD_XY, 1.0, 1.0, 1.0).unwrap();
        let shear = Transform::shear(
            &Plane::WORLD_XY,
            Vector3::X,
            Vector3::new(1.0, 1.0, 0.0),
            Vector3::Z,
        );
        let t = b.transformed(&shear).unwrap();
        for c in b.corners() {
            assert!(t.contains_point(shear.transform_point(c), 1e-12));
        }
        assert_eq!(t.sizes(), [4.0, 2.0, 2.0]);
        let flatten = Transform::planar_projection(&Plane::WORLD_YZ);
        assert_eq!(
            b.transformed(&flatten),
            Err(Error::DegenerateTransformResult { what: "plane" })
        );
    }

    #[test]
    fn made_increasing_keeps_the_solid() {
        let b = OrientedBox::new(
            Plane::WORLD_XY,
            Interval::new(2.0, 0.0),
            Interval::new(0.0, 1.0),
            Interval::new(0.0, 1.0),
        );
        assert!(!b.is_valid());
        assert_eq!(b.degeneracy(0.0), None);
        assert_eq!(b.volume(), 2.0);
        let v = b.made_increasing();
        assert!(v.is_valid());
        assert_eq!(v.bounding_box(), b.bounding_box());
    }
}

//! Axis-aligned bounding boxes (Rhino's `BoundingBox`).

use crate::{Error, Interval, OrientedBox, Point3, Result, Vector3};

/// An axis-aligned box given by its minimum and maximum corners, as Rhino's `BoundingBox`.
///
/// A box is *empty* when a minimum coordinate exceeds the matching maximum.
/// [`BoundingBox::EMPTY`] has `min = +∞` and `max = −∞`, so that the union of the empty box
/// with anything is that thing. Measures of an empty box (centre, diagonal, corners) are not
/// finite; check [`is_empty`](Self::is_empty) or [`is_valid`](Self::is_valid) first.
///
/// # Examples
/// ```
/// use locus_kernel::{BoundingBox, Point3, Transform};
/// # fn main() -> locus_kernel::Result<()> {
/// let bbox = BoundingBox::from_points(&[Point3::new(1.0, 0.0, 0.0), Point3::new(0.0, 2.0, 3.0)])?;
/// assert_eq!(bbox.center(), Point3::new(0.5, 1.0, 1.5));
/// assert_eq!(bbox.corners()[6], bbox.max);
/// let turned = bbox.transformed(&Transform::rotation_z(std::f64::consts::FRAC_PI_2));
/// assert_eq!(turned.min, Point3::new(-2.0, 0.0, 0.0));
/// # Ok(())
/// # }
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BoundingBox {
    /// The corner with the smallest coordinates.
    pub min: Point3,
    /// The corner with the largest coordinates.
    pub max: Point3,
}

impl Default for BoundingBox {
    fn default() -> Self {
        Self::EMPTY
    }
}

impl BoundingBox {
    /// The empty box: `min = (+∞, +∞, +∞)`, `max = (−∞, −∞, −∞)`.
    pub const EMPTY: Self = Self {
        min: Point3::new(f64::INFINITY, f64::INFINITY, f64::INFINITY),
        max: Point3::new(f64::NEG_INFINITY, f64::NEG_INFINITY, f64::NEG_INFINITY),
    };

    /// The box with two opposite corners `a` and `b`, in any order (the minimum and maximum
    /// are taken coordinate by coordinate; a NaN coordinate gives way to the other corner's,
    /// as in [`include_point`](Self::include_point)).
    #[inline]
    pub fn new(a: Point3, b: Point3) -> Self {
        Self {
            min: Point3::new(a.x.min(b.x), a.y.min(b.y), a.z.min(b.z)),
            max: Point3::new(a.x.max(b.x), a.y.max(b.y), a.z.max(b.z)),
        }
    }

    /// The smallest box containing every point; [`BoundingBox::EMPTY`] for no points.
    ///
    /// # Errors
    /// [`Error::NotFinite`] when a point has a NaN or infinite coordinate.
    pub fn from_points(points: &[Point3]) -> Result<Self> {
        let mut bbox = Self::EMPTY;
        for &p in points {
            if !p.is_finite() {
                return Err(Error::NotFinite { what: "point" });
            }
            bbox.include_point(p);
        }
        Ok(bbox)
    }

    /// Grows the box to contain `p`. A NaN coordinate leaves that coordinate of the box
    /// unchanged; use [`from_points`](Self::from_points) to have it reported.
    #[inline]
    pub fn include_point(&mut self, p: Point3) {
        self.min = Point3::new(
            self.min.x.min(p.x),
            self.min.y.min(p.y),
            self.min.z.min(p.z),
        );
        self.max = Point3::new(
            self.max.x.max(p.x),
            self.max.y.max(p.y),
            self.max.z.max(p.z),
        );
    }

    /// The smallest box containing this box and `p`.
    #[inline]
    pub fn union_point(mut self, p: Point3) -> Self {
        self.include_point(p);
        self
    }

    /// The smallest box containing both boxes; the union with an empty box is the other box.
    #[inline]
    pub fn union(&self, other: &Self) -> Self {
        if other.is_empty() {
            return *self;
        }
        if self.is_empty() {
            return *other;
        }
        Self {
            min: Point3::new(
                self.min.x.min(other.min.x),
                self.min.y.min(other.min.y),
                self.min.z.min(other.min.z),
            ),
            max: Point3::new(
                self.max.x.max(other.max.x),
                self.max.y.max(other.max.y),
                self.max.z.max(other.max.z),
            ),
        }
    }

    /// The box common to both, or [`BoundingBox::EMPTY`] when they do not overlap. Boxes that
    /// only touch give a flat (degenerate) box.
    pub fn intersection(&self, other: &Self) -> Self {
        let res = Self {
            min: Point3::new(
                self.min.x.max(other.min.x),
                self.min.y.max(other.min.y),
                self.min.z.max(other.min.z),
            ),
            max: Point3::new(
                self.max.x.min(other.max.x),
                self.max.y.min(other.max.y),
                self.max.z.min(other.max.z),
            ),
        };
        if res.is_empty() { Self::EMPTY } else { res }
    }

    /// Whether the box contains no point: a minimum exceeds its maximum (or is NaN).
    #[inline]
    pub fn is_empty(&self) -> bool {
        !(self.min.x <= self.max.x && self.min.y <= self.max.y && self.min.z <= self.max.z)
    }

    /// Whether the box is finite and not empty (Rhino's `IsValid`).
    #[inline]
    pub fn is_valid(&self) -> bool {
        self.is_finite() && !self.is_empty()
    }

    /// Whether both corners are finite (false for the empty box).
    #[inline]
    pub fn is_finite(&self) -> bool {
        self.min.is_finite() && self.max.is_finite()
    }

    /// Whether `p` lies in the box, boundary included.
    #[inline]
    pub fn contains_point(&self, p: Point3) -> bool {
        (self.min.x..=self.max.x).contains(&p.x)
            && (self.min.y..=self.max.y).contains(&p.y)
            && (self.min.z..=self.max.z).contains(&p.z)
    }

    /// Whether `p` lies strictly inside the box, not on its boundary.
    #[inline]
    pub fn contains_point_strictly(&self, p: Point3) -> bool {
        self.min.x < p.x
            && p.x < self.max.x
            && self.min.y < p.y
            && p.y < self.max.y
            && self.min.z < p.z
            && p.z < self.max.z
    }

    /// Whether `other` lies in this box, boundary included. Every box contains the empty box.
    #[inline]
    pub fn contains(&self, other: &Self) -> bool {
        other.is_empty() || (self.contains_point(other.min) && self.contains_point(other.max))
    }

    /// The centre, halfway between the corners.
    #[inline]
    pub fn center(&self) -> Point3 {
        self.min.midpoint(self.max)
    }

    /// The diagonal vector from `min` to `max` (its components are the box's sizes).
    #[inline]
    pub fn diagonal(&self) -> Vector3 {
        self.max - self.min
    }

    /// The eight corners in Rhino's order (`BoundingBox.GetCorners`): the bottom face
    /// counter-clockwise from `min` seen from above, then the top face the same way:
    ///
    /// `0 (x0,y0,z0), 1 (x1,y0,z0), 2 (x1,y1,z0), 3 (x0,y1,z0),`
    /// `4 (x0,y0,z1), 5 (x1,y0,z1), 6 (x1,y1,z1), 7 (x0,y1,z1)`.
    pub fn corners(&self) -> [Point3; 8] {
        let (a, b) = (self.min, self.max);
        [
            Point3::new(a.x, a.y, a.z),
            Point3::new(b.x, a.y, a.z),
            Point3::new(b.x, b.y, a.z),
            Point3::new(a.x, b.y, a.z),
            Point3::new(a.x, a.y, b.z),
            Point3::new(b.x, a.y, b.z),
            Point3::new(b.x, b.y, b.z),
            Point3::new(a.x, b.y, b.z),
        ]
    }

    /// The surface area `2 (xy + yz + zx)`; 0 for an empty box.
    pub fn area(&self) -> f64 {
        if self.is_empty() {
            return 0.0;
        }
        let d = self.diagonal();
        2.0 * (d.x * d.y + d.y * d.z + d.z * d.x)
    }

    /// The volume `x y z`; 0 for an empty box.
    pub fn volume(&self) -> f64 {
        if self.is_empty() {
            return 0.0;
        }
        let d = self.diagonal();
        d.x * d.y * d.z
    }

    /// The x extent `min.x` to `max.x`.
    #[inline]
    pub fn x_interval(&self) -> Interval {
        Interval::new(self.min.x, self.max.x)
    }

    /// The y extent `min.y` to `max.y`.
    #[inline]
    pub fn y_interval(&self) -> Interval {
        Interval::new(self.min.y, self.max.y)
    }

    /// The z extent `min.z` to `max.z`.
    #[inline]
    pub fn z_interval(&self) -> Interval {
        Interval::new(self.min.z, self.max.z)
    }

    /// The point at normalized coordinates `(tx, ty, tz)`: `(0, 0, 0)` is `min`, `(1, 1, 1)` is
    /// `max` (Rhino's `PointAt`).
    #[inline]
    pub fn point_at(&self, tx: f64, ty: f64, tz: f64) -> Point3 {
        Point3::new(
            self.x_interval().parameter_at(tx),
            self.y_interval().parameter_at(ty),
            self.z_interval().parameter_at(tz),
        )
    }

    /// The point of the box closest to `p` (`p` itself when inside). For an empty box the
    /// result is not finite.
    #[inline]
    pub fn closest_point(&self, p: Point3) -> Point3 {
        Point3::new(
            p.x.max(self.min.x).min(self.max.x),
            p.y.max(self.min.y).min(self.max.y),
            p.z.max(self.min.z).min(self.max.z),
        )
    }

    /// The box grown by `amount` on every side (shrunk for a negative amount, possibly to
    /// empty). The empty box stays empty.
    pub fn inflated(&self, amount: f64) -> Self {
        if self.is_empty() {
            return *self;
        }
        let d = Vector3::new(amount, amount, amount);
        Self {
            min: self.min - d,
            max: self.max + d,
        }
    }

    /// How many of the three sizes are at most `tolerance`: 0 for a solid box, 1 for a
    /// rectangle, 2 for a segment, 3 for a point (Rhino's `IsDegenerate`), or `None` for an
    /// empty or non-finite box.
    pub fn degeneracy(&self, tolerance: f64) -> Option<usize> {
        if !self.is_valid() {
            return None;
        }
        let d = self.diagonal();
        Some([d.x, d.y, d.z].iter().filter(|&&s| s <= tolerance).count())
    }

    /// The box as an [`OrientedBox`] on the world XY plane.
    #[inline]
    pub fn to_oriented_box(&self) -> OrientedBox {
        OrientedBox::from_bounding_box(self)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Transform;

    fn unit_box() -> BoundingBox {
        BoundingBox::new(Point3::new(1.0, 2.0, 3.0), Point3::new(0.0, 0.0, 0.0))
    }

    #[test]
    fn new_sorts_corners() {
        let b = unit_box();
        assert_eq!(b.min, Point3::ORIGIN);
        assert_eq!(b.max, Point3::new(1.0, 2.0, 3.0));
        assert!(b.is_valid());
        assert_eq!(b.center(), Point3::new(0.5, 1.0, 1.5));
        assert_eq!(b.diagonal(), Vector3::new(1.0, 2.0, 3.0));
        assert_eq!(b.area(), 2.0 * (2.0 + 6.0 + 3.0));
        assert_eq!(b.volume(), 6.0);
    }

    #[test]
    fn corners_in_rhino_order() {
        let c = unit_box().corners();
        assert_eq!(c[0], Point3::new(0.0, 0.0, 0.0));
        assert_eq!(c[1], Point3::new(1.0, 0.0, 0.0));
        assert_eq!(c[2], Point3::new(1.0, 2.0, 0.0));
        assert_eq!(c[3], Point3::new(0.0, 2.0, 0.0));
        assert_eq!(c[4], Point3::new(0.0, 0.0, 3.0));
        assert_eq!(c[5], Point3::new(1.0, 0.0, 3.0));
        assert_eq!(c[6], Point3::new(1.0, 2.0, 3.0));
        assert_eq!(c[7], Point3::new(0.0, 2.0, 3.0));
    }

    #[test]
    fn empty_box_behaviour() {
        let e = BoundingBox::EMPTY;
        assert!(e.is_empty() && !e.is_valid());
        assert_eq!(e.union(&unit_box()), unit_box());
        assert_eq!(unit_box().union(&e), unit_box());
        assert_eq!(e.area(), 0.0);
        assert_eq!(e.volume(), 0.0);
        assert_eq!(e.degeneracy(0.0), None);
        assert!(unit_box().contains(&e));
        assert!(!e.contains_point(Point3::ORIGIN));
        assert_eq!(e.transformed(&Transform::IDENTITY), e);
        assert_eq!(e.inflated(1.0), e);
        assert_eq!(BoundingBox::from_points(&[]), Ok(e));
        assert_eq!(BoundingBox::default(), e);
    }

    #[test]
    fn from_points_reports_nan() {
        let pts = [
            Point3::new(1.0, -1.0, 0.0),
            Point3::new(-2.0, 5.0, 1.0),
            Point3::new(0.0, 0.0, -3.0),
        ];
        let b = BoundingBox::from_points(&pts).unwrap();
        assert_eq!(b.min, Point3::new(-2.0, -1.0, -3.0));
        assert_eq!(b.max, Point3::new(1.0, 5.0, 1.0));
        assert!(pts.iter().all(|&p| b.contains_point(p)));
        assert_eq!(
            BoundingBox::from_points(&[Point3::ORIGIN, Point3::new(f64::NAN, 0.0, 0.0)]),
            Err(Error::NotFinite { what: "point" })
        );
    }

    #[test]
    fn union_intersection_contains() {
        let a = unit_box();
        let b = BoundingBox::new(Point3::new(0.5, 1.0, -1.0), Point3::new(4.0, 4.0, 1.0));
        let u = a.union(&b);
        assert_eq!(u.min, Point3::new(0.0, 0.0, -1.0));
        assert_eq!(u.max, Point3::new(4.0, 4.0, 3.0));
        assert!(u.contains(&a) && u.contains(&b));
        let i = a.intersection(&b);
        assert_eq!(i.min, Point3::new(0.5, 1.0, 0.0));
        assert_eq!(i.max, Point3::new(1.0, 2.0, 1.0));
        let far = BoundingBox::new(Point3::new(9.0, 9.0, 9.0), Point3::new(10.0, 10.0, 10.0));
        assert!(a.intersection(&far).is_empty());
        assert!(a.contains_point(Point3::new(1.0, 2.0, 3.0)));
        assert!(!a.contains_point_strictly(Point3::new(1.0, 2.0, 3.0)));
        assert!(a.contains_point_strictly(Point3::new(0.5, 0.5, 0.5)));
        assert!(!a.contains_point(Point3::new(0.5, 0.5, f64::NAN)));
    }

    #[test]
    fn point_at_closest_point_inflate_degeneracy() {
        let a = unit_box();
        assert_eq!(a.point_at(0.5, 0.5, 1.0), Point3::new(0.5, 1.0, 3.0));
        assert_eq!(
            a.closest_point(Point3::new(5.0, -1.0, 1.0)),
            Point3::new(1.0, 0.0, 1.0)
        );
        let grown = a.inflated(1.0);
        assert_eq!(grown.min, Point3::new(-1.0, -1.0, -1.0));
        assert_eq!(grown.max, Point3::new(2.0, 3.0, 4.0));
        assert!(a.inflated(-1.0).is_empty());
        assert_eq!(a.degeneracy(0.0), Some(0));
        let flat = BoundingBox::new(Point3::ORIGIN, Point3::new(1.0, 1.0, 0.0));
        assert_eq!(flat.degeneracy(0.0), Some(1));
        let point = BoundingBox::new(Point3::ORIGIN, Point3::ORIGIN);
        assert_eq!(point.degeneracy(0.0), Some(3));
        assert_eq!(a.degeneracy(1.5), Some(1));
    }

    #[test]
    fn transformed_is_bbox_of_transformed_corners() {
        let a = unit_box();
        let moved = a.transformed(&Transform::translation(Vector3::new(1.0, 1.0, 1.0)));
        assert_eq!(moved.min, Point3::new(1.0, 1.0, 1.0));
        assert_eq!(moved.max, Point3::new(2.0, 3.0, 4.0));
        let turned = a.transformed(&Transform::rotation_z(std::f64::consts::FRAC_PI_2));
        assert_eq!(turned.min, Point3::new(-2.0, 0.0, 0.0));
        assert_eq!(turned.max, Point3::new(0.0, 1.0, 3.0));
        let r = Transform::rotation_z(0.3);
        let t = a.transformed(&r);
        for c in a.corners() {
            assert!(t.inflated(1e-15).contains_point(r.transform_point(c)));
        }
        assert_eq!(a.to_oriented_box().bounding_box(), a);
        assert_eq!(a.x_interval(), Interval::new(0.0, 1.0));
    }
}

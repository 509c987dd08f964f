//! Transforms applied to the elements of `geometry`: planes, boxes and vectors. They live here,
//! beside the transforms, so that `geometry` does not depend on `transform`.

use crate::{BoundingBox, Error, OrientedBox, Plane, Point3, Result, Transform, Vector3};

impl Plane {
    /// The plane transformed as Rhino transforms planes (`ON_Plane::Transform`).
    ///
    /// The origin is transformed as a point and the x and y axes as vectors (for projective
    /// transforms, as differences of transformed points); the result is then rebuilt with
    /// [`from_frame`](Self::from_frame): the x axis is the unit image of the x axis, the y axis
    /// the image of the y axis made perpendicular to it, and the normal their cross product.
    /// The plane therefore stays orthonormal and right-handed under every transform: under a
    /// mirror its normal is `x′ × y′`, the reverse of the mirrored normal, and under a shear or
    /// a non-uniform scale the axes are re-orthonormalized. The identity returns the plane
    /// unchanged, bit for bit.
    ///
    /// # Errors
    /// [`Error::NotFinite`] if the transform has a NaN or infinite entry,
    /// [`Error::DegenerateTransformResult`] when the transform collapses the x or y axis or makes
    /// them parallel (a projection onto a plane perpendicular to this one, a zero scale).
    pub fn transformed(&self, xform: &Transform) -> Result<Self> {
        if !xform.is_finite() {
            return Err(Error::NotFinite { what: "transform" });
        }
        if *xform == Transform::IDENTITY {
            return Ok(*self);
        }
        let origin = xform.transform_point(self.origin);
        let (x_dir, y_dir) = if xform.is_affine() {
            (
                xform.transform_vector(self.x_axis),
                xform.transform_vector(self.y_axis),
            )
        } else {
            (
                xform.transform_point(self.origin + self.x_axis) - origin,
                xform.transform_point(self.origin + self.y_axis) - origin,
            )
        };
        Self::from_frame(origin, x_dir, y_dir).map_err(|err| match err {
            Error::NotFinite { .. } => err,
            _ => Error::DegenerateTransformResult { what: "plane" },
        })
    }
}

impl BoundingBox {
    /// The bounding box of the eight transformed corners (Rhino's `BoundingBox.Transform`).
    ///
    /// This contains the transformed box, and is the tightest axis-aligned box that does for
    /// affine transforms; after a rotation it is in general larger than the rotated box (use
    /// [`OrientedBox`] to keep the orientation). The empty box stays empty.
    pub fn transformed(&self, xform: &Transform) -> Self {
        if self.is_empty() {
            return Self::EMPTY;
        }
        let mut res = Self::EMPTY;
        for corner in self.corners() {
            res.include_point(xform.transform_point(corner));
        }
        res
    }
}

impl OrientedBox {
    /// The box transformed as Rhino's `Box.Transform`: the plane is transformed as
    /// [`Plane::transformed`] (and so stays orthonormal and right-handed) and the new
    /// intervals are the ranges of the eight transformed corners' coordinates in it.
    ///
    /// For similarities (rigid motions, uniform scales, mirrors) the result is exactly the
    /// transformed box. For shears and non-uniform scales that do not follow the box's axes the
    /// transformed solid is not a box; the result is then the smallest box on the transformed
    /// plane that contains it.
    ///
    /// # Errors
    /// As [`Plane::transformed`]: [`Error::DegenerateTransformResult`] when the transform
    /// collapses the plane's x or y axis, [`Error::NotFinite`] for a non-finite transform.
    pub fn transformed(&self, xform: &Transform) -> Result<Self> {
        let plane = self.plane.transformed(xform)?;
        let mut corners = self.corners();
        xform.transform_points(&mut corners);
        Self::from_points_in_plane(&plane, &corners)
    }
}

impl Vector3 {
    /// The vector rotated by `angle` radians about `axis` (counter-clockwise seen from the tip
    /// of the axis), as Grasshopper's *Rotate* vector component.
    ///
    /// # Errors
    /// As [`Transform::rotation`].
    pub fn rotated(self, angle: f64, axis: Self) -> Result<Self> {
        if !self.is_finite() {
            return Err(Error::NotFinite { what: "vector" });
        }
        let rotation = Transform::rotation(angle, axis, Point3::ORIGIN)?;
        Ok(rotation.transform_vector(self))
    }
}

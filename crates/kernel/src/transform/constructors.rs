//! The constructors of [`Transform`] for the transformations of chapter 2 of the book, each
//! reproducing the matrix of the Rhino function named in its documentation.

use glam::{DMat3, DVec3};

use crate::geometry::tolerance::SQRT_EPSILON;
use crate::{Error, Plane, Point3, Result, Transform, Vector3};

impl Transform {
    /// The rotation by `angle` radians about the line through `center` along `axis`,
    /// counter-clockwise seen from the tip of the axis (right-hand rule).
    ///
    /// The matrix is Rhino's, entry for entry, including its clean-up of the sine and cosine
    /// (see [`rotation_sin_cos`](Self::rotation_sin_cos)): quarter and half turns have exact
    /// zeros and ones, and angles within [`SQRT_EPSILON`] of a multiple of 2π give the exact
    /// identity.
    ///
    /// # Errors
    /// [`Error::ZeroLength`] if the axis has zero length, [`Error::NotFinite`] for a NaN or
    /// infinite angle, axis or centre.
    pub fn rotation(angle: f64, axis: Vector3, center: Point3) -> Result<Self> {
        if !angle.is_finite() {
            return Err(Error::NotFinite { what: "angle" });
        }
        Self::rotation_sin_cos(angle.sin(), angle.cos(), axis, center)
    }

    /// The rotation whose angle has sine `sin` and cosine `cos`, about the line through
    /// `center` along `axis` (Rhino's `ON_Xform::Rotation(sin, cos, axis, center)`).
    ///
    /// As Rhino, the pair is first cleaned of noise: when `|sin| ≥ 1 − √ε` and `|cos| ≤ √ε` (or
    /// the other way round) it becomes an exact quarter turn (or an exact multiple of a half
    /// turn), with `√ε` = [`SQRT_EPSILON`]; a pair that is not on the unit circle to within
    /// `√ε` is normalized; and after that, components within machine epsilon of 0 or ±1 are
    /// snapped again. The matrix is then the Rodrigues rotation
    /// `R = cos·I + sin·[a]× + (1 − cos)·a aᵀ` of the unit axis `a`, with translation
    /// `center − R·center`.
    ///
    /// # Errors
    /// [`Error::ZeroLength`] if the axis has zero length, [`Error::InvalidInput`] if both
    /// `sin` and `cos` are zero, [`Error::NotFinite`] for NaN or infinite input.
    pub fn rotation_sin_cos(sin: f64, cos: f64, axis: Vector3, center: Point3) -> Result<Self> {
        if !sin.is_finite() || !cos.is_finite() {
            return Err(Error::NotFinite { what: "angle" });
        }
        if !axis.is_finite() {
            return Err(Error::NotFinite { what: "axis" });
        }
        if !center.is_finite() {
            return Err(Error::NotFinite { what: "center" });
        }
        let (s, c) = clean_sin_cos(sin, cos)?;
        let mut a = axis;
        if (a.length_squared() - 1.0).abs() > f64::EPSILON {
            a = a
                .try_normalize()
                .ok_or(Error::ZeroLength { what: "axis" })?;
        }
        if s == 0.0 && c == 1.0 {
            return Ok(Self::IDENTITY);
        }
        let t = 1.0 - c;
        // Row-major entries of the Rodrigues matrix, each written in the order of evaluation
        // openNURBS uses so that the rounding is the same.
        let r = [
            [
                a.x * a.x * t + c,
                a.x * a.y * t - a.z * s,
                a.x * a.z * t + a.y * s,
            ],
            [
                a.y * a.x * t + a.z * s,
                a.y * a.y * t + c,
                a.y * a.z * t - a.x * s,
            ],
            [
                a.z * a.x * t - a.y * s,
                a.z * a.y * t + a.x * s,
                a.z * a.z * t + c,
            ],
        ];
        let p = center;
        let translation = if p.x != 0.0 || p.y != 0.0 || p.z != 0.0 {
            // center − R·center, row by row.
            DVec3::new(
                -((r[0][0] - 1.0) * p.x + r[0][1] * p.y + r[0][2] * p.z),
                -(r[1][0] * p.x + (r[1][1] - 1.0) * p.y + r[1][2] * p.z),
                -(r[2][0] * p.x + r[2][1] * p.y + (r[2][2] - 1.0) * p.z),
            )
        } else {
            DVec3::ZERO
        };
        Ok(Self::from_linear_translation(
            DMat3::from_cols_array_2d(&r).transpose(),
            translation,
        ))
    }

    /// The rotation by `angle` radians about the world x axis (the book's
    /// `[[1,0,0,0],[0,cos,−sin,0],[0,sin,cos,0],[0,0,0,1]]`), cleaned as
    /// [`rotation`](Self::rotation). A non-finite angle gives a matrix of NaN.
    pub fn rotation_x(angle: f64) -> Self {
        Self::rotation(angle, Vector3::X, Point3::ORIGIN).unwrap_or(Self::NAN)
    }

    /// The rotation by `angle` radians about the world y axis (the book's
    /// `[[cos,0,sin,0],[0,1,0,0],[−sin,0,cos,0],[0,0,0,1]]`), cleaned as
    /// [`rotation`](Self::rotation). A non-finite angle gives a matrix of NaN.
    pub fn rotation_y(angle: f64) -> Self {
        Self::rotation(angle, Vector3::Y, Point3::ORIGIN).unwrap_or(Self::NAN)
    }

    /// The rotation by `angle` radians about the world z axis (the book's
    /// `[[cos,−sin,0,0],[sin,cos,0,0],[0,0,1,0],[0,0,0,1]]`), cleaned as
    /// [`rotation`](Self::rotation). A non-finite angle gives a matrix of NaN.
    pub fn rotation_z(angle: f64) -> Self {
        Self::rotation(angle, Vector3::Z, Point3::ORIGIN).unwrap_or(Self::NAN)
    }

    /// The rotation about `center` that turns the direction `start` into the direction `end`,
    /// about the axis `start × end` (Rhino's `Rotation(startDirection, endDirection, center)`).
    ///
    /// For parallel directions it is the identity; for opposite directions, a half turn about
    /// the axis [`Vector3::perpendicular`] to `start`.
    ///
    /// # Errors
    /// [`Error::ZeroLength`] if either direction has zero length, [`Error::NotFinite`] for NaN
    /// or infinite input.
    pub fn rotation_between(start: Vector3, end: Vector3, center: Point3) -> Result<Self> {
        let s = start.unitize()?;
        let e = end.unitize()?;
        let cos = s.dot(e);
        let axis = s.cross(e);
        let sin = axis.length();
        match axis.try_normalize() {
            Some(unit_axis) if sin != 0.0 => Self::rotation_sin_cos(sin, cos, unit_axis, center),
            _ => {
                let perpendicular = s
                    .perpendicular()
                    .ok_or(Error::ZeroLength { what: "vector" })?;
                let half_or_none = if cos < 0.0 { -1.0 } else { 1.0 };
                Self::rotation_sin_cos(0.0, half_or_none, perpendicular, center)
            }
        }
    }

    /// The uniform scale by `factor` about `center` (Rhino's `Scale(anchor, factor)`):
    /// `P′ = center + factor (P − center)`.
    pub fn scale(center: Point3, factor: f64) -> Self {
        let diagonal =
            Self::from_linear_translation(DMat3::from_diagonal(DVec3::splat(factor)), DVec3::ZERO);
        if center == Point3::ORIGIN {
            diagonal
        } else {
            let c = center.to_vector();
            Self::translation(c) * diagonal * Self::translation(-c)
        }
    }

    /// The non-uniform scale about `plane` by `x`, `y` and `z` along its axes (Rhino's
    /// `Scale(plane, x, y, z)`): the plane's origin is fixed and a point at plane coordinates
    /// `(u, v, w)` goes to `(x·u, y·v, z·w)`.
    pub fn scale_non_uniform(plane: &Plane, x: f64, y: f64, z: f64) -> Self {
        Self::shear(plane, plane.x_axis * x, plane.y_axis * y, plane.z_axis * z)
    }

    /// The shear (more generally, the affine map) that fixes the origin of `plane` and sends
    /// its x, y and z axes to the vectors `x`, `y` and `z` (Rhino's
    /// `Transform.Shear(plane, x, y, z)`, openNURBS `ON_Xform::Shear`).
    ///
    /// A point at plane coordinates `(u, v, w)` goes to `origin + u·x + v·y + w·z`. The book's
    /// shear along x keeping y and z is `shear(&Plane::WORLD_XY, X, Y + k·X, Z)`, say, and
    /// `shear(plane, X, Y, Z)` with the plane's own axes is the identity.
    pub fn shear(plane: &Plane, x: Vector3, y: Vector3, z: Vector3) -> Self {
        let to_plane = DMat3::from_cols(
            plane.x_axis.to_dvec3(),
            plane.y_axis.to_dvec3(),
            plane.z_axis.to_dvec3(),
        )
        .transpose();
        let to_images = DMat3::from_cols(x.to_dvec3(), y.to_dvec3(), z.to_dvec3());
        let o = plane.origin.to_vector();
        Self::translation(o)
            * Self::from_linear_translation(to_images, DVec3::ZERO)
            * Self::from_linear_translation(to_plane, DVec3::ZERO)
            * Self::translation(-o)
    }

    /// The reflection across `plane` (Rhino's `Transform.Mirror(plane)`): `P′ = P − 2 d n`
    /// with `d` the signed distance of `P` to the plane and `n` its unit normal. Its linear
    /// part has determinant −1, and [`Plane::transformed`] keeps mirrored planes right-handed.
    pub fn mirror(plane: &Plane) -> Self {
        mirror_matrix(plane.origin, plane.z_axis)
    }

    /// The reflection across the plane through `point` with normal `normal` (Rhino's
    /// `Transform.Mirror(point, normal)`); the normal need not be a unit vector.
    ///
    /// # Errors
    /// [`Error::ZeroLength`] if the normal has zero length, [`Error::NotFinite`] for NaN or
    /// infinite input.
    pub fn mirror_about(point: Point3, normal: Vector3) -> Result<Self> {
        if !point.is_finite() {
            return Err(Error::NotFinite { what: "point" });
        }
        let n = normal.unitize().map_err(|err| match err {
            Error::ZeroLength { .. } => Error::ZeroLength { what: "normal" },
            _ => Error::NotFinite { what: "normal" },
        })?;
        Ok(mirror_matrix(point, n))
    }

    /// The orthogonal projection onto `plane` (Rhino's `PlanarProjection`): every point goes to
    /// its [`Plane::closest_point`]. The book's projection onto world XY sets z to 0. It is
    /// singular and has no inverse.
    pub fn planar_projection(plane: &Plane) -> Self {
        let x = plane.x_axis.to_array();
        let y = plane.y_axis.to_array();
        let p = plane.origin.to_array();
        let mut rows = [[0.0; 4]; 4];
        for i in 0..3 {
            for j in 0..3 {
                rows[i][j] = x[i] * x[j] + y[i] * y[j];
            }
            let q = rows[i][0] * p[0] + rows[i][1] * p[1] + rows[i][2] * p[2];
            rows[i][3] = p[i] - q;
        }
        rows[3][3] = 1.0;
        Self::from_rows(rows)
    }

    /// The rigid motion (or, between planes of opposite handedness, the motion and mirror)
    /// that moves `from` onto `to`: its origin to `to`'s origin and its axes onto `to`'s axes
    /// (Rhino's `Transform.PlaneToPlane`, Grasshopper's *Orient*). A point keeps its plane
    /// coordinates: `from.point_at(u, v, w)` goes to `to.point_at(u, v, w)`.
    pub fn plane_to_plane(from: &Plane, to: &Plane) -> Self {
        let to_world = DMat3::from_cols(
            from.x_axis.to_dvec3(),
            from.y_axis.to_dvec3(),
            from.z_axis.to_dvec3(),
        )
        .transpose();
        let to_target = DMat3::from_cols(
            to.x_axis.to_dvec3(),
            to.y_axis.to_dvec3(),
            to.z_axis.to_dvec3(),
        );
        let rotation = Self::from_linear_translation(to_target, DVec3::ZERO)
            * Self::from_linear_translation(to_world, DVec3::ZERO);
        Self::translation(to.origin.to_vector())
            * rotation
            * Self::translation(-from.origin.to_vector())
    }

    /// The change of coordinates from `from` to `to` (Rhino's `ChangeBasis(plane0, plane1)`):
    /// it maps the *coordinates* `(a, b, c)` of a point in `from` to its coordinates in `to`, so
    /// that `from.point_at(a, b, c) == to.point_at(a′, b′, c′)`. With `from` the world XY plane
    /// it turns world coordinates into `to`'s coordinates.
    ///
    /// This is not [`plane_to_plane`](Self::plane_to_plane), which moves geometry: with
    /// `F(p) = plane_to_plane(&Plane::WORLD_XY, p)` the map from a plane's coordinates to world
    /// coordinates, `change_basis(from, to)` is `F(to)⁻¹ · F(from)` while
    /// `plane_to_plane(from, to)` is `F(to) · F(from)⁻¹`. Rhino solves for arbitrary bases;
    /// for our orthonormal planes `F(to)⁻¹` is its transpose, which is what is used here.
    pub fn change_basis(from: &Plane, to: &Plane) -> Self {
        let from_frame = Self::from_linear_translation(
            DMat3::from_cols(
                from.x_axis.to_dvec3(),
                from.y_axis.to_dvec3(),
                from.z_axis.to_dvec3(),
            ),
            from.origin.to_dvec3(),
        );
        let to_coordinates = Self::from_linear_translation(
            DMat3::from_cols(
                to.x_axis.to_dvec3(),
                to.y_axis.to_dvec3(),
                to.z_axis.to_dvec3(),
            )
            .transpose(),
            DVec3::ZERO,
        );
        to_coordinates * Self::translation(-to.origin.to_vector()) * from_frame
    }
}

/// Rhino's clean-up of a rotation's sine and cosine (`ON_Xform::Rotation`): exact quarter and
/// half turns, and a pair put back on the unit circle. Returns `(sin, cos)`.
fn clean_sin_cos(sin: f64, cos: f64) -> Result<(f64, f64)> {
    let sign = |x: f64| if x < 0.0 { -1.0 } else { 1.0 };
    let (mut s, mut c) = (sin, cos);
    if s.abs() >= 1.0 - SQRT_EPSILON && c.abs() <= SQRT_EPSILON {
        return Ok((sign(s), 0.0));
    }
    if c.abs() >= 1.0 - SQRT_EPSILON && s.abs() <= SQRT_EPSILON {
        return Ok((0.0, sign(c)));
    }
    if (c * c + s * s - 1.0).abs() > SQRT_EPSILON {
        let length = c.hypot(s);
        if length == 0.0 {
            return Err(Error::InvalidInput(
                "rotation sine and cosine are both zero".to_owned(),
            ));
        }
        c /= length;
        s /= length;
    }
    if c.abs() > 1.0 - f64::EPSILON || s.abs() < f64::EPSILON {
        return Ok((0.0, sign(c)));
    }
    if s.abs() > 1.0 - f64::EPSILON || c.abs() < f64::EPSILON {
        return Ok((sign(s), 0.0));
    }
    Ok((s, c))
}

/// The mirror matrix across the plane through `p` with unit normal `n`, with each entry written
/// as openNURBS's `ON_Xform::Mirror` evaluates it.
fn mirror_matrix(p: Point3, n: Vector3) -> Transform {
    let v = n * (2.0 * (n.x * p.x + n.y * p.y + n.z * p.z));
    Transform::from_rows([
        [
            1.0 - 2.0 * n.x * n.x,
            -2.0 * n.x * n.y,
            -2.0 * n.x * n.z,
            v.x,
        ],
        [
            -2.0 * n.y * n.x,
            1.0 - 2.0 * n.y * n.y,
            -2.0 * n.y * n.z,
            v.y,
        ],
        [
            -2.0 * n.z * n.x,
            -2.0 * n.z * n.y,
            1.0 - 2.0 * n.z * n.z,
            v.z,
        ],
        [0.0, 0.0, 0.0, 1.0],
    ])
}

#[cfg(test)]
pub(super) mod tests {
    use std::f64::consts::{FRAC_PI_2, PI};

    use super::*;

    /// Asserts that every entry of `t` is within `tol` of `expected` (row-major).
    pub(crate) fn assert_rows_near(t: &Transform, expected: [[f64; 4]; 4], tol: f64) {
        let rows = t.to_rows();
        for i in 0..4 {
            for j in 0..4 {
                assert!(
                    (rows[i][j] - expected[i][j]).abs() <= tol,
                    "entry [{i}][{j}] is {} not {}\n{rows:?}",
                    rows[i][j],
                    expected[i][j]
                );
            }
        }
    }

    #[test]
    fn quarter_turns_are_exact() {
        assert_rows_near(
            &Transform::rotation_z(FRAC_PI_2),
            [
                [0.0, -1.0, 0.0, 0.0],
                [1.0, 0.0, 0.0, 0.0],
                [0.0, 0.0, 1.0, 0.0],
                [0.0, 0.0, 0.0, 1.0],
            ],
            0.0,
        );
        assert_rows_near(
            &Transform::rotation_x(PI),
            [
                [1.0, 0.0, 0.0, 0.0],
                [0.0, -1.0, 0.0, 0.0],
                [0.0, 0.0, -1.0, 0.0],
                [0.0, 0.0, 0.0, 1.0],
            ],
            0.0,
        );
        assert_eq!(Transform::rotation_y(2.0 * PI), Transform::IDENTITY);
        assert_eq!(Transform::rotation_y(1e-9), Transform::IDENTITY);
        assert!(!Transform::rotation_y(f64::NAN).is_finite());
    }

    #[test]
    fn book_axis_rotations() {
        let b = 0.3f64;
        let (s, c) = b.sin_cos();
        assert_rows_near(
            &Transform::rotation_x(b),
            [
                [1.0, 0.0, 0.0, 0.0],
                [0.0, c, -s, 0.0],
                [0.0, s, c, 0.0],
                [0.0, 0.0, 0.0, 1.0],
            ],
            1e-16,
        );
        assert_rows_near(
            &Transform::rotation_y(b),
            [
                [c, 0.0, s, 0.0],
                [0.0, 1.0, 0.0, 0.0],
                [-s, 0.0, c, 0.0],
                [0.0, 0.0, 0.0, 1.0],
            ],
            1e-16,
        );
    }

    #[test]
    fn rotation_about_a_centre_fixes_the_axis() {
        let center = Point3::new(1.0, -1.0, 2.0);
        let axis = Vector3::new(1.0, 2.0, 3.0);
        let r = Transform::rotation(0.7, axis, center).unwrap();
        for t in [-2.0, 0.0, 3.5] {
            let on_axis = center + axis * t;
            assert!(r.transform_point(on_axis).abs_diff_eq(on_axis, 1e-14));
        }
        assert!((r.linear_determinant() - 1.0).abs() < 1e-15);
        assert!(r.is_similarity(1e-12));
        assert_eq!(
            Transform::rotation(1.0, Vector3::ZERO, center),
            Err(Error::ZeroLength { what: "axis" })
        );
        assert_eq!(
            Transform::rotation(f64::INFINITY, axis, center),
            Err(Error::NotFinite { what: "angle" })
        );
        assert!(Transform::rotation_sin_cos(0.0, 0.0, axis, center).is_err());
    }

    #[test]
    fn rotation_between_directions() {
        let c = Point3::new(1.0, 2.0, 3.0);
        let a = Vector3::new(1.0, 1.0, 0.0);
        let b = Vector3::new(0.0, -2.0, 5.0);
        let r = Transform::rotation_between(a, b, c).unwrap();
        let image = r.transform_vector(a.unitize().unwrap());
        assert!(image.abs_diff_eq(b.unitize().unwrap(), 1e-15));
        assert_eq!(r.transform_point(c), c);
        let half = Transform::rotation_between(a, -a * 3.0, c).unwrap();
        assert!(half.transform_vector(a).abs_diff_eq(-a, 1e-15));
        assert_eq!(
            Transform::rotation_between(a, a * 2.0, c).unwrap(),
            Transform::IDENTITY
        );
        assert!(Transform::rotation_between(Vector3::ZERO, a, c).is_err());
    }

    #[test]
    fn scale_about_centre_and_plane() {
        let s = Transform::scale(Point3::new(1.0, 2.0, 3.0), 2.0);
        assert_rows_near(
            &s,
            [
                [2.0, 0.0, 0.0, -1.0],
                [0.0, 2.0, 0.0, -2.0],
                [0.0, 0.0, 2.0, -3.0],
                [0.0, 0.0, 0.0, 1.0],
            ],
            0.0,
        );
        let plane =
            Plane::from_normal(Point3::new(1.0, 0.0, 0.0), Vector3::new(0.0, 1.0, 1.0)).unwrap();
        let ns = Transform::scale_non_uniform(&plane, 2.0, 3.0, -0.5);
        let p = plane.point_at(1.0, -2.0, 4.0);
        assert!(
            ns.transform_point(p)
                .abs_diff_eq(plane.point_at(2.0, -6.0, -2.0), 1e-14)
        );
        assert!(!ns.is_similarity(1e-9));
        assert!(Transform::scale(Point3::ORIGIN, -3.0).is_similarity(1e-15));
    }

    #[test]
    fn shear_maps_axes_to_the_given_vectors() {
        let plane = Plane::from_frame(
            Point3::new(2.0, 0.0, 1.0),
            Vector3::new(1.0, 1.0, 0.0),
            Vector3::new(0.0, 0.0, 1.0),
        )
        .unwrap();
        let (x, y, z) = (
            Vector3::new(1.0, 0.0, 0.0),
            Vector3::new(1.0, 1.0, 1.0),
            Vector3::new(0.0, 2.0, 0.0),
        );
        let s = Transform::shear(&plane, x, y, z);
        assert!(
            s.transform_point(plane.origin)
                .abs_diff_eq(plane.origin, 1e-15)
        );
        assert!(s.transform_vector(plane.x_axis).abs_diff_eq(x, 1e-15));
        assert!(s.transform_vector(plane.y_axis).abs_diff_eq(y, 1e-15));
        assert!(s.transform_vector(plane.z_axis).abs_diff_eq(z, 1e-15));
        let same = Transform::shear(&plane, plane.x_axis, plane.y_axis, plane.z_axis);
        assert!(same.is_identity(1e-15));
        // The book's shear in x along y, keeping z: x' = x + k y.
        let k = 0.5;
        let book = Transform::shear(
            &Plane::WORLD_XY,
            Vector3::X,
            Vector3::new(k, 1.0, 0.0),
            Vector3::Z,
        );
        assert_eq!(
            book.transform_point(Point3::new(1.0, 2.0, 3.0)),
            Point3::new(2.0, 2.0, 3.0)
        );
    }

    #[test]
    fn mirror_and_projection() {
        let m = Transform::mirror(&Plane::WORLD_XY);
        assert_rows_near(
            &m,
            [
                [1.0, 0.0, 0.0, 0.0],
                [0.0, 1.0, 0.0, 0.0],
                [0.0, 0.0, -1.0, 0.0],
                [0.0, 0.0, 0.0, 1.0],
            ],
            0.0,
        );
        assert!((m.linear_determinant() + 1.0).abs() < 1e-15);
        let plane =
            Plane::from_normal(Point3::new(0.0, 0.0, 2.0), Vector3::new(1.0, 1.0, 1.0)).unwrap();
        let p = Point3::new(3.0, -1.0, 4.0);
        let mirrored = Transform::mirror(&plane).transform_point(p);
        assert!((plane.signed_distance_to(mirrored) + plane.signed_distance_to(p)).abs() < 1e-14);
        assert!(
            plane
                .closest_point(mirrored)
                .abs_diff_eq(plane.closest_point(p), 1e-14)
        );
        let projected = Transform::planar_projection(&plane).transform_point(p);
        assert!(projected.abs_diff_eq(plane.closest_point(p), 1e-14));
        assert_rows_near(
            &Transform::planar_projection(&Plane::WORLD_XY),
            [
                [1.0, 0.0, 0.0, 0.0],
                [0.0, 1.0, 0.0, 0.0],
                [0.0, 0.0, 0.0, 0.0],
                [0.0, 0.0, 0.0, 1.0],
            ],
            0.0,
        );
        assert_eq!(
            Transform::mirror_about(Point3::ORIGIN, Vector3::ZERO),
            Err(Error::ZeroLength { what: "normal" })
        );
    }

    #[test]
    fn plane_to_plane_keeps_plane_coordinates() {
        let from = Plane::from_points(
            Point3::new(1.0, 2.0, 3.0),
            Point3::new(2.0, 2.0, 4.0),
            Point3::new(0.0, 5.0, 3.0),
        )
        .unwrap();
        let to =
            Plane::from_normal(Point3::new(-4.0, 0.5, 1.0), Vector3::new(0.0, 1.0, -2.0)).unwrap();
        let orient = Transform::plane_to_plane(&from, &to);
        let q = from.point_at(1.5, -2.0, 0.75);
        assert!(
            orient
                .transform_point(q)
                .abs_diff_eq(to.point_at(1.5, -2.0, 0.75), 1e-14)
        );
        let moved = orient.transform_plane(&from).unwrap();
        assert!(moved.abs_diff_eq(&to, 1e-14));
        let basis = Transform::change_basis(&from, &to);
        let [a, b, c] = to.local_coordinates(from.point_at(1.5, -2.0, 0.75));
        assert!(
            basis
                .transform_point(Point3::new(1.5, -2.0, 0.75))
                .abs_diff_eq(Point3::new(a, b, c), 1e-14)
        );
        let world = Transform::change_basis(&Plane::WORLD_XY, &to);
        let [u, v, w] = to.local_coordinates(q);
        assert!(
            world
                .transform_point(q)
                .abs_diff_eq(Point3::new(u, v, w), 1e-14)
        );
        let frame = |p: &Plane| Transform::plane_to_plane(&Plane::WORLD_XY, p);
        let composed = frame(&to).inverse().unwrap() * frame(&from);
        let diff = (basis.matrix - composed.matrix).to_cols_array();
        assert!(diff.iter().all(|d| d.abs() < 1e-14), "{diff:?}");
    }
}

//! Editing NURBS surfaces without changing their shape (reparameterizing, reversing,
//! transposing), transforming them, and recognizing collapsed and closed sides.

use crate::geometry::tolerance::ZERO_TOLERANCE;
use crate::surface::direction::{SurfaceDirection, SurfaceSide};
use crate::{Error, Interval, NurbsSurface, Point3, Result, Transform};

impl NurbsSurface {
    /// The same surface with its domains changed to `u` and `v` by a linear map of the knots.
    /// Every point keeps its place: `S'(u', v') = S(u, v)` for corresponding parameters.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] unless both intervals are finite and increasing.
    pub fn reparameterized(&self, u: Interval, v: Interval) -> Result<Self> {
        for (name, d) in [("u", u), ("v", v)] {
            if !d.is_finite() || !d.is_increasing() {
                return Err(Error::InvalidInput(format!(
                    "the new {name} domain {} to {} must be finite and increasing",
                    d.t0, d.t1
                )));
            }
        }
        let mut out = self.clone();
        out.knots_u = remap_knots(&self.knots_u, self.domain_u(), u);
        out.knots_v = remap_knots(&self.knots_v, self.domain_v(), v);
        Ok(out)
    }

    /// The same surface reparameterized to the unit square (Grasshopper's Reparameterize).
    pub fn normalized(&self) -> Self {
        // The unit intervals are valid, so this cannot fail.
        let mut out = self.clone();
        out.knots_u = remap_knots(&self.knots_u, self.domain_u(), Interval::UNIT);
        out.knots_v = remap_knots(&self.knots_v, self.domain_v(), Interval::UNIT);
        out
    }

    /// The surface transformed by `xform`, control point by control point in homogeneous
    /// coordinates (exact for every affine and projective transform).
    ///
    /// # Errors
    /// [`Error::NotFinite`] if the transform is not finite, [`Error::InvalidWeight`] if a
    /// projective transform sends a control point to or behind the plane at infinity.
    pub fn transformed(&self, xform: &Transform) -> Result<Self> {
        if !xform.is_finite() {
            return Err(Error::NotFinite { what: "transform" });
        }
        let m = xform.matrix;
        let affine = m.row(3) == glam::DVec4::new(0.0, 0.0, 0.0, 1.0);
        let mut out = self.clone();
        for (index, (p, w)) in out.points.iter_mut().zip(&mut out.weights).enumerate() {
            if affine {
                *p = xform.transform_point(*p);
            } else {
                let h = m * glam::DVec4::new(p.x * *w, p.y * *w, p.z * *w, *w);
                if !(h.w.is_finite() && h.w > 0.0) {
                    return Err(Error::InvalidWeight { index, weight: h.w });
                }
                *p = Point3::new(h.x / h.w, h.y / h.w, h.z / h.w);
                *w = h.w;
            }
            if !p.is_finite() {
                return Err(Error::NotFinite {
                    what: "transformed control point",
                });
            }
        }
        out.rational = out.weights.iter().any(|&w| w != 1.0);
        Ok(out)
    }

    /// The surface with the given direction reversed, as Rhino's `Reverse`: the knots are
    /// negated and reversed, so the domain `[t0, t1]` becomes `[−t1, −t0]` and the point at
    /// parameter `t` moves to `−t`. Reversing one direction flips the normal.
    pub fn reversed(&self, direction: SurfaceDirection) -> Self {
        let mut out = self.clone();
        let (nu, nv) = (self.count_u, self.count_v);
        for i in 0..nu {
            for j in 0..nv {
                let (si, sj) = match direction {
                    SurfaceDirection::U => (nu - 1 - i, j),
                    SurfaceDirection::V => (i, nv - 1 - j),
                };
                out.points[i * nv + j] = self.points[si * nv + sj];
                out.weights[i * nv + j] = self.weights[si * nv + sj];
            }
        }
        let knots = match direction {
            SurfaceDirection::U => &mut out.knots_u,
            SurfaceDirection::V => &mut out.knots_v,
        };
        knots.reverse();
        for k in knots.iter_mut() {
            *k = -*k;
        }
        out
    }

    /// The surface with `u` and `v` swapped (Rhino's Transpose); the normal flips.
    pub fn transposed(&self) -> Self {
        let (nu, nv) = (self.count_u, self.count_v);
        let mut points = Vec::with_capacity(self.points.len());
        let mut weights = Vec::with_capacity(self.points.len());
        for j in 0..nv {
            for i in 0..nu {
                points.push(self.points[i * nv + j]);
                weights.push(self.weights[i * nv + j]);
            }
        }
        Self {
            degree_u: self.degree_v,
            degree_v: self.degree_u,
            count_u: nv,
            count_v: nu,
            points,
            weights,
            knots_u: self.knots_v.clone(),
            knots_v: self.knots_u.clone(),
            rational: self.rational,
        }
    }

    /// The control points of the boundary curve along one side: the side's row or column of
    /// the grid where the knots are clamped at that end, otherwise the control points of the
    /// boundary isocurve.
    fn side_points(&self, side: SurfaceSide) -> Vec<Point3> {
        let (nu, nv) = (self.count_u, self.count_v);
        let fixed = side.fixed_direction();
        let knots = self.knots(fixed);
        let p = self.degree(fixed);
        let clamped = if side.is_at_end() {
            knots[knots.len() - p..]
                .iter()
                .all(|&k| k == knots[knots.len() - 1])
        } else {
            knots[..p].iter().all(|&k| k == knots[0])
        };
        if !clamped {
            let t = if side.is_at_end() {
                self.domain(fixed).t1
            } else {
                self.domain(fixed).t0
            };
            if let Ok(curve) = self.isocurve(fixed.other(), t) {
                return curve.points().to_vec();
            }
        }
        match side {
            SurfaceSide::South => (0..nu).map(|i| self.points[i * nv]).collect(),
            SurfaceSide::North => (0..nu).map(|i| self.points[i * nv + nv - 1]).collect(),
            SurfaceSide::West => self.points[..nv].to_vec(),
            SurfaceSide::East => self.points[(nu - 1) * nv..].to_vec(),
        }
    }

    /// The point a side collapses to, or `None` when the side is not singular.
    ///
    /// A side is singular when all the control points of its boundary curve coincide within
    /// [`ZERO_TOLERANCE`] (scaled by the size of the coordinates), as at the poles of a sphere
    /// and the apex of a cone (openNURBS's `IsSingular`); the whole side is then that one
    /// point. For knots clamped at that end these are the side's own control points.
    pub fn singular_point(&self, side: SurfaceSide) -> Option<Point3> {
        let pts = self.side_points(side);
        let first = pts[0];
        let scale = 1.0 + first.to_vector().length();
        pts.iter()
            .all(|p| p.distance(first) <= ZERO_TOLERANCE * scale)
            .then_some(first)
    }

    /// Whether the given side is singular (see [`singular_point`](Self::singular_point)).
    #[inline]
    pub fn is_singular(&self, side: SurfaceSide) -> bool {
        self.singular_point(side).is_some()
    }

    /// Whether the surface is closed in the given direction: the boundary curves at the start
    /// and end of that direction coincide (checked on the boundary curves themselves, at the
    /// control points' Greville-like sample parameters, within `tolerance`).
    pub fn is_closed(&self, direction: SurfaceDirection, tolerance: f64) -> bool {
        let (d, other) = (self.domain(direction), self.domain(direction.other()));
        let samples = 2 * self.count(direction.other()) + 3;
        (0..=samples).all(|k| {
            let t = other.parameter_at(k as f64 / samples as f64);
            let (a, b) = match direction {
                SurfaceDirection::U => (self.point_at(d.t0, t), self.point_at(d.t1, t)),
                SurfaceDirection::V => (self.point_at(t, d.t0), self.point_at(t, d.t1)),
            };
            a.distance(b) <= tolerance
        })
    }
}

/// Maps knots linearly so that `from` becomes `to`, with the domain ends exact.
fn remap_knots(knots: &[f64], from: Interval, to: Interval) -> Vec<f64> {
    let scale = to.length() / from.length();
    knots
        .iter()
        .map(|&k| {
            if k == from.t0 {
                to.t0
            } else if k == from.t1 {
                to.t1
            } else {
                to.t0 + (k - from.t0) * scale
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::surface::tests::wavy;
    use crate::{Cone, Cylinder, Plane, Sphere, Vector3};

    fn samples(s: &NurbsSurface) -> impl Iterator<Item = (f64, f64)> + '_ {
        (0..=6).flat_map(move |i| {
            (0..=6).map(move |j| {
                (
                    s.domain_u().parameter_at(i as f64 / 6.0),
                    s.domain_v().parameter_at(j as f64 / 6.0),
                )
            })
        })
    }

    #[test]
    fn reparameterizing_keeps_every_point() {
        let s = wavy(true);
        let r = s
            .reparameterized(Interval::new(10.0, 11.0), Interval::new(-4.0, 4.0))
            .unwrap();
        assert_eq!(r.domain_u(), Interval::new(10.0, 11.0));
        assert_eq!(r.domain_v(), Interval::new(-4.0, 4.0));
        for (u, v) in samples(&s) {
            let nu = 10.0 + s.domain_u().normalized_parameter_at(u).unwrap();
            let nv = -4.0 + 8.0 * s.domain_v().normalized_parameter_at(v).unwrap();
            assert!(r.point_at(nu, nv).distance(s.point_at(u, v)) < 1e-13);
        }
        let n = s.normalized();
        assert_eq!(n.domain_u(), Interval::UNIT);
        assert!(n.point_at(1.0, 1.0).distance(s.point_at(2.0, 3.0)) < 1e-14);
        assert!(
            s.reparameterized(Interval::new(1.0, 0.0), Interval::UNIT)
                .is_err()
        );
        assert!(
            s.reparameterized(Interval::UNIT, Interval::new(0.0, f64::NAN))
                .is_err()
        );
    }

    #[test]
    fn reversing_and_transposing_keep_the_shape_and_flip_the_normal() {
        let s = wavy(true);
        let ru = s.reversed(SurfaceDirection::U);
        let rv = s.reversed(SurfaceDirection::V);
        let t = s.transposed();
        assert_eq!(ru.domain_u(), Interval::new(-2.0, 0.0));
        assert_eq!(rv.domain_v(), Interval::new(-3.0, 1.0));
        for (u, v) in samples(&s) {
            let p = s.point_at(u, v);
            let n = s.normal_at(u, v).unwrap();
            assert!(ru.point_at(-u, v).distance(p) < 1e-13);
            assert!(rv.point_at(u, -v).distance(p) < 1e-13);
            assert!(t.point_at(v, u).distance(p) < 1e-13);
            assert!((ru.normal_at(-u, v).unwrap() + n).length() < 1e-12);
            assert!((t.normal_at(v, u).unwrap() + n).length() < 1e-12);
        }
        assert_eq!(t.transposed(), s);
        assert_eq!(ru.reversed(SurfaceDirection::U), s);
    }

    #[test]
    fn transforms_move_points_exactly() {
        let s = wavy(true);
        let m = Transform::from_rows([
            [0.0, -2.0, 0.0, 1.0],
            [1.0, 0.0, 0.0, 2.0],
            [0.0, 0.0, 3.0, -1.0],
            [0.0, 0.0, 0.0, 1.0],
        ]);
        let moved = s.transformed(&m).unwrap();
        // A projective transform: weights change, the shape maps exactly.
        let persp = Transform::from_rows([
            [1.0, 0.0, 0.0, 0.0],
            [0.0, 1.0, 0.0, 0.0],
            [0.0, 0.0, 1.0, 0.0],
            [0.02, 0.01, 0.0, 1.0],
        ]);
        let projected = s.transformed(&persp).unwrap();
        for (u, v) in samples(&s) {
            let p = s.point_at(u, v);
            assert!(moved.point_at(u, v).distance(m.transform_point(p)) < 1e-13);
            assert!(projected.point_at(u, v).distance(persp.transform_point(p)) < 1e-13);
        }
        let nan = Transform::from_rows([[f64::NAN; 4]; 4]);
        assert!(s.transformed(&nan).is_err());
        let behind = Transform::from_rows([
            [1.0, 0.0, 0.0, 0.0],
            [0.0, 1.0, 0.0, 0.0],
            [0.0, 0.0, 1.0, 0.0],
            [-1.0, 0.0, 0.0, 0.0],
        ]);
        assert!(matches!(
            s.transformed(&behind),
            Err(Error::InvalidWeight { .. })
        ));
    }

    #[test]
    fn singular_and_closed_sides() {
        let sphere = Sphere::new(Point3::new(1.0, 2.0, 3.0), 2.0)
            .unwrap()
            .to_nurbs()
            .unwrap();
        assert_eq!(
            sphere.singular_point(SurfaceSide::South),
            Some(Point3::new(1.0, 2.0, 1.0))
        );
        assert_eq!(
            sphere.singular_point(SurfaceSide::North),
            Some(Point3::new(1.0, 2.0, 5.0))
        );
        assert!(!sphere.is_singular(SurfaceSide::East) && !sphere.is_singular(SurfaceSide::West));
        assert!(sphere.is_closed(SurfaceDirection::U, 1e-12));
        assert!(!sphere.is_closed(SurfaceDirection::V, 1e-12));

        let plane =
            Plane::from_normal(Point3::new(0.5, 1.0, -1.0), Vector3::new(1.0, -1.5, 5.0)).unwrap();
        let cone = Cone::new(plane, 3.0, 1.5).unwrap().to_nurbs().unwrap();
        assert_eq!(cone.singular_point(SurfaceSide::South), Some(plane.origin));
        assert!(!cone.is_singular(SurfaceSide::North));
        let cone_back = Cone::new(plane, -3.0, 1.5).unwrap().to_nurbs().unwrap();
        assert_eq!(
            cone_back.singular_point(SurfaceSide::North),
            Some(plane.origin)
        );
        assert_eq!(cone_back.domain_v(), Interval::new(-3.0, 0.0));

        let cylinder = Cylinder::new(plane, 1.0, 2.0).unwrap().to_nurbs().unwrap();
        assert!(SurfaceSide::ALL.iter().all(|&s| !cylinder.is_singular(s)));
        assert!(cylinder.is_closed(SurfaceDirection::U, 1e-12));
        assert!(!wavy(false).is_closed(SurfaceDirection::U, 1e-9));

        // Unclamped in v: the first column of control points coincides, but the boundary
        // v = v0 is not a point, so the side is not singular.
        let apex = Point3::new(0.0, 0.0, 0.0);
        let points = (0..3)
            .map(|i| {
                vec![
                    apex,
                    Point3::new(i as f64, 1.0, 0.0),
                    Point3::new(i as f64, 2.0, 1.0),
                    Point3::new(i as f64, 3.0, 0.0),
                ]
            })
            .collect();
        let s = NurbsSurface::non_rational(
            1,
            2,
            points,
            vec![0.0, 1.0, 2.0],
            vec![-1.0, 0.0, 1.0, 2.0, 3.0],
        )
        .unwrap();
        assert!(!s.is_singular(SurfaceSide::South));
        let d = s.domain_v();
        assert!(s.point_at(0.0, d.t0).distance(s.point_at(2.0, d.t0)) > 0.5);
    }
}

//! Tight bounding boxes of surfaces (curves: `curve/nurbs/bounding_box.rs`, B-reps:
//! `brep/bounding_box.rs`).
//!
//! The largest value of a coordinate over a surface is reached on its boundary or at an
//! interior point where that coordinate is stationary (`∂S_k/∂u = ∂S_k/∂v = 0`, where the
//! normal is parallel to the axis). The boundary is handled curve by curve: a curve's extremes
//! are at its ends or where `C_k'(t) = 0`. Both searches sample each polynomial span, then
//! polish the best samples with Newton's method confined to the span, so the boxes are tight
//! to rounding rather than the loose boxes of the control points.

use crate::curve::nurbs::bounding_box::{MAX_ITERATIONS, SAMPLES, include_curve};
use crate::surface::direction::{SurfaceDirection, SurfaceSide};
use crate::{BoundingBox, NurbsSurface, Point3};

impl NurbsSurface {
    /// The box of the control points, which contains the surface (the convex hull property of
    /// positive weights) but is usually larger than it.
    pub fn control_bounding_box(&self) -> BoundingBox {
        let mut bbox = BoundingBox::EMPTY;
        for &p in self.points() {
            bbox.include_point(p);
        }
        bbox
    }

    /// The tight axis-aligned bounding box of the surface over its whole domain.
    pub fn bounding_box(&self) -> BoundingBox {
        let mut bbox = BoundingBox::EMPTY;
        let (du, dv) = (self.domain_u(), self.domain_v());
        for side in SurfaceSide::ALL {
            if let Some(p) = self.singular_point(side) {
                bbox.include_point(p);
                continue;
            }
            let curve = match side {
                SurfaceSide::South => self.isocurve(SurfaceDirection::U, dv.t0),
                SurfaceSide::North => self.isocurve(SurfaceDirection::U, dv.t1),
                SurfaceSide::West => self.isocurve(SurfaceDirection::V, du.t0),
                SurfaceSide::East => self.isocurve(SurfaceDirection::V, du.t1),
            };
            // The domain ends are finite, so the isocurve always exists.
            if let Ok(curve) = curve {
                include_curve(&curve, &mut bbox);
            }
        }
        self.include_interior_extremes(&|_, _| true, &mut bbox);
        bbox
    }

    /// Adds to `bbox` the interior points where a coordinate is stationary and extreme within
    /// its polynomial patch, for parameters that `accept` admits.
    pub(crate) fn include_interior_extremes(
        &self,
        accept: &dyn Fn(f64, f64) -> bool,
        bbox: &mut BoundingBox,
    ) {
        let breaks_u = self.span_breaks(SurfaceDirection::U);
        let breaks_v = self.span_breaks(SurfaceDirection::V);
        let mut grid = [[Point3::ORIGIN; SAMPLES]; SAMPLES];
        for wu in breaks_u.windows(2) {
            for wv in breaks_v.windows(2) {
                let rect = [wu[0], wu[1], wv[0], wv[1]];
                let at = |range: (f64, f64), k: usize| {
                    let s = k as f64 / (SAMPLES - 1) as f64;
                    (1.0 - s) * range.0 + s * range.1
                };
                for (i, row) in grid.iter_mut().enumerate() {
                    for (j, p) in row.iter_mut().enumerate() {
                        *p = self.point_at(at((wu[0], wu[1]), i), at((wv[0], wv[1]), j));
                    }
                }
                for axis in 0..3 {
                    for sign in [1.0, -1.0] {
                        // Start from the sample with the largest signed coordinate.
                        let mut best = (f64::NEG_INFINITY, 0, 0);
                        for (i, row) in grid.iter().enumerate() {
                            for (j, p) in row.iter().enumerate() {
                                let value = sign * p.to_array()[axis];
                                if value > best.0 {
                                    best = (value, i, j);
                                }
                            }
                        }
                        let (u, v) = (at((wu[0], wu[1]), best.1), at((wv[0], wv[1]), best.2));
                        let (u, v) = self.climb(axis, sign, u, v, rect);
                        if accept(u, v) {
                            bbox.include_point(self.point_at(u, v));
                        }
                    }
                }
            }
        }
    }

    /// Newton's method for a stationary point of `sign · S_axis` inside `rect`, stopping at
    /// the rectangle's sides (whose extremes the boundary curves cover) and never letting the
    /// value decrease.
    fn climb(&self, axis: usize, sign: f64, mut u: f64, mut v: f64, rect: [f64; 4]) -> (f64, f64) {
        let value = |u: f64, v: f64| sign * self.point_at(u, v).to_array()[axis];
        let mut f = value(u, v);
        for _ in 0..MAX_ITERATIONS {
            let d = self.derivatives_unchecked(u, v, 2);
            let c = |w: crate::Vector3| sign * w.to_array()[axis];
            let (gu, gv) = (c(d.du), c(d.dv));
            // Maximize: the step solves H s = −g with H negative definite near a maximum.
            let (huu, huv, hvv) = (c(d.duu), c(d.duv), c(d.dvv));
            let det = huu * hvv - huv * huv;
            let (mut su, mut sv) = if huu < 0.0 && det > 0.0 {
                (-(hvv * gu - huv * gv) / det, -(huu * gv - huv * gu) / det)
            } else {
                // Not concave here: move uphill by a tenth of the patch.
                let scale = 0.1 * (rect[1] - rect[0]).max(rect[3] - rect[2]);
                let norm = gu.hypot(gv);
                if norm == 0.0 {
                    break;
                }
                (gu / norm * scale, gv / norm * scale)
            };
            let mut accepted = false;
            for _ in 0..40 {
                let nu = (u + su).clamp(rect[0], rect[1]);
                let nv = (v + sv).clamp(rect[2], rect[3]);
                let nf = value(nu, nv);
                if nf >= f {
                    let small = (nu - u).abs() <= 4.0 * f64::EPSILON * (1.0 + u.abs())
                        && (nv - v).abs() <= 4.0 * f64::EPSILON * (1.0 + v.abs());
                    u = nu;
                    v = nv;
                    f = nf;
                    accepted = !small;
                    break;
                }
                su *= 0.5;
                sv *= 0.5;
            }
            if !accepted {
                break;
            }
        }
        (u, v)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::surface::tests::wavy;
    use crate::{Brep, NurbsCurve};
    use crate::{Cylinder, Interval, OrientedBox, Plane, Sphere, Vector3};

    fn close(a: &BoundingBox, b: &BoundingBox, tol: f64) -> bool {
        a.min.distance(b.min) <= tol && a.max.distance(b.max) <= tol
    }

    #[test]
    fn sphere_and_tilted_cylinder_boxes_are_tight() {
        let c = Point3::new(1.0, -2.0, 0.5);
        let s = Sphere::new(c, 2.0).unwrap().to_nurbs().unwrap();
        let expected = BoundingBox::new(
            c - Vector3::new(2.0, 2.0, 2.0),
            c + Vector3::new(2.0, 2.0, 2.0),
        );
        assert!(close(&s.bounding_box(), &expected, 1e-12));

        // A cylinder about a tilted axis: its box is that of the two end discs, whose extent
        // along world axis k is r·√(1 − a_k²) about each centre.
        let axis = Vector3::new(1.0, 2.0, 2.0) / 3.0;
        let plane = Plane::from_normal(Point3::ORIGIN, axis).unwrap();
        let cyl = Cylinder::new(plane, 1.5, 4.0).unwrap();
        let top = plane.origin + axis * 4.0;
        let reach = |a: f64| 1.5 * (1.0 - a * a).sqrt();
        let r = Vector3::new(reach(axis.x), reach(axis.y), reach(axis.z));
        let mut expected = BoundingBox::new(plane.origin - r, plane.origin + r);
        expected = expected.union(&BoundingBox::new(top - r, top + r));
        let brep = Brep::from_cylinder(&cyl, true).unwrap();
        assert!(
            close(&brep.bounding_box(), &expected, 1e-12),
            "{:?} vs {expected:?}",
            brep.bounding_box()
        );
        assert!(close(
            &cyl.to_nurbs().unwrap().bounding_box(),
            &expected,
            1e-12
        ));
        // The control points' box is larger.
        assert!(!close(
            &cyl.to_nurbs().unwrap().control_bounding_box(),
            &expected,
            1e-3
        ));
    }

    #[test]
    fn surface_box_contains_dense_samples_and_touches_them() {
        for rational in [false, true] {
            let s = wavy(rational);
            let bbox = s.bounding_box();
            let mut sampled = BoundingBox::EMPTY;
            let n = 300;
            for i in 0..=n {
                for j in 0..=n {
                    let p = s.point_at(
                        s.domain_u().parameter_at(i as f64 / n as f64),
                        s.domain_v().parameter_at(j as f64 / n as f64),
                    );
                    assert!(bbox.inflated(1e-12).contains_point(p));
                    sampled.include_point(p);
                }
            }
            // Dense sampling reaches the true extremes to second order in the spacing.
            assert!(close(&bbox, &sampled, 1e-4));
        }
    }

    #[test]
    fn curve_box_is_tight() {
        // A parabola through (0,0), (1,1), (2,0): its control points reach y = 2.
        let c = NurbsCurve::new_non_rational(
            2,
            vec![
                Point3::ORIGIN,
                Point3::new(1.0, 2.0, 0.0),
                Point3::new(2.0, 0.0, 0.0),
            ],
            vec![0.0, 0.0, 1.0, 1.0],
        )
        .unwrap();
        let expected = BoundingBox::new(Point3::ORIGIN, Point3::new(2.0, 1.0, 0.0));
        assert!(close(&c.bounding_box(), &expected, 1e-14));
    }

    #[test]
    fn box_and_trimmed_faces() {
        let ob = OrientedBox::new(
            Plane::from_normal(Point3::new(1.0, 1.0, 1.0), Vector3::new(0.0, 0.0, 1.0)).unwrap(),
            Interval::new(0.0, 2.0),
            Interval::new(0.0, 3.0),
            Interval::new(0.0, 4.0),
        );
        let b = Brep::from_box(&ob).unwrap();
        assert!(close(&b.bounding_box(), &ob.bounding_box(), 1e-14));
        let tri = [
            Point3::new(0.0, 0.0, 0.0),
            Point3::new(3.0, 0.0, 1.0),
            Point3::new(0.0, 2.0, 2.0),
        ];
        let t = Brep::from_planar_polyline(&tri, 1e-9).unwrap();
        let expected = BoundingBox::from_points(&tri).unwrap();
        assert!(close(&t.bounding_box(), &expected, 1e-14));
    }
}

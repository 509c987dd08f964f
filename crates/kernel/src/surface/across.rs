//! Points and normals of a surface at a fixed set of parameters across one direction, for one
//! parameter along it at a time: what a mesher probing isocurves asks for.
//!
//! For a parameter `t` along the direction, the surface restricted to `t` is a curve across
//! it whose homogeneous control points are `Qⱼ(t) = Σᵣ Nᵣ(t) wᵣⱼ Pᵣⱼ`, and its derivative
//! along the direction is the curve of `Q′ⱼ(t) = Σᵣ N′ᵣ(t) wᵣⱼ Pᵣⱼ`. The basis functions (and
//! their derivatives) at the parameters across are fixed, so [`AcrossFrames`] computes them
//! once; each `t` then costs one span search, one set of basis functions and the two row
//! curves, and each point `2(q + 1)` homogeneous control points instead of a full
//! [`NurbsSurface::derivatives_at`] (two span searches, two sets of basis functions with
//! derivatives and `(p + 1)(q + 1)` control points, three times over).
//!
//! The normals are those of [`NurbsSurface::normal_at`] up to rounding: `Su × Sv` where it is
//! well defined, and `normal_at` itself (its limit at poles and apexes) elsewhere.

use crate::curve::nurbs::basis::{MAX_ORDER, span_index};
use crate::surface::basis_with_derivatives;
use crate::surface::derivatives::SurfaceDerivatives;
use crate::surface::direction::SurfaceDirection;
use crate::surface::normal::regular_normal;
use crate::{NurbsSurface, Point3, Vector3};

/// Evaluates a surface at `(t, s)` for every `s` of a fixed list across the direction of `t`.
#[derive(Debug)]
pub(crate) struct AcrossFrames<'a> {
    surface: &'a NurbsSurface,
    /// Whether `t` is `u` (and the parameters across are values of `v`).
    along_u: bool,
    across: Vec<f64>,
    /// Per parameter across: its basis functions and their first derivatives.
    basis: Vec<[[f64; MAX_ORDER]; 2]>,
    /// Per parameter across: the index of its first control point in the row curves.
    first: Vec<usize>,
    /// The homogeneous control points of the row curve at `t`, and of its derivative in `t`.
    row: Vec<[f64; 4]>,
    row_dt: Vec<[f64; 4]>,
}

impl<'a> AcrossFrames<'a> {
    /// Prepares to evaluate `surface` along `direction` at the parameters `across` of the
    /// other direction (finite, and inside its domain or clamped to it as
    /// [`NurbsSurface::point_at`] does).
    pub(crate) fn new(
        surface: &'a NurbsSurface,
        direction: SurfaceDirection,
        across: &[f64],
    ) -> Self {
        let along_u = matches!(direction, SurfaceDirection::U);
        let (degree, knots, count) = if along_u {
            (surface.degree_v(), surface.knots_v(), surface.count_v())
        } else {
            (surface.degree_u(), surface.knots_u(), surface.count_u())
        };
        let mut basis = Vec::with_capacity(across.len());
        let mut first = Vec::with_capacity(across.len());
        for &s in across {
            let span = span_index(degree, knots, s);
            let mut all = [[0.0; MAX_ORDER]; 3];
            basis_with_derivatives(degree, knots, span, s, &mut all);
            basis.push([all[0], all[1]]);
            first.push(span + 1 - degree);
        }
        Self {
            surface,
            along_u,
            across: across.to_vec(),
            basis,
            first,
            row: vec![[0.0; 4]; count],
            row_dt: vec![[0.0; 4]; count],
        }
    }

    /// Calls `f(point, normal)` for `(t, s)` with every `s` across, in order; the normal is
    /// `None` where [`NurbsSurface::normal_at`] fails.
    pub(crate) fn eval(&mut self, t: f64, mut f: impl FnMut(Point3, Option<Vector3>)) {
        let surface = self.surface;
        let (degree, knots) = if self.along_u {
            (surface.degree_u(), surface.knots_u())
        } else {
            (surface.degree_v(), surface.knots_v())
        };
        let span = span_index(degree, knots, t);
        let mut nt = [[0.0; MAX_ORDER]; 3];
        basis_with_derivatives(degree, knots, span, t, &mut nt);
        let start = span + 1 - degree;
        self.fill_rows(start, degree, &nt);
        let order = if self.along_u {
            surface.degree_v() + 1
        } else {
            surface.degree_u() + 1
        };
        for ((&s, basis), &first) in self.across.iter().zip(&self.basis).zip(&self.first) {
            let (mut a, mut a_t, mut a_s) = ([0.0; 4], [0.0; 4], [0.0; 4]);
            let rows = self.row[first..first + order]
                .iter()
                .zip(&self.row_dt[first..]);
            for ((&b, &db), (h, h_t)) in basis[0].iter().zip(&basis[1]).zip(rows) {
                for c in 0..4 {
                    a[c] += b * h[c];
                    a_t[c] += b * h_t[c];
                    a_s[c] += db * h[c];
                }
            }
            let inv = 1.0 / a[3];
            let point = Vector3::new(a[0] * inv, a[1] * inv, a[2] * inv);
            let derivative = |d: [f64; 4]| (Vector3::new(d[0], d[1], d[2]) - point * d[3]) * inv;
            let (d_t, d_s) = (derivative(a_t), derivative(a_s));
            let (du, dv) = if self.along_u { (d_t, d_s) } else { (d_s, d_t) };
            let d = SurfaceDerivatives {
                point: Point3::from_vector(point),
                du,
                dv,
                duu: Vector3::ZERO,
                duv: Vector3::ZERO,
                dvv: Vector3::ZERO,
            };
            let normal = regular_normal(&d).or_else(|| {
                let (u, v) = if self.along_u { (t, s) } else { (s, t) };
                surface.normal_at(u, v).ok()
            });
            f(d.point, normal);
        }
    }

    /// The row curves at `t`: the homogeneous control points across, blended by the basis
    /// functions (values and first derivatives) `nt` of the `degree + 1` rows from `start`.
    fn fill_rows(&mut self, start: usize, degree: usize, nt: &[[f64; MAX_ORDER]; 3]) {
        let surface = self.surface;
        let (points, weights, count_v) = (surface.points(), surface.weights(), surface.count_v());
        self.row.fill([0.0; 4]);
        self.row_dt.fill([0.0; 4]);
        for (r, (&b, &db)) in nt[0][..=degree].iter().zip(&nt[1]).enumerate() {
            for (k, (h, h_t)) in self.row.iter_mut().zip(self.row_dt.iter_mut()).enumerate() {
                // Along u the row runs over v (index k) at u-row `start + r`; along v it runs
                // over u (index k) at v-column `start + r`.
                let index = if self.along_u {
                    (start + r) * count_v + k
                } else {
                    k * count_v + start + r
                };
                let (p, w) = (points[index], weights[index]);
                let hw = [w * p.x, w * p.y, w * p.z, w];
                for c in 0..4 {
                    h[c] += b * hw[c];
                    h_t[c] += db * hw[c];
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::surface::tests::wavy;
    use crate::{Point3, Sphere};

    fn check(surface: &NurbsSurface) {
        let (du, dv) = (surface.domain_u(), surface.domain_v());
        let vs: Vec<f64> = (0..=12).map(|k| dv.parameter_at(k as f64 / 12.0)).collect();
        let us: Vec<f64> = (0..=12).map(|k| du.parameter_at(k as f64 / 12.0)).collect();
        for (direction, along, across) in [
            (SurfaceDirection::U, &us, &vs),
            (SurfaceDirection::V, &vs, &us),
        ] {
            let mut frames = AcrossFrames::new(surface, direction, across);
            for &t in along {
                let mut k = 0;
                frames.eval(t, |p, n| {
                    let s = across[k];
                    k += 1;
                    let (u, v) = match direction {
                        SurfaceDirection::U => (t, s),
                        SurfaceDirection::V => (s, t),
                    };
                    let scale = surface.point_at(u, v).to_vector().length().max(1.0);
                    assert!(
                        p.distance(surface.point_at(u, v)) <= 1e-13 * scale,
                        "{u} {v}"
                    );
                    match (n, surface.normal_at(u, v).ok()) {
                        (Some(a), Some(b)) => assert!((a - b).length() <= 1e-12, "{u} {v}"),
                        (a, b) => assert_eq!(a.is_some(), b.is_some(), "{u} {v}"),
                    }
                });
                assert_eq!(k, across.len());
            }
        }
    }

    #[test]
    fn frames_across_match_points_and_normals() {
        check(&wavy(false));
        check(&wavy(true));
    }

    #[test]
    fn frames_at_a_sphere_poles_are_the_limit_normals() {
        let sphere = Sphere::new(Point3::new(1.0, 2.0, 3.0), 2.0)
            .unwrap()
            .to_nurbs()
            .unwrap();
        check(&sphere);
    }
}

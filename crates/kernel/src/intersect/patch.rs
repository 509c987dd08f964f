//! A piece of a surface in Bézier form that can be cut further: the homogeneous control points
//! `(w·P, w)` of one knot-span rectangle's polynomial patch, or of a part of it, with its
//! parameter rectangle.
//!
//! As for curve pieces (`piece.rs`), the patch lies in the convex hull of its projected control
//! points, and any function that is linear in the homogeneous point, such as `w` times the
//! signed distance from a plane, has the patch's control values as its Bernstein coefficients.

use crate::curve::bezier_piece::blossoms;
use crate::curve::nurbs::basis::MAX_ORDER;
use crate::intersect::piece::Aabb;
use crate::{NurbsSurface, Plane, Point3, Vector3};

/// A polynomial patch on `[u0, u1] × [v0, v1]`, in Bézier form.
#[derive(Clone, Debug)]
pub(crate) struct Patch {
    /// The parameter rectangle, `[u0, u1]`.
    pub(crate) u: [f64; 2],
    /// The parameter rectangle, `[v0, v1]`.
    pub(crate) v: [f64; 2],
    /// Control points in `u` (degree in `u` + 1).
    pub(crate) nu: usize,
    /// Control points in `v` (degree in `v` + 1).
    pub(crate) nv: usize,
    /// Homogeneous control points, `i · nv + j`.
    h: Vec<[f64; 4]>,
}

/// The Rhino-form knot indices of the non-empty spans of one direction.
pub(crate) fn span_indices(knots: &[f64], degree: usize, count: usize) -> Vec<usize> {
    (degree - 1..count - 1)
        .filter(|&i| knots[i] < knots[i + 1])
        .collect()
}

impl Patch {
    /// The patch of spans `su` × `sv` (Rhino-form knot indices of non-empty spans).
    pub(crate) fn of_spans(surface: &NurbsSurface, su: usize, sv: usize) -> Self {
        let (p, q) = (surface.degree_u(), surface.degree_v());
        let (first_u, first_v) = (su + 1 - p, sv + 1 - q);
        let knots_u = &surface.knots_u()[first_u..first_u + 2 * p];
        let knots_v = &surface.knots_v()[first_v..first_v + 2 * q];
        let range_u = [surface.knots_u()[su], surface.knots_u()[su + 1]];
        let range_v = [surface.knots_v()[sv], surface.knots_v()[sv + 1]];
        let count_v = surface.count_v();
        let mut rows = vec![[[0.0; 4]; MAX_ORDER]; p + 1];
        for (i, row) in rows.iter_mut().enumerate() {
            let mut homogeneous = [[0.0; 4]; MAX_ORDER];
            for (j, h) in homogeneous[..=q].iter_mut().enumerate() {
                let k = (first_u + i) * count_v + first_v + j;
                let (pt, w) = (surface.points()[k], surface.weights()[k]);
                *h = [pt.x * w, pt.y * w, pt.z * w, w];
            }
            blossoms::<MAX_ORDER>(q, knots_v, range_v, &homogeneous[..=q], &mut row[..=q]);
        }
        let mut h = vec![[0.0; 4]; (p + 1) * (q + 1)];
        for j in 0..=q {
            let column: [[f64; 4]; MAX_ORDER] =
                std::array::from_fn(|i| if i <= p { rows[i][j] } else { [0.0; 4] });
            let mut bezier = [[0.0; 4]; MAX_ORDER];
            blossoms::<MAX_ORDER>(p, knots_u, range_u, &column[..=p], &mut bezier[..=p]);
            for i in 0..=p {
                h[i * (q + 1) + j] = bezier[i];
            }
        }
        Self {
            u: range_u,
            v: range_v,
            nu: p + 1,
            nv: q + 1,
            h,
        }
    }

    /// Every patch of the surface, by span rows.
    pub(crate) fn all(surface: &NurbsSurface) -> Vec<Self> {
        let su = span_indices(surface.knots_u(), surface.degree_u(), surface.count_u());
        let sv = span_indices(surface.knots_v(), surface.degree_v(), surface.count_v());
        let mut out = Vec::with_capacity(su.len() * sv.len());
        for &i in &su {
            for &j in &sv {
                out.push(Self::of_spans(surface, i, j));
            }
        }
        out
    }

    /// The homogeneous control point `(i, j)`.
    #[inline]
    pub(crate) fn homogeneous(&self, i: usize, j: usize) -> [f64; 4] {
        self.h[i * self.nv + j]
    }

    /// The Euclidean control point `(i, j)`.
    #[inline]
    pub(crate) fn point(&self, i: usize, j: usize) -> Point3 {
        let q = self.homogeneous(i, j);
        Point3::new(q[0] / q[3], q[1] / q[3], q[2] / q[3])
    }

    /// The box of the Euclidean control points, which holds the patch.
    pub(crate) fn aabb(&self) -> Aabb {
        let mut lo = [f64::INFINITY; 3];
        let mut hi = [f64::NEG_INFINITY; 3];
        for q in &self.h {
            for c in 0..3 {
                let x = q[c] / q[3];
                lo[c] = lo[c].min(x);
                hi[c] = hi[c].max(x);
            }
        }
        [lo, hi]
    }

    /// The signed distances of the control points from `plane` and their weights, as the
    /// Bernstein coefficients `w·d` of the numerator of the patch's distance and `w` of its
    /// denominator, `i · nv + j`.
    pub(crate) fn plane_values(&self, plane: &Plane) -> (Vec<f64>, Vec<f64>) {
        let o = plane.origin;
        let n = plane.z_axis;
        let numerator = self
            .h
            .iter()
            .map(|q| {
                (q[0] - q[3] * o.x) * n.x + (q[1] - q[3] * o.y) * n.y + (q[2] - q[3] * o.z) * n.z
            })
            .collect();
        let weights = self.h.iter().map(|q| q[3]).collect();
        (numerator, weights)
    }

    /// The point and its first partial derivatives `[S, Su, Sv]` at `(u, v)` (one-sided on the
    /// patch's sides), by de Casteljau's algorithm on the homogeneous points in `v` and then
    /// in `u`, and the quotient rule.
    pub(crate) fn derivatives(&self, u: f64, v: f64) -> [Vector3; 3] {
        let (hu, hv) = (self.u[1] - self.u[0], self.v[1] - self.v[0]);
        let su = if hu > 0.0 { (u - self.u[0]) / hu } else { 0.0 };
        let sv = if hv > 0.0 { (v - self.v[0]) / hv } else { 0.0 };
        let mut rows = [[0.0; 4]; MAX_ORDER];
        let mut rows_dv = [[0.0; 4]; MAX_ORDER];
        for ((row, row_dv), net_row) in rows
            .iter_mut()
            .zip(rows_dv.iter_mut())
            .zip(self.h.chunks_exact(self.nv))
        {
            (*row, *row_dv) = bezier_with_derivative(net_row, sv);
        }
        let (p, pu) = bezier_with_derivative(&rows[..self.nu], su);
        let (pv, _) = bezier_with_derivative(&rows_dv[..self.nu], su);
        let w = p[3];
        let s = Vector3::new(p[0], p[1], p[2]) / w;
        let ku = if hu > 0.0 { 1.0 / hu } else { 0.0 };
        let kv = if hv > 0.0 { 1.0 / hv } else { 0.0 };
        let du = (Vector3::new(pu[0], pu[1], pu[2]) - s * pu[3]) / w * ku;
        let dv = (Vector3::new(pv[0], pv[1], pv[2]) - s * pv[3]) / w * kv;
        [s, du, dv]
    }

    /// The slab across the plane of the patch's diagonals that holds its control points (and
    /// so the patch); `None` when the diagonals are parallel (a patch collapsed to a curve).
    pub(crate) fn slab(&self) -> Option<Slab> {
        let (nu, nv) = (self.nu, self.nv);
        let origin = self.point(0, 0);
        let normal = (self.point(nu - 1, nv - 1) - origin)
            .cross(self.point(0, nv - 1) - self.point(nu - 1, 0));
        let length = normal.length();
        if length == 0.0 || !length.is_finite() {
            return None;
        }
        let normal = normal / length;
        let (lo, hi) = (0..nu)
            .flat_map(|i| (0..nv).map(move |j| (i, j)))
            .map(|(i, j)| (self.point(i, j) - origin).dot(normal))
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), d| {
                (lo.min(d), hi.max(d))
            });
        Some(Slab {
            origin,
            normal,
            lo,
            hi,
        })
    }

    /// How far the control points lie from the bilinear patch through the four corners and
    /// from the plane across its diagonals, as a fraction of the diagonal of the patch's box
    /// (`relative`) or absolutely (`absolute`): whether the patch is nearly flat, where a line
    /// meets it at most once and Newton's method converges from a planar estimate. A bilinear
    /// patch's net is its corners, but when it is twisted it is a saddle that a line can cross
    /// twice, so the distance from the plane counts too. `slab` is the patch's
    /// [`slab`](Self::slab), which the caller has already computed.
    pub(crate) fn is_flat(&self, slab: Option<&Slab>, relative: f64, absolute: f64) -> bool {
        let (nu, nv) = (self.nu, self.nv);
        let c = [
            self.point(0, 0),
            self.point(nu - 1, 0),
            self.point(0, nv - 1),
            self.point(nu - 1, nv - 1),
        ];
        let mut deviation: f64 = 0.0;
        for i in 0..nu {
            let a = if nu > 1 {
                i as f64 / (nu - 1) as f64
            } else {
                0.0
            };
            for j in 0..nv {
                let b = if nv > 1 {
                    j as f64 / (nv - 1) as f64
                } else {
                    0.0
                };
                let bilinear = c[0].to_vector() * ((1.0 - a) * (1.0 - b))
                    + c[1].to_vector() * (a * (1.0 - b))
                    + c[2].to_vector() * ((1.0 - a) * b)
                    + c[3].to_vector() * (a * b);
                deviation = deviation.max((self.point(i, j).to_vector() - bilinear).length());
            }
        }
        // Half the slab: the distance from its middle plane. Diagonals along one line (a patch
        // collapsed to a curve or a point) give no plane, and then only a patch within
        // `absolute` of its first corner is flat.
        deviation = deviation.max(match slab {
            Some(slab) => 0.5 * slab.thickness(),
            None => (0..nu)
                .flat_map(|i| (0..nv).map(move |j| (i, j)))
                .map(|(i, j)| self.point(i, j).distance(c[0]))
                .fold(0.0, f64::max),
        });
        let bbox = self.aabb();
        let size = (0..3)
            .map(|k| (bbox[1][k] - bbox[0][k]).powi(2))
            .sum::<f64>()
            .sqrt();
        deviation <= absolute || deviation <= relative * size
    }

    /// The direction to halve in: across the direction whose control net bends more (its
    /// rows or columns deviate more from their chords), or the longer one when neither bends.
    pub(crate) fn split_in_u(&self) -> bool {
        let (nu, nv) = (self.nu, self.nv);
        let bend = |along_u: bool| -> (f64, f64) {
            let (lines, count) = if along_u { (nv, nu) } else { (nu, nv) };
            let at = |line: usize, k: usize| {
                if along_u {
                    self.point(k, line)
                } else {
                    self.point(line, k)
                }
            };
            let (mut deviation, mut length): (f64, f64) = (0.0, 0.0);
            for line in 0..lines {
                let (p0, p1) = (at(line, 0), at(line, count - 1));
                let chord = p1 - p0;
                let l2 = chord.length_squared();
                length = length.max(l2.sqrt());
                for k in 1..count.saturating_sub(1) {
                    let d = at(line, k) - p0;
                    let t = if l2 > 0.0 {
                        (d.dot(chord) / l2).clamp(0.0, 1.0)
                    } else {
                        0.0
                    };
                    deviation = deviation.max((d - chord * t).length());
                }
            }
            (deviation, length)
        };
        let (bend_u, length_u) = bend(true);
        let (bend_v, length_v) = bend(false);
        if bend_u.max(bend_v) > 1e-3 * length_u.max(length_v) {
            bend_u >= bend_v
        } else {
            length_u >= length_v
        }
    }

    /// The two halves across `u` (`in_u`) or `v`, by de Casteljau's algorithm at the middle.
    pub(crate) fn halve(&self, in_u: bool) -> (Self, Self) {
        let (nu, nv) = (self.nu, self.nv);
        let mut left = self.clone();
        let mut right = self.clone();
        let (count, lines) = if in_u { (nu, nv) } else { (nv, nu) };
        let index = |line: usize, k: usize| {
            if in_u { k * nv + line } else { line * nv + k }
        };
        for line in 0..lines {
            let mut q = [[0.0; 4]; MAX_ORDER];
            for (k, x) in q[..count].iter_mut().enumerate() {
                *x = self.h[index(line, k)];
            }
            left.h[index(line, 0)] = q[0];
            right.h[index(line, count - 1)] = q[count - 1];
            for level in 1..count {
                for i in 0..count - level {
                    let next = q[i + 1];
                    for (x, y) in q[i].iter_mut().zip(next) {
                        *x = 0.5 * (*x + y);
                    }
                }
                left.h[index(line, level)] = q[0];
                right.h[index(line, count - 1 - level)] = q[count - 1 - level];
            }
        }
        if in_u {
            let m = 0.5 * (self.u[0] + self.u[1]);
            left.u[1] = m;
            right.u[0] = m;
        } else {
            let m = 0.5 * (self.v[0] + self.v[1]);
            left.v[1] = m;
            right.v[0] = m;
        }
        (left, right)
    }
}

/// A Bézier curve of homogeneous points at the local parameter `s`, and its derivative in `s`.
fn bezier_with_derivative(points: &[[f64; 4]], s: f64) -> ([f64; 4], [f64; 4]) {
    let n = points.len();
    let mut q = [[0.0; 4]; MAX_ORDER];
    q[..n].copy_from_slice(points);
    if n == 1 {
        return (q[0], [0.0; 4]);
    }
    for level in 1..n - 1 {
        for i in 0..n - level {
            let next = q[i + 1];
            for (x, y) in q[i].iter_mut().zip(next) {
                *x += s * (y - *x);
            }
        }
    }
    let k = (n - 1) as f64;
    let derivative = std::array::from_fn(|c| k * (q[1][c] - q[0][c]));
    let point = std::array::from_fn(|c| q[0][c] + s * (q[1][c] - q[0][c]));
    (point, derivative)
}

/// The points `x` with `lo ≤ (x − origin)·normal ≤ hi`.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Slab {
    pub(crate) origin: Point3,
    /// Unit length.
    pub(crate) normal: Vector3,
    pub(crate) lo: f64,
    pub(crate) hi: f64,
}

impl Slab {
    /// `hi − lo`.
    pub(crate) fn thickness(&self) -> f64 {
        self.hi - self.lo
    }

    /// Whether all of `points` lie more than `gap` outside the slab, on one side.
    pub(crate) fn separates(&self, points: impl Iterator<Item = Point3>, gap: f64) -> bool {
        let (lo, hi) = points
            .map(|p| (p - self.origin).dot(self.normal))
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), d| {
                (lo.min(d), hi.max(d))
            });
        lo > self.hi + gap || hi < self.lo - gap
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Sphere;

    #[test]
    fn patches_bound_and_halve_like_the_surface() {
        let s = Sphere::new(Point3::new(1.0, 2.0, 3.0), 2.0)
            .unwrap()
            .to_nurbs()
            .unwrap();
        let patches = Patch::all(&s);
        assert_eq!(patches.len(), 8);
        for patch in &patches {
            // The corners of the patch are points of the surface.
            let corners = [
                (patch.u[0], patch.v[0], patch.point(0, 0)),
                (
                    patch.u[1],
                    patch.v[1],
                    patch.point(patch.nu - 1, patch.nv - 1),
                ),
            ];
            for (u, v, p) in corners {
                assert!(s.point_at(u, v).distance(p) < 1e-12);
            }
            let (l, r) = patch.halve(true);
            let (b, _) = r.halve(false);
            assert!(s.point_at(l.u[1], l.v[0]).distance(l.point(l.nu - 1, 0)) < 1e-12);
            assert!(s.point_at(b.u[0], b.v[1]).distance(b.point(0, b.nv - 1)) < 1e-12);
            let bbox = b.aabb();
            let p = s.point_at(0.5 * (b.u[0] + b.u[1]), 0.5 * (b.v[0] + b.v[1]));
            for (c, x) in p.to_array().into_iter().enumerate() {
                assert!(x >= bbox[0][c] - 1e-12 && x <= bbox[1][c] + 1e-12);
            }
        }
    }
}

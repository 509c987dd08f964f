//! Area, volume and their centroids for faces and B-reps.
//!
//! Every quantity is an integral over the faces' trimmed parameter regions `D`:
//!
//! | quantity | integrand over `D` (`N = Su × Sv`, `N⁺` oriented outwards) |
//! | --- | --- |
//! | area | `|N|` |
//! | first moment of area | `S |N|` |
//! | volume (divergence theorem) | `S · N⁺ / 3` |
//! | first moment of volume, per axis `k` | `S_k² N⁺_k / 2` (the flux of `(x²/2, 0, 0)` and so on) |
//!
//! An untrimmed face (its loop runs around the whole parameter rectangle) is integrated
//! patch by patch with tensor-product 10-point Gauss–Legendre quadrature, each panel compared
//! with its four quarters and split where they disagree; the basis functions are computed once
//! per row and column of nodes. A trimmed face is turned into line integrals over its loops by
//! Green's theorem: `∬_D g du dv = ∮_∂D G dv` with `G(u, v) = ∫_{u_ref}^{u} g(s, v) ds`, the
//! outer loop counter-clockwise and holes clockwise. Both the inner integral (split at the
//! surface's `u` knots) and the line integral (split at the trim's knots and where a straight
//! trim crosses a knot line of the surface) use adaptive 10-point Gauss–Legendre quadrature,
//! each panel compared with its two halves.
//!
//! A panel is accepted when the finer estimate agrees with the coarser one to 1e-11 of the
//! B-rep's size (in the scaled units below); the accepted finer estimate is then usually exact
//! to rounding, since halving a panel divides the error of an n-point rule by about `2^(2n)`.
//! For planar faces bounded by straight trims every integrand is a polynomial of low degree and
//! the first panel is already exact. Spheres, cylinders and cones agree with their formulas to
//! about 1e-15 relative (see the tests).
//!
//! Coordinates are taken relative to the centre of the B-rep's control-point box and scaled by
//! its size, which avoids the cancellation of the divergence theorem far from the origin.

use std::sync::OnceLock;

use crate::brep::Brep;
use crate::curve::nurbs::basis::{MAX_ORDER, span_index};
use crate::surface::basis_with_derivatives;
use crate::{Error, NurbsCurve, NurbsSurface, Point3, Result, Vector3};

/// The number of Gauss–Legendre nodes per panel.
const NODES: usize = 10;
/// The agreement required between a panel and its refinement, in units of the B-rep's size.
const TOLERANCE: f64 = 1e-11;
/// The deepest halving of a panel.
const MAX_DEPTH: usize = 30;
/// The deepest quartering of a patch of an untrimmed face.
const MAX_PATCH_DEPTH: usize = 12;

/// The integrated quantities, in scaled coordinates: area, first moments of area (3), volume,
/// first moments of volume (3).
type Moments = [f64; 8];

const ZERO: Moments = [0.0; 8];

/// The area of a face or B-rep and the centroid of that area.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AreaProperties {
    /// The surface area.
    pub area: f64,
    /// The centroid of the area: the mean of the surface points weighted by area.
    pub centroid: Point3,
}

/// The volume enclosed by a closed B-rep and the centroid of that volume.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct VolumeProperties {
    /// The enclosed volume, positive when the faces face outwards.
    pub volume: f64,
    /// The centroid of the enclosed volume.
    pub centroid: Point3,
}

impl Brep {
    /// The area and area centroid of the whole B-rep (Grasshopper's Area on a B-rep; Rhino's
    /// `AreaMassProperties`).
    ///
    /// # Errors
    /// [`Error::InvalidInput`] for a B-rep without faces, [`Error::Degenerate`] if its total
    /// area is zero.
    pub fn area_properties(&self) -> Result<AreaProperties> {
        let faces: Vec<usize> = (0..self.faces.len()).collect();
        self.area_properties_of(&faces)
    }

    /// The area and area centroid of face `index` within its trim loops.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] if there is no face `index`, [`Error::Degenerate`] for a face of
    /// zero area.
    pub fn face_area_properties(&self, index: usize) -> Result<AreaProperties> {
        if index >= self.faces.len() {
            return Err(Error::InvalidInput(format!(
                "face index {index} is out of range for a brep with {} faces",
                self.faces.len()
            )));
        }
        self.area_properties_of(&[index])
    }

    /// The total area of the faces.
    ///
    /// # Errors
    /// As [`area_properties`](Self::area_properties).
    pub fn area(&self) -> Result<f64> {
        Ok(self.area_properties()?.area)
    }

    /// The volume and volume centroid of a closed B-rep (Grasshopper's Volume; Rhino's
    /// `VolumeMassProperties`), by the divergence theorem over its faces.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] if the B-rep is not closed ([`Brep::is_solid`]),
    /// [`Error::Degenerate`] if the enclosed volume is zero.
    pub fn volume_properties(&self) -> Result<VolumeProperties> {
        if !self.is_solid() {
            return Err(Error::InvalidInput(
                "the brep is not closed, so it encloses no volume".into(),
            ));
        }
        let faces: Vec<usize> = (0..self.faces.len()).collect();
        let (frame, m) = self.integrate(&faces)?;
        if m[4] == 0.0 || !m[4].is_finite() {
            return Err(Error::Degenerate {
                what: "brep volume",
            });
        }
        let l = frame.size;
        Ok(VolumeProperties {
            volume: m[4] * l * l * l,
            centroid: frame.center + Vector3::new(m[5], m[6], m[7]) * (l / m[4]),
        })
    }

    /// The enclosed volume of a closed B-rep.
    ///
    /// # Errors
    /// As [`volume_properties`](Self::volume_properties).
    pub fn volume(&self) -> Result<f64> {
        Ok(self.volume_properties()?.volume)
    }

    fn area_properties_of(&self, faces: &[usize]) -> Result<AreaProperties> {
        if faces.is_empty() {
            return Err(Error::InvalidInput("the brep has no faces".into()));
        }
        let (frame, m) = self.integrate(faces)?;
        if m[0] <= 0.0 || !m[0].is_finite() {
            return Err(Error::Degenerate { what: "brep area" });
        }
        let l = frame.size;
        Ok(AreaProperties {
            area: m[0] * l * l,
            centroid: frame.center + Vector3::new(m[1], m[2], m[3]) * (l / m[0]),
        })
    }

    /// Integrates the moments of the given faces in the scaled frame of those faces.
    fn integrate(&self, faces: &[usize]) -> Result<(Frame, Moments)> {
        let frame = Frame::around(faces.iter().map(|&f| &self.faces[f].surface))?;
        let mut total = ZERO;
        for &f in faces {
            let face = &self.faces[f];
            let integrator = FaceIntegrator::new(&face.surface, face.reversed, &frame);
            if self.is_untrimmed(f) {
                add_to(&mut total, &integrator.whole_surface());
                continue;
            }
            for &l in &face.loops {
                for &t in &self.loops[l].trims {
                    add_to(&mut total, &integrator.trim(&self.trims[t].curve));
                }
            }
        }
        if total.iter().any(|x| !x.is_finite()) {
            return Err(Error::NotFinite {
                what: "mass property",
            });
        }
        Ok((frame, total))
    }
}

impl NurbsSurface {
    /// The area and area centroid of the whole surface (Grasshopper's Area on an untrimmed
    /// surface), by the same quadrature as [`Brep::area_properties`].
    ///
    /// # Errors
    /// [`Error::Degenerate`] for a surface of zero area.
    pub fn area_properties(&self) -> Result<AreaProperties> {
        let frame = Frame::around(std::iter::once(self))?;
        let m = FaceIntegrator::new(self, false, &frame).whole_surface();
        if m.iter().any(|x| !x.is_finite()) {
            return Err(Error::NotFinite {
                what: "mass property",
            });
        }
        if m[0] <= 0.0 {
            return Err(Error::Degenerate {
                what: "surface area",
            });
        }
        let l = frame.size;
        Ok(AreaProperties {
            area: m[0] * l * l,
            centroid: frame.center + Vector3::new(m[1], m[2], m[3]) * (l / m[0]),
        })
    }
}

/// The centre and size used to scale coordinates.
#[derive(Clone, Copy, Debug)]
struct Frame {
    center: Point3,
    size: f64,
}

impl Frame {
    /// The centre of the control points' box and its half diagonal.
    fn around<'a>(surfaces: impl Iterator<Item = &'a NurbsSurface>) -> Result<Self> {
        let mut lo = [f64::INFINITY; 3];
        let mut hi = [f64::NEG_INFINITY; 3];
        for s in surfaces {
            for p in s.points() {
                for (k, c) in p.to_array().into_iter().enumerate() {
                    lo[k] = lo[k].min(c);
                    hi[k] = hi[k].max(c);
                }
            }
        }
        let center = Point3::new(
            0.5 * (lo[0] + hi[0]),
            0.5 * (lo[1] + hi[1]),
            0.5 * (lo[2] + hi[2]),
        );
        let size = 0.5 * Vector3::new(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]).length();
        if !(size.is_finite() && center.is_finite()) {
            return Err(Error::NotFinite { what: "brep" });
        }
        if size == 0.0 {
            return Err(Error::Degenerate { what: "brep" });
        }
        Ok(Self { center, size })
    }
}

/// Evaluates the Green's-theorem integrals of one face.
struct FaceIntegrator<'a> {
    surface: &'a NurbsSurface,
    /// +1 when the face's outward direction is `Su × Sv`, −1 when reversed.
    sign: f64,
    center: Vector3,
    inverse_size: f64,
    breaks_u: Vec<f64>,
    breaks_v: Vec<f64>,
    /// The lower limit of the inner integral.
    u_ref: f64,
}

impl<'a> FaceIntegrator<'a> {
    fn new(surface: &'a NurbsSurface, reversed: bool, frame: &Frame) -> Self {
        Self {
            surface,
            sign: if reversed { -1.0 } else { 1.0 },
            center: frame.center.to_vector(),
            inverse_size: 1.0 / frame.size,
            breaks_u: surface.span_breaks(crate::SurfaceDirection::U),
            breaks_v: surface.span_breaks(crate::SurfaceDirection::V),
            u_ref: surface.domain_u().t0,
        }
    }

    /// The integrand at `(u, v)` in scaled coordinates.
    fn integrand(&self, u: f64, v: f64) -> Moments {
        let (p, q) = (self.surface.degree_u, self.surface.degree_v);
        let su = span_index(p, &self.surface.knots_u, u);
        let sv = span_index(q, &self.surface.knots_v, v);
        let mut bu = [[0.0; MAX_ORDER]; 3];
        let mut bv = [[0.0; MAX_ORDER]; 3];
        basis_with_derivatives(p, &self.surface.knots_u, su, u, &mut bu);
        basis_with_derivatives(q, &self.surface.knots_v, sv, v, &mut bv);
        self.integrand_from_basis(su + 1 - p, &bu, sv + 1 - q, &bv)
    }

    /// The integrand from the basis functions and first derivatives in `u` (first control
    /// point row `i0`) and `v` (first column `j0`).
    #[inline]
    fn integrand_from_basis(
        &self,
        i0: usize,
        bu: &[[f64; MAX_ORDER]; 3],
        j0: usize,
        bv: &[[f64; MAX_ORDER]; 3],
    ) -> Moments {
        let s = self.surface;
        let (p, q, count_v) = (s.degree_u, s.degree_v, s.count_v);
        // Homogeneous point and first partial derivatives.
        let mut h = [[0.0f64; 4]; 3];
        for (r, (&nu, &du)) in bu[0][..=p].iter().zip(&bu[1][..=p]).enumerate() {
            let row = (i0 + r) * count_v + j0;
            let mut c = [[0.0f64; 4]; 2];
            let cvs = s.points[row..=row + q]
                .iter()
                .zip(&s.weights[row..=row + q]);
            for ((pt, &w), (&nv, &dv)) in cvs.zip(bv[0][..=q].iter().zip(&bv[1][..=q])) {
                let hw = [pt.x * w, pt.y * w, pt.z * w, w];
                for (m, &x) in hw.iter().enumerate() {
                    c[0][m] += nv * x;
                    c[1][m] += dv * x;
                }
            }
            for m in 0..4 {
                h[0][m] += nu * c[0][m];
                h[1][m] += du * c[0][m];
                h[2][m] += nu * c[1][m];
            }
        }
        let w = h[0][3];
        let point = Vector3::new(h[0][0], h[0][1], h[0][2]) / w;
        let du = (Vector3::new(h[1][0], h[1][1], h[1][2]) - point * h[1][3]) / w;
        let dv = (Vector3::new(h[2][0], h[2][1], h[2][2]) - point * h[2][3]) / w;
        let s2 = self.inverse_size * self.inverse_size;
        let n = du.cross(dv) * s2;
        let a = n.length();
        let r = (point - self.center) * self.inverse_size;
        let no = n * self.sign;
        [
            a,
            r.x * a,
            r.y * a,
            r.z * a,
            r.dot(no) / 3.0,
            0.5 * r.x * r.x * no.x,
            0.5 * r.y * r.y * no.y,
            0.5 * r.z * r.z * no.z,
        ]
    }

    /// The integral over the whole parameter rectangle: tensor-product Gauss–Legendre per
    /// patch, each patch compared with its four quarters and split where they disagree.
    fn whole_surface(&self) -> Moments {
        let mut total = ZERO;
        for wu in self.breaks_u.windows(2) {
            for wv in self.breaks_v.windows(2) {
                let rect = [wu[0], wu[1], wv[0], wv[1]];
                let whole = self.tensor_panel(rect);
                add_to(&mut total, &self.refine_patch(rect, whole, MAX_PATCH_DEPTH));
            }
        }
        total
    }

    fn refine_patch(&self, [u0, u1, v0, v1]: [f64; 4], whole: Moments, depth: usize) -> Moments {
        let (um, vm) = (0.5 * (u0 + u1), 0.5 * (v0 + v1));
        let quarters = [
            [u0, um, v0, vm],
            [um, u1, v0, vm],
            [u0, um, vm, v1],
            [um, u1, vm, v1],
        ];
        let parts = quarters.map(|q| self.tensor_panel(q));
        let mut sum = ZERO;
        for part in &parts {
            add_to(&mut sum, part);
        }
        let error = sum
            .iter()
            .zip(&whole)
            .fold(0.0f64, |e, (s, w)| e.max((s - w).abs()));
        if error <= TOLERANCE || depth == 0 || !(um > u0 && um < u1 && vm > v0 && vm < v1) {
            return sum;
        }
        let mut out = ZERO;
        for (q, part) in quarters.into_iter().zip(parts) {
            add_to(&mut out, &self.refine_patch(q, part, depth - 1));
        }
        out
    }

    /// One tensor-product Gauss–Legendre panel over a rectangle inside one patch, with the
    /// basis functions computed once per node row and column.
    fn tensor_panel(&self, [u0, u1, v0, v1]: [f64; 4]) -> Moments {
        let (x, w) = gauss_legendre();
        let s = self.surface;
        let (p, q) = (s.degree_u, s.degree_v);
        let (mu, hu) = (0.5 * (u0 + u1), 0.5 * (u1 - u0));
        let (mv, hv) = (0.5 * (v0 + v1), 0.5 * (v1 - v0));
        let mut basis_v = [[[0.0; MAX_ORDER]; 3]; NODES];
        let mut first_v = [0usize; NODES];
        for (k, (bv, j0)) in basis_v.iter_mut().zip(&mut first_v).enumerate() {
            let v = mv + hv * x[k];
            let span = span_index(q, &s.knots_v, v);
            basis_with_derivatives(q, &s.knots_v, span, v, bv);
            *j0 = span + 1 - q;
        }
        let mut total = ZERO;
        let mut bu = [[0.0; MAX_ORDER]; 3];
        for (xi, wi) in x.iter().zip(w) {
            let u = mu + hu * xi;
            let span = span_index(p, &s.knots_u, u);
            basis_with_derivatives(p, &s.knots_u, span, u, &mut bu);
            let i0 = span + 1 - p;
            for ((bv, &j0), wj) in basis_v.iter().zip(&first_v).zip(w) {
                let value = self.integrand_from_basis(i0, &bu, j0, bv);
                let weight = wi * wj;
                for (t, v) in total.iter_mut().zip(value) {
                    *t += weight * v;
                }
            }
        }
        scale(&total, hu * hv)
    }

    /// `G(u, v) = ∫_{u_ref}^{u} g(s, v) ds`, split at the `u` knots.
    fn inner(&self, u: f64, v: f64) -> Moments {
        if u == self.u_ref {
            return ZERO;
        }
        let (lo, hi, sign) = if u > self.u_ref {
            (self.u_ref, u, 1.0)
        } else {
            (u, self.u_ref, -1.0)
        };
        let f = |s: f64| self.integrand(s, v);
        let mut total = ZERO;
        let mut a = lo;
        for &k in self.breaks_u.iter().filter(|&&k| k > lo && k < hi) {
            add_to(&mut total, &integrate(&f, a, k));
            a = k;
        }
        add_to(&mut total, &integrate(&f, a, hi));
        scale(&total, sign)
    }

    /// `∮ G dv` along one trim.
    fn trim(&self, curve: &NurbsCurve) -> Moments {
        let pts = curve.points();
        // A trim along which v is constant contributes nothing (dv = 0).
        if pts.iter().all(|p| p.y == pts[0].y) {
            return ZERO;
        }
        // Along u = u_ref the inner integral vanishes.
        if pts.iter().all(|p| p.x == self.u_ref) {
            return ZERO;
        }
        let mut cuts = curve.span_breaks();
        if curve.degree() == 1 {
            // Straight pieces: also cut where they cross a knot line of the surface, where the
            // integrand is less smooth.
            for w in curve.span_breaks().windows(2) {
                let (t0, t1) = (w[0], w[1]);
                let (p0, p1) = (curve.point_at(t0), curve.point_at(t1));
                for (breaks, c0, c1) in [(&self.breaks_u, p0.x, p1.x), (&self.breaks_v, p0.y, p1.y)]
                {
                    for &k in breaks {
                        if (c0 < k && k < c1) || (c1 < k && k < c0) {
                            cuts.push(t0 + (t1 - t0) * (k - c0) / (c1 - c0));
                        }
                    }
                }
            }
            cuts.sort_by(f64::total_cmp);
            cuts.dedup();
        }
        let f = |t: f64| {
            let (p, d1, _) = curve.point_and_derivatives_at(t);
            scale(&self.inner(p.x, p.y), d1.y)
        };
        let mut total = ZERO;
        for w in cuts.windows(2) {
            add_to(&mut total, &integrate(&f, w[0], w[1]));
        }
        total
    }
}

/// The Gauss–Legendre nodes on `[−1, 1]` and their weights, by Newton's method on the
/// Legendre polynomial, computed once.
fn gauss_legendre() -> &'static ([f64; NODES], [f64; NODES]) {
    static TABLE: OnceLock<([f64; NODES], [f64; NODES])> = OnceLock::new();
    TABLE.get_or_init(|| {
        let n = NODES;
        let mut x = [0.0; NODES];
        let mut w = [0.0; NODES];
        for i in 0..n {
            let mut z = (std::f64::consts::PI * (i as f64 + 0.75) / (n as f64 + 0.5)).cos();
            let mut derivative = 1.0;
            for _ in 0..100 {
                let (mut p0, mut p1) = (1.0, z);
                for k in 1..n {
                    let p2 = ((2 * k + 1) as f64 * z * p1 - k as f64 * p0) / (k + 1) as f64;
                    p0 = p1;
                    p1 = p2;
                }
                derivative = n as f64 * (z * p1 - p0) / (z * z - 1.0);
                let step = p1 / derivative;
                z -= step;
                if step.abs() < 1e-16 {
                    break;
                }
            }
            x[i] = z;
            w[i] = 2.0 / ((1.0 - z * z) * derivative * derivative);
        }
        (x, w)
    })
}

/// One Gauss–Legendre panel over `[a, b]`.
fn panel(f: &impl Fn(f64) -> Moments, a: f64, b: f64) -> Moments {
    let (x, w) = gauss_legendre();
    let (mid, half) = (0.5 * (a + b), 0.5 * (b - a));
    let mut total = ZERO;
    for (xi, wi) in x.iter().zip(w) {
        let value = f(mid + half * xi);
        for (t, v) in total.iter_mut().zip(value) {
            *t += wi * v;
        }
    }
    scale(&total, half)
}

/// Adaptive Gauss–Legendre quadrature of `f` over `[a, b]`.
fn integrate(f: &impl Fn(f64) -> Moments, a: f64, b: f64) -> Moments {
    if a == b {
        return ZERO;
    }
    let whole = panel(f, a, b);
    refine(f, a, b, whole, MAX_DEPTH)
}

fn refine(f: &impl Fn(f64) -> Moments, a: f64, b: f64, whole: Moments, depth: usize) -> Moments {
    let m = 0.5 * (a + b);
    let left = panel(f, a, m);
    let right = panel(f, m, b);
    let mut sum = left;
    add_to(&mut sum, &right);
    let error = sum
        .iter()
        .zip(&whole)
        .fold(0.0f64, |e, (s, w)| e.max((s - w).abs()));
    if error <= TOLERANCE || depth == 0 || !(m > a && m < b) {
        return sum;
    }
    let mut out = refine(f, a, m, left, depth - 1);
    add_to(&mut out, &refine(f, m, b, right, depth - 1));
    out
}

fn add_to(total: &mut Moments, value: &Moments) {
    for (t, v) in total.iter_mut().zip(value) {
        *t += v;
    }
}

fn scale(m: &Moments, s: f64) -> Moments {
    m.map(|x| x * s)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Cone, Cylinder, Interval, OrientedBox, Plane, Sphere, Transform};
    use std::f64::consts::PI;

    fn rel(a: f64, b: f64) -> f64 {
        (a - b).abs() / b.abs().max(1e-300)
    }

    #[test]
    fn gauss_legendre_is_exact_for_degree_19() {
        let f = |t: f64| [t.powi(19) + t.powi(18), 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0];
        let exact = (2f64.powi(20) - 1.0) / 20.0 + (2f64.powi(19) - 1.0) / 19.0;
        assert!(rel(panel(&f, 1.0, 2.0)[0], exact) < 1e-14);
    }

    #[test]
    fn box_area_volume_and_centroids_are_exact() {
        let plane =
            Plane::from_normal(Point3::new(100.0, -50.0, 20.0), Vector3::new(1.0, 2.0, 2.0))
                .unwrap();
        let b = Brep::from_box(&OrientedBox::new(
            plane,
            Interval::new(-1.0, 1.0),
            Interval::new(0.0, 3.0),
            Interval::new(6.0, 2.0),
        ))
        .unwrap();
        let a = b.area_properties().unwrap();
        let v = b.volume_properties().unwrap();
        let centre = plane.point_at(0.0, 1.5, 4.0);
        assert!(rel(a.area, 2.0 * (2.0 * 3.0 + 3.0 * 4.0 + 2.0 * 4.0)) < 1e-14);
        assert!(rel(v.volume, 24.0) < 1e-14);
        assert!(a.centroid.distance(centre) < 1e-12);
        assert!(v.centroid.distance(centre) < 1e-12);
        // One face: its area and centre.
        let top = b.face_area_properties(5).unwrap();
        assert!(rel(top.area, 6.0) < 1e-14);
        assert!(top.centroid.distance(plane.point_at(0.0, 1.5, 6.0)) < 1e-12);
        assert!(b.face_area_properties(6).is_err());
    }

    #[test]
    fn greens_theorem_agrees_with_direct_quadrature_on_multi_span_surfaces() {
        for rational in [false, true] {
            let surface = crate::surface::tests::wavy(rational);
            let brep = Brep::from_surface(surface.clone()).unwrap();
            let frame = Frame::around(std::iter::once(&surface)).unwrap();
            for reversed in [false, true] {
                let integrator = FaceIntegrator::new(&surface, reversed, &frame);
                let direct = integrator.whole_surface();
                let mut green = ZERO;
                for t in brep.trims() {
                    add_to(&mut green, &integrator.trim(&t.curve));
                }
                for (a, b) in direct.iter().zip(&green) {
                    assert!((a - b).abs() < 1e-13, "{direct:?} vs {green:?}");
                }
            }
            // And against a fine midpoint rule for the area.
            let (du, dv) = (surface.domain_u(), surface.domain_v());
            let n = 200;
            let (hu, hv) = (du.length() / n as f64, dv.length() / n as f64);
            let mut area = 0.0;
            for i in 0..n {
                for j in 0..n {
                    let d = surface
                        .derivatives_at(
                            du.t0 + (i as f64 + 0.5) * hu,
                            dv.t0 + (j as f64 + 0.5) * hv,
                            1,
                        )
                        .unwrap();
                    area += d.du.cross(d.dv).length() * hu * hv;
                }
            }
            assert!(rel(brep.area().unwrap(), area) < 1e-4);
        }
    }

    #[test]
    fn sphere_area_and_volume() {
        let centre = Point3::new(1.0, -2.0, 0.5);
        let b = Brep::from_sphere(&Sphere::new(centre, 2.0).unwrap()).unwrap();
        let a = b.area_properties().unwrap();
        assert_eq!(a, b.faces()[0].surface.area_properties().unwrap());
        let v = b.volume_properties().unwrap();
        assert!(rel(a.area, 16.0 * PI) < 1e-12, "{}", rel(a.area, 16.0 * PI));
        assert!(
            rel(v.volume, 32.0 / 3.0 * PI) < 1e-12,
            "{}",
            rel(v.volume, 32.0 / 3.0 * PI)
        );
        assert!(a.centroid.distance(centre) < 1e-12);
        assert!(v.centroid.distance(centre) < 1e-12);
    }

    #[test]
    fn capped_cylinder_and_cone() {
        let plane =
            Plane::from_normal(Point3::new(-1.0, 0.5, 2.0), Vector3::new(0.3, 0.4, 1.0)).unwrap();
        let cyl = Cylinder::new(plane, 1.5, 4.0).unwrap();
        let b = Brep::from_cylinder(&cyl, true).unwrap();
        let a = b.area_properties().unwrap();
        let v = b.volume_properties().unwrap();
        assert!(rel(a.area, 2.0 * PI * 1.5 * 4.0 + 2.0 * PI * 2.25) < 1e-12);
        assert!(rel(v.volume, PI * 2.25 * 4.0) < 1e-12);
        let mid = plane.origin + plane.z_axis * 2.0;
        assert!(v.centroid.distance(mid) < 1e-12 && a.centroid.distance(mid) < 1e-12);
        // The open tube has an area but no volume.
        let open = Brep::from_cylinder(&cyl, false).unwrap();
        assert!(rel(open.area().unwrap(), cyl.lateral_area()) < 1e-12);
        assert!(open.volume().is_err());

        for height in [3.0, -3.0] {
            let cone = Cone::new(plane, height, 1.5).unwrap();
            let b = Brep::from_cone(&cone, true).unwrap();
            let a = b.area_properties().unwrap();
            let v = b.volume_properties().unwrap();
            assert!(rel(a.area, cone.lateral_area() + PI * 2.25) < 1e-12);
            assert!(
                rel(v.volume, cone.volume()) < 1e-12,
                "{} vs {}",
                v.volume,
                cone.volume()
            );
            // A solid cone's centroid is a quarter of the way from the base to the apex.
            let expected = plane.origin + plane.z_axis * (0.75 * height);
            assert!(v.centroid.distance(expected) < 1e-12);
        }
    }

    #[test]
    fn planar_faces_with_holes_and_circles() {
        let square = [
            Point3::new(0.0, 0.0, 0.0),
            Point3::new(4.0, 0.0, 0.0),
            Point3::new(4.0, 4.0, 0.0),
            Point3::new(0.0, 4.0, 0.0),
        ];
        let hole = vec![
            Point3::new(1.0, 1.0, 0.0),
            Point3::new(2.0, 1.0, 0.0),
            Point3::new(2.0, 2.0, 0.0),
            Point3::new(1.0, 2.0, 0.0),
        ];
        let b = Brep::from_planar_polylines(&square, &[hole], 1e-9).unwrap();
        let a = b.area_properties().unwrap();
        assert!(rel(a.area, 15.0) < 1e-14);
        // (16·(2, 2) − 1·(1.5, 1.5)) / 15
        let c = Point3::new((32.0 - 1.5) / 15.0, (32.0 - 1.5) / 15.0, 0.0);
        assert!(a.centroid.distance(c) < 1e-13);
        // A triangle's centroid is the mean of its corners.
        let tri = [
            Point3::new(0.0, 0.0, 1.0),
            Point3::new(3.0, 0.0, 2.0),
            Point3::new(0.0, 3.0, 4.0),
        ];
        let t = Brep::from_planar_polyline(&tri, 1e-9).unwrap();
        let a = t.area_properties().unwrap();
        let expected_area = 0.5 * (tri[1] - tri[0]).cross(tri[2] - tri[0]).length();
        assert!(rel(a.area, expected_area) < 1e-14);
        assert!(a.centroid.distance(Point3::new(1.0, 1.0, 7.0 / 3.0)) < 1e-13);
    }

    #[test]
    fn transformed_breps_keep_positive_volume() {
        let b = Brep::from_sphere(&Sphere::new(Point3::ORIGIN, 1.0).unwrap()).unwrap();
        let mirror = Transform::from_rows([
            [1.0, 0.0, 0.0, 3.0],
            [0.0, -2.0, 0.0, 0.0],
            [0.0, 0.0, 1.0, 0.0],
            [0.0, 0.0, 0.0, 1.0],
        ]);
        let m = b.transformed(&mirror).unwrap();
        let v = m.volume_properties().unwrap();
        assert!(rel(v.volume, 8.0 / 3.0 * PI) < 1e-12);
        assert!(v.centroid.distance(Point3::new(3.0, 0.0, 0.0)) < 1e-12);
        assert!(Brep::default().area().is_err());
    }
}

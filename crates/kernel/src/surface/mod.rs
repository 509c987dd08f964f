//! NURBS surfaces: a tensor-product grid of control points with weights and two knot vectors
//! in Rhino form.
//!
//! The surface is
//! `S(u, v) = Σᵢ Σⱼ Nᵢ(u) Mⱼ(v) wᵢⱼ Pᵢⱼ / Σᵢ Σⱼ Nᵢ(u) Mⱼ(v) wᵢⱼ`
//! with B-spline basis functions `Nᵢ` of degree `p` on the `u` knots and `Mⱼ` of degree `q` on
//! the `v` knots (see [`basis`](crate::basis)). Control point `Pᵢⱼ` is stored at
//! `i · count_v + j`: rows run along `u`, and each row holds the `count_v` points of one
//! `v` column, exactly like the `cvs_u_by_v[i][j]` arrays of the reference cases.

pub(crate) mod across;
pub(crate) mod bezier_patch;
pub(crate) mod bounding_box;
pub(crate) mod closest_point;
pub(crate) mod coons;
pub(crate) mod curvature;
pub(crate) mod derivatives;
pub(crate) mod direction;
pub(crate) mod edit;
pub(crate) mod forms;
pub(crate) mod grid;
pub(crate) mod isocurve;
pub(crate) mod loft;
pub(crate) mod normal;
pub(crate) mod offset;
pub(crate) mod revolution;
pub(crate) mod ruled;
pub(crate) mod sphere_fit;
pub(crate) mod subsurface;
pub(crate) mod sweep;

use crate::curve::nurbs::basis::{MAX_DEGREE, MAX_ORDER, basis_functions, span_index};
use crate::surface::direction::SurfaceDirection;
use crate::{Error, Interval, Point3, Result, SurfaceDerivatives, Vector3};

/// A non-uniform rational B-spline surface with knots in Rhino form.
///
/// In each direction there are `count ≥ degree + 1` control points and
/// `count + degree − 1` knots (Rhino form: the two superfluous end knots of the textbook form
/// are omitted). The domain in `u` is `knots_u[degree_u − 1] ..= knots_u[count_u − 1]`, and
/// likewise in `v`.
///
/// Instances are always valid: every constructor checks degrees, counts, knots and weights.
///
/// # Examples
/// ```
/// use locus_kernel::{Point3, Sphere};
/// # fn main() -> locus_kernel::Result<()> {
/// // Rhino's sphere of radius 2: degree 2 × 2, 9 × 5 control points.
/// let sphere = Sphere::new(Point3::ORIGIN, 2.0)?.to_nurbs()?;
/// assert_eq!((sphere.count_u(), sphere.count_v()), (9, 5));
///
/// // The book's Pull: the closest point to a point outside, with its parameters.
/// let cp = sphere.closest_point(Point3::new(0.0, 3.0, 4.0))?;
/// assert!((cp.distance - 3.0).abs() < 1e-12);
/// let normal = sphere.normal_at(cp.u, cp.v)?;
/// assert!((normal.y - 0.6).abs() < 1e-12 && (normal.z - 0.8).abs() < 1e-12);
///
/// // Curvatures are signed against the outward normal, as in Rhino.
/// let k = sphere.curvature_at(cp.u, cp.v)?;
/// assert!((k.gaussian - 0.25).abs() < 1e-12 && (k.mean + 0.5).abs() < 1e-12);
/// # Ok(())
/// # }
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct NurbsSurface {
    pub(crate) degree_u: usize,
    pub(crate) degree_v: usize,
    pub(crate) count_u: usize,
    pub(crate) count_v: usize,
    /// Euclidean control points, `i · count_v + j`.
    pub(crate) points: Vec<Point3>,
    /// Weights, parallel to `points`.
    pub(crate) weights: Vec<f64>,
    pub(crate) knots_u: Vec<f64>,
    pub(crate) knots_v: Vec<f64>,
    /// Whether any weight differs from 1.
    pub(crate) rational: bool,
}

impl NurbsSurface {
    /// Creates a surface from its degrees, a grid of control points `points[i][j]` (`i` along
    /// `u`, `j` along `v`), the matching grid of weights, and knot vectors in Rhino form.
    ///
    /// # Errors
    /// - [`Error::InvalidDegree`] if a degree is 0 or above [`MAX_DEGREE`];
    /// - [`Error::TooFewPoints`] if a direction has fewer than `degree + 1` control points;
    /// - [`Error::InvalidInput`] if the grid is ragged or the weights grid has another shape;
    /// - [`Error::InvalidKnots`] for a knot count other than `count + degree − 1`, decreasing
    ///   knots, a multiplicity above the degree, or an empty domain;
    /// - [`Error::InvalidWeight`] for a weight that is not positive and finite;
    /// - [`Error::NotFinite`] for NaN or infinite control points or knots.
    pub fn new(
        degree_u: usize,
        degree_v: usize,
        points: Vec<Vec<Point3>>,
        weights: Vec<Vec<f64>>,
        knots_u: Vec<f64>,
        knots_v: Vec<f64>,
    ) -> Result<Self> {
        let count_u = points.len();
        let count_v = points.first().map_or(0, Vec::len);
        if points.iter().any(|row| row.len() != count_v) {
            return Err(Error::InvalidInput(
                "control point grid rows have different lengths".into(),
            ));
        }
        if weights.len() != count_u || weights.iter().any(|row| row.len() != count_v) {
            return Err(Error::InvalidInput(format!(
                "weights grid must be {count_u} by {count_v} like the control points"
            )));
        }
        Self::from_flat(
            [degree_u, degree_v],
            [count_u, count_v],
            points.into_iter().flatten().collect(),
            weights.into_iter().flatten().collect(),
            [knots_u, knots_v],
        )
    }

    /// Creates a non-rational surface (all weights 1) from a grid of control points.
    ///
    /// # Errors
    /// As [`NurbsSurface::new`].
    pub fn non_rational(
        degree_u: usize,
        degree_v: usize,
        points: Vec<Vec<Point3>>,
        knots_u: Vec<f64>,
        knots_v: Vec<f64>,
    ) -> Result<Self> {
        let weights = points.iter().map(|row| vec![1.0; row.len()]).collect();
        Self::new(degree_u, degree_v, points, weights, knots_u, knots_v)
    }

    /// Creates a surface from flat, row-major storage: control point `(i, j)` at
    /// `i · counts[1] + j`. `degrees`, `counts` and `knots` are given as `[u, v]`.
    ///
    /// # Errors
    /// As [`NurbsSurface::new`], and [`Error::InvalidInput`] if `points` or `weights` do not
    /// hold `counts[0] · counts[1]` entries.
    pub fn from_flat(
        degrees: [usize; 2],
        counts: [usize; 2],
        points: Vec<Point3>,
        weights: Vec<f64>,
        knots: [Vec<f64>; 2],
    ) -> Result<Self> {
        let [degree_u, degree_v] = degrees;
        let [count_u, count_v] = counts;
        let [knots_u, knots_v] = knots;
        validate_direction("u", degree_u, count_u, &knots_u)?;
        validate_direction("v", degree_v, count_v, &knots_v)?;
        let n = count_u * count_v;
        if points.len() != n || weights.len() != n {
            return Err(Error::InvalidInput(format!(
                "a {count_u} by {count_v} surface needs {n} control points and weights, got {} \
                 and {}",
                points.len(),
                weights.len()
            )));
        }
        if let Some(index) = weights.iter().position(|w| !(w.is_finite() && *w > 0.0)) {
            return Err(Error::InvalidWeight {
                index,
                weight: weights[index],
            });
        }
        if points.iter().any(|p| !p.is_finite()) {
            return Err(Error::NotFinite {
                what: "control point",
            });
        }
        let rational = weights.iter().any(|&w| w != 1.0);
        Ok(Self {
            degree_u,
            degree_v,
            count_u,
            count_v,
            points,
            weights,
            knots_u,
            knots_v,
            rational,
        })
    }

    /// The degree in `u`.
    #[inline]
    pub fn degree_u(&self) -> usize {
        self.degree_u
    }

    /// The degree in `v`.
    #[inline]
    pub fn degree_v(&self) -> usize {
        self.degree_v
    }

    /// The degree in the given direction.
    #[inline]
    pub fn degree(&self, direction: SurfaceDirection) -> usize {
        match direction {
            SurfaceDirection::U => self.degree_u,
            SurfaceDirection::V => self.degree_v,
        }
    }

    /// The number of control points along `u` (the number of rows of the grid).
    #[inline]
    pub fn count_u(&self) -> usize {
        self.count_u
    }

    /// The number of control points along `v` (the length of each row of the grid).
    #[inline]
    pub fn count_v(&self) -> usize {
        self.count_v
    }

    /// The number of control points in the given direction.
    #[inline]
    pub fn count(&self, direction: SurfaceDirection) -> usize {
        match direction {
            SurfaceDirection::U => self.count_u,
            SurfaceDirection::V => self.count_v,
        }
    }

    /// All control points, row-major: `(i, j)` at `i · count_v + j`.
    #[inline]
    pub fn points(&self) -> &[Point3] {
        &self.points
    }

    /// All weights, parallel to [`points`](Self::points).
    #[inline]
    pub fn weights(&self) -> &[f64] {
        &self.weights
    }

    /// Control point `(i, j)`, or `None` outside the grid.
    #[inline]
    pub fn control_point(&self, i: usize, j: usize) -> Option<Point3> {
        (i < self.count_u && j < self.count_v).then(|| self.points[i * self.count_v + j])
    }

    /// The weight of control point `(i, j)`, or `None` outside the grid.
    #[inline]
    pub fn weight(&self, i: usize, j: usize) -> Option<f64> {
        (i < self.count_u && j < self.count_v).then(|| self.weights[i * self.count_v + j])
    }

    /// The knots in `u`, in Rhino form.
    #[inline]
    pub fn knots_u(&self) -> &[f64] {
        &self.knots_u
    }

    /// The knots in `v`, in Rhino form.
    #[inline]
    pub fn knots_v(&self) -> &[f64] {
        &self.knots_v
    }

    /// The knots in the given direction.
    #[inline]
    pub fn knots(&self, direction: SurfaceDirection) -> &[f64] {
        match direction {
            SurfaceDirection::U => &self.knots_u,
            SurfaceDirection::V => &self.knots_v,
        }
    }

    /// Whether any weight differs from 1.
    #[inline]
    pub fn is_rational(&self) -> bool {
        self.rational
    }

    /// The domain in `u`: `knots_u[degree_u − 1]` to `knots_u[count_u − 1]`.
    #[inline]
    pub fn domain_u(&self) -> Interval {
        Interval::new(
            self.knots_u[self.degree_u - 1],
            self.knots_u[self.count_u - 1],
        )
    }

    /// The domain in `v`: `knots_v[degree_v − 1]` to `knots_v[count_v − 1]`.
    #[inline]
    pub fn domain_v(&self) -> Interval {
        Interval::new(
            self.knots_v[self.degree_v - 1],
            self.knots_v[self.count_v - 1],
        )
    }

    /// The domain in the given direction.
    #[inline]
    pub fn domain(&self, direction: SurfaceDirection) -> Interval {
        match direction {
            SurfaceDirection::U => self.domain_u(),
            SurfaceDirection::V => self.domain_v(),
        }
    }

    /// The distinct knot values inside the domain in the given direction, from its start to
    /// its end: the boundaries of the polynomial spans.
    pub fn span_breaks(&self, direction: SurfaceDirection) -> Vec<f64> {
        let p = self.degree(direction);
        let n = self.count(direction);
        let knots = self.knots(direction);
        let mut breaks: Vec<f64> = Vec::with_capacity(n - p + 1);
        for &k in &knots[p - 1..n] {
            if breaks.last() != Some(&k) {
                breaks.push(k);
            }
        }
        breaks
    }

    /// The interior knots of the domain in the given direction whose multiplicity reaches the
    /// degree: there the surface is only C0 and may have a crease.
    pub fn c0_knots(&self, direction: SurfaceDirection) -> Vec<f64> {
        let p = self.degree(direction);
        let n = self.count(direction);
        let knots = self.knots(direction);
        let interior = &knots[p..n - 1];
        let mut out = Vec::new();
        let mut i = 0;
        while i < interior.len() {
            let mut j = i;
            while j + 1 < interior.len() && interior[j + 1] == interior[i] {
                j += 1;
            }
            if j + 1 - i >= p {
                out.push(interior[i]);
            }
            i = j + 1;
        }
        out
    }

    /// Whether every control point, weight and knot is finite (always true for a surface built
    /// by the checked constructors; kept for symmetry with the other geometry types).
    pub fn is_finite(&self) -> bool {
        self.points.iter().all(|p| p.is_finite())
            && self.weights.iter().all(|w| w.is_finite())
            && self.knots_u.iter().all(|k| k.is_finite())
            && self.knots_v.iter().all(|k| k.is_finite())
    }

    /// Whether the surface satisfies every rule the constructor checks.
    pub fn is_valid(&self) -> bool {
        validate_direction("u", self.degree_u, self.count_u, &self.knots_u).is_ok()
            && validate_direction("v", self.degree_v, self.count_v, &self.knots_v).is_ok()
            && self.points.len() == self.count_u * self.count_v
            && self.weights.len() == self.points.len()
            && self.weights.iter().all(|w| w.is_finite() && *w > 0.0)
            && self.points.iter().all(|p| p.is_finite())
    }

    /// The point at `(u, v)`, or an error if a parameter is not finite.
    ///
    /// # Errors
    /// [`Error::NotFinite`] if `u` or `v` is NaN or infinite.
    #[inline]
    pub fn try_point_at(&self, u: f64, v: f64) -> Result<Point3> {
        check_parameters(u, v)?;
        Ok(self.point_at(u, v))
    }

    /// The point at `(u, v)`.
    ///
    /// Parameters outside the domain extrapolate the polynomial of the nearest span, as Rhino
    /// does. A NaN parameter gives a NaN point (use [`try_point_at`](Self::try_point_at) to
    /// have it reported).
    pub fn point_at(&self, u: f64, v: f64) -> Point3 {
        let (p, q) = (self.degree_u, self.degree_v);
        let su = span_index(p, &self.knots_u, u);
        let sv = span_index(q, &self.knots_v, v);
        let mut nu = [0.0; MAX_ORDER];
        let mut nv = [0.0; MAX_ORDER];
        basis_functions(p, &self.knots_u, su, u, &mut nu);
        basis_functions(q, &self.knots_v, sv, v, &mut nv);
        let i0 = su + 1 - p;
        let j0 = sv + 1 - q;
        let (mut x, mut y, mut z, mut w) = (0.0, 0.0, 0.0, 0.0);
        for (r, &bu) in nu[..=p].iter().enumerate() {
            let row = (i0 + r) * self.count_v + j0;
            let pts = &self.points[row..=row + q];
            if self.rational {
                let ws = &self.weights[row..=row + q];
                for ((pt, &wt), &bv) in pts.iter().zip(ws).zip(&nv[..=q]) {
                    let b = bu * bv * wt;
                    x += b * pt.x;
                    y += b * pt.y;
                    z += b * pt.z;
                    w += b;
                }
            } else {
                let (mut rx, mut ry, mut rz) = (0.0, 0.0, 0.0);
                for (pt, &bv) in pts.iter().zip(&nv[..=q]) {
                    rx += bv * pt.x;
                    ry += bv * pt.y;
                    rz += bv * pt.z;
                }
                x += bu * rx;
                y += bu * ry;
                z += bu * rz;
            }
        }
        if self.rational {
            Point3::new(x / w, y / w, z / w)
        } else {
            Point3::new(x, y, z)
        }
    }

    /// The point and the partial derivatives up to `order` (0, 1 or 2) at `(u, v)`.
    ///
    /// Rational surfaces are differentiated through their homogeneous form
    /// (The NURBS Book, A3.6 and A4.4). At a knot the derivatives are those of the span that
    /// starts there (the last span at the end of the domain).
    ///
    /// # Errors
    /// [`Error::NotFinite`] if `u` or `v` is not finite, [`Error::InvalidInput`] if `order`
    /// is above 2.
    pub fn derivatives_at(&self, u: f64, v: f64, order: usize) -> Result<SurfaceDerivatives> {
        check_parameters(u, v)?;
        if order > 2 {
            return Err(Error::InvalidInput(format!(
                "derivative order {order} is above the supported 2"
            )));
        }
        Ok(self.derivatives_unchecked(u, v, order))
    }

    /// [`derivatives_at`](Self::derivatives_at) without checking the parameters.
    pub(crate) fn derivatives_unchecked(&self, u: f64, v: f64, order: usize) -> SurfaceDerivatives {
        let (p, q) = (self.degree_u, self.degree_v);
        let su = span_index(p, &self.knots_u, u);
        let sv = span_index(q, &self.knots_v, v);
        let mut nu = [[0.0; MAX_ORDER]; 3];
        let mut nv = [[0.0; MAX_ORDER]; 3];
        basis_with_derivatives(p, &self.knots_u, su, u, &mut nu);
        basis_with_derivatives(q, &self.knots_v, sv, v, &mut nv);
        let i0 = su + 1 - p;
        let j0 = sv + 1 - q;
        // a[k][l] is the homogeneous derivative ∂^(k+l) Sw / ∂u^k ∂v^l.
        let mut a = [[[0.0f64; 4]; 3]; 3];
        for k in 0..=order {
            let mut temp = [[0.0f64; 4]; MAX_ORDER];
            for (r, &b) in nu[k][..=p].iter().enumerate() {
                if b == 0.0 {
                    continue;
                }
                let row = (i0 + r) * self.count_v + j0;
                for (s, t) in temp[..=q].iter_mut().enumerate() {
                    let pt = self.points[row + s];
                    let bw = b * self.weights[row + s];
                    t[0] += bw * pt.x;
                    t[1] += bw * pt.y;
                    t[2] += bw * pt.z;
                    t[3] += bw;
                }
            }
            for l in 0..=(order - k) {
                let mut acc = [0.0f64; 4];
                for (t, &b) in temp[..=q].iter().zip(&nv[l][..=q]) {
                    for c in 0..4 {
                        acc[c] += b * t[c];
                    }
                }
                a[k][l] = acc;
            }
        }
        rational_derivatives(&a, order)
    }
}

/// The `p + 1` non-zero basis functions at `t` in span `span` with their first and second
/// derivatives: `out[k][r]` is the `k`-th derivative of the `r`-th function.
///
/// This is the triangle of The NURBS Book's A2.2 run up to degree `p`, with the derivatives
/// read off its last two steps: for the step from degree `j − 1` to `j` the algorithm forms
/// `temp_r = N_{r,j−1} / (u_{r+j} − u_r)`, and `N'_{r,j} = j (temp_{r−1} − temp_r)`. Applying
/// the same identity to the derivatives of degree `p − 1` gives the second derivatives. It is
/// equivalent to A2.3 for two derivatives but does a fraction of its work, which matters in
/// the hot loops of closest points and mass properties.
pub(crate) fn basis_with_derivatives(
    p: usize,
    knots: &[f64],
    span: usize,
    t: f64,
    out: &mut [[f64; MAX_ORDER]; 3],
) {
    let mut left = [0.0; MAX_ORDER];
    let mut right = [0.0; MAX_ORDER];
    for j in 1..=p {
        left[j] = t - knots[span + 1 - j];
        right[j] = knots[span + j] - t;
    }
    let mut n = [0.0; MAX_ORDER];
    n[0] = 1.0;
    // One step of the triangle from degree j − 1 to j; records temp_r and returns nothing.
    let step = |n: &mut [f64; MAX_ORDER], j: usize, temps: &mut [f64; MAX_ORDER]| {
        let mut saved = 0.0;
        for r in 0..j {
            let denom = right[r + 1] + left[j - r];
            let temp = if denom != 0.0 { n[r] / denom } else { 0.0 };
            temps[r] = temp;
            n[r] = saved + right[r + 1] * temp;
            saved = left[j - r] * temp;
        }
        n[j] = saved;
    };
    let mut temps = [0.0; MAX_ORDER];
    for j in 1..=p.saturating_sub(2) {
        step(&mut n, j, &mut temps);
    }
    // Derivatives of the degree p − 1 functions.
    let mut dm = [0.0; MAX_ORDER];
    if p >= 2 {
        step(&mut n, p - 1, &mut temps);
        let f = (p - 1) as f64;
        for (r, d) in dm[..p].iter_mut().enumerate() {
            let before = if r > 0 { temps[r - 1] } else { 0.0 };
            let after = if r < p - 1 { temps[r] } else { 0.0 };
            *d = f * (before - after);
        }
    }
    // The last step, with the first and second derivative quotients.
    let mut q = [0.0; MAX_ORDER];
    for (r, qr) in q[..p].iter_mut().enumerate() {
        let denom = right[r + 1] + left[p - r];
        *qr = if denom != 0.0 { dm[r] / denom } else { 0.0 };
    }
    step(&mut n, p, &mut temps);
    let f = p as f64;
    for r in 0..=p {
        let (t0, q0) = if r > 0 {
            (temps[r - 1], q[r - 1])
        } else {
            (0.0, 0.0)
        };
        let (t1, q1) = if r < p { (temps[r], q[r]) } else { (0.0, 0.0) };
        out[0][r] = n[r];
        out[1][r] = f * (t0 - t1);
        out[2][r] = f * (q0 - q1);
    }
}

/// Rejects NaN and infinite parameters.
#[inline]
pub(crate) fn check_parameters(u: f64, v: f64) -> Result<()> {
    if u.is_finite() && v.is_finite() {
        Ok(())
    } else {
        Err(Error::NotFinite { what: "parameter" })
    }
}

/// Checks the degree, control point count and Rhino-form knots of one direction.
fn validate_direction(name: &str, degree: usize, count: usize, knots: &[f64]) -> Result<()> {
    if degree == 0 || degree > MAX_DEGREE {
        return Err(Error::InvalidDegree {
            degree,
            reason: format!("the {name} degree must be between 1 and {MAX_DEGREE}"),
        });
    }
    if count < degree + 1 {
        return Err(Error::TooFewPoints {
            what: if name == "u" {
                "a nurbs surface in u"
            } else {
                "a nurbs surface in v"
            },
            needed: degree + 1,
            got: count,
        });
    }
    if knots.len() != count + degree - 1 {
        return Err(Error::InvalidKnots {
            reason: format!(
                "{name} needs {} knots for {count} control points of degree {degree}, got {}",
                count + degree - 1,
                knots.len()
            ),
        });
    }
    if knots.iter().any(|k| !k.is_finite()) {
        return Err(Error::NotFinite { what: "knot" });
    }
    let mut run = 1;
    for i in 1..knots.len() {
        if knots[i] < knots[i - 1] {
            return Err(Error::InvalidKnots {
                reason: format!("{name} knots decrease at index {i}"),
            });
        }
        if knots[i] == knots[i - 1] {
            run += 1;
            if run > degree {
                return Err(Error::InvalidKnots {
                    reason: format!(
                        "{name} knot {} has multiplicity above the degree {degree}",
                        knots[i]
                    ),
                });
            }
        } else {
            run = 1;
        }
    }
    if knots[degree - 1] >= knots[count - 1] {
        return Err(Error::InvalidKnots {
            reason: format!("the {name} domain is empty"),
        });
    }
    Ok(())
}

/// The point and derivatives up to `order` (at most 2) of a rational surface from the
/// homogeneous ones, `a[k][l] = ∂^(k+l) Sw / ∂u^k ∂v^l` (The NURBS Book, A4.4).
pub(crate) fn rational_derivatives(a: &[[[f64; 4]; 3]; 3], order: usize) -> SurfaceDerivatives {
    const BINOMIAL: [[f64; 3]; 3] = [[1.0, 0.0, 0.0], [1.0, 1.0, 0.0], [1.0, 2.0, 1.0]];
    let mut s = [[[0.0f64; 3]; 3]; 3];
    let w0 = a[0][0][3];
    for k in 0..=order {
        for l in 0..=(order - k) {
            let mut v = [a[k][l][0], a[k][l][1], a[k][l][2]];
            for j in 1..=l {
                let f = BINOMIAL[l][j] * a[0][j][3];
                for c in 0..3 {
                    v[c] -= f * s[k][l - j][c];
                }
            }
            for i in 1..=k {
                let f = BINOMIAL[k][i] * a[i][0][3];
                for c in 0..3 {
                    v[c] -= f * s[k - i][l][c];
                }
                let mut v2 = [0.0f64; 3];
                for j in 1..=l {
                    let g = BINOMIAL[l][j] * a[i][j][3];
                    for c in 0..3 {
                        v2[c] += g * s[k - i][l - j][c];
                    }
                }
                for c in 0..3 {
                    v[c] -= BINOMIAL[k][i] * v2[c];
                }
            }
            for c in 0..3 {
                s[k][l][c] = v[c] / w0;
            }
        }
    }
    let vec = |x: [f64; 3]| Vector3::new(x[0], x[1], x[2]);
    SurfaceDerivatives {
        point: Point3::new(s[0][0][0], s[0][0][1], s[0][0][2]),
        du: vec(s[1][0]),
        dv: vec(s[0][1]),
        duu: vec(s[2][0]),
        duv: vec(s[1][1]),
        dvv: vec(s[0][2]),
    }
}

#[cfg(test)]
pub(crate) mod tests;

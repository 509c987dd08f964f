//! NURBS curves: validation, evaluation of points and derivatives, and the local differential
//! geometry (tangent, curvature, frame) derived from them.
//!
//! A NURBS curve of degree `p` with `n` control points `P_i`, weights `w_i` and a knot vector in
//! Rhino form (`n + p − 1` knots) is
//!
//! ```text
//! C(t) = Σ N_i,p(t) w_i P_i / Σ N_i,p(t) w_i
//! ```
//!
//! Points are evaluated from the `p + 1` non-zero basis functions of the span containing `t`
//! ([`crate::basis`]). Derivatives are those of the homogeneous curve `(Σ N w P, Σ N w)` followed
//! by the quotient rule (The NURBS Book, A4.2).
//!
//! Editing operations (knot insertion, split, reverse, transform, reparameterization) live in
//! `nurbs_curve_edit.rs`, batch evaluation in `nurbs_curve_batch.rs`.

pub mod basis;
pub(crate) mod batch;
pub(crate) mod bounding_box;
pub(crate) mod compatible;
pub(crate) mod create;
pub(crate) mod edit;
pub(crate) mod interpolate;
pub(crate) mod interpolate_periodic;

use crate::curve::nurbs::basis::{MAX_DEGREE, MAX_ORDER};
use crate::geometry::tolerance::ZERO_TOLERANCE;
use crate::{Error, Interval, Plane, Point3, Result, Vector3, perpendicular_to};

/// A non-uniform rational B-spline curve in Rhino's representation.
///
/// Control points are Euclidean with a separate weight (the homogeneous point is `(w·P, w)`),
/// and the knot vector is in Rhino form: `|knots| = |points| + degree − 1`. Periodic curves are
/// stored as Rhino stores them: unclamped knots, with the last `degree` control points repeating
/// the first ones; they evaluate like any other curve.
///
/// The fields are private so that every value is valid: construct with [`NurbsCurve::new`] or one
/// of the constructions (`create`, `interpolate`, exact forms of lines, circles and arcs).
#[derive(Clone, Debug, PartialEq)]
pub struct NurbsCurve {
    degree: usize,
    points: Vec<Point3>,
    weights: Vec<f64>,
    knots: Vec<f64>,
    rational: bool,
}

impl NurbsCurve {
    /// Creates a curve from its degree, Euclidean control points, weights and knots (Rhino form).
    ///
    /// # Errors
    /// - [`Error::InvalidDegree`] if the degree is 0 or above [`MAX_DEGREE`];
    /// - [`Error::TooFewPoints`] with fewer than `degree + 1` control points;
    /// - [`Error::InvalidInput`] if there are not as many weights as points;
    /// - [`Error::NotFinite`] for a NaN or infinite coordinate;
    /// - [`Error::InvalidWeight`] for a weight that is zero, negative or not finite;
    /// - [`Error::InvalidKnots`] if the knot count is not `points + degree − 1`, a knot is not
    ///   finite, the knots decrease, a knot is repeated more than `degree` times, or the first or
    ///   last span of the domain is empty.
    pub fn new(
        degree: usize,
        points: Vec<Point3>,
        weights: Vec<f64>,
        knots: Vec<f64>,
    ) -> Result<Self> {
        validate(degree, &points, &weights, &knots)?;
        let rational = weights.iter().any(|&w| w != 1.0);
        Ok(Self {
            degree,
            points,
            weights,
            knots,
            rational,
        })
    }

    /// Creates a non-rational curve (all weights 1).
    ///
    /// # Errors
    /// As [`NurbsCurve::new`].
    pub fn new_non_rational(degree: usize, points: Vec<Point3>, knots: Vec<f64>) -> Result<Self> {
        let weights = vec![1.0; points.len()];
        Self::new(degree, points, weights, knots)
    }

    /// Assembles a curve from parts that the caller guarantees to be valid.
    pub(crate) fn from_parts_unchecked(
        degree: usize,
        points: Vec<Point3>,
        weights: Vec<f64>,
        knots: Vec<f64>,
    ) -> Self {
        debug_assert!(validate(degree, &points, &weights, &knots).is_ok());
        let rational = weights.iter().any(|&w| w != 1.0);
        Self {
            degree,
            points,
            weights,
            knots,
            rational,
        }
    }

    /// The degree.
    #[inline]
    pub fn degree(&self) -> usize {
        self.degree
    }

    /// The order, `degree + 1`.
    #[inline]
    pub fn order(&self) -> usize {
        self.degree + 1
    }

    /// The Euclidean control points.
    #[inline]
    pub fn points(&self) -> &[Point3] {
        &self.points
    }

    /// The weights, one per control point.
    #[inline]
    pub fn weights(&self) -> &[f64] {
        &self.weights
    }

    /// The knots in Rhino form.
    #[inline]
    pub fn knots(&self) -> &[f64] {
        &self.knots
    }

    /// The number of control points.
    #[inline]
    pub fn point_count(&self) -> usize {
        self.points.len()
    }

    /// The parameter interval `[knots[degree − 1], knots[point_count − 1]]`.
    #[inline]
    pub fn domain(&self) -> Interval {
        Interval::new(
            self.knots[self.degree - 1],
            self.knots[self.points.len() - 1],
        )
    }

    /// The number of non-empty spans (polynomial pieces).
    pub fn span_count(&self) -> usize {
        self.span_indices().count()
    }

    /// The Rhino knot indices `i` of the non-empty spans `[knots[i], knots[i+1]]` of the domain,
    /// in increasing order.
    pub fn span_indices(&self) -> impl Iterator<Item = usize> + '_ {
        let k = &self.knots;
        (self.degree - 1..self.points.len() - 1).filter(move |&i| k[i] < k[i + 1])
    }

    /// The distinct knot values inside the domain, its ends included: the breakpoints between
    /// the polynomial pieces.
    pub fn span_breaks(&self) -> Vec<f64> {
        let mut out: Vec<f64> = self.span_indices().map(|i| self.knots[i]).collect();
        out.push(self.domain().t1);
        out
    }

    /// Whether some weight differs from 1 (the curve is then a true rational curve).
    #[inline]
    pub fn is_rational(&self) -> bool {
        self.rational
    }

    /// Whether every control point, weight and knot is finite.
    pub fn is_finite(&self) -> bool {
        self.points.iter().all(|p| p.is_finite())
            && self.weights.iter().all(|w| w.is_finite())
            && self.knots.iter().all(|k| k.is_finite())
    }

    /// Whether the curve satisfies every rule that [`NurbsCurve::new`] checks.
    ///
    /// Always true for values built through the public API; provided for symmetry with Rhino's
    /// `IsValid` and as a check after deserialization.
    pub fn is_valid(&self) -> bool {
        validate(self.degree, &self.points, &self.weights, &self.knots).is_ok()
    }

    /// Whether the curve is periodic in Rhino's sense: degree at least 2, knot spacing repeating
    /// with the period of the domain, and the last `degree` control points (with their weights)
    /// repeating the first ones. Such a curve is closed and smooth at its seam.
    pub fn is_periodic(&self) -> bool {
        let p = self.degree;
        let n = self.points.len();
        if p < 2 || n < 2 * p {
            return false;
        }
        let m = n - p; // The number of distinct control points.
        let period = self.domain().length();
        let scale = self.knots.iter().fold(period.abs(), |s, k| s.max(k.abs()));
        let tol = 1e-12 * scale.max(1.0);
        let k = &self.knots;
        for i in 0..k.len() - m {
            if ((k[i + m] - k[i]) - period).abs() > tol {
                return false;
            }
        }
        (0..p)
            .all(|i| self.points[i] == self.points[i + m] && self.weights[i] == self.weights[i + m])
    }

    /// Whether the curve is closed: it is periodic, or its start and end points coincide (within
    /// [`ZERO_TOLERANCE`] relative to the size of the control polygon) and it does not collapse
    /// to the start point, as Rhino's `IsClosed`.
    pub fn is_closed(&self) -> bool {
        if self.is_periodic() {
            return true;
        }
        if self.points.len() < 3 || (self.degree > 1 && self.points.len() < 4) {
            return false;
        }
        let d = self.domain();
        let a = self.point_at(d.t0);
        let b = self.point_at(d.t1);
        let tol = self.coincidence_tolerance();
        if a.distance(b) > tol {
            return false;
        }
        let c = self.point_at(d.parameter_at(1.0 / 3.0));
        let e = self.point_at(d.parameter_at(2.0 / 3.0));
        a.distance(c) > tol || a.distance(e) > tol
    }

    /// The distance under which two points of this curve count as the same point:
    /// [`ZERO_TOLERANCE`] scaled by the size of the control polygon (at least 1).
    pub(crate) fn coincidence_tolerance(&self) -> f64 {
        let size = self.points.iter().fold(1.0f64, |m, p| {
            m.max(p.x.abs()).max(p.y.abs()).max(p.z.abs())
        });
        ZERO_TOLERANCE * size
    }

    /// The point at the start of the domain.
    #[inline]
    pub fn start_point(&self) -> Point3 {
        self.point_at(self.domain().t0)
    }

    /// The point at the end of the domain.
    #[inline]
    pub fn end_point(&self) -> Point3 {
        self.point_at(self.domain().t1)
    }

    /// The point at parameter `t`.
    ///
    /// Parameters outside the domain extrapolate the first or last polynomial piece, as Rhino
    /// does. A NaN parameter gives a NaN point (use [`NurbsCurve::try_point_at`] to have it
    /// reported).
    #[inline]
    pub fn point_at(&self, t: f64) -> Point3 {
        let p = self.degree;
        let span = basis::span_index(p, &self.knots, t);
        let mut n = [0.0; MAX_ORDER];
        basis::basis_functions(p, &self.knots, span, t, &mut n);
        self.combine(span, &n)
    }

    /// The point at `t`, or an error if `t` is not finite.
    ///
    /// # Errors
    /// [`Error::NotFinite`] when `t` is NaN or infinite.
    pub fn try_point_at(&self, t: f64) -> Result<Point3> {
        if !t.is_finite() {
            return Err(Error::NotFinite { what: "parameter" });
        }
        Ok(self.point_at(t))
    }

    /// The curve point from the basis functions `n[..=degree]` of span `span`.
    #[inline]
    pub(crate) fn combine(&self, span: usize, n: &[f64; MAX_ORDER]) -> Point3 {
        let p = self.degree;
        let first = span + 1 - p;
        let cvs = &self.points[first..=first + p];
        let (mut x, mut y, mut z) = (0.0, 0.0, 0.0);
        if self.rational {
            let ws = &self.weights[first..=first + p];
            let mut w = 0.0;
            for j in 0..=p {
                let b = n[j] * ws[j];
                x += b * cvs[j].x;
                y += b * cvs[j].y;
                z += b * cvs[j].z;
                w += b;
            }
            Point3::new(x / w, y / w, z / w)
        } else {
            for j in 0..=p {
                x += n[j] * cvs[j].x;
                y += n[j] * cvs[j].y;
                z += n[j] * cvs[j].z;
            }
            Point3::new(x, y, z)
        }
    }

    /// The homogeneous derivatives `A^(k) = (Σ N^(k) w P, Σ N^(k) w)` for `k ≤ min(order,
    /// degree)` at `t`, from the right of a knot (from the left at the end of the domain).
    fn homogeneous_derivatives(
        &self,
        span: usize,
        t: f64,
        order: usize,
        out: &mut [[f64; 4]; MAX_ORDER],
    ) {
        let p = self.degree;
        let top = order.min(p);
        // Rows for the derivatives asked for only (most callers want up to the second).
        let mut few = [[0.0; MAX_ORDER]; 3];
        let mut all;
        let ders: &mut [[f64; MAX_ORDER]] = if top < few.len() {
            &mut few[..=top]
        } else {
            all = [[0.0; MAX_ORDER]; MAX_ORDER];
            &mut all[..=top]
        };
        basis::basis_function_derivatives(p, &self.knots, span, t, top, ders);
        let first = span + 1 - p;
        for (k, row) in ders.iter().enumerate().take(top + 1) {
            let mut acc = [0.0; 4];
            let cvs = &self.points[first..=first + p];
            let ws = &self.weights[first..=first + p];
            for ((&n, &w), c) in row.iter().zip(ws).zip(cvs) {
                let b = n * w;
                acc[0] += b * c.x;
                acc[1] += b * c.y;
                acc[2] += b * c.z;
                acc[3] += b;
            }
            out[k] = acc;
        }
    }

    /// Writes the position (as a vector from the origin) and the derivatives at `t` to `out`:
    /// `out[0]` is `C(t)`, `out[k]` the `k`-th derivative, for `k < out.len()`. Allocation-free.
    ///
    /// At an interior knot the derivatives are those from the right (the span starting at the
    /// knot); at the end of the domain those from the left.
    pub fn derivatives_into(&self, t: f64, out: &mut [Vector3]) {
        let span = basis::span_index(self.degree, &self.knots, t);
        self.derivatives_in_span(span, t, out);
    }

    /// As [`NurbsCurve::derivatives_into`], with the polynomial piece of the span `span` (a
    /// Rhino knot index from [`NurbsCurve::span_indices`]), so that at a knot the derivatives
    /// of either adjacent piece can be had.
    pub(crate) fn derivatives_in_span(&self, span: usize, t: f64, out: &mut [Vector3]) {
        if out.is_empty() {
            return;
        }
        let order = out.len() - 1;
        let p = self.degree;
        let mut aw = [[0.0; 4]; MAX_ORDER];
        self.homogeneous_derivatives(span, t, order, &mut aw);
        let w0 = aw[0][3];
        // C^(k) = (A^(k) − Σ_{i=1..k} C(k,i) w^(i) C^(k−i)) / w, with w^(i) = 0 for i > degree.
        for k in 0..=order {
            let mut v = if k <= p {
                Vector3::new(aw[k][0], aw[k][1], aw[k][2])
            } else {
                Vector3::ZERO
            };
            if self.rational {
                let mut binom = 1.0;
                for i in 1..=k.min(p) {
                    binom = binom * (k + 1 - i) as f64 / i as f64;
                    v -= out[k - i] * (binom * aw[i][3]);
                }
                v = v / w0;
            }
            out[k] = v;
        }
    }

    /// The position (as a vector from the origin) and derivatives up to `order` at `t`:
    /// element `k` is the `k`-th derivative, element 0 the point, as Rhino's `DerivativeAt`.
    pub fn derivatives_at(&self, t: f64, order: usize) -> Vec<Vector3> {
        let mut out = vec![Vector3::ZERO; order + 1];
        self.derivatives_into(t, &mut out);
        out
    }

    /// The point and the first and second derivatives at `t`.
    #[inline]
    pub fn point_and_derivatives_at(&self, t: f64) -> (Point3, Vector3, Vector3) {
        let mut d = [Vector3::ZERO; 3];
        self.derivatives_into(t, &mut d);
        (Point3::from_vector(d[0]), d[1], d[2])
    }

    /// The first derivative `C'(t)`.
    #[inline]
    pub fn derivative_at(&self, t: f64) -> Vector3 {
        let mut d = [Vector3::ZERO; 2];
        self.derivatives_into(t, &mut d);
        d[1]
    }

    /// The unit tangent at `t`, or `None` where every derivative up to the degree vanishes
    /// (a curve collapsed to a point).
    ///
    /// Where the first derivative is zero (a degenerate control polygon), the direction is that
    /// of the first non-zero higher derivative, taken in the direction of travel, as Rhino's
    /// `ON_EvTangent` does.
    pub fn tangent_at(&self, t: f64) -> Option<Vector3> {
        let mut d = [Vector3::ZERO; MAX_ORDER];
        let order = self.degree.min(MAX_DEGREE);
        self.derivatives_into(t, &mut d[..=order]);
        let at_end = t >= self.domain().t1;
        tangent_from_derivatives(&d[1..=order], at_end)
    }

    /// The curvature vector at `t`: it points to the centre of the osculating circle and its
    /// length is the curvature `1/r`. `None` where the first derivative vanishes.
    pub fn curvature_at(&self, t: f64) -> Option<Vector3> {
        let (_, d1, d2) = self.point_and_derivatives_at(t);
        curvature_vector(d1, d2)
    }

    /// The signed curvature at `t` of a curve lying in a plane with normal `normal`: positive
    /// where the curve turns counter-clockwise seen from the side the normal points to
    /// (osculating circle on the left), negative where it turns clockwise.
    /// `None` where the first derivative or the normal vanishes.
    pub fn signed_curvature_at(&self, t: f64, normal: Vector3) -> Option<f64> {
        let (_, d1, d2) = self.point_and_derivatives_at(t);
        signed_curvature(d1, d2, normal)
    }

    /// The Frenet-style frame at `t`: origin on the curve, x axis the unit tangent, y axis the
    /// direction of the curvature vector, z axis their cross product. Where the curvature is
    /// zero the y axis is a perpendicular chosen as Rhino's `PerpendicularTo`.
    /// `None` where the tangent is undefined.
    pub fn frame_at(&self, t: f64) -> Option<Plane> {
        let (p, d1, d2) = self.point_and_derivatives_at(t);
        let tangent = self.tangent_at(t)?;
        frame_from(p, tangent, curvature_vector(d1, d2))
    }
}

/// The unit tangent from derivatives `ders[0] = C'`, `ders[1] = C''`, … : the first derivative
/// that does not vanish, in the direction of travel (`at_end` tells that the parameter is at the
/// end of the domain, where the derivatives are approached from the left).
pub(crate) fn tangent_from_derivatives(ders: &[Vector3], at_end: bool) -> Option<Vector3> {
    let scale = ders.iter().fold(0.0f64, |m, d| m.max(d.length()));
    for (i, d) in ders.iter().enumerate() {
        let k = i + 1;
        if let Some(u) = d.try_normalize() {
            if d.length() <= 1e-12 * scale && k < ders.len() {
                continue;
            }
            // Near t₁ from the left C(t) − C(t₁) ≈ d (t − t₁)^k / k!, whose velocity has the
            // sign of (t − t₁)^(k−1): negative for even k.
            return Some(if at_end && k % 2 == 0 { -u } else { u });
        }
    }
    None
}

/// The curvature vector `(C'' − (C''·T)T) / |C'|²` with `T = C'/|C'|`, or `None` when `C'`
/// vanishes.
pub(crate) fn curvature_vector(d1: Vector3, d2: Vector3) -> Option<Vector3> {
    let len2 = d1.length_squared();
    let t = d1.try_normalize()?;
    Some((d2 - t * d2.dot(t)) / len2)
}

/// The signed curvature `(C' × C'')·n / |C'|³` about the unit normal `n`.
pub(crate) fn signed_curvature(d1: Vector3, d2: Vector3, normal: Vector3) -> Option<f64> {
    let n = normal.try_normalize()?;
    d1.try_normalize()?;
    let len = d1.length();
    Some(d1.cross(d2).dot(n) / (len * len * len))
}

/// The frame at `origin` with x axis `tangent` (unit) and y axis along `curvature` when it is
/// non-zero and not parallel to the tangent.
pub(crate) fn frame_from(
    origin: Point3,
    tangent: Vector3,
    curvature: Option<Vector3>,
) -> Option<Plane> {
    let y = curvature
        .and_then(|k| (k - tangent * k.dot(tangent)).try_normalize())
        .or_else(|| perpendicular_to(tangent).try_normalize())?;
    Some(Plane {
        origin,
        x_axis: tangent,
        y_axis: y,
        z_axis: tangent.cross(y),
    })
}

/// Checks every rule of a NURBS curve; see [`NurbsCurve::new`].
pub(crate) fn validate(
    degree: usize,
    points: &[Point3],
    weights: &[f64],
    knots: &[f64],
) -> Result<()> {
    if degree == 0 {
        return Err(Error::InvalidDegree {
            degree,
            reason: "the degree must be at least 1".into(),
        });
    }
    if degree > MAX_DEGREE {
        return Err(Error::InvalidDegree {
            degree,
            reason: format!("the degree must be at most {MAX_DEGREE}"),
        });
    }
    if points.len() < degree + 1 {
        return Err(Error::TooFewPoints {
            what: "a nurbs curve of this degree",
            needed: degree + 1,
            got: points.len(),
        });
    }
    if weights.len() != points.len() {
        return Err(Error::InvalidInput(format!(
            "{} weights for {} control points",
            weights.len(),
            points.len()
        )));
    }
    if points.iter().any(|p| !p.is_finite()) {
        return Err(Error::NotFinite {
            what: "control point",
        });
    }
    if let Some((index, &weight)) = weights
        .iter()
        .enumerate()
        .find(|&(_, &w)| !(w.is_finite() && w > 0.0))
    {
        return Err(Error::InvalidWeight { index, weight });
    }
    validate_knots(degree, points.len(), knots)
}

/// Checks a Rhino-form knot vector for `point_count` control points of degree `degree`.
pub(crate) fn validate_knots(degree: usize, point_count: usize, knots: &[f64]) -> Result<()> {
    let expected = point_count + degree - 1;
    if knots.len() != expected {
        return Err(Error::InvalidKnots {
            reason: format!(
                "{} knots for {point_count} control points of degree {degree}, expected {expected}",
                knots.len()
            ),
        });
    }
    if let Some(i) = knots.iter().position(|k| !k.is_finite()) {
        return Err(Error::InvalidKnots {
            reason: format!("knot {i} is not finite"),
        });
    }
    let mut run = 1;
    for i in 1..knots.len() {
        if knots[i] < knots[i - 1] {
            return Err(Error::InvalidKnots {
                reason: format!(
                    "knots decrease at index {i} ({} after {})",
                    knots[i],
                    knots[i - 1]
                ),
            });
        }
        if knots[i] == knots[i - 1] {
            run += 1;
            if run > degree {
                return Err(Error::InvalidKnots {
                    reason: format!(
                        "knot {} has multiplicity above the degree {degree}",
                        knots[i]
                    ),
                });
            }
        } else {
            run = 1;
        }
    }
    // The first and last spans of the domain must not be empty (Rhino's ON_IsValidKnotVector).
    let lo = degree - 1;
    let hi = point_count - 1;
    if knots[lo] >= knots[lo + 1] || knots[hi - 1] >= knots[hi] {
        return Err(Error::InvalidKnots {
            reason: "the first and last spans of the domain must not be empty".into(),
        });
    }
    Ok(())
}

#[cfg(test)]
mod tests;

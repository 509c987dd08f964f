//! Degree elevation and compatible curves: curves with one degree and one knot vector, whose
//! control points can be paired up to build ruled surfaces and lofts.
//!
//! Degree elevation raises the degree by `t` without changing the shape: every distinct knot
//! gains multiplicity `t` (the ends become `degree + t` fold). The new control points are
//! found by interpolating the curve at the Greville abscissae of the new knot vector in
//! homogeneous coordinates: the elevated curve lies exactly in the new spline space, so the
//! interpolation reproduces it (up to rounding). The collocation matrix of B-splines at the
//! Greville abscissae is banded and totally positive, so Gaussian elimination without pivoting
//! is stable (de Boor, *A Practical Guide to Splines*, ch. XIII).
//!
//! [`NurbsCurve::make_compatible`] reparameterizes curves to `0..1`, clamps them, elevates them
//! to the highest degree among them and inserts every knot of each into the others.

use crate::curve::nurbs::basis::{MAX_DEGREE, MAX_ORDER, basis_functions, span_index};
use crate::{Error, Interval, NurbsCurve, Result};

/// Pivots of the collocation system smaller than this are taken as singular.
const SINGULAR_PIVOT: f64 = 1e-14;

impl NurbsCurve {
    /// The homogeneous point `(w·P, w)` at `t`.
    fn homogeneous_at(&self, t: f64) -> [f64; 4] {
        let p = self.degree();
        let knots = self.knots();
        let span = span_index(p, knots, t);
        let mut basis = [0.0; MAX_ORDER];
        basis_functions(p, knots, span, t, &mut basis);
        let first = span + 1 - p;
        let mut h = [0.0; 4];
        for (k, &b) in basis[..=p].iter().enumerate() {
            let (pt, w) = (self.points()[first + k], self.weights()[first + k]);
            h[0] += b * w * pt.x;
            h[1] += b * w * pt.y;
            h[2] += b * w * pt.z;
            h[3] += b * w;
        }
        h
    }

    /// The same curve at degree `degree` (not below its own), clamped: every distinct knot
    /// gains multiplicity `degree − self.degree()`.
    ///
    /// # Errors
    /// [`Error::InvalidDegree`] for a degree below the curve's or above [`MAX_DEGREE`];
    /// [`Error::InvalidInput`] if the collocation system is singular (not for valid curves).
    pub fn elevated(&self, degree: usize) -> Result<Self> {
        let p = self.degree();
        if degree < p || degree > MAX_DEGREE {
            return Err(Error::InvalidDegree {
                degree,
                reason: format!("elevation needs a degree from {p} to {MAX_DEGREE}"),
            });
        }
        let clamped = self.clamped();
        if degree == p {
            return Ok(clamped);
        }
        let t = degree - p;
        let q = degree;
        // Distinct knots with their multiplicities; the ends are clamped (multiplicity p).
        let mut distinct: Vec<(f64, usize)> = Vec::new();
        for &k in clamped.knots() {
            match distinct.last_mut() {
                Some((v, m)) if *v == k => *m += 1,
                _ => distinct.push((k, 1)),
            }
        }
        let mut knots = Vec::new();
        for (k, m) in distinct {
            knots.extend(std::iter::repeat_n(k, m + t));
        }
        let count = knots.len() + 1 - q;
        // Greville abscissae in Rhino form: the mean of knots[i..i + q].
        let greville: Vec<f64> = (0..count)
            .map(|i| knots[i..i + q].iter().sum::<f64>() / q as f64)
            .collect();
        let rhs: Vec<[f64; 4]> = greville
            .iter()
            .map(|&g| clamped.homogeneous_at(g))
            .collect();
        let cvs = solve_collocation(q, &knots, &greville, rhs)?;
        Self::from_homogeneous(q, &cvs, knots)
    }

    /// The curves made compatible: each reparameterized to `0..1`, clamped, raised to the
    /// highest degree among them, and with every knot of each inserted into the others, so
    /// that all have the same degree, knot vector and number of control points. Shapes are
    /// unchanged.
    ///
    /// # Errors
    /// [`Error::TooFewPoints`] for no curves; the errors of [`NurbsCurve::elevated`] and
    /// [`NurbsCurve::insert_knot`].
    pub fn make_compatible(curves: &[NurbsCurve]) -> Result<Vec<NurbsCurve>> {
        if curves.is_empty() {
            return Err(Error::TooFewPoints {
                what: "compatible curves",
                needed: 1,
                got: 0,
            });
        }
        let degree = curves.iter().map(NurbsCurve::degree).max().unwrap_or(1);
        let mut out = Vec::with_capacity(curves.len());
        for c in curves {
            let unit = c.clamped().reparameterized(Interval::UNIT)?;
            out.push(unit.elevated(degree)?);
        }
        // The union of the interior knots, each with its highest multiplicity.
        let mut union: Vec<(f64, usize)> = Vec::new();
        for c in &out {
            let knots = c.knots();
            let interior = &knots[degree..knots.len() - degree];
            let mut i = 0;
            while i < interior.len() {
                let k = interior[i];
                let m = interior[i..].iter().take_while(|&&x| x == k).count();
                match union.iter_mut().find(|(v, _)| *v == k) {
                    Some((_, um)) => *um = (*um).max(m),
                    None => union.push((k, m)),
                }
                i += m;
            }
        }
        for c in &mut out {
            for &(k, m) in &union {
                let have = c.knot_multiplicity(k);
                if have < m {
                    *c = c.insert_knot(k, m - have)?;
                }
            }
        }
        Ok(out)
    }
}

impl NurbsCurve {
    /// The curve between `a` and `b` at `factor` (Rhino's tween curves, Grasshopper's Tween
    /// Curve): the two made compatible ([`NurbsCurve::make_compatible`], domain `0..1`) and
    /// every homogeneous control point blended, `(1 − f) A + f B`, so that the factor 0 gives
    /// `a` and 1 gives `b` (as shapes). Factors outside `0..1` extrapolate.
    ///
    /// # Errors
    /// [`Error::NotFinite`] for a non-finite factor; [`Error::InvalidWeight`] when the blended
    /// weights are not positive (far extrapolation of rational curves); the errors of
    /// [`NurbsCurve::make_compatible`].
    pub fn tween(a: &NurbsCurve, b: &NurbsCurve, factor: f64) -> Result<Self> {
        if !factor.is_finite() {
            return Err(Error::NotFinite { what: "factor" });
        }
        let curves = Self::make_compatible(&[a.clone(), b.clone()])?;
        let (ha, hb) = (
            curves[0].homogeneous_points(),
            curves[1].homogeneous_points(),
        );
        let blended: Vec<[f64; 4]> = ha
            .iter()
            .zip(&hb)
            .map(|(p, q)| std::array::from_fn(|k| (1.0 - factor) * p[k] + factor * q[k]))
            .collect();
        Self::from_homogeneous(curves[0].degree(), &blended, curves[0].knots().to_vec())
    }
}

/// Solves the banded collocation system `Σⱼ Nⱼ(ξᵢ) xⱼ = rhsᵢ` for homogeneous points, by
/// Gaussian elimination without pivoting in band storage.
pub(crate) fn solve_collocation(
    degree: usize,
    knots: &[f64],
    params: &[f64],
    mut rhs: Vec<[f64; 4]>,
) -> Result<Vec<[f64; 4]>> {
    let n = params.len();
    let width = 2 * degree + 1;
    // band[r][k] holds A[r][r + k − degree].
    let mut band = vec![vec![0.0; width]; n];
    let mut basis = [0.0; MAX_ORDER];
    for (r, &x) in params.iter().enumerate() {
        let span = span_index(degree, knots, x);
        basis_functions(degree, knots, span, x, &mut basis);
        let first = span + 1 - degree;
        for (k, &b) in basis[..=degree].iter().enumerate() {
            let col = first + k;
            if col + degree < r || col > r + degree {
                if b != 0.0 {
                    return Err(Error::InvalidInput(
                        "degree elevation: a collocation point lies outside its band".into(),
                    ));
                }
                continue;
            }
            band[r][col + degree - r] = b;
        }
    }
    let singular = || Error::InvalidInput("degree elevation: singular collocation system".into());
    for c in 0..n {
        let pivot = band[c][degree];
        if pivot.abs() < SINGULAR_PIVOT {
            return Err(singular());
        }
        for r in c + 1..n.min(c + degree + 1) {
            let factor = band[r][c + degree - r] / pivot;
            if factor == 0.0 {
                continue;
            }
            band[r][c + degree - r] = 0.0;
            for col in c + 1..n.min(c + degree + 1) {
                let v = band[c][col + degree - c];
                band[r][col + degree - r] -= factor * v;
            }
            let rc = rhs[c];
            for (x, y) in rhs[r].iter_mut().zip(rc) {
                *x -= factor * y;
            }
        }
    }
    for r in (0..n).rev() {
        let mut acc = rhs[r];
        for col in r + 1..n.min(r + degree + 1) {
            let a = band[r][col + degree - r];
            for (x, y) in acc.iter_mut().zip(rhs[col]) {
                *x -= a * y;
            }
        }
        let d = band[r][degree];
        rhs[r] = acc.map(|x| x / d);
    }
    if rhs.iter().flatten().any(|x| !x.is_finite()) || rhs.iter().any(|h| h[3] <= 0.0) {
        return Err(singular());
    }
    Ok(rhs)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Circle, Plane, Point3};

    fn wavy() -> NurbsCurve {
        NurbsCurve::new(
            3,
            vec![
                Point3::new(0.0, 0.0, 0.0),
                Point3::new(1.0, 2.0, 0.0),
                Point3::new(2.0, -1.0, 1.0),
                Point3::new(3.0, 1.0, 0.0),
                Point3::new(4.0, 0.0, 2.0),
                Point3::new(5.0, 1.0, 0.0),
            ],
            vec![1.0, 2.0, 0.5, 1.0, 1.5, 1.0],
            vec![0.0, 0.0, 0.0, 1.0, 2.5, 3.0, 3.0, 3.0],
        )
        .unwrap()
    }

    fn same_shape(a: &NurbsCurve, b: &NurbsCurve, tol: f64) {
        let (da, db) = (a.domain(), b.domain());
        for k in 0..=50 {
            let s = k as f64 / 50.0;
            let pa = a.point_at(da.parameter_at(s));
            let pb = b.point_at(db.parameter_at(s));
            assert!(pa.distance(pb) < tol, "{s}: {pa:?} {pb:?}");
        }
    }

    #[test]
    fn elevation_keeps_the_shape_and_adds_multiplicity() {
        let c = wavy();
        for degree in 3..=6 {
            let e = c.elevated(degree).unwrap();
            assert_eq!(e.degree(), degree);
            assert_eq!(e.domain(), c.domain());
            let t = degree - 3;
            assert_eq!(e.knot_multiplicity(1.0), 1 + t);
            assert_eq!(e.point_count(), 6 + 3 * t);
            same_shape(&c, &e, 1e-12);
        }
        assert!(c.elevated(2).is_err());
        // A rational circle (degree 2, double knots) raised to 3 and 5.
        let circle = Circle::new(Plane::WORLD_XY, 2.0).unwrap().to_nurbs();
        for degree in [3, 5] {
            let e = circle.elevated(degree).unwrap();
            same_shape(&circle, &e, 1e-12);
            for k in 0..40 {
                let t = e.domain().parameter_at(k as f64 / 40.0);
                assert!((e.point_at(t).to_vector().length() - 2.0).abs() < 1e-12);
            }
        }
    }

    #[test]
    fn compatible_curves_share_degree_and_knots() {
        let line = NurbsCurve::new_non_rational(
            1,
            vec![Point3::new(0.0, 5.0, 0.0), Point3::new(5.0, 5.0, 0.0)],
            vec![10.0, 20.0],
        )
        .unwrap();
        let circle = Circle::new(Plane::WORLD_XY, 1.0).unwrap().to_nurbs();
        let curves = [line.clone(), wavy(), circle.clone()];
        let out = NurbsCurve::make_compatible(&curves).unwrap();
        for c in &out {
            assert_eq!(c.degree(), 3);
            assert_eq!(c.knots(), out[0].knots());
            assert_eq!(c.domain(), Interval::UNIT);
        }
        for (a, b) in curves.iter().zip(&out) {
            same_shape(a, b, 1e-12);
        }
        assert!(NurbsCurve::make_compatible(&[]).is_err());
    }

    #[test]
    fn tweens_blend_between_two_curves() {
        let a = NurbsCurve::create(
            &[
                Point3::new(0.0, 0.0, 0.0),
                Point3::new(1.0, 1.0, 0.0),
                Point3::new(2.0, 0.0, 0.0),
            ],
            2,
            false,
        )
        .unwrap();
        let b = NurbsCurve::create(
            &[
                Point3::new(0.0, 0.0, 2.0),
                Point3::new(1.0, 0.0, 2.0),
                Point3::new(2.0, 0.0, 2.0),
                Point3::new(3.0, 0.0, 2.0),
            ],
            3,
            false,
        )
        .unwrap();
        let half = NurbsCurve::tween(&a, &b, 0.5).unwrap();
        // Ends and the point at every normalized parameter are the averages.
        for k in 0..=10 {
            let s = f64::from(k) / 10.0;
            let pa = a.point_at(a.domain().parameter_at(s));
            let pb = b.point_at(b.domain().parameter_at(s));
            let mid = Point3::from_vector((pa.to_vector() + pb.to_vector()) * 0.5);
            assert!(half.point_at(s).distance(mid) < 1e-12, "{s}");
        }
        let zero = NurbsCurve::tween(&a, &b, 0.0).unwrap();
        assert!(
            zero.point_at(0.3)
                .distance(a.point_at(a.domain().parameter_at(0.3)))
                < 1e-12
        );
        assert!(NurbsCurve::tween(&a, &b, f64::NAN).is_err());
    }
}

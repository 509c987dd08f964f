//! Operations that build a new NURBS curve from an old one without changing its shape (knot
//! insertion, clamping, splitting, reparameterization, reversal) or by mapping it (transform).
//!
//! Knot insertion is Boehm's algorithm on the homogeneous control points (The NURBS Book, A5.1),
//! one knot at a time, written on Rhino-form knots: with the full knot vector `U_j = k_{j−1}`,
//! inserting `u` replaces the control points by
//!
//! ```text
//! Q_i = α_i P_i + (1 − α_i) P_{i−1},   α_i = clamp((u − U_i) / (U_{i+p} − U_i), 0, 1)
//! ```
//!
//! with `Q_0 = P_0` and `Q_n = P_{n−1}`, which never reads the two superfluous end knots.

use crate::{Error, Interval, NurbsCurve, Point3, Result, Transform};

/// Homogeneous control points `(w x, w y, w z, w)`.
type Homogeneous = Vec<[f64; 4]>;

impl NurbsCurve {
    /// The homogeneous control points `(w·P, w)`.
    pub(crate) fn homogeneous_points(&self) -> Homogeneous {
        self.points()
            .iter()
            .zip(self.weights())
            .map(|(p, &w)| [w * p.x, w * p.y, w * p.z, w])
            .collect()
    }

    /// Rebuilds a curve from homogeneous control points and knots, checking the result.
    pub(crate) fn from_homogeneous(
        degree: usize,
        cvs: &[[f64; 4]],
        knots: Vec<f64>,
    ) -> Result<Self> {
        let points = cvs
            .iter()
            .map(|h| Point3::new(h[0] / h[3], h[1] / h[3], h[2] / h[3]))
            .collect();
        let weights = cvs.iter().map(|h| h[3]).collect();
        Self::new(degree, points, weights, knots)
    }

    /// The number of knots equal to `t`.
    pub fn knot_multiplicity(&self, t: f64) -> usize {
        self.knots().iter().filter(|&&k| k == t).count()
    }

    /// The same curve with the knot `t` inserted `times` times (Boehm's algorithm).
    ///
    /// # Errors
    /// [`Error::NotFinite`] for a NaN or infinite `t`; [`Error::InvalidInput`] when `t` is not
    /// strictly inside the domain or when the multiplicity of `t` would exceed the degree.
    pub fn insert_knot(&self, t: f64, times: usize) -> Result<Self> {
        if !t.is_finite() {
            return Err(Error::NotFinite { what: "knot" });
        }
        let d = self.domain();
        if !(t > d.t0 && t < d.t1) {
            return Err(Error::InvalidInput(format!(
                "knot {t} is not inside the domain {} to {}",
                d.t0, d.t1
            )));
        }
        let existing = self.knot_multiplicity(t);
        if existing + times > self.degree() {
            return Err(Error::InvalidInput(format!(
                "inserting knot {t} {times} times would give multiplicity {} above the degree {}",
                existing + times,
                self.degree()
            )));
        }
        if times == 0 {
            return Ok(self.clone());
        }
        let mut cvs = self.homogeneous_points();
        let mut knots = self.knots().to_vec();
        for _ in 0..times {
            insert_once(self.degree(), &mut cvs, &mut knots, t);
        }
        Self::from_homogeneous(self.degree(), &cvs, knots)
    }

    /// The same curve with clamped ends: the first and last `degree` knots equal the domain's
    /// ends, so the curve starts at its first control point and ends at its last, as Rhino's
    /// `ClampEnd`. A clamped curve is returned unchanged; a periodic curve loses its periodic
    /// structure (but not its shape).
    pub fn clamped(&self) -> Self {
        let p = self.degree();
        let d = self.domain();
        let mut cvs = self.homogeneous_points();
        let mut knots = self.knots().to_vec();
        // The start: make t0 a knot of multiplicity p, then drop what precedes it.
        while knots.iter().filter(|&&k| k == d.t0).count() < p {
            insert_once(p, &mut cvs, &mut knots, d.t0);
        }
        let first = knots.iter().position(|&k| k == d.t0).expect("t0 is a knot");
        knots.drain(..first);
        cvs.drain(..first);
        // The end, symmetrically.
        while knots.iter().filter(|&&k| k == d.t1).count() < p {
            insert_once(p, &mut cvs, &mut knots, d.t1);
        }
        let last = knots
            .iter()
            .rposition(|&k| k == d.t1)
            .expect("t1 is a knot");
        let excess = knots.len() - 1 - last;
        knots.truncate(last + 1);
        cvs.truncate(cvs.len() - excess);
        Self::from_homogeneous(p, &cvs, knots).unwrap_or_else(|_| self.clone())
    }

    /// The two curves on either side of `t`, which together trace this curve: the first on
    /// `[t0, t]`, the second on `[t, t1]`. Both are clamped.
    ///
    /// # Errors
    /// [`Error::NotFinite`] for a NaN `t`; [`Error::InvalidInput`] when `t` is not strictly
    /// inside the domain.
    pub fn split_at(&self, t: f64) -> Result<(Self, Self)> {
        let p = self.degree();
        let existing = self.knot_multiplicity(t);
        let times = p.saturating_sub(existing);
        let refined = self.insert_knot(t, times)?;
        let knots = refined.knots();
        let a = knots.iter().position(|&k| k == t).expect("t is a knot");
        let cvs = refined.homogeneous_points();
        let left = Self::from_homogeneous(p, &cvs[..=a], knots[..a + p].to_vec())?;
        let right = Self::from_homogeneous(p, &cvs[a..], knots[a..].to_vec())?;
        Ok((left.clamped(), right.clamped()))
    }

    /// The part of the curve on the sub-interval `interval` (increasing, inside the domain),
    /// clamped, with `interval` as its domain.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] when the interval is not increasing or not inside the domain.
    pub fn trim(&self, interval: Interval) -> Result<Self> {
        let d = self.domain();
        if !interval.is_finite() || interval.t0 >= interval.t1 {
            return Err(Error::InvalidInput(format!(
                "trim interval {} to {} is not increasing",
                interval.t0, interval.t1
            )));
        }
        if interval.t0 < d.t0 || interval.t1 > d.t1 {
            return Err(Error::InvalidInput(format!(
                "trim interval {} to {} is not inside the domain {} to {}",
                interval.t0, interval.t1, d.t0, d.t1
            )));
        }
        let mut c = self.clamped();
        if interval.t0 > d.t0 {
            c = c.split_at(interval.t0)?.1;
        }
        if interval.t1 < d.t1 {
            c = c.split_at(interval.t1)?.0;
        }
        Ok(c)
    }

    /// The same curve on a new domain: the knots are mapped linearly so that the domain becomes
    /// `domain`; every point keeps its place, only the parameters change.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] when `domain` is not finite and increasing.
    pub fn reparameterized(&self, domain: Interval) -> Result<Self> {
        if !domain.is_finite() || domain.t0 >= domain.t1 {
            return Err(Error::InvalidInput(format!(
                "domain {} to {} is not increasing",
                domain.t0, domain.t1
            )));
        }
        let d = self.domain();
        let knots = self
            .knots()
            .iter()
            .map(|&k| {
                if k == d.t0 {
                    domain.t0
                } else if k == d.t1 {
                    domain.t1
                } else {
                    domain.parameter_at((k - d.t0) / d.length())
                }
            })
            .collect();
        Self::new(
            self.degree(),
            self.points().to_vec(),
            self.weights().to_vec(),
            knots,
        )
    }

    /// The parameter on a curve reparameterized from this curve's domain to `domain` that
    /// corresponds to `t` here.
    pub fn map_parameter(&self, t: f64, domain: Interval) -> f64 {
        let d = self.domain();
        domain.parameter_at((t - d.t0) / d.length())
    }

    /// The same curve traced in the opposite direction. As in Rhino, the domain `[t0, t1]`
    /// becomes `[−t1, −t0]`, so the point at `t` moves to parameter `−t`.
    pub fn reversed(&self) -> Self {
        let mut points = self.points().to_vec();
        let mut weights = self.weights().to_vec();
        points.reverse();
        weights.reverse();
        let knots = self.knots().iter().rev().map(|&k| -k).collect();
        Self::from_parts_unchecked(self.degree(), points, weights, knots)
    }

    /// The curve mapped by `transform`, applied to the homogeneous control points, so that the
    /// result is exact for every affine and projective transform.
    ///
    /// # Errors
    /// [`Error::NotFinite`] when the transform is not finite; [`Error::InvalidWeight`] when a
    /// projective transform sends a control point to or behind the plane at infinity.
    pub fn transformed(&self, transform: &Transform) -> Result<Self> {
        if !transform.is_finite() {
            return Err(Error::NotFinite { what: "transform" });
        }
        let m = transform.to_rows();
        let cvs: Homogeneous = self
            .homogeneous_points()
            .iter()
            .map(|h| {
                let row = |r: [f64; 4]| r[0] * h[0] + r[1] * h[1] + r[2] * h[2] + r[3] * h[3];
                [row(m[0]), row(m[1]), row(m[2]), row(m[3])]
            })
            .collect();
        Self::from_homogeneous(self.degree(), &cvs, self.knots().to_vec())
    }
}

/// Inserts `u` once into homogeneous control points and Rhino-form knots (Boehm). `u` must lie
/// in the closed domain.
fn insert_once(degree: usize, cvs: &mut Homogeneous, knots: &mut Vec<f64>, u: f64) {
    let p = degree;
    let n = cvs.len();
    let mut out = Vec::with_capacity(n + 1);
    out.push(cvs[0]);
    for i in 1..n {
        // U_i = k[i − 1], U_{i+p} = k[i + p − 1].
        let lo = knots[i - 1];
        let hi = knots[i + p - 1];
        let alpha = if hi > lo {
            ((u - lo) / (hi - lo)).clamp(0.0, 1.0)
        } else if u >= hi {
            1.0
        } else {
            0.0
        };
        let (a, b) = (cvs[i], cvs[i - 1]);
        out.push(std::array::from_fn(|c| alpha * a[c] + (1.0 - alpha) * b[c]));
    }
    out.push(cvs[n - 1]);
    *cvs = out;
    let at = knots.partition_point(|&k| k <= u);
    knots.insert(at, u);
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Vector3;

    fn curve() -> NurbsCurve {
        NurbsCurve::new(
            3,
            vec![
                Point3::new(0.0, 0.0, 0.0),
                Point3::new(1.0, 3.0, 0.0),
                Point3::new(3.0, 4.0, 1.0),
                Point3::new(5.0, 2.0, 0.0),
                Point3::new(7.0, 5.0, 2.0),
                Point3::new(9.0, 1.0, 0.0),
            ],
            vec![1.0, 0.5, 2.0, 1.0, 1.5, 1.0],
            vec![0.0, 0.0, 0.0, 1.0, 2.5, 4.0, 4.0, 4.0],
        )
        .unwrap()
    }

    fn periodic() -> NurbsCurve {
        let base = [
            Point3::new(0.0, 0.0, 0.0),
            Point3::new(10.0, 0.0, 0.0),
            Point3::new(10.0, 10.0, 0.0),
            Point3::new(0.0, 10.0, 0.0),
        ];
        let mut pts = base.to_vec();
        pts.extend_from_slice(&base[..3]);
        NurbsCurve::new_non_rational(3, pts, vec![-2.0, -1.0, 0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0])
            .unwrap()
    }

    fn same_shape(a: &NurbsCurve, b: &NurbsCurve, map: impl Fn(f64) -> f64) {
        let d = a.domain();
        for i in 0..=50 {
            let t = d.parameter_at(i as f64 / 50.0);
            let (pa, pb) = (a.point_at(t), b.point_at(map(t)));
            assert!(pa.distance(pb) < 1e-12, "t {t}: {pa:?} vs {pb:?}");
        }
    }

    #[test]
    fn knot_insertion_keeps_the_shape() {
        let c = curve();
        for (t, times) in [(0.5, 1), (1.0, 2), (3.0, 3), (2.5, 1)] {
            let r = c.insert_knot(t, times).unwrap();
            assert_eq!(r.point_count(), c.point_count() + times);
            assert_eq!(r.knot_multiplicity(t), c.knot_multiplicity(t) + times);
            same_shape(&c, &r, |t| t);
        }
        assert!(c.insert_knot(1.0, 3).is_err());
        assert!(c.insert_knot(0.0, 1).is_err());
        assert!(c.insert_knot(f64::NAN, 1).is_err());
    }

    #[test]
    fn split_and_trim_keep_the_shape() {
        for c in [curve(), periodic()] {
            let d = c.domain();
            let t = d.parameter_at(0.37);
            let (a, b) = c.split_at(t).unwrap();
            assert_eq!(a.domain(), Interval::new(d.t0, t));
            assert_eq!(b.domain(), Interval::new(t, d.t1));
            same_shape(&a, &c, |s| s);
            same_shape(&b, &c, |s| s);
            assert!(a.end_point().distance(b.start_point()) < 1e-12);
            let part = c
                .trim(Interval::new(d.parameter_at(0.2), d.parameter_at(0.7)))
                .unwrap();
            same_shape(&part, &c, |s| s);
        }
    }

    #[test]
    fn clamping_a_periodic_curve_keeps_the_shape() {
        let c = periodic();
        assert!(c.is_periodic());
        let k = c.clamped();
        assert!(!k.is_periodic());
        assert!(k.is_closed());
        assert_eq!(k.domain(), c.domain());
        assert_eq!(k.knots()[..3], [0.0, 0.0, 0.0]);
        same_shape(&c, &k, |t| t);
        assert_eq!(k.points()[0], k.start_point());
    }

    #[test]
    fn reparameterize_and_reverse() {
        let c = curve();
        let r = c.reparameterized(Interval::new(-1.0, 1.0)).unwrap();
        assert_eq!(r.domain(), Interval::new(-1.0, 1.0));
        same_shape(&c, &r, |t| c.map_parameter(t, Interval::new(-1.0, 1.0)));
        assert!(c.reparameterized(Interval::new(1.0, 1.0)).is_err());
        assert!(c.reparameterized(Interval::new(2.0, 1.0)).is_err());
        let v = c.reversed();
        assert_eq!(v.domain(), Interval::new(-4.0, 0.0));
        same_shape(&c, &v, |t| -t);
        let dt = c.derivative_at(1.3);
        assert!((v.derivative_at(-1.3) + dt).length() < 1e-12);
    }

    #[test]
    fn transform_moves_every_point() {
        let c = curve();
        let v = Vector3::new(1.0, -2.0, 3.0);
        let moved = c.transformed(&Transform::translation(v)).unwrap();
        for i in 0..=20 {
            let t = 4.0 * i as f64 / 20.0;
            assert!(moved.point_at(t).distance(c.point_at(t) + v) < 1e-12);
        }
        // A projective transform: compare with mapping the points themselves.
        let persp = Transform::from_rows([
            [1.0, 0.0, 0.0, 0.0],
            [0.0, 1.0, 0.0, 0.0],
            [0.0, 0.0, 1.0, 0.0],
            [0.02, 0.01, 0.0, 1.0],
        ]);
        let image = c.transformed(&persp).unwrap();
        for i in 0..=20 {
            let t = 4.0 * i as f64 / 20.0;
            let q = persp.transform_point(c.point_at(t));
            assert!(image.point_at(t).distance(q) < 1e-12);
        }
        let mut bad = Transform::IDENTITY;
        bad.matrix.x_axis.x = f64::NAN;
        assert!(c.transformed(&bad).is_err());
    }
}

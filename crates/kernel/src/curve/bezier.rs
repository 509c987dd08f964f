//! Bézier curves of any degree, evaluated with de Casteljau's algorithm.

use crate::curve::nurbs::basis::{MAX_DEGREE, MAX_ORDER};
use crate::{Error, NurbsCurve, Point3, Result, Vector3};

/// A non-rational Bézier curve on the parameter interval `[0, 1]`, of degree
/// `points.len() − 1` (from 1 to [`MAX_DEGREE`]).
#[derive(Clone, Debug, PartialEq)]
pub struct Bezier {
    points: Vec<Point3>,
}

impl Bezier {
    /// The Bézier curve with control points `points`.
    ///
    /// # Errors
    /// [`Error::TooFewPoints`] with fewer than two points; [`Error::InvalidDegree`] with more
    /// than `MAX_DEGREE + 1`; [`Error::NotFinite`] for NaN or infinite points.
    pub fn new(points: Vec<Point3>) -> Result<Self> {
        if points.len() < 2 {
            return Err(Error::TooFewPoints {
                what: "a bezier curve",
                needed: 2,
                got: points.len(),
            });
        }
        if points.len() > MAX_ORDER {
            return Err(Error::InvalidDegree {
                degree: points.len() - 1,
                reason: format!("the degree must be at most {MAX_DEGREE}"),
            });
        }
        if points.iter().any(|p| !p.is_finite()) {
            return Err(Error::NotFinite { what: "point" });
        }
        Ok(Self { points })
    }

    /// The control points.
    #[inline]
    pub fn points(&self) -> &[Point3] {
        &self.points
    }

    /// The degree, one less than the number of control points.
    #[inline]
    pub fn degree(&self) -> usize {
        self.points.len() - 1
    }

    /// The point at `t` by de Casteljau's algorithm: repeatedly replace each pair of
    /// consecutive points by the point at `t` between them, until one point is left. For a cubic
    /// with points A, B, C, D this is the book's M, N, O (on AB, BC, CD), then P, Q (on MN, NO),
    /// then R on PQ.
    pub fn de_casteljau(&self, t: f64) -> Point3 {
        let mut level = [Point3::ORIGIN; MAX_ORDER];
        let n = self.points.len();
        level[..n].copy_from_slice(&self.points);
        for len in (1..n).rev() {
            for i in 0..len {
                level[i] = level[i].lerp(level[i + 1], t);
            }
        }
        level[0]
    }

    /// The point at `t` (de Casteljau).
    #[inline]
    pub fn point_at(&self, t: f64) -> Point3 {
        self.de_casteljau(t)
    }

    /// The first derivative at `t`: the degree times the hodograph, the Bézier curve of the
    /// differences `P_{i+1} − P_i`, itself evaluated by de Casteljau.
    pub fn derivative_at(&self, t: f64) -> Vector3 {
        let mut d = [Vector3::ZERO; MAX_ORDER];
        let n = self.points.len() - 1;
        for (i, w) in self.points.windows(2).enumerate() {
            d[i] = (w[1] - w[0]) * n as f64;
        }
        de_casteljau_vectors(&mut d[..n], t)
    }

    /// The second derivative at `t`.
    pub fn second_derivative_at(&self, t: f64) -> Vector3 {
        let p = self.degree();
        if p < 2 {
            return Vector3::ZERO;
        }
        let mut d = [Vector3::ZERO; MAX_ORDER];
        let f = (p * (p - 1)) as f64;
        for (i, w) in self.points.windows(3).enumerate() {
            d[i] = ((w[2] - w[1]) - (w[1] - w[0])) * f;
        }
        de_casteljau_vectors(&mut d[..p - 1], t)
    }

    /// The two Bézier curves on `[0, t]` and `[t, 1]` (each reparameterized to `[0, 1]`), from
    /// the sides of de Casteljau's triangle.
    pub fn split_at(&self, t: f64) -> (Self, Self) {
        let n = self.points.len();
        let mut level = self.points.clone();
        let mut left = Vec::with_capacity(n);
        let mut right = Vec::with_capacity(n);
        left.push(level[0]);
        right.push(level[n - 1]);
        for len in (1..n).rev() {
            for i in 0..len {
                level[i] = level[i].lerp(level[i + 1], t);
            }
            left.push(level[0]);
            right.push(level[len - 1]);
        }
        right.reverse();
        (Self { points: left }, Self { points: right })
    }

    /// The exact NURBS form: the same control points, knots `0 (×degree), 1 (×degree)`.
    pub fn to_nurbs(&self) -> NurbsCurve {
        let p = self.degree();
        let mut knots = vec![0.0; p];
        knots.extend(std::iter::repeat_n(1.0, p));
        NurbsCurve::from_parts_unchecked(p, self.points.clone(), vec![1.0; p + 1], knots)
    }
}

/// De Casteljau on vectors, in place.
fn de_casteljau_vectors(v: &mut [Vector3], t: f64) -> Vector3 {
    let n = v.len();
    for len in (1..n).rev() {
        for i in 0..len {
            v[i] = v[i] * (1.0 - t) + v[i + 1] * t;
        }
    }
    v[0]
}

#[cfg(test)]
mod tests {
    use super::*;

    fn cubic() -> Bezier {
        Bezier::new(vec![
            Point3::new(0.0, 0.0, 0.0),
            Point3::new(1.0, 4.0, 0.0),
            Point3::new(5.0, 4.0, 2.0),
            Point3::new(6.0, 0.0, 0.0),
        ])
        .unwrap()
    }

    #[test]
    fn book_de_casteljau_steps() {
        // The book's six steps for points A, B, C, D at t = 0.25.
        let c = cubic();
        let [a, b, cc, d] = [c.points[0], c.points[1], c.points[2], c.points[3]];
        let t = 0.25;
        let m = a.lerp(b, t);
        let n = b.lerp(cc, t);
        let o = cc.lerp(d, t);
        let p = m.lerp(n, t);
        let q = n.lerp(o, t);
        let r = p.lerp(q, t);
        assert_eq!(m, Point3::new(0.25, 1.0, 0.0));
        assert_eq!(r, c.de_casteljau(t));
        // The Bernstein form gives the same point: (1−t)³A + 3t(1−t)²B + 3t²(1−t)C + t³D.
        let s = 1.0 - t;
        let bern = Point3::from_vector(
            a.to_vector() * (s * s * s)
                + b.to_vector() * (3.0 * t * s * s)
                + cc.to_vector() * (3.0 * t * t * s)
                + d.to_vector() * (t * t * t),
        );
        assert!(r.distance(bern) < 1e-15);
        assert_eq!(r, Point3::new(1.21875, 2.25, 0.28125));
    }

    #[test]
    fn nurbs_form_derivatives_and_split() {
        let c = cubic();
        let n = c.to_nurbs();
        for i in 0..=20 {
            let t = i as f64 / 20.0;
            let (p, d1, d2) = n.point_and_derivatives_at(t);
            assert!(p.distance(c.point_at(t)) < 1e-14);
            assert!((d1 - c.derivative_at(t)).length() < 1e-12);
            assert!((d2 - c.second_derivative_at(t)).length() < 1e-12);
        }
        let (l, r) = c.split_at(0.3);
        for i in 0..=10 {
            let s = i as f64 / 10.0;
            assert!(l.point_at(s).distance(c.point_at(0.3 * s)) < 1e-14);
            assert!(r.point_at(s).distance(c.point_at(0.3 + 0.7 * s)) < 1e-14);
        }
    }

    #[test]
    fn any_degree_and_bad_input() {
        let pts: Vec<Point3> = (0..=15)
            .map(|i| Point3::new(i as f64, ((i * i) % 7) as f64, 0.0))
            .collect();
        let high = Bezier::new(pts.clone()).unwrap();
        assert_eq!(high.degree(), 15);
        let n = high.to_nurbs();
        assert!(n.point_at(0.37).distance(high.point_at(0.37)) < 1e-12);
        let mut more = pts;
        more.push(Point3::ORIGIN);
        assert!(Bezier::new(more).is_err());
        assert!(Bezier::new(vec![Point3::ORIGIN]).is_err());
        let line = Bezier::new(vec![Point3::ORIGIN, Point3::new(2.0, 0.0, 0.0)]).unwrap();
        assert_eq!(line.derivative_at(0.5), Vector3::new(2.0, 0.0, 0.0));
        assert_eq!(line.second_derivative_at(0.5), Vector3::ZERO);
    }
}

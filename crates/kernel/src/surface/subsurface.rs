//! Sub-surfaces: the part of a surface over a rectangle of its parameters (Rhino's
//! `Surface.Trim`, Grasshopper's Isotrim).

use crate::surface::direction::SurfaceDirection;
use crate::{Error, Interval, NurbsCurve, NurbsSurface, Result};

impl NurbsSurface {
    /// The part of the surface over `u × v`, an exact NURBS surface whose domains are `u` and
    /// `v` (each increasing and inside the surface's domain): every point keeps its
    /// parameters, `S'(s, t) = S(s, t)`.
    ///
    /// Each direction is cut by knot insertion to full multiplicity at the interval's ends, as
    /// a curve is trimmed, applied to every row of control points in homogeneous form; a side
    /// left whole keeps its control points (clamped).
    ///
    /// # Errors
    /// [`Error::InvalidInput`] when an interval is not finite, not increasing, or not inside
    /// the domain.
    pub fn sub_surface(&self, u: Interval, v: Interval) -> Result<Self> {
        let trimmed_u = self.trimmed_in_u(u)?;
        // Trimming in v is trimming in u of the transposed surface.
        Ok(trimmed_u.transposed().trimmed_in_u(v)?.transposed())
    }

    /// The surface cut to `u` in the u direction only.
    fn trimmed_in_u(&self, u: Interval) -> Result<Self> {
        let d = self.domain_u();
        if !u.is_finite() || u.t0 >= u.t1 {
            return Err(Error::InvalidInput(format!(
                "the sub-domain {} to {} is not increasing",
                u.t0, u.t1
            )));
        }
        if u.t0 < d.t0 || u.t1 > d.t1 {
            return Err(Error::InvalidInput(format!(
                "the sub-domain {} to {} is not inside the domain {} to {}",
                u.t0, u.t1, d.t0, d.t1
            )));
        }
        let (nu, nv) = (self.count_u, self.count_v);
        let mut columns = Vec::with_capacity(nv);
        for j in 0..nv {
            let points = (0..nu).map(|i| self.points[i * nv + j]).collect();
            let weights = (0..nu).map(|i| self.weights[i * nv + j]).collect();
            let curve = NurbsCurve::new(self.degree_u, points, weights, self.knots_u.clone())?;
            columns.push(curve.trim(u)?);
        }
        let first = columns.first().ok_or(Error::TooFewPoints {
            what: "a sub-surface",
            needed: 1,
            got: 0,
        })?;
        let count_u = first.points().len();
        let knots_u = first.knots().to_vec();
        let mut points = Vec::with_capacity(count_u * nv);
        let mut weights = Vec::with_capacity(count_u * nv);
        for i in 0..count_u {
            for c in &columns {
                points.push(c.points()[i]);
                weights.push(if self.rational { c.weights()[i] } else { 1.0 });
            }
        }
        NurbsSurface::from_flat(
            [self.degree_u, self.degree_v],
            [count_u, nv],
            points,
            weights,
            [knots_u, self.knots_v.clone()],
        )
    }

    /// The sub-surface over the normalized rectangle `[s0, s1] × [t0, t1]` of the domain
    /// (0 at the start of a direction, 1 at its end).
    ///
    /// # Errors
    /// As [`NurbsSurface::sub_surface`].
    pub fn sub_surface_normalized(&self, s: Interval, t: Interval) -> Result<Self> {
        let map =
            |d: Interval, r: Interval| Interval::new(d.parameter_at(r.t0), d.parameter_at(r.t1));
        self.sub_surface(
            map(self.domain(SurfaceDirection::U), s),
            map(self.domain(SurfaceDirection::V), t),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::surface::tests::wavy;
    use crate::{Point3, Sphere};

    fn close(a: Point3, b: Point3) -> bool {
        a.distance(b) < 1e-12 * (1.0 + a.to_vector().length())
    }

    #[test]
    fn sub_surface_keeps_every_point_and_parameter() {
        for rational in [false, true] {
            let s = wavy(rational);
            let (u, v) = (Interval::new(0.3, 1.7), Interval::new(-0.5, 2.2));
            let sub = s.sub_surface(u, v).unwrap();
            assert_eq!(sub.domain_u(), u);
            assert_eq!(sub.domain_v(), v);
            assert_eq!(sub.is_rational(), rational);
            for a in 0..=8 {
                for b in 0..=8 {
                    let (pu, pv) = (
                        u.parameter_at(a as f64 / 8.0),
                        v.parameter_at(b as f64 / 8.0),
                    );
                    assert!(close(sub.point_at(pu, pv), s.point_at(pu, pv)), "{pu} {pv}");
                }
            }
        }
    }

    #[test]
    fn sub_surface_of_the_whole_domain_and_on_knots() {
        let sphere = Sphere::new(Point3::new(1.0, 2.0, 3.0), 2.0)
            .unwrap()
            .to_nurbs()
            .unwrap();
        let (du, dv) = (sphere.domain_u(), sphere.domain_v());
        let whole = sphere.sub_surface(du, dv).unwrap();
        assert_eq!(whole.domain_u(), du);
        // A cut exactly on an interior knot (the sphere's quadrant seams).
        let knot = sphere.knots_u()[sphere.knots_u().len() / 2];
        let half = sphere.sub_surface(Interval::new(du.t0, knot), dv).unwrap();
        for k in 0..=10 {
            let pu = Interval::new(du.t0, knot).parameter_at(k as f64 / 10.0);
            let pv = dv.parameter_at(0.37);
            assert!(close(half.point_at(pu, pv), sphere.point_at(pu, pv)));
            assert!(
                (half.point_at(pu, pv).distance(Point3::new(1.0, 2.0, 3.0)) - 2.0).abs() < 1e-12
            );
        }
    }

    #[test]
    fn bad_sub_domains_are_errors() {
        let s = wavy(false);
        let dv = s.domain_v();
        for u in [
            Interval::new(1.0, 1.0),
            Interval::new(1.5, 0.5),
            Interval::new(-1.0, 1.0),
            Interval::new(0.0, f64::NAN),
        ] {
            assert!(s.sub_surface(u, dv).is_err(), "{u:?}");
        }
    }
}

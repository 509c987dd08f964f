//! Ruled surfaces: the surface of straight lines between two curves, a curve extruded along a
//! vector, and a curve extruded to a point.
//!
//! All three have `u` along the curve(s) and degree 1 in `v`, with the first curve at
//! `v = v0` and the second curve (or the moved curve, or the apex) at `v = v1`. They are built
//! in homogeneous form: the `v = v1` row of control points carries the same weights as the
//! first curve's (for an extrusion and an apex) so that the rulings are straight lines.

use crate::{Error, NurbsCurve, NurbsSurface, Point3, Result, Vector3};

impl NurbsSurface {
    /// The ruled surface between curves `a` and `b` (Rhino's `CreateRuledSurface`, Grasshopper's
    /// Ruled Surface): the curves are made compatible ([`NurbsCurve::make_compatible`]: domain
    /// `0..1`, the higher degree, merged knots) and joined by straight lines between points of
    /// equal parameter. The domain is `0..1` both ways; the isocurve `v = 0` is `a` and `v = 1`
    /// is `b`.
    ///
    /// # Errors
    /// As [`NurbsCurve::make_compatible`] and [`NurbsSurface::new`].
    pub fn ruled(a: &NurbsCurve, b: &NurbsCurve) -> Result<Self> {
        let curves = NurbsCurve::make_compatible(&[a.clone(), b.clone()])?;
        let (a, b) = (&curves[0], &curves[1]);
        let points = a
            .points()
            .iter()
            .zip(b.points())
            .map(|(&p, &q)| vec![p, q])
            .collect();
        let weights = a
            .weights()
            .iter()
            .zip(b.weights())
            .map(|(&p, &q)| vec![p, q])
            .collect();
        Self::new(
            a.degree(),
            1,
            points,
            weights,
            a.knots().to_vec(),
            vec![0.0, 1.0],
        )
    }

    /// The curve swept along `direction` (Rhino's `Surface.CreateExtrusion`): `S(u, v) =
    /// C(u) + v · direction / |direction|`, `u` on the curve's domain and `v` from `0` to the
    /// direction's length (degree 1).
    ///
    /// # Errors
    /// [`Error::NotFinite`] for a non-finite direction, [`Error::ZeroLength`] for a zero one.
    pub fn extrusion(curve: &NurbsCurve, direction: Vector3) -> Result<Self> {
        if !direction.is_finite() {
            return Err(Error::NotFinite {
                what: "extrusion direction",
            });
        }
        let length = direction.length();
        if length <= crate::geometry::tolerance::ZERO_TOLERANCE {
            return Err(Error::ZeroLength {
                what: "extrusion direction",
            });
        }
        let points = curve
            .points()
            .iter()
            .map(|&p| vec![p, p + direction])
            .collect();
        let weights = curve.weights().iter().map(|&w| vec![w, w]).collect();
        Self::new(
            curve.degree(),
            1,
            points,
            weights,
            curve.knots().to_vec(),
            vec![0.0, length],
        )
    }

    /// The lines from the curve to the point `apex` (Grasshopper's Extrude Point): `S(u, v) =
    /// (1 − v) C(u) + v · apex`, `u` on the curve's domain, `v` from `0` to `1`; the side
    /// `v = 1` is collapsed to the apex.
    ///
    /// # Errors
    /// [`Error::NotFinite`] for a non-finite apex.
    pub fn extrusion_to_point(curve: &NurbsCurve, apex: Point3) -> Result<Self> {
        if !apex.is_finite() {
            return Err(Error::NotFinite { what: "apex" });
        }
        let points = curve.points().iter().map(|&p| vec![p, apex]).collect();
        let weights = curve.weights().iter().map(|&w| vec![w, w]).collect();
        Self::new(
            curve.degree(),
            1,
            points,
            weights,
            curve.knots().to_vec(),
            vec![0.0, 1.0],
        )
    }
}

impl NurbsSurface {
    /// The bilinear patch on four corners (Rhino's `NurbsSurface.CreateFromCorners`,
    /// Grasshopper's 4Point Surface): `S(u, v) = (1−u)(1−v) a + u(1−v) b + u v c + (1−u) v d`,
    /// degree 1 both ways on `0..1`, so `a`, `b`, `c`, `d` sit at `(0,0)`, `(1,0)`, `(1,1)`,
    /// `(0,1)`. With `d = c` the side from `d` to `c` collapses and the patch is the triangle
    /// `a b c`.
    ///
    /// # Errors
    /// [`Error::NotFinite`] for a non-finite corner; [`Error::Degenerate`] when the corners do
    /// not span a surface (all on one line).
    pub fn from_corners(a: Point3, b: Point3, c: Point3, d: Point3) -> Result<Self> {
        if [a, b, c, d].iter().any(|p| !p.is_finite()) {
            return Err(Error::NotFinite { what: "corner" });
        }
        let size = [b, c, d].iter().fold(0.0f64, |m, p| m.max(p.distance(a)));
        let spans = (b - a)
            .cross(d - a)
            .length()
            .max((c - b).cross(d - c).length())
            .max((b - a).cross(c - a).length());
        let least = crate::geometry::tolerance::ZERO_TOLERANCE * size * size;
        if spans.is_nan() || spans <= least {
            return Err(Error::Degenerate {
                what: "four-point surface",
            });
        }
        Self::non_rational(
            1,
            1,
            vec![vec![a, d], vec![b, c]],
            vec![0.0, 1.0],
            vec![0.0, 1.0],
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Circle, Interval, Plane, SurfaceDirection};

    fn arc_curve() -> NurbsCurve {
        Circle::new(Plane::WORLD_XY, 2.0).unwrap().to_nurbs()
    }

    fn cubic() -> NurbsCurve {
        NurbsCurve::new_non_rational(
            3,
            vec![
                Point3::new(0.0, 0.0, 3.0),
                Point3::new(1.0, 1.0, 3.0),
                Point3::new(2.0, -1.0, 4.0),
                Point3::new(3.0, 0.0, 3.0),
                Point3::new(4.0, 2.0, 3.0),
            ],
            vec![5.0, 5.0, 5.0, 6.0, 8.0, 8.0, 8.0],
        )
        .unwrap()
    }

    fn assert_curves_match(a: &NurbsCurve, b: &NurbsCurve) {
        for k in 0..=40 {
            let s = k as f64 / 40.0;
            let pa = a.point_at(a.domain().parameter_at(s));
            let pb = b.point_at(b.domain().parameter_at(s));
            assert!(pa.distance(pb) < 1e-12, "{s}: {pa:?} {pb:?}");
        }
    }

    #[test]
    fn four_corners_make_a_bilinear_patch() {
        let (a, b, c, d) = (
            Point3::new(0.0, 0.0, 0.0),
            Point3::new(2.0, 0.0, 0.0),
            Point3::new(2.0, 1.0, 1.0),
            Point3::new(0.0, 1.0, 0.0),
        );
        let s = NurbsSurface::from_corners(a, b, c, d).unwrap();
        assert_eq!(s.point_at(0.0, 0.0), a);
        assert_eq!(s.point_at(1.0, 0.0), b);
        assert_eq!(s.point_at(1.0, 1.0), c);
        assert_eq!(s.point_at(0.0, 1.0), d);
        // The centre is the average of the corners.
        let centre = s.point_at(0.5, 0.5);
        assert!(centre.distance(Point3::new(1.0, 0.5, 0.25)) < 1e-15);
        // Three corners: the last side collapses.
        let t = NurbsSurface::from_corners(a, b, c, c).unwrap();
        assert!(t.is_singular(crate::SurfaceSide::North));
        assert!(NurbsSurface::from_corners(a, a, a, a).is_err());
        assert!(NurbsSurface::from_corners(a, b, Point3::new(4.0, 0.0, 0.0), b).is_err());
    }

    #[test]
    fn ruled_surface_has_its_curves_as_edges() {
        let (a, b) = (arc_curve(), cubic());
        let s = NurbsSurface::ruled(&a, &b).unwrap();
        assert_eq!((s.degree_u(), s.degree_v()), (3, 1));
        assert_eq!(
            (s.domain_u(), s.domain_v()),
            (Interval::UNIT, Interval::UNIT)
        );
        assert_curves_match(&s.isocurve(SurfaceDirection::U, 0.0).unwrap(), &a);
        assert_curves_match(&s.isocurve(SurfaceDirection::U, 1.0).unwrap(), &b);
        // Rulings are straight: every point of a ruling lies on the line between its ends
        // (the rational circle makes the parameter along it non-uniform).
        for k in 0..=10 {
            let u = k as f64 / 10.0;
            let (p, q) = (s.point_at(u, 0.0), s.point_at(u, 1.0));
            let axis = (q - p).normalize_or_zero();
            for v in [0.25, 0.5, 0.75] {
                let x = s.point_at(u, v) - p;
                assert!((x - axis * x.dot(axis)).length() < 1e-12);
            }
        }
    }

    #[test]
    fn extrusion_moves_the_curve() {
        let c = arc_curve();
        let d = Vector3::new(0.0, 0.0, 3.0);
        let s = NurbsSurface::extrusion(&c, d).unwrap();
        assert_eq!(s.domain_v(), Interval::new(0.0, 3.0));
        let top = s.isocurve(SurfaceDirection::U, 3.0).unwrap();
        for k in 0..=20 {
            let t = c.domain().parameter_at(k as f64 / 20.0);
            assert!(top.point_at(t).distance(c.point_at(t) + d) < 1e-12);
            assert!(s.point_at(t, 1.5).distance(c.point_at(t) + d * 0.5) < 1e-12);
        }
        // Lateral area of the cylinder of radius 2 and height 3.
        let area = s.area_properties().unwrap().area;
        assert!((area - 12.0 * std::f64::consts::PI).abs() < 1e-9, "{area}");
        assert!(NurbsSurface::extrusion(&c, Vector3::ZERO).is_err());
        assert!(NurbsSurface::extrusion(&c, Vector3::new(f64::NAN, 0.0, 0.0)).is_err());
    }

    #[test]
    fn extrusion_to_a_point_is_a_cone() {
        let c = arc_curve();
        let apex = Point3::new(0.0, 0.0, 4.0);
        let s = NurbsSurface::extrusion_to_point(&c, apex).unwrap();
        let (du, _) = (s.domain_u(), s.domain_v());
        for k in 0..=10 {
            let u = du.parameter_at(k as f64 / 10.0);
            assert!(s.point_at(u, 1.0).distance(apex) < 1e-12);
            let p = s.point_at(u, 0.25);
            assert!((p.z - 1.0).abs() < 1e-12 && ((p.x.hypot(p.y)) - 1.5).abs() < 1e-12);
        }
        // Lateral area of the cone: π r √(r² + h²) = 2π√20.
        let area = s.area_properties().unwrap().area;
        let exact = std::f64::consts::PI * 2.0 * 20f64.sqrt();
        assert!((area - exact).abs() < 1e-9, "{area}");
    }
}

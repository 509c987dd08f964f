//! Offsets of surfaces: the surface `S(u, v) + d N(u, v)` approximated by a NURBS surface.
//!
//! The exact offset of a NURBS surface is not a NURBS surface in general (its normal has a
//! square root in it), so, as Rhino's `Surface.Offset`, the result is an approximation within a
//! tolerance. Offset points are sampled on a grid of parameters (the surface's span breaks,
//! each span divided evenly), and the bicubic (or lower degree, for few samples) surface through
//! them is found by global interpolation at those same parameters (The NURBS Book, §9.2.5):
//! every row is interpolated along `u`, then every column of the resulting control points
//! along `v`, with knots by averaging (eq. 9.8). The result has the surface's domain and, at
//! every sample, exactly the offset point of the same parameters. Its distance from the exact
//! offset is measured at the centres and edge midpoints of the grid's cells; while it exceeds
//! the tolerance, every cell is split in four, up to [`MAX_OFFSET_GRID`] samples a side.
//! Interpolation reproduces polynomials up to its degree, so planes offset exactly.
//!
//! The normal is [`NurbsSurface::normal_at`]'s, with its limit at singular points (a sphere's
//! poles), so an offset sphere is again a closed sphere-like surface. An offset larger than the
//! radius of curvature on the concave side folds the surface over itself; that is not detected.

use crate::curve::nurbs::compatible::solve_collocation;
use crate::{Error, NurbsSurface, Point3, Result, SurfaceDirection};

/// The most samples along one side of the grid of an offset surface.
pub const MAX_OFFSET_GRID: usize = 257;

/// Knots by averaging (The NURBS Book eq. 9.8) for interpolation at `params`, in Rhino form.
fn averaged_knots(params: &[f64], degree: usize) -> Vec<f64> {
    let n = params.len() - 1;
    let mut knots = vec![params[0]; degree];
    for j in 1..=n - degree {
        knots.push(params[j..j + degree].iter().sum::<f64>() / degree as f64);
    }
    knots.extend(std::iter::repeat_n(params[n], degree));
    knots
}

/// The sample parameters in one direction: the span breaks, each span divided into `per_span`.
fn sample_parameters(breaks: &[f64], per_span: usize) -> Vec<f64> {
    let mut out = Vec::with_capacity((breaks.len() - 1) * per_span + 1);
    for w in breaks.windows(2) {
        for k in 0..per_span {
            out.push(w[0] + (w[1] - w[0]) * k as f64 / per_span as f64);
        }
    }
    out.push(breaks[breaks.len() - 1]);
    out
}

/// The interpolating surface of degree up to 3 through `grid[i][j]` at `(us[i], vs[j])`.
fn interpolate_grid(us: &[f64], vs: &[f64], grid: &[Vec<Point3>]) -> Result<NurbsSurface> {
    let pu = 3.min(us.len() - 1);
    let pv = 3.min(vs.len() - 1);
    let ku = averaged_knots(us, pu);
    let kv = averaged_knots(vs, pv);
    let hom = |p: Point3| [p.x, p.y, p.z, 1.0];
    // Rows along u, for every v sample: the columns of the intermediate control net.
    let mut columns: Vec<Vec<[f64; 4]>> = vec![Vec::with_capacity(vs.len()); us.len()];
    for j in 0..vs.len() {
        let row: Vec<[f64; 4]> = grid.iter().map(|col| hom(col[j])).collect();
        let solved = solve_collocation(pu, &ku, us, row)?;
        for (i, h) in solved.into_iter().enumerate() {
            columns[i].push(h);
        }
    }
    let mut points = Vec::with_capacity(us.len());
    for column in columns {
        let solved = solve_collocation(pv, &kv, vs, column)?;
        points.push(
            solved
                .into_iter()
                .map(|h| Point3::new(h[0], h[1], h[2]))
                .collect(),
        );
    }
    NurbsSurface::non_rational(pu, pv, points, ku, kv)
}

impl NurbsSurface {
    /// The surface offset by `distance` along its normals (negative: against them),
    /// approximated within `tolerance` (see the module documentation). A distance of zero gives
    /// the surface itself.
    ///
    /// # Errors
    /// [`Error::NotFinite`] for a non-finite distance; [`Error::InvalidInput`] for a tolerance
    /// that is not positive, and when the tolerance is not reached with
    /// [`MAX_OFFSET_GRID`] samples a side; [`Error::Degenerate`] where the surface has no
    /// normal.
    pub fn offset(&self, distance: f64, tolerance: f64) -> Result<NurbsSurface> {
        if !distance.is_finite() {
            return Err(Error::NotFinite {
                what: "offset distance",
            });
        }
        if !(tolerance.is_finite() && tolerance > 0.0) {
            return Err(Error::InvalidInput(format!(
                "offset tolerance {tolerance} is not a positive distance"
            )));
        }
        if distance == 0.0 {
            return Ok(self.clone());
        }
        let breaks_u = self.span_breaks(SurfaceDirection::U);
        let breaks_v = self.span_breaks(SurfaceDirection::V);
        let offset_at = |u: f64, v: f64| -> Result<Point3> {
            Ok(self.point_at(u, v) + self.normal_at(u, v)? * distance)
        };
        // Start with enough samples per span for a cubic to follow the span's shape.
        let mut per_u = (self.degree_u + 1).max(2);
        let mut per_v = (self.degree_v + 1).max(2);
        loop {
            let us = sample_parameters(&breaks_u, per_u);
            let vs = sample_parameters(&breaks_v, per_v);
            let grid: Vec<Vec<Point3>> = us
                .iter()
                .map(|&u| vs.iter().map(|&v| offset_at(u, v)).collect())
                .collect::<Result<_>>()?;
            let approx = interpolate_grid(&us, &vs, &grid)?;
            let mut worst = 0.0f64;
            let mid = |a: &[f64], k: usize| 0.5 * (a[k] + a[k + 1]);
            for i in 0..us.len() {
                for j in 0..vs.len() {
                    let mut checks = Vec::with_capacity(3);
                    if i + 1 < us.len() {
                        checks.push((mid(&us, i), vs[j]));
                    }
                    if j + 1 < vs.len() {
                        checks.push((us[i], mid(&vs, j)));
                    }
                    if i + 1 < us.len() && j + 1 < vs.len() {
                        checks.push((mid(&us, i), mid(&vs, j)));
                    }
                    for (u, v) in checks {
                        worst = worst.max(approx.point_at(u, v).distance(offset_at(u, v)?));
                    }
                }
            }
            if worst <= tolerance {
                return Ok(approx);
            }
            if us.len().max(vs.len()) >= MAX_OFFSET_GRID {
                return Err(Error::InvalidInput(format!(
                    "the offset surface is {worst} from the exact offset with {} by {} samples, \
                     more than the tolerance {tolerance}",
                    us.len(),
                    vs.len()
                )));
            }
            let grow = |per: usize, breaks: &[f64]| {
                let spans = breaks.len() - 1;
                if (2 * per) * spans < MAX_OFFSET_GRID {
                    2 * per
                } else {
                    ((MAX_OFFSET_GRID - 1) / spans).max(per)
                }
            };
            let (next_u, next_v) = (grow(per_u, &breaks_u), grow(per_v, &breaks_v));
            if next_u == per_u && next_v == per_v {
                return Err(Error::InvalidInput(format!(
                    "the offset surface is {worst} from the exact offset, more than the \
                     tolerance {tolerance}, and the surface has too many spans to sample finer"
                )));
            }
            per_u = next_u;
            per_v = next_v;
        }
    }
}

#[cfg(test)]
mod tests {
    use proptest::prelude::*;

    use super::*;
    use crate::{Interval, Plane, Sphere, Vector3};

    #[test]
    fn a_plane_offsets_exactly() {
        let s = NurbsSurface::from_plane(
            &Plane::WORLD_XY,
            Interval::new(0.0, 4.0),
            Interval::new(0.0, 2.0),
        )
        .unwrap();
        let o = s.offset(1.5, 1e-9).unwrap();
        for (u, v) in [(0.0, 0.0), (0.3, 0.7), (1.0, 1.0)] {
            let (u, v) = (o.domain_u().parameter_at(u), o.domain_v().parameter_at(v));
            let p = o.point_at(u, v);
            assert!((p.z - 1.5).abs() < 1e-12, "{p:?}");
            assert!(p.distance(s.point_at(u, v) + Vector3::new(0.0, 0.0, 1.5)) < 1e-12);
        }
        assert_eq!(s.offset(0.0, 1e-9).unwrap(), s);
        assert!(s.offset(f64::NAN, 1e-9).is_err());
        assert!(s.offset(1.0, 0.0).is_err());
    }

    #[test]
    fn a_sphere_grows() {
        let s = Sphere::new(Point3::new(1.0, 2.0, 3.0), 5.0)
            .unwrap()
            .to_nurbs()
            .unwrap();
        let o = s.offset(2.0, 1e-4).unwrap();
        for k in 0..=20 {
            for l in 0..=20 {
                let u = o.domain_u().parameter_at(k as f64 / 20.0);
                let v = o.domain_v().parameter_at(l as f64 / 20.0);
                let r = o.point_at(u, v).distance(Point3::new(1.0, 2.0, 3.0));
                assert!((r - 7.0).abs() < 1e-4, "{u} {v}: {r}");
            }
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(24))]

        /// Points of the offset of a sphere lie at the offset distance from the sphere, within
        /// the tolerance, outwards and inwards.
        #[test]
        fn offset_points_lie_at_the_distance(
            radius in 0.5f64..20.0,
            fraction in -0.8f64..2.0,
            s in 0.0f64..1.0,
            t in 0.0f64..1.0,
        ) {
            let centre = Point3::new(-3.0, 1.0, 2.0);
            let sphere = Sphere::new(centre, radius).unwrap().to_nurbs().unwrap();
            let distance = fraction * radius;
            let tolerance = 1e-3;
            let o = sphere.offset(distance, tolerance).unwrap();
            let p = o.point_at(o.domain_u().parameter_at(s), o.domain_v().parameter_at(t));
            let from_sphere = (p.distance(centre) - radius).abs();
            prop_assert!((from_sphere - distance.abs()).abs() <= tolerance);
        }
    }
}

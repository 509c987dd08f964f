//! Surfaces from their edges (Rhino's `EdgeSrf`, Grasshopper's Edge Surface): the bilinearly
//! blended Coons patch of two, three or four curves that form a closed chain.
//!
//! The curves are chained end to start (reversed where needed) into the four sides: south
//! `S(u)`, east `E(v)`, north `N(u)` and west `W(v)` (north and west running against the chain),
//! with three curves the west side collapsed to the first curve's start and with two curves
//! both east and west collapsed. Opposite sides are made compatible
//! ([`NurbsCurve::make_compatible`], domain `0..1`). The patch
//! `S(u)(1−v) + N(u)v + W(v)(1−u) + E(v)u − B(u, v)`, `B` the bilinear patch of the corners, is
//! a NURBS surface of the same degrees and knots: because B-splines reproduce linear functions
//! at the Greville abscissae `ξ` of their knots, its control points are the same sum taken at
//! the sides' control points and the Greville abscissae (the discrete Coons formula). It is
//! done in homogeneous coordinates after each side's weights are scaled so its end weights are
//! 1, so that rational sides (arcs, whose end weights are equal) are reproduced exactly too; a
//! rational side whose end weights differ is an error.

use crate::{Error, NurbsCurve, NurbsSurface, Point3, Result};

/// The most edge curves a patch takes.
const MAX_EDGES: usize = 4;

impl NurbsSurface {
    /// The Coons patch of 2 to 4 `edges` that chain into a closed loop (see the module
    /// documentation), each end meeting the next curve's start or end within `tolerance`.
    /// `u` runs along the first curve, `v` from it to the opposite side, both on `0..1`.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] for fewer than 2 or more than 4 curves, curves that do not
    /// chain into a closed loop, a rational curve with unequal end weights, or a patch whose
    /// blended weights are not positive; the errors of [`NurbsCurve::make_compatible`].
    pub fn from_edges(edges: &[NurbsCurve], tolerance: f64) -> Result<Self> {
        if edges.len() < 2 || edges.len() > MAX_EDGES {
            return Err(Error::InvalidInput(format!(
                "an edge surface needs 2 to {MAX_EDGES} curves, got {}",
                edges.len()
            )));
        }
        if tolerance.is_nan() || tolerance < 0.0 {
            return Err(Error::InvalidInput(format!(
                "the tolerance must not be negative, got {tolerance}"
            )));
        }
        let chain = chain(edges, tolerance)?;
        let point = |p: Point3| NurbsCurve::new_non_rational(1, vec![p, p], vec![0.0, 1.0]);
        let (south, east, north, west) = match chain.len() {
            2 => (
                chain[0].clone(),
                point(chain[0].end_point())?,
                chain[1].reversed(),
                point(chain[0].start_point())?,
            ),
            3 => (
                chain[0].clone(),
                chain[1].clone(),
                chain[2].reversed(),
                point(chain[0].start_point())?,
            ),
            _ => (
                chain[0].clone(),
                chain[1].clone(),
                chain[2].reversed(),
                chain[3].reversed(),
            ),
        };
        let su = NurbsCurve::make_compatible(&[normalized(&south)?, normalized(&north)?])?;
        let sv = NurbsCurve::make_compatible(&[normalized(&west)?, normalized(&east)?])?;
        let (s, n) = (su[0].homogeneous_points(), su[1].homogeneous_points());
        let (w, e) = (sv[0].homogeneous_points(), sv[1].homogeneous_points());
        let xi_u = greville(su[0].degree(), su[0].knots());
        let xi_v = greville(sv[0].degree(), sv[0].knots());
        // The corners, homogeneous with weight 1.
        let corner = |h: [f64; 4]| [h[0] / h[3], h[1] / h[3], h[2] / h[3], 1.0];
        let p00 = corner(s[0]);
        let p10 = corner(s[s.len() - 1]);
        let p01 = corner(n[0]);
        let p11 = corner(n[n.len() - 1]);
        let (count_u, count_v) = (s.len(), w.len());
        let mut points = Vec::with_capacity(count_u * count_v);
        let mut weights = Vec::with_capacity(count_u * count_v);
        for i in 0..count_u {
            let a = xi_u[i];
            for j in 0..count_v {
                let b = xi_v[j];
                let mut h = [0.0; 4];
                for k in 0..4 {
                    let bilinear = (1.0 - a) * (1.0 - b) * p00[k]
                        + a * (1.0 - b) * p10[k]
                        + (1.0 - a) * b * p01[k]
                        + a * b * p11[k];
                    h[k] = s[i][k] * (1.0 - b) + n[i][k] * b + w[j][k] * (1.0 - a) + e[j][k] * a
                        - bilinear;
                }
                if h[3].is_nan() || h[3] <= 0.0 {
                    return Err(Error::InvalidInput(
                        "the edge curves' weights blend to a weight that is not positive".into(),
                    ));
                }
                points.push(Point3::new(h[0] / h[3], h[1] / h[3], h[2] / h[3]));
                weights.push(h[3]);
            }
        }
        if weights.iter().all(|&x| (x - 1.0).abs() <= 1e-15) {
            weights.fill(1.0);
        }
        NurbsSurface::from_flat(
            [su[0].degree(), sv[0].degree()],
            [count_u, count_v],
            points,
            weights,
            [su[0].knots().to_vec(), sv[0].knots().to_vec()],
        )
    }
}

/// The curves in chain order, each turned to start where the previous one ends, the last
/// ending where the first starts.
fn chain(edges: &[NurbsCurve], tolerance: f64) -> Result<Vec<NurbsCurve>> {
    let mut rest: Vec<NurbsCurve> = edges[1..].to_vec();
    let mut out = vec![edges[0].clone()];
    while !rest.is_empty() {
        let end = out[out.len() - 1].end_point();
        let (k, reversed, d) = rest
            .iter()
            .enumerate()
            .flat_map(|(k, c)| {
                [
                    (k, false, c.start_point().distance(end)),
                    (k, true, c.end_point().distance(end)),
                ]
            })
            .min_by(|a, b| a.2.total_cmp(&b.2))
            .unwrap_or((0, false, f64::INFINITY));
        if d > tolerance {
            return Err(Error::InvalidInput(format!(
                "the edge curves do not chain: no curve starts or ends within {tolerance} of \
                 the end of curve {}",
                out.len() - 1
            )));
        }
        let c = rest.remove(k);
        out.push(if reversed { c.reversed() } else { c });
    }
    let gap = out[out.len() - 1]
        .end_point()
        .distance(out[0].start_point());
    if gap > tolerance {
        return Err(Error::InvalidInput(format!(
            "the edge curves do not close: the chain's ends are {gap} apart"
        )));
    }
    Ok(out)
}

/// The curve with its weights scaled so that its end weights are 1.
fn normalized(curve: &NurbsCurve) -> Result<NurbsCurve> {
    let w = curve.weights();
    let (first, last) = (w[0], w[w.len() - 1]);
    if (last / first - 1.0).abs() > 1e-12 {
        return Err(Error::InvalidInput(
            "a rational edge curve with different end weights is not supported".into(),
        ));
    }
    let weights = w.iter().map(|x| x / first).collect();
    NurbsCurve::new(
        curve.degree(),
        curve.points().to_vec(),
        weights,
        curve.knots().to_vec(),
    )
}

/// The Greville abscissae of a knot vector in Rhino form: the averages of `degree`
/// consecutive knots.
fn greville(degree: usize, knots: &[f64]) -> Vec<f64> {
    let count = knots.len() + 1 - degree;
    (0..count)
        .map(|i| knots[i..i + degree].iter().sum::<f64>() / degree as f64)
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Arc, Circle, Interval, Plane, SurfaceDirection};

    fn line(a: Point3, b: Point3) -> NurbsCurve {
        NurbsCurve::new_non_rational(1, vec![a, b], vec![0.0, 1.0]).unwrap()
    }

    #[test]
    fn four_lines_give_the_bilinear_patch() {
        let (a, b, c, d) = (
            Point3::new(0.0, 0.0, 0.0),
            Point3::new(2.0, 0.0, 0.0),
            Point3::new(2.0, 1.0, 1.0),
            Point3::new(0.0, 1.0, 0.0),
        );
        // Out of order and one reversed: still chained.
        let edges = [line(a, b), line(d, c), line(c, b), line(d, a)];
        let s = NurbsSurface::from_edges(&edges, 1e-9).unwrap();
        let bilinear = NurbsSurface::from_corners(a, b, c, d).unwrap();
        for i in 0..=4 {
            for j in 0..=4 {
                let (u, v) = (f64::from(i) / 4.0, f64::from(j) / 4.0);
                assert!(s.point_at(u, v).distance(bilinear.point_at(u, v)) < 1e-14);
            }
        }
    }

    #[test]
    fn the_edges_lie_on_the_patch() {
        // A quarter-circle arc (rational), a cubic and two lines.
        let arc = Arc::new(
            Circle::new(Plane::WORLD_XY, 2.0).unwrap(),
            Interval::new(0.0, std::f64::consts::FRAC_PI_2),
        )
        .unwrap()
        .to_nurbs();
        let top = arc.end_point();
        let cubic = NurbsCurve::create(
            &[
                top,
                Point3::new(-0.5, 1.5, 1.0),
                Point3::new(-1.0, 1.0, -1.0),
                Point3::new(-1.0, 0.0, 0.0),
            ],
            3,
            false,
        )
        .unwrap();
        let l1 = line(Point3::new(-1.0, 0.0, 0.0), Point3::ORIGIN);
        let l2 = line(Point3::ORIGIN, arc.start_point());
        let edges = [arc.clone(), cubic.clone(), l1.clone(), l2.clone()];
        let s = NurbsSurface::from_edges(&edges, 1e-9).unwrap();
        let south = s.isocurve(SurfaceDirection::U, 0.0).unwrap();
        for k in 0..=16 {
            let t = f64::from(k) / 16.0;
            let p = arc.point_at(arc.domain().parameter_at(t));
            assert!(south.point_at(t).distance(p) < 1e-12, "{t}");
            let q = cubic.point_at(cubic.domain().parameter_at(t));
            assert!(s.point_at(1.0, t).distance(q) < 1e-12, "{t}");
        }
        // Three edges: the west side collapses to the first curve's start.
        let tri = NurbsSurface::from_edges(
            &[
                arc.clone(),
                cubic,
                line(Point3::new(-1.0, 0.0, 0.0), arc.start_point()),
            ],
            1e-9,
        )
        .unwrap();
        assert!(tri.is_singular(crate::SurfaceSide::West));
    }

    #[test]
    fn bad_edges() {
        let a = line(Point3::ORIGIN, Point3::new(1.0, 0.0, 0.0));
        let b = line(Point3::new(1.0, 0.0, 0.0), Point3::new(1.0, 1.0, 0.0));
        assert!(NurbsSurface::from_edges(std::slice::from_ref(&a), 1e-9).is_err());
        assert!(NurbsSurface::from_edges(&[a.clone(), b.clone()], 1e-9).is_err());
        let c = line(Point3::new(5.0, 5.0, 0.0), Point3::new(6.0, 5.0, 0.0));
        assert!(NurbsSurface::from_edges(&[a, b, c], 1e-9).is_err());
    }
}

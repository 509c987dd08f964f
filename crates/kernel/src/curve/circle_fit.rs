//! The circle that fits a set of points best (Rhino's `Circle.TryFitCircleToPoints`,
//! Grasshopper's Circle Fit).
//!
//! The points are first fitted with a plane ([`Plane::fit`]) and taken into its coordinates.
//! In the plane, the algebraic fit (Kåsa's: the least-squares solution of
//! `x² + y² + D·x + E·y + F = 0`, exact for points on a circle) gives a first centre and radius,
//! which Gauss–Newton's method on the geometric distances `|p − c| − r` then refines: the result
//! minimises the sum of squared distances from the points, measured in the plane, to the circle.
//! The circle lies in the fitted plane, centred at the fitted centre, its x axis the plane's;
//! the deviation is the largest distance in space from a point to the circle.

use crate::geometry::small_linear::solve_dense;
use crate::{Circle, Error, Plane, Point3, Result, Vector3};

/// Gauss–Newton iterations at most.
const MAX_ITERATIONS: usize = 100;

/// A fitted circle with the largest distance from a point to it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CircleFit {
    /// The circle.
    pub circle: Circle,
    /// The largest distance from one of the points to the circle.
    pub deviation: f64,
}

impl Circle {
    /// The circle that fits `points` best (see the module documentation).
    ///
    /// # Errors
    /// [`Error::TooFewPoints`] with fewer than three points, [`Error::NotFinite`] for a point
    /// that is not finite, [`Error::Collinear`] when the points lie on one line (no circle),
    /// [`Error::Degenerate`] when the fit does not converge to a finite circle.
    ///
    /// # Examples
    /// ```
    /// use locus_kernel::{Circle, Point3};
    /// let points: Vec<Point3> = (0..7)
    ///     .map(|k| {
    ///         let t = 0.4 + k as f64;
    ///         Point3::new(1.0 + 2.0 * t.cos(), -3.0 + 2.0 * t.sin(), 5.0)
    ///     })
    ///     .collect();
    /// let fit = Circle::fit(&points).unwrap();
    /// assert!((fit.circle.radius - 2.0).abs() < 1e-12);
    /// assert!(fit.circle.plane.origin.distance(Point3::new(1.0, -3.0, 5.0)) < 1e-12);
    /// assert!(fit.deviation < 1e-12);
    /// ```
    pub fn fit(points: &[Point3]) -> Result<CircleFit> {
        let plane = Plane::fit(points)?.plane;
        let local: Vec<(f64, f64)> = points
            .iter()
            .map(|&p| {
                let d = p - plane.origin;
                (d.dot(plane.x_axis), d.dot(plane.y_axis))
            })
            .collect();
        let (mut cx, mut cy, mut r) = algebraic(&local)?;
        for _ in 0..MAX_ITERATIONS {
            // Residuals f_i = |p_i − c| − r with gradient (−(p−c)/|p−c|, −1).
            let mut jtj = [[0.0; 3]; 3];
            let mut jtf = [0.0; 3];
            for &(x, y) in &local {
                let (dx, dy) = (x - cx, y - cy);
                let d = dx.hypot(dy);
                if d == 0.0 {
                    continue;
                }
                let row = [-dx / d, -dy / d, -1.0];
                let f = d - r;
                for i in 0..3 {
                    for j in 0..3 {
                        jtj[i][j] += row[i] * row[j];
                    }
                    jtf[i] += row[i] * f;
                }
            }
            let Some(step) = solve3(jtj, jtf) else {
                break;
            };
            let (nx, ny, nr) = (cx - step[0], cy - step[1], r - step[2]);
            let moved = step[0].abs().max(step[1].abs()).max(step[2].abs());
            (cx, cy, r) = (nx, ny, nr);
            if moved <= 1e-15 * r.abs().max(cx.abs()).max(cy.abs()).max(1e-300) {
                break;
            }
        }
        if !(cx.is_finite() && cy.is_finite() && r.is_finite()) || r <= 0.0 {
            return Err(Error::Degenerate {
                what: "fitted circle",
            });
        }
        let center = plane.origin + plane.x_axis * cx + plane.y_axis * cy;
        let circle = Circle::new(
            Plane {
                origin: center,
                ..plane
            },
            r,
        )?;
        let deviation = points
            .iter()
            .map(|&p| distance_to_circle(&circle, p))
            .fold(0.0, f64::max);
        Ok(CircleFit { circle, deviation })
    }
}

/// The distance in space from `p` to the circle.
fn distance_to_circle(circle: &Circle, p: Point3) -> f64 {
    let d = p - circle.plane.origin;
    let height = d.dot(circle.plane.z_axis);
    let radial: Vector3 = d - circle.plane.z_axis * height;
    (radial.length() - circle.radius).hypot(height)
}

/// Kåsa's algebraic fit in the plane: centre and radius. Coordinates are taken about their
/// centroid for conditioning.
fn algebraic(points: &[(f64, f64)]) -> Result<(f64, f64, f64)> {
    let n = points.len() as f64;
    let (mx, my) = points
        .iter()
        .fold((0.0, 0.0), |(a, b), &(x, y)| (a + x / n, b + y / n));
    let mut m = [[0.0; 3]; 3];
    let mut rhs = [0.0; 3];
    for &(x, y) in points {
        let (u, v) = (x - mx, y - my);
        let row = [u, v, 1.0];
        let target = -(u * u + v * v);
        for i in 0..3 {
            for j in 0..3 {
                m[i][j] += row[i] * row[j];
            }
            rhs[i] += row[i] * target;
        }
    }
    let [d, e, f] = solve3(m, rhs).ok_or(Error::Collinear)?;
    let (cu, cv) = (-d / 2.0, -e / 2.0);
    let r2 = cu * cu + cv * cv - f;
    if !r2.is_finite() || r2 <= 0.0 {
        return Err(Error::Collinear);
    }
    Ok((mx + cu, my + cv, r2.sqrt()))
}

/// Solves a 3 × 3 normal system, `None` when it is singular to rounding (a pivot below 1e-14
/// of its largest entry).
fn solve3(m: [[f64; 3]; 3], r: [f64; 3]) -> Option<[f64; 3]> {
    let scale = m
        .iter()
        .flatten()
        .fold(0.0f64, |a, x| a.max(x.abs()))
        .max(f64::MIN_POSITIVE);
    solve_dense(m, r, 1e-14 * scale)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn on_circle(center: Point3, normal: Vector3, radius: f64, angles: &[f64]) -> Vec<Point3> {
        let c = Circle::from_center_normal(center, normal, radius).unwrap();
        angles
            .iter()
            .map(|&t| {
                c.plane.origin + (c.plane.x_axis * t.cos() + c.plane.y_axis * t.sin()) * c.radius
            })
            .collect()
    }

    #[test]
    fn points_on_a_tilted_circle_give_it_back() {
        let normal = Vector3::new(0.3, -0.5, 0.8);
        let points = on_circle(
            Point3::new(2.0, 1.0, -1.0),
            normal,
            3.5,
            &[0.1, 0.9, 2.0, 2.2, 4.0],
        );
        let fit = Circle::fit(&points).unwrap();
        assert!((fit.circle.radius - 3.5).abs() < 1e-12);
        assert!(
            fit.circle
                .plane
                .origin
                .distance(Point3::new(2.0, 1.0, -1.0))
                < 1e-12
        );
        assert!(
            fit.circle
                .plane
                .z_axis
                .cross(normal.normalize_or_zero())
                .length()
                < 1e-12
        );
        assert!(fit.deviation < 1e-12);
    }

    #[test]
    fn a_short_arc_is_fitted_exactly_too() {
        // Five points over 6° of a circle of radius 100: the algebraic fit is poorly
        // conditioned there, the geometric refinement is not.
        let angles: Vec<f64> = (0..5).map(|k| 0.02 * k as f64).collect();
        let points = on_circle(Point3::ORIGIN, Vector3::Z, 100.0, &angles);
        let fit = Circle::fit(&points).unwrap();
        assert!(
            (fit.circle.radius - 100.0).abs() < 1e-7,
            "{}",
            fit.circle.radius
        );
    }

    #[test]
    fn noisy_points_give_the_least_squares_circle_and_their_deviation() {
        // Alternating radii 1.1 and 0.9 at evenly spaced angles: by symmetry the best circle
        // has radius 1 about the origin, and every point lies 0.1 from it.
        let points: Vec<Point3> = (0..12)
            .map(|k| {
                let t = std::f64::consts::TAU * k as f64 / 12.0;
                let r = if k % 2 == 0 { 1.1 } else { 0.9 };
                Point3::new(r * t.cos(), r * t.sin(), 0.0)
            })
            .collect();
        let fit = Circle::fit(&points).unwrap();
        assert!((fit.circle.radius - 1.0).abs() < 1e-12);
        assert!(fit.circle.plane.origin.distance(Point3::ORIGIN) < 1e-12);
        assert!((fit.deviation - 0.1).abs() < 1e-12);
    }

    #[test]
    fn too_few_collinear_or_bad_points_are_errors() {
        let p = |x: f64, y: f64| Point3::new(x, y, 0.0);
        assert!(matches!(
            Circle::fit(&[p(0.0, 0.0), p(1.0, 0.0)]),
            Err(Error::TooFewPoints { .. })
        ));
        assert!(matches!(
            Circle::fit(&[p(0.0, 0.0), p(1.0, 1.0), p(2.0, 2.0), p(3.0, 3.0)]),
            Err(Error::Collinear)
        ));
        assert!(Circle::fit(&[p(0.0, 0.0), p(1.0, 0.0), p(f64::NAN, 1.0)]).is_err());
    }
}

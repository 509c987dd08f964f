//! The sphere that fits a set of points best (Rhino's `Sphere.FitSphereToPoints`,
//! Grasshopper's Sphere Fit).
//!
//! The algebraic fit (the least-squares solution of `x² + y² + z² + D·x + E·y + F·z + G = 0`,
//! taken about the points' centroid for conditioning, exact for points on a sphere) gives a
//! first centre and radius, which Gauss–Newton's method on the geometric distances `|p − c| − r`
//! then refines: the result minimises the sum of squared distances from the points to the
//! sphere. The sphere is oriented by the world axes (Rhino's `Sphere(Point3d, double)`); the
//! deviation is the largest distance from a point to it.

use crate::geometry::small_linear::solve_dense;
use crate::{Error, Point3, Result, Sphere};

/// Gauss–Newton iterations at most.
const MAX_ITERATIONS: usize = 100;

/// A fitted sphere with the largest distance from a point to it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SphereFit {
    /// The sphere, oriented by the world axes.
    pub sphere: Sphere,
    /// The largest distance from one of the points to the sphere.
    pub deviation: f64,
}

impl Sphere {
    /// The sphere that fits `points` best (see the module documentation).
    ///
    /// # Errors
    /// [`Error::TooFewPoints`] with fewer than four points, [`Error::NotFinite`] for a point
    /// that is not finite, [`Error::Degenerate`] when the points lie in one plane (a circle, a
    /// line or one point: no single sphere) or the fit does not converge to a finite sphere.
    ///
    /// # Examples
    /// ```
    /// use locus_kernel::{Point3, Sphere};
    /// let points = [
    ///     Point3::new(3.0, 0.0, 0.0),
    ///     Point3::new(1.0, 2.0, 0.0),
    ///     Point3::new(1.0, 0.0, 2.0),
    ///     Point3::new(-1.0, 0.0, 0.0),
    ///     Point3::new(1.0, 0.0, -2.0),
    /// ];
    /// let fit = Sphere::fit(&points).unwrap();
    /// assert!((fit.sphere.radius - 2.0).abs() < 1e-12);
    /// assert!(fit.sphere.center().distance(Point3::new(1.0, 0.0, 0.0)) < 1e-12);
    /// assert!(fit.deviation < 1e-12);
    /// ```
    pub fn fit(points: &[Point3]) -> Result<SphereFit> {
        if points.len() < 4 {
            return Err(Error::TooFewPoints {
                what: "sphere fit",
                needed: 4,
                got: points.len(),
            });
        }
        if points.iter().any(|p| !p.is_finite()) {
            return Err(Error::NotFinite { what: "point" });
        }
        let (mut c, mut r) = algebraic(points)?;
        for _ in 0..MAX_ITERATIONS {
            // Residuals f_i = |p_i − c| − r with gradient (−(p−c)/|p−c|, −1).
            let mut jtj = [[0.0; 4]; 4];
            let mut jtf = [0.0; 4];
            for &p in points {
                let d = p - c;
                let length = d.length();
                if length == 0.0 {
                    continue;
                }
                let row = [-d.x / length, -d.y / length, -d.z / length, -1.0];
                let f = length - r;
                for i in 0..4 {
                    for j in 0..4 {
                        jtj[i][j] += row[i] * row[j];
                    }
                    jtf[i] += row[i] * f;
                }
            }
            let Some(step) = solve4(jtj, jtf) else {
                break;
            };
            c = Point3::new(c.x - step[0], c.y - step[1], c.z - step[2]);
            r -= step[3];
            let moved = step.iter().fold(0.0f64, |a, s| a.max(s.abs()));
            let size = r.abs().max(c.x.abs()).max(c.y.abs()).max(c.z.abs());
            if moved <= 1e-15 * size.max(1e-300) {
                break;
            }
        }
        if !(c.is_finite() && r.is_finite()) || r <= 0.0 {
            return Err(Error::Degenerate {
                what: "fitted sphere",
            });
        }
        let sphere = Sphere::new(c, r)?;
        let deviation = points
            .iter()
            .map(|&p| (p.distance(c) - r).abs())
            .fold(0.0, f64::max);
        Ok(SphereFit { sphere, deviation })
    }
}

/// The algebraic fit: centre and radius. Coordinates are taken about their centroid for
/// conditioning.
fn algebraic(points: &[Point3]) -> Result<(Point3, f64)> {
    let n = points.len() as f64;
    let (mx, my, mz) = points.iter().fold((0.0, 0.0, 0.0), |(a, b, c), p| {
        (a + p.x / n, b + p.y / n, c + p.z / n)
    });
    let mut m = [[0.0; 4]; 4];
    let mut rhs = [0.0; 4];
    for p in points {
        let (u, v, w) = (p.x - mx, p.y - my, p.z - mz);
        let row = [u, v, w, 1.0];
        let target = -(u * u + v * v + w * w);
        for i in 0..4 {
            for j in 0..4 {
                m[i][j] += row[i] * row[j];
            }
            rhs[i] += row[i] * target;
        }
    }
    let coplanar = Error::Degenerate {
        what: "point set (coplanar points fit no single sphere)",
    };
    let [d, e, f, g] = solve4(m, rhs).ok_or(coplanar.clone())?;
    let (cu, cv, cw) = (-d / 2.0, -e / 2.0, -f / 2.0);
    let r2 = cu * cu + cv * cv + cw * cw - g;
    if !r2.is_finite() || r2 <= 0.0 {
        return Err(coplanar);
    }
    Ok((Point3::new(mx + cu, my + cv, mz + cw), r2.sqrt()))
}

/// Solves a 4 × 4 normal system, `None` when it is singular to rounding (a pivot below 1e-14
/// of its largest entry).
fn solve4(m: [[f64; 4]; 4], r: [f64; 4]) -> Option<[f64; 4]> {
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

    /// Points on the sphere about `center` of `radius` at the given (longitude, latitude)
    /// pairs.
    fn on_sphere(center: Point3, radius: f64, angles: &[(f64, f64)]) -> Vec<Point3> {
        angles
            .iter()
            .map(|&(u, v)| {
                Point3::new(
                    center.x + radius * v.cos() * u.cos(),
                    center.y + radius * v.cos() * u.sin(),
                    center.z + radius * v.sin(),
                )
            })
            .collect()
    }

    #[test]
    fn points_on_a_sphere_give_it_back() {
        let center = Point3::new(2.0, -1.0, 7.5);
        let points = on_sphere(
            center,
            3.25,
            &[
                (0.1, 0.2),
                (1.3, -0.7),
                (2.9, 0.4),
                (4.0, 1.1),
                (5.5, -0.1),
                (0.7, -1.3),
            ],
        );
        let fit = Sphere::fit(&points).unwrap();
        assert!((fit.sphere.radius - 3.25).abs() < 1e-12);
        assert!(fit.sphere.center().distance(center) < 1e-12);
        assert!(fit.deviation < 1e-12);
        assert_eq!(fit.sphere.plane.x_axis, crate::Plane::WORLD_XY.x_axis);
    }

    #[test]
    fn four_points_on_a_small_cap_of_a_large_sphere_are_fitted_exactly() {
        // A cap of about 3° on a sphere of radius 1000 far from the origin: the algebraic fit
        // is poorly conditioned there, the geometric refinement is not.
        let center = Point3::new(-500.0, 200.0, 1000.0);
        let points = on_sphere(
            center,
            1000.0,
            &[
                (0.0, 0.0),
                (0.05, 0.0),
                (0.0, 0.05),
                (0.04, 0.03),
                (0.02, 0.01),
            ],
        );
        let fit = Sphere::fit(&points).unwrap();
        assert!(
            (fit.sphere.radius - 1000.0).abs() < 1e-6,
            "{}",
            fit.sphere.radius
        );
        assert!(fit.sphere.center().distance(center) < 1e-6);
    }

    #[test]
    fn noisy_points_give_the_least_squares_sphere_and_their_deviation() {
        // The six axis points at radius 1.1 and the eight cube corners at radius 0.9: by
        // symmetry the centre is the origin, and the best radius is the mean distance,
        // (6·1.1 + 8·0.9) / 14.
        let mut points = Vec::new();
        for axis in 0..3 {
            for sign in [-1.0, 1.0] {
                let mut c = [0.0; 3];
                c[axis] = 1.1 * sign;
                points.push(Point3::new(c[0], c[1], c[2]));
            }
        }
        let k = 0.9 / 3f64.sqrt();
        for &x in &[-k, k] {
            for &y in &[-k, k] {
                for &z in &[-k, k] {
                    points.push(Point3::new(x, y, z));
                }
            }
        }
        let fit = Sphere::fit(&points).unwrap();
        let mean = (6.0 * 1.1 + 8.0 * 0.9) / 14.0;
        assert!((fit.sphere.radius - mean).abs() < 1e-12);
        assert!(fit.sphere.center().distance(Point3::ORIGIN) < 1e-12);
        assert!((fit.deviation - (1.1 - mean)).abs() < 1e-12);
    }

    #[test]
    fn too_few_coplanar_or_bad_points_are_errors() {
        let p = Point3::new;
        assert!(matches!(
            Sphere::fit(&[p(0.0, 0.0, 0.0), p(1.0, 0.0, 0.0), p(0.0, 1.0, 0.0)]),
            Err(Error::TooFewPoints {
                needed: 4,
                got: 3,
                ..
            })
        ));
        // Four points on a circle lie in one plane: every sphere through the circle fits.
        let circle = [
            p(1.0, 0.0, 0.0),
            p(0.0, 1.0, 0.0),
            p(-1.0, 0.0, 0.0),
            p(0.0, -1.0, 0.0),
        ];
        assert!(matches!(
            Sphere::fit(&circle),
            Err(Error::Degenerate { .. })
        ));
        let same = [p(1.0, 2.0, 3.0); 5];
        assert!(Sphere::fit(&same).is_err());
        let nan = [
            p(1.0, 0.0, 0.0),
            p(0.0, 1.0, 0.0),
            p(0.0, 0.0, 1.0),
            p(f64::NAN, 0.0, 0.0),
        ];
        assert!(matches!(Sphere::fit(&nan), Err(Error::NotFinite { .. })));
    }
}

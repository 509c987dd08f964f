//! The plane that fits a set of points best in the least-squares sense (Rhino's
//! `Plane.FitPlaneToPoints`): through the centroid, with the normal along the direction in which
//! the points spread least.
//!
//! The directions are the eigenvectors of the points' covariance matrix, found by Jacobi
//! rotations (exact for symmetric 3 × 3 matrices to rounding, and never failing to converge on
//! finite input). The x axis is the direction of most spread, the normal that of least.
//!
//! *Orientation* (decided here, Rhino's choice not being documented): an eigenvector's sign is
//! arbitrary, so the normal is turned to point up (positive world z), or, for a vertical plane,
//! towards positive y, then positive x; the x axis is turned so that its largest component is
//! positive; y is `z × x`. Terrain-like point sets so get planes facing up.

use crate::{Error, Plane, Point3, Result, Vector3};

/// The least-squares fit of a plane to points, and how far the points lie from it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PlaneFit {
    /// The plane, through the centroid of the points.
    pub plane: Plane,
    /// The largest distance of a point from the plane.
    pub deviation: f64,
}

/// Points whose spread across their main direction is less than this fraction of their spread
/// along it lie on a line, for [`Plane::fit`].
pub const LINE_SPREAD: f64 = 1e-6;

/// Jacobi sweeps at most; each sweep squares the off-diagonal error, so a few suffice.
const MAX_SWEEPS: usize = 64;

impl Plane {
    /// The plane that fits `points` best (least squares), with the largest distance of a point
    /// from it.
    ///
    /// # Errors
    /// [`Error::TooFewPoints`] with fewer than three points, [`Error::NotFinite`] for a NaN or
    /// infinite point, [`Error::Collinear`] when the points lie on one line (or one point), so
    /// that no plane is determined.
    pub fn fit(points: &[Point3]) -> Result<PlaneFit> {
        if points.len() < 3 {
            return Err(Error::TooFewPoints {
                what: "a fitted plane",
                needed: 3,
                got: points.len(),
            });
        }
        if points.iter().any(|p| !p.is_finite()) {
            return Err(Error::NotFinite { what: "point" });
        }
        let n = points.len() as f64;
        let centroid = points.iter().fold(Vector3::ZERO, |s, p| s + p.to_vector()) / n;
        let centroid = Point3::ORIGIN + centroid;
        let mut m = [[0.0; 3]; 3];
        for p in points {
            let d = *p - centroid;
            let d = [d.x, d.y, d.z];
            for (i, row) in m.iter_mut().enumerate() {
                for (j, x) in row.iter_mut().enumerate() {
                    *x += d[i] * d[j];
                }
            }
        }
        let (values, vectors) = symmetric_eigen(m);
        let mut order = [0, 1, 2];
        order.sort_by(|&a, &b| values[b].total_cmp(&values[a]));
        let axis = |k: usize| Vector3::new(vectors[0][k], vectors[1][k], vectors[2][k]);
        let (largest, middle) = (values[order[0]], values[order[1]]);
        // Points on a line spread in one direction only: no plane is determined. The variances
        // carry rounding errors of about 1e-16 of the largest, so a second spread below
        // [`LINE_SPREAD`] of the first counts as none.
        if middle.is_nan() || middle <= (LINE_SPREAD * LINE_SPREAD) * largest || largest <= 0.0 {
            return Err(Error::Collinear);
        }
        let z = oriented_normal(axis(order[2]));
        let mut x = axis(order[0]);
        // Remove any rounding component along z, then fix the sign.
        x = (x - z * x.dot(z)).try_normalize().ok_or(Error::Collinear)?;
        let largest_component = [x.x, x.y, x.z]
            .into_iter()
            .max_by(|a, b| a.abs().total_cmp(&b.abs()))
            .unwrap_or(1.0);
        if largest_component < 0.0 {
            x = -x;
        }
        let plane = Plane {
            origin: centroid,
            x_axis: x,
            y_axis: z.cross(x),
            z_axis: z,
        };
        let deviation = points
            .iter()
            .map(|&p| plane.value_at(p).abs())
            .fold(0.0, f64::max);
        Ok(PlaneFit { plane, deviation })
    }
}

/// The normal turned up (positive z), or for a vertical normal towards positive y, then x.
fn oriented_normal(z: Vector3) -> Vector3 {
    let z = z.try_normalize().unwrap_or(Vector3::Z);
    let key = if z.z.abs() > 1e-12 {
        z.z
    } else if z.y.abs() > 1e-12 {
        z.y
    } else {
        z.x
    };
    if key < 0.0 { -z } else { z }
}

/// The eigenvalues and eigenvectors (as the columns of the second result) of a symmetric 3 × 3
/// matrix, by cyclic Jacobi rotations.
fn symmetric_eigen(mut a: [[f64; 3]; 3]) -> ([f64; 3], [[f64; 3]; 3]) {
    let mut v = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    for _ in 0..MAX_SWEEPS {
        let off = a[0][1].powi(2) + a[0][2].powi(2) + a[1][2].powi(2);
        let diagonal = a[0][0].powi(2) + a[1][1].powi(2) + a[2][2].powi(2);
        if off <= 1e-32 * diagonal || off == 0.0 {
            break;
        }
        for (p, q) in [(0, 1), (0, 2), (1, 2)] {
            if a[p][q] == 0.0 {
                continue;
            }
            // The rotation that zeroes a[p][q] (Golub and Van Loan, 8.4.2).
            let theta = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
            let t = theta.signum() / (theta.abs() + (theta * theta + 1.0).sqrt());
            let t = if theta == 0.0 { 1.0 } else { t };
            let c = 1.0 / (t * t + 1.0).sqrt();
            let s = t * c;
            for row in a.iter_mut() {
                let (akp, akq) = (row[p], row[q]);
                row[p] = c * akp - s * akq;
                row[q] = s * akp + c * akq;
            }
            let (row_p, row_q) = (a[p], a[q]);
            a[p] = std::array::from_fn(|k| c * row_p[k] - s * row_q[k]);
            a[q] = std::array::from_fn(|k| s * row_p[k] + c * row_q[k]);
            for row in &mut v {
                let (vkp, vkq) = (row[p], row[q]);
                row[p] = c * vkp - s * vkq;
                row[q] = s * vkp + c * vkq;
            }
        }
    }
    ([a[0][0], a[1][1], a[2][2]], v)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn points_on_a_tilted_plane_fit_it_exactly() {
        // Points on z = 0.5 x + 2, spread more along x than y.
        let points: Vec<Point3> = (0..5)
            .flat_map(|i| (0..3).map(move |j| (i as f64 * 2.0, j as f64)))
            .map(|(x, y)| Point3::new(x, y, 0.5 * x + 2.0))
            .collect();
        let fit = Plane::fit(&points).unwrap();
        let expected_normal = Vector3::new(-0.5, 0.0, 1.0) / 1.25f64.sqrt();
        assert!((fit.plane.z_axis - expected_normal).length() < 1e-12);
        assert!(fit.deviation < 1e-12);
        assert!((fit.plane.origin - Point3::new(4.0, 1.0, 4.0)).length() < 1e-12);
        // Most spread along the slope of x.
        let expected_x = Vector3::new(1.0, 0.0, 0.5) / 1.25f64.sqrt();
        assert!((fit.plane.x_axis - expected_x).length() < 1e-12);
        assert!((fit.plane.y_axis - Vector3::Y).length() < 1e-12);
    }

    #[test]
    fn the_deviation_is_the_farthest_point() {
        // A square at z = 0 and its centre raised by 1: the plane is z = 0.2 (the mean), the
        // centre lies 0.8 from it.
        let mut points = vec![
            Point3::new(-1.0, -1.0, 0.0),
            Point3::new(1.0, -1.0, 0.0),
            Point3::new(1.0, 1.0, 0.0),
            Point3::new(-1.0, 1.0, 0.0),
        ];
        points.push(Point3::new(0.0, 0.0, 1.0));
        let fit = Plane::fit(&points).unwrap();
        assert!((fit.plane.z_axis - Vector3::Z).length() < 1e-12);
        assert!((fit.plane.origin.z - 0.2).abs() < 1e-12);
        assert!((fit.deviation - 0.8).abs() < 1e-12);
    }

    #[test]
    fn a_vertical_plane_faces_positive_y() {
        let points = [
            Point3::new(0.0, 3.0, 0.0),
            Point3::new(5.0, 3.0, 0.0),
            Point3::new(0.0, 3.0, 2.0),
            Point3::new(5.0, 3.0, 2.0),
        ];
        let fit = Plane::fit(&points).unwrap();
        assert!((fit.plane.z_axis - Vector3::Y).length() < 1e-12);
        assert!((fit.plane.x_axis - Vector3::X).length() < 1e-12);
    }

    #[test]
    fn lines_points_and_bad_input_have_no_plane() {
        let line: Vec<Point3> = (0..4)
            .map(|i| Point3::new(i as f64, 2.0 * i as f64, 0.0))
            .collect();
        assert!(matches!(Plane::fit(&line), Err(Error::Collinear)));
        let same = [Point3::ORIGIN; 5];
        assert!(matches!(Plane::fit(&same), Err(Error::Collinear)));
        assert!(matches!(
            Plane::fit(&[Point3::ORIGIN, Point3::ORIGIN]),
            Err(Error::TooFewPoints { .. })
        ));
        let nan = [
            Point3::ORIGIN,
            Point3::new(1.0, 0.0, 0.0),
            Point3::new(f64::NAN, 1.0, 0.0),
        ];
        assert!(matches!(Plane::fit(&nan), Err(Error::NotFinite { .. })));
    }
}

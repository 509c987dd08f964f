//! Whether a point lies inside a closed planar curve (Rhino's `Curve.Contains`, Grasshopper's
//! Point In Curve).
//!
//! The point is projected onto the curve's plane. Within the tolerance of the curve it is on
//! it; otherwise the winding number of a polygon through samples of the curve (every span
//! break among them, so a polyline is its own polygon) decides. A point closer to the curve
//! than twice the polygon's largest deviation from the curve is decided instead by the side of
//! the curve it lies on at its closest point (the inside is to the left of the tangent, seen
//! from the normal about which the curve turns counter-clockwise).

use crate::{Curve, Error, Point3, Result, Vector3};

/// Samples per span of the polygon that decides containment.
const SAMPLES_PER_SPAN: usize = 32;
/// The most samples the polygon takes.
const MAX_SAMPLES: usize = 200_000;

/// Where a point lies with respect to a closed planar curve.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Containment {
    /// Outside the region the curve bounds (Grasshopper's 0).
    Outside = 0,
    /// On the curve, within the tolerance (1).
    Coincident = 1,
    /// Inside the region (2).
    Inside = 2,
}

impl Curve {
    /// Where `p` lies with respect to this closed planar curve, after projecting it onto the
    /// curve's plane, and the projected point (see the module documentation).
    ///
    /// # Errors
    /// [`Error::NotFinite`] for a non-finite point, [`Error::InvalidInput`] for a tolerance that
    /// is not positive, a curve that is not closed, or one whose control points lie farther
    /// than the tolerance from their plane.
    pub fn contains_point(&self, p: Point3, tolerance: f64) -> Result<(Containment, Point3)> {
        if !p.is_finite() {
            return Err(Error::NotFinite { what: "point" });
        }
        if !(tolerance > 0.0 && tolerance.is_finite()) {
            return Err(Error::InvalidInput(format!(
                "the tolerance must be positive, got {tolerance}"
            )));
        }
        if !self.is_closed() {
            return Err(Error::InvalidInput("the curve is not closed".into()));
        }
        let (polygon, deviation) = self.sample_polygon();
        let (origin, normal) = plane_of(&polygon, self.to_nurbs().points(), tolerance)?;
        let projected = p - normal * (p - origin).dot(normal);
        let closest = self.closest_point(projected)?;
        if closest.distance <= tolerance {
            return Ok((Containment::Coincident, projected));
        }
        let inside = if closest.distance <= 2.0 * deviation {
            // Counter-clockwise about `normal` (plane_of orients it so): inside is left.
            let tangent = self.tangent_at(closest.t).ok_or(Error::Degenerate {
                what: "curve tangent",
            })?;
            (projected - closest.point).dot(normal.cross(tangent)) > 0.0
        } else {
            winding(&polygon, projected, normal) != 0
        };
        let relation = if inside {
            Containment::Inside
        } else {
            Containment::Outside
        };
        Ok((relation, projected))
    }

    /// Points along the closed curve at every span break and [`SAMPLES_PER_SPAN`] per span
    /// (the last point not repeating the first), and the largest distance of the curve from
    /// the polygon's edges at their middles.
    fn sample_polygon(&self) -> (Vec<Point3>, f64) {
        let d = self.domain();
        let breaks: Vec<f64> = match self {
            Curve::Nurbs(c) => c.span_breaks(),
            Curve::Polyline { polyline, .. } => {
                let n = polyline.segment_count();
                (0..=n)
                    .map(|i| d.parameter_at(i as f64 / n as f64))
                    .collect()
            }
            _ => (0..=4)
                .map(|i| d.parameter_at(f64::from(i) / 4.0))
                .collect(),
        };
        let straight = self.degree() == 1;
        let per = if straight {
            1
        } else {
            SAMPLES_PER_SPAN
                .min(MAX_SAMPLES / breaks.len().max(1))
                .max(1)
        };
        let mut ts = Vec::with_capacity(per * breaks.len());
        for w in breaks.windows(2) {
            for i in 0..per {
                ts.push(w[0] + (w[1] - w[0]) * i as f64 / per as f64);
            }
        }
        let points: Vec<Point3> = ts.iter().map(|&t| self.point_at(t)).collect();
        let mut deviation = 0.0f64;
        if !straight {
            for (k, &t) in ts.iter().enumerate() {
                let next = ts.get(k + 1).copied().unwrap_or(d.t1);
                let mid = self.point_at(0.5 * (t + next));
                let (a, b) = (points[k], points[(k + 1) % points.len()]);
                deviation = deviation.max(distance_to_segment(mid, a, b));
            }
        }
        (points, deviation)
    }
}

/// The distance from `p` to the segment `a b`.
fn distance_to_segment(p: Point3, a: Point3, b: Point3) -> f64 {
    let ab = b - a;
    let len2 = ab.length_squared();
    let s = if len2 > 0.0 {
        ((p - a).dot(ab) / len2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    p.distance(a + ab * s)
}

/// The plane of a closed polygon: its vertex average and Newell's normal (so that the polygon
/// runs counter-clockwise about it), with every control point of the curve within `tolerance`.
fn plane_of(polygon: &[Point3], controls: &[Point3], tolerance: f64) -> Result<(Point3, Vector3)> {
    let n = polygon.len();
    let sum = polygon.iter().fold(Vector3::ZERO, |s, p| s + p.to_vector());
    let origin = Point3::from_vector(sum / n as f64);
    let mut normal = Vector3::ZERO;
    for i in 0..n {
        normal += (polygon[i] - origin).cross(polygon[(i + 1) % n] - origin);
    }
    let normal = normal
        .try_normalize()
        .ok_or_else(|| Error::InvalidInput("the curve encloses no area".into()))?;
    if controls
        .iter()
        .any(|p| (*p - origin).dot(normal).abs() > tolerance)
    {
        return Err(Error::InvalidInput("the curve is not planar".into()));
    }
    Ok((origin, normal))
}

/// The winding number of the closed polygon about `p`, both in the plane with `normal`.
fn winding(polygon: &[Point3], p: Point3, normal: Vector3) -> i32 {
    // Coordinates in the plane.
    let x = crate::perpendicular_to(normal).normalize_or_zero();
    let y = normal.cross(x);
    let uv = |q: Point3| {
        let v = q - p;
        (v.dot(x), v.dot(y))
    };
    let n = polygon.len();
    let mut w = 0;
    for i in 0..n {
        let (ax, ay) = uv(polygon[i]);
        let (bx, by) = uv(polygon[(i + 1) % n]);
        let cross = ax * by - bx * ay;
        if ay <= 0.0 {
            if by > 0.0 && cross > 0.0 {
                w += 1;
            }
        } else if by <= 0.0 && cross < 0.0 {
            w -= 1;
        }
    }
    w
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Circle, Line, Plane, Polyline};

    #[test]
    fn points_and_a_big_circle() {
        // Radius 1000: the polygon strays far more than the tolerance from the circle; points
        // just off it are decided by the side test.
        let c = Curve::from(Circle::new(Plane::WORLD_XY, 1000.0).unwrap());
        let tol = 0.001;
        let at = |r: f64, z: f64| Point3::new(r * 0.6, r * 0.8, z);
        assert_eq!(
            c.contains_point(at(999.99, 5.0), tol).unwrap().0,
            Containment::Inside
        );
        assert_eq!(
            c.contains_point(at(1000.01, 0.0), tol).unwrap().0,
            Containment::Outside
        );
        assert_eq!(
            c.contains_point(at(1000.0005, 0.0), tol).unwrap().0,
            Containment::Coincident
        );
        assert_eq!(
            c.contains_point(Point3::ORIGIN, tol).unwrap().0,
            Containment::Inside
        );
        let (_, projected) = c.contains_point(at(10.0, 5.0), tol).unwrap();
        assert_eq!(projected.z, 0.0);
        // Clockwise the same answers.
        let cw = c.reversed();
        assert_eq!(
            cw.contains_point(at(999.99, 5.0), tol).unwrap().0,
            Containment::Inside
        );
        assert_eq!(
            cw.contains_point(at(1000.01, 0.0), tol).unwrap().0,
            Containment::Outside
        );
    }

    #[test]
    fn a_concave_polygon() {
        // An L: the notch is outside.
        let l = Curve::from(
            Polyline::new(vec![
                Point3::new(0.0, 0.0, 0.0),
                Point3::new(2.0, 0.0, 0.0),
                Point3::new(2.0, 1.0, 0.0),
                Point3::new(1.0, 1.0, 0.0),
                Point3::new(1.0, 2.0, 0.0),
                Point3::new(0.0, 2.0, 0.0),
                Point3::new(0.0, 0.0, 0.0),
            ])
            .unwrap(),
        );
        let t = 1e-3;
        assert_eq!(
            l.contains_point(Point3::new(1.5, 1.5, 0.0), t).unwrap().0,
            Containment::Outside
        );
        assert_eq!(
            l.contains_point(Point3::new(0.5, 1.5, 0.0), t).unwrap().0,
            Containment::Inside
        );
        assert_eq!(
            l.contains_point(Point3::new(1.0, 1.5, 0.0), t).unwrap().0,
            Containment::Coincident
        );
    }

    #[test]
    fn bad_curves() {
        let line = Curve::from(Line::new(Point3::ORIGIN, Point3::new(1.0, 0.0, 0.0)));
        assert!(line.contains_point(Point3::ORIGIN, 1e-3).is_err());
        let twisted = Curve::from(
            Polyline::new(vec![
                Point3::new(0.0, 0.0, 0.0),
                Point3::new(1.0, 0.0, 0.0),
                Point3::new(1.0, 1.0, 1.0),
                Point3::new(0.0, 1.0, 0.0),
                Point3::new(0.0, 0.0, 0.0),
            ])
            .unwrap(),
        );
        assert!(twisted.contains_point(Point3::ORIGIN, 1e-3).is_err());
        let c = Curve::from(Circle::new(Plane::WORLD_XY, 1.0).unwrap());
        assert!(
            c.contains_point(Point3::new(f64::NAN, 0.0, 0.0), 1e-3)
                .is_err()
        );
    }
}

//! Intersections of lines and planes, by openNURBS's formulas (`ON_Intersect` for a line and a
//! line, a line and a plane, two planes and three planes), so that results equal Rhino's.
//!
//! Lines are infinite here: parameters may lie outside `[0, 1]`, as Rhino reports them.

use crate::geometry::tolerance::ZERO_TOLERANCE;
use crate::{Line, Plane, Point3, Vector3};

/// The closest points of two infinite lines: the parameters `(a, b)` on each (Rhino's
/// `Line.PointAt`, `from + t·(to − from)`), or `None` when the lines are parallel (or either
/// has no direction).
///
/// The parameters solve the normal equations of `|A(a) − B(b)|²`; lines whose directions make
/// an angle whose sine is below [`ZERO_TOLERANCE`] count as parallel.
pub fn line_line(a: &Line, b: &Line) -> Option<(f64, f64)> {
    let (da, db) = (a.direction(), b.direction());
    let c = b.from - a.from;
    let (aa, bb, ab) = (da.dot(da), db.dot(db), da.dot(db));
    let usable = aa.is_finite() && bb.is_finite() && aa > 0.0 && bb > 0.0;
    if !usable {
        return None;
    }
    let det = aa * bb - ab * ab;
    let sine_squared = da.cross(db).length_squared() / (aa * bb);
    let parallel = sine_squared.is_nan() || sine_squared <= ZERO_TOLERANCE * ZERO_TOLERANCE;
    if parallel || !det.is_finite() {
        return None;
    }
    let (ca, cb) = (da.dot(c), db.dot(c));
    let s = (ca * bb - ab * cb) / det;
    let t = (ab * ca - aa * cb) / det;
    (s.is_finite() && t.is_finite()).then_some((s, t))
}

/// The parameter on the infinite line where it meets the plane, or `None` when the line is
/// parallel to it (the plane's equation has the same value at both ends: exactly, as in
/// openNURBS, so that no tolerance hides a steep but short line).
pub fn line_plane(line: &Line, plane: &Plane) -> Option<f64> {
    let a = plane.value_at(line.from);
    let b = plane.value_at(line.to);
    let d = a - b;
    if d == 0.0 || !d.is_finite() {
        return None;
    }
    let t = a / d;
    t.is_finite().then_some(t)
}

/// The line where two planes meet, as openNURBS builds it: its start is the point on both planes
/// nearest (in the third plane's sense) the midpoint of the two origins, on the plane through that
/// midpoint perpendicular to the line; its direction is `B.normal × A.normal`, of length the sine
/// of the angle between the planes. `None` for parallel (or coincident) planes.
pub fn plane_plane(a: &Plane, b: &Plane) -> Option<Line> {
    let d = b.z_axis.cross(a.z_axis);
    let mid = Point3::from_dvec3(0.5 * (a.origin.to_dvec3() + b.origin.to_dvec3()));
    let third = Plane::from_normal(mid, d).ok()?;
    let from = plane_plane_plane(a, b, &third)?;
    Some(Line::new(from, from + d))
}

/// The point where three planes meet, or `None` when their normals are dependent (two of the
/// planes parallel, or all three sharing a direction).
///
/// Solves the three plane equations by Cramer's rule on the normals, the determinant measured
/// against [`ZERO_TOLERANCE`] relative to the normals' lengths.
pub fn plane_plane_plane(a: &Plane, b: &Plane, c: &Plane) -> Option<Point3> {
    let (na, nb, nc) = (a.z_axis, b.z_axis, c.z_axis);
    let det = na.dot(nb.cross(nc));
    let scale = na.length() * nb.length() * nc.length();
    if !det.is_finite() || det.abs() <= ZERO_TOLERANCE * scale {
        return None;
    }
    let (da, db, dc) = (
        na.dot(a.origin.to_vector()),
        nb.dot(b.origin.to_vector()),
        nc.dot(c.origin.to_vector()),
    );
    let p: Vector3 = (nb.cross(nc) * da + nc.cross(na) * db + na.cross(nb) * dc) / det;
    let p = Point3::from_vector(p);
    p.is_finite().then_some(p)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn p(x: f64, y: f64, z: f64) -> Point3 {
        Point3::new(x, y, z)
    }

    fn v(x: f64, y: f64, z: f64) -> Vector3 {
        Vector3::new(x, y, z)
    }

    #[test]
    fn skew_lines_meet_at_their_closest_points() {
        // Values from rhino3dm 8.17's Intersection.LineLine.
        let a = Line::new(p(0.0, 0.0, -1.0), p(1.0, 1.0, 4.0));
        let b = Line::new(p(0.0, 1.0, 0.0), p(3.0, 1.0, 1.0));
        let (s, t) = line_line(&a, &b).unwrap();
        assert!((s - 0.252_427_184_466_019_4).abs() < 1e-15);
        assert!((t - 0.101_941_747_572_815_52).abs() < 1e-15);
        assert!(line_line(&a, &a).is_none());
        assert!(line_line(&a, &Line::new(p(5.0, 0.0, 0.0), p(6.0, 1.0, 5.0))).is_none());
    }

    #[test]
    fn a_line_meets_a_plane_on_its_infinite_extension() {
        let plane = Plane::from_normal(p(1.0, 2.0, 3.0), v(0.0, 0.0, 1.0)).unwrap();
        let line = Line::new(p(0.0, 0.0, -1.0), p(1.0, 1.0, 4.0));
        assert!((line_plane(&line, &plane).unwrap() - 0.8).abs() < 1e-15);
        let short = Line::new(p(0.0, 0.0, 0.0), p(0.0, 0.0, 1.0));
        assert!((line_plane(&short, &plane).unwrap() - 3.0).abs() < 1e-15);
        let flat = Line::new(p(0.0, 0.0, 0.0), p(1.0, 0.0, 0.0));
        assert!(line_plane(&flat, &plane).is_none());
    }

    #[test]
    fn two_planes_meet_on_rhinos_line() {
        // rhino3dm 8.17: from (3.5, 0.5, 3), to (3.5, −0.394427…, 3).
        let a = Plane::from_normal(p(1.0, 2.0, 3.0), v(0.0, 0.0, 1.0)).unwrap();
        let b = Plane::from_normal(p(5.0, -1.0, 0.0), v(1.0, 0.0, 0.5)).unwrap();
        let line = plane_plane(&a, &b).unwrap();
        assert!(line.from.distance(p(3.5, 0.5, 3.0)) < 1e-14);
        assert!(line.to.distance(p(3.5, -0.394_427_190_999_915_86, 3.0)) < 1e-14);
        assert!(plane_plane(&a, &a.translated(v(0.0, 0.0, 2.0))).is_none());
        assert!(plane_plane(&a, &a.flipped()).is_none());
    }

    #[test]
    fn three_planes_meet_at_a_point() {
        let a = Plane::from_normal(p(1.0, 2.0, 3.0), v(0.0, 0.0, 1.0)).unwrap();
        let b = Plane::from_normal(p(5.0, -1.0, 0.0), v(1.0, 0.0, 0.5)).unwrap();
        let c = Plane::from_normal(p(0.0, 7.0, 0.0), v(0.0, 1.0, 0.0)).unwrap();
        let x = plane_plane_plane(&a, &b, &c).unwrap();
        assert!(x.distance(p(3.5, 7.0, 3.0)) < 1e-14);
        let parallel = a.translated(v(0.0, 0.0, 1.0));
        assert!(plane_plane_plane(&a, &parallel, &c).is_none());
    }
}

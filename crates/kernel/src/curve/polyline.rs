//! Polylines: chains of line segments.

use crate::geometry::tolerance::ZERO_TOLERANCE;
use crate::{Error, Interval, Line, NurbsCurve, Point3, Result, Transform, Vector3};

/// A chain of straight segments through at least two finite points, as Rhino's `Polyline`.
///
/// As a curve (Rhino's `PolylineCurve`) a polyline has the parameter `i` at its vertex `i`, so
/// the domain is `[0, n − 1]` and each segment is one unit of parameter.
#[derive(Clone, Debug, PartialEq)]
pub struct Polyline {
    points: Vec<Point3>,
}

impl Polyline {
    /// The polyline through `points`.
    ///
    /// # Errors
    /// [`Error::TooFewPoints`] with fewer than two points; [`Error::NotFinite`] for a NaN or
    /// infinite point.
    pub fn new(points: Vec<Point3>) -> Result<Self> {
        if points.len() < 2 {
            return Err(Error::TooFewPoints {
                what: "a polyline",
                needed: 2,
                got: points.len(),
            });
        }
        if points.iter().any(|p| !p.is_finite()) {
            return Err(Error::NotFinite { what: "point" });
        }
        Ok(Self { points })
    }

    /// The vertices.
    #[inline]
    pub fn points(&self) -> &[Point3] {
        &self.points
    }

    /// The number of segments, one less than the number of points.
    #[inline]
    pub fn segment_count(&self) -> usize {
        self.points.len() - 1
    }

    /// The segment `i` (from vertex `i` to vertex `i + 1`).
    ///
    /// # Panics
    /// When `i >= segment_count()`.
    #[inline]
    pub fn segment(&self, i: usize) -> Line {
        Line::new(self.points[i], self.points[i + 1])
    }

    /// The segments in order.
    pub fn segments(&self) -> impl Iterator<Item = Line> + '_ {
        self.points.windows(2).map(|w| Line::new(w[0], w[1]))
    }

    /// The total length.
    pub fn length(&self) -> f64 {
        self.segments().map(|s| s.length()).sum()
    }

    /// The domain `[0, n − 1]`.
    #[inline]
    pub fn domain(&self) -> Interval {
        Interval::new(0.0, self.segment_count() as f64)
    }

    /// Whether the polyline has at least four points and its last point coincides with the
    /// first (within [`ZERO_TOLERANCE`]), as Rhino's `IsClosed`.
    pub fn is_closed(&self) -> bool {
        self.points.len() >= 4
            && self.points[0].distance(self.points[self.points.len() - 1]) <= ZERO_TOLERANCE
    }

    /// The average of the vertices (Grasshopper's Polygon Center, CenterV); the closing
    /// vertex of a closed polyline, which repeats the first, is counted once.
    pub fn vertex_average(&self) -> Point3 {
        let pts = if self.is_closed() {
            &self.points[..self.points.len() - 1]
        } else {
            &self.points[..]
        };
        let sum = pts.iter().fold(Vector3::ZERO, |s, p| s + p.to_vector());
        Point3::from_vector(sum / pts.len() as f64)
    }

    /// The centroid of the segments as a wire of uniform density: their midpoints weighted by
    /// their lengths (Polygon Center's CenterE); the vertex average when the polyline has no
    /// length.
    pub fn wire_centroid(&self) -> Point3 {
        let (mut sum, mut total) = (Vector3::ZERO, 0.0);
        for s in self.segments() {
            let l = s.length();
            sum += (s.from.to_vector() + s.to.to_vector()) * (0.5 * l);
            total += l;
        }
        if total > 0.0 {
            Point3::from_vector(sum / total)
        } else {
            self.vertex_average()
        }
    }

    /// The area centroid of the region a closed polyline bounds (Polygon Center's CenterA):
    /// the triangles from the vertex average to every segment, weighted by their vector areas
    /// projected on the polygon's normal (Newell's), which is the planar centroid for a planar
    /// polygon. `None` for an open polyline or one that encloses no area.
    pub fn area_centroid(&self) -> Option<Point3> {
        if !self.is_closed() {
            return None;
        }
        let o = self.vertex_average();
        let mut normal = Vector3::ZERO;
        let areas: Vec<(Vector3, Vector3)> = self
            .segments()
            .map(|s| {
                let a = (s.from - o).cross(s.to - o) * 0.5;
                normal += a;
                (
                    a,
                    (o.to_vector() + s.from.to_vector() + s.to.to_vector()) / 3.0,
                )
            })
            .collect();
        let n = normal.try_normalize()?;
        let (mut sum, mut total) = (Vector3::ZERO, 0.0);
        for (a, c) in areas {
            let w = a.dot(n);
            sum += c * w;
            total += w;
        }
        (total != 0.0 && total.is_finite()).then(|| Point3::from_vector(sum / total))
    }

    /// The segment index and local parameter in `[0, 1]` of the parameter `t`; parameters
    /// outside the domain extend the first or last segment.
    pub(crate) fn segment_parameter(&self, t: f64) -> (usize, f64) {
        let last = self.segment_count() - 1;
        let i = if t.is_nan() || t < 1.0 {
            0
        } else {
            // Truncation of a finite non-negative value; huge values clamp to the last segment.
            (t.floor().min(last as f64)) as usize
        };
        (i, t - i as f64)
    }

    /// The point at parameter `t` (vertex `i` at `t = i`).
    pub fn point_at(&self, t: f64) -> Point3 {
        let (i, s) = self.segment_parameter(t);
        self.segment(i).point_at(s)
    }

    /// The parameter of the point closest to `p` (the first one when several are equally close).
    pub fn closest_parameter(&self, p: Point3) -> f64 {
        let mut best = (f64::INFINITY, 0.0);
        for (i, seg) in self.segments().enumerate() {
            let s = seg.closest_parameter(p);
            let d = seg.point_at(s).distance_squared(p);
            if d < best.0 {
                best = (d, i as f64 + s);
            }
        }
        best.1
    }

    /// The polyline with its points in the opposite order.
    pub fn reversed(&self) -> Self {
        let mut points = self.points.clone();
        points.reverse();
        Self { points }
    }

    /// The polyline with every vertex mapped by `transform`.
    pub fn transformed(&self, transform: &Transform) -> Self {
        Self {
            points: self
                .points
                .iter()
                .map(|&p| transform.transform_point(p))
                .collect(),
        }
    }

    /// The exact NURBS form: degree 1, the vertices as control points, knots `0, 1, …, n − 1`.
    pub fn to_nurbs(&self) -> NurbsCurve {
        let knots = (0..self.points.len()).map(|i| i as f64).collect();
        NurbsCurve::from_parts_unchecked(
            1,
            self.points.clone(),
            vec![1.0; self.points.len()],
            knots,
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn square() -> Polyline {
        Polyline::new(vec![
            Point3::new(0.0, 0.0, 0.0),
            Point3::new(10.0, 0.0, 0.0),
            Point3::new(10.0, 10.0, 0.0),
            Point3::new(0.0, 10.0, 0.0),
            Point3::new(0.0, 0.0, 0.0),
        ])
        .unwrap()
    }

    #[test]
    fn evaluation_length_and_closest_point() {
        let p = square();
        assert_eq!(p.length(), 40.0);
        assert!(p.is_closed());
        assert_eq!(p.point_at(1.5), Point3::new(10.0, 5.0, 0.0));
        assert_eq!(p.point_at(4.0), Point3::new(0.0, 0.0, 0.0));
        assert!(p.point_at(f64::NAN).x.is_nan());
        assert_eq!(p.closest_parameter(Point3::new(12.0, 3.0, 0.0)), 1.3);
        let n = p.to_nurbs();
        for i in 0..=40 {
            let t = i as f64 / 10.0;
            assert!(n.point_at(t).distance(p.point_at(t)) < 1e-14);
        }
    }

    #[test]
    fn centres_of_a_polygon() {
        // A trapezoid (0,0), (4,0), (4,2), (0,4): vertex average (2, 1.5); edges of lengths
        // 4, 2, √20, 4 with midpoints (2,0), (4,1), (2,3), (0,2); area 12 made of the
        // rectangle 4 × 2 (centroid (2,1), area 8) and the triangle (0,2), (4,2), (0,4)
        // (centroid (4/3, 8/3), area 4): centroid (16 + 16/3, 8 + 32/3) / 12.
        let p = Polyline::new(vec![
            Point3::new(0.0, 0.0, 0.0),
            Point3::new(4.0, 0.0, 0.0),
            Point3::new(4.0, 2.0, 0.0),
            Point3::new(0.0, 4.0, 0.0),
            Point3::new(0.0, 0.0, 0.0),
        ])
        .unwrap();
        assert!(p.vertex_average().distance(Point3::new(2.0, 1.5, 0.0)) < 1e-15);
        let r = 20f64.sqrt();
        let total = 10.0 + r;
        let want = Point3::new(
            (8.0 + 8.0 + 2.0 * r) / total,
            (2.0 + 3.0 * r + 8.0) / total,
            0.0,
        );
        assert!(p.wire_centroid().distance(want) < 1e-14);
        let want = Point3::new((16.0 + 16.0 / 3.0) / 12.0, (8.0 + 32.0 / 3.0) / 12.0, 0.0);
        assert!(p.area_centroid().unwrap().distance(want) < 1e-14);
        // Reversed, the same centroid; open, none.
        assert!(p.reversed().area_centroid().unwrap().distance(want) < 1e-14);
        let open = Polyline::new(p.points()[..4].to_vec()).unwrap();
        assert!(open.area_centroid().is_none());
    }

    #[test]
    fn too_few_or_bad_points() {
        assert!(Polyline::new(vec![Point3::ORIGIN]).is_err());
        assert!(Polyline::new(vec![Point3::ORIGIN, Point3::new(f64::NAN, 0.0, 0.0)]).is_err());
    }
}

//! Planar triangulations of point sets, as Grasshopper's Mesh › Triangulation components build
//! them: the Delaunay mesh, its edges, the Voronoi cells and the convex hull.
//!
//! The points are taken in a plane (given, or the least-squares plane of the points,
//! [`Plane::fit`]) and triangulated by their plane coordinates with the `spade` crate's
//! Delaunay triangulation (robust orientation and in-circle predicates; the same crate meshes
//! trimmed faces in `tessellate.rs`). The mesh keeps the points where they are: a terrain
//! survey triangulated in the world XY plane gives a terrain mesh.
//!
//! Points whose plane coordinates coincide with an earlier point's are *duplicates*: they
//! take no part (the first of them stands for all) and are reported by their indices, so that
//! callers can say so. Everything is computed in input order, so results do not depend on
//! anything but the points.

use spade::{DelaunayTriangulation, HasPosition, Point2, Triangulation};

use crate::{Error, Mesh, MeshFace, Plane, Point3, Polyline, Result};

/// A point in the triangulation: its plane coordinates.
#[derive(Clone, Copy, Debug)]
struct Site {
    position: Point2<f64>,
}

impl HasPosition for Site {
    type Scalar = f64;
    fn position(&self) -> Point2<f64> {
        self.position
    }
}

/// The Delaunay triangulation of points in a plane.
#[derive(Debug)]
pub struct PlanarTriangulation {
    plane: Plane,
    points: Vec<Point3>,
    /// The plane coordinates of every point.
    uv: Vec<(f64, f64)>,
    /// For each triangulation vertex, the index of the point it stands for (its first
    /// occurrence).
    point_of_vertex: Vec<usize>,
    /// For each point, its triangulation vertex.
    vertex_of_point: Vec<usize>,
    /// The indices of the points that repeat an earlier point's plane coordinates.
    duplicates: Vec<usize>,
    triangulation: DelaunayTriangulation<Site>,
}

impl PlanarTriangulation {
    /// The triangulation of `points` in `plane`, or in the points' best-fit plane.
    ///
    /// # Errors
    /// [`Error::NotFinite`] for a NaN or infinite point; [`Error::TooFewPoints`] with fewer
    /// than three distinct points; [`Error::Collinear`] when the points lie on one line in the
    /// plane; [`Error::InvalidInput`] for coordinates too large or small to triangulate.
    pub fn new(points: &[Point3], plane: Option<&Plane>) -> Result<Self> {
        if points.iter().any(|p| !p.is_finite()) {
            return Err(Error::NotFinite { what: "point" });
        }
        let plane = match plane {
            Some(plane) => *plane,
            None if points.len() < 3 => {
                return Err(Error::TooFewPoints {
                    what: "a triangulation",
                    needed: 3,
                    got: points.len(),
                });
            }
            None => Plane::fit(points)?.plane,
        };
        let uv: Vec<(f64, f64)> = points
            .iter()
            .map(|&p| {
                let [u, v, _] = plane.local_coordinates(p);
                (u, v)
            })
            .collect();
        let mut triangulation = DelaunayTriangulation::<Site>::new();
        let mut point_of_vertex = Vec::with_capacity(points.len());
        let mut vertex_of_point = Vec::with_capacity(points.len());
        let mut duplicates = Vec::new();
        for (i, &(u, v)) in uv.iter().enumerate() {
            let site = Site {
                position: Point2::new(u, v),
            };
            let handle = triangulation.insert(site).map_err(|e| {
                Error::InvalidInput(format!("point {i} cannot be triangulated: {e:?}"))
            })?;
            let vertex = handle.index();
            if vertex < point_of_vertex.len() {
                duplicates.push(i);
            } else {
                point_of_vertex.push(i);
            }
            vertex_of_point.push(vertex);
        }
        if point_of_vertex.len() < 3 {
            return Err(Error::TooFewPoints {
                what: "a triangulation",
                needed: 3,
                got: point_of_vertex.len(),
            });
        }
        if triangulation.num_inner_faces() == 0 {
            return Err(Error::Collinear);
        }
        Ok(Self {
            plane,
            points: points.to_vec(),
            uv,
            point_of_vertex,
            vertex_of_point,
            duplicates,
            triangulation,
        })
    }

    /// The plane the points were triangulated in.
    pub fn plane(&self) -> &Plane {
        &self.plane
    }

    /// The indices of the points left out because an earlier point has the same plane
    /// coordinates.
    pub fn duplicates(&self) -> &[usize] {
        &self.duplicates
    }

    /// The Delaunay mesh: the distinct points as vertices (in input order), triangles
    /// counter-clockwise about the plane's normal, in the order spade reports them.
    ///
    /// # Errors
    /// None in practice; the mesh constructor's checks hold by construction.
    pub fn mesh(&self) -> Result<Mesh> {
        let vertices = self
            .point_of_vertex
            .iter()
            .map(|&i| self.points[i])
            .collect();
        let faces = self
            .triangulation
            .inner_faces()
            .map(|f| {
                let [a, b, c] = f.vertices().map(|v| v.fix().index() as u32);
                MeshFace::triangle(a, b, c)
            })
            .collect();
        Mesh::new(vertices, faces)
    }

    /// The edges of the triangulation, as pairs of point indices `(i, j)` with `i < j`, sorted.
    pub fn edges(&self) -> Vec<(usize, usize)> {
        let mut edges: Vec<(usize, usize)> = self
            .triangulation
            .undirected_edges()
            .map(|e| {
                let [a, b] = e.vertices().map(|v| self.point_of_vertex[v.fix().index()]);
                (a.min(b), a.max(b))
            })
            .collect();
        edges.sort_unstable();
        edges
    }

    /// For every point, the indices of the points it shares a triangulation edge with,
    /// ascending. A duplicate has the connections of the point it repeats.
    pub fn connectivity(&self) -> Vec<Vec<usize>> {
        let mut neighbours = vec![Vec::new(); self.point_of_vertex.len()];
        for (i, j) in self.edges() {
            neighbours[self.vertex_of_point[i]].push(j);
            neighbours[self.vertex_of_point[j]].push(i);
        }
        for n in &mut neighbours {
            n.sort_unstable();
        }
        self.vertex_of_point
            .iter()
            .map(|&v| neighbours[v].clone())
            .collect()
    }

    /// The convex hull: the indices of the points on it, counter-clockwise about the plane's
    /// normal, starting at the lowest index. Points in the middle of a hull edge are not
    /// corners and are left out.
    pub fn convex_hull(&self) -> Vec<usize> {
        // spade lists the hull's edges clockwise; reversed, their starts go counter-clockwise.
        let mut hull: Vec<usize> = self
            .triangulation
            .convex_hull()
            .map(|e| self.point_of_vertex[e.from().fix().index()])
            .collect();
        hull.reverse();
        // Leave out points on the straight run between their neighbours.
        let n = hull.len();
        let corner = |k: usize| {
            let (a, b, c) = (
                self.uv[hull[(k + n - 1) % n]],
                self.uv[hull[k]],
                self.uv[hull[(k + 1) % n]],
            );
            exact_orientation(a, b, c) != 0.0
        };
        let corners: Vec<usize> = (0..n).filter(|&k| corner(k)).map(|k| hull[k]).collect();
        let start = (0..corners.len()).min_by_key(|&k| corners[k]).unwrap_or(0);
        corners[start..]
            .iter()
            .chain(&corners[..start])
            .copied()
            .collect()
    }

    /// The Voronoi cell of every point, clipped to a convex boundary given by its corners in
    /// plane coordinates (counter-clockwise): `None` for a duplicate point. Each cell is the
    /// boundary cut by the bisector of the point and each of its Delaunay neighbours (the
    /// neighbours are the only points whose bisectors bound the cell), as a closed polyline
    /// in the plane, counter-clockwise.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] for a boundary that is not convex and counter-clockwise.
    pub fn voronoi_cells(&self, boundary: &[(f64, f64)]) -> Result<Vec<Option<Polyline>>> {
        check_convex(boundary)?;
        let connectivity = self.connectivity();
        let mut duplicate = vec![false; self.points.len()];
        for &d in &self.duplicates {
            duplicate[d] = true;
        }
        let mut cells = Vec::with_capacity(self.points.len());
        for (i, neighbours) in connectivity.iter().enumerate() {
            if duplicate[i] {
                cells.push(None);
                continue;
            }
            let p = self.uv[i];
            let mut cell = boundary.to_vec();
            for &j in neighbours {
                let q = self.uv[j];
                // Keep the side of the bisector nearer p: (x − m)·(q − p) ≤ 0.
                let m = (0.5 * (p.0 + q.0), 0.5 * (p.1 + q.1));
                let d = (q.0 - p.0, q.1 - p.1);
                cell = clip_half_plane(&cell, |x| (x.0 - m.0) * d.0 + (x.1 - m.1) * d.1);
                if cell.is_empty() {
                    break;
                }
            }
            if cell.len() < 3 {
                // The point lies outside the boundary, or its cell is cut away entirely.
                cells.push(None);
                continue;
            }
            let mut corners: Vec<Point3> = cell
                .iter()
                .map(|&(u, v)| self.plane.point_at(u, v, 0.0))
                .collect();
            corners.push(corners[0]);
            cells.push(Some(Polyline::new(corners)?));
        }
        Ok(cells)
    }

    /// The plane coordinates of the point `i`.
    pub fn uv(&self, i: usize) -> (f64, f64) {
        self.uv[i]
    }

    /// The smallest rectangle (in plane coordinates) holding every point, enlarged on each
    /// side by `margin` times its larger side: counter-clockwise corners from the lowest.
    pub fn bounding_rectangle(&self, margin: f64) -> [(f64, f64); 4] {
        let (mut u0, mut v0, mut u1, mut v1) = (
            f64::INFINITY,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::NEG_INFINITY,
        );
        for &(u, v) in &self.uv {
            (u0, v0, u1, v1) = (u0.min(u), v0.min(v), u1.max(u), v1.max(v));
        }
        let pad = margin * (u1 - u0).max(v1 - v0);
        let (u0, v0, u1, v1) = (u0 - pad, v0 - pad, u1 + pad, v1 + pad);
        [(u0, v0), (u1, v0), (u1, v1), (u0, v1)]
    }
}

/// The orientation of `a b c`: positive when counter-clockwise, negative when clockwise, zero
/// when on one line, exactly (Shewchuk's adaptive predicate, the `robust` crate spade uses).
fn exact_orientation(a: (f64, f64), b: (f64, f64), c: (f64, f64)) -> f64 {
    let p = |q: (f64, f64)| robust::Coord { x: q.0, y: q.1 };
    robust::orient2d(p(a), p(b), p(c))
}

/// The orientation determinant of `a b c` (twice the signed area), in floating point.
fn orient(a: (f64, f64), b: (f64, f64), c: (f64, f64)) -> f64 {
    (b.0 - a.0) * (c.1 - a.1) - (c.0 - a.0) * (b.1 - a.1)
}

/// Rejects a polygon that is not convex and counter-clockwise (three or more corners, every
/// turn to the left or straight, some turn to the left).
fn check_convex(polygon: &[(f64, f64)]) -> Result<()> {
    let n = polygon.len();
    if n < 3 {
        return Err(Error::InvalidInput(format!(
            "a boundary needs at least three corners, got {n}"
        )));
    }
    let mut area = 0.0;
    for k in 0..n {
        let (a, b, c) = (polygon[k], polygon[(k + 1) % n], polygon[(k + 2) % n]);
        let turn = orient(a, b, c);
        let scale = ((b.0 - a.0).hypot(b.1 - a.1)) * ((c.0 - b.0).hypot(c.1 - b.1));
        if turn < -1e-12 * scale {
            return Err(Error::InvalidInput(
                "the boundary must be convex (a rectangle, a regular polygon…)".to_owned(),
            ));
        }
        area += polygon[k].0 * polygon[(k + 1) % n].1 - polygon[(k + 1) % n].0 * polygon[k].1;
    }
    if area <= 0.0 {
        return Err(Error::InvalidInput(
            "the boundary has no area in the plane".to_owned(),
        ));
    }
    Ok(())
}

/// The part of a convex polygon where `f ≤ 0` (Sutherland and Hodgman's clip by one line, `f`
/// affine).
fn clip_half_plane(polygon: &[(f64, f64)], f: impl Fn((f64, f64)) -> f64) -> Vec<(f64, f64)> {
    let n = polygon.len();
    let mut out = Vec::with_capacity(n + 1);
    for k in 0..n {
        let (a, b) = (polygon[k], polygon[(k + 1) % n]);
        let (fa, fb) = (f(a), f(b));
        if fa <= 0.0 {
            out.push(a);
        }
        if (fa < 0.0 && fb > 0.0) || (fa > 0.0 && fb < 0.0) {
            let t = fa / (fa - fb);
            out.push((a.0 + t * (b.0 - a.0), a.1 + t * (b.1 - a.1)));
        }
    }
    // Drop repeated corners (a cut through a corner adds it twice).
    out.dedup_by(|a, b| a == b);
    if out.len() > 1 && out.first() == out.last() {
        out.pop();
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Vector3;

    fn square_with_centre() -> Vec<Point3> {
        vec![
            Point3::new(0.0, 0.0, 0.0),
            Point3::new(2.0, 0.0, 0.0),
            Point3::new(2.0, 2.0, 0.0),
            Point3::new(0.0, 2.0, 0.0),
            Point3::new(1.0, 1.0, 0.5),
        ]
    }

    #[test]
    fn a_square_with_its_centre_gives_four_triangles_facing_up() {
        let t = PlanarTriangulation::new(&square_with_centre(), Some(&Plane::WORLD_XY)).unwrap();
        let mesh = t.mesh().unwrap();
        assert_eq!(mesh.vertices().len(), 5);
        assert_eq!(mesh.faces().len(), 4);
        // Every triangle uses the centre and faces +z (counter-clockwise seen from above).
        for f in mesh.faces() {
            assert!(f.corners().contains(&4));
            let [a, b, c] = [0, 1, 2].map(|k| mesh.vertices()[f.vertices[k] as usize]);
            assert!((b - a).cross(c - a).z > 0.0);
        }
        // The vertices keep their heights.
        assert_eq!(mesh.vertices()[4], Point3::new(1.0, 1.0, 0.5));
        assert_eq!(
            t.edges(),
            vec![
                (0, 1),
                (0, 3),
                (0, 4),
                (1, 2),
                (1, 4),
                (2, 3),
                (2, 4),
                (3, 4)
            ]
        );
        assert_eq!(t.connectivity()[4], vec![0, 1, 2, 3]);
        assert_eq!(t.connectivity()[0], vec![1, 3, 4]);
        assert_eq!(t.convex_hull(), vec![0, 1, 2, 3]);
    }

    #[test]
    fn the_best_fit_plane_faces_up_and_duplicates_are_reported() {
        let mut points = square_with_centre();
        points.push(Point3::new(2.0, 0.0, 0.0));
        let t = PlanarTriangulation::new(&points, None).unwrap();
        // The centre is raised and a corner counted twice, so the plane tilts a little; it
        // faces up.
        assert!(t.plane().z_axis.z > 0.99, "{:?}", t.plane());
        let flat = PlanarTriangulation::new(&points[..4], None).unwrap();
        assert!((flat.plane().z_axis - Vector3::Z).length() < 1e-12);
        assert_eq!(t.duplicates(), &[5]);
        assert_eq!(t.mesh().unwrap().vertices().len(), 5);
        assert_eq!(t.connectivity()[5], t.connectivity()[1]);
    }

    #[test]
    fn points_on_hull_edges_are_not_corners() {
        let points: Vec<Point3> = [
            (0.0, 0.0),
            (1.0, 0.0),
            (2.0, 0.0),
            (2.0, 2.0),
            (0.0, 2.0),
            (1.0, 1.0),
        ]
        .iter()
        .map(|&(x, y)| Point3::new(x, y, 0.0))
        .collect();
        let t = PlanarTriangulation::new(&points, Some(&Plane::WORLD_XY)).unwrap();
        assert_eq!(t.convex_hull(), vec![0, 2, 3, 4]);
    }

    #[test]
    fn voronoi_cells_of_a_grid_are_squares_around_each_point() {
        // A 3 × 3 grid of spacing 2; in the boundary [−1, 5]², every cell is the 2 × 2 square
        // around its point.
        let points: Vec<Point3> = (0..9)
            .map(|k| Point3::new(2.0 * (k % 3) as f64, 2.0 * (k / 3) as f64, 0.0))
            .collect();
        let t = PlanarTriangulation::new(&points, Some(&Plane::WORLD_XY)).unwrap();
        let boundary = [(-1.0, -1.0), (5.0, -1.0), (5.0, 5.0), (-1.0, 5.0)];
        let cells = t.voronoi_cells(&boundary).unwrap();
        for (k, cell) in cells.iter().enumerate() {
            let cell = cell.as_ref().unwrap();
            let p = points[k];
            assert_eq!(cell.points().len(), 5, "cell {k}: {:?}", cell.points());
            assert_eq!(cell.points()[0], cell.points()[4]);
            for q in &cell.points()[..4] {
                assert!(
                    ((q.x - p.x).abs() - 1.0).abs() < 1e-12,
                    "cell {k} corner {q:?}"
                );
                assert!(
                    ((q.y - p.y).abs() - 1.0).abs() < 1e-12,
                    "cell {k} corner {q:?}"
                );
            }
        }
    }

    #[test]
    fn voronoi_cells_cover_the_boundary() {
        // Random-ish points: the cells' areas add up to the boundary's.
        let points: Vec<Point3> = (0..40)
            .map(|k| {
                let t = k as f64;
                Point3::new((t * 7.31).sin() * 10.0, (t * 3.77).cos() * 10.0, 0.0)
            })
            .collect();
        let t = PlanarTriangulation::new(&points, Some(&Plane::WORLD_XY)).unwrap();
        let boundary = t.bounding_rectangle(0.1);
        let cells = t.voronoi_cells(&boundary).unwrap();
        let area: f64 = cells
            .iter()
            .flatten()
            .map(|c| {
                let p = c.points();
                0.5 * p
                    .windows(2)
                    .map(|w| w[0].x * w[1].y - w[1].x * w[0].y)
                    .sum::<f64>()
            })
            .sum();
        let (w, h) = (boundary[1].0 - boundary[0].0, boundary[2].1 - boundary[1].1);
        assert!(
            (area - w * h).abs() < 1e-9 * w * h,
            "{area} against {}",
            w * h
        );
    }

    #[test]
    fn degenerate_input_is_refused() {
        let line: Vec<Point3> = (0..5).map(|i| Point3::new(i as f64, 0.0, 0.0)).collect();
        assert!(matches!(
            PlanarTriangulation::new(&line, Some(&Plane::WORLD_XY)),
            Err(Error::Collinear)
        ));
        assert!(matches!(
            PlanarTriangulation::new(&line, None),
            Err(Error::Collinear)
        ));
        let two = [Point3::ORIGIN, Point3::new(1.0, 0.0, 0.0), Point3::ORIGIN];
        assert!(matches!(
            PlanarTriangulation::new(&two, Some(&Plane::WORLD_XY)),
            Err(Error::TooFewPoints { got: 2, .. })
        ));
        let nan = [
            Point3::ORIGIN,
            Point3::new(f64::NAN, 0.0, 0.0),
            Point3::new(0.0, 1.0, 0.0),
        ];
        assert!(matches!(
            PlanarTriangulation::new(&nan, None),
            Err(Error::NotFinite { .. })
        ));
        // A huge coordinate spade cannot take is an error, not a panic.
        let huge = [
            Point3::ORIGIN,
            Point3::new(1e300, 0.0, 0.0),
            Point3::new(0.0, 1.0, 0.0),
        ];
        let _ = PlanarTriangulation::new(&huge, Some(&Plane::WORLD_XY));
        // Points seen edge-on in the plane lie on one line.
        let vertical: Vec<Point3> = (0..4)
            .map(|i| Point3::new(0.0, i as f64 % 2.0, (i / 2) as f64))
            .collect();
        assert!(PlanarTriangulation::new(&vertical, Some(&Plane::WORLD_XY)).is_err());
        // A boundary that is not convex is refused.
        let t = PlanarTriangulation::new(&square_with_centre(), Some(&Plane::WORLD_XY)).unwrap();
        let dart = [(0.0, 0.0), (4.0, 0.0), (1.0, 1.0), (0.0, 4.0)];
        assert!(t.voronoi_cells(&dart).is_err());
        let clockwise = [(0.0, 0.0), (0.0, 4.0), (4.0, 4.0), (4.0, 0.0)];
        assert!(t.voronoi_cells(&clockwise).is_err());
    }
}

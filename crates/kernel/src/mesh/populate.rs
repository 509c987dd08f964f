//! Random points spread over a curve, a B-rep (or surface) or a mesh: Grasshopper's Populate
//! Geometry.
//!
//! A [`GeometrySampler`] draws points uniformly by length (curves) or area (surfaces, B-reps,
//! meshes): it divides the geometry into small pieces (the segments of the curve's polyline
//! within the meshing limits, the triangles of the mesh or of the B-rep's mesh), picks a piece
//! with probability proportional to its size, then a uniform point in it. Points of a curve
//! are evaluated on the curve at the parameter interpolated in the segment; points of a B-rep
//! are evaluated on the face surface at the parameters interpolated in the triangle, so they
//! lie exactly on the B-rep and inside its trims (only their density follows the mesh's
//! approximation of length and area). [`spread_points`] then spreads them by best-candidate
//! sampling.

use crate::geometry::best_candidate::best_candidate_points;
use crate::mesh::parameters::MeshingParameters;
use crate::mesh::tessellate::{FaceTriangle, curve_parameters};
use crate::{BoundingBox, Brep, Curve, Error, Mesh, Point3, Result};

/// The pieces points are drawn from.
#[derive(Debug)]
enum Pieces<'a> {
    /// A curve and the parameters that divide it into segments.
    Curve {
        curve: &'a Curve,
        parameters: Vec<f64>,
    },
    /// A B-rep's mesh triangles, in their faces' parameter planes.
    Faces {
        brep: &'a Brep,
        triangles: Vec<FaceTriangle>,
    },
    /// Triangles in space.
    Triangles(Vec<[Point3; 3]>),
}

/// Draws random points spread uniformly over a curve, a B-rep or a mesh (see the module
/// documentation).
#[derive(Debug)]
pub struct GeometrySampler<'a> {
    pieces: Pieces<'a>,
    /// The running sum of the pieces' sizes, one per piece.
    cumulative: Vec<f64>,
    /// 1 for a curve, 2 for a surface or mesh.
    dimension: u8,
    bounds: BoundingBox,
}

impl<'a> GeometrySampler<'a> {
    /// A sampler of a curve, divided within `parameters`.
    ///
    /// # Errors
    /// When the curve cannot be divided within the limits, or has no length.
    pub fn curve(curve: &'a Curve, parameters: &MeshingParameters) -> Result<Self> {
        parameters.validate()?;
        let ts = curve_parameters(&curve.to_nurbs(), parameters)?;
        let points: Vec<Point3> = ts.iter().map(|&t| curve.point_at(t)).collect();
        let cumulative = running_sum(points.windows(2).map(|w| w[0].distance(w[1])));
        Self::new(
            Pieces::Curve {
                curve,
                parameters: ts,
            },
            cumulative,
            1,
            &points,
        )
    }

    /// A sampler of a B-rep's faces, through its mesh within `parameters`.
    ///
    /// # Errors
    /// When the B-rep cannot be meshed, or has no area.
    pub fn brep(brep: &'a Brep, parameters: &MeshingParameters) -> Result<Self> {
        let (mesh, triangles) = Mesh::from_brep_with_face_triangles(brep, parameters)?;
        let cumulative = running_sum(mesh.triangles().map(|t| triangle_area(&mesh, t)));
        Self::new(
            Pieces::Faces { brep, triangles },
            cumulative,
            2,
            mesh.vertices(),
        )
    }

    /// A sampler of a mesh's faces (quads as two triangles).
    ///
    /// # Errors
    /// When the mesh has no area.
    pub fn mesh(mesh: &Mesh) -> Result<Self> {
        let v = mesh.vertices();
        let triangles: Vec<[Point3; 3]> =
            mesh.triangles().map(|t| t.map(|i| v[i as usize])).collect();
        let cumulative = running_sum(triangles.iter().map(|t| area(*t)));
        Self::new(Pieces::Triangles(triangles), cumulative, 2, v)
    }

    fn new(
        pieces: Pieces<'a>,
        cumulative: Vec<f64>,
        dimension: u8,
        points: &[Point3],
    ) -> Result<Self> {
        let total = cumulative.last().copied().unwrap_or(0.0);
        if !(total.is_finite() && total > 0.0) {
            return Err(Error::InvalidInput(format!(
                "the geometry has no {} to put points on",
                if dimension == 1 { "length" } else { "area" }
            )));
        }
        let mut bounds = BoundingBox::EMPTY;
        for p in points {
            bounds.include_point(*p);
        }
        Ok(Self {
            pieces,
            cumulative,
            dimension,
            bounds,
        })
    }

    /// The length of the curve or the area of the surface or mesh, as its pieces measure it.
    pub fn measure(&self) -> f64 {
        self.cumulative.last().copied().unwrap_or(0.0)
    }

    /// One random point, from three numbers in `[0, 1)` that `random` returns (only one for a
    /// curve).
    pub fn sample(&self, random: &mut impl FnMut() -> f64) -> Point3 {
        let (k, within) = self.pick(random());
        match &self.pieces {
            Pieces::Curve { curve, parameters } => {
                let (t0, t1) = (parameters[k], parameters[k + 1]);
                curve.point_at(t0 + within * (t1 - t0))
            }
            Pieces::Faces { brep, triangles } => {
                let FaceTriangle { face, uv } = triangles[k];
                let [a, b, c] = barycentric(random(), random());
                let u = a * uv[0][0] + b * uv[1][0] + c * uv[2][0];
                let v = a * uv[0][1] + b * uv[1][1] + c * uv[2][1];
                brep.faces()[face].surface.point_at(u, v)
            }
            Pieces::Triangles(triangles) => {
                let [p, q, r] = triangles[k];
                let [a, b, c] = barycentric(random(), random());
                Point3::from_vector(p.to_vector() * a + q.to_vector() * b + r.to_vector() * c)
            }
        }
    }

    /// The piece at the fraction `x` of the total size, and how far into it.
    fn pick(&self, x: f64) -> (usize, f64) {
        let total = self.measure();
        let target = x.clamp(0.0, 1.0) * total;
        let k = self
            .cumulative
            .partition_point(|&c| c <= target)
            .min(self.cumulative.len() - 1);
        let start = if k == 0 { 0.0 } else { self.cumulative[k - 1] };
        let size = self.cumulative[k] - start;
        let within = if size > 0.0 {
            ((target - start) / size).clamp(0.0, 1.0)
        } else {
            0.0
        };
        (k, within)
    }
}

/// `count` random points spread over the sampler's geometry by best-candidate sampling (each
/// the best of [`BEST_CANDIDATES`](crate::BEST_CANDIDATES) draws, farthest from the points
/// before it and from `existing`), from the numbers in `[0, 1)` that `random` returns.
pub fn spread_points(
    sampler: &GeometrySampler<'_>,
    count: usize,
    existing: &[Point3],
    mut random: impl FnMut() -> f64,
) -> Vec<Point3> {
    let per_point = sampler.measure() / (count + existing.len()).max(1) as f64;
    let spacing = if sampler.dimension == 1 {
        per_point
    } else {
        per_point.sqrt()
    };
    // Points on a surface may bulge out of its mesh's box by up to the chord deviation: a
    // margin keeps them in the grid.
    let d = sampler.bounds.diagonal();
    let margin = 0.05 * d.x.max(d.y).max(d.z);
    let m = crate::Vector3::new(margin, margin, margin);
    let bounds = BoundingBox::new(sampler.bounds.min - m, sampler.bounds.max + m);
    best_candidate_points(bounds, spacing, count, existing, || {
        Some(sampler.sample(&mut random))
    })
}

fn running_sum(sizes: impl Iterator<Item = f64>) -> Vec<f64> {
    let mut sum = 0.0;
    sizes
        .map(|s| {
            sum += if s.is_finite() { s } else { 0.0 };
            sum
        })
        .collect()
}

fn area([a, b, c]: [Point3; 3]) -> f64 {
    0.5 * (b - a).cross(c - a).length()
}

fn triangle_area(mesh: &Mesh, t: [u32; 3]) -> f64 {
    let v = mesh.vertices();
    area(t.map(|i| v[i as usize]))
}

/// Barycentric weights of a uniform point of a triangle from two uniform numbers.
fn barycentric(r1: f64, r2: f64) -> [f64; 3] {
    let s = r1.sqrt();
    [1.0 - s, s * (1.0 - r2), s * r2]
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::best_candidate::tests::lcg;
    use crate::{Circle, Plane, Sphere};

    fn nearest_neighbour_distances(points: &[Point3]) -> Vec<f64> {
        points
            .iter()
            .enumerate()
            .map(|(i, p)| {
                points
                    .iter()
                    .enumerate()
                    .filter(|(j, _)| *j != i)
                    .map(|(_, q)| p.distance(*q))
                    .fold(f64::INFINITY, f64::min)
            })
            .collect()
    }

    #[test]
    fn points_lie_on_a_sphere_and_spread_out() {
        let sphere = Sphere::new(Point3::ORIGIN, 3.0).unwrap();
        let brep = Brep::from_surface(sphere.to_nurbs().unwrap()).unwrap();
        let sampler = GeometrySampler::brep(&brep, &MeshingParameters::default()).unwrap();
        let area = 4.0 * std::f64::consts::PI * 9.0;
        assert!(
            (sampler.measure() - area).abs() < 0.01 * area,
            "{} {area}",
            sampler.measure()
        );
        let points = spread_points(&sampler, 200, &[], lcg(7));
        assert_eq!(points.len(), 200);
        for p in &points {
            assert!((p.distance(Point3::ORIGIN) - 3.0).abs() < 1e-9, "{p:?}");
        }
        // Spread: no two points closer than a fifth of the mean spacing of a uniform layout.
        let spacing = (area / 200.0).sqrt();
        let nearest = nearest_neighbour_distances(&points);
        assert!(nearest.iter().all(|&d| d > 0.2 * spacing), "{nearest:?}");
        // Both hemispheres get about half.
        let north = points.iter().filter(|p| p.z > 0.0).count();
        assert!((70..=130).contains(&north), "{north}");
    }

    #[test]
    fn face_triangles_map_to_their_mesh_triangles() {
        let cylinder = crate::Cylinder::new(Plane::WORLD_XY, 2.0, 5.0)
            .unwrap()
            .to_nurbs()
            .unwrap();
        let brep = Brep::from_surface(cylinder).unwrap();
        let (mesh, triangles) =
            Mesh::from_brep_with_face_triangles(&brep, &MeshingParameters::default()).unwrap();
        assert_eq!(mesh.faces().len(), triangles.len());
        for (ids, t) in mesh.triangles().zip(&triangles) {
            let surface = &brep.faces()[t.face].surface;
            for k in 0..3 {
                let on_surface = surface.point_at(t.uv[k][0], t.uv[k][1]);
                let vertex = mesh.vertices()[ids.iter().copied().nth(k).unwrap() as usize];
                // Corners match in some order (reversed faces swap two).
                let matches = ids
                    .iter()
                    .any(|&i| mesh.vertices()[i as usize].distance(on_surface) < 1e-9);
                assert!(matches, "{on_surface:?} vs {vertex:?}");
            }
        }
    }

    #[test]
    fn points_of_a_trimmed_face_stay_inside_its_trims() {
        // A planar face with a square hole: no point falls in the hole.
        let outer = crate::Polyline::new(vec![
            Point3::new(0.0, 0.0, 0.0),
            Point3::new(4.0, 0.0, 0.0),
            Point3::new(4.0, 4.0, 0.0),
            Point3::new(0.0, 4.0, 0.0),
            Point3::new(0.0, 0.0, 0.0),
        ])
        .unwrap();
        let hole = crate::Polyline::new(vec![
            Point3::new(1.0, 1.0, 0.0),
            Point3::new(3.0, 1.0, 0.0),
            Point3::new(3.0, 3.0, 0.0),
            Point3::new(1.0, 3.0, 0.0),
            Point3::new(1.0, 1.0, 0.0),
        ])
        .unwrap();
        let (breps, _) =
            Brep::planar_regions(&[Curve::from(outer), Curve::from(hole)], 1e-9).unwrap();
        let sampler = GeometrySampler::brep(&breps[0], &MeshingParameters::default()).unwrap();
        assert!((sampler.measure() - 12.0).abs() < 1e-9);
        for p in spread_points(&sampler, 300, &[], lcg(3)) {
            let in_hole =
                p.x > 1.0 + 1e-9 && p.x < 3.0 - 1e-9 && p.y > 1.0 + 1e-9 && p.y < 3.0 - 1e-9;
            assert!(!in_hole && p.z.abs() < 1e-12, "{p:?}");
        }
    }

    #[test]
    fn points_on_a_circle_are_on_it_and_avoid_existing_points() {
        let circle = Curve::from(Circle::new(Plane::WORLD_XY, 2.0).unwrap());
        let sampler = GeometrySampler::curve(&circle, &MeshingParameters::default()).unwrap();
        let existing = [Point3::new(2.0, 0.0, 0.0)];
        let points = spread_points(&sampler, 20, &existing, lcg(11));
        assert_eq!(points.len(), 20);
        for p in &points {
            assert!((p.distance(Point3::ORIGIN) - 2.0).abs() < 1e-12);
            assert!(p.distance(existing[0]) > 0.1, "{p:?}");
        }
    }

    #[test]
    fn the_same_seed_gives_the_same_points_and_empty_geometry_is_refused() {
        let mesh = Mesh::new(
            vec![
                Point3::ORIGIN,
                Point3::new(1.0, 0.0, 0.0),
                Point3::new(1.0, 1.0, 0.0),
                Point3::new(0.0, 1.0, 0.0),
            ],
            vec![crate::MeshFace::quad(0, 1, 2, 3)],
        )
        .unwrap();
        let sampler = GeometrySampler::mesh(&mesh).unwrap();
        let a = spread_points(&sampler, 50, &[], lcg(5));
        assert_eq!(a, spread_points(&sampler, 50, &[], lcg(5)));
        assert!(
            a.iter()
                .all(|p| (0.0..=1.0).contains(&p.x) && (0.0..=1.0).contains(&p.y))
        );
        let flat = Mesh::new(
            vec![
                Point3::ORIGIN,
                Point3::new(1.0, 0.0, 0.0),
                Point3::new(2.0, 0.0, 0.0),
            ],
            vec![crate::MeshFace::triangle(0, 1, 2)],
        )
        .unwrap();
        assert!(GeometrySampler::mesh(&flat).is_err());
    }
}

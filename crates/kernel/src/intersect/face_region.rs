//! The region of a B-rep face, for intersections that must keep only what lies on the face:
//! whether a point of the face's surface lies inside its trim loops, and whether the face is
//! planar.
//!
//! A point within the tolerance of one of the face's edges lies on its border and counts as
//! inside; any other point is tested against the trim loops in the parameter rectangle by the
//! even-odd rule, each trim sampled densely per span (the loops are only consulted away from
//! the border, where the sampling error of the trims cannot change the answer).

use crate::{Brep, NurbsSurface, Plane, Point3};

/// Samples per span of a curved trim.
const TRIM_SAMPLES: usize = 32;

/// A face's trim loops as polygons in its parameter rectangle, and its edges.
#[derive(Clone, Debug)]
pub(crate) struct FaceRegion {
    polygons: Vec<Vec<(f64, f64)>>,
    untrimmed: bool,
    edges: Vec<usize>,
}

impl FaceRegion {
    /// The region of face `face` of `brep`.
    pub(crate) fn new(brep: &Brep, face: usize) -> Self {
        let f = &brep.faces()[face];
        let mut edges = Vec::new();
        let polygons = f
            .loops
            .iter()
            .map(|&l| {
                let mut polygon = Vec::new();
                for &t in &brep.loops()[l].trims {
                    let trim = &brep.trims()[t];
                    if let Some(e) = trim.edge
                        && !edges.contains(&e)
                    {
                        edges.push(e);
                    }
                    let curve = &trim.curve;
                    let n = if curve.degree() == 1 { 1 } else { TRIM_SAMPLES };
                    for w in curve.span_breaks().windows(2) {
                        for k in 0..n {
                            let p = curve.point_at(w[0] + (w[1] - w[0]) * k as f64 / n as f64);
                            polygon.push((p.x, p.y));
                        }
                    }
                }
                polygon
            })
            .collect();
        Self {
            polygons,
            untrimmed: brep.is_untrimmed(face),
            edges,
        }
    }

    /// Whether the face is its whole surface.
    pub(crate) fn is_untrimmed(&self) -> bool {
        self.untrimmed
    }

    /// The edges of the face.
    pub(crate) fn edges(&self) -> &[usize] {
        &self.edges
    }

    /// Whether `(u, v)` lies inside the trim loops (even-odd).
    pub(crate) fn contains_uv(&self, u: f64, v: f64) -> bool {
        if self.untrimmed {
            return true;
        }
        let mut inside = false;
        for polygon in &self.polygons {
            let n = polygon.len();
            for i in 0..n {
                let (a, b) = (polygon[i], polygon[(i + 1) % n]);
                if (a.1 > v) != (b.1 > v) {
                    let x = a.0 + (v - a.1) / (b.1 - a.1) * (b.0 - a.0);
                    if u < x {
                        inside = !inside;
                    }
                }
            }
        }
        inside
    }

    /// Whether `p` lies within `tolerance` of one of the face's edges.
    pub(crate) fn on_border(&self, brep: &Brep, p: Point3, tolerance: f64) -> bool {
        self.edges.iter().any(|&e| {
            let curve = &brep.edges()[e].curve;
            curve
                .closest_point(p)
                .is_ok_and(|c| c.distance <= tolerance)
        })
    }

    /// Whether the point `p`, with surface parameters `uv` when known, lies on the face:
    /// on its border, or on its surface inside its loops.
    pub(crate) fn contains(
        &self,
        brep: &Brep,
        surface: &NurbsSurface,
        p: Point3,
        uv: Option<(f64, f64)>,
        tolerance: f64,
    ) -> bool {
        if self.on_border(brep, p, tolerance) {
            return true;
        }
        let (u, v) = match uv {
            Some(uv) => uv,
            None => match surface.closest_point(p) {
                Ok(c) if c.distance <= tolerance => (c.u, c.v),
                _ => return false,
            },
        };
        self.contains_uv(u, v)
    }
}

/// The plane of a surface whose control points all lie within `tolerance` of one, if it has
/// one: through the first control point, normal to the surface at the middle of its domain (or
/// to the diagonals of its control net where that normal is degenerate).
pub(crate) fn planar_surface(surface: &NurbsSurface, tolerance: f64) -> Option<Plane> {
    let (du, dv) = (surface.domain_u(), surface.domain_v());
    let points = surface.points();
    let origin = points[0];
    let normal = surface.normal_at(du.mid(), dv.mid()).ok().or_else(|| {
        let (nu, nv) = (surface.count_u(), surface.count_v());
        let corner = |i: usize, j: usize| points[i * nv + j];
        let a = corner(nu - 1, nv - 1) - corner(0, 0);
        let b = corner(0, nv - 1) - corner(nu - 1, 0);
        a.cross(b).try_normalize()
    })?;
    let plane = Plane::from_normal(origin, normal).ok()?;
    points
        .iter()
        .all(|&p| plane.signed_distance_to(p).abs() <= tolerance)
        .then_some(plane)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Cylinder, Interval, OrientedBox, Vector3};

    #[test]
    fn a_cylinder_cap_contains_its_disc_only() {
        let c = Cylinder::new(Plane::WORLD_XY, 1.0, 2.0).unwrap();
        let b = Brep::from_cylinder(&c, true).unwrap();
        let cap = (0..b.faces().len())
            .find(|&f| planar_surface(&b.faces()[f].surface, 1e-12).is_some())
            .unwrap();
        let region = FaceRegion::new(&b, cap);
        assert!(!region.is_untrimmed());
        let s = &b.faces()[cap].surface;
        let z = s.point_at(s.domain_u().mid(), s.domain_v().mid()).z;
        assert!(region.contains(&b, s, Point3::new(0.5, 0.2, z), None, 1e-9));
        assert!(region.contains(&b, s, Point3::new(1.0, 0.0, z), None, 1e-9));
        assert!(!region.contains(&b, s, Point3::new(0.9, 0.9, z), None, 1e-9));
        assert!(planar_surface(&b.faces()[0].surface, 1e-9).is_none());
    }

    #[test]
    fn box_faces_are_planar_and_untrimmed() {
        let b = Brep::from_box(&OrientedBox::new(
            Plane::WORLD_XY,
            Interval::new(0.0, 1.0),
            Interval::new(0.0, 2.0),
            Interval::new(0.0, 3.0),
        ))
        .unwrap();
        for f in 0..6 {
            let plane = planar_surface(&b.faces()[f].surface, 1e-12).unwrap();
            assert!(
                plane.z_axis.cross(Vector3::Z).length() < 1e-12
                    || plane.z_axis.dot(Vector3::Z).abs() < 1e-12
            );
            assert!(FaceRegion::new(&b, f).is_untrimmed());
        }
    }
}

//! Tight bounding boxes of B-reps: vertices, the extremes of every edge, and the interior
//! extremes of each face inside its trimmed region.

use crate::curve::nurbs::bounding_box::include_curve;
use crate::{BoundingBox, Brep};

impl Brep {
    /// The tight axis-aligned bounding box: the vertices, the extremes of every edge, and the
    /// interior extremes of each face that lie inside its trimmed region.
    pub fn bounding_box(&self) -> BoundingBox {
        let mut bbox = BoundingBox::EMPTY;
        for v in &self.vertices {
            bbox.include_point(v.point);
        }
        for e in &self.edges {
            include_curve(&e.curve, &mut bbox);
        }
        for f in 0..self.faces.len() {
            let surface = &self.faces[f].surface;
            if self.is_untrimmed(f) {
                surface.include_interior_extremes(&|_, _| true, &mut bbox);
            } else {
                let polygons = self.face_polygons(f);
                surface.include_interior_extremes(&|u, v| inside(&polygons, u, v), &mut bbox);
            }
        }
        bbox
    }

    /// The face's loops as polygons in parameter space, each trim sampled densely per span.
    fn face_polygons(&self, f: usize) -> Vec<Vec<(f64, f64)>> {
        self.faces[f]
            .loops
            .iter()
            .map(|&l| {
                let mut polygon = Vec::new();
                for &t in &self.loops[l].trims {
                    let curve = &self.trims[t].curve;
                    let breaks = curve.span_breaks();
                    let n = if curve.degree() == 1 { 1 } else { 32 };
                    for w in breaks.windows(2) {
                        for k in 0..n {
                            let p = curve.point_at(w[0] + (w[1] - w[0]) * k as f64 / n as f64);
                            polygon.push((p.x, p.y));
                        }
                    }
                }
                polygon
            })
            .collect()
    }
}

/// Even-odd containment of `(u, v)` in a set of polygons (outer boundary and holes).
fn inside(polygons: &[Vec<(f64, f64)>], u: f64, v: f64) -> bool {
    let mut count = false;
    for polygon in polygons {
        let n = polygon.len();
        for i in 0..n {
            let (a, b) = (polygon[i], polygon[(i + 1) % n]);
            if (a.1 > v) != (b.1 > v) {
                let x = a.0 + (v - a.1) / (b.1 - a.1) * (b.0 - a.0);
                if u < x {
                    count = !count;
                }
            }
        }
    }
    count
}

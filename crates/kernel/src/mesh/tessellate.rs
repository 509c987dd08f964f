//! Meshing B-reps and surfaces.
//!
//! Every B-rep edge is divided once (by its 3-D curve and the meshing limits) and its points
//! become mesh vertices shared by the faces on both sides, so that a closed B-rep gives a
//! closed mesh. Each face is then triangulated in its parameter plane: the points of its trim
//! loops (taken from the shared edge divisions) are the constraint edges of a constrained
//! Delaunay triangulation (the `spade` crate), and the nodes of an adaptive parameter grid
//! inside the trimmed region are its interior points. Triangles outside the region (outside the
//! outer loop or inside a hole) are dropped. Along a singular side (a sphere's pole, a cone's
//! apex) every boundary point maps to the one B-rep vertex there, so the triangles touching the
//! side collapse into a fan around that vertex and the degenerate ones are dropped.
//!
//! The parameter plane is scaled by the surface's mean speed in each direction before
//! triangulating, so that the Delaunay criterion sees shapes close to those on the surface,
//! and its interior nodes sheared by a millionth so that no grid cell is a Delaunay tie
//! ([`SHEAR`]).

use spade::{ConstrainedDelaunayTriangulation, HasPosition, Point2, Triangulation};

use crate::mesh::parameters::{MAX_MESH_VERTICES, MeshingParameters, SURFACE_CHORD_SHARE};
use crate::mesh::sampling::{Family, Probe, thin_out};
use crate::surface::across::AcrossFrames;
use crate::surface::direction::{SurfaceDirection, SurfaceSide};
use crate::{Brep, Error, Mesh, MeshFace, NurbsCurve, NurbsSurface, Point3, Result, Vector3};

/// How many isocurves probe one direction of a surface, at most.
const MAX_PROBE_CURVES: usize = 65;

/// The shear of the interior grid nodes in the scaled parameter plane, `x + SHEAR · y`: it
/// makes the grid's cells parallelograms, whose corners are never on one circle. On an exact
/// rectangle grid every cell is a tie for the Delaunay criterion, which spade's exact
/// predicates can only settle on their slow adaptive path (a third of the meshing time), and
/// each cell's diagonal is left to the tie-break; sheared, every cell is cut along the same
/// diagonal, on the fast path. The boundary points are not sheared: rounding would take points
/// of a straight side off their line, and the triangulation would fill the dents with slivers.
/// A millionth of a cell leaves the interior nodes far inside their clearance from the trims.
const SHEAR: f64 = 1e-6;

/// Interior grid nodes nearer than this fraction of the local grid cell to a trim are left
/// out, so that no sliver forms between a grid node and a boundary point.
const BOUNDARY_CLEARANCE: f64 = 0.3;

/// A vertex of the parameter-plane triangulation: its scaled position and its mesh vertex.
#[derive(Clone, Copy, Debug)]
struct UvVertex {
    position: Point2<f64>,
    id: u32,
    /// The surface parameters (the position is scaled, and sheared for interior nodes).
    uv: [f64; 2],
}

impl HasPosition for UvVertex {
    type Scalar = f64;
    fn position(&self) -> Point2<f64> {
        self.position
    }
}

/// A triangle of a B-rep's mesh in the parameter plane of the face it lies on: the surface
/// of face `face` at `uv[k]` is the triangle's `k`-th corner (so the surface at a convex
/// combination of the `uv` is a point of the face, inside its trims).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FaceTriangle {
    /// The index of the B-rep face.
    pub face: usize,
    /// The face-surface parameters of the three corners.
    pub uv: [[f64; 2]; 3],
}

/// The mesh being built: vertices and the sums of the surface normals seen at each.
#[derive(Debug, Default)]
struct Builder {
    vertices: Vec<Point3>,
    normal_sums: Vec<Vector3>,
    faces: Vec<MeshFace>,
    /// Whether to record `face_triangles`.
    record: bool,
    /// Per mesh face (all triangles), its face and parameters, when `record` is set.
    face_triangles: Vec<FaceTriangle>,
}

impl Builder {
    fn vertex(&mut self, p: Point3) -> Result<u32> {
        if self.vertices.len() >= MAX_MESH_VERTICES {
            return Err(Error::InvalidInput(format!(
                "meshing would make more than {MAX_MESH_VERTICES} vertices; loosen the \
                 meshing parameters"
            )));
        }
        self.vertices.push(p);
        self.normal_sums.push(Vector3::ZERO);
        Ok((self.vertices.len() - 1) as u32)
    }

    fn finish(self) -> Result<Mesh> {
        let mesh = Mesh::new(self.vertices, self.faces)?;
        let fallback = mesh.clone().with_computed_normals();
        let computed = fallback.normals().unwrap_or_default();
        let normals = self
            .normal_sums
            .iter()
            .zip(computed)
            .map(|(n, &c)| n.try_normalize().unwrap_or(c))
            .collect();
        mesh.with_normals(normals)
    }
}

/// The parameters dividing an edge curve.
pub(crate) fn curve_parameters(curve: &NurbsCurve, limits: &MeshingParameters) -> Result<Vec<f64>> {
    let mut eval = |t: f64, out: &mut Vec<Probe>| {
        let (point, d1, _) = curve.point_and_derivatives_at(t);
        out.push(Probe {
            point,
            direction: d1.try_normalize(),
        });
    };
    Family::new(&mut eval).refine(&curve.span_breaks(), limits)
}

/// The parameters dividing one direction of a surface, probed along isocurves at (at most
/// [`MAX_PROBE_CURVES`]) span breaks and span midpoints of the other direction.
fn surface_parameters(
    surface: &NurbsSurface,
    direction: SurfaceDirection,
    limits: &MeshingParameters,
) -> Result<Vec<f64>> {
    let other = match direction {
        SurfaceDirection::U => SurfaceDirection::V,
        SurfaceDirection::V => SurfaceDirection::U,
    };
    let other_breaks = surface.span_breaks(other);
    let mut across = Vec::with_capacity(2 * other_breaks.len());
    for w in other_breaks.windows(2) {
        across.push(w[0]);
        across.push(0.5 * (w[0] + w[1]));
    }
    across.extend(other_breaks.last());
    let across = thin_out(&across, MAX_PROBE_CURVES);
    let mut frames = AcrossFrames::new(surface, direction, &across);
    let mut eval = |t: f64, out: &mut Vec<Probe>| {
        frames.eval(t, |point, normal| {
            out.push(Probe {
                point,
                direction: normal,
            });
        });
    };
    Family::new(&mut eval).refine(&surface.span_breaks(direction), limits)
}

/// One boundary point of a face: its parameters and its mesh vertex.
#[derive(Clone, Copy, Debug)]
struct LoopPoint {
    uv: (f64, f64),
    id: u32,
}

/// Whether `p` lies inside the loops by the even-odd rule.
fn inside(p: (f64, f64), loops: &[Vec<(f64, f64)>]) -> bool {
    let mut inside = false;
    for polygon in loops {
        let n = polygon.len();
        for i in 0..n {
            let (a, b) = (polygon[i], polygon[(i + 1) % n]);
            if (a.1 > p.1) != (b.1 > p.1) {
                let x = a.0 + (p.1 - a.1) / (b.1 - a.1) * (b.0 - a.0);
                if p.0 < x {
                    inside = !inside;
                }
            }
        }
    }
    inside
}

/// The distance from `p` to the segment `a b`.
fn segment_distance(p: (f64, f64), a: (f64, f64), b: (f64, f64)) -> f64 {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let len2 = dx * dx + dy * dy;
    let t = if len2 > 0.0 {
        (((p.0 - a.0) * dx + (p.1 - a.1) * dy) / len2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    let (x, y) = (a.0 + t * dx - p.0, a.1 + t * dy - p.1);
    (x * x + y * y).sqrt()
}

impl Mesh {
    /// The mesh of a B-rep (Rhino's `Mesh.CreateFromBrep`, Grasshopper's Mesh Brep): one mesh
    /// of all faces, with vertices shared along edges, triangles counter-clockwise seen from
    /// outside (each face's `reversed` flag honoured) and vertex normals from the surfaces.
    /// A closed B-rep gives a closed mesh ([`Mesh::is_closed_and_oriented`]).
    ///
    /// # Errors
    /// [`Error::InvalidInput`] for bad parameters, for limits that would need more than
    /// [`MAX_MESH_VERTICES`](crate::mesh::parameters::MAX_MESH_VERTICES) vertices, or for trim
    /// loops that cross each other in a face's parameter plane.
    pub fn from_brep(brep: &Brep, parameters: &MeshingParameters) -> Result<Self> {
        mesh_brep(brep, parameters, false).map(|(mesh, _)| mesh)
    }

    /// The mesh of a B-rep as [`Mesh::from_brep`] makes it, with the face and the parameters
    /// of every triangle (one [`FaceTriangle`] per mesh face, in order), to map points of the
    /// mesh back onto the B-rep exactly.
    ///
    /// # Errors
    /// As [`Mesh::from_brep`].
    pub fn from_brep_with_face_triangles(
        brep: &Brep,
        parameters: &MeshingParameters,
    ) -> Result<(Self, Vec<FaceTriangle>)> {
        mesh_brep(brep, parameters, true)
    }

    /// The mesh of a whole surface (Grasshopper's Mesh Surface, Rhino's
    /// `Mesh.CreateFromSurface`), through its B-rep so that seams close and collapsed sides
    /// become fans.
    ///
    /// # Errors
    /// As [`Mesh::from_brep`].
    pub fn from_surface(surface: &NurbsSurface, parameters: &MeshingParameters) -> Result<Self> {
        parameters.validate()?;
        Self::from_brep(&Brep::from_surface(surface.clone())?, parameters)
    }
}

/// Meshes a B-rep (see [`Mesh::from_brep`]), recording each triangle's face and parameters
/// when `record` is set.
fn mesh_brep(
    brep: &Brep,
    parameters: &MeshingParameters,
    record: bool,
) -> Result<(Mesh, Vec<FaceTriangle>)> {
    parameters.validate()?;
    let mut b = Builder {
        record,
        ..Builder::default()
    };

    for v in brep.vertices() {
        b.vertex(v.point)?;
    }
    // Each edge divided once; the mesh vertices along it, first vertex to last.
    let mut edge_divisions: Vec<(Vec<f64>, Vec<u32>)> = Vec::with_capacity(brep.edges().len());
    // An edge chord is a side of triangles whose other direction adds its own share of the
    // deviation, so edges get the same share as each direction of a surface.
    let edge_limits = MeshingParameters {
        max_chord_deviation: parameters.max_chord_deviation * SURFACE_CHORD_SHARE,
        ..*parameters
    };
    for edge in brep.edges() {
        let ts = curve_parameters(&edge.curve, &edge_limits)?;
        let mut ids = Vec::with_capacity(ts.len());
        for (k, &t) in ts.iter().enumerate() {
            let id = if k == 0 {
                edge.vertices[0] as u32
            } else if k + 1 == ts.len() {
                edge.vertices[1] as u32
            } else {
                b.vertex(edge.curve.point_at(t))?
            };
            ids.push(id);
        }
        edge_divisions.push((ts, ids));
    }
    for f in 0..brep.faces().len() {
        mesh_face(brep, f, &edge_divisions, parameters, &mut b)?;
    }
    let face_triangles = std::mem::take(&mut b.face_triangles);
    Ok((b.finish()?, face_triangles))
}

/// Triangulates face `f` into the builder.
fn mesh_face(
    brep: &Brep,
    f: usize,
    edge_divisions: &[(Vec<f64>, Vec<u32>)],
    parameters: &MeshingParameters,
    b: &mut Builder,
) -> Result<()> {
    let face = &brep.faces()[f];
    let surface = &face.surface;
    let per_direction = MeshingParameters {
        max_chord_deviation: parameters.max_chord_deviation * SURFACE_CHORD_SHARE,
        ..*parameters
    };
    let us = surface_parameters(surface, SurfaceDirection::U, &per_direction)?;
    let vs = surface_parameters(surface, SurfaceDirection::V, &per_direction)?;
    if b.vertices.len() + us.len() * vs.len() > MAX_MESH_VERTICES {
        return Err(Error::InvalidInput(format!(
            "meshing would make more than {MAX_MESH_VERTICES} vertices; loosen the meshing \
             parameters"
        )));
    }

    let (du, dv) = (surface.domain_u(), surface.domain_v());
    // The loops as boundary points, each trim contributing its points but its last.
    let mut loops: Vec<Vec<LoopPoint>> = Vec::with_capacity(face.loops.len());
    for &l in &face.loops {
        let mut points = Vec::new();
        for &t in &brep.loops()[l].trims {
            let trim = &brep.trims()[t];
            let (s0, s1) = (trim.curve.domain().t0, trim.curve.domain().t1);
            // Points of a trim along a side of the parameter rectangle are put exactly on it,
            // so that rounding cannot make the rectangle's sides concave (and slivers form).
            let side = brep.trim_side(t);
            let uv_at = |s: f64| {
                let p = trim.curve.point_at(s);
                match side {
                    Some(SurfaceSide::South) => (p.x, dv.t0),
                    Some(SurfaceSide::North) => (p.x, dv.t1),
                    Some(SurfaceSide::West) => (du.t0, p.y),
                    Some(SurfaceSide::East) => (du.t1, p.y),
                    None => (p.x, p.y),
                }
            };
            match trim.edge {
                None => points.push(LoopPoint {
                    uv: uv_at(s0),
                    id: trim.vertices[0] as u32,
                }),
                Some(e) => {
                    let (ts, ids) = &edge_divisions[e];
                    let (t0, t1) = (ts[0], ts[ts.len() - 1]);
                    let n = ts.len();
                    for k in 0..n - 1 {
                        let j = if trim.reversed { n - 1 - k } else { k };
                        let frac = (ts[j] - t0) / (t1 - t0);
                        let s = if trim.reversed {
                            s0 + (1.0 - frac) * (s1 - s0)
                        } else {
                            s0 + frac * (s1 - s0)
                        };
                        points.push(LoopPoint {
                            uv: uv_at(s),
                            id: ids[j],
                        });
                    }
                }
            }
        }
        if points.len() >= 2 {
            loops.push(points);
        }
    }
    if loops.is_empty() {
        return Ok(());
    }

    // Scale the parameter plane by the mean speed of the surface in each direction.
    let speed = |dir: SurfaceDirection| -> f64 {
        let (along, across) = match dir {
            SurfaceDirection::U => (&us, &vs),
            SurfaceDirection::V => (&vs, &us),
        };
        let mut total = 0.0;
        for &c in thin_out(across, 9).iter() {
            for w in along.windows(2) {
                let (a, bb) = match dir {
                    SurfaceDirection::U => ((w[0], c), (w[1], c)),
                    SurfaceDirection::V => ((c, w[0]), (c, w[1])),
                };
                total += surface
                    .point_at(a.0, a.1)
                    .distance(surface.point_at(bb.0, bb.1));
            }
        }
        let span = match dir {
            SurfaceDirection::U => du.length(),
            SurfaceDirection::V => dv.length(),
        };
        let count = thin_out(across, 9).len() as f64;
        let s = total / (count * span);
        if s.is_finite() && s > 0.0 { s } else { 1.0 }
    };
    let (su, sv) = (speed(SurfaceDirection::U), speed(SurfaceDirection::V));
    let scaled = |uv: (f64, f64)| ((uv.0 - du.t0) * su, (uv.1 - dv.t0) * sv);
    let scaled_loops: Vec<Vec<(f64, f64)>> = loops
        .iter()
        .map(|l| l.iter().map(|p| scaled(p.uv)).collect())
        .collect();

    let untrimmed = brep.is_untrimmed(f);
    let mut cdt_vertices: Vec<UvVertex> = Vec::new();
    let mut constraints: Vec<[usize; 2]> = Vec::new();
    for (l, points) in loops.iter().enumerate() {
        let start = cdt_vertices.len();
        for (p, &q) in points.iter().zip(&scaled_loops[l]) {
            cdt_vertices.push(UvVertex {
                position: Point2::new(q.0, q.1),
                id: p.id,
                uv: [p.uv.0, p.uv.1],
            });
        }
        let n = points.len();
        for i in 0..n {
            constraints.push([start + i, start + (i + 1) % n]);
        }
    }

    // Interior grid nodes, clear of the boundary.
    let segments: Vec<((f64, f64), (f64, f64))> = scaled_loops
        .iter()
        .flat_map(|l| (0..l.len()).map(move |i| (l[i], l[(i + 1) % l.len()])))
        .collect();
    let mut interior_uv: Vec<(f64, f64)> = Vec::new();
    for i in 1..us.len().saturating_sub(1) {
        for j in 1..vs.len().saturating_sub(1) {
            let (u, v) = (us[i], vs[j]);
            if !untrimmed {
                let p = scaled((u, v));
                if !inside(p, &scaled_loops) {
                    continue;
                }
                let cell = ((us[i + 1] - us[i]).min(us[i] - us[i - 1]) * su)
                    .min((vs[j + 1] - vs[j]).min(vs[j] - vs[j - 1]) * sv);
                let clearance = BOUNDARY_CLEARANCE * cell;
                if segments
                    .iter()
                    .any(|&(a, c)| segment_distance(p, a, c) < clearance)
                {
                    continue;
                }
            }
            interior_uv.push((u, v));
        }
    }
    let sign = if face.reversed { -1.0 } else { 1.0 };
    for &(u, v) in &interior_uv {
        let id = b.vertex(surface.point_at(u, v))?;
        if let Ok(n) = surface.normal_at(u, v) {
            b.normal_sums[id as usize] = n * sign;
        }
        let q = scaled((u, v));
        cdt_vertices.push(UvVertex {
            position: Point2::new(q.0 + SHEAR * q.1, q.1),
            id,
            uv: [u, v],
        });
    }
    // Boundary vertices get the average of the normals of the faces they border.
    for points in &loops {
        for p in points {
            if let Ok(n) = surface.normal_at(p.uv.0, p.uv.1) {
                b.normal_sums[p.id as usize] += n * sign;
            }
        }
    }

    let mut crossing = false;
    let cdt = ConstrainedDelaunayTriangulation::<UvVertex>::try_bulk_load_cdt(
        cdt_vertices,
        constraints,
        |_| crossing = true,
    )
    .map_err(|e| Error::InvalidInput(format!("face {f} cannot be triangulated: {e:?}")))?;
    if crossing {
        return Err(Error::InvalidInput(format!(
            "the trims of face {f} cross each other in its parameter plane"
        )));
    }
    for triangle in cdt.inner_faces() {
        let [a, c, d] = triangle.vertices().map(|v| *v.data());
        let ids = [a.id, c.id, d.id];
        if ids[0] == ids[1] || ids[1] == ids[2] || ids[0] == ids[2] {
            continue;
        }
        if !untrimmed {
            let centroid = (
                (a.position.x + c.position.x + d.position.x) / 3.0,
                (a.position.y + c.position.y + d.position.y) / 3.0,
            );
            if !inside(centroid, &scaled_loops) {
                continue;
            }
        }
        if b.record {
            b.face_triangles.push(FaceTriangle {
                face: f,
                uv: [a.uv, c.uv, d.uv],
            });
        }
        // spade's faces are counter-clockwise in the (u, v) plane, i.e. along Su × Sv.
        b.faces.push(if face.reversed {
            MeshFace::triangle(ids[0], ids[2], ids[1])
        } else {
            MeshFace::triangle(ids[0], ids[1], ids[2])
        });
    }
    Ok(())
}

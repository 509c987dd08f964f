//! Geometry to display primitives: curves to polylines, surfaces and B-reps to meshes.
//!
//! The tolerances of [`Tessellation`] are display tolerances (how far a drawn polyline or mesh
//! may stray from the true geometry), not modelling tolerances.

use locus_kernel::{Brep, Curve, Mesh, MeshFace, NurbsSurface, Point3, SurfaceDirection};

/// How finely geometry is drawn.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Tessellation {
    /// The largest distance between a curve and its polyline, in model units.
    pub chord_tolerance: f64,
    /// Most segments of one curve (a bound for hostile or huge curves).
    pub max_segments: usize,
    /// Samples per span and direction of a surface.
    pub surface_samples_per_span: usize,
}

/// [`Tessellation::chord_tolerance`] by default: 0.01 model units.
pub const DEFAULT_CHORD_TOLERANCE: f64 = 0.01;
/// [`Tessellation::max_segments`] by default.
pub const DEFAULT_MAX_SEGMENTS: usize = 100_000;

impl Default for Tessellation {
    fn default() -> Self {
        Self {
            chord_tolerance: DEFAULT_CHORD_TOLERANCE,
            max_segments: DEFAULT_MAX_SEGMENTS,
            surface_samples_per_span: 8,
        }
    }
}

/// A curve as a polyline whose midpoints stray at most the chord tolerance from the curve:
/// each span is split in half until the curve's midpoint of each piece lies within the
/// tolerance of the chord (and at least four pieces per curved span, so that an S-shaped span
/// whose midpoint happens to lie on its chord is not drawn straight).
pub fn curve(curve: &Curve, settings: &Tessellation) -> Vec<Point3> {
    let nurbs = curve.to_nurbs();
    let breaks = nurbs.span_breaks();
    let linear = nurbs.degree() == 1;
    let tol = settings.chord_tolerance.max(1e-12);
    let mut points = vec![curve.point_at(breaks[0])];
    let budget = settings.max_segments.max(breaks.len());
    for w in breaks.windows(2) {
        let mut stack = vec![(w[0], w[1], 0u32)];
        // Depth-first, right half pushed first, so points come out in order.
        while let Some((a, b, depth)) = stack.pop() {
            let (pa, pb) = (curve.point_at(a), curve.point_at(b));
            let m = 0.5 * (a + b);
            let pm = curve.point_at(m);
            let chord_mid = pa + (pb - pa) * 0.5;
            let split = !linear
                && points.len() + stack.len() < budget
                && depth < 24
                && (depth < 2 || (pm - chord_mid).length() > tol);
            if split {
                stack.push((m, b, depth + 1));
                stack.push((a, m, depth + 1));
            } else {
                points.push(pb);
            }
        }
    }
    points
}

/// A surface as a mesh of quads on a grid of [`Tessellation::surface_samples_per_span`]
/// samples per span; quads that collapse at a singular side become triangles.
///
/// # Errors
/// When the surface cannot be evaluated.
pub fn surface(surface: &NurbsSurface, settings: &Tessellation) -> Result<Mesh, String> {
    let n = settings.surface_samples_per_span.max(1);
    let params = |dir| {
        let breaks = surface.span_breaks(dir);
        let mut ts = vec![breaks[0]];
        for w in breaks.windows(2) {
            for k in 1..=n {
                ts.push(w[0] + (w[1] - w[0]) * k as f64 / n as f64);
            }
        }
        ts
    };
    let (us, vs) = (params(SurfaceDirection::U), params(SurfaceDirection::V));
    let mut grid = vec![Point3::ORIGIN; us.len() * vs.len()];
    surface
        .points_on_grid(&us, &vs, &mut grid)
        .map_err(|e| e.to_string())?;
    let index = |i: usize, j: usize| (i * vs.len() + j) as u32;
    let mut faces = Vec::new();
    for i in 0..us.len() - 1 {
        for j in 0..vs.len() - 1 {
            let corners = [
                index(i, j),
                index(i + 1, j),
                index(i + 1, j + 1),
                index(i, j + 1),
            ];
            let mut distinct: Vec<u32> = Vec::with_capacity(4);
            for c in corners {
                let p = grid[c as usize];
                if !distinct.iter().any(|&d| grid[d as usize] == p) {
                    distinct.push(c);
                }
            }
            match distinct[..] {
                [a, b, c, d] => faces.push(MeshFace::quad(a, b, c, d)),
                [a, b, c] => faces.push(MeshFace::triangle(a, b, c)),
                _ => {}
            }
        }
    }
    Mesh::new(grid, faces)
        .map(Mesh::with_computed_normals)
        .map_err(|e| e.to_string())
}

/// A B-rep as one mesh of its faces.
///
/// # Errors
/// For a trimmed face other than a box side, which this interim mesher cannot yet draw.
pub fn brep(brep: &Brep, settings: &Tessellation) -> Result<Mesh, String> {
    let mut mesh = Mesh::default();
    for (f, face) in brep.faces().iter().enumerate() {
        if !brep.is_untrimmed(f) {
            return Err(format!("face {f} is trimmed"));
        }
        let mut face_mesh = surface(&face.surface, settings)?;
        if face.reversed {
            face_mesh = face_mesh.flipped();
        }
        mesh.append(&face_mesh);
    }
    Ok(mesh)
}

/// The edges of a B-rep as polylines.
pub fn brep_edges(brep: &Brep, settings: &Tessellation) -> Vec<Vec<Point3>> {
    brep.edges()
        .iter()
        .map(|e| curve(&Curve::from(e.curve.clone()), settings))
        .collect()
}

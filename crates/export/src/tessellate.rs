//! Geometry to display primitives through the kernel's tessellation: curves to polylines,
//! surfaces and B-reps to meshes (`locus_kernel::MeshingParameters`).

use locus_kernel::{Brep, Curve, Mesh, MeshingParameters, NurbsSurface, Point3};

/// How finely geometry is drawn: the kernel's meshing parameters (Rhino's spirit: maximum
/// angle, chord deviation, edge lengths) for surfaces, B-reps and curves alike.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct Tessellation {
    /// The meshing parameters; the default is the kernel's default.
    pub parameters: MeshingParameters,
}

/// A curve as a polyline within the meshing limits.
///
/// # Errors
/// The kernel's reason, e.g. for limits that would need too many points.
pub fn curve(curve: &Curve, settings: &Tessellation) -> Result<Vec<Point3>, String> {
    curve
        .to_polyline(&settings.parameters)
        .map(|p| p.points().to_vec())
        .map_err(|e| e.to_string())
}

/// A surface as a mesh.
///
/// # Errors
/// The kernel's reason.
pub fn surface(surface: &NurbsSurface, settings: &Tessellation) -> Result<Mesh, String> {
    Mesh::from_surface(surface, &settings.parameters).map_err(|e| e.to_string())
}

/// A B-rep as one mesh of its faces, closed where the B-rep is.
///
/// # Errors
/// The kernel's reason.
pub fn brep(brep: &Brep, settings: &Tessellation) -> Result<Mesh, String> {
    Mesh::from_brep(brep, &settings.parameters).map_err(|e| e.to_string())
}

/// The edges of a B-rep as polylines.
///
/// # Errors
/// As [`curve`].
pub fn brep_edges(brep: &Brep, settings: &Tessellation) -> Result<Vec<Vec<Point3>>, String> {
    brep.edges()
        .iter()
        .map(|e| curve(&Curve::from(e.curve.clone()), settings))
        .collect()
}

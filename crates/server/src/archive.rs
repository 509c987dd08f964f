//! The boundary to openNURBS archive JSON (`{"version", "archive3dm", "opennurbs", "data"}`,
//! what rhino3dm's `CommonObject.Encode`/`Decode` use) for curves, surfaces, B-reps and meshes.
//!
//! The archive reader and writer live in a crate of their own (being built on another branch).
//! Until it is part of the workspace, these functions refuse with a clear message; every other
//! module goes through them, so the crate plugs in here alone.

use locus_runtime::Value;
use serde_json::Value as Json;

/// The .NET type names Compute uses for archive-encoded geometry.
pub const ARCHIVE_TYPES: &[&str] = &[
    "Rhino.Geometry.Curve",
    "Rhino.Geometry.NurbsCurve",
    "Rhino.Geometry.PolylineCurve",
    "Rhino.Geometry.PolyCurve",
    "Rhino.Geometry.LineCurve",
    "Rhino.Geometry.ArcCurve",
    "Rhino.Geometry.Surface",
    "Rhino.Geometry.NurbsSurface",
    "Rhino.Geometry.Brep",
    "Rhino.Geometry.Extrusion",
    "Rhino.Geometry.Mesh",
    "Rhino.Geometry.SubD",
];

/// Encodes a curve, surface or B-rep as Compute's `(type, data)`.
///
/// # Errors
/// The reason the value cannot be written (for now: the archive writer is not built in).
pub fn encode(value: &Value) -> Result<(&'static str, String), String> {
    Err(format!(
        "a {} cannot be sent in Rhino.Compute form by this build yet (openNURBS archives are \
         not built in); use POST /v1/run for exact NURBS data",
        value.data_type().name()
    ))
}

/// Decodes archive JSON sent as an item of .NET type `type_name`.
///
/// # Errors
/// The reason the item cannot be read (for now: the archive reader is not built in).
pub fn decode(type_name: &str, _data: &Json) -> Result<Value, String> {
    Err(format!(
        "{type_name} items (openNURBS archives) cannot be read by this build yet"
    ))
}

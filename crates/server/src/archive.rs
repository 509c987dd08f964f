//! The boundary to openNURBS archive JSON (`{"version", "archive3dm", "opennurbs", "data"}`,
//! what rhino3dm's `CommonObject.Encode`/`Decode` use) for curves, surfaces, B-reps and meshes.
//!
//! The archive reader and writer are the `locus-opennurbs-archive` crate; every other module
//! goes through these two functions. Curves, NURBS surfaces, B-reps and meshes go both ways.

use locus_opennurbs_archive::{Geometry, decode_json, encode_json};
use locus_runtime::{Shared, Value};
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

/// Encodes a curve or surface as Compute's `(type, data)`: the RhinoCommon type name and the
/// CommonObject JSON as text.
///
/// # Errors
/// The reason the value cannot be written (B-reps, for now).
pub fn encode(value: &Value) -> Result<(&'static str, String), String> {
    let geometry = match value {
        Value::Curve(c) => Geometry::Curve((**c).clone()),
        Value::Surface(s) => Geometry::Surface((**s).clone()),
        Value::Brep(b) => Geometry::Brep((**b).clone()),
        Value::Mesh(m) => Geometry::Mesh((**m).clone()),
        other => {
            return Err(format!(
                "a {} is not archive geometry; POST /v1/run gives its exact data",
                other.data_type().name()
            ));
        }
    };
    let json = encode_json(&geometry).map_err(|e| format!("cannot write the archive: {e}"))?;
    Ok((geometry.rhino_type_name(), json.to_string()))
}

/// Decodes archive JSON sent as an item of .NET type `type_name`.
///
/// # Errors
/// The reason the item cannot be read, from the archive reader (class, byte) or for geometry
/// locus has no value type for.
pub fn decode(type_name: &str, data: &Json) -> Result<Value, String> {
    match decode_json(data) {
        Ok(Geometry::Curve(c)) => Ok(Value::Curve(Shared::new(c))),
        Ok(Geometry::Surface(s)) => Ok(Value::Surface(Shared::new(s))),
        Ok(Geometry::Brep(b)) => Ok(Value::Brep(Shared::new(b))),
        Ok(Geometry::Mesh(m)) => Ok(Value::Mesh(Shared::new(m))),
        Err(e) => Err(format!("a {type_name} item does not read: {e}")),
    }
}

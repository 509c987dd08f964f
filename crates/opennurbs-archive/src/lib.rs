//! openNURBS binary archives of single objects, as Rhino.Compute and rhino3dm exchange
//! geometry.
//!
//! rhino3dm's `CommonObject.Encode()` and RhinoCommon's `CommonObject.ToJSON` write one object
//! as JSON: `{"version": 10000, "archive3dm": 60, "opennurbs": <int>, "data": "<base64>"}`,
//! where `data` is an openNURBS binary archive holding that object alone and `archive3dm` and
//! `opennurbs` are the archive's 3dm and openNURBS versions (needed to read it). `Decode` reads
//! it back. [`encode_json`] and [`decode_json`] do the same for locus's geometry;
//! [`encode`] and [`decode`] are the binary level.
//!
//! # Layout
//! The archive is one *object record*, a tree of chunks (see [`binary`] for chunks, CRCs and
//! compressed buffers):
//!
//! ```text
//! TCODE_OPENNURBS_CLASS            length
//!   TCODE_OPENNURBS_CLASS_UUID     length  class id (16 bytes)           CRC-32
//!   TCODE_OPENNURBS_CLASS_DATA     length  what the class's Write wrote  CRC-32
//!   TCODE_OPENNURBS_CLASS_USERDATA length  ... (any number; skipped on read)
//!   TCODE_OPENNURBS_CLASS_END      0       (short chunk)
//! ```
//!
//! Class data starts with a version byte (`major·16 + minor`); the fields after it are those of
//! openNURBS's `Write` for the class, little-endian:
//! - `ON_Mesh` 3.8 ([`mesh`]): counts, texture domains, float bounding boxes, faces as four
//!   indices of 1, 2 or 4 bytes, float vertices, normals, texture coordinates, curvatures and
//!   colours as compressed buffers, a mapping tag, and the exact double-precision vertices in a
//!   chunk of their own;
//! - `ON_NurbsCurve` 1.1 and `ON_NurbsSurface` 1.0 ([`nurbs`]): dimension, rational flag,
//!   orders, control point counts, knots in Rhino's form (`|knots| = |points| + degree − 1`)
//!   and control points, *homogeneous* for rational geometry (`w·x, w·y, w·z, w`);
//! - `ON_LineCurve`, `ON_PolylineCurve`, `ON_ArcCurve` and `ON_PolyCurve` ([`curve`]).
//!
//! # What is supported
//! | class | write | read, as |
//! | --- | --- | --- |
//! | `ON_Mesh` | triangles and quads, normals, colours, double vertices | [`Mesh`] (texture coordinates, curvatures, n-gons are dropped) |
//! | `ON_NurbsCurve` | every [`Curve::Nurbs`] | [`Curve::Nurbs`] (2-D and 3-D) |
//! | `ON_LineCurve` | [`Curve::Line`] | [`Curve::Line`] |
//! | `ON_PolylineCurve` | [`Curve::Polyline`] (uniform parameters) | [`Curve::Polyline`], or a degree-1 [`Curve::Nurbs`] when its parameters are not uniform |
//! | `ON_ArcCurve` | [`Curve::Arc`], [`Curve::Circle`] | [`Curve::Arc`] or [`Curve::Circle`] |
//! | `ON_PolyCurve` | — | one [`Curve::Nurbs`]: the segments joined at a common degree |
//! | `ON_NurbsSurface` | [`NurbsSurface`] | [`NurbsSurface`] |
//!
//! Other classes (B-reps, extrusions, SubDs, points, annotations, ...) are reported as
//! [`Error::UnsupportedClass`] with their class id and name. User data is skipped on read and
//! never written. Archives of 3dm version 5 and older (4-byte chunk lengths) are refused.
//!
//! # Hostile input
//! Reading never panics and never allocates more than the input could hold: every length and
//! count is checked against the bytes left in its chunk before anything is read or reserved,
//! chunk nesting is bounded by [`binary::MAX_DEPTH`], every CRC is checked, deflated buffers
//! are inflated only up to their declared (and bounded) size, and the decoded geometry goes
//! through the kernel's validating constructors. Failures are [`Error`]s that say what was
//! wrong and at which byte.

pub mod binary;
pub mod curve;
mod error;
pub mod mesh;
pub mod nurbs;
mod object;
pub mod polycurve;

pub use crate::error::{Error, Result};
pub use crate::object::ClassId;

use base64::Engine as _;
pub use locus_kernel::{Curve, Mesh, NurbsSurface};
use serde_json::{Value, json};

/// The `version` field of CommonObject JSON (the serialisation's own version).
pub const JSON_VERSION: i64 = 10000;
/// The 3dm archive version that locus writes, as rhino3dm's `Encode` does (`archive3dm`).
pub const ARCHIVE_3DM_VERSION: i32 = 60;
/// The openNURBS version that locus writes (`opennurbs`): the value rhino3dm 8 writes for a
/// version-60 archive, an encoded version number that is negative as a signed `int`.
pub const OPENNURBS_VERSION: i64 = -1_869_833_980;

/// A piece of geometry that a CommonObject archive holds.
#[derive(Clone, Debug, PartialEq)]
pub enum Geometry {
    /// A polygon mesh (`ON_Mesh`).
    Mesh(Mesh),
    /// A curve (`ON_NurbsCurve`, `ON_LineCurve`, `ON_PolylineCurve`, `ON_ArcCurve`; a
    /// polycurve is read as one NURBS curve).
    Curve(Curve),
    /// A NURBS surface (`ON_NurbsSurface`).
    Surface(NurbsSurface),
}

impl Geometry {
    /// The RhinoCommon type that Compute names for this geometry (`Rhino.Geometry.Mesh`, ...).
    pub fn rhino_type_name(&self) -> &'static str {
        match self {
            Self::Mesh(_) => "Rhino.Geometry.Mesh",
            Self::Curve(Curve::Nurbs(_)) => "Rhino.Geometry.NurbsCurve",
            Self::Curve(Curve::Line { .. }) => "Rhino.Geometry.LineCurve",
            Self::Curve(Curve::Polyline { .. }) => "Rhino.Geometry.PolylineCurve",
            Self::Curve(Curve::Arc { .. } | Curve::Circle { .. }) => "Rhino.Geometry.ArcCurve",
            Self::Surface(_) => "Rhino.Geometry.NurbsSurface",
        }
    }
}

/// Versions an archive was written with, needed to read some version-dependent fields.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Versions {
    /// The 3dm archive version (`archive3dm`: 50, 60, 70, 80, ...).
    pub archive_3dm: i32,
    /// The openNURBS version (`opennurbs`), as an unsigned encoded number.
    pub opennurbs: u32,
}

impl Default for Versions {
    fn default() -> Self {
        Self {
            archive_3dm: ARCHIVE_3DM_VERSION,
            opennurbs: OPENNURBS_VERSION as u32,
        }
    }
}

/// Writes `geometry` as an openNURBS archive of one object (the bytes of `data`).
///
/// # Errors
/// [`Error::TooLarge`] when a count does not fit openNURBS's 32-bit `int`.
pub fn encode(geometry: &Geometry) -> Result<Vec<u8>> {
    let mut w = binary::Writer::new();
    object::write_object(&mut w, geometry)?;
    Ok(w.into_bytes())
}

/// Reads the object of an openNURBS archive written with [`Versions::default`] or similar.
///
/// # Errors
/// Any [`Error`]: damaged, truncated or hostile bytes, or a class locus does not read.
pub fn decode(data: &[u8]) -> Result<Geometry> {
    decode_with(data, Versions::default())
}

/// Reads the object of an openNURBS archive written with the given versions.
///
/// # Errors
/// As [`decode`], and [`Error::UnsupportedVersion`] for 3dm versions before 50.
pub fn decode_with(data: &[u8], versions: Versions) -> Result<Geometry> {
    if versions.archive_3dm < 50 {
        return Err(Error::UnsupportedVersion(versions.archive_3dm));
    }
    let mut r = binary::Reader::new(data);
    let g = object::read_object(&mut r, versions, 0)?;
    Ok(g)
}

/// Writes `geometry` as CommonObject JSON, as rhino3dm's `Encode` does.
///
/// # Errors
/// As [`encode`].
pub fn encode_json(geometry: &Geometry) -> Result<Value> {
    let data = encode(geometry)?;
    Ok(json!({
        "version": JSON_VERSION,
        "archive3dm": ARCHIVE_3DM_VERSION,
        "opennurbs": OPENNURBS_VERSION,
        "data": base64::engine::general_purpose::STANDARD.encode(data),
    }))
}

/// Reads CommonObject JSON, as rhino3dm's `Decode` does. `archive3dm` and `opennurbs` may be
/// numbers or numeric strings; a missing `opennurbs` means the current version.
///
/// # Errors
/// [`Error::Json`] for a missing or malformed field or bad base64, then as [`decode_with`].
pub fn decode_json(value: &Value) -> Result<Geometry> {
    let obj = value
        .as_object()
        .ok_or_else(|| Error::Json("CommonObject JSON must be an object".into()))?;
    let int = |key: &str| -> Result<Option<i64>> {
        match obj.get(key) {
            None | Some(Value::Null) => Ok(None),
            Some(Value::Number(n)) => n
                .as_i64()
                .map(Some)
                .ok_or_else(|| Error::Json(format!("`{key}` must be an integer, got {n}"))),
            Some(Value::String(s)) => s
                .trim()
                .parse()
                .map(Some)
                .map_err(|_| Error::Json(format!("`{key}` must be an integer, got {s:?}"))),
            Some(other) => Err(Error::Json(format!(
                "`{key}` must be an integer, got {other}"
            ))),
        }
    };
    let archive_3dm =
        int("archive3dm")?.ok_or_else(|| Error::Json("`archive3dm` is missing".into()))?;
    let archive_3dm = i32::try_from(archive_3dm)
        .map_err(|_| Error::Json(format!("`archive3dm` {archive_3dm} is out of range")))?;
    let opennurbs = match int("opennurbs")? {
        None => OPENNURBS_VERSION as u32,
        // The field is a C `int` holding an unsigned number: accept both readings.
        Some(v) if (i64::from(i32::MIN)..=i64::from(u32::MAX)).contains(&v) => v as u32,
        Some(v) => return Err(Error::Json(format!("`opennurbs` {v} is out of range"))),
    };
    let data = match obj.get("data") {
        Some(Value::String(s)) => s,
        Some(_) => return Err(Error::Json("`data` must be a base64 string".into())),
        None => return Err(Error::Json("`data` is missing".into())),
    };
    let bytes = base64::engine::general_purpose::STANDARD
        .decode(data.trim())
        .map_err(|e| Error::Json(format!("`data` is not base64: {e}")))?;
    decode_with(
        &bytes,
        Versions {
            archive_3dm,
            opennurbs,
        },
    )
}

//! Internalised Rhino geometry (`ON_Data` items): read into locus values, and written back.
//!
//! Grasshopper stores geometry internalised in a parameter as a byte array item `ON_Data`
//! (type code 20). Measured on the public corpus (`runxel__*.ghx`), the bytes are:
//!
//! 1. raw deflate (no zlib header) of
//! 2. a .NET BinaryFormatter stream (MS-NRBF) of the RhinoCommon object, whose
//!    `ISerializable` data are four members: `version` (10000), `archive3dm` (the 3dm
//!    version, 50 for Rhino 6), `opennurbs` (the openNURBS version) and `data` (a byte
//!    array), the same fields as RhinoCommon's CommonObject JSON; the stream may be followed
//!    by zero bytes (a buffer's unused capacity);
//! 3. `data` is an openNURBS archive of the one object, read by
//!    [`locus_opennurbs_archive`].
//!
//! The NRBF stream is read with the `nrbf` crate. That crate expands a record of *n* nulls
//! into *n* values without checking *n* against anything, so a 30-byte hostile stream could
//! ask for 2³¹ of them; and it can panic on an inconsistent multi-dimensional array. Before
//! handing the bytes over, [`decode`] therefore locates the byte array by the shape every
//! RhinoCommon payload has (it is the last record: `ArraySinglePrimitive` of bytes, then
//! `MessageEnd`), bounds the records before it to [`MAX_FRAME_BYTES`], refuses null records
//! there that ask for more nulls than the frame has bytes, and catches a panic. Every real
//! payload passes this (the frame holds no null records at all).
//!
//! Writing is the reverse, with the frame that RhinoCommon writes (checked byte for byte
//! against the corpus's payloads in the tests).

use std::io::Read;

use base64::Engine;
use flate2::Compression;
use flate2::read::DeflateDecoder;
use flate2::write::DeflateEncoder;
use locus_opennurbs_archive::{Geometry, Versions};
use locus_runtime::{Shared, Value};

/// The largest inflated payload read, in bytes (64 MiB, as [`crate::Limits`]'s longest string).
pub const MAX_PAYLOAD_BYTES: u64 = 64 << 20;

/// The most bytes of NRBF records before the geometry's byte array (real payloads have about
/// 200: the header, the library name, the class record and three integers).
pub const MAX_FRAME_BYTES: usize = 4096;

/// The library name written for RhinoCommon classes: the one Rhino 6 writes (every file of the
/// corpus has it, and Rhino 7 and 8 read those files).
pub const RHINOCOMMON_LIBRARY: &str =
    "RhinoCommon, Version=6.19.19295.1001, Culture=neutral, PublicKeyToken=552281e97c755530";

/// The serialisation's own `version` member.
const SERIALISATION_VERSION: i32 = 10000;

/// NRBF record types used here (MS-NRBF 2.1.2.1).
const RECORD_OBJECT_NULL_MULTIPLE: u8 = 0x0E;
const RECORD_ARRAY_SINGLE_PRIMITIVE: u8 = 0x0F;
const RECORD_MESSAGE_END: u8 = 0x0B;
/// `PrimitiveTypeEnumeration::Byte`.
const PRIMITIVE_BYTE: u8 = 2;

/// Reads an `ON_Data` item's bytes into a locus value (a curve, surface, B-rep or mesh).
///
/// # Errors
/// A sentence saying what was wrong: not deflate, not a RhinoCommon object, an openNURBS
/// class locus does not read, damaged bytes.
pub fn decode(compressed: &[u8]) -> Result<Value, String> {
    let mut stream = Vec::new();
    DeflateDecoder::new(compressed)
        .take(MAX_PAYLOAD_BYTES + 1)
        .read_to_end(&mut stream)
        .map_err(|e| format!("the bytes are not deflate data: {e}"))?;
    if stream.len() as u64 > MAX_PAYLOAD_BYTES {
        return Err(format!(
            "the payload inflates to more than {MAX_PAYLOAD_BYTES} bytes"
        ));
    }
    while stream.last() == Some(&0) {
        stream.pop();
    }
    let frame = frame_length(&stream)?;
    check_nulls(&stream[..frame])?;
    let parsed = std::panic::catch_unwind(|| nrbf::RemotingMessage::parse(&stream).map(fields));
    let (class, versions, data) = match parsed {
        Ok(Ok(Some(fields))) => fields,
        Ok(Ok(None)) => {
            return Err("the payload is not a RhinoCommon object with openNURBS data".to_owned());
        }
        Ok(Err(e)) => return Err(format!("the payload is not a .NET serialisation: {e}")),
        Err(_) => return Err("the payload's .NET serialisation is inconsistent".to_owned()),
    };
    let geometry = locus_opennurbs_archive::decode_with(&data, versions)
        .map_err(|e| format!("{class}: {e}"))?;
    Ok(match geometry {
        Geometry::Curve(c) => Value::Curve(Shared::new(c)),
        Geometry::Surface(s) => Value::Surface(Shared::new(s)),
        Geometry::Brep(b) => Value::Brep(Shared::new(b)),
        Geometry::Mesh(m) => Value::Mesh(Shared::new(m)),
    })
}

/// The class name, versions and openNURBS bytes of a RhinoCommon object.
fn fields(message: nrbf::RemotingMessage<'_>) -> Option<(String, Versions, Vec<u8>)> {
    let nrbf::RemotingMessage::Value(nrbf::Value::Object(object)) = message else {
        return None;
    };
    if !object.class.starts_with("Rhino.Geometry.") {
        return None;
    }
    let int = |name: &str| match object.members.get(name) {
        Some(nrbf::Value::Int32(i)) => Some(*i),
        _ => None,
    };
    let versions = Versions {
        archive_3dm: int("archive3dm")?,
        // A C `int` holding an unsigned number.
        opennurbs: int("opennurbs")? as u32,
    };
    let Some(nrbf::Value::Array(items)) = object.members.get("data") else {
        return None;
    };
    let data = items
        .iter()
        .map(|v| match v {
            nrbf::Value::Byte(b) => Some(*b),
            _ => None,
        })
        .collect::<Option<Vec<u8>>>()?;
    Some((object.class.to_owned(), versions, data))
}

/// How many bytes of records come before the byte array that ends the stream.
fn frame_length(stream: &[u8]) -> Result<usize, String> {
    let not_rhino = || "the payload is not a RhinoCommon object with openNURBS data".to_owned();
    let (&last, body) = stream.split_last().ok_or_else(not_rhino)?;
    if last != RECORD_MESSAGE_END {
        return Err(not_rhino());
    }
    // `ArraySinglePrimitive`: type, object id (4), length (4), primitive type, the items.
    (0..=body.len().min(MAX_FRAME_BYTES))
        .find(|&o| {
            let Some(head) = body.get(o..o + 10) else {
                return false;
            };
            let length = i32::from_le_bytes([head[5], head[6], head[7], head[8]]);
            head[0] == RECORD_ARRAY_SINGLE_PRIMITIVE
                && head[9] == PRIMITIVE_BYTE
                && usize::try_from(length).is_ok_and(|n| o + 10 + n == body.len())
        })
        .ok_or_else(not_rhino)
}

/// Refuses `ObjectNullMultiple` records (as far as a byte can be one) asking for more nulls
/// than the frame has bytes.
fn check_nulls(frame: &[u8]) -> Result<(), String> {
    for (k, w) in frame.windows(5).enumerate() {
        let count = i32::from_le_bytes([w[1], w[2], w[3], w[4]]);
        if w[0] == RECORD_OBJECT_NULL_MULTIPLE
            && usize::try_from(count).map_or(true, |n| n > frame.len())
        {
            return Err(format!(
                "the payload's .NET serialisation asks for {count} nulls at byte {k}, which no \
                 RhinoCommon object has"
            ));
        }
    }
    Ok(())
}

/// Writes a locus value as an `ON_Data` item's bytes, as Grasshopper does (`None` for values
/// that are not geometry openNURBS holds: curves, surfaces, B-reps and meshes).
///
/// # Errors
/// A sentence when the geometry does not fit an openNURBS archive.
pub fn encode(value: &Value) -> Option<Result<Vec<u8>, String>> {
    let geometry = match value {
        Value::Curve(c) => Geometry::Curve((**c).clone()),
        Value::Surface(s) => Geometry::Surface((**s).clone()),
        Value::Brep(b) => Geometry::Brep((**b).clone()),
        Value::Mesh(m) => Geometry::Mesh((**m).clone()),
        _ => return None,
    };
    let data = match locus_opennurbs_archive::encode(&geometry) {
        Ok(d) => d,
        Err(e) => return Some(Err(e.to_string())),
    };
    let versions = Versions::default();
    let stream = nrbf_stream(geometry.rhino_type_name(), versions, &data);
    let mut deflate = DeflateEncoder::new(Vec::new(), Compression::default());
    Some(
        std::io::Write::write_all(&mut deflate, &stream)
            .and_then(|()| deflate.finish())
            .map_err(|e| e.to_string()),
    )
}

/// The base64 text of [`encode`]'s bytes, as a `.ghx` holds it.
pub fn encode_base64(value: &Value) -> Option<Result<String, String>> {
    encode(value).map(|r| r.map(|b| base64::engine::general_purpose::STANDARD.encode(b)))
}

/// The NRBF stream RhinoCommon writes for one geometry object (MS-NRBF 2.6: a header, the
/// library, a class with members and types, the byte array, the end).
fn nrbf_stream(class: &str, versions: Versions, data: &[u8]) -> Vec<u8> {
    const LIBRARY_ID: i32 = 2;
    const OBJECT_ID: i32 = 1;
    const ARRAY_ID: i32 = 3;
    let mut s = Vec::with_capacity(data.len() + 256);
    let int = |s: &mut Vec<u8>, i: i32| s.extend_from_slice(&i.to_le_bytes());
    // SerializationHeaderRecord: root id, header id, major and minor version.
    s.push(0x00);
    for i in [OBJECT_ID, -1, 1, 0] {
        int(&mut s, i);
    }
    // BinaryLibrary.
    s.push(0x0C);
    int(&mut s, LIBRARY_ID);
    crate::binary::write_string(&mut s, RHINOCOMMON_LIBRARY);
    // ClassWithMembersAndTypes: three Int32 members and a Byte[].
    s.push(0x05);
    int(&mut s, OBJECT_ID);
    crate::binary::write_string(&mut s, class);
    int(&mut s, 4);
    for name in ["version", "archive3dm", "opennurbs", "data"] {
        crate::binary::write_string(&mut s, name);
    }
    // BinaryTypeEnumeration: Primitive ×3, PrimitiveArray; then Int32 ×3, Byte.
    s.extend_from_slice(&[0, 0, 0, 7, 8, 8, 8, PRIMITIVE_BYTE]);
    int(&mut s, LIBRARY_ID);
    int(&mut s, SERIALISATION_VERSION);
    int(&mut s, versions.archive_3dm);
    int(&mut s, versions.opennurbs as i32);
    // MemberReference to the array.
    s.push(0x09);
    int(&mut s, ARRAY_ID);
    s.push(RECORD_ARRAY_SINGLE_PRIMITIVE);
    int(&mut s, ARRAY_ID);
    int(&mut s, i32::try_from(data.len()).unwrap_or(i32::MAX));
    s.push(PRIMITIVE_BYTE);
    s.extend_from_slice(data);
    s.push(RECORD_MESSAGE_END);
    s
}

#[cfg(test)]
mod tests {
    use super::*;
    use locus_kernel::{Curve, Line, Point3};

    fn line() -> Value {
        Value::Curve(Shared::new(Curve::from(Line::new(
            Point3::new(0.0, 0.0, 0.0),
            Point3::new(1.0, 2.0, 3.0),
        ))))
    }

    #[test]
    fn written_geometry_reads_back() {
        let bytes = encode(&line()).expect("geometry").expect("encodes");
        assert_eq!(decode(&bytes), Ok(line()));
    }

    #[test]
    fn values_that_are_not_geometry_are_not_written() {
        assert!(encode(&Value::Number(1.0)).is_none());
    }

    fn deflate(bytes: &[u8]) -> Vec<u8> {
        let mut d = DeflateEncoder::new(Vec::new(), Compression::default());
        std::io::Write::write_all(&mut d, bytes).unwrap();
        d.finish().unwrap()
    }

    #[test]
    fn damaged_payloads_are_errors() {
        let stream = nrbf_stream(
            "Rhino.Geometry.LineCurve",
            Versions::default(),
            &[1, 2, 3, 4],
        );
        // Not deflate, empty, not NRBF, a truncated stream, trailing garbage, bad openNURBS.
        for bad in [
            vec![0xFF; 16],
            deflate(&[]),
            deflate(b"hello"),
            deflate(&stream[..stream.len() - 3]),
            deflate(&[stream.as_slice(), &[7, 7]].concat()),
            deflate(&stream),
        ] {
            let e = decode(&bad).expect_err("an error");
            assert!(!e.is_empty());
        }
        // Zero padding after the end is what Grasshopper's buffers hold.
        let padded = [stream.as_slice(), &[0; 64]].concat();
        assert!(decode(&deflate(&padded)).unwrap_err().contains("LineCurve"));
    }

    #[test]
    fn a_record_asking_for_billions_of_nulls_is_refused_before_parsing() {
        // A header, an ArraySingleObject of i32::MAX items, one ObjectNullMultiple of
        // i32::MAX nulls, then a byte array ending the stream.
        let mut s = vec![0x00];
        for i in [1i32, -1, 1, 0] {
            s.extend_from_slice(&i.to_le_bytes());
        }
        s.push(0x10);
        s.extend_from_slice(&1i32.to_le_bytes());
        s.extend_from_slice(&i32::MAX.to_le_bytes());
        s.push(RECORD_OBJECT_NULL_MULTIPLE);
        s.extend_from_slice(&i32::MAX.to_le_bytes());
        s.push(RECORD_ARRAY_SINGLE_PRIMITIVE);
        s.extend_from_slice(&2i32.to_le_bytes());
        s.extend_from_slice(&1i32.to_le_bytes());
        s.push(PRIMITIVE_BYTE);
        s.push(0);
        s.push(RECORD_MESSAGE_END);
        let e = decode(&deflate(&s)).expect_err("refused");
        assert!(e.contains("nulls"), "{e}");
    }

    #[test]
    fn every_prefix_and_byte_flip_of_a_payload_is_an_error_or_a_value() {
        let bytes = encode(&line()).unwrap().unwrap();
        let mut stream = Vec::new();
        DeflateDecoder::new(bytes.as_slice())
            .read_to_end(&mut stream)
            .unwrap();
        for n in 0..stream.len() {
            let _ = decode(&deflate(&stream[..n]));
        }
        for k in 0..stream.len() {
            let mut s = stream.clone();
            s[k] ^= 0xA5;
            let _ = decode(&deflate(&s));
        }
    }

    /// The `ON_Data` streams of a checked-in `.ghx` file (base64 of `<stream>` elements).
    fn corpus_payloads(name: &str) -> Vec<Vec<u8>> {
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("tests/data")
            .join(name);
        let text = std::fs::read_to_string(path).expect("a test file");
        text.split("name=\"ON_Data\"")
            .skip(1)
            .map(|rest| {
                let stream = rest.find("<stream").expect("a stream");
                let start = stream + rest[stream..].find('>').expect("a stream tag") + 1;
                let end = rest.find("</stream>").expect("a stream end");
                base64::engine::general_purpose::STANDARD
                    .decode(rest[start..end].trim())
                    .expect("base64")
            })
            .collect()
    }

    #[test]
    fn rhinocommon_payloads_of_the_corpus_read_and_are_written_back_byte_for_byte() {
        let mut count = 0;
        for (file, kind) in [
            ("runxel__calculate_curvature.ghx", "NURBS Curve"),
            ("runxel__crossing_lines_intensity.ghx", "Line Curve"),
            ("runxel__split_curve_into_regions.ghx", "NURBS Curve"),
        ] {
            for compressed in corpus_payloads(file) {
                let value = decode(&compressed).unwrap_or_else(|e| panic!("{file}: {e}"));
                let Value::Curve(c) = &value else {
                    panic!("{file}: {value:?}")
                };
                let found = match &**c {
                    Curve::Nurbs(_) => "NURBS Curve",
                    Curve::Line { .. } => "Line Curve",
                    _ => "another curve",
                };
                assert_eq!(found, kind, "{file}");
                // The stream Rhino 6 wrote, without its zero padding, is exactly the stream
                // this module writes for the same class, versions and openNURBS bytes.
                let mut stream = Vec::new();
                DeflateDecoder::new(compressed.as_slice())
                    .read_to_end(&mut stream)
                    .unwrap();
                while stream.last() == Some(&0) {
                    stream.pop();
                }
                let (class, versions, data) =
                    fields(nrbf::RemotingMessage::parse(&stream).unwrap())
                        .expect("a RhinoCommon object");
                assert_eq!(nrbf_stream(&class, versions, &data), stream, "{file}");
                count += 1;
            }
        }
        assert_eq!(count, 13);
    }

    #[test]
    fn lengths_are_written_in_seven_bit_groups() {
        let mut s = Vec::new();
        crate::binary::write_string(&mut s, &"a".repeat(200));
        assert_eq!(&s[..2], &[0xC8, 0x01]);
        assert_eq!(s.len(), 202);
    }
}

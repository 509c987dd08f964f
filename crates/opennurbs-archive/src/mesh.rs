//! `ON_Mesh` class data, version 3.8 (3dm version 60 and later).
//!
//! Field order (`ON_Mesh::Write`): vertex and face counts; packed texture and surface domains
//! and scale; float bounding boxes of vertices, normals and texture coordinates; a closed flag;
//! optional mesh parameters and curvature statistics (each in a chunk); faces as four vertex
//! indices of 1, 2 or 4 bytes (by vertex count), a triangle repeating its third index; then
//! compressed buffers of float vertices, float normals, texture coordinates, curvatures and
//! colours (`ON_Color`: red, green, blue and *transparency*, 0 = opaque); a texture rotation
//! flag, a mapping id, surface parameters, a mapping tag chunk, manifold/oriented/solid flags,
//! n-gons (a chunk), the double-precision vertices (a chunk) and their bounding box.
//!
//! locus writes the exact double-precision vertices as well as the float ones, so that
//! coordinates round-trip exactly; on read it takes the double ones when they agree with the
//! float ones (openNURBS's own rule), else the float ones.

use locus_kernel::{Color, Mesh, MeshFace, Point3, Vector3};

use crate::binary::{Reader, UNSET_VALUE, Writer, tcode};
use crate::{Error, Result, Versions};

/// The largest decompressed buffer a mesh may declare (256 MiB: about 11 million double
/// vertices), so that a small hostile archive cannot make the reader allocate gigabytes.
pub const MAX_BUFFER_BYTES: usize = 256 << 20;

/// The first openNURBS version whose meshes store a mapping tag (`ON_Mesh::Read`).
const MAPPING_TAG_VERSION: u32 = 200_606_010;

/// The largest `f32` not above `x` (`ON_FloatFloor`).
fn float_floor(x: f64) -> f32 {
    let f = x as f32;
    if f64::from(f) > x { f.next_down() } else { f }
}

/// The smallest `f32` not below `x` (`ON_FloatCeil`).
fn float_ceil(x: f64) -> f32 {
    let f = x as f32;
    if f64::from(f) < x { f.next_up() } else { f }
}

fn le_bytes_f32(values: impl Iterator<Item = f32>) -> Vec<u8> {
    values.flat_map(f32::to_le_bytes).collect()
}

/// Writes `ON_Mesh` class data.
///
/// # Errors
/// [`Error::TooLarge`] for counts above `i32::MAX` or buffers of 4 GiB or more.
pub fn write(w: &mut Writer, m: &Mesh) -> Result<()> {
    let vertices = m.vertices();
    let faces = m.faces();
    let n = vertices.len();
    w.version(3, 8);
    w.count(n)?;
    w.count(faces.len())?;
    // Packed texture domain and surface domain: unset; surface scale: 0.
    w.f64s(&[UNSET_VALUE; 8]);
    w.f64s(&[0.0, 0.0]);
    let bbox = (n > 0).then(|| m.bounding_box());
    match &bbox {
        Some(b) => {
            for x in [b.min.x, b.min.y, b.min.z] {
                w.f32(float_floor(x));
            }
            for x in [b.max.x, b.max.y, b.max.z] {
                w.f32(float_ceil(x));
            }
        }
        None => {
            for x in [1.0, 1.0, 1.0, -1.0, -1.0, -1.0] {
                w.f32(x);
            }
        }
    }
    // Normal and texture bounding boxes: empty (openNURBS recomputes them).
    for x in [1.0, 1.0, 1.0, -1.0, -1.0, -1.0, 1.0, 1.0, -1.0, -1.0] {
        w.f32(x);
    }
    w.i32(-1); // closed: unknown
    w.u8(0); // no mesh parameters
    for _ in 0..4 {
        w.u8(0); // no curvature statistics
    }
    // Faces.
    let index_size: i32 = if n < 256 {
        1
    } else if n < 65536 {
        2
    } else {
        4
    };
    w.i32(index_size);
    for f in faces {
        for &i in &f.vertices {
            match index_size {
                1 => w.u8(i as u8),
                2 => w.u16(i as u16),
                _ => w.u32(i),
            }
        }
    }
    if n > 0 {
        w.compressed_buffer(&le_bytes_f32(
            vertices
                .iter()
                .flat_map(|p| [p.x as f32, p.y as f32, p.z as f32]),
        ))?;
        match m.normals() {
            Some(normals) => w.compressed_buffer(&le_bytes_f32(
                normals
                    .iter()
                    .flat_map(|v| [v.x as f32, v.y as f32, v.z as f32]),
            ))?,
            None => w.compressed_buffer(&[])?,
        }
        w.compressed_buffer(&[])?; // texture coordinates
        w.compressed_buffer(&[])?; // curvatures
        match m.colors() {
            Some(colors) => {
                let bytes: Vec<u8> = colors
                    .iter()
                    .flat_map(|c| [c.r, c.g, c.b, 255 - c.a])
                    .collect();
                w.compressed_buffer(&bytes)?;
            }
            None => w.compressed_buffer(&[])?,
        }
    }
    w.i32(0); // packed texture rotation
    w.uuid(&[0; 16]); // texture mapping id
    if n > 0 {
        w.compressed_buffer(&[])?; // surface parameters
    }
    // Mapping tag 1.1: nil id, CRC 0, identity transform, mapping type 0.
    w.begin_versioned_chunk(tcode::ANONYMOUS_CHUNK, 1, 1);
    w.uuid(&[0; 16]);
    w.u32(0);
    for i in 0..4 {
        for j in 0..4 {
            w.f64(if i == j { 1.0 } else { 0.0 });
        }
    }
    w.i32(0);
    w.end_chunk();
    // Manifold, oriented, solid: unknown.
    w.u8(0);
    w.u8(0);
    w.u8(0);
    w.bool(false); // n-gons
    w.bool(n > 0); // double-precision vertices
    if n > 0 {
        w.begin_versioned_chunk(tcode::ANONYMOUS_CHUNK, 1, 0);
        w.count(n)?;
        let bytes: Vec<u8> = vertices
            .iter()
            .flat_map(|p| [p.x, p.y, p.z])
            .flat_map(f64::to_le_bytes)
            .collect();
        w.compressed_buffer(&bytes)?;
        w.end_chunk();
    }
    match &bbox {
        Some(b) => w.f64s(&[b.min.x, b.min.y, b.min.z, b.max.x, b.max.y, b.max.z]),
        None => w.f64s(&[UNSET_VALUE; 6]),
    }
    Ok(())
}

/// A compressed buffer of `n` items of `item` bytes each, or `None` when it is empty.
fn optional_buffer(
    r: &mut Reader<'_>,
    n: usize,
    item: usize,
    what: &'static str,
) -> Result<Option<Vec<u8>>> {
    let size = n
        .checked_mul(item)
        .filter(|&s| s <= MAX_BUFFER_BYTES)
        .ok_or_else(|| {
            Error::Invalid(format!(
                "{what}: {n} items exceed the limit of {MAX_BUFFER_BYTES} bytes"
            ))
        })?;
    let data = r.compressed_buffer(size, what)?;
    Ok((!data.is_empty()).then_some(data))
}

fn f32s(bytes: &[u8]) -> impl Iterator<Item = f32> + '_ {
    bytes
        .chunks_exact(4)
        .map(|b| f32::from_le_bytes([b[0], b[1], b[2], b[3]]))
}

/// Skips a chunk that a flag byte says is there.
fn skip_flagged_chunk(r: &mut Reader<'_>, what: &'static str) -> Result<()> {
    if r.u8(what)? != 0 {
        r.skip_chunk()?;
    }
    Ok(())
}

/// Reads `ON_Mesh` class data (version 3.x).
///
/// # Errors
/// [`Error::Invalid`] for a version other than 3.x, counts or index sizes openNURBS does not
/// write, or buffers of the wrong size; [`Error::Truncated`]/[`Error::Crc`] for damaged bytes;
/// [`Error::Geometry`] when the kernel refuses the mesh (e.g. a face index past the vertices).
pub fn read(r: &mut Reader<'_>, v: Versions) -> Result<Mesh> {
    let (major, minor) = r.version("ON_Mesh version")?;
    if major != 3 {
        return Err(Error::Invalid(format!(
            "ON_Mesh version {major}.{minor} is not supported (locus reads 3.x)"
        )));
    }
    let at = r.position();
    let n = r.i32("ON_Mesh vertex count")?;
    let nf = r.i32("ON_Mesh face count")?;
    let (Ok(n), Ok(nf)) = (usize::try_from(n), usize::try_from(nf)) else {
        return Err(Error::Invalid(format!(
            "ON_Mesh at byte {at} has {n} vertices and {nf} faces"
        )));
    };
    if n.saturating_mul(24) > MAX_BUFFER_BYTES {
        return Err(Error::Invalid(format!(
            "ON_Mesh has {n} vertices, more than the limit of {} ",
            MAX_BUFFER_BYTES / 24
        )));
    }
    r.skip(10 * 8, "ON_Mesh domains")?;
    r.skip(16 * 4, "ON_Mesh bounding boxes")?;
    r.i32("ON_Mesh closed flag")?;
    skip_flagged_chunk(r, "ON_Mesh mesh parameters")?;
    for _ in 0..4 {
        skip_flagged_chunk(r, "ON_Mesh curvature statistics")?;
    }
    let at = r.position();
    let index_size = r.i32("ON_Mesh face index size")?;
    let index_size = match index_size {
        1 | 2 | 4 => index_size as usize,
        s => {
            return Err(Error::Invalid(format!(
                "ON_Mesh face index size at byte {at} is {s}; openNURBS writes 1, 2 or 4"
            )));
        }
    };
    let raw = r.bytes(
        nf.checked_mul(4 * index_size).ok_or(Error::TooLarge(nf))?,
        "ON_Mesh faces",
    )?;
    let faces: Vec<MeshFace> = raw
        .chunks_exact(4 * index_size)
        .map(|f| MeshFace {
            vertices: std::array::from_fn(|k| {
                let b = &f[k * index_size..(k + 1) * index_size];
                match index_size {
                    1 => u32::from(b[0]),
                    2 => u32::from(u16::from_le_bytes([b[0], b[1]])),
                    _ => u32::from_le_bytes([b[0], b[1], b[2], b[3]]),
                }
            }),
        })
        .collect();
    let mut floats = None;
    let mut normals = None;
    let mut colors = None;
    if n > 0 {
        floats = optional_buffer(r, n, 12, "ON_Mesh vertices")?;
        normals = optional_buffer(r, n, 12, "ON_Mesh normals")?;
        optional_buffer(r, n, 8, "ON_Mesh texture coordinates")?;
        optional_buffer(r, n, 16, "ON_Mesh curvatures")?;
        colors = optional_buffer(r, n, 4, "ON_Mesh colours")?;
    }
    let mut doubles = None;
    if minor >= 2 {
        r.i32("ON_Mesh texture rotation")?;
    }
    if minor >= 3 {
        r.uuid("ON_Mesh mapping id")?;
        if n > 0 {
            optional_buffer(r, n, 16, "ON_Mesh surface parameters")?;
        }
        if minor >= 4 && v.opennurbs >= MAPPING_TAG_VERSION {
            r.skip_chunk()?; // mapping tag
            if minor >= 5 {
                r.skip(3, "ON_Mesh manifold flags")?;
                if minor >= 6 {
                    if r.bool("ON_Mesh n-gon flag")? {
                        r.skip_chunk()?;
                    }
                    if minor >= 7 && r.bool("ON_Mesh double vertex flag")? {
                        let (major, _) = r.begin_versioned_chunk("ON_Mesh double vertices")?;
                        if major != 1 {
                            return Err(Error::Invalid(format!(
                                "ON_Mesh double vertices version {major} is not supported"
                            )));
                        }
                        let count = r.i32("ON_Mesh double vertex count")?;
                        let count = usize::try_from(count).map_err(|_| {
                            Error::Invalid(format!("ON_Mesh double vertex count {count}"))
                        })?;
                        if count > 0 {
                            doubles = optional_buffer(r, count, 24, "ON_Mesh double vertices")?
                                .filter(|_| count == n);
                        }
                        r.end_chunk()?;
                    }
                    // minor 8: the double bounding box follows; not needed.
                }
            }
        }
    }
    let Some(floats) = floats.or_else(|| (n == 0).then(Vec::new)) else {
        return Err(Error::Invalid(
            "ON_Mesh has a vertex count but no vertices".into(),
        ));
    };
    let float_points: Vec<[f32; 3]> = f32s(&floats)
        .collect::<Vec<_>>()
        .chunks_exact(3)
        .map(|c| [c[0], c[1], c[2]])
        .collect();
    let vertices: Vec<Point3> = match doubles {
        Some(d) => {
            let dv: Vec<Point3> = d
                .chunks_exact(24)
                .map(|b| {
                    let x = |k: usize| {
                        f64::from_le_bytes(b[k * 8..k * 8 + 8].try_into().unwrap_or_default())
                    };
                    Point3::new(x(0), x(1), x(2))
                })
                .collect();
            // openNURBS keeps the doubles only when they agree with the floats.
            let agree = dv.iter().zip(&float_points).all(|(p, f)| {
                let m = f.iter().fold(0.0_f64, |a, &x| a.max(f64::from(x).abs()));
                let d = [p.x, p.y, p.z].iter().zip(f).fold(0.0_f64, |a, (&x, &y)| {
                    a.max((f64::from(x as f32) - f64::from(y)).abs())
                });
                d <= m * 1e-6
            });
            if agree {
                dv
            } else {
                floats_to_points(&float_points)
            }
        }
        None => floats_to_points(&float_points),
    };
    let geometry = |source| Error::Geometry {
        what: "ON_Mesh",
        source,
    };
    let mut mesh = Mesh::new(vertices, faces).map_err(geometry)?;
    if let Some(nb) = normals {
        let ns: Vec<Vector3> = f32s(&nb)
            .collect::<Vec<_>>()
            .chunks_exact(3)
            .map(|c| Vector3::new(c[0].into(), c[1].into(), c[2].into()))
            .collect();
        mesh = mesh.with_normals(ns).map_err(geometry)?;
    }
    if let Some(cb) = colors {
        let cs = cb
            .chunks_exact(4)
            .map(|c| Color::rgba(c[0], c[1], c[2], 255 - c[3]))
            .collect();
        mesh = mesh.with_colors(cs).map_err(geometry)?;
    }
    Ok(mesh)
}

fn floats_to_points(f: &[[f32; 3]]) -> Vec<Point3> {
    f.iter()
        .map(|c| Point3::new(c[0].into(), c[1].into(), c[2].into()))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn float_floor_and_ceil_bracket_the_double() {
        for x in [0.1, -0.1, 1.0, 1e10 + 0.3, -3.7e-5] {
            assert!(f64::from(float_floor(x)) <= x && f64::from(float_ceil(x)) >= x);
        }
    }
}

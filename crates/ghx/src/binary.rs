//! The binary form of a GH_IO archive (`.gh` files and the `ClusterDocument` of clusters):
//! raw deflate around a stream of chunks.
//!
//! Layout (little-endian throughout, strings as .NET writes them: a 7-bit variable-length byte
//! count, then UTF-8):
//!
//! ```text
//! chunk := name:string  index:i32 (−1 = none)  item_count:i32  chunk_count:i32
//!          item × item_count  chunk × chunk_count
//! item  := name:string  index:i32 (−1 = none)  type_code:i32  value
//! ```
//!
//! Values are fixed-size records (bool 1 byte, int32 4, double 8, GUID 16 in .NET's byte order,
//! point3d 3 doubles, plane 9 doubles, colour one ARGB int32, …), strings as above, byte arrays
//! and bitmaps an int32 length and the bytes, decimals .NET's 16-byte form.

use std::io::Read;

use flate2::read::DeflateDecoder;

use crate::archive::{Chunk, Item, Value};
use crate::error::ArchiveError;
use crate::limits::Limits;

/// Inflates raw-deflate data and reads the binary archive in it. `cluster_depth` is how many
/// clusters this archive is nested in (0 for a file).
pub fn read_compressed(
    bytes: &[u8],
    limits: &Limits,
    cluster_depth: usize,
) -> Result<Chunk, ArchiveError> {
    if bytes.len() > limits.max_file_bytes {
        return Err(ArchiveError::FileTooLarge {
            size: bytes.len(),
            limit: limits.max_file_bytes,
        });
    }
    let context = if cluster_depth == 0 {
        "file".to_owned()
    } else {
        format!("cluster at depth {cluster_depth}")
    };
    let data = inflate(bytes, limits, &context)?;
    let root = read_binary(&data, limits)?;
    // A file's root chunk is "Root"; a cluster's is "Document".
    let expected = if cluster_depth == 0 {
        "Root"
    } else {
        "Document"
    };
    if root.name != expected {
        return Err(ArchiveError::Bad {
            path: root.name,
            reason: format!("not a Grasshopper archive (the root chunk is not \"{expected}\")"),
        });
    }
    Ok(root)
}

/// Inflates raw deflate data within the size and ratio bounds of `limits`.
pub fn inflate(bytes: &[u8], limits: &Limits, context: &str) -> Result<Vec<u8>, ArchiveError> {
    let by_ratio = bytes
        .len()
        .saturating_mul(limits.max_ratio)
        .max(limits.ratio_free_bytes);
    let limit = by_ratio.min(limits.max_decompressed_bytes);
    let mut out = Vec::with_capacity(bytes.len().saturating_mul(4).min(limit));
    let mut decoder = DeflateDecoder::new(bytes).take(limit as u64 + 1);
    decoder
        .read_to_end(&mut out)
        .map_err(|e| ArchiveError::Deflate {
            context: context.to_owned(),
            reason: e.to_string(),
        })?;
    if out.len() > limit {
        return Err(ArchiveError::Bomb {
            context: context.to_owned(),
            compressed: bytes.len(),
            limit,
        });
    }
    if out.is_empty() {
        return Err(ArchiveError::Deflate {
            context: context.to_owned(),
            reason: "no data".to_owned(),
        });
    }
    Ok(out)
}

/// Reads an uncompressed binary archive: its root chunk and everything in it, which must
/// fill the data exactly.
pub fn read_binary(data: &[u8], limits: &Limits) -> Result<Chunk, ArchiveError> {
    let mut reader = Reader {
        data,
        pos: 0,
        limits,
        path: Vec::new(),
        entries: 0,
    };
    let root = reader.chunk()?;
    if reader.pos != data.len() {
        return Err(ArchiveError::Bad {
            path: root.name,
            reason: format!(
                "{} bytes after the end of the root chunk",
                data.len() - reader.pos
            ),
        });
    }
    Ok(root)
}

struct Reader<'a> {
    data: &'a [u8],
    pos: usize,
    limits: &'a Limits,
    path: Vec<String>,
    entries: usize,
}

impl Reader<'_> {
    fn path(&self) -> String {
        if self.path.is_empty() {
            "archive".to_owned()
        } else {
            self.path.join("/")
        }
    }

    fn take(&mut self, n: usize, what: &str) -> Result<&[u8], ArchiveError> {
        match self.pos.checked_add(n) {
            Some(end) if end <= self.data.len() => {
                let s = &self.data[self.pos..end];
                self.pos = end;
                Ok(s)
            }
            _ => Err(ArchiveError::Truncated {
                path: self.path(),
                offset: self.data.len(),
                what: what.to_owned(),
            }),
        }
    }

    fn array<const N: usize>(&mut self, what: &str) -> Result<[u8; N], ArchiveError> {
        let s = self.take(N, what)?;
        let mut a = [0; N];
        a.copy_from_slice(s);
        Ok(a)
    }

    fn i32(&mut self, what: &str) -> Result<i32, ArchiveError> {
        Ok(i32::from_le_bytes(self.array(what)?))
    }

    fn f32(&mut self, what: &str) -> Result<f32, ArchiveError> {
        Ok(f32::from_le_bytes(self.array(what)?))
    }

    fn f64(&mut self, what: &str) -> Result<f64, ArchiveError> {
        Ok(f64::from_le_bytes(self.array(what)?))
    }

    fn f64s<const N: usize>(&mut self, what: &str) -> Result<[f64; N], ArchiveError> {
        let mut a = [0.0; N];
        for v in &mut a {
            *v = self.f64(what)?;
        }
        Ok(a)
    }

    /// A count that must be non-negative and fit in what is left of the data
    /// (`min_size` bytes per element at least).
    fn count(&mut self, what: &str, min_size: usize) -> Result<usize, ArchiveError> {
        let n = self.i32(what)?;
        let left = self.data.len() - self.pos;
        match usize::try_from(n) {
            Ok(n) if n.saturating_mul(min_size) <= left => Ok(n),
            Ok(n) => Err(ArchiveError::Bad {
                path: self.path(),
                reason: format!(
                    "{what} is {n}, more than the {left} bytes left in the archive can hold"
                ),
            }),
            Err(_) => Err(ArchiveError::Bad {
                path: self.path(),
                reason: format!("{what} is negative ({n})"),
            }),
        }
    }

    fn string(&mut self, what: &str) -> Result<String, ArchiveError> {
        // .NET's 7-bit encoded length: at most five bytes.
        let mut len: u64 = 0;
        for shift in 0..5 {
            let b = self.array::<1>(what)?[0];
            len |= u64::from(b & 0x7f) << (7 * shift);
            if b & 0x80 == 0 {
                break;
            }
            if shift == 4 {
                return Err(ArchiveError::Bad {
                    path: self.path(),
                    reason: format!("the length of {what} is malformed"),
                });
            }
        }
        let len = self.byte_len(len, what)?;
        let bytes = self.take(len, what)?;
        String::from_utf8(bytes.to_vec()).map_err(|_| ArchiveError::Bad {
            path: self.path(),
            reason: format!("{what} is not UTF-8"),
        })
    }

    fn byte_len(&self, len: u64, what: &str) -> Result<usize, ArchiveError> {
        if len > self.limits.max_string_bytes as u64 {
            return Err(ArchiveError::TooMany {
                path: self.path(),
                what: format!("the length of {what} ({len} bytes)"),
                limit: self.limits.max_string_bytes,
            });
        }
        Ok(len as usize)
    }

    fn bytes(&mut self, what: &str) -> Result<Vec<u8>, ArchiveError> {
        let n = self.i32(what)?;
        let n = u64::try_from(n).map_err(|_| ArchiveError::Bad {
            path: self.path(),
            reason: format!("the length of {what} is negative ({n})"),
        })?;
        let n = self.byte_len(n, what)?;
        Ok(self.take(n, what)?.to_vec())
    }

    fn index(&mut self, what: &str) -> Result<Option<i32>, ArchiveError> {
        let i = self.i32(what)?;
        Ok((i >= 0).then_some(i))
    }

    fn count_entry(&mut self) -> Result<(), ArchiveError> {
        self.entries += 1;
        if self.entries > self.limits.max_entries {
            return Err(ArchiveError::TooMany {
                path: self.path(),
                what: "the number of chunks and items".to_owned(),
                limit: self.limits.max_entries,
            });
        }
        Ok(())
    }

    fn chunk(&mut self) -> Result<Chunk, ArchiveError> {
        if self.path.len() >= self.limits.max_depth {
            return Err(ArchiveError::TooDeep {
                path: self.path(),
                limit: self.limits.max_depth,
            });
        }
        self.count_entry()?;
        let name = self.string("a chunk name")?;
        let index = self.index("a chunk index")?;
        self.path.push(match index {
            Some(i) => format!("{name}[{i}]"),
            None => name.clone(),
        });
        // An item takes at least 10 bytes (name length, index, type code, one byte of
        // value); a chunk at least 13.
        let item_count = self.count("the item count", 10)?;
        let chunk_count = self.count("the chunk count", 13)?;
        let mut items = Vec::with_capacity(item_count.min(1024));
        for _ in 0..item_count {
            items.push(self.item()?);
        }
        let mut chunks = Vec::with_capacity(chunk_count.min(1024));
        for _ in 0..chunk_count {
            chunks.push(self.chunk()?);
        }
        self.path.pop();
        Ok(Chunk {
            name,
            index,
            items,
            chunks,
        })
    }

    fn item(&mut self) -> Result<Item, ArchiveError> {
        self.count_entry()?;
        let name = self.string("an item name")?;
        let index = self.index("an item index")?;
        let code = self.i32("an item type")?;
        let what = format!("item {name}");
        let value = match code {
            1 => Value::Bool(self.array::<1>(&what)?[0] != 0),
            2 => Value::Byte(self.array::<1>(&what)?[0]),
            3 => Value::Int32(self.i32(&what)?),
            4 => Value::Int64(i64::from_le_bytes(self.array(&what)?)),
            5 => Value::Single(self.f32(&what)?),
            6 => Value::Double(self.f64(&what)?),
            7 => Value::Decimal(decimal(self.array(&what)?)),
            8 => Value::Date(i64::from_le_bytes(self.array(&what)?)),
            9 => Value::Guid(guid_text(&self.array(&what)?)),
            10 => Value::String(self.string(&what)?),
            20 => Value::Bytes(self.bytes(&what)?),
            21 => {
                let n = self.count(&format!("the length of {what}"), 8)?;
                let mut v = Vec::with_capacity(n);
                for _ in 0..n {
                    v.push(self.f64(&what)?);
                }
                Value::Doubles(v)
            }
            30 => Value::DrawingPoint([self.i32(&what)?, self.i32(&what)?]),
            31 => Value::DrawingPointF([self.f32(&what)?, self.f32(&what)?]),
            32 => Value::DrawingSize([self.i32(&what)?, self.i32(&what)?]),
            33 => Value::DrawingSizeF([self.f32(&what)?, self.f32(&what)?]),
            34 => Value::DrawingRectangle([
                self.i32(&what)?,
                self.i32(&what)?,
                self.i32(&what)?,
                self.i32(&what)?,
            ]),
            35 => Value::DrawingRectangleF([
                self.f32(&what)?,
                self.f32(&what)?,
                self.f32(&what)?,
                self.f32(&what)?,
            ]),
            36 => {
                let argb = u32::from_le_bytes(self.array(&what)?);
                Value::Color(argb.to_be_bytes())
            }
            37 => Value::Bitmap(self.bytes(&what)?),
            50 => Value::Point2(self.f64s(&what)?),
            51 => Value::Point3(self.f64s(&what)?),
            52 => Value::Point4(self.f64s(&what)?),
            60 => Value::Interval(self.f64s(&what)?),
            61 => Value::Interval2(self.f64s(&what)?),
            70 => Value::Line(self.f64s(&what)?),
            71 => Value::BoundingBox(self.f64s(&what)?),
            72 => Value::Plane(self.f64s(&what)?),
            80 => Value::Version([self.i32(&what)?, self.i32(&what)?, self.i32(&what)?]),
            _ => {
                return Err(ArchiveError::Bad {
                    path: format!("{}/{name}", self.path()),
                    reason: format!("unknown item type code {code}"),
                });
            }
        };
        Ok(Item { name, index, value })
    }
}

/// Writes a chunk as an uncompressed binary archive, the inverse of [`read_binary`]: every
/// chunk and item in order, each value in its type's fixed layout. Decimals are written as the
/// shortest decimal that reads back as the same double; a GUID that is not GUID text is
/// written as the nil GUID.
pub fn write_binary(root: &Chunk) -> Vec<u8> {
    let mut out = Vec::new();
    write_chunk(&mut out, root);
    out
}

/// Writes a chunk as a raw-deflate-compressed binary archive (the form of `.gh` files and of
/// a cluster's `ClusterDocument`).
pub fn write_compressed(root: &Chunk) -> Vec<u8> {
    use flate2::{Compression, write::DeflateEncoder};
    use std::io::Write;
    let mut e = DeflateEncoder::new(Vec::new(), Compression::default());
    // Writing into memory cannot fail.
    let _ = e.write_all(&write_binary(root));
    e.finish().unwrap_or_default()
}

/// A string as .NET's `BinaryWriter` writes it (and MS-NRBF's `LengthPrefixedString`): the
/// UTF-8 length in 7-bit groups, low group first, then the bytes.
pub(crate) fn write_string(out: &mut Vec<u8>, s: &str) {
    let mut n = s.len();
    loop {
        let b = (n & 0x7f) as u8;
        n >>= 7;
        if n == 0 {
            out.push(b);
            break;
        }
        out.push(b | 0x80);
    }
    out.extend_from_slice(s.as_bytes());
}

fn write_index(out: &mut Vec<u8>, index: Option<i32>) {
    out.extend(index.unwrap_or(-1).to_le_bytes());
}

fn write_len(out: &mut Vec<u8>, n: usize) {
    out.extend(i32::try_from(n).unwrap_or(i32::MAX).to_le_bytes());
}

fn write_chunk(out: &mut Vec<u8>, chunk: &Chunk) {
    write_string(out, &chunk.name);
    write_index(out, chunk.index);
    write_len(out, chunk.items.len());
    write_len(out, chunk.chunks.len());
    for item in &chunk.items {
        write_item(out, item);
    }
    for c in &chunk.chunks {
        write_chunk(out, c);
    }
}

fn write_item(out: &mut Vec<u8>, item: &Item) {
    write_string(out, &item.name);
    write_index(out, item.index);
    out.extend(item.value.type_code().to_le_bytes());
    let f64s = |out: &mut Vec<u8>, v: &[f64]| v.iter().for_each(|x| out.extend(x.to_le_bytes()));
    let i32s = |out: &mut Vec<u8>, v: &[i32]| v.iter().for_each(|x| out.extend(x.to_le_bytes()));
    let f32s = |out: &mut Vec<u8>, v: &[f32]| v.iter().for_each(|x| out.extend(x.to_le_bytes()));
    match &item.value {
        Value::Bool(b) => out.push(u8::from(*b)),
        Value::Byte(b) => out.push(*b),
        Value::Int32(v) => out.extend(v.to_le_bytes()),
        Value::Int64(v) | Value::Date(v) => out.extend(v.to_le_bytes()),
        Value::Single(v) => out.extend(v.to_le_bytes()),
        Value::Double(v) => out.extend(v.to_le_bytes()),
        Value::Decimal(v) => out.extend(decimal_bytes(*v)),
        Value::Guid(g) => out.extend(guid_bytes(g).unwrap_or([0; 16])),
        Value::String(s) => write_string(out, s),
        Value::Bytes(b) | Value::Bitmap(b) => {
            write_len(out, b.len());
            out.extend_from_slice(b);
        }
        Value::Doubles(v) => {
            write_len(out, v.len());
            f64s(out, v);
        }
        Value::DrawingPoint(v) | Value::DrawingSize(v) => i32s(out, v),
        Value::DrawingPointF(v) | Value::DrawingSizeF(v) => f32s(out, v),
        Value::DrawingRectangle(v) => i32s(out, v),
        Value::DrawingRectangleF(v) => f32s(out, v),
        Value::Color(argb) => out.extend(u32::from_be_bytes(*argb).to_le_bytes()),
        Value::Point2(v) => f64s(out, v),
        Value::Point3(v) => f64s(out, v),
        Value::Point4(v) | Value::Interval2(v) => f64s(out, v),
        Value::Interval(v) => f64s(out, v),
        Value::Line(v) | Value::BoundingBox(v) => f64s(out, v),
        Value::Plane(v) => f64s(out, v),
        Value::Version(v) => i32s(out, v),
    }
}

/// GUID text in .NET's `Guid.ToByteArray` order (see [`guid_text`]).
pub(crate) fn guid_bytes(text: &str) -> Option<[u8; 16]> {
    let hex: Vec<u8> = text.bytes().filter(|&b| b != b'-').collect();
    if hex.len() != 32 || text.len() != 36 {
        return None;
    }
    let mut raw = [0u8; 16];
    for (k, pair) in hex.chunks(2).enumerate() {
        let pair = std::str::from_utf8(pair).ok()?;
        raw[k] = u8::from_str_radix(pair, 16).ok()?;
    }
    let mut b = raw;
    b[0..4].copy_from_slice(&[raw[3], raw[2], raw[1], raw[0]]);
    b[4..6].copy_from_slice(&[raw[5], raw[4]]);
    b[6..8].copy_from_slice(&[raw[7], raw[6]]);
    Some(b)
}

/// A double as .NET's 16-byte decimal: the shortest decimal digits that read back as the same
/// double, as a 96-bit integer and a scale (at most 28). Values a decimal cannot hold (not
/// finite, or beyond its range) are written as zero.
fn decimal_bytes(x: f64) -> [u8; 16] {
    let mut b = [0u8; 16];
    if !x.is_finite() {
        return b;
    }
    let text = format!("{:e}", x.abs());
    let (digits, exponent) = text.split_once('e').unwrap_or((&text, "0"));
    let exponent: i32 = exponent.parse().unwrap_or(0);
    let (whole, fraction) = digits.split_once('.').unwrap_or((digits, ""));
    let all = format!("{whole}{fraction}");
    // value = all × 10^(exponent − fraction digits)
    let mut power = exponent - fraction.len() as i32;
    let mut mantissa: u128 = all.parse().unwrap_or(0);
    while power > 0 && mantissa < (1u128 << 96) {
        mantissa *= 10;
        power -= 1;
    }
    if power > 0 || mantissa >= (1u128 << 96) || -power > 28 {
        return b;
    }
    let scale = (-power) as u32;
    b[0..12].copy_from_slice(&mantissa.to_le_bytes()[0..12]);
    let sign = if x.is_sign_negative() && mantissa != 0 {
        0x8000_0000
    } else {
        0
    };
    b[12..16].copy_from_slice(&((scale << 16) | sign).to_le_bytes());
    b
}

/// .NET's `Guid.ToByteArray` order: the first three fields little-endian, the rest as is.
pub(crate) fn guid_text(b: &[u8; 16]) -> String {
    format!(
        "{:02x}{:02x}{:02x}{:02x}-{:02x}{:02x}-{:02x}{:02x}-{:02x}{:02x}-{:02x}{:02x}{:02x}{:02x}{:02x}{:02x}",
        b[3],
        b[2],
        b[1],
        b[0],
        b[5],
        b[4],
        b[7],
        b[6],
        b[8],
        b[9],
        b[10],
        b[11],
        b[12],
        b[13],
        b[14],
        b[15]
    )
}

/// .NET's 16-byte decimal: a 96-bit integer (lo, mid, hi) and a flags word holding the scale
/// (bits 16–23) and the sign (bit 31), to the nearest double.
fn decimal(b: [u8; 16]) -> f64 {
    let word = |i: usize| u32::from_le_bytes([b[i], b[i + 1], b[i + 2], b[i + 3]]);
    let (lo, mid, hi, flags) = (word(0), word(4), word(8), word(12));
    let mantissa = (u128::from(hi) << 64) | (u128::from(mid) << 32) | u128::from(lo);
    let scale = ((flags >> 16) & 0xff).min(28) as i32;
    let value = mantissa as f64 / 10f64.powi(scale);
    if flags & 0x8000_0000 != 0 {
        -value
    } else {
        value
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn guids_read_in_dotnet_byte_order() {
        let bytes = [
            0x33, 0x22, 0x11, 0x00, 0x55, 0x44, 0x77, 0x66, 0x88, 0x99, 0xaa, 0xbb, 0xcc, 0xdd,
            0xee, 0xff,
        ];
        assert_eq!(guid_text(&bytes), "00112233-4455-6677-8899-aabbccddeeff");
    }

    #[test]
    fn decimals_keep_scale_and_sign() {
        let mut b = [0u8; 16];
        b[0..4].copy_from_slice(&642u32.to_le_bytes());
        b[12..16].copy_from_slice(&(2u32 << 16).to_le_bytes());
        assert_eq!(decimal(b), 6.42);
        b[15] |= 0x80;
        assert_eq!(decimal(b), -6.42);
    }

    #[test]
    fn a_zip_bomb_is_refused() {
        use flate2::{Compression, write::DeflateEncoder};
        use std::io::Write;
        let mut e = DeflateEncoder::new(Vec::new(), Compression::best());
        e.write_all(&vec![0u8; 64 << 20]).unwrap();
        let bomb = e.finish().unwrap();
        let err = read_compressed(&bomb, &Limits::default(), 0).unwrap_err();
        assert!(matches!(err, ArchiveError::Bomb { .. }), "{err}");
        assert!(err.to_string().contains("zip bomb"), "{err}");
    }

    #[test]
    fn huge_declared_counts_and_lengths_are_errors_not_allocations() {
        // "Root", index −1, 2^31−1 items.
        let mut data = vec![4, b'R', b'o', b'o', b't'];
        data.extend((-1i32).to_le_bytes());
        data.extend(i32::MAX.to_le_bytes());
        data.extend(0i32.to_le_bytes());
        let err = read_binary(&data, &Limits::default()).unwrap_err();
        assert!(
            err.to_string().contains("the item count is 2147483647"),
            "{err}"
        );
        // A name claiming 2 GB.
        let data = [0xff, 0xff, 0xff, 0xff, 0x07, b'R'];
        let err = read_binary(&data, &Limits::default()).unwrap_err();
        assert!(matches!(err, ArchiveError::TooMany { .. }), "{err}");
    }

    #[test]
    fn deep_nesting_is_refused() {
        // Each chunk "c", index −1, no items, one chunk: nested forever (until the data ends).
        let mut data = vec![4, b'R', b'o', b'o', b't'];
        let level = |d: &mut Vec<u8>| {
            d.extend((-1i32).to_le_bytes());
            d.extend(0i32.to_le_bytes());
            d.extend(1i32.to_le_bytes());
        };
        level(&mut data);
        for _ in 0..100 {
            data.extend([1, b'c']);
            level(&mut data);
        }
        data.extend(vec![0; 13 * 2]);
        let err = read_binary(&data, &Limits::default()).unwrap_err();
        assert!(
            matches!(err, ArchiveError::TooDeep { limit: 64, .. }),
            "{err}"
        );
    }

    #[test]
    fn guids_and_decimals_write_back_as_they_read() {
        let text = "00112233-4455-6677-8899-aabbccddeeff";
        assert_eq!(guid_text(&guid_bytes(text).unwrap()), text);
        assert_eq!(guid_bytes("not a guid"), None);
        for x in [6.42, -6.42, 0.0, 1e-20, 123_456_789.125, 0.1, 7.0e20] {
            assert_eq!(decimal(decimal_bytes(x)), x, "{x}");
        }
        // Out of a decimal's range: zero, not a wrong number.
        assert_eq!(decimal(decimal_bytes(1e40)), 0.0);
        assert_eq!(decimal(decimal_bytes(f64::NAN)), 0.0);
    }

    /// Every value type and nesting writes and reads back unchanged.
    #[test]
    fn a_chunk_of_every_type_writes_and_reads_back() {
        let item = |name: &str, index: Option<i32>, value: Value| Item {
            name: name.to_owned(),
            index,
            value,
        };
        let root = Chunk {
            name: "Document".to_owned(),
            index: None,
            items: vec![
                item("b", None, Value::Bool(true)),
                item("y", Some(3), Value::Byte(7)),
                item("i", None, Value::Int32(-5)),
                item("l", None, Value::Int64(-1 << 40)),
                item("f", None, Value::Single(1.5)),
                item("d", None, Value::Double(-0.1)),
                item("m", None, Value::Decimal(2.25)),
                item("t", None, Value::Date(637_361_165_902_844_751)),
                item(
                    "g",
                    None,
                    Value::Guid("f31d8d7a-7536-4ac8-9c96-fde6ecda4d0a".into()),
                ),
                item("s", Some(0), Value::String("é\r\nü".repeat(40))),
                item("a", None, Value::Bytes(vec![1, 2, 3])),
                item("ds", None, Value::Doubles(vec![1.0, f64::INFINITY])),
                item("p", None, Value::DrawingPoint([1, -2])),
                item("pf", None, Value::DrawingPointF([1.5, -2.5])),
                item("sz", None, Value::DrawingSize([3, 4])),
                item("szf", None, Value::DrawingSizeF([3.5, 4.5])),
                item("r", None, Value::DrawingRectangle([1, 2, 3, 4])),
                item("rf", None, Value::DrawingRectangleF([1.0, 2.0, 3.0, 4.0])),
                item("c", None, Value::Color([255, 10, 20, 30])),
                item("bm", None, Value::Bitmap(vec![0x89, b'P'])),
                item("p2", None, Value::Point2([1.0, 2.0])),
                item("p3", None, Value::Point3([1.0, 2.0, 3.0])),
                item("p4", None, Value::Point4([1.0, 2.0, 3.0, 4.0])),
                item("iv", None, Value::Interval([0.0, 1.0])),
                item("iv2", None, Value::Interval2([0.0, 1.0, 2.0, 3.0])),
                item("ln", None, Value::Line([0.0, 1.0, 2.0, 3.0, 4.0, 5.0])),
                item(
                    "bb",
                    None,
                    Value::BoundingBox([0.0, 1.0, 2.0, 3.0, 4.0, 5.0]),
                ),
                item(
                    "pl",
                    None,
                    Value::Plane([0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0]),
                ),
                item("v", None, Value::Version([1, 0, 7])),
            ],
            chunks: vec![Chunk {
                name: "Object".to_owned(),
                index: Some(0),
                items: vec![item("Name", None, Value::String(String::new()))],
                chunks: vec![Chunk::default()],
            }],
        };
        let data = write_binary(&root);
        assert_eq!(read_binary(&data, &Limits::default()).unwrap(), root);
        let compressed = write_compressed(&root);
        let mut file_root = root.clone();
        file_root.name = "Root".to_owned();
        assert_eq!(
            read_compressed(&write_compressed(&file_root), &Limits::default(), 0).unwrap(),
            file_root
        );
        assert_eq!(
            read_compressed(&compressed, &Limits::default(), 1).unwrap(),
            root
        );
    }
}

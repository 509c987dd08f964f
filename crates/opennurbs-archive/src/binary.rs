//! The byte level of an openNURBS archive: little-endian numbers, chunks with lengths and CRCs,
//! and compressed buffers.
//!
//! A *chunk* is a 4-byte type code followed by an 8-byte value (archives of version 50 and
//! later). In a *short* chunk (type code bit `0x8000_0000`) the value is the whole payload; in
//! a *long* chunk the value is the length of the bytes that follow. A long chunk whose type code
//! has the bit `0x8000` set ends with the CRC-32 (zlib's) of its own payload. Bytes of nested
//! chunks, including their headers, count towards the innermost chunk only, never towards the
//! chunk around them; both [`Writer`] and [`Reader`] keep one running CRC per open chunk and
//! feed only the innermost, as openNURBS does.

use crate::{Error, Result};

/// Chunk type codes used by single-object archives (`opennurbs_3dm.h`).
pub mod tcode {
    /// Bit of a short chunk: the value is the payload, no bytes follow.
    pub const SHORT: u32 = 0x8000_0000;
    /// Bit of a chunk that ends with a CRC-32 of its payload.
    pub const CRC: u32 = 0x8000;
    /// A chunk of user data without a type of its own (nested records, compressed buffers).
    pub const ANONYMOUS_CHUNK: u32 = 0x4000_0000 | CRC;
    /// An object record: class id, class data, user data, end mark.
    pub const OPENNURBS_CLASS: u32 = 0x0002_7FFA;
    /// The class id of an object record.
    pub const OPENNURBS_CLASS_UUID: u32 = 0x0002_0000 | CRC | 0x7FFB;
    /// The data that the class's `Write` wrote.
    pub const OPENNURBS_CLASS_DATA: u32 = 0x0002_0000 | CRC | 0x7FFC;
    /// User data attached to an object (skipped on read, never written).
    pub const OPENNURBS_CLASS_USERDATA: u32 = 0x0002_0000 | 0x7FFD;
    /// The end mark of an object record (a short chunk).
    pub const OPENNURBS_CLASS_END: u32 = 0x0002_0000 | SHORT | 0x7FFF;
}

/// openNURBS's "unset" double, `ON_UNSET_VALUE`, written for intervals that are not set.
pub const UNSET_VALUE: f64 = -1.234_321e308;

/// Buffers longer than this are deflated by [`Writer::compressed_buffer`] (openNURBS's rule).
const COMPRESS_ABOVE: usize = 128;

struct OpenChunk {
    /// Offset of the 8-byte length field.
    length_at: usize,
    crc: Option<crc32fast::Hasher>,
}

/// Writes an archive into memory.
#[derive(Default)]
pub struct Writer {
    buf: Vec<u8>,
    open: Vec<OpenChunk>,
}

impl std::fmt::Debug for Writer {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Writer")
            .field("len", &self.buf.len())
            .field("open_chunks", &self.open.len())
            .finish()
    }
}

impl Writer {
    /// An empty archive.
    pub fn new() -> Self {
        Self::default()
    }

    /// The bytes written so far.
    ///
    /// # Panics
    /// Never; but the bytes are only a valid archive once every chunk is ended.
    pub fn into_bytes(self) -> Vec<u8> {
        debug_assert!(self.open.is_empty(), "unbalanced chunks");
        self.buf
    }

    fn raw(&mut self, bytes: &[u8]) {
        self.buf.extend_from_slice(bytes);
    }

    /// Writes payload bytes, feeding the innermost chunk's CRC.
    pub fn bytes(&mut self, bytes: &[u8]) {
        if let Some(OpenChunk { crc: Some(h), .. }) = self.open.last_mut() {
            h.update(bytes);
        }
        self.raw(bytes);
    }

    /// One byte.
    pub fn u8(&mut self, v: u8) {
        self.bytes(&[v]);
    }
    /// A `bool` as one byte, 0 or 1.
    pub fn bool(&mut self, v: bool) {
        self.u8(u8::from(v));
    }
    /// A 16-bit integer.
    pub fn u16(&mut self, v: u16) {
        self.bytes(&v.to_le_bytes());
    }
    /// A 32-bit signed integer.
    pub fn i32(&mut self, v: i32) {
        self.bytes(&v.to_le_bytes());
    }
    /// A 32-bit unsigned integer.
    pub fn u32(&mut self, v: u32) {
        self.bytes(&v.to_le_bytes());
    }
    /// A count or index as openNURBS's 32-bit `int`.
    ///
    /// # Errors
    /// [`Error::TooLarge`] above `i32::MAX`.
    pub fn count(&mut self, v: usize) -> Result<()> {
        let v = i32::try_from(v).map_err(|_| Error::TooLarge(v))?;
        self.i32(v);
        Ok(())
    }
    /// A 32-bit float.
    pub fn f32(&mut self, v: f32) {
        self.bytes(&v.to_le_bytes());
    }
    /// A double.
    pub fn f64(&mut self, v: f64) {
        self.bytes(&v.to_le_bytes());
    }
    /// Doubles.
    pub fn f64s(&mut self, v: &[f64]) {
        for &x in v {
            self.f64(x);
        }
    }
    /// A UUID given in its usual text order (`Data1-Data2-Data3-Data4`): openNURBS writes
    /// `Data1..3` little-endian and `Data4` as bytes.
    pub fn uuid(&mut self, id: &[u8; 16]) {
        let mut b = *id;
        b[0..4].reverse();
        b[4..6].reverse();
        b[6..8].reverse();
        self.bytes(&b);
    }
    /// An interval as two doubles.
    pub fn interval(&mut self, t0: f64, t1: f64) {
        self.f64(t0);
        self.f64(t1);
    }
    /// openNURBS's empty bounding box `(1,0,0)–(-1,0,0)`, written where a class reserves one.
    pub fn empty_bounding_box(&mut self) {
        self.f64s(&[1.0, 0.0, 0.0, -1.0, 0.0, 0.0]);
    }
    /// A chunk version byte, `major·16 + minor`.
    pub fn version(&mut self, major: u8, minor: u8) {
        self.u8(major << 4 | (minor & 0xF));
    }

    /// Opens a long chunk; close it with [`Writer::end_chunk`].
    pub fn begin_chunk(&mut self, tcode: u32) {
        debug_assert_eq!(tcode & tcode::SHORT, 0);
        self.raw(&tcode.to_le_bytes());
        let length_at = self.buf.len();
        self.raw(&0i64.to_le_bytes());
        let crc = (tcode & tcode::CRC != 0).then(crc32fast::Hasher::new);
        self.open.push(OpenChunk { length_at, crc });
    }

    /// Opens a long chunk that starts with a version as two `int`s (`BeginWrite3dmChunk` with
    /// a major and minor version).
    pub fn begin_versioned_chunk(&mut self, tcode: u32, major: i32, minor: i32) {
        self.begin_chunk(tcode);
        self.i32(major);
        self.i32(minor);
    }

    /// Closes the innermost chunk: writes its CRC if it has one, then its length.
    pub fn end_chunk(&mut self) {
        let Some(chunk) = self.open.pop() else {
            debug_assert!(false, "end_chunk without begin_chunk");
            return;
        };
        if let Some(h) = chunk.crc {
            let crc = h.finalize();
            self.raw(&crc.to_le_bytes());
        }
        let length = (self.buf.len() - chunk.length_at - 8) as u64;
        self.buf[chunk.length_at..chunk.length_at + 8].copy_from_slice(&length.to_le_bytes());
    }

    /// A short chunk: type code and value only.
    pub fn short_chunk(&mut self, tcode: u32, value: i64) {
        debug_assert_ne!(tcode & tcode::SHORT, 0);
        self.raw(&tcode.to_le_bytes());
        self.raw(&value.to_le_bytes());
    }

    /// A buffer as `WriteCompressedBuffer` writes it: its size, its CRC-32, a method byte and
    /// the bytes, deflated (zlib, in an anonymous chunk) when longer than 128 bytes.
    ///
    /// # Errors
    /// [`Error::TooLarge`] for a buffer of 4 GiB or more.
    pub fn compressed_buffer(&mut self, data: &[u8]) -> Result<()> {
        let size = u32::try_from(data.len()).map_err(|_| Error::TooLarge(data.len()))?;
        self.u32(size);
        if data.is_empty() {
            return Ok(());
        }
        self.u32(crc32fast::hash(data));
        if data.len() > COMPRESS_ABOVE {
            self.u8(1);
            use std::io::Write as _;
            let mut z = flate2::write::ZlibEncoder::new(Vec::new(), flate2::Compression::best());
            // Writing into a Vec cannot fail.
            let deflated = z
                .write_all(data)
                .and_then(|()| z.finish())
                .map_err(|e| Error::Invalid(format!("deflate: {e}")))?;
            self.begin_chunk(tcode::ANONYMOUS_CHUNK);
            self.bytes(&deflated);
            self.end_chunk();
        } else {
            self.u8(0);
            self.bytes(data);
        }
        Ok(())
    }
}

struct ReadChunk {
    tcode: u32,
    /// Offset of the first payload byte.
    start: usize,
    /// End of the payload that the class reads (before the CRC, if any).
    content_end: usize,
    /// End of the chunk.
    end: usize,
    crc: Option<crc32fast::Hasher>,
}

/// Reads an archive from memory. Every read is bounded by the innermost open chunk (or the
/// end of the data), so a length or count in hostile bytes can never read past them or make
/// the reader allocate more than the bytes it was given could hold.
pub struct Reader<'a> {
    data: &'a [u8],
    pos: usize,
    open: Vec<ReadChunk>,
}

impl std::fmt::Debug for Reader<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Reader")
            .field("len", &self.data.len())
            .field("pos", &self.pos)
            .field("open_chunks", &self.open.len())
            .finish()
    }
}

/// Nested chunks deeper than this are refused (a polycurve of polycurves of ... could
/// otherwise recurse without bound).
pub const MAX_DEPTH: usize = 64;

impl<'a> Reader<'a> {
    /// A reader of `data`.
    pub fn new(data: &'a [u8]) -> Self {
        Self {
            data,
            pos: 0,
            open: Vec::new(),
        }
    }

    /// The current offset.
    pub fn position(&self) -> usize {
        self.pos
    }

    /// Where the innermost chunk's readable payload ends.
    fn limit(&self) -> usize {
        self.open.last().map_or(self.data.len(), |c| c.content_end)
    }

    /// The bytes left in the innermost chunk.
    pub fn remaining(&self) -> usize {
        self.limit().saturating_sub(self.pos)
    }

    fn raw(&mut self, n: usize, what: &'static str) -> Result<&'a [u8]> {
        let end = self.pos.checked_add(n).filter(|&e| e <= self.limit());
        let Some(end) = end else {
            return Err(Error::Truncated {
                what,
                at: self.pos,
                needed: n,
                available: self.remaining(),
            });
        };
        let s = &self.data[self.pos..end];
        self.pos = end;
        Ok(s)
    }

    /// Reads payload bytes, feeding the innermost chunk's CRC.
    pub fn bytes(&mut self, n: usize, what: &'static str) -> Result<&'a [u8]> {
        let s = self.raw(n, what)?;
        if let Some(ReadChunk { crc: Some(h), .. }) = self.open.last_mut() {
            h.update(s);
        }
        Ok(s)
    }

    fn array<const N: usize>(&mut self, what: &'static str) -> Result<[u8; N]> {
        let s = self.bytes(N, what)?;
        let mut a = [0; N];
        a.copy_from_slice(s);
        Ok(a)
    }

    /// One byte.
    pub fn u8(&mut self, what: &'static str) -> Result<u8> {
        Ok(self.array::<1>(what)?[0])
    }
    /// A `bool` byte (any non-zero value is true, as openNURBS reads it).
    pub fn bool(&mut self, what: &'static str) -> Result<bool> {
        Ok(self.u8(what)? != 0)
    }
    /// A 16-bit integer.
    pub fn u16(&mut self, what: &'static str) -> Result<u16> {
        Ok(u16::from_le_bytes(self.array(what)?))
    }
    /// A 32-bit signed integer.
    pub fn i32(&mut self, what: &'static str) -> Result<i32> {
        Ok(i32::from_le_bytes(self.array(what)?))
    }
    /// A 32-bit unsigned integer.
    pub fn u32(&mut self, what: &'static str) -> Result<u32> {
        Ok(u32::from_le_bytes(self.array(what)?))
    }
    /// A 32-bit float.
    pub fn f32(&mut self, what: &'static str) -> Result<f32> {
        Ok(f32::from_le_bytes(self.array(what)?))
    }
    /// A double.
    pub fn f64(&mut self, what: &'static str) -> Result<f64> {
        Ok(f64::from_le_bytes(self.array(what)?))
    }
    /// `n` doubles, after checking that the chunk holds them.
    pub fn f64s(&mut self, n: usize, what: &'static str) -> Result<Vec<f64>> {
        let s = self.bytes(n.checked_mul(8).ok_or(Error::TooLarge(n))?, what)?;
        Ok(s.chunks_exact(8)
            .map(|b| f64::from_le_bytes(b.try_into().unwrap_or_default()))
            .collect())
    }
    /// A count as openNURBS's `int`: negative is an error, and a count of items of
    /// `item_size` bytes each must fit in what is left of the chunk.
    pub fn count(&mut self, item_size: usize, what: &'static str) -> Result<usize> {
        let at = self.pos;
        let n = self.i32(what)?;
        let n = usize::try_from(n)
            .map_err(|_| Error::Invalid(format!("negative {what} {n} at byte {at}")))?;
        if n.saturating_mul(item_size) > self.remaining() {
            return Err(Error::Truncated {
                what,
                at,
                needed: n.saturating_mul(item_size),
                available: self.remaining(),
            });
        }
        Ok(n)
    }
    /// A UUID, returned in its usual text order.
    pub fn uuid(&mut self, what: &'static str) -> Result<[u8; 16]> {
        let mut b: [u8; 16] = self.array(what)?;
        b[0..4].reverse();
        b[4..6].reverse();
        b[6..8].reverse();
        Ok(b)
    }
    /// A chunk version byte as `(major, minor)`.
    pub fn version(&mut self, what: &'static str) -> Result<(u8, u8)> {
        let v = self.u8(what)?;
        Ok((v >> 4, v & 0xF))
    }
    /// Skips `n` bytes of the innermost chunk (counted in its CRC).
    pub fn skip(&mut self, n: usize, what: &'static str) -> Result<()> {
        self.bytes(n, what).map(|_| ())
    }

    /// Opens the next chunk and returns its type code and value. For a long chunk the reader
    /// then reads inside it until [`Reader::end_chunk`]; a short chunk is complete at once and
    /// must not be ended.
    ///
    /// # Errors
    /// [`Error::Truncated`] if the header or the length runs past the enclosing chunk,
    /// [`Error::Invalid`] for a negative length or nesting deeper than [`MAX_DEPTH`].
    pub fn begin_chunk(&mut self) -> Result<(u32, i64)> {
        let at = self.pos;
        let tc = u32::from_le_bytes(
            self.raw(4, "chunk type code")?
                .try_into()
                .unwrap_or_default(),
        );
        let value = i64::from_le_bytes(self.raw(8, "chunk length")?.try_into().unwrap_or_default());
        if tc & tcode::SHORT != 0 {
            return Ok((tc, value));
        }
        if self.open.len() >= MAX_DEPTH {
            return Err(Error::Invalid(format!(
                "chunks nested deeper than {MAX_DEPTH} at byte {at}"
            )));
        }
        let len = usize::try_from(value).map_err(|_| {
            Error::Invalid(format!("chunk {tc:#010x} at byte {at} has length {value}"))
        })?;
        if len > self.remaining() {
            return Err(Error::Truncated {
                what: "chunk",
                at,
                needed: len,
                available: self.remaining(),
            });
        }
        let has_crc = tc & tcode::CRC != 0;
        if has_crc && len < 4 {
            return Err(Error::Invalid(format!(
                "chunk {tc:#010x} at byte {at} is too short ({len} bytes) for its CRC"
            )));
        }
        let end = self.pos + len;
        self.open.push(ReadChunk {
            tcode: tc,
            start: self.pos,
            content_end: if has_crc { end - 4 } else { end },
            end,
            crc: has_crc.then(crc32fast::Hasher::new),
        });
        Ok((tc, value))
    }

    /// Opens a long chunk that must have type code `tc`.
    ///
    /// # Errors
    /// As [`Reader::begin_chunk`], and [`Error::Invalid`] for another type code.
    pub fn expect_chunk(&mut self, tc: u32, what: &'static str) -> Result<()> {
        let at = self.pos;
        let (found, _) = self.begin_chunk()?;
        if found != tc {
            if found & tcode::SHORT == 0 {
                self.open.pop();
            }
            return Err(Error::Invalid(format!(
                "expected {what} (chunk {tc:#010x}) at byte {at}, found chunk {found:#010x}"
            )));
        }
        Ok(())
    }

    /// Opens an anonymous chunk that starts with a version as two `int`s, returning them.
    ///
    /// # Errors
    /// As [`Reader::expect_chunk`].
    pub fn begin_versioned_chunk(&mut self, what: &'static str) -> Result<(i32, i32)> {
        self.expect_chunk(tcode::ANONYMOUS_CHUNK, what)?;
        Ok((self.i32(what)?, self.i32(what)?))
    }

    /// Closes the innermost chunk. When its payload was read to the end, its CRC is checked;
    /// a payload read only in part (a newer minor version with fields this reader does not
    /// know) is skipped, as openNURBS does.
    ///
    /// # Errors
    /// [`Error::Crc`] when the CRC does not match.
    pub fn end_chunk(&mut self) -> Result<()> {
        let Some(chunk) = self.open.pop() else {
            return Err(Error::Invalid("end of a chunk that was not begun".into()));
        };
        if let Some(h) = chunk.crc
            && self.pos == chunk.content_end
        {
            let stored = u32::from_le_bytes(
                self.data[chunk.content_end..chunk.end]
                    .try_into()
                    .unwrap_or_default(),
            );
            let computed = h.finalize();
            if stored != computed {
                return Err(Error::Crc {
                    tcode: chunk.tcode,
                    at: chunk.start,
                    stored,
                    computed,
                });
            }
        }
        self.pos = chunk.end;
        Ok(())
    }

    /// Skips the next chunk whole, long or short.
    ///
    /// # Errors
    /// As [`Reader::begin_chunk`].
    pub fn skip_chunk(&mut self) -> Result<u32> {
        let (tc, _) = self.begin_chunk()?;
        if tc & tcode::SHORT == 0
            && let Some(chunk) = self.open.pop()
        {
            self.pos = chunk.end;
        }
        Ok(tc)
    }

    /// Reads a buffer written by `WriteCompressedBuffer` that must hold `expected` bytes.
    ///
    /// # Errors
    /// [`Error::Invalid`] when the stored size differs from `expected`, the method is unknown
    /// or the deflated data is damaged or of another size; [`Error::Crc`] when the CRC of the
    /// bytes does not match.
    pub fn compressed_buffer(&mut self, expected: usize, what: &'static str) -> Result<Vec<u8>> {
        let at = self.pos;
        let size = self.u32(what)? as usize;
        if size == 0 {
            return Ok(Vec::new());
        }
        if size != expected {
            return Err(Error::Invalid(format!(
                "{what} at byte {at} holds {size} bytes, expected {expected}"
            )));
        }
        let crc = self.u32(what)?;
        let method = self.u8(what)?;
        let data = match method {
            0 => self.bytes(size, what)?.to_vec(),
            1 => {
                self.expect_chunk(tcode::ANONYMOUS_CHUNK, what)?;
                let n = self.remaining();
                let deflated = self.bytes(n, what)?;
                self.end_chunk()?;
                inflate_exact(deflated, size)
                    .map_err(|e| Error::Invalid(format!("{what} at byte {at}: {e}")))?
            }
            m => {
                return Err(Error::Invalid(format!(
                    "{what} at byte {at} has unknown compression method {m}"
                )));
            }
        };
        let computed = crc32fast::hash(&data);
        if computed != crc {
            return Err(Error::Crc {
                tcode: 0,
                at,
                stored: crc,
                computed,
            });
        }
        Ok(data)
    }
}

/// Inflates a zlib stream that must produce exactly `size` bytes, never allocating more.
fn inflate_exact(deflated: &[u8], size: usize) -> std::result::Result<Vec<u8>, String> {
    use std::io::Read as _;
    let mut out = Vec::with_capacity(size.min(deflated.len().saturating_mul(1032)));
    let mut z = flate2::read::ZlibDecoder::new(deflated).take(size as u64 + 1);
    z.read_to_end(&mut out)
        .map_err(|e| format!("inflate: {e}"))?;
    if out.len() != size {
        return Err(format!("inflated to {} bytes, expected {size}", out.len()));
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn nested_chunk_bytes_do_not_count_in_the_outer_crc() {
        let mut w = Writer::new();
        w.begin_chunk(tcode::OPENNURBS_CLASS_DATA);
        w.i32(7);
        w.begin_chunk(tcode::ANONYMOUS_CHUNK);
        w.f64(1.5);
        w.end_chunk();
        w.i32(9);
        w.end_chunk();
        let bytes = w.into_bytes();
        // Outer CRC is over 7 and 9 only.
        let mut h = crc32fast::Hasher::new();
        h.update(&7i32.to_le_bytes());
        h.update(&9i32.to_le_bytes());
        let n = bytes.len();
        assert_eq!(&bytes[n - 4..], &h.finalize().to_le_bytes());

        let mut r = Reader::new(&bytes);
        r.expect_chunk(tcode::OPENNURBS_CLASS_DATA, "data").unwrap();
        assert_eq!(r.i32("a").unwrap(), 7);
        r.expect_chunk(tcode::ANONYMOUS_CHUNK, "inner").unwrap();
        assert_eq!(r.f64("b").unwrap(), 1.5);
        r.end_chunk().unwrap();
        assert_eq!(r.i32("c").unwrap(), 9);
        r.end_chunk().unwrap();
        assert_eq!(r.position(), bytes.len());
    }

    #[test]
    fn a_flipped_bit_fails_the_crc() {
        let mut w = Writer::new();
        w.begin_chunk(tcode::ANONYMOUS_CHUNK);
        w.f64(2.0);
        w.end_chunk();
        let mut bytes = w.into_bytes();
        bytes[14] ^= 1;
        let mut r = Reader::new(&bytes);
        r.begin_chunk().unwrap();
        r.f64("x").unwrap();
        assert!(matches!(r.end_chunk(), Err(Error::Crc { .. })));
    }

    #[test]
    fn compressed_buffers_round_trip_both_methods() {
        for n in [0usize, 5, 128, 129, 5000] {
            let data: Vec<u8> = (0..n).map(|i| (i * 7 % 251) as u8).collect();
            let mut w = Writer::new();
            w.begin_chunk(tcode::OPENNURBS_CLASS_DATA);
            w.compressed_buffer(&data).unwrap();
            w.end_chunk();
            let bytes = w.into_bytes();
            let mut r = Reader::new(&bytes);
            r.begin_chunk().unwrap();
            assert_eq!(r.compressed_buffer(n, "buf").unwrap(), data);
            r.end_chunk().unwrap();
        }
    }

    #[test]
    fn counts_are_bounded_by_the_chunk() {
        let mut w = Writer::new();
        w.begin_chunk(tcode::ANONYMOUS_CHUNK);
        w.i32(1_000_000_000);
        w.end_chunk();
        let bytes = w.into_bytes();
        let mut r = Reader::new(&bytes);
        r.begin_chunk().unwrap();
        assert!(matches!(r.count(8, "points"), Err(Error::Truncated { .. })));
    }
}

//! Errors of reading and writing archives.

/// Why an archive could not be read or written.
#[derive(Debug, thiserror::Error)]
pub enum Error {
    /// The bytes end (or the enclosing chunk ends) before what must be read.
    #[error("truncated: {what} at byte {at} needs {needed} bytes, {available} left")]
    Truncated {
        /// What was being read.
        what: &'static str,
        /// The byte offset.
        at: usize,
        /// How many bytes it needs.
        needed: usize,
        /// How many bytes are left in the enclosing chunk.
        available: usize,
    },
    /// A stored CRC-32 does not match the bytes.
    #[error(
        "CRC mismatch in chunk {tcode:#010x} at byte {at}: stored {stored:#010x}, computed {computed:#010x}"
    )]
    Crc {
        /// The chunk's type code (0 for a compressed buffer).
        tcode: u32,
        /// The offset of its payload.
        at: usize,
        /// The CRC in the archive.
        stored: u32,
        /// The CRC of the bytes.
        computed: u32,
    },
    /// The archive holds an object of a class that locus does not read.
    #[error("unsupported openNURBS class {name} ({id})")]
    UnsupportedClass {
        /// The class id, as text.
        id: String,
        /// The class name when known, else "unknown class".
        name: &'static str,
    },
    /// The archive's 3dm version is not supported.
    #[error("unsupported 3dm archive version {0} (locus reads version 50 and later)")]
    UnsupportedVersion(i32),
    /// A class's data is not what openNURBS writes.
    #[error("{0}")]
    Invalid(String),
    /// The decoded parts do not make valid geometry.
    #[error("{what}: {source}")]
    Geometry {
        /// Which object.
        what: &'static str,
        /// The kernel's reason.
        source: locus_kernel::Error,
    },
    /// A count or size that openNURBS cannot store (above `i32::MAX` or 4 GiB).
    #[error("{0} is too large for an openNURBS archive")]
    TooLarge(usize),
    /// CommonObject JSON that is not well formed.
    #[error("CommonObject JSON: {0}")]
    Json(String),
}

/// A result with an archive [`Error`].
pub type Result<T> = std::result::Result<T, Error>;

//! Why an archive could not be read.

use thiserror::Error;

/// Why a `.gh`, `.ghx` or cluster archive could not be read. Messages name the chunk path
/// (`Root/Definition/DefinitionObjects/Object[3]`) and, for binary archives, the byte offset
/// in the decompressed data.
#[derive(Clone, Debug, Error, PartialEq, Eq)]
pub enum ArchiveError {
    /// The file is larger than the limit.
    #[error("the file is {size} bytes, more than the limit of {limit}")]
    FileTooLarge {
        /// The file's size.
        size: usize,
        /// The limit.
        limit: usize,
    },
    /// The compressed data does not inflate.
    #[error("{context}: the compressed archive is corrupt: {reason}")]
    Deflate {
        /// What was being read (`file`, or the cluster's chunk path).
        context: String,
        /// The decoder's reason.
        reason: String,
    },
    /// Decompression would pass a bound (a zip bomb, or a larger archive than allowed).
    #[error(
        "{context}: the archive inflates to more than {limit} bytes ({compressed} compressed), refused as a possible zip bomb"
    )]
    Bomb {
        /// What was being read.
        context: String,
        /// The compressed size.
        compressed: usize,
        /// The bound that was passed.
        limit: usize,
    },
    /// The XML is not well-formed, or not a GH_IO archive.
    #[error("line {line}, column {column}: {reason}")]
    Xml {
        /// 1-based line.
        line: u32,
        /// 1-based column.
        column: u32,
        /// What is wrong.
        reason: String,
    },
    /// The binary archive ends too early.
    #[error("{path}: the archive ends at byte {offset} while reading {what}")]
    Truncated {
        /// The chunk path.
        path: String,
        /// The offset in the decompressed data.
        offset: usize,
        /// What was being read.
        what: String,
    },
    /// A value that does not read as its type.
    #[error("{path}: {reason}")]
    Bad {
        /// The chunk path (and item).
        path: String,
        /// What is wrong.
        reason: String,
    },
    /// Chunks or clusters nest deeper than allowed.
    #[error("{path}: chunks nest deeper than the limit of {limit}")]
    TooDeep {
        /// The chunk path where the limit was reached.
        path: String,
        /// The limit.
        limit: usize,
    },
    /// More chunks and items than allowed, or a string longer than allowed.
    #[error("{path}: {what} passes the limit of {limit}")]
    TooMany {
        /// The chunk path.
        path: String,
        /// What passed the limit.
        what: String,
        /// The limit.
        limit: usize,
    },
}

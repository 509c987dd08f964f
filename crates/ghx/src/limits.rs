//! Hard bounds on what a reader accepts, so that a hostile file (a zip bomb, deep nesting,
//! a 2 GB string, a billion declared items) ends in a clear error instead of exhausting memory
//! or time.

/// The bounds a reader enforces. [`Limits::default`] suits every real definition seen (the
/// largest public `.ghx` files are a few MB); hosts that read untrusted files may lower them.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Limits {
    /// The largest input file, in bytes (default 256 MiB).
    pub max_file_bytes: usize,
    /// The largest decompressed binary archive, in bytes (default 256 MiB).
    pub max_decompressed_bytes: usize,
    /// The largest ratio of decompressed to compressed size (default 200); real archives
    /// compress 3–10×, zip bombs 1000× and more.
    pub max_ratio: usize,
    /// Decompressed sizes up to this many bytes are accepted whatever the ratio
    /// (default 1 MiB), so that small, highly repetitive archives still read.
    pub ratio_free_bytes: usize,
    /// The deepest nesting of chunks (default 64; real files nest about 12 deep).
    pub max_depth: usize,
    /// The deepest nesting of clusters inside clusters (default 8).
    pub max_cluster_depth: usize,
    /// The most chunks plus items in one archive (default 20 million).
    pub max_entries: usize,
    /// The longest string or byte array, in bytes (default 64 MiB).
    pub max_string_bytes: usize,
}

impl Default for Limits {
    fn default() -> Self {
        Self {
            max_file_bytes: 256 << 20,
            max_decompressed_bytes: 256 << 20,
            max_ratio: 200,
            ratio_free_bytes: 1 << 20,
            max_depth: 64,
            max_cluster_depth: 8,
            max_entries: 20_000_000,
            max_string_bytes: 64 << 20,
        }
    }
}

//! Grasshopper definitions for locus: reading `.ghx` (XML), `.gh` (binary) and nested cluster
//! archives into one chunk/item model ([`Chunk`]), and mapping them onto a locus [`Graph`]
//! through the node registry, by type GUID ([`import`]).
//!
//! The crate depends on the runtime only; it knows the node library through the
//! [`NodeRegistry`] it is given (`NodeType::gh_guids`). See `docs/grasshopper-files.md` for
//! what is supported, dropped and unsupported.
//!
//! ```no_run
//! let mut registry = locus_runtime::NodeRegistry::new();
//! // locus_nodes::register(&mut registry);
//! let bytes = std::fs::read("definition.ghx")?;
//! let import = locus_ghx::import(&bytes, &registry, &locus_ghx::Limits::default())?;
//! print!("{}", import.report.summary());
//! println!("{}", locus_ghx::to_ron(&import));
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! [`Graph`]: locus_runtime::Graph

mod archive;
mod binary;
mod document;
mod error;
mod export;
mod import;
mod internalised;
mod known;
mod limits;
mod literal;
mod report;
mod ron;
mod xml;

pub use crate::archive::{Chunk, Form, Item, Value, detect, read_archive};
pub use crate::binary::{inflate, read_binary, read_compressed, write_binary, write_compressed};
pub use crate::document::{
    GhDocument, GhItem, GhModifier, GhObject, GhParam, GhTree, Library, read_cluster, read_document,
};
pub use crate::error::ArchiveError;
pub use crate::export::{ExportError, ExportWarning, export_ghx};
pub use crate::import::{Import, import_document};
pub use crate::known::{KNOWN, Special, special};
pub use crate::limits::Limits;
pub use crate::report::{ComputeName, ImportDiagnostic, ObjectRef, Outcome, Report};
pub use crate::ron::to_ron;
pub use crate::xml::read_xml;

use locus_runtime::NodeRegistry;

/// Reads a `.gh` or `.ghx` file's bytes and maps the definition onto a graph.
pub fn import(
    bytes: &[u8],
    registry: &NodeRegistry,
    limits: &Limits,
) -> Result<Import, ArchiveError> {
    let root = read_archive(bytes, limits)?;
    let doc = read_document(&root)?;
    Ok(import_document(&doc, registry, limits))
}

/// Whether a path names a Grasshopper file (`.gh` or `.ghx`, any case).
pub fn is_grasshopper_path(path: &std::path::Path) -> bool {
    path.extension()
        .and_then(|e| e.to_str())
        .is_some_and(|e| e.eq_ignore_ascii_case("gh") || e.eq_ignore_ascii_case("ghx"))
}

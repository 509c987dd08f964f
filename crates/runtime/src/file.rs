//! The graph file format: the RON reader that keeps positions, the document and its canonical
//! writer, literal values (geometry too) read against a port's type, and the text form of values.

pub(crate) mod bless;
pub(crate) mod canonical;
pub(crate) mod expected;
pub(crate) mod format;
pub(crate) mod literal;
pub(crate) mod literal_geometry;
pub(crate) mod literal_mesh;
pub(crate) mod syntax;
pub(crate) mod value_text;
pub(crate) mod write;

//! x
use locus_runtime::NodeRegistry;
/// r
pub fn register(_r: &mut NodeRegistry) {}

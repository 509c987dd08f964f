//! Runtime messages: remarks, warnings and errors that nodes report while they run.

use std::fmt;

use crate::{NodeId, TreePath};

/// The severity of a runtime message, in increasing order.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Level {
    /// Information only; does not mark the node.
    Remark,
    /// Something may be wrong; the node ran (Grasshopper's orange).
    Warning,
    /// An iteration or the whole node failed (Grasshopper's red).
    Error,
}

impl Level {
    /// The lower-case name (`remark`, `warning`, `error`).
    pub fn name(self) -> &'static str {
        match self {
            Level::Remark => "remark",
            Level::Warning => "warning",
            Level::Error => "error",
        }
    }
}

impl fmt::Display for Level {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// A message reported by a node during evaluation.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Message {
    /// The node that reported it.
    pub node: NodeId,
    /// How severe it is.
    pub level: Level,
    /// The output path of the iteration that reported it, if it came from one.
    pub path: Option<TreePath>,
    /// The item index within that branch, if it came from an item iteration.
    pub index: Option<usize>,
    /// What happened, in plain words.
    pub text: String,
}

impl fmt::Display for Message {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: node \"{}\"", self.level, self.node)?;
        match (&self.path, self.index) {
            (Some(p), Some(i)) => write!(f, " at {p}[{i}]")?,
            (Some(p), None) => write!(f, " at {p}")?,
            _ => {}
        }
        write!(f, ": {}", self.text)
    }
}

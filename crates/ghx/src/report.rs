//! What an import found: one outcome per Grasshopper object, diagnostics naming the object,
//! and the summary `locus import --report` prints.

use std::fmt::Write as _;

use locus_runtime::{Level, NodeId};

/// The Grasshopper object a diagnostic or outcome is about.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct ObjectRef {
    /// The type name the file gives (`Number Slider`).
    pub type_name: String,
    /// The user-visible name.
    pub name: String,
    /// The nickname.
    pub nickname: String,
    /// The instance GUID.
    pub instance: String,
    /// The type GUID.
    pub type_guid: String,
    /// The cluster path the object sits in (empty at the top level): `outer/inner`.
    pub cluster: String,
}

impl std::fmt::Display for ObjectRef {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}", self.type_name)?;
        if !self.nickname.is_empty() && self.nickname != self.type_name {
            write!(f, " \"{}\"", self.nickname)?;
        }
        if !self.cluster.is_empty() {
            write!(f, " in cluster {}", self.cluster)?;
        }
        Ok(())
    }
}

/// How Rhino.Compute names one input or output of a definition, and which graph input or
/// output it is.
///
/// Compute finds an input by the whole nickname of the group it is the first object of
/// (`RH_IN:radius`, also the old `RH_IN:102:0001` with its type code), or by the nickname of a
/// Hops Get parameter; an output by the whole nickname of its `RH_OUT` group. The graph's own
/// names drop the `RH_IN:`/`RH_OUT:` prefix and type code, and are made unique.
#[derive(Clone, Debug, PartialEq)]
pub struct ComputeName {
    /// Compute's name, as clients send it in `ParamName`.
    pub name: String,
    /// The graph input or output's name.
    pub graph: String,
    /// The y position of the object on the canvas (Compute's `/io` lists them top to bottom).
    pub canvas_y: f64,
}

/// What became of one object.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Outcome {
    /// Mapped onto a node.
    Mapped(NodeId),
    /// A pass-through parameter: its wires were joined across it.
    PassThrough,
    /// Dropped with a remark (display-only objects).
    Dropped,
    /// Ignored (groups, scribbles, sketches).
    Ignored,
    /// Cannot run: a short kind (`script`, `plugin`, `component`, `cluster`, `hops`).
    Unsupported(&'static str),
}

/// One problem or remark of an import.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ImportDiagnostic {
    /// How bad it is.
    pub severity: Level,
    /// A stable code (`unsupported-script`, `no-data`, `port-name`, …).
    pub code: &'static str,
    /// The message, naming the object.
    pub message: String,
    /// The Grasshopper object.
    pub object: Option<ObjectRef>,
    /// The locus node, when the object was mapped.
    pub node: Option<NodeId>,
    /// The port, when the diagnostic is about one.
    pub port: Option<String>,
}

impl std::fmt::Display for ImportDiagnostic {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}[{}]: {}", self.severity, self.code, self.message)
    }
}

/// The summary of an import.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Report {
    /// Each object with its outcome, in file order (clusters' objects after their cluster).
    pub objects: Vec<(ObjectRef, Outcome)>,
    /// The diagnostics, in file order.
    pub diagnostics: Vec<ImportDiagnostic>,
}

impl Report {
    /// Whether every object that computes something was mapped: the whole definition can run.
    pub fn runs_whole(&self) -> bool {
        !self
            .objects
            .iter()
            .any(|(_, o)| matches!(o, Outcome::Unsupported(_)))
    }

    /// The summary as text: counts, then the unsupported and dropped objects with reasons.
    pub fn summary(&self) -> String {
        let count =
            |f: &dyn Fn(&Outcome) -> bool| self.objects.iter().filter(|(_, o)| f(o)).count();
        let mut out = String::new();
        let _ = writeln!(out, "objects: {}", self.objects.len());
        let _ = writeln!(
            out,
            "mapped: {}",
            count(&|o| matches!(o, Outcome::Mapped(_)))
        );
        let _ = writeln!(
            out,
            "pass-through: {}",
            count(&|o| *o == Outcome::PassThrough)
        );
        let _ = writeln!(out, "dropped: {}", count(&|o| *o == Outcome::Dropped));
        let _ = writeln!(out, "ignored: {}", count(&|o| *o == Outcome::Ignored));
        let mut kinds: Vec<&'static str> = self
            .objects
            .iter()
            .filter_map(|(_, o)| match o {
                Outcome::Unsupported(k) => Some(*k),
                _ => None,
            })
            .collect();
        kinds.sort_unstable();
        let mut by_kind: Vec<(&str, usize)> = Vec::new();
        for k in kinds {
            match by_kind.last_mut() {
                Some((last, n)) if *last == k => *n += 1,
                _ => by_kind.push((k, 1)),
            }
        }
        let total: usize = by_kind.iter().map(|(_, n)| n).sum();
        let kinds: Vec<String> = by_kind.iter().map(|(k, n)| format!("{k} {n}")).collect();
        if kinds.is_empty() {
            let _ = writeln!(out, "unsupported: 0");
        } else {
            let _ = writeln!(out, "unsupported: {total} ({})", kinds.join(", "));
        }
        let _ = writeln!(
            out,
            "runs whole: {}",
            if self.runs_whole() { "yes" } else { "no" }
        );
        for d in &self.diagnostics {
            let _ = writeln!(out, "{d}");
        }
        out
    }
}

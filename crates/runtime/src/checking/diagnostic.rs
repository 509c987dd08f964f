//! Diagnostics: problems found while reading or checking a graph, with their place in the file.

use std::fmt;

use crate::{DataType, Modifier};

/// How serious a diagnostic is.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Severity {
    /// The graph cannot run.
    Error,
    /// The graph runs, but probably not as meant.
    Warning,
}

impl Severity {
    /// The lower-case name (`error`, `warning`).
    pub fn name(self) -> &'static str {
        match self {
            Severity::Error => "error",
            Severity::Warning => "warning",
        }
    }
}

/// A place in a graph file.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct Location {
    /// The 1-based line.
    pub line: usize,
    /// The 1-based column, counted in characters.
    pub column: usize,
    /// The byte offset from the start of the file.
    pub offset: usize,
}

/// Whether a port is an input or an output.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum PortDirection {
    /// An input.
    Input,
    /// An output.
    Output,
}

impl PortDirection {
    /// The lower-case name (`input`, `output`).
    pub fn name(self) -> &'static str {
        match self {
            PortDirection::Input => "input",
            PortDirection::Output => "output",
        }
    }
}

/// What is wrong. The `Display` text is the message printed after `error:`.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum DiagnosticKind {
    /// The text is not valid RON.
    Syntax {
        /// What the reader expected or found.
        message: String,
    },
    /// The RON is valid but is not a graph: a missing or unknown field, a value of the wrong
    /// kind, a duplicate key.
    Malformed {
        /// What is wrong.
        message: String,
    },
    /// The file declares a format version this build does not read.
    UnsupportedVersion {
        /// The version in the file.
        found: String,
    },
    /// A node id that cannot be used (empty, or with a dot or whitespace).
    InvalidNodeId {
        /// The id.
        node: String,
    },
    /// Two nodes have the same id.
    DuplicateNodeId {
        /// The id.
        node: String,
        /// The line of the first node with this id, when known.
        first_line: Option<usize>,
    },
    /// A node names a type the registry does not have.
    UnknownNodeType {
        /// The node.
        node: String,
        /// The type id it names.
        node_type: String,
        /// Registered ids close to it.
        suggestions: Vec<String>,
    },
    /// A port reference that is not of the form `node.port`.
    BadPortRef {
        /// Where it is used (`wire`, `named input "t"`).
        context: String,
        /// The text.
        text: String,
    },
    /// A wire or named input or output refers to a node that does not exist.
    UnknownNode {
        /// Where it is used.
        context: String,
        /// The node id.
        node: String,
    },
    /// A node has no port of that name.
    UnknownPort {
        /// The node.
        node: String,
        /// The node's type id.
        node_type: String,
        /// The port name.
        port: String,
        /// Whether an input or an output was looked for.
        direction: PortDirection,
        /// The valid names (nicknames).
        valid: Vec<String>,
    },
    /// A port reference names an input where an output is needed, or the reverse.
    WrongDirection {
        /// Where it is used (`wire source`, `named output "R"`).
        context: String,
        /// The node.
        node: String,
        /// The port.
        port: String,
        /// What the port is.
        found: PortDirection,
    },
    /// A wire whose data no cast can turn into the input's type.
    IncompatibleWire {
        /// The source, `node.port`.
        from: String,
        /// The target, `node.port`.
        to: String,
        /// The source port's type.
        from_type: DataType,
        /// The target port's type.
        to_type: DataType,
    },
    /// The same wire twice.
    DuplicateWire {
        /// The source, `node.port`.
        from: String,
        /// The target, `node.port`.
        to: String,
    },
    /// A required input with no wire, no value and no default.
    MissingInput {
        /// The node.
        node: String,
        /// The input.
        port: String,
    },
    /// A named graph input targets an input that has no value until a host sets it.
    UnsetGraphInput {
        /// The named input.
        name: String,
        /// The node.
        node: String,
        /// The input.
        port: String,
    },
    /// A value given for an input that is also wired, which Grasshopper ignores.
    ValueIgnored {
        /// The node.
        node: String,
        /// The input.
        port: String,
    },
    /// A value that does not parse as the input's type.
    BadValue {
        /// The node.
        node: String,
        /// The input.
        port: String,
        /// Why, such as `expected a point (x, y, z), found "abc"`.
        message: String,
    },
    /// A setting the node type does not have.
    UnknownSetting {
        /// The node.
        node: String,
        /// The setting.
        setting: String,
        /// The valid settings.
        valid: Vec<String>,
    },
    /// A setting value that does not parse as the setting's type.
    BadSetting {
        /// The node.
        node: String,
        /// The setting.
        setting: String,
        /// Why.
        message: String,
    },
    /// Variable input names given for a node type with fixed inputs, or invalid names.
    BadInputNames {
        /// The node.
        node: String,
        /// What is wrong.
        message: String,
    },
    /// A modifier on a port whose type (or direction) it does not apply to.
    ModifierNotApplicable {
        /// The node.
        node: String,
        /// The port.
        port: String,
        /// Whether the port is an input or an output.
        direction: PortDirection,
        /// The modifier.
        modifier: Modifier,
        /// The input's type.
        data_type: DataType,
    },
    /// Two modifiers that exclude each other (flatten, graft, simplify).
    ConflictingModifiers {
        /// The node.
        node: String,
        /// The port.
        port: String,
        /// Whether the port is an input or an output.
        direction: PortDirection,
        /// The first modifier.
        first: Modifier,
        /// The second modifier.
        second: Modifier,
    },
    /// More than one input of a node marked principal.
    SeveralPrincipalInputs {
        /// The node.
        node: String,
        /// The inputs marked principal.
        ports: Vec<String>,
    },
    /// Wires that form a cycle.
    Cycle {
        /// The nodes of the cycle in wire order; the first is repeated at the end.
        nodes: Vec<String>,
    },
    /// Two named inputs, or two named outputs, with the same name.
    DuplicateName {
        /// `input` or `output`.
        direction: PortDirection,
        /// The name.
        name: String,
    },
    /// An expected value for an output the graph does not declare.
    UnknownExpectedOutput {
        /// The name.
        name: String,
        /// The declared output names.
        valid: Vec<String>,
    },
    /// An expected value that does not parse as the output's type.
    BadExpected {
        /// The output name.
        name: String,
        /// Why.
        message: String,
    },
    /// A sub-graph node whose graph cannot be used: a `path` that cannot be read or is not
    /// allowed here, a nesting or size limit reached, a port it cannot take.
    SubGraph {
        /// The sub-graph node.
        node: String,
        /// What is wrong.
        message: String,
    },
    /// A graph file that includes itself, directly or through other files.
    SubGraphCycle {
        /// The sub-graph node that closes the chain.
        node: String,
        /// The files of the chain, the first repeated at the end.
        files: Vec<String>,
    },
}

fn quoted_list(items: &[String]) -> String {
    let quoted: Vec<String> = items.iter().map(|s| format!("\"{s}\"")).collect();
    quoted.join(", ")
}

impl fmt::Display for DiagnosticKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        use DiagnosticKind::*;
        match self {
            Syntax { message } => write!(f, "syntax error: {message}"),
            Malformed { message } => f.write_str(message),
            UnsupportedVersion { found } => write!(
                f,
                "unsupported format version {found} (this build reads version {})",
                crate::FORMAT_VERSION
            ),
            InvalidNodeId { node } => write!(
                f,
                "invalid node id \"{node}\" (ids are non-empty and have no dots, slashes, quotes \
                 or spaces; a slash separates a sub-graph's id from its nodes' ids)"
            ),
            DuplicateNodeId { node, first_line } => {
                write!(f, "duplicate node id \"{node}\"")?;
                match first_line {
                    Some(line) => write!(f, " (first used on line {line})"),
                    None => Ok(()),
                }
            }
            UnknownNodeType {
                node,
                node_type,
                suggestions,
            } => {
                write!(f, "unknown node type \"{node_type}\" on node \"{node}\"")?;
                if !suggestions.is_empty() {
                    write!(f, " (did you mean {}?)", quoted_list(suggestions))?;
                }
                Ok(())
            }
            BadPortRef { context, text } => {
                write!(f, "expected \"node.port\" in {context}, found \"{text}\"")
            }
            UnknownNode { context, node } => write!(f, "unknown node \"{node}\" in {context}"),
            UnknownPort {
                node,
                node_type,
                port,
                direction,
                valid,
            } => {
                let d = direction.name();
                write!(f, "unknown {d} \"{port}\" on node \"{node}\" (")?;
                if valid.is_empty() {
                    write!(f, "{node_type} has no {d}s)")
                } else {
                    write!(f, "{node_type} has {d}s {})", quoted_list(valid))
                }
            }
            WrongDirection {
                context,
                node,
                port,
                found,
            } => {
                let needed = match found {
                    PortDirection::Input => "an output",
                    PortDirection::Output => "an input",
                };
                write!(
                    f,
                    "{context} must be {needed}, but \"{node}.{port}\" is an {}",
                    found.name()
                )
            }
            IncompatibleWire {
                from,
                to,
                from_type,
                to_type,
            } => write!(
                f,
                "wire \"{from}\" → \"{to}\" has no cast from {from_type} to {to_type}"
            ),
            DuplicateWire { from, to } => write!(f, "duplicate wire \"{from}\" → \"{to}\""),
            MissingInput { node, port } => write!(
                f,
                "input \"{port}\" of node \"{node}\" has no wire, no value and no default"
            ),
            UnsetGraphInput { name, node, port } => write!(
                f,
                "named input \"{name}\" sets input \"{port}\" of node \"{node}\", which has no \
                 value until a host sets it"
            ),
            ValueIgnored { node, port } => write!(
                f,
                "the value of input \"{port}\" of node \"{node}\" is ignored because the input \
                 is wired"
            ),
            BadValue {
                node,
                port,
                message,
            } => write!(
                f,
                "bad value for input \"{port}\" of node \"{node}\": {message}"
            ),
            UnknownSetting {
                node,
                setting,
                valid,
            } => {
                write!(f, "unknown setting \"{setting}\" on node \"{node}\" ")?;
                if valid.is_empty() {
                    f.write_str("(it has no settings)")
                } else {
                    write!(f, "(settings: {})", quoted_list(valid))
                }
            }
            BadSetting {
                node,
                setting,
                message,
            } => write!(
                f,
                "bad value for setting \"{setting}\" of node \"{node}\": {message}"
            ),
            BadInputNames { node, message } => write!(f, "{message} on node \"{node}\""),
            ModifierNotApplicable {
                node,
                port,
                direction,
                modifier,
                data_type,
            } => {
                let d = direction.name();
                if *direction == PortDirection::Output && !modifier.applies_to_outputs() {
                    return write!(
                        f,
                        "modifier {} does not apply to output \"{port}\" of node \"{node}\" (it \
                         applies to inputs only)",
                        modifier.name()
                    );
                }
                let applies = match modifier {
                    Modifier::Invert => format!("Boolean {d}s"),
                    Modifier::Degrees => format!("Number {d}s"),
                    Modifier::Reparameterize => format!("Curve and Surface {d}s"),
                    _ => format!("every {d}"),
                };
                write!(
                    f,
                    "modifier {} does not apply to {d} \"{port}\" of node \"{node}\", which is \
                     of type {data_type} (it applies to {applies})",
                    modifier.name()
                )
            }
            ConflictingModifiers {
                node,
                port,
                direction,
                first,
                second,
            } => write!(
                f,
                "modifiers {} and {} exclude each other on {} \"{port}\" of node \"{node}\"",
                first.name(),
                second.name(),
                direction.name()
            ),
            SeveralPrincipalInputs { node, ports } => write!(
                f,
                "node \"{node}\" has more than one principal input ({})",
                quoted_list(ports)
            ),
            Cycle { nodes } => {
                let path: Vec<String> = nodes.iter().map(|n| format!("\"{n}\"")).collect();
                write!(f, "wires form a cycle: {}", path.join(" → "))
            }
            DuplicateName { direction, name } => {
                write!(f, "duplicate named {} \"{name}\"", direction.name())
            }
            UnknownExpectedOutput { name, valid } => {
                write!(f, "expected value for unknown output \"{name}\" ")?;
                if valid.is_empty() {
                    f.write_str("(the graph has no named outputs)")
                } else {
                    write!(f, "(outputs: {})", quoted_list(valid))
                }
            }
            SubGraph { node, message } => write!(f, "sub-graph \"{node}\": {message}"),
            SubGraphCycle { node, files } => write!(
                f,
                "sub-graph \"{node}\" includes itself: {}",
                files.join(" -> ")
            ),
            BadExpected { name, message } => {
                write!(f, "bad expected value for output \"{name}\": {message}")
            }
        }
    }
}

/// One problem in a graph: what, how serious, and where.
#[derive(Clone, Debug, PartialEq)]
pub struct Diagnostic {
    /// Error or warning.
    pub severity: Severity,
    /// What is wrong.
    pub kind: DiagnosticKind,
    /// Where in the file, when the graph was read from text.
    pub location: Option<Location>,
    /// The file the location is in, when it is not the file checked but one of its
    /// sub-graphs' (`parts/x.ron`, relative to the checked file's directory).
    pub file: Option<String>,
}

impl Diagnostic {
    /// An error without location.
    pub fn error(kind: DiagnosticKind) -> Self {
        Self {
            severity: Severity::Error,
            kind,
            location: None,
            file: None,
        }
    }

    /// A warning without location.
    pub fn warning(kind: DiagnosticKind) -> Self {
        Self {
            severity: Severity::Warning,
            kind,
            location: None,
            file: None,
        }
    }

    /// Whether this is an error.
    pub fn is_error(&self) -> bool {
        self.severity == Severity::Error
    }

    /// The message, without location and severity.
    pub fn message(&self) -> String {
        self.kind.to_string()
    }

    /// The node the diagnostic is about, if it is about one.
    pub fn node(&self) -> Option<&str> {
        use DiagnosticKind::*;
        match &self.kind {
            InvalidNodeId { node }
            | DuplicateNodeId { node, .. }
            | UnknownNodeType { node, .. }
            | UnknownNode { node, .. }
            | UnknownPort { node, .. }
            | WrongDirection { node, .. }
            | MissingInput { node, .. }
            | UnsetGraphInput { node, .. }
            | ValueIgnored { node, .. }
            | BadValue { node, .. }
            | UnknownSetting { node, .. }
            | BadSetting { node, .. }
            | BadInputNames { node, .. }
            | ModifierNotApplicable { node, .. }
            | ConflictingModifiers { node, .. }
            | SeveralPrincipalInputs { node, .. }
            | SubGraph { node, .. }
            | SubGraphCycle { node, .. } => Some(node),
            Cycle { nodes } => nodes.first().map(String::as_str),
            _ => None,
        }
    }

    /// The port the diagnostic is about, if it is about one.
    pub fn port(&self) -> Option<&str> {
        use DiagnosticKind::*;
        match &self.kind {
            UnknownPort { port, .. }
            | WrongDirection { port, .. }
            | MissingInput { port, .. }
            | UnsetGraphInput { port, .. }
            | ValueIgnored { port, .. }
            | BadValue { port, .. }
            | ModifierNotApplicable { port, .. }
            | ConflictingModifiers { port, .. } => Some(port),
            _ => None,
        }
    }

    /// The diagnostic of a sub-graph's checking, seen from the graph that includes it as node
    /// `node`: the node ids it names become nested ids (`node/inner`), and `file` (the
    /// sub-graph's file, when it has one of its own) becomes its file unless it has a deeper one.
    pub(crate) fn nest(mut self, node: &str, file: Option<&str>) -> Self {
        use DiagnosticKind::*;
        let id = |s: &mut String| *s = format!("{node}/{s}");
        match &mut self.kind {
            InvalidNodeId { node }
            | DuplicateNodeId { node, .. }
            | UnknownNodeType { node, .. }
            | UnknownNode { node, .. }
            | UnknownPort { node, .. }
            | WrongDirection { node, .. }
            | MissingInput { node, .. }
            | UnsetGraphInput { node, .. }
            | ValueIgnored { node, .. }
            | BadValue { node, .. }
            | UnknownSetting { node, .. }
            | BadSetting { node, .. }
            | BadInputNames { node, .. }
            | ModifierNotApplicable { node, .. }
            | ConflictingModifiers { node, .. }
            | SeveralPrincipalInputs { node, .. }
            | SubGraph { node, .. }
            | SubGraphCycle { node, .. } => id(node),
            IncompatibleWire { from, to, .. } | DuplicateWire { from, to } => {
                id(from);
                id(to);
            }
            Cycle { nodes } => nodes.iter_mut().for_each(id),
            _ => {}
        }
        self.file = match (self.file.take(), file) {
            (Some(inner), Some(outer)) => Some(relative_to_file(outer, &inner)),
            (None, Some(outer)) => Some(outer.to_owned()),
            (inner, None) => inner,
        };
        self
    }

    /// A printable form that starts with the file name: `graph.ron:12:5: error: …`.
    pub fn display_in<'a>(&'a self, file: &'a str) -> impl fmt::Display + 'a {
        InFile {
            diagnostic: self,
            file,
        }
    }
}

impl fmt::Display for Diagnostic {
    /// Prints `12:5: error: message`, or `error: message` without location.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match (&self.file, self.location) {
            (Some(file), Some(l)) => write!(f, "{file}:{}:{}: ", l.line, l.column)?,
            (Some(file), None) => write!(f, "{file}: ")?,
            (None, Some(l)) => write!(f, "{}:{}: ", l.line, l.column)?,
            (None, None) => {}
        }
        write!(f, "{}: {}", self.severity.name(), self.kind)
    }
}

/// `path`, given relative to the directory of `file`, as a path like `file` (`a/b.ron` and
/// `parts/c.ron` give `a/parts/c.ron`).
fn relative_to_file(file: &str, path: &str) -> String {
    match std::path::Path::new(file).parent() {
        Some(dir) if !dir.as_os_str().is_empty() => dir.join(path).display().to_string(),
        _ => path.to_owned(),
    }
}

struct InFile<'a> {
    diagnostic: &'a Diagnostic,
    file: &'a str,
}

impl fmt::Display for InFile<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let d = self.diagnostic;
        match (&d.file, d.location) {
            // A sub-graph file's diagnostic names that file, relative to the checked one's
            // directory.
            (Some(sub), _) => {
                let mut d = d.clone();
                d.file = Some(relative_to_file(self.file, sub));
                write!(f, "{d}")
            }
            (None, Some(_)) => write!(f, "{}:{}", self.file, d),
            (None, None) => write!(f, "{}: {}", self.file, d),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn prints_with_file_line_and_column() {
        let mut d = Diagnostic::error(DiagnosticKind::UnknownNodeType {
            node: "d1".into(),
            node_type: "vector.dot".into(),
            suggestions: vec!["vector.dot_product".into()],
        });
        d.location = Some(Location {
            line: 12,
            column: 5,
            offset: 200,
        });
        assert_eq!(
            d.display_in("graph.ron").to_string(),
            "graph.ron:12:5: error: unknown node type \"vector.dot\" on node \"d1\" (did you \
             mean \"vector.dot_product\"?)"
        );
        d.location = None;
        assert_eq!(
            d.display_in("g.ron").to_string(),
            format!("g.ron: error: {}", d.kind)
        );
        assert_eq!(d.node(), Some("d1"));
    }
}

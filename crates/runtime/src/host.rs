//! The host API: loading a graph from text or a file, setting named inputs from data trees or
//! literal text, and reading results. See the crate docs for a complete example.

use std::path::{Path, PathBuf};

use crate::{
    Checked, DataType, Diagnostic, Document, EvalError, Evaluator, NodeRegistry, parse_literal,
};

/// Why a graph file could not be loaded.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum LoadError {
    /// The file could not be read.
    #[error("cannot read {}: {message}", path.display())]
    Io {
        /// The file.
        path: PathBuf,
        /// The operating system's reason.
        message: String,
    },
    /// The text is not a valid graph, or checking found errors: every diagnostic (errors and
    /// warnings, in file order), each with its line and column.
    #[error("the graph has {} error(s); the first: {}", count_errors(.0), first_error(.0))]
    Invalid(Vec<Diagnostic>),
}

fn count_errors(d: &[Diagnostic]) -> usize {
    d.iter()
        .filter(|d| d.severity == crate::Severity::Error)
        .count()
}

fn first_error(d: &[Diagnostic]) -> String {
    d.iter()
        .find(|d| d.severity == crate::Severity::Error)
        .map(ToString::to_string)
        .unwrap_or_default()
}

/// Reads and checks a graph file.
///
/// # Errors
/// [`LoadError::Io`] when the file cannot be read, [`LoadError::Invalid`] with every diagnostic
/// when it is not a valid graph.
pub fn load_file(path: impl AsRef<Path>, registry: &NodeRegistry) -> Result<Checked, LoadError> {
    let path = path.as_ref();
    let text = crate::read_graph_file(path, crate::MAX_GRAPH_FILE_BYTES).map_err(|message| {
        LoadError::Io {
            path: path.to_owned(),
            message,
        }
    })?;
    Document::parse(&text)
        .and_then(|doc| doc.with_origin(path).check(registry))
        .map_err(LoadError::Invalid)
}

impl Checked {
    /// An evaluator for the checked plan (the warnings are dropped; read them first).
    pub fn into_evaluator(self) -> Evaluator {
        Evaluator::new(self.plan)
    }
}

impl Evaluator {
    /// Reads and checks a graph and makes an evaluator for it.
    ///
    /// # Errors
    /// Every diagnostic (with line and column) when the text is not a valid graph.
    pub fn from_text(text: &str, registry: &NodeRegistry) -> Result<Self, Vec<Diagnostic>> {
        Ok(Document::parse(text)?.check(registry)?.into_evaluator())
    }

    /// Reads and checks a graph file and makes an evaluator for it.
    ///
    /// # Errors
    /// As [`load_file`].
    pub fn from_file(path: impl AsRef<Path>, registry: &NodeRegistry) -> Result<Self, LoadError> {
        Ok(load_file(path, registry)?.into_evaluator())
    }

    /// The type of a named input (the type of the port it sets).
    pub fn input_type(&self, name: &str) -> Option<DataType> {
        let plan = self.plan();
        let &(_, node, port) = plan.inputs.iter().find(|(n, _, _)| n == name)?;
        Some(plan.nodes[node].inputs[port].port.data_type)
    }

    /// Gives a named input a value written as a literal (`"(1, 2, 3)"`, `"[1, 2, 3]"`,
    /// `"{\"{0;1}\": [1, 2]}"`), read against the input's type as the `--set` option of the
    /// command line does; see `docs/graph-format.md` for the forms.
    ///
    /// # Errors
    /// [`EvalError::UnknownInput`] when the graph has no input of that name;
    /// [`EvalError::BadValue`] naming the input when the text is not a value of its type.
    pub fn set_input_text(&mut self, name: &str, literal: &str) -> Result<(), EvalError> {
        let Some(data_type) = self.input_type(name) else {
            return Err(self.unknown_input(name));
        };
        if literal.len() > crate::MAX_TEXT_BYTES {
            return Err(EvalError::BadValue {
                name: name.to_owned(),
                message: format!(
                    "the text is too long ({} bytes; the limit is {} bytes)",
                    literal.len(),
                    crate::MAX_TEXT_BYTES
                ),
            });
        }
        let tree = parse_literal(literal, data_type).map_err(|e| EvalError::BadValue {
            name: name.to_owned(),
            message: e.message,
        })?;
        self.set_input(name, tree)
    }
}

/// Hosts hold evaluators, plans and registries across threads: each is `Send` and `Sync`.
const _: () = {
    const fn assert_send_sync<T: Send + Sync>() {}
    assert_send_sync::<Evaluator>();
    assert_send_sync::<crate::Plan>();
    assert_send_sync::<NodeRegistry>();
    assert_send_sync::<crate::DataTree>();
    assert_send_sync::<Checked>();
};

//! Exceptions, diagnostics and runtime messages as Python objects.

use locus_runtime::{Diagnostic, Message};
use pyo3::exceptions::{PyException, PyValueError};
use pyo3::prelude::*;
use pyo3::types::PyList;

pyo3::create_exception!(
    locus,
    GraphError,
    PyException,
    "A graph that does not read or check. `diagnostics` lists every problem (a list of \
     `Diagnostic`, errors and warnings in file order, with line and column)."
);

pyo3::create_exception!(
    locus,
    InputError,
    PyValueError,
    "A value that cannot be given to a graph input: an unknown input name, a Python object \
     with no locus form, or items that do not cast to the input's type (the message names the \
     input, path and item)."
);

/// A problem found while reading or checking a graph.
#[pyclass(module = "locus", name = "Diagnostic", frozen, get_all)]
#[derive(Clone, Debug)]
pub struct PyDiagnostic {
    /// `"error"` or `"warning"`.
    pub severity: &'static str,
    /// What is wrong.
    pub message: String,
    /// The 1-based line in the graph text, if known.
    pub line: Option<usize>,
    /// The 1-based column in the graph text, if known.
    pub column: Option<usize>,
    /// The node it is about, if any.
    pub node: Option<String>,
    /// The port it is about, if any.
    pub port: Option<String>,
    text: String,
}

impl From<&Diagnostic> for PyDiagnostic {
    fn from(d: &Diagnostic) -> Self {
        Self {
            severity: d.severity.name(),
            message: d.message(),
            line: d.location.map(|l| l.line),
            column: d.location.map(|l| l.column),
            node: d.node().map(str::to_owned),
            port: d.port().map(str::to_owned),
            text: d.to_string(),
        }
    }
}

#[pymethods]
impl PyDiagnostic {
    fn __str__(&self) -> &str {
        &self.text
    }

    fn __repr__(&self) -> String {
        format!("Diagnostic({:?})", self.text)
    }
}

/// A remark, warning or error that a node reported while the graph ran.
#[pyclass(module = "locus", name = "Message", frozen, get_all)]
#[derive(Clone, Debug)]
pub struct PyMessage {
    /// The node's id.
    pub node: String,
    /// `"remark"`, `"warning"` or `"error"`.
    pub level: &'static str,
    /// The output path of the iteration (`"{0;1}"`), if it came from one.
    pub path: Option<String>,
    /// The item index within that branch, if it came from an item iteration.
    pub index: Option<usize>,
    /// What happened.
    pub text: String,
    full: String,
}

impl From<&Message> for PyMessage {
    fn from(m: &Message) -> Self {
        Self {
            node: m.node.0.clone(),
            level: m.level.name(),
            path: m.path.as_ref().map(ToString::to_string),
            index: m.index,
            text: m.text.clone(),
            full: m.to_string(),
        }
    }
}

#[pymethods]
impl PyMessage {
    fn __str__(&self) -> &str {
        &self.full
    }

    fn __repr__(&self) -> String {
        format!("Message({:?})", self.full)
    }
}

/// A `GraphError` listing the diagnostics (each prefixed with `file` when given).
pub(crate) fn graph_error(py: Python<'_>, diagnostics: &[Diagnostic], file: Option<&str>) -> PyErr {
    let errors = diagnostics.iter().filter(|d| d.is_error()).count();
    let mut text = format!("the graph has {errors} error(s)");
    for d in diagnostics {
        text.push('\n');
        match file {
            Some(f) => text.push_str(&d.display_in(f).to_string()),
            None => text.push_str(&d.to_string()),
        }
    }
    let err = GraphError::new_err(text);
    let list = PyList::new(py, diagnostics.iter().map(PyDiagnostic::from));
    if let Ok(list) = list {
        // Setting an attribute on a fresh exception instance does not fail.
        let _ = err.value(py).setattr("diagnostics", list);
    }
    err
}

/// A `GraphError` with a plain message and no diagnostics.
pub(crate) fn graph_error_message(py: Python<'_>, message: String) -> PyErr {
    let err = GraphError::new_err(message);
    let _ = err.value(py).setattr("diagnostics", PyList::empty(py));
    err
}

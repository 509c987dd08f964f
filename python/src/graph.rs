//! `locus.Graph`: a checked graph with the whole node library, its named inputs and outputs,
//! evaluation without the GIL, and results as Python values.

use std::path::PathBuf;
use std::sync::OnceLock;

use locus_runtime::{
    Access, DataTree, DataType, Diagnostic, Document, EvalError, Evaluator, NodeRegistry,
    cast_tree, parse_literal,
};
use pyo3::exceptions::{PyKeyError, PyOSError, PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList, PyTuple};

use crate::convert::{tree_from_py, tree_to_dict, tree_to_numpy, tree_to_py};
use crate::errors::{InputError, PyDiagnostic, PyMessage, graph_error, graph_error_message};

/// The runtime's thread count for the Python setting: 0 is one thread per core (the runtime
/// itself takes only counts of at least 1).
fn thread_count(threads: usize) -> usize {
    if threads == 0 {
        std::thread::available_parallelism().map_or(1, usize::from)
    } else {
        threads
    }
}

/// The interpreter that imported this module (`sys.executable`), which runs script nodes.
static INTERPRETER: OnceLock<String> = OnceLock::new();

/// Records the interpreter that runs script nodes (called once, when the module is imported).
pub(crate) fn set_interpreter(executable: String) {
    let _ = INTERPRETER.set(executable);
}

/// The node library, registered once per process. Script nodes run in worker processes of
/// this very interpreter (so with this `locus` package), unless `$LOCUS_PYTHON` names another.
pub(crate) fn registry() -> &'static NodeRegistry {
    static REGISTRY: OnceLock<NodeRegistry> = OnceLock::new();
    REGISTRY.get_or_init(|| {
        let mut registry = NodeRegistry::new();
        locus_nodes::register(&mut registry);
        let from_env =
            std::env::var_os(locus_nodes::script::PYTHON_ENV).is_some_and(|p| !p.is_empty());
        let config = match INTERPRETER.get() {
            Some(exe) if !exe.is_empty() && !from_env => {
                locus_nodes::script::PythonConfig::Interpreter(exe.into())
            }
            _ => locus_nodes::script::PythonConfig::FromEnvironment,
        };
        registry.register(locus_nodes::script::python(config));
        registry
    })
}

/// A named input or output of a graph, with its type and where it is wired.
#[pyclass(module = "locus", name = "Port", frozen, get_all)]
#[derive(Debug)]
pub struct PyPort {
    /// The name hosts use (`g.set(name, ...)`, `g[name]`).
    pub name: String,
    /// `"input"` or `"output"`.
    pub direction: &'static str,
    /// The value type (`"Number"`, `"Point"`, `"Curve"`, ...; `"Generic"` for any).
    #[pyo3(name = "type")]
    pub data_type: &'static str,
    /// `"item"`, `"list"` or `"tree"`: how the node reads it (inputs).
    pub access: &'static str,
    /// Whether an input may be left without data.
    pub optional: bool,
    /// What the port means (from the node library).
    pub description: String,
    /// The id of the node it belongs to.
    pub node: String,
    /// The node's type (`"params.number"`, ...).
    pub node_type: String,
    /// The port's nickname on that node.
    pub port: String,
    /// For an input, the value the graph gives it (or the port's default), else `None`.
    pub default: Py<PyAny>,
}

#[pymethods]
impl PyPort {
    fn __repr__(&self) -> String {
        format!(
            "Port({:?}, {}, type={:?}, node={:?}, port={:?})",
            self.name, self.direction, self.data_type, self.node, self.port
        )
    }
}

fn access_name(access: Access) -> &'static str {
    match access {
        Access::Item => "item",
        Access::List => "list",
        Access::Tree => "tree",
    }
}

/// A graph ready to evaluate, with the whole node library.
///
/// ```python
/// g = locus.Graph.load("graphs/tangent_spheres.ron")
/// g.set("t", 0.3)
/// g.evaluate()          # releases the GIL while the graph runs
/// g["r1"], g["S1"], g.messages
/// ```
#[pyclass(module = "locus", name = "Graph")]
#[derive(Debug)]
pub struct PyGraph {
    evaluator: Evaluator,
    text: String,
    path: Option<PathBuf>,
    name: String,
    description: String,
    warnings: Vec<Diagnostic>,
    /// Inputs given by the host, in the order first set (for `copy` and pickling).
    set_inputs: Vec<(String, DataTree)>,
    threads: usize,
    stale: bool,
}

impl PyGraph {
    fn build(py: Python<'_>, text: String, path: Option<PathBuf>) -> PyResult<Self> {
        let file = path.as_ref().map(|p| p.display().to_string());
        let mut document =
            Document::parse(&text).map_err(|d| graph_error(py, &d, file.as_deref()))?;
        // Sub-graph `path:`s are relative to the graph's own file.
        if let Some(p) = &path {
            document = document.with_origin(p.clone());
        }
        let name = document.graph().name.clone();
        let description = document.graph().description.clone();
        let checked = document
            .check(registry())
            .map_err(|d| graph_error(py, &d, file.as_deref()))?;
        let warnings = checked.warnings.clone();
        Ok(Self {
            evaluator: checked.into_evaluator(),
            text,
            path,
            name,
            description,
            warnings,
            set_inputs: Vec::new(),
            threads: 0,
            stale: true,
        })
    }

    fn input_type(&self, name: &str) -> PyResult<DataType> {
        self.evaluator.input_type(name).ok_or_else(|| {
            let known: Vec<&str> = self.evaluator.input_names().collect();
            InputError::new_err(format!(
                "unknown input \"{name}\" (the graph's inputs are: {})",
                if known.is_empty() {
                    "none".to_owned()
                } else {
                    known.join(", ")
                }
            ))
        })
    }

    /// Sets an input to a tree already of (or castable to) its type.
    fn set_tree(&mut self, name: &str, data_type: DataType, tree: DataTree) -> PyResult<()> {
        let tree = if data_type == DataType::Generic {
            tree
        } else {
            let (cast, failures) = cast_tree(&tree, data_type);
            if let Some((path, index, error)) = failures.first() {
                let more = match failures.len() {
                    1 => String::new(),
                    n => format!(" (and {} more items)", n - 1),
                };
                return Err(InputError::new_err(format!(
                    "input \"{name}\": {path}[{index}]: {error}{more}"
                )));
            }
            cast
        };
        self.evaluator
            .set_input(name, tree.clone())
            .map_err(|e| InputError::new_err(e.to_string()))?;
        match self.set_inputs.iter_mut().find(|(n, _)| n == name) {
            Some((_, t)) => *t = tree,
            None => self.set_inputs.push((name.to_owned(), tree)),
        }
        self.stale = true;
        Ok(())
    }

    fn ensure_evaluated(&mut self, py: Python<'_>) {
        if self.stale {
            self.evaluate(py);
        }
    }

    fn output_tree(&self, name: &str) -> PyResult<&DataTree> {
        self.evaluator.output(name).ok_or_else(|| {
            let known: Vec<&str> = self.evaluator.output_names().collect();
            PyKeyError::new_err(format!(
                "unknown output \"{name}\" (the graph's outputs are: {})",
                if known.is_empty() {
                    "none".to_owned()
                } else {
                    known.join(", ")
                }
            ))
        })
    }

    fn port_infos<'py>(&self, py: Python<'py>, inputs: bool) -> PyResult<Bound<'py, PyDict>> {
        let plan = self.evaluator.plan();
        let dict = PyDict::new(py);
        let named = if inputs { &plan.inputs } else { &plan.outputs };
        for (name, node, port) in named {
            let plan_node = &plan.nodes[*node];
            let (p, default) = if inputs {
                let input = &plan_node.inputs[*port];
                let default = match &input.value {
                    Some(tree) => tree_to_py(py, tree)?.unbind(),
                    None => py.None(),
                };
                (&input.port, default)
            } else {
                (&plan_node.node_type.outputs[*port], py.None())
            };
            let info = PyPort {
                name: name.clone(),
                direction: if inputs { "input" } else { "output" },
                data_type: p.data_type.name(),
                access: access_name(p.access),
                optional: p.optional,
                description: p.description.clone(),
                node: plan_node.id.0.clone(),
                node_type: plan_node.node_type.id.clone(),
                port: p.nickname.clone(),
                default,
            };
            dict.set_item(name, Bound::new(py, info)?)?;
        }
        Ok(dict)
    }
}

#[pymethods]
impl PyGraph {
    /// Reads and checks a graph file (`.ron`). `GraphError` lists every problem with its line
    /// and column; `OSError` when the file cannot be read.
    #[staticmethod]
    fn load(py: Python<'_>, path: PathBuf) -> PyResult<Self> {
        if let Some(ext) = path.extension().and_then(|e| e.to_str())
            && (ext.eq_ignore_ascii_case("gh") || ext.eq_ignore_ascii_case("ghx"))
        {
            return Err(graph_error_message(
                py,
                format!(
                    "{}: Grasshopper files are not read yet; this version reads locus graphs \
                     (.ron)",
                    path.display()
                ),
            ));
        }
        let text = std::fs::read_to_string(&path)
            .map_err(|e| PyOSError::new_err(format!("cannot read {}: {e}", path.display())))?;
        Self::build(py, text, Some(path))
    }

    /// Reads and checks a graph from its text.
    #[staticmethod]
    fn from_text(py: Python<'_>, text: String) -> PyResult<Self> {
        Self::build(py, text, None)
    }

    /// A graph restored from its text and inputs (used by pickling).
    #[staticmethod]
    #[pyo3(signature = (text, path, inputs, threads=0))]
    fn _restore(
        py: Python<'_>,
        text: String,
        path: Option<PathBuf>,
        inputs: Vec<(String, Bound<'_, PyAny>)>,
        threads: usize,
    ) -> PyResult<Self> {
        let mut graph = Self::build(py, text, path)?;
        for (name, value) in inputs {
            graph.set(&name, &value)?;
        }
        graph.set_threads(threads)?;
        Ok(graph)
    }

    /// The graph's text (what is shipped to sweep workers).
    #[getter]
    fn text(&self) -> &str {
        &self.text
    }

    /// The file it was loaded from, if any.
    #[getter]
    fn path(&self) -> Option<PathBuf> {
        self.path.clone()
    }

    /// The graph's name.
    #[getter]
    fn name(&self) -> &str {
        &self.name
    }

    /// The graph's description.
    #[getter]
    fn description(&self) -> &str {
        &self.description
    }

    /// The named inputs: a dict from name to `Port` (type, access, node, default, ...).
    #[getter]
    fn inputs<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        self.port_infos(py, true)
    }

    /// The named outputs: a dict from name to `Port`.
    #[getter]
    fn outputs<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        self.port_infos(py, false)
    }

    /// Warnings found while checking (the graph runs despite them).
    #[getter]
    fn warnings(&self) -> Vec<PyDiagnostic> {
        self.warnings.iter().map(PyDiagnostic::from).collect()
    }

    /// How many threads an evaluation may use (0: one per core, the default; 1: the calling
    /// thread only, best when Python threads or processes evaluate several graphs at once).
    #[getter]
    fn threads(&self) -> usize {
        self.threads
    }

    #[setter]
    fn set_threads(&mut self, threads: usize) -> PyResult<()> {
        self.evaluator
            .set_threads(thread_count(threads))
            .map_err(|e| PyValueError::new_err(e.to_string()))?;
        self.threads = threads;
        Ok(())
    }

    /// Gives a named input a value (see the module docs for the conversions). The items are
    /// cast to the input's type now, so a value that does not fit raises `InputError` naming
    /// the input, path and item.
    fn set(&mut self, name: &str, value: &Bound<'_, PyAny>) -> PyResult<()> {
        let data_type = self.input_type(name)?;
        let tree = tree_from_py(value, data_type)
            .map_err(|e| InputError::new_err(format!("input \"{name}\": {}", e.0)))?;
        self.set_tree(name, data_type, tree)
    }

    /// Gives a named input a value written as in graph files (`"(1, 2, 3)"`, `"[1, 2]"`,
    /// `"{\"{0;1}\": [1, 2]}"`), as `locus run --set` does.
    fn set_text(&mut self, name: &str, literal: &str) -> PyResult<()> {
        let data_type = self.input_type(name)?;
        let tree = parse_literal(literal, data_type).map_err(|e| {
            InputError::new_err(
                EvalError::BadValue {
                    name: name.to_owned(),
                    message: e.message,
                }
                .to_string(),
            )
        })?;
        self.set_tree(name, data_type, tree)
    }

    /// Goes back to the graph's own value for an input.
    fn clear(&mut self, name: &str) -> PyResult<()> {
        self.input_type(name)?;
        self.evaluator.clear_input(name);
        self.set_inputs.retain(|(n, _)| n != name);
        self.stale = true;
        Ok(())
    }

    /// Runs the nodes whose inputs changed since the last evaluation (all of them the first
    /// time). The GIL is released meanwhile, so other Python threads run, and other graphs can
    /// evaluate on them at the same time.
    fn evaluate(&mut self, py: Python<'_>) {
        let evaluator = &mut self.evaluator;
        py.detach(move || evaluator.evaluate());
        self.stale = false;
    }

    /// A named output in its simplest form: the item for one item, a list for one branch
    /// `{0}`, a dict `{"{0;1}": [...]}` otherwise, `None` when empty. Evaluates first if an
    /// input changed.
    fn __getitem__(&mut self, py: Python<'_>, name: &str) -> PyResult<Py<PyAny>> {
        self.ensure_evaluated(py);
        let tree = self.output_tree(name)?;
        Ok(tree_to_py(py, tree)?.unbind())
    }

    fn __contains__(&self, name: &str) -> bool {
        self.evaluator.output_names().any(|n| n == name)
    }

    /// A named output as a dict from path text to lists of items, whatever its shape.
    fn tree<'py>(&mut self, py: Python<'py>, name: &str) -> PyResult<Bound<'py, PyDict>> {
        self.ensure_evaluated(py);
        tree_to_dict(py, self.output_tree(name)?)
    }

    /// A named output's items (all branches in order) as one numpy array: numbers and
    /// integers `(N,)`, booleans `(N,)`, points and vectors `(N, 3)`; nulls are NaN in float
    /// arrays. The typed column is copied once into the array, with no Python object per item.
    fn array<'py>(&mut self, py: Python<'py>, name: &str) -> PyResult<Bound<'py, PyAny>> {
        self.ensure_evaluated(py);
        let tree = self.output_tree(name)?;
        let plan = self.evaluator.plan();
        let declared = plan
            .outputs
            .iter()
            .find(|(n, _, _)| n == name)
            .map_or(DataType::Generic, |&(_, node, port)| {
                plan.nodes[node].node_type.outputs[port].data_type
            });
        tree_to_numpy(py, tree, declared)
            .map_err(|m| PyTypeError::new_err(format!("output \"{name}\" has no numpy form: {m}")))
    }

    /// Every named output (or those in `names`) in its simplest form, as a dict.
    #[pyo3(signature = (names=None))]
    fn results<'py>(
        &mut self,
        py: Python<'py>,
        names: Option<Vec<String>>,
    ) -> PyResult<Bound<'py, PyDict>> {
        self.ensure_evaluated(py);
        let names: Vec<String> = match names {
            Some(n) => n,
            None => self.evaluator.output_names().map(str::to_owned).collect(),
        };
        let dict = PyDict::new(py);
        for name in names {
            let tree = self.output_tree(&name)?;
            dict.set_item(&name, tree_to_py(py, tree)?)?;
        }
        Ok(dict)
    }

    /// The messages of the last evaluation, in node order.
    #[getter]
    fn messages(&self) -> Vec<PyMessage> {
        self.evaluator.messages().map(PyMessage::from).collect()
    }

    /// The ids of the nodes the last evaluation ran.
    #[getter]
    fn last_run(&self) -> Vec<String> {
        self.evaluator
            .last_run()
            .iter()
            .map(|id| id.0.clone())
            .collect()
    }

    /// An independent graph with the same text, inputs and threads (not yet evaluated).
    fn copy(&self) -> PyResult<Self> {
        let mut evaluator = Evaluator::new(self.evaluator.plan().clone());
        evaluator
            .set_threads(thread_count(self.threads))
            .map_err(|e| PyValueError::new_err(e.to_string()))?;
        for (name, tree) in &self.set_inputs {
            evaluator
                .set_input(name, tree.clone())
                .map_err(|e| InputError::new_err(e.to_string()))?;
        }
        Ok(Self {
            evaluator,
            text: self.text.clone(),
            path: self.path.clone(),
            name: self.name.clone(),
            description: self.description.clone(),
            warnings: self.warnings.clone(),
            set_inputs: self.set_inputs.clone(),
            threads: self.threads,
            stale: true,
        })
    }

    fn __repr__(&self) -> String {
        let inputs: Vec<&str> = self.evaluator.input_names().collect();
        let outputs: Vec<&str> = self.evaluator.output_names().collect();
        format!(
            "Graph({:?}, inputs={inputs:?}, outputs={outputs:?})",
            self.name
        )
    }

    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<Bound<'py, PyTuple>> {
        let py = slf.py();
        let g = slf.borrow();
        let inputs = PyList::empty(py);
        for (name, tree) in &g.set_inputs {
            inputs.append((name, tree_to_dict(py, tree)?))?;
        }
        let restore = slf.get_type().getattr("_restore")?;
        (restore, (g.text.clone(), g.path.clone(), inputs, g.threads)).into_pyobject(py)
    }
}

//! The Python side of script nodes: the worker's requests as Python objects and its replies
//! as bytes, through the same protocol code as the engine (`locus_nodes::script`), and
//! `locus.call`, one node of the library on Python values (what the GhPython compatibility
//! layer computes with).

use locus_nodes::script::protocol::{
    InputData, OutputData, PROTOCOL_VERSION, Reply, Request, SharedData,
};
use locus_runtime::{Access, DataTree, DataType, Level, NodeCall, Value, cast_value};
use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyBytes, PyDict, PyList, PyTuple};

use crate::convert::{tree_from_py, tree_to_dict, tree_to_py, value_to_py};
use crate::graph::registry;

fn access_name(access: Access) -> &'static str {
    match access {
        Access::Item => "item",
        Access::List => "list",
        Access::Tree => "tree",
    }
}

fn reply_bytes<'py>(py: Python<'py>, reply: &Reply) -> PyResult<Bound<'py, PyBytes>> {
    let bytes = reply.encode().map_err(PyValueError::new_err)?;
    Ok(PyBytes::new(py, &bytes))
}

/// The worker's first message: the protocol it speaks, the package and Python versions.
#[pyfunction]
pub(crate) fn _script_hello<'py>(
    py: Python<'py>,
    version: &str,
    python: &str,
) -> PyResult<Bound<'py, PyBytes>> {
    reply_bytes(
        py,
        &Reply::Hello {
            protocol: PROTOCOL_VERSION,
            version: version.to_owned(),
            python: python.to_owned(),
        },
    )
}

/// A reply saying that a request could not be run at all.
#[pyfunction]
pub(crate) fn _script_fatal<'py>(py: Python<'py>, why: &str) -> PyResult<Bound<'py, PyBytes>> {
    reply_bytes(py, &Reply::Fatal(why.to_owned()))
}

/// A request as a dict: `code`, `ghpython`, `time_limit`, `inputs` (a list of
/// `(name, access, hint)`), `outputs` (names), `shared` (lists and dicts of paths) and
/// `iterations` (per iteration, per input: `(False, item)` or `(True, index into shared)`).
#[pyfunction]
pub(crate) fn _script_read_request<'py>(
    py: Python<'py>,
    data: &[u8],
) -> PyResult<Bound<'py, PyDict>> {
    let request = Request::decode(data).map_err(|e| PyValueError::new_err(e.0))?;
    let d = PyDict::new(py);
    d.set_item("node", &request.node)?;
    d.set_item("code", &request.code)?;
    d.set_item("ghpython", request.ghpython)?;
    d.set_item("time_limit", request.time_limit)?;
    let inputs = PyList::empty(py);
    for i in &request.inputs {
        inputs.append((&i.name, access_name(i.access), &i.hint))?;
    }
    d.set_item("inputs", inputs)?;
    d.set_item("outputs", &request.outputs)?;
    let shared = PyList::empty(py);
    for s in &request.shared {
        match s {
            SharedData::List(items) => {
                let list = PyList::empty(py);
                for v in items {
                    match v {
                        Some(v) => list.append(value_to_py(py, v)?)?,
                        None => list.append(py.None())?,
                    }
                }
                shared.append(list)?;
            }
            SharedData::Tree(tree) => shared.append(tree_to_dict(py, tree)?)?,
        }
    }
    d.set_item("shared", shared)?;
    let iterations = PyList::empty(py);
    for iteration in &request.iterations {
        let row = PyList::empty(py);
        for data in iteration {
            match data {
                InputData::Item(Some(v)) => row.append((false, value_to_py(py, v)?))?,
                InputData::Item(None) => row.append((false, py.None()))?,
                InputData::Shared(k) => row.append((true, *k))?,
            }
        }
        iterations.append(row)?;
    }
    d.set_item("iterations", iterations)?;
    Ok(d)
}

fn item(obj: &Bound<'_, PyAny>, output: &str) -> PyResult<Option<Value>> {
    crate::convert::item_from_py(obj, DataType::Generic)
        .map_err(|e| PyTypeError::new_err(format!("output {output}: {e}")))
}

/// One output's value: `None` (not assigned), or `(kind, value)` with kind `"item"`, `"list"`
/// (a sequence of items) or `"tree"` (a dict of paths).
fn output_data(obj: &Bound<'_, PyAny>, output: &str) -> PyResult<OutputData> {
    if obj.is_none() {
        return Ok(OutputData::Unset);
    }
    let (kind, value): (String, Bound<'_, PyAny>) = obj.extract()?;
    Ok(match kind.as_str() {
        "item" => OutputData::Item(item(&value, output)?),
        "list" => {
            let mut items = Vec::new();
            for v in value.try_iter()? {
                items.push(item(&v?, output)?);
            }
            OutputData::List(items)
        }
        "tree" => OutputData::Tree(
            tree_from_py(&value, DataType::Generic)
                .map_err(|e| PyTypeError::new_err(format!("output {output}: {}", e.0)))?,
        ),
        other => {
            return Err(PyValueError::new_err(format!(
                "unknown output kind {other:?}"
            )));
        }
    })
}

/// The reply for one iteration: the outputs (per output, see `output_data`), what was printed,
/// the messages as `(level, text)` with level `"remark"`, `"warning"` or `"error"`, and the
/// error text. An output that does not convert raises `TypeError` naming it.
#[pyfunction]
#[pyo3(signature = (names, outputs, printed, messages, error=None))]
pub(crate) fn _script_done<'py>(
    py: Python<'py>,
    names: Vec<String>,
    outputs: Vec<Bound<'py, PyAny>>,
    printed: &str,
    messages: Vec<(String, String)>,
    error: Option<String>,
) -> PyResult<Bound<'py, PyBytes>> {
    let outputs = outputs
        .iter()
        .zip(
            names
                .iter()
                .map(String::as_str)
                .chain(std::iter::repeat("?")),
        )
        .map(|(o, name)| output_data(o, name))
        .collect::<PyResult<Vec<_>>>()?;
    let messages = messages
        .into_iter()
        .map(|(level, text)| {
            let level = match level.as_str() {
                "remark" => Level::Remark,
                "warning" => Level::Warning,
                _ => Level::Error,
            };
            (level, text)
        })
        .collect();
    reply_bytes(
        py,
        &Reply::Done(locus_nodes::script::protocol::Outcome {
            outputs,
            printed: printed.to_owned(),
            messages,
            error,
        }),
    )
}

/// Runs one node of the library on Python values and returns its outputs, in port order, each
/// in its simplest form (as `Graph.__getitem__` gives them): `locus.call("vector.distance",
/// (0, 0, 0), (3, 4, 0))` is `5.0`. A node with several outputs gives a tuple.
///
/// Inputs are given in port order, converted as `Graph.set` converts values (a list is a
/// branch, a dict of paths a tree); `None` leaves an input unset (its default). Settings are
/// keyword arguments (`expression="x*2"`). Items are iterated with Grasshopper's matching
/// rules, as in a graph. An error the node reports raises `ValueError` with its message.
#[pyfunction]
#[pyo3(signature = (node_type, *inputs, **settings))]
pub(crate) fn call<'py>(
    py: Python<'py>,
    node_type: &str,
    inputs: &Bound<'py, PyTuple>,
    settings: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyAny>> {
    let Some(t) = registry().get(node_type) else {
        return Err(PyValueError::new_err(format!(
            "unknown node type {node_type:?}"
        )));
    };
    let ports = t.resolve_inputs(None);
    if inputs.len() > ports.len() {
        return Err(PyTypeError::new_err(format!(
            "{node_type} has {} inputs, {} given",
            ports.len(),
            inputs.len()
        )));
    }
    let mut trees: Vec<Option<DataTree>> = Vec::new();
    for (k, (obj, port)) in inputs.iter().zip(&ports).enumerate() {
        if obj.is_none() {
            trees.push(None);
            continue;
        }
        let tree = tree_from_py(&obj, port.data_type).map_err(|e| {
            PyValueError::new_err(format!(
                "{node_type}: input {k} ({}): {}",
                port.nickname, e.0
            ))
        })?;
        trees.push(Some(tree));
    }
    let mut values = Vec::new();
    if let Some(settings) = settings {
        for (name, value) in settings.iter() {
            let name: String = name.extract()?;
            let Some(setting) = t.settings.iter().find(|s| s.name == name) else {
                return Err(PyTypeError::new_err(format!(
                    "{node_type} has no setting {name:?}"
                )));
            };
            let v = crate::convert::item_from_py(&value, setting.data_type)
                .map_err(PyValueError::new_err)?
                .ok_or_else(|| PyValueError::new_err(format!("setting {name} is None")))?;
            let v = cast_value(&v, setting.data_type)
                .map_err(|e| PyValueError::new_err(format!("setting {name}: {e}")))?;
            values.push((name, v));
        }
    }
    let result = py.detach(|| {
        let mut call = NodeCall::new(t);
        for tree in trees {
            call = match tree {
                Some(tree) => call.input(tree),
                None => call.skip_input(),
            };
        }
        for (name, v) in values {
            call = call.setting(&name, v);
        }
        call.run()
    });
    if let Some(m) = result.messages.iter().find(|m| m.level == Level::Error) {
        let mut text = m.text.clone();
        if let Some(path) = &m.path {
            text = match m.index {
                Some(i) => format!("{path}[{i}]: {text}"),
                None => format!("{path}: {text}"),
            };
        }
        return Err(PyValueError::new_err(format!("{node_type}: {text}")));
    }
    let outputs = result
        .outputs
        .iter()
        .map(|tree| tree_to_py(py, tree))
        .collect::<PyResult<Vec<_>>>()?;
    if outputs.len() == 1 {
        return Ok(outputs
            .into_iter()
            .next()
            .unwrap_or_else(|| py.None().into_bound(py)));
    }
    Ok(PyTuple::new(py, outputs)?.into_any())
}

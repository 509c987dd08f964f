//! The Python extension module `locus._locus`: graphs, values and geometry of locus for
//! Python. The package `locus` (in `python/locus/`) re-exports it and adds sweeps.
//!
//! It uses only the public API of `locus-runtime` (the [`Evaluator`](locus_runtime::Evaluator)
//! host API, data trees, literals and casts), `locus-kernel` and `locus-nodes`.

mod arrays;
mod convert;
mod curves;
mod errors;
mod geometry;
mod graph;
mod script;
mod solids;

use pyo3::prelude::*;

/// Converts a Python value to a locus data tree of type `type_name` and back, as `Graph.set`
/// and `Graph.tree` do (for tests and for checking a value without a graph).
#[pyfunction]
#[pyo3(signature = (value, type_name="Generic"))]
fn _roundtrip<'py>(
    py: Python<'py>,
    value: &Bound<'py, PyAny>,
    type_name: &str,
) -> PyResult<Bound<'py, pyo3::types::PyDict>> {
    let data_type = locus_runtime::DataType::from_name(type_name).ok_or_else(|| {
        pyo3::exceptions::PyValueError::new_err(format!("unknown type {type_name:?}"))
    })?;
    let tree =
        convert::tree_from_py(value, data_type).map_err(|e| errors::InputError::new_err(e.0))?;
    convert::tree_to_dict(py, &tree)
}

/// The ids of every node type in the library.
#[pyfunction]
fn node_types() -> Vec<String> {
    graph::registry().iter().map(|t| t.id.clone()).collect()
}

#[pymodule]
fn _locus(m: &Bound<'_, PyModule>) -> PyResult<()> {
    let py = m.py();
    m.add_class::<graph::PyGraph>()?;
    m.add_class::<graph::PyPort>()?;
    m.add_class::<errors::PyDiagnostic>()?;
    m.add_class::<errors::PyMessage>()?;
    m.add_class::<geometry::PyPoint3>()?;
    m.add_class::<geometry::PyVector3>()?;
    m.add_class::<geometry::PyPlane>()?;
    m.add_class::<geometry::PyDomain>()?;
    m.add_class::<geometry::PyTransform>()?;
    m.add_class::<geometry::PyBox>()?;
    m.add_class::<curves::PyCurve>()?;
    m.add_class::<curves::PySurface>()?;
    m.add_class::<solids::PyBrep>()?;
    m.add_class::<solids::PyMesh>()?;
    m.add("GraphError", py.get_type::<errors::GraphError>())?;
    m.add("InputError", py.get_type::<errors::InputError>())?;
    m.add_function(wrap_pyfunction!(_roundtrip, m)?)?;
    m.add_function(wrap_pyfunction!(node_types, m)?)?;
    m.add_function(wrap_pyfunction!(script::call, m)?)?;
    m.add_function(wrap_pyfunction!(script::_script_hello, m)?)?;
    m.add_function(wrap_pyfunction!(script::_script_fatal, m)?)?;
    m.add_function(wrap_pyfunction!(script::_script_read_request, m)?)?;
    m.add_function(wrap_pyfunction!(script::_script_done, m)?)?;
    let executable: String = py
        .import("sys")?
        .getattr("executable")?
        .extract()
        .unwrap_or_default();
    graph::set_interpreter(executable);
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    Ok(())
}

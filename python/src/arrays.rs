//! numpy arrays in and out.
//!
//! Reading an array takes its memory in place (after `numpy.ascontiguousarray`, which copies
//! only arrays that are not already contiguous `float64`/`int64`/`bool`) and copies it once into
//! the typed column of a tree; writing a typed column copies it once into a new array. No Python
//! object is made per item either way.

use locus_kernel::{Point3, Vector3};
use numpy::{
    PyArray1, PyArray2, PyArrayDyn, PyArrayMethods, PyUntypedArray, PyUntypedArrayMethods,
};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyString;

use crate::geometry::point_like;

/// The `numpy` module.
fn numpy_module(py: Python<'_>) -> PyResult<Bound<'_, PyModule>> {
    py.import("numpy")
}

/// `numpy.ascontiguousarray(obj, dtype=dtype)` as a typed array.
pub(crate) fn contiguous<'py, T: numpy::Element>(
    obj: &Bound<'py, PyAny>,
    dtype: &str,
) -> PyResult<Bound<'py, PyArrayDyn<T>>> {
    let py = obj.py();
    let array =
        numpy_module(py)?.call_method1("ascontiguousarray", (obj, PyString::new(py, dtype)))?;
    Ok(array.cast_into::<PyArrayDyn<T>>()?)
}

/// The array behind an object, if it is a numpy array.
pub(crate) fn as_array<'a, 'py>(
    obj: &'a Bound<'py, PyAny>,
) -> Option<&'a Bound<'py, PyUntypedArray>> {
    obj.cast::<PyUntypedArray>().ok()
}

/// Three-column float data of an `(N, 3)` array (copied once out of the array's memory).
pub(crate) fn xyz_rows(obj: &Bound<'_, PyAny>) -> PyResult<Vec<[f64; 3]>> {
    let array = contiguous::<f64>(obj, "float64")?;
    let shape = array.shape().to_vec();
    if shape.len() != 2 || shape[1] != 3 {
        return Err(PyValueError::new_err(format!(
            "expected an (N, 3) array of coordinates, found shape {shape:?}"
        )));
    }
    let read = array.readonly();
    let data = read
        .as_slice()
        .map_err(|e| PyValueError::new_err(e.to_string()))?;
    Ok(data.chunks_exact(3).map(|c| [c[0], c[1], c[2]]).collect())
}

/// Points from an `(N, 3)` array or a sequence of point-likes, all finite.
pub(crate) fn points_from_py(obj: &Bound<'_, PyAny>) -> PyResult<Vec<Point3>> {
    if as_array(obj).is_some() {
        let rows = xyz_rows(obj)?;
        if let Some(i) = rows.iter().position(|c| !c.iter().all(|x| x.is_finite())) {
            return Err(PyValueError::new_err(format!(
                "point {i} is not finite: {:?}",
                rows[i]
            )));
        }
        return Ok(rows.into_iter().map(Point3::from_array).collect());
    }
    obj.try_iter()
        .map_err(|_| PyValueError::new_err("expected a list of points or an (N, 3) array"))?
        .enumerate()
        .map(|(i, item)| {
            point_like(&item?).map_err(|e| PyValueError::new_err(format!("point {i}: {e}")))
        })
        .collect()
}

/// Points as an `(N, 3)` float array.
pub(crate) fn points_to_numpy<'py>(
    py: Python<'py>,
    points: &[Point3],
) -> PyResult<Bound<'py, PyArray2<f64>>> {
    let flat: Vec<f64> = points.iter().flat_map(|p| p.to_array()).collect();
    PyArray1::from_vec(py, flat).reshape([points.len(), 3])
}

/// Vectors as an `(N, 3)` float array.
pub(crate) fn vectors_to_numpy<'py>(
    py: Python<'py>,
    vectors: &[Vector3],
) -> PyResult<Bound<'py, PyArray2<f64>>> {
    let flat: Vec<f64> = vectors.iter().flat_map(|v| v.to_array()).collect();
    PyArray1::from_vec(py, flat).reshape([vectors.len(), 3])
}

//! Values and data trees between Python and locus.
//!
//! Python to locus (for an input of a given type, the *hint*):
//!
//! | Python | locus |
//! | --- | --- |
//! | `None` | no data (an empty tree); inside a list, a null item |
//! | `bool`, `int`, `float`, `str` | Boolean, Integer (Number on a Number input), Number, Text |
//! | `Point3`, `Vector3`, `Plane`, `Domain`, `Transform`, `Box`, `NurbsCurve`, `NurbsSurface`, `Brep` | the value |
//! | a tuple of three numbers | a Point (a Vector on a Vector input) |
//! | a tuple of two numbers on a Domain input | a Domain |
//! | a tuple of two domains (or of two pairs) on a Domain2 input, and out | a Domain2 |
//! | a list (or a tuple on a Number, Integer, Boolean or Text input) | one branch `{0}` |
//! | a dict `{"{0;1}": [...], (2, 0): [...]}` | a tree, keys as paths |
//! | numpy `(N,)` float / int / bool | one branch of numbers / integers / booleans |
//! | numpy `(N, 3)` | one branch of points (vectors on a Vector input) |
//! | numpy scalars and 0-d arrays | the item |
//!
//! locus to Python is the reverse: items become the classes above (lines, circles and arcs
//! become `NurbsCurve`s that remember their form), nulls `None`, branches lists.

use std::collections::BTreeMap;

use locus_runtime::{Branch, Column, DataTree, DataType, TreePath, Value};
use numpy::{PyArray1, PyArrayDescrMethods, PyArrayMethods, PyUntypedArrayMethods};
use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict, PyFloat, PyInt, PyList, PyString, PyTuple};

use crate::arrays::{as_array, contiguous, points_to_numpy, vectors_to_numpy, xyz_rows};
use crate::curves::{PyCurve, PySurface};
use crate::geometry::{PyBox, PyDomain, PyPlane, PyPoint3, PyTransform, PyVector3, type_name};
use crate::solids::{PyBrep, PyMesh};

/// One value as a Python object.
pub(crate) fn value_to_py<'py>(py: Python<'py>, value: &Value) -> PyResult<Bound<'py, PyAny>> {
    Ok(match value {
        Value::Number(x) => PyFloat::new(py, *x).into_any(),
        Value::Integer(i) => i.into_pyobject(py)?.into_any(),
        Value::Boolean(b) => PyBool::new(py, *b).to_owned().into_any(),
        Value::Text(s) => PyString::new(py, s).into_any(),
        Value::Point(p) => Bound::new(py, PyPoint3(*p))?.into_any(),
        Value::Vector(v) => Bound::new(py, PyVector3(*v))?.into_any(),
        Value::Plane(p) => Bound::new(py, PyPlane(*p))?.into_any(),
        Value::Domain(d) => Bound::new(py, PyDomain(*d))?.into_any(),
        // A Domain² as the tuple of its u and v domains.
        Value::Domain2(d) => PyTuple::new(
            py,
            [
                Bound::new(py, PyDomain(d.u))?,
                Bound::new(py, PyDomain(d.v))?,
            ],
        )?
        .into_any(),
        Value::Transform(t) => Bound::new(py, PyTransform(*t))?.into_any(),
        Value::Box(b) => Bound::new(py, PyBox(*b))?.into_any(),
        Value::Surface(s) => Bound::new(py, PySurface(s.clone()))?.into_any(),
        Value::Brep(b) => Bound::new(py, PyBrep(b.clone()))?.into_any(),
        Value::Mesh(m) => Bound::new(py, PyMesh(m.clone()))?.into_any(),
        // A colour as its (r, g, b, a) channels, 0 to 255.
        Value::Colour(c) => PyTuple::new(py, [c.r, c.g, c.b, c.a])?.into_any(),
        Value::Line(_) | Value::Circle(_) | Value::Arc(_) | Value::Curve(_) => {
            let curve = PyCurve::from_value(value)
                .ok_or_else(|| PyTypeError::new_err("not a curve value"))?;
            Bound::new(py, curve)?.into_any()
        }
    })
}

/// A branch as a Python list (nulls as `None`), built per column type.
pub(crate) fn branch_to_list<'py>(
    py: Python<'py>,
    branch: &Branch,
) -> PyResult<Bound<'py, PyList>> {
    let nulls = branch.null_mask();
    let is_null = |i: usize| nulls.get(i).copied().unwrap_or(false);
    let none = || py.None().into_bound(py);
    let items: Vec<Bound<'py, PyAny>> = match branch.column() {
        Column::Number(v) => v
            .iter()
            .enumerate()
            .map(|(i, x)| {
                if is_null(i) {
                    none()
                } else {
                    PyFloat::new(py, *x).into_any()
                }
            })
            .collect(),
        Column::Boolean(v) => v
            .iter()
            .enumerate()
            .map(|(i, b)| {
                if is_null(i) {
                    none()
                } else {
                    PyBool::new(py, *b).to_owned().into_any()
                }
            })
            .collect(),
        _ => (0..branch.len())
            .map(|i| match branch.value(i) {
                Some(v) if !is_null(i) => value_to_py(py, &v),
                _ => Ok(none()),
            })
            .collect::<PyResult<_>>()?,
    };
    PyList::new(py, items)
}

/// A tree as a dict from path text (`"{0;1}"`) to a list of items.
pub(crate) fn tree_to_dict<'py>(py: Python<'py>, tree: &DataTree) -> PyResult<Bound<'py, PyDict>> {
    let dict = PyDict::new(py);
    for (path, branch) in tree.branches() {
        dict.set_item(path.to_string(), branch_to_list(py, branch)?)?;
    }
    Ok(dict)
}

/// A tree in its simplest Python form: `None` without branches, the item for one item at
/// `{0}`, a list for one branch at `{0}`, else a dict from path text to lists.
pub(crate) fn tree_to_py<'py>(py: Python<'py>, tree: &DataTree) -> PyResult<Bound<'py, PyAny>> {
    let branches = tree.branches();
    match branches {
        [] => Ok(py.None().into_bound(py)),
        [(path, branch)] if *path == TreePath::zero() => {
            if branch.len() == 1 {
                match branch.value(0) {
                    Some(v) if !branch.is_null(0) => value_to_py(py, &v),
                    _ => Ok(py.None().into_bound(py)),
                }
            } else {
                branch_to_list(py, branch).map(Bound::into_any)
            }
        }
        _ => tree_to_dict(py, tree).map(Bound::into_any),
    }
}

/// The items of a tree (all branches in order) as one numpy array: numbers `(N,)` float64
/// (nulls NaN), integers `(N,)` int64, booleans `(N,)` bool, points and vectors `(N, 3)`
/// float64 (nulls NaN rows). Each typed column is copied once into the array. A tree without
/// items takes the type of its first typed branch, else `declared` (the port's type).
pub(crate) fn tree_to_numpy<'py>(
    py: Python<'py>,
    tree: &DataTree,
    declared: DataType,
) -> Result<Bound<'py, PyAny>, String> {
    let mut data_type = None;
    for (path, b) in tree.branches() {
        if b.is_empty() {
            continue;
        }
        let t = if b.data_type() == DataType::Generic {
            b.clone().narrowed().data_type()
        } else {
            b.data_type()
        };
        match data_type {
            None => data_type = Some(t),
            Some(d) if d == t => {}
            Some(d) => {
                return Err(format!(
                    "branch {path} holds {t} items where the branches before hold {d}"
                ));
            }
        }
    }
    let data_type = data_type
        .or_else(|| {
            tree.branches()
                .iter()
                .map(|(_, b)| b.data_type())
                .find(|&t| t != DataType::Generic)
        })
        .unwrap_or(if declared == DataType::Generic {
            DataType::Number
        } else {
            declared
        });
    let count = tree.item_count();
    let narrowed: Vec<Branch> = tree
        .branches()
        .iter()
        .map(|(_, b)| {
            if b.data_type() == DataType::Generic {
                b.clone().narrowed()
            } else {
                b.clone()
            }
        })
        .collect();
    let masked = |b: &Branch, i: usize| b.null_mask().get(i).copied().unwrap_or(false);
    let err = |what: &str| {
        format!(
            "it holds {what}; numpy arrays take numbers, integers, booleans, points and vectors"
        )
    };
    Ok(match data_type {
        DataType::Number => {
            let mut out = Vec::with_capacity(count);
            for b in &narrowed {
                let s = b.slice::<f64>().unwrap_or(&[]);
                if b.has_nulls() {
                    out.extend(
                        s.iter()
                            .enumerate()
                            .map(|(i, &x)| if masked(b, i) { f64::NAN } else { x }),
                    );
                } else {
                    out.extend_from_slice(s);
                }
            }
            PyArray1::from_vec(py, out).into_any()
        }
        DataType::Integer => {
            let mut out = Vec::with_capacity(count);
            for b in &narrowed {
                if b.has_nulls() {
                    return Err("it has null integers, which numpy integer arrays cannot hold; read it with tree()".to_owned());
                }
                out.extend_from_slice(b.slice::<i64>().unwrap_or(&[]));
            }
            PyArray1::from_vec(py, out).into_any()
        }
        DataType::Boolean => {
            let mut out = Vec::with_capacity(count);
            for b in &narrowed {
                if b.has_nulls() {
                    return Err("it has null booleans, which numpy boolean arrays cannot hold; read it with tree()".to_owned());
                }
                out.extend_from_slice(b.slice::<bool>().unwrap_or(&[]));
            }
            PyArray1::from_vec(py, out).into_any()
        }
        DataType::Point => {
            let mut out = Vec::with_capacity(count);
            for b in &narrowed {
                let s = b.slice::<locus_kernel::Point3>().unwrap_or(&[]);
                out.extend(s.iter().enumerate().map(|(i, &p)| {
                    if masked(b, i) {
                        locus_kernel::Point3::new(f64::NAN, f64::NAN, f64::NAN)
                    } else {
                        p
                    }
                }));
            }
            points_to_numpy(py, &out)
                .map_err(|e| e.to_string())?
                .into_any()
        }
        DataType::Vector => {
            let mut out = Vec::with_capacity(count);
            for b in &narrowed {
                let s = b.slice::<locus_kernel::Vector3>().unwrap_or(&[]);
                out.extend(s.iter().enumerate().map(|(i, &v)| {
                    if masked(b, i) {
                        locus_kernel::Vector3::new(f64::NAN, f64::NAN, f64::NAN)
                    } else {
                        v
                    }
                }));
            }
            vectors_to_numpy(py, &out)
                .map_err(|e| e.to_string())?
                .into_any()
        }
        DataType::Generic => return Err(err("items of mixed types")),
        other => return Err(err(&format!("{other} items"))),
    })
}

/// Why a Python object could not become a tree: the message names the path and item.
#[derive(Debug)]
pub(crate) struct ConvertError(pub String);

impl ConvertError {
    fn at(path: &TreePath, index: Option<usize>, message: impl std::fmt::Display) -> Self {
        match index {
            Some(i) => Self(format!("{path}[{i}]: {message}")),
            None => Self(format!("{path}: {message}")),
        }
    }
}

/// Whether any tuple, on an input of this type, is a list rather than one coordinate item.
fn tuples_are_lists(hint: DataType) -> bool {
    matches!(
        hint,
        DataType::Number | DataType::Integer | DataType::Boolean | DataType::Text
    )
}

/// A tree from a Python object, for an input of type `hint`.
pub(crate) fn tree_from_py(
    obj: &Bound<'_, PyAny>,
    hint: DataType,
) -> Result<DataTree, ConvertError> {
    let zero = TreePath::zero();
    if obj.is_none() {
        return Ok(DataTree::new());
    }
    if let Ok(dict) = obj.cast::<PyDict>() {
        let mut branches: BTreeMap<TreePath, Branch> = BTreeMap::new();
        for (key, value) in dict.iter() {
            let path = path_from_key(&key)?;
            let branch = if value.is_none() {
                let mut b = Branch::new(DataType::Generic);
                b.push_null();
                b
            } else if is_sequence_like(&value, hint) {
                branch_from_py(&value, hint, &path)?
            } else {
                single(&value, hint, &path)?
            };
            if branches.insert(path.clone(), branch).is_some() {
                return Err(ConvertError(format!("path {path} is given twice")));
            }
        }
        return Ok(DataTree::from_branches(branches));
    }
    let branch = if is_sequence_like(obj, hint) {
        branch_from_py(obj, hint, &zero)?
    } else {
        single(obj, hint, &zero)?
    };
    Ok(DataTree::from_branches([(zero, branch)]))
}

/// A branch of one item.
fn single(obj: &Bound<'_, PyAny>, hint: DataType, path: &TreePath) -> Result<Branch, ConvertError> {
    let value = item_from_py(obj, hint).map_err(|m| ConvertError::at(path, None, m))?;
    let mut branch = Branch::new(value.as_ref().map_or(DataType::Generic, Value::data_type));
    branch.push_option(value);
    Ok(branch)
}

/// Whether an object stands for a list of items (a branch) rather than one item.
fn is_sequence_like(obj: &Bound<'_, PyAny>, hint: DataType) -> bool {
    if obj.cast::<PyList>().is_ok() {
        return true;
    }
    if let Some(array) = as_array(obj) {
        return array.ndim() > 0;
    }
    if obj.cast::<PyTuple>().is_ok() {
        return tuples_are_lists(hint)
            || coordinate_tuple(obj, hint).is_none() && domain2_tuple(obj, hint).is_none();
    }
    false
}

/// A tree path from a dict key: path text (`"{0;1}"`, `"0;1"`), an int, or a tuple of ints.
fn path_from_key(key: &Bound<'_, PyAny>) -> Result<TreePath, ConvertError> {
    if let Ok(text) = key.cast::<PyString>() {
        let text = text.to_string();
        let trimmed = text.trim();
        let braced = if trimmed.starts_with('{') {
            trimmed.to_owned()
        } else {
            format!("{{{trimmed}}}")
        };
        return braced
            .parse::<TreePath>()
            .map_err(|e| ConvertError(format!("bad tree path {text:?}: {e:?}")));
    }
    if let Ok(i) = key.extract::<u32>() {
        return Ok(TreePath::new(vec![i]));
    }
    if let Ok(indices) = key.extract::<Vec<u32>>() {
        return Ok(TreePath::new(indices));
    }
    Err(ConvertError(format!(
        "a tree key is a path such as \"{{0;1}}\", an index or a tuple of indices, found {}",
        type_name(key)
    )))
}

/// A branch from a list, a tuple or a numpy array.
fn branch_from_py(
    obj: &Bound<'_, PyAny>,
    hint: DataType,
    path: &TreePath,
) -> Result<Branch, ConvertError> {
    if as_array(obj).is_some() {
        return branch_from_array(obj, hint).map_err(|m| ConvertError::at(path, None, m));
    }
    let iter = obj
        .try_iter()
        .map_err(|e| ConvertError::at(path, None, e))?;
    let mut values: Vec<Option<Value>> = Vec::new();
    for (i, item) in iter.enumerate() {
        let item = item.map_err(|e| ConvertError::at(path, Some(i), e))?;
        if item.cast::<PyList>().is_ok()
            || item.cast::<PyDict>().is_ok()
            || as_array(&item).is_some_and(|a| a.ndim() > 0)
        {
            return Err(ConvertError::at(
                path,
                Some(i),
                "a list inside a list: give a tree as a dict {\"{0}\": [...], \"{1}\": [...]}, \
                 and points as tuples (x, y, z) or an (N, 3) array",
            ));
        }
        values.push(item_from_py(&item, hint).map_err(|m| ConvertError::at(path, Some(i), m))?);
    }
    Ok(branch_of(values))
}

/// A branch holding these items, typed when they share a type.
fn branch_of(values: Vec<Option<Value>>) -> Branch {
    let mut common = None;
    let mut mixed = false;
    for v in values.iter().flatten() {
        match common {
            None => common = Some(v.data_type()),
            Some(t) if t == v.data_type() => {}
            Some(_) => mixed = true,
        }
    }
    let data_type = if mixed {
        DataType::Generic
    } else {
        common.unwrap_or(DataType::Generic)
    };
    let mut branch = Branch::new(data_type);
    for v in values {
        branch.push_option(v);
    }
    branch
}

/// A branch from a numpy array of one or two dimensions (read in place, copied once).
fn branch_from_array(obj: &Bound<'_, PyAny>, hint: DataType) -> Result<Branch, String> {
    let array = as_array(obj).ok_or("not an array")?;
    let shape = array.shape().to_vec();
    let dtype = array.dtype();
    let kind = dtype.kind();
    let describe = || format!("a numpy array of shape {shape:?} and dtype {}", dtype);
    let read_err = |e: PyErr| e.to_string();
    match (shape.len(), kind) {
        (1, b'b') => {
            let a = contiguous::<bool>(obj, "bool").map_err(read_err)?;
            let r = a.readonly();
            let s = r.as_slice().map_err(|e| e.to_string())?;
            Ok(Branch::from_items(s.to_vec()))
        }
        (1, b'i' | b'u') if hint != DataType::Number => {
            if kind == b'u' && dtype.itemsize() >= 8 {
                let a = contiguous::<u64>(obj, "uint64").map_err(read_err)?;
                let r = a.readonly();
                let s = r.as_slice().map_err(|e| e.to_string())?;
                let items = s
                    .iter()
                    .enumerate()
                    .map(|(i, &x)| {
                        i64::try_from(x)
                            .map_err(|_| format!("item {i}: {x} is too large for an Integer"))
                    })
                    .collect::<Result<Vec<i64>, String>>()?;
                return Ok(Branch::from_items(items));
            }
            let a = contiguous::<i64>(obj, "int64").map_err(read_err)?;
            let r = a.readonly();
            let s = r.as_slice().map_err(|e| e.to_string())?;
            Ok(Branch::from_items(s.to_vec()))
        }
        (1, b'i' | b'u' | b'f') => {
            let a = contiguous::<f64>(obj, "float64").map_err(read_err)?;
            let r = a.readonly();
            let s = r.as_slice().map_err(|e| e.to_string())?;
            Ok(Branch::from_items(s.to_vec()))
        }
        (2, b'i' | b'u' | b'f') if shape[1] == 3 => {
            let rows = xyz_rows(obj).map_err(read_err)?;
            if let Some(i) = rows.iter().position(|c| !c.iter().all(|x| x.is_finite())) {
                return Err(format!("row {i} is not finite: {:?}", rows[i]));
            }
            if hint == DataType::Vector {
                Ok(Branch::from_items(
                    rows.into_iter()
                        .map(locus_kernel::Vector3::from_array)
                        .collect(),
                ))
            } else {
                Ok(Branch::from_items(
                    rows.into_iter()
                        .map(locus_kernel::Point3::from_array)
                        .collect(),
                ))
            }
        }
        (1, b'O' | b'U' | b'S') => {
            let list = obj.call_method0("tolist").map_err(read_err)?;
            let mut values = Vec::with_capacity(shape[0]);
            for (i, item) in list.try_iter().map_err(read_err)?.enumerate() {
                let item = item.map_err(read_err)?;
                values.push(item_from_py(&item, hint).map_err(|m| format!("item {i}: {m}"))?);
            }
            Ok(branch_of(values))
        }
        _ => Err(format!(
            "{} cannot be a branch: give (N,) numbers or (N, 3) points",
            describe()
        )),
    }
}

/// A pair of domains (`Domain` objects or `(start, end)` tuples) on a Domain² input.
fn domain2_tuple(obj: &Bound<'_, PyAny>, hint: DataType) -> Option<Value> {
    if hint != DataType::Domain2 {
        return None;
    }
    let tuple = obj.cast::<PyTuple>().ok()?;
    let domain = |o: Bound<'_, PyAny>| match o.cast::<PyDomain>() {
        Ok(d) => Some(d.get().0),
        Err(_) => match coordinate_tuple(&o, DataType::Domain) {
            Some(Value::Domain(d)) => Some(d),
            _ => None,
        },
    };
    match tuple.len() {
        2 => Some(Value::Domain2(locus_kernel::UvInterval::new(
            domain(tuple.get_item(0).ok()?)?,
            domain(tuple.get_item(1).ok()?)?,
        ))),
        _ => None,
    }
}

/// Three (or two) numbers of a tuple that stands for one point, vector or domain.
fn coordinate_tuple(obj: &Bound<'_, PyAny>, hint: DataType) -> Option<Value> {
    let tuple = obj.cast::<PyTuple>().ok()?;
    let numeric = |o: &Bound<'_, PyAny>| {
        (o.cast::<PyFloat>().is_ok() || o.cast::<PyInt>().is_ok()) && o.cast::<PyBool>().is_err()
    };
    if !tuple.iter().all(|o| numeric(&o)) {
        return None;
    }
    match (tuple.len(), hint) {
        (2, DataType::Domain) => {
            let [t0, t1] = obj.extract::<[f64; 2]>().ok()?;
            Some(Value::Domain(locus_kernel::Interval::new(t0, t1)))
        }
        (3, DataType::Vector) => Some(Value::Vector(locus_kernel::Vector3::from_array(
            obj.extract().ok()?,
        ))),
        (3, _) => Some(Value::Point(locus_kernel::Point3::from_array(
            obj.extract().ok()?,
        ))),
        _ => None,
    }
}

/// One item from a Python object; `Ok(None)` for `None` (a null item).
pub(crate) fn item_from_py(
    obj: &Bound<'_, PyAny>,
    hint: DataType,
) -> Result<Option<Value>, String> {
    if obj.is_none() {
        return Ok(None);
    }
    if let Ok(b) = obj.cast::<PyBool>() {
        return Ok(Some(Value::Boolean(b.is_true())));
    }
    if obj.cast::<PyInt>().is_ok() {
        if hint == DataType::Number {
            let x: f64 = obj.extract().map_err(|e: PyErr| e.to_string())?;
            return Ok(Some(Value::Number(x)));
        }
        return obj
            .extract::<i64>()
            .map(|i| Some(Value::Integer(i)))
            .map_err(|_| format!("{} does not fit in a 64-bit Integer", obj));
    }
    if let Ok(f) = obj.cast::<PyFloat>() {
        return Ok(Some(Value::Number(f.value())));
    }
    if let Ok(s) = obj.cast::<PyString>() {
        return s
            .extract::<String>()
            .map(|s| Some(Value::Text(s)))
            .map_err(|e| format!("text that is not valid Unicode: {e}"));
    }
    if let Ok(p) = obj.cast::<PyPoint3>() {
        let p = p.get().0;
        if !p.is_finite() {
            return Err(format!("the point {p:?} is not finite"));
        }
        return Ok(Some(Value::Point(p)));
    }
    if let Ok(v) = obj.cast::<PyVector3>() {
        let v = v.get().0;
        if !v.is_finite() {
            return Err(format!("the vector {v:?} is not finite"));
        }
        return Ok(Some(Value::Vector(v)));
    }
    if let Ok(p) = obj.cast::<PyPlane>() {
        return Ok(Some(Value::Plane(p.get().0)));
    }
    if let Ok(d) = obj.cast::<PyDomain>() {
        return Ok(Some(Value::Domain(d.get().0)));
    }
    if let Ok(t) = obj.cast::<PyTransform>() {
        return Ok(Some(Value::Transform(t.get().0)));
    }
    if let Ok(b) = obj.cast::<PyBox>() {
        return Ok(Some(Value::Box(b.get().0)));
    }
    if let Ok(c) = obj.cast::<PyCurve>() {
        return Ok(Some(c.get().value.clone()));
    }
    if let Ok(s) = obj.cast::<PySurface>() {
        return Ok(Some(Value::Surface(s.get().0.clone())));
    }
    if let Ok(b) = obj.cast::<PyBrep>() {
        return Ok(Some(Value::Brep(b.get().0.clone())));
    }
    if let Ok(m) = obj.cast::<PyMesh>() {
        return Ok(Some(Value::Mesh(m.get().0.clone())));
    }
    if let Some(v) = domain2_tuple(obj, hint) {
        return Ok(Some(v));
    }
    if let Some(v) = coordinate_tuple(obj, hint) {
        if let Value::Point(p) = &v
            && !p.is_finite()
        {
            return Err(format!("the point {p:?} is not finite"));
        }
        if let Value::Vector(p) = &v
            && !p.is_finite()
        {
            return Err(format!("the vector {p:?} is not finite"));
        }
        return Ok(Some(v));
    }
    // numpy scalars and 0-d arrays: their Python item.
    if let Some(array) = as_array(obj) {
        if array.ndim() == 0 {
            let item = obj.call_method0("item").map_err(|e| e.to_string())?;
            return item_from_py(&item, hint);
        }
    } else if obj.hasattr("dtype").unwrap_or(false) && obj.hasattr("item").unwrap_or(false) {
        let item = obj.call_method0("item").map_err(|e| e.to_string())?;
        if !item.is(obj) && item.get_type().ne(obj.get_type()).unwrap_or(true) {
            return item_from_py(&item, hint);
        }
    }
    Err(format!(
        "cannot convert {} to a locus value",
        type_name(obj)
    ))
}

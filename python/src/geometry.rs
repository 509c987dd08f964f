//! The small geometry value types as Python classes: `Point3`, `Vector3`, `Plane`, `Domain`,
//! `Transform` and `Box`. Each is immutable, compares by value and pickles exactly (its
//! coordinates as Python floats).

use locus_kernel::{Interval, OrientedBox, Plane, Point3, Transform, Vector3};
use numpy::{PyArray1, PyArray2, PyArrayMethods};
use pyo3::exceptions::{PyIndexError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyTuple, PyType};

/// A kernel error as a Python `ValueError`.
pub(crate) fn kernel_error(what: &str, e: &locus_kernel::Error) -> PyErr {
    PyValueError::new_err(format!("invalid {what}: {e}"))
}

/// Three coordinates from a `Point3`, a `Vector3` or any sequence of three numbers.
pub(crate) fn coords(obj: &Bound<'_, PyAny>, what: &str) -> PyResult<[f64; 3]> {
    if let Ok(p) = obj.cast::<PyPoint3>() {
        return Ok(p.get().0.to_array());
    }
    if let Ok(v) = obj.cast::<PyVector3>() {
        return Ok(v.get().0.to_array());
    }
    obj.extract::<[f64; 3]>().map_err(|_| {
        PyValueError::new_err(format!(
            "expected a {what}: a Point3, a Vector3 or three numbers, found {}",
            type_name(obj)
        ))
    })
}

/// A point from a `Point3` or three numbers (finite).
pub(crate) fn point_like(obj: &Bound<'_, PyAny>) -> PyResult<Point3> {
    let c = coords(obj, "point")?;
    finite(c, "point").map(Point3::from_array)
}

/// A vector from a `Vector3` or three numbers (finite).
pub(crate) fn vector_like(obj: &Bound<'_, PyAny>) -> PyResult<Vector3> {
    let c = coords(obj, "vector")?;
    finite(c, "vector").map(Vector3::from_array)
}

fn finite(c: [f64; 3], what: &str) -> PyResult<[f64; 3]> {
    if c.iter().all(|x| x.is_finite()) {
        Ok(c)
    } else {
        Err(PyValueError::new_err(format!(
            "a {what} needs finite coordinates, found ({}, {}, {})",
            c[0], c[1], c[2]
        )))
    }
}

/// The Python type name of an object, for messages.
pub(crate) fn type_name(obj: &Bound<'_, PyAny>) -> String {
    obj.get_type()
        .name()
        .map(|n| n.to_string())
        .unwrap_or_else(|_| "an object".to_owned())
}

/// A Python float as Python's `repr` writes it (shortest round trip).
pub(crate) fn float_repr(x: f64) -> String {
    if x.is_nan() {
        "nan".to_owned()
    } else if x.is_infinite() {
        if x > 0.0 { "inf" } else { "-inf" }.to_owned()
    } else if x == x.trunc() && x.abs() < 1e16 {
        format!("{x:.1}")
    } else {
        format!("{x}")
    }
}

fn xyz_repr(name: &str, c: [f64; 3]) -> String {
    format!(
        "{name}({}, {}, {})",
        float_repr(c[0]),
        float_repr(c[1]),
        float_repr(c[2])
    )
}

/// The item `index` (negative from the end) of three coordinates.
fn coordinate(c: [f64; 3], index: isize) -> PyResult<f64> {
    let i = if index < 0 { index + 3 } else { index };
    usize::try_from(i)
        .ok()
        .and_then(|i| c.get(i).copied())
        .ok_or_else(|| PyIndexError::new_err("a 3-D coordinate index is 0, 1 or 2"))
}

fn numpy3<'py>(py: Python<'py>, c: [f64; 3]) -> Bound<'py, PyArray1<f64>> {
    PyArray1::from_slice(py, &c)
}

/// A location in 3-D space. `Point3 - Point3` is a `Vector3`; `Point3 + Vector3` a `Point3`.
///
/// Unpacks as `x, y, z = p`, converts with `numpy.asarray(p)`, and pickles exactly.
#[pyclass(module = "locus", name = "Point3", frozen, eq)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PyPoint3(pub Point3);

#[pymethods]
#[allow(
    clippy::wrong_self_convention,
    reason = "Python methods take &self, even on Copy types"
)]
impl PyPoint3 {
    #[new]
    fn new(x: f64, y: f64, z: f64) -> Self {
        Self(Point3::new(x, y, z))
    }

    /// The x coordinate.
    #[getter]
    fn x(&self) -> f64 {
        self.0.x
    }

    /// The y coordinate.
    #[getter]
    fn y(&self) -> f64 {
        self.0.y
    }

    /// The z coordinate.
    #[getter]
    fn z(&self) -> f64 {
        self.0.z
    }

    /// The distance to another point.
    fn distance_to(&self, other: &Bound<'_, PyAny>) -> PyResult<f64> {
        Ok(self.0.distance(point_like(other)?))
    }

    /// The coordinates as a tuple `(x, y, z)`.
    fn to_tuple(&self) -> (f64, f64, f64) {
        (self.0.x, self.0.y, self.0.z)
    }

    /// The coordinates as a numpy array of shape `(3,)`.
    #[pyo3(signature = (dtype=None, copy=None))]
    fn __array__<'py>(
        &self,
        py: Python<'py>,
        dtype: Option<&Bound<'py, PyAny>>,
        copy: Option<bool>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let _ = copy;
        array_with_dtype(numpy3(py, self.0.to_array()).into_any(), dtype)
    }

    fn __sub__<'py>(&self, other: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyAny>> {
        let py = other.py();
        if let Ok(p) = other.cast::<PyPoint3>() {
            return Bound::new(py, PyVector3(self.0 - p.get().0)).map(Bound::into_any);
        }
        if let Ok(v) = other.cast::<PyVector3>() {
            return Bound::new(py, PyPoint3(self.0 - v.get().0)).map(Bound::into_any);
        }
        Ok(py.NotImplemented().into_bound(py))
    }

    fn __add__<'py>(&self, other: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyAny>> {
        let py = other.py();
        if let Ok(v) = other.cast::<PyVector3>() {
            return Bound::new(py, PyPoint3(self.0 + v.get().0)).map(Bound::into_any);
        }
        Ok(py.NotImplemented().into_bound(py))
    }

    fn __len__(&self) -> usize {
        3
    }

    fn __getitem__(&self, index: isize) -> PyResult<f64> {
        coordinate(self.0.to_array(), index)
    }

    fn __repr__(&self) -> String {
        xyz_repr("Point3", self.0.to_array())
    }

    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<Bound<'py, PyTuple>> {
        let p = slf.get().0;
        (slf.get_type(), (p.x, p.y, p.z)).into_pyobject(slf.py())
    }
}

/// A displacement in 3-D space.
///
/// Supports `+`, `-`, unary `-`, `*` and `/` by a number; unpacks as `x, y, z = v` and pickles
/// exactly.
#[pyclass(module = "locus", name = "Vector3", frozen, eq)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PyVector3(pub Vector3);

#[pymethods]
#[allow(
    clippy::wrong_self_convention,
    reason = "Python methods take &self, even on Copy types"
)]
impl PyVector3 {
    #[new]
    fn new(x: f64, y: f64, z: f64) -> Self {
        Self(Vector3::new(x, y, z))
    }

    /// The x component.
    #[getter]
    fn x(&self) -> f64 {
        self.0.x
    }

    /// The y component.
    #[getter]
    fn y(&self) -> f64 {
        self.0.y
    }

    /// The z component.
    #[getter]
    fn z(&self) -> f64 {
        self.0.z
    }

    /// The length.
    #[getter]
    fn length(&self) -> f64 {
        self.0.length()
    }

    /// The vector of length 1 in the same direction; `ValueError` for a zero vector.
    fn unitized(&self) -> PyResult<Self> {
        self.0
            .unitize()
            .map(Self)
            .map_err(|e| kernel_error("vector", &e))
    }

    /// The dot product.
    fn dot(&self, other: &Bound<'_, PyAny>) -> PyResult<f64> {
        Ok(self.0.dot(vector_like(other)?))
    }

    /// The cross product.
    fn cross(&self, other: &Bound<'_, PyAny>) -> PyResult<Self> {
        Ok(Self(self.0.cross(vector_like(other)?)))
    }

    /// The components as a tuple `(x, y, z)`.
    fn to_tuple(&self) -> (f64, f64, f64) {
        (self.0.x, self.0.y, self.0.z)
    }

    /// The components as a numpy array of shape `(3,)`.
    #[pyo3(signature = (dtype=None, copy=None))]
    fn __array__<'py>(
        &self,
        py: Python<'py>,
        dtype: Option<&Bound<'py, PyAny>>,
        copy: Option<bool>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let _ = copy;
        array_with_dtype(numpy3(py, self.0.to_array()).into_any(), dtype)
    }

    fn __add__<'py>(&self, other: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyAny>> {
        let py = other.py();
        if let Ok(v) = other.cast::<PyVector3>() {
            return Bound::new(py, PyVector3(self.0 + v.get().0)).map(Bound::into_any);
        }
        if let Ok(p) = other.cast::<PyPoint3>() {
            return Bound::new(py, PyPoint3(p.get().0 + self.0)).map(Bound::into_any);
        }
        Ok(py.NotImplemented().into_bound(py))
    }

    fn __sub__<'py>(&self, other: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyAny>> {
        let py = other.py();
        if let Ok(v) = other.cast::<PyVector3>() {
            return Bound::new(py, PyVector3(self.0 - v.get().0)).map(Bound::into_any);
        }
        Ok(py.NotImplemented().into_bound(py))
    }

    fn __mul__(&self, factor: f64) -> Self {
        Self(self.0 * factor)
    }

    fn __rmul__(&self, factor: f64) -> Self {
        Self(self.0 * factor)
    }

    fn __truediv__(&self, divisor: f64) -> PyResult<Self> {
        if divisor == 0.0 {
            return Err(pyo3::exceptions::PyZeroDivisionError::new_err(
                "vector division by zero",
            ));
        }
        Ok(Self(self.0 * (1.0 / divisor)))
    }

    fn __neg__(&self) -> Self {
        Self(-self.0)
    }

    fn __len__(&self) -> usize {
        3
    }

    fn __getitem__(&self, index: isize) -> PyResult<f64> {
        coordinate(self.0.to_array(), index)
    }

    fn __repr__(&self) -> String {
        xyz_repr("Vector3", self.0.to_array())
    }

    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<Bound<'py, PyTuple>> {
        let v = slf.get().0;
        (slf.get_type(), (v.x, v.y, v.z)).into_pyobject(slf.py())
    }
}

/// `array.astype(dtype)` when a dtype is asked for.
fn array_with_dtype<'py>(
    array: Bound<'py, PyAny>,
    dtype: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyAny>> {
    match dtype {
        Some(d) if !d.is_none() => array.call_method1("astype", (d,)),
        _ => Ok(array),
    }
}

/// A plane: an origin and three orthonormal axes (right-handed), as Rhino's planes.
///
/// `Plane(origin, x_axis, y_axis)` makes the frame orthonormal (`y_axis` only fixes the side);
/// `Plane.world_xy()` and `Plane.from_normal(origin, normal)` are the other constructors.
#[pyclass(module = "locus", name = "Plane", frozen, eq)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PyPlane(pub Plane);

#[pymethods]
impl PyPlane {
    #[new]
    fn new(
        origin: &Bound<'_, PyAny>,
        x_axis: &Bound<'_, PyAny>,
        y_axis: &Bound<'_, PyAny>,
    ) -> PyResult<Self> {
        Plane::from_frame(
            point_like(origin)?,
            vector_like(x_axis)?,
            vector_like(y_axis)?,
        )
        .map(Self)
        .map_err(|e| kernel_error("plane", &e))
    }

    /// The world XY plane.
    #[staticmethod]
    fn world_xy() -> Self {
        Self(Plane::WORLD_XY)
    }

    /// The plane through `origin` with the given normal (its x axis chosen as Rhino does).
    #[staticmethod]
    fn from_normal(origin: &Bound<'_, PyAny>, normal: &Bound<'_, PyAny>) -> PyResult<Self> {
        Plane::from_normal(point_like(origin)?, vector_like(normal)?)
            .map(Self)
            .map_err(|e| kernel_error("plane", &e))
    }

    /// A plane from exact axes (as pickled); they must be orthonormal.
    #[classmethod]
    fn _from_axes(
        _cls: &Bound<'_, PyType>,
        origin: [f64; 3],
        x: [f64; 3],
        y: [f64; 3],
        z: [f64; 3],
    ) -> PyResult<Self> {
        let plane = Plane {
            origin: Point3::from_array(origin),
            x_axis: Vector3::from_array(x),
            y_axis: Vector3::from_array(y),
            z_axis: Vector3::from_array(z),
        };
        if plane.is_valid() {
            Ok(Self(plane))
        } else {
            Err(PyValueError::new_err(
                "invalid plane: the axes are not finite, unit length and perpendicular",
            ))
        }
    }

    /// The origin.
    #[getter]
    fn origin(&self) -> PyPoint3 {
        PyPoint3(self.0.origin)
    }

    /// The x axis (unit length).
    #[getter]
    fn x_axis(&self) -> PyVector3 {
        PyVector3(self.0.x_axis)
    }

    /// The y axis (unit length).
    #[getter]
    fn y_axis(&self) -> PyVector3 {
        PyVector3(self.0.y_axis)
    }

    /// The z axis, the normal (unit length).
    #[getter]
    fn z_axis(&self) -> PyVector3 {
        PyVector3(self.0.z_axis)
    }

    /// The point at plane coordinates `(u, v, w)`.
    #[pyo3(signature = (u, v, w=0.0))]
    fn point_at(&self, u: f64, v: f64, w: f64) -> PyPoint3 {
        PyPoint3(self.0.point_at(u, v, w))
    }

    /// The closest point of the plane to `point`.
    fn closest_point(&self, point: &Bound<'_, PyAny>) -> PyResult<PyPoint3> {
        Ok(PyPoint3(self.0.closest_point(point_like(point)?)))
    }

    /// The signed distance of `point` from the plane (positive on the normal's side).
    fn distance_to(&self, point: &Bound<'_, PyAny>) -> PyResult<f64> {
        Ok(self.0.signed_distance_to(point_like(point)?))
    }

    fn __repr__(&self) -> String {
        let p = self.0;
        format!(
            "Plane(origin={}, x_axis={}, y_axis={})",
            xyz_repr("Point3", p.origin.to_array()),
            xyz_repr("Vector3", p.x_axis.to_array()),
            xyz_repr("Vector3", p.y_axis.to_array()),
        )
    }

    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<Bound<'py, PyTuple>> {
        let p = slf.get().0;
        let rebuild = slf.get_type().getattr("_from_axes")?;
        (
            rebuild,
            (
                p.origin.to_array(),
                p.x_axis.to_array(),
                p.y_axis.to_array(),
                p.z_axis.to_array(),
            ),
        )
            .into_pyobject(slf.py())
    }
}

/// A domain: an interval of numbers from `t0` to `t1` (which may decrease).
#[pyclass(module = "locus", name = "Domain", frozen, eq)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PyDomain(pub Interval);

#[pymethods]
impl PyDomain {
    #[new]
    fn new(t0: f64, t1: f64) -> Self {
        Self(Interval::new(t0, t1))
    }

    /// The start.
    #[getter]
    fn t0(&self) -> f64 {
        self.0.t0
    }

    /// The end.
    #[getter]
    fn t1(&self) -> f64 {
        self.0.t1
    }

    /// `t1 - t0`.
    #[getter]
    fn length(&self) -> f64 {
        self.0.length()
    }

    /// The number at normalised parameter `s` (0 at `t0`, 1 at `t1`).
    fn parameter_at(&self, s: f64) -> f64 {
        self.0.parameter_at(s)
    }

    /// Whether `t` lies in the domain (either direction).
    fn __contains__(&self, t: f64) -> bool {
        self.0.contains(t)
    }

    fn __len__(&self) -> usize {
        2
    }

    fn __getitem__(&self, index: isize) -> PyResult<f64> {
        match index {
            0 | -2 => Ok(self.0.t0),
            1 | -1 => Ok(self.0.t1),
            _ => Err(PyIndexError::new_err("a domain has two ends, 0 and 1")),
        }
    }

    fn __repr__(&self) -> String {
        format!(
            "Domain({}, {})",
            float_repr(self.0.t0),
            float_repr(self.0.t1)
        )
    }

    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<Bound<'py, PyTuple>> {
        let d = slf.get().0;
        (slf.get_type(), (d.t0, d.t1)).into_pyobject(slf.py())
    }
}

/// A domain from a `Domain` or two numbers.
pub(crate) fn domain_like(obj: &Bound<'_, PyAny>) -> PyResult<Interval> {
    if let Ok(d) = obj.cast::<PyDomain>() {
        return Ok(d.get().0);
    }
    let [t0, t1] = obj.extract::<[f64; 2]>().map_err(|_| {
        PyValueError::new_err(format!(
            "expected a domain: a Domain or two numbers, found {}",
            type_name(obj)
        ))
    })?;
    Ok(Interval::new(t0, t1))
}

/// A 4×4 transformation acting on column vectors `[x, y, z, 1]`; `a @ b` applies `b` first.
///
/// `Transform(rows)` takes four rows of four numbers (or a `(4, 4)` numpy array).
#[pyclass(module = "locus", name = "Transform", frozen, eq)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PyTransform(pub Transform);

#[pymethods]
#[allow(
    clippy::wrong_self_convention,
    reason = "Python methods take &self, even on Copy types"
)]
impl PyTransform {
    #[new]
    fn new(rows: &Bound<'_, PyAny>) -> PyResult<Self> {
        let rows: [[f64; 4]; 4] = rows.extract().map_err(|_| {
            PyValueError::new_err(format!(
                "a transform takes four rows of four numbers, found {}",
                type_name(rows)
            ))
        })?;
        Ok(Self(Transform::from_rows(rows)))
    }

    /// The identity.
    #[staticmethod]
    fn identity() -> Self {
        Self(Transform::IDENTITY)
    }

    /// A translation by a vector.
    #[staticmethod]
    fn translation(vector: &Bound<'_, PyAny>) -> PyResult<Self> {
        Ok(Self(Transform::translation(vector_like(vector)?)))
    }

    /// A rotation by `angle` radians about the axis through `center` (Rhino's
    /// `Transform.Rotation`; right-handed about `axis`).
    #[staticmethod]
    #[pyo3(signature = (angle, axis=None, center=None))]
    fn rotation(
        angle: f64,
        axis: Option<&Bound<'_, PyAny>>,
        center: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<Self> {
        let axis = axis.map_or(Ok(Vector3::new(0.0, 0.0, 1.0)), vector_like)?;
        let center = center.map_or(Ok(Point3::ORIGIN), point_like)?;
        Transform::rotation(angle, axis, center)
            .map(Self)
            .map_err(|e| kernel_error("rotation", &e))
    }

    /// A uniform scale by `factor` about `center` (Rhino's `Transform.Scale`).
    #[staticmethod]
    fn scale(center: &Bound<'_, PyAny>, factor: f64) -> PyResult<Self> {
        Ok(Self(Transform::scale(point_like(center)?, factor)))
    }

    /// A scale by `x`, `y` and `z` along the axes of `plane`, about its origin.
    #[staticmethod]
    fn scale_non_uniform(plane: &Bound<'_, PyPlane>, x: f64, y: f64, z: f64) -> Self {
        Self(Transform::scale_non_uniform(&plane.get().0, x, y, z))
    }

    /// The mirror image in a plane.
    #[staticmethod]
    fn mirror(plane: &Bound<'_, PyPlane>) -> Self {
        Self(Transform::mirror(&plane.get().0))
    }

    /// The transform that maps plane `source` onto plane `target` (Orient).
    #[staticmethod]
    fn plane_to_plane(source: &Bound<'_, PyPlane>, target: &Bound<'_, PyPlane>) -> Self {
        Self(Transform::plane_to_plane(&source.get().0, &target.get().0))
    }

    /// The inverse; `ValueError` when the matrix is singular.
    fn inverse(&self) -> PyResult<Self> {
        self.0
            .inverse()
            .map(Self)
            .map_err(|e| kernel_error("transform", &e))
    }

    /// The matrix as four rows of four numbers.
    #[getter]
    fn rows(&self) -> [[f64; 4]; 4] {
        self.0.to_rows()
    }

    /// The matrix as a `(4, 4)` numpy array.
    fn to_numpy<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        let flat: Vec<f64> = self.0.to_rows().iter().flatten().copied().collect();
        PyArray1::from_vec(py, flat).reshape([4, 4])
    }

    /// The image of a point.
    fn transform_point(&self, point: &Bound<'_, PyAny>) -> PyResult<PyPoint3> {
        Ok(PyPoint3(self.0.transform_point(point_like(point)?)))
    }

    /// The image of a vector (translations do not move vectors).
    fn transform_vector(&self, vector: &Bound<'_, PyAny>) -> PyResult<PyVector3> {
        Ok(PyVector3(self.0.transform_vector(vector_like(vector)?)))
    }

    fn __matmul__(&self, other: &Bound<'_, Self>) -> Self {
        Self(self.0.then_after(&other.get().0))
    }

    fn __repr__(&self) -> String {
        let rows = self.0.to_rows().map(|r| {
            let items: Vec<String> = r.iter().map(|&x| float_repr(x)).collect();
            format!("[{}]", items.join(", "))
        });
        format!("Transform([{}])", rows.join(", "))
    }

    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<Bound<'py, PyTuple>> {
        let rows = slf.get().0.to_rows();
        (slf.get_type(), (rows,)).into_pyobject(slf.py())
    }
}

/// An oriented box: a plane and three domains along its axes (Grasshopper's Box).
#[pyclass(module = "locus", name = "Box", frozen, eq)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PyBox(pub OrientedBox);

#[pymethods]
impl PyBox {
    #[new]
    fn new(
        plane: &Bound<'_, PyPlane>,
        x: &Bound<'_, PyAny>,
        y: &Bound<'_, PyAny>,
        z: &Bound<'_, PyAny>,
    ) -> PyResult<Self> {
        let b = OrientedBox::new(
            plane.get().0,
            domain_like(x)?,
            domain_like(y)?,
            domain_like(z)?,
        );
        if b.is_valid() {
            Ok(Self(b))
        } else {
            Err(PyValueError::new_err(
                "invalid box: its plane or extents are not finite",
            ))
        }
    }

    /// The box's plane.
    #[getter]
    fn plane(&self) -> PyPlane {
        PyPlane(self.0.plane)
    }

    /// The extent along the plane's x axis.
    #[getter]
    fn x(&self) -> PyDomain {
        PyDomain(self.0.x)
    }

    /// The extent along the plane's y axis.
    #[getter]
    fn y(&self) -> PyDomain {
        PyDomain(self.0.y)
    }

    /// The extent along the plane's z axis.
    #[getter]
    fn z(&self) -> PyDomain {
        PyDomain(self.0.z)
    }

    /// The centre.
    #[getter]
    fn center(&self) -> PyPoint3 {
        PyPoint3(self.0.center())
    }

    /// The volume.
    #[getter]
    fn volume(&self) -> f64 {
        self.0.volume()
    }

    /// The eight corners as a `(8, 3)` numpy array, in Rhino's order.
    fn corners<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        let flat: Vec<f64> = self.0.corners().iter().flat_map(|p| p.to_array()).collect();
        PyArray1::from_vec(py, flat).reshape([8, 3])
    }

    fn __repr__(&self) -> String {
        format!(
            "Box({}, x={}, y={}, z={})",
            self.plane().__repr__(),
            self.x().__repr__(),
            self.y().__repr__(),
            self.z().__repr__()
        )
    }

    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<Bound<'py, PyTuple>> {
        let b = slf.get().0;
        let py = slf.py();
        let plane = Bound::new(py, PyPlane(b.plane))?;
        (
            slf.get_type(),
            (plane, (b.x.t0, b.x.t1), (b.y.t0, b.y.t1), (b.z.t0, b.z.t1)),
        )
            .into_pyobject(py)
    }
}

//! Curves and surfaces as Python classes: `NurbsCurve` (every curve value: lines, polylines,
//! circles, arcs and NURBS curves, each kept in its exact form) and `NurbsSurface`.
//!
//! Both pickle as the graph format's literal text of the value, which the runtime writes with
//! round-trip exact numbers and reads back through the kernel's validating constructors, so a
//! tampered pickle is refused with the kernel's reason instead of making an invalid curve.

use locus_kernel::{Circle, Curve, Interval, Line, NurbsCurve, NurbsSurface, Polyline};
use locus_runtime::{DataType, Literal, Shared, Value};
use numpy::{PyArray1, PyArray2, PyArray3, PyArrayMethods};
use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyTuple, PyType};

use crate::arrays::{points_from_py, points_to_numpy};
use crate::geometry::{PyDomain, PyPlane, PyPoint3, PyVector3, kernel_error, point_like};

/// The canonical literal text of a value, for pickling.
pub(crate) fn literal_of(value: &Value) -> PyResult<String> {
    Literal::from_value(value)
        .map(|l| l.0)
        .map_err(|e| PyTypeError::new_err(format!("cannot pickle this value: {}", e.message)))
}

/// A value read back from its literal text.
pub(crate) fn value_from_literal(text: &str, type_name: &str) -> PyResult<Value> {
    let data_type = DataType::from_name(type_name)
        .ok_or_else(|| PyValueError::new_err(format!("unknown value type {type_name:?}")))?;
    Literal(text.to_owned())
        .parse_value(data_type)
        .map_err(|e| PyValueError::new_err(format!("invalid {type_name} literal: {}", e.message)))
}

/// Knots in Rhino form for a clamped curve of `count` points with uniform interior knots.
fn clamped_uniform_knots(count: usize, degree: usize) -> PyResult<Vec<f64>> {
    if degree == 0 || count <= degree {
        return Err(PyValueError::new_err(format!(
            "a degree-{degree} curve needs at least {} control points, found {count}",
            degree + 1
        )));
    }
    let spans = count - degree;
    let mut knots = vec![0.0; degree];
    knots.extend((1..spans).map(|i| i as f64));
    knots.extend(std::iter::repeat_n(spans as f64, degree));
    Ok(knots)
}

/// A curve: a line, polyline, circle, arc or NURBS curve, kept in its exact form.
///
/// Every curve evaluates as the NURBS curve it stands for (`control_points`, `weights` and
/// `knots` are those of that NURBS form). `NurbsCurve(points, degree=3)` makes Grasshopper's
/// Nurbs Curve through control points; `NurbsCurve.line`, `.polyline` and `.circle` make the
/// exact forms.
#[pyclass(module = "locus", name = "NurbsCurve", frozen)]
#[derive(Clone, Debug)]
pub struct PyCurve {
    /// The value as it flows in graphs (`Line`, `Circle`, `Arc` or `Curve`).
    pub value: Value,
    /// The curve to evaluate.
    pub curve: Shared<Curve>,
}

impl PyCurve {
    /// The Python curve of a curve-like value, or `None` for other values.
    pub(crate) fn from_value(value: &Value) -> Option<Self> {
        let curve = match value {
            Value::Line(l) => Shared::new(Curve::from(*l)),
            Value::Circle(c) => Shared::new(Curve::from(*c)),
            Value::Arc(a) => Shared::new(Curve::from(*a)),
            Value::Curve(c) => c.clone(),
            _ => return None,
        };
        Some(Self {
            value: value.clone(),
            curve,
        })
    }

    fn from_curve(curve: Curve) -> Self {
        let curve = Shared::new(curve);
        Self {
            value: Value::Curve(curve.clone()),
            curve,
        }
    }

    fn nurbs(&self) -> NurbsCurve {
        match &*self.curve {
            Curve::Nurbs(n) => n.clone(),
            other => other.to_nurbs(),
        }
    }
}

#[pymethods]
impl PyCurve {
    #[new]
    #[pyo3(signature = (points, degree=3, weights=None, knots=None, periodic=false))]
    fn new(
        points: &Bound<'_, PyAny>,
        degree: usize,
        weights: Option<Vec<f64>>,
        knots: Option<Vec<f64>>,
        periodic: bool,
    ) -> PyResult<Self> {
        let points = points_from_py(points)?;
        let curve = match (weights, knots) {
            (None, None) => NurbsCurve::create(&points, degree, periodic),
            (weights, knots) => {
                if periodic {
                    return Err(PyValueError::new_err(
                        "periodic=True makes its own knots: give points and degree only",
                    ));
                }
                let knots = match knots {
                    Some(k) => k,
                    None => clamped_uniform_knots(points.len(), degree)?,
                };
                let weights = weights.unwrap_or_else(|| vec![1.0; points.len()]);
                NurbsCurve::new(degree, points, weights, knots)
            }
        }
        .map_err(|e| kernel_error("curve", &e))?;
        Ok(Self::from_curve(Curve::Nurbs(curve)))
    }

    /// The line segment from `start` to `end`.
    #[staticmethod]
    fn line(start: &Bound<'_, PyAny>, end: &Bound<'_, PyAny>) -> PyResult<Self> {
        let line = Line::new(point_like(start)?, point_like(end)?);
        if line.length() == 0.0 {
            return Err(PyValueError::new_err(
                "invalid line: start and end coincide",
            ));
        }
        Ok(Self {
            value: Value::Line(line),
            curve: Shared::new(Curve::from(line)),
        })
    }

    /// The polyline through `points` (an `(N, 3)` array or a list of points).
    #[staticmethod]
    fn polyline(points: &Bound<'_, PyAny>) -> PyResult<Self> {
        let polyline =
            Polyline::new(points_from_py(points)?).map_err(|e| kernel_error("polyline", &e))?;
        Ok(Self::from_curve(Curve::from(polyline)))
    }

    /// The circle of `radius` around the origin of `plane`, in that plane.
    #[staticmethod]
    fn circle(plane: &Bound<'_, PyPlane>, radius: f64) -> PyResult<Self> {
        let circle = Circle::new(plane.get().0, radius).map_err(|e| kernel_error("circle", &e))?;
        Ok(Self {
            value: Value::Circle(circle),
            curve: Shared::new(Curve::from(circle)),
        })
    }

    /// A curve from its literal text in the graph format (used by pickling).
    #[classmethod]
    fn _from_literal(_cls: &Bound<'_, PyType>, text: &str, type_name: &str) -> PyResult<Self> {
        let value = value_from_literal(text, type_name)?;
        Self::from_value(&value)
            .ok_or_else(|| PyValueError::new_err(format!("{type_name} is not a curve type")))
    }

    /// The exact form: `"line"`, `"polyline"`, `"circle"`, `"arc"` or `"nurbs"`.
    #[getter]
    fn kind(&self) -> &'static str {
        match &*self.curve {
            Curve::Line { .. } => "line",
            Curve::Polyline { .. } => "polyline",
            Curve::Circle { .. } => "circle",
            Curve::Arc { .. } => "arc",
            Curve::Nurbs(_) => "nurbs",
        }
    }

    /// The degree of the NURBS form.
    #[getter]
    fn degree(&self) -> usize {
        self.curve.degree()
    }

    /// The parameter domain.
    #[getter]
    fn domain(&self) -> PyDomain {
        PyDomain(self.curve.domain())
    }

    /// Whether the curve ends where it starts.
    #[getter]
    fn is_closed(&self) -> bool {
        self.curve.is_closed()
    }

    /// Whether the curve is periodic (closed with matching derivatives, Rhino's periodic form).
    #[getter]
    fn is_periodic(&self) -> bool {
        self.curve.is_periodic()
    }

    /// The start point.
    #[getter]
    fn start(&self) -> PyPoint3 {
        PyPoint3(self.curve.start_point())
    }

    /// The end point.
    #[getter]
    fn end(&self) -> PyPoint3 {
        PyPoint3(self.curve.end_point())
    }

    /// The control points of the NURBS form, as an `(N, 3)` numpy array.
    #[getter]
    fn control_points<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        points_to_numpy(py, self.nurbs().points())
    }

    /// The weights of the NURBS form, as an `(N,)` numpy array.
    #[getter]
    fn weights<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        PyArray1::from_slice(py, self.nurbs().weights())
    }

    /// The knots of the NURBS form in Rhino form (`points + degree - 1` of them).
    #[getter]
    fn knots<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        PyArray1::from_slice(py, self.nurbs().knots())
    }

    /// The point at parameter `t`.
    fn point_at(&self, t: f64) -> PyPoint3 {
        PyPoint3(self.curve.point_at(t))
    }

    /// The points at many parameters, as an `(N, 3)` numpy array (one batch evaluation).
    fn points_at<'py>(&self, py: Python<'py>, ts: Vec<f64>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        let mut out = vec![locus_kernel::Point3::ORIGIN; ts.len()];
        let curve = self.curve.clone();
        py.detach(|| curve.points_at(&ts, &mut out))
            .map_err(|e| kernel_error("parameter", &e))?;
        points_to_numpy(py, &out)
    }

    /// The unit tangent at `t`, or `None` where the derivative vanishes.
    fn tangent_at(&self, t: f64) -> Option<PyVector3> {
        self.curve.tangent_at(t).map(PyVector3)
    }

    /// The length (arc length of the NURBS form).
    fn length(&self) -> f64 {
        self.nurbs().length()
    }

    /// Without `samples`: the control points of the NURBS form as an `(N, 3)` array. With
    /// `samples = n`: `n` points at parameters evenly spaced over the domain, ends included.
    #[pyo3(signature = (samples=None))]
    fn to_numpy<'py>(
        &self,
        py: Python<'py>,
        samples: Option<usize>,
    ) -> PyResult<Bound<'py, PyArray2<f64>>> {
        match samples {
            None => self.control_points(py),
            Some(n) => {
                if n > locus_kernel::MAX_DIVISIONS {
                    return Err(PyValueError::new_err(format!(
                        "at most {} samples",
                        locus_kernel::MAX_DIVISIONS
                    )));
                }
                let d = self.curve.domain();
                let ts: Vec<f64> = match n {
                    0 => Vec::new(),
                    1 => vec![d.t0],
                    _ => (0..n)
                        .map(|i| d.parameter_at(i as f64 / (n - 1) as f64))
                        .collect(),
                };
                self.points_at(py, ts)
            }
        }
    }

    fn __eq__(&self, other: &Bound<'_, PyAny>) -> bool {
        other
            .cast::<PyCurve>()
            .is_ok_and(|o| o.get().value == self.value)
    }

    fn __repr__(&self) -> String {
        let d = self.curve.domain();
        format!(
            "NurbsCurve(kind={:?}, degree={}, domain=({}, {}))",
            self.kind(),
            self.degree(),
            d.t0,
            d.t1
        )
    }

    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<Bound<'py, PyTuple>> {
        let value = &slf.get().value;
        let rebuild = slf.get_type().getattr("_from_literal")?;
        (rebuild, (literal_of(value)?, value.data_type().name())).into_pyobject(slf.py())
    }
}

/// A NURBS surface: a grid of control points (`count_u × count_v`), weights and knots in Rhino
/// form in both directions.
///
/// `NurbsSurface(points, degree_u=3, degree_v=3, knots_u=None, knots_v=None, weights=None)`
/// takes a `(count_u, count_v, 3)` grid; missing knots are clamped and uniform.
#[pyclass(module = "locus", name = "NurbsSurface", frozen)]
#[derive(Clone, Debug)]
pub struct PySurface(pub Shared<NurbsSurface>);

#[pymethods]
impl PySurface {
    #[new]
    #[pyo3(signature = (points, degree_u=3, degree_v=3, knots_u=None, knots_v=None, weights=None))]
    fn new(
        points: &Bound<'_, PyAny>,
        degree_u: usize,
        degree_v: usize,
        knots_u: Option<Vec<f64>>,
        knots_v: Option<Vec<f64>>,
        weights: Option<Vec<Vec<f64>>>,
    ) -> PyResult<Self> {
        let rows: Vec<Bound<'_, PyAny>> = points
            .try_iter()?
            .collect::<PyResult<_>>()
            .map_err(|_| PyValueError::new_err("a surface takes a grid of control points"))?;
        let grid: Vec<Vec<locus_kernel::Point3>> =
            rows.iter().map(points_from_py).collect::<PyResult<_>>()?;
        let count_u = grid.len();
        let count_v = grid.first().map_or(0, Vec::len);
        let knots_u = match knots_u {
            Some(k) => k,
            None => clamped_uniform_knots(count_u, degree_u)?,
        };
        let knots_v = match knots_v {
            Some(k) => k,
            None => clamped_uniform_knots(count_v, degree_v)?,
        };
        let weights = weights.unwrap_or_else(|| vec![vec![1.0; count_v]; count_u]);
        NurbsSurface::new(degree_u, degree_v, grid, weights, knots_u, knots_v)
            .map(|s| Self(Shared::new(s)))
            .map_err(|e| kernel_error("surface", &e))
    }

    /// A surface from its literal text in the graph format (used by pickling).
    #[classmethod]
    fn _from_literal(_cls: &Bound<'_, PyType>, text: &str) -> PyResult<Self> {
        match value_from_literal(text, "Surface")? {
            Value::Surface(s) => Ok(Self(s)),
            _ => Err(PyValueError::new_err("not a surface literal")),
        }
    }

    /// The degree in `u`.
    #[getter]
    fn degree_u(&self) -> usize {
        self.0.degree_u()
    }

    /// The degree in `v`.
    #[getter]
    fn degree_v(&self) -> usize {
        self.0.degree_v()
    }

    /// The number of control points in `u`.
    #[getter]
    fn count_u(&self) -> usize {
        self.0.count_u()
    }

    /// The number of control points in `v`.
    #[getter]
    fn count_v(&self) -> usize {
        self.0.count_v()
    }

    /// The parameter domain in `u`.
    #[getter]
    fn domain_u(&self) -> PyDomain {
        PyDomain(self.0.domain_u())
    }

    /// The parameter domain in `v`.
    #[getter]
    fn domain_v(&self) -> PyDomain {
        PyDomain(self.0.domain_v())
    }

    /// The knots in `u` (Rhino form).
    #[getter]
    fn knots_u<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        PyArray1::from_slice(py, self.0.knots_u())
    }

    /// The knots in `v` (Rhino form).
    #[getter]
    fn knots_v<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        PyArray1::from_slice(py, self.0.knots_v())
    }

    /// The weights as a `(count_u, count_v)` numpy array.
    #[getter]
    fn weights<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        PyArray1::from_slice(py, self.0.weights()).reshape([self.0.count_u(), self.0.count_v()])
    }

    /// The control points as a `(count_u, count_v, 3)` numpy array.
    #[getter]
    fn control_points<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray3<f64>>> {
        let flat: Vec<f64> = self.0.points().iter().flat_map(|p| p.to_array()).collect();
        PyArray1::from_vec(py, flat).reshape([self.0.count_u(), self.0.count_v(), 3])
    }

    /// The point at parameters `(u, v)`.
    fn point_at(&self, u: f64, v: f64) -> PyPoint3 {
        PyPoint3(self.0.point_at(u, v))
    }

    /// The unit normal at `(u, v)`; `ValueError` where the surface is degenerate.
    fn normal_at(&self, u: f64, v: f64) -> PyResult<PyVector3> {
        self.0
            .normal_at(u, v)
            .map(PyVector3)
            .map_err(|e| kernel_error("surface point", &e))
    }

    /// Without `samples`: the control points as a `(count_u, count_v, 3)` array. With
    /// `samples = (nu, nv)`: an `(nu, nv, 3)` grid of points at parameters evenly spaced over
    /// the domain, ends included.
    #[pyo3(signature = (samples=None))]
    fn to_numpy<'py>(
        &self,
        py: Python<'py>,
        samples: Option<(usize, usize)>,
    ) -> PyResult<Bound<'py, PyArray3<f64>>> {
        let Some((nu, nv)) = samples else {
            return self.control_points(py);
        };
        if nu.saturating_mul(nv) > locus_kernel::MAX_DIVISIONS {
            return Err(PyValueError::new_err(format!(
                "at most {} samples",
                locus_kernel::MAX_DIVISIONS
            )));
        }
        let spaced = |d: Interval, n: usize| -> Vec<f64> {
            match n {
                0 => Vec::new(),
                1 => vec![d.t0],
                _ => (0..n)
                    .map(|i| d.parameter_at(i as f64 / (n - 1) as f64))
                    .collect(),
            }
        };
        let us = spaced(self.0.domain_u(), nu);
        let vs = spaced(self.0.domain_v(), nv);
        let mut out = vec![locus_kernel::Point3::ORIGIN; nu * nv];
        let surface = self.0.clone();
        py.detach(|| surface.points_on_grid(&us, &vs, &mut out))
            .map_err(|e| kernel_error("grid", &e))?;
        let flat: Vec<f64> = out.iter().flat_map(|p| p.to_array()).collect();
        PyArray1::from_vec(py, flat).reshape([nu, nv, 3])
    }

    fn __eq__(&self, other: &Bound<'_, PyAny>) -> bool {
        other
            .cast::<PySurface>()
            .is_ok_and(|o| *o.get().0 == *self.0)
    }

    fn __repr__(&self) -> String {
        format!(
            "NurbsSurface(degree=({}, {}), points={}×{})",
            self.0.degree_u(),
            self.0.degree_v(),
            self.0.count_u(),
            self.0.count_v()
        )
    }

    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<Bound<'py, PyTuple>> {
        let value = Value::Surface(slf.get().0.clone());
        let rebuild = slf.get_type().getattr("_from_literal")?;
        (rebuild, (literal_of(&value)?,)).into_pyobject(slf.py())
    }
}

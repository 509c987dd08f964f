//! B-reps and meshes as Python classes: `Brep` and `Mesh`.

use locus_kernel::{
    Brep, BrepEdge, BrepFace, BrepLoop, BrepTrim, BrepVertex, Color, Curve, LoopKind, Mesh,
    MeshFace, NurbsCurve, Point3, Sphere, TrimKind,
};
use locus_runtime::Shared;
use numpy::{PyArray1, PyArray2, PyArrayMethods, PyUntypedArrayMethods};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::{PyList, PyTuple, PyType};

use crate::arrays::{as_array, contiguous, points_from_py, points_to_numpy, vectors_to_numpy};
use crate::curves::{PyCurve, PySurface};
use crate::geometry::{PyBox, kernel_error, point_like, vector_like};

/// A pickled trim: curve, edge, reversed, loop index and vertices.
type PickledTrim<'py> = (Bound<'py, PyCurve>, Option<usize>, bool, usize, [usize; 2]);

/// A boundary representation: faces on NURBS surfaces bounded by trim loops, joined along
/// edges (Rhino's polysurfaces and solids).
///
/// Made by graphs, or by `Brep.from_box`, `Brep.from_surface` and `Brep.sphere`.
#[pyclass(module = "locus", name = "Brep", frozen)]
#[derive(Clone, Debug)]
pub struct PyBrep(pub Shared<Brep>);

#[pymethods]
impl PyBrep {
    /// The closed B-rep of a box (six faces).
    #[staticmethod]
    fn from_box(b: &Bound<'_, PyBox>) -> PyResult<Self> {
        Brep::from_box(&b.get().0)
            .map(|b| Self(Shared::new(b)))
            .map_err(|e| kernel_error("box", &e))
    }

    /// The one-face B-rep of an untrimmed surface.
    #[staticmethod]
    fn from_surface(s: &Bound<'_, PySurface>) -> PyResult<Self> {
        Brep::from_surface((*s.get().0).clone())
            .map(|b| Self(Shared::new(b)))
            .map_err(|e| kernel_error("surface", &e))
    }

    /// The closed B-rep of a sphere (Rhino's sphere form).
    #[staticmethod]
    fn sphere(center: &Bound<'_, PyAny>, radius: f64) -> PyResult<Self> {
        let sphere =
            Sphere::new(point_like(center)?, radius).map_err(|e| kernel_error("sphere", &e))?;
        Brep::from_sphere(&sphere)
            .map(|b| Self(Shared::new(b)))
            .map_err(|e| kernel_error("sphere", &e))
    }

    /// The number of faces.
    #[getter]
    fn face_count(&self) -> usize {
        self.0.faces().len()
    }

    /// The number of edges.
    #[getter]
    fn edge_count(&self) -> usize {
        self.0.edges().len()
    }

    /// The number of vertices.
    #[getter]
    fn vertex_count(&self) -> usize {
        self.0.vertices().len()
    }

    /// The surfaces of the faces (untrimmed), in face order.
    #[getter]
    fn surfaces(&self) -> Vec<PySurface> {
        self.0
            .faces()
            .iter()
            .map(|f| PySurface(Shared::new(f.surface.clone())))
            .collect()
    }

    /// The 3-D curves of the edges, in edge order.
    #[getter]
    fn edges(&self) -> Vec<PyCurve> {
        self.0
            .edges()
            .iter()
            .filter_map(|e| {
                PyCurve::from_value(&locus_runtime::Value::Curve(Shared::new(
                    locus_kernel::Curve::Nurbs(e.curve.clone()),
                )))
            })
            .collect()
    }

    /// The vertices as a `(V, 3)` numpy array.
    #[getter]
    fn vertices<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        let points: Vec<_> = self.0.vertices().iter().map(|v| v.point).collect();
        points_to_numpy(py, &points)
    }

    /// Whether the B-rep encloses a volume (every edge joins two faces).
    #[getter]
    fn is_solid(&self) -> bool {
        self.0.is_solid()
    }

    /// The surface area of the trimmed faces.
    fn area(&self, py: Python<'_>) -> PyResult<f64> {
        let b = self.0.clone();
        py.detach(|| b.area())
            .map_err(|e| kernel_error("B-rep", &e))
    }

    /// The enclosed volume; `ValueError` for an open B-rep.
    fn volume(&self, py: Python<'_>) -> PyResult<f64> {
        let b = self.0.clone();
        py.detach(|| b.volume())
            .map_err(|e| kernel_error("B-rep", &e))
    }

    /// A B-rep from its parts (used by pickling); the topology is checked by the kernel.
    #[classmethod]
    fn _from_parts(
        _cls: &Bound<'_, PyType>,
        faces: Vec<(Bound<'_, PySurface>, Vec<usize>, bool)>,
        loops: Vec<(usize, bool, Vec<usize>)>,
        trims: Vec<PickledTrim<'_>>,
        edges: Vec<(Bound<'_, PyCurve>, [usize; 2])>,
        vertices: Vec<[f64; 3]>,
    ) -> PyResult<Self> {
        let nurbs = |c: &Bound<'_, PyCurve>| -> PyResult<NurbsCurve> {
            match &*c.get().curve {
                Curve::Nurbs(n) => Ok(n.clone()),
                _ => Err(PyValueError::new_err("B-rep curves are NURBS curves")),
            }
        };
        let faces = faces
            .into_iter()
            .map(|(surface, loops, reversed)| BrepFace {
                surface: (*surface.get().0).clone(),
                loops,
                reversed,
            })
            .collect();
        let loops = loops
            .into_iter()
            .map(|(face, outer, trims)| BrepLoop {
                face,
                kind: if outer {
                    LoopKind::Outer
                } else {
                    LoopKind::Inner
                },
                trims,
            })
            .collect();
        let trims = trims
            .iter()
            .map(|(curve, edge, reversed, loop_index, vertices)| {
                Ok(BrepTrim {
                    curve: nurbs(curve)?,
                    edge: *edge,
                    reversed: *reversed,
                    kind: TrimKind::Boundary,
                    loop_index: *loop_index,
                    vertices: *vertices,
                })
            })
            .collect::<PyResult<_>>()?;
        let edges = edges
            .iter()
            .map(|(curve, vertices)| {
                Ok(BrepEdge {
                    curve: nurbs(curve)?,
                    vertices: *vertices,
                    trims: Vec::new(),
                })
            })
            .collect::<PyResult<_>>()?;
        let vertices = vertices
            .into_iter()
            .map(|p| BrepVertex {
                point: Point3::from_array(p),
                edges: Vec::new(),
            })
            .collect();
        Brep::from_parts(vertices, edges, trims, loops, faces)
            .map(|b| Self(Shared::new(b)))
            .map_err(|e| kernel_error("B-rep", &e))
    }

    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<Bound<'py, PyTuple>> {
        let py = slf.py();
        let b = &slf.get().0;
        let curve = |c: &NurbsCurve| -> PyResult<Bound<'py, PyCurve>> {
            let value = locus_runtime::Value::Curve(Shared::new(Curve::Nurbs(c.clone())));
            let curve =
                PyCurve::from_value(&value).ok_or_else(|| PyValueError::new_err("not a curve"))?;
            Bound::new(py, curve)
        };
        let faces = PyList::empty(py);
        for f in b.faces() {
            let surface = Bound::new(py, PySurface(Shared::new(f.surface.clone())))?;
            faces.append((surface, f.loops.clone(), f.reversed))?;
        }
        let loops: Vec<(usize, bool, Vec<usize>)> = b
            .loops()
            .iter()
            .map(|l| (l.face, l.kind == LoopKind::Outer, l.trims.clone()))
            .collect();
        let trims = PyList::empty(py);
        for t in b.trims() {
            trims.append((
                curve(&t.curve)?,
                t.edge,
                t.reversed,
                t.loop_index,
                t.vertices,
            ))?;
        }
        let edges = PyList::empty(py);
        for e in b.edges() {
            edges.append((curve(&e.curve)?, e.vertices))?;
        }
        let vertices: Vec<[f64; 3]> = b.vertices().iter().map(|v| v.point.to_array()).collect();
        let rebuild = slf.get_type().getattr("_from_parts")?;
        (rebuild, (faces, loops, trims, edges, vertices)).into_pyobject(py)
    }

    fn __eq__(&self, other: &Bound<'_, PyAny>) -> bool {
        other.cast::<PyBrep>().is_ok_and(|o| *o.get().0 == *self.0)
    }

    fn __repr__(&self) -> String {
        format!(
            "Brep(faces={}, edges={}, vertices={}, solid={})",
            self.face_count(),
            self.edge_count(),
            self.vertex_count(),
            if self.is_solid() { "True" } else { "False" }
        )
    }
}

/// A polygon mesh of triangles and quads with optional vertex normals and colours.
///
/// `Mesh(vertices, faces, normals=None, colors=None)`: vertices `(N, 3)`; faces `(M, 3)` or
/// `(M, 4)` vertex indices (or a list of 3- and 4-tuples; a triangle may also be written as four
/// indices repeating the third); normals `(N, 3)`; colours `(N, 4)` RGBA bytes.
#[pyclass(module = "locus", name = "Mesh", frozen)]
#[derive(Clone, Debug)]
pub struct PyMesh(pub Shared<Mesh>);

fn mesh_faces(obj: &Bound<'_, PyAny>) -> PyResult<Vec<MeshFace>> {
    let rows: Vec<Vec<i64>> = if as_array(obj).is_some() {
        let array = contiguous::<i64>(obj, "int64")?;
        let shape = array.shape().to_vec();
        if shape.len() != 2 || !(shape[1] == 3 || shape[1] == 4) {
            return Err(PyValueError::new_err(format!(
                "mesh faces are an (M, 3) or (M, 4) array of vertex indices, found shape {shape:?}"
            )));
        }
        let read = array.readonly();
        let data = read
            .as_slice()
            .map_err(|e| PyValueError::new_err(e.to_string()))?;
        data.chunks_exact(shape[1]).map(<[i64]>::to_vec).collect()
    } else {
        obj.extract()?
    };
    rows.iter()
        .enumerate()
        .map(|(i, r)| {
            let index = |k: usize| {
                u32::try_from(r[k]).map_err(|_| {
                    PyValueError::new_err(format!("mesh face {i}: bad vertex index {}", r[k]))
                })
            };
            match r.len() {
                3 => Ok(MeshFace::triangle(index(0)?, index(1)?, index(2)?)),
                4 => Ok(MeshFace::quad(index(0)?, index(1)?, index(2)?, index(3)?)),
                n => Err(PyValueError::new_err(format!(
                    "mesh face {i} has {n} indices: a face is a triangle (3) or a quad (4)"
                ))),
            }
        })
        .collect()
}

#[pymethods]
impl PyMesh {
    #[new]
    #[pyo3(signature = (vertices, faces, normals=None, colors=None))]
    fn new(
        vertices: &Bound<'_, PyAny>,
        faces: &Bound<'_, PyAny>,
        normals: Option<&Bound<'_, PyAny>>,
        colors: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<Self> {
        let mut mesh = Mesh::new(points_from_py(vertices)?, mesh_faces(faces)?)
            .map_err(|e| kernel_error("mesh", &e))?;
        if let Some(n) = normals.filter(|n| !n.is_none()) {
            let normals = if as_array(n).is_some() {
                crate::arrays::xyz_rows(n)?
                    .into_iter()
                    .map(locus_kernel::Vector3::from_array)
                    .collect()
            } else {
                n.try_iter()?
                    .map(|v| vector_like(&v?))
                    .collect::<PyResult<Vec<_>>>()?
            };
            mesh = mesh
                .with_normals(normals)
                .map_err(|e| kernel_error("mesh", &e))?;
        }
        if let Some(c) = colors.filter(|c| !c.is_none()) {
            let rows: Vec<[u8; 4]> = if as_array(c).is_some() {
                let array = contiguous::<u8>(c, "uint8")?;
                let shape = array.shape().to_vec();
                if shape.len() != 2 || shape[1] != 4 {
                    return Err(PyValueError::new_err(format!(
                        "mesh colours are an (N, 4) array of RGBA bytes, found shape {shape:?}"
                    )));
                }
                let read = array.readonly();
                let data = read
                    .as_slice()
                    .map_err(|e| PyValueError::new_err(e.to_string()))?;
                data.chunks_exact(4)
                    .map(|c| [c[0], c[1], c[2], c[3]])
                    .collect()
            } else {
                c.extract::<Vec<(u8, u8, u8, u8)>>()?
                    .into_iter()
                    .map(|(r, g, b, a)| [r, g, b, a])
                    .collect()
            };
            let colors = rows
                .into_iter()
                .map(|[r, g, b, a]| Color { r, g, b, a })
                .collect();
            mesh = mesh
                .with_colors(colors)
                .map_err(|e| kernel_error("mesh", &e))?;
        }
        Ok(Self(Shared::new(mesh)))
    }

    /// The vertices as an `(N, 3)` numpy array.
    #[getter]
    fn vertices<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        points_to_numpy(py, self.0.vertices())
    }

    /// The faces as an `(M, 4)` array of vertex indices (a triangle repeats its third index).
    #[getter]
    fn faces<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<u32>>> {
        let flat: Vec<u32> = self.0.faces().iter().flat_map(|f| f.vertices).collect();
        PyArray1::from_vec(py, flat).reshape([self.0.faces().len(), 4])
    }

    /// The vertex normals as an `(N, 3)` array, or `None`.
    #[getter]
    fn normals<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyArray2<f64>>>> {
        self.0
            .normals()
            .map(|n| vectors_to_numpy(py, n))
            .transpose()
    }

    /// The vertex colours as an `(N, 4)` array of RGBA bytes, or `None`.
    #[getter]
    fn colors<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyArray2<u8>>>> {
        self.0
            .colors()
            .map(|c| {
                let flat: Vec<u8> = c.iter().flat_map(|c| [c.r, c.g, c.b, c.a]).collect();
                PyArray1::from_vec(py, flat).reshape([c.len(), 4])
            })
            .transpose()
    }

    /// The number of triangles once quads are split.
    #[getter]
    fn triangle_count(&self) -> usize {
        self.0.triangle_count()
    }

    /// Whether every edge joins exactly two faces, consistently oriented.
    #[getter]
    fn is_closed(&self) -> bool {
        self.0.is_closed_and_oriented()
    }

    /// The surface area.
    fn area(&self) -> f64 {
        self.0.area()
    }

    /// The enclosed volume (meaningful for a closed mesh).
    fn volume(&self) -> f64 {
        self.0.volume()
    }

    fn __eq__(&self, other: &Bound<'_, PyAny>) -> bool {
        other.cast::<PyMesh>().is_ok_and(|o| *o.get().0 == *self.0)
    }

    fn __repr__(&self) -> String {
        format!(
            "Mesh(vertices={}, faces={})",
            self.0.vertices().len(),
            self.0.faces().len()
        )
    }

    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<Bound<'py, PyTuple>> {
        let py = slf.py();
        let m = &slf.get().0;
        let vertices: Vec<[f64; 3]> = m.vertices().iter().map(|p| p.to_array()).collect();
        let faces: Vec<Vec<u32>> = m.faces().iter().map(|f| f.corners().to_vec()).collect();
        let normals = m
            .normals()
            .map(|n| n.iter().map(|v| v.to_array()).collect::<Vec<_>>());
        let colors = m
            .colors()
            .map(|c| c.iter().map(|c| (c.r, c.g, c.b, c.a)).collect::<Vec<_>>());
        let faces = PyList::new(py, faces)?;
        (slf.get_type(), (vertices, faces, normals, colors)).into_pyobject(py)
    }
}

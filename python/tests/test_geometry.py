"""The geometry classes: construction, evaluation, numpy forms and exact pickling."""

import copy
import math
import pickle

import numpy as np
import pytest
from hypothesis import given, strategies as st

import locus

finite = st.floats(allow_nan=False, allow_infinity=False, width=64)
small = st.floats(-1e6, 1e6)
coords = st.tuples(finite, finite, finite)


def round_trip(obj):
    out = pickle.loads(pickle.dumps(obj, protocol=pickle.HIGHEST_PROTOCOL))
    assert type(out) is type(obj)
    assert out == obj
    assert copy.deepcopy(obj) == obj
    return out


@given(coords)
def test_points_and_vectors_pickle_exactly(c):
    p = round_trip(locus.Point3(*c))
    assert (p.x, p.y, p.z) == c
    v = round_trip(locus.Vector3(*c))
    assert tuple(v) == c


@given(st.tuples(small, small, small), st.tuples(small, small, small).filter(lambda v: sum(x * x for x in v) > 1e-6))
def test_planes_pickle_exactly(origin, normal):
    plane = locus.Plane.from_normal(origin, normal)
    out = round_trip(plane)
    assert out.z_axis == plane.z_axis and out.origin == plane.origin


def test_tampered_plane_pickles_are_refused():
    with pytest.raises(ValueError, match="invalid plane"):
        locus.Plane._from_axes((0, 0, 0), (1, 0, 0), (1, 0, 0), (0, 0, 1))


@given(finite, finite)
def test_domains_pickle(t0, t1):
    d = round_trip(locus.Domain(t0, t1))
    assert (d.t0, d.t1) == (t0, t1)


@st.composite
def nurbs(draw):
    degree = draw(st.integers(1, 4))
    n = draw(st.integers(degree + 1, degree + 6))
    weights = draw(st.one_of(st.none(), st.lists(st.floats(0.01, 100), min_size=n, max_size=n)))
    periodic = weights is None and draw(st.booleans()) and n >= max(3, degree + 2)
    points = draw(st.lists(st.tuples(small, small, small), min_size=n, max_size=n, unique=periodic))
    if periodic:
        return locus.NurbsCurve(points, degree=degree, periodic=True)
    return locus.NurbsCurve(points, degree=degree, weights=weights)


@given(nurbs())
def test_curves_pickle_exactly(curve):
    out = round_trip(curve)
    np.testing.assert_array_equal(out.knots, curve.knots)
    np.testing.assert_array_equal(out.weights, curve.weights)
    t = curve.domain.parameter_at(0.37)
    assert out.point_at(t) == curve.point_at(t)


def test_curve_forms_pickle_and_keep_their_kind():
    plane = locus.Plane((1, 2, 3), (1, 1, 0), (0, 0, 1))
    for c in [
        locus.NurbsCurve.line((0, 0, 0), (3, 4, 0)),
        locus.NurbsCurve.circle(plane, 2.5),
        locus.NurbsCurve.polyline(np.array([[0, 0, 0], [1, 0, 0], [1, 1, 1]], dtype=float)),
    ]:
        assert round_trip(c).kind == c.kind


def test_curve_evaluation_and_numpy():
    line = locus.NurbsCurve.line((0, 0, 0), (3, 4, 0))
    assert line.length() == pytest.approx(5)
    assert line.domain == locus.Domain(0, 5)  # Rhino: a line is parameterised by length
    assert line.point_at(2.5) == locus.Point3(1.5, 2, 0)
    assert tuple(line.tangent_at(0.2)) == pytest.approx((0.6, 0.8, 0), abs=1e-15)
    samples = line.to_numpy(5)
    np.testing.assert_allclose(samples[:, 0], [0, 0.75, 1.5, 2.25, 3])
    np.testing.assert_array_equal(line.to_numpy(), [[0, 0, 0], [3, 4, 0]])
    pts = line.points_at([0.0, 5.0])
    np.testing.assert_array_equal(pts, [[0, 0, 0], [3, 4, 0]])
    circle = locus.NurbsCurve.circle(locus.Plane.world_xy(), 1.0)
    assert circle.is_closed and circle.length() == pytest.approx(2 * math.pi, rel=1e-9)
    assert circle.domain.t1 == pytest.approx(2 * math.pi)
    assert circle.to_numpy().shape == (9, 3)  # Rhino's 9-point rational circle
    # A NaN parameter gives a NaN point, never a crash.
    nurbs = locus.NurbsCurve([(0, 0, 0), (1, 1, 0), (2, 0, 0)], degree=2)
    for c in (line, nurbs):
        assert np.isnan(c.points_at([float("nan")])).all()


def test_bad_curves_are_refused_with_the_kernels_reason():
    with pytest.raises(ValueError, match="invalid curve"):
        locus.NurbsCurve([(0, 0, 0), (1, 0, 0)], degree=3)
    with pytest.raises(ValueError, match="invalid curve"):
        locus.NurbsCurve([(0, 0, 0), (1, 0, 0)], degree=1, knots=[1, 0])
    with pytest.raises(ValueError, match="invalid curve"):
        locus.NurbsCurve([(0, 0, 0), (1, 0, 0)], degree=1, weights=[1, 0])
    with pytest.raises(ValueError, match="not finite"):
        locus.NurbsCurve(np.array([[0, 0, 0], [np.inf, 0, 0]]), degree=1)
    with pytest.raises(ValueError, match="invalid line"):
        locus.NurbsCurve.line((1, 1, 1), (1, 1, 1))
    with pytest.raises(ValueError, match="invalid"):
        locus.NurbsCurve._from_literal("(degree: 9, points: [], knots: [])", "Curve")
    with pytest.raises(ValueError):
        locus.NurbsCurve.circle(locus.Plane.world_xy(), 0.0)


@st.composite
def surfaces(draw):
    du, dv = draw(st.integers(1, 3)), draw(st.integers(1, 3))
    nu, nv = draw(st.integers(du + 1, du + 3)), draw(st.integers(dv + 1, dv + 3))
    grid = draw(st.lists(st.lists(st.tuples(small, small, small), min_size=nv, max_size=nv), min_size=nu, max_size=nu))
    weights = draw(st.one_of(st.none(), st.lists(st.lists(st.floats(0.1, 10), min_size=nv, max_size=nv), min_size=nu, max_size=nu)))
    return locus.NurbsSurface(grid, degree_u=du, degree_v=dv, weights=weights)


@given(surfaces())
def test_surfaces_pickle_exactly(surface):
    out = round_trip(surface)
    np.testing.assert_array_equal(out.control_points, surface.control_points)
    assert out.point_at(out.domain_u.parameter_at(0.3), out.domain_v.parameter_at(0.6)) == surface.point_at(
        surface.domain_u.parameter_at(0.3), surface.domain_v.parameter_at(0.6)
    )


def test_surface_grids():
    s = locus.NurbsSurface(np.array([[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 0]]], dtype=float), degree_u=1, degree_v=1)
    grid = s.to_numpy((3, 2))
    assert grid.shape == (3, 2, 3)
    np.testing.assert_allclose(grid[1, 1], [0.5, 1, 0])
    assert s.normal_at(0.5, 0.5) == locus.Vector3(0, 0, 1)
    assert s.control_points.shape == (2, 2, 3) and s.weights.shape == (2, 2)


def test_transforms_and_boxes():
    t = locus.Transform.translation((1, 2, 3))
    assert t.transform_point((0, 0, 0)) == locus.Point3(1, 2, 3)
    assert t.transform_vector((1, 0, 0)) == locus.Vector3(1, 0, 0)
    assert (t @ t).transform_point((0, 0, 0)) == locus.Point3(2, 4, 6)
    np.testing.assert_array_equal(t.to_numpy()[:3, 3], [1, 2, 3])
    assert round_trip(locus.Transform(t.to_numpy())) == t
    box = locus.Box(locus.Plane.world_xy(), (0, 1), (0, 2), locus.Domain(0, 3))
    assert box.volume == 6 and box.corners().shape == (8, 3)
    round_trip(box)


def test_breps():
    box = locus.Brep.from_box(locus.Box(locus.Plane.world_xy(), (0, 1), (0, 2), (0, 3)))
    assert (box.face_count, box.edge_count, box.vertex_count, box.is_solid) == (6, 12, 8, True)
    assert box.volume() == pytest.approx(6) and box.area() == pytest.approx(22)
    assert box.vertices.shape == (8, 3)
    assert all(isinstance(s, locus.NurbsSurface) for s in box.surfaces)
    sphere = locus.Brep.sphere((0, 0, 0), 2)
    assert sphere.volume() == pytest.approx(4 / 3 * math.pi * 8, rel=1e-6)
    with pytest.raises(ValueError):
        locus.Brep.sphere((0, 0, 0), -1)


@given(st.lists(st.tuples(small, small, small), min_size=4, max_size=12), st.data())
def test_meshes_pickle_exactly(vertices, data):
    n = len(vertices)
    faces = data.draw(st.lists(st.lists(st.integers(0, n - 1), min_size=3, max_size=4, unique=True), min_size=1, max_size=6))
    colors = data.draw(st.one_of(st.none(), st.lists(st.tuples(*[st.integers(0, 255)] * 4), min_size=n, max_size=n)))
    mesh = locus.Mesh(vertices, faces, colors=colors)
    out = round_trip(mesh)
    np.testing.assert_array_equal(out.vertices, np.array(vertices, dtype=float))
    np.testing.assert_array_equal(out.faces, mesh.faces)


def test_mesh_arrays_and_validation():
    v = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], dtype=float)
    quad = locus.Mesh(v, np.array([[0, 1, 2, 3]]), normals=np.tile([0.0, 0.0, 1.0], (4, 1)))
    assert quad.area() == pytest.approx(1) and quad.triangle_count == 2
    assert quad.normals.shape == (4, 3) and quad.colors is None
    round_trip(quad)
    with pytest.raises(ValueError, match="vertex"):
        locus.Mesh(v, [(0, 1, 7)])
    with pytest.raises(ValueError):
        locus.Mesh(v, [(0, 1)])
    with pytest.raises(ValueError):
        locus.Mesh(v, [(0, 1, -2)])


def test_point_and_vector_arithmetic():
    a, b = locus.Point3(1, 2, 3), locus.Point3(4, 6, 3)
    assert b - a == locus.Vector3(3, 4, 0)
    assert (b - a).length == 5 and a.distance_to(b) == 5
    assert a + locus.Vector3(1, 1, 1) == locus.Point3(2, 3, 4)
    assert 2 * locus.Vector3(1, 2, 3) == locus.Vector3(2, 4, 6)
    assert -locus.Vector3(1, 0, 0) == locus.Vector3(-1, 0, 0)
    assert locus.Vector3(1, 0, 0).cross((0, 1, 0)) == locus.Vector3(0, 0, 1)
    with pytest.raises(TypeError):
        a + b  # a point plus a point has no meaning
    with pytest.raises(ValueError):
        locus.Vector3(0, 0, 0).unitized()
    np.testing.assert_array_equal(np.asarray([a, b]), [[1, 2, 3], [4, 6, 3]])
    x, y, z = a
    assert (x, y, z) == (1, 2, 3) and a[-1] == 3
    assert repr(a) == "Point3(1.0, 2.0, 3.0)"


def test_breps_pickle_exactly_and_tampered_ones_are_refused():
    plane = locus.Plane.from_normal((1, 2, 3), (1, 1, 1))
    breps = [
        locus.Brep.from_box(locus.Box(plane, (0, 1), (-2, 2), (0, 0.5))),
        locus.Brep.sphere((1, 2, 3), 2.5),
        locus.Brep.from_surface(locus.NurbsSurface([[(0, 0, 0), (0, 1, 0)], [(1, 0, 0), (1, 1, 1)]], degree_u=1, degree_v=1)),
    ]
    for b in breps:
        out = round_trip(b)
        assert out.volume() == b.volume() if b.is_solid else out.area() == b.area()
    rebuild, (faces, loops, trims, edges, vertices) = breps[0].__reduce__()
    broken = list(trims)
    curve, edge, reversed_, loop_index, ends = broken[0]
    broken[0] = (curve, edge, reversed_, 99, ends)
    with pytest.raises(ValueError, match="invalid B-rep: .*trim 0"):
        rebuild(faces, loops, broken, edges, vertices)
    with pytest.raises(ValueError, match="vertex"):
        rebuild(faces, loops, trims, edges, vertices[:3])

"""Values both ways between Python and locus: property tests with hypothesis.

Each value goes into a graph through a parameter node (which passes data through unchanged)
and comes back out; what comes out must be what went in, and feeding it to another graph must
give the same tree again.
"""

import math

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st
from hypothesis.extra import numpy as hnp

import locus
from conftest import passthrough

settings.register_profile("ci", max_examples=60, deadline=None)
settings.load_profile("ci")

finite = st.floats(allow_nan=False, allow_infinity=False, width=64)
reals = st.floats(allow_nan=True, allow_infinity=True, width=64)
ints64 = st.integers(min_value=-(2**63), max_value=2**63 - 1)
texts = st.text(alphabet=st.characters(blacklist_categories=("Cs",)), max_size=20)
coords = st.tuples(finite, finite, finite)
paths = st.lists(st.integers(0, 50), min_size=1, max_size=4)


def same(a, b):
    """Equality that treats NaN as equal to NaN, element by element."""
    if isinstance(a, float) and isinstance(b, float):
        return (math.isnan(a) and math.isnan(b)) or a == b
    if isinstance(a, list) and isinstance(b, list):
        return len(a) == len(b) and all(same(x, y) for x, y in zip(a, b))
    if isinstance(a, dict) and isinstance(b, dict):
        return a.keys() == b.keys() and all(same(a[k], b[k]) for k in a)
    return type(a) is type(b) and a == b


def through(type_name, value):
    g = passthrough(type_name)
    g.set("x", value)
    g.evaluate()
    return g


@given(st.lists(reals, max_size=20))
def test_numbers(values):
    g = through("Number", values)
    assert same(g.tree("y"), {"{0}": values} if values else {"{0}": []})
    assert same(locus._locus._roundtrip(values, "Number"), {"{0}": values})


@given(reals)
def test_a_number_is_one_item(x):
    assert same(through("Number", x)["y"], x)


@given(st.lists(ints64, max_size=20))
def test_integers(values):
    assert same(through("Integer", values).tree("y"), {"{0}": values})


def test_integers_beyond_64_bits_are_refused():
    with pytest.raises(locus.InputError, match="64-bit"):
        through("Integer", [2**63])


@given(st.lists(st.integers(-(2**53), 2**53), max_size=10))
def test_ints_on_a_number_input_are_numbers(values):
    assert same(through("Number", values).tree("y"), {"{0}": [float(v) for v in values]})


@given(st.lists(st.booleans(), max_size=20))
def test_booleans(values):
    assert same(through("Boolean", values).tree("y"), {"{0}": values})


@given(st.lists(texts, max_size=10))
def test_texts(values):
    assert same(through("Text", values).tree("y"), {"{0}": values})


@given(st.lists(st.one_of(st.none(), finite), max_size=10))
def test_nulls(values):
    out = through("Number", values).tree("y")["{0}"]
    assert same(out, values)


@given(st.dictionaries(st.tuples(*[st.integers(0, 9)] * 2), st.lists(finite, max_size=5), max_size=6))
def test_trees_from_dicts(tree):
    expected = {"{%d;%d}" % k: v for k, v in sorted(tree.items())}
    g = through("Number", {"{%d;%d}" % k: v for k, v in tree.items()})
    got = g.tree("y")
    assert same(got, expected)
    assert list(got) == list(expected), "branches come out sorted by path"
    # Tuple keys are paths too, and the output fed back in is the same tree.
    assert same(through("Number", tree).tree("y"), expected)
    assert same(through("Number", got).tree("y"), expected)


@given(paths, st.lists(ints64, max_size=5))
def test_path_text_forms(path, values):
    key = "{" + ";".join(map(str, path)) + "}"
    assert same(through("Integer", {key: values}).tree("y"), {key: values})
    assert same(through("Integer", {";".join(map(str, path)): values}).tree("y"), {key: values})


@given(hnp.arrays(np.float64, st.integers(0, 50), elements=reals))
def test_numpy_numbers(array):
    g = through("Number", array)
    out = g.array("y")
    assert out.dtype == np.float64
    np.testing.assert_array_equal(out, array)


@given(hnp.arrays(np.int64, st.integers(0, 50)))
def test_numpy_integers(array):
    out = through("Integer", array).array("y")
    assert out.dtype == np.int64
    np.testing.assert_array_equal(out, array)


@given(hnp.arrays(np.bool_, st.integers(0, 50)))
def test_numpy_booleans(array):
    out = through("Boolean", array).array("y")
    assert out.dtype == np.bool_
    np.testing.assert_array_equal(out, array)


@given(hnp.arrays(np.float64, st.tuples(st.integers(0, 30), st.just(3)), elements=finite))
def test_numpy_points_and_vectors(array):
    points = through("Point", array)
    np.testing.assert_array_equal(points.array("y"), array)
    assert all(isinstance(p, locus.Point3) for p in points.tree("y")["{0}"])
    vectors = through("Vector", array)
    np.testing.assert_array_equal(vectors.array("y"), array)
    assert all(isinstance(v, locus.Vector3) for v in vectors.tree("y")["{0}"])


@given(hnp.arrays(st.sampled_from([np.float32, np.int32, np.uint8, np.int16]), st.integers(0, 20)))
def test_other_numpy_dtypes_are_read_as_their_values(array):
    out = through("Number", array).array("y")
    np.testing.assert_array_equal(out, array.astype(np.float64))


def test_non_contiguous_arrays_are_read_correctly():
    base = np.arange(30, dtype=np.float64).reshape(10, 3)
    np.testing.assert_array_equal(through("Point", base[::2]).array("y"), base[::2])
    np.testing.assert_array_equal(through("Number", base[:, 1]).array("y"), base[:, 1])


@given(coords)
def test_points_as_tuples_and_objects(c):
    assert through("Point", c)["y"] == locus.Point3(*c)
    assert through("Point", locus.Point3(*c))["y"] == locus.Point3(*c)
    assert through("Vector", c)["y"] == locus.Vector3(*c)
    assert through("Geometry", [locus.Point3(*c), locus.Vector3(*c)]).tree("y") == {
        "{0}": [locus.Point3(*c), locus.Vector3(*c)]
    }


def _roundtrip_items(values):
    return locus._locus._roundtrip(values, "Generic")["{0}"]


@given(st.lists(st.one_of(ints64, finite, st.booleans(), texts), max_size=10))
def test_numpy_scalars_are_items(values):
    scalars = [np.float64(v) if isinstance(v, float) else v for v in values]
    assert same(_roundtrip_items(scalars), _roundtrip_items(values))
    x = np.float32(1.5)
    assert through("Number", x)["y"] == 1.5
    assert through("Integer", np.int64(7))["y"] == 7
    assert through("Boolean", np.bool_(True))["y"] is True
    assert through("Number", np.array(2.5))["y"] == 2.5


@st.composite
def curves(draw):
    degree = draw(st.integers(1, 3))
    n = draw(st.integers(degree + 1, degree + 5))
    small = st.floats(-1e6, 1e6)
    points = draw(st.lists(st.tuples(small, small, small), min_size=n, max_size=n))
    weights = draw(st.one_of(st.none(), st.lists(st.floats(0.1, 10), min_size=n, max_size=n)))
    return locus.NurbsCurve(points, degree=degree, weights=weights)


@given(curves())
def test_curves_both_ways(curve):
    out = through("Curve", curve)["y"]
    assert out == curve
    np.testing.assert_array_equal(out.control_points, curve.control_points)
    np.testing.assert_array_equal(out.knots, curve.knots)


def test_every_geometry_class_goes_through_graphs():
    plane = locus.Plane.from_normal((1, 2, 3), (0, 1, 1))
    box = locus.Box(plane, (0, 1), (0, 2), (0, 3))
    surface = locus.NurbsSurface([[(0, 0, 0), (0, 1, 0)], [(1, 0, 0), (1, 1, 1)]], degree_u=1, degree_v=1)
    items = [
        locus.Point3(1, 2, 3),
        plane,
        box,
        locus.NurbsCurve.line((0, 0, 0), (1, 0, 0)),
        locus.NurbsCurve.circle(plane, 2.0),
        locus.NurbsCurve.polyline([(0, 0, 0), (1, 0, 0), (1, 1, 0)]),
        surface,
        locus.Brep.from_box(box),
    ]
    out = through("Geometry", items).tree("y")["{0}"]
    assert out == items
    assert [c.kind for c in out[3:6]] == ["line", "circle", "polyline"]
    assert through("Plane", plane)["y"] == plane
    assert through("Domain", (2, 5))["y"] == locus.Domain(2, 5)
    t = locus.Transform.translation((1, 2, 3))
    assert through("Transform", t)["y"] == t
    assert through("Surface", surface)["y"] == surface
    assert through("Brep", locus.Brep.from_box(box))["y"].is_solid


def test_graph_casts_apply_on_the_way_in():
    # Grasshopper's casts: text that reads as a number, a number on an integer input.
    assert through("Number", "2.5")["y"] == 2.5
    assert through("Integer", 2.6)["y"] == 3
    assert through("Boolean", 0)["y"] is False


def test_meshes_flow_through_graphs():
    mesh = locus.Mesh([(0, 0, 0), (1, 0, 0), (0, 1, 0)], [(0, 1, 2)])
    assert through("Mesh", mesh)["y"] == mesh
    assert through("Geometry", mesh)["y"] == mesh


def test_none_is_no_data():
    g = through("Number", None)
    assert g["y"] is None
    assert any(m.level == "warning" for m in g.messages)

"""Loading, inputs and outputs, evaluation, messages and errors of locus.Graph."""

import math
import pickle

import numpy as np
import pytest

import locus
from conftest import TANGENT_SPHERES


def test_inputs_and_outputs_have_types_and_metadata(spheres):
    assert list(spheres.inputs) == ["A", "B", "t"]
    t = spheres.inputs["t"]
    assert (t.name, t.direction, t.type, t.access, t.node, t.node_type, t.port) == (
        "t", "input", "Number", "list", "t", "params.number", "Num",
    )
    assert t.default == 0.25
    assert spheres.inputs["B"].type == "Point"
    assert spheres.inputs["B"].default == locus.Point3(8, 6, 0)
    assert list(spheres.outputs) == ["D", "C1", "C2", "r1", "r2", "S1", "S2", "gap1", "gap2"]
    assert spheres.outputs["S1"].type == "Surface"
    assert spheres.outputs["r1"].node_type == "vector.distance"
    assert spheres.name == "tangent_spheres"
    assert "spheres" in spheres.description.lower()


def test_the_worked_example(spheres):
    spheres.evaluate()
    # By hand (the graph's own comment): |AB| = 10, t = 0.25.
    assert spheres["D"] == locus.Point3(2, 1.5, 0)
    assert spheres["r1"] == pytest.approx(1.25)
    assert spheres["r2"] == pytest.approx(3.75)
    assert spheres["gap1"] == pytest.approx(0, abs=1e-9)
    s1 = spheres["S1"]
    assert isinstance(s1, locus.NurbsSurface)
    assert (s1.degree_u, s1.degree_v, s1.count_u, s1.count_v) == (2, 2, 9, 5)
    assert spheres.messages == []


def test_set_and_re_evaluate_runs_only_downstream(spheres):
    spheres.evaluate()
    spheres.set("t", 0.5)
    spheres.set("B", (10, 0, 0))
    spheres.evaluate()
    assert spheres["D"] == locus.Point3(5, 0, 0)
    assert spheres["r1"] == pytest.approx(2.5)
    spheres.set("t", 0.75)
    spheres.evaluate()
    assert "a" not in spheres.last_run and "b" not in spheres.last_run
    assert "d" in spheres.last_run


def test_getitem_evaluates_when_an_input_changed(spheres):
    spheres.set("t", 0.5)
    assert spheres["r1"] == pytest.approx(2.5)  # no explicit evaluate()
    spheres.clear("t")
    assert spheres["r1"] == pytest.approx(1.25)


def test_lists_give_lists_and_numpy_arrays(spheres):
    spheres.set("t", np.array([0.25, 0.5, 0.75]))
    assert spheres["r1"] == pytest.approx([1.25, 2.5, 3.75])
    r1 = spheres.array("r1")
    assert r1.dtype == np.float64 and r1.shape == (3,)
    d = spheres.array("D")
    assert d.shape == (3, 3)
    np.testing.assert_allclose(d[1], [4, 3, 0])
    assert spheres.tree("r1") == {"{0}": pytest.approx([1.25, 2.5, 3.75])}
    with pytest.raises(TypeError, match="S1"):
        spheres.array("S1")


def test_a_failing_iteration_is_a_null_and_a_message(spheres):
    spheres.set("t", [0.0, 0.5])
    radii = spheres["r1"]
    assert radii[0] == 0.0
    spheres_out = spheres["S1"]
    assert spheres_out[0] is None and isinstance(spheres_out[1], locus.NurbsSurface)
    errors = [m for m in spheres.messages if m.level == "error"]
    assert errors, spheres.messages
    m = next(m for m in errors if m.node == "s1")
    assert (m.path, m.index) == ("{0}", 0)
    assert "radius" in m.text
    assert str(m).startswith('error: node "s1" at {0}[0]')
    assert math.isnan(spheres.array("gap1")[0])


def test_input_errors_name_the_input_path_and_item(spheres):
    with pytest.raises(locus.InputError, match=r'unknown input "nope" \(the graph\'s inputs are: A, B, t\)'):
        spheres.set("nope", 1)
    with pytest.raises(locus.InputError, match=r'input "t": \{0\}\[1\]: .*"abc"'):
        spheres.set("t", [1.0, "abc"])
    with pytest.raises(locus.InputError, match=r'input "B": \{0\}\[0\]: cannot convert object'):
        spheres.set("B", [object()])
    with pytest.raises(locus.InputError, match="list inside a list"):
        spheres.set("t", [[1, 2]])
    with pytest.raises(locus.InputError, match="bad tree path"):
        spheres.set("t", {"{x}": [1]})
    with pytest.raises(locus.InputError, match="shape"):
        spheres.set("B", np.zeros((2, 2)))
    with pytest.raises(locus.InputError, match="not finite"):
        spheres.set("B", np.array([[0, 0, np.nan]]))
    with pytest.raises(locus.InputError):
        spheres.set_text("B", "(1, 2")
    assert isinstance(locus.InputError("x"), ValueError)
    # Nothing was changed by the failed calls.
    assert spheres["r1"] == pytest.approx(1.25)


def test_set_text_reads_graph_literals(spheres):
    spheres.set_text("B", "(10, 0, 0)")
    spheres.set_text("t", '{"{0;1}": [0.5], "{1}": [0.25]}')
    assert spheres.tree("r1") == {"{0;1}": [pytest.approx(2.5)], "{1}": [pytest.approx(1.25)]}
    assert spheres["r1"] == {"{0;1}": [pytest.approx(2.5)], "{1}": [pytest.approx(1.25)]}


def test_graph_errors_carry_every_diagnostic():
    text = """(
    format: 1,
    nodes: [
        (id: "a", type: "params.nope"),
        (id: "b", type: "maths.addition", values: {"Q": 1}),
    ],
)"""
    with pytest.raises(locus.GraphError) as info:
        locus.Graph.from_text(text)
    diagnostics = info.value.diagnostics
    assert len(diagnostics) >= 2
    first = diagnostics[0]
    assert (first.severity, first.line, first.node) == ("error", 4, "a")
    assert "params.nope" in first.message
    assert any(d.port == "Q" for d in diagnostics)
    assert str(info.value).startswith(f"the graph has {sum(d.severity == 'error' for d in diagnostics)} error(s)")


def test_malformed_text_and_files():
    with pytest.raises(locus.GraphError) as info:
        locus.Graph.from_text("(format: 1, nodes: [")
    assert info.value.diagnostics[0].line == 1
    with pytest.raises(OSError):
        locus.Graph.load("/nonexistent/graph.ron")
    with pytest.raises(locus.GraphError, match="Grasshopper files"):
        locus.Graph.load("definition.ghx")
    for junk in ["", "\x00\x01", "[" * 10_000, "(format: 99)"]:
        with pytest.raises(locus.GraphError):
            locus.Graph.from_text(junk)


def test_pickle_and_copy_keep_text_and_inputs(spheres):
    spheres.set("t", [0.5, 0.75])
    spheres.threads = 1
    clone = pickle.loads(pickle.dumps(spheres))
    assert clone.threads == 1
    assert clone["r1"] == spheres["r1"]
    other = spheres.copy()
    other.set("t", 0.25)
    assert other["r1"] == pytest.approx(1.25)
    assert spheres["r1"] == pytest.approx([2.5, 3.75])
    assert clone.text == spheres.text == TANGENT_SPHERES.read_text()


def test_threads_setting(spheres):
    for n in (0, 1, 2):
        spheres.threads = n
        spheres.set("t", [0.1 * k for k in range(1, 9)])
        assert spheres["r1"] == pytest.approx([0.5 * k for k in range(1, 9)])


def test_every_graph_of_the_repository_loads_and_runs():
    from conftest import GRAPHS

    files = sorted(GRAPHS.glob("*.ron"))
    assert len(files) > 10
    for f in files:
        g = locus.Graph.load(f)
        g.threads = 1
        g.evaluate()
        results = g.results()
        assert set(results) == set(g.outputs)


def test_node_types_lists_the_library():
    types = locus.node_types()
    assert "surface.sphere" in types and "params.number" in types and len(types) > 150

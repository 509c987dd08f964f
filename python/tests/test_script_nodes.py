"""Python script nodes (script.python) run from this package: each evaluation sends every
iteration to a worker process of this interpreter and reads the outcomes back."""

import time

import pytest

import locus

HEADER = '(format: 1, nodes: ['


def script_graph(code, inputs, values=None, outputs=("a",), access="", hints="", timeout=None,
                 ghpython=False):
    """A graph with one script node "s" fed by parameter nodes; named outputs as the node's."""
    values = values or {}
    nodes, wires = [], []
    for name in inputs:
        value = values.get(name)
        literal = "" if value is None else f', values: {{"Data": {value}}}'
        nodes.append(f'(id: "{name}_in", type: "params.data"{literal})')
        wires.append(f'("{name}_in.Data", "s.{name}")')
    settings = {"code": code, "access": access, "hints": hints, "ghpython": ghpython}
    if timeout is not None:
        settings["timeout"] = timeout
    rendered = ", ".join(
        f'"{k}": {"true" if v is True else "false" if v is False else repr_ron(v)}'
        for k, v in settings.items()
    )
    names = ", ".join(f'"{n}"' for n in inputs)
    outs = ", ".join(f'"{o}"' for o in outputs)
    nodes.append(
        f'(id: "s", type: "script.python", inputs: [{names}], outputs: [{outs}], '
        f"settings: {{{rendered}}})"
    )
    named = ", ".join(f'"{o}": "s.{o}"' for o in ("out",) + tuple(outputs))
    named_inputs = ", ".join(f'"{n}": "{n}_in.Data"' for n in inputs)
    text = HEADER + ", ".join(nodes) + "], wires: [" + ", ".join(wires) + "], "
    text += f"inputs: {{{named_inputs}}}, outputs: {{{named}}})"
    g = locus.Graph.from_text(text)
    g.threads = 1
    return g


def repr_ron(v):
    if isinstance(v, str):
        return '"' + v.replace("\\", "\\\\").replace('"', '\\"').replace("\n", "\\n") + '"'
    return repr(v)


def test_item_inputs_iterate_and_outputs_come_back_in_order():
    g = script_graph("a = x * y\nb = [x, y]", ["x", "y"], {"x": "[1, 2, 3]", "y": "10"},
                     outputs=("a", "b"))
    g.evaluate()
    assert g["a"] == [10, 20, 30]
    # A list per call is a branch per call, the iteration index appended to the path.
    assert g["b"] == {"{0;0}": [1, 10], "{0;1}": [2, 10], "{0;2}": [3, 10]}
    assert g.messages == []


def test_list_and_tree_access_and_dicts_as_trees():
    g = script_graph(
        "a = sum(xs)\nb = {'{1;2}': sorted(t)}",
        ["xs", "t"],
        {"xs": "[1.5, 2.5]", "t": '{"{0;4}": [1], "{3}": [2, 3]}'},
        outputs=("a", "b"),
        access="xs: list, t: tree",
    )
    g.evaluate()
    assert g["a"] == 4.0
    assert g["b"] == {"{1;2}": ["{0;4}", "{3}"]}


def test_values_arrive_as_the_package_classes_and_go_back():
    g = script_graph(
        "import locus\nassert isinstance(p, locus.Point3), type(p)\n"
        "a = locus.NurbsCurve.line(p, locus.Point3(p.x, p.y, p.z + n))",
        ["p", "n"],
        {"p": "(1, 2, 3)", "n": '"2"'},
        hints="p: Point, n: int",
    )
    g.evaluate()
    assert g.messages == []
    line = g["a"]
    assert isinstance(line, locus.NurbsCurve) and line.kind == "line"
    assert line.end == locus.Point3(1, 2, 5)


def test_print_is_a_remark_and_the_out_output():
    g = script_graph("print('x is', x)\na = x", ["x"], {"x": "[1, 2]"})
    g.evaluate()
    assert g["out"] == ["x is 1", "x is 2"]
    assert [(m.level, m.index, m.text) for m in g.messages] == [
        ("remark", 0, "x is 1"),
        ("remark", 1, "x is 2"),
    ]


def test_an_exception_is_an_error_on_its_item_with_the_line():
    g = script_graph("import math\n\na = math.sqrt(x)", ["x"], {"x": "[4, -1, 9]"})
    g.evaluate()
    assert g["a"] == [2.0, None, 3.0]
    (m,) = g.messages
    assert (m.level, m.path, m.index) == ("error", "{0}", 1)
    assert m.text == "line 3: ValueError: math domain error"


def test_a_runaway_script_is_stopped_at_its_time_limit():
    g = script_graph("while x > 1:\n    pass\na = x", ["x"], {"x": "[1, 2, 3]"}, timeout=0.3)
    t0 = time.perf_counter()
    g.evaluate()
    assert time.perf_counter() - t0 < 10
    assert g["a"] == [1, None, None]
    # The worker interrupts each looping call at the limit and goes on with the next item.
    assert [(m.level, m.index) for m in g.messages] == [("error", 1), ("error", 2)]
    for m in g.messages:
        assert m.text.startswith("line ") and m.text.endswith(
            ": the script ran longer than its time limit of 0.3 s"
        ), m.text


def test_a_script_that_kills_its_python_does_not_take_the_host_down():
    g = script_graph("import os\nif x == 2:\n    os._exit(7)\na = x", ["x"], {"x": "[1, 2, 3]"})
    g.evaluate()
    assert g["a"] == [1, None, None]
    errors = [m.text for m in g.messages if m.level == "error"]
    assert "ended with exit code 7 while the script ran" in errors[0]
    assert errors[1].startswith("not run")
    # This process is fine, and the next evaluation starts a new worker.
    g.set("x", [5])
    g.evaluate()
    assert g["a"] == 5


def test_scripts_share_nothing_between_calls_but_sticky():
    g = script_graph(
        "import scriptcontext as sc\n"
        "sc.sticky['n'] = sc.sticky.get('n', 0) + 1\n"
        "a = ('seen' in globals(), sc.sticky['n'] > 0)\nseen = True",
        ["x"], {"x": "[1, 2]"}, ghpython=True,
    )
    g.evaluate()
    assert g.messages == []
    assert g["a"] == {"{0;0}": [False, True], "{0;1}": [False, True]}


def test_a_batch_of_items_costs_one_round_trip():
    """A thousand iterations in one request: measured, and far below a round trip each."""
    g = script_graph("a = x + 1", ["x"], {"x": "[" + ", ".join(str(i) for i in range(1000)) + "]"})
    g.evaluate()  # starts the worker
    t0 = time.perf_counter()
    g.set("x", list(range(1, 1001)))
    g.evaluate()
    elapsed = time.perf_counter() - t0
    assert g["a"][-1] == 1001
    print(f"1000 script calls in one evaluation: {elapsed * 1e3:.1f} ms")
    assert elapsed < 30

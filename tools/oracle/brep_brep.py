#!/usr/bin/env python3
"""Reference values for Brep | Brep from OpenCASCADE (`BRepAlgoAPI_Section`).

Writes `tests/data/generated/occt-brep-brep.json`, which `crates/kernel/tests/oracle_brep_brep.rs`
replays. The shapes use the recipes of the shared oracle (`tests/data/oracle/ops-cases.json`,
read by `crates/kernel/tests/support/breps.rs`): boxes, spheres, capped cylinders, capped cones
and tori, in generic positions drawn from a fixed seed. For each pair the file records the
total length of the section edges, the number of wires they connect into and whether each is
closed, the section's tight bounding box, and the largest edge tolerance OpenCASCADE reports
(how far its approximated edges may be from the true intersection).

Run with OpenCASCADE's Python bindings from PyPI:

    python3 -m venv /tmp/ocp && /tmp/ocp/bin/pip install cadquery-ocp-novtk
    /tmp/ocp/bin/python tools/oracle/brep_brep.py
"""

import json
import math
import random
from pathlib import Path

from OCP.BRep import BRep_Tool
from OCP.BRepAlgoAPI import BRepAlgoAPI_Section
from OCP.BRepBndLib import BRepBndLib
from OCP.BRepGProp import BRepGProp
from OCP.BRepPrimAPI import (
    BRepPrimAPI_MakeBox,
    BRepPrimAPI_MakeCone,
    BRepPrimAPI_MakeCylinder,
    BRepPrimAPI_MakeSphere,
    BRepPrimAPI_MakeTorus,
)
from OCP.Bnd import Bnd_Box
from OCP.GProp import GProp_GProps
from OCP.TopAbs import TopAbs_EDGE
from OCP.TopExp import TopExp, TopExp_Explorer
from OCP.TopoDS import TopoDS
from OCP.gp import gp_Ax2, gp_Dir, gp_Pnt

ROOT = Path(__file__).resolve().parents[2]
OUT = ROOT / "tests" / "data" / "generated" / "occt-brep-brep.json"
rng = random.Random(20261207)


def unit(v):
    n = math.sqrt(sum(x * x for x in v))
    return [x / n for x in v]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def frame(origin, normal=None):
    """A right-handed plane through `origin`: random (or given) normal, random x axis."""
    n = unit(normal or [rng.uniform(-1, 1) for _ in range(3)])
    t = unit([rng.uniform(-1, 1) for _ in range(3)])
    x = unit(cross(cross(n, t), n))
    y = cross(n, x)
    return {"origin": origin, "x_axis": x, "y_axis": y, "normal": n}


def ax2(p, origin=None):
    o = origin or p["origin"]
    return gp_Ax2(gp_Pnt(*o), gp_Dir(*p["normal"]), gp_Dir(*p["x_axis"]))


def occ_shape(b):
    kind = b["kind"]
    if kind == "box":
        p = b["plane"]
        (x0, x1), (y0, y1), (z0, z1) = b["x"], b["y"], b["z"]
        corner = [
            p["origin"][k] + x0 * p["x_axis"][k] + y0 * p["y_axis"][k] + z0 * p["normal"][k]
            for k in range(3)
        ]
        return BRepPrimAPI_MakeBox(ax2(p, corner), x1 - x0, y1 - y0, z1 - z0).Shape()
    if kind == "sphere":
        return BRepPrimAPI_MakeSphere(gp_Pnt(*b["center"]), b["radius"]).Shape()
    if kind == "cylinder":
        assert b["capped"]
        return BRepPrimAPI_MakeCylinder(ax2(b["base_plane"]), b["radius"], b["height"]).Shape()
    if kind == "cone":
        assert b["capped"]
        return BRepPrimAPI_MakeCone(ax2(b["apex_plane"]), 0.0, b["radius"], b["height"]).Shape()
    if kind == "torus":
        return BRepPrimAPI_MakeTorus(ax2(b["plane"]), b["major_radius"], b["minor_radius"]).Shape()
    raise ValueError(kind)


def rand_point(scale=1.0):
    return [rng.uniform(-scale, scale) for _ in range(3)]


def wires(ends, gap=1e-6):
    """Connects edges (pairs of end points) into chains; whether each chain is closed."""
    nodes = []

    def node(p):
        for i, q in enumerate(nodes):
            if math.dist(p, q) <= gap:
                return i
        nodes.append(p)
        return len(nodes) - 1

    links = [(node(a), node(b)) for a, b in ends]
    parent = list(range(len(nodes)))

    def root(i):
        while parent[i] != i:
            parent[i] = parent[parent[i]]
            i = parent[i]
        return i

    degree = [0] * len(nodes)
    for a, b in links:
        degree[a] += 1
        degree[b] += 1
        parent[root(a)] = root(b)
    chains = {}
    for a, _ in links:
        chains.setdefault(root(a), set())
    for i in range(len(nodes)):
        if root(i) in chains:
            chains[root(i)].add(i)
    return [all(degree[i] == 2 for i in members) for members in chains.values()]


def section(a, b):
    op = BRepAlgoAPI_Section(occ_shape(a), occ_shape(b), False)
    op.Approximation(True)
    op.ComputePCurveOn1(True)
    op.ComputePCurveOn2(True)
    op.Build()
    assert op.IsDone()
    shape = op.Shape()
    props = GProp_GProps()
    BRepGProp.LinearProperties_s(shape, props)
    ends = []
    worst = 0.0
    explorer = TopExp_Explorer(shape, TopAbs_EDGE)
    while explorer.More():
        edge = TopoDS.Edge(explorer.Current())
        worst = max(worst, BRep_Tool.Tolerance_s(edge))
        pair = []
        for vertex in (TopExp.FirstVertex_s(edge), TopExp.LastVertex_s(edge)):
            p = BRep_Tool.Pnt_s(vertex)
            pair.append((p.X(), p.Y(), p.Z()))
        ends.append(pair)
        explorer.Next()
    count = len(ends)
    closed = wires(ends)
    box = Bnd_Box()
    bbox = None
    if count:
        BRepBndLib.AddOptimal_s(shape, box, False, False)
        lo, hi = box.CornerMin(), box.CornerMax()
        bbox = {"min": [lo.X(), lo.Y(), lo.Z()], "max": [hi.X(), hi.Y(), hi.Z()]}
    return {
        "length": props.Mass(),
        "edges": count,
        "wires_closed": sorted(closed),
        "bbox": bbox,
        "edge_tolerance": worst,
    }


def sphere(c, r):
    return {"kind": "sphere", "center": c, "radius": r}


def cylinder(origin, r, h, normal=None):
    return {"kind": "cylinder", "base_plane": frame(origin, normal), "radius": r, "height": h,
            "capped": True}


def cone(apex, h, r, normal=None):
    return {"kind": "cone", "apex_plane": frame(apex, normal), "height": h, "radius": r,
            "capped": True}


def box(origin, x, y, z, normal=None):
    return {"kind": "box", "plane": frame(origin, normal), "x": x, "y": y, "z": z}


def torus(origin, major, minor, normal=None):
    return {"kind": "torus", "plane": frame(origin, normal), "major_radius": major,
            "minor_radius": minor}


def main():
    cases = []

    def case(name, notes, a, b):
        cases.append({"id": name, "notes": notes, "inputs": {"a": a, "b": b},
                      "expected": section(a, b)})

    case("bb-01-spheres", "two crossing spheres: one circle",
         sphere(rand_point(0.3), 1.7), sphere([1.1, 0.6, -0.4], 1.2))
    case("bb-02-sphere-cylinder", "a sphere through the side of a capped cylinder: one closed curve",
         sphere([0.9, 0.2, 1.6], 1.1), cylinder([0.1, -0.2, -0.3], 1.3, 3.7, [0.1, 0.05, 1.0]))
    case("bb-03-cylinders-oblique",
         "two capped cylinders of different radii with skew axes: closed curves on the sides",
         cylinder([-2.0, 0.1, 0.2], 0.8, 4.0, [1.0, 0.15, 0.1]),
         cylinder([0.3, 0.2, -2.0], 1.5, 4.2, [0.05, -0.1, 1.0]))
    case("bb-04-boxes", "two rotated boxes overlapping at a corner: a polygon",
         box([0.0, 0.0, 0.0], [-1.0, 1.0], [-1.2, 1.3], [-0.9, 1.1]),
         box([0.8, 0.7, 0.9], [-1.1, 1.0], [-1.0, 1.2], [-1.3, 0.8]))
    corner_box = box([0.0, 0.0, 0.0], [0.0, 2.0], [0.0, 2.5], [0.0, 1.8], [0.1, 0.2, 1.0])
    f = corner_box["plane"]
    near_corner = [f["origin"][k] + 1.9 * f["x_axis"][k] + 2.3 * f["y_axis"][k]
                   + 1.6 * f["normal"][k] for k in range(3)]
    case("bb-05-box-sphere", "a sphere about a point near a rotated box's corner: arcs on three "
         "faces", corner_box, sphere(near_corner, 0.8))
    case("bb-06-cone-cylinder", "a capped cone through a capped cylinder",
         cone([0.0, 0.0, 2.5], 3.5, 1.6, [0.05, 0.1, -1.0]),
         cylinder([-2.5, 0.3, 0.8], 0.7, 5.0, [1.0, -0.1, 0.2]))
    case("bb-07-torus-sphere", "a sphere through a torus's tube",
         torus([0.0, 0.0, 0.0], 2.2, 0.7, [0.1, -0.05, 1.0]), sphere([2.0, 0.7, 0.5], 0.9))
    case("bb-08-torus-cylinder", "a capped cylinder through a torus across its tube",
         torus([0.0, 0.0, 0.0], 2.0, 0.6, [0.0, 0.1, 1.0]),
         cylinder([1.9, 0.2, -2.0], 0.35, 4.0, [0.1, 0.05, 1.0]))
    case("bb-09-apart", "a sphere beside a box: nothing",
         box([0.0, 0.0, 0.0], [0.0, 1.0], [0.0, 1.0], [0.0, 1.0]), sphere([4.0, 4.0, 4.0], 1.0))

    OUT.parent.mkdir(parents=True, exist_ok=True)
    doc = {
        "source": "OpenCASCADE BRepAlgoAPI_Section (cadquery-ocp-novtk), tools/oracle/brep_brep.py",
        "conventions": "shapes as in ops-cases.json (support/breps.rs); lengths are sums over "
                       "the section edges; wires from ShapeAnalysis_FreeBounds at 1e-6",
        "cases": cases,
    }
    OUT.write_text(json.dumps(doc, indent=1) + "\n")
    for c in cases:
        e = c["expected"]
        print(c["id"], e["length"], e["edges"], e["wires_closed"], e["edge_tolerance"])


if __name__ == "__main__":
    main()

"""Shared fixtures: the repository's graphs and small pass-through graphs."""

from pathlib import Path

import pytest

import locus

ROOT = Path(__file__).resolve().parents[2]
GRAPHS = ROOT / "graphs"
TANGENT_SPHERES = GRAPHS / "tangent_spheres.ron"

#: (node type, port nickname) of the parameter nodes, by value type.
PARAMS = {
    "Number": ("params.number", "Num"),
    "Integer": ("params.integer", "Int"),
    "Boolean": ("params.boolean", "Bool"),
    "Text": ("params.text", "Txt"),
    "Domain": ("params.domain", "Domain"),
    "Point": ("params.point", "Pt"),
    "Vector": ("params.vector", "Vec"),
    "Plane": ("params.plane", "Pln"),
    "Curve": ("params.curve", "Crv"),
    "Surface": ("params.surface", "Srf"),
    "Brep": ("params.brep", "Brep"),
    "Mesh": ("params.mesh", "Mesh"),
    "Transform": ("params.transform", "Transform"),
    "Geometry": ("params.geometry", "Geo"),
}


def passthrough_text(type_name: str) -> str:
    """A graph with one parameter node of the type: input "x", output "y"."""
    node, port = PARAMS[type_name]
    return (
        f'(format: 1, nodes: [(id: "p", type: "{node}")], '
        f'inputs: {{"x": "p.{port}"}}, outputs: {{"y": "p.{port}"}})'
    )


_CACHE = {}


def passthrough(type_name: str) -> locus.Graph:
    if type_name not in _CACHE:
        g = locus.Graph.from_text(passthrough_text(type_name))
        g.threads = 1
        _CACHE[type_name] = g
    return _CACHE[type_name]


@pytest.fixture
def spheres() -> locus.Graph:
    return locus.Graph.load(TANGENT_SPHERES)

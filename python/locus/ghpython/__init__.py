"""The GhPython compatibility layer: the most common GhPython idioms on locus's kernel.

Script nodes with the ``ghpython`` setting (and every GhPython component read from a
Grasshopper file) run with this layer installed: ``import Rhino``, ``import Rhino.Geometry as
rg``, ``import rhinoscriptsyntax as rs``, ``import scriptcontext``, ``import Grasshopper`` and
``from ghpythonlib import treehelpers`` find the modules of ``locus/ghpython/modules``, and
values arrive as their classes: a point as ``rg.Point3d``, a curve as ``rg.NurbsCurve`` (or
``LineCurve``, ``ArcCurve``, ``PolylineCurve``), a B-rep as ``rg.Brep``, a list input as a list
with .NET's ``Count``, a tree input as a ``Grasshopper.DataTree``. What a script assigns to its
outputs goes back to locus values the same way.

It covers what the tutorial scripts of *Essential Mathematics for Computational Design* use and
the everyday RhinoCommon around it (``docs/python.md`` lists it); anything else raises
``AttributeError`` naming what is missing, which becomes the error of the script's item.

``install()`` puts the modules on ``sys.path``; tests and other programs may call it too.
"""

import os
import sys

import locus

from . import _curves, _surfaces, _vectors

MODULES = os.path.join(os.path.dirname(os.path.abspath(__file__)), "modules")


def install():
    """Makes ``import Rhino``, ``import rhinoscriptsyntax`` and the other GhPython modules
    find this layer (idempotent)."""
    if MODULES not in sys.path:
        sys.path.insert(0, MODULES)


class NetList(list):
    """A list input as GhPython gives it: a Python list that also has .NET's ``Count`` and
    ``Add``."""

    Count = property(len)

    def Add(self, item):
        self.append(item)

    def AddRange(self, items):
        self.extend(items)

    def Insert(self, index, item):
        self.insert(index, item)

    def RemoveAt(self, index):
        del self[index]

    def Clear(self):
        del self[:]

    def Contains(self, item):
        return item in self

    def IndexOf(self, item):
        return self.index(item) if item in self else -1

    def ToArray(self):
        return list(self)


def _item_to_rhino(value, hint):
    if isinstance(value, locus.Point3):
        if hint == "GeometryBase":
            return _curves.Point(value)
        return _vectors.Point3d(value)
    if isinstance(value, locus.Vector3):
        return _vectors.Vector3d(value)
    if isinstance(value, locus.Plane):
        return _vectors.Plane(value)
    if isinstance(value, locus.Domain):
        return _vectors.Interval(value.t0, value.t1)
    if isinstance(value, locus.Transform):
        return _vectors.Transform(value)
    if isinstance(value, locus.Box):
        return _surfaces.Box(value)
    if isinstance(value, locus.NurbsCurve):
        kind = value.kind
        if hint == "Line" and kind == "line":
            return _curves.Line(_vectors.Point3d(value.start), _vectors.Point3d(value.end))
        if hint == "Polyline" and kind == "polyline":
            return _curves.Polyline(_vectors.Point3d(p) for p in value.control_points)
        return _curves._curve(value)
    if isinstance(value, locus.NurbsSurface):
        return _surfaces.NurbsSurface._wrap(value)
    if isinstance(value, locus.Brep):
        return _surfaces.Brep._wrap(value)
    if isinstance(value, locus.Mesh):
        return _surfaces.Mesh._wrap(value)
    return value


def to_rhino(value, hint=""):
    """A locus value (an item, a list, or a dict of paths) as the Rhino object GhPython would
    give a script for an input with this type hint."""
    if isinstance(value, dict):
        install()
        from Grasshopper import DataTree

        return DataTree._from_dict({k: [_item_to_rhino(v, hint) for v in items] for k, items in value.items()})
    if isinstance(value, list):
        return NetList(_item_to_rhino(v, hint) for v in value)
    return _item_to_rhino(value, hint)


def to_locus(value):
    """What a script assigned to an output, with Rhino objects made locus values again (lists
    and ``DataTree``s item by item)."""
    if value is None:
        return None
    convert = getattr(value, "_to_locus", None)
    if convert is not None and (not isinstance(value, list) or isinstance(value, _curves.Polyline)):
        return convert()
    tree = getattr(value, "_to_dict", None)
    if tree is not None:
        return {k: [to_locus(v) for v in items] for k, items in tree().items()}
    if isinstance(value, dict):
        return {k: [to_locus(v) for v in items] for k, items in value.items()}
    if isinstance(value, (list, tuple, set, frozenset)):
        return [to_locus(v) for v in value]
    return value

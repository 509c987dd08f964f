"""``Rhino`` for GhPython scripts run by locus: ``Rhino.Geometry`` and ``Rhino.RhinoMath``
(the compatibility layer of ``locus.ghpython``; there is no Rhino document)."""

from locus.ghpython._vectors import RhinoMath

from . import Geometry

__all__ = ["Geometry", "RhinoMath"]

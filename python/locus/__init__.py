"""locus for Python: load node graphs, set inputs, evaluate, read results; sweep design spaces.

>>> import locus
>>> g = locus.Graph.load("graphs/tangent_spheres.ron")
>>> g.set("t", 0.3)
>>> g.evaluate()
>>> g["r1"]
1.5

Values convert both ways: numbers, booleans and text; lists become one branch and dicts
``{"{0;1}": [...]}`` trees; numpy ``(N,)`` arrays numbers and ``(N, 3)`` arrays points; geometry
is :class:`Point3`, :class:`Vector3`, :class:`Plane`, :class:`NurbsCurve`,
:class:`NurbsSurface`, :class:`Brep`, :class:`Mesh` (and :class:`Domain`, :class:`Transform`,
:class:`Box`), all of which pickle.

:func:`sweep` evaluates many variants of a graph on a local process pool or a Dask cluster and
returns a pandas DataFrame.
"""

from ._locus import (
    Box,
    Brep,
    Diagnostic,
    Domain,
    Graph,
    GraphError,
    InputError,
    Mesh,
    Message,
    NurbsCurve,
    NurbsSurface,
    Plane,
    Point3,
    Port,
    Transform,
    Vector3,
    __version__,
    call,
    node_types,
)
from .sweep import sweep, variants

__all__ = [
    "Box",
    "Brep",
    "Diagnostic",
    "Domain",
    "Graph",
    "GraphError",
    "InputError",
    "Mesh",
    "Message",
    "NurbsCurve",
    "NurbsSurface",
    "Plane",
    "Point3",
    "Port",
    "Transform",
    "Vector3",
    "__version__",
    "call",
    "node_types",
    "sweep",
    "variants",
]

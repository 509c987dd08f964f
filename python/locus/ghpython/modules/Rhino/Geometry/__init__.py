"""``Rhino.Geometry`` for GhPython scripts run by locus (``locus.ghpython``): RhinoCommon's
names and semantics over locus's kernel."""

from locus.ghpython._curves import (
    Arc,
    ArcCurve,
    Circle,
    Curve,
    GeometryBase,
    Line,
    LineCurve,
    NurbsCurve,
    Point,
    Polyline,
    PolylineCurve,
)
from locus.ghpython._surfaces import (
    AreaMassProperties,
    Box,
    Brep,
    BrepEdge,
    BrepFace,
    BrepTrim,
    BrepVertex,
    Mesh,
    NurbsSurface,
    Sphere,
    Surface,
    VolumeMassProperties,
)
from locus.ghpython._vectors import (
    BoundingBox,
    Interval,
    Plane,
    Point2d,
    Point3d,
    Transform,
    Vector3d,
)

Point3f = Point3d
Vector3f = Vector3d

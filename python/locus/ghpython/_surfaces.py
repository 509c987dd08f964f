"""``Rhino.Geometry``'s surfaces and solids: ``Surface``, ``NurbsSurface``, ``Brep`` with its
faces, edges, trims and vertices, the ``Sphere`` and ``Box`` structs, ``AreaMassProperties``,
``VolumeMassProperties`` and ``Mesh``.

As for curves, each object holds a ``locus`` value and evaluates through the node library, so a
script's numbers are the graph nodes' numbers. A B-rep's topology is read from the locus
``Brep``'s parts (the same parts it pickles as).
"""

import locus

from ._curves import GeometryBase, _curve, _flat, _pt
from ._vectors import Interval, Plane, Point3d, Vector3d, _xyz


class Surface(GeometryBase):
    """``Rhino.Geometry.Surface``: an untrimmed NURBS surface."""

    def Domain(self, direction):
        return Interval(*(self._g.domain_u if direction == 0 else self._g.domain_v))

    def PointAt(self, u, v):
        return Point3d(locus.call("surface.evaluate_surface", self._g, (u, v, 0.0))[0])

    def NormalAt(self, u, v):
        return Vector3d(locus.call("surface.evaluate_surface", self._g, (u, v, 0.0))[1])

    def FrameAt(self, u, v):
        frame = locus.call("surface.evaluate_surface", self._g, (u, v, 0.0))[4]
        return True, Plane(frame)

    def ClosestPoint(self, point):
        """``(True, u, v)``: the parameters of the closest point (IronPython's ``out`` form)."""
        _, uv, _ = locus.call("surface.surface_closest_point", _pt(point), self._g)
        return True, uv.x, uv.y

    def IsoCurve(self, direction, constant):
        """The isocurve at ``constant`` running in ``direction`` (0: u varies, 1: v varies)."""
        u_curves, v_curves = locus.call(
            "surface.iso_curve", self._g, (constant, constant, 0.0) if direction else (constant, constant, 0.0)
        )
        return _curve(u_curves if direction == 0 else v_curves)

    def ToBrep(self):
        return Brep._wrap(locus.Brep.from_surface(self._g))

    def ToNurbsSurface(self):
        return NurbsSurface._wrap(self._g)


class NurbsSurface(Surface):
    """``Rhino.Geometry.NurbsSurface``."""

    @staticmethod
    def CreateFromCorners(a, b, c, d=None):
        corners = [a, b, c, d if d is not None else c]
        grid = [[_pt(corners[0]), _pt(corners[3])], [_pt(corners[1]), _pt(corners[2])]]
        return NurbsSurface._wrap(locus.NurbsSurface(grid, degree=(1, 1)))

    @staticmethod
    def CreateFromPoints(points, u_count, v_count, u_degree, v_degree):
        pts = [_pt(p) for p in points]
        grid = [pts[i * v_count:(i + 1) * v_count] for i in range(u_count)]
        return NurbsSurface._wrap(locus.NurbsSurface(grid, degree=(u_degree, v_degree)))

    @property
    def Points(self):
        return [[Point3d(p) for p in row] for row in self._g.control_points]


class Sphere:
    """``Rhino.Geometry.Sphere``: a centre and a radius (a struct). Assigned to an output, it
    becomes the surface Grasshopper's Sphere component makes (Rhino's sphere form)."""

    def __init__(self, center_or_plane, radius):
        if isinstance(center_or_plane, Plane):
            self.EquatorialPlane = Plane(center_or_plane)
        else:
            self.EquatorialPlane = Plane()
            self.EquatorialPlane.Origin = Point3d(center_or_plane)
        self.Radius = float(radius)

    Center = property(lambda self: self.EquatorialPlane.Origin)
    Diameter = property(lambda self: 2.0 * self.Radius)
    IsValid = property(lambda self: self.Radius > 0.0)

    def PointAt(self, longitude, latitude):
        return Point3d(self.ToNurbsSurface()._g.point_at(longitude, latitude))

    def ClosestPoint(self, point):
        return Point3d(locus.call("surface.surface_closest_point", _pt(point), self._to_locus())[0])

    def ToNurbsSurface(self):
        return NurbsSurface._wrap(self._to_locus())

    def ToBrep(self):
        return Brep._wrap(locus.call("params.brep", self._to_locus()))

    def _to_locus(self):
        return locus.call("surface.sphere", self.EquatorialPlane._to_locus(), self.Radius)


class Box:
    """``Rhino.Geometry.Box``: a plane and three intervals (a struct)."""

    def __init__(self, *args):
        if len(args) == 1 and isinstance(args[0], locus.Box):
            self._b = args[0]
        elif len(args) == 1:  # a BoundingBox
            bbox = args[0]
            self._b = locus.Box(
                locus.Plane.world_xy(),
                (bbox.Min.X, bbox.Max.X),
                (bbox.Min.Y, bbox.Max.Y),
                (bbox.Min.Z, bbox.Max.Z),
            )
        else:
            plane, x, y, z = args
            self._b = locus.Box(plane._to_locus(), tuple(x), tuple(y), tuple(z))

    Plane = property(lambda self: Plane(self._b.plane))
    X = property(lambda self: Interval(*self._b.x))
    Y = property(lambda self: Interval(*self._b.y))
    Z = property(lambda self: Interval(*self._b.z))
    Center = property(lambda self: Point3d(self._b.center))
    Volume = property(lambda self: self._b.volume)
    IsValid = property(lambda self: self._b.volume > 0.0)

    def GetCorners(self):
        return [Point3d(*c) for c in self._b.corners()]

    def ToBrep(self):
        return Brep._wrap(locus.Brep.from_box(self._b))

    def Transform(self, xform):
        self._b = locus.call("transform.transform", self._b, xform._to_locus())
        return True

    def _to_locus(self):
        return self._b


class _Topology:
    """A B-rep's parts, read once: (faces, loops, trims, edges, vertices)."""

    def __init__(self, brep):
        faces, loops, trims, edges, vertices = brep.__reduce__()[1]
        self.faces, self.loops, self.trims, self.edges, self.vertices = faces, loops, trims, edges, vertices


class BrepVertex:
    """``Rhino.Geometry.BrepVertex``."""

    def __init__(self, brep, index):
        self._brep, self.VertexIndex = brep, index

    @property
    def Location(self):
        return Point3d(*self._brep._topology().vertices[self.VertexIndex])


class BrepEdge(GeometryBase):
    """``Rhino.Geometry.BrepEdge``: an edge, a curve in 3-D."""

    def __init__(self, brep, index):
        self._brep, self.EdgeIndex = brep, index
        super().__init__(brep._topology().edges[index][0])

    Domain = property(lambda self: Interval(*self._g.domain))
    PointAtStart = property(lambda self: Point3d(self._g.start))
    PointAtEnd = property(lambda self: Point3d(self._g.end))

    def PointAt(self, t):
        return Point3d(self._g.point_at(t))

    def DuplicateCurve(self):
        return _curve(self._g)

    def AdjacentFaces(self):
        topology = self._brep._topology()
        return sorted(
            {topology.loops[t[3]][0] for t in topology.trims if t[1] == self.EdgeIndex}
        )


class BrepTrim:
    """``Rhino.Geometry.BrepTrim``: a curve in a face's parameter rectangle (points are
    ``(u, v, 0)``); ``Edge`` is ``None`` for a singular trim (a side that collapses to a
    point)."""

    def __init__(self, brep, index):
        self._brep, self.TrimIndex = brep, index
        self._part = brep._topology().trims[index]

    @property
    def Edge(self):
        edge = self._part[1]
        return None if edge is None else BrepEdge(self._brep, edge)

    @property
    def Face(self):
        loop = self._brep._topology().loops[self._part[3]]
        return BrepFace(self._brep, loop[0])

    PointAtStart = property(lambda self: Point3d(self._part[0].start))
    PointAtEnd = property(lambda self: Point3d(self._part[0].end))
    Domain = property(lambda self: Interval(*self._part[0].domain))
    IsReversed = property(lambda self: self._part[2])

    def PointAt(self, t):
        return Point3d(self._part[0].point_at(t))


class BrepFace(Surface):
    """``Rhino.Geometry.BrepFace``: a face, evaluated on its untrimmed surface."""

    def __init__(self, brep, index):
        self._brep, self.FaceIndex = brep, index
        surface, _, reversed_ = brep._topology().faces[index]
        super().__init__(surface)
        self.OrientationIsReversed = reversed_

    def NormalAt(self, u, v):
        n = Surface.NormalAt(self, u, v)
        return -n if self.OrientationIsReversed else n

    def DuplicateFace(self, duplicate_meshes=False):
        return self._brep.Faces.ExtractFace(self.FaceIndex)

    def DuplicateSurface(self):
        return NurbsSurface._wrap(self._g)

    def ToBrep(self):
        return self.DuplicateFace()

    def Transform(self, xform):
        raise TypeError("a BrepFace belongs to its Brep: transform the Brep, or DuplicateFace()")


class _List(list):
    """A read-only list of a B-rep's components with .NET's ``Count``."""

    Count = property(len)


class BrepFaceList(_List):
    """``Brep.Faces``."""

    def __init__(self, brep):
        super().__init__(BrepFace(brep, k) for k in range(len(brep._topology().faces)))
        self._brep = brep

    def ExtractFace(self, index):
        """The face as a B-rep of its own (Deconstruct Brep's faces)."""
        faces = _flat(locus.call("surface.deconstruct_brep", self._brep._g)[0])
        return Brep._wrap(faces[index])


class Brep(GeometryBase):
    """``Rhino.Geometry.Brep``: faces, edges, trims and vertices."""

    def _replace(self, value):
        self._g = value
        self.__dict__.pop("_parts", None)

    def _topology(self):
        if "_parts" not in self.__dict__:
            self.__dict__["_parts"] = _Topology(self._g)
        return self.__dict__["_parts"]

    Faces = property(lambda self: BrepFaceList(self))
    Edges = property(lambda self: _List(BrepEdge(self, k) for k in range(len(self._topology().edges))))
    Trims = property(lambda self: _List(BrepTrim(self, k) for k in range(len(self._topology().trims))))
    Vertices = property(
        lambda self: _List(BrepVertex(self, k) for k in range(len(self._topology().vertices)))
    )
    IsSolid = property(lambda self: self._g.is_solid)
    IsSurface = property(lambda self: self._g.face_count == 1)

    def GetArea(self, *args):
        return self._g.area()

    def GetVolume(self, *args):
        return self._g.volume()

    def DuplicateBrep(self):
        return self.Duplicate()

    @staticmethod
    def CreateFromBox(box):
        if isinstance(box, Box):
            return box.ToBrep()
        corners = [_pt(p) for p in box]
        return Brep._wrap(locus.call("params.brep", _flat(locus.call("surface.bounding_box", corners, True)[0])[0]))

    @staticmethod
    def CreateFromSphere(sphere):
        return sphere.ToBrep()

    @staticmethod
    def CreateFromSurface(surface):
        return surface.ToBrep()

    @staticmethod
    def JoinBreps(breps, tolerance=None):
        joined = _flat(locus.call("surface.brep_join", [b._g for b in breps])[0])
        return [Brep._wrap(b) for b in joined]


class AreaMassProperties:
    """``Rhino.Geometry.AreaMassProperties``: area and area centroid (Grasshopper's Area)."""

    def __init__(self, area, centroid):
        self.Area, self.Centroid = area, Point3d(centroid)

    @staticmethod
    def Compute(geometry, *args):
        area, centroid = locus.call("surface.area", _geometry(geometry))
        return AreaMassProperties(area, centroid)


class VolumeMassProperties:
    """``Rhino.Geometry.VolumeMassProperties``: volume and volume centroid (Volume)."""

    def __init__(self, volume, centroid):
        self.Volume, self.Centroid = volume, Point3d(centroid)

    @staticmethod
    def Compute(geometry, *args):
        volume, centroid = locus.call("surface.volume", _geometry(geometry))
        return VolumeMassProperties(volume, centroid)


class Mesh(GeometryBase):
    """``Rhino.Geometry.Mesh`` (what the node library does with meshes)."""

    @property
    def Vertices(self):
        return _List(Point3d(*v) for v in self._g.vertices)

    @property
    def Faces(self):
        return _List(tuple(f) for f in self._g.faces)

    @staticmethod
    def CreateFromBrep(brep, *args):
        meshes = _flat(locus.call("mesh.mesh_brep", brep._g))
        return [Mesh._wrap(m) for m in meshes]


def _geometry(obj):
    """The locus value of a Rhino object (or of a locus value)."""
    to_locus = getattr(obj, "_to_locus", None)
    return to_locus() if to_locus is not None else obj


_ = _xyz  # re-exported helpers stay importable from here

"""``Rhino.Geometry``'s geometry base class, points as geometry, and curves: ``Curve``,
``NurbsCurve``, ``LineCurve``, ``ArcCurve``, ``PolylineCurve`` and the ``Line``, ``Circle``,
``Arc`` and ``Polyline`` structs.

A geometry object holds a ``locus`` value (``_g``) and replaces it when transformed in place,
as RhinoCommon's objects change themselves. Evaluations go through the node library
(``locus.call``), so a script gets exactly the numbers the corresponding graph nodes give.
"""

import math

import locus

from ._vectors import BoundingBox, Interval, Plane, Point3d, Transform, Vector3d, _xyz


def _pt(p):
    return locus.Point3(*_xyz(p))


def _flat(value):
    """The items of a ``locus.call`` output, whatever its shape (an item, a list, or a dict of
    paths when a list output got its iteration's path)."""
    if value is None:
        return []
    if isinstance(value, dict):
        return [item for _, items in sorted(value.items(), key=lambda kv: _path_key(kv[0])) for item in items]
    if isinstance(value, list):
        return value
    return [value]


def _path_key(text):
    return tuple(int(i) for i in text.strip("{}").split(";") if i)


class GeometryBase:
    """``Rhino.Geometry.GeometryBase``: what every geometry object can do."""

    def __init__(self, value):
        self._g = value

    def _replace(self, value):
        self._g = value

    def Transform(self, xform):
        """Transforms the object in place (``True``)."""
        self._replace(locus.call("transform.transform", self._g, xform._to_locus()))
        return True

    def Translate(self, *args):
        v = args[0] if len(args) == 1 else Vector3d(*args)
        return self.Transform(Transform.Translation(v))

    def Rotate(self, angle, axis, center):
        return self.Transform(Transform.Rotation(angle, axis, center))

    def Scale(self, factor):
        return self.Transform(Transform.Scale(Point3d.Origin, factor))

    def GetBoundingBox(self, accurate_or_plane=True):
        """The world-aligned bounding box (``accurate`` is ignored: locus's boxes are tight);
        with a plane, the box of the object in that plane's coordinates."""
        if isinstance(accurate_or_plane, Plane):
            box = _flat(
                locus.call("surface.bounding_box", self._g, False, accurate_or_plane._to_locus())[1]
            )[0]
            return BoundingBox(
                Point3d(box.x[0], box.y[0], box.z[0]), Point3d(box.x[1], box.y[1], box.z[1])
            )
        box = _flat(locus.call("surface.bounding_box", self._g)[0])[0]
        corners = box.corners()
        return BoundingBox([Point3d(*c) for c in corners])

    def Duplicate(self):
        return type(self)._wrap(self._g)

    @classmethod
    def _wrap(cls, value):
        obj = cls.__new__(cls)
        GeometryBase.__init__(obj, value)
        return obj

    @property
    def IsValid(self):
        return self._g is not None

    def _to_locus(self):
        return self._g

    def __repr__(self):
        return f"{type(self).__name__}({self._g!r})"


class Point(GeometryBase):
    """``Rhino.Geometry.Point``: a point as a geometry object (what ``GeometryBase`` inputs
    give for points)."""

    def __init__(self, location):
        super().__init__(_pt(location))

    @property
    def Location(self):
        return Point3d(self._g)

    @Location.setter
    def Location(self, p):
        self._g = _pt(p)


class Curve(GeometryBase):
    """``Rhino.Geometry.Curve``: any curve (lines, arcs, polylines and NURBS curves)."""

    @property
    def Domain(self):
        return Interval(*self._g.domain)

    @Domain.setter
    def Domain(self, domain):
        self._g = locus.call(
            "curve.curve_domain", self._g, Interval(domain)._to_locus()
        )[0]

    @property
    def Degree(self):
        return self._g.degree

    @property
    def IsClosed(self):
        return self._g.is_closed

    @property
    def IsPeriodic(self):
        return self._g.is_periodic

    @property
    def PointAtStart(self):
        return Point3d(self._g.start)

    @property
    def PointAtEnd(self):
        return Point3d(self._g.end)

    def PointAt(self, t):
        return Point3d(locus.call("curve.evaluate_curve", self._g, t)[0])

    def TangentAt(self, t):
        tangent = locus.call("curve.evaluate_curve", self._g, t)[1]
        return Vector3d(tangent) if tangent is not None else Vector3d.Zero

    @property
    def TangentAtStart(self):
        return self.TangentAt(self.Domain.T0)

    @property
    def TangentAtEnd(self):
        return self.TangentAt(self.Domain.T1)

    def CurvatureAt(self, t):
        k = locus.call("curve.curvature", self._g, t)[1]
        return Vector3d(k) if k is not None else Vector3d.Zero

    def FrameAt(self, t):
        p, tangent = self.PointAt(t), self.TangentAt(t)
        k = self.CurvatureAt(t)
        if k.IsZero:
            return True, Plane(p, tangent)
        return True, Plane(p, tangent, k)

    def GetLength(self, *args):
        return locus.call("curve.length", self._g)

    def ClosestPoint(self, point, maximum_distance=None):
        """``(True, t)``: the parameter of the closest point (IronPython's ``out`` form)."""
        _, t, d = locus.call("curve.curve_closest_point", _pt(point), self._g)
        if maximum_distance is not None and maximum_distance > 0 and d > maximum_distance:
            return False, 0.0
        return True, t

    def DivideByCount(self, count, include_ends=True):
        """The parameters of ``count`` equal-length segments' ends."""
        params = _flat(locus.call("curve.divide_curve", self._g, count, False)[2])
        if not include_ends and not self.IsClosed:
            params = params[1:-1]
        return params

    def DivideByLength(self, length, include_ends=True):
        params = _flat(locus.call("curve.divide_length", self._g, length)[2])
        return params if include_ends else params[1:]

    def LengthParameter(self, length):
        t = locus.call("curve.evaluate_length", self._g, length, False)[2]
        return True, t

    def NormalizedLengthParameter(self, s):
        t = locus.call("curve.evaluate_length", self._g, s, True)[2]
        return True, t

    def Reverse(self):
        self._g = locus.call("curve.flip_curve", self._g)[0]
        return True

    def Split(self, t):
        pieces = _flat(locus.call("curve.split_curve", self._g, t))
        return [_curve(p) for p in pieces if p is not None]

    def ToNurbsCurve(self):
        return NurbsCurve._wrap(self._g)

    def DuplicateCurve(self):
        return self.Duplicate()

    @staticmethod
    def CreateControlPointCurve(points, degree=3):
        return NurbsCurve.Create(False, degree, points)

    @staticmethod
    def CreateInterpolatedCurve(points, degree=3, *args):
        pts = [_pt(p) for p in points]
        return _curve(locus.call("curve.interpolate", pts, degree)[0])

    @staticmethod
    def JoinCurves(curves, tolerance=None):
        joined = _flat(locus.call("curve.join_curves", [c._g for c in curves]))
        return [_curve(c) for c in joined]


class NurbsCurve(Curve):
    """``Rhino.Geometry.NurbsCurve``."""

    @staticmethod
    def Create(periodic, degree, points):
        """A curve through its control points (clamped, or periodic)."""
        pts = [_pt(p) for p in points]
        return NurbsCurve._wrap(locus.call("curve.nurbs_curve", pts, degree, bool(periodic))[0])

    @property
    def Points(self):
        return [Point3d(p) for p in self._g.control_points]

    @property
    def Knots(self):
        return list(self._g.knots)

    @property
    def Weights(self):
        return list(self._g.weights)

    @property
    def IsRational(self):
        return any(w != 1.0 for w in self._g.weights)


class LineCurve(Curve):
    """``Rhino.Geometry.LineCurve``."""

    def __init__(self, *args):
        line = args[0] if len(args) == 1 else Line(*args)
        super().__init__(locus.NurbsCurve.line(_pt(line.From), _pt(line.To)))

    @property
    def Line(self):
        return Line(self.PointAtStart, self.PointAtEnd)


class PolylineCurve(Curve):
    """``Rhino.Geometry.PolylineCurve``."""

    def __init__(self, points):
        super().__init__(locus.NurbsCurve.polyline([_pt(p) for p in points]))


class ArcCurve(Curve):
    """``Rhino.Geometry.ArcCurve``: an arc or a whole circle."""

    def __init__(self, arc_or_circle):
        super().__init__(arc_or_circle.ToNurbsCurve()._g)


def _curve(value):
    """A locus curve value as the matching Rhino curve class."""
    kind = getattr(value, "kind", "nurbs")
    cls = {"line": LineCurve, "polyline": PolylineCurve, "circle": ArcCurve, "arc": ArcCurve}.get(
        kind, NurbsCurve
    )
    return cls._wrap(value)


class Line:
    """``Rhino.Geometry.Line``: a segment from ``From`` to ``To`` (a struct)."""

    def __init__(self, *args):
        if len(args) == 2 and isinstance(args[1], Vector3d):
            self.From, self.To = Point3d(args[0]), Point3d(args[0]) + args[1]
        elif len(args) == 2:
            self.From, self.To = Point3d(args[0]), Point3d(args[1])
        elif len(args) == 3:
            start, direction, length = args
            d = Vector3d(direction)
            d.Unitize()
            self.From, self.To = Point3d(start), Point3d(start) + d * length
        elif len(args) == 6:
            self.From, self.To = Point3d(*args[:3]), Point3d(*args[3:])
        else:
            self.From, self.To = Point3d.Origin, Point3d.Origin

    @property
    def Length(self):
        return self.From.DistanceTo(self.To)

    @property
    def Direction(self):
        return self.To - self.From

    @property
    def UnitTangent(self):
        d = self.Direction
        d.Unitize()
        return d

    def PointAt(self, t):
        return self.From + (self.To - self.From) * t

    def ClosestParameter(self, point):
        d = self.Direction
        return ((Point3d(point) - self.From) * d) / (d * d)

    def ClosestPoint(self, point, limit_to_finite_segment):
        t = self.ClosestParameter(point)
        if limit_to_finite_segment:
            t = min(max(t, 0.0), 1.0)
        return self.PointAt(t)

    def DistanceTo(self, point, limit_to_finite_segment):
        return self.ClosestPoint(point, limit_to_finite_segment).DistanceTo(point)

    def Flip(self):
        self.From, self.To = self.To, self.From

    def Transform(self, xform):
        self.From, self.To = xform * self.From, xform * self.To
        return True

    def ToNurbsCurve(self):
        return LineCurve(self)

    def __repr__(self):
        return f"Line({self.From}, {self.To})"

    def _to_locus(self):
        return locus.NurbsCurve.line(_pt(self.From), _pt(self.To))


class Circle:
    """``Rhino.Geometry.Circle``: a plane and a radius (a struct)."""

    def __init__(self, *args):
        if len(args) == 1:
            self.Plane, self.Radius = Plane(), float(args[0])
        elif isinstance(args[0], Plane):
            self.Plane, self.Radius = Plane(args[0]), float(args[1])
        elif len(args) == 2:
            plane = Plane()
            plane.Origin = Point3d(args[0])
            self.Plane, self.Radius = plane, float(args[1])
        else:
            c = locus.call("curve.circle_3pt", *(_pt(p) for p in args))[0]
            self.Plane, self.Radius = Plane(c.plane if hasattr(c, "plane") else None), 0.0
            raise TypeError("Circle through three points is not supported yet")

    Center = property(lambda self: self.Plane.Origin)
    Normal = property(lambda self: self.Plane.ZAxis)
    Circumference = property(lambda self: 2.0 * math.pi * self.Radius)
    Diameter = property(lambda self: 2.0 * self.Radius)

    def PointAt(self, t):
        return self.Plane.PointAt(self.Radius * math.cos(t), self.Radius * math.sin(t))

    def ToNurbsCurve(self):
        return ArcCurve._wrap(locus.NurbsCurve.circle(self.Plane._to_locus(), self.Radius))

    def _to_locus(self):
        return locus.NurbsCurve.circle(self.Plane._to_locus(), self.Radius)

    def __repr__(self):
        return f"Circle({self.Center}, {self.Radius})"


class Arc:
    """``Rhino.Geometry.Arc``: a circle and an angle interval (a struct)."""

    def __init__(self, *args):
        if len(args) == 2 and isinstance(args[0], Circle):
            circle, angle = args
            self.Plane, self.Radius = circle.Plane, circle.Radius
            self.AngleDomain = Interval(0.0, angle) if isinstance(angle, (int, float)) else Interval(angle)
        elif len(args) == 3 and isinstance(args[0], Plane):
            self.Plane, self.Radius = args[0], float(args[1])
            self.AngleDomain = Interval(0.0, float(args[2]))
        elif len(args) == 3:
            value = locus.call("curve.arc_3pt", *(_pt(p) for p in args))[0]
            self._from_value(value)
        else:
            raise TypeError("Arc takes a circle and an angle, a plane, radius and angle, or three points")

    def _from_value(self, value):
        self._value = value
        self.Plane = None
        self.Radius = None
        self.AngleDomain = Interval(*value.domain)

    def ToNurbsCurve(self):
        return ArcCurve._wrap(self._to_locus())

    def _to_locus(self):
        if getattr(self, "_value", None) is not None:
            return self._value
        return locus.call(
            "curve.arc", self.Plane._to_locus(), self.Radius, self.AngleDomain._to_locus()
        )[0]


class Polyline(list):
    """``Rhino.Geometry.Polyline``: a list of points."""

    def __init__(self, points=()):
        super().__init__(Point3d(p) for p in points)

    Count = property(len)

    def Add(self, *args):
        self.append(Point3d(*args) if len(args) == 3 else Point3d(args[0]))

    @property
    def Length(self):
        return sum(a.DistanceTo(b) for a, b in zip(self, self[1:]))

    @property
    def IsClosed(self):
        return len(self) > 2 and self[0] == self[-1]

    def ToNurbsCurve(self):
        return PolylineCurve(self)

    def ToPolylineCurve(self):
        return PolylineCurve(self)

    def _to_locus(self):
        return locus.NurbsCurve.polyline([_pt(p) for p in self])

"""``Rhino.Geometry``'s value types: points, vectors, intervals, planes, transforms and
bounding boxes, with RhinoCommon's names and semantics, over locus's own classes.

They are mutable, as RhinoCommon's structs are (``v.Unitize()`` changes ``v``); assigning one
to a variable copies nothing, as in IronPython. Computations that need the kernel (rotations,
inverses, distances) go through the ``locus`` package's classes, so that they give exactly what
the graph nodes give.
"""

import math

import locus

UnsetValue = -1.23432101234321e308
ZERO_TOLERANCE = 2.3283064365386963e-10  # openNURBS's ON_ZERO_TOLERANCE (2^-32)


class RhinoMath:
    """``Rhino.RhinoMath``: constants and angle conversions."""

    UnsetValue = UnsetValue
    ZeroTolerance = ZERO_TOLERANCE
    SqrtEpsilon = 1.490116119385e-08
    DefaultAngleTolerance = math.pi / 180.0

    @staticmethod
    def ToRadians(degrees):
        return math.radians(degrees)

    @staticmethod
    def ToDegrees(radians):
        return math.degrees(radians)

    @staticmethod
    def IsValidDouble(x):
        return x != UnsetValue and math.isfinite(x)

    @staticmethod
    def Clamp(value, lo, hi):
        return min(max(value, lo), hi)


def _xyz(obj):
    """The coordinates of a point or vector of either library, or of a 3-sequence."""
    if isinstance(obj, (Point3d, Vector3d)):
        return obj.X, obj.Y, obj.Z
    if isinstance(obj, (locus.Point3, locus.Vector3)):
        return obj.x, obj.y, obj.z
    location = getattr(obj, "Location", None)
    if location is not None:
        return location.X, location.Y, location.Z
    x, y, z = obj
    return float(x), float(y), float(z)


class _Triple:
    __slots__ = ("X", "Y", "Z")

    def __init__(self, *args):
        if len(args) == 3:
            self.X, self.Y, self.Z = (float(a) for a in args)
        elif len(args) == 1:
            self.X, self.Y, self.Z = _xyz(args[0])
        elif not args:
            self.X = self.Y = self.Z = 0.0
        else:
            raise TypeError(f"{type(self).__name__} takes x, y, z or one point or vector")

    def __getitem__(self, i):
        return (self.X, self.Y, self.Z)[i]

    def __setitem__(self, i, value):
        setattr(self, "XYZ"[i], float(value))

    def __len__(self):
        return 3

    def __iter__(self):
        return iter((self.X, self.Y, self.Z))

    def __eq__(self, other):
        return type(other) is type(self) and (self.X, self.Y, self.Z) == (other.X, other.Y, other.Z)

    def __ne__(self, other):
        return not self == other

    def __hash__(self):
        return hash((type(self).__name__, self.X, self.Y, self.Z))

    def __str__(self):
        return f"{self.X:g},{self.Y:g},{self.Z:g}"

    def __repr__(self):
        return f"{type(self).__name__}({self.X!r}, {self.Y!r}, {self.Z!r})"

    def ToString(self):
        return str(self)

    @property
    def IsValid(self):
        return all(math.isfinite(c) and c != UnsetValue for c in self)

    def EpsilonEquals(self, other, epsilon):
        return all(abs(a - b) <= epsilon for a, b in zip(self, other))

    def Transform(self, xform):
        """Applies a transform in place (translations do not move vectors)."""
        moved = xform * self
        self.X, self.Y, self.Z = moved.X, moved.Y, moved.Z
        return True


class Point3d(_Triple):
    """``Rhino.Geometry.Point3d``: a location."""

    __slots__ = ()

    def __add__(self, other):
        if isinstance(other, (Point3d, Vector3d)):
            return Point3d(self.X + other.X, self.Y + other.Y, self.Z + other.Z)
        return NotImplemented

    __radd__ = __add__

    def __sub__(self, other):
        if isinstance(other, Point3d):
            return Vector3d(self.X - other.X, self.Y - other.Y, self.Z - other.Z)
        if isinstance(other, Vector3d):
            return Point3d(self.X - other.X, self.Y - other.Y, self.Z - other.Z)
        return NotImplemented

    def __mul__(self, factor):
        if isinstance(factor, (int, float)):
            return Point3d(self.X * factor, self.Y * factor, self.Z * factor)
        return NotImplemented

    __rmul__ = __mul__

    def __truediv__(self, divisor):
        return Point3d(self.X / divisor, self.Y / divisor, self.Z / divisor)

    def __neg__(self):
        return Point3d(-self.X, -self.Y, -self.Z)

    def DistanceTo(self, other):
        return locus.Point3(*self).distance_to(tuple(_xyz(other)))

    def DistanceToSquared(self, other):
        return self.DistanceTo(other) ** 2

    @staticmethod
    def Add(a, b):
        return a + b

    @staticmethod
    def Subtract(a, b):
        return a - b

    @staticmethod
    def Multiply(a, b):
        return a * b

    @staticmethod
    def Divide(a, b):
        return a / b

    @staticmethod
    def FromPoint3f(p):
        return Point3d(p)

    def _to_locus(self):
        return locus.Point3(self.X, self.Y, self.Z)


Point3d.Origin = property(lambda self: Point3d(0, 0, 0))


class _ClassProperty:
    def __init__(self, make):
        self.make = make

    def __get__(self, obj, owner):
        return self.make()


Point3d.Origin = _ClassProperty(lambda: Point3d(0.0, 0.0, 0.0))
Point3d.Unset = _ClassProperty(lambda: Point3d(UnsetValue, UnsetValue, UnsetValue))


class Point2d:
    """``Rhino.Geometry.Point2d``: a point in a plane, or a parameter pair (u, v)."""

    __slots__ = ("X", "Y")

    def __init__(self, *args):
        if len(args) == 2:
            self.X, self.Y = float(args[0]), float(args[1])
        elif len(args) == 1:
            p = args[0]
            self.X, self.Y = float(p[0]) if not hasattr(p, "X") else p.X, (
                float(p[1]) if not hasattr(p, "Y") else p.Y
            )
        else:
            self.X = self.Y = 0.0

    def __getitem__(self, i):
        return (self.X, self.Y)[i]

    def __iter__(self):
        return iter((self.X, self.Y))

    def __eq__(self, other):
        return isinstance(other, Point2d) and (self.X, self.Y) == (other.X, other.Y)

    def __repr__(self):
        return f"Point2d({self.X!r}, {self.Y!r})"

    def __str__(self):
        return f"{self.X:g},{self.Y:g}"

    def DistanceTo(self, other):
        return math.hypot(self.X - other.X, self.Y - other.Y)


class Vector3d(_Triple):
    """``Rhino.Geometry.Vector3d``: a direction and length. ``a * b`` of two vectors is their
    dot product, as in RhinoCommon."""

    __slots__ = ()

    def __add__(self, other):
        if isinstance(other, Vector3d):
            return Vector3d(self.X + other.X, self.Y + other.Y, self.Z + other.Z)
        if isinstance(other, Point3d):
            return Point3d(self.X + other.X, self.Y + other.Y, self.Z + other.Z)
        return NotImplemented

    def __sub__(self, other):
        if isinstance(other, Vector3d):
            return Vector3d(self.X - other.X, self.Y - other.Y, self.Z - other.Z)
        return NotImplemented

    def __mul__(self, other):
        if isinstance(other, Vector3d):
            return self.X * other.X + self.Y * other.Y + self.Z * other.Z
        if isinstance(other, (int, float)):
            return Vector3d(self.X * other, self.Y * other, self.Z * other)
        return NotImplemented

    def __rmul__(self, other):
        if isinstance(other, (int, float)):
            return Vector3d(self.X * other, self.Y * other, self.Z * other)
        return NotImplemented

    def __truediv__(self, divisor):
        return Vector3d(self.X / divisor, self.Y / divisor, self.Z / divisor)

    def __neg__(self):
        return Vector3d(-self.X, -self.Y, -self.Z)

    @property
    def Length(self):
        return locus.Vector3(*self).length

    @property
    def SquareLength(self):
        return self.X * self.X + self.Y * self.Y + self.Z * self.Z

    @property
    def IsZero(self):
        return self.X == 0.0 and self.Y == 0.0 and self.Z == 0.0

    @property
    def IsUnitVector(self):
        return abs(self.Length - 1.0) <= 1.490116119385e-08

    def IsTiny(self, tolerance=1e-12):
        return all(abs(c) <= tolerance for c in self)

    def Unitize(self):
        """Makes the vector unit length in place; ``False`` (and unchanged) when it is zero."""
        try:
            u = locus.Vector3(*self).unitized()
        except ValueError:
            return False
        self.X, self.Y, self.Z = u.x, u.y, u.z
        return True

    def Reverse(self):
        self.X, self.Y, self.Z = -self.X, -self.Y, -self.Z
        return True

    def Rotate(self, angle, axis):
        r = locus.Transform.rotation(angle, tuple(axis))
        moved = r.transform_vector(tuple(self))
        self.X, self.Y, self.Z = moved.x, moved.y, moved.z
        return True

    def IsParallelTo(self, other, angle_tolerance=math.pi / 180.0):
        a, b = Vector3d(self), Vector3d(other)
        if not (a.Unitize() and b.Unitize()):
            return 0
        d = a * b
        if d >= math.cos(angle_tolerance):
            return 1
        if d <= -math.cos(angle_tolerance):
            return -1
        return 0

    def IsPerpendicularTo(self, other, angle_tolerance=math.pi / 180.0):
        a, b = Vector3d(self), Vector3d(other)
        if not (a.Unitize() and b.Unitize()):
            return False
        return abs(a * b) <= math.sin(angle_tolerance)

    @staticmethod
    def CrossProduct(a, b):
        return Vector3d(
            a.Y * b.Z - a.Z * b.Y,
            a.Z * b.X - a.X * b.Z,
            a.X * b.Y - a.Y * b.X,
        )

    @staticmethod
    def Multiply(a, b):
        return a * b

    @staticmethod
    def Add(a, b):
        return a + b

    @staticmethod
    def Subtract(a, b):
        return a - b

    @staticmethod
    def Negate(v):
        return -v

    @staticmethod
    def VectorAngle(a, b, plane=None):
        """The angle between two vectors, 0 to π (or 0 to 2π measured in ``plane``)."""
        if plane is not None:
            return locus.call("vector.angle", a._to_locus(), b._to_locus(), plane._to_locus())[0]
        return locus.call("vector.angle", a._to_locus(), b._to_locus())[0]

    def _to_locus(self):
        return locus.Vector3(self.X, self.Y, self.Z)


Vector3d.Zero = _ClassProperty(lambda: Vector3d(0.0, 0.0, 0.0))
Vector3d.XAxis = _ClassProperty(lambda: Vector3d(1.0, 0.0, 0.0))
Vector3d.YAxis = _ClassProperty(lambda: Vector3d(0.0, 1.0, 0.0))
Vector3d.ZAxis = _ClassProperty(lambda: Vector3d(0.0, 0.0, 1.0))
Vector3d.Unset = _ClassProperty(lambda: Vector3d(UnsetValue, UnsetValue, UnsetValue))


class Interval:
    """``Rhino.Geometry.Interval``: a domain from ``T0`` to ``T1``."""

    __slots__ = ("T0", "T1")

    def __init__(self, t0=0.0, t1=0.0):
        if isinstance(t0, (Interval, locus.Domain)):
            t0, t1 = t0[0], t0[1]
        self.T0, self.T1 = float(t0), float(t1)

    def __getitem__(self, i):
        return (self.T0, self.T1)[i]

    def __iter__(self):
        return iter((self.T0, self.T1))

    def __eq__(self, other):
        return isinstance(other, Interval) and (self.T0, self.T1) == (other.T0, other.T1)

    def __repr__(self):
        return f"Interval({self.T0!r}, {self.T1!r})"

    def __str__(self):
        return f"{self.T0:g},{self.T1:g}"

    Min = property(lambda self: min(self.T0, self.T1))
    Max = property(lambda self: max(self.T0, self.T1))
    Mid = property(lambda self: self.ParameterAt(0.5))
    Length = property(lambda self: self.T1 - self.T0)
    IsIncreasing = property(lambda self: self.T0 < self.T1)
    IsValid = property(lambda self: math.isfinite(self.T0) and math.isfinite(self.T1))

    def ParameterAt(self, normalized):
        return locus.Domain(self.T0, self.T1).parameter_at(normalized)

    def NormalizedParameterAt(self, t):
        return (t - self.T0) / (self.T1 - self.T0)

    def IncludesParameter(self, t, strict=False):
        lo, hi = self.Min, self.Max
        return lo < t < hi if strict else lo <= t <= hi

    def Swap(self):
        self.T0, self.T1 = self.T1, self.T0

    def Reverse(self):
        self.T0, self.T1 = -self.T1, -self.T0

    def _to_locus(self):
        return locus.Domain(self.T0, self.T1)


class Plane:
    """``Rhino.Geometry.Plane``: an origin and three orthonormal axes."""

    __slots__ = ("_p",)

    def __init__(self, *args):
        if len(args) == 1:
            other = args[0]
            self._p = other._p if isinstance(other, Plane) else other
        elif len(args) == 2:
            self._p = locus.Plane.from_normal(tuple(_xyz(args[0])), tuple(_xyz(args[1])))
        elif len(args) == 3:
            origin, x, y = (tuple(_xyz(a)) for a in args)
            if isinstance(args[1], Point3d):  # three points: origin, x point, y point
                ox, oy = tuple(a - b for a, b in zip(x, origin)), tuple(a - b for a, b in zip(y, origin))
                self._p = locus.Plane(origin, ox, oy)
            else:
                self._p = locus.Plane(origin, x, y)
        elif not args:
            self._p = locus.Plane.world_xy()
        else:
            raise TypeError("Plane takes a plane, origin and normal, or origin and two axes")

    @staticmethod
    def WorldXY():
        return Plane()

    @staticmethod
    def _world(x, y):
        return Plane(locus.Plane((0, 0, 0), x, y))

    Origin = property(lambda self: Point3d(self._p.origin), lambda self, o: self._set_origin(o))
    XAxis = property(lambda self: Vector3d(self._p.x_axis))
    YAxis = property(lambda self: Vector3d(self._p.y_axis))
    ZAxis = property(lambda self: Vector3d(self._p.z_axis))
    Normal = ZAxis
    IsValid = property(lambda self: True)

    def _set_origin(self, origin):
        p = self._p
        self._p = locus.Plane._from_axes(tuple(_xyz(origin)), p.x_axis, p.y_axis, p.z_axis)

    def PointAt(self, u, v, w=0.0):
        return Point3d(self._p.point_at(u, v, w))

    def ClosestPoint(self, point):
        return Point3d(self._p.closest_point(tuple(_xyz(point))))

    def DistanceTo(self, point):
        return self._p.distance_to(tuple(_xyz(point)))

    def Flip(self):
        p = self._p
        self._p = locus.Plane._from_axes(p.origin, p.y_axis, p.x_axis, -p.z_axis)

    def Transform(self, xform):
        moved = locus.call("transform.transform", self._p, xform._to_locus())
        self._p = moved
        return True

    def __eq__(self, other):
        return isinstance(other, Plane) and self._p == other._p

    def __repr__(self):
        return f"Plane(Origin={self.Origin}, Z={self.ZAxis})"

    def _to_locus(self):
        return self._p


Plane.WorldXY = staticmethod(lambda: Plane())
Plane.WorldYZ = staticmethod(lambda: Plane._world((0, 1, 0), (0, 0, 1)))
Plane.WorldZX = staticmethod(lambda: Plane._world((0, 0, 1), (1, 0, 0)))


class Transform:
    """``Rhino.Geometry.Transform``: a 4×4 matrix (``M00`` … ``M33``). ``a * b`` applies
    ``b`` first; ``xform * point`` transforms a point."""

    def __init__(self, diagonal=None):
        if isinstance(diagonal, locus.Transform):
            self._t = diagonal
        elif isinstance(diagonal, Transform):
            self._t = diagonal._t
        elif diagonal is None:
            self._t = locus.Transform([[0.0] * 4 for _ in range(4)])
        else:
            d = float(diagonal)
            self._t = locus.Transform([[d if i == j else 0.0 for j in range(4)] for i in range(4)])

    def __getattr__(self, name):
        if len(name) == 3 and name[0] == "M" and name[1] in "0123" and name[2] in "0123":
            return self._t.rows[int(name[1])][int(name[2])]
        raise AttributeError(name)

    def __getitem__(self, ij):
        i, j = ij
        return self._t.rows[i][j]

    @staticmethod
    def Identity():
        return Transform(locus.Transform.identity())

    @staticmethod
    def Translation(*args):
        v = args[0] if len(args) == 1 else Vector3d(*args)
        return Transform(locus.Transform.translation(tuple(_xyz(v))))

    @staticmethod
    def Rotation(*args):
        """``Rotation(angle, center)`` about the z axis, ``Rotation(angle, axis, center)``,
        ``Rotation(sin, cos, axis, center)`` or ``Rotation(start_direction, end_direction,
        center)``."""
        if len(args) == 2:
            angle, center = args
            return Transform(locus.Transform.rotation(angle, (0, 0, 1), tuple(_xyz(center))))
        if len(args) == 3 and isinstance(args[0], (int, float)):
            angle, axis, center = args
            return Transform(locus.Transform.rotation(angle, tuple(_xyz(axis)), tuple(_xyz(center))))
        if len(args) == 3:
            start, end, center = args
            a, b = Vector3d(start), Vector3d(end)
            if not (a.Unitize() and b.Unitize()):
                raise ValueError("Transform.Rotation: a direction is zero")
            axis = Vector3d.CrossProduct(a, b)
            angle = math.atan2(axis.Length, a * b)
            if axis.Length == 0.0:
                axis = Vector3d(0, 0, 1)
            return Transform.Rotation(angle, axis, center)
        if len(args) == 4:
            sin, cos, axis, center = args
            return Transform.Rotation(math.atan2(sin, cos), axis, center)
        raise TypeError("Transform.Rotation: unsupported arguments")

    @staticmethod
    def Scale(*args):
        """``Scale(center, factor)`` or ``Scale(plane, x, y, z)``."""
        if len(args) == 2:
            center, factor = args
            return Transform(locus.Transform.scale(tuple(_xyz(center)), factor))
        plane, x, y, z = args
        return Transform(locus.Transform.scale_non_uniform(plane._to_locus(), x, y, z))

    @staticmethod
    def Mirror(*args):
        plane = args[0] if len(args) == 1 else Plane(args[0], args[1])
        return Transform(locus.Transform.mirror(plane._to_locus()))

    @staticmethod
    def PlaneToPlane(source, target):
        return Transform(locus.Transform.plane_to_plane(source._to_locus(), target._to_locus()))

    @staticmethod
    def Multiply(a, b):
        return a * b

    def TryGetInverse(self):
        """``(True, inverse)``, or ``(False, zero)`` when the matrix is singular (IronPython's
        form of the ``out`` parameter)."""
        try:
            return True, Transform(self._t.inverse())
        except ValueError:
            return False, Transform(0.0)

    @property
    def IsIdentity(self):
        return self._t == locus.Transform.identity()

    @property
    def IsValid(self):
        return all(math.isfinite(x) for row in self._t.rows for x in row)

    def __mul__(self, other):
        if isinstance(other, Transform):
            return Transform(self._t @ other._t)
        if isinstance(other, Point3d):
            return Point3d(self._t.transform_point(tuple(other)))
        if isinstance(other, Vector3d):
            return Vector3d(self._t.transform_vector(tuple(other)))
        return NotImplemented

    def __eq__(self, other):
        return isinstance(other, Transform) and self._t == other._t

    def __repr__(self):
        return f"Transform({self._t.rows!r})"

    def ToFloatArray(self, row_dominant=True):
        rows = self._t.rows
        if row_dominant:
            return [x for row in rows for x in row]
        return [rows[i][j] for j in range(4) for i in range(4)]

    def _to_locus(self):
        return self._t


class BoundingBox:
    """``Rhino.Geometry.BoundingBox``: a world-aligned box from ``Min`` to ``Max``."""

    def __init__(self, *args):
        if len(args) == 2:
            self.Min, self.Max = Point3d(args[0]), Point3d(args[1])
        elif len(args) == 6:
            self.Min, self.Max = Point3d(*args[:3]), Point3d(*args[3:])
        elif len(args) == 1:
            points = [Point3d(p) for p in args[0]]
            if not points:
                self.Min, self.Max = Point3d.Unset, Point3d.Unset
            else:
                self.Min = Point3d(*(min(p[i] for p in points) for i in range(3)))
                self.Max = Point3d(*(max(p[i] for p in points) for i in range(3)))
        else:
            self.Min, self.Max = Point3d.Unset, Point3d.Unset

    Empty = _ClassProperty(lambda: BoundingBox())

    @property
    def IsValid(self):
        return self.Min.IsValid and self.Max.IsValid and all(a <= b for a, b in zip(self.Min, self.Max))

    @property
    def Center(self):
        return Point3d(*((a + b) * 0.5 for a, b in zip(self.Min, self.Max)))

    @property
    def Diagonal(self):
        return self.Max - self.Min

    def Union(self, *args):
        """Grows this box in place to hold another box or a point (``BoundingBox.Union(a, b)``
        as a static call gives a new box)."""
        if len(args) == 2:
            box = BoundingBox(args[0].Min, args[0].Max)
            box.Union(args[1])
            return box
        other = args[0]
        if isinstance(other, BoundingBox):
            if not other.IsValid:
                return
            lo, hi = other.Min, other.Max
        else:
            lo = hi = Point3d(other)
        if not self.IsValid:
            self.Min, self.Max = Point3d(lo), Point3d(hi)
            return
        self.Min = Point3d(*(min(a, b) for a, b in zip(self.Min, lo)))
        self.Max = Point3d(*(max(a, b) for a, b in zip(self.Max, hi)))

    def Contains(self, point, strict=False):
        p = Point3d(point)
        if strict:
            return all(lo < c < hi for lo, c, hi in zip(self.Min, p, self.Max))
        return all(lo <= c <= hi for lo, c, hi in zip(self.Min, p, self.Max))

    def GetCorners(self):
        (x0, y0, z0), (x1, y1, z1) = tuple(self.Min), tuple(self.Max)
        return [
            Point3d(x0, y0, z0), Point3d(x1, y0, z0), Point3d(x1, y1, z0), Point3d(x0, y1, z0),
            Point3d(x0, y0, z1), Point3d(x1, y0, z1), Point3d(x1, y1, z1), Point3d(x0, y1, z1),
        ]

    def __repr__(self):
        return f"BoundingBox({self.Min}, {self.Max})"

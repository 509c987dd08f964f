"""``rhinoscriptsyntax`` for GhPython scripts run by locus: its point, vector, plane,
transform, curve and surface functions on the ``Rhino.Geometry`` compatibility layer.

There is no Rhino document: where rhinoscriptsyntax adds an object to the document and returns
its id (``AddPoint``, ``AddLine``, ``AddSphere``…), these return the geometry itself, which a
script can pass to the other functions or assign to an output, as GhPython's ``ghdoc`` lets it.
Functions take points as ``Point3d``s, ``Point`` objects or ``[x, y, z]`` lists, as
rhinoscriptsyntax's ``coerce3dpoint`` does.
"""

import math

import Rhino.Geometry as rg
from locus.ghpython._vectors import _xyz


def _point(p):
    if isinstance(p, rg.Point3d):
        return rg.Point3d(p)
    return rg.Point3d(*_xyz(p))


def _vector(v):
    if isinstance(v, rg.Vector3d):
        return rg.Vector3d(v)
    return rg.Vector3d(*_xyz(v))


def _curve(c):
    if isinstance(c, rg.Curve):
        return c
    if isinstance(c, (rg.Line, rg.Circle, rg.Arc, rg.Polyline)):
        return c.ToNurbsCurve()
    raise TypeError(f"{c!r} is not a curve")


def _surface(s):
    if isinstance(s, rg.Surface):
        return s
    if isinstance(s, rg.Brep) and len(s.Faces) == 1:
        return s.Faces[0]
    if isinstance(s, rg.Sphere):
        return s.ToNurbsSurface()
    raise TypeError(f"{s!r} is not a surface")


# Points


def AddPoint(point, y=None, z=None):
    return rg.Point(_point(point) if y is None else rg.Point3d(point, y, z))


def AddPoints(points):
    return [AddPoint(p) for p in points]


def CreatePoint(point, y=None, z=None):
    return _point(point) if y is None else rg.Point3d(point, y, z)


def PointCoordinates(point):
    return _point(point)


def PointAdd(point1, point2):
    return _point(point1) + _vector(point2)


def PointSubtract(point1, point2):
    return _point(point1) - _vector(point2)


def PointScale(point, scale):
    return _point(point) * scale


def PointDivide(point, divide):
    return _point(point) / divide


def PointCompare(point1, point2, tolerance=None):
    tolerance = 1e-9 if tolerance is None else tolerance
    return _point(point1).DistanceTo(_point(point2)) <= tolerance


def PointTransform(point, xform):
    return xform * _point(point)


def Distance(point1, point2):
    if isinstance(point2, (list, tuple)) and point2 and not isinstance(point2[0], (int, float)):
        return [_point(point1).DistanceTo(_point(p)) for p in point2]
    return _point(point1).DistanceTo(_point(point2))


def PointArrayBoundingBox(points):
    return rg.BoundingBox([_point(p) for p in points]).GetCorners()


def PointClosestObject(point, objects):
    best = None
    for obj in objects:
        c = _curve(obj)
        _, t = c.ClosestPoint(point)
        p = c.PointAt(t)
        d = p.DistanceTo(_point(point))
        if best is None or d < best[2]:
            best = (obj, p, d)
    return (best[0], best[1]) if best else None


# Vectors


def CreateVector(vector, y=None, z=None):
    return _vector(vector) if y is None else rg.Vector3d(vector, y, z)


def VectorCreate(to_point, from_point):
    return _point(to_point) - _point(from_point)


def VectorAdd(vector1, vector2):
    return _vector(vector1) + _vector(vector2)


def VectorSubtract(vector1, vector2):
    return _vector(vector1) - _vector(vector2)


def VectorScale(vector, scale):
    return _vector(vector) * scale


def VectorDivide(vector, divide):
    return _vector(vector) / divide


def VectorMultiply(vector1, vector2):
    return _vector(vector1) * _vector(vector2)


def VectorDotProduct(vector1, vector2):
    return _vector(vector1) * _vector(vector2)


def VectorCrossProduct(vector1, vector2):
    return rg.Vector3d.CrossProduct(_vector(vector1), _vector(vector2))


def VectorLength(vector):
    return _vector(vector).Length


def VectorUnitize(vector):
    v = _vector(vector)
    return v if v.Unitize() else None


def VectorReverse(vector):
    return -_vector(vector)


def VectorAngle(vector1, vector2):
    """The angle in degrees."""
    a, b = _vector(vector1), _vector(vector2)
    if not (a.Unitize() and b.Unitize()):
        return None
    return math.degrees(math.acos(max(-1.0, min(1.0, a * b))))


def VectorRotate(vector, angle_degrees, axis):
    v = _vector(vector)
    v.Rotate(math.radians(angle_degrees), _vector(axis))
    return v


def VectorTransform(vector, xform):
    return xform * _vector(vector)


def VectorCompare(vector1, vector2):
    a, b = tuple(_vector(vector1)), tuple(_vector(vector2))
    return (a > b) - (a < b)


def IsVectorZero(vector):
    return _vector(vector).IsZero


def IsVectorTiny(vector):
    return _vector(vector).IsTiny()


def IsVectorParallelTo(vector1, vector2):
    return _vector(vector1).IsParallelTo(_vector(vector2))


def IsVectorPerpendicularTo(vector1, vector2):
    return _vector(vector1).IsPerpendicularTo(_vector(vector2))


# Planes


def WorldXYPlane():
    return rg.Plane.WorldXY()


def WorldYZPlane():
    return rg.Plane.WorldYZ()


def WorldZXPlane():
    return rg.Plane.WorldZX()


def PlaneFromNormal(origin, normal, xaxis=None):
    if xaxis is None:
        return rg.Plane(_point(origin), _vector(normal))
    y = rg.Vector3d.CrossProduct(_vector(normal), _vector(xaxis))
    return rg.Plane(_point(origin), _vector(xaxis), y)


def PlaneFromFrame(origin, x_axis, y_axis):
    return rg.Plane(_point(origin), _vector(x_axis), _vector(y_axis))


def PlaneFromPoints(origin, x, y):
    return rg.Plane(_point(origin), _point(x), _point(y))


def CreatePlane(plane_or_origin, x_axis=None, y_axis=None):
    if isinstance(plane_or_origin, rg.Plane):
        return rg.Plane(plane_or_origin)
    return rg.Plane(_point(plane_or_origin), _vector(x_axis or (1, 0, 0)), _vector(y_axis or (0, 1, 0)))


def EvaluatePlane(plane, parameter):
    return plane.PointAt(parameter[0], parameter[1])


def PlaneClosestPoint(plane, point, return_point=True):
    if return_point:
        return plane.ClosestPoint(_point(point))
    p = plane.ClosestPoint(_point(point)) - plane.Origin
    return (p * plane.XAxis, p * plane.YAxis)


def DistanceToPlane(plane, point):
    return (_point(point) - plane.Origin) * plane.ZAxis


def MovePlane(plane, origin):
    moved = rg.Plane(plane)
    moved.Origin = _point(origin)
    return moved


# Transforms


def XformTranslation(vector):
    return rg.Transform.Translation(_vector(vector))


def XformRotation2(angle_degrees, rotation_axis, center_point):
    return rg.Transform.Rotation(math.radians(angle_degrees), _vector(rotation_axis), _point(center_point))


def XformScale(scale, point=None):
    center = _point(point) if point is not None else rg.Point3d.Origin
    if isinstance(scale, (int, float)):
        return rg.Transform.Scale(center, scale)
    plane = rg.Plane.WorldXY()
    plane.Origin = center
    return rg.Transform.Scale(plane, *scale)


def XformMirror(mirror_plane_point, mirror_plane_normal):
    return rg.Transform.Mirror(_point(mirror_plane_point), _vector(mirror_plane_normal))


def XformIdentity():
    return rg.Transform.Identity()


def XformMultiply(xform1, xform2):
    return xform1 * xform2


def XformInverse(xform):
    ok, inverse = xform.TryGetInverse()
    return inverse if ok else None


def XformChangeBasis(initial_plane, final_plane):
    return rg.Transform.PlaneToPlane(initial_plane, final_plane)


def _transformed(obj, xform):
    if isinstance(obj, (rg.Point3d, rg.Vector3d)):
        return xform * obj
    duplicate = obj.Duplicate()
    duplicate.Transform(xform)
    return duplicate


def TransformObject(object_id, matrix, copy=False):
    return _transformed(object_id, matrix)


def TransformObjects(object_ids, matrix, copy=False):
    return [_transformed(o, matrix) for o in object_ids]


def MoveObject(object_id, translation):
    return _transformed(object_id, XformTranslation(translation))


def MoveObjects(object_ids, translation):
    return [MoveObject(o, translation) for o in object_ids]


def RotateObject(object_id, center_point, rotation_angle, axis=None, copy=False):
    axis = axis if axis is not None else (0, 0, 1)
    return _transformed(object_id, XformRotation2(rotation_angle, axis, center_point))


def ScaleObject(object_id, origin, scale, copy=False):
    return _transformed(object_id, XformScale(scale, origin))


def CopyObject(object_id, translation=None):
    return MoveObject(object_id, translation) if translation is not None else object_id.Duplicate()


def BoundingBox(objects, view_or_plane=None, in_world_coords=True):
    if not isinstance(objects, (list, tuple)):
        objects = [objects]
    box = rg.BoundingBox()
    for obj in objects:
        if isinstance(obj, (rg.Point3d, list, tuple)):
            box.Union(_point(obj))
        else:
            box.Union(obj.GetBoundingBox(True))
    return box.GetCorners() if box.IsValid else None


# Curves


def AddLine(start, end):
    return rg.LineCurve(_point(start), _point(end))


def AddPolyline(points, replace_id=None):
    return rg.PolylineCurve([_point(p) for p in points])


def AddCircle(plane_or_center, radius):
    if isinstance(plane_or_center, rg.Plane):
        return rg.Circle(plane_or_center, radius).ToNurbsCurve()
    return rg.Circle(_point(plane_or_center), radius).ToNurbsCurve()


def AddArc(plane, radius, angle_degrees):
    return rg.Arc(plane, radius, math.radians(angle_degrees)).ToNurbsCurve()


def AddArc3Pt(start, end, point_on_arc):
    return rg.Arc(_point(start), _point(point_on_arc), _point(end)).ToNurbsCurve()


def AddCurve(points, degree=3):
    return rg.NurbsCurve.Create(False, degree, [_point(p) for p in points])


def AddInterpCurve(points, degree=3, *args):
    return rg.Curve.CreateInterpolatedCurve([_point(p) for p in points], degree)


def CurveDomain(curve_id, segment_index=-1):
    d = _curve(curve_id).Domain
    return [d.T0, d.T1]


def EvaluateCurve(curve_id, t, segment_index=-1):
    return _curve(curve_id).PointAt(t)


def CurveTangent(curve_id, parameter, segment_index=-1):
    return _curve(curve_id).TangentAt(parameter)


def CurveCurvature(curve_id, parameter):
    """``(point, tangent, center, radius vector… )`` as rhinoscriptsyntax: point, tangent,
    centre of curvature, radius and curvature vector."""
    c = _curve(curve_id)
    point, tangent, k = c.PointAt(parameter), c.TangentAt(parameter), c.CurvatureAt(parameter)
    length = k.Length
    if length == 0.0:
        return None
    radius = 1.0 / length
    center = point + k * (radius * radius)
    return point, tangent, center, radius, k


def CurveStartPoint(curve_id, segment_index=-1, point=None):
    return _curve(curve_id).PointAtStart


def CurveEndPoint(curve_id, segment_index=-1):
    return _curve(curve_id).PointAtEnd


def CurveMidPoint(curve_id, segment_index=-1):
    c = _curve(curve_id)
    _, t = c.NormalizedLengthParameter(0.5)
    return c.PointAt(t)


def CurveLength(curve_id, segment_index=-1, sub_domain=None):
    return _curve(curve_id).GetLength()


def CurveClosestPoint(curve_id, point, segment_index=-1):
    ok, t = _curve(curve_id).ClosestPoint(_point(point))
    return t if ok else None


def CurveDegree(curve_id, segment_index=-1):
    return _curve(curve_id).Degree


def CurvePoints(curve_id, segment_index=-1):
    return _curve(curve_id).ToNurbsCurve().Points


def CurveKnots(curve_id, segment_index=-1):
    return _curve(curve_id).ToNurbsCurve().Knots


def CurveWeights(curve_id, segment_index=-1):
    return _curve(curve_id).ToNurbsCurve().Weights


def IsCurveClosed(curve_id):
    return _curve(curve_id).IsClosed


def DivideCurve(curve_id, segments, create_points=False, return_points=True):
    c = _curve(curve_id)
    params = c.DivideByCount(segments, True)
    return [c.PointAt(t) for t in params] if return_points else params


def DivideCurveLength(curve_id, length, create_points=False, return_points=True):
    c = _curve(curve_id)
    params = c.DivideByLength(length, True)
    return [c.PointAt(t) for t in params] if return_points else params


def ReverseCurve(curve_id):
    c = _curve(curve_id).Duplicate()
    c.Reverse()
    return c


# Surfaces


def AddSphere(center_or_plane, radius):
    return rg.Sphere(center_or_plane, radius).ToBrep()


def AddSrfPt(points):
    return rg.NurbsSurface.CreateFromCorners(*[_point(p) for p in points]).ToBrep()


def AddPlaneSurface(plane, u_dir, v_dir):
    return rg.Brep._wrap(
        __import__("locus").call("surface.plane_surface", plane._to_locus(), (0, u_dir), (0, v_dir))
    )


def SurfaceDomain(surface_id, direction):
    d = _surface(surface_id).Domain(direction)
    return [d.T0, d.T1]


def SurfaceClosestPoint(surface_id, test_point):
    ok, u, v = _surface(surface_id).ClosestPoint(_point(test_point))
    return (u, v) if ok else None


def EvaluateSurface(surface_id, u, v):
    return _surface(surface_id).PointAt(u, v)


def SurfaceNormal(surface_id, uv_parameter):
    return _surface(surface_id).NormalAt(uv_parameter[0], uv_parameter[1])


def SurfaceFrame(surface_id, uv_parameter):
    return _surface(surface_id).FrameAt(uv_parameter[0], uv_parameter[1])[1]


def SurfaceArea(object_id):
    return [rg.AreaMassProperties.Compute(object_id).Area, 0.0]


def SurfaceAreaCentroid(object_id):
    props = rg.AreaMassProperties.Compute(object_id)
    return props.Centroid, rg.Vector3d(0, 0, 0)


def SurfaceVolume(object_id):
    return [rg.VolumeMassProperties.Compute(object_id).Volume, 0.0]


def SurfaceVolumeCentroid(object_id):
    props = rg.VolumeMassProperties.Compute(object_id)
    return props.Centroid, rg.Vector3d(0, 0, 0)


def ExplodePolysurfaces(object_ids, delete_input=False):
    if not isinstance(object_ids, (list, tuple)):
        object_ids = [object_ids]
    return [b.Faces.ExtractFace(i) for b in object_ids for i in range(len(b.Faces))]


def IsSurface(object_id):
    return isinstance(object_id, (rg.Surface, rg.Sphere)) or (
        isinstance(object_id, rg.Brep) and len(object_id.Faces) == 1
    )


def IsCurve(object_id):
    return isinstance(object_id, (rg.Curve, rg.Line, rg.Circle, rg.Arc, rg.Polyline))


def IsPoint(object_id):
    return isinstance(object_id, (rg.Point3d, rg.Point))


def IsBrep(object_id):
    return isinstance(object_id, rg.Brep)


def IsPolysurface(object_id):
    return isinstance(object_id, rg.Brep) and len(object_id.Faces) > 1


def coerce3dpoint(point, raise_on_error=False):
    try:
        return _point(point)
    except (TypeError, ValueError):
        if raise_on_error:
            raise
        return None


def coerce3dvector(vector, raise_on_error=False):
    try:
        return _vector(vector)
    except (TypeError, ValueError):
        if raise_on_error:
            raise
        return None


def coercecurve(curve_id, segment_index=-1, raise_if_missing=False):
    try:
        return _curve(curve_id)
    except TypeError:
        if raise_if_missing:
            raise
        return None


def coercesurface(object_id, raise_on_fail=False):
    try:
        return _surface(object_id)
    except TypeError:
        if raise_on_fail:
            raise
        return None


def coercegeometry(object_id, raise_if_missing=False):
    return object_id


def coercebrep(object_id, raise_if_missing=False):
    return object_id if isinstance(object_id, rg.Brep) else None

"""The GhPython compatibility layer on its own (in this process): RhinoCommon's semantics for
the value types, geometry evaluated through the node library, rhinoscriptsyntax, and trees."""

import math

import pytest

import locus
from locus import ghpython

ghpython.install()

import Rhino  # noqa: E402
import Rhino.Geometry as rg  # noqa: E402
import rhinoscriptsyntax as rs  # noqa: E402
from ghpythonlib import treehelpers  # noqa: E402
from Grasshopper import DataTree  # noqa: E402
from Grasshopper.Kernel.Data import GH_Path  # noqa: E402


def approx_xyz(p, xyz, tol=1e-12):
    return all(abs(a - b) <= tol for a, b in zip((p.X, p.Y, p.Z), xyz))


def test_points_and_vectors_follow_rhinocommon():
    a, b = rg.Point3d(1, 2, 3), rg.Point3d(4, 6, 3)
    v = b - a
    assert isinstance(v, rg.Vector3d) and (v.X, v.Y, v.Z) == (3, 4, 0)
    assert isinstance(a + v, rg.Point3d) and isinstance(a - v, rg.Point3d)
    assert v * v == 25.0  # the dot product
    assert isinstance(v * 2, rg.Vector3d) and isinstance(2 * v, rg.Vector3d)
    assert a.DistanceTo(b) == 5.0 and v.Length == 5.0
    # Structs change in place.
    assert v.Unitize() and approx_xyz(v, (0.6, 0.8, 0))
    v *= 2.5
    assert approx_xyz(v, (1.5, 2.0, 0))
    zero = rg.Vector3d.Zero
    assert not zero.Unitize() and zero.IsZero
    assert rg.Vector3d.CrossProduct(rg.Vector3d.XAxis, rg.Vector3d.YAxis) == rg.Vector3d.ZAxis
    assert not rg.Point3d.Unset.IsValid and rg.Point3d.Origin == rg.Point3d(0, 0, 0)
    assert str(rg.Point3d(1, 2.5, 0)) == "1,2.5,0"


def test_transforms_compose_right_to_left_and_invert():
    move = rg.Transform.Translation(rg.Vector3d(1, 0, 0))
    turn = rg.Transform.Rotation(math.pi / 2, rg.Point3d.Origin)
    p = (move * turn) * rg.Point3d(1, 0, 0)  # turn first, then move
    assert approx_xyz(p, (1, 1, 0))
    p = (turn * move) * rg.Point3d(1, 0, 0)
    assert approx_xyz(p, (0, 2, 0))
    ok, inverse = (move * turn).TryGetInverse()
    product = inverse * (move * turn)
    assert ok and all(abs(product[i, j] - (i == j)) < 1e-12 for i in range(4) for j in range(4))
    assert approx_xyz(inverse * rg.Point3d(1, 1, 0), (1, 0, 0))
    ok, _ = rg.Transform(0.0).TryGetInverse()
    assert not ok
    s = rg.Transform.Scale(rg.Point3d(1, 1, 1), 2)
    assert approx_xyz(s * rg.Point3d(2, 2, 2), (3, 3, 3))
    axis = rg.Transform.Rotation(math.pi, rg.Vector3d(1, 0, 0), rg.Point3d(0, 1, 0))
    assert approx_xyz(axis * rg.Point3d(0, 2, 0), (0, 0, 0), 1e-12)
    assert s.M00 == 2.0 and s.M03 == -1.0 and s.M33 == 1.0
    # Points as geometry transform in place.
    pt = rg.Point(rg.Point3d(1, 0, 0))
    pt.Transform(turn)
    assert approx_xyz(pt.Location, (0, 1, 0))


def test_bounding_boxes_grow_by_union():
    box = rg.BoundingBox(rg.Point3d(0, 0, 0), rg.Point3d(1, 1, 1))
    box.Union(rg.BoundingBox(rg.Point3d(-1, 2, 0), rg.Point3d(0, 3, 5)))
    assert box.Min == rg.Point3d(-1, 0, 0) and box.Max == rg.Point3d(1, 3, 5)
    assert box.Center == rg.Point3d(0, 1.5, 2.5)
    empty = rg.BoundingBox.Empty
    empty.Union(rg.Point3d(2, 2, 2))
    assert empty.IsValid and empty.Min == empty.Max == rg.Point3d(2, 2, 2)


def test_curves_evaluate_as_the_curve_nodes_do():
    circle = rg.Circle(rg.Plane.WorldXY(), 2.0).ToNurbsCurve()
    assert isinstance(circle, rg.Curve) and circle.IsClosed
    d = circle.Domain
    assert (d.Min, d.Max) == (0.0, 2 * math.pi)
    assert approx_xyz(circle.PointAt(math.pi / 2), (0, 2, 0), 1e-12)
    assert approx_xyz(circle.TangentAt(0.0), (0, 1, 0), 1e-12)
    k = circle.CurvatureAt(1.0)
    assert abs(k.Length - 0.5) < 1e-12
    assert abs(circle.GetLength() - 4 * math.pi) < 1e-9
    ok, t = circle.ClosestPoint(rg.Point3d(0, -5, 0))
    assert ok and abs(t - 1.5 * math.pi) < 1e-9
    line = rg.Line(rg.Point3d(0, 0, 0), rg.Point3d(3, 4, 0))
    assert line.Length == 5.0 and line.PointAt(0.5) == rg.Point3d(1.5, 2, 0)
    lc = line.ToNurbsCurve()
    assert lc.PointAtEnd == rg.Point3d(3, 4, 0)
    assert lc.TangentAtStart.EpsilonEquals(rg.Vector3d(0.6, 0.8, 0), 1e-12)
    nurbs = rg.NurbsCurve.Create(False, 3, [rg.Point3d(i, i * i, 0) for i in range(5)])
    assert nurbs.Degree == 3 and len(nurbs.Points) == 5
    assert nurbs.PointAtStart == rg.Point3d(0, 0, 0) and nurbs.PointAtEnd == rg.Point3d(4, 16, 0)
    params = nurbs.DivideByCount(4, True)
    assert len(params) == 5 and params[0] == nurbs.Domain.T0
    moved = nurbs.Duplicate()
    moved.Translate(0, 0, 1)
    assert moved.PointAtStart == rg.Point3d(0, 0, 1) and nurbs.PointAtStart.Z == 0


def test_surfaces_and_breps():
    sphere = rg.Sphere(rg.Point3d(0, 0, 0), 2.0)
    srf = sphere.ToNurbsSurface()
    ok, u, v = srf.ClosestPoint(rg.Point3d(0, 0, 5))
    assert ok and approx_xyz(srf.PointAt(u, v), (0, 0, 2), 1e-9)
    assert approx_xyz(srf.NormalAt(u, v), (0, 0, 1), 1e-9)
    box = rg.Box(rg.Plane.WorldXY(), rg.Interval(0, 2), rg.Interval(0, 3), rg.Interval(0, 4))
    brep = box.ToBrep()
    assert brep.IsSolid and len(brep.Faces) == 6 and brep.Faces.Count == 6
    assert abs(brep.GetVolume() - 24.0) < 1e-9
    props = rg.AreaMassProperties.Compute(brep)
    assert abs(props.Area - 52.0) < 1e-9 and approx_xyz(props.Centroid, (1, 1.5, 2), 1e-9)
    face = brep.Faces.ExtractFace(0)
    assert len(face.Faces) == 1 and not face.IsSolid
    poles = [
        t.Face.PointAt(t.PointAtStart.X, t.PointAtStart.Y)
        for t in sphere.ToBrep().Trims
        if t.Edge is None
    ]
    assert sorted(round(p.Z, 9) for p in poles) == [-2.0, 2.0]


def test_rhinoscriptsyntax_points_vectors_and_curves():
    assert rs.VectorCreate([3, 4, 0], [0, 0, 0]) == rg.Vector3d(3, 4, 0)
    assert rs.VectorLength([3, 4, 0]) == 5.0
    assert rs.VectorDotProduct([1, 2, 3], [4, 5, 6]) == 32.0
    assert rs.VectorCrossProduct([1, 0, 0], [0, 1, 0]) == rg.Vector3d(0, 0, 1)
    assert abs(rs.VectorAngle([1, 0, 0], [0, 1, 0]) - 90.0) < 1e-12
    assert rs.PointAdd([1, 1, 1], [1, 2, 3]) == rg.Point3d(2, 3, 4)
    assert rs.Distance([0, 0, 0], [0, 3, 4]) == 5.0
    assert rs.VectorUnitize([0, 0, 2]) == rg.Vector3d(0, 0, 1)
    assert rs.PointCoordinates(rs.AddPoint(1, 2, 3)) == rg.Point3d(1, 2, 3)
    line = rs.AddLine([0, 0, 0], [10, 0, 0])
    assert rs.CurveLength(line) == 10.0
    # A line curve's domain is its length, as Rhino's LineCurve.
    assert rs.CurveDomain(line) == [0.0, 10.0]
    assert rs.EvaluateCurve(line, 2.5) == rg.Point3d(2.5, 0, 0)
    assert rs.CurveClosestPoint(line, [4, 3, 0]) == pytest.approx(4.0)
    points = rs.DivideCurve(line, 5)
    assert [p.X for p in points] == pytest.approx([0, 2, 4, 6, 8, 10])
    circle = rs.AddCircle(rs.WorldXYPlane(), 3)
    point, tangent, center, radius, k = rs.CurveCurvature(circle, 0.0)
    assert radius == pytest.approx(3.0) and approx_xyz(center, (0, 0, 0), 1e-9)
    moved = rs.TransformObject(line, rs.XformTranslation([0, 0, 5]))
    assert rs.CurveStartPoint(moved) == rg.Point3d(0, 0, 5)
    assert rs.CurveStartPoint(line) == rg.Point3d(0, 0, 0)
    rot = rs.XformRotation2(90, [0, 0, 1], [0, 0, 0])
    assert approx_xyz(rs.PointTransform([1, 0, 0], rot), (0, 1, 0), 1e-12)


def test_rhinoscriptsyntax_surfaces():
    sphere = rs.AddSphere([0, 0, 0], 3)
    u, v = rs.SurfaceClosestPoint(sphere, [0, 5, 0])
    assert approx_xyz(rs.EvaluateSurface(sphere, u, v), (0, 3, 0), 1e-9)
    assert approx_xyz(rs.SurfaceNormal(sphere, [u, v]), (0, 1, 0), 1e-9)
    assert rs.SurfaceArea(sphere)[0] == pytest.approx(4 * math.pi * 9)
    assert rs.IsSurface(sphere) and not rs.IsCurve(sphere)


def test_trees_and_treehelpers():
    tree = treehelpers.list_to_tree([[1, 2], [3]])
    assert [str(p) for p in tree.Paths] == ["{0;0}", "{0;1}"]
    assert tree.Branch(GH_Path(0, 1)) == [3] and tree.DataCount == 3
    assert treehelpers.tree_to_list(tree) == [[1, 2], [3]]
    t = DataTree[object]()
    t.Add("a", GH_Path(2))
    t.AddRange(["b", "c"], GH_Path(0, 1))
    assert ghpython.to_locus(t) == {"{0;1}": ["b", "c"], "{2}": ["a"]}


def test_values_convert_both_ways():
    p = ghpython.to_rhino(locus.Point3(1, 2, 3))
    assert isinstance(p, rg.Point3d)
    assert ghpython.to_locus(p) == locus.Point3(1, 2, 3)
    assert isinstance(ghpython.to_rhino(locus.Point3(1, 2, 3), "GeometryBase"), rg.Point)
    line = ghpython.to_rhino(locus.NurbsCurve.line((0, 0, 0), (1, 0, 0)))
    assert isinstance(line, rg.LineCurve)
    back = ghpython.to_locus(line)
    assert isinstance(back, locus.NurbsCurve) and back.kind == "line"
    struct = ghpython.to_rhino(locus.NurbsCurve.line((0, 0, 0), (1, 0, 0)), "Line")
    assert isinstance(struct, rg.Line)
    items = ghpython.to_rhino([locus.Point3(0, 0, 0), None])
    assert items.Count == 2 and items[1] is None
    tree = ghpython.to_rhino({"{0;1}": [1.0]})
    assert isinstance(tree, DataTree) and tree.Branch(GH_Path(0, 1)) == [1.0]
    assert ghpython.to_locus([rg.Vector3d(1, 0, 0), 2]) == [locus.Vector3(1, 0, 0), 2]
    assert isinstance(ghpython.to_locus(rg.Polyline([(0, 0, 0), (1, 0, 0), (1, 1, 0)])), locus.NurbsCurve)


def test_what_the_layer_lacks_is_a_clear_error():
    with pytest.raises(AttributeError, match="Offset"):
        rg.NurbsCurve.Create(False, 1, [rg.Point3d(0, 0, 0), rg.Point3d(1, 0, 0)]).Offset
    assert Rhino.RhinoMath.ToRadians(180) == math.pi

"""locus's openNURBS archives against rhino3dm (PyPI): rhino3dm decodes what locus encodes, and
locus decodes what rhino3dm encodes, into equal geometry."""

import math

import pytest
import rhino3dm as r

from rhino_describe import assert_close, describe, locus, locus_decode, locus_encode

TAU = 2 * math.pi


def grid_mesh(nu, nv, colors=True, normals=True):
    vs = [[i * 0.25, j * 0.5, math.sin(i * 0.3) * math.cos(j * 0.2)] for i in range(nu) for j in range(nv)]
    faces = []
    for i in range(nu - 1):
        for j in range(nv - 1):
            a = i * nv + j
            if (i + j) % 3 == 0:
                faces.append([a, a + nv, a + nv + 1, a + nv + 1])
                faces.append([a, a + nv + 1, a + 1, a + 1])
            else:
                faces.append([a, a + nv, a + nv + 1, a + 1])
    d = {"type": "mesh", "vertices": vs, "faces": faces, "normals": None, "colors": None}
    if normals:
        d["normals"] = [[0.0, 0.6, 0.8]] * len(vs)
    if colors:
        d["colors"] = [[k % 256, (3 * k) % 256, (7 * k) % 256, 255 if k % 5 else 100] for k in range(len(vs))]
    return d


PERIODIC_CUBIC = {
    "type": "nurbs_curve",
    "degree": 3,
    # 4 distinct points, the last 3 repeat the first 3 (Rhino's periodic form).
    "points": [[0, 0, 0], [2, 0, 0], [2, 2, 1], [0, 2, 0], [0, 0, 0], [2, 0, 0], [2, 2, 1]],
    "weights": [1.0] * 7,
    "knots": [-2.0, -1.0, 0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0],
}

S = math.sqrt(0.5)
LOCUS_CASES = {
    "mesh_small": {
        "type": "mesh",
        "vertices": [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0.5], [0.123456789012345, 2, 3]],
        "faces": [[0, 1, 2, 3], [2, 3, 4, 4]],
        "normals": [[0, 0, 1], [0, 0, 1], [0, 1, 0], [1, 0, 0], [0.6, 0.8, 0]],
        "colors": [[10, 20, 30, 255], [1, 2, 3, 128], [4, 5, 6, 255], [7, 8, 9, 0], [255, 255, 255, 255]],
    },
    "mesh_plain": grid_mesh(4, 3, colors=False, normals=False),
    "mesh_2_byte_indices": grid_mesh(30, 20),
    "mesh_4_byte_indices": grid_mesh(300, 220, colors=False),
    "nurbs_cubic": {
        "type": "nurbs_curve",
        "degree": 3,
        "points": [[0, 0, 0], [1, 2, 0], [3, 2, 1], [4, 0, 1], [6, 1, 2]],
        "weights": [1.0] * 5,
        "knots": [0.0, 0.0, 0.0, 1.5, 4.0, 4.0, 4.0],
    },
    "nurbs_rational_quarter_circle": {
        "type": "nurbs_curve",
        "degree": 2,
        "points": [[3, 0, 0], [3, 3, 0], [0, 3, 0]],
        "weights": [1.0, S, 1.0],
        "knots": [0.0, 0.0, 1.0, 1.0],
    },
    "nurbs_periodic": PERIODIC_CUBIC,
    "line": {"type": "line", "from": [0, 0, 0], "to": [1, 2, 3], "domain": [0.0, 5.0]},
    "polyline": {"type": "polyline", "points": [[0, 0, 0], [1, 0, 0], [1, 1, 0], [2, 3, 4]], "domain": [0.0, 3.0]},
    "circle": {
        "type": "circle",
        "plane": {"origin": [1, 2, 3], "x": [1, 0, 0], "y": [0, 1, 0], "z": [0, 0, 1]},
        "radius": 2.0,
        "domain": [0.0, TAU],
    },
    "arc": {
        "type": "arc",
        "plane": {"origin": [1, 2, 3], "x": [0, 1, 0], "y": [0, 0, 1], "z": [1, 0, 0]},
        "radius": 2.0,
        "angle": [0.5, 2.0],
        "domain": [0.0, 1.0],
    },
    "surface_bilinear": {
        "type": "nurbs_surface",
        "degree": [1, 1],
        "count": [2, 2],
        "points": [[0, 0, 0], [0, 1, 0], [1, 0, 0], [1, 1, 1]],
        "weights": [1.0] * 4,
        "knots_u": [0.0, 1.0],
        "knots_v": [0.0, 1.0],
    },
    "surface_rational_cylinder_patch": {
        "type": "nurbs_surface",
        "degree": [2, 1],
        "count": [3, 2],
        "points": [[3, 0, 0], [3, 0, 5], [3, 3, 0], [3, 3, 5], [0, 3, 0], [0, 3, 5]],
        "weights": [1.0, 1.0, S, S, 1.0, 1.0],
        "knots_u": [0.0, 0.0, 1.0, 1.0],
        "knots_v": [-1.0, 4.0],
    },
    "surface_cubic_by_quadratic": {
        "type": "nurbs_surface",
        "degree": [3, 2],
        "count": [5, 4],
        "points": [[i, j, (i * j) % 3 * 0.5] for i in range(5) for j in range(4)],
        "weights": [1.0] * 20,
        "knots_u": [0.0, 0.0, 0.0, 0.4, 1.0, 1.0, 1.0],
        "knots_v": [0.0, 0.0, 0.5, 2.0, 2.0],
    },
}


@pytest.mark.parametrize("name", sorted(LOCUS_CASES))
def test_rhino3dm_decodes_what_locus_encodes(name):
    desc = LOCUS_CASES[name]
    encoded = locus_encode(desc)
    assert encoded["version"] == 10000 and encoded["archive3dm"] == 60
    obj = r.CommonObject.Decode(encoded)
    assert obj is not None, "rhino3dm could not decode"
    assert obj.IsValid, obj.IsValidWithLog() if hasattr(obj, "IsValidWithLog") else ""
    got = describe(obj)
    expected = dict(desc)
    if desc["type"] == "mesh":
        # rhino3dm keeps normals in single precision.
        assert_close(expected.pop("normals"), got.pop("normals"), tol=1e-7)
    if desc["type"] == "circle":
        assert obj.IsCompleteCircle
    assert_close(expected, got, tol=1e-14)
    if desc["type"] == "nurbs_curve" and name == "nurbs_periodic":
        assert obj.IsPeriodic
    # And locus reads its own bytes back unchanged (normals are stored in single precision).
    back = locus_decode(encoded)
    expected = dict(desc)
    if desc["type"] == "mesh":
        assert_close(expected.pop("normals"), back.pop("normals"), tol=1e-7)
    assert_close(expected, back, tol=0)


def rhino_meshes():
    m = r.Mesh()
    for i in range(25):
        for j in range(12):
            m.Vertices.Add(i * 0.1, j * 0.2, ((i * j) % 7) * 0.01)
    for i in range(24):
        for j in range(11):
            a = i * 12 + j
            if j % 2:
                m.Faces.AddFace(a, a + 12, a + 13, a + 1)
            else:
                m.Faces.AddFace(a, a + 12, a + 13)
    m.Normals.ComputeNormals()
    for k in range(len(m.Vertices)):
        m.VertexColors.Add(k % 256, (5 * k) % 256, 17)
    small = r.Mesh()
    for p in [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0.5)]:
        small.Vertices.Add(*p)
    small.Faces.AddFace(0, 1, 2, 3)
    return {"mesh_grid_normals_colours": m, "mesh_quad": small}


def tilted_circle():
    c = r.Circle(r.Point3d(1, 2, 3), 2.5).ToNurbsCurve()
    c.Rotate(0.7, r.Vector3d(1, 1, 0), r.Point3d(1, 2, 3))
    return c


def rhino_curves():
    pts = [r.Point3d(0, 0, 0), r.Point3d(1, 2, 0), r.Point3d(3, 2, 1), r.Point3d(4, 0, 1), r.Point3d(6, 1, 2)]
    return {
        "nurbs_cubic": r.NurbsCurve.Create(False, 3, pts),
        "nurbs_periodic": r.NurbsCurve.Create(True, 3, pts),
        "nurbs_rational_circle": tilted_circle(),
        "line": r.LineCurve(r.Point3d(0, 0, 0), r.Point3d(1, 2, 3)),
        "polyline": r.PolylineCurve([r.Point3d(0, 0, 0), r.Point3d(1, 0, 0), r.Point3d(1, 1, 0), r.Point3d(5, 1, 2)]),
        "arc_curve": r.ArcCurve.CreateFromArc(r.Arc(r.Point3d(1, 0, 0), r.Point3d(2, 1, 0), r.Point3d(3, 0, 0))),
        "circle_curve": r.ArcCurve.CreateFromCircle(r.Circle(r.Point3d(1, 2, 3), 2.0)),
    }


def rhino_surfaces():
    sphere = r.NurbsSurface.CreateFromSphere(r.Sphere(r.Point3d(1, 2, 3), 2))
    cyl = r.NurbsSurface.CreateFromCylinder(
        r.Cylinder(r.Circle(r.Point3d(0, 0, 0), 1.5), 4.0)
    )
    a = r.NurbsCurve.Create(False, 3, [r.Point3d(0, 0, 0), r.Point3d(1, 1, 0), r.Point3d(2, 0, 0), r.Point3d(3, 1, 0)])
    b = r.NurbsCurve.Create(False, 2, [r.Point3d(0, 0, 2), r.Point3d(1.5, 2, 2), r.Point3d(3, 0, 2)])
    ruled = r.NurbsSurface.CreateRuledSurface(a, b)
    return {"surface_sphere": sphere, "surface_cylinder": cyl, "surface_ruled": ruled}


RHINO_CASES = {**rhino_meshes(), **rhino_curves(), **rhino_surfaces()}


@pytest.mark.parametrize("name", sorted(RHINO_CASES))
def test_locus_decodes_what_rhino3dm_encodes(name):
    obj = RHINO_CASES[name]
    assert obj.IsValid
    got = locus_decode(obj.Encode())
    expected = describe(obj)
    if expected["type"] == "mesh" and expected["normals"] is not None:
        assert_close(expected.pop("normals"), got.pop("normals"), tol=1e-7)
    if expected["type"] == "circle":
        # locus's plane is orthonormalised from the stored axes: equal within rounding.
        assert_close(expected, got, tol=1e-15)
    else:
        assert_close(expected, got, tol=0)


def test_polycurve_is_read_as_one_nurbs_curve_through_the_same_points():
    pc = r.PolyCurve()
    pc.Append(r.Line(r.Point3d(0, 0, 0), r.Point3d(1, 0, 0)))
    pc.Append(r.Arc(r.Point3d(1, 0, 0), r.Point3d(2, 1, 0), r.Point3d(3, 0, 0)))
    pc.Append(r.NurbsCurve.Create(False, 3, [r.Point3d(3, 0, 0), r.Point3d(4, -1, 0), r.Point3d(5, 1, 1), r.Point3d(6, 0, 0)]))
    assert pc.IsValid
    got = locus_decode(pc.Encode())
    assert got["type"] == "nurbs_curve" and got["degree"] == 3
    # Evaluate locus's curve with rhino3dm: encode it back and compare points. The line and
    # NURBS segments keep their parameters; the arc's NURBS form traces the same arc at other
    # parameters (an ArcCurve is parameterised by angle), so its points are checked on the arc.
    joined = r.CommonObject.Decode(locus_encode(got))
    assert joined.IsValid
    assert_close([joined.Domain.T0, joined.Domain.T1], [pc.Domain.T0, pc.Domain.T1], tol=1e-15)
    for i in range(pc.SegmentCount):
        d = pc.SegmentDomain(i)
        for k in range(21):
            t = d.T0 + (d.T1 - d.T0) * k / 20
            p = joined.PointAt(t)
            if i == 1:
                assert abs(_xyz(p)[0] - 2.0) ** 2 + _xyz(p)[1] ** 2 == pytest.approx(1.0, abs=1e-12)
                if k in (0, 20):
                    assert_close(_xyz(p), _xyz(pc.PointAt(t)), tol=1e-12)
            else:
                assert_close(_xyz(p), _xyz(pc.PointAt(t)), tol=1e-12)


def _xyz(p):
    return [p.X, p.Y, p.Z]


def test_errors_are_reported_not_crashed():
    enc = r.NurbsCurve.Create(False, 1, [r.Point3d(0, 0, 0), r.Point3d(1, 0, 0)]).Encode()
    data = enc["data"]
    bad = [
        {**enc, "data": data[: len(data) // 2]},
        {**enc, "data": "not base64!"},
        {**enc, "archive3dm": 4},
        {"data": data},
        {**enc, "data": data[:40] + ("A" if data[40] != "A" else "B") + data[41:]},
    ]
    answers = locus([{"op": "decode", "encoded": b} for b in bad])
    assert all("error" in a for a in answers), answers

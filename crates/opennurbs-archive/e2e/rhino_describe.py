"""Describe rhino3dm geometry in the plain JSON form of locus's archive_json example
(crates/opennurbs-archive/tests/common/describe.rs), and compare descriptions."""

import json
import math
import os
import subprocess

import rhino3dm as r

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", "..", ".."))
TOOL = os.environ.get(
    "LOCUS_ARCHIVE_JSON", os.path.join(ROOT, "target", "debug", "examples", "archive_json")
)


def locus(requests):
    """Runs locus's archive_json example on a list of requests and returns its answers."""
    out = subprocess.run(
        [TOOL], input=json.dumps(requests), capture_output=True, text=True, timeout=60, check=True
    )
    return json.loads(out.stdout)


def locus_encode(desc):
    (a,) = locus([{"op": "encode", "geometry": desc}])
    assert "error" not in a, a
    return a["encoded"]


def locus_decode(encoded):
    (a,) = locus([{"op": "decode", "encoded": encoded}])
    assert "error" not in a, a
    return a["geometry"]


def _p(p):
    return [p.X, p.Y, p.Z]


def _h(p):
    """A homogeneous Point4d as a Euclidean point and its weight."""
    return [p.X / p.W, p.Y / p.W, p.Z / p.W], p.W


def _plane(pl):
    return {"origin": _p(pl.Origin), "x": _p(pl.XAxis), "y": _p(pl.YAxis), "z": _p(pl.ZAxis)}


def describe(o):
    """The description of a rhino3dm object, from rhino3dm's own API."""
    if isinstance(o, r.Mesh):
        n = len(o.Vertices)
        faces = []
        for i in range(len(o.Faces)):
            f = o.Faces[i]
            faces.append(list(f))
        return {
            "type": "mesh",
            "vertices": [_p(o.Vertices.Point3dAt(i)) for i in range(n)],
            "faces": faces,
            "normals": [_p(o.Normals[i]) for i in range(n)] if len(o.Normals) == n and n else None,
            "colors": [list(o.VertexColors[i]) for i in range(n)]
            if len(o.VertexColors) == n and n
            else None,
        }
    if isinstance(o, r.NurbsCurve):
        pts, ws = zip(*(_h(o.Points[i]) for i in range(len(o.Points))))
        return {
            "type": "nurbs_curve",
            "degree": o.Degree,
            "points": list(pts),
            "weights": list(ws),
            "knots": list(o.Knots),
        }
    if isinstance(o, r.LineCurve):
        d = o.Domain
        return {"type": "line", "from": _p(o.PointAtStart), "to": _p(o.PointAtEnd), "domain": [d.T0, d.T1]}
    if isinstance(o, r.PolylineCurve):
        d = o.Domain
        return {
            "type": "polyline",
            "points": [_p(o.Point(i)) for i in range(o.PointCount)],
            "domain": [d.T0, d.T1],
        }
    if isinstance(o, r.ArcCurve):
        a = o.Arc
        d = o.Domain
        desc = {"plane": _plane(a.Plane), "radius": o.Radius, "domain": [d.T0, d.T1]}
        if o.IsCompleteCircle:
            desc["type"] = "circle"
        else:
            desc["type"] = "arc"
            desc["angle"] = [a.StartAngle, a.EndAngle]
        return desc
    if isinstance(o, r.NurbsSurface):
        cu, cv = o.Points.CountU, o.Points.CountV
        pts, ws = [], []
        for i in range(cu):
            for j in range(cv):
                p, w = _h(o.Points[i, j])
                pts.append(p)
                ws.append(w)
        return {
            "type": "nurbs_surface",
            "degree": [o.Degree(0), o.Degree(1)],
            "count": [cu, cv],
            "points": pts,
            "weights": ws,
            "knots_u": list(o.KnotsU),
            "knots_v": list(o.KnotsV),
        }
    raise TypeError(f"no description for {type(o).__name__}")


def assert_close(a, b, tol=1e-12, path="$"):
    """Asserts that two descriptions are equal, numbers within tol (relative, floor 1)."""
    if isinstance(a, dict):
        assert isinstance(b, dict) and set(a) == set(b), f"{path}: keys {sorted(a)} != {sorted(b)}"
        for k in a:
            assert_close(a[k], b[k], tol, f"{path}.{k}")
    elif isinstance(a, (list, tuple)):
        assert isinstance(b, (list, tuple)) and len(a) == len(b), f"{path}: {a!r} != {b!r}"
        for i, (x, y) in enumerate(zip(a, b)):
            assert_close(x, y, tol, f"{path}[{i}]")
    elif isinstance(a, (int, float)) and not isinstance(a, bool):
        assert isinstance(b, (int, float)), f"{path}: {a!r} != {b!r}"
        assert math.isclose(a, b, rel_tol=tol, abs_tol=tol), f"{path}: {a!r} != {b!r}"
    else:
        assert a == b, f"{path}: {a!r} != {b!r}"

"""The official Rhino.Compute Python client (compute-rhino3d) against `locus serve`, with the
geometry decoded by rhino3dm."""
import json
import math
import os

import compute_rhino3d.Grasshopper as gh
import requests
import rhino3dm

HERE = os.path.dirname(__file__)
DEFS = os.path.join(HERE, "..", "tests", "definitions")
TANGENT = os.path.join(DEFS, "tangent_spheres.ron")
TYPES = os.path.join(DEFS, "types.ron")


def outputs(answer):
    """{name: [(type, decoded data), ...]} of an answer."""
    out = {}
    for tree in answer["values"]:
        items = []
        for branch in tree["InnerTree"].values():
            for item in branch:
                items.append((item["type"], json.loads(item["data"])))
        out[tree["ParamName"]] = items
    return out


def test_tangent_spheres_through_the_official_client(server_url):
    t = gh.DataTree("t")
    t.Append([0], [0.5])
    b = gh.DataTree("B")
    b.Append([0], [rhino3dm.Point3d(10, 0, 0)])
    answer = gh.EvaluateDefinition(TANGENT, [t, b])
    assert "errors" not in answer, answer.get("errors")
    out = outputs(answer)
    assert out["D"] == [("Rhino.Geometry.Point3d", {"X": 5.0, "Y": 0.0, "Z": 0.0})]
    assert out["r1"] == [("System.Double", 2.5)]
    assert out["r2"] == [("System.Double", 2.5)]
    # The spheres decode with rhino3dm into NURBS surfaces whose points lie at the radius.
    for name, centre, radius in [("S1", (2.5, 0, 0), 2.5), ("S2", (7.5, 0, 0), 2.5)]:
        (kind, data), = out[name]
        assert kind == "Rhino.Geometry.NurbsSurface"
        srf = rhino3dm.CommonObject.Decode(data)
        assert isinstance(srf, rhino3dm.NurbsSurface)
        assert (srf.Degree(0), srf.Degree(1)) == (2, 2)
        u0, u1 = srf.Domain(0).T0, srf.Domain(0).T1
        v0, v1 = srf.Domain(1).T0, srf.Domain(1).T1
        for i in range(5):
            for j in range(5):
                p = srf.PointAt(u0 + (u1 - u0) * i / 4, v0 + (v1 - v0) * j / 4)
                d = math.dist((p.X, p.Y, p.Z), centre)
                assert abs(d - radius) < 1e-9, (name, i, j, d)


def test_the_answer_pointer_solves_again_without_the_definition(server_url):
    t = gh.DataTree("t")
    t.Append([0], [0.25])
    first = gh.EvaluateDefinition(TANGENT, [t])
    pointer = first["pointer"]
    assert pointer.startswith("md5_")
    body = {"pointer": pointer, "values": [t.data]}
    second = requests.post(server_url + "/grasshopper", json=body, timeout=30).json()
    assert outputs(second)["D"] == outputs(first)["D"]
    assert outputs(second)["D"] == [("Rhino.Geometry.Point3d", {"X": 2.0, "Y": 1.5, "Z": 0.0})]


def test_plain_types_and_rhino3dm_geometry_round_trip(server_url):
    trees = []

    def put(name, value):
        tree = gh.DataTree(name)
        tree.Append([0, 1], [value])
        trees.append(tree)

    plane = rhino3dm.Plane(rhino3dm.Point3d(1, 2, 3), rhino3dm.Vector3d(0, 0, 1))
    put("Num", 2.5)
    put("Int", 4)
    put("Bool", "false")  # booleans go as JSON text (Python's True becomes "True")
    put("Text", "hello")
    put("Pt", rhino3dm.Point3d(1, -2, 3.5))
    put("Vec", rhino3dm.Vector3d(0, 1, 0))
    put("Pln", plane)
    curve = rhino3dm.NurbsCurve.Create(
        False, 3, [rhino3dm.Point3d(0, 0, 0), rhino3dm.Point3d(1, 2, 0),
                   rhino3dm.Point3d(3, 2, 1), rhino3dm.Point3d(4, 0, 0)])
    put("Crv", curve)
    answer = gh.EvaluateDefinition(TYPES, trees)
    assert "errors" not in answer, answer.get("errors")
    out = outputs(answer)
    assert out["Num"] == [("System.Double", 2.5)]
    assert out["Int"] == [("System.Int32", 4)]
    assert out["Bool"] == [("System.Boolean", False)]
    assert out["Text"] == [("System.String", "hello")]
    assert out["Sum"] == [("System.Double", 6.5)]
    assert out["Pt"] == [("Rhino.Geometry.Point3d", {"X": 1.0, "Y": -2.0, "Z": 3.5})]
    assert out["Vec"] == [("Rhino.Geometry.Vector3d", {"X": 0.0, "Y": 1.0, "Z": 0.0})]
    (kind, pln), = out["Pln"]
    assert kind == "Rhino.Geometry.Plane"
    assert pln["Origin"] == {"X": 1.0, "Y": 2.0, "Z": 3.0}
    assert pln["ZAxis"] == {"X": 0.0, "Y": 0.0, "Z": 1.0}
    # Outputs keep the input paths.
    sent = {tree.data["ParamName"] for tree in trees}
    for tree in answer["values"]:
        if tree["ParamName"] in sent:
            assert list(tree["InnerTree"]) == ["{0;1}"], tree
    # The curve comes back as the same curve, decoded by rhino3dm.
    (kind, data), = out["Crv"]
    assert kind == "Rhino.Geometry.NurbsCurve"
    back = rhino3dm.CommonObject.Decode(data)
    assert back.Degree == 3 and len(back.Points) == 4
    for k in range(11):
        t = curve.Domain.T0 + (curve.Domain.T1 - curve.Domain.T0) * k / 10
        p, q = curve.PointAt(t), back.PointAt(t)
        assert math.dist((p.X, p.Y, p.Z), (q.X, q.Y, q.Z)) < 1e-12
    (kind, data), = out["Srf"]
    assert isinstance(rhino3dm.CommonObject.Decode(data), rhino3dm.NurbsSurface)


def test_io_describes_the_definition(server_url):
    with open(TANGENT, encoding="utf-8") as f:
        import base64
        algo = base64.b64encode(f.read().encode("utf-8")).decode()
    io = requests.post(server_url + "/io", json={"algo": algo}, timeout=30).json()
    assert io["InputNames"] == ["A", "B", "t"]
    assert io["Inputs"][2]["ParamType"] == "Number"
    assert io["Inputs"][2]["Default"]["InnerTree"]["{0}"] == [
        {"type": "System.Double", "data": "0.25"}]
    assert io["CacheKey"].startswith("md5_")


def test_caller_errors_are_400_with_a_reason(server_url):
    t = gh.DataTree("t")
    t.Append([0], ["not a number"])
    answer = gh.EvaluateDefinition(TANGENT, [t])
    assert answer["error"]["status"] == 400
    assert 'input "t" {0}[0]' in answer["error"]["message"]
    r = requests.post(server_url + "/grasshopper", data=b"{nope", timeout=30)
    assert r.status_code == 400 and "not JSON" in r.json()["error"]["message"]


SAMPLES = os.path.join(DEFS, "grasshopper")


def circle_inputs(centre, radius):
    """The inputs of mcneel/compute's circle samples: Compute names them by their whole group
    nickname, type code included (the point is `RH_IN:102:0001`, the radius `RH_IN:105:0001`)."""
    pt = gh.DataTree("RH_IN:102:0001")
    pt.Append([0], [rhino3dm.Point3d(*centre)])
    r = gh.DataTree("RH_IN:105:0001")
    r.Append([0], [radius])
    return [pt, r]


def circles(answer, name):
    """The circles of one output, decoded: [(centre, normal, radius), ...] in order."""
    (tree,) = [t for t in answer["values"] if t["ParamName"] == name]
    out = []
    for branch in tree["InnerTree"].values():
        for item in branch:
            assert item["type"] == "Rhino.Geometry.Circle", item
            c = json.loads(item["data"])
            o, z = c["Plane"]["Origin"], c["Plane"]["ZAxis"]
            out.append(((o["X"], o["Y"], o["Z"]), (z["X"], z["Y"], z["Z"]), c["Radius"]))
    return out


def close(a, b, tol=1e-9):
    return all(abs(x - y) <= tol for x, y in zip(a, b))


def test_compute_sample_simple_circle_one(server_url):
    # The definition (crates/server/tests/definitions/grasshopper/, from mcneel/compute): Circle
    # CNR with centre the point input, radius the number input, and normal (0, 0, 1) typed into
    # the component; the circle goes to a Circle parameter grouped as RH_OUT:109:0001. So the
    # answer is one circle centred at the point we send, in the XY plane, of the radius we send.
    answer = gh.EvaluateDefinition(
        os.path.join(SAMPLES, "mcneel-compute__simple_circle_one.ghx"),
        circle_inputs((3.0, 4.0, 0.5), 2.5))
    assert "errors" not in answer, answer.get("errors")
    assert [t["ParamName"] for t in answer["values"]] == ["RH_OUT:109:0001"]
    ((centre, normal, radius),) = circles(answer, "RH_OUT:109:0001")
    assert close(centre, (3.0, 4.0, 0.5)) and close(normal, (0, 0, 1)) and radius == 2.5
    # rhino3dm agrees that this circle has the expected length (2 pi r) and centre.
    c = rhino3dm.Circle(rhino3dm.Point3d(*centre), radius)
    assert abs(c.Circumference - 2 * math.pi * 2.5) < 1e-12


def test_compute_sample_simple_circle_array(server_url):
    # The same circle (RH_OUT:109:0001), divided by Divide Curve into N = 10 equal segments
    # (typed into the component; K = false), and a circle of the same radius centred at each of
    # the 10 division points (RH_OUT:109:0002). The circle starts on its plane's x axis, which
    # for the normal (0, 0, 1) is the world x axis, so point k is centre + r (cos 2 pi k / 10,
    # sin 2 pi k / 10, 0).
    cx, cy, cz, r = 1.0, -2.0, 0.0, 4.0
    answer = gh.EvaluateDefinition(
        os.path.join(SAMPLES, "mcneel-compute__simple_circle_array.ghx"),
        circle_inputs((cx, cy, cz), r))
    assert "errors" not in answer, answer.get("errors")
    assert [t["ParamName"] for t in answer["values"]] == ["RH_OUT:109:0001", "RH_OUT:109:0002"]
    ((centre, _, radius),) = circles(answer, "RH_OUT:109:0001")
    assert close(centre, (cx, cy, cz)) and radius == r
    ring = circles(answer, "RH_OUT:109:0002")
    assert len(ring) == 10
    for k, (centre, normal, radius) in enumerate(ring):
        a = 2 * math.pi * k / 10
        assert close(centre, (cx + r * math.cos(a), cy + r * math.sin(a), cz)), (k, centre)
        assert close(normal, (0, 0, 1)) and abs(radius - r) < 1e-12


def test_io_names_inputs_and_outputs_as_compute_does(server_url):
    with open(os.path.join(SAMPLES, "mcneel-compute__simple_circle_array.ghx"), "rb") as f:
        import base64
        algo = base64.b64encode(f.read()).decode()
    io = requests.post(server_url + "/io", json={"algo": algo}, timeout=30).json()
    assert sorted(io["InputNames"]) == ["RH_IN:102:0001", "RH_IN:105:0001"]
    assert io["OutputNames"] == ["RH_OUT:109:0001", "RH_OUT:109:0002"]
    types = {i["Name"]: i["ParamType"] for i in io["Inputs"]}
    assert types == {"RH_IN:102:0001": "Point", "RH_IN:105:0001": "Number"}
    # The same definition by pointer: a file under --definitions.
    body = {"pointer": "grasshopper/mcneel-compute__simple_circle_one.ghx",
            "values": [
                {"ParamName": "RH_IN:102:0001", "InnerTree": {"{0}": [
                    {"type": "Rhino.Geometry.Point3d", "data": '{"X":0,"Y":0,"Z":0}'}]}},
                {"ParamName": "RH_IN:105:0001", "InnerTree": {"{0}": [
                    {"type": "System.Double", "data": "1.0"}]}}]}
    answer = requests.post(server_url + "/grasshopper", json=body, timeout=30).json()
    ((centre, _, radius),) = circles(answer, "RH_OUT:109:0001")
    assert close(centre, (0, 0, 0)) and radius == 1.0

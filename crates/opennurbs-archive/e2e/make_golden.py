"""Writes rhino3dm-made encodings with rhino3dm's own description of each object into
crates/opennurbs-archive/tests/golden/, so that `cargo test` replays them without Python.

Run from anywhere with a Python that has rhino3dm: python make_golden.py"""

import json
import os

import rhino3dm as r

from rhino_describe import HERE, describe
from test_rhino3dm import RHINO_BREPS, RHINO_CASES, polycurve

OUT = os.path.join(HERE, "..", "tests", "golden")


def main():
    os.makedirs(OUT, exist_ok=True)
    cases = dict(RHINO_CASES)
    cases["polycurve_line_arc_nurbs"] = polycurve()
    exact = {}
    for name, (b, area, volume) in RHINO_BREPS.items():
        cases[name] = b
        exact[name] = {"area": area, "volume": volume}
    for name, obj in sorted(cases.items()):
        entry = {
            "rhino3dm": r.__version__,
            "class": type(obj).__name__,
            "encoded": obj.Encode(),
        }
        try:
            entry["expect"] = describe(obj)
        except TypeError:
            entry["expect"] = None
        if name in exact:
            entry["exact"] = exact[name]
        if isinstance(obj, r.PolyCurve):
            d = obj.Domain
            entry["samples"] = [
                [d.T0 + (d.T1 - d.T0) * k / 8, [obj.PointAt(d.T0 + (d.T1 - d.T0) * k / 8).X,
                                                 obj.PointAt(d.T0 + (d.T1 - d.T0) * k / 8).Y,
                                                 obj.PointAt(d.T0 + (d.T1 - d.T0) * k / 8).Z]]
                for k in range(9)
            ]
        with open(os.path.join(OUT, name + ".json"), "w") as f:
            json.dump(entry, f, indent=1)
            f.write("\n")
        print("wrote", name)


if __name__ == "__main__":
    main()

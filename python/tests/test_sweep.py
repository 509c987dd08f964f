"""Sweeps on a local process pool and on a real Dask cluster (LocalCluster, 2 worker processes)."""

import importlib

import numpy as np
import pandas as pd
import pytest

import locus
from conftest import TANGENT_SPHERES

distributed = pytest.importorskip("dask.distributed")


@pytest.fixture(scope="module")
def client():
    cluster = distributed.LocalCluster(
        n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None, silence_logs=40
    )
    c = distributed.Client(cluster)
    yield c
    c.close()
    cluster.close()


OUTPUTS = ["D", "r1", "r2", "S1", "gap1"]


def test_variants_product_and_zip():
    v = locus.variants({"a": [1, 2], "b": np.array([10.0, 20.0, 30.0])})
    assert v[:4] == [{"a": 1, "b": 10.0}, {"a": 1, "b": 20.0}, {"a": 1, "b": 30.0}, {"a": 2, "b": 10.0}]
    assert len(v) == 6
    assert locus.variants({"a": [1, 2], "b": [3, 4]}, mode="zip") == [{"a": 1, "b": 3}, {"a": 2, "b": 4}]
    points = locus.variants({"B": np.array([[1.0, 0, 0], [0, 1, 0]])})
    assert points == [{"B": (1.0, 0.0, 0.0)}, {"B": (0.0, 1.0, 0.0)}]
    with pytest.raises(ValueError, match="as many values"):
        locus.variants({"a": [1, 2], "b": [3]}, mode="zip")
    with pytest.raises(ValueError):
        locus.variants({"a": [1]}, mode="diagonal")


def check_frame(df, ts, bs):
    assert len(df) == len(ts) * len(bs)
    assert list(df.columns) == ["t", "B"] + OUTPUTS + ["messages", "error"]
    # Input order: t outer, B inner.
    assert df["t"].tolist() == [t for t in ts for _ in bs]
    assert df["B"].tolist() == [b for _ in ts for b in bs]
    ok = df[df["error"].isna()]
    for row in ok.itertuples():
        length = np.linalg.norm(np.array(row.B))
        assert row.r1 == pytest.approx(row.t * length / 2)
        assert row.r2 == pytest.approx((1 - row.t) * length / 2)


def test_local_pool_equals_in_process_run():
    ts = np.linspace(0.1, 0.9, 9)
    bs = [(8.0, 6.0, 0.0), (0.0, 0.0, 10.0)]
    g = locus.Graph.load(TANGENT_SPHERES)
    inline = locus.sweep(g, {"t": ts, "B": bs}, outputs=OUTPUTS, workers=0, progress=False)
    check_frame(inline, ts, bs)
    pooled = locus.sweep(g, {"t": ts, "B": bs}, outputs=OUTPUTS, workers=2, batch_size=4, progress=False)
    pd.testing.assert_frame_equal(inline, pooled)
    assert isinstance(pooled["S1"][0], locus.NurbsSurface)


def test_dask_sweep_equals_the_local_one(client):
    assert len(client.scheduler_info()["workers"]) == 2
    values = {"t": np.linspace(0.0, 1.0, 41), "B": [(8.0, 6.0, 0.0), (3.0, 4.0, 0.0)]}
    g = locus.Graph.load(TANGENT_SPHERES)
    g.set("A", (0, 0, 0))
    local = locus.sweep(g, values, outputs=OUTPUTS, workers=2, progress=False)
    remote = locus.sweep(g, values, outputs=OUTPUTS, client=client, batch_size=5, progress=False)
    pd.testing.assert_frame_equal(local, remote)
    # t = 0 makes a sphere of radius 0: a node error, reported in its row.
    first = remote.iloc[0]
    assert first["S1"] is None and first["error"] is None
    assert any('node "s1"' in m and "radius" in m for m in first["messages"])
    # Both workers took part.
    ran = client.run(lambda: len(importlib.import_module("locus.sweep")._GRAPHS))
    assert sorted(ran.values()) == [1, 1]


def test_a_failing_variant_is_a_row_with_its_error(client):
    values = {"t": [0.25, "not a number", 0.75, float("nan")]}
    for backend in ({"workers": 0}, {"client": client}):
        df = locus.sweep(str(TANGENT_SPHERES), values, outputs=["r1"], progress=False, **backend)
        assert len(df) == 4
        assert df["r1"][0] == pytest.approx(1.25) and df["r1"][2] == pytest.approx(3.75)
        assert df["r1"][1] is None or np.isnan(df["r1"][1])
        assert df["error"][1].startswith("InputError: input \"t\"")
        assert df["error"][0] is None and df["error"][2] is None
        assert df["error"][3] is None and any("error" in m for m in df["messages"][3])


def test_geometry_summaries_and_unknown_names():
    df = locus.sweep(TANGENT_SPHERES, {"t": [0.5]}, outputs=["S1", "D"], workers=0, geometry="summary", progress=False)
    assert df["S1"][0] == "NurbsSurface(degree=(2, 2), points=9×5)"
    with pytest.raises(KeyError, match="unknown outputs"):
        locus.sweep(TANGENT_SPHERES, {"t": [0.5]}, outputs=["nope"], workers=0, progress=False)
    with pytest.raises(KeyError, match="unknown inputs"):
        locus.sweep(TANGENT_SPHERES, {"x": [0.5]}, workers=0, progress=False)

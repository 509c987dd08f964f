"""Throughput of a 10,000-variant tangent-spheres sweep: local pool vs Dask, 1 vs 2 workers.

    python python/benchmarks/sweep_throughput.py [--variants 10000]

Every run sweeps t over the same values and keeps the same outputs; the frames are checked to
be identical. Times are wall-clock times of the `locus.sweep` call: for the local pool they
include starting its processes (the pool lives for one sweep), for Dask they do not (the
cluster is started before, as a user's would be). The in-process run (workers=0) is the
baseline of one core without any pool.
"""

import argparse
import os
import time
from pathlib import Path

import numpy as np
import pandas as pd

import locus

GRAPH = Path(__file__).resolve().parents[2] / "graphs" / "tangent_spheres.ron"
OUTPUTS = ["D", "r1", "r2", "gap1", "gap2"]


def timed(**kwargs):
    values = {"t": np.linspace(0.01, 0.99, kwargs.pop("n"))}
    start = time.perf_counter()
    df = locus.sweep(GRAPH, values, outputs=OUTPUTS, progress=False, **kwargs)
    return time.perf_counter() - start, df


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--variants", type=int, default=10_000)
    parser.add_argument("--repeat", type=int, default=2, help="runs per case; the best is kept")
    args = parser.parse_args()
    n = args.variants
    from dask.distributed import Client, LocalCluster

    results = []
    reference = None

    def record(name, workers, run):
        nonlocal reference
        best = None
        for _ in range(args.repeat):
            seconds, df = run()
            best = seconds if best is None else min(best, seconds)
        if reference is None:
            reference = df
        else:
            pd.testing.assert_frame_equal(reference, df)
        assert df["error"].isna().all()
        results.append((name, workers, best))
        print(f"{name:>10} {workers} worker(s): {best:7.2f} s  {n / best:9.0f} variants/s", flush=True)

    record("in-process", 1, lambda: timed(n=n, workers=0))
    for w in (1, 2):
        record("local pool", w, lambda w=w: timed(n=n, workers=w))
    for w in (1, 2):
        cluster = LocalCluster(n_workers=w, threads_per_worker=1, processes=True, dashboard_address=None, silence_logs=40)
        client = Client(cluster)
        try:
            record("dask", w, lambda: timed(n=n, client=client))
        finally:
            client.close()
            cluster.close()

    base = {name: s for name, w, s in results if w == 1}
    local1 = base["local pool"]
    print()
    print(f"{n:,} variants; load average {os.getloadavg()[0]:.1f} on {os.cpu_count()} cores")
    print()
    print("| backend | workers | time | variants/s | vs 1 worker | vs local pool, 1 worker |")
    print("| --- | --- | --- | --- | --- | --- |")
    for name, w, s in results:
        print(f"| {name} | {w} | {s:.2f} s | {n / s:,.0f} | {base[name] / s:.2f}× | {local1 / s:.2f}× |")


if __name__ == "__main__":
    main()

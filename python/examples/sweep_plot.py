"""The README's sweep example: the tangent spheres over t and two positions of B.

    python python/examples/sweep_plot.py [docs/images/sweep.png]

Prints the first rows of the sweep's DataFrame as a Markdown table and saves a plot of the two
radii against t.
"""

import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

import locus

ROOT = Path(__file__).resolve().parents[2]


def main():
    out = Path(sys.argv[1]) if len(sys.argv) > 1 else ROOT / "docs" / "images" / "sweep.png"
    g = locus.Graph.load(ROOT / "graphs" / "tangent_spheres.ron")
    df = locus.sweep(
        g,
        {"B": [(8, 6, 0), (12, 9, 0)], "t": np.linspace(0, 1, 21)},
        outputs=["r1", "r2", "S1"],
        geometry="summary",
        workers=2,
        progress=False,
    )
    shown = df.iloc[[0, 1, 2, 10, 21]]
    print("| B | t | r1 | r2 | S1 | messages |")
    print("| --- | --- | --- | --- | --- | --- |")
    for row in shown.itertuples():
        messages = "; ".join(row.messages) or ""
        r1 = f"{row.r1:.3f}" if row.r1 is not None and not np.isnan(row.r1) else ""
        r2 = f"{row.r2:.3f}" if row.r2 is not None and not np.isnan(row.r2) else ""
        print(f"| {row.B} | {row.t:.2f} | {r1} | {r2} | {row.S1 or ''} | {messages} |")
    print(f"\n{len(df)} rows, {df['error'].notna().sum()} errors, "
          f"{sum(bool(m) for m in df['messages'])} rows with messages")

    fig, ax = plt.subplots(figsize=(7, 4), dpi=110)
    for b, group in df.groupby(df["B"].astype(str), sort=False):
        ax.plot(group["t"], group["r1"], marker="o", ms=3, label=f"r1, B = {b}")
        ax.plot(group["t"], group["r2"], marker="s", ms=3, ls="--", label=f"r2, B = {b}")
    ax.set_xlabel("t (where the spheres touch along AB)")
    ax.set_ylabel("radius")
    ax.set_title("Tangent spheres: a locus sweep of 42 variants")
    ax.grid(alpha=0.3)
    ax.legend()
    fig.tight_layout()
    out.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(out)
    print(f"saved {out.relative_to(ROOT) if out.is_relative_to(ROOT) else out}")


if __name__ == "__main__":
    main()

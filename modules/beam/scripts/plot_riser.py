#!/usr/bin/python3
"""Seed 000 Figs. 3.11-3.12 for our riser: deformed shapes of cases (a)-(d) at the snapshot
instants and the envelope of the largest bending moment along the length.

Data: the CSV files `fowtsim bench riser` writes (it prints their folder, by default
/tmp/fowtsim_bench_riser). Usage:
    python3 modules/beam/scripts/plot_riser.py [DATA_DIR] [OUT_DIR]
OUT_DIR defaults to modules/beam/figures/ (riser_shapes.png, riser_moment_envelope.png).
Line styles follow the seed's caption: (a) dash-dot, (b) red solid, (c) dashed, (d) dotted.
"""
import csv
import os
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

STYLE = {"a": dict(ls="-.", color="k"), "b": dict(ls="-", color="tab:red"),
         "c": dict(ls="--", color="tab:blue"), "d": dict(ls=":", color="tab:green", lw=2)}


def read(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    data = sys.argv[1] if len(sys.argv) > 1 else "/tmp/fowtsim_bench_riser"
    out = sys.argv[2] if len(sys.argv) > 2 else os.path.join(here, "..", "figures")
    os.makedirs(out, exist_ok=True)

    shapes = {}
    for c in "abcd":
        by_time = defaultdict(list)
        for row in read(os.path.join(data, f"riser_{c}_shapes.csv")):
            by_time[float(row["t_s"])].append((float(row["y_m"]), float(row["z_m"])))
        shapes[c] = by_time
    times = sorted(shapes["a"])
    fig, axes = plt.subplots(1, len(times), figsize=(2.6 * len(times), 6), sharey=True)
    for ax, t in zip(axes, times):
        for c in "abcd":
            y, z = zip(*shapes[c][t])
            ax.plot(y, [zz - z[0] for zz in z], label=f"case ({c})", **STYLE[c])
        ax.set_title(f"t = {t:g} s")
        ax.set_xlabel("sway y [m]")
        ax.grid(alpha=0.3)
    axes[0].set_ylabel("height above the wellhead [m]")
    axes[-1].legend(loc="lower right", fontsize=8)
    fig.suptitle("Riser deformations (seed 000 Fig. 3.11; top swayed 5 sin(0.2π(t − 1)) m)")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "riser_shapes.png"), dpi=110)

    fig, ax = plt.subplots(figsize=(6, 6))
    for c in "abcd":
        rows = read(os.path.join(data, f"riser_{c}_envelope.csv"))
        ax.plot([float(r["max_bending_moment_N_m"]) / 1e3 for r in rows], [float(r["s_m"]) for r in rows],
                label=f"case ({c})", **STYLE[c])
    ax.set_xlabel("largest |M| over the run [kN·m]")
    ax.set_ylabel("height above the wellhead [m]")
    ax.set_title("Maximum bending moments along the riser (seed 000 Fig. 3.12)")
    ax.grid(alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(out, "riser_moment_envelope.png"), dpi=110)


if __name__ == "__main__":
    main()

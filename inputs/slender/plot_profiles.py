#!/usr/bin/python3
"""Runs the four shipped slender decks and draws their profiles along the body, frequency domain
against time domain, as the seed 004 figures ("Preliminary results for a rigid body floating wind
turbine (tower)" / "... flexible marine riser"): displacement and bending stress, amplitude in the
regular wave, RMS in the JONSWAP sea; the riser's stress both ways (EI v'' and inertia relief).

  /usr/bin/python3 inputs/slender/plot_profiles.py FOWTSIM [--out DIR] [--runs DIR]

FOWTSIM: the fowtsim binary (e.g. build/driver/fowtsim). PNGs go to DIR (default: figures/ beside
this script, where the README links them). Exit codes: 0 written, 2 a run failed, 3 matplotlib missing.
"""
import argparse
import os
import subprocess
import sys
import tempfile

try:
    import numpy as np
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError as e:
    sys.stderr.write(f"plot_profiles.py: {e}; use Debian's /usr/bin/python3 with python3-matplotlib\n")
    sys.exit(3)

HERE = os.path.dirname(os.path.realpath(__file__))
# deck stem, title, x of the still water level from the bottom end (plotted as elevation z = x − x_swl),
# and the stress columns to draw (the rigid tower has no EI v'').
CASES = [
    ("oc3_tower_harmonic", "OC3 rigid floating tower, regular wave H 6 m, T 10 s", 120.0, ["ir"]),
    ("oc3_tower_jonswap", "OC3 rigid floating tower, JONSWAP Hs 6 m, Tp 10 s, γ 3.3", 120.0, ["ir"]),
    ("riser_harmonic", "Seed 000 riser (300 m), regular wave H 6 m, T 10 s", 300.0, ["ei", "ir"]),
    ("riser_jonswap", "Seed 000 riser (300 m), JONSWAP Hs 6 m, Tp 10 s, γ 3.3", 300.0, ["ei", "ir"]),
]
NAMES = {"ei": "EI v''", "ir": "inertia relief"}


def run(fowtsim, stem, runs):
    base = os.path.join(runs, stem)
    result = subprocess.run([fowtsim, "run", os.path.join(HERE, stem + ".yaml"), "-o", base],
                            stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    if result.returncode != 0:
        sys.stderr.write(f"plot_profiles.py: {stem}: {result.stderr}")
        sys.exit(2)
    statistic = "amplitude" if stem.endswith("harmonic") else "rms"
    return statistic, np.genfromtxt(f"{base}.{statistic}.csv", delimiter=",", names=True)


def plot(stem, title, swl, stresses, statistic, p, out):
    z = p["x_m"] - swl
    word = "amplitude" if statistic == "amplitude" else "RMS"
    fig, (left, right) = plt.subplots(1, 2, figsize=(9, 5.5), sharey=True)
    left.plot(p["fd_displacement_m"], z, "-", label="frequency domain")
    left.plot(p["td_displacement_m"], z, "--", label="time domain")
    left.set_xlabel(f"{word} displacement [m]")
    left.set_ylabel("elevation above still water [m]")
    for kind in stresses:
        right.plot(p[f"fd_stress_{kind}_Pa"] / 1e6, z, "-", label=f"FD, {NAMES[kind]}")
        right.plot(p[f"td_stress_{kind}_Pa"] / 1e6, z, "--", label=f"TD, {NAMES[kind]}")
    right.set_xlabel(f"{word} bending stress [MPa]")
    for ax in (left, right):
        ax.axhline(0.0, color="0.7", lw=0.8)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
    fig.suptitle(title)
    fig.tight_layout()
    path = os.path.join(out, stem + ".png")
    fig.savefig(path, dpi=100)
    plt.close(fig)
    print(path)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("fowtsim")
    parser.add_argument("--out", default=os.path.join(HERE, "figures"))
    parser.add_argument("--runs", help="where the runs' files go (default: a temporary folder)")
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)
    with tempfile.TemporaryDirectory() as tmp:
        runs = args.runs or tmp
        for stem, title, swl, stresses in CASES:
            statistic, profiles = run(args.fowtsim, stem, runs)
            plot(stem, title, swl, stresses, statistic, profiles, args.out)


if __name__ == "__main__":
    main()

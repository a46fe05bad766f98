#!/usr/bin/python3
"""Runs the two shipped JONSWAP decks and draws the response spectra at their stations, frequency
domain (drag linearised, <output>.spectra.csv) against time domain (nonlinear Morison drag, the
station channels of <output>.h5 after the transient, Welch's averaged periodogram): displacement and
inertia-relief moment, as the seed 004 figures set FD beside TD.

  /usr/bin/python3 inputs/slender/plot_spectra.py FOWTSIM [--out DIR] [--runs DIR]

FOWTSIM: the fowtsim binary (e.g. build/driver/fowtsim). PNGs go to DIR (default: figures/ beside
this script, where the README links them). Exit codes: 0 written, 2 a run failed, 3 a module missing.
"""
import argparse
import os
import subprocess
import sys
import tempfile

try:
    import h5py
    import numpy as np
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError as e:
    sys.stderr.write(f"plot_spectra.py: {e}; use Debian's /usr/bin/python3 with python3-h5py and python3-matplotlib\n")
    sys.exit(3)

HERE = os.path.dirname(os.path.realpath(__file__))
# deck stem, title, the stations' labels (the decks' analysis.stations_m), transient [s] (analysis.transient_s)
CASES = [
    ("oc3_tower_jonswap", "OC3 rigid floating tower, JONSWAP Hs 6 m, Tp 10 s",
     ["z −12 m (taper)", "SWL", "tower base +10 m", "tower top"], 600.0),
    ("riser_jonswap", "Seed 000 riser (300 m), JONSWAP Hs 6 m, Tp 10 s",
     ["x 150 m", "x 250 m", "x 280 m", "x 295 m"], 600.0),
]
SEGMENT_S = 200.0  # Welch segments: Δω = 2π/200 ≈ 0.03 rad/s, 11 half-overlapping segments in 1200 s


def run(fowtsim, stem, runs):
    base = os.path.join(runs, stem)
    result = subprocess.run([fowtsim, "run", os.path.join(HERE, stem + ".yaml"), "-o", base + ".h5"],
                            stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    if result.returncode != 0:
        sys.stderr.write(f"plot_spectra.py: {stem}: {result.stderr}")
        sys.exit(2)
    return base


def welch(x, dt):
    """One-sided spectrum in ω [unit²·s/rad] by Welch's method (Hann window, 50 % overlap)."""
    n = int(round(SEGMENT_S / dt))
    window = np.hanning(n)
    scale = 1.0 / (np.sum(window ** 2) / dt)  # density per Hz of one segment
    segments = [x[i:i + n] - np.mean(x[i:i + n]) for i in range(0, len(x) - n + 1, n // 2)]
    power = np.mean([np.abs(np.fft.rfft(s * window)) ** 2 for s in segments], axis=0) * scale
    power[1:-1] *= 2.0  # one-sided
    f = np.fft.rfftfreq(n, dt)
    return 2 * np.pi * f, power / (2 * np.pi)


def plot(stem, title, labels, transient, base, out):
    fd = np.genfromtxt(base + ".spectra.csv", delimiter=",", names=True)
    with h5py.File(base + ".h5", "r") as f:
        t = f["Time"][:]
        keep = t >= transient - 1e-9
        dt = t[1] - t[0]
        td = {name: f[name][:][keep] for name in f.keys() if name.startswith("Stn")}
    fig, axes = plt.subplots(2, len(labels), figsize=(3.2 * len(labels), 6.5), sharex=True)
    for k, label in enumerate(labels):
        for row, (channel, unit) in enumerate([("Disp", "m²·s/rad"), ("MomIR", "(kN·m)²·s/rad")]):
            ax = axes[row][k]
            name = f"Stn{k + 1}{channel}"
            ax.semilogy(fd["omega_rad_s"], fd[name], "-", label="frequency domain")
            w, s = welch(td[name], dt)
            ax.semilogy(w, s, "--", label="time domain (Welch)")
            peak = max(fd[name].max(), s.max())
            ax.set_ylim(peak * 1e-4, peak * 3)
            ax.set_xlim(0.2, 2.0)
            ax.grid(alpha=0.3, which="both")
            if row == 0:
                ax.set_title(label, fontsize=9)
            if k == 0:
                ax.set_ylabel(("displacement" if channel == "Disp" else "moment (inertia relief)") + f"\n[{unit}]", fontsize=8)
            if row == 1:
                ax.set_xlabel("ω [rad/s]")
    axes[0][0].legend(fontsize=7)
    fig.suptitle(title + ": response spectra at the stations")
    fig.tight_layout()
    path = os.path.join(out, stem + "_spectra.png")
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
    with tempfile.TemporaryDirectory() as scratch:
        runs = args.runs or scratch
        os.makedirs(runs, exist_ok=True)
        for stem, title, labels, transient in CASES:
            plot(stem, title, labels, transient, run(args.fowtsim, stem, runs), args.out)
    return 0


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/env python3
"""Seed 000 Table 4.3, the POM ratios and the spectral peaks of §4.6.4 beside our six cases.

Reads OUTDIR/dels_table43.csv, OUTDIR/dels_plain.csv and OUTDIR/modes.h5 written by
run_seed_cases.sh, prints Markdown tables (ours, the seed's, ours/seed) and checks the seed's
findings that we reproduce (README.md says which we do not, and why); exits 1 if one fails.
Uses Debian's python3-numpy and python3-h5py."""
import csv
import sys
from pathlib import Path

import h5py
import numpy as np

CASES = ["120m_fixed", "120m_typical", "120m_extreme", "74m_fixed", "74m_typical", "74m_extreme"]
TITLES = ["120-m Fixed", "120-m Typical", "120-m Extreme", "74-m Fixed", "74-m Typical", "74-m Extreme"]
# Table 4.3 of the seed [N·m, N, N, N·m]; our channels are in kN and kN·m (factor 1e3).
SEED = {
    "RootMxyb1": ("Bending moment (N·m)", [2.208e6, 3.242e6, 4.757e6, 3.200e6, 3.562e6, 4.759e6]),
    "RootFxyb1": ("Shear force (N)", [7.576e4, 9.207e4, 1.733e5, 9.708e4, 1.029e5, 1.679e5]),
    "RootFzb1": ("Axial force (N)", [2.201e5, 2.369e5, 2.682e5, 2.021e5, 1.987e5, 2.560e5]),
    "RotTorq": ("Shaft torque (N·m)", [1.762e5, 3.646e5, 8.679e5, 1.552e5, 1.998e5, 9.955e5]),
}
SEED_POM = {"120m_typical": [92.8, 6.1, 0.6], "74m_typical": [94.5, 4.8, 0.3]}


def case_of(path):
    return Path(path).stem.replace("table42_", "")


def read_dels(path, scale):
    dels = {}
    with open(path) as f:
        for row in csv.DictReader(f):
            if row["damage_equivalent_load"]:  # channels without a fatigue entry have none
                dels[(case_of(row["file"]), row["channel"])] = scale * float(row["damage_equivalent_load"])
    return dels


def print_table(title, dels):
    print(f"| {title} | " + " | ".join(TITLES) + " |")
    print("|---|" + "---|" * len(CASES))
    for channel, (name, seed) in SEED.items():
        cells = [f"{dels[(c, channel)]:.3g} ({dels[(c, channel)] / s:.2f})" for c, s in zip(CASES, seed)]
        print(f"| {name} | " + " | ".join(cells) + " |")
    print()


def peaks(freq, density, low, high, count):
    """Frequencies of the `count` highest local maxima of a spectrum inside [low, high] Hz."""
    inner = [k for k in range(1, len(density) - 1)
             if low <= freq[k] <= high and density[k] > density[k - 1] and density[k] >= density[k + 1]]
    return sorted(freq[k] for k in sorted(inner, key=lambda k: -density[k])[:count])


def main(out):
    # One-sided amplitude (half the MLife range), Goodman factor 1 (ranges about each case's own mean).
    amplitude = read_dels(out / "dels_plain.csv", 1e3 / 2.0)
    goodman = read_dels(out / "dels_table43.csv", 1e3)  # MLife range, Goodman to a zero mean
    print("| seed | " + " | ".join(TITLES) + " |")
    print("|---|" + "---|" * len(CASES))
    for channel, (name, seed) in SEED.items():
        print(f"| {name} | " + " | ".join(f"{s:.4g}" for s in seed) + " |")
    print()
    print_table("ours: one-sided amplitude, no Goodman (ours/seed)", amplitude)
    print_table("ours: MLife range, Goodman to zero mean (ours/seed)", goodman)

    print("| typical case | POM ratios, ours [%] | seed [%] | POM 1 PSD peaks [Hz] | POM 2 peak 0.8–1.3 Hz | PtfmPitch peaks < 0.06 Hz, 0.5–0.7 Hz | RootMyb1 peaks 0.1–0.7 Hz |")
    print("|---|---|---|---|---|---|---|")
    pom = {}
    with h5py.File(out / "modes.h5", "r") as f:
        spectra = {(case_of(g.attrs["file"]), g.attrs["channel"]): (np.array(g["frequency_hz"]), np.array(g["density"]))
                   for g in f["psd"].values()}
        for g in f["pom"].values():
            case = case_of(g.attrs["file"])
            ratio = 100.0 * np.array(g["singular_value_ratios"])
            freq = np.array(g["mode_psd_frequency_hz"])
            density = np.array(g["mode_psd_density"])
            pom[case] = ratio
            pitch = spectra[(case, "PtfmPitch")]
            flap = spectra[(case, "RootMyb1")]
            print(f"| {case} | {ratio[0]:.1f} / {ratio[1]:.1f} / {ratio[2]:.1f} | "
                  + " / ".join(f"{v}" for v in SEED_POM[case]) + " | "
                  + ", ".join(f"{v:.2f}" for v in peaks(freq, density[0], 0.01, 2.0, 4)) + " | "
                  + ", ".join(f"{v:.2f}" for v in peaks(freq, density[1], 0.8, 1.3, 1)) + " | "
                  + ", ".join(f"{v:.2f}" for v in peaks(*pitch, 0.005, 0.06, 1) + peaks(*pitch, 0.5, 0.7, 1)) + " | "
                  + ", ".join(f"{v:.2f}" for v in peaks(*flap, 0.1, 0.7, 3)) + " |")

    def a(case, channel):
        return amplitude[(case, channel)]
    loads = list(SEED)
    # The seed's findings (§4.6.4–4.6.5) that hold in ours, with the seed's own numbers in comments:
    checks = [
        # the first POM carries most of a blade's deflection, the first three nearly all (seed 92.8 /
        # 94.5 % and 99.5 / 99.6 %; ours 91.1 / 92.0 % and 99.0 / 99.1 % on the shipped decks)
        ("first POM > 85 %, first three > 97 % (both typical cases)",
         all(r[0] > 85.0 and r[:3].sum() > 97.0 for r in pom.values())),
        # every load's DEL is larger in the extreme condition than in the typical one (seed: all 8 pairs)
        ("extreme > typical for all four loads, both spars",
         all(a(f"{s}_extreme", c) > a(f"{s}_typical", c) for s in ("120m", "74m") for c in loads)),
        # "fatigue damage ... for the original 120-m spar and the compliant 74-m spar is found to be
        # similar for the extreme operational condition" (seed: within 15 %, shaft torque the most)
        ("extreme: 74-m within 15 % of 120-m for all four loads",
         all(abs(a("74m_extreme", c) / a("120m_extreme", c) - 1.0) < 0.15 for c in loads)),
        # "the DEL's for the 74-m floating spar that barely oscillates are similar to those for the
        # fixed case" (seed: −2 … +29 %)
        ("74-m typical within 30 % of 74-m fixed for all four loads",
         all(abs(a("74m_typical", c) / a("74m_fixed", c) - 1.0) < 0.30 for c in loads)),
    ]
    failed = 0
    for name, ok in checks:
        print(f"{'PASS' if ok else 'FAIL'}  {name}")
        failed += not ok
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(Path(sys.argv[1])))

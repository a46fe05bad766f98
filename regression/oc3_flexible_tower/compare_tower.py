"""The OC3 load case with the flexible tower against OpenFAST v5's `…_600s.out` (issue 24).

Usage: compare_tower.py REFERENCE.out RIGID_TOWER.out FLEXIBLE_TOWER.out

Both of ours carry rigid blades (ElastoDyn's are flexible: not yet like-for-like in the blades),
WAMIT potential flow, unsteady airfoils and the tower's aerodynamics, as OpenFAST's deck. Prints
means and standard deviations over 100–600 s for the rigid and the flexible tower, the tower peak
of the spectra, and checks what the tower itself decides, each bound with its reason.
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "oc3_potential_flow"))
from compare import read_out  # noqa: E402  (the one .out reader of the regression scripts)

WINDOW = (100.0, 600.0)


def channels(path):
    names, rows = read_out(path)
    return {name: rows[:, i] for i, name in enumerate(names)}


def window(table, name):
    t = table["Time"]
    mask = (t >= WINDOW[0]) & (t <= WINDOW[1])
    return t[mask], table[name][mask]


def tower_peak(t, x, low=0.40, high=0.56):
    """Where the tower's first-mode peak lies: the centroid ∫f S df / ∫S df of the PSD over
    [low, high] Hz (Welch, 100-s Hann segments, half overlap). In operation the fore-aft peak is
    broad and flat-topped (aerodynamic damping; OpenFAST's is level within 3 % over 0.50–0.52 Hz),
    so its highest bin is a poor locator; the band stops below 3P (0.605 Hz at 12.1 rpm)."""
    dt = t[1] - t[0]
    n = int(round(100.0 / dt))
    x = x - x.mean()
    psd = 0.0
    for start in range(0, len(x) - n + 1, n // 2):
        psd = psd + np.abs(np.fft.rfft(x[start:start + n] * np.hanning(n))) ** 2
    f = np.fft.rfftfreq(n, dt)
    band = (f >= low) & (f <= high)
    return float(np.sum(f[band] * psd[band]) / np.sum(psd[band]))


def main():
    ref, rigid, flexible = (channels(p) for p in sys.argv[1:4])
    print(f"OC3 load case {WINDOW[0]:.0f}–{WINDOW[1]:.0f} s: OpenFAST v5 (ElastoDyn) vs ours, rigid blades")
    print(f"{'channel':<11}{'unit':>6} {'OF mean':>10} {'rigid':>10} {'flexible':>10} {'Δ%':>6} | "
          f"{'OF std':>9} {'rigid':>9} {'flexible':>9} {'Δ%':>6}")
    stats = {}
    for name, unit in [("PtfmSurge", "m"), ("PtfmPitch", "deg"), ("PtfmRoll", "deg"), ("RotSpeed", "rpm"),
                       ("TwrBsFxt", "kN"), ("TwrBsMxt", "kN-m"), ("TwrBsMyt", "kN-m"), ("YawBrFxp", "kN"),
                       ("YawBrMyp", "kN-m"), ("TTDspFA", "m"), ("TTDspSS", "m"), ("TwHt1MLxt", "kN-m"),
                       ("TwHt1MLyt", "kN-m"), ("TwrClrnc1", "m")]:
        row = []
        for table in (ref, rigid, flexible):
            if name in table:
                _, x = window(table, name)
                row.append((x.mean(), x.std()))
            else:
                row.append((float("nan"), float("nan")))
        stats[name] = row
        (rm, rs), (am, as_), (fm, fs) = row
        print(f"{name:<11}{unit:>6} {rm:10.4g} {am:10.4g} {fm:10.4g} {100 * (fm / rm - 1):+6.1f} | "
              f"{rs:9.4g} {as_:9.4g} {fs:9.4g} {100 * (fs / rs - 1):+6.1f}")
    peaks = {}
    for name in ("TwrBsMxt", "TwrBsMyt", "TTDspFA", "TTDspSS"):
        of = tower_peak(*window(ref, name))
        ours = tower_peak(*window(flexible, name))
        peaks[name] = (of, ours)
        print(f"tower peak {name:<9} OpenFAST {of:.4f} Hz, ours {ours:.4f} Hz ({100 * (ours / of - 1):+.2f} %)")

    failures = []

    def check(ok, text):
        print(("PASS " if ok else "FAIL ") + text)
        if not ok:
            failures.append(text)

    # The tower's first modes on the floating platform. Side-to-side: the 2 % (measured
    # +0.64 % TwrBsMxt, +0.53 % TTDspSS). Fore-aft: 5 %, measured −1.98 % (TwrBsMyt) and −2.09 %
    # (TTDspFA) — our blades are rigid, ElastoDyn's flap (first collective flap ≈ 0.7 Hz) couples
    # with the fore-aft mode; the 2 % applies once the blades are like-for-like.
    for name, (of, ours) in peaks.items():
        bound = 0.02 if name in ("TwrBsMxt", "TTDspSS") else 0.05
        check(abs(ours / of - 1.0) < bound, f"{name} tower peak within {100 * bound:.0f} % of OpenFAST's")
    # Means the tower's elastic model decides, within the 2 % (measured +0.4, +0.1, +0.4,
    # +0.8, +0.9 %).
    for name in ("PtfmSurge", "PtfmPitch", "TwrBsMyt", "TTDspFA", "TwHt1MLyt"):
        of, ours = stats[name][0][0], stats[name][2][0]
        check(abs(ours / of - 1.0) < 0.02, f"{name} mean within 2 % of OpenFAST's")
    # The side-to-side tower-base moment the rigid tower missed (issue 24: std 0.59× OpenFAST's):
    # the flexible tower must close at least half of that gap (measured 0.58× → 0.80×).
    of, rigid_std, flexible_std = (stats["TwrBsMxt"][k][1] for k in range(3))
    check(abs(flexible_std / of - 1.0) < 0.5 * abs(rigid_std / of - 1.0),
          f"TwrBsMxt std {flexible_std / of:.2f}× OpenFAST's (rigid tower {rigid_std / of:.2f}×): gap at least halved")
    if failures:
        print(f"FAIL: {len(failures)} check(s)")
        sys.exit(1)
    print("all checks pass")


if __name__ == "__main__":
    main()

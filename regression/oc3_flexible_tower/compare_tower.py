"""The OC3 load case with the flexible tower and Rayleigh–Ritz blades against OpenFAST v5's `…_600s.out`
(issue 24).

Usage: compare_tower.py REFERENCE.out RIGID_TOWER.out FLEXIBLE_TOWER.out RR_RIGID_TOWER.out RR_FLEXIBLE_TOWER.out
       [MBBT_FLEXIBLE_TOWER.out]

The first two carry rigid blades, the last two Rayleigh–Ritz blades (ElastoDyn's: the same
structural model as OpenFAST's deck, so the last case is like-for-like in structure); all with WAMIT
potential flow, unsteady airfoils and the tower's aerodynamics, as OpenFAST's deck; the optional sixth
carries the MBBT blades on the flexible tower (issue 24's interface mass). Prints means and
standard deviations over 100–600 s, the tower peak of the spectra, and checks what the structure
decides, each bound with its reason.
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "oc3_potential_flow"))
from compare import Checks, read_out  # noqa: E402  (the regression scripts' one .out reader and PASS/FAIL lines)

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


CASES = ("rigid/rigid", "rigid/flex", "RR/rigid", "RR/flex")  # blades/tower
CHANNELS = [("PtfmSurge", "m"), ("PtfmPitch", "deg"), ("PtfmRoll", "deg"), ("RotSpeed", "rpm"), ("GenPwr", "kW"),
            ("TwrBsFxt", "kN"), ("TwrBsMxt", "kN-m"), ("TwrBsMyt", "kN-m"), ("YawBrFxp", "kN"), ("YawBrMyp", "kN-m"),
            ("TTDspFA", "m"), ("TTDspSS", "m"), ("TwHt1MLxt", "kN-m"), ("TwHt1MLyt", "kN-m"), ("TwrClrnc1", "m"),
            ("OoPDefl1", "m"), ("IPDefl1", "m"), ("RootMxc1", "kN-m"), ("RootMyc1", "kN-m"), ("RootFzc1", "kN")]


def main():
    ref, *ours = (channels(p) for p in sys.argv[1:6])
    mbbt = channels(sys.argv[6]) if len(sys.argv) > 6 else None
    print(f"OC3 load case {WINDOW[0]:.0f}–{WINDOW[1]:.0f} s: OpenFAST v5 (ElastoDyn) vs ours, blades/tower; "
          "Δ% of RR/flex (like-for-like)")
    print(f"{'channel':<10}{'unit':>5} {'OF mean':>9}" + "".join(f"{c:>11}" for c in CASES) + f"{'Δ%':>6} | "
          f"{'OF std':>8}" + "".join(f"{c:>11}" for c in CASES) + f"{'Δ%':>6}")
    stats = {}
    for name, unit in CHANNELS:
        row = []
        for table in (ref, *ours):
            if name in table:
                _, x = window(table, name)
                row.append((x.mean(), x.std()))
            else:
                row.append((float("nan"), float("nan")))
        stats[name] = row
        means = "".join(f"{m:11.4g}" for m, _ in row[1:])
        stds = "".join(f"{s:11.4g}" for _, s in row[1:])
        print(f"{name:<10}{unit:>5} {row[0][0]:9.4g}{means}{100 * (row[4][0] / row[0][0] - 1):+6.1f} | "
              f"{row[0][1]:8.4g}{stds}{100 * (row[4][1] / row[0][1] - 1):+6.1f}")
    peaks = {}
    for name in ("TwrBsMxt", "TwrBsMyt", "TTDspFA", "TTDspSS"):
        of = tower_peak(*window(ref, name))
        rigid_blades = tower_peak(*window(ours[1], name))
        rr = tower_peak(*window(ours[3], name))
        peaks[name] = (of, rigid_blades, rr)
        print(f"tower peak {name:<9} OpenFAST {of:.4f} Hz; rigid blades {rigid_blades:.4f} Hz ({100 * (rigid_blades / of - 1):+.2f} %), "
              f"RR blades {rr:.4f} Hz ({100 * (rr / of - 1):+.2f} %)")

    check = Checks()

    # The tower's first modes on the floating platform. Like-for-like (RR blades on the flexible
    # tower): the 2 % for all four (measured +0.76, +0.04, +0.02, +0.73 %). Rigid blades on
    # the flexible tower: side-to-side 2 % (measured +0.64, +0.53 %); fore-aft 5 %, measured −1.98 %
    # (TwrBsMyt) and −2.09 % (TTDspFA): ElastoDyn's flap mode (≈ 0.7 Hz) couples with the fore-aft
    # mode, which the RR blades bring back.
    for name, (of, rigid_blades, rr) in peaks.items():
        check(abs(rr / of - 1.0) < 0.02, f"{name} tower peak, RR blades, within 2 % of OpenFAST's")
        bound = 0.02 if name in ("TwrBsMxt", "TTDspSS") else 0.05
        check(abs(rigid_blades / of - 1.0) < bound, f"{name} tower peak, rigid blades, within {100 * bound:.0f} % of OpenFAST's")
    # Means the structure decides, within the 2 %. Rigid blades on the flexible tower
    # (measured +0.4, +0.1, +0.4, +0.8, +0.9 %); RR blades on it (measured +1.3, +0.8, +0.7, +0.6,
    # +0.9, +0.4, +1.9, +1.0 %).
    for name in ("PtfmSurge", "PtfmPitch", "TwrBsMyt", "TTDspFA", "TwHt1MLyt"):
        of, ours_mean = stats[name][0][0], stats[name][2][0]
        check(abs(ours_mean / of - 1.0) < 0.02, f"{name} mean, rigid blades, within 2 % of OpenFAST's")
    for name in ("PtfmSurge", "PtfmPitch", "TwrBsMyt", "TTDspFA", "TwHt1MLyt", "RootMyc1", "RootMxc1", "RootFzc1"):
        of, ours_mean = stats[name][0][0], stats[name][4][0]
        check(abs(ours_mean / of - 1.0) < 0.02, f"{name} mean, RR blades, within 2 % of OpenFAST's")
    # The blades' in-plane motion is gravity and the edge mode: ElastoDyn's own shape and stiffness,
    # so its standard deviation agrees closely (measured −0.0 %, IPDefl1; RootMxc1 +0.6 %): 2 %.
    for name in ("IPDefl1", "RootMxc1"):
        of, rr = stats[name][0][1], stats[name][4][1]
        check(abs(rr / of - 1.0) < 0.02, f"{name} std, RR blades, within 2 % of OpenFAST's")
    # The side-to-side tower-base moment the rigid tower missed (issue 24: std 0.59× OpenFAST's):
    # the flexible tower must close at least half of that gap (measured 0.58× → 0.80×).
    of, rigid_std, flexible_std = (stats["TwrBsMxt"][k][1] for k in range(3))
    check(abs(flexible_std / of - 1.0) < 0.5 * abs(rigid_std / of - 1.0),
          f"TwrBsMxt std {flexible_std / of:.2f}× OpenFAST's (rigid tower {rigid_std / of:.2f}×): gap at least halved")
    if mbbt is not None:
        check_mbbt(ref, mbbt, check)
    check.finish()


def check_mbbt(ref, mbbt, check):
    """MBBT blades on the flexible tower against OpenFAST (ElastoDyn blades: not the same blade model).
    The tower's peaks are the flexible tower's with the blades' inertia on it: 2 % (measured +0.62,
    +0.11, +0.11, +0.60 %). Means and spreads the platform, the tower base and the rotor speed decide:
    2 % and 5 % (measured means −0.0, −0.2, +0.2, −0.1, −0.2 %; std +0.5, +2.9, +3.9, +3.6 %). Not
    checked, with the reason (the same on the rigid tower with MBBT blades, so the blades' model and
    coupling, not the tower): PtfmPitch std +13.6 % (rigid tower +12.3 %), RootMyc1 std +12 %,
    OoPDefl1 std +18 % (BeamDyn-like blades against ElastoDyn's); TwrBsMxt std −11 % (rigid tower −44 %)."""
    print("MBBT blades, flexible tower: channel, OpenFAST mean/std, ours (Δ%)")
    for name, _ in CHANNELS:
        if name not in mbbt or name not in ref:
            continue
        (_, y), (_, x) = window(ref, name), window(mbbt, name)
        print(f"  {name:<10} {y.mean():11.4g} {y.std():10.4g} | {x.mean():11.4g} ({100 * (x.mean() / y.mean() - 1):+5.1f}) "
              f"{x.std():10.4g} ({100 * (x.std() / y.std() - 1):+5.1f})")
    for name in ("TwrBsMxt", "TwrBsMyt", "TTDspFA", "TTDspSS"):
        of, ours = tower_peak(*window(ref, name)), tower_peak(*window(mbbt, name))
        check(abs(ours / of - 1.0) < 0.02, f"{name} tower peak, MBBT blades, {100 * (ours / of - 1):+.2f} % (within 2 %)")
    for name in ("PtfmSurge", "PtfmPitch", "RotSpeed", "TwrBsMyt", "TTDspFA"):
        of, ours = window(ref, name)[1].mean(), window(mbbt, name)[1].mean()
        check(abs(ours / of - 1.0) < 0.02, f"{name} mean, MBBT blades, {100 * (ours / of - 1):+.2f} % (within 2 %)")
    for name in ("PtfmSurge", "RotSpeed", "TwrBsMyt", "TTDspFA"):
        of, ours = window(ref, name)[1].std(), window(mbbt, name)[1].std()
        check(abs(ours / of - 1.0) < 0.05, f"{name} std, MBBT blades, {100 * (ours / of - 1):+.2f} % (within 5 %)")


if __name__ == "__main__":
    main()

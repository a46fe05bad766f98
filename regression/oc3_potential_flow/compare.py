#!/usr/bin/env python3
"""The OC3 load case against OpenFAST v5 (run_oc3_cases.sh): statistics, correlations and RAOs of
each run against OpenFAST's `…_600s.out` over 100–600 s, printed as Markdown tables, then the checks
(each with its bound and why). Usage: compare.py REFERENCE.out OUTDIR. Exit 1 on a failed check."""
import sys

import numpy as np

CASES = [("morison", "Morison, quasi-steady (before)"), ("wamit", "WAMIT"), ("wamit_ua", "WAMIT + UA"),
         ("wamit_ua_dbemt", "WAMIT + UA + DBEMT"), ("wamit_ua_tower", "WAMIT + UA + tower (TwrPotent, TwrAero)")]
CHANNELS = [  # (OpenFAST name, ours, unit)
    ("RotSpeed", "RotSpeed", "rpm"), ("BldPitch1", "BldPitch1", "deg"), ("GenPwr", "GenPwr", "kW"),
    ("PtfmSurge", "PtfmSurge", "m"), ("PtfmHeave", "PtfmHeave", "m"), ("PtfmPitch", "PtfmPitch", "deg"),
    ("PtfmYaw", "PtfmYaw", "deg"), ("RootMyc1", "RootMyc1", "kN·m"), ("RootMxc1", "RootMxc1", "kN·m"),
    ("OoPDefl1", "OoPDefl1", "m"), ("IPDefl1", "IPDefl1", "m"), ("TwrBsMyt", "TwrBsMyt", "kN·m"),
    ("RotThrust", "RotThrust", "kN"), ("HydroFxi", "HydroFxi", "N"), ("B1RdtFxi", "B1RdtFxi", "N")]
BANDS = [(0.08, 0.10), (0.10, 0.12), (0.12, 0.15), (0.15, 0.20)]  # Hz: where the sea's energy is (Tp 10 s)
T0 = 100.0


class Checks:
    """PASS/FAIL lines of a regression script; finish() exits 1 if any failed."""

    def __init__(self):
        self.failures = []

    def __call__(self, ok, what):
        print(("PASS  " if ok else "FAIL  ") + what)
        if not ok:
            self.failures.append(what)

    def finish(self):
        if self.failures:
            print(f"{len(self.failures)} check(s) failed")
            sys.exit(1)
        print("all checks passed")


def read_out(path):
    lines = open(path).read().splitlines()
    start = next(i for i, l in enumerate(lines) if l.split()[:1] == ["Time"])
    names = lines[start].split()
    rows = []
    for line in lines[start + 2:]:
        try:
            rows.append([float(x) for x in line.split()])
        except ValueError:
            pass
    return names, np.array(rows)


def transfer(eta, x, fs, segments=10):
    """Cross-spectral H = S_ηx / S_ηη (Hann windows, `segments` non-overlapping segments): the part
    of the motion the waves drive; the wind-driven part averages out of S_ηx."""
    n = len(eta) // segments
    w = np.hanning(n)
    sxy = sxx = 0.0
    for k in range(segments):
        a = np.fft.rfft(w * (eta[k * n:(k + 1) * n] - eta[k * n:(k + 1) * n].mean()))
        b = np.fft.rfft(w * (x[k * n:(k + 1) * n] - x[k * n:(k + 1) * n].mean()))
        sxy = sxy + np.conj(a) * b
        sxx = sxx + np.abs(a) ** 2
    return np.fft.rfftfreq(n, 1.0 / fs), sxy / sxx


def main():
    reference, outdir = sys.argv[1], sys.argv[2]
    rn, rd = read_out(reference)
    t = rd[:, 0]
    window = t >= T0
    runs = {case: read_out(f"{outdir}/{case}.out") for case, _ in CASES}

    def ours(case, name):
        n, d = runs[case]
        return np.interp(t[window], d[:, 0], d[:, n.index(name)])

    print(f"\n| channel | OpenFAST mean ± std | " + " | ".join(f"{label}: mean ± std (corr.)" for _, label in CASES) + " |")
    print("|---|---|" + "---|" * len(CASES))
    stats = {}
    for ref_name, our_name, unit in CHANNELS:
        x = rd[window, rn.index(ref_name)]
        cells = []
        for case, _ in CASES:
            if our_name not in runs[case][0]:  # e.g. the radiation load without potential flow
                cells.append("—")
                continue
            y = ours(case, our_name)
            stats[case, ref_name] = (y.mean(), y.std(), np.corrcoef(x, y)[0, 1], x.mean(), x.std())
            cells.append(f"{y.mean():.4g} ± {y.std():.3g} ({stats[case, ref_name][2]:.3f})")
        print(f"| {ref_name} [{unit}] | {x.mean():.4g} ± {x.std():.3g} | " + " | ".join(cells) + " |")

    eta = rd[window, rn.index("Wave1Elev")]
    fs = 1.0 / (t[1] - t[0])
    rao = {}
    print(f"\n| RAO \\|S_ηx/S_ηη\\|, band | OpenFAST | " + " | ".join(label for _, label in CASES) + " |")
    print("|---|---|" + "---|" * len(CASES))
    for ref_name, unit in [("PtfmHeave", "m/m"), ("PtfmPitch", "deg/m"), ("PtfmSurge", "m/m")]:
        f, h_ref = transfer(eta, rd[window, rn.index(ref_name)], fs)
        h = {case: transfer(eta, ours(case, ref_name), fs)[1] for case, _ in CASES}
        for lo, hi in BANDS:
            band = (f >= lo) & (f < hi)
            r = np.mean(np.abs(h_ref[band]))
            rao[ref_name, lo] = (r, {case: np.mean(np.abs(h[case][band])) for case, _ in CASES})
            print(f"| {ref_name} [{unit}], {lo:.2f}–{hi:.2f} Hz | {r:.4g} | "
                  + " | ".join(f"{rao[ref_name, lo][1][case]:.4g} ({100 * (rao[ref_name, lo][1][case] / r - 1):+.1f} %)"
                               for case, _ in CASES) + " |")

    check = Checks()
    print()
    # Heave RAO: potential flow reproduces OpenFAST's (measured within 0.4–2.2 % per band); Morison
    # with Ca = 1 is 13–19 % high. Band means of 10-segment cross-spectral estimates scatter by a few
    # per cent (coherence 0.9), so 6 %: tight enough to tell the models apart.
    for lo, _ in BANDS:
        r, ours_rao = rao["PtfmHeave", lo]
        for case in ("wamit", "wamit_ua"):
            check(abs(ours_rao[case] / r - 1) < 0.06, f"{case}: heave RAO {lo:.2f} Hz within 6 % of OpenFAST's")
        check(abs(ours_rao["wamit"] / r - 1) < abs(ours_rao["morison"] / r - 1),
              f"heave RAO {lo:.2f} Hz: WAMIT closer to OpenFAST than Morison")
    # Pitch and surge RAOs: measured +1–9 % with either hydro model (the rigid tower and the
    # platform's own rotary inertia, not the hydrodynamics): 15 %.
    for name in ("PtfmPitch", "PtfmSurge"):
        for lo, _ in BANDS:
            r, ours_rao = rao[name, lo]
            check(abs(ours_rao["wamit"] / r - 1) < 0.15, f"wamit: {name} RAO {lo:.2f} Hz within 15 % of OpenFAST's")
    # Means within 5 % (issue 12's bound for the coupled case) and the histories follow OpenFAST's
    # (same wind and sea): correlations measured 0.96–0.99 for these channels, bound 0.9.
    for case in ("wamit", "wamit_ua"):
        for name in ("RotSpeed", "GenPwr", "PtfmSurge", "PtfmPitch", "RootMyc1", "OoPDefl1", "TwrBsMyt"):
            mean, _, _, ref_mean, _ = stats[case, name]
            check(abs(mean / ref_mean - 1) < 0.05, f"{case}: {name} mean within 5 % ({mean:.4g} vs {ref_mean:.4g})")
        for name in ("RotSpeed", "BldPitch1", "PtfmSurge", "PtfmHeave", "PtfmPitch", "PtfmYaw", "TwrBsMyt"):
            check(stats[case, name][2] > 0.9, f"{case}: {name} correlation {stats[case, name][2]:.3f} > 0.9")
    # What potential flow moves: heave and yaw follow OpenFAST's more closely (measured heave
    # 0.944 → 0.975, yaw 0.929 → 0.976).
    for name in ("PtfmHeave", "PtfmYaw"):
        check(stats["wamit", name][2] > stats["morison", name][2], f"{name}: WAMIT correlates better than Morison")
    # The tower as OpenFAST's deck has it (potential flow and drag, TwrPotent 1, TwrAero): the mean
    # offsets that stayed with every hydro model close (measured surge +0.6 %, pitch −1.0 %,
    # TwrBsMyt −2.0 %, from −3.7, −4.5, −4.8 % without; issue 23's goal 2 % for surge and pitch; the
    # tower-base moment keeps a part the flexible tower explains, README), and the channels whose
    # definitions changed carry what OpenFAST's carry: RotThrust the hub's weight (−1.4 %; −13 %
    # without it), B1RdtFxi and HydroFxi the added-mass reaction (std +1.0 % and −5.1 %; without it
    # B1RdtFxi's std was a tenth of OpenFAST's).
    tower = "wamit_ua_tower"
    for name, bound in (("PtfmSurge", 0.02), ("PtfmPitch", 0.02), ("TwrBsMyt", 0.03), ("RotThrust", 0.03)):
        mean, _, _, ref_mean, _ = stats[tower, name]
        check(abs(mean / ref_mean - 1) < bound, f"{tower}: {name} mean within {bound:.0%} ({mean:.4g} vs {ref_mean:.4g})")
        check(abs(mean / ref_mean - 1) < abs(stats["wamit_ua", name][0] / ref_mean - 1),
              f"{tower}: {name} mean closer to OpenFAST's than without the tower")
    for name, bound in (("B1RdtFxi", 0.05), ("HydroFxi", 0.10)):
        _, std, _, _, ref_std = stats[tower, name]
        check(abs(std / ref_std - 1) < bound, f"{tower}: {name} std within {bound:.0%} ({std:.4g} vs {ref_std:.4g})")
    check.finish()


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""Every OpenFAST-named channel we write, and the check that covers its definition (issue 23: same
name, same meaning). Usage: channel_definitions.py OPENFAST_RUNS_DIR OC3_REFERENCE.out OUR_RUN.out

A channel is "OpenFAST-named" when any OpenFAST output under OPENFAST_RUNS_DIR has it. Those the
OC3 load case holds are checked here against it (OUR_RUN: the case with OpenFAST's wind file, sea,
WAMIT, UA and tower: regression/oc3_potential_flow/run_oc3_cases.sh), 100–600 s, each with its
criterion and the reason for it; the others name the test that compares them with another
OpenFAST run, or say why none does. A shared channel without an entry fails the script: a new
OpenFAST-named channel must say how its meaning is checked. Prints one line per channel."""
import glob
import re
import sys

import numpy as np

from compare import read_out  # the same reader as the OC3 table (this folder)

T0 = 100.0
ALIASES = {"FAIRTEN1": "T[1]", "FAIRTEN2": "T[2]", "FAIRTEN3": "T[3]",  # MAP++'s names for ours
           "ANCHTEN1": "T_a[1]", "ANCHTEN2": "T_a[2]", "ANCHTEN3": "T_a[3]"}
# Our unit → OpenFAST's, where they differ for the same channel.
SCALE = {}

SAME_RUN = "same wind file, sea and models: "
# (pattern, kind, bound, why). Kinds: stats (mean and std within bound of max(|mean|, std) and of
# std), mean (mean only: the std differs for the stated model reason), corr (correlation above
# bound), elsewhere (another test compares it: named), differs (no check: the models differ, why).
CHECKS = [
    (r"Wind1Vel[XYZ]", "stats", 0.05, SAME_RUN + "the inflow at the hub probe (measured ≤ 1.6 %)"),
    (r"Wave1Elev", "stats", 0.05, SAME_RUN + "the replayed elevation (0.0 %)"),
    (r"Azimuth", "stats", 0.05, "rotor azimuth 0–360° (uniform: mean 180, std 104)"),
    (r"RotSpeed|GenSpeed", "stats", 0.05, "rotor and HSS speed (≤ 1.1 %)"),
    (r"GenPwr|GenTq", "stats", 0.05, "ServoDyn's: the demand of the row's time (≤ 4.3 %)"),
    (r"RotThrust|LSShftFxa", "stats", 0.05, "ElastoDyn's: blades plus hub weight less inertia (−1.4 %, std +4.9 %)"),
    (r"RotTorq|LSShftMxa", "stats", 0.05, "LSS torque less hub inertia (+1.2 %, −4.3 %)"),
    (r"PtfmSurge", "stats", 0.05, "platform reference point surge (+0.6 %, +1.8 %)"),
    (r"PtfmPitch", "mean", 0.02, "mean +−1.0 %; std +12 %: pitch RAO +2–10 % (rigid tower, README)"),
    (r"PtfmHeave", "corr", 0.95, "heave mean offset (second-order response, README): correlation 0.977"),
    (r"PtfmYaw", "corr", 0.95, "yaw means 0.01° vs 0.14°: correlation 0.982"),
    (r"PtfmSway|PtfmRoll", "differs", None, "side-side: OpenFAST's tower and drivetrain reactions; ours rigid (no side-side mode)"),
    (r"BldPitch[123]", "std", 0.05, "ElastoDyn's actual pitch; mean +0.21° (the detuned OC3 loop), std −1.1 %"),
    (r"IPDefl[123]", "stats", 0.05, "in-plane tip deflection, coned frame (≤ 4.4 %)"),
    (r"OoPDefl[123]", "mean", 0.05, "out-of-plane tip deflection (−2.6 %); std +17 %: our beam blades vs ElastoDyn's 2 flap modes"),
    (r"TwstDefl[123]", "differs", None, "ElastoDyn has no blade torsion (its 0 is no measurement); ours the beam's tip twist"),
    (r"RootF[yz]c[123]|RootMxc[123]", "stats", 0.05, "blade root loads, coned frame, blade on hub (≤ 4.7 %)"),
    (r"RootFxc[123]|RootMyc[123]", "mean", 0.05, "flapwise root load mean (≤ 1.7 %); std +5–12 %: the blade models, as OoPDefl"),
    (r"RootMzc[123]", "std", 0.05, "root pitching moment: mean −0.5 vs −6.3 kN·m (ElastoDyn has no torsion), std ≤ 2.9 %"),
    (r"RtArea", "mean", 0.05, "swept area of the deflected rotor (+0.1 %); std follows OoPDefl"),
    (r"YawBrFzp|YawBrMxp", "stats", 0.05, "yaw-bearing weight and shaft torque (≤ 4.4 %)"),
    (r"YawBrFxp", "mean", 0.05, "yaw-bearing fore-aft force (−3.8 %); std −7 %: no tower mode behind it"),
    (r"YawBrFyp|YawBrMyp|YawBrMzp", "differs", None, "tower-top side/tilt/yaw reactions of OpenFAST's flexible tower and yaw spring"),
    (r"TwrBsF[xz]t|TwrBsMyt", "stats", 0.05, "tower-base loads, tower drag included (≤ 4.6 %)"),
    (r"TwrBsFyt|TwrBsMxt|TwrBsMzt", "differs", None, "side-side and torsion of the tower base: OpenFAST's tower modes; ours rigid"),
    (r"NacYaw", "differs", None, "OpenFAST's yaw spring moves 0.002°; ours has no yaw DOF in this deck"),
    (r"NcIMUTA[xyz]s", "differs", None, "nacelle accelerations carry OpenFAST's tower modes; ours rigid"),
    (r"HydroFzi|B1HDSF[xy]i|B1HDSMzi|B1Wvs[FM][xyz]i", "stats", 0.05, "HydroDyn's definitions (≤ 0.3 %; zero where OpenFAST's is)"),
    (r"HydroFxi", "std", 0.10, "with the added-mass reaction (std −5.1 %; without it a third)"),
    (r"HydroMyi|B1HDSMyi|B1HDSFzi", "mean", 0.05, "pitch restoring and buoyancy (≤ 1 %); std follows PtfmPitch, PtfmHeave"),
    (r"B1RdtF[xz]i|B1RdtM[xyz]i", "stats", 0.05, "radiation with the A(∞) reaction (std ≤ 3.1 %; without it a tenth)"),
    (r"HydroFyi|HydroMxi|HydroMzi|B1HDSMxi|B1RdtFyi", "differs", None, "follow sway, roll, yaw (above)"),
    (r"(FAIRTEN|ANCHTEN)[123]", "stats", 0.05, "MAP++'s T[i], T_a[i] (≤ 2.6 %)"),
    (r"RtAero(Pwr|Fxh|Mxh|Cp|Ct)|B1N[0-9]+(Alpha|AxInd)", "elsewhere", None,
     "`fowtsim verify aero`: the rotor against openfast-runs/aero_steady, 7 points (power, thrust, torque, Cp, Ct 1 %, α 0.3°, induction 0.01)"),
    (r"B1Root(Fzr|Myr|Mxr)|B1TipTD[xy]r", "elsewhere", None,
     "`fowtsim verify turbine-validation`: seed §4.5.3 against OpenFAST + BeamDyn (means 0.5 %, std, correlation)"),
    (r"B[123]Root[FM][xyz]r|B[123]TipTD[xyz]r", "elsewhere", None,
     "one function writes every component of every blade (driver/engine/scenes/turbine_blades.cpp); B1's are compared"),
    (r"RtSpeed|RtTSR|RtVAvgxh|RtSkew|RtAeroCq|B1N[0-9]+F[xy]", "elsewhere", None,
     "`fowtsim verify aero`: the channels as written against openfast-runs/aero_steady, 7 points (RtSpeed, "
     "RtVAvgxh 5e-8, RtTSR 4.9e-5, RtAeroCq 0.11 %, RtSkew 8e-15°; B1N2-3 Fx/Fy 0.26 % of the largest node load)"),
]


def openfast_names(runs_dir):
    names = set()
    for f in glob.glob(f"{runs_dir}/**/*.out", recursive=True):
        for line in open(f, errors="replace").read().splitlines()[:12]:
            if line.split()[:1] == ["Time"]:
                names |= {n.strip() for n in line.split("\t")}
                break
    return names


def main():
    runs_dir, reference, ours_path = sys.argv[1:4]
    of_all = openfast_names(runs_dir)
    rn, rd = read_out(reference)
    on, od = read_out(ours_path)
    t = rd[:, 0]
    window = t >= T0
    shared = [n for n in on[1:] if n in of_all or ALIASES.get(n) in of_all]
    failures, counts = [], {}
    print(f"{len(shared)} OpenFAST-named channels in {ours_path}")
    for name in shared:
        entry = next((e for e in CHECKS if re.fullmatch(e[0], name)), None)
        if entry is None:
            failures.append(f"{name}: no entry: say how its definition is checked")
            print(f"MISSING  {name}")
            continue
        _, kind, bound, why = entry
        counts[kind] = counts.get(kind, 0) + 1
        ref_name = ALIASES.get(name, name)
        if kind in ("elsewhere", "differs") or ref_name not in rn:
            if kind not in ("elsewhere", "differs"):
                failures.append(f"{name}: a {kind} check, but the OC3 run has no {ref_name}")
            print(f"{kind.upper():9} {name:12} {why}")
            continue
        x = rd[window, rn.index(ref_name)]
        y = np.interp(t[window], od[:, 0], od[:, on.index(name)])
        scale = max(abs(x.mean()), x.std())
        d_mean = (y.mean() - x.mean()) / scale if scale > 0 else 0.0
        d_std = (y.std() - x.std()) / x.std() if x.std() > 0 else 0.0
        corr = np.corrcoef(x, y)[0, 1] if x.std() > 0 and y.std() > 0 else 1.0
        ok = {"stats": abs(d_mean) <= bound and abs(d_std) <= bound, "mean": abs(d_mean) <= bound,
              "std": abs(d_std) <= bound, "corr": corr > bound}[kind]
        measured = f"Δmean {100 * d_mean:+.1f} %, Δstd {100 * d_std:+.1f} %, corr {corr:.3f}"
        print(f"{'PASS' if ok else 'FAIL':9} {name:12} {kind} {bound:g}: {measured} — {why}")
        if not ok:
            failures.append(f"{name}: {kind} {bound:g}: {measured}")
    print("by check: " + ", ".join(f"{k} {v}" for k, v in sorted(counts.items())))
    if failures:
        print(f"{len(failures)} channel(s) failed:\n  " + "\n  ".join(failures))
        sys.exit(1)
    print("every OpenFAST-named channel has its definition check; all checked ones pass")


if __name__ == "__main__":
    main()

#!/usr/bin/python3
"""Frequency-domain screening against our own time domain (issue 25, "Beyond the seed").

For a grid of mean wind speeds and sea states over a base deck (default the OC3-Hywind turbine deck
with Morison hydro, rigid blades, BEM and the OC3 baseline controller), each case is
  * screened:  fowtsim screen DECK --set ... -o FD.h5   (RAOs, PSDs, standard deviations), and
  * simulated: fowtsim run over T_TRANSIENT + T_RECORD seconds from the screening's operating
               point, several seeds of the turbulence and the wave phases; the statistics over the
               last T_RECORD seconds (one full period of the periodic wave record: its sample
               variance is the spectrum's, so the waves' part has no sampling scatter).
Writes OUT/table.md (FD std, TD mean ± scatter over seeds, ratio) and OUT/psd_<case>.png (FD PSD
against the TD Welch PSDs). Usage: fd_td.py FOWTSIM OUTDIR [--seeds N] [--quick]
"""
import argparse, os, subprocess, sys
import numpy as np
import h5py

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
CHANNELS = ["PtfmSurge", "PtfmHeave", "PtfmPitch", "TwrBsMyt", "NcIMUTAxs", "RotSpeed", "BldPitch1"]
T_TRANSIENT, T_RECORD = 300.0, 600.0


def screen(fowtsim, deck, settings, out):
    args = [fowtsim, "screen", deck, "-o", out]
    for s in settings:
        args += ["--set", s]
    text = subprocess.run(args, check=True, capture_output=True, text=True).stdout
    with h5py.File(out) as h:
        r = {k: h[k][()] for k in h.keys()}
        r["channels"] = [c.decode() if isinstance(c, bytes) else c for c in r["channels"]]
    return r, text


def operating_point(text):
    """The initial conditions of the screening's operating point (its `operating point` line)."""
    import re
    line = next(l for l in text.splitlines() if l.startswith("operating point"))
    rpm = float(re.search(r"rotor ([-\d.e+]+) rpm", line).group(1))
    pitch = float(re.search(r"pitch ([-\d.e+]+)°, generator", line).group(1))
    surge = float(re.search(r"surge ([-\d.e+]+) m", line).group(1))
    heave = float(re.search(r"heave ([-\d.e+]+) m", line).group(1))
    ptfm_pitch = float(re.search(r"pitch ([-\d.e+]+)° \(", line).group(1))
    return [f"structure.initial_conditions.rotor_speed_rpm={rpm}",
            f"structure.initial_conditions.blade_pitch_deg={pitch}",
            f"structure.initial_conditions.platform_position_m=[{surge}, 0, {heave}]",
            f"structure.initial_conditions.platform_angles_deg=[0, {ptfm_pitch}, 0]"]


def run_td(fowtsim, deck, settings, out):
    if not os.path.exists(out + ".h5"):
        args = [fowtsim, "run", deck, "-o", out, "--tmax", str(T_TRANSIENT + T_RECORD)]
        for s in settings:
            args += ["--set", s]
        subprocess.run(args, check=True, capture_output=True)
    with h5py.File(out + ".h5") as h:  # fowtsim's HDF5: one dataset per channel, Time first
        return h["Time"][()], {c: h[c][()] for c in CHANNELS}


def welch(x, dt, segment_s=200.0):
    n = int(segment_s / dt)
    step = n // 2
    w = np.hanning(n)
    psd = []
    for i0 in range(0, len(x) - n + 1, step):
        seg = x[i0:i0 + n] - np.mean(x[i0:i0 + n])
        X = np.fft.rfft(seg * w)
        psd.append(2.0 * dt * np.abs(X) ** 2 / np.sum(w ** 2))
    f = np.fft.rfftfreq(n, dt)
    p = np.mean(psd, axis=0)
    p[0] /= 2.0
    return f, p


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("fowtsim")
    ap.add_argument("outdir")
    ap.add_argument("--deck", default=os.path.join(ROOT, "inputs/oc3_hywind/turbine_ntm_12mps_irregular.yaml"))
    ap.add_argument("--seeds", type=int, default=3)
    ap.add_argument("--winds", default="8,12,18")
    ap.add_argument("--seas", default="2:8,6:10")
    args = ap.parse_args()
    os.makedirs(args.outdir, exist_ok=True)
    winds = [float(v) for v in args.winds.split(",")]
    seas = [tuple(float(x) for x in s.split(":")) for s in args.seas.split(",")]
    rows = []
    for v in winds:
        for hs, tp in seas:
            name = f"ws{v:g}_hs{hs:g}_tp{tp:g}"
            sea = [f"wind.speed_m_s={v}", f"waves.hs_m={hs}", f"waves.tp_s={tp}"]
            fd, text = screen(args.fowtsim, args.deck, sea, os.path.join(args.outdir, name + "_fd.h5"))
            ic = operating_point(text)
            td_std, td_psd = [], []
            for seed in range(1, args.seeds + 1):
                s = sea + ic + [f"wind.turbulence.seed={1000 + seed}", f"waves.seed={seed}",
                                f"wind.turbulence.duration_s={T_TRANSIENT + T_RECORD + 60}",
                                f"waves.duration_s={T_RECORD}", "output.decimation=4",
                                "output.channels=[" + ", ".join(CHANNELS) + "]"]
                t, ch = run_td(args.fowtsim, args.deck, s, os.path.join(args.outdir, f"{name}_s{seed}"))
                keep = t >= t[-1] - T_RECORD + 1e-9
                dt = t[1] - t[0]
                td_std.append([np.std(ch[c][keep]) for c in CHANNELS])
                td_psd.append([welch(ch[c][keep], dt) for c in CHANNELS])
            td_std = np.array(td_std)
            fd_std = [fd["std_total"][fd["channels"].index(c)] for c in CHANNELS]
            rows.append((name, v, hs, tp, fd, fd_std, td_std, td_psd))
            print(name, "FD", np.round(fd_std, 4), "TD", np.round(td_std.mean(axis=0), 4), flush=True)
    write_table(args.outdir, rows)
    plot(args.outdir, rows)


def write_table(outdir, rows):
    with open(os.path.join(outdir, "table.md"), "w") as out:
        out.write("| case | channel | FD std (waves, wind) | TD std mean ± sd over seeds | FD/TD |\n|---|---|---|---|---|\n")
        for name, v, hs, tp, fd, fd_std, td_std, _ in rows:
            for k, c in enumerate(CHANNELS):
                i = fd["channels"].index(c)
                m, sd = td_std[:, k].mean(), td_std[:, k].std(ddof=1) if len(td_std) > 1 else 0.0
                out.write(f"| {v:g} m/s, Hs {hs:g} m, Tp {tp:g} s | {c} | {fd_std[k]:.4g} ({fd['std_waves'][i]:.3g}, "
                          f"{fd['std_wind'][i]:.3g}) | {m:.4g} ± {sd:.2g} | {fd_std[k] / m:.3f} |\n")
    print(open(os.path.join(outdir, "table.md")).read())


def plot(outdir, rows):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    for name, v, hs, tp, fd, fd_std, td_std, td_psd in rows:
        fig, axes = plt.subplots(2, 2, figsize=(10, 7))
        for ax, c in zip(axes.flat, ["PtfmSurge", "PtfmHeave", "PtfmPitch", "TwrBsMyt"]):
            k = CHANNELS.index(c)
            for s, spectra in enumerate(td_psd):
                f, p = spectra[k]
                ax.loglog(f[1:], p[1:], color="0.6", lw=0.8, label="time domain (seeds)" if s == 0 else None)
            i = fd["channels"].index(c)
            ax.loglog(fd["frequency_hz"], fd["psd"][i], "C3", lw=1.5, label="frequency domain")
            ax.set_title(f"{c} [{fd['units'][i].decode() if isinstance(fd['units'][i], bytes) else fd['units'][i]}]")
            ax.set_xlim(2e-3, 0.5)
            top = max(np.max(p[1:]) for f, p in (spectra[k] for spectra in td_psd))
            ax.set_ylim(1e-6 * top, 10.0 * top)
            ax.set_xlabel("frequency [Hz]")
            ax.set_ylabel("PSD [unit²/Hz]")
            ax.grid(True, which="both", alpha=0.3)
        axes[0, 0].legend(fontsize=8)
        fig.suptitle(f"OC3-Hywind, {v:g} m/s NTM, JONSWAP Hs {hs:g} m Tp {tp:g} s: FD screening vs TD")
        fig.tight_layout()
        fig.savefig(os.path.join(outdir, f"psd_{name}.png"), dpi=90)
        plt.close(fig)


if __name__ == "__main__":
    main()

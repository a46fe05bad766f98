#!/usr/bin/python3
"""Independent numbers for reference_run_tests.cpp, computed with numpy only (Debian's python3-numpy).

Run once: /usr/bin/python3 modules/post/tests/reference_numbers.py ../shared/reference/openfast-runs/...
/5MW_OC3Spar_DLL_WTurb_WavesIrr_600s.out — prints statistics, rainflow DELs and Welch peaks over
60–600 s. Rainflow here is ASTM E1049-85's three-point method written out step by step (the C++
code uses the four-point formulation), and Welch is written with numpy's FFT, so the two agree only
if both are right.
"""
import sys

import numpy as np


def read_out(path):
    with open(path) as f:
        lines = f.readlines()
    start = next(i for i, line in enumerate(lines) if line.split() and line.split()[0] == "Time")
    names = lines[start].split()
    data = np.array([[float(x) for x in line.split()] for line in lines[start + 2:] if line.strip()])
    return names, data


def turning_points(x):
    points = [x[0]]
    for v in x[1:]:
        if v == points[-1]:
            continue
        if len(points) >= 2 and (points[-1] - points[-2]) * (v - points[-1]) > 0:
            points[-1] = v
        else:
            points.append(v)
    return points


def astm_three_point(x):
    """ASTM E1049-85 §5.4.4, steps 1–6, residue as half cycles. Returns (range, mean, count)."""
    cycles, stack = [], []  # stack[0] is the starting point S
    for point in turning_points(x):
        stack.append(point)
        while len(stack) >= 3:
            X = abs(stack[-1] - stack[-2])
            Y = abs(stack[-2] - stack[-3])
            if X < Y:
                break
            if len(stack) == 3:  # Y contains the starting point S: half cycle, drop the first point
                cycles.append((Y, 0.5 * (stack[0] + stack[1]), 0.5))
                stack.pop(0)
            else:
                cycles.append((Y, 0.5 * (stack[-2] + stack[-3]), 1.0))
                last = stack.pop()
                stack.pop()
                stack.pop()
                stack.append(last)
    for a, b in zip(stack[:-1], stack[1:]):
        cycles.append((abs(b - a), 0.5 * (a + b), 0.5))
    return cycles


def damage_equivalent_load(x, duration, m, ultimate=None, fixed_mean=0.0):
    total = 0.0
    for r, mean, n in astm_three_point(x):
        if ultimate is not None:
            r = r * (ultimate - abs(fixed_mean)) / (ultimate - abs(mean))
        total += n * r ** m
    return (total / duration) ** (1.0 / m)


def welch(x, fs, length):
    k = np.arange(length)
    w = 0.5 * (1 - np.cos(2 * np.pi * k / length))
    hop = length // 2
    acc, count = np.zeros(length // 2 + 1), 0
    for s in range(0, len(x) - length + 1, hop):
        seg = x[s:s + length]
        acc += np.abs(np.fft.rfft(w * (seg - seg.mean()))) ** 2
        count += 1
    p = acc / (fs * np.sum(w * w) * count)
    p[1:-1 if length % 2 == 0 else None] *= 2
    return np.arange(len(p)) * fs / length, p


def main(path):
    names, data = read_out(path)
    t = data[:, 0]
    rows = (t >= 60 - 1e-9) & (t <= 600 + 1e-9)
    t = t[rows]
    duration = t[-1] - t[0]
    fs = (len(t) - 1) / (t[-1] - t[0])
    for name, m, ultimate in (("RootMyc1", 10, 1.775e4), ("RotTorq", 3, 8.909e3), ("TwrBsMyt", 4, None),
                              ("PtfmPitch", None, None), ("GenPwr", None, None)):
        x = data[rows, names.index(name)]
        d = x - x.mean()
        m2, m3, m4 = (d ** 2).mean(), (d ** 3).mean(), (d ** 4).mean()
        print(f"{name}: min {x.min()!r} max {x.max()!r} mean {x.mean()!r} std {np.sqrt(m2)!r} "
              f"skew {m3 / m2 ** 1.5!r} kurt {m4 / m2 ** 2!r} tmin {t[x.argmin()]!r} tmax {t[x.argmax()]!r}")
        if m:
            print(f"  DEL m={m}: {damage_equivalent_load(x, duration, m)!r}"
                  f"  Goodman (L_ult {ultimate}): {damage_equivalent_load(x, duration, m, ultimate) if ultimate else None!r}")
        f, p = welch(x, fs, int(round(100 * fs)))
        peaks = [k for k in range(1, len(p) - 1) if p[k] > p[k - 1] and p[k] >= p[k + 1]]
        peaks.sort(key=lambda k: -p[k])
        print("  peaks", [(f[k], p[k]) for k in peaks[:3]], "integral", p.sum() * (f[1] - f[0]), "var", m2)


if __name__ == "__main__":
    main(sys.argv[1])

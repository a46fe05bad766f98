#!/usr/bin/python3
"""Proves that an outside tool (h5py, from Debian's python3-h5py) reads our HDF5 output:
every channel a 1-D float64 dataset with a unit attribute, Time first and increasing, run
metadata present, and values equal to those in the text output of the same run."""
import sys

import h5py
import numpy as np

h5_path, out_path = sys.argv[1], sys.argv[2]
with h5py.File(h5_path, "r") as f:
    for key in ("version", "deck_path", "deck_hash", "seeds", "dt_s", "dt_coupling_s", "wall_time_s", "status"):
        assert key in f.attrs, f"missing run attribute {key}"
    assert f.attrs["status"] == "completed", f.attrs["status"]
    time = f["Time"][:]
    assert time.dtype == np.float64 and time.ndim == 1 and np.all(np.diff(time) > 0)
    channels = {name: f[name][:] for name in f.keys()}
    for name, ds in f.items():
        assert ds.shape == time.shape, name
        assert isinstance(ds.attrs["unit"], str) and ds.attrs["unit"], name

# The text output of the same run holds the same numbers to its 10 significant digits.
with open(out_path) as text:
    lines = text.read().splitlines()
header = next(i for i, line in enumerate(lines) if line.split() and line.split()[0] == "Time")
names = lines[header].split()
table = np.loadtxt(lines[header + 2:])
for column, name in enumerate(names):
    ref = channels[name]
    assert np.allclose(table[:, column], ref, rtol=1e-9, atol=1e-12), name  # %.9E keeps 10 digits
print(f"h5py read {len(channels)} channels x {time.size} samples from {h5_path}: OK")

#!/usr/bin/python3
"""Proves that a reader of OpenFAST's binary format written from its documentation alone (no
fowtsim code; the layout openfast_toolbox's FASTOutputFile and MLife's ReadFASTbinary read) reads
our .outb: FileFmtID 3, float64 rows time-major, uniform time from TimeOut1 and TimeIncr. The
values must equal those of the HDF5 output of the same deck bit for bit, the names be the HDF5's
cut to 10 characters. openfast_toolbox itself is not installed here; this reader follows its
load_binary_output step by step.

Usage: check_outb_numpy.py FOWTSIM DECK REFERENCE.h5 OUTDIR"""
import os
import subprocess
import sys

import h5py
import numpy as np

fowtsim, deck, reference, outdir = sys.argv[1:5]
os.makedirs(outdir, exist_ok=True)
path = os.path.join(outdir, "run.outb")
subprocess.run([fowtsim, "run", deck, "-o", path], check=True, stdout=subprocess.DEVNULL)


def read_outb(path):
    with open(path, "rb") as f:
        def read(dtype, count=1):
            return np.fromfile(f, dtype=dtype, count=count)

        file_id = int(read("<i2")[0])
        assert file_id in (1, 2, 3, 4), f"FileID {file_id}"
        len_name = int(read("<i2")[0]) if file_id == 4 else 10
        n_channels, n_t = (int(v) for v in read("<i4", 2))
        first, step = (float(v) for v in read("<f8", 2))  # TimeOut1, TimeIncr (FileID 2-4)
        assert file_id != 1, "packed time not expected from fowtsim"
        if file_id == 3:
            scale, offset = np.ones(n_channels), np.zeros(n_channels)
        else:
            scale, offset = read("<f4", n_channels), read("<f4", n_channels)
        description = f.read(int(read("<i4")[0])).decode("ascii").strip()
        names = [f.read(len_name).decode("ascii").strip() for _ in range(n_channels + 1)]
        units = [f.read(len_name).decode("ascii").strip()[1:-1] for _ in range(n_channels + 1)]
        data = read("<f8" if file_id == 3 else "<i2", n_t * n_channels)
        assert data.size == n_t * n_channels, "file shorter than its header says"
        assert f.read() == b"", "bytes after the rows the header counts"
    values = (data.reshape(n_t, n_channels) - offset) / scale
    time = first + step * np.arange(n_t)
    return file_id, description, names, units, time, values


file_id, description, names, units, time, values = read_outb(path)
assert file_id == 3, file_id
assert description.endswith("Status: completed"), description
with h5py.File(reference, "r") as f:
    assert f.attrs["deck_hash"] in description, description
    h5_names = []  # in creation order, the order of the .outb's columns (keys() sorts by name)
    f.id.links.visit(lambda n: h5_names.append(n.decode()), idx_type=h5py.h5.INDEX_CRT_ORDER)
    assert len(h5_names) == len(names), (len(h5_names), len(names))
    assert names[0] == "Time" and units[0] == "s"
    ref_time = f["Time"][:]
    assert time.size == ref_time.size, (time.size, ref_time.size)
    assert np.allclose(time, ref_time, rtol=0, atol=1e-12 * max(1.0, ref_time[-1])), "time grid"
    for column, name in enumerate(h5_names[1:]):
        assert names[column + 1] == name[:10], (names[column + 1], name)
        assert units[column + 1] == f[name].attrs["unit"][:8], (units[column + 1], f[name].attrs["unit"])
        ref = f[name][:]
        # bit for bit: float64 compared as integers (NaN and -0.0 included)
        assert np.array_equal(values[:, column].view(np.int64), ref.view(np.int64)), name
print(f"numpy read {len(names) - 1} channels x {time.size} rows from {path}, equal to {reference} bit for bit: OK")

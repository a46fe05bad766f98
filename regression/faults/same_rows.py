"""same_rows.py REFERENCE TEST [prefix]: compares two fowtsim outputs (.h5 or .out) channel by
channel, bit for bit (.h5) or text field for field (.out). Without `prefix` TEST must hold all of
REFERENCE's rows; with it, TEST's rows must be REFERENCE's first rows (a run cut short). Prints the
rows and channels compared; exits 1 on the first difference."""
import sys

import h5py
import numpy as np


def rows_of(path):
    if path.endswith(".h5"):
        with h5py.File(path, "r") as f:
            names = list(f.keys())
            return {n: f[n][:] for n in names}
    lines = open(path).read().split("\n")
    names = lines[6].split("\t")  # line 7: OpenFAST's layout
    rows = [l.split("\t") for l in lines[8:] if l.strip()]
    return {n: np.array([r[i] for r in rows]) for i, n in enumerate(names)}


reference, test = rows_of(sys.argv[1]), rows_of(sys.argv[2])
prefix = len(sys.argv) > 3 and sys.argv[3] == "prefix"
if sorted(reference) != sorted(test):
    sys.exit(f"different channels: {sorted(set(reference) ^ set(test))}")
n_ref, n_test = len(reference["Time"]), len(test["Time"])
if n_test == 0 or (n_test != n_ref if not prefix else n_test > n_ref):
    sys.exit(f"{n_test} rows in {sys.argv[2]} against {n_ref} in {sys.argv[1]}")
for name in reference:
    a, b = reference[name][:n_test], test[name]
    if len(b) != n_test or not np.array_equal(a, b):
        bad = int(np.argmax(a != b)) if len(b) == n_test else -1
        sys.exit(f"{name} differs at row {bad}")
print(f"{n_test} rows x {len(reference)} channels identical")

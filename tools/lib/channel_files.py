"""Channel files as tools/plot reads them: our HDF5 run outputs, OpenFAST text outputs (.out) and
OpenFAST binary outputs (.outb, FileFmtID 1 to 4), each as one `Channels` (names, units, columns),
so a run of ours can be overlaid on OpenFAST's.

The layouts are the ones the C++ readers document (modules/io/src/openfast_text_reader.cpp,
openfast_binary_reader.cpp); this is a separate Python reading, not a call into them.
"""
import numpy as np


class Channels:
    """Time and named channels of one file; units without their brackets ("kN-m", not "(kN-m)")."""

    def __init__(self, path, names, units, columns):
        self.path = path
        self.names = list(names)
        self.units = dict(zip(names, units))
        self.columns = dict(zip(names, columns))

    @property
    def time(self):
        return self.columns[self.names[0]]

    def find(self, name):
        """The stored name of a channel: exact, else without letter case (OpenFAST's names are
        case-insensitive), else None."""
        if name in self.columns:
            return name
        folded = [n for n in self.names if n.lower() == name.lower()]
        return folded[0] if folded else None


class FormatError(Exception):
    pass


def strip_brackets(unit):
    # OpenFAST writes "(m)"; MAP++'s channels come as "[N]".
    unit = unit.strip()
    if len(unit) >= 2 and unit[0] + unit[-1] in ("()", "[]"):
        return unit[1:-1].strip()
    return unit


def read_text_out(path):
    """OpenFAST text output: free header lines, a names line starting with "Time", a units line,
    then one row per output time (tab- or blank-separated; Fortran "D" exponents accepted)."""
    with open(path, "r", errors="replace") as f:
        lines = f.read().splitlines()
    for i, line in enumerate(lines):
        fields = line.split("\t") if "\t" in line else line.split()
        fields = [x.strip() for x in fields if x.strip()]
        if fields and fields[0].lower() == "time":
            break
    else:
        raise FormatError(f"{path}: no names line starting with Time")
    names = fields
    units_line = lines[i + 1] if i + 1 < len(lines) else ""
    units = [x for x in (units_line.split("\t") if "\t" in units_line else units_line.split()) if x.strip()]
    if len(units) != len(names):
        raise FormatError(f"{path}: {len(names)} names but {len(units)} units on line {i + 2}")
    rows = []
    for number, line in enumerate(lines[i + 2:], start=i + 3):
        tokens = line.split()
        if not tokens:
            continue
        if len(tokens) != len(names):
            # A killed writer's last row is cut short: keep the whole rows before it, as the C++ reader.
            if number == len(lines):
                break
            raise FormatError(f"{path}:{number}: {len(tokens)} values, expected {len(names)}")
        rows.append([float(t.replace("D", "E").replace("d", "e")) for t in tokens])
    data = np.array(rows, dtype=float).reshape(-1, len(names))
    return Channels(path, names, [strip_brackets(u) for u in units], [data[:, k] for k in range(len(names))])


# FileFmtID of OpenFAST's binary outputs.
WITH_TIME, WITHOUT_TIME, NO_COMPRESS_WITHOUT_TIME, CHAN_LEN_IN = 1, 2, 3, 4


def read_binary_outb(path):
    """OpenFAST binary output, little-endian stream (no record markers):
    int16 FileID; int16 LenName if FileID 4 (else 10); int32 NumOutChans, NT;
    float64 TimeScl, TimeOff (FileID 1) or TimeOut1, TimeIncr; float32 ColScl[n], ColOff[n]
    unless FileID 3; int32 LenDesc and the description; n+1 names and n+1 units of LenName bytes;
    int32 packed time[NT] if FileID 1; data time-major, float64 if FileID 3 else int16 with
    value = (packed - ColOff) / ColScl and time = (packed - TimeOff) / TimeScl."""
    with open(path, "rb") as f:
        raw = f.read()
    pos = 0

    def take(dtype, count=1):
        nonlocal pos
        dtype = np.dtype(dtype).newbyteorder("<")
        size = dtype.itemsize * count
        if pos + size > len(raw):
            raise FormatError(f"{path}: file ends at byte {len(raw)}, {size} more bytes needed at {pos}")
        values = np.frombuffer(raw, dtype=dtype, count=count, offset=pos)
        pos += size
        return values

    file_id = int(take(np.int16)[0])
    if file_id not in (WITH_TIME, WITHOUT_TIME, NO_COMPRESS_WITHOUT_TIME, CHAN_LEN_IN):
        raise FormatError(f"{path}: unknown FileID {file_id} (expected 1 to 4); not an OpenFAST binary output?")
    name_length = int(take(np.int16)[0]) if file_id == CHAN_LEN_IN else 10
    n, steps = (int(v) for v in take(np.int32, 2))
    if name_length <= 0 or n < 0 or steps < 0:
        raise FormatError(f"{path}: invalid header: LenName {name_length}, NumOutChans {n}, NT {steps}")
    time_a, time_b = take(np.float64, 2)
    if file_id != NO_COMPRESS_WITHOUT_TIME:
        scale = take(np.float32, n).astype(float)
        offset = take(np.float32, n).astype(float)
    description_length = int(take(np.int32)[0])
    take(np.uint8, description_length)

    def texts():
        return [bytes(take(np.uint8, name_length)).decode("latin-1").strip(" \0") for _ in range(n + 1)]

    names, units = texts(), texts()
    time_bytes = 4 * steps if file_id == WITH_TIME else 0
    value_size = 8 if file_id == NO_COMPRESS_WITHOUT_TIME else 2
    if len(raw) - pos != time_bytes + steps * n * value_size:
        raise FormatError(f"{path}: {len(raw) - pos} data bytes after the header, "
                          f"expected {time_bytes + steps * n * value_size} for {n} channels x {steps} steps")
    if file_id == WITH_TIME:
        time = (take(np.int32, steps).astype(float) - time_b) / time_a
    else:
        time = time_a + np.arange(steps) * time_b
    if file_id == NO_COMPRESS_WITHOUT_TIME:
        data = take(np.float64, steps * n).reshape(steps, n)
    else:
        data = (take(np.int16, steps * n).reshape(steps, n).astype(float) - offset) / scale
    return Channels(path, names, [strip_brackets(u) for u in units], [time] + [data[:, k] for k in range(n)])


def read_h5(path):
    """Our run output: one dataset per channel at the root, Time first, each with a `unit` attribute."""
    import h5py
    with h5py.File(path, "r") as f:
        if "Time" not in f:
            raise FormatError(f"{path}: no Time dataset; not a fowtsim run output?")
        names = ["Time"] + [k for k in f if k != "Time" and isinstance(f[k], h5py.Dataset) and f[k].shape == f["Time"].shape]
        units = [f[k].attrs.get("unit", "") for k in names]
        units = [u.decode() if isinstance(u, bytes) else str(u) for u in units]
        return Channels(path, names, units, [f[k][:] for k in names])


def read_channels(path):
    """By extension: .h5, .outb, else an OpenFAST-style text output."""
    lower = str(path).lower()
    if lower.endswith((".h5", ".hdf5")):
        return read_h5(path)
    if lower.endswith(".outb"):
        return read_binary_outb(path)
    return read_text_out(path)

# Shared helpers of the fault scripts (sourced). Every check prints what it checked; the first
# failed check ends the script with exit 1.
set -euo pipefail
PY=/usr/bin/python3   # Debian's python3 with numpy and h5py
HERE=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
DEFAULT_DECK=$(cd "$HERE/../.." && pwd)/inputs/oc3_hywind/turbine_flexible_ntm_12mps_irregular.yaml
checks=0

fail() { echo "FAILED: $*"; exit 1; }
ok() { checks=$((checks + 1)); echo "ok: $*"; }
skip() { echo "SKIPPED: $*"; exit 4; }
expect() { # expect DESCRIPTION COMMAND...: the command must succeed
  local what=$1; shift
  if "$@"; then ok "$what"; else fail "$what"; fi
}
done_checks() { echo "$checks checks passed"; }

# h5_status FILE: the HDF5 output's status attribute.
h5_status() { "$PY" -c 'import h5py,sys; print(h5py.File(sys.argv[1], "r").attrs["status"])' "$1"; }
# out_status FILE: the .out's line 5 ("Status: …"), without the prefix and padding.
out_status() { sed -n 5p "$1" | sed -e 's/^Status: //' -e 's/ *$//'; }
# h5_rows FILE: rows of Time.
h5_rows() { "$PY" -c 'import h5py,sys; print(h5py.File(sys.argv[1], "r")["Time"].shape[0])' "$1"; }
# same_rows REFERENCE TEST [prefix]: every channel of TEST equals REFERENCE bit for bit, over all
# of REFERENCE's rows, or (prefix) over TEST's rows, which must be a leading part of REFERENCE's.
same_rows() { "$PY" "$HERE/same_rows.py" "$@"; }
# checkpoint_time FILE: simulated time of a checkpoint (its header's step × dt).
checkpoint_time() {
  "$PY" -c '
import struct, sys
b = open(sys.argv[1], "rb").read()
assert b[:11] == b"FOWTSIMCHK5", "not a checkpoint"
step, dt = struct.unpack_from("<qd", b, 11 + 16 + 40)
print(step * dt)' "$1"
}
# wait_for FILE SECONDS: until FILE exists (0) or the time is up (1).
wait_for() {
  local i
  for ((i = 0; i < $2 * 20; i++)); do [ -e "$1" ] && return 0; sleep 0.05; done
  return 1
}

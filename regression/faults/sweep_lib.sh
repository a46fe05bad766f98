# Shared by the sweep fault scripts (sourced): a small sweep spec, the status of an output and the
# checks every script makes at its end. Expects FOWTSIM, OUT and SRC (the source tree) to be set.

# A 4-case DLC 1.2 sweep on the rigid OC3 deck: 12 s per case (2 s transient + 10 s analysed) on a
# 7×7 turbulence grid, a few seconds of wall time each, so a pool is still running when the
# scripts act on it.
write_small_spec() {
  cat > "$OUT/spec.yaml" <<SPEC
sweep:
  name: fault
  base_deck: $SRC/inputs/oc3_hywind/turbine_ntm_12mps_irregular.yaml
  transient_s: 2
  analysis_s: ${1:-10}
load_cases:
  - name: c
    preset: dlc1.2
    wind_speeds_m_s: [8, 12]
    seeds: 2
    sea_state: {hs_m: 1.5, tp_s: 6.0}
    set: {wind.turbulence.ny: [7], wind.turbulence.nz: [7]}
load_table:
  channels: [GenPwr, PtfmPitch]
SPEC
}

CASES="c_ws8_s1 c_ws8_s2 c_ws12_s1 c_ws12_s2"

# The 'status' attribute of an output ("completed", "interrupted at …", "running", …).
h5_status() {
  /usr/bin/python3 -c 'import h5py, sys
with h5py.File(sys.argv[1], "r") as f: print(f.attrs["status"])' "$1"
}

# "STATE EXIT_CODE" of a case's load-table row ("" without one).
table_row() {
  /usr/bin/python3 -c 'import csv, sys
for r in csv.DictReader(open(sys.argv[1])):
    if r["case"] == sys.argv[2]: print(r["state"], r["exit_code"])' "$1" "$2"
}

fail() { echo "FAIL: $*"; exit 1; }

# Waits (up to 20 s) until a case of the pool in folder $1 writes its temporary output.
wait_for_running_case() {
  for _ in $(seq 200); do
    compgen -G "$1/cases/*.running.h5" > /dev/null && return 0
    sleep 0.1
  done
  fail "no case of the sweep in $1 started within 20 s"
}

# Every case of the folder $1 completed: output status, exit code, load-table row; no temporary
# left. A case that completed its output after its pool was killed has no exit code (no pool saw it
# exit): its row says completed with the exit code empty, which is the truth. Prints the counts.
check_all_completed() {
  local dir=$1 n=0 exited=0 rows
  for c in $CASES; do
    [ -f "$dir/cases/$c.h5" ] || fail "$c: no output"
    local status; status=$(h5_status "$dir/cases/$c.h5")
    [ "$status" = completed ] || fail "$c: output status '$status'"
    local code; code=$(cat "$dir/logs/$c.exit" 2> /dev/null)
    [ -z "$code" ] || [ "$code" = 0 ] || fail "$c: completed output, exit code file says '$code'"
    [ "$code" = 0 ] && exited=$((exited + 1))
    local row; row=$(table_row "$dir/load_table.csv" "$c")
    [ "$row" = "completed $code" ] || fail "$c: load-table row says '$row', expected 'completed $code'"
    n=$((n + 1))
  done
  rows=$(($(wc -l < "$dir/load_table.csv") - 1))
  [ "$rows" -eq 4 ] || fail "load table has $rows rows, expected 4"
  local left; left=$(find "$dir/cases" -name '*.running.*' | wc -l)
  [ "$left" -eq 0 ] || fail "$left temporary outputs left in $dir/cases"
  echo "checked: $n/4 outputs say completed ($exited with exit code 0, $((n - exited)) completed after their pool died, no exit code), $rows/4 load-table rows agree, $left temporaries left"
}

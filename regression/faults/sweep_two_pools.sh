#!/bin/bash
# Fault (issue 22, item 2): a second sweep started on the output folder of a running one. Without
# a folder lock the second reran the first's cases into the same temporary outputs and logs: the
# finished outputs were lost and the load table read the other pool's logs ("failed, exit_code 0").
# Now the second (a pool, --slurm, --collect) stops at once with exit 2 naming the first's PID, and
# changes nothing; the first completes every case, each output, exit code and row saying so.
# Usage: bash sweep_two_pools.sh FOWTSIM OUTDIR
set -u
FOWTSIM=$1
OUT=$2
SRC=$(cd "$(dirname "$0")/../.." && pwd)
source "$(dirname "$0")/sweep_lib.sh"
rm -rf "$OUT" && mkdir -p "$OUT"
write_small_spec 60
DIR=$OUT/sweep

"$FOWTSIM" sweep "$OUT/spec.yaml" --jobs 2 --output-dir "$DIR" > "$OUT/first.log" 2>&1 &
first=$!
wait_for_running_case "$DIR"

# Each way a second sweep could write into the folder, while the first runs.
refused=0
for action in "--jobs 2" "--slurm --dry-run" "--collect"; do
  # shellcheck disable=SC2086  # the action is several words
  "$FOWTSIM" sweep "$OUT/spec.yaml" $action --output-dir "$DIR" > "$OUT/second.log" 2>&1
  rc=$?
  [ $rc -eq 2 ] || fail "second sweep ($action) exited $rc while the first ran, expected 2: $(cat "$OUT/second.log")"
  grep -q "in use by another sweep (pid=$first " "$OUT/second.log" || fail "second sweep ($action) does not name PID $first: $(cat "$OUT/second.log")"
  grep -q "^pid=$first " "$DIR/.sweep.lock" || fail "the lock file no longer names the first sweep after ($action): $(cat "$DIR/.sweep.lock")"
  refused=$((refused + 1))
done
[ -e "$DIR/slurm/sweep.sbatch" ] && fail "the refused --slurm wrote slurm/sweep.sbatch"
echo "checked: $refused/3 second sweeps (pool, --slurm --dry-run, --collect) refused with exit 2 naming PID $first; lock file unchanged; no sbatch script written"

wait $first
rc=$?
[ $rc -eq 0 ] || fail "the first sweep exited $rc: $(tail -5 "$OUT/first.log")"
check_all_completed "$DIR"
echo "PASS"

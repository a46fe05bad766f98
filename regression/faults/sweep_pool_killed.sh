#!/bin/bash
# Fault (issue 22, item 2): a sweep pool killed outright (SIGKILL) while its cases run. Its cases
# used to run on as orphans, and an immediate rerun started the same cases into the same temporary
# outputs: two finished outputs were lost. Now the cases get SIGTERM when their pool dies and close
# their outputs as interrupted; they keep the folder locked until they have, so a rerun waits for
# them, keeps what completed before the kill, reruns the rest and ends with every case completed.
# Two rounds: a rerun at once; and a folder collected once the orphans have ended (each output and
# row must say completed or interrupted, as it is), then rerun.
# Usage: bash sweep_pool_killed.sh FOWTSIM OUTDIR
set -u
FOWTSIM=$1
OUT=$2
SRC=$(cd "$(dirname "$0")/../.." && pwd)
source "$(dirname "$0")/sweep_lib.sh"
rm -rf "$OUT" && mkdir -p "$OUT"
write_small_spec 60

# Starts a pool on folder $1 (2 processes) and SIGKILLs it once its first case has ended while
# others run. Sets ORPHANS (pids of the cases it had running) and KEPT ("case mtime" lines of the
# outputs completed by then).
start_and_kill_pool() {
  local dir=$1
  "$FOWTSIM" sweep "$OUT/spec.yaml" --jobs 2 --output-dir "$dir" > "$OUT/killed.log" 2>&1 &
  local pool=$!
  for _ in $(seq 400); do
    compgen -G "$dir/logs/*.exit" > /dev/null && compgen -G "$dir/cases/*.running.h5" > /dev/null && break
    sleep 0.05
  done
  ORPHANS=$(pgrep -P "$pool" | tr '\n' ' ')
  kill -KILL "$pool"
  wait "$pool" 2> /dev/null
  [ -n "$ORPHANS" ] || fail "the pool had no case running when it was killed"
  KEPT=$(for c in $CASES; do
    [ -f "$dir/cases/$c.h5" ] && [ "$(h5_status "$dir/cases/$c.h5")" = completed ] && echo "$c $(stat -c %y "$dir/cases/$c.h5")"
  done)
  [ -n "$KEPT" ] || fail "no case had completed when the pool was killed"
}

# True while a pid runs (a zombie waiting for a reaper counts as ended).
running() { local s; s=$(ps -o stat= -p "$1" 2> /dev/null) && [ "${s:0:1}" != Z ]; }

# The outputs completed before the kill are the same files after the rerun.
check_kept() {
  local dir=$1 n=0
  while read -r c mtime; do
    [ "$(stat -c %y "$dir/cases/$c.h5")" = "$mtime" ] || fail "$c completed before the kill but its output was rewritten"
    n=$((n + 1))
  done <<< "$KEPT"
  echo "checked: $n output(s) completed before the kill kept untouched by the rerun"
}

# Round 1: kill, rerun at once.
DIR=$OUT/immediate
start_and_kill_pool "$DIR"
"$FOWTSIM" sweep "$OUT/spec.yaml" --jobs 2 --output-dir "$DIR" > "$OUT/rerun1.log" 2>&1
rc=$?
[ $rc -eq 0 ] || fail "the immediate rerun exited $rc: $(tail -8 "$OUT/rerun1.log")"
for p in $ORPHANS; do running "$p" && fail "case process $p of the killed pool still runs after the rerun"; done
echo "checked: $(echo $ORPHANS | wc -w) case process(es) of the killed pool ended; rerun exit 0$(grep -q waiting "$OUT/rerun1.log" && echo ', after waiting for them')"
check_kept "$DIR"
check_all_completed "$DIR"

# Round 2: kill, let the orphans end, collect: each output and row tells what happened.
DIR=$OUT/collected
start_and_kill_pool "$DIR"
for _ in $(seq 100); do
  alive=0
  for p in $ORPHANS; do running "$p" && alive=$((alive + 1)); done
  [ $alive -eq 0 ] && break
  sleep 0.1
done
[ $alive -eq 0 ] || fail "$alive case process(es) of the killed pool still run 10 s after it died"
"$FOWTSIM" sweep "$OUT/spec.yaml" --collect --output-dir "$DIR" > "$OUT/collect.log" 2>&1
completed=0 interrupted=0 missing=0
for c in $CASES; do
  row=$(table_row "$DIR/load_table.csv" "$c")
  if [ -f "$DIR/cases/$c.h5" ]; then
    status=$(h5_status "$DIR/cases/$c.h5")
    case "$status" in
      completed) [ "${row%% *}" = completed ] || fail "$c: output completed, row says '$row'"; completed=$((completed + 1)) ;;
      "interrupted at"*"(SIGTERM)") [ "${row%% *}" = interrupted ] || fail "$c: output '$status', row says '$row'"; interrupted=$((interrupted + 1)) ;;
      *) fail "$c: output status '$status' after its pool was killed" ;;
    esac
  else
    [ "$row" = "missing " ] || fail "$c: no output, row says '$row'"
    missing=$((missing + 1))
  fi
done
[ $interrupted -ge 1 ] || fail "no output says interrupted: the killed pool's cases did not close theirs"
left=$(find "$DIR/cases" -name '*.running.*' | wc -l)
[ "$left" -eq 0 ] || fail "$left temporary output(s) left by the killed pool's cases"
echo "checked: after the kill $completed completed, $interrupted interrupted (SIGTERM), $missing not started; output status and table row agree for 4/4; $left temporaries left"
"$FOWTSIM" sweep "$OUT/spec.yaml" --jobs 2 --output-dir "$DIR" > "$OUT/rerun2.log" 2>&1
rc=$?
[ $rc -eq 0 ] || fail "the rerun after collecting exited $rc: $(tail -8 "$OUT/rerun2.log")"
grep -q "4 ($completed completed earlier and skipped)" "$OUT/rerun2.log" || fail "the rerun did not skip the $completed completed case(s): $(grep cases "$OUT/rerun2.log")"
check_kept "$DIR"
check_all_completed "$DIR"
echo "PASS"

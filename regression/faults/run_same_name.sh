#!/usr/bin/env bash
# Two runs on one output name: the second stops at once (exit 2) naming the first's PID, and the
# first finishes with all its rows under the final name.
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"
fowtsim=$1 out=$2
rm -rf "$out" && mkdir -p "$out" && cd "$out"

"$fowtsim" run "$DEFAULT_DECK" --tmax 300 -o x > first.log 2>&1 &
first=$!
wait_for x.running.h5 60 || fail "the first run never created x.running.h5"
rc=0; "$fowtsim" run "$DEFAULT_DECK" --tmax 120 -o x > second.log 2>&1 || rc=$?
[ "$rc" -eq 2 ] && ok "the second run exits 2" || fail "the second run exited $rc (second.log: $(tail -2 second.log))"
grep -q "being written by another run (PID $first " second.log && ok "it names the first run's PID $first" \
  || fail "no PID $first in: $(cat second.log)"
rc=0; wait "$first" || rc=$?
[ "$rc" -eq 0 ] && ok "the first run exits 0" || fail "the first run exited $rc: $(tail -3 first.log)"
[ "$(h5_status x.h5)" = completed ] && ok "x.h5 status completed" || fail "x.h5 status $(h5_status x.h5)"
[ "$(h5_rows x.h5)" -eq 3001 ] && ok "x.h5 holds all 3001 rows (0-300 s)" || fail "x.h5 has $(h5_rows x.h5) rows"
[ ! -e x.running.h5 ] && [ ! -e x.lock ] && ok "no temporary or lock left" || fail "left: $(ls)"
# The name is free again: a later run takes it.
"$fowtsim" run "$DEFAULT_DECK" --tmax 10 -o x > third.log 2>&1 && ok "a later run on the name runs" || fail "$(tail -2 third.log)"
done_checks

#!/usr/bin/env bash
# A run with checkpoints stopped by SIGKILL, SIGHUP and SIGTERM, each then restarted without -o:
# - SIGHUP/SIGTERM: exit 129/143, files under their final names with status "interrupted … (SIG…)";
# - SIGKILL: the temporary is readable, says "running", and holds every row up to the checkpoint
#   (a checkpoint is never ahead of the rows);
# - the restart continues the same output: both files end up identical to an uninterrupted run's,
#   bit for bit (.h5) and byte for byte (.out), with no .unfinished or temporary file left.
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"
fowtsim=$1 out=$2
rm -rf "$out" && mkdir -p "$out" && cd "$out"
tmax=300
"$fowtsim" run "$DEFAULT_DECK" --tmax $tmax -o ref --out-format both > ref.log 2>&1 || fail "reference run: $(tail -2 ref.log)"

for sig in KILL HUP TERM; do
  x=$sig/x
  mkdir -p $sig
  "$fowtsim" run "$DEFAULT_DECK" --tmax $tmax -o $x --out-format both --checkpoint-every 10 > $sig/run.log 2>&1 &
  pid=$!
  wait_for $x.chk 60 || fail "$sig: no checkpoint written"
  sleep 0.$((RANDOM % 8 + 2))
  kill -$sig $pid
  rc=0; wait $pid || rc=$?
  t_chk=$(checkpoint_time $x.chk)
  case $sig in
    KILL)
      [ "$rc" -eq 137 ] && ok "SIGKILL: exit 137 at checkpoint t = $t_chk s" || fail "SIGKILL: exit $rc (did the run end first?)"
      [ "$(h5_status $x.running.h5)" = running ] && ok "SIGKILL: x.running.h5 readable, status running" || fail "status $(h5_status $x.running.h5)"
      [ "$(out_status $x.running.out)" = running ] && ok "SIGKILL: x.running.out status line: running" || fail "status $(out_status $x.running.out)"
      last=$("$PY" -c 'import h5py,sys; print(h5py.File(sys.argv[1], "r")["Time"][-1])' $x.running.h5)
      "$PY" -c "import sys; sys.exit(not $last >= $t_chk)" && ok "SIGKILL: rows reach t = $last s, not behind the checkpoint ($t_chk s)" \
        || fail "SIGKILL: rows end at $last s, the checkpoint is at $t_chk s"
      same_rows ref.h5 $x.running.h5 prefix > /dev/null && ok "SIGKILL: its rows are the reference's" || fail "SIGKILL: rows differ"
      ;;
    *)
      code=$([ $sig = HUP ] && echo 129 || echo 143)
      [ "$rc" -eq "$code" ] && ok "SIG$sig: exit $code" || fail "SIG$sig: exit $rc: $(tail -2 $sig/run.log)"
      case "$(h5_status $x.h5)" in "interrupted at t = "*"(SIG$sig)") ok "SIG$sig: x.h5 status $(h5_status $x.h5)";; *) fail "x.h5 status $(h5_status $x.h5)";; esac
      case "$(out_status $x.out)" in "interrupted at t = "*"(SIG$sig)") ok "SIG$sig: x.out line 5 says interrupted";; *) fail "x.out status $(out_status $x.out)";; esac
      "$fowtsim" post $x.out --channels RotSpeed > $sig/post.log 2>&1 || fail "post of an interrupted .out: $(tail -2 $sig/post.log)"
      grep -q "warning: .*did not complete" $sig/post.log && ok "SIG$sig: post reads x.out and warns it is incomplete" || fail "post gave no warning"
      same_rows ref.h5 $x.h5 prefix > /dev/null && ok "SIG$sig: its rows are the reference's" || fail "SIG$sig: rows differ"
      ;;
  esac
  "$fowtsim" run "$DEFAULT_DECK" --tmax $tmax --restart $x.chk --out-format both > $sig/restart.log 2>&1 || fail "$sig restart: $(tail -2 $sig/restart.log)"
  grep -q "continues" $sig/restart.log && ok "$sig: the restart says which output it continues" || fail "no note: $(cat $sig/restart.log)"
  same_rows ref.h5 $x.h5 > /dev/null && ok "$sig: restarted x.h5 = the uninterrupted run, all $(h5_rows $x.h5) rows" || fail "$sig: x.h5 differs"
  cmp -s ref.out $x.out && ok "$sig: restarted x.out = the uninterrupted run's, byte for byte" || fail "$sig: x.out differs"
  [ -z "$(ls $sig | grep -E 'running|unfinished|lock')" ] && ok "$sig: no temporary, unfinished file or lock left" || fail "left: $(ls $sig)"
done

# A checkpoint cut short (as a full disk once left it) is named as damaged.
head -c 45056 KILL/x.chk > cut.chk
rc=0; "$fowtsim" run "$DEFAULT_DECK" --tmax $tmax --restart cut.chk -o cut > cut.log 2>&1 || rc=$?
[ "$rc" -eq 2 ] && grep -q "damaged" cut.log && ok "a truncated checkpoint: exit 2, named as damaged" || fail "exit $rc: $(tail -2 cut.log)"
[ ! -e cut.h5 ] && ok "and nothing written" || fail "cut.h5 written"
done_checks

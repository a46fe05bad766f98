#!/usr/bin/env bash
# A full disk (a tmpfs of 20 MB, a private mount): the run stops with exit 2 and the reason, and
# every row it computed is in both files, identical to the same rows of a run on a roomy disk,
# with a status that says the disk was full; a checkpoint left there is whole and continues the
# run bit-identically elsewhere. A disk too small to close the outputs stops before any file.
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"
fowtsim=$1 out=$2
if [ -z "${FOWTSIM_IN_PRIVATE_MOUNT:-}" ]; then
  # A private mount namespace: the tmpfs disappears with the script, whatever happens.
  unshare -m true 2>/dev/null || skip "no private mount namespace here (unshare -m needs CAP_SYS_ADMIN)"
  rc=0; FOWTSIM_IN_PRIVATE_MOUNT=1 unshare -m bash "${BASH_SOURCE[0]}" "$@" || rc=$?
  [ "$rc" -eq 99 ] && skip "cannot mount a tmpfs here (needs CAP_SYS_ADMIN)"
  exit "$rc"
fi
rm -rf "$out" && mkdir -p "$out/full" "$out/tiny" && cd "$out"
mount -t tmpfs -o size=20m tmpfs full 2>/dev/null && mount -t tmpfs -o size=200k tmpfs tiny 2>/dev/null || exit 99

"$fowtsim" run "$DEFAULT_DECK" --tmax 300 -o ref --out-format both > ref.log 2>&1 || fail "reference run: $(tail -2 ref.log)"
rc=0; "$fowtsim" run "$DEFAULT_DECK" --tmax 300 -o full/x --out-format both --checkpoint-every 20 > full.log 2>&1 || rc=$?
[ "$rc" -eq 2 ] && ok "the run on a full disk exits 2" || fail "exit $rc: $(tail -2 full.log)"
grep -q "is full" full.log && ok "and says the disk is full" || fail "no reason given: $(tail -2 full.log)"
[ -e full/x.h5 ] && [ -e full/x.out ] && [ ! -e full/x.running.h5 ] && ok "both files under their final names" || fail "$(ls full)"
case "$(h5_status full/x.h5)" in "failed: "*"is full"*) ok "x.h5 status: failed, disk full";; *) fail "x.h5 status $(h5_status full/x.h5)";; esac
case "$(out_status full/x.out)" in "failed: "*"is full"*) ok "x.out status line: failed, disk full";; *) fail "x.out status $(out_status full/x.out)";; esac
rows=$(h5_rows full/x.h5)
same_rows ref.h5 full/x.h5 prefix && ok "the $rows rows in x.h5 are the reference's, bit for bit" || fail "x.h5 rows differ"
same_rows ref.out full/x.out prefix && ok "the rows in x.out are the reference's, digit for digit" || fail "x.out rows differ"
[ "$(grep -c . full/x.out)" -eq $((rows + 5)) ] && ok "x.out holds the same $rows rows as x.h5" || fail "x.out and x.h5 hold different rows"
# The checkpoint left on the full disk is whole: a restart elsewhere continues to the reference.
[ -e full/x.chk ] || fail "no checkpoint on the full disk"
t_chk=$(checkpoint_time full/x.chk)
"$fowtsim" run "$DEFAULT_DECK" --tmax 300 --restart full/x.chk -o cont --out-format both > cont.log 2>&1 || fail "restart: $(tail -2 cont.log)"
same_rows ref.h5 cont.h5 && ok "the checkpoint at t = $t_chk s continues, with the full disk's rows, to the reference" || fail "cont.h5 differs"
# Too small to close the outputs: the run stops before creating any of them.
rc=0; "$fowtsim" run "$DEFAULT_DECK" --tmax 10 -o tiny/x > tiny.log 2>&1 || rc=$?
[ "$rc" -eq 2 ] && grep -q "cannot hold back" tiny.log && ok "a 200 kB disk stops the run at its start (exit 2, why)" || fail "exit $rc: $(tail -2 tiny.log)"
[ -z "$(ls tiny)" ] && ok "and leaves nothing on it" || fail "left: $(ls tiny)"
done_checks

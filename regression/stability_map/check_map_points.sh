#!/usr/bin/env bash
# The stability map's claims that matter (README "Stability map", `fowtsim bench stability`), on
# the default deck on the rigid tower for 120 s:
#   - single_rate ΔT = Δt = 0.8 s stops on the beam's small-angle guard at t = 3.2 s: exit 3, the
#     guard's message, both files "failed: …" keeping every step before it (0, 0.8, 1.6, 2.4 s);
#   - single_rate at 0.4 s, the largest single-rate step that runs, and multi_rate ΔT = 0.8 s,
#     Δt = 0.4 s, the largest stable multi-rate point of the grid, run to the end within the
#     README's criteria (finite, |PtfmPitch| < 20°, RotSpeed in (0, 25) rpm).
# Three runs of 1-2 s each.
source "$(dirname "${BASH_SOURCE[0]}")/../faults/lib.sh"
fowtsim=$1 out=$2
rm -rf "$out" && mkdir -p "$out" && cd "$out"

# point NAME ΔT N MODE: a deck of the default deck at that coupling, every large step written; on
# the rigid tower with RK4 steps of 20 ms, where the map of the blades' exchange was measured.
point() {
  cat > "$1.yaml" <<DECK
include: [$DEFAULT_DECK]
simulation: {t_max_s: 120.0, dt_s: $2}
output: {decimation: 1, channels: [PtfmPitch, RotSpeed]}
blades: {coupling: $4, substeps: $3}
structure: {tower: {flexible: false}, max_step_s: 0.02}
DECK
}
# within_criteria FILE: every row finite and inside the README's criteria, the last at 120 s.
within_criteria() {
  "$PY" - "$1" <<'PY'
import sys, h5py, numpy as np
f = h5py.File(sys.argv[1], "r")
t, pitch, rpm = (np.asarray(f[c]) for c in ("Time", "PtfmPitch", "RotSpeed"))
ok = np.isfinite(pitch).all() and np.isfinite(rpm).all() and (abs(pitch) < 20).all() and ((rpm > 0) & (rpm < 25)).all()
print(f"  last row t = {t[-1]:g} s, max |PtfmPitch| = {abs(pitch).max():.2f} deg, RotSpeed {rpm.min():.2f}-{rpm.max():.2f} rpm")
sys.exit(0 if ok and abs(t[-1] - 120.0) < 1e-9 else 1)
PY
}

point sr08 0.8 1 single_rate
rc=0; "$fowtsim" run sr08.yaml --out-format both -o sr08 > sr08.log 2>&1 || rc=$?
[ "$rc" -eq 3 ] && ok "single_rate 0.8 s exits 3 (numerical failure)" || fail "single_rate 0.8 s exited $rc: $(tail -3 sr08.log)"
# The time and the guard are the claim; the increment's size (0.134 rad today) only has to be over
# the limit, so any value above it is accepted.
guard='beam at t = 3\.2 s: an incremental rotation of [0-9.]+ rad in one step exceeds the small-angle limit 0\.1 rad'
grep -qE "numerical failure: $guard" sr08.log && ok "it says the small-angle guard stopped it at 3.2 s" \
  || fail "no '$guard' in: $(cat sr08.log)"
[[ "$(h5_status sr08.h5)" =~ ^failed:\ $guard ]] && ok "sr08.h5 status failed: <the guard's message>" \
  || fail "sr08.h5 status: $(h5_status sr08.h5)"
[[ "$(out_status sr08.out)" =~ ^failed:\ $guard ]] && ok "sr08.out status failed: <the guard's message>" \
  || fail "sr08.out status: $(out_status sr08.out)"
times=$("$PY" -c 'import h5py,sys; print(" ".join(f"{t:g}" for t in h5py.File(sys.argv[1], "r")["Time"]))' sr08.h5)
[ "$times" = "0 0.8 1.6 2.4" ] && ok "sr08.h5 keeps the rows of every step before the refused one (0-2.4 s)" \
  || fail "sr08.h5 rows at t = $times"
out_rows=$(tail -n +9 sr08.out | grep -c .)  # line 7 names, line 8 units, then the rows
[ "$out_rows" -eq 4 ] && ok "sr08.out keeps the same 4 rows" || fail "sr08.out has $out_rows rows"

for p in "sr04 0.4 1 single_rate" "mr08 0.8 2 multi_rate"; do
  set -- $p
  point "$@"
  rc=0; "$fowtsim" run "$1.yaml" -o "$1" > "$1.log" 2>&1 || rc=$?
  [ "$rc" -eq 0 ] && ok "$4 ΔT = $2 s, $3 blade step(s) per large step: exits 0" || fail "$1 exited $rc: $(tail -3 "$1.log")"
  [ "$(h5_status "$1.h5")" = completed ] && ok "$1.h5 status completed" || fail "$1.h5 status $(h5_status "$1.h5")"
  expect "$1 runs to 120 s within the criteria" within_criteria "$1.h5"
done
done_checks

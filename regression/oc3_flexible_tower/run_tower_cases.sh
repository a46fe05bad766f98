#!/usr/bin/env bash
# The OC3 load case with the flexible tower and Rayleigh–Ritz blades against OpenFAST v5 (issue 24):
# 600 s with OpenFAST's TurbSim file and its sea replayed from Wave1Elev, WAMIT potential flow,
# unsteady airfoils and the tower's aerodynamics (as regression/oc3_potential_flow's wamit_ua_tower
# case); rigid and Rayleigh–Ritz blades (ElastoDyn's blade file), each on the rigid and on the
# flexible tower (a gauge at ElastoDyn's TwrGagNd 10: 36.86 m); and the MBBT blades (23 volumes) on the
# flexible tower (its interface mass, modules/multibody/README.md; ≈ 12 s). Two runs at a time (≈ 10 s
# each with rigid blades, ≈ 30 s with Rayleigh–Ritz blades), then compare_tower.py.
# Usage: run_tower_cases.sh FOWTSIM OUTDIR.
set -euo pipefail
fowtsim=$1
out=$2
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../oc3_openfast_run.sh"
write_deck() {  # name tower-keys rotor-keys [extra include]
  cat > "$out/$1.yaml" <<DECK
include: [$inputs/oc3_hywind/structure.yaml, $inputs/oc3_hywind/hydro_potential_flow.yaml, $inputs/oc3_hywind/mooring.yaml,
          $inputs/oc3_hywind/controller.yaml, $inputs/oc3_hywind/aero_oc3.yaml${4:+, $4}]
simulation: {t_max_s: 600.0, dt_s: 0.02}
output: {format: out, decimation: 4}
structure: {initial_conditions: {rotor_speed_rpm: 12.1}, tower: $2, rotor: $3}
wind: {model: bts, file: $runs/5MW_Baseline/Wind/90m_12mps_twr_600s.bts, speed_m_s: 12.0, reference_height_m: 90.0}
waves: {model: elevation_series, file: $reference, depth_m: 320.0, stretching: none}
aero: {unsteady_airfoil: hgm}
DECK
}
rr="{rayleigh_ritz_blade_file: $inputs/nrel5mw/blade_elastodyn.yaml}"
write_deck rigid_tower "{flexible: false}" "{}"
write_deck flexible_tower "{flexible: true, gauge_heights_m: [36.86]}" "{}"
write_deck rr_rigid_tower "{flexible: false}" "$rr"
write_deck rr_flexible_tower "{flexible: true, gauge_heights_m: [36.86]}" "$rr"
write_deck mbbt_flexible_tower "{flexible: true, gauge_heights_m: [36.86]}" "{}" "$inputs/nrel5mw/blade_structure.yaml"
echo "blades: {segments: 23, coupling: multi_rate, substeps: 4, start: static}" >> "$out/mbbt_flexible_tower.yaml"
for pair in "rigid_tower flexible_tower" "rr_rigid_tower rr_flexible_tower" "mbbt_flexible_tower"; do
  set -- $pair
  "$fowtsim" run "$out/$1.yaml" -o "$out/$1" > "$out/$1.log" 2>&1 &
  first=$!
  if [ $# -gt 1 ]; then "$fowtsim" run "$out/$2.yaml" -o "$out/$2" > "$out/$2.log" 2>&1; fi
  wait "$first"
done
for case in rigid_tower flexible_tower rr_rigid_tower rr_flexible_tower mbbt_flexible_tower; do
  echo "$case: $(grep -h "real-time" "$out/$case.log" || true)"
done
/usr/bin/python3 "$here/compare_tower.py" "$reference" "$out/rigid_tower.out" "$out/flexible_tower.out" \
  "$out/rr_rigid_tower.out" "$out/rr_flexible_tower.out" "$out/mbbt_flexible_tower.out"

#!/usr/bin/env bash
# The OC3 load case with the flexible tower against OpenFAST v5 (issue 24): 600 s with OpenFAST's
# TurbSim file and its sea replayed from Wave1Elev, WAMIT potential flow, unsteady airfoils and the
# tower's aerodynamics (as regression/oc3_potential_flow's wamit_ua_tower case), rigid blades, on
# the rigid and on the flexible tower (a gauge at ElastoDyn's TwrGagNd 10: 36.86 m). Both runs at
# once (≈ 10 s each), then compare_tower.py. Usage: run_tower_cases.sh FOWTSIM OUTDIR.
set -euo pipefail
fowtsim=$1
out=$2
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../oc3_openfast_run.sh"
write_deck() {  # name tower-keys
  cat > "$out/$1.yaml" <<DECK
include: [$inputs/oc3_hywind/structure.yaml, $inputs/oc3_hywind/hydro_potential_flow.yaml, $inputs/oc3_hywind/mooring.yaml,
          $inputs/oc3_hywind/controller.yaml, $inputs/oc3_hywind/aero_oc3.yaml]
simulation: {t_max_s: 600.0, dt_s: 0.02}
output: {format: out, decimation: 4}
structure: {initial_conditions: {rotor_speed_rpm: 12.1}, tower: $2}
wind: {model: bts, file: $runs/5MW_Baseline/Wind/90m_12mps_twr_600s.bts, speed_m_s: 12.0, reference_height_m: 90.0}
waves: {model: elevation_series, file: $reference, depth_m: 320.0, stretching: none}
aero: {unsteady_airfoil: hgm}
DECK
}
write_deck rigid_tower "{flexible: false}"
write_deck flexible_tower "{flexible: true, gauge_heights_m: [36.86]}"
"$fowtsim" run "$out/rigid_tower.yaml" -o "$out/rigid_tower" > "$out/rigid_tower.log" 2>&1 &
rigid=$!
"$fowtsim" run "$out/flexible_tower.yaml" -o "$out/flexible_tower" > "$out/flexible_tower.log" 2>&1
wait "$rigid"
grep -h "real-time" "$out"/*.log || true
/usr/bin/python3 "$here/compare_tower.py" "$reference" "$out/rigid_tower.out" "$out/flexible_tower.out"

#!/usr/bin/env bash
# The OC3 load case against OpenFAST v5 (issue 15, "the comparison that shows it"): 600 s with
# OpenFAST's TurbSim file and its sea replayed from Wave1Elev (waves.model elevation_series),
# flexible blades, once per hydro/aero model:
#   morison      Morison strips (Ca = 1) and nonlinear hydrostatics, quasi-steady airfoils (before);
#   wamit        WAMIT potential flow as OpenFAST's deck (inputs/oc3_hywind/hydro_potential_flow.yaml);
#   wamit_ua     the same with unsteady airfoil aerodynamics (OpenFAST's deck runs UA_Mod 3);
#   wamit_ua_dbemt  and with Øye's dynamic inflow (OpenFAST's deck has DBEMT off: for information);
#   wamit_ua_tower  WAMIT + UA with the tower as OpenFAST's deck has it (TwrPotent 1, TwrAero True:
#                   inputs/oc3_hywind/aero_oc3.yaml) — the closest to OpenFAST's run.
# Two runs at a time (≈ 1 minute on 2 cores), then compare.py: the table of means, standard deviations and correlations
# against OpenFAST's `…_600s.out`, the wave-to-motion transfer functions (RAOs) of heave, pitch and
# surge, and the checks. Usage: run_oc3_cases.sh FOWTSIM OUTDIR. Skips without the reference data.
set -euo pipefail
fowtsim=$1
out=$2
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../oc3_openfast_run.sh"
write_deck() {  # name hydro-file extra-yaml [aero-file]
  cat > "$out/$1.yaml" <<DECK
include: [$inputs/oc3_hywind/structure.yaml, $inputs/oc3_hywind/$2, $inputs/oc3_hywind/mooring.yaml,
          $inputs/oc3_hywind/controller.yaml, $inputs/${4:-nrel5mw/aero.yaml}, $inputs/nrel5mw/blade_structure.yaml]
simulation: {t_max_s: 600.0, dt_s: 0.02}
output: {format: out, decimation: 4}
structure: {initial_conditions: {rotor_speed_rpm: 12.1}}
wind: {model: bts, file: $runs/5MW_Baseline/Wind/90m_12mps_twr_600s.bts, speed_m_s: 12.0, reference_height_m: 90.0}
waves: {model: elevation_series, file: $reference, depth_m: 320.0, stretching: none}
blades: {segments: 23, substeps: 4, start: centrifugal}
$3
DECK
}
write_deck morison hydro.yaml ""
write_deck wamit hydro_potential_flow.yaml ""
write_deck wamit_ua hydro_potential_flow.yaml "aero: {unsteady_airfoil: hgm}"
write_deck wamit_ua_dbemt hydro_potential_flow.yaml "aero: {unsteady_airfoil: hgm, dynamic_inflow: oye}"
write_deck wamit_ua_tower hydro_potential_flow.yaml "aero: {unsteady_airfoil: hgm}" oc3_hywind/aero_oc3.yaml
pids=()
for case in morison wamit wamit_ua wamit_ua_dbemt wamit_ua_tower; do
  "$fowtsim" run "$out/$case.yaml" -o "$out/$case" > "$out/$case.log" 2>&1 &
  pids+=($!)
  if [ ${#pids[@]} -ge 2 ]; then wait "${pids[0]}"; pids=("${pids[@]:1}"); fi
done
for p in "${pids[@]}"; do wait "$p"; done
grep -h "real-time" "$out"/*.log || true
/usr/bin/python3 "$here/compare.py" "$reference" "$out"
# Every OpenFAST-named channel we write and the check that covers its meaning (issue 23).
/usr/bin/python3 "$here/channel_definitions.py" "$(cd "$root/.." && pwd)/shared/reference/openfast-runs" "$reference" \
  "$out/wamit_ua_tower.out"

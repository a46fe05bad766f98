#!/usr/bin/env bash
# regression/faults/truncated_inputs.sh FOWTSIM OUTDIR SOURCE_DIR
# Issue 22 item 8: foreign input files cut short must stop a run as an input error (exit 2) naming
# the file, before anything is written. Copies of OpenFAST's OC3 WAMIT files (Spar.1, .3, .hst) and
# of a BeamDyn case (../shared/reference) are cut inside a number, at a line end, at a block
# boundary and by their last N bytes; a deck (or the BeamDyn driver) using each copy is run.
set -uo pipefail
fowtsim=$1 out=$2 src=$3
reference=$src/../shared/reference
hydro=$reference/r-test/glue-codes/openfast/5MW_Baseline/HydroData
beamdyn=$reference/r-test/modules/beamdyn/bd_5MW_dynamic_gravity_Az00
if [[ ! -f $hydro/Spar.1 || ! -f $beamdyn/beam_props.inp ]]; then
  echo "SKIPPED: the OpenFAST reference inputs are not in $reference"
  exit 4
fi
rm -rf "$out" && mkdir -p "$out/deck/hd" "$out/bd" "$out/runs"
cp "$src"/inputs/oc3_hywind/*.yaml "$out/deck/"
sed -i 's#^\(\s*wamit_root:\).*#\1 hd/Spar#' "$out/deck/hydro_potential_flow.yaml"
deck=$out/deck/free_decay_heave_wamit.yaml
checked=0 failed=0

restore() { cp "$hydro"/Spar.* "$out/deck/hd/"; cp "$beamdyn"/*.inp "$out/bd/"; chmod u+w "$out"/deck/hd/* "$out"/bd/*; }

# run_case NAME FILE_NAMED EXPECTED_EXIT COMMAND...: runs fowtsim COMMAND -o runs/NAME and checks the
# exit code; for exit 2 also that stderr names FILE_NAMED and that no runs/NAME* file exists.
run_case() {
  local name=$1 named=$2 expected=$3
  shift 3
  "$fowtsim" run "$@" --tmax 0.1 -o "$out/runs/$name" > "$out/runs/$name.log" 2>&1
  local code=$? problem=""
  if [[ $code != "$expected" ]]; then
    problem="exit $code, expected $expected"
  elif [[ $expected == 2 ]]; then
    grep -q -- "$named" "$out/runs/$name.log" || problem="the message does not name $named"
    compgen -G "$out/runs/$name.*" | grep -v "\.log$" > /dev/null && problem="an output was written: $(ls "$out/runs/$name".* | grep -v '\.log$')"
  fi
  checked=$((checked + 1))
  if [[ -n $problem ]]; then
    failed=$((failed + 1))
    echo "FAIL $name: $problem"
    sed 's/^/    /' "$out/runs/$name.log" | tail -3
  else
    echo "ok   $name (exit $code)$( [[ $expected == 2 ]] && echo ": $(grep -o -- "$named[^ ]*" "$out/runs/$name.log" | head -1)")"
  fi
}

# Line number where the block holding line N ends (a block: consecutive lines with the same
# first `fields` fields), so that a cut there leaves whole blocks only.
block_end() {
  awk -v n="$2" -v k="$3" '{ key = ""; for (i = 1; i <= k; ++i) key = key " " $i }
    NR > n && key != last { print NR - 1; exit } { last = key }' "$1"
}

# WAMIT: the complete files run; each cut copy is refused naming the file.
restore
run_case wamit_complete Spar 0 "$deck"
for file in Spar.1 Spar.3 Spar.hst; do
  lines=$(wc -l < "$hydro/$file")
  half=$((lines / 2))
  fields=1 && [[ $file == Spar.3 ]] && fields=2
  # Inside a number, at the last byte, at a line end inside a block, and at a block boundary (the
  # file then holds whole periods only: only the .1/.3 comparison of periods finds it).
  cuts=("bytes:3" "bytes:9" "bytes:1" "bytes:100" "lines:$((half + 3))" "lines:$(block_end "$hydro/$file" "$half" "$fields")")
  for cut in "${cuts[@]}"; do
    restore
    kind=${cut%%:*} n=${cut#*:}
    if [[ $kind == bytes ]]; then head -c -"$n" "$hydro/$file" > "$out/deck/hd/$file"; else head -n "$n" "$hydro/$file" > "$out/deck/hd/$file"; fi
    run_case "${file/./_}_${kind}_$n" "$file" 2 "$deck"
  done
done

# BeamDyn: the blade file cut inside its last number (9 bytes: 7.000000E-01 read as 7.0), by its
# last byte, mid-table and after a whole station; the primary file cut in half.
restore
run_case beamdyn_complete bd_driver 0 "$out/bd/bd_driver.inp"
props_lines=$(wc -l < "$beamdyn/beam_props.inp")
for cut in "bytes:9" "bytes:1" "bytes:40" "lines:$((props_lines / 2))" "lines:$((props_lines - 15))"; do
  restore
  kind=${cut%%:*} n=${cut#*:}
  if [[ $kind == bytes ]]; then head -c -"$n" "$beamdyn/beam_props.inp" > "$out/bd/beam_props.inp"; else head -n "$n" "$beamdyn/beam_props.inp" > "$out/bd/beam_props.inp"; fi
  run_case "beam_props_${kind}_$n" beam_props.inp 2 "$out/bd/bd_driver.inp"
done
restore
head -n "$(($(wc -l < "$beamdyn/bd_primary.inp") / 2))" "$beamdyn/bd_primary.inp" > "$out/bd/bd_primary.inp"
run_case bd_primary_half bd_primary.inp 2 "$out/bd/bd_driver.inp"

echo "truncated_inputs: $checked runs checked (WAMIT .1/.3/.hst and BeamDyn cuts refused with exit 2, the file named and nothing written; the complete files run), $failed failed"
[[ $failed == 0 ]]

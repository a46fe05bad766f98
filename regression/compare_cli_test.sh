#!/usr/bin/env bash
# regression/compare_cli_test.sh FOWTSIM REFERENCE SHARED_DIR SCRATCH
# `fowtsim compare` exit codes (0 pass, 1 fail, 2 error) on our files, and reading the real
# OpenFAST outputs under SHARED_DIR/reference (skipped, with a message, when absent).
set -uo pipefail
fowtsim=$1 reference=$2 shared=$3 scratch=$4
mkdir -p "$scratch"
failures=0
expect() {  # expect CODE DESCRIPTION -- command…
  local want=$1 what=$2; shift 3
  "$@" > "$scratch/last.txt" 2>&1
  local got=$?
  if [ "$got" -ne "$want" ]; then
    echo "FAIL: $what: exit $got, expected $want"; cat "$scratch/last.txt"; failures=$((failures + 1))
  else
    echo "ok:   $what (exit $got)"
  fi
}

expect 0 "identical files pass" -- "$fowtsim" compare "$reference" "$reference"

# One channel (ToySlowPos, column 2) scaled by 1.01 in every data row (rows start after the units line).
awk 'BEGIN{OFS="\t"} f && NF>1 {$2 = sprintf("%.9E", $2 * 1.01)} /^\(s\)/ {f=1} {print}' "$reference" > "$scratch/perturbed.out"
expect 1 "one channel perturbed by 1 % fails" -- "$fowtsim" compare "$reference" "$scratch/perturbed.out" --rtol 1e-3 --atol 1e-6
grep -q "ToySlowPos .*FAIL" "$scratch/last.txt" || { echo "FAIL: the perturbed channel is not the one reported"; failures=$((failures + 1)); }
[ "$(grep -c 'PASS$' "$scratch/last.txt")" -ge 8 ] || { echo "FAIL: the untouched channels should pass"; failures=$((failures + 1)); }
expect 0 "the same perturbation passes a 2 % tolerance" -- "$fowtsim" compare "$reference" "$scratch/perturbed.out" --rtol 0.02 --atol 1e-6
expect 1 "a requested channel missing from the test fails" -- "$fowtsim" compare "$reference" "$reference" --channels ToySlowPos,NoSuchChannel
expect 2 "a missing file is an error" -- "$fowtsim" compare "$reference" "$scratch/does-not-exist.out"

if [ -d "$shared/reference" ]; then
  while IFS= read -r -d '' f; do
    expect 0 "reads OpenFAST output ${f#"$shared"/}" -- "$fowtsim" compare "$f" "$f"
  done < <(find "$shared/reference" -name '*.out' -print0 | sort -z)
else
  echo "SKIPPED: OpenFAST reference outputs (no $shared/reference)"
fi
exit $((failures > 0))

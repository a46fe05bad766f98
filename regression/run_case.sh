#!/usr/bin/env bash
# regression/run_case.sh FOWTSIM DECK REFERENCE TOLERANCES OUTDIR
# Runs DECK, then compares both output formats against the stored REFERENCE channel by channel.
set -euo pipefail
fowtsim=$1 deck=$2 reference=$3 tolerances=$4 outdir=$5
rm -rf "$outdir" && mkdir -p "$outdir"
"$fowtsim" run "$deck" -o "$outdir/run" --out-format both
"$fowtsim" compare "$reference" "$outdir/run.h5" --tolerances "$tolerances"
"$fowtsim" compare "$reference" "$outdir/run.out" --tolerances "$tolerances"

# Sourced by the regression scripts that compare with OpenFAST v5's OC3 ten-minute run: sets
# `root` (the repository), `inputs`, `runs` (the OpenFAST case folder) and `reference` (its
# `…_600s.out`), creates `$out`, and exits with CTest's skip code 4 when the reference data is
# absent. Needs `here` (the calling script's folder) and `out`.
root=$(cd "$here/../.." && pwd)
inputs=$root/inputs
runs=$(cd "$root/.." && pwd)/shared/reference/openfast-runs/oc3_spar_wturb_wavesirr/glue-codes/openfast
reference=$runs/5MW_OC3Spar_DLL_WTurb_WavesIrr/5MW_OC3Spar_DLL_WTurb_WavesIrr_600s.out
if [ ! -f "$reference" ]; then
  echo "SKIPPED: no OpenFAST OC3 600-s run at $reference"
  exit 4  # CTest SKIP_RETURN_CODE, as the C++ tests
fi
mkdir -p "$out"

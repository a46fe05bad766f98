#!/usr/bin/env bash
# regression/seed_table43/run_seed_cases.sh FOWTSIM OUTDIR
# The six cases of seed 000 Table 4.2 (inputs/seed_cases/, 800 s from rest, two at a time), then
# `fowtsim post` on 200–800 s: the DELs of Table 4.3 (del_table43.yaml), the proper orthogonal modes
# of blade 1 in the typical cases and the platform-pitch spectra; table43.py prints the comparison
# with the seed and checks the seed's findings. Figures: tools/plot into OUTDIR/plots.
set -euo pipefail
fowtsim=$1 out=$2
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
decks=$here/../../inputs/seed_cases
rm -rf "$out" && mkdir -p "$out"
cases=(table42_120m_fixed table42_120m_typical table42_120m_extreme table42_74m_fixed table42_74m_typical table42_74m_extreme)
printf '%s\n' "${cases[@]}" | xargs -P 2 -I{} sh -c "'$fowtsim' run '$decks/{}.yaml' -o '$out/{}.h5' > '$out/{}.log' 2>&1 || { cat '$out/{}.log'; exit 1; }"
files=()
for c in "${cases[@]}"; do files+=("$out/$c.h5"); done
for config in table43 plain; do
  "$fowtsim" post "${files[@]}" --window 200 800 --del-config "$here/del_$config.yaml" \
    --channels RootMxyb1,RootFxyb1,RootFzb1,RotTorq,PtfmPitch,BldPitch1,GenPwr -o "$out/dels_$config.csv" > "$out/dels_$config.txt"
done
"$fowtsim" post "$out/table42_120m_typical.h5" "$out/table42_74m_typical.h5" --window 200 800 --channels PtfmPitch \
  --psd-channels PtfmPitch,RootMyb1 --pom 'B1N*_TD?r' -o "$out/modes.h5" --plot "$out/plots" > "$out/modes.txt"
/usr/bin/python3 "$here/table43.py" "$out"

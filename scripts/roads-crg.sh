#!/bin/sh
# Draws docs/roads-crg.png (and .svg): the effective road of a tire over one track of an
# OpenCRG road against the track's raw profile, for the README's "Roads from other tools":
#   sh scripts/roads-crg.sh path/to/tirenv path/to/halfround_6in.crg [OUTDIR]
# The road is Project Chrono's halfround_6in.crg (data/vehicle/terrain/crg_roads/, BSD-3: a
# 6 inch half-round across a flat road, 1 cm grid, binary KRBI). The default tire at
# 17860 N, about the ring reference tire's load at the paper's middle regime (17848 N at its
# 0.33 m patch, tirenv flat --model ring); the track at v = 0.9 m, every 2 mm over the
# obstacle. Writes
# OUTDIR/roads-crg.dat (block 0: the raw track, x and z; block 1: x and h of each model, all in
# m and mm), then runs gnuplot in OUTDIR on docs/roads-crg.gp (kept in the repository beside
# the .dat it reads; run it by hand from docs/).
# SPDX-License-Identifier: Apache-2.0
set -eu
bin=$1 road=$2 out=${3:-docs}
gp=$(cd "$(dirname "$0")/../docs" && pwd)/roads-crg.gp
load=17860
track=0.9
sweep="--x-from 48.8 --x-to 51.5 --dx 0.002"
models="rigid springs ring cam"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

"$bin" convert --profile "$road" --track $track -o "$work/raw.csv" 2>/dev/null
for m in $models; do
    "$bin" envelope --model $m --profile "$road" --track $track --load $load $sweep \
        -o "$work/$m.csv" 2>/dev/null
done
{
    echo "# Effective road over a track of an OpenCRG road: $(basename "$road"), v = $track m,"
    echo "# the default tire at $load N ($("$bin" --version))."
    echo "# block 0: the raw track, x_m z_mm (the road file's 1 cm rows)"
    grep -v '^#' "$work/raw.csv" | awk -F, 'NR > 1 && $1 >= 48.8 && $1 <= 51.5 {
        printf "%.4f %.3f\n", $1, 1000 * $2 }'
    printf '\n\n# block 1: x_m, then h_mm of each model: %s\n' "$models"
    paste -d, "$work/rigid.csv" "$work/springs.csv" "$work/ring.csv" "$work/cam.csv" |
        awk -F, 'NR > 1 { printf "%.4f %.3f %.3f %.3f %.3f\n", $1, 1000 * $3, 1000 * $11,
            1000 * $19, 1000 * $27 }'
} >"$out/roads-crg.dat"
cd "$out"
gnuplot "$gp"

#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# --crg-nan-mode: what a missing OpenCRG grid value a track needs becomes (keep: an error,
# nearest: the nearest valid value of its cross section, a number: that height, file: the
# file's GRID_NAN_MODE), for convert and the commands that take --profile; refused where it
# has no meaning. tests/data/nan_border.crg misses the left long section in rows 2 and 3.
# Usage: tests/cli/cli_crg_nan.sh BIN TESTDATA_DIR
# shellcheck disable=SC2016,SC2034,SC2086
. "$(dirname "$0")/../lib/clilib.sh"
road=$data/nan_border.crg

run "$bin" convert --profile "$road" --track 1 -o t.csv
check "without the option or a GRID_NAN_MODE in the file: exit 2, naming the row, nothing written" \
    '[ $rc -eq 2 ] && grep -q "row 2 (u = 0.5 m)" err && [ ! -e t.csv ]'
run "$bin" convert --profile "$road" --track 1 --crg-nan-mode keep -o t.csv
check "keep: the same error" '[ $rc -eq 2 ] && grep -q "no value" err && [ ! -e t.csv ]'
run "$bin" convert --profile "$road" --track 1 --crg-nan-mode nearest -o t.csv
check "nearest: rows 2 and 3 take the cross section's nearest values 0.021 and 0.022" \
    '[ $rc -eq 0 ] && [ "$(grep -v "^#" t.csv | tr "\n" " ")" = "x_m,z_m 0,0.03 0.5,0.021 1,0.022 1.5,0.033 2,0.034 " ]'
run "$bin" convert --profile "$road" --track 0.5 --crg-nan-mode -0.125 -o t.csv
check "a number: the missing values are that height (v = 0.5: halfway to it)" \
    '[ $rc -eq 0 ] && grep -q "^0.5,-0.052" t.csv && grep -q "^1.5,0.028" t.csv'
sed 's/^\* none$/GRID_NAN_MODE = 1\nGRID_NAN_OFFSET = 0.5/' "$road" >mods.crg
run "$bin" convert --profile mods.crg --track 1 --crg-nan-mode file -o t.csv
check "file: the file's GRID_NAN_MODE 1 with its offset 0.5" '[ $rc -eq 0 ] && grep -q "^0.5,0.5$" t.csv'
awk '/^\$ROAD_CRG_MODS/ { skip = 1; next } skip && /^\$/ { skip = 0; if ($0 == "$") next } !skip' \
    "$road" >defaults.crg
run "$bin" convert --profile defaults.crg --track 1 -o t.csv
check "without a modifiers section, OpenCRG's defaults: GRID_NAN_MODE 2, and REFPOINT_Z = 0 at
      (u = 0, v = -1) puts every height 0.010 m lower" \
    '[ $rc -eq 0 ] && grep -v "^#" t.csv | awk -F, "NR > 1 { split(\"0.02 0.011 0.012 0.023 0.024\", e, \" \");
      if (\$2 - e[NR - 1] > 1e-15 || e[NR - 1] - \$2 > 1e-15) bad = 1; n++ } END { exit bad || n != 5 }"'
rm -f t.csv
run "$bin" convert --profile defaults.crg --track 1 --crg-nan-mode keep -o t.csv
check "... and --crg-nan-mode keep still refuses the missing values" '[ $rc -eq 2 ] && [ ! -e t.csv ]'
rm -f t.csv
run "$bin" convert --profile mods.crg --track 1 --crg-nan-mode keep -o t.csv
check "the option overrides the file's mode" '[ $rc -eq 2 ] && [ ! -e t.csv ]'
run "$bin" envelope --model rigid --profile "$road" --track 1 --crg-nan-mode nearest --load 3000 \
    --x-from 0.5 --x-to 1.5 --dx 0.5 -o e.csv
check "envelope takes it too" '[ $rc -eq 0 ] && [ "$(wc -l <e.csv)" -eq 4 ]'
run "$bin" convert --profile "$road" --track 1 --crg-nan-mode bogus -o t.csv
check "a bad mode: usage error (exit 1) naming what is expected" \
    '[ $rc -eq 1 ] && grep -q "keep, nearest, file or a height" err'
printf 'x_m,z_m\n0,0\n1,0\n' >flat.csv
run "$bin" envelope --model rigid --profile flat.csv --crg-nan-mode nearest --load 3000 -o e.csv
check "envelope over a CSV road: exit 1, it applies to an OpenCRG road" \
    '[ $rc -eq 1 ] && grep -q "applies to an OpenCRG road" err'
run "$bin" envelope --model rigid --cleat 0.1,0.05 --crg-nan-mode nearest --load 3000 -o e.csv
check "with a generated obstacle: exit 1" '[ $rc -eq 1 ] && grep -q "crg-nan-mode applies to a road file" err'
clilib_done

#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# End-to-end checks of tirenv road and the cam model: the ISO 8608 road's file, the cam over it,
# and --stream writing the whole-profile CSV byte for byte.
# Usage: tests/cli/cli_road_cam.sh BIN TESTDATA_DIR. TAP lines, as tests/cli/cli.sh, from which it
# was split so that CTest runs the parts side by side.
# shellcheck disable=SC2016,SC2034,SC2086
. "$(dirname "$0")/../lib/clilib.sh"

# --- road and the cam model ------------------------------------------------------------
run "$bin" road --class C --length 50 --dx 0.01 --seed 3 -o road.csv
check "road: exit 0, '#' header naming the class and seed, x_m,z_m, 5001 vertices from 0,0" \
    '[ $rc -eq 0 ] && grep -q "^# ISO 8608 class C" road.csv && grep -q "seed 3" road.csv &&
     [ "$(grep -v "^#" road.csv | head -n 1)" = x_m,z_m ] &&
     [ "$(grep -v "^#" road.csv | sed -n 2p)" = 0,0 ] &&
     [ $(grep -vc "^#" road.csv) -eq 5002 ] && grep -q "rms .* mm" err'
run "$bin" road --class C --length 50 --dx 0.01 --seed 3 -o road2.csv
check "road: same seed, same file" '[ $rc -eq 0 ] && cmp -s road.csv road2.csv'
run "$bin" road --class Q --length 50 -o o.csv
check "road --class Q: exit 1 naming A to H" '[ $rc -eq 1 ] && grep -q "A to H" err && no_file o.csv'
run "$bin" road --class C -o o.csv
check "road without --length: exit 1" '[ $rc -eq 1 ] && grep -q -- "--length" err && no_file o.csv'
run "$bin" road --class C --length 50 --dx 0.5 -o o.csv
check "road --dx too coarse for the band: exit 2 naming dx, no file" \
    '[ $rc -eq 2 ] && grep -q "dx" err && no_file o.csv'
run "$bin" envelope --model cam --profile road.csv --load 12000 --dx 0.01 -o rc.csv
check "envelope --model cam over the generated road" \
    '[ $rc -eq 0 ] && [ "$(head -n 1 rc.csv)" = x_m,z_m,h_m,slope,fx_N,fz_N,contacts,iterations ] &&
     grep -q "cam model" err'
run "$bin" envelope --model cam --cleat 0.30,0.10 --contact-length 0.33 -o cam.csv
check "envelope --model cam: the tandem rides the 0.30 x 0.10 m cleat's full height" \
    '[ $rc -eq 0 ] && grep -q "peak h 100.000 mm" err && [ "$(sed -n 2p cam.csv | cut -d, -f7,8)" = 2,0 ]'
run "$bin" flat --model cam --contact-length 0.33 --csv
check "flat --model cam --contact-length 0.33: contact length 0.33" \
    '[ $rc -eq 0 ] && [ "$(sed -n 2p out | cut -d, -f4)" = 0.33 ]'
# The stiffness is the vertical law's tangent: VERTICAL_STIFFNESS at FNOMIN (docs section 7.3).
run "$bin" flat --model cam --load 17900 --csv
check "flat --model cam --load 17900 (FNOMIN): the stiffness is VERTICAL_STIFFNESS" \
    '[ $rc -eq 0 ] && [ "$(sed -n 2p out | cut -d, -f5)" = 371000 ]'
# The warm start carries over from window to window, so --stream writes the whole-profile
# CSV byte for byte, iterations included.
for m in rigid springs cam; do
    run "$bin" envelope --model $m --profile road.csv --load 12000 --dx 0.01 -o whole_$m.csv
    run "$bin" envelope --model $m --profile road.csv --load 12000 --dx 0.01 --stream \
        -o stream_$m.csv
    check "envelope --model $m --stream: the whole-profile CSV, byte for byte" \
        '[ $rc -eq 0 ] && cmp -s whole_$m.csv stream_$m.csv && grep -q "$m model" err &&
         [ $(rows stream_$m.csv) -eq 5141 ]'
done
printf 'x_m,z_m\n0,0\n1,0.01\n0.5,0\n' >late.csv
run "$bin" envelope --model rigid --profile late.csv --load 1e4 --stream -o o.csv
check "envelope --stream over a malformed profile: exit 2 naming file:line, no file" \
    '[ $rc -eq 2 ] && grep -q "late.csv:4" err && no_file o.csv'
run "$bin" envelope --model rigid --cleat 0.1,0.02 --load 1e4 --stream -o o.csv
check "envelope --stream without --profile: exit 1" '[ $rc -eq 1 ] && no_file o.csv'
# ELLIPS_MAX_STEP: a 40 mm cleat 30 m down a 40 m road, beyond the first chunks; each way of
# sweeping it names the same first position, and the curve is the same bytes.
awk 'BEGIN { print "x_m,z_m"; for (k = 0; k <= 4000; ++k)
             printf "%.2f,%s\n", k / 100, (k >= 3000 && k < 3020) ? "0.04" : "0" }' >step.csv
for way in "--jobs 1" "--jobs 2" "--jobs 1 --stream" "--jobs 2 --stream"; do
    tag=$(echo $way | tr -d ' -')
    run "$bin" envelope --model cam --profile step.csv --load 12000 --dx 0.01 \
        --set ELLIPS_MAX_STEP=0.025 $way -o step_$tag.csv
    grep "warning" err >step_$tag.warn
done
check "ELLIPS_MAX_STEP: one warning at the cleat, the same whatever the jobs and --stream" \
    '[ $rc -eq 0 ] && [ $(wc -l <step_jobs1.warn) -eq 1 ] &&
     grep -q "at x = 29\.[0-9]* m a cam touches the ground .* mm above its lowest point" step_jobs1.warn &&
     grep -q "ELLIPS_MAX_STEP (25 mm)" step_jobs1.warn &&
     cmp -s step_jobs1.warn step_jobs2.warn && cmp -s step_jobs1.warn step_jobs1stream.warn &&
     cmp -s step_jobs1.warn step_jobs2stream.warn && cmp -s step_jobs1.csv step_jobs2stream.csv'
run "$bin" envelope --model cam --profile step.csv --load 12000 --dx 0.01 -o step_none.csv
check "without ELLIPS_MAX_STEP: no warning, the same curve" \
    '[ $rc -eq 0 ] && ! grep -q warning err && cmp -s step_none.csv step_jobs1.csv'
run "$bin" help
check "help lists road" '[ $rc -eq 0 ] && grep -q "^  road " out'

clilib_done

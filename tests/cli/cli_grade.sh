#!/bin/sh
# Roads with elevation and grade from the command line (docs/models.md sections 2.5 and 2.6):
# a road at 2.1 m climbing 5 % runs with every streaming model, whole and streamed alike;
# --relative-to datum (the default) keeps the grade in h, --relative-to ground takes the road's
# local level out (on the straight grade the rigid disc's h is then R0*(sqrt(1 + s^2) - 1));
# on level ground at 0 both are the same, byte for byte; over several tracks of an OpenCRG
# road h less the mean of their levels, streamed too; a bad value is misuse.
# Usage: tests/cli/cli_grade.sh BIN TESTDATA_DIR. SPDX-License-Identifier: Apache-2.0
# shellcheck disable=SC2016,SC2034,SC2086
. "$(dirname "$0")/../lib/clilib.sh"

# 40 m: level at 2.1 m, then 5 % up over 30 m with a 0.2 x 0.05 m cleat on the grade at 20 m,
# level at 3.6 m beyond.
awk 'BEGIN {
    print "x_m,z_m"
    print "0,2.1"
    for (i = 0; i <= 300; i++) {
        x = 5 + 0.1 * i; z = 2.1 + 0.05 * (x - 5)
        if (x > 19.95 && x < 20.25) continue
        print x "," z
        if (i == 149) {
            b = 2.1 + 0.05 * 14.95
            print "19.95," b; print "19.95," b + 0.05
            print "20.15," b + 0.05 + 0.01; print "20.15," 2.1 + 0.05 * 15.15
        }
    }
    print "40,3.6"
}' >road.csv

# The tire's radius pinned, so that the closed form below does not hang on the default tire.
tire='--set UNLOADED_RADIUS=0.7123'
for model in rigid springs cam point; do
    run "$bin" envelope --model $model --profile road.csv --load 12000 --x-from 1 --x-to 39 \
        --dx 0.01 $tire -o $model.csv
    check "$model over a road at 2.1 m climbing 5 %: a curve" \
        '[ "$rc" -eq 0 ] && [ "$(rows $model.csv)" -eq 3801 ]'
    run "$bin" envelope --model $model --profile road.csv --load 12000 --x-from 1 --x-to 39 \
        --dx 0.01 $tire --stream -o $model-s.csv
    check "$model streamed: the same bytes" '[ "$rc" -eq 0 ] && cmp -s $model.csv $model-s.csv'
    run "$bin" envelope --model $model --profile road.csv --load 12000 --x-from 1 --x-to 39 \
        --dx 0.01 $tire --relative-to ground -o $model-g.csv
    check "$model relative to the ground: a curve" '[ "$rc" -eq 0 ]'
    run "$bin" envelope --model $model --profile road.csv --load 12000 --x-from 1 --x-to 39 \
        --dx 0.01 $tire --relative-to ground --stream -o $model-gs.csv
    check "$model relative to the ground, streamed: the same bytes" \
        '[ "$rc" -eq 0 ] && cmp -s $model-g.csv $model-gs.csv'
done

# On the straight grade (x in 8..16 m, far from the level stretches and the cleat), h relative
# to the datum is the road plus the offset, relative to the ground the offset alone.
check "rigid, datum: h follows the road (2.1 m + 5 %) plus R0*(sqrt(1+s^2)-1)" \
    'awk -F, "NR > 1 && \$1 >= 8 && \$1 <= 16 {
        want = 2.1 + 0.05 * (\$1 - 5) + 0.7123 * (sqrt(1.0025) - 1)
        d = \$3 - want; if (d < 0) d = -d; if (d > 2e-6) bad++; n++ }
        END { exit !(n > 700 && bad == 0) }" rigid.csv'
check "rigid, ground: h is R0*(sqrt(1+s^2)-1) = 0.890 mm along the grade" \
    'awk -F, "NR > 1 && \$1 >= 8 && \$1 <= 16 {
        d = \$3 - 0.7123 * (sqrt(1.0025) - 1); if (d < 0) d = -d; if (d > 2e-6) bad++; n++ }
        END { exit !(n > 700 && bad == 0) }" rigid-g.csv'
check "point, ground: h is 0 along the grade" \
    'awk -F, "NR > 1 && \$1 >= 8 && \$1 <= 16 { d = \$3; if (d < 0) d = -d; if (d > 1e-8) bad++ }
        END { exit bad > 0 }" point-g.csv'
check "springs, ground: the cleat on the grade stands out, up to about its 5 cm" \
    'awk -F, "NR > 1 && \$1 > 19 && \$1 < 21 && \$3 > m { m = \$3 } END { exit !(m > 0.035 && m < 0.065) }" springs-g.csv'
check "z_m is the centre's height either way" \
    'cut -d, -f1,2 springs.csv >a && cut -d, -f1,2 springs-g.csv >b && cmp -s a b'

# Several tracks of a banked OpenCRG road: h less the mean of the tracks' levels, streamed as
# in whole mode (the stream took the level of --track alone: 1,958 of 2,341 rows differed).
banked="$data/samples/crg/handmade_banked.crg"
run "$bin" envelope --model rigid --profile "$banked" --tracks 3 --relative-to ground \
    --load 4000 --dx 0.01 -o b3.csv
check "three tracks of a banked road relative to the ground: a curve" '[ "$rc" -eq 0 ]'
for j in 1 2; do
    run "$bin" envelope --model rigid --profile "$banked" --tracks 3 --relative-to ground \
        --load 4000 --dx 0.01 --stream --jobs $j -o b3-$j.csv
    check "... streamed with --jobs $j: the same bytes" '[ "$rc" -eq 0 ] && cmp -s b3.csv b3-$j.csv'
done

# Level ground at 0: the level is 0, and the two are the same bytes.
run "$bin" envelope --model springs --cleat 0.30,0.10 --contact-length 0.33 -o c.csv
run "$bin" envelope --model springs --cleat 0.30,0.10 --contact-length 0.33 \
    --relative-to ground -o cg.csv
check "a cleat on level ground: ground and datum give the same bytes" \
    '[ "$rc" -eq 0 ] && cmp -s c.csv cg.csv'

run "$bin" envelope --model rigid --cleat 0.30,0.10 --load 1000 --relative-to road -o x.csv
check "--relative-to road: misuse, exit 1, naming the choices" \
    '[ "$rc" -eq 1 ] && grep -q "ground or datum" err && no_file x.csv'
run "$bin" envelope --help
check "--help explains --relative-to and its default" \
    '[ "$rc" -eq 0 ] && grep -q "relative-to" out && grep -q "datum (default)" out'
run "$bin" predict --help
check "predict takes --relative-to too" '[ "$rc" -eq 0 ] && grep -q "relative-to" out'

clilib_done

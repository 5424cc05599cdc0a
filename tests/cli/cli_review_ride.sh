#!/bin/sh
# What a user's review of tirenv ride found, each checked so that it stays fixed: its plots,
# a level road's crest factor, a dt too fine, the balance of load and input on a jump
# (docs/perf-s24-qa.md lists what was tried). Usage: sh cli_review_ride.sh BIN TESTDATA_DIR.
# SPDX-License-Identifier: Apache-2.0
. "$(dirname "$0")/../lib/clilib.sh"

# A ride over a level road has no vibration and so no crest factor (0/0): the tables say '-',
# not nan as if a figure; the CSV keeps nan, which its readers take for a missing value. Its
# plot: a way of enveloping is dashed only where the run draws a model both ways; the default
# alone (dynamic) keeps each model's own line, which over a road's dense oscillation dashes
# made unreadable; x spans the run, not a fifth more on either side.
printf 'x_m,z_m\n0,0\n' >level.csv
run "$bin" ride --profile level.csv --speed 10km/h --model point,cam --jobs 1 --out-dir level
check "ride over a level road: crest '-' in the printed table and comfort.md, nan in the CSV" \
    '[ $rc -eq 0 ] && ! grep -qi nan out && grep -qE "^point +10.00 +0.0000 +- " out &&
     grep -q "| point | dynamic | 10.0 | 0.000 | - |" level/comfort.md &&
     grep -q "^point,.*,0,nan,0," level/comfort.csv'
check "... one way of enveloping: no line of seat.gp dashed, x fixed to the run" \
    '[ "$(grep -c "^set style line" level/seat.gp)" -eq 2 ] &&
     ! grep -q "^set style line.* dt [2-9]" level/seat.gp &&
     grep -q "set autoscale xfix" level/seat.gp'
run "$bin" ride --profile level.csv --speed 10km/h --model cam --enveloping static,dynamic \
    --jobs 1 --out-dir both
check "ride, static and dynamic: the dynamic line dashed, the static one not" \
    '[ $rc -eq 0 ] && grep -q "dt 1 *# cam-static" both/seat.gp &&
     grep -q "dt 2 *# cam-dynamic" both/seat.gp'

# ride --dt finer than the weighting filters take: refused before the run as --dt, exit 1 (it
# ran, then failed as bad data in the field fs).
run "$bin" ride --cleat 0.3,0.05 --speed 10km/h --model point --dt 1e-6 --jobs 1
check "ride --dt 1e-6: exit 1 naming --dt and the finest it takes, 1e-05 s" \
    '[ $rc -eq 1 ] && grep -q -- "--dt: 1e-06 s is finer.*at least 1e-05 s" err'

# The ride's balance of load and input on a jump of the springs model's effective road with
# the load: over a class H road the Illinois steps crawled and the ride stopped, exit 3, with a
# bracket 9e-6 N wide; bisection past their budget closes it.
"$bin" road --class H --length 3 --dx 0.01 --seed 2 -o roadH.csv 2>/dev/null
run "$bin" ride --profile roadH.csv --speed 10km/h --model springs --jobs 1
check "ride, springs over a class H road: the balance found on its jump, exit 0" \
    '[ $rc -eq 0 ] && grep -qE "^springs +10.00 " out'

clilib_done

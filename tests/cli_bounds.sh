#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# Counts and values from input bounded before they are used (issue 27): positions from
# --x-from/--x-to/--dx (--stream included), lines longer than the readers' cap in the middle
# of a file, and tire and vehicle values outside their plausible ranges, each refused with a
# message naming the option, line or key, exit 1 or 2, quickly, and no output left.
. "$(dirname "$0")/clilib.sh"

printf 'x_m,z_m\n0,0\n1,0.05\n2,0\n' >p.csv

# Each of these hung, or wrote gigabytes, or printed a 301-digit count.
for args in "--x-to 1e300" "--x-to 1e9" "--x-from -1e300 --x-to 1e300" "--dx 1e-300"; do
    for mode in "" "--stream"; do
        run timeout 20 "$bin" envelope --model springs --load 13000 --profile p.csv $mode \
            $args -o out.csv
        check "envelope $mode $args: exit 1, 'too many' with the cap, no output" \
            '[ $rc -eq 1 ] && grep -q "positions from .* is too many (at most 10*)" err &&
             [ "$(wc -c <err)" -lt 200 ] && no_file out.csv'
    done
done
run timeout 20 "$bin" envelope --model springs --load 13000 --profile p.csv --stream \
    --x-from 1e300 --x-to 1e300 -o out.csv
check "--stream at x = 1e300: exit 1, the step does not move x" \
    '[ $rc -eq 1 ] && grep -q "does not move x" err && no_file out.csv'
# The cap of --stream is higher than a whole sweep's: 2e7 positions stream (not run: counted).
run timeout 20 "$bin" envelope --model springs --load 13000 --profile p.csv --x-to 2e4 \
    -o out.csv
check "a whole sweep of 2e7 positions: refused at 1e7" \
    '[ $rc -eq 1 ] && grep -q "at most 10000000)" err'

# A comment line past the 65,536-character cap in the middle of a file: an error at its
# line, never a file read up to it (convert wrote 3 of 6 vertices with exit 0).
long=$(awk 'BEGIN { s = "#"; while (length(s) < 70000) s = s s; print s }')
{ printf 'x_m,z_m\n0,0\n0.5,0\n'; echo "$long"; printf '1,0.05\n1.5,0\n2,0\n'; } >long.csv
run "$bin" convert --profile long.csv -o out.csv
check "convert: a 70,000-character comment on line 4 is an error at line 4" \
    '[ $rc -eq 2 ] && grep -q "long.csv:4: line longer than 65536" err && no_file out.csv'
{ printf '[DIMENSION]\nUNLOADED_RADIUS = 0.7\n'; echo "$long" | tr '#' '!';
  printf '[ENVELOPING_SPRINGS]\nRADIAL_STIFFNESS = 1e6\n'; } >long.tir
run "$bin" flat --model springs --load 13000 --tire long.tir
check "flat: a 70,000-character comment in a .tir is an error at line 3" \
    '[ $rc -eq 2 ] && grep -q "long.tir:3: line longer than 65536" err'

# Values outside the plausible ranges (docs/formats.md sections 1 and 3), named.
for kv in NODE_ANGLE=1e-20 TREAD_STIFFNESS=1e-308 VERTICAL_STIFFNESS=1e-308 \
          ELLIPS_SHIFT=1e308 RADIAL_STIFFNESS=1e308 MAX_ITERATIONS=1000000000; do
    run timeout 20 "$bin" flat --model ring --load 13000 --set "$kv"
    check "--set $kv: exit 2 naming ${kv%%=*} and its range" \
        '[ $rc -eq 2 ] && grep -q "${kv%%=*}" err && grep -q "range\|elements" err'
done
for kv in MASS=1e9 SEAT_AHEAD_OF_CG=1e9 GRAVITY=1e-308 FRONT_AXLE.TIRE_STIFFNESS=1e-308; do
    run timeout 20 "$bin" ride --cleat 0.1,0.05 --speed 2 --set "$kv"
    check "ride --set $kv: exit 2 naming ${kv%%=*}" \
        '[ $rc -eq 2 ] && grep -q "${kv%%=*}: .*plausible range" err'
done

clilib_done

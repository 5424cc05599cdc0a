#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# End-to-end checks of the network over any profile (the equivalent-cleat decomposition,
# nn_road.h) and of the ride with it over a generated road.
# Usage: tests/cli/cli_network_road.sh BIN TESTDATA_DIR. TAP lines, as tests/cli/cli.sh, from which it
# was split so that CTest runs the parts side by side.
# shellcheck disable=SC2016,SC2034,SC2086
. "$(dirname "$0")/../lib/clilib.sh"

# The generated road and a malformed profile the checks below run over.
run "$bin" road --class C --length 50 --dx 0.01 --seed 3 -o road.csv
[ $rc -eq 0 ] || echo "# tirenv road failed (exit $rc): the checks over road.csv fail"
printf 'x_m,z_m\n0,0\n1,0.01\n0.5,0\n' >late.csv

# --- the network over any profile (equivalent-cleat decomposition, nn_road.h) -----------
# The network of the study, trained on the embedded data set (lm, seed 1, one restart).
run "$bin" train --data "$data/../../data/dataset" --restarts 1 -o net.json
check "train on the embedded data set writes a model file" '[ $rc -eq 0 ] && [ -s net.json ]'
run "$bin" envelope --model nn --nn net.json --profile road.csv --contact-length 0.33 \
    --dx 0.01 --extrapolate -o rn.csv
check "envelope --model nn --profile over the generated road: header, 5141 finite rows" \
    '[ $rc -eq 0 ] && [ "$(head -n 1 rn.csv)" = "$header" ] && [ $(rows rn.csv) -eq 5141 ] &&
     grep -q "obstacles above a baseline" err &&
     awk -F, "NR > 1 && (\$3 + 0 != \$3 || \$4 + 0 != \$4) { bad = 1 } END { exit bad }" rn.csv'
# A road too long for the baseline's grid is refused with the count as a number, not 158
# digits that filled the message and cut off what to do.
# The longest a profile can be: 2e9 m (tirenv/profile.h), vertices 1e7 m apart.
awk 'BEGIN { print "x_m,z_m"; for (i = -100; i <= 100; i++) print i "e7," (i ? 0 : 0.05) }' \
    >vast.csv
run "$bin" envelope --model nn --nn net.json --profile vast.csv --contact-length 0.33 \
    --x-from 0 --x-to 1 -o vast-out.csv
check "a 2e9 m road: exit 2, the count as a number and the advice in the message, no file" \
    '[ $rc -eq 2 ] && grep -Eq "needs [0-9]+ baseline points" err &&
     grep -q "raise the spacing" err && no_file vast-out.csv'
# Beyond that the profile is refused as read, naming the row.
printf 'x_m,z_m\n-1e155,0\n0,0.05\n1e155,0\n' >vaster.csv
run "$bin" envelope --model nn --nn net.json --profile vaster.csv --contact-length 0.33 \
    --x-from 0 --x-to 1 -o vast-out.csv
check "a 2e155 m road: exit 2 naming its first row, no file" \
    '[ $rc -eq 2 ] && grep -q "vaster.csv:2:1: x_m: x_m = -1e155 is beyond" err &&
     no_file vast-out.csv'
printf 'x_m,z_m\n-0.05,0\n-0.05,0.075\n0.05,0.075\n0.05,0\n' >cleat.csv
run "$bin" envelope --model nn --nn net.json --profile cleat.csv --contact-length 0.38 -o pc.csv
run "$bin" envelope --model nn --nn net.json --cleat 0.10,0.075 --contact-length 0.38 -o cc.csv
check "envelope --model nn: a cleat as --profile gives --cleat's curve (h within 1e-9 m)" \
    '[ $rc -eq 0 ] && same_h pc.csv cc.csv 1e-9 && near "$(peak_h cc.csv)" 0.04 0.035'
# A bump on a stretch of flat ground (not the bare four corners of a centred cleat, which the
# network takes as its own case, the cleat): with --extrapolate the decomposition clamps it.
printf 'x_m,z_m\n-1,0\n-0.05,0\n-0.05,0.15\n0.05,0.15\n0.05,0\n1,0\n' >tall.csv
run "$bin" predict --nn net.json --profile tall.csv --contact-length 0.38 --extrapolate -o o.csv
check "predict --profile with a bump above the trained heights: one warning with the count" \
    '[ $rc -eq 0 ] && [ $(grep -c "warning: 1 of 1 obstacles outside" err) -eq 1 ] &&
     grep -q "1 heights above 0.1 m" err'
run "$bin" envelope --model nn --nn net.json --profile late.csv --contact-length 0.33 -o nn.csv
check "envelope --model nn over a malformed profile: exit 2 naming file:line, no file" \
    '[ $rc -eq 2 ] && grep -q "late.csv:4" err && no_file nn.csv'
run "$bin" ride --profile road.csv --speed 10km/h --model nn,cam --nn net.json --dx 0.01 \
    --extrapolate
check "ride --model nn,cam over the generated road: a finite row for each" \
    '[ $rc -eq 0 ] && [ $(grep -Ec "^(nn|cam) +10\.00 +[0-9]" out) -eq 2 ]'

clilib_done

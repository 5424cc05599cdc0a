#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# convert of a bounded obstacle (a profile that starts and ends with a wall) to OpenCRG: flat
# ground of --pad m (default 1) is added beyond the walls, so that read back the rigid disc
# sits on the ground before the cleat, not 100 mm up on a plateau; --pad 0 refuses, saying
# how; a profile without a wall at its ends is written as before, and RDF is not padded.
# Usage: tests/cli/cli_convert_pad.sh BIN TESTDATA_DIR
# shellcheck disable=SC2016,SC2034,SC2086
. "$(dirname "$0")/../lib/clilib.sh"
printf 'x_m,z_m\n-0.05,0\n-0.05,0.1\n0.05,0.1\n0.05,0\n' >cleat.csv
run "$bin" convert --profile cleat.csv --dx 0.01 -o cleat.crg
check "a cleat to .crg: padded by 1 m of flat ground at each end (rows from -1.05 to 1.05 m)" \
    '[ $rc -eq 0 ] && grep -aq "^REFERENCE_LINE_START_U   = -1.05" cleat.crg &&
     grep -aq "^REFERENCE_LINE_END_U     = 1.05" cleat.crg'
run "$bin" envelope --model rigid --profile cleat.crg --load 4000 --x-from -0.75 --x-to -0.75 -o d.csv
check "read back, the rigid disc at x = -0.75 m sits on the ground (h = 0), as on the CSV" \
    '[ $rc -eq 0 ] && [ "$(tail -n 1 d.csv | cut -d, -f3)" = "0" ]'
run "$bin" envelope --model rigid --profile cleat.crg --load 4000 --x-from 0 --x-to 0 -o top.csv
check "and on top of the cleat at x = 0 it is 100 mm up" \
    '[ $rc -eq 0 ] && [ "$(tail -n 1 top.csv | cut -d, -f3)" = "0.1" ]'
run "$bin" convert --profile cleat.csv --dx 0.01 --pad 0.25 -o c25.crg
check "--pad 0.25: rows from -0.3 m" '[ $rc -eq 0 ] && grep -aq "^REFERENCE_LINE_START_U   = -0.3" c25.crg'
run "$bin" convert --profile cleat.csv --dx 0.01 --pad 0 -o c0.crg
check "--pad 0: refused (exit 2) naming the wall and --pad, nothing written" \
    '[ $rc -eq 2 ] && grep -q "starts with a wall at x = -0.05 m" err && grep -q -- "--pad M" err && [ ! -e c0.crg ]'
run "$bin" convert --profile cleat.csv --dx 0.01 --pad -1 -o c0.crg
check "--pad -1: usage error" '[ $rc -eq 1 ] && [ ! -e c0.crg ]'
# A pad beyond a profile's longest segment (1e7 m) or its coordinates (1e9 m) is --pad's error;
# it was refused as the profile's, "cleat.csv: x: vertex 1: x = -1e+300 m", a vertex the file
# does not have.
run "$bin" convert --profile cleat.csv --dx 0.01 --pad 1e300 -o big.crg
check "--pad 1e300: refused (exit 2) naming --pad and its bound, not a vertex of the file" \
    '[ $rc -eq 2 ] && grep -q "^tirenv: --pad: 1e+300 m .*expected at most 1e+07 m" err &&
     ! grep -q "vertex" err && [ ! -e big.crg ]'
printf 'x_m,z_m\n-1,0\n-0.05,0\n-0.05,0.1\n0.05,0.1\n0.05,0\n1,0\n' >ground.csv
run "$bin" convert --profile ground.csv --dx 0.01 -o ground.crg
check "a profile with ground at its ends: not padded (rows from -1 m)" \
    '[ $rc -eq 0 ] && grep -aq "^REFERENCE_LINE_START_U   = -1$" ground.crg'
run "$bin" convert --profile cleat.csv -o cleat.rdf
check "to .rdf: not padded (4 vertices)" '[ $rc -eq 0 ] && grep -q "4 vertices" err'
clilib_done

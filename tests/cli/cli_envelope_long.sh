#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# envelope over many positions: written to a file, rows go out as they are computed and the
# 10 M-position cap of the commands that hold their points does not apply (up to 1e8); where
# the points are held (standard output, an effective road) more than 10 M is refused before
# any work, with the limit named, and nothing is written.
# Usage: tests/cli/cli_envelope_long.sh BIN TESTDATA_DIR.
# Conditions are single-quoted for eval; bin, data and rc are clilib's.
# shellcheck disable=SC2016,SC2034,SC2086,SC2154
# shellcheck source=tests/lib/clilib.sh
. "$(dirname "$0")/../lib/clilib.sh"

"$bin" road --class C --length 12 --dx 0.01 --seed 2 -o road.csv 2>/dev/null
many='--x-from 0 --x-to 11 --dx 1e-6'  # 11,000,001 positions
run "$bin" envelope --model cam --profile road.csv --load 4000 $many
check "11 M positions to standard output: refused, naming 10000000 and -o, no row" \
    '[ $rc -ne 0 ] && grep -q "at most 10000000" err && grep -q -- "-o FILE.csv" err &&
     [ ! -s out ]'
run "$bin" envelope --model cam --profile road.csv --load 4000 $many -o road.rdf
check "11 M positions into an effective road: refused, no file" \
    '[ $rc -ne 0 ] && grep -q "at most 10000000" err && no_file road.rdf'
run "$bin" envelope --model cam --profile road.csv --load 4000 --x-from 0 --x-to 11 \
    --dx 1e-9 -o curve.csv
check "11e9 positions to a file: refused, naming the limit 1e8, no file" \
    '[ $rc -ne 0 ] && grep -q "at most 100000000" err && no_file curve.csv'

clilib_done

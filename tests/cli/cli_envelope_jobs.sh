#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# envelope --jobs N: one road's positions in chunks of 8192 on N threads, each chunk solved
# from a cold start at its first position, so that the output is the same bytes for every N,
# written to a file (a round of chunks at a time) or to standard output (all at the end).
# Usage: tests/cli/cli_envelope_jobs.sh BIN TESTDATA_DIR.
# Conditions are single-quoted for eval; bin, data and rc are clilib's.
# shellcheck disable=SC2016,SC2034,SC2086,SC2154
# shellcheck source=tests/lib/clilib.sh
. "$(dirname "$0")/../lib/clilib.sh"

# 30 m every 1 mm: 30,001 positions, four chunks (the last one short).
"$bin" road --class C --length 30 --dx 0.01 --seed 2 -o road.csv 2>/dev/null
sweep='--x-from 0 --x-to 30 --dx 0.001'
for model in springs cam; do
    for j in 1 3; do
        run "$bin" envelope --model $model --profile road.csv $sweep --load 4000 --jobs $j \
            -o $model-$j.csv
        rc_j=$rc
        check "envelope --model $model --jobs $j: exit 0, 30,001 rows" \
            '[ $rc_j -eq 0 ] && [ "$(wc -l <$model-$j.csv)" -eq 30002 ]'
    done
    check "$model: --jobs 3 writes the bytes of --jobs 1" 'cmp -s $model-1.csv $model-3.csv'
done
run "$bin" envelope --model springs --profile road.csv $sweep --load 4000 --jobs 2
check "springs --jobs 2 to standard output: the bytes of the file" \
    '[ $rc -eq 0 ] && cmp -s out springs-1.csv'
for j in 1 2; do
    run "$bin" envelope --model springs --profile road.csv $sweep --load 4000 --jobs $j \
        --relative-to ground -o ground-$j.rdf
done
check "-o .rdf --relative-to ground: --jobs 2 = --jobs 1" \
    '[ $rc -eq 0 ] && [ -s ground-1.rdf ] && cmp -s ground-1.rdf ground-2.rdf'
run "$bin" envelope --model springs --profile road.csv $sweep --load 4000 --jobs 0
check "--jobs 0: a usage error naming --jobs" '[ $rc -ne 0 ] && grep -q -- "--jobs" err'

clilib_done

#!/bin/sh
# --extrapolate (the network outside its trained ranges) where the work runs on --jobs
# threads: sweep passes it to every case's model, and ride's model inputs, computed on the
# jobs, honour it, with the same table for --jobs 1 and 2 apart from the CPU times.
# Usage: tests/cli/cli_jobs_extrapolate.sh BIN TESTDATA_DIR.
# SPDX-License-Identifier: Apache-2.0
# Conditions are single-quoted for eval; bin, data and rc are clilib's.
# shellcheck disable=SC2016,SC2034,SC2086,SC2154
# shellcheck source=tests/lib/clilib.sh
. "$(dirname "$0")/../lib/clilib.sh"

dataset="$data/../../data/dataset"
run "$bin" train --data "$dataset" --restarts 1 --epochs 60 -o net.json
check "a network to test with" '[ $rc -eq 0 ] && [ -s net.json ]'

# A 5 mm cleat is lower than the lowest trained one (25 mm).
grid='--lengths 0.02,0.3 --heights 0.005,0.05 --contact-lengths 0.33'
run "$bin" sweep --model nn --nn net.json $grid --jobs 2 -o s1
check "sweep --model nn over a 5 mm cleat: exit 2 naming the height and --extrapolate" \
    '[ $rc -eq 2 ] && grep -q "obstacle height" err && grep -q -- "--extrapolate" err &&
     no_file s1'
run "$bin" sweep --model nn --nn net.json --extrapolate $grid --jobs 2 -o s2
check "with --extrapolate: the 4 cases written" \
    '[ $rc -eq 0 ] && [ "$(ls s2/curves | wc -l)" -eq 4 ]'

"$bin" road --class C --length 30 --dx 0.01 --seed 1 -o road.csv 2>/dev/null
for j in 1 2; do
    run "$bin" ride --profile road.csv --speed 10km/h,15km/h --model point,nn --nn net.json \
        --dx 0.01 --extrapolate --jobs $j
    rc_j=$rc
    # the table without its CPU columns (cpu_s, x_real time)
    awk '{ NF = NF - 2; print }' out >table-$j.txt
    check "ride --model point,nn --extrapolate --jobs $j: exit 0, 4 rows" \
        '[ $rc_j -eq 0 ] && [ "$(grep -c "^nn \|^point " table-$j.txt)" -eq 4 ]'
done
check "ride: --jobs 2 = --jobs 1 apart from the CPU times" 'cmp -s table-1.txt table-2.txt'

clilib_done

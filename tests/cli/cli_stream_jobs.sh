#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# envelope --stream --jobs N: the road read once, in order, whole mode's chunks of 8192
# positions computed on N threads, each on the piece of road within the tire's reach of its
# positions, the points written in order: the same bytes for every N, and whole mode's, over a
# CSV road (a file and standard input), an OpenCRG road (one track and three) and an RDF road.
# 100,001 positions are 13 chunks, so that --jobs 2 and 3 run two rounds (4 N chunks a round),
# the second round's road read while the first is computed. A wall before metres of level
# ground, a chunk starting on them, streams whole mode's bytes too. An error mid-road (a bad
# row, ground the hub cannot clear), in the second round: --jobs 2 and 3 fail as --jobs 1
# does, the same message, nothing written.
# Usage: tests/cli/cli_stream_jobs.sh BIN TESTDATA_DIR.
# Conditions are single-quoted for eval; bin, data and rc are clilib's.
# shellcheck disable=SC2016,SC2034,SC2086,SC2154
# shellcheck source=tests/lib/clilib.sh
. "$(dirname "$0")/../lib/clilib.sh"

run "$bin" road --class C --length 100 --dx 0.01 --seed 3 -o road.csv
check "setup: a 100 m class C road at 1 cm" '[ $rc -eq 0 ]'
run "$bin" convert --profile road.csv -o road.crg
check "setup: the road as OpenCRG" '[ $rc -eq 0 ]'
sweep='--x-from 0 --x-to 100 --dx 0.001 --load 4000'

# same ROAD WHAT OPTIONS...: whole mode, then --stream with --jobs 1, 2 and 3, all one bytes.
# SAME_JOBS, when set, names the --jobs values instead.
same() {
    road=$1
    what=$2
    shift 2
    run "$bin" envelope --model springs --profile $road $sweep "$@" --jobs 2 -o whole.csv
    check "$what: whole mode, 100,001 rows" \
        '[ $rc -eq 0 ] && [ "$(wc -l <whole.csv)" -eq 100002 ]'
    for j in ${SAME_JOBS:-1 2 3}; do
        run "$bin" envelope --model springs --profile $road $sweep "$@" --stream --jobs $j \
            -o stream-$j.csv
        check "$what: --stream --jobs $j writes whole mode's bytes" \
            '[ $rc -eq 0 ] && cmp -s whole.csv stream-$j.csv'
    done
}
same road.csv "CSV road"
run "$bin" envelope --model springs --profile road.csv $sweep --stream --jobs 2
check "--stream --jobs 2 to standard output: whole mode's bytes" \
    '[ $rc -eq 0 ] && cmp -s out whole.csv'
run sh -c '"$0" envelope --model springs --profile /dev/stdin $1 --stream --jobs 3 <road.csv' \
    "$bin" "$sweep"
check "--stream --jobs 3 from standard input: whole mode's bytes" \
    '[ $rc -eq 0 ] && cmp -s out whole.csv'
# A sweep whose chunks would each span more than 256 m of road (--dx 0.05: 410 m) streams on
# one thread, in the tire's reach: still whole mode's bytes, here 2,001 positions in one chunk.
run "$bin" envelope --model springs --profile road.csv --dx 0.05 --load 4000 --jobs 2 -o sparse-whole.csv
run "$bin" envelope --model springs --profile road.csv --dx 0.05 --load 4000 --stream --jobs 2 \
    -o sparse-stream.csv
check "--dx 0.05 (chunks of 410 m: one thread) --stream --jobs 2: whole mode's bytes" \
    '[ $rc -eq 0 ] && cmp -s sparse-whole.csv sparse-stream.csv && [ "$(wc -l <sparse-stream.csv)" -gt 2000 ]'
run "$bin" convert --profile road.csv -o road.rdf
run "$bin" envelope --model springs --profile road.rdf $sweep --stream --jobs 2 -o rdf.csv
check "an RDF road, --stream --jobs 2: the CSV road's bytes" \
    '[ $rc -eq 0 ] && cmp -s rdf.csv whole.csv'
same road.crg "OpenCRG road"
# Three tracks cost four times one track. The sanitizer build (TIRENV_TEST_SANITIZED=1) streams
# them with --jobs 3 alone: two rounds of chunks on threads, the code --jobs 2 runs (--jobs 1
# and 2 stream one track above); the sanitizers look for memory errors, and the Release
# build compares the bytes of every N.
if [ "${TIRENV_TEST_SANITIZED:-0}" = 1 ]; then
    echo "# sanitizer build: three tracks streamed with --jobs 3 only"
    SAME_JOBS=3
    same road.crg "OpenCRG road, three tracks" --tracks 3
    unset SAME_JOBS
else
    same road.crg "OpenCRG road, three tracks" --tracks 3
fi

# A wall at x = 5 m, then level ground to 80 m: whole mode solves every position there (its test
# for level ground within reach sees the wall's first row behind the reach); chunks 1 and 2
# (from x = 40.96 m) of --stream --jobs 2 were given windows that began at the wall's second
# row, took the level shortcut, and wrote other iterations and fx from position 8192 on.
printf 'x_m,z_m\n0,0.031\n5,0.031\n5,0.012\n80,0.012\n81,0.02\n' >wall.csv
wall='--profile wall.csv --x-from 0 --x-to 82 --dx 0.005 --load 4000'
run "$bin" envelope --model springs $wall --jobs 2 -o wall-whole.csv
for j in 1 2; do
    run "$bin" envelope --model springs $wall --stream --jobs $j -o wall-$j.csv
    check "a wall, then level ground: --stream --jobs $j writes whole mode's bytes" \
        '[ $rc -eq 0 ] && cmp -s wall-whole.csv wall-$j.csv'
done

# fails NAME WHAT: road NAME streamed with --jobs 1, 2 and 3 fails alike, nothing written.
fails() {
    for j in 1 2 3; do
        run "$bin" envelope --model springs --profile $1 $sweep --stream --jobs $j -o e-$j.csv
        cp err err-$j
        rc_j=$rc
        check "$2, --jobs $j: exit 2, no file" '[ $rc_j -eq 2 ] && [ ! -e e-$j.csv ]'
    done
    check "$2: --jobs 2 and 3 say what --jobs 1 says" \
        '[ -s err-1 ] && cmp -s err-1 err-2 && cmp -s err-1 err-3'
}
# Line 8003 is x = 80 m: position 80,000, chunk 9, the second round for --jobs 2 and 3.
awk 'NR == 8003 { print "80,abc"; next } { print }' road.csv >bad.csv
fails bad.csv "a bad row at x = 80 m"
check "the bad row named at its line" 'grep -q "bad.csv:8003:.*z_m" err-2'
awk -F, 'NR == 8003 { print $1 ",2.5"; next } { print }' road.csv >spike.csv
fails spike.csv "ground 2.5 m high at x = 80 m"
check "the hub that cannot clear it named" 'grep -q "hub clears the ground" err-2'

clilib_done

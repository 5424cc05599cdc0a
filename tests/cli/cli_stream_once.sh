#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# envelope --stream reads a CSV road once into a file: its ends from its first and
# last rows, its rows as the tire rolls, those past the sweep after it. Whole mode's bytes, and
# whole mode's error for a bad row anywhere, at its line, with no file: in the middle of the
# sweep, past the sweep's end (read after it), as the last row (its ends then read from the
# start). Written through (standard output), every row is checked first, so a bad row leaves
# standard output empty. An OpenCRG or an RDF road into a file is read once too (its ends from
# the OpenCRG road's pass at open or the RDF road's poly_line, which its readers share): whole
# mode's bytes, and whole mode's error for a track that needs a missing value, mid-sweep or past
# the sweep's end.
. "$(dirname "$0")/../lib/clilib.sh"

cam="--model cam --load 13000"
run "$bin" road --class C --length 30 --dx 0.001 -o road.csv
check "setup: a 30 m class C road at 1 mm" '[ $rc -eq 0 ] && [ "$(rows road.csv)" -gt 30000 ]'

run "$bin" envelope $cam --profile road.csv -o whole.csv
check "whole run" '[ $rc -eq 0 ]'
run "$bin" envelope $cam --profile road.csv --stream -o stream.csv
check "--stream into a file: whole mode's bytes" '[ $rc -eq 0 ] && cmp -s whole.csv stream.csv'
run "$bin" envelope $cam --profile road.csv --stream
check "--stream to standard output: the same bytes" '[ $rc -eq 0 ] && cmp -s whole.csv out'
run "$bin" envelope $cam --profile road.csv --stream --x-from 3 --x-to 4.5 -o part.csv
run "$bin" envelope $cam --profile road.csv --x-from 3 --x-to 4.5 -o part_whole.csv
check "--stream over part of the road: whole mode's bytes" \
    '[ $rc -eq 0 ] && cmp -s part.csv part_whole.csv'

# bad NAME LINE TEXT: road.csv with line LINE replaced by TEXT, as NAME.
bad() {
    awk -v n="$2" -v t="$3" 'NR == n { print t; next } { print }' road.csv >"$1"
}
bad mid.csv 12000 '11.9,abc'
want_error mid.csv
check "setup: whole mode refuses the bad middle row at its line" \
    'grep -q "^tirenv: mid.csv:12000:6: z_m: expected a number" want'
stream_refuses_mid mid.csv
bad back.csv 25000 '5,0'
want_error back.csv
run "$bin" envelope $cam --profile back.csv --stream -o s.csv
check "an x that goes back: whole mode's error, no file" \
    '[ $rc -eq 2 ] && grep -q "back.csv:25000:1: x_m: x_m decreases" err && cmp -s err want &&
     no_file s.csv'
last=$(($(wc -l <road.csv)))
bad end.csv "$last" '29.999,0.1q'
want_error end.csv
run "$bin" envelope $cam --profile end.csv --stream -o s.csv
check "a bad last row (the road's end): whole mode's error at its line, no file" \
    '[ $rc -eq 2 ] && grep -q "end.csv:$last:" err && cmp -s err want && no_file s.csv'

# OpenCRG (text, so that a value can be taken out) and RDF roads of the first 10 m.
awk -F, '/^#/ || $1 == "x_m" || $1 <= 10' road.csv >short.csv
run "$bin" convert --profile short.csv --crg-encoding ldfi -o road.crg
check "setup: road.crg (LDFI)" '[ $rc -eq 0 ]'
run "$bin" convert --profile short.csv -o road.rdf
check "setup: road.rdf" '[ $rc -eq 0 ]'
for f in crg rdf; do
    run "$bin" envelope $cam --profile road.$f -o whole.csv
    check "$f: whole run" '[ $rc -eq 0 ] && [ "$(rows whole.csv)" -gt 9000 ]'
    run "$bin" envelope $cam --profile road.$f --stream -o stream.csv
    check "$f: --stream into a file, whole mode's bytes" '[ $rc -eq 0 ] && cmp -s whole.csv stream.csv'
    run "$bin" envelope $cam --profile road.$f --stream --relative-to ground -o stream.csv
    run "$bin" envelope $cam --profile road.$f --relative-to ground -o whole.csv
    check "$f: --relative-to ground (the level's reader of the same file): whole mode's bytes" \
        '[ $rc -eq 0 ] && cmp -s whole.csv stream.csv'
done
# Row 9001 (u = 9 m) misses its value of the long section at v = -0.5 m, which the track there
# needs (no GRID_NAN_MODE in the file: an error naming the row).
head=$(grep -n '^\$\$\$\$' road.crg | tail -1 | cut -d: -f1)
awk -v n=$((head + 9001)) 'NR == n { $0 = sprintf("%-20s%s", "*missing*", substr($0, 21)) } 1' \
    road.crg >gap.crg
want_track_error() {
    rm -f want
    run "$bin" envelope $cam --profile gap.crg --track -0.5 -o w.csv
    [ $rc -eq 2 ] && no_file w.csv && cp err want
}
want_track_error
check "setup: whole mode refuses the track's missing value at row 9001" \
    'grep -q "needs long section 1 .* at row 9001 (u = 9 m)" want'
run "$bin" envelope $cam --profile gap.crg --track -0.5 --stream -o s.csv
check "crg --stream into a file, the track's missing value mid-sweep: whole mode's error, no file" \
    '[ $rc -eq 2 ] && cmp -s err want && no_file s.csv'
run "$bin" envelope $cam --profile gap.crg --track -0.5 --stream --x-from 1 --x-to 2 -o s.csv
check "crg, the missing value past the sweep's end: still read, the same error, no file" \
    '[ $rc -eq 2 ] && cmp -s err want && no_file s.csv'
run "$bin" envelope $cam --profile gap.crg --track 0.5 --stream -o s.csv
run "$bin" envelope $cam --profile gap.crg --track 0.5 -o w.csv
check "crg, a track that needs only the other long section: runs, whole mode's bytes" \
    '[ $rc -eq 0 ] && cmp -s s.csv w.csv'

clilib_done

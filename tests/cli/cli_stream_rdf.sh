#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# An RDF road is read in bounded memory: one scan checks its rows as they pass and
# keeps none, then the sweep reads them from a window of the file as the tire rolls. A 20 m
# poly_line road at 1 mm (20,001 rows, some 700 KB: ten times the reader's 64 KB window) whose
# sides differ, with comment and blank lines inside its table: --stream gives whole mode's bytes
# on every side, into a file and to standard output; a bad row mid-sweep, past the sweep's end
# or as the last row, and an x that goes back late in the road, fail as in whole mode, at
# their line, with no file (standard output empty).
. "$(dirname "$0")/../lib/clilib.sh"

cam="--model cam --load 13000"
run "$bin" road --class C --length 20 --dx 0.001 -o road.csv
check "setup: a 20 m class C road at 1 mm" '[ $rc -eq 0 ] && [ "$(rows road.csv)" -gt 20000 ]'
# z_left the road, z_right half of it plus 2 mm; a comment line every 4,000 rows, a blank one
# every 7,000.
awk -F, 'BEGIN { print "[MDI_HEADER]\nFILE_TYPE = '"'rdf'"'\n[UNITS]\nLENGTH = '"'meter'"'";
                 print "[MODEL]\nMETHOD = '"'2D'"'\nROAD_TYPE = '"'poly_line'"'";
                 print "[PARAMETERS]\nOFFSET = 0\n(XZ_DATA)\n{ x z_left z_right }" }
         /^#/ || $1 == "x_m" { next }
         { n++; if (n % 4000 == 0) print "$ row " n; if (n % 7000 == 0) print "";
           printf "%s %s %.9g\n", $1, $2, 0.5 * $2 + 0.002 }' road.csv >road.rdf
check "setup: road.rdf" '[ "$(grep -c "^[0-9]" road.rdf)" -gt 20000 ]'

for side in mean left right; do
    run "$bin" envelope $cam --profile road.rdf --side $side -o whole_$side.csv
    check "$side: whole run" '[ $rc -eq 0 ] && [ "$(rows whole_$side.csv)" -gt 19000 ]'
    run "$bin" envelope $cam --profile road.rdf --side $side --stream -o stream.csv
    check "$side: --stream into a file, whole mode's bytes" \
        '[ $rc -eq 0 ] && cmp -s whole_$side.csv stream.csv'
done
check "the sides differ" '! cmp -s whole_left.csv whole_right.csv &&
                          ! cmp -s whole_left.csv whole_mean.csv'
run "$bin" envelope $cam --profile road.rdf --side right --stream
check "--stream to standard output: the same bytes" '[ $rc -eq 0 ] && cmp -s whole_right.csv out'
run "$bin" envelope $cam --profile road.rdf --stream --x-from 7 --x-to 9.5 -o part.csv
run "$bin" envelope $cam --profile road.rdf --x-from 7 --x-to 9.5 -o part_whole.csv
check "--stream over part of the road: whole mode's bytes" \
    '[ $rc -eq 0 ] && cmp -s part.csv part_whole.csv'

# bad NAME X TEXT: road.rdf with the row at x = X replaced by TEXT, as NAME; its line in $line.
bad() {
    line=$(grep -n "^$2 " road.rdf | head -1 | cut -d: -f1)
    awk -v n="$line" -v t="$3" 'NR == n { print t; next } { print }' road.rdf >"$1"
}
bad mid.rdf 12.5 '12.5 0.001 0.00x'
want_error mid.rdf
check "setup: whole mode refuses the bad middle row at its line and column" \
    'grep -q "^tirenv: mid.rdf:$line:[0-9]*: XZ_DATA: z_right: expected a finite number" want'
stream_refuses_mid mid.rdf
bad back.rdf 17.25 '3 0 0'
want_error back.rdf
run "$bin" envelope $cam --profile back.rdf --stream --x-to 2 -o s.csv
check "an x that goes back past the sweep: whole mode's error at its row, no file" \
    '[ $rc -eq 2 ] && grep -q "back.rdf:$line: XZ_DATA: vertex [0-9]*: x = 3 is less than" err &&
     cmp -s err want && no_file s.csv'
last=$(tail -1 road.rdf | cut -d" " -f1)
bad end.rdf "$last" "$last 0 0 0"
want_error end.rdf
run "$bin" envelope $cam --profile end.rdf --stream -o s.csv
check "a bad last row: whole mode's error at its line, no file" \
    '[ $rc -eq 2 ] && grep -q "end.rdf:$line:" err && cmp -s err want && no_file s.csv'

clilib_done

#!/bin/sh
# tirenv convert end to end: roads between CSV, OpenCRG and RDF files, formats told by content,
# round trips to the written precision, misuse and bad files refused without output.
# Usage: tests/cli/cli_convert.sh BIN TESTDATA_DIR, with TIRENV_SAMPLES naming the
# sample files (CTest sets it). SPDX-License-Identifier: Apache-2.0
# shellcheck disable=SC2016,SC2034,SC2086
. "$(dirname "$0")/../lib/clilib.sh"

samples=${TIRENV_SAMPLES:-}
if [ -z "$samples" ] || [ ! -f "$samples/crg/Horstwalde.crg" ]; then
    echo "not ok 1 - the sample files (TIRENV_SAMPLES='$samples') are missing"
    exit 1
fi
crg=$samples/crg
rdf=$samples/rdf

# data rows of two CSVs equal number by number within TOL (the '#' comments may differ)
same_rows() {
    grep -v '^#' "$1" >a.rows && grep -v '^#' "$2" >b.rows &&
        [ "$(wc -l <a.rows)" -eq "$(wc -l <b.rows)" ] && [ "$(wc -l <a.rows)" -gt 1 ] &&
        paste -d, a.rows b.rows | awk -F, -v t="$3" '
            NR == 1 { if ($1 != "x_m" || $3 != "x_m") bad = 1; next }
            { for (k = 1; k <= 2; k++) { d = $k - $(k + 2); if (d > t || -d > t) bad = 1 } }
            END { exit bad }'
}

# --- help and misuse ---------------------------------------------------------------------
run "$bin" convert --help
check "convert --help: usage on stdout, exit 0" '[ $rc -eq 0 ] && grep -q "^usage: tirenv convert" out'
run "$bin" help
check "'tirenv help' lists convert" 'grep -q "^  convert " out'
run "$bin" convert --profile "$crg/Horstwalde.crg"
check "no -o: exit 1 naming it" '[ $rc -eq 1 ] && grep -q -- "-o OUT" err'
run "$bin" convert --profile "$crg/Horstwalde.crg" -o road.dat
check "unknown output extension: exit 1, nothing written" \
    '[ $rc -eq 1 ] && grep -q "unknown extension" err && no_file road.dat'
run "$bin" convert --profile "$crg/Horstwalde.crg" --crg-encoding abcd -o x.crg
check "bad --crg-encoding: exit 1" '[ $rc -eq 1 ] && grep -q "crg-encoding" err'
run "$bin" convert --profile "$rdf/plateau.rdf" --track 0.5 -o x.csv
check "--track on an RDF road: exit 1 pointing at --side" \
    '[ $rc -eq 1 ] && grep -q "use --side" err && no_file x.csv'
run "$bin" convert --profile "$crg/Horstwalde.crg" --track abc -o x.csv
check "malformed --track: exit 1" '[ $rc -eq 1 ] && grep -q -- "--track" err'

# --- CRG ----------------------------------------------------------------------------------
run "$bin" convert --profile "$crg/Horstwalde.crg" -o h.csv
check "Horstwalde to CSV: 2503 rows from x = 0 to 250.2, summary on stderr" \
    '[ $rc -eq 0 ] && [ $(grep -vc "^#" h.csv) -eq 2504 ] && grep -q "^250.2[0-9]*,0$" h.csv &&
     grep -q "^x_m,z_m$" h.csv && grep -q "2503 rows, x 0 to 250.2 m" err'
for enc in kdbi krbi ldfi lrfi; do
    run "$bin" convert --profile h.csv --crg-encoding $enc -o h-$enc.crg
    ok=$rc
    run "$bin" convert --profile h-$enc.crg -o h-$enc.csv
    tol=0
    [ $enc = lrfi ] && tol=5e-8
    [ $enc = ldfi ] && tol=1e-16
    [ $enc = krbi ] && tol=1e-7
    check "CRG -> CSV -> CRG ($enc) -> CSV: the same heights within $tol m" \
        '[ $ok -eq 0 ] && [ $rc -eq 0 ] && same_rows h.csv h-$enc.csv $tol'
done
# LRFI's 10-character numbers hold 7 decimals below 10 m in magnitude, a decimal fewer for
# each further digit before the point (Barber.crg reaches -12.192 m; its round trip came back
# 7.9e-8 m off): 12 m down within 5e-7 m, not 5e-8.
printf 'x_m,z_m\n0,-12.19199992085961\n0.1,-12.1234567891\n0.2,3.12345678912\n' >deep.csv
run "$bin" convert --profile deep.csv --crg-encoding lrfi -o deep.crg
ok=$rc
run "$bin" convert --profile deep.crg -o deep.back.csv
check "LRFI from 10 m in magnitude: 6 decimals (within 5e-7 m, not 5e-8)" \
    '[ $ok -eq 0 ] && [ $rc -eq 0 ] && same_rows deep.csv deep.back.csv 5e-7 &&
     ! same_rows deep.csv deep.back.csv 5e-8'
check "KDBI keeps the CSV's numbers exactly, text and all" \
    '[ "$(grep -v "^#" h.csv)" = "$(grep -v "^#" h-kdbi.csv)" ]'
run "$bin" convert --profile "$crg/Horstwalde.crg" --track 1.6 -o h16.csv
run "$bin" convert --profile "$crg/Horstwalde.crg" --crg-encoding ldfi -o all.crg
ok=$rc
run "$bin" convert --profile all.crg --track 1.6 -o all16.csv
check "CRG -> CRG keeps every long section: the track at v = 1.6 m is unchanged" \
    '[ $ok -eq 0 ] && [ $rc -eq 0 ] && grep -q "^#:LDFI" all.crg &&
     [ $(grep -c "^D:long section" all.crg) -eq 45 ] && same_rows h16.csv all16.csv 1e-16'
cp "$crg/halfround_6in.crg" road.txt
run "$bin" convert --profile road.txt -o -
check "a .crg named road.txt is read as one (by content); '-o -' writes CSV to stdout" \
    '[ $rc -eq 0 ] && [ $(grep -vc "^#" out) -eq 10002 ] && grep -q "^50.15,0.1523" out'
run "$bin" convert --profile "$crg/handmade_straight.crg" --track -1.5 --crg-nan-mode keep \
    -o nan.csv
check "a track through missing values, kept missing: exit 2 naming row and long section, no file" \
    '[ $rc -eq 2 ] && grep -q "long section 1 (v = -1.5 m) at row 8" err && no_file nan.csv'
run "$bin" convert --profile "$crg/handmade_straight.crg" --track -1.5 -o nan.csv
check "... without a modifiers section, OpenCRG's default GRID_NAN_MODE 2 fills them (rows 8, 9)" \
    '[ $rc -eq 0 ] && grep -q "^7,0.0111111$" nan.csv && grep -q "^8,0.0111111$" nan.csv'
run "$bin" convert --profile "$crg/handmade_circle.crg" -o circle.crg
check "a curved reference line to .crg: exit 2 saying why, no file" \
    '[ $rc -eq 2 ] && grep -q "curved reference line" err && no_file circle.crg'
run "$bin" convert --profile "$crg/handmade_straight.crg" --track 2 -o out.csv
check "a track beyond the road: exit 2, no file" \
    '[ $rc -eq 2 ] && grep -q "beyond the road" err && no_file out.csv'
run "$bin" convert --profile "$crg/handmade_platform.crg" -o p.csv
check "a malformed number in a .crg header: exit 2 naming file:line:column and key" \
    '[ $rc -eq 2 ] && grep -q "handmade_platform.crg:35:28: GRID_NAN_MODE" err && no_file p.csv'
head -c 3000 "$crg/Horstwalde.crg" >cut.crg
run "$bin" convert --profile cut.crg -o cut.csv
check "a truncated binary .crg: exit 2, no file" \
    '[ $rc -eq 2 ] && grep -q "truncated data" err && no_file cut.csv'
run "$bin" convert --profile "$crg/handmade_curved_banked_sloped.crg" --track 0.5 -o c.rdf
check "a curved, banked, sloped CRG track to RDF" \
    '[ $rc -eq 0 ] && grep -q "^ROAD_TYPE     = '"'poly_line'"'" c.rdf &&
     [ $(awk "/XZ_DATA/ { on = 1; next } on" c.rdf | wc -l) -eq 23 ]'

# --- RDF and CSV --------------------------------------------------------------------------
run "$bin" convert --profile "$rdf/plateau.rdf" -o p.csv
ok=$rc
run "$bin" convert --profile p.csv -o p.rdf
ok2=$rc
run "$bin" convert --profile p.rdf -o p2.csv
check "RDF -> CSV -> RDF -> CSV: the same numbers exactly" \
    '[ $ok -eq 0 ] && [ $ok2 -eq 0 ] && [ $rc -eq 0 ] && same_rows p.csv p2.csv 0 &&
     grep -q "^110,4.9$" p.csv'
for side in left right mean; do
    run "$bin" convert --profile "$rdf/plateau.rdf" --side $side -o s.csv
    check "--side $side" '[ $rc -eq 0 ] && same_rows p.csv s.csv 0'
done
printf 'x_m,z_m\n0,0\n0.1,0.01\n0.3,0.02\n' >uneven.csv
run "$bin" convert --profile uneven.csv -o u.crg
check "an unevenly spaced CSV to .crg without --dx: exit 2, no file" \
    '[ $rc -eq 2 ] && grep -q "evenly spaced" err && no_file u.crg'
run "$bin" convert --profile uneven.csv --dx 0.05 --half-width 1.5 -o u.crg
ok=$rc
run "$bin" convert --profile u.crg --track -1.4 -o u.csv
check "... with --dx 0.05: resampled on 7 rows, the same heights across 3 m" \
    '[ $ok -eq 0 ] && [ $rc -eq 0 ] && [ $(grep -vc "^#" u.csv) -eq 8 ] &&
     grep -q "^0.2,0.0150*1*$" u.csv && grep -aq "LONG_SECTION_V_LEFT      = 1.5" u.crg'
# An option that changes nothing in what this conversion writes is refused, not ignored: the
# copy of every long section keeps the input's rows and widths; CSV and RDF outputs have no
# encoding, increment, width or padding; --side and --crg-nan-mode read one input format.
echo keep >kept.crg
# The roads by names without blanks: the option lists below are split into words.
ln -s "$crg/handmade_straight.crg" "$rdf/plateau.rdf" .
for args in "--profile handmade_straight.crg --dx 0.25 -o kept.crg" \
    "--profile handmade_straight.crg --half-width 3 -o kept.crg" \
    "--profile handmade_straight.crg --track 0 --pad 1 -o kept.crg" \
    "--profile uneven.csv --dx 0.05 -o kept.csv" "--profile uneven.csv --pad 1 -o kept.rdf" \
    "--profile uneven.csv --crg-encoding lrfi -o kept.rdf" \
    "--profile uneven.csv --half-width 1 -o kept.csv" \
    "--profile uneven.csv --side left --dx 0.05 -o kept.crg" \
    "--profile plateau.rdf --crg-nan-mode keep -o kept.csv"; do
    run "$bin" convert $args
    check "convert $args: exit 1 naming it, the old file kept" \
        '[ $rc -eq 1 ] && grep -q "applies to\|copied to a .crg" err && [ "$(cat kept.crg)" = keep ] &&
         [ ! -e kept.csv ] && [ ! -e kept.rdf ]'
done
run "$bin" convert --profile "$crg/handmade_straight.crg" --track 0 --dx 0.25 --half-width 3 \
    -o one.crg
check "... --dx and --half-width with --track: one track resampled, 89 rows 6 m wide" \
    '[ $rc -eq 0 ] && grep -aq "REFERENCE_LINE_INCREMENT = 0.25" one.crg &&
     grep -aq "LONG_SECTION_V_LEFT      = 3" one.crg'
run "$bin" convert --profile uneven.csv --dx 1e-9 -o big.crg
check "--dx 1e-9 over 0.3 m: 3e8 rows refused before any is written (exit 2), no file" \
    '[ $rc -eq 2 ] && grep -q "too many" err && no_file big.crg'
run "$bin" convert --profile "$crg/handmade_straight.crg" --track 0 --dx 1e-7 -o big.crg
check "... and from a .crg track: 2.2e8 rows over 22 m refused, no file" \
    '[ $rc -eq 2 ] && grep -q "too many" err && no_file big.crg'
printf 'x_m,z_m\n0,0\n1,x\n' >bad.csv
run "$bin" convert --profile bad.csv -o b.rdf
check "a malformed CSV: exit 2 naming file:line, no file" \
    '[ $rc -eq 2 ] && grep -q "bad.csv:3" err && no_file b.rdf'

# One vertex has no spacing for a .crg's grid: the refusal names the option that gives one,
# and with it, the empty extent (no "-0 increments").
printf 'x_m,z_m\n0,0\n' >single.csv
run "$bin" convert --profile single.csv -o single.crg
check "a one-vertex CSV to .crg: exit 2 naming --dx, no file" \
    '[ $rc -eq 2 ] && grep -q -- "--dx M resamples" err && no_file single.crg'
run "$bin" convert --profile single.csv -o single.crg --dx 0.01
check "the same with --dx: exit 2, 0 increments, no file" \
    '[ $rc -eq 2 ] && grep -q "holds 0 increments" err && ! grep -q -- "--dx M" err &&
     no_file single.crg'

clilib_done

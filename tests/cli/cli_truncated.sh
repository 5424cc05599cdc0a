#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# Every reader of the CLI given its file cut inside the last line, as a copy that stopped or a
# full disk leaves it: exit 2, a message naming the file and that line, no output file. Each
# cut leaves a last line that still parses ("0.97363" of "0.973639", "design = 14.9" of
# "14.9R28", a manifest row without its curve, which then imports the log instead), which
# before read as a shorter number or word with exit 0; the rule is docs/formats.md section 1
# ("Last line"), for OpenCRG text its fixed-width records (section 5.1). The whole file reads
# (exit 0), and a file cut at a line end is a shorter file of its format (exit 0), except a
# data set's manifest whose source.txt declares its number of cases (formats.md section 9), or
# a sweep's whose sweep.txt does (section 13).
. "$(dirname "$0")/../lib/clilib.sh"

root=$data/../..
# cut FILE DROP OUT: FILE without its last DROP bytes, into OUT.
cut_file() {
    size=$(wc -c <"$1")
    head -c $((size - $2)) "$1" >"$3"
}

# refused WHAT FILE LINE SAYS OUTPUT CMD...: exit 2, "FILE:LINE" and SAYS in the message, no
# OUTPUT (- for none).
refused() {
    what=$1 file=$2 line=$3 says=$4 output=$5
    shift 5
    rm -f "$output"
    run "$@"
    check "$what: exit 2 at $file:$line, no output" \
        '[ $rc -eq 2 ] && grep -q "$file:$line:.*$says" err &&
         { [ "$output" = - ] || no_file "$output"; }'
}

ends="the file ends inside this line"

# Profile CSV, whole and streamed, LF and CRLF line ends.
cp "$data/profile_good.csv" p.csv
run "$bin" convert --profile p.csv -o o.csv
check "a whole profile reads" '[ $rc -eq 0 ] && [ -s o.csv ]'
for drop in 4 5; do
    cut_file "$data/profile_good.csv" $drop p.csv
    refused "profile cut $drop bytes before its end" p.csv 12 "$ends" o.csv \
        "$bin" convert --profile p.csv -o o.csv
    refused "streamed profile cut $drop bytes before its end" p.csv 12 "$ends" o.csv \
        "$bin" envelope --model rigid --load 20000 --profile p.csv --stream -o o.csv
done
cut_file "$data/profile_crlf.csv" 2 p.csv
refused "CRLF profile cut inside its last line" p.csv 9 "$ends" o.csv \
    "$bin" convert --profile p.csv -o o.csv
head -n 7 "$data/profile_good.csv" >p.csv
run "$bin" convert --profile p.csv -o o.csv
check "a profile cut at a line end is a shorter profile" '[ $rc -eq 0 ] && [ -s o.csv ]'

# .tir and .veh: the last line a key's, cut inside its comment.
cut_file "$root/data/tires/default.tir" 2 t.tir
refused ".tir cut inside its last line" t.tir 199 "$ends" - \
    "$bin" flat --csv --load 20000 --tire t.tir
mkdir vehicles
cp "$root/data/vehicles/tractor.veh" vehicles/v.veh
ln -s "$root/data/tires" tires
run "$bin" ride --vehicle vehicles/v.veh --cleat 0.1,0.05 --speed 5 --model point
check "a whole .veh reads" '[ $rc -eq 0 ]'
cut_file "$root/data/vehicles/tractor.veh" 2 vehicles/v.veh
refused ".veh cut inside its last line" vehicles/v.veh 78 "$ends" - \
    "$bin" ride --vehicle vehicles/v.veh --cleat 0.1,0.05 --speed 5 --model point

# RDF and OpenCRG text (LRFI, LDFI) roads.
cut_file "$data/samples/rdf/plateau.rdf" 2 r.rdf
refused "RDF cut inside its last row" r.rdf 71 "$ends" o.csv \
    "$bin" convert --profile r.rdf -o o.csv
cut_file "$data/samples/crg/handmade_straight.crg" 2 r.crg
refused "LRFI .crg cut inside its last number" r.crg 99 "truncated data" o.csv \
    "$bin" convert --profile r.crg -o o.csv
cut_file "$data/samples/crg/handmade_straight_double.crg" 2 r.crg
refused "LDFI .crg cut inside its last number" r.crg 126 "truncated data" o.csv \
    "$bin" convert --profile r.crg -o o.csv
cut_file "$data/samples/crg/handmade_straight.crg" 1 r.crg
run "$bin" convert --profile r.crg -o o.csv
check "a .crg without its last line end reads (a whole fixed-width record)" \
    '[ $rc -eq 0 ] && [ -s o.csv ]'

# A network file: JSON, cut anywhere, does not parse.
cut_file "$data/nn-v1.json" 3 n.json
run "$bin" predict --nn n.json --cleat 0.15,0.05 --contact-length 0.33
check "network JSON cut short: exit 2 naming it" '[ $rc -eq 2 ] && grep -q "n.json" err'

# A rig log.
cut_file "$root/data/dataset/logs/A.csv" 2 l.csv
refused "rig log cut inside its last sample" l.csv 2013 "$ends" o.csv \
    "$bin" import --log l.csv --cleat 0.05,0.025 --contact-length 0.28 -o o.csv

# A data set: its manifest, a curve, source.txt.
cp -R "$data/dataset_good" ds
run "$bin" dataset list ds
check "the whole data set lists" '[ $rc -eq 0 ]'
cut_file "$data/dataset_good/curves/J.csv" 2 ds/curves/J.csv
refused "curve cut inside its last point" ds/curves/J.csv 7 "$ends" - \
    "$bin" dataset list ds
cp "$data/dataset_good/curves/J.csv" ds/curves/J.csv
{
    head -n 3 "$data/dataset_good/cases.csv"
    printf 'F,validation,0.38,17860.42,0.30,0.10,logs/F.csv,curves/J.csv\n'
} >m.csv
cut_file m.csv 13 ds/cases.csv
refused "manifest cut before its last row's curve" ds/cases.csv 4 "$ends" - \
    "$bin" dataset list ds
cp "$data/dataset_good/cases.csv" ds/cases.csv
printf 'format = tirenv-dataset 1\ndesign = 14.9R28\n' >s.txt
cut_file s.txt 4 ds/source.txt
refused "source.txt cut inside its last value" ds/source.txt 2 "$ends" - \
    "$bin" dataset list ds

# An embedded data set, whose source.txt declares its 28 cases: its manifest cut at a line end,
# a whole row short, is refused by every command that reads the data set, with no output.
cp -R "$root/data/dataset-205-60R15" d205
run "$bin" dataset list d205
check "the whole embedded data set lists, with its 28 cases as declared" \
    '[ $rc -eq 0 ] && grep -q "^28 cases, as source.txt declares" out &&
     [ "$(grep -c " 101$" out)" -eq 28 ]'
manifest=$root/data/dataset-205-60R15/cases.csv
head -n $(($(wc -l <"$manifest") - 1)) "$manifest" >d205/cases.csv
end=$(($(wc -l <d205/cases.csv) + 1))
says="27 cases, but d205/source.txt:7 declares cases = 28"
refused "manifest cut at a line end, one case short: dataset list" d205/cases.csv $end "$says" \
    - "$bin" dataset list d205
refused "... fit" d205/cases.csv $end "$says" f.tir "$bin" fit --model cam --data d205 -o f.tir
refused "... train" d205/cases.csv $end "$says" n.json \
    "$bin" train --data d205 --seeds 1 -o n.json
refused "... compare" d205/cases.csv $end "$says" c "$bin" compare --data d205 -o c
refused "... study" d205/cases.csv $end "$says" s "$bin" study --data d205 -o s

# A sweep's data set has no source.txt: its sweep.txt declares the grid's cases (and a shard's
# part of them). Its manifest or sweep.csv cut at a line end, whole rows short, is refused by
# the data-set readers, by the same sweep run again (which took it for complete, nothing to
# do) and by sweep merge, naming the file and the line after its last row.
grid="--model cam --lengths 0.1,0.2,0.3 --heights 0.05,0.1 --contact-lengths 0.3,0.35"
run "$bin" sweep $grid -o sw
check "a whole sweep (12 cases) lists as a data set" \
    '[ $rc -eq 0 ] && "$bin" dataset list sw >out && [ "$(grep -c "^c00" out)" -eq 12 ]'
head -n $(($(wc -l <sw/cases.csv) - 2)) sw/cases.csv >m.csv && cp m.csv sw/cases.csv
end=$(($(wc -l <sw/cases.csv) + 1))
refused "sweep manifest cut at a line end, two cases short: dataset list" sw/cases.csv $end \
    "10 cases, but sw/sweep.txt:11 declares cases = 12" - "$bin" dataset list sw
refused "... train" sw/cases.csv $end "declares cases = 12" n.json \
    "$bin" train --data sw --seeds 1 -o n.json
refused "... the same sweep again (not 'complete, nothing to do')" sw/cases.csv $end \
    "10 rows, but the sweep has 12 cases" - "$bin" sweep $grid -o sw
run "$bin" sweep $grid -o sw2
head -n -1 sw2/sweep.csv >k.csv && cp k.csv sw2/sweep.csv
refused "... its sweep.csv cut so: the same sweep again" sw2/sweep.csv $(($(wc -l <k.csv) + 1)) \
    "11 rows, but the sweep has 12 cases" - "$bin" sweep $grid -o sw2
# A case's curve cut at a line end, points short: no whole case of the sweep.
run "$bin" sweep $grid -o sw3
head -n -3 sw3/curves/c0002.csv >c.csv && cp c.csv sw3/curves/c0002.csv
run "$bin" dataset list sw3
check "a sweep's curve cut at a line end: dataset list, exit 2 naming the curve and x_N" \
    '[ $rc -eq 2 ] && grep -q "sw3/curves/c0002.csv: x_N: 98 points, where a sweep.s curve" err'
run "$bin" sweep $grid -o sw3
check "... the same sweep again: exit 2 naming the curve (not 'complete, nothing to do')" \
    '[ $rc -eq 2 ] &&
     grep -q "sw3/curves/c0002.csv: x_N: this file, in a sweep taken for complete, .*: 98 points" err'
for k in 0 1; do
    "$bin" sweep $grid --shard $k/2 -o part$k 2>/dev/null
done
head -n -1 part1/cases.csv >m.csv && cp m.csv part1/cases.csv
end=$(($(wc -l <m.csv) + 1))
refused "a shard's manifest cut so: dataset list" part1/cases.csv $end \
    "5 cases, but part1/sweep.txt:11 declares cases = 12 of shard 1/2 (6 rows)" - \
    "$bin" dataset list part1
refused "... sweep merge, nothing written" part1/cases.csv $end \
    "5 rows, but shard 1/2 of the sweep's 12 cases has 6" merged \
    "$bin" sweep merge part0 part1 -o merged

clilib_done

#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# Counts and values from input bounded before they are used: positions from
# --x-from/--x-to/--dx (--stream included), lines longer than the readers' cap in the middle
# of a file, and tire and vehicle values outside their plausible ranges, each refused with a
# message naming the option, line or key, exit 1 or 2, quickly, and no output left.
. "$(dirname "$0")/../lib/clilib.sh"

printf 'x_m,z_m\n0,0\n1,0.05\n2,0\n' >p.csv

# Each of these hung, or wrote gigabytes, or printed a 301-digit count.
for args in "--x-to 1e300" "--x-to 1e9" "--x-from -1e300 --x-to 1e300" "--dx 1e-300"; do
    for mode in "" "--stream"; do
        run timeout 20 "$bin" envelope --model springs --load 13000 --profile p.csv $mode \
            $args -o out.csv
        check "envelope $mode $args: exit 1, 'too many' with the cap, no output" \
            '[ $rc -eq 1 ] && grep -q "positions from .* is too many (at most 10*)" err &&
             [ "$(wc -c <err)" -lt 200 ] && no_file out.csv'
    done
done
run timeout 20 "$bin" envelope --model springs --load 13000 --profile p.csv --stream \
    --x-from 1e300 --x-to 1e300 -o out.csv
check "--stream at x = 1e300: exit 1, the step does not move x" \
    '[ $rc -eq 1 ] && grep -q "does not move x" err && no_file out.csv'
# A road whose last x is 1e308: refused at its row as the whole read refuses it, where --stream
# took it from the file's end unchecked for its sweep's end ("inf positions ... is too many",
# exit 1, naming no file).
printf 'x_m,z_m\n0,0\n1e308,0\n' >far.csv
for mode in "" "--stream"; do
    run timeout 20 "$bin" envelope --model springs --load 13000 --profile far.csv $mode \
        -o out.csv
    check "envelope $mode over a road to x = 1e308: exit 2 at far.csv:3, x_m named" \
        '[ $rc -eq 2 ] && grep -q "far.csv:3:1: x_m: x_m = 1e308 is beyond" err && no_file out.csv'
done
# A sweep that holds its points (standard output) stops at 1e7 positions; one whose rows go to
# a CSV file as they are computed takes up to 1e8, as --stream (not run: counted).
run timeout 20 "$bin" envelope --model springs --load 13000 --profile p.csv --x-to 2e4
check "a whole sweep of 2e7 positions to standard output: refused at 1e7" \
    '[ $rc -ne 0 ] && grep -q "at most 10000000" err && [ ! -s out ]'

# A comment line past the 65,536-character cap in the middle of a file: an error at its
# line, never a file read up to it (convert wrote 3 of 6 vertices with exit 0).
long=$(awk 'BEGIN { s = "#"; while (length(s) < 70000) s = s s; print s }')
{ printf 'x_m,z_m\n0,0\n0.5,0\n'; echo "$long"; printf '1,0.05\n1.5,0\n2,0\n'; } >long.csv
run "$bin" convert --profile long.csv -o out.csv
check "convert: a 70,000-character comment on line 4 is an error at line 4" \
    '[ $rc -eq 2 ] && grep -q "long.csv:4: line longer than 65536" err && no_file out.csv'
{ printf '[DIMENSION]\nUNLOADED_RADIUS = 0.7\n'; echo "$long" | tr '#' '!';
  printf '[ENVELOPING_SPRINGS]\nRADIAL_STIFFNESS = 1e6\n'; } >long.tir
run "$bin" flat --model springs --load 13000 --tire long.tir
check "flat: a 70,000-character comment in a .tir is an error at line 3" \
    '[ $rc -eq 2 ] && grep -q "long.tir:3: line longer than 65536" err'

# Values outside the plausible ranges (docs/formats.md sections 1 and 3), named.
for kv in NODE_ANGLE=1e-20 TREAD_STIFFNESS=1e-308 VERTICAL_STIFFNESS=1e-308 \
          ELLIPS_SHIFT=1e308 RADIAL_STIFFNESS=1e308 MAX_ITERATIONS=1000000000; do
    run timeout 20 "$bin" flat --model ring --load 13000 --set "$kv"
    check "--set $kv: exit 2 naming ${kv%%=*} and its range" \
        '[ $rc -eq 2 ] && grep -q "${kv%%=*}" err && grep -q "range\|elements" err'
done
for kv in MASS=1e9 SEAT_AHEAD_OF_CG=1e9 GRAVITY=1e-308 FRONT_AXLE.TIRE_STIFFNESS=1e-308; do
    run timeout 20 "$bin" ride --cleat 0.1,0.05 --speed 2 --set "$kv"
    check "ride --set $kv: exit 2 naming ${kv%%=*}" \
        '[ $rc -eq 2 ] && grep -q "${kv%%=*}: .*\(plausible range\|unphysical\)" err'
done

# A .veh's MASS of 1e308: its overflowing load is named at MASS's line, not the tire stiffness's.
sed 's/^MASS  *= 4500 /MASS = 1e308 /' "$data/../../data/vehicles/tractor.veh" >heavy.veh
ln -s "$data/../../data/tires" tires 2>/dev/null
mkdir -p veh && mv heavy.veh veh/
run "$bin" ride --vehicle veh/heavy.veh --cleat 0.1,0.05 --speed 5 --model point
check "ride: a .veh's MASS = 1e308: exit 2 at MASS's line, MASS named" \
    '[ $rc -eq 2 ] && grep -q "veh/heavy.veh:40: MASS: " err'

# A rig log's reading beyond 1e9 (s or m), at its line, column and field: one sample of 1e308
# was taken as a late time (exit 0), or made an error at another line and field, or overflowed
# into a curve point refused naming the output file.
log=$data/../../data/dataset/logs/A.csv
col=1
for f in t_s x_m z_m; do
    for v in 1e308 -1e308; do
        awk -F, -v OFS=, -v c=$col -v v=$v 'NR == 5 { $c = v } { print }' "$log" >far.csv
        run "$bin" import --log far.csv --cleat 0.05,0.025 --contact-length 0.28 -o imp.csv
        check "import: a log's $f = $v on line 5: exit 2 there, $f named, no output" \
            '[ $rc -eq 2 ] && grep -q "far.csv:5:[0-9]*: $f: $f = $v is beyond" err &&
             no_file imp.csv'
    done
    col=$((col + 1))
done

# OpenCRG: a height beyond 1e9 m at its line, column and long section (1e308 became -1e308 on
# every row of a converted track, exit 0, and streamed "out of memory"); an increment beyond a
# road's longest segment, 1e7 m, at its header line (convert wrote a CSV tirenv refused, and a
# streamed sweep said "out of memory").
crg=$data/samples/crg/handmade_straight.crg
sep=$(grep -n '^\$\$\$\$' "$crg" | cut -d: -f1)
awk -v l=$((sep + 1)) 'NR == l { $0 = sprintf("%10s", "1e308") substr($0, 11) } { print }' \
    "$crg" >far.crg
for mode in "convert --profile far.crg -o out.csv" \
            "envelope --model rigid --load 20000 --profile far.crg --stream -o out.csv"; do
    run "$bin" $mode
    check "${mode%% *} of a .crg with a height of 1e308: exit 2 at its line and long section" \
        '[ $rc -eq 2 ] && grep -q "far.crg:$((sep + 1)):1: long section 1 .*1e+308 m is beyond" err &&
         no_file out.csv'
done
sed 's/^REFERENCE_LINE_INCREMENT = 1.0/REFERENCE_LINE_INCREMENT = 2e7/' "$crg" >wide.crg
for mode in "convert --profile wide.crg -o out.csv" \
            "envelope --model rigid --load 20000 --profile wide.crg --stream --dx 1e5 -o out.csv"; do
    run "$bin" $mode
    check "${mode%% *} of a .crg 2e7 m between cross sections: exit 2 at the increment" \
        '[ $rc -eq 2 ] && grep -q "wide.crg:32: REFERENCE_LINE_INCREMENT: 20000000 m; expected at most" err &&
         no_file out.csv'
done

# RDF: the mean of the sides (the default) is refused where a side is, at its line: 1e308 on
# the left and -1e308 on the right made a mean of 0 (exit 0), 1e308 on both "z = inf".
rdf=$data/samples/rdf/plateau.rdf
sed '60s/.*/   190.000   1e308   -1e308/' "$rdf" >far.rdf
for side in mean left right; do
    run "$bin" convert --profile far.rdf --side $side -o out.csv
    check "convert --side $side of an RDF with 1e308 and -1e308 on line 60: exit 2 there" \
        '[ $rc -eq 2 ] && grep -q "far.rdf:60: XZ_DATA: vertex 35: z = -*1e+308 m is beyond" err &&
         no_file out.csv'
done

# A data set's numbers within 1e9 (m or N), at their line, column and field: a load of 1e308
# was listed as 309 digits and trained into a network (exit 0), an imported curve's h of 1e308
# fitted into a tire file (exit 0) and made training fail naming no file.
cp -R "$data/dataset_good" dsl
sed -i 's/^J,train,0.33,13527.5/J,train,0.33,1e308/' dsl/cases.csv
run "$bin" train --data dsl --seeds 1 -o n.json
check "train: a manifest's load_N = 1e308: exit 2 at its line and column, no model file" \
    '[ $rc -eq 2 ] && grep -q "dsl/cases.csv:5:14: load_N: load_N = 1e308 is beyond" err &&
     no_file n.json'
cp -R "$data/dataset_good" dsc
sed -i 's/^0.5,-0.245548,0.0213867/0.5,-0.245548,1e308/' dsc/curves/J.csv
run "$bin" fit --data dsc -o f.tir
check "fit: a curve's h_m = 1e308: exit 2 at its line and column, no tire file" \
    '[ $rc -eq 2 ] && grep -q "dsc/curves/J.csv:5:15: h_m: h_m = 1e308 is beyond" err &&
     no_file f.tir'

# A sweep's cleat longer than a road's longest segment (1e7 m), named as envelope --cleat
# names it: 1e308 ran into "case c0000 (...): out of memory".
run "$bin" sweep --model cam --lengths 1e308 --heights 0.05 --contact-lengths 0.3 -o sl
check "sweep --lengths 1e308: exit 2 naming lengths and the 1e7 m bound, nothing written" \
    '[ $rc -eq 2 ] && grep -q "lengths: value 1 is 1e+308; expected a positive number up to 1e7 m" err &&
     [ ! -e sl ] && [ ! -e sl.partial ]'

# Resources: a sweep of more than 1e6 cases is refused before anything is written; a
# manifest's duplicate case is found on its own line among 100,000 (a scan of every earlier
# name took 66 s there); a model file past 64 MiB is refused without being parsed.
list=$(awk 'BEGIN { for (i = 1; i <= 101; ++i) printf "%s%.4f", (i > 1 ? "," : ""), 0.01 + i / 1000 }')
run "$bin" sweep --lengths "$list" --heights "$list" --contact-lengths "$list" -o big
check "sweep of 101^3 = 1,030,301 cases: exit 2 naming the cap, nothing written" \
    '[ $rc -eq 2 ] && grep -q "more than 1000000 cases" err && [ ! -e big ] &&
     [ ! -e big.partial ]'
mkdir many
awk 'BEGIN { print "case,split,contact_length_m,load_N,obstacle_length_m,obstacle_height_m,log,curve"
             for (i = 1; i <= 100000; ++i) printf "c%d,train,0.3,13000,0.1,0.05,,c.csv\n", i
             print "c77777,train,0.3,13000,0.1,0.05,,c.csv" }' >many/cases.csv
run "$bin" dataset list many
check "cases.csv: the duplicate c77777 named at line 100002" \
    '[ $rc -eq 2 ] && grep -q "many/cases.csv:100002:1: case: case .c77777. appears twice" err'
head -c 68000000 /dev/zero | tr '\0' ' ' >big.json
run "$bin" predict --nn big.json --cleat 0.1,0.05 --contact-length 0.3
check "a 68 MB model file: exit 2, larger than 64 MiB" \
    '[ $rc -eq 2 ] && grep -q "big.json: larger than 64 MiB" err'
rm -f big.json

clilib_done

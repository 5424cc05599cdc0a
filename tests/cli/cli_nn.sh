#!/bin/sh
# The network's CLI: the paper's setup and the default (an ensemble with the even input) in
# model files of version 3, a version-1 file still predicting, a contact law's knot edited by
# hand caught by the checksum, the centre of the default's
# curve flat, tirenv train --seeds, and refusals. SPDX-License-Identifier: Apache-2.0
. "$(dirname "$0")/../lib/clilib.sh"
set_data="$data/../../data/dataset"

run "$bin" train --data "$set_data" --paper --restarts 2 --epochs 60 -o paper.json
check "train --paper: one network of the paper's form in a version 3 file" \
    '[ $rc -eq 0 ] && grep -q "\"version\": 3" paper.json &&
     grep -q "\"input_form\": \"paper\"" paper.json && grep -q "\"target\": \"h\"" paper.json &&
     grep -q "the restart best on control alone" out'
# The first decimal of the contact law's first load changed (by 0.1 N at most, the knots still
# ascending): version 3's checksum covers the law's knots, so the file is refused naming it,
# not driven at other loads.
awk '/"load_N"/ { knot = 1; print; next }
     knot == 1 && match($0, /\.[0-9]/) {
         d = substr($0, RSTART + 1, 1); d = d == "9" ? "8" : d + 1
         $0 = substr($0, 1, RSTART) d substr($0, RSTART + 2); knot = 0 } { print }' \
    paper.json >knot.json
run "$bin" predict --nn knot.json --cleat 0.10,0.10 --load 20000 -o knot.csv
check "predict, a contact law's knot edited: exit 2 naming the file, checksum and the law" \
    '[ $rc -eq 2 ] && ! cmp -s paper.json knot.json &&
     grep -q "knot.json: checksum: .*contact law (training.data.contact_law).*altered" err &&
     no_file knot.csv'
run "$bin" predict --nn paper.json --cleat 0.10,0.10 --load 20000 -o knot.csv
check "predict, the same file unedited: exit 0" '[ $rc -eq 0 ] && [ -s knot.csv ]'
run "$bin" train --data "$set_data" --restarts 3 --ensemble 2 --epochs 60 -o ens.json
check "train (default forms) --ensemble 2: the mean of 2 of 3 restarts, even input, h/H" \
    '[ $rc -eq 0 ] && grep -q "\"input_form\": \"even\"" ens.json &&
     grep -q "\"target\": \"h/H\"" ens.json && grep -q "the mean of the 2 restarts" out &&
     [ "$(grep -c "\"layers\"" ens.json)" -eq 2 ]'
# The last three positions before the centre, 0.1 mm apart: the slope into the centre of the
# even input's curve vanishes with the step (dh/dx ~ x), so over 0.1 mm it is below 1e-3.
run "$bin" predict --nn ens.json --cleat 0.10,0.10 --contact-length 0.28 --x-from -0.0002 \
    --x-to 0 --dx 0.0001 -o centre.csv
check "predict, even input: flat into the obstacle centre (|dh/dx| < 1e-3 over 0.1 mm)" \
    '[ $rc -eq 0 ] && grep -q "network: input even, target h/H, mean of 2 networks" err &&
     awk -F, "NR == 3 { a = \$3 } NR == 4 { d = (\$3 - a) / 1e-4; exit !(d < 1e-3 && d > -1e-3) }" centre.csv'
run "$bin" predict --nn "$data/nn-v1.json" --cleat 0.10,0.10 --contact-length 0.28 -o v1.csv
check "predict with a version 1 model file (the paper's form, one network)" \
    '[ $rc -eq 0 ] && grep -q "network: input paper, target h, mean of 1 network$" err && [ -s v1.csv ]'
run "$bin" train --data "$set_data" --seeds 3 --restarts 2 --epochs 40 -o med.json
check "train --seeds 3: a line per seed, the spread, the median seed written" \
    '[ $rc -eq 0 ] && [ $(grep -cE "^ +[123] +[0-9.]+ +[0-9.]+ " out) -eq 3 ] &&
     grep -q "over 3 seeds" out && grep -q "<- nearest the median" out && [ -s med.json ]'
# A data set without control cases: the training error selects, and the report says so
# rather than printing an error over no points (0.0000) or the seeds' spread on it (nan).
cp -r "$set_data" nocontrol
sed 's/,control,/,train,/' "$set_data/cases.csv" >nocontrol/cases.csv
run "$bin" train --data nocontrol --seeds 2 --restarts 1 --epochs 5
check "train without control cases: said, '-' for the empty split, no nan" \
    '[ $rc -eq 0 ] && grep -q "best on the training error alone" out &&
     grep -q "no control cases" out && grep -qE "^  control +0 +- +-$" out &&
     grep -q "control cases, the same measure: none" out && ! grep -qi nan out'
run "$bin" train --data "$set_data" --input odd -o x.json
check "train --input odd: exit 1, no file" '[ $rc -eq 1 ] && grep -q "paper or even" err && no_file x.json'
run "$bin" train --data "$set_data" --ensemble 0 -o x.json
check "train --ensemble 0: exit 1, no file" '[ $rc -eq 1 ] && no_file x.json'
run "$bin" train --data "$set_data" --restarts 1000000000 -o x.json
check "train --restarts 1e9: exit 1 naming the option and its range, no file" \
    '[ $rc -eq 1 ] && grep -q -- "--restarts: expected an integer from 1 to 100000" err &&
     no_file x.json'
run "$bin" train --data "$set_data" --lm-solver gsl -o x.json
check "train --lm-solver gsl (version 0.1's, gone with GSL): exit 1 naming cholesky, no file" \
    '[ $rc -eq 1 ] && grep -q "expected cholesky" err && no_file x.json'
clilib_done

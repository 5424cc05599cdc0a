#!/bin/sh
# What a user's review of the commands found, each checked so that it stays fixed: a network
# trained on a sweep at one working regime, import's grid options misused, ...
# (docs/perf-s24-qa.md lists what was tried). Usage: sh cli_review.sh BIN TESTDATA_DIR.
# SPDX-License-Identifier: Apache-2.0
root=$(cd "$(dirname "$0")/../.." && pwd)
. "$(dirname "$0")/../lib/clilib.sh"

# flat --model rigid at the paper's regimes: three rows alike but for the load, each with
# contact length 0, said what they are (they read as a model that missed the regimes).
run "$bin" flat --model rigid
check "flat --model rigid: the table says what its loads are" \
    '[ $rc -eq 0 ] && [ "$(grep -c " 0.0000 " out)" -eq 3 ] &&
     grep -q "^(the rigid model does not deflect: each load is the springs model.s" out'

# --method with a model that solves nothing (the cam): said, as --set METHOD is, not taken
# silently; the springs model takes it without a word.
run "$bin" envelope --model cam --method secant --cleat 0.1,0.1 --contact-length 0.28 -o cam.csv
check "envelope --model cam --method secant: a line says the cam does not read it" \
    '[ $rc -eq 0 ] && grep -q "^tirenv: --method: .*the cam does not read it" err'
run "$bin" envelope --model springs --method secant --cleat 0.1,0.1 --contact-length 0.28 \
    -o springs.csv
check "... the springs model: no such line" '[ $rc -eq 0 ] && ! grep -q -- "--method" err'

# A sweep at one contact length is a data set like any other: its model's flat ground gives
# the relation between load and contact length the network file records, around that one
# load. Before, train trained, then refused to write (exit 2) for want of a second load.
run "$bin" sweep --lengths 0.1 --heights 0.03,0.05,0.1 --contact-lengths 0.3 --model springs \
    --control-fraction 0.34 --validation-fraction 0.34 --jobs 1 -o one
check "sweep at one contact length: written" '[ $rc -eq 0 ] && [ -s one/cases.csv ]'
run "$bin" train --data one --restarts 1 --epochs 5 --jobs 1 -o one.json
check "train on it: exit 0, the file written with its contact law" \
    '[ $rc -eq 0 ] && grep -q "\"contact_law\"" one.json &&
     grep -q "the springs model.s flat ground" one.json'
run "$bin" envelope --model nn --nn one.json --cleat 0.1,0.1 --contact-length 0.3 -o one.csv
check "the network so trained drives envelope at its contact length" \
    '[ $rc -eq 0 ] && [ "$(rows one.csv)" -gt 100 ]'
# train --ensemble K over fewer restarts made the mean of fewer networks than asked, silently.
run "$bin" train --data one --restarts 2 --ensemble 3 --epochs 5 --jobs 1 -o ens.json
check "train --ensemble 3 --restarts 2: exit 1 naming both, nothing written" \
    '[ $rc -eq 1 ] && grep -q -- "--ensemble 3.*2 restarts" err && no_file ens.json'

# A study told the wrong model simulated the data: the contact law it would record is no one
# tire's, said naming the data set (the message named no file).
run "$bin" study --data one --simulated-by ring --seeds 1 --no-images --jobs 1 -o st
check "study --simulated-by ring on springs data: exit 2 naming the data set" \
    '[ $rc -eq 2 ] && grep -q "^tirenv: one: contact law: the ring model of this tire" err'

# Measured data (no model that simulated them) at one load give no relation: refused before
# any training, naming the data set, nothing written.
cp -r one measured
rm measured/sweep.txt measured/sweep.csv
run "$bin" train --data measured --restarts 1 --epochs 5 --jobs 1 -o m.json
check "train -o on measured data at one load: exit 2 before training, naming the data set" \
    '[ $rc -eq 2 ] && grep -q "measured.*load.*two different" err && ! grep -q epoch out &&
     no_file m.json'

# A sweep over a tire key has no one tire that simulated it, and its cases share a contact
# length at different loads: their power law is flat, no tire's. Refused before training, naming
# the data set (it was refused after the training, as "contact law: point 2", naming nothing).
run "$bin" sweep --lengths 0.1 --heights 0.05 --contact-lengths 0.28 --model springs \
    --set UNLOADED_RADIUS=0.5,0.7 --jobs 1 -o keys
run "$bin" train --data keys --restarts 1 --epochs 5 --jobs 1 -o keys.json
check "train -o on a sweep over UNLOADED_RADIUS: exit 2 before training, naming the data set" \
    '[ $rc -eq 2 ] && grep -q "keys: load: .*does not grow with the load" err &&
     ! grep -q epoch out && no_file keys.json'

# sweep merge -o naming one of its parts: refused as such (exit 1), not as "another sweep".
"$bin" sweep --lengths 0.1,0.2 --heights 0.05 --contact-lengths 0.3 --model rigid --shard 0/2 \
    --jobs 1 -o part0 2>/dev/null
"$bin" sweep --lengths 0.1,0.2 --heights 0.05 --contact-lengths 0.3 --model rigid --shard 1/2 \
    --jobs 1 -o part1 2>/dev/null
run "$bin" sweep merge part0 part1 -o ./part1/
check "sweep merge -o a part: exit 1 naming it, the part kept" \
    '[ $rc -eq 1 ] && grep -q -- "-o ./part1/ is the part part1" err &&
     grep -q "shard = 1/2" part1/sweep.txt'

# A sweep of the network at a contact length records the load its file's tire carries there,
# as envelope --model nn says it (the springs model of the tire file stood in: 18803 N at 0.3 m
# where the network's ring carries 19276 N).
"$bin" train --data "$root/data/dataset" --restarts 1 --epochs 5 --jobs 1 -o net.json >/dev/null
run "$bin" sweep --lengths 0.1 --heights 0.05 --contact-lengths 0.3 --model nn --nn net.json \
    --jobs 1 -o netsweep
"$bin" envelope --model nn --nn net.json --cleat 0.1,0.05 --contact-length 0.3 -o net.csv \
    2>net.err
check "sweep --model nn at 0.3 m: the load envelope --model nn gives there" \
    '[ $rc -eq 0 ] && want=$(sed -n "s/.*, load \([0-9.]*\) N .*/\1/p" net.err) &&
     [ -n "$want" ] && [ "$(awk -F, "/^c0000,/ { printf \"%.6g\", \$4 }" netsweep/cases.csv)" = "$want" ]'

# import's grid: a reversed one is a misuse of its two options, exit 1, named as options.
"$bin" rig --model springs --cleat 0.1,0.1 --contact-length 0.28 -o log.csv 2>/dev/null
run "$bin" import --log log.csv --cleat 0.1,0.1 --contact-length 0.28 --x-n-from 1 \
    --x-n-to 0 -o curve.csv
check "import --x-n-from 1 --x-n-to 0: exit 1 naming the options, nothing written" \
    '[ $rc -eq 1 ] && grep -q -- "--x-n-from, --x-n-to" err && no_file curve.csv'

# convert --dx to .crg over a length that is no whole number of --dx: the rows reach the end
# (the last one past it, on the level ground beyond); they stopped short, at 0.9 m of a 1 m
# ramp to 0.05 m, so the road read back ended at 0.045 m.
printf 'x_m,z_m\n0,0\n1,0.05\n' >ramp.csv
"$bin" convert --profile ramp.csv --dx 0.3 -o ramp.crg 2>/dev/null
run "$bin" convert --profile ramp.crg -o back.csv
check "convert --dx 0.3 of a 1 m ramp: rows to 1.2 m, the last at the end height 0.05 m" \
    '[ $rc -eq 0 ] && [ "$(rows back.csv)" -eq 6 ] && tail -1 back.csv | grep -q "^1.2,0.05$"'

# The README's tour shows each envelope command's summary line as the program prints it (the
# warm start's iteration counts had moved on without it).
readme=$root/README.md
for model in springs ring; do
    run "$bin" envelope --model $model --cleat 0.10,0.10 --contact-length 0.28 -o tour.csv
    check "README's tour: the $model envelope summary line is the program's" \
        '[ $rc -eq 0 ] && grep -qF "$(cat err)" "$readme"'
done

clilib_done

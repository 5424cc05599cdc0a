#!/bin/sh
# tirenv sweep from outside: a data set the other commands read, the same bytes for --jobs 1
# and 3, shards merged equal to one run, the progress bar where asked, and misuse refused
# (a run killed midway and resumed: sweep_killed.sh). Usage: sh cli_sweep.sh BIN TESTDATA_DIR.
# SPDX-License-Identifier: Apache-2.0
# shellcheck disable=SC2016,SC2154 # conditions are single-quoted for eval; bin is clilib's
# shellcheck source=tests/lib/clilib.sh
. "$(dirname "$0")/../lib/clilib.sh"

grid='--lengths 0.05,0.15,0.25 --heights 0.03,0.08 --contact-lengths 0.3,0.38
      --set INTERRADIAL_STIFFNESS=8000,12000 --model springs --validation-fraction 0.25'

run "$bin" sweep $grid -o one --jobs 1
check "sweep writes a data set" '[ $rc -eq 0 ] && [ -s one/cases.csv ] && [ -d one/curves ] &&
    [ "$(ls one/curves | wc -l)" -eq 24 ] && [ ! -e one.partial ]'
check "the manifest says SIMULATED and has a row per case" \
    'grep -q "^# SIMULATED" one/cases.csv && [ "$(grep -c "^c00" one/cases.csv)" -eq 24 ]'
check "a quarter of the cases are validation ones" \
    '[ "$(grep -c ",validation," one/cases.csv)" -eq 6 ]'
check "no progress bar when stderr is not a terminal" '! grep -q "cases (" err'

check "no warning that a swept key is unread: the springs model reads INTERRADIAL_STIFFNESS" \
    '! grep -q "may not read" err'
# A key the model does not read gives every value the same cases: said (the README's example
# once swept the springs model's RADIAL_STIFFNESS for the ring); the ring's air is read.
run "$bin" sweep --model ring --lengths 0.1 --heights 0.05 --contact-lengths 0.33 \
    --set RADIAL_STIFFNESS=1.4e6,1.8e6 --set INFLPRES=0.8e5,1.6e5 -o unread
check "sweep warns of a swept key the model's curve does not depend on, and only of it" \
    '[ $rc -eq 0 ] && grep -q "warning: --set RADIAL_STIFFNESS: the ring model.s curve over the first cleat is the same, bit for bit" err &&
     ! grep -q "warning: --set INFLPRES" err && [ -s unread/cases.csv ]'

run "$bin" dataset list one
check "dataset list reads it" '[ $rc -eq 0 ] && grep -q c0023 out'
check "dataset list says the sweep simulated it, the tire per case" \
    'grep -q "SIMULATED by the springs model (tirenv sweep: one/sweep.txt); tire one/tire.tir with each case.s keys of sweep.csv" out'
# A sweep's data are SIMULATED (its sweep.txt), never measurements; a sweep that set a tire key
# has no one tire file as its reference: study and compare say so rather than fit its model.
run "$bin" study --data one --seeds 1 --no-images -o st_one
check "study refuses a sweep over a tire key without --simulated-by or --measured, naming it" \
    '[ $rc -eq 2 ] && grep -q "one/sweep.txt:[0-9]*: the sweep set INTERRADIAL_STIFFNESS" err &&
     grep -q -- "--measured" err && [ ! -e st_one ]'
run "$bin" compare --data one --models rigid --no-images -o cmp_one
check "compare refuses it too, offering --simulated" \
    '[ $rc -eq 2 ] && grep -q "the sweep set INTERRADIAL_STIFFNESS" err &&
     grep -q -- "--simulated" err && [ ! -e cmp_one ]'
# sweep.txt's keys are tirenv's own: a misspelt one is refused, not read past (the set key
# unseen, the cases would be taken as the springs model's on one tire.tir).
cp -R one typo && sed 's/^set /sett /' one/sweep.txt >typo/sweep.txt
run "$bin" compare --data typo --models rigid --no-images -o cmp_typo
check "a sweep.txt with an unknown key: exit 2 naming file, line and the key" \
    '[ $rc -eq 2 ] && grep -q "typo/sweep.txt:[0-9]*:1: sett INTERRADIAL_STIFFNESS: unknown key" err &&
     [ ! -e cmp_typo ]'
run "$bin" compare --data one --models rigid --no-images --simulated -o cmp_one
check "compare --simulated takes it as simulated by a model it does not compare" \
    '[ $rc -eq 0 ] && grep -q "SIMULATED" out'
run "$bin" sweep --lengths 0.05,0.15 --heights 0.03 --contact-lengths 0.3,0.38 --model springs \
    --validation-fraction 0.5 -o plain
run "$bin" compare --data plain --models rigid --no-images -o cmp_plain
check "a sweep of one tire is SIMULATED by its model with its tire.tir, the reference" \
    '[ $rc -eq 0 ] && grep -q "These data are SIMULATED.*springs reference model" cmp_plain/report.md &&
     grep -q "(.plain/tire.tir.); it simulated the data" cmp_plain/report.md'
check "... its own curves, no rig: said so, not the rig's noise" \
    'grep -q "are the springs model.s own curves (a tirenv sweep without --rig: no sensor noise" cmp_plain/report.md &&
     ! grep -q "noise and the import" cmp_plain/report.md &&
     grep -q "SIMULATED data: the springs model.s own curves" cmp_plain/c0000.gp'
# The study over it: the obstacles outside the grid are the model's own curves too, and its
# error there (zero) is not taken for how it generalises.
# A whole study: its network's training took some 80 CPU seconds under the sanitizers, the
# longest part of make test's sanitizer run; the sanitizers see fit, train and compare in their
# own tests.
if [ "${TIRENV_TEST_SANITIZED:-0}" = 1 ]; then
    echo "# sanitizer build: study --data plain left to the Release build (a whole study)"
else
    run "$bin" study --data plain --seeds 1 --no-images -o st_plain
    check "study over a sweep without --rig: the outside curves are the model's own, no rig" \
        '[ $rc -eq 0 ] && grep -q "curves that are the springs model.s own, as the data set.s (no rig" st_plain/report.md &&
         grep -q "SIMULATED.* as the springs reference model.s own curves (no rig)" st_plain/outside/report.md &&
         grep -q "its error is zero by construction, not how it generalises" st_plain/report.md &&
         ! grep -q "times the physical model.s" st_plain/report.md'
fi
run "$bin" sweep --lengths 0.05,0.15 --heights 0.03 --contact-lengths 0.3,0.38 --model springs \
    --rig --validation-fraction 0.5 -o plain_rig
run "$bin" compare --data plain_rig --models rigid --no-images -o cmp_rig
check "a sweep --rig: the virtual rig on its model, its noise and import" \
    '[ $rc -eq 0 ] && grep -q "SIMULATED.* by the virtual rig on the springs reference model" cmp_rig/report.md &&
     grep -q "noise and the import" cmp_rig/report.md'
run "$bin" train --data one --restarts 1 --epochs 20 -o nn.json
check "train reads it" '[ $rc -eq 0 ] && [ -s nn.json ]'

run "$bin" sweep $grid -o three --jobs 3 --progress
check "--jobs 3 writes the bytes of --jobs 1" '[ $rc -eq 0 ] && diff -r one three >&2'
check "--progress draws lines on a pipe" 'grep -q "24/24 cases (100 %)" err'

for k in 0 1 2 3; do
    "$bin" sweep $grid -o "part$k" --shard "$k/4" --jobs 2 2>/dev/null
done
run "$bin" sweep merge part3 part1 part0 part2 -o merged
check "four shards merged equal one run, byte for byte" '[ $rc -eq 0 ] && diff -r one merged >&2'
run "$bin" sweep merge part0 part1 part2 -o merged2
check "merge names a missing shard" '[ $rc -eq 2 ] && grep -q "missing: 3" err && [ ! -e merged2 ]'
# A case file cut short (a part copied in part from a node) is refused, naming it, not merged.
cp part1/curves/c0001.csv c0001.whole
head -n 40 c0001.whole >part1/curves/c0001.csv
run "$bin" sweep merge part0 part1 part2 part3 -o merged4
check "merge refuses a part's curve cut short, naming it" \
    '[ $rc -eq 2 ] && grep -q "part1/curves/c0001.csv.*not a whole case file" err &&
     [ ! -e merged4 ]'
cp c0001.whole part1/curves/c0001.csv
rm -f part2/cases.csv
run "$bin" sweep merge part0 part1 part2 part3 -o merged3
check "merge refuses an incomplete shard" '[ $rc -eq 2 ] && grep -q "not complete" err'

# A resumed run keeps what an interrupted one wrote, but not a file that is not whole: it is
# named; removed, the case runs again and the set is the one run's, byte for byte.
cp -r one again.partial
rm again.partial/cases.csv
head -c 200 one/curves/c0005.csv >again.partial/curves/c0005.csv
run "$bin" sweep $grid -o again
check "a resume refuses a kept curve cut short, naming it" \
    '[ $rc -eq 2 ] && grep -q "c0005.csv.*kept from an interrupted run" err &&
     [ ! -e again ] && [ -d again.partial ]'
rm again.partial/curves/c0005.csv
run "$bin" sweep $grid -o again
check "... removed, its case runs again: the bytes of one run" \
    '[ $rc -eq 0 ] && grep -q "1 cases run, 23 kept" err && diff -r one again >&2'

run "$bin" sweep --lengths 0.1 --heights 0.05 --loads 9000,13000 --model springs -o loads
check "--loads: each case's contact length is the model's at its load, longer at more load" \
    '[ $rc -eq 0 ] && grep -q "^loads_N = 9000,13000$" loads/sweep.txt &&
     awk -F, '"'"'/^c0/ { l[NR] = $3; g[NR] = $4; n++ }
         END { exit !(n == 2 && l[5] > 0.15 && l[6] > l[5] && g[5] == 9000 && g[6] == 13000) }'"'"' \
         loads/cases.csv'

run "$bin" sweep --lengths 0.1 --heights 0.05 --contact-lengths 0.3 --model springs -o one
check "another sweep into a complete one is refused" '[ $rc -eq 2 ] && grep -q "another sweep" err'
run "$bin" sweep $grid -o one
check "a complete sweep is not run again" '[ $rc -eq 0 ] && grep -q "nothing to do" err'
run "$bin" sweep --lengths 0.1 --heights 0.05 -o x
check "a regime list is required" '[ $rc -eq 1 ] && [ ! -e x ] && [ ! -e x.partial ]'
run "$bin" sweep --lengths 0.1,abc --heights 0.05 --contact-lengths 0.3 -o x
check "a malformed list is named" '[ $rc -eq 1 ] && grep -q "lengths" err'
run "$bin" sweep --lengths 0.1 --heights 0.05 --contact-lengths 0.3 --shard 4/4 -o x
check "a shard beyond the count is refused" '[ $rc -eq 1 ] && grep -q "shard" err'
run "$bin" sweep --lengths 0.1 --heights 0.05 --contact-lengths 0.3 --set NOPE=1,2 -o x
check "an unknown tire key is named" '[ $rc -eq 2 ] && grep -q "NOPE" err && [ ! -e x ]'
run "$bin" sweep --lengths 0.1 --heights 0.05 --contact-lengths 0.3 --split train \
    --validation-fraction 0.1 -o x
check "--split and the fractions together are refused" '[ $rc -eq 1 ]'
run "$bin" sweep --jobs 0 --lengths 0.1 --heights 0.05 --contact-lengths 0.3 -o x
check "--jobs 0 is refused" '[ $rc -eq 1 ] && grep -q -- "--jobs" err'
# A seed of nothing the sweep draws changes nothing: refused (both were taken, exit 0).
run "$bin" sweep --lengths 0.1 --heights 0.05 --contact-lengths 0.3 --split-seed 5 -o x
check "--split-seed without the fractions is refused" \
    '[ $rc -eq 1 ] && grep -q -- "--split-seed seeds the permutation" err && [ ! -e x ]'
run "$bin" sweep --lengths 0.1 --heights 0.05 --contact-lengths 0.3 --seed 5 -o x
check "--seed without --rig is refused" \
    '[ $rc -eq 1 ] && grep -q -- "--seed seeds the virtual rig" err && [ ! -e x ]'
run "$bin" sweep --help
check "sweep --help documents shards, merge and --jobs" \
    '[ $rc -eq 0 ] && grep -q -- "--shard K/N" out && grep -q "sweep merge" out &&
     grep -q -- "--jobs N" out'

# The rigid disc and the point have no contact length at a load: a sweep over loads is refused
# before anything is written (each case failed after DIR.partial was made, and left it).
for m in rigid point; do
    run "$bin" sweep --model $m --lengths 0.1 --heights 0.05 --loads 3000 -o noload
    check "sweep --model $m --loads: exit 2 naming loads, no DIR nor DIR.partial" \
        '[ $rc -eq 2 ] && grep -q "loads: the $m model has no contact length of its own" err &&
         [ ! -e noload ] && [ ! -e noload.partial ]'
done

clilib_done

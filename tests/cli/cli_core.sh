#!/bin/sh
# The command line as one parser and one table of model types: every command answers --help,
# misuse, a repeated option and a leftover argument alike; every model type, the network and
# the point contact included, runs through envelope and ride; options may be abbreviated as
# getopt allows (--mod nn). Usage: tests/cli/cli_core.sh BIN TESTDATA_DIR.
# SPDX-License-Identifier: Apache-2.0
# shellcheck disable=SC2016,SC2034,SC2086
. "$(dirname "$0")/../lib/clilib.sh"

commands='flat envelope road rig import dataset study fit train predict compare ride bench'

# --- every command alike --------------------------------------------------------------------
for c in $commands; do
    run "$bin" $c --help
    check "$c --help: usage on stdout, nothing on stderr, exit 0" \
        '[ $rc -eq 0 ] && grep -q "^usage: tirenv $c" out && [ ! -s err ]'
    run "$bin" $c --no-such-option
    check "$c --no-such-option: usage on stderr, nothing on stdout, exit 1" \
        '[ $rc -eq 1 ] && [ ! -s out ] && grep -q "usage: tirenv $c" err'
done
for c in flat envelope road rig import study fit train predict compare ride bench; do
    run "$bin" $c stray-argument
    check "$c stray-argument: exit 1 naming it" \
        '[ $rc -eq 1 ] && [ ! -s out ] && grep -q "stray-argument" err'
done
run "$bin" dataset list dir-one dir-two
check "dataset list takes one directory: the second is named, exit 1" \
    '[ $rc -eq 1 ] && grep -q "dir-two" err && ! grep -q "expected .build. or .list." err'
run "$bin" help --help
check "help --help: the command list on stdout, exit 0" '[ $rc -eq 0 ] && grep -q "^commands:" out'

# --- a single-valued option given twice is misuse, naming it; --set repeats ----------------
run "$bin" envelope --model springs --cleat 0.3,0.1 --load 1 --load 2
check "envelope --load twice: exit 1 naming --load, nothing written" \
    '[ $rc -eq 1 ] && [ ! -s out ] && grep -q -- "--load given twice" err'
run "$bin" envelope --model rigid --model springs --cleat 0.3,0.1 --load 1e4
check "envelope --model twice: exit 1 naming --model" \
    '[ $rc -eq 1 ] && grep -q -- "--model given twice" err'
run "$bin" envelope --model rigid --cleat 0.3,0.1 --cleat 0.2,0.1 --load 1e4
check "envelope --cleat twice: exit 1 naming --cleat" \
    '[ $rc -eq 1 ] && grep -q -- "--cleat given twice" err'
run "$bin" envelope --model rigid --cleat 0.3,0.1 --load 1e4 -o a.csv --output b.csv
check "envelope -o and --output: one option given twice, exit 1, no file" \
    '[ $rc -eq 1 ] && grep -q -- "--output given twice" err && no_file a.csv && no_file b.csv'
run "$bin" ride --cleat 0.3,0.05 --speed 3 --speed 4 --model point
check "ride --speed twice: exit 1 naming --speed" \
    '[ $rc -eq 1 ] && grep -q -- "--speed given twice" err'
run "$bin" train --data x --epochs 3 --epochs 4
check "train --epochs twice: exit 1 naming --epochs" \
    '[ $rc -eq 1 ] && grep -q -- "--epochs given twice" err'
run "$bin" flat --contact-length 0.33 --csv --set RADIAL_STIFFNESS=1e6 --set RADIAL_STIFFNESS=2e6
cp out twice.csv
run "$bin" flat --contact-length 0.33 --csv --set RADIAL_STIFFNESS=2e6
check "--set repeats, applied in order: the last assignment wins" \
    '[ $rc -eq 0 ] && cmp -s out twice.csv'

# --- the table of model types -----------------------------------------------------------------
run "$bin" envelope --help
models=$(sed -n 's/^  --model NAME *one of //p' out)
check "envelope --help lists the model types, nn and point among them" \
    'echo " $models " | grep -q " nn " && echo " $models " | grep -q " point " &&
     echo " $models " | grep -q " springs "'
run "$bin" train --data "$data/../../data/dataset" --restarts 1 --epochs 40 -o net.json
check "a network to run (train, 40 epochs)" '[ $rc -eq 0 ] && [ -s net.json ]'
for m in $models; do
    nn=
    [ "$m" = nn ] && nn="--nn net.json"
    run "$bin" envelope --model $m $nn --cleat 0.30,0.05 --contact-length 0.33 --dx 0.01 \
        -o env_$m.csv
    check "envelope --model $m: the header and 171 rows, the summary names the model" \
        '[ $rc -eq 0 ] && [ "$(head -n 1 env_$m.csv)" = "$header" ] &&
         [ $(rows env_$m.csv) -eq 171 ] && grep -q "$m model" err'
done
run "$bin" envelope --mod nn --nn net.json --cleat 0.30,0.05 --contact-length 0.33 --dx 0.01 \
    -o abbrev.csv
check "envelope --mod nn (getopt's abbreviation of --model): the same curve" \
    '[ $rc -eq 0 ] && cmp -s abbrev.csv env_nn.csv'
run "$bin" predict --nn net.json --cleat 0.30,0.05 --contact-length 0.33 --dx 0.01 -o pred.csv
check "predict is envelope --model nn, byte for byte" '[ $rc -eq 0 ] && cmp -s pred.csv env_nn.csv'
printf 'x_m,z_m\n-0.15,0\n-0.15,0.05\n0.15,0.05\n0.15,0\n' >corners.csv
run "$bin" envelope --model nn --nn net.json --profile corners.csv --contact-length 0.33 \
    --dx 0.01 -o corners_nn.csv
check "the network over a --profile of the cleat's four corners: the --cleat curve's h" \
    '[ $rc -eq 0 ] && same_h corners_nn.csv env_nn.csv 0'
check "point contact: h is the ground itself (0.05 m on the cleat, 0 off it; walls skipped)" \
    'awk -F, "NR > 1 { a = \$1 < 0 ? -\$1 : \$1
                       if (a < 0.1499 && \$3 != 0.05 || a > 0.1501 && \$3 != 0) bad = 1 }
              END { exit bad }" env_point.csv'
run "$bin" envelope --model nn --cleat 0.30,0.05 --contact-length 0.33
check "envelope --model nn without --nn: exit 1 naming --nn" \
    '[ $rc -eq 1 ] && [ ! -s out ] && grep -q -- "--nn FILE" err'
run "$bin" envelope --model springs --nn net.json --cleat 0.30,0.05 --contact-length 0.33
check "envelope --nn with a model that takes no network: exit 1" \
    '[ $rc -eq 1 ] && grep -q -- "--nn is for a model" err'
run "$bin" road --class C --length 20 --dx 0.01 --seed 5 -o road.csv
run "$bin" envelope --model nn --nn net.json --profile road.csv --load 12000 --dx 0.01 \
    --extrapolate -o whole_nn.csv
run "$bin" envelope --model nn --nn net.json --profile road.csv --load 12000 --dx 0.01 \
    --extrapolate --stream -o stream_nn.csv
check "the network streams, byte for byte the whole-profile CSV, its warnings after the rows" \
    '[ $rc -eq 0 ] && [ -s stream_nn.csv ] && cmp -s whole_nn.csv stream_nn.csv &&
     grep -q "warning: .* lower than the lowest trained cleat" err'
run "$bin" envelope --model point --profile road.csv --load 12000 --dx 0.01 -o whole_point.csv
run "$bin" envelope --model point --profile road.csv --load 12000 --dx 0.01 --stream \
    -o stream_point.csv
check "the point contact streams, byte for byte the whole-profile CSV" \
    '[ $rc -eq 0 ] && cmp -s whole_point.csv stream_point.csv'
run "$bin" rig --model nn --cleat 0.3,0.1 --load 1e4 -o log.csv
check "rig --model nn (rig takes no network): exit 1 saying so, no file" \
    '[ $rc -eq 1 ] && grep -q "does not take" err && no_file log.csv'
run "$bin" fit --model point --data "$data/dataset_good"
check "fit --model point: exit 1 listing the models that can be fitted" \
    '[ $rc -eq 1 ] && grep -q "springs ring cam" err'
run "$bin" flat --model point --load 10000 --csv
check "flat --model point: no deflection, no contact length" \
    '[ $rc -eq 0 ] && [ "$(sed -n 2p out | cut -d, -f3,4)" = 0,0 ]'

# --- ride and the plots: the same models, the same colours ----------------------------------
# --extrapolate: by the contact law of the network's data (tirenv train records it) the front
# tire's 8.74 kN is a 0.23 m patch, below the data set's 0.28 m.
run "$bin" ride --cleat 0.30,0.05 --speed 10km/h --model point,rigid,cam,nn --nn net.json \
    --out-dir rd --series --extrapolate
check "ride with point, rigid, cam and nn as model types: a row each" \
    '[ $rc -eq 0 ] && [ $(rows rd/comfort.csv) -eq 4 ] && [ -s rd/series-nn-10kmh.csv ]'
run "$bin" compare --data "$data/dataset_good" --nn net.json --models rigid,cam,nn \
    --no-images -o cmp
check "compare --models with nn as a model type: its column last" \
    '[ $rc -eq 0 ] && [ "$(tail -n 1 cmp/timing.csv | cut -d, -f1)" = nn ]'
# One parser of model lists (cli_model_list): an empty name or one too many (compare takes 7,
# ride 8) is a usage error naming the option, and nothing is run.
eight=rigid,rigid,rigid,rigid,rigid,rigid,rigid,rigid
for bad in "ride --cleat 0.30,0.05 --speed 10km/h --out-dir cmp-bad --model rigid,,cam" \
    "ride --cleat 0.30,0.05 --speed 10km/h --out-dir cmp-bad --model $eight,cam" \
    "compare --data $data/dataset_good --no-images -o cmp-bad --models rigid," \
    "compare --data $data/dataset_good --no-images -o cmp-bad --models $eight"; do
    run "$bin" $bad
    check "${bad%% *} with a bad model list: exit 1, the option named, nothing run" \
        '[ $rc -eq 1 ] && grep -q -- "--model.*: expected 1 to [78] comma-separated model names" err &&
         no_file cmp-bad'
done
run "$bin" compare --data "$data/dataset_good" --no-images -o cmp-bad --models rigid,tank
check "compare --models with an unknown name: exit 1, the names listed" \
    '[ $rc -eq 1 ] && grep -q "expected one of rigid" err && no_file cmp-bad'
# An unknown model name is said with the option that gave it (each of these said --model).
for bad in "study --simulated-by tank --no-images -o cmp-bad:study: --simulated-by" \
    "compare --data $data/dataset_good --no-images -o cmp-bad --simulated-by tank:--simulated-by" \
    "compare --data $data/dataset_good --no-images -o cmp-bad --models rigid,tank:--models" \
    "identify --reference ring,tank:--reference" \
    "ride --cleat 0.30,0.05 --speed 10km/h --out-dir cmp-bad --model point,tank:ride: --model"; do
    run "$bin" ${bad%%:*}
    opt=${bad#*:}
    check "${bad%% *} ${opt##* } tank: exit 1, '$opt' named, nothing run" \
        '[ $rc -eq 1 ] && grep -q -- "^tirenv: $opt: expected one of rigid" err && no_file cmp-bad'
done
colour() {  # colour FILE.gp MODEL: the line colour the script gives the model
    sed -n "s/^set style line [0-9]* lc rgb '\\(#[0-9a-f]*\\)'.*# $2\$/\\1/p" "$1" | head -n 1
}
gp=$(ls cmp/*.gp | head -n 1)
check "one colour table: rigid, cam and nn look the same in the ride's and compare's plots" \
    'for m in rigid cam nn; do a=$(colour rd/seat.gp $m); b=$(colour "$gp" $m);
         [ -n "$a" ] && [ "$a" = "$b" ] || exit 1; done'

clilib_done

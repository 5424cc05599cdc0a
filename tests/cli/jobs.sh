#!/bin/sh
# --jobs N changes how long a command takes, never what it computes: each command run with
# --jobs 1 (serial) and --jobs 3 (more threads than this machine's cores, so the work really
# interleaves) writes the same files, byte for byte, apart from the timings they report.
# (dataset build: tests/dataset/dataset_regenerates.sh; study: tests/study/study_killed.sh; sweep:
# tests/cli/cli_sweep.sh and test_sweep.)
#   sh tests/cli/jobs.sh BIN DATASET_DIR
# SPDX-License-Identifier: Apache-2.0
set -u
bin=$1 data=$2
case $bin in /*) ;; *) bin=$PWD/$bin ;; esac
case $data in /*) ;; *) data=$PWD/$data ;; esac
here=$(cd "$(dirname "$0")" && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cd "$tmp" || exit 2
# shellcheck source=tests/lib/untimed.sh
. "$here/../lib/untimed.sh"
n=0 failed=0
check() {
    n=$((n + 1))
    if eval "$2"; then
        echo "ok $n - $1"
    else
        failed=$((failed + 1))
        echo "not ok $n - $1"
    fi
}

for j in 1 3; do
    "$bin" fit --data "$data" --jobs $j -o "fit-$j.tir" >"fit-$j.txt" 2>/dev/null
    mkdir -p "fit-$j" && mv "fit-$j.tir" "fit-$j/fitted.tir" && mv "fit-$j.txt" "fit-$j/out.txt"
done
check "fit: --jobs 3 = --jobs 1 (fitted tire, per-case errors)" 'same_apart_from_timings fit-1 fit-3'

for j in 1 3; do
    mkdir -p "train-$j"
    "$bin" train --data "$data" --jobs $j -o "train-$j/nn.json" 2>/dev/null |
        grep -v "model written to" >"train-$j/out.txt"
done
check "train: --jobs 3 = --jobs 1 (8 restarts: the network, its errors)" \
    '[ -s train-1/nn.json ] && same_apart_from_timings train-1 train-3'

for j in 1 3; do
    "$bin" compare --tire fit-1/fitted.tir --nn train-1/nn.json --split train \
        --models rigid,springs,cam,ring,nn --no-images --jobs $j -o "compare-$j" \
        >/dev/null 2>&1
done
check "compare: --jobs 3 = --jobs 1 (19 cases x 5 models)" \
    '[ -s compare-1/errors.csv ] && same_apart_from_timings compare-1 compare-3'

# ride: 4 models x 3 speeds; the comfort tables apart from their last two columns (CPU time
# and times real time), every series and plot file byte for byte.
for j in 1 3; do
    "$bin" ride --cleat 0.30,0.05 --speed 5km/h,10km/h,15km/h --model point,springs,cam,nn \
        --nn train-1/nn.json --extrapolate --out-dir "ride-$j" --series --jobs $j >"ride-$j.txt" \
        2>"ride-$j.err"
    awk '{ NF -= 2; print }' "ride-$j.txt" >"ride-$j/table.txt"
    cut -d, -f1-14 "ride-$j/comfort.csv" >"ride-$j/comfort-untimed.csv"
    rm "ride-$j/comfort.csv" "ride-$j/comfort.md"
done
check "ride: --jobs 3 = --jobs 1 (comfort figures, series, plots)" \
    '[ -s ride-1/comfort-untimed.csv ] && [ "$(wc -l <ride-1/table.txt)" -eq 14 ] &&
     same_apart_from_timings ride-1 ride-3 && cmp -s ride-1.err ride-3.err'

# ride with every way of enveloping (the tables over loads, and the direct evaluation whose
# models each run makes for itself): the table apart from its timings, the series.
for j in 1 3; do
    "$bin" ride --cleat 0.30,0.05 --speed 5km/h,15km/h --model point,cam \
        --enveloping static,dynamic,direct --out-dir "env-$j" --series --jobs $j \
        >"env-$j.txt" 2>"env-$j.err"
    awk '{ NF -= 2; print }' "env-$j.txt" >"env-$j.table"
done
check "ride --enveloping static,dynamic,direct: --jobs 3 = --jobs 1 (table, 12 series)" \
    '[ "$(ls env-1/series-*.csv | wc -l)" -eq 12 ] && cmp -s env-1.table env-3.table &&
     (for f in env-1/series-*.csv; do cmp -s "$f" "env-3/${f#env-1/}" || exit 1; done)'

echo "$((n - failed)) passed, $failed failed"
[ "$failed" -eq 0 ]

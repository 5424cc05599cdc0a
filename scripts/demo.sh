#!/bin/sh
# Writes the enveloping curves of the default tire over the paper's three Table 3 obstacles
# (cases F, J, R), with the rigid and the springs model, plus the flat-ground table and the
# one-line summaries. Usage: scripts/demo.sh BIN OUTDIR ("make demo" runs it).
# SPDX-License-Identifier: GPL-3.0-or-later
set -eu

if [ $# -ne 2 ]; then
    echo "usage: $0 BIN OUTDIR" >&2
    exit 1
fi
bin=$1
out=$2
mkdir -p "$out"

# Summaries are collected beside the output and moved into place at the end, so that a
# failed run does not leave a summary.txt that looks complete.
err=$(mktemp)
summary=$out/summary.txt.tmp
trap 'rm -f "$err" "$summary" "$out/flat.csv.tmp"' EXIT

{
    echo "tirenv demo: enveloping curves of the default tire over the obstacles of the"
    echo "paper's Table 3 (Stojic), computed by $("$bin" --version) with the rigid and the"
    echo "springs model. Model output, not measurements. h = z - z_flat is the effective"
    echo "road profile; the CSV columns are x_m,z_m,h_m,fx_N,fz_N,contacts,iterations."
    echo "Lines below: the summary 'tirenv envelope' prints for each curve."
} >"$summary"

# The flat-ground state at the paper's three working regimes (contact lengths in m).
"$bin" flat --csv >"$out/flat.csv.tmp"
mv "$out/flat.csv.tmp" "$out/flat.csv"

# case, contact length (m), cleat length,height (m)
for spec in "F 0.38 0.30,0.10" "J 0.33 0.30,0.05" "R 0.28 0.10,0.10"; do
    # shellcheck disable=SC2086 # split on purpose: case, contact length, cleat
    set -- $spec
    echo "" >>"$summary"
    echo "case $1: contact length $2 m, cleat $3 m (length,height)" >>"$summary"
    for model in springs rigid; do
        if ! "$bin" envelope --model "$model" --cleat "$3" --contact-length "$2" \
            -o "$out/$1-$model.csv" 2>"$err"; then
            cat "$err" >&2
            echo "demo: case $1, $model model failed" >&2
            exit 1
        fi
        cat "$err" >>"$summary"
    done
done

mv "$summary" "$out/summary.txt"
echo "demo: wrote $out/{F,J,R}-{springs,rigid}.csv, $out/flat.csv and $out/summary.txt"

#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# The ring reference tire's convergence in NODE_ANGLE (docs/models.md section 5.6): for every
# case of a data set (its cleat and load), the enveloping curve on a 1 mm grid at NODE_ANGLE
# 0.5, 0.25, 0.125 and 0.0625 degrees (or the degrees in $ANGLES, coarsest first), and per case
# the largest |h| change of each halving (mm), with the time each resolution took over all
# cases.
#   [ANGLES="0.125 0.0625 0.03125"] [CASES="S C R"] scripts/ring_convergence.sh TIRENV
#       [DATASET_DIR] [TIRE.tir]
# CASES: only these cases of the data set (all by default).
# DATASET_DIR defaults to data/dataset, TIRE to data/tires/default.tir.
set -eu
bin=$1
data=${2:-data/dataset}
tire=${3:-data/tires/default.tir}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
angles=${ANGLES:-0.5 0.25 0.125 0.0625}
rad() { awk -v d="$1" 'BEGIN { printf "%.17g", d * atan2(0, -1) / 180 }'; }
for a in $angles; do echo 0 >"$tmp/time-$a"; done
printf 'case  load_N    cleat_m       '
prev=""
for a in $angles; do [ -n "$prev" ] && printf '  %11s' "$prev->$a"; prev=$a; done
printf '   (max |dh|, mm)\n'
cases=${CASES:-}
grep -v '^#' "$data/cases.csv" | tail -n +2 | while IFS=, read -r case split lc load L H rest; do
    if [ -n "$cases" ]; then
        case " $cases " in *" $case "*) ;; *) continue ;; esac
    fi
    for a in $angles; do
        t0=$(date +%s.%N)
        "$bin" envelope --model ring --cleat "$L,$H" --load "$load" --dx 0.001 \
            --tire "$tire" --set NODE_ANGLE="$(rad "$a")" -o "$tmp/$case-$a.csv" 2>/dev/null
        t1=$(date +%s.%N)
        awk -v a="$t0" -v b="$t1" '{ printf "%.3f\n", $1 + b - a }' "$tmp/time-$a" \
            >"$tmp/t" && mv "$tmp/t" "$tmp/time-$a"
    done
    line=$(printf '%-4s  %-8s  %-5s x %-5s' "$case" "$load" "$L" "$H")
    prev=""
    for a in $angles; do
        if [ -n "$prev" ]; then
            d=$(paste -d, "$tmp/$case-$prev.csv" "$tmp/$case-$a.csv" | awk -F, '
                NR > 1 { if ($1 != $9) { print "grid mismatch" > "/dev/stderr"; exit 1 }
                         d = $3 - $11; if (d < 0) d = -d; if (d > m) m = d }
                END { printf "%.3f", 1e3 * m }')
            line="$line  $(printf '%11s' "$d")"
        fi
        prev=$a
    done
    echo "$line"
done
printf 'time over all cases (s):'
for a in $angles; do printf '  %s deg %s' "$a" "$(cat "$tmp/time-$a")"; done
printf '\n'

#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# Compares `tirenv envelope` of two builds byte for byte over cleats, steps, a triangle, a
# plate, a half-cylinder and an ISO 8608 class C road at 1 mm and 10 mm, with the springs
# model's continuous contact and rays at several loads (and the ring and rigid over one cleat).
# A speed-up that is meant to keep every output bit for bit must leave no difference: the CSVs
# (9 digits, iterations and contacts) and h written as an OpenCRG file of binary doubles (exact).
#   usage: scripts/springs-bitcmp.sh BASE_TIRENV NEW_TIRENV [WORKDIR]
# Exit status 0 if every pair of outputs is identical, 1 otherwise.
# With TOL set (in m, e.g. TOL=1e-9), a change at round-off level is allowed: the exit codes
# and messages must still be identical, and h (from the OpenCRG files, exact) within TOL at
# every position (the CSVs' other columns may differ); the largest |dh| is printed.
set -eu
tol=${TOL:-}
maxdh=0
base=$1 new=$2 dir=${3:-$(mktemp -d)}
mkdir -p "$dir"
"$base" road --class C --length 12 --dx 0.001 --seed 1 -o "$dir/road1.csv" 2>/dev/null
"$base" road --class C --length 12 --dx 0.01 --seed 1 -o "$dir/road10.csv" 2>/dev/null
"$base" road --class E --length 6 --dx 0.001 --seed 7 -o "$dir/roadE.csv" 2>/dev/null
fail=0 count=0
# within NAME: the largest |dh| between the two builds' h, read exactly from their OpenCRG
# files (binary big-endian doubles after the header, 2 a position); fails if one exceeds TOL,
# either holds a NaN where the other does not, or the CSVs' x columns differ.
within() {
    b="$dir/$1.base" n="$dir/$1.new"
    awk -F, 'NR == FNR { x[FNR] = $1; n = FNR; next } $1 != x[FNR] { exit 1 }
             END { exit FNR != n }' "$b.csv" "$n.csv" || return 1
    rows=$(($(wc -l < "$b.csv") - 1))
    hb=$(od -An -v -tf8 --endian=big -j $(($(wc -c < "$b.crg") - 16 * rows)) "$b.crg")
    hn=$(od -An -v -tf8 --endian=big -j $(($(wc -c < "$n.crg") - 16 * rows)) "$n.crg")
    printf '%s\n' "$hb" | tr -s ' ' '\n' | grep -v '^$' > "$b.h"
    printf '%s\n' "$hn" | tr -s ' ' '\n' | grep -v '^$' > "$n.h"
    paste -d' ' "$b.h" "$n.h" | awk -v tol="$tol" -v rows="$rows" '
        { if ($1 == $2) next
          if ($1 ~ /nan/ || $2 ~ /nan/) { bad = 1; next }
          d = $1 - $2; if (d < 0) d = -d
          if (d > tol) bad = 1
          if (d > mx) mx = d }
        END { printf "%.3g\n", mx + 0; exit (bad || NR != 2 * rows) }'
}
run() { # name, args...
    name=$1; shift
    rb=0; rn=0
    "$base" envelope --jobs 1 "$@" -o "$dir/$name.base.csv" 2>"$dir/$name.base.err" || rb=$?
    "$new" envelope --jobs 1 "$@" -o "$dir/$name.new.csv" 2>"$dir/$name.new.err" || rn=$?
    "$base" envelope --jobs 1 "$@" -o "$dir/$name.base.crg" 2>/dev/null || true
    "$new" envelope --jobs 1 "$@" -o "$dir/$name.new.crg" 2>/dev/null || true
    count=$((count + 1))
    if [ -n "$tol" ]; then
        if [ "$rb" != "$rn" ] || ! cmp -s "$dir/$name.base.err" "$dir/$name.new.err" ||
            { [ -e "$dir/$name.base.csv" ] && ! dh=$(within "$name"); }; then
            echo "DIFFERS: $name ($*)"
            fail=1
        elif [ -e "$dir/$name.base.csv" ]; then
            maxdh=$(awk -v a="$maxdh" -v b="$dh" 'BEGIN { print (b + 0 > a + 0) ? b : a }')
            [ "$dh" = 0 ] || echo "moved: $name |dh| <= $dh m"
        fi
        return 0
    fi
    if [ "$rb" != "$rn" ] || ! cmp -s "$dir/$name.base.err" "$dir/$name.new.err" ||
        { [ -e "$dir/$name.base.csv" ] && ! cmp -s "$dir/$name.base.csv" "$dir/$name.new.csv"; } ||
        { [ -e "$dir/$name.base.crg" ] && ! cmp -s "$dir/$name.base.crg" "$dir/$name.new.crg"; }; then
        echo "DIFFERS: $name ($*)"
        fail=1
    fi
}
for contact in continuous rays; do
    set_c="--set ENVELOPING_SPRINGS.CONTACT=$contact"
    for load in 6000 13000 22000; do
        s="--model springs $set_c --load $load"
        run "cleat_bench_${contact}_$load" $s --cleat 0.30,0.10 --x-from -1 --x-to 0.5
        run "cleat_0.3x0.08_${contact}_$load" $s --cleat 0.30,0.08
        run "cleat_0.1x0.1_${contact}_$load" $s --cleat 0.10,0.10
        run "cleat_0.05x0.025_${contact}_$load" $s --cleat 0.05,0.025 --dx 0.0007
        run "step_up_${contact}_$load" $s --step 0,0.1
        run "step_down_${contact}_$load" $s --step 0,-0.06
        run "triangle_${contact}_$load" $s --triangle 0.2,0.08
        run "cylinder_${contact}_$load" $s --cylinder 0.05
        [ "$contact" = rays ] ||
            run "plate_${contact}_$load" $s --trapezoid 0.004,0.004,0.1
        run "road1_${contact}_$load" $s --profile "$dir/road1.csv" --x-from 0.5 --x-to 11.5 --dx 0.01
        run "road10_${contact}_$load" $s --profile "$dir/road10.csv" --x-from 0.5 --x-to 11.5 --dx 0.01
        run "roadE_${contact}_$load" $s --profile "$dir/roadE.csv" --x-from 0.5 --x-to 5.5 --dx 0.003
    done
    run "cleat_cl_${contact}" --model springs $set_c --contact-length 0.38 --cleat 0.30,0.10
    run "road1_fine_${contact}" --model springs $set_c --contact-length 0.33 \
        --profile "$dir/road1.csv" --x-from 1 --x-to 3
done
run rigid_cleat --model rigid --load 13000 --cleat 0.30,0.10
run ring_cleat --model ring --load 13000 --cleat 0.10,0.05 --dx 0.004
echo "$count cases compared in $dir"
[ -z "$tol" ] || echo "largest |dh| $maxdh m (TOL $tol m)"
exit $fail

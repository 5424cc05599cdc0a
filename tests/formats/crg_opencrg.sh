#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# The effective road tirenv writes over an OpenCRG road lies where that road is, read by
# OpenCRG's own C API as Chrono reads it (tests/formats/crg_opencrg.c): the road tests/data/
# placed_bump.crg starts at x = 100, y = -20 m, heading 0.5 rad, 3.2 m high, and the track is
# v = 0.9 m off its reference line; then the same over that road without its modifiers
# section, which OpenCRG's default modifiers place (and tirenv with them). Then the effective
# road without the $ROAD_CRG_MODS section tirenv writes: OpenCRG's default modifiers move it
# to the origin and the check must fail (the test can fail, and the section is what places
# the road).
#   sh tests/formats/crg_opencrg.sh TIRENV CRG_OPENCRG DATA_DIR
set -u
cli=$1 reader=$2 data=$3
tmp=$(mktemp -d "${TMPDIR:-/tmp}/tirenv-opencrg.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
road=$data/placed_bump.crg
# run ROAD ARGS...: the sweep over ROAD's track (a function: a path with blanks stays one word).
run() {
    road_=$1
    shift
    "$cli" envelope --model springs --profile "$road_" --track 0.9 --load 4000 --x-from 47 \
        --x-to 53.5 --dx 0.005 "$@"
}
run "$road" -o "$tmp/curve.csv" 2>"$tmp/err" || { cat "$tmp/err"; exit 1; }
run "$road" -o "$tmp/eff.crg" --crg-encoding kdbi 2>"$tmp/err" || { cat "$tmp/err"; exit 1; }
"$reader" "$road" "$tmp/eff.crg" "$tmp/curve.csv" 0.9 1.0
status=$?
# The same road without its (empty) $ROAD_CRG_MODS section: OpenCRG's default modifiers place
# it (its start at v = -1 at the origin, heading 0, height 0 there), tirenv reads it so too,
# and the effective road lies where OpenCRG puts that road.
awk '/^\$ROAD_CRG_MODS/ { skip = 1; next } skip && /^\$/ { skip = 0; if ($0 == "$") next } !skip' \
    "$road" >"$tmp/defaults.crg"
run "$tmp/defaults.crg" -o "$tmp/curve2.csv" 2>"$tmp/err" || { cat "$tmp/err"; exit 1; }
run "$tmp/defaults.crg" -o "$tmp/eff2.crg" 2>"$tmp/err" || { cat "$tmp/err"; exit 1; }
echo "# the road without a modifiers section (OpenCRG's defaults)"
"$reader" "$tmp/defaults.crg" "$tmp/eff2.crg" "$tmp/curve2.csv" 0.9 1.0 || status=1
if grep -q "^REFERENCE_LINE_START_X   = 100$" "$tmp/eff2.crg"; then
    echo "not ok - over the road without modifiers the effective road kept the header's placement"
    status=1
fi
awk '/^\$ROAD_CRG_MODS/ {skip = 1; next} skip && /^\$/ {skip = 0; next} !skip' \
    "$tmp/eff.crg" >"$tmp/nomods.crg"
"$reader" "$road" "$tmp/nomods.crg" "$tmp/curve.csv" 0.9 1.0 >"$tmp/log" 2>&1
if [ "$(grep -c '^not ok' "$tmp/log")" -eq 0 ] || ! grep -q '^ok 2 ' "$tmp/log"; then
    echo "not ok - without \$ROAD_CRG_MODS the reader did not run or found no difference: the check cannot fail"
    sed 's/^/#   /' "$tmp/log"
    status=1
else
    echo "ok - without \$ROAD_CRG_MODS OpenCRG's default modifiers move the effective road (the check fails: $(grep -c '^not ok' "$tmp/log") checks)"
fi
# A road that is no OpenCRG file (a generated cleat, a CSV road) has x = u and y = v: the
# effective road tirenv writes, and a CSV road converted to OpenCRG, lie where that x is. Their
# lines started at the origin, so OpenCRG's x/y evaluation put each height x_from before its x
# (the cleat's effective road peaked at x = 0.75 m, not 0).
echo "# the effective road over a generated cleat, along x"
"$cli" envelope --model springs --cleat 0.30,0.10 --load 4000 --x-from -0.75 --x-to 0.75 \
    --dx 0.005 -o "$tmp/cleat.csv" 2>"$tmp/err" || { cat "$tmp/err"; exit 1; }
"$cli" envelope --model springs --cleat 0.30,0.10 --load 4000 --x-from -0.75 --x-to 0.75 \
    --dx 0.005 -o "$tmp/cleat.crg" 2>"$tmp/err" || { cat "$tmp/err"; exit 1; }
"$reader" - "$tmp/cleat.crg" "$tmp/cleat.csv" 0 || status=1
echo "# a CSV road from x = 5 m converted to OpenCRG, along x (its heights: the point contact's h)"
"$cli" road --class C --length 20 --dx 0.01 --seed 1 -o "$tmp/road0.csv" 2>"$tmp/err" ||
    { cat "$tmp/err"; exit 1; }
awk -F, '/^#/ || !/^[-0-9.]/ { print; next } { printf "%.10g,%s\n", $1 + 5, $2 }' \
    "$tmp/road0.csv" >"$tmp/road.csv"
"$cli" convert --profile "$tmp/road.csv" -o "$tmp/road.crg" 2>"$tmp/err" &&
    "$cli" envelope --model point --profile "$tmp/road.csv" --load 4000 --x-from 8 --x-to 22 \
        --dx 0.01 -o "$tmp/point.csv" 2>"$tmp/err" || { cat "$tmp/err"; exit 1; }
"$reader" - "$tmp/road.crg" "$tmp/point.csv" 0 || status=1
exit $status

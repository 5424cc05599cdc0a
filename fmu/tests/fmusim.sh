#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# tirenv's FMU in an importer nobody here wrote: the Modelica Association's fmusim (its C
# version, tests/third_party/fmusim), co-simulation, the wheel stepped along
# tests/data/placed_bump.crg (track v = 0.9 m, 4000 N, x = 47 + t m, 1301 steps of 5 mm)
# against 'tirenv envelope' over the same positions; then the same run stopped halfway with its
# state saved (--final-fmu-state-file) and resumed in a fresh instance from it
# (--initial-fmu-state-file, which fmusim restores before initialising, with no parameter set
# again), which must continue the whole run's outputs bit for bit.
# Labelled interop (ctest -L interop).
#   sh fmu/tests/fmusim.sh FMUSIM TIRENV FMU DATA_DIR
set -u
fmusim=$1 cli=$2 fmu=$3 data=$4
tmp=$(mktemp -d "${TMPDIR:-/tmp}/tirenv-fmusim.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
status=0
n=0
check() {
    n=$((n + 1))
    if eval "$2"; then echo "ok $n - $1"; else echo "not ok $n - $1"; status=1; return 1; fi
}
# Absolute: the FMU takes a relative road_file as relative to its resources/.
road=$(cd "$data" && pwd)/placed_bump.crg
case $fmu in /*) ;; *) fmu=$(pwd)/$fmu ;; esac
# Inputs at every communication point: x = 47 + t exactly as the CLI's positions 47 + k dx.
awk 'BEGIN { print "\"time\",\"x\",\"load\""
             for (k = 0; k <= 1300; k++) printf "%.17g,%.17g,4000\n", k * 0.005, 47 + k * 0.005 }' \
    >"$tmp/in.csv"
sim="--interface-type cs --input-file $tmp/in.csv --output-interval 0.005
     --output-variable h --output-variable slope"
# shellcheck disable=SC2086 # $sim is words
"$fmusim" $sim --start-value road_file "$road" --start-value track 0.9 --stop-time 6.5 \
    --output-file "$tmp/whole.csv" "$fmu" >"$tmp/log" 2>&1
rc=$?
check "fmusim runs the FMU over placed_bump.crg (exit 0, 1302 rows)" \
    '[ $rc -eq 0 ] && [ "$(wc -l <"$tmp/whole.csv")" -eq 1302 ]' || sed 's/^/#   /' "$tmp/log"
"$cli" envelope --model springs --profile "$road" --track 0.9 --load 4000 --x-from 47 \
    --x-to 53.5 --dx 0.005 -o "$tmp/cli.csv" 2>"$tmp/log" || sed 's/^/#   /' "$tmp/log"
# fmusim records after each step the outputs of the inputs at the step's start (co-simulation:
# row k + 1 is h(x_k)), and row 0 those of initialisation at x_0. The CLI prints 9 significant
# digits: half a unit of the 9th, 5e-9 m for heights of 1 to 10 m (3.2 m here).
check "its h and slope are the CLI's at every position, within half the CLI's last digit" \
    'paste -d, "$tmp/cli.csv" "$tmp/whole.csv" | awk -F, "
        function tol(v) { v = v < 0 ? -v : v; if (v < 1e-300) return 1e-12
                          return 0.5 * 10 ^ (int(log(v) / log(10) + 100) - 100 - 8) + 1e-12 }
        function off(a, b) { d = a - b; return (d < 0 ? -d : d) > tol(a) }
        NR == 1 { next }
        { h[NR - 2] = \$3; s[NR - 2] = \$4; fh[NR - 2] = \$10; fs[NR - 2] = \$11; rows = NR - 1 }
        END { bad = off(h[0], fh[0]) || off(s[0], fs[0]); m = 0
              for (k = 1; k < rows; k++) {
                  bad = bad || off(h[k - 1], fh[k]) || off(s[k - 1], fs[k])
                  if (h[k - 1] != 3.2) m++ }
              exit bad || rows != 1301 || m < 100 }"'
# shellcheck disable=SC2086
"$fmusim" $sim --start-value road_file "$road" --start-value track 0.9 --stop-time 3.25 \
    --final-fmu-state-file "$tmp/state.bin" --output-file "$tmp/first.csv" "$fmu" \
    >"$tmp/log" 2>&1
rc=$?
check "stopped at t = 3.25 s with its state saved to a file" \
    '[ $rc -eq 0 ] && [ -s "$tmp/state.bin" ]' || sed 's/^/#   /' "$tmp/log"
# shellcheck disable=SC2086
"$fmusim" $sim --start-time 3.25 --stop-time 6.5 --initial-fmu-state-file "$tmp/state.bin" \
    --output-file "$tmp/second.csv" "$fmu" >"$tmp/log" 2>&1
rc=$?
values() { awk -F, -v from="$2" -v to="$3" 'NR > 1 && $1 + 0 >= from - 1e-9 && $1 + 0 <= to + 1e-9 {
                print $2 "," $3 }' "$1"; }
check "restored into a fresh instance (no parameter set again), it goes on as the whole run, bit for bit (651 rows from t = 3.25 s)" \
    '[ $rc -eq 0 ] && [ "$(values "$tmp/second.csv" 3.25 6.5)" = "$(values "$tmp/whole.csv" 3.25 6.5)" ] &&
     [ "$(values "$tmp/second.csv" 3.25 6.5 | wc -l)" -eq 651 ]' || sed 's/^/#   /' "$tmp/log"
check "... and the first half is the whole run's too" \
    '[ "$(values "$tmp/first.csv" 0 3.25)" = "$(values "$tmp/whole.csv" 0 3.25)" ]'
echo "1..$n"
exit $status

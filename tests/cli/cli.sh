#!/bin/sh
# End-to-end checks of the tirenv command-line tool: exit codes, where messages go, what they
# name, exact CSV layout, and that a failure leaves no file (complete or partial) behind.
# Usage: tests/cli/cli.sh BIN TESTDATA_DIR. Prints "ok N - what" / "not ok N - what" per check
# and exits non-zero if any failed. The road and cam, network and ride checks are in
# cli_road_cam.sh, cli_network_road.sh and cli_ride_tractor.sh, which CTest runs beside this
# one. SPDX-License-Identifier: Apache-2.0
# shellcheck disable=SC2016,SC2034,SC2086
. "$(dirname "$0")/../lib/clilib.sh"

# --- help and misuse --------------------------------------------------------------------
for args in "help" "--help" "help envelope" "flat --help" "envelope --help" "bench --help"; do
    # shellcheck disable=SC2086 # split on purpose
    run "$bin" $args
    check "'tirenv $args' prints usage on stdout, exit 0" \
        '[ $rc -eq 0 ] && grep -q "^usage: tirenv" out && [ ! -s err ]'
done
run "$bin" help
check "'tirenv help' documents exit codes 1, 2 and 3" \
    'grep -q "^  1  misuse" out && grep -q "^  2  bad data" out && grep -q "^  3  numerical" out'
run "$bin" --version
check "--version prints the version, exit 0" '[ $rc -eq 0 ] && grep -q "^tirenv [0-9]" out'
run "$bin" --version envelope
check "--version with an operand is misuse, exit 1, nothing on stdout" \
    '[ $rc -eq 1 ] && [ ! -s out ] && grep -q "no operand" err'
run "$bin" --help envelope
check "--help CMD is help CMD: the command's usage, exit 0" \
    '[ $rc -eq 0 ] && grep -q "^usage: tirenv envelope" out'
run "$bin" envelope --model rigid --cleat 0.3,0.1 --load 20000 -o ""
check "-o with an empty path is misuse, exit 1" '[ $rc -eq 1 ] && grep -q "^tirenv: -o: empty" err'
# Standard output that cannot be written (a full disk: /dev/full) is an error for what main
# prints itself as for what a command prints.
for args in "--help" "--version" "help" "flat --help"; do
    # shellcheck disable=SC2086 # split on purpose
    "$bin" $args >/dev/full 2>err
    rc=$?
    check "'tirenv $args' into a full disk: exit 2, said on stderr" \
        '[ $rc -eq 2 ] && grep -q "error writing to standard output" err'
done
run "$bin"
check "no command: usage on stderr, exit 1" '[ $rc -eq 1 ] && [ ! -s out ] && grep -q usage err'
run "$bin" frobnicate
check "unknown command: named on stderr, exit 1" \
    '[ $rc -eq 1 ] && [ ! -s out ] && grep -q frobnicate err'
run "$bin" envelope --model springs $cleat_F --frobnicate
check "unknown option: named by the whole command, usage on stderr, exit 1" \
    '[ $rc -eq 1 ] && [ ! -s out ] && grep -q "usage: tirenv envelope" err &&
     grep -q "^tirenv envelope: unrecognized option .--frobnicate.$" err'
run "$bin" fit --data
check "an option without its value: named by the whole command, exit 1" \
    '[ $rc -eq 1 ] && grep -q "^tirenv fit: option .--data. requires an argument$" err'
run "$bin" envelope --model springs --cleat 0.30,0.10 --load 12kN
check "malformed --load: exit 1 naming the option" '[ $rc -eq 1 ] && grep -q -- "--load" err'
run "$bin" envelope --model springs --cleat 0.30 --load 1e4
check "--cleat with one number: exit 1 saying what is expected" \
    '[ $rc -eq 1 ] && grep -q "L,H" err'
run "$bin" envelope --model springs --cleat 0.3,0.1 --triangle 0.2,0.1 --load 1e4
check "two obstacle options: exit 1" '[ $rc -eq 1 ] && grep -q "only one obstacle" err'
run "$bin" envelope --model springs --cleat 0.3,0.1 --load 1e4 --contact-length 0.3
check "--load with --contact-length: exit 1" \
    '[ $rc -eq 1 ] && [ ! -s out ] && grep -q -- "--contact-length" err'
run "$bin" envelope --cleat 0.3,0.1 --load 1e4
check "envelope without --model: exit 1" '[ $rc -eq 1 ] && grep -q -- "--model" err'
run "$bin" envelope --model no-such-model --cleat 0.3,0.1 --load 1e4
check "unknown --model: exit 1 listing the models" '[ $rc -eq 1 ] && grep -q springs err'
run "$bin" bench --repeat 0
check "bench --repeat 0: exit 1" '[ $rc -eq 1 ] && grep -q -- "--repeat" err'

# --- envelope output --------------------------------------------------------------------
run "$bin" envelope --model springs $cleat_F --x-from -0.9 --x-to 0.9 --dx 0.01 -o c.csv
check "envelope -o: exit 0, nothing on stdout" '[ $rc -eq 0 ] && [ ! -s out ] && [ -s c.csv ]'
check "envelope writes the exact header" '[ "$(head -n 1 c.csv)" = "$header" ]'
check "x from -0.9 to 0.9 at 0.01 m gives 181 rows, ends included" \
    '[ $(rows c.csv) -eq 181 ] && [ "$(sed -n 2p c.csv | cut -d, -f1)" = -0.9 ] &&
     [ "$(tail -n 1 c.csv | cut -d, -f1)" = 0.9 ]'
check "h is 0 at both ends" 'ends_flat c.csv 1e-9'
check "springs peak h is below the 0.10 m cleat and above 90 mm" \
    'h=$(peak_h c.csv) && near "$h" 0.095 0.005000001'
check "summary on stderr names model, peak and first rise" \
    'grep -q "springs model" err && grep -q "peak h" err && grep -q "first rise" err'
check "no temporary file left after success" '[ $rc -eq 0 ] && no_file none.csv'
# The cam peaks over the cleat's centre, at a sweep x some 1e-17 m below 0: shown as 0.
run "$bin" envelope --model cam --cleat 0.10,0.10 --contact-length 0.28 -o cam.csv
check "summary: a peak at x = -1e-17 m reads x = 0.0000 m, not -0.0000" \
    '[ $rc -eq 0 ] && grep -q "peak h 93.106 mm at x = 0.0000 m," err'
run "$bin" envelope --model springs $cleat_F --x-from -0.9 --x-to 0.9 --dx 0.01
check "without -o the same CSV goes to stdout" '[ $rc -eq 0 ] && cmp -s out c.csv'
run "$bin" envelope --model springs $cleat_F -o - --x-from -0.9 --x-to 0.9 --dx 0.01
check "-o - is stdout" '[ $rc -eq 0 ] && cmp -s out c.csv'
# A subnormal position is a number like any other (strtod's underflow is its rounding, as the
# file readers take it; it was refused as no number): h there is h at 0 within 1e-9 m.
sub=-4.9406564584124654e-324
run "$bin" envelope --model springs $cleat_F --x-from 0 --x-to 0 -o zero.csv
run "$bin" envelope --model springs $cleat_F --x-from $sub --x-to $sub -o sub.csv
check "--x-from $sub: exit 0, h that at 0 within 1e-9 m" \
    '[ $rc -eq 0 ] && [ $(rows sub.csv) -eq 1 ] &&
     near "$(sed -n 2p sub.csv | cut -d, -f3)" "$(sed -n 2p zero.csv | cut -d, -f3)" 1e-9'
run "$bin" envelope --model rigid $cleat_F -o d.csv
check "default sweep: (first x - R0 - 0.02) to (last x + R0 + 0.02) at 1 mm, 1701 rows" \
    '[ $rc -eq 0 ] && [ $(rows d.csv) -eq 1701 ] && [ "$(sed -n 2p d.csv | cut -d, -f1)" = -0.85 ]'
check "rigid disc peaks at exactly the cleat height" 'near "$(peak_h d.csv)" 0.1 1e-12'

printf 'x_m,z_m\n# the same triangle as --triangle 0.2,0.05\n-0.1,0\n0,0.05\n0.1,0\n' >tri.csv
run "$bin" envelope --model springs --profile tri.csv --load 15000 --dx 0.005 -o p.csv
run "$bin" envelope --model springs --triangle 0.2,0.05 --load 15000 --dx 0.005 -o g.csv
check "--profile CSV and the generator give the same curve" '[ $rc -eq 0 ] && cmp -s p.csv g.csv'

# The springs values fitted to the data set's curves (before the default tire was identified
# on the ring's flat ground): with the identified ones the paper's plain secant meets equal
# forces at two heights near a corner of this cleat (division by zero in its eq. 2, exit 3).
fitted="--set RADIAL_STIFFNESS=7.83e5 --set INTERRADIAL_STIFFNESS=1.41e4"
run "$bin" envelope --model springs $cleat_F --method secant $fitted -o s.csv
check "--method secant (the paper's eq. 2) over a cleat: exit 0, full curve" \
    '[ $rc -eq 0 ] && [ $(rows s.csv) -eq 1701 ]'
run "$bin" envelope --model springs $cleat_F $fitted -o n.csv
check "secant and newton curves agree to 1e-7 m" 'same_h s.csv n.csv 1e-7'

# The independent reference curves of docs/models.md section 4, through --set and the CLI's sweep,
# at the file's load: its regime is the chord of the free circle, not the springs model's
# contact length (the length its tread touches, section 1.3).
ref=$data/springs-reference.csv
for c in 1 2 3 4; do
    # shellcheck disable=SC2046 # one line of numbers, split on purpose
    set -- $(awk -F, -v c="$c" '$1 == c { print $2, $3, $4, $5, $6, $12, $8, $9; exit }' "$ref")
    [ $# -eq 8 ] || set -- missing-reference-case x x x x x x x
    run "$bin" envelope --model springs --set UNLOADED_RADIUS="$1" --set RADIAL_STIFFNESS="$2" \
        --set INTERRADIAL_STIFFNESS="$3" --set SEGMENT_ANGLE="$5" --set ELEMENT_ANGLE="$4" \
        --set ENVELOPING_SPRINGS.CONTACT=rays \
        --cleat "$7,$8" --load "$6" --x-from -0.5 --x-to 0.1 --dx 0.05 -o ref$c.csv
    check "reference case $c through --set: h within 1e-8 m, load within 1e-3 N" \
        '[ $rc -eq 0 ] && matches_reference ref$c.csv $c "$ref"'
done

# --- bad data: exit 2, message names the culprit, no file -------------------------------
run "$bin" envelope --model springs $cleat_F --set RADIAL_STIFFNESS=-1 -o o.csv
check "unphysical --set: exit 2 naming the key, no output or temporary file" \
    '[ $rc -eq 2 ] && grep -q RADIAL_STIFFNESS err && no_file o.csv'
run "$bin" envelope --model springs $cleat_F --set NO_SUCH_KEY=1 -o o.csv
check "unknown --set key: exit 2 naming it" '[ $rc -eq 2 ] && grep -q NO_SUCH_KEY err'
printf 'x_m,z_m\n0,0\n0.1,zero\n' >bad.csv
run "$bin" envelope --model springs --profile bad.csv --load 1e4 -o o.csv
check "malformed profile CSV: exit 2 naming file:line" \
    '[ $rc -eq 2 ] && grep -q "bad.csv:3" err && no_file o.csv'
printf '[DIMENSION]\nUNLOADED_RADIUS = big\n' >bad.tir
run "$bin" envelope --model springs $cleat_F --tire bad.tir -o o.csv
check "malformed --tire file: exit 2 naming file:line" \
    '[ $rc -eq 2 ] && grep -q "bad.tir:2" err && no_file o.csv'
run "$bin" flat --tire missing.tir
check "missing --tire file: exit 2 naming it" '[ $rc -eq 2 ] && grep -q missing.tir err'
run "$bin" envelope --model springs --cleat 0.30,-0.10 --load 1e4 -o o.csv
check "negative cleat height: exit 2" '[ $rc -eq 2 ] && no_file o.csv'
run "$bin" envelope --model springs --cleat 0.30,0.70 --load 1e4 -o o.csv
check "obstacle above the tire centre: exit 2" '[ $rc -eq 2 ] && no_file o.csv'
run "$bin" envelope --model springs $cleat_F -o no-such-dir/o.csv
check "unwritable -o: exit 2 naming the path" '[ $rc -eq 2 ] && grep -q no-such-dir err'

mkdir -p empty small/tires
run env TIRENV_DATA="$work/empty" "$bin" flat
check "TIRENV_DATA without a default tire: exit 2 naming \$TIRENV_DATA/tires/default.tir" \
    '[ $rc -eq 2 ] && grep -q "$work/empty/tires/default.tir" err'
printf '[DIMENSION]\nUNLOADED_RADIUS = 0.5\n' >small/tires/default.tir
# At a load: a contact length is the springs model's load, which this tire has none of.
run env TIRENV_DATA="$work/small" "$bin" envelope --model rigid --cleat 0.30,0.10 --load 17860 \
    -o r.csv
check "TIRENV_DATA picks the default tire (R0 0.5 m: sweep from -0.67 m)" \
    '[ $rc -eq 0 ] && [ "$(sed -n 2p r.csv | cut -d, -f1)" = -0.67 ]'

# --- numerical failure: exit 3, no file -------------------------------------------------
run "$bin" envelope --model springs --cleat 0.30,0.10 --load 1e9 -o o.csv
check "load beyond what the tire carries: exit 3 naming the load, no file" \
    '[ $rc -eq 3 ] && grep -q "1e+09 N" err && no_file o.csv'
# The paper's plain secant has no bracket; over case R's cleat at the largest contact length
# it runs away at the corner where the rays' F_z jumps, and the message must say where.
run "$bin" envelope --model springs --cleat 0.10,0.10 --contact-length 0.38 --method secant \
    --set ENVELOPING_SPRINGS.CONTACT=rays -o o.csv
check "no convergence: exit 3 naming the position x, no file" \
    '[ $rc -eq 3 ] && grep -q "x = -\{0,1\}[0-9.]* m" err && no_file o.csv'
# With the continuous contact F_z does not jump there, and the same secant converges.
run "$bin" envelope --model springs --cleat 0.10,0.10 --contact-length 0.38 --method secant \
    -o sec.csv
check "the secant over the continuous contact: a curve" '[ $rc -eq 0 ] && [ "$(rows sec.csv)" -gt 1000 ]'

# --- flat and bench ---------------------------------------------------------------------
run "$bin" flat
check "flat: a row for each contact length 0.28, 0.33, 0.38 m" \
    '[ $rc -eq 0 ] && [ $(grep -Ec " 0\.(28|33|38)00 " out) -eq 3 ]'
run "$bin" flat --csv
check "flat --csv: exact header and three rows at 0.28, 0.33, 0.38 m" \
    '[ $rc -eq 0 ] && [ "$(head -n 1 out)" = load_N,z_flat_m,deflection_m,contact_length_m,stiffness_N_per_m ] &&
     [ "$(tail -n +2 out | cut -d, -f4 | tr "\n" " ")" = "0.28 0.33 0.38 " ]'
cp out table.csv
run "$bin" flat --contact-length 0.33 --csv
check "flat --contact-length 0.33 matches the table's row" \
    '[ $rc -eq 0 ] && [ "$(sed -n 2p out)" = "$(sed -n 3p table.csv)" ]'
run "$bin" flat --load 15000
check "flat --load: load in N and kN, stiffness in N/m and kN/m" \
    '[ $rc -eq 0 ] && grep -q "15000 N (15 kN)" out && grep -q "N/m (.* kN/m)" out'
# --quick: every part of the bench on a 100 m road (the full 1 km one took most of this
# test's time under AddressSanitizer); cli_bench.sh checks the JSON figures themselves. This
# is the one run of the tables (--quick runs each method once: cli_bench.sh's own run of the
# same tables was a second bench of the same work).
run "$bin" bench --quick
check "bench --quick: four methods, the machine, the single-thread note" \
    '[ $rc -eq 0 ] && [ $(grep -Ec "^(rigid|springs newton|springs secant|springs brent) +[0-9]" out) -eq 4 ] &&
     grep -q "^machine:" out && grep -q "single-threaded" out'
check "bench without --json: the tables with the ring's row, no JSON" \
    '[ $rc -eq 0 ] && grep -q "^springs newton " out && grep -q "^ring newton " out &&
     ! grep -q "{" out'

clilib_done

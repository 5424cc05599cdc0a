#!/bin/sh
# Inputs that were accepted and gave wrong answers or unclear messages, checked from outside:
# each refused with a clear message and its exit code, nothing written, or accepted with a
# warning where a user may mean it. The library's side of each is in tests/model/test_model_range.c,
# test_ride_checks.c, test_nn_extrapolate.c, test_train_diverged.c, test_rig_checks.c,
# test_readers_nul.c, test_compare_checks.c and test_file_roundtrip.c.
# Usage: tests/cli/cli_validation.sh BIN TESTDATA_DIR. SPDX-License-Identifier: Apache-2.0
# shellcheck disable=SC2016,SC2034,SC2086
. "$(dirname "$0")/../lib/clilib.sh"

dataset="$data/../../data/dataset"

# --- each model's valid load range (docs/models.md section 1.3) ---------------------------
# The contact law of the default tire before it was identified on the ring (Q_RA1 0.61, Q_RA2
# 0.66, with the linear vertical law of VERTICAL_STIFFNESS 297000 N/m identified before Q_FZ2
# was read), which meets the chord of the free circle at 136 kN; the identified one at 337 kN.
old_law="--set Q_RA1=0.61 --set Q_RA2=0.66 --set VERTICAL_STIFFNESS=297000 --set Q_FZ2=0"
run "$bin" flat --model cam --load 2e5 $old_law
check "flat --model cam --load 2e5 (a 1.7 m patch on a 1.36 m tire): exit 2 naming the limit" \
    '[ $rc -eq 2 ] && grep -q "200000 N .* beyond the cam model.s valid range, up to 136043 N" err &&
     grep -q "chord of the free circle" err'
run "$bin" flat --model cam --load 1.3e5 $old_law
check "flat --model cam --load 1.3e5, inside the range: exit 0" '[ $rc -eq 0 ]'
run "$bin" flat --model ring --load 4e5
check "flat --model ring --load 4e5 (its patch shrinking): exit 2 naming the peak" \
    '[ $rc -eq 2 ] && grep -q "beyond the ring model.s valid range, up to" err &&
     grep -q "contact length peaks" err'
run "$bin" envelope --model cam --cleat 0.3,0.1 --contact-length 1.3 -o c.csv $old_law
check "envelope --model cam --contact-length 1.3: exit 2, no file" \
    '[ $rc -eq 2 ] && grep -q "contact length: 1.3 m is beyond" err && no_file c.csv'
run "$bin" flat --model rigid --load 1e9
check "flat --model rigid takes any load" '[ $rc -eq 0 ]'

# --- the ride's RK4 step and unphysical vehicles (section 9.6) -----------------------------
stiff='--set FRONT_AXLE.TIRE_STIFFNESS=1e9 --set REAR_AXLE.TIRE_STIFFNESS=1e9'
run "$bin" ride --cleat 0.30,0.05 --speed 10km/h --model point $stiff -o s.csv
check "ride with 1e9 N/m tires at dt 1 ms: exit 2 naming dt, the limit and rk8pd, no file" \
    '[ $rc -eq 2 ] && grep -q "dt: RK4.s step 0.0005 s" err && grep -q "exceeds 0.5" err &&
     grep -q "rk8pd" err && no_file s.csv'
run "$bin" ride --cleat 0.30,0.05 --speed 10km/h --model point $stiff --solver rk8pd
check "the same ride with rk8pd: exit 0" '[ $rc -eq 0 ] && grep -q "^point " out'
run "$bin" ride --cleat 0.30,0.05 --speed 10km/h --model point --set MASS=1e30
check "ride --set MASS=1e30 (nan in the crest factor before): exit 2, MASS implausible" \
    '[ $rc -eq 2 ] && grep -q "MASS: 1e+30 kg is outside the plausible range" err && ! grep -q nan out'

# --- the network outside its training range (sections 6.3 and 12) -------------------------
run "$bin" train --data "$dataset" --restarts 1 --epochs 60 -o net.json
check "a network to test with" '[ $rc -eq 0 ] && [ -s net.json ]'
printf 'x_m,z_m\n-1,0\n-0.05,0\n-0.05,0.5\n0.05,0.5\n0.05,0\n1,0\n' >wall.csv
run "$bin" predict --nn net.json --profile wall.csv --contact-length 0.33 -o w.csv
check "predict over a 0.5 m wall: exit 2 naming the obstacle, its height and the range" \
    '[ $rc -eq 2 ] && grep -q "obstacle height: the obstacle at x = .* 0.5 m high" err &&
     grep -q "heights 0.025 to 0.1 m" err && grep -q -- "--extrapolate" err && no_file w.csv'
run "$bin" predict --nn net.json --profile wall.csv --contact-length 0.33 --extrapolate -o w.csv
check "with --extrapolate: clamped, with a warning" \
    '[ $rc -eq 0 ] && [ -s w.csv ] && grep -q "warning: 1 of 1 obstacles outside" err'
run "$bin" envelope --model nn --nn net.json --cleat 0.30,0.05 --contact-length 0.5 -o w.csv
check "envelope --model nn at a contact length of 0.5 m: exit 2 naming it and the range" \
    '[ $rc -eq 2 ] && grep -q "contact length: 0.5 m is outside .* 0.28 to 0.43 m" err'
run "$bin" envelope --model nn --nn net.json --cleat 0.30,0.05 --contact-length 0.33 -o w.csv
check "inside the range: exit 0, no warning" '[ $rc -eq 0 ] && ! grep -q warning err'
run "$bin" envelope --model springs --extrapolate --cleat 0.30,0.05 --contact-length 0.33
check "--extrapolate without a network: exit 1" \
    '[ $rc -eq 1 ] && grep -q -- "--extrapolate is for a trained network" err'
"$bin" road --class C --length 30 --dx 0.01 --seed 1 -o road.csv 2>/dev/null
run "$bin" ride --profile road.csv --speed 10km/h --model nn --nn net.json --dx 0.01
# The first input outside the trained range is the front tire's: 8.74 kN is a 0.19 m patch
# by the contact law of the network's data (docs/models.md section 14.3).
check "ride --model nn over a road of low bumps: exit 2 without --extrapolate" \
    '[ $rc -eq 2 ] && grep -q "contact length: 0.1898.* outside the range the network was trained on" err'
run "$bin" ride --profile road.csv --speed 10km/h --model nn --nn net.json --dx 0.01 \
    --extrapolate
check "and with it (as make demo runs it): a row, the scaled bumps warned of" \
    '[ $rc -eq 0 ] && grep -q "^nn " out && grep -q "lower than the lowest trained" err'

# --- training that diverges (section 6.4) -------------------------------------------------
run "$bin" train --data "$dataset" --trainer backprop --learning-rate 1e6 --epochs 20 -o d.json
check "train --learning-rate 1e6: exit 3 saying it diverged, no model file" \
    '[ $rc -eq 3 ] && grep -q "diverged" err && grep -q "lower the learning rate" err &&
     no_file d.json'

# --- rig logs (section 5.7) ----------------------------------------------------------------
R='--cleat 0.10,0.10 --contact-length 0.28'
for bad in '--speed 1e9' '--rate 1e-9' '--offset 1e300,1e300' '--rate 1e7'; do
    run "$bin" rig --model springs $R $bad -o bad.csv
    check "rig $bad: exit 2 with the reason, no log" \
        '[ $rc -eq 2 ] && grep -Eq "needs at least 40|resolution" err && no_file bad.csv'
done
run "$bin" rig --model springs --cleat 0.10,0.10 -o noload.csv
check "rig without --load or --contact-length: exit 1 (usage) asking for one, no log" \
    '[ $rc -eq 1 ] && grep -q "expected --load N or --contact-length M" err && no_file noload.csv'
run "$bin" rig --model springs $R -o log.csv
awk -F, 'BEGIN { OFS = "," } /^#/ || $1 == "t_s" { print; next } { $3 = $3 * 1000; print }' \
    log.csv >log-mm.csv
run "$bin" import --log log-mm.csv $R -o mm.csv
check "a log in millimetres: exit 2, not in metres (h above H + R0), no curve" \
    '[ $rc -eq 2 ] && grep -q "H + R0 = 0.78 m" err && grep -q "not in metres" err &&
     no_file mm.csv'
run "$bin" rig --model springs $R --speed 0.6 -o log6.csv
run "$bin" import --log log6.csv $R -o c6.csv
check "a log sampled every 6 mm: imported at the width cap with a warning on its noise" \
    '[ $rc -eq 0 ] && [ $(rows c6.csv) -eq 101 ] &&
     grep -q "warning: .* stopped at its cap" err && grep -q "against the 0.05 mm aimed at" err'
run "$bin" rig --model springs $R --speed 1.2 -o log12.csv
run "$bin" import --log log12.csv $R -o c12.csv
check "every 12 mm: refused, the cap's window holding fewer than 8 samples" \
    '[ $rc -eq 2 ] && grep -q "fitting a parabola needs 8" err && no_file c12.csv'

# --- NUL bytes (docs/formats.md section 1) -------------------------------------------------
printf 'x_m,z_m\n-0.05,0\n-0.05,0.1\000junk\n0.05,0.1\n0.05,0\n' >nul.csv
run "$bin" envelope --model rigid --profile nul.csv --load 1e4 -o n.csv
check "a profile with a NUL byte: exit 2 at file:line:column, no file" \
    '[ $rc -eq 2 ] && grep -q "nul.csv:3:10: a NUL byte" err && no_file n.csv'
run "$bin" envelope --model rigid --profile nul.csv --load 1e4 --stream -o n.csv
check "the same, streamed" '[ $rc -eq 2 ] && grep -q "nul.csv:3:10: a NUL byte" err'
printf '[DIMENSION]\nUNLOADED_RADIUS = 0.6\0005\n' >nul.tir
run "$bin" flat --tire nul.tir
check "a .tir with a NUL byte: exit 2 at file:line:column" \
    '[ $rc -eq 2 ] && grep -q "nul.tir:2:22: a NUL byte" err'

# --- compare (section 8) ------------------------------------------------------------------
run "$bin" compare --cases F,F -o cmp
check "compare --cases F,F: exit 2 naming F, no directory" \
    '[ $rc -eq 2 ] && grep -q "case .F. is listed twice" err && [ ! -e cmp ]'
run "$bin" compare --cases F --title "$(printf 'a\nb')" -o cmp
check "compare --title with a line break: exit 2, no directory" \
    '[ $rc -eq 2 ] && grep -q "title: a control character (0x0a)" err && [ ! -e cmp ]'
run "$bin" envelope --model rigid --cleat 0.3,0.05 --load 1 --load 2
check "a single-valued option given twice: exit 1 (the shared parser)" \
    '[ $rc -eq 1 ] && grep -q -- "--load given twice" err'
run "$bin" study --measured --simulated-by ring -o st
check "study --measured --simulated-by: exit 1 (the shared parser)" \
    '[ $rc -eq 1 ] && grep -q "contradict" err && [ ! -e st ]'

# --- fine springs elements (section 4.4) --------------------------------------------------
run "$bin" flat --set ELEMENT_ANGLE=2e-4
check "flat --set ELEMENT_ANGLE=2e-4: solved (the LCP's pass limit is its bound)" \
    '[ $rc -eq 0 ] && [ $(grep -c "^ *[0-9]" out) -eq 3 ]'

# --- clear messages -----------------------------------------------------------------------
run "$bin" ride --cleat 0.3,0.05 --speed 1e-6 --model point
check "ride --speed 1e-6: exit 1 naming the samples it would need, not 'out of memory'" \
    '[ $rc -eq 1 ] && grep -q "samples" err && grep -q -- "--speed" err &&
     ! grep -q "out of memory" err'
run "$bin" ride --cleat 0.3,0.05 --speed 3 --dt 1e-9 --model point
check "ride --dt 1e-9: exit 1 naming --dt, finer than the weightings take (1e-5 s)" \
    '[ $rc -eq 1 ] && grep -q -- "--dt: 1e-09 s is finer" err && ! grep -q "out of memory" err'
mkdir adir
run "$bin" ride --profile adir --speed 3 --model point
check "ride --profile DIR: exit 2, is a directory" \
    '[ $rc -eq 2 ] && grep -q "adir: is a directory; expected a CSV" err'
run "$bin" dataset list "$dataset" extra
check "dataset list DIR extra: exit 1 naming the extra argument" \
    '[ $rc -eq 1 ] && grep -q "unexpected argument .extra." err'

# --- .veh round trip (docs/formats.md section 3) ------------------------------------------
printf '[FRONT_AXLE]\nTIRE_FILE = /%sx%s\n' "'" "'" >q.veh
run "$bin" ride --cleat 0.3,0.05 --speed 3 --model point --vehicle q.veh
check "a .veh TIRE_FILE holding quotes: exit 2 at its line, as the writer refuses it" \
    '[ $rc -eq 2 ] && grep -q "q.veh:2: FRONT_AXLE.TIRE_FILE" err && grep -q "quote" err'

# --- profiles beyond what the models resolve (tirenv/profile.h, docs/models.md 2.1) -------
printf 'x_m,z_m\n-1e8,0\n0,0.05\n1e8,0\n' >hump.csv
run "$bin" envelope --model ring --profile hump.csv --load 10000 --x-from 0 --x-to 0
check "a 1e8 m segment (the ring gave h 41 mm for 50): exit 2 at its row, nothing printed" \
    '[ $rc -eq 2 ] && grep -q "hump.csv:3:1: x_m: x_m = 0 is 1e+08 m after the previous" err &&
     [ ! -s out ]'
run "$bin" envelope --model ring --cleat 2e7,0.05 --load 10000 --x-from 0 --x-to 0
check "a cleat 2e7 m long: exit 2 naming the limit" \
    '[ $rc -eq 2 ] && grep -q "sizes up to 1e+07 m" err && [ ! -s out ]'

clilib_done

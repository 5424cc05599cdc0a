#!/bin/sh
# tirenv ride --model cam on a tire file without the cam keys: refused, naming them, whichever
# way of enveloping (docs/models.md section 9.5) is asked; before, only static checked and
# dynamic and direct ran the cam with the default tire's shape.
# Usage: tests/cli/cli_ride_cam_keys.sh BIN TESTDATA_DIR. SPDX-License-Identifier: Apache-2.0
# shellcheck disable=SC2016,SC2034,SC2086
repo=$(cd "$(dirname "$0")/../.." && pwd)
. "$(dirname "$0")/../lib/clilib.sh"

grep -v -e '^Q_RA' -e '^ELLIPS_' "$repo/data/tires/default.tir" > nocam.tir
sed "s#'../tires/default.tir'#'$PWD/nocam.tir'#" "$repo/data/vehicles/tractor.veh" > nocam.veh
front_line=$(grep -n "^TIRE_FILE" nocam.veh | head -1 | cut -d: -f1)
check "the vehicle's tires are the tire file without the cam keys" \
    '[ $(grep -c nocam.tir nocam.veh) -eq 2 ] && ! grep -q ^ELLIPS_ nocam.tir'
for e in static dynamic direct; do
    run "$bin" ride --cleat 0.2,0.05 --speed 3 --dx 0.01 --model cam --enveloping $e \
        --vehicle nocam.veh
    # Q_RA1, Q_RA2 are derived on the file's own ring (docs/models.md section 14.2) and said;
    # the cam's shape cannot be, and is named.
    check "--enveloping $e: exit 2 naming the cam shape keys, the tire file and the vehicle's line, no table" \
        '[ $rc -eq 2 ] && grep -q "cam keys ELLIPS_SHIFT, ELLIPS_LENGTH" err &&
         grep -q "^tirenv: $PWD/nocam.tir: ELLIPS_SHIFT: .*(the front axle.s tire, named by nocam.veh:$front_line: \[FRONT_AXLE\] TIRE_FILE)$" err &&
         grep -q "nocam.tir: no Q_RA1, Q_RA2 of its own: derived on the ring" err && [ ! -s out ]'
done
# Only the rear tire without them: every way names the rear axle (direct named the front, whose
# check set both axles' models), the file and the --set that named it.
for e in static dynamic direct; do
    run "$bin" ride --cleat 0.2,0.05 --speed 3 --dx 0.01 --model cam --enveloping $e \
        --set "REAR_AXLE.TIRE_FILE=$PWD/nocam.tir"
    check "only the rear tire without the cam keys, --enveloping $e: exit 2 naming the rear axle" \
        '[ $rc -eq 2 ] && [ ! -s out ] && grep -q "^tirenv: $PWD/nocam.tir: ELLIPS_SHIFT: .*(the rear axle.s tire, named by --set REAR_AXLE.TIRE_FILE)$" err'
done
# A vehicle file through a pipe is read once: named without its line. The writer is fed and
# released as in cli_fifo.sh (clilib.sh's feed and release_writer).
mkfifo veh.fifo
feed nocam.veh veh.fifo
run timeout 60 "$bin" ride --cleat 0.2,0.05 --speed 3 --dx 0.01 --model cam --vehicle veh.fifo
release_writer veh.fifo
check "a piped vehicle file: the tire file and the vehicle's field, exit 2" \
    '[ $rc -eq 2 ] && grep -q "(the front axle.s tire, named by veh.fifo: \[FRONT_AXLE\] TIRE_FILE)$" err'
run "$bin" ride --cleat 0.2,0.05 --speed 3 --dx 0.01 --model springs --enveloping dynamic \
    --vehicle nocam.veh
check "the springs model does not need them: exit 0" '[ $rc -eq 0 ]'

# A tire whose ELLIPS_MAX_STEP (30 mm) is lower than the cleat: one warning an axle, naming the
# key, not repeated for the load table's end rows, whose ground is the same.
sed '/^ELLIPS_ORDER/a ELLIPS_MAX_STEP = 0.03' "$repo/data/tires/default.tir" > step.tir
run "$bin" ride --cleat 0.3,0.1 --speed 5km/h --dx 0.01 --model cam \
    --set "FRONT_AXLE.TIRE_FILE=$PWD/step.tir" --set "REAR_AXLE.TIRE_FILE=$PWD/step.tir"
check "cam over a cleat above ELLIPS_MAX_STEP: exit 0, one warning an axle" \
    '[ $rc -eq 0 ] && [ $(grep -c "warning: .*ELLIPS_MAX_STEP (30 mm)" err) -eq 2 ] &&
     grep -q "cam model, front axle: at x = " err && grep -q "cam model, rear axle: at x = " err'

clilib_done

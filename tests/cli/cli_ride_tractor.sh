#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# End-to-end checks of tirenv ride: the tractor over a cleat, its series and comfort files, and
# misuse and bad vehicle files refused without output.
# Usage: tests/cli/cli_ride_tractor.sh BIN TESTDATA_DIR. TAP lines, as tests/cli/cli.sh, from which it
# was split so that CTest runs the parts side by side.
# shellcheck disable=SC2016,SC2034,SC2086
. "$(dirname "$0")/../lib/clilib.sh"

# --- ride: the tractor over a profile ------------------------------------------------------
run "$bin" ride --help
check "ride --help prints usage, exit 0" '[ $rc -eq 0 ] && grep -q "^usage: tirenv ride" out'
run "$bin" ride --cleat 0.30,0.05 --speed 10km/h --model point -o series.csv
check "ride -o: exact header, 1 kHz rows from t = 0 at rest, a table row on stdout" \
    '[ $rc -eq 0 ] && [ "$(grep -v "^#" series.csv | head -n 1)" = "t_s,x_front_m,w_front_m,w_rear_m,z_m,theta_rad,z_axle_m,seat_az_m_s2,seat_awz_m_s2,seat_ax_m_s2,atheta_rad_s2,F_front_N,F_rear_N" ] &&
     [ "$(grep -v "^#" series.csv | sed -n 2p | cut -d, -f1,5,6)" = 0,0,0 ] &&
     [ "$(grep -v "^#" series.csv | sed -n 3p | cut -d, -f1)" = 0.001 ] &&
     [ $(grep -c "^point " out) -eq 1 ]'
run "$bin" ride --cleat 0.30,0.05 --speed 5km/h,15km/h --model point,cam --out-dir rd --series
check "ride --out-dir: comfort table of 2 models x 2 speeds, the plots as PNG and SVG" \
    '[ $rc -eq 0 ] && [ $(rows rd/comfort.csv) -eq 4 ] && [ -s rd/seat.png ] &&
     [ -s rd/seat.svg ] && [ -s rd/spectrum.png ] && [ -s rd/spectrum.svg ] &&
     [ -s rd/seat.gp ] && [ -s rd/series-cam-15kmh.csv ] &&
     [ -z "$(find rd -name "*tmp.*")" ]'
# The running r.m.s. figure: each panel's column peaks at its run's MTVV (comfort.csv), which is
# the maximum of that running r.m.s.; its rows keep the largest value they stand for.
check "ride --out-dir: the running r.m.s. figure, each column's maximum the run's MTVV" \
    '[ -s rd/seat-rms.png ] && [ -s rd/seat-rms.svg ] && [ -s rd/seat-rms.gp ] &&
     awk "FNR == NR { if (FNR > 1) { split(\$0, f, \",\"); mtvv[FNR - 2] = f[8] } next }
          /^#/ { b += (NF > 0 && seen); seen = 0; next }
          NF > 1 { seen = 1; for (i = 2; i <= NF; ++i) if (\$i > m[b, i]) m[b, i] = \$i; nc = NF - 1 }
          END { if (nc != 2) exit 1
                for (j = 0; j < 2; ++j) for (i = 0; i < nc; ++i) {
                    v = mtvv[j * nc + i]; d = m[j, i + 2] - v
                    if (!(v > 0) || d > 1e-5 * v || -d > 1e-5 * v) exit 1 } }" rd/comfort.csv rd/seat-rms.dat'
# Over 28,000 samples (70 m at 10 km/h) a seat.dat row stands for two: the one of larger
# magnitude, so that the plot keeps the run's peak (every other sample alone lost it: 9.10163
# against peak_az 9.10218 m/s^2 on this road).
"$bin" road --class D --length 70 --dx 0.01 --seed 3 -o road_d.csv >/dev/null 2>&1
run "$bin" ride --profile road_d.csv --speed 10km/h --model point --out-dir long
check "ride --out-dir over 70 m: seat.dat halved, its largest |a_z| the run's peak_az" \
    '[ $rc -eq 0 ] && [ $(grep -vc "^#" long/seat.dat) -lt 20001 ] &&
     awk "FNR == NR { if (FNR == 2) { split(\$0, f, \",\"); p = f[13] } next }
          !/^#/ && NF > 1 { v = \$2 < 0 ? -\$2 : \$2; if (v > m) m = v }
          END { d = m - p; exit !(p > 0 && d <= 1e-5 * p && -d <= 1e-5 * p) }" long/comfort.csv long/seat.dat'
check "ride over a cleat: point contact's seat acceleration peaks higher than the cam's" \
    'awk -F, "NR > 1 && \$3 == 5 { p[\$1] = \$13 } END { exit !(p[\"point\"] > 2 * p[\"cam\"]) }" rd/comfort.csv'
# Level ground leaves the seat still: a PSD of 0, which log axes cannot show. gnuplot refused
# the spectrum's panel ("all points y value undefined") and the run failed, exit 2, after
# every figure was computed.
printf 'x_m,z_m\n0,0\n10,0\n' >level.csv
run "$bin" ride --profile level.csv --speed 5 --model point,springs --out-dir lv
check "ride --out-dir over level ground: exit 0, both plots drawn, the spectrum's note says why it is empty" \
    '[ $rc -eq 0 ] && [ $(rows lv/comfort.csv) -eq 2 ] && [ -s lv/spectrum.png ] &&
     [ -s lv/spectrum.svg ] && grep -q "the PSD is 0: no vibration at the seat" lv/spectrum.gp &&
     awk -F, "NR > 1 && \$5 != 0 { exit 1 }" lv/comfort.csv'
# A grid coarser than a tenth of R0 steps over what it should follow: --dx 10 never sampled
# the cleat and printed a still seat, exit 0; a tenth of R0 (0.068 m) is still taken.
run "$bin" ride --cleat 0.30,0.05 --speed 5 --model point --dx 10 -o coarse.csv
check "ride --dx 10: exit 1 naming --dx and the bound, no file" \
    '[ $rc -eq 1 ] && grep -q -- "--dx: a grid of 10 m is coarser than a tenth of the tires. free radius" err &&
     no_file coarse.csv'
run "$bin" ride --cleat 0.30,0.05 --speed 5 --model point --dx 0.068 -o coarse.csv
check "ride --dx 0.068 (R0/10): exit 0, the cleat felt" \
    '[ $rc -eq 0 ] && awk -F, "NR > 1 && !/^#/ && (\$8 > 1 || \$8 < -1) { ok = 1 } END { exit !ok }" coarse.csv'
# Two runs of one name: 5 and 5.00001 m/s are both 18 km/h, and the second run's
# series-point-18kmh.csv replaced the first's; a model given twice ran twice into one file.
run "$bin" ride --cleat 0.30,0.05 --speed 5,5.00001 --model point --out-dir same --series
check "ride --speed 5,5.00001: exit 1 naming the shared 18 km/h, nothing written" \
    '[ $rc -eq 1 ] && grep -q "is 18 km/h, as speed 1 is" err && [ ! -e same ]'
run "$bin" ride --cleat 0.30,0.05 --speed 5 --model point,cam,point --out-dir same
check "ride --model point,cam,point: exit 1 naming point, nothing written" \
    '[ $rc -eq 1 ] && grep -q "'"'"'point'"'"' given twice" err && [ ! -e same ]'
run "$bin" ride --cleat 0.30,0.05 --speed 10km/h,20km/h --model point -o two.csv
check "ride -o with two speeds: exit 1, no file" '[ $rc -eq 1 ] && no_file two.csv'
run "$bin" ride --cleat 0.30,0.05 --speed 10mph
check "ride --speed 10mph: exit 1 naming the option and the library's reading of a speed" \
    '[ $rc -eq 1 ] && grep -q -- "--speed: expected a speed > 0 in m/s or with the suffix km/h, got .10mph." err'
run "$bin" ride --cleat 0.30,0.05 --speed 3 --solver rk5
check "ride --solver rk5: exit 1, the option and the library's message" \
    '[ $rc -eq 1 ] && grep -q -- "--solver: expected rk4 or rk8pd, got .rk5." err'
run "$bin" ride --cleat 0.30,0.05 --speed 3 --enveloping static,flat
check "ride --enveloping static,flat: exit 1, the option and the library's message" \
    '[ $rc -eq 1 ] && grep -q -- "--enveloping: expected static, dynamic or direct, got .flat." err'
run "$bin" ride --cleat 0.30,0.05 --speed 3 --enveloping direct,direct
check "ride --enveloping direct,direct: exit 1, given twice" \
    '[ $rc -eq 1 ] && grep -q -- "--enveloping: .direct. given twice" err'
run "$bin" ride --cleat 0.30,0.05 --speed 3 --dt 0.01
check "ride --dt too coarse for ISO 2631-1: exit 1" '[ $rc -eq 1 ] && grep -q "80 Hz" err'
run "$bin" ride --cleat 0.30,0.05 --speed 3 --model nn
check "ride --model nn without --nn: exit 1" '[ $rc -eq 1 ] && grep -q -- "--nn" err'
# Options that would change nothing are refused, as envelope's are: a network no model
# evaluates (it was not even opened, exit 0), a road file's option on a generated obstacle.
run "$bin" ride --cleat 0.30,0.05 --speed 3 --model springs --nn no-such.json -o nonn.csv
check "ride --nn without a network model: exit 1 naming --nn, no file" \
    '[ $rc -eq 1 ] && grep -q -- "--nn is for a model that evaluates a network" err &&
     [ ! -e nonn.csv ]'
for opt in '--track 0.5' '--side left' '--crg-nan-mode keep'; do
    run "$bin" ride --cleat 0.30,0.05 --speed 3 --model point $opt -o track.csv
    check "ride $opt on a cleat: exit 1, no file" \
        '[ $rc -eq 1 ] && grep -q "applies to a road file" err && [ ! -e track.csv ]'
    run "$bin" rig --cleat 0.10,0.10 --contact-length 0.28 --model springs $opt -o track.csv
    check "rig $opt on a cleat: exit 1, no log" \
        '[ $rc -eq 1 ] && grep -q "applies to a road file" err && [ ! -e track.csv ]'
done
printf '[BODY]\nMASS = 4500\nMASS_X = 1\n' >bad.veh
run "$bin" ride --cleat 0.30,0.05 --speed 3 --model point --vehicle bad.veh -o badveh.csv
check "ride with a bad vehicle file: exit 2 naming file:line and key, no file" \
    '[ $rc -eq 2 ] && grep -q "bad.veh:3" err && grep -q MASS_X err && no_file badveh.csv'
run "$bin" ride --cleat 0.30,0.05 --speed 3 --model point --set MASS=-1 -o neg.csv
check "ride --set MASS=-1: exit 2 naming MASS, no file" \
    '[ $rc -eq 2 ] && grep -q MASS err && no_file neg.csv'

# A vehicle file of one's own that leaves keys out runs on the default tractor's values for
# them, and says which; the shipped tractor.veh sets every key and says nothing.
printf '[BODY]\nMASS = 5200\n' >mass.veh
run "$bin" ride --cleat 0.30,0.05 --speed 3 --model point --vehicle mass.veh
check "ride --vehicle with MASS alone: exit 0, a warning naming PITCH_INERTIA and the tractor" \
    '[ $rc -eq 0 ] && grep -q "warning: mass.veh sets no BODY.PITCH_INERTIA, " err &&
     grep -q "the default tractor.s values" err && ! grep -q "BODY.MASS" err'
run "$bin" ride --cleat 0.30,0.05 --speed 3 --model point --vehicle "$data/../../data/vehicles/tractor.veh"
check "ride --vehicle tractor.veh: no warning of unset keys" \
    '[ $rc -eq 0 ] && ! grep -q "sets no" err'

clilib_done

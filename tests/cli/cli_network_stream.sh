#!/bin/sh
# envelope --model nn --stream end to end: the same bytes as the whole-profile run over an ISO
# 8608 road written by tirenv road at 1 mm (several times the streamed window long), a measured
# OpenCRG road (one track and three), cleats with a plateau longer than the window, a single
# cleat, to a file, to standard output and as an effective road; the same refusal of an
# obstacle outside the trained range, with no file.
# Usage: tests/cli/cli_network_stream.sh BIN TESTDATA_DIR, with TIRENV_SAMPLES naming the
# sample files (CTest sets it). SPDX-License-Identifier: Apache-2.0
# shellcheck disable=SC2016,SC2034,SC2086
. "$(dirname "$0")/../lib/clilib.sh"

samples=${TIRENV_SAMPLES:-}
if [ -z "$samples" ] || [ ! -f "$samples/crg/Barber.crg" ]; then
    echo "not ok 1 - the sample files (TIRENV_SAMPLES='$samples') are missing"
    exit 1
fi

# The network of the study, trained on the embedded data set (lm, seed 1, one restart).
run "$bin" train --data "$data/../../data/dataset" --restarts 1 -o net.json
check "train on the embedded data set writes a model file" '[ $rc -eq 0 ] && [ -s net.json ]'

# whole_stream NAME ARGS...: the envelope whole into NAME.w, streamed into NAME.s (-o or
# standard output as ARGS say), stderr of each kept; $rc is the streamed run's, $rc_w the
# whole run's.
whole_stream() {
    name=$1
    shift
    run "$bin" envelope --model nn --nn net.json "$@"
    rc_w=$rc
    cp out "$name.w.out"
    cp err "$name.w.err"
    [ -f "$name.csv" ] && mv "$name.csv" "$name.w.csv"
    [ -f "$name.crg" ] && mv "$name.crg" "$name.w.crg"
    run "$bin" envelope --model nn --nn net.json "$@" --stream
    cp out "$name.s.out"
    cp err "$name.s.err"
    [ -f "$name.csv" ] && mv "$name.csv" "$name.s.csv"
    [ -f "$name.crg" ] && mv "$name.crg" "$name.s.crg"
}

run "$bin" road --class C --length 60 --dx 0.001 --seed 3 -o road.csv
whole_stream iso --profile road.csv --contact-length 0.33 --extrapolate -o iso.csv
check "ISO 8608 road, 60 m at 1 mm: --stream writes the whole run's CSV byte for byte" \
    '[ $rc -eq 0 ] && [ $rc_w -eq 0 ] && [ $(rows iso.s.csv) -eq 61401 ] &&
     cmp -s iso.w.csv iso.s.csv'
check "ISO 8608 road: the same warnings and summary" \
    'cmp -s iso.w.err iso.s.err && grep -q "obstacles above a baseline" iso.s.err'
whole_stream isoout --profile road.csv --load 15000 --extrapolate --dx 0.0031 --x-from 7.77
check "ISO 8608 road to standard output at another load and sweep: the same bytes" \
    '[ $rc -eq 0 ] && [ $rc_w -eq 0 ] && [ -s isoout.s.out ] && cmp -s isoout.w.out isoout.s.out'
whole_stream eff --profile road.csv --contact-length 0.33 --extrapolate --dx 0.01 -o eff.crg
check "ISO 8608 road as an effective OpenCRG road: the same file" \
    '[ $rc -eq 0 ] && [ $rc_w -eq 0 ] && [ -s eff.s.crg ] && cmp -s eff.w.crg eff.s.crg'

whole_stream barber --profile "$samples/crg/Barber.crg" --contact-length 0.33 --extrapolate \
    --x-from 2800 --x-to 3300 --dx 0.005 -o barber.csv
check "measured road (Barber.crg, 500 m): --stream writes the same bytes" \
    '[ $rc -eq 0 ] && [ $rc_w -eq 0 ] && [ $(rows barber.s.csv) -eq 100001 ] &&
     cmp -s barber.w.csv barber.s.csv'
whole_stream barber3 --profile "$samples/crg/Barber.crg" --contact-length 0.33 --extrapolate \
    --tracks 3 --x-from 2800 --x-to 3000 --dx 0.005 -o barber3.csv
check "measured road over three tracks: the same bytes" \
    '[ $rc -eq 0 ] && [ $rc_w -eq 0 ] && [ -s barber3.s.csv ] && cmp -s barber3.w.csv barber3.s.csv'

# Cleats in and out of the trained range on level ground, and a plateau 12 m long (longer
# than the window, which holds about 9 m: the opening takes it into the baseline).
printf 'x_m,z_m\n0,0\n3.1,0\n3.1,0.05\n3.25,0.05\n3.25,0\n6.4,0\n6.4,0.08\n6.46,0.08\n6.46,0\n' \
    >cleats.csv
printf '6.52,0\n6.52,0.03\n6.8,0.03\n6.8,0\n10,0\n10,0.06\n22,0.06\n22,0\n30,0\n' >>cleats.csv
run "$bin" envelope --model nn --nn net.json --profile cleats.csv --contact-length 0.38 \
    --extrapolate -o cleats_w.csv
rc_w=$rc
run "$bin" envelope --model nn --nn net.json --profile cleats.csv --contact-length 0.38 \
    --extrapolate --stream -o cleats_s.csv
check "cleats and a plateau longer than the window: the same bytes, the curve lifted" \
    '[ $rc -eq 0 ] && [ $rc_w -eq 0 ] && [ $(rows cleats_s.csv) -gt 30000 ] &&
     cmp -s cleats_w.csv cleats_s.csv &&
     awk -F, "NR > 1 && \$3 > 0.05 { n++ } END { exit !(n > 1000) }" cleats_s.csv'
printf 'x_m,z_m\n-0.05,0\n-0.05,0.075\n0.05,0.075\n0.05,0\n' >cleat.csv
whole_stream one --profile cleat.csv --contact-length 0.38 --dx 0.0001 -o one.csv
check "a single cleat (the network's own case), 15001 positions: the same bytes" \
    '[ $rc -eq 0 ] && [ $rc_w -eq 0 ] && [ $(rows one.s.csv) -eq 15001 ] &&
     cmp -s one.w.csv one.s.csv'

# Without --extrapolate the road's obstacles (lower than any trained cleat) are refused.
whole_stream refused --profile road.csv --contact-length 0.33 -o refused.csv
check "outside the trained range: both refuse (exit 2), no file, the same obstacle named" \
    '[ $rc -eq 2 ] && [ $rc_w -eq 2 ] && no_file refused.csv && no_file refused.w.csv &&
     no_file refused.s.csv &&
     [ "$(grep -o "the obstacle at x = [^(]*" refused.w.err)" = \
       "$(grep -o "the obstacle at x = [^(]*" refused.s.err)" ] &&
     grep -q "streamed window" refused.s.err'
# predict is envelope --model nn: its --stream too, the same bytes and warnings.
run "$bin" predict --nn net.json --profile road.csv --contact-length 0.33 --extrapolate \
    --stream -o predict.csv
check "predict --stream: the envelope's streamed CSV, byte for byte, and its warnings" \
    '[ $rc -eq 0 ] && cmp -s predict.csv iso.s.csv &&
     [ "$(grep "^tirenv: predict: warning" err | sed "s/^tirenv: predict: //")" = \
       "$(grep "^tirenv: envelope: warning" iso.s.err | sed "s/^tirenv: envelope: //")" ] &&
     grep -q "^tirenv: predict: warning" err'

clilib_done

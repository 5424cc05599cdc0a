#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# tirenv study end to end on the embedded data set: every promised file, the simulated-data
# label, one error row per validation case and model, and a fitted tire that reads back. One
# study, at --jobs 3 (more threads than cores): that --jobs 1 writes the same files apart from
# the timings is checked on the test data set by tests/study/study_killed.sh, whose last run
# is at --jobs 1, at no extra study (a second study here cost as much as the first).
set -eu
bin=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
pass=0 fail=0
check() { # check N "what" command...
    n=$1 what=$2
    shift 2
    if "$@" >/dev/null 2>&1; then pass=$((pass + 1)); echo "ok $n - $what"
    else fail=$((fail + 1)); echo "not ok $n - $what"; fi
}
"$bin" study --jobs 3 -o "$tmp/s" >"$tmp/out" 2>&1 || { cat "$tmp/out"; echo "0 passed, 1 failed"; exit 1; }
for f in report.md errors.csv errors.md timing.csv fitted.tir nn.json nn-physical.json nn-seeds.csv \
         F.png F.svg F.gp F.dat J.png R.png AB.png physical-network/report.md \
         outside/report.md outside/tall.png outside/cylinder.png; do
    check 1 "study wrote $f" test -s "$tmp/s/$f"
done
check 2 "the report says the data are simulated" grep -q "SIMULATED" "$tmp/s/report.md"
# 4 validation cases x 5 models (rigid, springs, cam, ring, nn) plus the header.
check 3 "errors.csv: one row per case and model" test "$(wc -l <"$tmp/s/errors.csv")" -eq 21
check 4 "the fitted tire reads back" "$bin" flat --tire "$tmp/s/fitted.tir" --contact-length 0.33
check 5 "the trained network predicts case R" "$bin" predict --nn "$tmp/s/nn.json" \
    --cleat 0.10,0.10 --contact-length 0.28 -o "$tmp/R.csv"
# The stated accuracy on the validation cases (simulated by the ring tire): the identified
# springs model within 2 mm RMS on every case, the network within 5 mm (measured: at most
# 1.5 and 3.3 mm; the margins absorb a different libm or compiler, not a broken model).
within() { # within MODEL LIMIT_MM
    awk -F, -v m="$1" -v lim="$2" 'NR > 1 && $2 == m { n++; if (!($3 < lim)) bad++ }
        END { exit !(n == 4 && bad == 0) }' "$tmp/s/errors.csv"
}
check 6 "springs within 2 mm RMS on each validation case" within springs 2
check 7 "nn within 5 mm RMS on each validation case" within nn 5
# The network over 20 seeds: one row per seed, the validation error and one column per
# validation case; the report headlines their median, and it names the data set as given,
# not by the build machine's absolute path.
check 8 "nn-seeds.csv: header and 20 seeds" awk -F, '
    NR == 1 { ok = $0 == "seed,validation_rms_mm,F_rms_mm,J_rms_mm,R_rms_mm,AB_rms_mm" }
    NR > 1 { n++; if (NF != 6 || !($2 > 0)) ok = 0 }
    END { exit !(ok && n == 20) }' "$tmp/s/nn-seeds.csv"
check 9 "the report gives the median over the seeds" grep -q "over 20 seeds, median" "$tmp/s/report.md"
check 10 "the report names the data set relatively" grep -q 'Data: `data/dataset`' "$tmp/s/report.md"
check 11 "no absolute path of this machine in the report or model" \
    sh -c '! grep -q "$1" "$2/report.md" "$2/nn.json"' sh "$(cd "$(dirname "$0")/../.." && pwd)" "$tmp/s"
check 12 "errors.csv has rms_over_H" grep -q "^case,model,rms_mm,max_mm,peak_mm,first_rise_mm,rms_over_H$" "$tmp/s/errors.csv"
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]

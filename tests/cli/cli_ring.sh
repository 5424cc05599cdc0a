#!/bin/sh
# The ring reference tire's own state from the command line (docs/models.md section 5): the
# --detail columns of envelope, the tread compression of flat, and the embedded data set's
# cases with their lugs within their thickness.
# Usage: tests/cli/cli_ring.sh BIN TESTDATA_DIR. SPDX-License-Identifier: Apache-2.0
# shellcheck disable=SC2016,SC2034,SC2086
. "$(dirname "$0")/../lib/clilib.sh"

t_r=0.04  # the default tire's TREAD_THICKNESS, m

# Largest value of column C of a CSV (after the header).
col_max() {
    awk -F, -v c="$2" 'NR > 1 && (NR == 2 || $c > m) { m = $c } END { print m }' "$1"
}

# The blade on the Winkler tread (TREAD_SHEAR 0), whose lugs it compresses through to the
# belt; the default's shear-coupled tread spreads the 13 kN over its decay length and is
# compressed 24 mm of its 40, the belt untouched.
run "$bin" envelope --model ring --cleat 0.005,0.3 --load 13000 --x-from -0.02 --x-to 0.02 \
    --dx 0.001 --detail --set TREAD_SHEAR=0 -o blade.csv
check "envelope --detail: the header gains tread_max_m,belt_contacts" \
    '[ $rc -eq 0 ] && [ "$(head -n 1 blade.csv)" = "$header,tread_max_m,belt_contacts" ] &&
     [ "$(rows blade.csv)" -eq 41 ]'
check "a 5 x 300 mm blade lifts the ring by most of its height (h > 0.2 m at every row)" \
    'awk -F, "NR > 1 && \$3 <= 0.2 { bad = 1 } END { exit bad }" blade.csv'
check "on the blade the belt itself touches and the lugs are compressed through, not beyond" \
    'awk -F, -v t=$t_r "NR > 1 && (\$10 < 1 || \$9 > t || \$9 < t - 1e-3) { bad = 1 }
        END { exit bad }" blade.csv'
run "$bin" envelope --model ring --cleat 0.005,0.3 --load 13000 --x-from -0.02 --x-to 0.02 \
    --dx 0.001 --set TREAD_SHEAR=0 -o plain.csv
check "without --detail the rows are the same, without the two columns" \
    '[ $rc -eq 0 ] && [ "$(cut -d, -f1-8 blade.csv | tail -n +2)" = "$(tail -n +2 plain.csv)" ]'
run "$bin" envelope --model springs --cleat 0.10,0.10 --load 13000 --detail -o s.csv
check "--detail with another model: misuse, exit 1, no file" \
    '[ $rc -eq 1 ] && grep -q -- "--detail" err && no_file s.csv'
printf 'x_m,z_m\n-1,0\n0,0\n0,0.05\n0.2,0.05\n0.2,0\n1,0\n' >p.csv
run "$bin" envelope --model ring --profile p.csv --load 13000 --stream --detail -o s.csv
check "--detail with --stream: misuse, exit 1, no file" \
    '[ $rc -eq 1 ] && grep -q -- "--detail" err && no_file s.csv'

run "$bin" flat --model ring
check "flat --model ring: a tread column, compression a modest share of t_r at each regime" \
    '[ $rc -eq 0 ] && grep -q "tread_mm" out &&
     [ "$(awk "NR > 2 && \$8 > 0 && \$8 < 0.2 * $t_r * 1000 { k++ } END { print k }" out)" = 3 ]'
run "$bin" flat --model ring --csv
check "flat --model ring --csv: the column tread_max_m" \
    '[ $rc -eq 0 ] && head -n 1 out | grep -q ",tread_max_m$" && [ "$(rows out)" -eq 3 ]'
run "$bin" flat --model ring --load 17660
check "flat --model ring --load: a tread compression line" \
    '[ $rc -eq 0 ] && grep -q "^  tread compression " out'
run "$bin" flat --model springs --csv
check "flat with another model: the CSV as before" \
    '[ $rc -eq 0 ] && [ "$(head -n 1 out)" = load_N,z_flat_m,deflection_m,contact_length_m,stiffness_N_per_m ]'

# Every case of the embedded data set, as the ring runs it (2 mm steps over the approach
# half): the lugs never compressed beyond t_r (measured: at most 32.7 mm, case 19's 0.43 m
# over the 50 x 100 mm cleat). The sanitizer build (TIRENV_TEST_SANITIZED=1) runs 4 of the 28,
# every seventh from the fifth (5, 12, 19, 26: case 19 among them); the cases differ in their
# numbers, not in the code they run, and the 28 are most of this test's time (measured: 8.0
# of its 8.8 s of CPU in Release; under the sanitizers 31 s of CPU with all 28, 6.4 with
# these 4). The Release build runs all 28.
cases=$data/../../data/dataset/cases.csv
every=1 first=1 want=28
if [ "${TIRENV_TEST_SANITIZED:-0}" = 1 ]; then
    every=7 first=5 want=4
    echo "# sanitizer build: cases 5, 12, 19 and 26 of the 28 (the Release build: all 28)"
fi
worst=0
count=0
i=0
for spec in $(awk -F, '!/^#/ && NR > 1 && $1 != "case" { print $3 "," $5 "," $6 }' "$cases"); do
    i=$((i + 1))
    [ $i -ge $first ] && [ $(((i - first) % every)) -eq 0 ] || continue
    lc=${spec%%,*} rest=${spec#*,}
    run "$bin" envelope --model ring --cleat "$rest" --contact-length "$lc" --x-to 0 \
        --dx 0.002 --detail -o case.csv
    [ $rc -eq 0 ] || { worst=failed; break; }
    worst=$(awk -v a="$worst" -v b="$(col_max case.csv 9)" 'BEGIN { print (b > a ? b : a) }')
    count=$((count + 1))
done
check "$count of the 28 data set cases: largest tread compression $worst m <= t_r" \
    '[ "$i" -eq 28 ] && [ "$count" -eq $want ] &&
     awk -v w="$worst" -v t=$t_r "BEGIN { exit !(w <= t) }"'

clilib_done

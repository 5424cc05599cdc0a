#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# A road file is opened once and its format told once (tirenv_road_file): every
# command that takes --profile reads it from a FIFO, which a writer fills once and which can
# be opened once. Before, the CLI opened the file up to three times (to tell the format, to
# read it, and once more per streamed pass), so the second open waited for a writer that never
# came: each check below then ended by the timeout (exit 124). Each output is compared byte
# for byte with the same command's on the regular file.
. "$(dirname "$0")/../lib/clilib.sh"

springs="--model springs --load 13000"
cp "$data/profile_good.csv" road.csv
run "$bin" convert --profile road.csv -o road.rdf
check "setup: road.rdf" '[ $rc -eq 0 ]'
run "$bin" convert --profile road.csv --dx 0.01 --pad 0.5 -o road.crg
check "setup: road.crg" '[ $rc -eq 0 ]'

# through FILE CMD...: runs CMD with the FIFO ./fifo fed FILE once by a writer of its own,
# under a timeout; stdout to ./out, stderr to ./err, exit status in $rc.
through() {
    file=$1
    shift
    rm -f fifo
    mkfifo fifo || exit 2
    cat "$file" >fifo 2>/dev/null &
    writer=$!
    timeout 60 "$@" >out 2>err
    rc=$?
    kill "$writer" 2>/dev/null  # a writer the command never read (it failed before)
    wait "$writer" 2>/dev/null
}

# same WHAT FILE OUTPUT ARGS...: `tirenv ARGS --profile fifo` with fifo fed FILE once exits 0
# and writes OUTPUT as it does with a regular file of the same name (an output may name it).
same() {
    what=$1 file=$2 output=$3
    shift 3
    rm -f fifo
    cp "$file" fifo
    "$bin" "$@" --profile fifo >/dev/null 2>&1 && mv "$output" "ref.$output"
    through "$file" "$bin" "$@" --profile fifo
    check "$what: from a FIFO read once, exit 0 and the regular file's $output" \
        '[ $rc -eq 0 ] && [ -s "ref.$output" ] && cmp -s "$output" "ref.$output"'
    rm -f "$output" "ref.$output"
}

for f in csv crg rdf; do
    same "envelope, $f" road.$f env.csv envelope $springs -o env.csv
    same "envelope --stream, $f" road.$f env.csv envelope $springs --stream -o env.csv
    same "convert, $f" road.$f conv.csv convert -o conv.csv
done
# Two readers of the one open file at once: the sweep's and the level's under the centre.
same "envelope --stream --relative-to ground, csv" road.csv env.csv \
    envelope $springs --stream --relative-to ground -o env.csv
# The effective road placed on the input road's reference line, from the same open file.
same "envelope -o X.crg over a .crg" road.crg eff.crg envelope $springs -o eff.crg
same "envelope --tracks 3 over a .crg" road.crg env.csv \
    envelope $springs --tracks 3 --width 0.2 -o env.csv
same "rig, csv" road.csv log.csv rig $springs -o log.csv

# A pipe's errors name it, as a file's do; nothing is left behind.
printf 'x_m,z_m\n0,0\n1,oops\n' >bad.csv
through bad.csv "$bin" envelope $springs --profile fifo -o env.csv
check "a bad row from a FIFO: exit 2 naming fifo, line 3, z_m" \
    '[ $rc -eq 2 ] && grep -q "^tirenv: fifo:3:.*z_m" err && no_file env.csv'

clilib_done

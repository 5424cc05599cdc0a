#!/bin/sh
# Output files and directories from outside: -o onto a character device, a FIFO, a symbolic
# link and /dev/stdout leaves each what it was (the link's target updated); a write killed by
# SIGTERM or SIGINT leaves no temporary file, one killed by SIGKILL leaves one that the next
# run removes; a failed multi-file command leaves no directory, a killed one the old one; ride
# --out-dir writes series only when asked; every single-file writer and convert's CSV onto
# /dev/null and a FIFO. Usage: tests/cli/cli_output.sh BIN TESTDATA_DIR.
# SPDX-License-Identifier: Apache-2.0
# shellcheck disable=SC2016,SC2034,SC2086
. "$(dirname "$0")/../lib/clilib.sh"

rigid='envelope --model rigid --cleat 0.3,0.05 --load 13000'
"$bin" $rigid -o ref.csv 2>/dev/null || { echo "not ok - reference run failed"; exit 1; }
is_root=0
[ "$(id -u)" -eq 0 ] && is_root=1

# No temporary entry of an output anywhere below the current directory.
no_tmp() {
    [ -z "$(find . -name '*tirenv-tmp*' -print)" ]
}
# Device numbers of a node, "major,minor".
devnum() {
    stat -c '%t,%T' "$1"
}

# --- what is not a regular file is written through, never replaced ----------------------
run "$bin" $rigid -o /dev/null
check "-o /dev/null: exit 0, /dev/null still the character device 1,3" \
    '[ $rc -eq 0 ] && [ -c /dev/null ] && [ "$(devnum /dev/null)" = 1,3 ]'

if [ $is_root -eq 1 ]; then
    mknod cdev c 1 3
    run "$bin" $rigid -o cdev
    check "-o onto a character device made by mknod: exit 0, still that device" \
        '[ $rc -eq 0 ] && [ -c cdev ] && [ "$(devnum cdev)" = 1,3 ] && no_tmp'
    rm -f cdev
    mknod bdev b 7 0
    run "$bin" $rigid -o bdev
    check "-o onto a block device: refused (exit 2), the node untouched" \
        '[ $rc -eq 2 ] && grep -q "block device" err && [ -b bdev ] && no_tmp'
    rm -f bdev
else
    echo "# NOT TESTED: -o onto a device node made by mknod (and a block device) needs root;"
    echo "# this run is not root. /dev/null and the other checks below still ran."
fi

mkfifo fifo
cat fifo >from-fifo.csv &
reader=$!
run "$bin" $rigid -o fifo
wait $reader
check "-o onto a FIFO with a reader: the reader gets the CSV, the FIFO stays a FIFO" \
    '[ $rc -eq 0 ] && [ -p fifo ] && cmp -s from-fifo.csv ref.csv && no_tmp'
rm -f fifo

# Every command that writes one file writes through onto /dev/null (README: devices are
# written through), whatever format the name would otherwise pick: convert and road take CSV
# for a name without an extension that is a device, a FIFO or a descriptor, as for '-'.
printf 'x_m,z_m\n-1,0\n0,0.05\n1,0\n' >bump.csv
# The data set by a name without blanks: the option lists below are split into words.
ln -s "$data/dataset_good" good
for args in "convert --profile bump.csv" "road --class C --length 10" "$rigid" \
    "rig --model springs --cleat 0.1,0.025 --contact-length 0.43" \
    "ride --cleat 0.30,0.05 --speed 10km/h --model point" \
    "fit --data good" "train --data good --restarts 1 --epochs 5"; do
    run "$bin" $args -o /dev/null
    check "${args%% *} -o /dev/null: exit 0, /dev/null still the device" \
        '[ $rc -eq 0 ] && [ -c /dev/null ] && [ "$(devnum /dev/null)" = 1,3 ]'
done
run "$bin" rig --model springs --cleat 0.1,0.025 --contact-length 0.43 -o log.csv
run "$bin" import --log log.csv --cleat 0.1,0.025 --contact-length 0.43 -o /dev/null
check "import -o /dev/null: exit 0" '[ $rc -eq 0 ] && [ -c /dev/null ]'
run "$bin" convert --profile bump.csv -o /dev/stdout
check "convert -o /dev/stdout: the CSV on stdout" \
    '[ $rc -eq 0 ] && [ "$(head -n 1 out)" = x_m,z_m ] && grep -q "^0,0.05$" out'
mkfifo fifo
cat fifo >from-fifo.csv &
reader=$!
run "$bin" convert --profile bump.csv -o fifo
wait $reader
check "convert -o FIFO (no extension): its reader gets the CSV" \
    '[ $rc -eq 0 ] && [ -p fifo ] && [ "$(head -n 1 from-fifo.csv)" = x_m,z_m ] && no_tmp'
rm -f fifo
run "$bin" convert --profile bump.csv -o plainfile
check "convert -o a regular name without an extension: still exit 1 naming the extensions" \
    '[ $rc -eq 1 ] && grep -q "unknown extension" err && [ ! -e plainfile ]'

mkdir data
echo old >data/target.csv
ln -s data/target.csv link.csv
run "$bin" $rigid -o link.csv
check "-o onto a symbolic link: the link remains, its target is replaced" \
    '[ $rc -eq 0 ] && [ -L link.csv ] && [ "$(readlink link.csv)" = data/target.csv ] &&
     cmp -s data/target.csv ref.csv && no_tmp'

echo "first line" >log.csv
"$bin" $rigid -o /dev/stdout >>log.csv 2>err
rc=$?
check "-o /dev/stdout >> FILE appends to FILE, as the shell's redirection asks" \
    '[ $rc -eq 0 ] && [ "$(head -n 1 log.csv)" = "first line" ] &&
     [ "$(tail -n +2 log.csv | cmp - ref.csv && echo same)" = same ]'

run "$bin" $rigid -o "$PWD"
check "-o onto a directory: refused (exit 2) naming it" '[ $rc -eq 2 ] && grep -q "directory" err'

# --- a killed write ----------------------------------------------------------------------
# A slow write (the ring over a cleat at 0.1 mm, some seconds) into killed.csv, which holds
# the previous result; the signal comes once its temporary file exists.
slow='envelope --model ring --cleat 0.30,0.10 --contact-length 0.38 --dx 0.0001'
# kill_midway SIGNAL [launcher...]: starts the slow write, sends SIGNAL while it writes; sets
# rc to its exit status and seen=1 if the temporary file was there when the signal went.
kill_midway() {
    sig=$1
    shift
    "$@" "$bin" $slow -o killed.csv >/dev/null 2>err &
    pid=$!
    seen=0
    i=0
    while [ $i -lt 300 ]; do
        if [ -n "$(find . -name '.killed.csv.tirenv-tmp.*' -print)" ]; then
            seen=1
            break
        fi
        sleep 0.1
        i=$((i + 1))
    done
    kill -s "$sig" $pid
    wait $pid
    rc=$?
}
cp ref.csv killed.csv
kill_midway TERM
check "a write killed by SIGTERM: dies of it (143), no temporary file, the old file intact" \
    '[ $seen -eq 1 ] && [ $rc -eq 143 ] && no_tmp && cmp -s killed.csv ref.csv'
# An asynchronous command of a non-interactive shell starts with SIGINT ignored; env resets
# it, as an interactive shell does for a program it runs.
if env --default-signal=INT true 2>/dev/null; then
    kill_midway INT env --default-signal=INT
    check "a write killed by SIGINT: dies of it (130), no temporary file, the old file intact" \
        '[ $seen -eq 1 ] && [ $rc -eq 130 ] && no_tmp && cmp -s killed.csv ref.csv'
else
    echo "# NOT TESTED: SIGINT needs 'env --default-signal' (coreutils >= 8.31) to undo the"
    echo "# shell's SIG_IGN for a background job; SIGTERM above uses the same handler."
fi
kill_midway KILL
check "a write killed by SIGKILL leaves its temporary file (nothing can catch SIGKILL)" \
    '[ $seen -eq 1 ] && [ $rc -eq 137 ] && ! no_tmp && cmp -s killed.csv ref.csv'
run "$bin" $rigid -o other.csv
check "the next run writing into that directory removes it" '[ $rc -eq 0 ] && no_tmp'

# --- output directories ------------------------------------------------------------------
run "$bin" study --data /nonexistent -o rep
check "study --data /nonexistent -o rep: exit 2, no rep/ and nothing beside it" \
    '[ $rc -eq 2 ] && [ ! -e rep ] && no_tmp'
run "$bin" study --data /nonexistent -o new/sub/rep
check "... and no parent directories it would have made" '[ $rc -eq 2 ] && [ ! -e new ]'

good="--data good --models rigid --no-images"
mkdir cmp
echo "the user's notes" >cmp/notes.txt
run "$bin" compare $good -o cmp
check "compare -o over a directory: the comparison written, the user's file kept" \
    '[ $rc -eq 0 ] && [ -s cmp/report.md ] && [ -s cmp/errors.csv ] &&
     [ "$(cat cmp/notes.txt)" = "the user'"'"'s notes" ] && no_tmp'
ln -s cmp cmp-link
run "$bin" compare $good -o cmp-link
check "compare -o onto a link to a directory: the link remains, the directory rewritten" \
    '[ $rc -eq 0 ] && [ -L cmp-link ] && [ -d cmp ] && [ -s cmp/report.md ] && no_tmp'
echo "not a directory" >plain
run "$bin" compare $good -o plain
check "compare -o onto a file: refused (exit 2), the file untouched" \
    '[ $rc -eq 2 ] && [ "$(cat plain)" = "not a directory" ] && no_tmp'

run "$bin" ride --cleat 0.30,0.05 --speed 10km/h --model point --out-dir rd
check "ride --out-dir: comfort tables and plot data, no series unless asked" \
    '[ $rc -eq 0 ] && [ -s rd/comfort.csv ] && [ -s rd/seat.dat ] &&
     [ -z "$(find rd -name "series-*")" ] && no_tmp'
run "$bin" ride --cleat 0.30,0.05 --speed 10km/h --model point --out-dir rd --series
check "ride --out-dir --series: the run's series too" \
    '[ $rc -eq 0 ] && [ -s rd/series-point-10kmh.csv ] && [ -s rd/comfort.csv ]'
# -o and --out-dir together: a failure in the report (here a gnuplot that fails) leaves both as
# they were; -o's file is committed with the directory, not before it.
mkdir -p failing-bin
printf '#!/bin/sh\necho "drawing failed" >&2\nexit 1\n' >failing-bin/gnuplot
chmod +x failing-bin/gnuplot
echo kept >series.csv
run env PATH="$PWD/failing-bin:$PATH" "$bin" ride --cleat 0.30,0.05 --speed 10km/h --model point \
    -o series.csv --out-dir rd
check "ride -o with --out-dir whose report fails: exit 2, -o's file and the directory as they were" \
    '[ $rc -eq 2 ] && [ "$(cat series.csv)" = kept ] && [ -s rd/series-point-10kmh.csv ] &&
     grep -q "drawing failed" err && no_tmp'
# No gnuplot at all: the message names the program and how to install it, not a staging
# directory that is gone by the time it is read.
mkdir -p no-gnuplot-bin
ln -sf "$(command -v env)" no-gnuplot-bin/env
run env PATH="$PWD/no-gnuplot-bin" "$bin" ride --cleat 0.30,0.05 --speed 10km/h --model point \
    --out-dir rd-none
check "ride --out-dir without gnuplot: exit 2 naming gnuplot and gnuplot-nox, no temporary path" \
    '[ $rc -eq 2 ] && grep -q "cannot run .gnuplot." err && grep -q "gnuplot-nox" err &&
     ! grep -q "tirenv-tmp" err && [ ! -e rd-none ] && no_tmp'
run "$bin" ride --cleat 0.30,0.05 --speed 10km/h --model point --series
check "ride --series without --out-dir: exit 1" '[ $rc -eq 1 ] && grep -q -- "--out-dir" err'

# --crg-encoding is how an effective road goes into a .crg: with a CSV curve or an RDF road it
# would change nothing, and is refused rather than ignored.
echo keep >enc.csv
for o in "-o enc.csv" "-o enc.rdf" ""; do
    run "$bin" $rigid --crg-encoding lrfi $o
    check "envelope --crg-encoding lrfi ${o:-to standard output}: exit 1, nothing written" \
        '[ $rc -eq 1 ] && grep -q "crg-encoding applies to -o FILE.crg" err && [ ! -s out ] &&
         [ "$(cat enc.csv)" = keep ] && [ ! -e enc.rdf ]'
done
run "$bin" $rigid --crg-encoding lrfi -o enc.crg
check "... and with -o FILE.crg: written as LRFI" '[ $rc -eq 0 ] && grep -aq "^#:LRFI" enc.crg'

clilib_done

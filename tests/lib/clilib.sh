#!/bin/sh
# What every CLI check script (tests/cli_*.sh and cli.sh) shares: a scratch directory, run and
# check, and small CSV predicates. Sourced after setting bin and data:
#   . "$(dirname "$0")/../lib/clilib.sh"
# Prints "ok N - what" / "not ok N - what" per check; end with clilib_done.
# SPDX-License-Identifier: Apache-2.0
# Conditions are single-quoted shell code for eval (SC2016, SC2034); option lists in variables
# are split on purpose (SC2086).
# shellcheck disable=SC2016,SC2034,SC2086
set -u

if [ $# -ne 2 ]; then
    echo "usage: $0 BIN TESTDATA_DIR" >&2
    exit 2
fi
bin=$1
data=$2
# The checks run in a scratch directory: make relative paths absolute first (a bare name
# without a slash is left to the PATH search).
case $bin in /*) ;; */*) bin=$PWD/$bin ;; esac
case $data in /*) ;; *) data=$PWD/$data ;; esac
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
trap 'exit 2' INT TERM
cd "$work" || exit 2
unset TIRENV_DATA  # the checks assume the built-in default tire unless they set it

n=0
passed=0
failed=0

# run CMD...: stdout to ./out, stderr to ./err, exit status in $rc.
run() {
    "$@" >out 2>err
    rc=$?
}

# check WHAT CONDITION: CONDITION is shell code, evaluated after the last run. On failure the
# command's stderr is shown as a TAP comment.
check() {
    n=$((n + 1))
    if eval "$2"; then
        passed=$((passed + 1))
        echo "ok $n - $1"
    else
        failed=$((failed + 1))
        echo "not ok $n - $1"
        echo "# exit status $rc; stderr:"
        sed 's/^/#   /' err
    fi
}

# feed SRC FIFO: SRC's bytes written into FIFO (made by the caller) in the background, the
# writer's id in $writer. Its open of FIFO runs under timeout, so that a writer nobody reads
# ends by itself.
feed() {
    timeout 60 sh -c 'exec cat "$0" >"$1" 2>/dev/null' "$1" "$2" &
    writer=$!
}

# release_writer FIFO: ends the writer of feed by opening the FIFO read-write, which never
# blocks and lets a waiting open through (its writes then end on a closed pipe), again until
# the writer (timeout, which lives as long as its shell does) has ended: a shell that had not
# reached its open yet opens later. It is not killed: killing timeout could leave its shell
# behind, orphaned, blocked in the open of a FIFO in a deleted directory and holding CTest's
# output pipe, so that the test never ended (seen twice; a TERM can also be lost between the
# shell's fork and its open). At most timeout's 60 s.
release_writer() {
    release_tries=0 # not n, the checks' count
    while [ $release_tries -lt 1200 ] && [ -r "/proc/$writer/stat" ] &&
        ! grep -q ') Z ' "/proc/$writer/stat" 2>/dev/null; do
        : <>"$1"
        sleep 0.05
        release_tries=$((release_tries + 1))
    done
    wait "$writer" 2>/dev/null
}

# No output file and no temporary file beside it (.NAME.tirenv-tmp.* of an output, NAME.tmp.*
# of a plot being drawn).
no_file() {
    [ ! -e "$1" ] && [ -z "$(find . -name '*tmp.*' -print)" ]
}

# Whole mode's error for the road in $1 (envelope --profile $1, the cam model's $cam), in
# ./want: true if it fails with exit 2 and no file.
want_error() {
    rm -f want
    run "$bin" envelope $cam --profile "$1" -o w.csv
    [ $rc -eq 2 ] && no_file w.csv && cp err want
}

# --stream over the road in $1, bad in a middle row (want: whole mode's error, want_error):
# the same error and nothing written into a file, past the sweep's end, and to standard output.
stream_refuses_mid() {
    run "$bin" envelope $cam --profile "$1" --stream -o s.csv
    check "--stream into a file, a bad row mid-road: whole mode's error, no file" \
        '[ $rc -eq 2 ] && cmp -s err want && no_file s.csv'
    run "$bin" envelope $cam --profile "$1" --stream --x-from 1 --x-to 2 -o s.csv
    check "a bad row past the sweep's end: still read, the same error, no file" \
        '[ $rc -eq 2 ] && cmp -s err want && no_file s.csv'
    run "$bin" envelope $cam --profile "$1" --stream
    check "to standard output: the same error before any row" \
        '[ $rc -eq 2 ] && cmp -s err want && [ ! -s out ]'
}

# Number of CSV data rows (lines after the header).
rows() {
    echo $(($(wc -l <"$1") - 1))
}

# The largest h (m) in an envelope CSV.
peak_h() {
    awk -F, 'NR > 1 && (NR == 2 || $3 > m) { m = $3 } END { print m }' "$1"
}

# |A - B| <= TOL for numbers A, B.
near() {
    awk -v a="$1" -v b="$2" -v t="$3" 'BEGIN { d = a - b; exit !(d <= t && -d <= t) }'
}

# h within TOL at the first and the last position.
ends_flat() {
    awk -F, -v t="$2" 'NR == 2 { first = $3 } { last = $3 }
        END { exit !(first <= t && -first <= t && last <= t && -last <= t) }' "$1"
}

# Two envelope CSVs of equal length with h equal within TOL, row by row.
same_h() {
    [ -s "$1" ] && [ "$(wc -l <"$1")" -eq "$(wc -l <"$2")" ] &&
        paste -d, "$1" "$2" | awk -F, -v t="$3" '
            NR > 1 { d = $3 - $11; if (d > t || -d > t) bad = 1 }
            END { exit bad || NR < 2 }'
}

# An envelope CSV against case C of the reference file: all 10 positions present, h within
# 1e-8 m (the file has 9 decimals), load within 1e-3 N (CSV rows have 9 digits).
matches_reference() {
    awk -F, -v c="$2" '
        FNR == 1 { next }
        NR == FNR { k = sprintf("%.4f", $1); h[k] = $3; f[k] = $6; next }
        $1 == c {
            k = sprintf("%.4f", $10); ++seen
            if (!(k in h)) { bad = 1; next }
            d = h[k] - $11; e = f[k] - $12
            if (d > 1e-8 || -d > 1e-8 || e > 1e-3 || -e > 1e-3) bad = 1
        }
        END { exit bad || seen != 10 }' "$1" "$3"
}

header='x_m,z_m,h_m,slope,fx_N,fz_N,contacts,iterations'
cleat_F='--cleat 0.30,0.10 --contact-length 0.38'

# Ends the script: the tally, and the exit status CTest reads.
clilib_done() {
    echo "$passed passed, $failed failed"
    [ "$failed" -eq 0 ]
}

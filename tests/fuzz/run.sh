#!/bin/sh
# Runs one libFuzzer harness for a while: tests/fuzz/run.sh HARNESS SEED_CORPUS WORK_DIR [SECONDS]
# (SECONDS default $FUZZ_SECONDS, else 1: the smoke test of make test; make fuzz
# FUZZ_SECONDS=N runs longer). New inputs go to WORK_DIR/corpus, never into the repository's
# seed corpus; a crash, leak, hang (10 s per input) or sanitizer report writes its input to
# WORK_DIR and fails, naming the file to reproduce it with (HARNESS FILE).
# SPDX-License-Identifier: Apache-2.0
set -u
if [ $# -lt 3 ]; then
    echo "usage: $0 HARNESS SEED_CORPUS WORK_DIR [SECONDS]" >&2
    exit 2
fi
harness=$1 seeds=$2 work=$3
seconds=${4:-${FUZZ_SECONDS:-1}}
name=$(basename "$harness")
mkdir -p "$work/corpus" || exit 2
rm -f "$work"/crash-* "$work"/leak-* "$work"/timeout-* "$work"/oom-* "$work/log"
[ -d "$seeds" ] || { echo "# no seed corpus at $seeds: starting from nothing"; seeds=""; }
echo "# $name for $seconds s, seeds ${seeds:-none}, new inputs in $work/corpus"
# -max_len: the seeds decide it otherwise, and a rig log seed is 60 kB.
# $seeds is empty (no argument) or one directory (one argument, blanks and all).
"$harness" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=65536 \
    -print_final_stats=1 -artifact_prefix="$work/" "$work/corpus" ${seeds:+"$seeds"} \
    >"$work/log" 2>&1
status=$?
grep -E "stat::number_of_executed_units|stat::peak_rss|ERROR|SUMMARY|Test unit written|runtime error|Done [0-9]+ runs" \
    "$work/log" | sed 's/^/# /'
if [ $status -ne 0 ]; then
    echo "not ok - $name: exit status $status; the full log is $work/log"
    tail -40 "$work/log" | sed 's/^/#   /'
    exit 1
fi
echo "ok - $name: no crash, leak, hang or sanitizer report"

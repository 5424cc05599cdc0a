#!/bin/sh
# The shipped data set equals a fresh regeneration, byte for byte, run serially (--jobs 1) and
# on three threads (--jobs 3): the bytes do not depend on the number of jobs.
set -eu
bin=$1 shipped=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
pass=0 fail=0 n=0
for jobs in 1 3; do
    n=$((n + 1))
    "$bin" dataset build --jobs "$jobs" -o "$tmp/dataset-$jobs" 2>/dev/null
    if diff -r -x README.md "$shipped" "$tmp/dataset-$jobs" >"$tmp/diff"; then
        pass=$((pass + 1))
        echo "ok $n - data/dataset equals a fresh 'tirenv dataset build --jobs $jobs'"
    else
        fail=$((fail + 1))
        sed 's/^/# /' "$tmp/diff" | head -20
        echo "not ok $n - data/dataset differs from a fresh 'tirenv dataset build --jobs $jobs'"
    fi
done
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]

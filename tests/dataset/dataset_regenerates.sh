#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# A shipped data set equals a fresh regeneration, byte for byte (its README.md apart, which
# a person writes), run serially (--jobs 1) and on three threads (--jobs 3): the bytes do not
# depend on the number of jobs. tests/dataset/dataset_regenerates.sh BIN SHIPPED_DIR [DESIGN].
set -eu
bin=$1 shipped=$2 design=${3:-}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
pass=0 fail=0 n=0
for jobs in 1 3; do
    n=$((n + 1))
    "$bin" dataset build ${design:+--design "$design"} --jobs "$jobs" -o "$tmp/dataset-$jobs" \
        2>/dev/null
    what="$(basename "$shipped") equals a fresh 'tirenv dataset build${design:+ --design $design} --jobs $jobs'"
    if diff -r -x README.md "$shipped" "$tmp/dataset-$jobs" >"$tmp/diff"; then
        pass=$((pass + 1))
        echo "ok $n - $what"
    else
        fail=$((fail + 1))
        sed 's/^/# /' "$tmp/diff" | head -20
        echo "not ok $n - $what"
    fi
done
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]

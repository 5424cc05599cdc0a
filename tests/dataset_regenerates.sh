#!/bin/sh
# The shipped data set equals a fresh regeneration, byte for byte.
set -eu
bin=$1 shipped=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$bin" dataset build -o "$tmp/dataset" 2>/dev/null
if diff -r -x README.md "$shipped" "$tmp/dataset" >"$tmp/diff"; then
    echo "ok 1 - data/dataset equals a fresh 'tirenv dataset build'"
    echo "1 passed, 0 failed"
else
    head -20 "$tmp/diff"
    echo "not ok 1 - data/dataset differs from a fresh 'tirenv dataset build'"
    echo "0 passed, 1 failed"
    exit 1
fi

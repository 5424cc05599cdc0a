#!/bin/sh
# A shipped data set equals a fresh regeneration, byte for byte (its README.md apart, which
# a person writes): tests/dataset_regenerates.sh BIN SHIPPED_DIR [DESIGN].
set -eu
bin=$1 shipped=$2 design=${3:-}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$bin" dataset build ${design:+--design "$design"} -o "$tmp/dataset" 2>/dev/null
what="$(basename "$shipped") equals a fresh 'tirenv dataset build${design:+ --design $design}'"
if diff -r -x README.md "$shipped" "$tmp/dataset" >"$tmp/diff"; then
    echo "ok 1 - $what"
    echo "1 passed, 0 failed"
else
    sed 's/^/# /' "$tmp/diff" | head -20
    echo "not ok 1 - $what"
    echo "0 passed, 1 failed"
    exit 1
fi

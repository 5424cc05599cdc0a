#!/bin/sh
# The shared library exports the public API and nothing else: every dynamic symbol it
# defines is a tirenv_ name declared in a public header, none is a tirenv_x__y internal, and
# its soname carries the major version.
#   sh tests/package/exports.sh LIBTIRENV.so INCLUDE_DIR MAJOR [--asan]
# With --asan (a -fsanitize=address build) AddressSanitizer's __odr_asan.NAME, the one-
# definition-rule indicator it adds beside each exported variable NAME, is left out.
# SPDX-License-Identifier: Apache-2.0
set -u
lib=$1 include=$2 major=$3 asan=${4:-}
# shellcheck source=tests/lib/tap.sh
. "$(dirname "$0")/../lib/tap.sh"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

nm -D --defined-only "$lib" | awk '{ print $NF }' | sort >"$tmp/all"
if [ "$asan" = --asan ]; then
    grep -v '^__odr_asan\.tirenv_' "$tmp/all" >"$tmp/symbols"
else
    cp "$tmp/all" "$tmp/symbols"
fi
check "nm -D lists at least the model API" grep -qx tirenv_model_eval "$tmp/symbols"
grep -- __ "$tmp/symbols" >"$tmp/internal"
check "no exported symbol contains __ ($(wc -l <"$tmp/internal") do)" test ! -s "$tmp/internal" ||
    sed 's/^/#   /' "$tmp/internal"
grep -v '^tirenv_' "$tmp/symbols" >"$tmp/foreign"
check "every exported symbol starts with tirenv_" test ! -s "$tmp/foreign" ||
    sed 's/^/#   /' "$tmp/foreign"
# GCC's target_clones (src/nn/network.c) adds NAME.resolver, the ifunc that picks NAME's
# clone at load time, beside NAME itself: it counts as NAME.
grep -ohw 'tirenv_[A-Za-z0-9_]*' "$include"/tirenv/*.h | sort -u >"$tmp/declared"
sed 's/\.resolver$//' "$tmp/symbols" | sort -u | comm -23 - "$tmp/declared" >"$tmp/undeclared"
check "every exported symbol is declared in include/tirenv/ ($(wc -l <"$tmp/symbols") symbols)" \
    test ! -s "$tmp/undeclared" || sed 's/^/#   /' "$tmp/undeclared"
readelf -d "$lib" >"$tmp/dynamic"
check "soname libtirenv.so.$major" grep -q "(SONAME).*\[libtirenv\.so\.$major\]" "$tmp/dynamic"
tap_done

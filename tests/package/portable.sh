#!/bin/sh
# The generic C paths compile warning-free: every source of the library (src/, not the CLI's
# src/cli/, which has no such paths and takes its install layout from CMake) parsed with
# the flags of -DTIRENV_PORTABLE=ON (no SSE2 intrinsics, no AVX2 kernels, no per-processor
# clones: what a processor other than x86-64 compiles) and the project's warnings as errors, so
# that an x86-64 make test sees what a fresh clone elsewhere would fail to build. A syntax pass
# (some 4 s): the middle end's warnings and the outputs are make test-portable's (a whole
# build, its tests, its envelopes against the default build's, some 4 minutes). The flags
# come from CMakeLists.txt (TIRENV_WARNING_FLAGS, -Werror, TIRENV_PORTABLE_FLAGS, the
# packages' include directories):
#   sh tests/package/portable.sh CC SOURCE_DIR GENERATED_INCLUDE_DIR [CFLAGS...]
# SPDX-License-Identifier: Apache-2.0
set -u
cc=$1 src=$2 generated=$3
shift 3
# the packages' include directories as -I flags; a package in the compiler's own path gives "-I"
for a in "$@"; do
    shift
    [ "$a" = "-I" ] || set -- "$@" "$a"
done
# shellcheck source=tests/lib/tap.sh
. "$(dirname "$0")/../lib/tap.sh"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

count=0
for f in $(cd "$src" && find src -name '*.c' ! -path 'src/cli/*' | LC_ALL=C sort); do
    "$cc" -std=c11 -fsyntax-only -I"$src/include" -I"$generated" -I"$src/src" "$@" "$src/$f" \
        >"$tmp/log" 2>&1
    check "$f compiles warning-free with the generic paths alone" test $? -eq 0 ||
        sed 's/^/#   /' "$tmp/log"
    count=$((count + 1))
done
check "the sources were found ($count)" test "$count" -gt 100
case " $* " in
*" -Werror "*" -U__SSE2__ "*) check "the warnings as errors and the generic paths' flags given" true ;;
*) check "the warnings as errors and the generic paths' flags given ($*)" false ;;
esac
tap_done

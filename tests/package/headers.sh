#!/bin/sh
# The public headers as an embedder meets them: tirenv/tirenv.h includes every one of them,
# and each compiles on its own (self-contained, strict C11, no warning).
#   sh tests/package/headers.sh CC INCLUDE_DIR GENERATED_INCLUDE_DIR
# SPDX-License-Identifier: Apache-2.0
set -u
cc=$1 include=$2 generated=$3
# shellcheck source=tests/lib/tap.sh
. "$(dirname "$0")/../lib/tap.sh"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

for h in "$include"/tirenv/*.h "$generated"/tirenv/version.h; do
    name=$(basename "$h")
    case $name in tirenv.h | decls.h) continue ;; esac
    check "tirenv.h includes tirenv/$name" grep -q "^#include \"tirenv/$name\"" \
        "$include/tirenv/tirenv.h"
done
for h in "$include"/tirenv/*.h "$generated"/tirenv/version.h; do
    name=$(basename "$h")
    printf '#include "tirenv/%s"\n#include "tirenv/%s"\ntypedef int use_c;\n' "$name" "$name" \
        >"$tmp/use.c"
    "$cc" -std=c11 -Wall -Wextra -Wpedantic -Werror -fsyntax-only -I"$include" -I"$generated" \
        "$tmp/use.c" >"$tmp/log" 2>&1
    check "tirenv/$name compiles on its own, twice (include guard)" test $? -eq 0 ||
        sed 's/^/#   /' "$tmp/log"
done
tap_done

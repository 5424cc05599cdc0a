#!/bin/sh
# tirenv embedded in another project with add_subdirectory (tests/package/embed/CMakeLists.txt) is
# configured where pkg-config can see jansson and cminpack but not cmocka: it must configure.
#   sh tests/package/embed.sh CMAKE SOURCE_DIR
# SPDX-License-Identifier: Apache-2.0
set -u
cmake=$1 src=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mkdir "$tmp/pc"
for pkg in jansson cminpack; do
    ln -s "$(pkg-config --variable=pcfiledir "$pkg")/$pkg.pc" "$tmp/pc/$pkg.pc"
done
if ! PKG_CONFIG_LIBDIR=$tmp/pc pkg-config --exists cmocka && PKG_CONFIG_LIBDIR=$tmp/pc \
    "$cmake" -S "$src/tests/package/embed" -B "$tmp/build" -DTIRENV_SOURCE_DIR="$src" >"$tmp/log" 2>&1 &&
    grep -q "embed: tirenv::tirenv offered" "$tmp/log"; then
    echo "ok 1 - add_subdirectory(tirenv) configures without cmocka: no tests, no CLI, no -Werror"
else
    echo "not ok 1 - add_subdirectory(tirenv) configures without cmocka"
    sed 's/^/#   /' "$tmp/log"
    exit 1
fi

#!/bin/sh
# What a user does with tirenv, checked from outside the source tree: install it into a
# temporary prefix, move the installed tree elsewhere, build the programs of tests/package/consumer/
# against it with pkg-config and a Makefile (shared and fully static) and with CMake's
# find_package (tirenv::tirenv and tirenv::tirenv_static), and check that their curve equals
# the installed 'tirenv envelope' bit for bit; then run the installed CLI with no
# TIRENV_DATA from a directory unrelated to the clone.
#   sh tests/package/install.sh CMAKE BUILD_DIR SOURCE_DIR VERSION
# SPDX-License-Identifier: Apache-2.0
set -u
cmake=$1 build=$2 src=$3 version=$4
major=${version%%.*}

tmp=$(mktemp -d "${TMPDIR:-/tmp}/tirenv-install.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
trap 'exit 2' INT TERM
unset TIRENV_DATA PKG_CONFIG_PATH CMAKE_PREFIX_PATH LD_LIBRARY_PATH

# shellcheck source=tests/lib/tap.sh
. "$(dirname "$0")/../lib/tap.sh"
# run CMD...: stdout to $out, stderr to $err, exit status in $rc.
out=$tmp/out err=$tmp/err
run() {
    "$@" >"$out" 2>"$err"
    rc=$?
}

# 1. Install, and what lands where.
"$cmake" --install "$build" --prefix "$tmp/first" >"$tmp/install.log" 2>&1
check "cmake --install exits 0" test $? -eq 0
P=$tmp/first
for f in bin/tirenv lib/libtirenv.so.$version lib/libtirenv.a include/tirenv/tirenv.h \
         include/tirenv/version.h include/tirenv/model.h lib/pkgconfig/tirenv.pc \
         lib/cmake/tirenv/tirenvConfig.cmake lib/cmake/tirenv/tirenvConfigVersion.cmake \
         share/man/man1/tirenv.1 share/man/man1/tirenv-envelope.1 \
         share/tirenv/tires/default.tir share/tirenv/vehicles/tractor.veh \
         share/tirenv/dataset/cases.csv share/doc/tirenv/README.md \
         share/tirenv/fmu/tirenv_effective_road.fmu; do
    check "installs $f" test -f "$P/$f"
done
# Every relative link of the installed README (docs/, python/README.md, fmu/README.md) names
# an installed file; the #anchor is not checked.
doc=$P/share/doc/tirenv
links=$(grep -o '](\([^)]*\))' "$doc/README.md" | sed 's/^](//; s/)$//; s/#.*//' |
        grep -v -e '^[a-z][a-z]*:' -e '^$' | sort -u)
check "the installed README has relative links to follow" test -n "$links"
for l in $links; do
    check "the installed README's link $l resolves" test -e "$doc/$l"
done
check "libtirenv.so.$major links to the versioned library" \
    test "$(readlink "$P/lib/libtirenv.so.$major")" = "libtirenv.so.$version"
check "installs no build-tree data link" test ! -e "$P/bin/tirenv-data"
check "version.h says $version" grep -q "define TIRENV_VERSION \"$version\"" \
    "$P/include/tirenv/version.h"

# 2. The shared library: its soname, and only the public API exported.
readelf -d "$P/lib/libtirenv.so.$version" >"$tmp/dynamic"
check "readelf -d: soname libtirenv.so.$major" grep -q "(SONAME).*\[libtirenv.so.$major\]" \
    "$tmp/dynamic"
nm -D --defined-only "$P/lib/libtirenv.so.$version" | awk '{ print $NF }' >"$tmp/symbols"
check "nm -D: exports tirenv_ symbols" grep -q '^tirenv_model_eval$' "$tmp/symbols"
check "nm -D: no symbol with __ (no tirenv_x__y internal)" sh -c "! grep -q __ '$tmp/symbols'"
check "nm -D: nothing but tirenv_ symbols" sh -c "! grep -v '^tirenv_' '$tmp/symbols'"

# 3. No path of the source or build tree in what was installed (Release builds have no
# debug information to carry one).
for f in bin/tirenv lib/libtirenv.so.$version; do
    check "$f holds no path of the source tree" sh -c "! strings '$P/$f' | grep -qF '$src'"
    check "$f holds no path of the build tree" sh -c "! strings '$P/$f' | grep -qF '$build'"
done

# 4. Moved: the installed tree is copied elsewhere and the first copy removed.
Q=$tmp/moved/opt/tirenv
mkdir -p "$tmp/moved/opt" && cp -a "$P" "$Q" && rm -rf "$P"
check "the installed tree moves" test -x "$Q/bin/tirenv"
work=$tmp/elsewhere
mkdir -p "$work"
cd "$work" || exit 1

run "$Q/bin/tirenv" flat
check "moved, no TIRENV_DATA: tirenv flat exits 0" test "$rc" -eq 0
check "tirenv flat reads the moved tree's default tire" \
    grep -qF "tire $Q/share/tirenv/tires/default.tir," "$err" "$out"
run "$Q/bin/tirenv" envelope --model springs --cleat 0.30,0.10 --contact-length 0.33 -o cli.csv
check "moved, no TIRENV_DATA: tirenv envelope exits 0" test "$rc" -eq 0
check "tirenv envelope writes 1701 positions" test "$(wc -l <cli.csv)" -eq 1702
mkdir -p "$work/bin" && ln -s "$Q/bin/tirenv" "$work/bin/tirenv"
run "$work/bin/tirenv" flat
check "run through a symbolic link elsewhere, it still finds the moved tree's data" \
    sh -c "test $rc -eq 0 && grep -qF 'tire $Q/share/tirenv/tires/default.tir,' '$out'"
run env TIRENV_DATA="$work/none" "$Q/bin/tirenv" flat
check "TIRENV_DATA overrides the installed data: exit 2 naming it" \
    sh -c "test $rc -eq 2 && grep -qF '$work/none/tires/default.tir' '$err'"
check "man finds the installed pages" \
    sh -c "MANPATH='$Q/share/man' man -w tirenv-envelope | grep -qF '$Q/share/man/man1/tirenv-envelope.1'"

# 5. A consumer with a plain Makefile and pkg-config, shared then fully static.
export PKG_CONFIG_PATH=$Q/lib/pkgconfig
check "pkg-config --modversion tirenv is $version" test "$(pkg-config --modversion tirenv)" = "$version"
incdir=$(pkg-config --cflags-only-I tirenv | tr ' ' '\n' | sed -n 's/^-I//p' | head -n 1)
check "pkg-config --cflags: the moved tree's include/ (relocatable .pc)" \
    test "$(cd "$incdir" 2>/dev/null && pwd -P)" = "$(cd "$Q/include" && pwd -P)"
check "pkg-config --libs: -ltirenv, and no GSL" \
    sh -c "pkg-config --libs tirenv | grep -q -- '-ltirenv' && ! pkg-config --libs --static tirenv | grep -q -- '-lgsl'"
check "pkg-config --libs --static adds jansson and libm" \
    sh -c "pkg-config --libs --static tirenv | grep -q -- '-ljansson' && pkg-config --libs --static tirenv | grep -q -- '-lm'"
mkdir -p "$work/make" "$work/make-static"
cp "$src/tests/package/consumer/envelope.c" "$src/tests/package/consumer/Makefile" "$work/make/"
cp "$src/tests/package/consumer/envelope.c" "$src/tests/package/consumer/Makefile" "$work/make-static/"
make -s -C "$work/make" >"$tmp/make.log" 2>&1
check "the pkg-config consumer builds" test $? -eq 0 || cat "$tmp/make.log"
LD_LIBRARY_PATH=$Q/lib "$work/make/envelope" "$Q/share/tirenv/tires/default.tir" >make.csv
check "the pkg-config consumer runs" test $? -eq 0
check "it loads the moved libtirenv.so.$major" \
    sh -c "LD_LIBRARY_PATH='$Q/lib' ldd '$work/make/envelope' | grep -qF '$Q/lib/libtirenv.so.$major'"
check "its curve equals tirenv envelope's bit for bit" cmp -s make.csv cli.csv
make -s -C "$work/make-static" LDFLAGS=-static PCFLAGS=--static >"$tmp/make-static.log" 2>&1
check "the pkg-config consumer links fully static (pkg-config --static)" test $? -eq 0 ||
    cat "$tmp/make-static.log"
check "the static consumer needs no shared library" \
    sh -c "! readelf -d '$work/make-static/envelope' 2>/dev/null | grep -q NEEDED"
"$work/make-static/envelope" "$Q/share/tirenv/tires/default.tir" >static.csv
check "the static consumer's curve equals tirenv envelope's" cmp -s static.csv cli.csv

# The README's program, whole, taken from the README and built with the README's cc line; and
# tests/package/consumer/envelope.c is that program (after its two comment lines), so neither drifts.
mkdir -p "$work/readme"
awk '/^```c$/ { on = 1; next } on && /^```$/ { exit } on' "$src/README.md" \
    >"$work/readme/envelope.c"
check "the README holds a C program with main()" grep -q '^int main(' "$work/readme/envelope.c"
check "tests/package/consumer/envelope.c is the README's program" \
    sh -c "tail -n +3 '$src/tests/package/consumer/envelope.c' | cmp -s - '$work/readme/envelope.c'"
(cd "$work/readme" &&
    cc -o envelope envelope.c $(pkg-config --cflags --libs tirenv)) >"$tmp/readme.log" 2>&1
check "the README's program builds with the README's cc line" test $? -eq 0 ||
    cat "$tmp/readme.log"
LD_LIBRARY_PATH=$Q/lib "$work/readme/envelope" "$Q/share/tirenv/tires/default.tir" >readme.csv
check "the README's program: its curve equals tirenv envelope's bit for bit" \
    cmp -s readme.csv cli.csv
LD_LIBRARY_PATH=$Q/lib "$work/readme/envelope" "$work/missing.tir" >/dev/null 2>"$tmp/readme.err"
rc=$?
check "the README's program: a missing tire file exits 1 naming it" \
    sh -c "test $rc -eq 1 && grep -qF '$work/missing.tir' '$tmp/readme.err'"

# 6. A consumer with CMake: find_package(tirenv) and tirenv::tirenv / tirenv::tirenv_static.
mkdir -p "$work/cm"
cp "$src/tests/package/consumer/envelope.c" "$src/tests/package/consumer/CMakeLists.txt" "$work/cm/"
"$cmake" -S "$work/cm" -B "$work/cm/build" -DCMAKE_PREFIX_PATH="$Q" \
    -DCMAKE_BUILD_TYPE=Release >"$tmp/cmake.log" 2>&1 &&
    "$cmake" --build "$work/cm/build" >>"$tmp/cmake.log" 2>&1
check "the find_package(tirenv) consumer configures and builds" test $? -eq 0 ||
    cat "$tmp/cmake.log"
"$work/cm/build/envelope" "$Q/share/tirenv/tires/default.tir" >cmake.csv
check "tirenv::tirenv: its curve equals tirenv envelope's" cmp -s cmake.csv cli.csv
check "tirenv::tirenv is libtirenv.so.$major, found through its RUNPATH" \
    sh -c "ldd '$work/cm/build/envelope' | grep -qF '$Q/lib/libtirenv.so.$major'"
"$work/cm/build/envelope-static" "$Q/share/tirenv/tires/default.tir" >cmake-static.csv
check "tirenv::tirenv_static: its curve equals tirenv envelope's" cmp -s cmake-static.csv cli.csv
check "tirenv::tirenv_static links no libtirenv.so" \
    sh -c "! readelf -d '$work/cm/build/envelope-static' | grep -q 'libtirenv'"

# 7. DESTDIR stages an install under another root, as packagers do.
DESTDIR=$tmp/stage "$cmake" --install "$build" --prefix /usr/local >/dev/null 2>&1
check "DESTDIR=STAGE cmake --install --prefix /usr/local installs under STAGE/usr/local" \
    test -x "$tmp/stage/usr/local/bin/tirenv"

tap_done

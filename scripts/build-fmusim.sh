#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# Builds fmusim, the Modelica Association's FMU simulator, for the interop test fmu_fmusim
# (fmu/tests/fmusim.sh), offline, from a checkout of github.com/modelica/Reference-FMUs and
# Debian's libraries (libxml2-dev, zlib1g-dev, libminizip-dev, libsundials-dev; `scripts/deps.sh --interop`
# installs them). Its last C version is that repository's fmusim/ before commit 7b3fc08 (which
# moved it to github.com/modelica/fmusim, rewritten in Rust); its own build fetches and builds
# zlib, libxml2 and SUNDIALS 7, so this script compiles it directly, on a copy, with two
# changes:
#  - -DSUN_COMM_NULL=NULL: Debian's SUNDIALS 6 takes a plain pointer where 7 takes a
#    communicator (SUNContext_Create);
#  - FMISaveFMUStateToFile passes the state itself, not its address, to fmi2FreeFMUstate
#    (FMI 2.0: fmi2FMUstate*), which frees a wrong pointer in any FMU (the Reference FMUs'
#    own fmi2FreeFMUstate frees *FMUstate too): the address is passed.
#
#   sh scripts/build-fmusim.sh REFERENCE_FMUS_DIR OUT_DIR      (about 15 s; OUT_DIR/fmusim)
#   cmake -S . -B build "-DTIRENV_FMUSIM=$PWD/OUT_DIR/fmusim" && ctest --test-dir build -L interop
#
# REFERENCE_FMUS_DIR is a work tree at commit c8d4e6d90fa14be49d7622badf30e38eebea5e0a (the
# parent of 7b3fc08), or a git repository, from which that commit is taken.
set -eu
src=${1:?usage: build-fmusim.sh REFERENCE_FMUS_DIR OUT_DIR}
out=${2:?usage: build-fmusim.sh REFERENCE_FMUS_DIR OUT_DIR}
commit=c8d4e6d90fa14be49d7622badf30e38eebea5e0a
mkdir -p "$out"
out=$(cd "$out" && pwd)
work=$(mktemp -d "${TMPDIR:-/tmp}/tirenv-fmusim.XXXXXX")
trap 'rm -rf "$work"' EXIT
if [ -f "$src/fmusim/fmusim.c" ]; then
    cp -R "$src/fmusim" "$src/include" "$src/src" "$work/"
elif git -C "$src" cat-file -e "$commit^{commit}" 2>/dev/null; then
    git -C "$src" archive "$commit" fmusim include src | tar -x -C "$work"
else
    echo "build-fmusim: $src has neither fmusim/fmusim.c nor commit $commit" >&2
    exit 1
fi
cd "$work/fmusim"
grep -q 'FMI2FreeFMUstate(S, FMUState)' FMIUtil.c || {
    echo "build-fmusim: FMIUtil.c is not the version this script knows (commit $commit)" >&2
    exit 1
}
sed 's/FMI2FreeFMUstate(S, FMUState)/FMI2FreeFMUstate(S, \&FMUState)/' FMIUtil.c >FMIUtil.fixed.c
mv FMIUtil.fixed.c FMIUtil.c
# shellcheck disable=SC2046 # the source list is words
cc -O2 -w -std=gnu11 '-DFMUSIM_VERSION="c8d4e6d-tirenv"' -DSUN_COMM_NULL=NULL \
    -I. -I../include -I/usr/include/libxml2 -I/usr/include/minizip \
    ../src/FMI.c ../src/FMI1.c ../src/FMI2.c ../src/FMI3.c \
    ../src/structured_variable_name.yy.c ../src/structured_variable_name.tab.c \
    $(ls ./*.c) \
    -lxml2 -lminizip -lz -lsundials_cvode -lsundials_nvecserial -ldl -lm -o "$out/fmusim"
echo "build-fmusim: $out/fmusim"

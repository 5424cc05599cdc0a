#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# Installs the Debian packages tirenv needs to build, test and draw its plots. Idempotent:
# does nothing when they are present. As root it runs apt-get; otherwise it prints the line.
set -eu
# groff-base and man-db: the tests format and look up the generated man pages. clang and its
# runtime libraries (libFuzzer, sanitizers: only recommended by clang's packages, so named
# here) build the fuzz harnesses of tests/fuzz.
need="cmake make gcc pkg-config libcminpack-dev libcmocka-dev libjansson-dev gnuplot-nox groff-base man-db"
need="$need clang libclang-rt-14-dev"
# valgrind: the memcheck test (tests/model/memcheck.sh) finds reads of memory never written,
# which the sanitizers do not.
need="$need valgrind"
# locales: its locale sources and character maps, from which tests/io/test_c_numeric.c makes a
# locale whose decimal point is ',' (tirenv's files keep '.' whatever the host's locale).
need="$need locales"
# The Python module (python/) and its tests; the FMU's packaging and checks (fmu/).
need="$need python3 python3-dev python3-cffi python3-numpy python3-pytest python3-setuptools"
need="$need python3-wheel python3-venv python3-pip unzip libxml2-utils"
# The FMU's interop test: fmusim (tests/third_party/fmusim) reads FMUs with minizip and
# validates their descriptions with libxml2.
need="$need libxml2-dev zlib1g-dev libminizip-dev"
[ "${1:-}" = "--bench" ] && need="$need libfann-dev"
# --oldcpu: qemu's user-mode emulator, for make test-oldcpu (an x86-64 without AVX and FMA).
[ "${1:-}" = "--oldcpu" ] && need="$need qemu-user"
# --slurm: Slurm and munge, for tests/sweep/slurm.sh (scripts/slurm/ on a private single-node
# cluster). Optional: without them that test reports itself skipped, so a user who cannot
# install them is told how and goes on.
optional=0
if [ "${1:-}" = "--slurm" ]; then
    need="slurm-wlm munge"
    optional=1
fi

# One dpkg-query for all of them (make test runs this script twice; a query per package took
# seconds on a loaded machine): a line "NAME STATUS" per known package, none for an unknown one.
# shellcheck disable=SC2086 # $need is a list of names
installed=$(dpkg-query -W -f='${Package} ${Status}\n' $need 2>/dev/null || true)
missing=""
for pkg in $need; do
    if ! printf '%s\n' "$installed" | grep -q -x "$pkg [a-z]* ok installed"; then
        missing="$missing $pkg"
    fi
done
[ -z "$missing" ] && exit 0

if [ "$(id -u)" -eq 0 ]; then
    echo "deps: installing$missing" >&2
    export DEBIAN_FRONTEND=noninteractive
    if [ "$optional" -eq 1 ]; then
        if ! { apt-get update -qq && apt-get install -y -qq --no-install-recommends $missing \
                   >/dev/null; }; then
            echo "deps: could not install$missing (optional: the Slurm test is skipped)" >&2
        fi
        exit 0
    fi
    apt-get update -qq
    apt-get install -y -qq --no-install-recommends $missing >/dev/null
else
    echo "deps: missing packages; run:" >&2
    echo "  sudo apt-get update && sudo apt-get install -y$missing" >&2
    if [ "$optional" -eq 1 ]; then
        echo "deps: (optional: without them the Slurm test is skipped)" >&2
        exit 0
    fi
    exit 1
fi

#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# make test-oldcpu: the CLI BIN run on an emulated x86-64 without AVX, AVX2 and FMA
# (qemu-x86_64 -cpu Nehalem, user mode), where tirenv's generic paths and glibc's other libm
# paths run, against BIN on this machine: the envelopes of scripts/springs-bitcmp.sh byte for
# byte, then the 205/60R15 data set rebuilt (tests/dataset/dataset_regenerates.sh: the same
# bytes, or the same numbers where libm rounds differently; docs/models.md section 1.8).
# Usage, from the clone's root: scripts/oldcpu.sh BIN DIR (DIR: scratch files).
set -eu
[ $# -eq 2 ] || { echo "usage: scripts/oldcpu.sh BIN DIR" >&2; exit 2; }
bin=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
dir=$2
cpu=Nehalem
mkdir -p "$dir"
wrap=$dir/tirenv-$cpu
printf '#!/bin/sh\nexec qemu-x86_64 -cpu %s "%s" "$@"\n' "$cpu" "$bin" >"$wrap"
chmod +x "$wrap"
grep -q avx2 /proc/cpuinfo 2>/dev/null ||
    echo "oldcpu: this machine has no AVX2 itself: both runs take the generic paths" >&2
"$wrap" --version >/dev/null
sh scripts/springs-bitcmp.sh "$bin" "$wrap" "$dir/bitcmp"
sh tests/dataset/dataset_regenerates.sh "$wrap" data/dataset-205-60R15 205-60R15

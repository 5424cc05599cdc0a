#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# Runs fmu/examples/chrono_terrain.c, the worked example of fmu/README.md ("Chrono's way in"):
# the effective road of tests/data/placed_bump.crg at v = 0.9 m written by tirenv envelope,
# then queried in world x/y through the FMU and through the file read by OpenCRG.
#   sh fmu/tests/chrono_example.sh TIRENV CHRONO_TERRAIN FMU_TREE ROAD.crg
set -u
cli=$1 example=$2 tree=$3 road=$4
tmp=$(mktemp -d "${TMPDIR:-/tmp}/tirenv-chrono.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
"$cli" envelope --model springs --profile "$road" --track 0.9 --load 4000 --x-from 47 \
    --x-to 53.5 --dx 0.005 -o "$tmp/eff.crg" 2>"$tmp/err" || { cat "$tmp/err"; exit 1; }
"$example" "$tree" "$road" "$tmp/eff.crg" 0.9 4000 47 53.5 0.005

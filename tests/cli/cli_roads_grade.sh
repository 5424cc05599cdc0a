#!/bin/sh
# Roads with elevation and grade from other tools (ASAM's sloped hand-made roads, Horstwalde,
# Simscape's RDF plateau, the measured-like road 2 m up): whole and streamed, the same bytes as
# the track converted to CSV (the hub's clearance is checked per evaluation within the tire's
# reach, docs/models.md section 2.5). The springs model runs Horstwalde up to its 0.73 m drop,
# where its hub would pass under the edge (refused there: tests/profile/test_grade.c).
# Usage: tests/cli/cli_roads_grade.sh BIN TESTDATA_DIR, with TIRENV_SAMPLES as for cli_roads.sh.
# SPDX-License-Identifier: Apache-2.0
# shellcheck disable=SC2016,SC2034,SC2086
. "$(dirname "$0")/../lib/clilib.sh"
. "$(dirname "$0")/../lib/roads_lib.sh"

make_measured 2 measured.crg
graded() { compare_csv "$@"; }
for f in handmade_sloped handmade_sloped_opts handmade_curved_banked_sloped handmade_vtest; do
    graded $f springs "$crg/$f.crg" "--track -0.25" "--dx 0.005"
done
graded horstwalde springs "$crg/Horstwalde.crg" "--track 0.9" "--x-to 149 --dx 0.005"
graded horstwalde-cam cam "$crg/Horstwalde.crg" "--track 0.9" "--dx 0.005"
graded plateau springs "$rdf/plateau.rdf" "" "--x-from 95 --x-to 130 --dx 0.002"
graded plateau-left cam "$rdf/plateau.rdf" "--side left" "--x-from 95 --x-to 130"
graded measured springs measured.crg "--track 0.9" "--dx 0.002"
graded measured-cam cam measured.crg "--track 0.9" "--dx 0.002"
graded measured-nn-free point measured.crg "--track -1.3" "--dx 0.002"
# h relative to the road's local level: the level read from the file (whole, or streamed at
# --track) is the same as from its track converted to CSV.
graded measured-ground cam measured.crg "--track 0.9" "--dx 0.002 --relative-to ground"
graded measured-ground-springs springs measured.crg "--track 0.9" "--dx 0.004 --relative-to ground"

clilib_done

#!/bin/sh
# Roads with elevation and grade from other tools (ASAM's sloped hand-made roads, Horstwalde,
# Simscape's RDF plateau, the measured-like road 2 m up): whole and streamed, the same bytes as
# the track converted to CSV. That needs the clearance check made per evaluation within the
# tire's reach, which comes with --relative-to (docs/models.md section 2.5, pending); until the
# CLI has it, these roads are refused by the check over the whole profile, and this script
# checks that refusal instead: exit 2 naming the ground that reaches the centre, no file.
# Usage: tests/cli_roads_grade.sh BIN TESTDATA_DIR, with TIRENV_SAMPLES as for cli_roads.sh.
# SPDX-License-Identifier: GPL-3.0-or-later
# shellcheck disable=SC2016,SC2034,SC2086
. "$(dirname "$0")/clilib.sh"
. "$(dirname "$0")/roads_lib.sh"

make_measured 2 measured.crg
"$bin" envelope --help >help.txt 2>&1
if grep -q -- "--relative-to" help.txt; then
    graded() { compare_csv "$@"; }
else
    echo "# envelope has no --relative-to: checking that roads on grade are refused cleanly"
    graded() {
        run "$bin" envelope --model $2 --profile "$3" $4 $lc $5 -o "$1.out"
        check "$1: $2 over $(basename "$3") $4 refused (exit 2, the ground reaching the centre), no file" \
            '[ $rc -eq 2 ] && grep -q "reaches the tire centre" err && no_file "$1.out"'
    }
fi
for f in handmade_sloped handmade_sloped_opts handmade_curved_banked_sloped handmade_vtest; do
    graded $f springs "$crg/$f.crg" "--track -0.25" "--dx 0.005"
done
graded horstwalde springs "$crg/Horstwalde.crg" "--track 0.9" "--dx 0.005"
graded horstwalde-cam cam "$crg/Horstwalde.crg" "--track 0.9" "--dx 0.005"
graded plateau springs "$rdf/Plateau_Road.rdf" "" "--x-from 95 --x-to 130 --dx 0.002"
graded plateau-left cam "$rdf/Plateau_Road.rdf" "--side left" "--x-from 95 --x-to 130"
graded measured springs measured.crg "--track 0.9" "--dx 0.002"
graded measured-cam cam measured.crg "--track 0.9" "--dx 0.002"
graded measured-nn-free point measured.crg "--track -1.3" "--dx 0.002"

clilib_done

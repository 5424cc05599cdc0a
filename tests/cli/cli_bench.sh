#!/bin/sh
# tirenv bench --json: every figure of one run as one JSON object of name: number pairs, the
# figures the speed goals are stated in among them, all positive. That the tables stay the
# default is checked by cli.sh, on its run of bench --quick, in both builds. --quick keeps it
# to seconds (one run each, a 100 m road); the numbers are not checked against targets here
# (timings are no test), only that each was measured.
# Usage: tests/cli/cli_bench.sh BIN TESTDATA_DIR. SPDX-License-Identifier: Apache-2.0
# shellcheck disable=SC2016,SC2034,SC2086
. "$(dirname "$0")/../lib/clilib.sh"

run "$bin" bench --quick --json
check "bench --quick --json: exit 0, nothing on stderr" '[ "$rc" -eq 0 ] && [ ! -s err ]'
check "stdout is one JSON object with the named figures, each a positive number" \
    'python3 -c "
import json, math, sys
d = json.load(open(\"out\"))
assert isinstance(d, dict)
need = [\"rigid_cleat_pos_per_s\", \"springs_cleat_pos_per_s\", \"springs_road_pos_per_s\",
        \"ring_cleat_pos_per_s\", \"cam_road_pos_per_s\", \"nn_batch_per_s\",
        \"springs_evals_per_pos\", \"springs_over_rigid_cleat\", \"springs_over_rigid_road\",
        \"ring_over_rigid_cleat\", \"springs_road_evals_per_pos\", \"import_ms\",
        \"springs_over_rigid_cleat_best\", \"ring_over_rigid_cleat_best\", \"cleat_rounds\",
        \"ride_springs_x_real\", \"springs_road_10mm_pos_per_s\",
        \"springs_road_1mm_pos_per_s\", \"springs_fine_over_coarse_road\",
        \"springs_fine_over_coarse_road_best\", \"springs_fine_over_coarse_road_rounds\",
        \"envelope_jobs2_over_jobs1\", \"envelope_jobs_identical\", \"envelope_whole_peak_mb\",
        \"envelope_whole_s\", \"envelope_whole_positions\", \"envelope_stream_rdf_peak_mb\",
        \"envelope_stream_rdf_s\", \"envelope_stream_rdf_jobs2_peak_mb\",
        \"envelope_stream_rdf_jobs2_s\", \"envelope_stream_jobs2_over_jobs1\",
        \"envelope_stream_identical\"]
for k in need:
    v = d[k]
    assert isinstance(v, (int, float)) and not isinstance(v, bool), k
    assert math.isfinite(v) and v > 0, (k, v)
for k, v in d.items():
    assert isinstance(v, (int, float)) and math.isfinite(v), k
# Ratios as stated: springs time / rigid time from the same run, best over best; the targets
# figures are the medians of 2 * 1 + 1 interleaved rounds, each round with a ratio of its own.
r = d[\"rigid_cleat_pos_per_s\"] / d[\"springs_cleat_pos_per_s\"]
assert abs(d[\"springs_over_rigid_cleat_best\"] - r) <= 1e-9 * r
r = d[\"rigid_cleat_pos_per_s\"] / d[\"ring_cleat_pos_per_s\"]
assert abs(d[\"ring_over_rigid_cleat_best\"] - r) <= 1e-9 * r
assert d[\"cleat_rounds\"] == 3
# Below 1 since the approach to the cleat, level under the tire, needs no evaluation (models.md
# section 11.4); an evaluation at every position that touches keeps it above 1/2.
assert d[\"springs_evals_per_pos\"] > 0.5 and d[\"quick\"] == 1
f = d[\"springs_road_10mm_pos_per_s\"] / d[\"springs_road_1mm_pos_per_s\"]
assert abs(d[\"springs_fine_over_coarse_road_best\"] - f) <= 1e-9 * f
# --quick is one repeat: the fine and coarse sweeps interleaved over 2 * 1 + 1 rounds (the
# figure their median ratio, _best the ratio of the best sweeps).
assert d[\"springs_fine_over_coarse_road_rounds\"] == 3
# The 100 m road of --quick at 10 mm is 10,001 positions: a chunk of 8192 and one of 1809, so two
# threads take at least 8192 / 10001 of the time of one.
assert abs(d[\"envelope_jobs2_floor\"] - 8192 / 10001) <= 1e-12
# The jobs ratio is the median of 2 * 1 + 1 interleaved rounds, _best the ratio of the best sweeps.
assert d[\"envelope_jobs_rounds\"] == 3
j = d[\"envelope_jobs2_s\"] / d[\"envelope_jobs1_s\"]
assert abs(d[\"envelope_jobs2_over_jobs1_best\"] - j) <= 1e-9 * j
# The memory of whole mode, a child process over a 100 m road at 1 mm with --quick (10 km
# without): the default sweep, which reaches beyond the ends of the road, and more than the
# 3.5 MB a run over a generated cleat takes (the 100,001 vertices alone are 1.6 MB).
assert d[\"envelope_whole_road_m\"] == 100 and d[\"envelope_whole_positions\"] > 100001
assert d[\"envelope_whole_peak_mb\"] > 3.5
# --stream over the same road as an RDF file holds a window of its rows, not the road: less
# than whole mode, which holds it (some 4 MB against 12 over 100 m; both from a fresh bench
# --memory, whose resident set at the fork, which the kernel counts in the peak of a child,
# is some 4 MB, where the bench after its timings is at 13).
assert d[\"envelope_stream_rdf_peak_mb\"] < d[\"envelope_whole_peak_mb\"]
# --stream --jobs 2 holds two rounds of 8 chunks, each 8192 points of 64 bytes and the rows
# within reach of them, whatever the length of the road: some 20 MB (docs/models.md 2.4).
assert d[\"envelope_stream_rdf_jobs2_peak_mb\"] < 64
"'

# A method without an equilibrium on flat ground (MAX_ITERATIONS 2: every deformable model's)
# is said and its runs end: without --quick the runs go on until 0.2 s of sweeps, which such a
# method never spends (its setups once ran 100,000 times: over a minute for the ring alone).
# The bench then stops at its next part (the rig import sets the springs model: exit 3).
run timeout 60 "$bin" bench --repeat 1 --set MAX_ITERATIONS=2
check "bench without an equilibrium on flat ground: the table says so, exit 3 at once" \
    '[ "$rc" -eq 3 ] && grep -q "^ring newton failed everywhere, on flat ground: " out &&
     grep -q "^springs brent failed everywhere, on flat ground: " out'

run "$bin" bench --json --frobnicate
check "an unknown option: exit 1" '[ "$rc" -eq 1 ]'

clilib_done

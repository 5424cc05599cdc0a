#!/bin/sh
# Ground narrower than the springs model's ray spacing (docs/models.md section 4): a needle
# must not slip between the rays unseen. With CONTACT = 'rays' (the paper's contact) the
# springs model refuses it, naming the position, the feature's width and the spacing, and
# writes nothing; with the default continuous contact the tread carries it; features the
# rays resolve, and every model that follows the ground exactly, are unaffected.
# Usage: tests/cli/cli_needle.sh BIN TESTDATA_DIR. SPDX-License-Identifier: Apache-2.0
# shellcheck disable=SC2016,SC2034,SC2086
. "$(dirname "$0")/../lib/clilib.sh"

needle='--cleat 1e-9,0.1 --load 13000 --set ENVELOPING_SPRINGS.CONTACT=rays'

run "$bin" envelope --model springs $needle -o n.csv
check "a 1e-9 m x 0.1 m needle: springs refuses it, exit 2" '[ "$rc" -eq 2 ]'
check "the message says it slips between the rays: position, width, spacing" \
    'grep -q "at x = .* m a feature of the ground 1e-09 m wide" err &&
     grep -q "between two rays .* m apart that do not see it" err &&
     grep -q "cannot resolve it" err'
check "nothing is written" 'no_file n.csv'

run "$bin" envelope --model springs $needle --x-from -0.02 --x-to 0.02 --dx 0.001 -o n0.csv
check "right over the needle too (h = 0 there before)" \
    '[ "$rc" -eq 2 ] && grep -q "1e-09 m wide" err && no_file n0.csv'

run "$bin" envelope --model springs --cleat 0.004,0.1 --load 13000 --set ENVELOPING_SPRINGS.CONTACT=rays -o p.csv
check "a 4 mm plate, narrower than the 5.9 mm spacing: refused" \
    '[ "$rc" -eq 2 ] && grep -q "0.004 m wide" err && no_file p.csv'

run "$bin" envelope --model springs --cleat 0.004,0.1 --load 13000 --set ELEMENT_ANGLE=0.0025 \
    --set ENVELOPING_SPRINGS.CONTACT=rays -o p2.csv
check "the same plate with 0.0025 rad elements (1.7 mm apart): resolved" \
    '[ "$rc" -eq 0 ] && [ "$(rows p2.csv)" -gt 100 ]'

for obstacle in "--cleat 0.01,0.1" "--cleat 0.30,0.10" "--triangle 0.05,0.1" \
                "--cylinder 0.005" "--sine 0.002,0.004,40"; do
    run "$bin" envelope --model springs $obstacle --load 13000 -o w.csv
    check "springs over $obstacle (resolved, or within a spacing): a curve" \
        '[ "$rc" -eq 0 ] && [ "$(rows w.csv)" -gt 100 ]'
done

run "$bin" envelope --model springs --cleat 1e-9,0.1 --load 13000 -o c.csv
check "the continuous tread carries the needle: a curve, its peak within 0.1 m" \
    '[ "$rc" -eq 0 ] && [ "$(rows c.csv)" -gt 100 ] && awk -v p="$(peak_h c.csv)" "BEGIN { exit !(p > 0.05 && p <= 0.1) }"'
run "$bin" envelope --model springs --cleat 0.004,0.1 --load 13000 -o c2.csv
check "and the 4 mm plate" '[ "$rc" -eq 0 ] && [ "$(rows c2.csv)" -gt 100 ]'

run "$bin" envelope --model rigid $needle -o r.csv
check "the rigid disc follows the needle exactly: peak h 0.1 m" \
    '[ "$rc" -eq 0 ] && near "$(peak_h r.csv)" 0.1 1e-9'

clilib_done

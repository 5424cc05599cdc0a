#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# tirenv envelope --plot FILE.png: the curve written with -o FILE.csv drawn over the road under
# the centre (PNG, SVG, the gnuplot script and the road's data), and the combinations it
# refuses before any work, with nothing written.
# Usage: tests/cli/cli_envelope_plot.sh BIN TESTDATA_DIR. TAP lines, as tests/cli/cli.sh.
# shellcheck disable=SC2016,SC2034,SC2086
. "$(dirname "$0")/../lib/clilib.sh"

run "$bin" envelope --model springs --cleat 0.30,0.10 --contact-length 0.38 -o c.csv \
    --plot c.png
check "--plot over a cleat: exit 0, the PNG, SVG, script and road beside the curve" \
    '[ $rc -eq 0 ] && [ -s c.csv ] && [ -s c.png ] && [ -s c.svg ] && [ -s c.gp ] &&
     [ -s c-road.dat ] && [ -z "$(find . -name "*tmp.*")" ]'
check "the script reads the curve by its full path and the road beside it" \
    'grep -q "^curve = .$PWD/c.csv.$" c.gp && grep -q "^road = .c-road.dat.$" c.gp'
# The road's data: the cleat's four corners between the sweep's ends, its top 0.1 m.
check "the road drawn is the cleat under the sweep's range" \
    '[ "$(grep -v "^#" c-road.dat | tr "\n" " ")" = "-0.85,0 -0.15,0 -0.15,0.1 0.15,0.1 0.15,0 0.85,0 " ]'
# The script draws again by hand, from its directory, as its comment says.
rm -f c.png
(cd . && gnuplot c.gp >/dev/null 2>&1)
check "gnuplot c.gp redraws c.png" '[ -s c.png ]'

# A fine road longer than the drawn points: each bin's lowest and highest vertex kept, so
# that the drawn road spans the same heights.
"$bin" road --class D --length 30 --dx 0.001 --seed 2 -o road.csv 2>/dev/null
run "$bin" envelope --model cam --profile road.csv --contact-length 0.3 --x-from 1 --x-to 29 \
    --dx 0.01 -o r.csv --plot r
check "--plot over a 30 m road at 1 mm: at most 20,000 road points, its extremes kept" \
    '[ $rc -eq 0 ] && [ -s r.png ] && [ $(grep -vc "^#" r-road.dat) -le 20002 ] &&
     [ "$(awk -F, "NR > 1 && !/^#/ && \$1 >= 1 && \$1 <= 29 { if (!s || \$2 > hi) hi = \$2; if (!s || \$2 < lo) lo = \$2; s = 1 } END { print lo, hi }" road.csv)" = \
       "$(awk -F, "!/^#/ && \$1 > 1 && \$1 < 29 { if (!s || \$2 > hi) hi = \$2; if (!s || \$2 < lo) lo = \$2; s = 1 } END { print lo, hi }" r-road.dat)" ]'

# Refused before any work, nothing written.
run "$bin" envelope --model rigid --cleat 0.1,0.05 --load 1e4 --plot p.png
check "--plot without -o: exit 1, no file" '[ $rc -eq 1 ] && no_file p.png && grep -q -- "-o FILE.csv" err'
run "$bin" envelope --model rigid --cleat 0.1,0.05 --load 1e4 -o e.crg --plot p.png
check "--plot with -o FILE.crg: exit 1, no file" '[ $rc -eq 1 ] && no_file e.crg && no_file p.png'
run "$bin" envelope --model rigid --profile road.csv --stream --load 1e4 -o s.csv --plot p.png
check "--plot with --stream: exit 1, no file" '[ $rc -eq 1 ] && no_file s.csv && no_file p.png'
run "$bin" envelope --model rigid --cleat 0.1,0.05 --load 1e4 --relative-to ground -o g.csv \
    --plot p.png
check "--plot with --relative-to ground: exit 1, no file" '[ $rc -eq 1 ] && no_file g.csv'
run "$bin" envelope --model rigid --cleat 0.1,0.05 --load 1e4 -o d.csv --plot no/such/p.png
check "--plot into a directory that does not exist: exit 2 naming it, no curve either" \
    '[ $rc -eq 2 ] && no_file d.csv && grep -q "no/such" err'
echo old >kept.csv
echo file >afile
run "$bin" envelope --model rigid --cleat 0.1,0.05 --load 1e4 -o kept.csv --plot afile/p.png
check "--plot under a file, not a directory: exit 2 naming it, -o's file as it was" \
    '[ $rc -eq 2 ] && [ "$(cat kept.csv)" = old ] && grep -q "afile: --plot" err'

clilib_done

#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# The springs (or ring) model's smoothness over obstacles (docs/models.md section 4.8): the second
# difference of h on 1 mm sweeps of `tirenv envelope --model springs --load 13000`, positions
# within 3 mm of an obstacle vertex's x left out. Per obstacle: the largest |h(x-dx) - 2 h(x) +
# h(x+dx)|, how many positions exceed 0.2 mm, and where the largest sit (x, the number of
# elements the ground presses there, and whether that number changes at the neighbours: a
# contact starting or ending, a kink of the exact curve, not a ripple).
#
# usage: [MODEL=ring] scripts/springs_ripple.sh TIRENV [--set KEY=VALUE]...
#   e.g. scripts/springs_ripple.sh build/tirenv --set ELEMENT_ANGLE=0.0043633231299858239
# MODEL: the model swept (default springs; ring for docs/models.md section 5.3's figures).
set -eu
[ $# -ge 1 ] || { echo "usage: $0 TIRENV [--set KEY=VALUE]..." >&2; exit 1; }
tirenv=$1
shift
model=${MODEL:-springs}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$tirenv" road --class C --length 16 --dx 0.001 --seed 1 -o "$tmp/road.csv" 2>/dev/null

# name | obstacle options | the obstacle's vertices' x (m), comma separated
cases='cleat 0.30 x 0.08 m|--cleat 0.30,0.08|-0.15,0.15
cleat 0.10 x 0.10 m|--cleat 0.10,0.10|-0.05,0.05
cleat 0.05 x 0.025 m|--cleat 0.05,0.025|-0.025,0.025
step 0.1 m|--step 0,0.1|0
triangle 0.2 x 0.08 m|--triangle 0.2,0.08|-0.1,0,0.1
plate 0.004 x 0.1 m|--cleat 0.004,0.1|-0.002,0.002
ISO 8608 class C road at 1 mm, 16 m|--profile '"$tmp/road.csv"' --x-from 1 --x-to 15|'

echo "| obstacle | largest | > 0.2 mm | where (x m, pressed elements, state change) |"
echo "|---|---|---|---|"
echo "$cases" | while IFS='|' read -r name opts verts; do
    out="$tmp/h.csv"
    if ! eval "\"\$tirenv\" envelope --model \"\$model\" --load 13000 $opts \"\$@\" -o \"\$out\"" \
        2>"$tmp/err"; then
        echo "| $name | refused: $(tail -n 1 "$tmp/err") | | |"
        continue
    fi
    python3 - "$out" "$verts" "$name" <<'PY'
import csv, sys
path, verts, name = sys.argv[1], sys.argv[2], sys.argv[3]
vx = [float(v) for v in verts.split(',')] if verts else []
rows = list(csv.DictReader(open(path)))
x = [float(r['x_m']) for r in rows]
h = [float(r['h_m']) for r in rows]
c = [int(r['contacts']) for r in rows]
res = []
for k in range(1, len(x) - 1):
    if any(abs(x[k] - v) <= 0.003 + 1e-9 for v in vx):
        continue
    d2 = h[k - 1] - 2 * h[k] + h[k + 1]
    change = not (c[k - 1] == c[k] == c[k + 1])
    res.append((abs(d2), x[k], c[k], change))
res.sort(reverse=True)
n = sum(1 for r in res if r[0] > 2e-4)
where = '; '.join('%+.3f %d%s' % (r[1], r[2], ' yes' if r[3] else '')
                  for r in res[:4] if r[0] > 0.5e-4)
print('| %s | %.3f mm | %d of %d | %s |' % (name, res[0][0] * 1e3, n, len(res), where))
PY
done

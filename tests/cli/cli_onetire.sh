#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# One tire, every model, from the command line (docs/models.md section 14): tirenv identify and
# its in-place write; an MF-Tyre file without tirenv's sections (models derived and said, flat
# at its own loads, refusal naming the key); the network's own tire in envelope and the ride.
# Usage: tests/cli/cli_onetire.sh BIN TESTDATA_DIR.
# shellcheck disable=SC2016,SC2034,SC2086
. "$(dirname "$0")/../lib/clilib.sh"

repo=$(cd "$data/../.." && pwd)

# --- identify ------------------------------------------------------------------------------
cp "$repo/data/tires/default.tir" t.tir
run "$bin" identify --tire t.tir
check "identify: the default tire's values are those it writes (unchanged file)" \
    '[ $rc -eq 0 ] && grep -q "RADIAL_STIFFNESS *407000 " out && grep -q "Q_RA1 *0.461 " out &&
     cmp -s t.tir "$repo/data/tires/default.tir"'
run "$bin" identify --tire t.tir --set RADIAL_STIFFNESS=1e6 --write
check "identify --write: the file re-read has the identified values, comments and note kept" \
    '[ $rc -eq 0 ] && grep -q "^RADIAL_STIFFNESS *= 407000 *\$ c_r" t.tir &&
     [ $(grep -c "tirenv identify: begin" t.tir) -eq 1 ] &&
     [ $(grep -c "^\\$" t.tir) -eq $(grep -c "^\\$" "$repo/data/tires/default.tir") ]'
# A file of CRLF line ends keeps them (every line was written back with LF alone).
sed 's/$/\r/' "$repo/data/tires/default.tir" >crlf.tir
run "$bin" identify --tire crlf.tir --set RADIAL_STIFFNESS=1e6 --write
check "identify --write on a CRLF file: every line still ends in CRLF, else the LF file's bytes" \
    '[ $rc -eq 0 ] && [ "$(grep -c "$(printf "\r")\$" crlf.tir)" -eq "$(wc -l <crlf.tir)" ] &&
     tr -d "\r" <crlf.tir | cmp -s - t.tir'
# --set of a key --write does not write: the file would be another tire than its note says.
cp t.tir t0.tir
run "$bin" identify --tire t.tir --set FOUNDATION_STIFFNESS=2e5 --write
check "identify --write --set of a key not written: exit 1, named, the file unchanged" \
    '[ $rc -eq 1 ] && grep -q -- "--set FOUNDATION_STIFFNESS=2e5 with --write" err &&
     cmp -s t.tir t0.tir'
# --write-springs: the springs model's values alone (with its sidewall, docs/models.md 4.9),
# the cam's laws the file's (the 205/60R15, whose cam is TNO's): identified on its ring alone,
# whatever the start values (the values the file shipped with until its springs were
# identified on the ring and the cam together, docs/models.md 14.2); every other line and the
# note's place as shipped.
# strip FILE: the file without the springs keys identify writes and its note's lines.
strip() {
    sed -e '/^! tirenv identify: begin/,/^! tirenv identify: end/d' \
        -e '/^\(RADIAL_STIFFNESS\|INTERRADIAL_STIFFNESS\|SIDEWALL_STIFFNESS\|SIDEWALL_PRELOAD\) /d' "$1"
}
cp "$repo/data/tires/205-60R15-mfswift.tir" c.tir
run "$bin" identify --tire c.tir --set RADIAL_STIFFNESS=1e6 --set SIDEWALL_STIFFNESS=2e6 \
    --set SIDEWALL_PRELOAD=0 --write-springs
check "identify --write-springs: springs and sidewall written, the cam's laws kept, note rewritten" \
    '[ $rc -eq 0 ] && grep -q "^RADIAL_STIFFNESS *= 459000 " c.tir &&
     grep -q "^SIDEWALL_STIFFNESS *= 598000 " c.tir && grep -q "^SIDEWALL_PRELOAD *= 2530 " c.tir &&
     grep -q "^  SIDEWALL_STIFFNESS  *598000 N/m (was 2e+06)" out &&
     grep -q "^  the cam.s laws kept as read: VERTICAL_STIFFNESS 209652 N/m, .*Q_RA1 0.6715, " out &&
     ! grep -q "^  Q_RA1 " out &&
     grep -q "^Q_RA1 *= 0.6715 " c.tir && grep -q "^VERTICAL_STIFFNESS *= 209651.5 " c.tir &&
     grep -q "identify --write-springs" c.tir && [ "$(grep -c "^! tirenv identify: begin" c.tir)" = 1 ] &&
     strip c.tir >c.rest && strip "$repo/data/tires/205-60R15-mfswift.tir" >s.rest && cmp -s c.rest s.rest'
# --reference ring,cam: the springs model identified on the ring and the cam together (min-max,
# docs/models.md 14.1), at five loads (the shipped values are the 41 loads' of
# scripts/springs-softening-study.py); the cam, a reference, is the file's and not written
# even by --write; each model against each reference.
cp "$repo/data/tires/205-60R15-mfswift.tir" r.tir
run "$bin" identify --tire r.tir --reference ring,cam --loads 2000,3000,4000,5000,6000 --write
check "identify --reference ring,cam --write: the springs values written, the cam's kept, each pair tabled" \
    '[ $rc -eq 0 ] && grep -q "^RADIAL_STIFFNESS *= 445900 " r.tir &&
     grep -q "^INTERRADIAL_STIFFNESS *= 9847 " r.tir && grep -q "^SIDEWALL_STIFFNESS *= 595800 " r.tir &&
     grep -q "^SIDEWALL_PRELOAD *= 2662 " r.tir && grep -q "^  the cam.s laws kept as read: " out &&
     grep -q "^ *load_N *ring *cam *springs *ring *cam *springs\$" out &&
     [ "$(grep -c "^ *[2-6]000.0 " out)" = 5 ] &&
     grep -q "^springs against ring deflection 4.6 %, contact length 3.8 %;\$" out &&
     grep -q "^springs against cam deflection 4.7 %, contact length 4.7 %;\$" out &&
     grep -q "^cam against ring deflection 1.0 %, contact length 1.7 %\$" out &&
     grep -q "^! ring,cam --write. (docs/models.md section 14.1) on the ring.s and the cam.s flat ground" r.tir &&
     strip r.tir >r.rest && strip "$repo/data/tires/205-60R15-mfswift.tir" >s.rest && cmp -s r.rest s.rest'
cp "$repo/data/tires/205-60R15-mfswift.tir" r.tir
for ref in ring,springs ring,ring; do
    run "$bin" identify --tire r.tir --reference $ref --write
    check "identify --reference $ref: exit 1, quoted, the file unchanged" \
        '[ $rc -eq 1 ] && grep -q "got .$ref.\$" err && cmp -s r.tir "$repo/data/tires/205-60R15-mfswift.tir"'
done
run "$bin" identify --tire r.tir --reference ring,cam --set Q_RA1=0.7 --write
check "identify --reference ring,cam --write --set Q_RA1: exit 1 (the cam, a reference, is not written), unchanged" \
    '[ $rc -eq 1 ] && grep -q -- "--set Q_RA1=0.7 with --write" err &&
     cmp -s r.tir "$repo/data/tires/205-60R15-mfswift.tir"'
run "$bin" identify --tire r.tir --reference ring,cam --loads 2000,6000 --write
check "identify --reference ring,cam with two loads and a sidewall: exit 2, three needed, unchanged" \
    '[ $rc -eq 2 ] && grep -q "needs 3 to 64 loads, got 2" err &&
     cmp -s r.tir "$repo/data/tires/205-60R15-mfswift.tir"'
# ... on an MF-Tyre file whose ring is derived as it is read (with its springs model): refused,
# the file unchanged (written springs values would change the ring the next read derives).
cp "$data/samples/tir/mf_185_80R14.tir" m.tir
for w in --write --write-springs "--reference cam --write-springs" "--reference cam,ring --write"; do
    run "$bin" identify --tire m.tir $w
    check "identify $w on an MF-Tyre file without an [ENVELOPING_RING]: exit 1, said, unchanged" \
        '[ $rc -eq 1 ] && grep -q "its ring is derived from its MF-Tyre keys" err &&
         cmp -s m.tir "$data/samples/tir/mf_185_80R14.tir"'
done
run "$bin" identify --tire c.tir --write --write-springs
check "identify --write --write-springs: exit 1, one of them" '[ $rc -eq 1 ] && grep -q "one of them" err'
run "$bin" identify --loads 12000
check "identify --loads with one load: exit 1 saying two are needed" \
    '[ $rc -eq 1 ] && grep -q "at least two loads" err'
run "$bin" identify --loads 12000,15000,
check "identify --loads ending in a comma: exit 1 quoting it" \
    '[ $rc -eq 1 ] && grep -q "got .12000,15000,.\$" err'

# --- an MF-Tyre file without tirenv's sections ---------------------------------------------
mf=$data/samples/tir/mf_185_80R14.tir
run "$bin" flat --tire "$mf" --csv
check "flat on an MF-Tyre file: its own loads 0.5 to 1.5 FNOMIN (1900 to 5700 N), derived values said" \
    '[ $rc -eq 0 ] && [ $(rows out) -eq 5 ] && [ "$(sed -n 2p out | cut -d, -f1)" = 1900 ] &&
     [ "$(sed -n 6p out | cut -d, -f1)" = 5700 ] && grep -q "derived RADIAL_STIFFNESS" err'
run "$bin" flat --tire "$mf" --load 3800 --csv
# The file's law is VERTICAL_STIFFNESS alone: Q_FZ2 is identified on the derived ring with
# VERTICAL_STIFFNESS its tangent at FNOMIN (docs/models.md 14.2), so the deflection there is
# that law's, 27.35 mm as the note says (the secant 138.9 kN/m), not FNOMIN/VERTICAL_STIFFNESS
# = 21.71 mm; the springs model carries FNOMIN there (to the note's 4 digits).
check "its springs model: the deflection at FNOMIN the note says, the derived law's 27.35 mm" \
    '[ $rc -eq 0 ] && grep -q "derived on the ring Q_FZ2 = " err &&
     grep -q "(deflection 27.35 mm at FNOMIN 3800 N: secant stiffness 138.9 kN/m)" err &&
     near "$(sed -n 2p out | cut -d, -f3)" 0.02735 0.000005'
printf '[DIMENSION]\nUNLOADED_RADIUS = 0.376\n[VERTICAL]\nVERTICAL_STIFFNESS = 1.75e5\n' >nof.tir
run "$bin" flat --tire nof.tir --load 3000
check "a file without FNOMIN and no [ENVELOPING_SPRINGS]: exit 2 naming FNOMIN" \
    '[ $rc -eq 2 ] && grep -q "FNOMIN" err && grep -q "ENVELOPING_SPRINGS" err && [ ! -s out ]'
run "$bin" flat --tire nof.tir --load 3000 --model rigid
check "... the rigid disc needs neither: exit 0, the note says the springs model is not this tire's" \
    '[ $rc -eq 0 ] && grep -q "not this tire" err'

# --- the network's tire --------------------------------------------------------------------
run "$bin" train --data "$repo/data/dataset" --trainer lm --seed 3 -o nn.json
val_rms=$(awk '$1 == "validation" { print $3 }' out)
check "train records the contact law of the data's tire (the ring of source.txt)" \
    '[ $rc -eq 0 ] && [ -n "$val_rms" ] && grep -q "contact_law" nn.json &&
     grep -q "the ring model" nn.json'
# 17.1 kN, just above case R's 17044.68 N. The identified springs model touches about 0.28 m
# there too, so its springs are stiffened: without the recorded law (nn-v1.json below) the
# load would become that springs model's shorter patch, refused.
run "$bin" envelope --model nn --nn nn.json --cleat 0.10,0.10 --load 17100 \
    --set RADIAL_STIFFNESS=1.5e6 -o e.csv
check "envelope --model nn --load 17100: the ring's 0.28 m, whatever the tire file's springs" \
    '[ $rc -eq 0 ] && grep -q "contact length 0\.28[0-9]* m" err'
# The data set's ends are its cases' loads, knots of the law: case R's own load gives its 0.28 m,
# the trained range's very edge (its linear interpolation once gave 0.279999 m, refused); a
# load 0.01 N below it (the resolution cases.csv records loads to) is within the 1e-6 m the nn
# model takes as the edge: the same curve; 16 kN, below the cases, is refused.
run "$bin" envelope --model nn --nn nn.json --cleat 0.10,0.10 --load 17044.68 -o r.csv
check "envelope --model nn --load 17044.68 (case R's): accepted at exactly 0.28 m" \
    '[ $rc -eq 0 ] && grep -q "contact length 0\.28 m" err'
run "$bin" envelope --model nn --nn nn.json --cleat 0.10,0.10 --load 17044.67 -o r2.csv
check "... 0.01 N below it: accepted as the trained range's edge, the same curve (x to fx)" \
    '[ $rc -eq 0 ] && cut -d, -f1-5 r.csv >r.x && cut -d, -f1-5 r2.csv >r2.x && cmp -s r.x r2.x'
run "$bin" envelope --model nn --nn nn.json --cleat 0.10,0.10 --load 16000 -o b.csv
check "... 16 kN, below the data set's loads: refused, naming the contact length" \
    '[ $rc -ne 0 ] && grep -q "contact length" err && no_file b.csv'
# 18 kN: the springs model of the tire file, which stands in for the missing relation, touches
# 0.29 m there, inside the network's trained 0.28 to 0.43 m.
run "$bin" envelope --model nn --nn "$data/nn-v1.json" --cleat 0.10,0.10 --load 18000 -o o.csv
check "an older network file: read, with a warning naming training.data.contact_law" \
    '[ $rc -eq 0 ] && grep -q "warning: .*training.data.contact_law" err'
# tirenv_tir_need (docs/models.md 14.2): the network needs no springs model of the tire file
# (nof.tir above has none), its load's contact length is its own file's law; where an older
# file's springs stand-in, or a rigid disc's load at a --contact-length, would be another tire's,
# refused.
run "$bin" envelope --model nn --nn nn.json --tire nof.tir --cleat 0.10,0.10 --load 17100 -o n.csv
check "envelope --model nn, a tire file with no springs model: the network's own law, exit 0" \
    '[ $rc -eq 0 ] && grep -q "contact length 0\.28[0-9]* m" err'
run "$bin" envelope --model nn --nn "$data/nn-v1.json" --tire nof.tir --cleat 0.10,0.10 \
    --load 18000 -o n1.csv
check "... an older network file there: exit 2 naming training.data.contact_law and the tire" \
    '[ $rc -eq 2 ] && grep -q "nn-v1.json: training.data.contact_law: .* nof.tir has no springs" err &&
     no_file n1.csv'
run "$bin" ride --cleat 0.30,0.05 --speed 10km/h --model point,nn --nn "$data/nn-v1.json" \
    --extrapolate --enveloping static --out-dir rn --set FRONT_AXLE.TIRE_FILE=nof.tir \
    --set FRONT_AXLE.TIRE_DAMPING=3000
check "... and in the ride, an axle's tire without one: exit 2, the same words" \
    '[ $rc -eq 2 ] && grep -q "training.data.contact_law: .* nof.tir has no springs" err &&
     [ ! -e rn ]'
run "$bin" envelope --model rigid --tire nof.tir --cleat 0.10,0.10 --contact-length 0.3 -o rc.csv
check "the rigid disc at a --contact-length (the springs model's load) there: exit 2, FNOMIN" \
    '[ $rc -eq 2 ] && grep -q "FNOMIN" err && no_file rc.csv'
run "$bin" sweep --model rigid --tire nof.tir --lengths 0.1 --heights 0.05 --contact-lengths 0.3 \
    -o rsw
check "... and in a sweep over contact lengths (its cases' loads): exit 2, FNOMIN, nothing written" \
    '[ $rc -eq 2 ] && grep -q "FNOMIN" err && [ ! -e rsw ] && [ ! -e rsw.partial ]'
for regimes in "--loads 18000" "--contact-lengths 0.3"; do
    run "$bin" sweep --model nn --nn "$data/nn-v1.json" --extrapolate --tire nof.tir \
        --lengths 0.1 --heights 0.05 $regimes -o nsw
    check "... a sweep of an older network file at $regimes (the springs model's law): exit 2, nothing written" \
        '[ $rc -eq 2 ] && grep -q "nn-v1.json: training.data.contact_law: .* nof.tir has no springs" err &&
         [ ! -e nsw ] && [ ! -e nsw.partial ]'
done
# In the ride (inputs at each axle's static load), the network's input to the rear axle over
# the cleat against the ring's, the tire it was trained on (the data set's tire.tir): the RMS
# over the samples where either is above 0.1 mm within the network's own validation RMS. The
# tractor ballasted to 6 t (MASS): its rear tires' 17.8 kN is a 0.29 m patch, inside the data's
# 0.28 to 0.43 m (unballasted, 13.3 kN is 0.24 m, an extrapolation); the front's 11.6 kN is
# still below it: --extrapolate.
run "$bin" ride --cleat 0.30,0.05 --speed 10km/h --model ring,nn --nn nn.json --extrapolate \
    --enveloping static --out-dir rd --series --set MASS=6000 \
    --set FRONT_AXLE.TIRE_FILE="$repo/data/dataset/tire.tir" \
    --set REAR_AXLE.TIRE_FILE="$repo/data/dataset/tire.tir"
rms=$(paste -d, rd/series-ring-10kmh.csv rd/series-nn-10kmh.csv | awk -F, '
    /^#/ || /t_s/ { next }
    { r = $4; q = $17; if (r > 1e-4 || q > 1e-4) { s += (q - r) ^ 2; n++ } }
    END { if (n) printf "%.6f", 1e3 * sqrt(s / n) }')
check "ride: the network's rear input within its validation RMS of the ring's ($rms vs $val_rms mm)" \
    '[ $rc -eq 0 ] && [ -n "$rms" ] && awk -v a="$rms" -v b="$val_rms" "BEGIN { exit !(a < b) }"'

# The ride's tire springs and dampers (docs/models.md 9.1): the tire file's own where the
# vehicle gives none. The default tractor: each axle the default tire's vertical law, k_t its
# tangent at the axle's own static load; the user's MF-Tyre file on the rear axle: that file's
# linear law, 209651.5 N/m at any load, and no VERTICAL_DAMPING in it: refused without the
# vehicle's TIRE_DAMPING. A vehicle's TIRE_STIFFNESS: a linear spring.
car="$repo/data/tires/205-60R15-mfswift.tir"
law="tire file.s vertical law (k_t its tangent at the load)"
run "$bin" ride --cleat 0.30,0.05 --speed 10km/h --model point --out-dir rt
check "ride: comfort.md gives each axle's law, k_t and c_t from the tire file (311320, 342573 N/m)" \
    '[ $rc -eq 0 ] && grep -q "^| front | default.tir | 2 | 8737 | $law | 311321 | 3000 | tire file.s VERTICAL_DAMPING |" rt/comfort.md &&
     grep -q "^| rear | default.tir | 2 | 13335 | $law | 342573 |" rt/comfort.md'
run "$bin" ride --cleat 0.30,0.05 --speed 10km/h --model point --out-dir rs \
    --set FRONT_AXLE.TIRE_STIFFNESS=300000
check "ride --set FRONT_AXLE.TIRE_STIFFNESS: comfort.md gives that axle a linear spring, the other the law" \
    '[ $rc -eq 0 ] && grep -q "^| front | default.tir | 2 | 8737 | vehicle file.s TIRE_STIFFNESS (linear) | 300000 | 3000 |" rs/comfort.md &&
     grep -q "^| rear | default.tir | 2 | 13335 | $law | 342573 |" rs/comfort.md'
run "$bin" ride --cleat 0.30,0.05 --speed 10km/h --model point --out-dir rc \
    --set REAR_AXLE.TIRE_FILE="$car"
check "ride: a tire file without VERTICAL_DAMPING and no TIRE_DAMPING: exit 2 naming the axle, both keys, the file" \
    '[ $rc -eq 2 ] && grep -q "REAR_AXLE.TIRE_DAMPING: not given, and its tire file has no \[VERTICAL\] VERTICAL_DAMPING" err &&
     grep -q "the rear axle.s tire file .*205-60R15-mfswift.tir, named by --set REAR_AXLE.TIRE_FILE" err &&
     [ ! -e rc ]'
run "$bin" ride --cleat 0.30,0.05 --speed 10km/h --model point --out-dir rc \
    --set REAR_AXLE.TIRE_FILE="$car" --set REAR_AXLE.TIRE_DAMPING=500
check "... with the vehicle's TIRE_DAMPING: exit 0, k_t the file's 209652 N/m, c_t the vehicle's" \
    '[ $rc -eq 0 ] && grep -q "^| rear | 205-60R15-mfswift.tir | 2 | 13335 | $law | 209652 | 500 | vehicle file.s TIRE_DAMPING |" rc/comfort.md'

# The sidewall's keys (docs/models.md 4.9): refused when negative, or a preload without a
# stiffness, naming the key (test_springs_sidewall reads them in a file's units).
run "$bin" flat --set SIDEWALL_STIFFNESS=-5
check "flat --set SIDEWALL_STIFFNESS=-5: exit 2 (a bad --set), the key named" \
    '[ $rc -eq 2 ] && grep -q "SIDEWALL_STIFFNESS: must be zero" err && [ ! -s out ]'
run "$bin" flat --set SIDEWALL_PRELOAD=100
check "flat --set SIDEWALL_PRELOAD=100 without a stiffness: exit 2, the key named" \
    '[ $rc -eq 2 ] && grep -q "SIDEWALL_PRELOAD.*needs a sidewall" err && [ ! -s out ]'

run "$bin" identify --loads 1,2
check "identify at loads of 1 and 2 N: exit 2, the value out of range and the loads named" \
    '[ $rc -eq 2 ] && grep -q "Q_RA1: identified on the ring model at 2 loads 1 to 2 N: must be" err &&
     [ ! -s out ]'

clilib_done

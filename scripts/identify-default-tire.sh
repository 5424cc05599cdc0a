#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# One tire, every model, for the default tire in one command (docs/models.md section 14.1):
# re-identifies the springs model's RADIAL_STIFFNESS and INTERRADIAL_STIFFNESS and the cam's
# VERTICAL_STIFFNESS, Q_FZ2 (at the file's FNOMIN), Q_RA1 and Q_RA2 on the ring reference tire's
# flat ground at 0.5 to 1.5 times the file's FNOMIN, the springs model on its deflection and its
# contact length
# (`tirenv identify --write` on data/tires/default.tir, which records how in its '!' note),
# then copies the six values into tirenv_tire_default() (src/core/tire.c), which must equal
# the file (tests/formats/test_tir.c). Run it after any change to the ring or to its parameters:
#     scripts/identify-default-tire.sh [path/to/tirenv]      (default build/tirenv)
# then rebuild and check the vehicle file's comments on its loads (data/vehicles/tractor.veh)
# against `tirenv flat --model ring --load 13335.5` and `--load 8737.03`.
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
tirenv=${1:-$root/build/tirenv}
tir=$root/data/tires/default.tir
"$tirenv" identify --tire "$tir" --write
# The value of KEY in [SECTION] of the .tir file.
val() {
    awk -v sec="[$1]" -v key="$2" '
        /^[ \t]*\[/ { cur = toupper($1) }
        cur == sec && toupper($1) == key { sub(/^[^=]*=[ \t]*/, ""); sub(/[ \t]*\$.*/, ""); print; exit }
    ' "$tir"
}
c_r=$(val ENVELOPING_SPRINGS RADIAL_STIFFNESS)
c_b=$(val ENVELOPING_SPRINGS INTERRADIAL_STIFFNESS)
c_z=$(val VERTICAL VERTICAL_STIFFNESS)
q_fz2=$(val VERTICAL Q_FZ2)
q1=$(val CONTACT_PATCH Q_RA1)
q2=$(val CONTACT_PATCH Q_RA2)
for v in "$c_r" "$c_b" "$c_z" "$q_fz2" "$q1" "$q2"; do
    [ -n "$v" ] || { echo "identify-default-tire: a value is missing in $tir" >&2; exit 1; }
done
sed -i -E \
    -e "s/^( +\.c_r = )[^,]+,/\1$c_r,/" -e "s/^( +\.c_b = )[^,]+,/\1$c_b,/" \
    -e "s/^( +\.c_z = )[^,]+,/\1$c_z,/" -e "s/^( +\.q_fz2 = )[^,]+,/\1$q_fz2,/" \
    -e "s/^( +\.q_ra1 = )[^,]+,/\1$q1,/" \
    -e "s/^( +\.q_ra2 = )[^,]+,/\1$q2,/" "$root/src/core/tire.c"
echo "identify-default-tire: src/core/tire.c: c_r $c_r, c_b $c_b, c_z $c_z, q_fz2 $q_fz2, q_ra1 $q1, q_ra2 $q2"

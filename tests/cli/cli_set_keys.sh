#!/bin/sh
# --set of a key no model the command runs reads is said on standard error, naming the key,
# its section and the model: every model x a key of each section of the tire file, asserting
# the warning where the table says so and none elsewhere; where it warns, the curve is the one
# without the --set, byte for byte (the key is indeed not read: no false warning).
# Usage: tests/cli/cli_set_keys.sh BIN TESTDATA_DIR. SPDX-License-Identifier: Apache-2.0
# shellcheck disable=SC2016,SC2034,SC2086
repo=$(cd "$(dirname "$0")/../.." && pwd)
. "$(dirname "$0")/../lib/clilib.sh"

# One key of each section, at a value other than the default tire's that passes its check.
keys='DIMENSION:UNLOADED_RADIUS=0.69 VERTICAL:Q_FZ2=30 CONTACT_PATCH:Q_RA1=0.47
OPERATING_CONDITIONS:INFLPRES=130000 ENVELOPING_SPRINGS:RADIAL_STIFFNESS=450000
ENVELOPING_RING:FOUNDATION_STIFFNESS=1.2e5 ENVELOPING_SOLVER:FORCE_TOLERANCE=1e-5'

# CASE|options|noun in the message|sections it does not read
cases="rigid|--model rigid --load 20000|the rigid disc|VERTICAL CONTACT_PATCH OPERATING_CONDITIONS ENVELOPING_SPRINGS ENVELOPING_RING ENVELOPING_SOLVER
point|--model point --load 20000|the point|VERTICAL CONTACT_PATCH OPERATING_CONDITIONS ENVELOPING_SPRINGS ENVELOPING_RING ENVELOPING_SOLVER
rigid-at-length|--model rigid --contact-length 0.3|the rigid disc|VERTICAL CONTACT_PATCH OPERATING_CONDITIONS ENVELOPING_RING
springs|--model springs --load 20000|the springs model|VERTICAL CONTACT_PATCH OPERATING_CONDITIONS ENVELOPING_RING
ring|--model ring --load 20000|the ring|VERTICAL CONTACT_PATCH ENVELOPING_SPRINGS
cam|--model cam --load 20000|the cam|ENVELOPING_SPRINGS ENVELOPING_RING ENVELOPING_SOLVER
nn|--model nn --nn $data/nn-v1.json --contact-length 0.28|the network|VERTICAL CONTACT_PATCH OPERATING_CONDITIONS ENVELOPING_RING"

obstacle='--cleat 0.10,0.05 --x-from -0.8 --x-to 0.8 --dx 0.02'
while IFS='|' read -r name opts noun silent; do
    run "$bin" envelope $opts $obstacle -o base.csv
    check "$name: the curve without --set" '[ $rc -eq 0 ] && [ -s base.csv ] && ! grep -q -- "--set" err'
    for entry in $keys; do
        section=${entry%%:*}
        set=${entry#*:}
        key=${set%%=*}
        run "$bin" envelope $opts $obstacle --set "$set" -o set.csv
        case " $silent " in
        *" $section "*)
            check "$name --set $key: warned as [$section]'s, not read by $noun; curve unchanged" \
                '[ $rc -eq 0 ] && grep -q "^tirenv: --set $key: \[$section\] is .*; $noun does not read it$" err &&
                 [ "$(grep -c "^tirenv: --set" err)" -eq 1 ] && cmp -s base.csv set.csv' ;;
        *)
            check "$name --set $key: [$section] is read, no warning" \
                '[ $rc -eq 0 ] && ! grep -q -- "--set" err' ;;
        esac
    done
done <<EOF
$cases
EOF

# The brief's case, word for word; several models in one command name them all.
run "$bin" envelope --model ring --set RADIAL_STIFFNESS=1e6 $obstacle --load 20000 -o r.csv
check "envelope --model ring --set RADIAL_STIFFNESS: the springs model's, the ring does not read it" \
    '[ $rc -eq 0 ] && grep -qx "tirenv: --set RADIAL_STIFFNESS: \[ENVELOPING_SPRINGS\] is the springs model.s; the ring does not read it" err'
# compare: the models compared and the one that simulated the data (the embedded data set's
# ring), each at the case's load: the rigid disc does not read the springs model's keys here.
run "$bin" compare --data "$repo/data/dataset" --models rigid --no-images -o c0
run "$bin" compare --data "$repo/data/dataset" --models rigid --no-images -o c1 \
    --set RADIAL_STIFFNESS=9e5 --set Q_FZ2=30 --set FORCE_TOLERANCE=1e-3
check "compare --models rigid: springs and cam keys named with both models, the solver's not" \
    '[ $rc -eq 0 ] && [ "$(grep -c "^tirenv: --set" err)" -eq 2 ] &&
     grep -qx "tirenv: --set RADIAL_STIFFNESS: \[ENVELOPING_SPRINGS\] is the springs model.s; neither the rigid disc nor the ring reads it" err &&
     grep -q "^tirenv: --set Q_FZ2: \[VERTICAL\] is the cam.s; neither" err'
check "compare: the warned keys leave every error and curve the same bytes" \
    'cmp -s c0/errors.csv c1/errors.csv && cmp -s c0/AB.dat c1/AB.dat && cmp -s c0/F.dat c1/F.dat'
run "$bin" predict --nn "$data/nn-v1.json" $obstacle --contact-length 0.28 -o p0.csv
run "$bin" predict --nn "$data/nn-v1.json" $obstacle --contact-length 0.28 -o p1.csv \
    --set FOUNDATION_STIFFNESS=1.2e5 --set RADIAL_STIFFNESS=4.5e5
check "predict runs the network: the ring's key named, the springs model's (its stand-in) not" \
    '[ $rc -eq 0 ] && [ "$(grep -c "^tirenv: --set" err)" -eq 1 ] &&
     grep -qx "tirenv: --set FOUNDATION_STIFFNESS: \[ENVELOPING_RING\] is the ring.s; the network does not read it" err'
run "$bin" identify --reference ring --set Q_FZ2=30
check "identify: the reference, the springs model and the cam read every section" \
    '[ $rc -eq 0 ] && ! grep -q -- "--set" err'
run "$bin" flat --model cam --load 20000 --set ENVELOPING_SPRINGS.CONTACT=rays
check "flat --model cam, a SECTION.KEY assignment: named as given" \
    '[ $rc -eq 0 ] && grep -q "^tirenv: --set ENVELOPING_SPRINGS.CONTACT: \[ENVELOPING_SPRINGS\]" err'
run "$bin" flat --model springs --set INFLPRES=130000
check "flat without --load reads the ring (whether FNOMIN is in its regime): no warning" \
    '[ $rc -eq 0 ] && ! grep -q -- "--set" err'

# Each --help's example is a key its default model reads: no warning when it is used.
for c in flat bench fit compare; do
    run "$bin" $c --help
    check "$c --help: the --set example is the springs model's" \
        'grep -A3 -- "--set KEY=VALUE" out | grep -q "RADIAL_STIFFNESS"'
done
for c in rig import identify dataset; do
    run "$bin" $c --help
    check "$c --help: the --set example is the ring's" \
        'grep -A3 -- "--set KEY=VALUE" out | grep -q "FOUNDATION_STIFFNESS"'
done
clilib_done

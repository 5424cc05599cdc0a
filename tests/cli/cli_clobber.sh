#!/bin/sh
# -o naming a file the command reads is refused before anything runs, and the input is left
# as it was: every output is renamed over its target, so `envelope --profile road.csv -o
# road.csv` wrote the curve and the road was gone. A symbolic link to the input is the input;
# a hard link is another name, which the rename replaces while the input keeps its own.
# Usage: tests/cli/cli_clobber.sh BIN TESTDATA_DIR. SPDX-License-Identifier: Apache-2.0
# shellcheck disable=SC2016,SC2034,SC2086
repo=$(cd "$(dirname "$0")/../.." && pwd)
. "$(dirname "$0")/../lib/clilib.sh"

printf 'x_m,z_m\n-0.1,0\n0,0.05\n0.1,0\n' >road.csv
cp road.csv road0.csv
cp "$repo/data/tires/default.tir" t.tir
cp "$repo/data/vehicles/tractor.veh" v.veh
cp "$data/nn-v1.json" n.json
"$bin" rig --cleat 0.1,0.05 --load 20000 -o log.csv 2>/dev/null
for f in t.tir v.veh n.json log.csv; do cp $f $f.0; done

# refused WHAT FILE OPTION: exit 1, the message names -o, the option and the file, FILE as
# it was.
refused() {
    file=$2 option=$3
    check "$1" '[ $rc -eq 1 ] &&
        grep -q "^tirenv: .*: -o .* is the file $option .* reads: the output would replace it" err &&
        cmp -s $file $file.0'
}
cp road0.csv road.csv.0
run "$bin" envelope --model rigid --profile road.csv --load 20000 -o road.csv
refused "envelope --profile road.csv -o road.csv" road.csv --profile
run "$bin" envelope --model rigid --cleat 0.1,0.05 --load 20000 --tire t.tir -o t.tir
refused "envelope --tire t.tir -o t.tir" t.tir --tire
run "$bin" envelope --model rigid --profile road.csv --load 20000 --stream -o road.csv
refused "envelope --stream: the same" road.csv --profile
run "$bin" predict --nn n.json --cleat 0.1,0.05 --contact-length 0.28 -o n.json
refused "predict --nn n.json -o n.json" n.json --nn
run "$bin" rig --profile road.csv --load 20000 -o road.csv
refused "rig --profile road.csv -o road.csv" road.csv --profile
run "$bin" import --log log.csv --cleat 0.1,0.05 --load 20000 -o log.csv
refused "import --log log.csv -o log.csv" log.csv --log
run "$bin" ride --cleat 0.1,0.05 --model point --speed 5 --vehicle v.veh -o v.veh
refused "ride --vehicle v.veh -o v.veh" v.veh --vehicle
run "$bin" ride --profile road.csv --model point --speed 5 -o road.csv
refused "ride --profile road.csv -o road.csv" road.csv --profile

mkdir -p dd/tires
cp t.tir dd/tires/default.tir
cp t.tir dd/tires/default.tir.0
run env TIRENV_DATA="$PWD/dd" "$bin" envelope --model rigid --cleat 0.1,0.05 --load 20000 \
    -o dd/tires/default.tir
refused "envelope -o the default tire file, no --tire" dd/tires/default.tir --tire
run env TIRENV_DATA="$PWD/dd" "$bin" road --class C --length 1 -o dd/tires/default.tir
check "road -o the default tire file: written (road reads no tire)" \
    '[ $rc -eq 0 ] && head -n 1 dd/tires/default.tir | grep -q "^x_m,z_m"'

cp -r "$repo/data/dataset" D
cp D/cases.csv D/cases.csv.0
run "$bin" train --data D -o D/cases.csv
check "train --data D -o D/cases.csv: refused, exit 1, the manifest as it was" \
    '[ $rc -eq 1 ] && grep -q "is a file of the directory --data D, whose files it reads" err &&
     cmp -s D/cases.csv D/cases.csv.0'

ln -s road.csv link.csv
run "$bin" envelope --model rigid --profile road.csv --load 20000 -o link.csv
refused "-o a symbolic link to the input" road.csv --profile
run "$bin" envelope --model rigid --profile link.csv --load 20000 -o ./road.csv
refused "the input through a symbolic link, -o its target by another path" road.csv --profile

ln road.csv hard.csv
run "$bin" envelope --model rigid --profile road.csv --load 20000 -o hard.csv
check "-o a hard link of the input: written, the input's own name keeps the road" \
    '[ $rc -eq 0 ] && cmp -s road.csv road0.csv && head -n 1 hard.csv | grep -q "^x_m,z_m,h_m"'
run "$bin" envelope --model rigid --profile road.csv --load 20000 -o /dev/null
check "-o /dev/null is written through: no refusal" '[ $rc -eq 0 ]'
run "$bin" envelope --model rigid --profile road.csv --load 20000 -o curve.csv
check "-o another file: written" '[ $rc -eq 0 ] && [ "$(rows curve.csv)" -gt 100 ]'

# ride -o a path it cannot write is said before the inputs and runs (the message names no run:
# it named the run, after computing it).
mkdir -p outdir
run "$bin" ride --cleat 0.1,0.05 --model springs --speed 5 -o outdir
check "ride -o DIR: exit 2 before any run, naming the directory" \
    '[ $rc -eq 2 ] && grep -q "^tirenv: outdir: is a directory" err && ! grep -q "model (" err'
run "$bin" ride --cleat 0.1,0.05 --model springs --speed 5 -o nodir/series.csv
check "ride -o into a missing directory: exit 2 before any run" \
    '[ $rc -eq 2 ] && grep -q "^tirenv: nodir/series.csv: cannot create" err && ! grep -q "model (" err'
run "$bin" ride --cleat 0.1,0.05 --model point --speed 5 -o series.csv
check "ride -o a file: written, one row a sample after the header and comment" \
    '[ $rc -eq 0 ] && head -n 1 series.csv | grep -q "^t_s,x_front_m" && [ "$(rows series.csv)" -gt 1000 ]'
# dataset build writes tire.tir into -o DIR: --tire naming that file (or a link to it) is
# refused before any case runs, the user's file unchanged.
mkdir -p ds
cp "$repo/data/tires/205-60R15-mfswift.tir" ds/tire.tir
cp ds/tire.tir ds.before
ln -s ds/tire.tir link.tir
for t in ds/tire.tir link.tir; do
    run "$bin" dataset build --design 205-60R15 --tire $t -o ds
    check "dataset build --tire $t -o ds: exit 1 naming ds/tire.tir, the file unchanged, no case" \
        '[ $rc -eq 1 ] && grep -q "writes ds/tire.tir, which is the file --tire $t" err &&
         cmp -s ds/tire.tir ds.before && [ ! -e ds/cases.csv ]'
done

clilib_done

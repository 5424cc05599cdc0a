#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# Every input of every command (tirenv --help lists them) given as a FIFO, or as /dev/stdin
# from a pipe: read once, with the output a regular file gives; or, where the command reads
# the file twice, refused at once (exit 2, the file named, "a pipe", no output written). Each
# run is behind timeout, so a hang fails its check with exit status 124: `flat --tire FIFO`
# hung for ever, the tire file being opened a second time to derive its models.
# road has no input file. Usage: tests/cli/cli_fifo.sh BIN TESTDATA_DIR.
# shellcheck disable=SC2016,SC2034,SC2086
. "$(dirname "$0")/../lib/clilib.sh"

repo=$(cd "$data/../.." && pwd)
tir=$repo/data/tires/default.tir
car=$repo/data/tires/205-60R15-mfswift.tir
set_data=$repo/data/dataset

# fifo SRC CMD...: CMD with each argument @F@ replaced by ./ff, a FIFO that a background cat
# fills with SRC's bytes, under timeout (exit status 124 on a hang); stdout to ./out, stderr
# to ./err, exit status in $rc. A writer still waiting to open the FIFO (the command refused
# it before opening it) is ended by release_writer.
fifo() {
    src=$1
    shift
    rm -f ff
    mkfifo ff
    feed "$src" ff
    nargs=$#
    for a; do
        [ "$a" = @F@ ] && a=$PWD/ff
        set -- "$@" "$a"
    done
    shift "$nargs"
    timeout 120 "$@" >out 2>err
    rc=$?
    release_writer ff
    rm -f ff
}

# stdin SRC CMD...: CMD with @F@ as /dev/stdin, SRC piped in, under timeout.
stdin() {
    src=$1
    shift
    nargs=$#
    for a; do
        [ "$a" = @F@ ] && a=/dev/stdin
        set -- "$@" "$a"
    done
    shift "$nargs"
    cat "$src" | timeout 120 "$@" >out 2>err
    rc=$?
}

# refused FILE: exit 2 and the one-line message naming the pipe and why.
refused() {
    [ $rc -eq 2 ] && grep -q "^tirenv: $1: a pipe, which can be read only once; .*expected a regular file" err
}

# The references: each output from regular files.
"$bin" train --data "$set_data" --paper --restarts 1 --epochs 20 -o nn.json >/dev/null 2>&1
"$bin" rig --cleat 0.10,0.10 --load 20000 -o rig.log 2>/dev/null
"$bin" road --class C --length 20 -o road.csv 2>/dev/null
"$bin" convert --profile road.csv -o road.crg 2>/dev/null
"$bin" convert --profile road.csv -o road.rdf 2>/dev/null
printf 'x_m,z_m\n-1,0\n-0.05,0\n-0.05,0.1\n0.05,0.1\n0.05,0\n1,0\n' >cleat.csv
sed "s|'../tires/default.tir'|'$tir'|" "$repo/data/vehicles/tractor.veh" >abs.veh
sed "s|'../tires/default.tir'|'$PWD/ff'|" "$repo/data/vehicles/tractor.veh" >fifo.veh
[ -s nn.json ] && [ -s rig.log ] && [ -s road.rdf ] && [ -s road.crg ] || {
    echo "Bail out! the reference files could not be made"
    exit 2
}

# --- flat, identify: a tire file (the derivation read it a second time) ---------------------
"$bin" flat --tire "$tir" --load 20000 | tail -n +2 >want
fifo "$tir" "$bin" flat --tire @F@ --load 20000
check "flat --tire FIFO: exit 0, the file's figures" \
    '[ $rc -eq 0 ] && tail -n +2 out | cmp -s - want'
stdin "$tir" "$bin" flat --tire @F@ --load 20000
check "flat --tire /dev/stdin: exit 0, the file's figures" \
    '[ $rc -eq 0 ] && tail -n +2 out | cmp -s - want'
# The car tire's MF-Tyre keys without tirenv's sections: its ring and springs model derived
# from the bytes read once.
awk '/^\[/ { skip = ($0 ~ /^\[ENVELOPING_(SPRINGS|RING)\]/) } !skip' "$car" >mf.tir
"$bin" flat --tire mf.tir --model ring --load 4000 2>/dev/null | tail -n +2 >want
fifo mf.tir "$bin" flat --tire @F@ --model ring --load 4000
check "flat --tire FIFO --model ring, a file whose models are derived: exit 0, the same" \
    '[ $rc -eq 0 ] && tail -n +2 out | cmp -s - want &&
     grep -q "no \[ENVELOPING_RING\]: derived" err'
"$bin" identify --tire "$car" 2>/dev/null | tail -n +2 >want
fifo "$car" "$bin" identify --tire @F@
check "identify --tire FIFO: exit 0, the same table" \
    '[ $rc -eq 0 ] && tail -n +2 out | cmp -s - want'
fifo "$car" "$bin" identify --tire @F@ --write
check "identify --tire FIFO --write (set in place): refused at once" 'refused "$PWD/ff"'

# --- envelope, predict: tire, road files, network ------------------------------------------
"$bin" envelope --model springs --tire "$car" --cleat 0.05,0.02 --load 4000 -o want.csv 2>/dev/null
fifo "$car" "$bin" envelope --model springs --tire @F@ --cleat 0.05,0.02 --load 4000 -o got.csv
check "envelope --tire FIFO: exit 0, the same curve" '[ $rc -eq 0 ] && cmp -s got.csv want.csv'
for road in road.csv road.crg road.rdf; do
    "$bin" envelope --model springs --profile "$road" --load 20000 -o want.csv 2>/dev/null
    fifo "$road" "$bin" envelope --model springs --profile @F@ --load 20000 -o got.csv
    check "envelope --profile FIFO of $road: exit 0, the same curve" \
        '[ $rc -eq 0 ] && cmp -s got.csv want.csv'
    fifo "$road" "$bin" envelope --model rigid --stream --profile @F@ --load 20000 -o got.csv
    "$bin" envelope --model rigid --stream --profile "$road" --load 20000 -o want.csv 2>/dev/null
    check "envelope --stream --profile FIFO of $road: exit 0, the same curve" \
        '[ $rc -eq 0 ] && cmp -s got.csv want.csv'
done
"$bin" envelope --model rigid --profile road.rdf --load 20000 -o want.csv 2>/dev/null
stdin road.rdf "$bin" envelope --model rigid --profile @F@ --load 20000 -o got.csv
check "envelope --profile /dev/stdin (RDF): exit 0, the same curve" \
    '[ $rc -eq 0 ] && cmp -s got.csv want.csv'
"$bin" envelope --model nn --nn nn.json --cleat 0.1,0.1 --load 20000 -o want.csv 2>/dev/null
fifo nn.json "$bin" envelope --model nn --nn @F@ --cleat 0.1,0.1 --load 20000 -o got.csv
check "envelope --nn FIFO: exit 0, the same curve" '[ $rc -eq 0 ] && cmp -s got.csv want.csv'
"$bin" predict --nn nn.json --cleat 0.1,0.1 --load 20000 -o want.csv 2>/dev/null
fifo nn.json "$bin" predict --nn @F@ --cleat 0.1,0.1 --load 20000 -o got.csv
check "predict --nn FIFO: exit 0, the same curve" '[ $rc -eq 0 ] && cmp -s got.csv want.csv'
stdin nn.json "$bin" predict --nn @F@ --cleat 0.1,0.1 --load 20000 -o got.csv
check "predict --nn /dev/stdin: exit 0, the same curve" '[ $rc -eq 0 ] && cmp -s got.csv want.csv'
"$bin" predict --nn nn.json --profile cleat.csv --load 20000 -o want.csv 2>/dev/null
fifo cleat.csv "$bin" predict --nn nn.json --profile @F@ --load 20000 -o got.csv
check "predict --profile FIFO: exit 0, the same curve" '[ $rc -eq 0 ] && cmp -s got.csv want.csv'
"$bin" predict --nn nn.json --tire "$tir" --cleat 0.1,0.1 --contact-length 0.3 -o want.csv 2>/dev/null
fifo "$tir" "$bin" predict --nn nn.json --tire @F@ --cleat 0.1,0.1 --contact-length 0.3 -o got.csv
check "predict --tire FIFO: exit 0, the same curve" '[ $rc -eq 0 ] && cmp -s got.csv want.csv'

# --- convert, rig, import --------------------------------------------------------------------
for road in road.csv road.crg road.rdf; do
    "$bin" convert --profile "$road" -o want.rdf 2>/dev/null
    fifo "$road" "$bin" convert --profile @F@ -o got.rdf
    check "convert --profile FIFO of $road: exit 0, the same file" \
        '[ $rc -eq 0 ] && cmp -s got.rdf want.rdf'
done
fifo "$tir" "$bin" rig --tire @F@ --cleat 0.1,0.1 --load 20000 -o got.log
check "rig --tire FIFO: exit 0, the same log" '[ $rc -eq 0 ] && cmp -s got.log rig.log'
"$bin" rig --profile cleat.csv --load 20000 -o want.log 2>/dev/null
fifo cleat.csv "$bin" rig --profile @F@ --load 20000 -o got.log
check "rig --profile FIFO: exit 0, the same log" '[ $rc -eq 0 ] && cmp -s got.log want.log'
"$bin" import --log rig.log --cleat 0.1,0.1 --load 20000 -o want.csv 2>/dev/null
fifo rig.log "$bin" import --log @F@ --cleat 0.1,0.1 --load 20000 -o got.csv
check "import --log FIFO: exit 0, the same curve" '[ $rc -eq 0 ] && cmp -s got.csv want.csv'
stdin rig.log "$bin" import --log @F@ --cleat 0.1,0.1 --load 20000 -o got.csv
check "import --log /dev/stdin: exit 0, the same curve" '[ $rc -eq 0 ] && cmp -s got.csv want.csv'
fifo "$tir" "$bin" import --log rig.log --tire @F@ --cleat 0.1,0.1 --load 20000 -o got.csv
check "import --tire FIFO: exit 0, the same curve" '[ $rc -eq 0 ] && cmp -s got.csv want.csv'

# --- dataset, sweep: a tire; a data set's own files are refused (read more than once) -------
"$bin" dataset build --design 205-60R15 --tire "$car" -o ds-want 2>/dev/null
fifo "$car" "$bin" dataset build --design 205-60R15 --tire @F@ -o ds-got
check "dataset build --tire FIFO: exit 0, the same data set" \
    '[ $rc -eq 0 ] && diff -r ds-got ds-want >/dev/null'
for f in source.txt cases.csv curves/A.csv; do
    rm -rf ds
    cp -r "$set_data" ds
    rm "ds/$f"
    mkfifo "ds/$f"
    run timeout 120 "$bin" dataset list ds
    check "dataset list, $f a FIFO: refused at once naming it" 'refused "ds/$f"'
    run timeout 120 "$bin" fit --data ds -o fitted.tir
    check "fit --data, $f a FIFO: refused at once naming it, no file" \
        'refused "ds/$f" && no_file fitted.tir'
done
rm -rf ds
"$bin" sweep --lengths 0.1 --heights 0.05 --contact-lengths 0.3 --model springs --tire "$tir" \
    -o sw-want 2>/dev/null
fifo "$tir" "$bin" sweep --lengths 0.1 --heights 0.05 --contact-lengths 0.3 --model springs \
    --tire @F@ -o sw-got
check "sweep --tire FIFO: exit 0, the same data set" \
    '[ $rc -eq 0 ] && diff -r sw-got sw-want >/dev/null'
fifo nn.json "$bin" sweep --lengths 0.1 --heights 0.05 --contact-lengths 0.3 --model nn \
    --nn @F@ -o sw-nn
check "sweep --nn FIFO (read again for its fingerprint): refused at once, no data set" \
    'refused "$PWD/ff" && [ ! -e sw-nn ] && [ ! -e sw-nn.partial ]'
for k in 0 1; do
    "$bin" sweep --lengths 0.1,0.2 --heights 0.05 --contact-lengths 0.3 --model springs \
        --shard $k/2 -o part$k 2>/dev/null
done
"$bin" sweep merge part0 part1 -o merged-want 2>/dev/null
for f in sweep.txt cases.csv tire.tir; do
    cp -r part0 fpart
    rm "fpart/$f"
    mkfifo "fpart/$f"
    feed "part0/$f" "fpart/$f"
    run timeout 120 "$bin" sweep merge fpart part1 -o merged
    release_writer "fpart/$f"
    check "sweep merge, a part's $f a FIFO: exit 0, the same data set" \
        '[ $rc -eq 0 ] && diff -r merged merged-want >/dev/null'
    rm -rf fpart merged
done

# --- fit, train, study, compare: a tire, a network -------------------------------------------
"$bin" fit --data "$set_data" --tire "$tir" -o want.tir >/dev/null 2>&1
fifo "$tir" "$bin" fit --data "$set_data" --tire @F@ -o got.tir
check "fit --tire FIFO: exit 0, the same fitted tire" '[ $rc -eq 0 ] && cmp -s got.tir want.tir'
"$bin" train --data "$set_data" --tire "$tir" --paper --restarts 1 --epochs 20 -o want.json \
    >/dev/null 2>&1
fifo "$tir" "$bin" train --data "$set_data" --tire @F@ --paper --restarts 1 --epochs 20 \
    -o got.json
grep -v _time_s want.json >want.txt
check "train --tire FIFO: exit 0, the same network (its times apart)" \
    '[ $rc -eq 0 ] && grep -v _time_s got.json | cmp -s - want.txt'
"$bin" compare --data "$set_data" --tire "$tir" --nn nn.json --models rigid,springs,nn \
    --no-images -o cmp-want >/dev/null 2>&1
fifo "$tir" "$bin" compare --data "$set_data" --tire @F@ --nn nn.json --models rigid,springs,nn \
    --no-images -o cmp-tire
check "compare --tire FIFO: exit 0, the same errors" \
    '[ $rc -eq 0 ] && cmp -s cmp-tire/errors.csv cmp-want/errors.csv'
fifo nn.json "$bin" compare --data "$set_data" --tire "$tir" --nn @F@ --models rigid,springs,nn \
    --no-images -o cmp-nn
check "compare --nn FIFO: exit 0, the same errors" \
    '[ $rc -eq 0 ] && cmp -s cmp-nn/errors.csv cmp-want/errors.csv'
if [ "${TIRENV_TEST_SANITIZED:-0}" = 1 ]; then
    echo "# sanitizer build: study --tire FIFO left to the Release build (a whole study)"
else
    fifo "$tir" "$bin" study --tire @F@ --seeds 1 --no-images -o study
    check "study --tire FIFO --seeds 1: exit 0, its report" \
        '[ $rc -eq 0 ] && [ -s study/report.md ] && [ -s study/errors.csv ]'
fi

# --- ride: the vehicle, its tire files, the road, the network -------------------------------
"$bin" ride --vehicle abs.veh --cleat 0.1,0.1 --model springs --speed 10 -o want.csv >/dev/null 2>&1
fifo abs.veh "$bin" ride --vehicle @F@ --cleat 0.1,0.1 --model springs --speed 10 -o got.csv
check "ride --vehicle FIFO: exit 0, the same run" '[ $rc -eq 0 ] && cmp -s got.csv want.csv'
fifo "$tir" "$bin" ride --vehicle fifo.veh --cleat 0.1,0.1 --model springs --speed 10 -o got.csv
check "ride, both axles' TIRE_FILE one FIFO: read once, exit 0, the same run" \
    '[ $rc -eq 0 ] && cmp -s got.csv want.csv'
"$bin" ride --profile road.csv --model rigid --speed 10 -o want.csv >/dev/null 2>&1
fifo road.csv "$bin" ride --profile @F@ --model rigid --speed 10 -o got.csv
check "ride --profile FIFO: exit 0, the same run" '[ $rc -eq 0 ] && cmp -s got.csv want.csv'
"$bin" ride --cleat 0.1,0.1 --model nn --nn nn.json --extrapolate --speed 10 -o want.csv >/dev/null 2>&1
fifo nn.json "$bin" ride --cleat 0.1,0.1 --model nn --nn @F@ --extrapolate --speed 10 -o got.csv
check "ride --nn FIFO: exit 0, the same run" '[ $rc -eq 0 ] && cmp -s got.csv want.csv'

# --- bench: its child processes read the tire file again -----------------------------------
fifo "$tir" "$bin" bench --quick --tire @F@
check "bench --tire FIFO: refused at once (before any timing)" \
    'refused "$PWD/ff" && [ ! -s out ]'
# /dev/stdin redirected from a regular file is that file, also for the children, whose own
# standard input is /dev/null: they read the tire by its real path (they found it empty, and
# the bench failed at its memory part, after the timings). Some 0.7 s of CPU in Release, its
# children's sweeps over a 100 m road: left to the Release build.
if [ "${TIRENV_TEST_SANITIZED:-0}" = 1 ]; then
    echo "# sanitizer build: bench --tire /dev/stdin left to the Release build"
else
    timeout 120 "$bin" bench --memory --quick --json --tire /dev/stdin <"$tir" >out 2>err
    rc=$?
    check "bench --tire /dev/stdin from a file: its children read the file, exit 0" \
        '[ $rc -eq 0 ] && grep -q envelope_whole_peak_mb out'
fi

clilib_done

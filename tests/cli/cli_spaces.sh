#!/bin/sh
# A clone whose path has blanks. The suite runs from wherever the clone is, so a quoting slip
# (an unquoted "$x", a path put into an option list that is split into words) passes unless
# that path has a blank: this test gives it some, by links, without a second build or clone.
# Two directories hold the same links (src: the source tree, data: the test data, bin: the
# program's directory); one is named with two blanks. The CLI run through each on data reached
# through it, writing into it, gives the same bytes once that directory's name is replaced by
# the other's; cli_docs.sh (which walks the clone's files) passes from the blank-named one, its
# scratch directory there too; fuzz/run.sh hands its harness the seed corpus as one argument.
# Usage: sh cli_spaces.sh BIN TESTDATA_DIR.
# SPDX-License-Identifier: Apache-2.0
# shellcheck disable=SC2016,SC2034,SC2154 # conditions and what they read are for eval; bin is clilib's
root=$(cd "$(dirname "$0")/../.." && pwd)
# shellcheck source=tests/lib/clilib.sh
. "$(dirname "$0")/../lib/clilib.sh"

plain=$work/plain
spaced="$work/my  clone"  # two blanks: an unquoted echo would also make them one
for d in "$plain" "$spaced"; do
    mkdir "$d" "$d/out" "$d/tmp" &&
        ln -s "$root" "$d/src" && ln -s "$data" "$d/data" && ln -s "$(dirname "$bin")" "$d/bin" ||
        exit 2
done
prog=bin/$(basename "$bin")

# run_in DIR NAME CMD...: CMD with a leading @ of each word read as DIR and TIRENV_DATA set to
# DIR/src/data; stdout and stderr to DIR/out/NAME.out and .err, the exit status in rc.
run_in() {
    dir_=$1 name_=$2
    shift 2
    first_=1
    for a_; do
        [ $first_ -eq 1 ] && set -- && first_=0
        case $a_ in @*) a_=$dir_${a_#@} ;; esac
        set -- "$@" "$a_"
    done
    TIRENV_DATA=$dir_/src/data "$@" >"$dir_/out/$name_.out" 2>"$dir_/out/$name_.err"
    rc=$?
}

# same NAME CMD...: CMD in both directories, each run exit 0; every file of the spaced out/
# equals the plain one's, its directory's name put back to the plain one's (and fit's time
# left out).
same() {
    name=$1
    shift
    run_in "$plain" "$name" "$@"
    rc_plain=$rc
    run_in "$spaced" "$name" "$@"
    cp "$spaced/out/$name.err" err  # check shows the spaced run's errors
    bad=0
    [ $rc_plain -eq 0 ] && [ $rc -eq 0 ] || bad=1
    for f in "$plain/out"/*; do
        g=$spaced/out/$(basename "$f")
        # A path the user gave comes back in messages and listings; fit reports its time.
        [ -f "$g" ] && sed "s|$spaced|$plain|g; s/, [0-9.]* s,/, (time),/" "$g" >a &&
            sed "s/, [0-9.]* s,/, (time),/" "$f" >b && cmp -s a b || bad=1
    done
    rm -f "$plain/out"/* "$spaced/out"/*
}

same envelope "@/$prog" envelope --model springs --profile @/data/profile_good.csv \
    --tire @/src/data/tires/default.tir --load 12345 --dx 0.01 -o @/out/env.csv
check "envelope --profile, --tire and -o through the blanks: exit 0, the same bytes" '[ $bad -eq 0 ]'
same default "@/$prog" envelope --model springs --cleat 0.1,0.05 --load 13000 --dx 0.05 \
    -o @/out/default.csv
check "... the default tire from TIRENV_DATA through the blanks: the same bytes" '[ $bad -eq 0 ]'
same list "@/$prog" dataset list @/data/dataset_good
check "dataset list of a data set through the blanks: exit 0, the same listing" '[ $bad -eq 0 ]'
same embedded "@/$prog" dataset list
check "... the embedded data set, from TIRENV_DATA: the same listing" '[ $bad -eq 0 ]'
same fit "@/$prog" fit --data @/data/dataset_good -o @/out/fit.tir
check "fit --data, -o through the blanks: exit 0, the same bytes" '[ $bad -eq 0 ]'
same crg "@/$prog" convert --profile @/data/samples/crg/handmade_straight.crg \
    -o @/out/straight.csv
check "convert of a CRG sample through the blanks: exit 0, the same bytes" '[ $bad -eq 0 ]'
same rdf "@/$prog" convert --profile @/data/samples/rdf/plateau.rdf --dx 0.05 -o @/out/plateau.crg
check "convert of an RDF road to .crg through the blanks: exit 0, the same bytes" '[ $bad -eq 0 ]'

# cli_docs.sh finds the clone from its own path and hands its file lists to awk and grep.
TMPDIR=$spaced/tmp sh "$spaced/src/tests/cli/cli_docs.sh" "$spaced/$prog" "$spaced/data" \
    >docs.out 2>docs.err
rc=$?
head -n 20 docs.err >err  # a split path fails on every file: the first lines say enough
check "cli_docs.sh run from the blank-named clone, its scratch directory there: all ok" \
    '[ $rc -eq 0 ] && grep -q "^ok " docs.out && ! grep -q "^not ok" docs.out ||
     { grep "^not ok" docs.out; false; }'

# fuzz/run.sh with a stand-in harness that prints its arguments, one a line, into the log.
printf '#!/bin/sh\nprintf "%%s\\n" "$@"\n' >"$spaced/harness"
chmod +x "$spaced/harness"
seeds=$spaced/src/tests/fuzz/corpus/profile_csv
TMPDIR=$spaced/tmp sh "$spaced/src/tests/fuzz/run.sh" "$spaced/harness" "$seeds" \
    "$spaced/fuzz" 1 >fuzz.out 2>err
rc=$?
check "fuzz/run.sh: the seed corpus through the blanks reaches the harness as one argument" \
    '[ $rc -eq 0 ] && [ -d "$seeds" ] && grep -qxF "$seeds" "$spaced/fuzz/log"'

clilib_done

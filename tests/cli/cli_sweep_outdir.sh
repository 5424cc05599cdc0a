#!/bin/sh
# tirenv sweep's output directories beside the others' (docs/formats.md sections 1 and 13):
# sweep merge builds its result in a staging directory swapped in whole (tirenv_outdir), which
# leaves nothing behind on success or failure and nothing but the old directory when refused;
# a sweep's resumable DIR.partial is not such a staging directory and is never swept away by
# another command writing beside it; files written from several threads at once get the
# umask's mode. Usage: sh cli_sweep_outdir.sh BIN TESTDATA_DIR.
# SPDX-License-Identifier: Apache-2.0
# shellcheck disable=SC2016,SC2086,SC2154 # conditions are single-quoted for eval; the grid's
# options are split on purpose; bin is clilib's
# shellcheck source=tests/lib/clilib.sh
. "$(dirname "$0")/../lib/clilib.sh"

grid='--lengths 0.05,0.15 --heights 0.03,0.08 --contact-lengths 0.3,0.38 --model springs'

# Nothing but the named entries in the current directory (and run's out and err): no
# staging directory, no temporary file, no merge directory of the old design
# (DIR.merge.<pid>.<k>).
only() {
    [ "$(find . -mindepth 1 -maxdepth 1 | sed 's|^\./||' | grep -c -v -x -e out -e err "$@")" \
        -eq 0 ]
}

for k in 0 1; do
    "$bin" sweep $grid -o "part$k" --shard "$k/2" --jobs 2 2>/dev/null
done
"$bin" sweep $grid -o one --jobs 1 2>/dev/null
run "$bin" sweep merge part1 part0 -o merged
check "merge writes the one-part run's bytes and leaves no staging directory" \
    '[ $rc -eq 0 ] && diff -r one merged >&2 && only -e part0 -e part1 -e one -e merged'

mkdir empty
run "$bin" sweep merge part0 part1 -o empty
check "merge into an empty directory fills it" '[ $rc -eq 0 ] && diff -r one empty >&2'

mkdir other
echo keep >other/mine.txt
run "$bin" sweep merge part0 part1 -o other
check "merge refuses a directory holding something else, and leaves it as it was" \
    '[ $rc -ne 0 ] && [ "$(ls -A other)" = mine.txt ] && grep -q -x keep other/mine.txt &&
     only -e part0 -e part1 -e one -e merged -e empty -e other'

run "$bin" sweep merge part0 part1 -o ""
check "merge -o with an empty path is misuse, exit 1, as every command's -o" \
    '[ $rc -eq 1 ] && grep -q "needs a directory, got an empty path" err'

run "$bin" sweep merge part0 -o lonely
check "a failed merge leaves neither the target nor a staging directory" \
    '[ $rc -eq 2 ] && [ ! -e lonely ] &&
     only -e part0 -e part1 -e one -e merged -e empty -e other'

# A sweep's DIR.partial, as a killed run leaves it, beside an output directory that another
# command writes: the latter's stale-entry sweep must leave the partial sweep alone, and the
# sweep then resumes from it.
# The killed run's directory is a copy of the one-part run's (the same grid on one thread:
# the same bytes, as the last check shows again), not a fourth sweep of it.
cp -R one resumed.partial
rm resumed.partial/cases.csv resumed.partial/curves/c0001.csv
run "$bin" sweep merge part0 part1 -o merged-again
check "another output directory written beside DIR.partial leaves it alone" \
    '[ $rc -eq 0 ] && [ -d resumed.partial ] && [ -s resumed.partial/curves/c0000.csv ]'
run "$bin" sweep $grid -o resumed --jobs 2
check "the sweep then resumes from DIR.partial, to the bytes of one run" \
    '[ $rc -eq 0 ] && grep -q "1 cases run, 7 kept" err && diff -r one resumed >&2 &&
     [ ! -e resumed.partial ]'

# The files' mode comes from the umask, read without setting it (several threads create
# files at once); a new file gets 0666 minus the umask, as fopen gives.
run sh -c "umask 027 && \"$bin\" sweep $grid -o masked --jobs 3"
check "files written on 3 threads under umask 027 are rw-r-----" \
    '[ $rc -eq 0 ] && [ -z "$(find masked -type f ! -perm 640 -print)" ] &&
     [ "$(find masked -type f | wc -l)" -gt 8 ]'
run sh -c "umask 022 && \"$bin\" dataset build --design 205-60R15 --jobs 3 -o ds"
check "dataset build --jobs 3 under umask 022: files rw-r--r--, whole directory in place" \
    '[ $rc -eq 0 ] && [ -s ds/cases.csv ] && [ -z "$(find ds -type f ! -perm 644 -print)" ] &&
     [ -z "$(find . -name "*tirenv-tmp*" -print)" ]'

clilib_done

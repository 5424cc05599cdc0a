#!/bin/sh
# Memcheck over the deformable models' sweeps: no value computed from memory that was never
# written. The ring's Newton driver read entries of its vectors it never wrote (knots made for
# corners outside the contact window, src/model/ring_knots.c find_knots); a fresh mapping gave
# zeros (the CLI), reused heap garbage (Python, once NumPy's freed arrays had raised malloc's
# mmap threshold), and NaN garbage failed a sweep the CLI had computed. The vectors are left
# unzeroed so that memcheck sees such a read (zeroed, it saw none while the read stayed). The
# sanitizer build does not see such reads (MemorySanitizer would; it is clang's and needs
# every library rebuilt), so valgrind runs the Release binary (6.9 s of CPU, 2.3 s of it the
# Brent run below). Labelled slow so that the sanitizer build, whose binary valgrind cannot
# run, leaves it out.
# Usage: tests/model/memcheck.sh BIN. SPDX-License-Identifier: Apache-2.0
bin=$1
if ! command -v valgrind >/dev/null 2>&1; then
    echo "memcheck.sh: valgrind not found; scripts/deps.sh installs it (apt-get install valgrind)" >&2
    exit 1
fi
dir=$(mktemp -d) || exit 1
trap 'rm -rf "$dir"' EXIT
fail=0
# memcheck WHAT ENVELOPE-OPTIONS...: tirenv envelope under valgrind, one line of TAP.
memcheck() {
    what=$1
    shift
    valgrind --error-exitcode=9 -q "$bin" envelope "$@" --jobs 1 -o "$dir/out.csv" 2>"$dir/err"
    rc=$?
    if [ $rc -ne 0 ] || grep -q "uninitialised\|Invalid read\|Invalid write" "$dir/err"; then
        echo "not ok - $what under memcheck: exit $rc" >&2
        head -n 30 "$dir/err" >&2
        fail=1
    else
        echo "ok - $what under memcheck: no error"
    fi
}
# Case R's cleat and contact length, as the Python module's test sweeps it.
for model in ring springs; do
    memcheck "$model over case R's cleat" --model $model --cleat 0.1,0.1 --contact-length 0.28 \
        --x-from -0.75 --x-to 0.75 --dx 0.005
done
# The ring by Brent's method at one position: its bracket of the flat ground's load takes the
# centre inside the ground, where ring_ground.c compared the pieces' lines it had not cast.
memcheck "ring by Brent's method (the centre inside the ground)" --model ring --method brent \
    --cleat 0.1,0.1 --contact-length 0.28 --x-from 0 --x-to 0 --dx 0.1
exit $fail

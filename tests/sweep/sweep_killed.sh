#!/bin/sh
# tirenv sweep killed while it writes (kill -9, the ring on the virtual rig: about a quarter
# second a case), then the same command: it keeps what was written and finishes with the
# bytes of an uninterrupted run. Labelled slow (the sanitizer build's ring would take
# minutes). Usage: sh sweep_killed.sh BIN TESTDATA_DIR.
# SPDX-License-Identifier: Apache-2.0
# shellcheck disable=SC2016,SC2154 # conditions are single-quoted for eval; bin is clilib's
# shellcheck source=tests/lib/clilib.sh
. "$(dirname "$0")/../lib/clilib.sh"

slow='--lengths 0.1,0.2,0.3,0.15 --heights 0.05,0.1 --contact-lengths 0.3,0.35 --model ring --rig'
"$bin" sweep $slow -o whole --jobs 2 2>/dev/null
"$bin" sweep $slow -o killed --jobs 1 2>/dev/null &
pid=$!
tries=0
while [ "$(ls killed.partial/curves 2>/dev/null | wc -l)" -lt 2 ] && [ $tries -lt 600 ]; do
    sleep 0.05
    tries=$((tries + 1))
done
kill -9 "$pid" 2>/dev/null
wait "$pid" 2>/dev/null
check "a killed run leaves DIR.partial, not DIR" '[ -d killed.partial ] && [ ! -e killed ]'
run "$bin" sweep $slow -o killed --jobs 2
check "the same command resumes it, keeping the cases written" \
    '[ $rc -eq 0 ] && grep -q "kept from an interrupted run" err && ! grep -q " 0 kept" err'
check "and writes the uninterrupted bytes" 'diff -r whole killed >&2 && [ ! -e killed.partial ]'
run "$bin" sweep $slow -o killed
check "a complete sweep is not run again" '[ $rc -eq 0 ] && grep -q "nothing to do" err'

clilib_done

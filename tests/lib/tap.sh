#!/bin/sh
# What the check scripts that run commands rather than conditions share (manpages.sh and
# package/headers.sh, exports.sh, install.sh; the CLI's scripts have clilib.sh): a TAP line a
# check and the summary. Sourced:
#   . "$(dirname "$0")/../lib/tap.sh"
#   check WHAT CMD...   ...   tap_done (its status is the script's: end with it)
# SPDX-License-Identifier: Apache-2.0

n=0 failed=0

# check WHAT CMD...: one TAP line; returns CMD's status (so that "|| cat LOG" shows why).
check() {
    what=$1
    shift
    n=$((n + 1))
    if "$@"; then
        echo "ok $n - $what"
    else
        failed=$((failed + 1))
        echo "not ok $n - $what"
        return 1
    fi
}

# The summary line; fails if a check did.
tap_done() {
    echo "$((n - failed)) passed, $failed failed"
    [ "$failed" -eq 0 ]
}

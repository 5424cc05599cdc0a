#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# Sourced by python/tests/wheel.sh and python/tests/install.sh (the module installed as a
# user installs it): a scratch directory, TAP checks that show the tail of a failing
# command's output, the virtual environment that sees Debian's packages, and the summary.
#   . "$(dirname "$0")/../../tests/lib/tap_venv.sh"
#   tap_begin NAME ... check "what" CMD... ... tap_venv "what" PYTHON DIR [ARG...] ... tap_end
# tap_end's status is the script's: end with it.

# tap_begin NAME: $tmp, a fresh directory (${TMPDIR:-/tmp}/tirenv-NAME.XXXXXX) removed on exit;
# the counters at zero.
tap_begin() {
    tmp=$(mktemp -d "${TMPDIR:-/tmp}/tirenv-$1.XXXXXX") || exit 2
    trap 'rm -rf "$tmp"' EXIT
    n=0 failed=0
}

# check WHAT CMD...: runs CMD with its output in $tmp/log; one TAP line, and on failure the
# last 20 lines of the log as TAP comments.
check() {
    what=$1
    shift
    n=$((n + 1))
    if "$@" >"$tmp/log" 2>&1; then
        echo "ok $n - $what"
    else
        failed=$((failed + 1))
        echo "not ok $n - $what"
        sed 's/^/#   /' "$tmp/log" | tail -20
    fi
}

# tap_venv WHAT PYTHON DIR [ARG...]: a check that PYTHON makes a virtual environment in DIR
# that sees Debian's packages (python3-cffi, python3-numpy), with python -m venv's ARGs.
tap_venv() {
    tap_venv_what=$1 tap_venv_python=$2 tap_venv_dir=$3
    shift 3
    check "$tap_venv_what" "$tap_venv_python" -m venv --system-site-packages "$@" "$tap_venv_dir"
}

# tap_end: the plan and the count; exits non-zero if a check failed.
tap_end() {
    echo "1..$n"
    echo "$((n - failed)) passed, $failed failed"
    [ "$failed" -eq 0 ]
}

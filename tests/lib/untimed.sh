#!/bin/sh
# Sourced by tests/cli/jobs.sh and tests/study/study_killed.sh: two output trees equal apart
# from the timings they report (--jobs changes how long a command takes, never what it
# computes).
# SPDX-License-Identifier: Apache-2.0

# A report's text without what was timed: durations become T, and the lines of the timing
# tables and the speed sentences (ratios of timings) go.
untimed() {
    sed -E 's/[0-9][0-9.]*(e[-+]?[0-9]+)? ?(ns|µs|us|ms|s)([^a-zA-Z0-9]|$)/T\3/g' "$1" |
        grep -v -E '^\| [a-z]+ \| T \||Per position, measured|times as long|_time_s|took T'
}

# Two output trees equal apart from timings: timing.csv and the images skipped, reports and
# JSON through untimed, everything else byte for byte. Prints the first difference. The texts
# compared go to temporary files of their own: tests that run at once share a working
# directory (two studies once compared each other's reports there).
same_apart_from_timings() {
    ok=0
    ta=$(mktemp) tb=$(mktemp)
    for f in $(cd "$1" && find . -type f | sort); do
        case $f in
        */timing.csv | *.png | *.svg) continue ;;
        *.md | *.json | *.txt)
            untimed "$1/$f" >"$ta"
            untimed "$2/$f" >"$tb"
            if ! cmp -s "$ta" "$tb"; then
                echo "# $f differs beyond timings:"
                diff "$ta" "$tb" | head -n 6 | sed 's/^/#   /'
                ok=1
            fi
            ;;
        *)
            if ! cmp -s "$1/$f" "$2/$f"; then
                echo "# $f differs"
                ok=1
            fi
            ;;
        esac
    done
    rm -f "$ta" "$tb"
    [ "$(cd "$1" && find . -type f ! -name '*.png' ! -name '*.svg' | sort)" = \
      "$(cd "$2" && find . -type f ! -name '*.png' ! -name '*.svg' | sort)" ] || {
        echo "# the two runs wrote different files"
        ok=1
    }
    return $ok
}


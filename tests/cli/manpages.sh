#!/bin/sh
# The man pages the build writes from the --help texts (scripts/manpages.sh): one per command
# that 'tirenv --help' lists, each with the sections a man page has, every long option of the
# command's --help in it, and groff formats each without a warning (-ww: all of them).
#   sh tests/cli/manpages.sh BIN MANDIR
# SPDX-License-Identifier: Apache-2.0
set -u
bin=$1 dir=$2
# shellcheck source=tests/lib/tap.sh
. "$(dirname "$0")/../lib/tap.sh"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

commands=$("$bin" --help | awk '/^commands:$/ { on = 1; next } on && /^$/ { exit }
                                on && $1 != "help" { print $1 }')
check "tirenv --help lists commands" test -n "$commands"
for c in "" $commands; do
    page=$dir/tirenv${c:+-$c}.1
    name=tirenv${c:+-$c}
    check "$name.1 exists" test -s "$page" || continue
    for s in NAME SYNOPSIS DESCRIPTION "SEE ALSO"; do
        check "$name.1 has a $s section" grep -q "^\.SH \"\?$s\"\?$" "$page"
    done
    check "$name.1: .TH $name 1" grep -q "^\.TH $(echo "$name" | tr a-z A-Z) 1 " "$page"
    check "$name.1: NAME says '$name \\- ...'" grep -q "^$name \\\\- ." "$page"
    if [ -n "$c" ]; then
        check "$name.1 has an OPTIONS section" grep -q '^\.SH OPTIONS$' "$page"
        # Every --option of the help text, with its dashes as \- in roff (one awk: the page's
        # options with \- read back as -, then the help's looked up in them).
        "$bin" "$c" --help >"$tmp/help"
        missing=$(awk '
            FNR == NR { gsub(/\\-/, "-"); s = $0
                        while (match(s, /--[a-z][a-z-]*/)) {
                            seen[substr(s, RSTART, RLENGTH)] = 1; s = substr(s, RSTART + RLENGTH) }
                        next }
            { s = $0
              while (match(s, /--[a-z][a-z-]*/)) {
                  o = substr(s, RSTART, RLENGTH); s = substr(s, RSTART + RLENGTH)
                  if (!(o in seen) && !(o in told)) { told[o] = 1; printf " %s", o } } }
        ' "$page" "$tmp/help")
        check "$name.1 names every option of 'tirenv $c --help'${missing:+ (missing:$missing)}" \
            test -z "$missing"
    fi
    groff -man -Tutf8 -ww -z "$page" >"$tmp/groff" 2>&1
    check "groff -man -ww formats $name.1 without a warning" \
        sh -c "test $? -eq 0 && test ! -s '$tmp/groff'" || sed 's/^/#   /' "$tmp/groff"
done
tap_done

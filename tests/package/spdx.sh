#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# Every source file the licence script covers (scripts/spdx.sh --list: C, headers, CMake,
# scripts, Python, build files) carries exactly one SPDX-License-Identifier line, and it says
# Apache-2.0; the script finds nothing to change (it is idempotent); and the licence text and
# the notice are there.
#   sh tests/package/spdx.sh SOURCE_DIR
set -u
src=$1
n=0 fail=0
ok() { n=$((n + 1)); echo "ok $n - $1"; }
bad() { n=$((n + 1)); fail=1; echo "not ok $n - $1"; }

list=$(sh "$src/scripts/spdx.sh" --list "$src")
count=$(echo "$list" | grep -c .)
[ "$count" -gt 300 ] && ok "the script covers $count files" || bad "the script covers only $count files"
# The files whose identifiers (the word after each one, on its line or the next where a
# comment wrapped it) are not exactly one Apache-2.0; one perl for all files.
# shellcheck disable=SC2086
wrong=$(cd "$src" && perl -e 'for my $f (@ARGV) {
    open(my $h, "<", $f) or die "$f: $!\n";
    my $t = do { local $/; <$h> };
    my @i = $t =~ /SPDX-License-Identifier:[ \t]*(?:\n[ \t]*\*?[ \t]*)?([A-Za-z0-9.+-]+)/g;
    print " $f" unless "@i" eq "Apache-2.0";
}' $list) || wrong="$wrong (perl failed)"
[ -z "$wrong" ] && ok "every covered file has one SPDX line, Apache-2.0" ||
    bad "files without exactly one Apache-2.0 SPDX line:$(echo "$wrong" | tr ' ' '\n' | head -n 20 | tr '\n' ' ')"
if out=$(sh "$src/scripts/spdx.sh" --check "$src"); then
    ok "scripts/spdx.sh --check: nothing to change"
else
    bad "scripts/spdx.sh --check would change: $(echo "$out" | head -n 5 | tr '\n' ' ')"
fi
grep -q 'Apache License' "$src/LICENSE" && grep -q 'Version 2.0, January 2004' "$src/LICENSE" &&
    grep -q 'END OF TERMS AND CONDITIONS' "$src/LICENSE" && ok "LICENSE: the Apache-2.0 text, whole" ||
    bad "LICENSE is not the Apache-2.0 text"
grep -q 'Argonne National Laboratory' "$src/NOTICE" && ok "NOTICE: Minpack's acknowledgement" ||
    bad "NOTICE lacks Minpack's acknowledgement"
cmp -s "$src/LICENSE" "$src/python/LICENSE" && cmp -s "$src/NOTICE" "$src/python/NOTICE" &&
    ok "python/LICENSE and python/NOTICE (the wheel's copies) are the repository's" ||
    bad "python/LICENSE or python/NOTICE differ from the repository's"
exit $fail

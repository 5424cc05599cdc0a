#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# Gives every source file of the repository (C, headers, CMake, scripts, Python, build files)
# an SPDX line naming Apache-2.0: turns the GPL-3.0-or-later identifier of version 0.1 into
# it, and adds the line, as the file's first comment (after a #! line), where
# a file has none. Idempotent: a second run changes nothing. Files the project vendors from
# elsewhere (tests/third_party/, tests/data/, tests/fuzz/corpus/, data/) keep their own.
#   sh scripts/spdx.sh [--check | --list] [ROOT]
# --check: change nothing, list the files that would change, exit 1 if any; --list: print
# the files it covers. ROOT defaults to the repository holding this script.
set -eu
mode=apply
case "${1:-}" in
    --check) mode=check; shift ;;
    --list) mode=list; shift ;;
esac
root=${1:-$(cd "$(dirname "$0")/.." && pwd)}
cd "$root"
tag=SPDX-License-Identifier
id="$tag: Apache-2.0"

files() {
    if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
        git ls-files
    else
        find . -type f ! -path './.git/*' | sed 's|^\./||'
    fi | grep -E '(\.(c|h|sh|py|cmake|in|sbatch|gp|toml)|(^|/)CMakeLists\.txt|(^|/)Makefile|^\.ci/run)$' |
        grep -Ev '^(tests/third_party/|tests/data/|tests/fuzz/corpus/|data/)' | LC_ALL=C sort
}

# The comment that carries the line, by the file's kind.
line_for() {
    case "$1" in
        *.c | *.h | *.h.in) echo "/* $id */" ;;
        *) echo "# $id" ;;
    esac
}

# The identifiers each file states, one line per file: "FILE<tab>ID ID ..." (nothing after
# the tab where it states none): the word after each SPDX tag and its colon, on its line or,
# where a comment wrapped it, at the start of the next (after " * "). One perl for all files.
ids_of() {
    perl -e 'for my $f (@ARGV) {
        open(my $h, "<", $f) or die "$f: $!\n";
        my $t = do { local $/; <$h> };
        my @i = $t =~ /SPDX-License-Identifier:[ \t]*(?:\n[ \t]*\*?[ \t]*)?([A-Za-z0-9.+-]+)/g;
        print "$f\t@i\n";
    }' "$@"
}

present() {
    for f in $(files); do
        [ -f "$f" ] && echo "$f"
    done
}

if [ "$mode" = list ]; then
    present
    exit 0
fi
tab=$(printf '\t')
changed=0
# shellcheck disable=SC2046
all=$(ids_of $(present))
while IFS=$tab read -r f ids; do
    [ -n "$f" ] || continue
    case "$ids" in
        Apache-2.0) continue ;;
        *GPL-3.0-or-later* | "") ;;
        *) continue ;;  # another licence: a file of someone else's, kept as it is
    esac
    changed=1
    if [ "$mode" = check ]; then
        echo "$f"
        continue
    fi
    tmp="$f.spdx.$$"
    if [ -n "$ids" ]; then
        perl -0pe 's/(SPDX-License-Identifier:[ \t]*(?:\n[ \t]*\*?[ \t]*)?)GPL-3\.0-or-later/${1}Apache-2.0/g' "$f" >"$tmp"
    elif head -n 1 "$f" | grep -q '^#!'; then
        { head -n 1 "$f"; line_for "$f"; tail -n +2 "$f"; } >"$tmp"
    else
        { line_for "$f"; cat "$f"; } >"$tmp"
    fi
    chmod --reference="$f" "$tmp" 2>/dev/null || true
    mv "$tmp" "$f"
done <<EOF
$all
EOF
[ "$mode" = check ] && [ "$changed" -eq 1 ] && exit 1
exit 0

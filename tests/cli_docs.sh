#!/bin/sh
# The documentation a user has is the repository's: every "docs/models.md section N" and
# "docs/formats.md section N" cited by the README, headers, sources, help texts, data files and
# tests names a section that exists, and nothing points outside the repository (../shared,
# MODEL.md) or at issue numbers. Usage: sh cli_docs.sh BIN TESTDATA_DIR.
# SPDX-License-Identifier: GPL-3.0-or-later
# shellcheck disable=SC2016,SC2154 # conditions are single-quoted for eval; bin is clilib's
root=$(cd "$(dirname "$0")/.." && pwd)
# shellcheck source=tests/clilib.sh
. "$(dirname "$0")/clilib.sh"

models=$root/docs/models.md
formats=$root/docs/formats.md

run test -f "$models"
check "docs/models.md exists" '[ $rc -eq 0 ]'
run test -f "$formats"
check "docs/formats.md exists" '[ $rc -eq 0 ]'

# The files that cite the documentation.
find "$root/README.md" "$root/include" "$root/src" "$root/bench" "$root/tests" \
    "$root/data/tires" "$root/data/vehicles" "$root/data/dataset/README.md" -type f \
    \( -name '*.[ch]' -o -name '*.md' -o -name '*.tir' -o -name '*.veh' -o -name '*.sh' \) \
    -print | sort >files

# Every citation, with the line breaks of comments and C strings joined, as "FILE: models 7.6".
: >citations
while read -r f; do
    tr '\n' ' ' <"$f" |
        sed 's/\\n"[[:space:]]*"/ /g; s/! : COMMENT :/ /g; s/ \* / /g; s/ [$!#] / /g' |
        tr -s ' ' |
        grep -o 'docs/\(models\|formats\)\.md,\{0,1\} sections\{0,1\} [0-9][0-9.]*\( and [0-9][0-9.]*\)\{0,1\}' |
        sed 's|docs/\([a-z]*\)\.md,\{0,1\} sections\{0,1\} |\1 |; s/ and / /; s/\.$//; s/\. / /' |
        while read -r doc a b; do
            echo "${f#"$root"/}: $doc $a"
            [ -n "$b" ] && echo "${f#"$root"/}: $doc ${b%.}"
        done >>citations
done <files
check "more than 100 citations found (the scan is not vacuous)" '[ "$(wc -l <citations)" -gt 100 ]'

# "## N. Title" for a section, "### N.M Title" for a subsection.
: >missing
while read -r where doc num; do
    file=$models
    [ "$doc" = formats ] && file=$formats
    case $num in
    *.*) pattern="^### $num " ;;
    *) pattern="^## $num\\. " ;;
    esac
    grep -q "$pattern" "$file" || echo "$where cites docs/$doc.md section $num" >>missing
done <citations
cp missing err
check "every cited section exists in docs/ ($(wc -l <citations) citations)" '[ ! -s missing ]'

# A bare "models.md" in the code is a citation that lost its path.
: >bare
while read -r f; do
    case $f in "$root"/tests/*) continue ;; esac
    grep -n 'models\.md\|formats\.md' "$f" | grep -v 'docs/\(models\|formats\)\.md' |
        sed "s|^|${f#"$root"/}:|" >>bare
done <files
cp bare err
check "no citation without its docs/ path" '[ ! -s bare ]'

# Nothing a user has points outside the repository or at issues.
grep -rn 'shared/\|MODEL\.md\|issue [0-9]' "$root/README.md" "$root/docs" "$root/include" \
    "$root/src" "$root/data" >outside
cp outside err
check "README, docs, include, src, data point at nothing outside the repository" \
    '[ ! -s outside ]'

# Relative links of the documentation lead to files that exist.
: >links
for md in "$root/README.md" "$root"/docs/*.md; do
    dir=$(dirname "$md")
    grep -o '](\([^)#:]*\))' "$md" | sed 's/^](//; s/)$//' | while read -r target; do
        [ -z "$target" ] || [ -e "$dir/$target" ] || echo "${md#"$root"/}: $target" >>links
    done
done
cp links err
check "relative links in README.md and docs/ exist" '[ ! -s links ]'

# The help texts that cite the documentation say so in the built program too.
run "$bin" ride --help
check "tirenv ride --help cites docs/models.md sections 9 and 10" \
    '[ $rc -eq 0 ] && grep -q "docs/models.md sections 9 and 10" out'

clilib_done

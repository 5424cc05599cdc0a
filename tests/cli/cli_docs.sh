#!/bin/sh
# The documentation a user has is the repository's: every "docs/models.md section N" and
# "docs/formats.md section N" cited by the README, headers, sources, help texts, data files and
# tests names a section that exists, and nothing points outside the repository (a folder
# beside the clone, MODEL.md) or at issue numbers; no file of the repository reads a folder
# beside the clone (tests/data/samples/README.md: a test passes in any clone); the paths and
# tirenv_ names the Markdown writes exist; every command's --help lists the options it takes.
# Usage: sh cli_docs.sh BIN TESTDATA_DIR.
# SPDX-License-Identifier: Apache-2.0
# shellcheck disable=SC2016,SC2154 # conditions are single-quoted for eval; bin is clilib's
root=$(cd "$(dirname "$0")/../.." && pwd)
# shellcheck source=tests/lib/clilib.sh
. "$(dirname "$0")/../lib/clilib.sh"

models=$root/docs/models.md
formats=$root/docs/formats.md

run test -f "$models"
check "docs/models.md exists" '[ $rc -eq 0 ]'
run test -f "$formats"
check "docs/formats.md exists" '[ $rc -eq 0 ]'

# The files that cite the documentation.
find "$root/README.md" "$root/include" "$root/src" "$root/bench" "$root/tests" \
    "$root/data/tires" "$root/data/vehicles" "$root/data/dataset/README.md" \
    "$root/data/dataset-205-60R15/README.md" -type f \
    \( -name '*.[ch]' -o -name '*.md' -o -name '*.tir' -o -name '*.veh' -o -name '*.sh' \) \
    -print | sort >files

# Every citation, with the line breaks of comments and C strings joined, as "FILE: models 7.6".
# One awk over all files: a shell loop per file costs a fork per tool and file. The list goes
# through xargs -0: the clone's own path may have blanks.
tr '\n' '\0' <files | xargs -0 awk -v root="$root/" '
function flush(   t, m, doc, nums, k, parts) {
    if (name == "")
        return
    t = text
    gsub(/\\n"[[:space:]]*"/, " ", t)
    gsub(/! : COMMENT :/, " ", t)
    gsub(/ \* /, " ", t)
    gsub(/ [$!#] /, " ", t)
    gsub(/[[:space:]]+/, " ", t)
    while (match(t, /docs\/(models|formats)\.md,? sections? [0-9][0-9.]*( and [0-9][0-9.]*)?/)) {
        m = substr(t, RSTART, RLENGTH)
        t = substr(t, RSTART + RLENGTH)
        doc = m ~ /^docs\/models/ ? "models" : "formats"
        sub(/^docs\/[a-z]*\.md,? sections? /, "", m)
        k = split(m, parts, / and /)
        for (i = 1; i <= k; i++) {
            sub(/\.$/, "", parts[i])
            print name ": " doc " " parts[i]
        }
    }
}
FNR == 1 { flush(); name = substr(FILENAME, length(root) + 1); text = "" }
{ text = text " " $0 }
END { flush() }' >citations
check "more than 100 citations found (the scan is not vacuous)" '[ "$(wc -l <citations)" -gt 100 ]'

# "## N. Title" for a section, "### N.M Title" for a subsection.
awk '
FILENAME == ARGV[1] && /^## [0-9]+\. / { sub(/\.$/, "", $2); have["models " $2] = 1 }
FILENAME == ARGV[1] && /^### [0-9]+\.[0-9]+ / { have["models " $2] = 1 }
FILENAME == ARGV[2] && /^## [0-9]+\. / { sub(/\.$/, "", $2); have["formats " $2] = 1 }
FILENAME == ARGV[3] && !(($2 " " $3) in have) { print $1 " cites docs/" $2 ".md section " $3 }
' "$models" "$formats" citations >missing
cp missing err
check "every cited section exists in docs/ ($(wc -l <citations) citations)" '[ ! -s missing ]'

# A bare "models.md" in the code is a citation that lost its path.
grep -v "^$root/tests/" files | tr '\n' '\0' | xargs -0 grep -n 'models\.md\|formats\.md' |
    grep -v 'docs/\(models\|formats\)\.md' >bare
cp bare err
check "no citation without its docs/ path" '[ ! -s bare ]'

# Nothing a user has points outside the repository or at issues.
grep -rn 'shared/\|MODEL\.md\|issue [0-9]' "$root/README.md" "$root/docs" "$root/include" \
    "$root/src" "$root/data" >outside
cp outside err
check "README, docs, include, src, data point at nothing outside the repository" \
    '[ ! -s outside ]'

# No test, script or build file reads the folder beside the clone that the developers' machines
# once had: what the tests need is under tests/data.
grep -rn --exclude-dir=.git '\.\./shared' "$root/README.md" "$root/Makefile" \
    "$root/CMakeLists.txt" "$root/cmake" "$root/docs" "$root/include" "$root/src" \
    "$root/data" "$root/tests" "$root/scripts" "$root/bench" "$root/python" "$root/fmu" >beside
cp beside err
check "no file of the repository reads a folder beside the clone" '[ ! -s beside ]'

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

# The Markdown a user reads: the README, docs/ and the READMEs of python/, fmu/ and the data.
ls "$root/README.md" "$root"/docs/*.md "$root"/python/README.md "$root"/fmu/README.md \
    "$root"/data/*/README.md | tr '\n' '\0' >mds

# Every repository path they name (src/model/springs.c, include/tirenv/ride.h, tests/..., a
# directory such as src/train/) exists, from the top or from the file's own directory; a
# pattern (tests/cli_*.sh) is not a path.
xargs -0 awk -v root="$root/" '
{
    s = $0
    while (match(s, /(^|[^A-Za-z0-9_.\/-])(src|include|tests|scripts|bench|data|python|fmu|cmake|docs)\/[A-Za-z0-9_.\/-]*/)) {
        p = substr(s, RSTART, RLENGTH)
        s = substr(s, RSTART + RLENGTH)
        if (s ~ /^[*<{$]/)
            continue
        sub(/^[^a-z]/, "", p)
        sub(/[.]+$/, "", p)
        print substr(FILENAME, length(root) + 1) " " p
    }
}' <mds >paths
: >stale
while read -r md path; do
    [ -e "$root/$path" ] || [ -e "$root/$(dirname "$md")/$path" ] || echo "$md: $path" >>stale
done <paths
cp stale err
check "every repository path the Markdown names exists ($(wc -l <paths) paths)" \
    '[ "$(wc -l <paths)" -gt 100 ] && [ ! -s stale ]'

# Every tirenv_ name they write (tirenv_model_alloc, `tirenv_ride_run()`, tirenv_tire) is in
# the code of include/, src/, python/ or fmu/, comments left out: a function, type or macro
# that was renamed or removed is found. CMake's tirenv::NAME targets are not C names.
find "$root/include" "$root/src" "$root/python" "$root/fmu" -type f \
    \( -name '*.[ch]' -o -name '*.py' \) -print | sort >code_files
tr '\n' '\0' <code_files | xargs -0 awk '
FNR == 1 { incomment = 0 }
{
    line = $0
    out = ""
    while (line != "") {
        if (incomment) {
            i = index(line, "*/")
            if (!i)
                break
            line = substr(line, i + 2)
            incomment = 0
        } else {
            i = index(line, "/*")
            if (!i) {
                out = out line
                break
            }
            out = out substr(line, 1, i - 1)
            line = substr(line, i + 2)
            incomment = 1
        }
    }
    sub(/\/\/.*/, "", out)
    while (match(out, /tirenv_[A-Za-z0-9_]+/)) {
        print substr(out, RSTART, RLENGTH)
        out = substr(out, RSTART + RLENGTH)
    }
}' | sort -u >code_names
xargs -0 awk -v root="$root/" '
{
    s = $0
    while (match(s, /(^|[^:A-Za-z0-9_])tirenv_[A-Za-z0-9_]*[A-Za-z0-9]/)) {
        n = substr(s, RSTART, RLENGTH)
        s = substr(s, RSTART + RLENGTH)
        if (s ~ /^[*_]/)  # a family (tirenv_model_*), not a name
            continue
        sub(/^[^t]/, "", n)
        print n " " substr(FILENAME, length(root) + 1)
    }
}' <mds | sort -u >doc_names
awk 'FILENAME == ARGV[1] { have[$1] = 1; next } !($1 in have) { print }' code_names doc_names \
    >unknown
cp unknown err
check "every tirenv_ name in the Markdown is in the code ($(cut -d" " -f1 doc_names | sort -u | wc -l) names)" \
    '[ "$(wc -l <doc_names)" -gt 50 ] && [ ! -s unknown ]'

# Every command's --help lists every long option the command accepts: the parser compares
# them itself when it prints the help (src/cli/parse.c) and names what is missing on stderr.
commands=$("$bin" --help | awk '/^commands:$/ { on = 1; next } on && /^$/ { exit }
                                on && $1 != "help" { print $1 }')
: >unlisted
for c in $commands; do
    "$bin" "$c" --help >/dev/null 2>>unlisted || echo "$c --help: exit status $?" >>unlisted
done
cp unlisted err
check "every command's --help lists all its long options ($(echo "$commands" | wc -w) commands)" \
    '[ -n "$commands" ] && [ ! -s unlisted ]'
# ... and its usage synopsis (the lines before the first blank one) names every long option the
# options list describes, but the obstacles (OBSTACLE there), --output (-o) and --help: a user
# reads the synopsis first (envelope's lacked --jobs, --detail and --crg-nan-mode).
: >unsummarised
for c in $commands; do
    "$bin" "$c" --help 2>/dev/null | awk -v c="$c" '
        !body && /^$/ { body = 1; next }
        !body { syn = syn " " $0; next }
        !/^[ ][ ][ ]?[ ]?(-[a-z], )?--[a-z]/ { next }
        {
            line = $0
            sub(/^ *(-[a-z], )?/, ", ", line)
            while (match(line, /, --[a-z0-9-]+/)) {
                name = substr(line, RSTART + 4, RLENGTH - 4)
                line = substr(line, RSTART + RLENGTH)
                if (name !~ /^(help|output|cleat|step|trapezoid|triangle|cylinder|sine|profile)$/ &&
                    syn !~ ("--" name "([^a-z0-9-]|$)"))
                    print c ": the synopsis lacks --" name
            }
        }' >>unsummarised
done
cp unsummarised err
check "every command's usage synopsis names all its options but the obstacles, -o and --help" \
    '[ ! -s unsummarised ]'
# The commands that read a data set take its own tire by default, and their --tire says so
# (it said tires/default.tir, as for the others; train's, "the default tire").
for c in compare study fit train; do
    run "$bin" "$c" --help
    check "tirenv $c --help: --tire defaults to the tire the data set's source.txt names" \
        '[ $rc -eq 0 ] && grep -A1 "^  --tire FILE" out | grep -q "source.txt names"'
done
run "$bin" dataset --help
check "tirenv dataset --help: --tire defaults to the design's" \
    '[ $rc -eq 0 ] && grep -q "^  --tire FILE  .*default: the design.s" out'
run "$bin" predict --help
check "tirenv predict --help lists --model, which it takes" \
    '[ $rc -eq 0 ] && grep -q "^  --model NAME  " out'

# The help texts that cite the documentation say so in the built program too.
run "$bin" ride --help
check "tirenv ride --help cites docs/models.md sections 9 and 10" \
    '[ $rc -eq 0 ] && grep -q "docs/models.md sections 9 and 10" out'

clilib_done

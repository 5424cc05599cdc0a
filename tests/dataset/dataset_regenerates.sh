#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# A shipped data set equals a fresh regeneration (its README.md apart, which a person writes),
# run serially (--jobs 1) and on three threads (--jobs 3): the bytes do not depend on the
# number of jobs. tests/dataset/dataset_regenerates.sh BIN SHIPPED_DIR [DESIGN].
#
# Byte for byte on a machine whose libm takes the paths of the one that made the data set.
# glibc picks its sin, cos, exp, log, ... by the processor (x86-64 without FMA and AVX2 takes
# others), and those may round a last bit differently: there the imported curves moved by up
# to 2.5e-11 m (glibc 2.36 with GLIBC_TUNABLES=glibc.cpu.hwcaps=-AVX2,-FMA), and `make test`
# must pass on such a machine too. So a file whose bytes differ passes when it has the same
# lines, the same text, and every number within TOL (1e-9, times the number where it exceeds
# 1): forty times that spread, and far below any change a model makes (a change of a
# model, its tire or the rig moves the curves by micrometres at least). The TAP line says
# which: "the same bytes" or "the same numbers".
set -eu
bin=$1 shipped=$2 design=${3:-}
tol=1e-9
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
pass=0 fail=0 n=0

# numbers_equal A B: the same lines and fields, text equal, numbers within tol; prints the
# largest difference.
numbers_equal() {
    awk -F, -v tol="$tol" '
        function num(s) { return s ~ /^[-+]?([0-9]+\.?[0-9]*|\.[0-9]+)([eE][-+]?[0-9]+)?$/ }
        function abs(v) { return v < 0 ? -v : v }
        NR == FNR { line[FNR] = $0; n_a = FNR; next }
        {
            if (FNR > n_a) { bad = 1; exit }
            na = split(line[FNR], a, ","); nb = split($0, b, ",")
            if (na != nb) { bad = 1; exit }
            for (i = 1; i <= na; ++i) {
                if (a[i] == b[i]) continue
                if (!num(a[i]) || !num(b[i])) { bad = 1; exit }
                d = abs(a[i] - b[i]); s = abs(a[i]) > 1 ? abs(a[i]) : 1
                if (d > tol * s) { bad = 1; exit }
                if (d > worst) worst = d
            }
            n_b = FNR
        }
        END { if (bad || n_b != n_a) exit 1; printf "%.3g\n", worst }' "$1" "$2"
}

for jobs in 1 3; do
    n=$((n + 1))
    fresh=$tmp/dataset-$jobs
    "$bin" dataset build ${design:+--design "$design"} --jobs "$jobs" -o "$fresh" 2>/dev/null
    what="$(basename "$shipped") equals a fresh 'tirenv dataset build${design:+ --design $design} --jobs $jobs'"
    if diff -r -x README.md "$shipped" "$fresh" >"$tmp/diff"; then
        pass=$((pass + 1))
        echo "ok $n - $what: the same bytes"
        continue
    fi
    # The same files, then each differing one's numbers.
    ok=1 worst=0 files=0
    (cd "$shipped" && find . -type f ! -name README.md | sort) >"$tmp/a.list"
    (cd "$fresh" && find . -type f ! -name README.md | sort) >"$tmp/b.list"
    cmp -s "$tmp/a.list" "$tmp/b.list" || ok=0
    if [ $ok -eq 1 ]; then
        while read -r f; do
            cmp -s "$shipped/$f" "$fresh/$f" && continue
            files=$((files + 1))
            if ! d=$(numbers_equal "$shipped/$f" "$fresh/$f"); then
                ok=0
                echo "# $f: not the same numbers within $tol"
                break
            fi
            worst=$(awk -v a="$worst" -v b="$d" 'BEGIN { print (b + 0 > a + 0) ? b : a }')
        done <"$tmp/a.list"
    fi
    if [ $ok -eq 1 ]; then
        pass=$((pass + 1))
        echo "ok $n - $what: the same numbers (files differing in their last digits: $files, by at most $worst; this libm rounds differently)"
    else
        fail=$((fail + 1))
        sed 's/^/# /' "$tmp/diff" | head -20
        echo "not ok $n - $what"
    fi
done
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]

#!/bin/sh
# The FMU's package: the zip holds what FMI 2.0 section 2.3 asks of a linux64 co-simulation
# FMU, modelDescription.xml is well-formed XML (xmllint), and the binary is self-contained
# (ldd: libc and libm only, no GSL, cminpack, jansson or libtirenv) and exports the fmi2 functions only.
# In a sanitizer build (second argument 1) the sanitizers' runtimes are allowed besides.
# usage: fmu_package.sh FMU [SANITIZED]        SPDX-License-Identifier: Apache-2.0
set -u
fmu=$1
sanitized=${2:-0}
allowed="linux-vdso|ld-linux|libc\.so|libm\.so"
[ "$sanitized" = 1 ] && allowed="$allowed|libasan|libubsan|libgcc_s|libstdc\+\+"

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
n=0
failed=0
check() {
    n=$((n + 1))
    if eval "$2"; then echo "ok $n - $1"; else failed=$((failed + 1)); echo "not ok $n - $1"; fi
}
unzip -q "$fmu" -d "$work" || { echo "not ok 1 - unzip $fmu"; exit 1; }
so=$work/binaries/linux64/tirenv_effective_road.so
check "the zip holds modelDescription.xml, the linux64 binary and the resources" \
    '[ -f "$work/modelDescription.xml" ] && [ -f "$so" ] && [ -f "$work/resources/default.tir" ] && [ -f "$work/resources/road.csv" ]'
check "modelDescription.xml is well-formed XML (xmllint)" \
    'xmllint --noout "$work/modelDescription.xml"'
check "its modelIdentifier names the binary" \
    'grep -q "modelIdentifier=\"tirenv_effective_road\"" "$work/modelDescription.xml"'
ldd "$so" >"$work/ldd" 2>&1
check "the binary needs only libc and libm (ldd: $(awk '{print $1}' "$work/ldd" | tr '\n' ' '))" \
    '! grep -Eq "libgsl|libjansson|libtirenv|libcblas|libcminpack|not found" "$work/ldd" && [ "$(grep -Evc "$allowed" "$work/ldd")" -eq 0 ]'
nm -D --defined-only "$so" | awk '{print $3}' >"$work/exports"
check "it exports the 34 fmi2 functions of co-simulation and nothing else ($(wc -l <"$work/exports") symbols)" \
    '[ "$(grep -c "^fmi2" "$work/exports")" -eq 34 ] && ! grep -qv "^fmi2" "$work/exports"'
echo "1..$n"
echo "$((n - failed)) passed, $failed failed"
[ "$failed" -eq 0 ]

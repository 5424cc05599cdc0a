#!/bin/sh
# Real MF-Tyre / PAC2002 .tir files through the CLI: every sample loads and 'tirenv flat' on it
# prints sensible numbers (the file's own radius; deflections a tire has; the cam's stiffness
# the file's VERTICAL_STIFFNESS), the cam refused without the cam keys, bad files refused.
# Usage: tests/cli/cli_tir.sh BIN TESTDATA_DIR, with TIRENV_SAMPLES naming the sample
# files (CTest sets it). SPDX-License-Identifier: Apache-2.0
# shellcheck disable=SC2016,SC2034,SC2086
. "$(dirname "$0")/../lib/clilib.sh"

samples=${TIRENV_SAMPLES:-}
if [ -z "$samples" ] || [ ! -d "$samples/tir" ]; then
    echo "not ok 1 - the sample files (TIRENV_SAMPLES='$samples') are missing"
    exit 1
fi

# flat's CSV rows: z_flat + deflection = R0, 0 < deflection < R0/5, stiffness > 0
sensible() {
    awk -F, -v r0="$2" 'NR > 1 { n++; d = $2 + $3 - r0
        if (d > 1e-8 || -d > 1e-8 || !($3 > 0 && $3 < r0 / 5) || !($5 > 0)) bad = 1 }
        END { exit bad || n != 5 }' "$1"
}

# The sanitizer build (TIRENV_TEST_SANITIZED=1) leaves out the 335/65R22.5 and the HMMWV,
# whose derivations took 8.7 of this test's 20 s of CPU there: the command's code is the same
# for every file, and test_onetire derives both files under the sanitizers too. The Release
# build runs all four.
files="335_65R22_5_G275MSA_60psi:0.4987 HMMWV_Pac02Tire:0.4699"
files="$files tractor_430_50R38:0.6731 mf_185_80R14:0.376"
if [ "${TIRENV_TEST_SANITIZED:-0}" = 1 ]; then
    files="tractor_430_50R38:0.6731 mf_185_80R14:0.376"
    echo "# sanitizer build: flat on 2 of the 4 files (the Release build: all four)"
fi
for spec in $files; do
    name=${spec%%:*}
    r0=${spec#*:}
    run "$bin" flat --csv --tire "$samples/tir/$name.tir"
    check "$name.tir loads; flat: z_flat + deflection = R0 = $r0 m, deflection < R0/5, at 0.5 to 1.5 FNOMIN; springs derived, the cam against the ring said" \
        '[ $rc -eq 0 ] && sensible out $r0 && grep -q "derived RADIAL_STIFFNESS" err &&
         grep -q "cam against ring at 0.5 to 1.5 FNOMIN, deflection up to" err'
    case $name in
    tractor_430_50R38)
        check "... its own cam contact law kept, not mixed with the ring's" \
            'grep -q "the file'"'"'s own cam contact law kept (Q_RA1 = 0.6, Q_RA2 = 0.7)" err'
        check "... its springs model, on the ring searched on those laws, with a sidewall in series, said" \
            'grep -q "derived RADIAL_STIFFNESS = [^;]*, SIDEWALL_STIFFNESS = [^;]*, SIDEWALL_PRELOAD = " err' ;;
    *)
        check "... no Q_RA1, Q_RA2 of its own: derived on the ring and said" \
            'grep -q "no Q_RA1, Q_RA2 of its own: derived on the ring Q_RA1 = " err' ;;
    esac
done

run "$bin" flat --csv --model cam --load 30000 --tire "$samples/tir/tractor_430_50R38.tir"
check "cam at FNOMIN 30 kN: the file's VERTICAL_STIFFNESS 1e6 N/m, deflection 0.03 m" \
    '[ $rc -eq 0 ] && awk -F, "NR == 2 { exit !(\$3 == 0.03 && \$5 == 1000000) }" out'
check "... its cam laws all its own, the cam alone used: the ring and springs model not derived, said" \
    'grep -q "no \[ENVELOPING_RING\]: the ring model not derived (the cam alone is used" err &&
     ! grep -q "derived TREAD_THICKNESS" err'
run "$bin" flat --model cam --tire "$samples/tir/tractor_430_50R38.tir"
check "... flat --model cam without --load: 0.5 to 1.5 FNOMIN, the file's load range (no ring to compare with)" \
    '[ $rc -eq 0 ] && grep -q "at 0.5 to 1.5 times its nominal load 30000 N" out &&
     grep -q "^ *45000.0 .* 0.04500 " out'
# The refusal is one code path for every file without the cam's shape keys, and each command
# derives the file's ring and springs model first (2.7 and 1.8 s of CPU for the 335/65R22.5
# and the HMMWV, 0.5 s for the 185/80R14): shown on the cheapest. The other two files' cam
# contact laws are derived and compared above (flat) and in tests/study/test_onetire.c.
for name in mf_185_80R14; do
    run "$bin" flat --model cam --tire "$samples/tir/$name.tir"
    check "$name.tir has no cam shape keys (its Q_RA1, Q_RA2 derived): --model cam exits 2 naming them and the file" \
        '[ $rc -eq 2 ] && grep -q "cam keys ELLIPS_SHIFT, ELLIPS_LENGTH, ELLIPS_HEIGHT, ELLIPS_ORDER " err &&
         grep -q "^tirenv: $samples/tir/$name.tir: ELLIPS_SHIFT: the tire has no value" err'
    run "$bin" envelope --model cam --cleat 0.1,0.05 --load 5000 --tire "$samples/tir/$name.tir" \
        -o e.csv
    check "... and envelope --model cam too, without an output file" \
        '[ $rc -eq 2 ] && grep -q "cam keys" err && no_file e.csv'
    run "$bin" compare --models rigid,cam --cases R --no-images --tire "$samples/tir/$name.tir" \
        -o cmp
    check "... and compare --models rigid,cam, naming the file, without a report (it compared the default tire's cam)" \
        '[ $rc -eq 2 ] && grep -q "^tirenv: $samples/tir/$name.tir: ELLIPS_SHIFT: " err && [ ! -e cmp ]'
    run "$bin" sweep --model cam --lengths 0.05 --heights 0.02 --loads 3800 \
        --tire "$samples/tir/$name.tir" -o swp
    check "... and sweep --model cam, naming the file, writing nothing (it swept the default tire's cam)" \
        '[ $rc -eq 2 ] && grep -q "^tirenv: $samples/tir/$name.tir: ELLIPS_SHIFT: " err &&
         [ ! -e swp ] && [ ! -e swp.partial ]'
    run "$bin" bench --quick --tire "$samples/tir/$name.tir"
    check "... and bench, naming the file, before any timing (it timed the default tire's cam, then stopped in the ride)" \
        '[ $rc -eq 2 ] && grep -q "^tirenv: $samples/tir/$name.tir: ELLIPS_SHIFT: " err && [ ! -s out ]'
    run "$bin" dataset build --design 205-60R15 --tire "$samples/tir/$name.tir" -o ds
    check "... and dataset build of the cam's design, naming the file, writing nothing" \
        '[ $rc -eq 2 ] && grep -q "^tirenv: $samples/tir/$name.tir: ELLIPS_SHIFT: " err && [ ! -e ds ]'
done
run "$bin" flat --model cam --tire "$samples/tir/mf_185_80R14.tir" --set Q_RA1=0.6 \
    --set Q_RA2=0.7 --set ELLIPS_SHIFT=0.8 --set ELLIPS_LENGTH=1.4 --set ELLIPS_HEIGHT=0.9 \
    --set ELLIPS_ORDER=1.6
check "--set of the missing cam keys makes the cam run" '[ $rc -eq 0 ]'
run "$bin" sweep --model cam --lengths 0.05 --heights 0.02 --loads 3800 \
    --tire "$samples/tir/mf_185_80R14.tir" --set ELLIPS_SHIFT=0.8,0.9 --set ELLIPS_LENGTH=1.4 \
    --set ELLIPS_HEIGHT=0.9 --set ELLIPS_ORDER=1.6 -o swp2
check "... and so do swept ones, in a sweep" '[ $rc -eq 0 ] && [ -f swp2/cases.csv ]'

: >empty.tir
run "$bin" flat --tire empty.tir
check "an empty .tir: exit 2, not the default tire" \
    '[ $rc -eq 2 ] && grep -q "empty.tir: the empty file sets none of the keys" err'
printf '[DIMENSION]\nUNLOADED_RADIUS = 0.7\nRADIAL_STIFFNESS = 1.6e6\n' >wrong.tir
run "$bin" flat --tire wrong.tir
check "RADIAL_STIFFNESS under [DIMENSION]: exit 2 naming both sections" \
    '[ $rc -eq 2 ] && grep -q "wrong.tir:3:1: RADIAL_STIFFNESS: key of \[ENVELOPING_SPRINGS\] in \[DIMENSION\]" err'
printf '[UNITS]\nLENGTH = '"'mm'"'\n[DIMENSION]\nUNLOADED_RADIUS = 680\n' >mm.tir
run "$bin" flat --csv --tire mm.tir
check "a file with UNLOADED_RADIUS alone: the springs model is not derived, exit 2 naming FNOMIN" \
    '[ $rc -eq 2 ] && grep -q "FNOMIN" err'
# VERTICAL_STIFFNESS in N/mm: 296 N/mm is 296 kN/m. Q_FZ2 = 0, a linear law of the file's
# own, keeps the deflection at FNOMIN 17700/296000 m (without it Q_FZ2 is derived on the ring,
# docs/models.md 14.2).
printf '[UNITS]\nLENGTH = '"'mm'"'\n[DIMENSION]\nUNLOADED_RADIUS = 680\n[VERTICAL]\nFNOMIN = 17700\nVERTICAL_STIFFNESS = 296\nQ_FZ2 = 0\n' >mm.tir
run "$bin" flat --csv --tire mm.tir --load 17700
check "LENGTH = 'mm': UNLOADED_RADIUS 680 mm is 0.68 m, VERTICAL_STIFFNESS 296 N/mm is 296 kN/m" \
    '[ $rc -eq 0 ] && awk -F, "NR == 2 { d = \$2 + \$3 - 0.68; exit !(d < 1e-9 && -d < 1e-9 && \$3 > 0.0597 && \$3 < 0.0599) }" out'

clilib_done

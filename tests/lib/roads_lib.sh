#!/bin/sh
# What tests/cli/cli_roads.sh and tests/cli/cli_roads_grade.sh share: the sample files, a measured-like
# OpenCRG road of their own, and the check that a road file gives the same curves as its track
# converted to CSV. Sourced after clilib.sh. SPDX-License-Identifier: Apache-2.0
# shellcheck disable=SC2016,SC2034,SC2086,SC2154

samples=${TIRENV_SAMPLES:-}
if [ -z "$samples" ] || [ ! -f "$samples/crg/Horstwalde.crg" ]; then
    echo "not ok 1 - the sample files (TIRENV_SAMPLES='$samples') are missing"
    exit 1
fi
crg=$samples/crg
rdf=$samples/rdf
lc='--contact-length 0.33'

# make_measured ELEVATION FILE [straight]: a measured-like OpenCRG road (LDFI text), 40 m on a
# 1 cm grid, a curved reference line (heading 0.015 rad per m; with "straight", none: a straight
# line from x = 7, y = -3 m at heading 0.4 rad), 9 long sections over 4 m at the height
# ELEVATION (REFERENCE_LINE_START_Z), an empty $ROAD_CRG_MODS section (placed as the header
# says, not by OpenCRG's default modifiers), roughness of a few mm that differs across (two waves and
# seeded noise), a 5 cm cleat under the left half at u = 12 m and a 3 cm pothole at 20 m.
make_measured() {
    awk -v elev="$1" -v straight="${3:-}" 'function rec(vals, n,   i, line) {
            line = ""
            for (i = 1; i <= n; i++) {
                line = line vals[i]
                if (i % 4 == 0 || i == n) { print line; line = "" }
            }
        }
        BEGIN {
            nv = 9; nu = 4001; du = 0.01; pi = 3.14159265358979
            print "$CT"
            print "A measured-like road for the tirenv tests: 40 m, 1 cm grid, curved"
            print "$ROAD_CRG"
            print "REFERENCE_LINE_START_U   = 0"
            print "REFERENCE_LINE_END_U     = 40"
            print "REFERENCE_LINE_INCREMENT = 0.01"
            printf "REFERENCE_LINE_START_Z   = %s\n", elev
            if (straight) {
                print "REFERENCE_LINE_START_X   = 7"
                print "REFERENCE_LINE_START_Y   = -3"
                print "REFERENCE_LINE_START_PHI = 0.4"
            }
            print "LONG_SECTION_V_RIGHT     = -2"
            print "LONG_SECTION_V_LEFT      = 2"
            print "$"
            print "$ROAD_CRG_MODS"
            print "* none: the road where the header places it (no default modifiers)"
            print "$"
            print "$KD_DEFINITION"
            print "#:LDFI"
            if (!straight) print "D:reference line phi,rad"
            for (j = 0; j < nv; j++) printf "D:long section at v = %.1f,m\n", -2 + 0.5 * j
            print "$"
            print "$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$$"
            seed = 12345
            for (i = 0; i < nu; i++) {
                u = i * du
                k = straight ? 0 : 1
                if (!straight)
                    v[1] = (i == 0) ? sprintf("%20s", "*unused*") : sprintf("%20.12e", 0.015 * u)
                for (j = 0; j < nv; j++) {
                    w = -2 + 0.5 * j
                    seed = (seed * 1103515245 + 12345) % 2147483648
                    g = 0.004 * sin(2 * pi * u / 0.73 + w) + 0.003 * sin(2 * pi * u / 2.9 - 0.7 * w) \
                        + 0.001 * (seed / 2147483648 - 0.5)
                    if (w > 0 && u >= 11.95 && u <= 12.05) g += 0.05
                    if (w >= 0.5 && w <= 1.5 && u >= 20 && u <= 20.4) g -= 0.03
                    v[j + 1 + k] = sprintf("%20.12e", g)
                }
                rec(v, nv + k)
            }
        }' >"$2"
}

# x and h of an envelope CSV, printed as the curve prints them.
xh() {
    awk -F, 'NR > 1 { print $1 "," $3 }' "$1"
}

# The x and z of a road file read back through 'tirenv convert' to CSV, printed with the
# envelope's 9 significant digits.
road_xh() {
    f=$1
    shift
    "$bin" convert --profile "$f" "$@" -o road.rows.csv 2>/dev/null &&
        grep -v '^#' road.rows.csv | awk -F, 'NR > 1 { printf "%.9g,%.9g\n", $1, $2 }'
}

# h of two envelope CSVs of equal length equal within TOL, row by row.
h_within() {
    [ -s "$1" ] && [ "$(wc -l <"$1")" -eq "$(wc -l <"$2")" ] &&
        paste -d, "$1" "$2" | awk -F, -v t="$3" '
            NR > 1 { d = $3 - $11; if ($1 != $9 || d > t || -d > t) bad = 1 }
            END { exit bad || NR < 2 }'
}

# compare_csv NAME MODEL ROAD OPTS SWEEP: the model over ROAD (--profile, OPTS selecting the
# track) whole and streamed, and over the same track converted to CSV, whole and streamed: the
# four curves equal byte for byte. Streams only where the model streams.
# The sanitizer build (TIRENV_TEST_SANITIZED=1) takes a springs sweep's --dx four times larger:
# the same code over a quarter of the positions (the springs cases were most of
# cli_roads_grade's time there); the Release build takes the steps given.
compare_csv() {
    name=$1 model=$2 road=$3 opts=$4 sweep=$5
    if [ "${TIRENV_TEST_SANITIZED:-0}" = 1 ] && [ $model = springs ]; then
        sweep=$(echo "$sweep" | awk '{ for (i = 2; i <= NF; i++) if ($(i - 1) == "--dx") $i *= 4
            print }')
    fi
    run "$bin" convert --profile "$road" $opts -o "$name.track.csv"
    ok_conv=$rc
    run "$bin" envelope --model $model --profile "$road" $opts $lc $sweep -o "$name.road.out"
    ok_road=$rc
    cp "$name.road.out" "$name.road.csv" 2>/dev/null
    run "$bin" envelope --model $model --profile "$name.track.csv" $lc $sweep -o "$name.csv.out"
    ok_csv=$rc
    same='[ $ok_conv -eq 0 ] && [ $ok_road -eq 0 ] && [ $ok_csv -eq 0 ] &&
          [ $(rows $name.road.out) -gt 100 ] && cmp -s $name.road.out $name.csv.out'
    if [ $model = cam ] || [ $model = springs ] || [ $model = rigid ]; then
        run "$bin" envelope --model $model --profile "$road" $opts $lc $sweep --stream \
            -o "$name.road.stream"
        ok_stream=$rc
        run "$bin" envelope --model $model --profile "$name.track.csv" $lc $sweep --stream \
            -o "$name.csv.stream"
        same="$same"' && [ $ok_stream -eq 0 ] && [ $rc -eq 0 ] &&
              cmp -s $name.road.out $name.road.stream && cmp -s $name.road.out $name.csv.stream'
    fi
    check "$name: $model over $(basename "$road") $opts, whole and streamed = the track as CSV, byte for byte" "$same"
}


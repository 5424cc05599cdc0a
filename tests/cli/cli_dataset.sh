#!/bin/sh
# The embedded data sets from the command line: dataset build --design, what a built data set
# records about its source (source.txt, tire.tir) and how list, fit and study use it; bad
# source files refused with file, line and key. Usage: tests/cli/cli_dataset.sh BIN TESTDATA_DIR.
# SPDX-License-Identifier: Apache-2.0
# shellcheck disable=SC2016,SC2034,SC2086
. "$(dirname "$0")/../lib/clilib.sh"

run "$bin" dataset build --design no-such-design -o d
check "dataset build --design with an unknown name: exit 1 listing the designs" \
    '[ $rc -eq 1 ] && grep -q "14.9R28" err && grep -q "205-60R15" err && [ ! -e d ]'
run "$bin" dataset build --help
check "dataset build --help lists both designs with their models" \
    '[ $rc -eq 0 ] && grep -q "205-60R15.*model cam" out && grep -q "14.9R28.*model ring" out'

run "$bin" dataset build --design 205-60R15 -o d205
check "dataset build --design 205-60R15: 28 cases, logs, curves, tire.tir, source.txt" \
    '[ $rc -eq 0 ] && [ "$(rows d205/cases.csv)" -eq 30 ] &&
     [ "$(ls d205/logs | wc -l)" -eq 28 ] && [ "$(ls d205/curves | wc -l)" -eq 28 ] &&
     [ -s d205/tire.tir ] && [ -s d205/source.txt ]'
check "the manifest says SIMULATED, by the cam, and how to regenerate it" \
    'grep -q "^# SIMULATED" d205/cases.csv && grep -q "MF-Swift" d205/cases.csv &&
     grep -q "dataset build --design 205-60R15" d205/cases.csv'
check "19 train, 5 control, 4 validation cases (F, J, R, AB)" \
    '[ "$(grep -c ",train," d205/cases.csv)" -eq 19 ] &&
     [ "$(grep -c ",control," d205/cases.csv)" -eq 5 ] &&
     [ "$(grep ",validation," d205/cases.csv | cut -d, -f1 | tr "\n" " ")" = "F J R AB " ]'
check "no cleat taller than ELLIPS_MAX_STEP, 25 mm" \
    'awk -F, "!/^#/ && NR > 3 && \$6 > 0.025 { bad = 1 } END { exit bad }" d205/cases.csv'
check "source.txt: design 205-60R15, model cam, tire tire.tir, cases 28" \
    'grep -q "^design = 205-60R15$" d205/source.txt && grep -q "^model = cam$" d205/source.txt &&
     grep -q "^tire = tire.tir$" d205/source.txt && grep -q "^cases = 28$" d205/source.txt'
check "tire.tir: the 205/60R15's radius and cam, no tirenv version in it" \
    'grep -q "^UNLOADED_RADIUS *= 0.3135 " d205/tire.tir &&
     grep -q "^ELLIPS_SHIFT *= 0.8328 " d205/tire.tir && ! grep -qi "written by tirenv [0-9]" d205/tire.tir'

run "$bin" dataset list d205
check "dataset list: SIMULATED by the cam, with its tire, the count, then the 28 cases" \
    '[ $rc -eq 0 ] && grep -q "^SIMULATED by the cam model" out && grep -q "d205/tire.tir" out &&
     grep -q "^28 cases, as source.txt declares$" out && [ "$(grep -c " 101$" out)" -eq 28 ]'
run "$bin" dataset list --design 205-60R15 d205
check "dataset list --design: exit 1 (a data set names its own source)" \
    '[ $rc -eq 1 ] && grep -q "design" err'

# fit takes the data set's tire when --tire is not given: the cam fit (quick) writes it back.
run "$bin" fit --model cam --data d205 -o fitted.tir
check "fit --data: the data set's own tire (R0 0.3135 m in the fitted file)" \
    '[ $rc -eq 0 ] && grep -q "^UNLOADED_RADIUS *= 0.3135 " fitted.tir'
run "$bin" fit --model cam --data d205 --tire "$data/tir_mftyre.tir" -o other.tir
check "fit --data --tire: --tire wins over the data set's tire" \
    '[ $rc -eq 0 ] && ! grep -q "^UNLOADED_RADIUS *= 0.3135 " other.tir'
run "$bin" fit --model ring --fit-radius --data d205
check "fit --model ring --fit-radius: exit 1 pointing at --all" \
    '[ $rc -eq 1 ] && grep -q -- "--all" err'
run "$bin" fit --model ring --check-refinement --data d205
check "fit --model ring --check-refinement: exit 1 (ELEMENT_ANGLE is the springs model's)" \
    '[ $rc -eq 1 ] && grep -q "ELEMENT_ANGLE" err'
run "$bin" study --simulated-by nn --data d205
check "study --simulated-by nn: exit 1 (the rig runs a physical model)" \
    '[ $rc -eq 1 ] && grep -q "physical model" err'

# A source.txt that does not parse is bad data: exit 2 naming file, line and key, and the
# commands that read it stop before doing anything.
bad_source() { # bad_source TEXT: a copy of the data set with this source.txt
    rm -rf bad && cp -r d205 bad && printf '%s\n' "$1" >bad/source.txt
}
bad_source "$(printf 'format = tirenv-dataset 1\nmodel = cam\nsimulator = ring')"
run "$bin" dataset list bad
check "source.txt with an unknown key: exit 2 naming file, line 3 and the key" \
    '[ $rc -eq 2 ] && grep -q "bad/source.txt:3" err && grep -q "simulator" err'
run "$bin" study --data bad -o s
check "study --data with that data set: exit 2, no report" \
    '[ $rc -eq 2 ] && grep -q "source.txt:3" err && [ ! -e s/report.md ]'
bad_source "$(printf 'format = tirenv-dataset 1\nmodel = nn')"
run "$bin" dataset list bad
check "source.txt naming the network as the simulator: exit 2" \
    '[ $rc -eq 2 ] && grep -q "source.txt:2" err && grep -q "model" err'
bad_source "$(printf 'format = tirenv-dataset 2\nmodel = cam')"
run "$bin" dataset list bad
check "source.txt of another format version: exit 2 naming the format" \
    '[ $rc -eq 2 ] && grep -q "source.txt:1" err && grep -q "tirenv-dataset 1" err'
bad_source "$(printf 'model = cam\nmodel = ring\nformat = tirenv-dataset 1')"
run "$bin" dataset list bad
check "source.txt with a key given twice: exit 2 at its second line" \
    '[ $rc -eq 2 ] && grep -q "source.txt:2" err && grep -q "twice" err'
bad_source "model = cam"
run "$bin" dataset list bad
check "source.txt without its format line: exit 2" \
    '[ $rc -eq 2 ] && grep -q "format" err'
bad_source "$(printf 'format = tirenv-dataset 1\nmodel = cam\ncases = 28.0')"
run "$bin" dataset list bad
check "source.txt with a count of cases not a whole number: exit 2 at line 3, key cases" \
    '[ $rc -eq 2 ] && grep -q "bad/source.txt:3:9: cases: " err && grep -q "28.0" err'
bad_source "$(printf 'format = tirenv-dataset 1\nmodel = cam\ncases = 29')"
run "$bin" study --data bad -o s
check "source.txt declaring 29 cases of the 28: exit 2 naming both files, no report" \
    '[ $rc -eq 2 ] && grep -q "bad/cases.csv:.*28 cases, but bad/source.txt:3 declares" err &&
     [ ! -e s ]'
bad_source "$(printf 'format = tirenv-dataset 1\nthe cam made these')"
run "$bin" dataset list bad
check "source.txt with a line that is not key = value: exit 2 at line 2" \
    '[ $rc -eq 2 ] && grep -q "source.txt:2" err'
rm -f bad/source.txt
run "$bin" dataset list bad
check "a data set without source.txt lists as before, with no simulator named" \
    '[ $rc -eq 0 ] && ! grep -q "SIMULATED by" out && [ "$(grep -c " 101$" out)" -eq 28 ]'

clilib_done

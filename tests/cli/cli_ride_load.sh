#!/bin/sh
# tirenv ride --enveloping (docs/models.md section 9.5): the input follows the tire load by
# default; static and dynamic side by side give a row each in comfort.csv (its last column
# says which) and comfort.md compares them; a model whose road does not depend on the load
# (the point contact) gives the same figures either way; bad values are misuse.
# Usage: tests/cli/cli_ride_load.sh BIN TESTDATA_DIR. SPDX-License-Identifier: Apache-2.0
# shellcheck disable=SC2016,SC2034,SC2086
. "$(dirname "$0")/../lib/clilib.sh"

run "$bin" ride --cleat 0.30,0.05 --speed 10km/h --model point,cam \
    --enveloping static,dynamic --out-dir rd --series
check "static and dynamic: 4 rows, the last column names the way" \
    '[ $rc -eq 0 ] && [ $(rows rd/comfort.csv) -eq 4 ] &&
     head -n 1 rd/comfort.csv | grep -q ",real_time_factor,enveloping$" &&
     [ "$(cut -d, -f1,17 rd/comfort.csv | sed 1d | tr "\n" " ")" = "point,static point,dynamic cam,static cam,dynamic " ]'
check "a series per model and way" \
    '[ -s rd/series-cam-dynamic-10kmh.csv ] && [ -s rd/series-cam-static-10kmh.csv ]'
check "comfort.md compares each way with the static run" \
    'grep -q "Following the load" rd/comfort.md && grep -q "| cam | 10.0 | dynamic |" rd/comfort.md'
check "the point contact does not depend on the load: a_wz and VDV the same either way" \
    '[ "$(awk -F, "\$1 == \"point\" { print \$5, \$7 }" rd/comfort.csv | uniq | wc -l)" -eq 1 ]'
check "the cam does: its dynamic a_wz differs from its static one" \
    '[ "$(awk -F, "\$1 == \"cam\" { print \$5 }" rd/comfort.csv | uniq | wc -l)" -eq 2 ]'
check "the dynamic input follows the load: w_front differs from the static run where the tire is loaded" \
    'paste -d, rd/series-cam-static-10kmh.csv rd/series-cam-dynamic-10kmh.csv |
     awk -F, "NR > 2 { d = \$3 - \$16; if (d < 0) d = -d; if (d > m) m = d } END { exit !(m > 1e-4) }"'

run "$bin" ride --cleat 0.30,0.05 --speed 10km/h --model cam -o default.csv
run "$bin" ride --cleat 0.30,0.05 --speed 10km/h --model cam --enveloping dynamic -o dyn.csv
check "the default is dynamic" '[ $rc -eq 0 ] && cmp -s default.csv dyn.csv'
run "$bin" ride --cleat 0.30,0.05 --speed 10km/h --model springs --solver rk8pd \
    --enveloping dynamic -o rk8.csv
check "dynamic with RK8PD runs" '[ $rc -eq 0 ] && [ $(rows rk8.csv) -gt 1000 ]'

run "$bin" ride --cleat 0.30,0.05 --speed 10km/h --model cam --enveloping load
check "--enveloping load: misuse, exit 1, naming the ways" \
    '[ $rc -eq 1 ] && grep -q "static, dynamic or direct" err'
run "$bin" ride --cleat 0.30,0.05 --speed 10km/h --model cam --enveloping static,static
check "--enveloping static,static: misuse" '[ $rc -eq 1 ] && grep -q "at most once" err'
run "$bin" ride --cleat 0.30,0.05 --speed 10km/h --model cam --enveloping static,dynamic -o x.csv
check "-o with two ways: misuse, no file" '[ $rc -eq 1 ] && no_file x.csv'
run "$bin" ride --help
check "--help says what the ways are and which is the default" \
    '[ $rc -eq 0 ] && grep -q "enveloping" out && grep -q "dynamic (default)" out'

clilib_done

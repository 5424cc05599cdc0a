#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# The CSV files tirenv writes read as they are in numpy (docs/formats.md section 1): the header
# line first, then the '#' comment lines, then the rows, so numpy.genfromtxt(names=True) finds
# every column by its name and reads every row. Each writer with comment lines is run: road,
# convert (a .crg track), rig, import, ride -o, sweep (cases.csv, sweep.csv). A profile with its
# comment lines before the header, as earlier versions wrote, still reads, to the same bits,
# and so does such a manifest (tests/data/dataset_good, which many tests read, keeps that
# layout on purpose).
# Needs /usr/bin/python3 with numpy (scripts/deps.sh installs python3-numpy); without it the
# test fails saying so. Usage: tests/cli/cli_csv_numpy.sh BIN TESTDATA_DIR.
# shellcheck disable=SC2016,SC2034,SC2086
. "$(dirname "$0")/../lib/clilib.sh"

python=${TIRENV_PYTHON:-/usr/bin/python3}
run "$python" -c 'import numpy'
check "$python imports numpy (scripts/deps.sh installs python3-numpy)" '[ $rc -eq 0 ]'

# reads_in_numpy FILE [bare]: the first line is the header, a '#' line follows it (unless
# bare: import writes none), and genfromtxt(names=True) gives the header's names and one
# record per data row, all finite.
cat >reads.py <<'EOF'
import sys
import numpy as np
path = sys.argv[1]
with open(path) as f:
    lines = f.read().splitlines()
header = lines[0].split(",")
rows = [l for l in lines[1:] if l.strip() and not l.startswith("#")]
assert not lines[0].startswith("#"), "the first line is a comment"
assert sys.argv[2:] == ["bare"] or any(l.startswith("# ") for l in lines), "no comment line"
a = np.genfromtxt(path, delimiter=",", names=True, dtype=None, encoding="utf-8")
a = np.atleast_1d(a)
assert list(a.dtype.names) == header, (a.dtype.names, header)
assert len(a) == len(rows), (len(a), len(rows))
for name in header:
    if a[name].dtype.kind == "f":
        assert np.all(np.isfinite(a[name])), name
print(len(a), "rows,", len(header), "columns")
EOF
reads_in_numpy() {
    "$python" reads.py "$@" >numpy.out 2>err
}

run "$bin" road --class C --length 20 --dx 0.01 --seed 3 -o road.csv
check "road: numpy reads x_m and z_m of every row" '[ $rc -eq 0 ] && reads_in_numpy road.csv'
run "$bin" convert --profile "$data/samples/crg/halfround_6in.crg" --track 0.5 -o track.csv
check "convert (a .crg track to CSV): numpy reads it" '[ $rc -eq 0 ] && reads_in_numpy track.csv'
run "$bin" rig --model springs --cleat 0.1,0.025 --contact-length 0.43 --seed 2 -o log.csv
check "rig: numpy reads t_s, x_m, z_m" '[ $rc -eq 0 ] && reads_in_numpy log.csv'
run "$bin" import --log log.csv --cleat 0.1,0.025 --contact-length 0.43 -o curve.csv
check "import: numpy reads x_N, x_m, h_m" '[ $rc -eq 0 ] && reads_in_numpy curve.csv bare'
run "$bin" ride --cleat 0.30,0.05 --speed 10km/h --model point -o series.csv
check "ride -o: numpy reads the 13 columns" '[ $rc -eq 0 ] && reads_in_numpy series.csv'
run "$bin" sweep --lengths 0.05,0.15 --heights 0.03 --contact-lengths 0.3 \
    --set INTERRADIAL_STIFFNESS=8000,12000 --model springs -o sw
check "sweep: numpy reads its cases.csv and sweep.csv" \
    '[ $rc -eq 0 ] && reads_in_numpy sw/cases.csv && reads_in_numpy sw/sweep.csv'

# The readers: a file in the old layout (comments, then the header) reads as the new one does.
{ grep '^#' road.csv; grep -v '^#' road.csv; } >old.csv
run "$bin" envelope --model rigid --profile road.csv --load 12000 --dx 0.01 -o new-h.csv
run "$bin" envelope --model rigid --profile old.csv --load 12000 --dx 0.01 -o old-h.csv
check "a profile with its comment lines before the header reads to the same curve" \
    '[ $rc -eq 0 ] && [ "$(head -n 1 old.csv | cut -c1)" = "#" ] && cmp -s new-h.csv old-h.csv'
printf 'case,split,contact_length_m,load_N,obstacle_length_m,obstacle_height_m,log,curve\n' >x
mkdir -p ds/curves
{ echo '# an old-style manifest: the comment first'; cat x
  echo 'A,train,0.43,15000,0.1,0.025,,curves/A.csv'; } >ds/cases.csv
{ echo '# an old-style curve: the comment first'; cat curve.csv; } >ds/curves/A.csv
run "$bin" dataset list ds
check "dataset list reads an old-style manifest (comments first)" \
    '[ $rc -eq 0 ] && grep -q "^ *A " out'

clilib_done
